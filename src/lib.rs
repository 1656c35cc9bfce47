//! raytree: a Whitted-style ray tracer that can show its work.
//!
//! The modules follow the lecture (`shared/lecture-raytracing.md`): the camera and
//! its rays ([`camera`], [`ray`]), ray–object intersection ([`sphere`], [`plane`],
//! [`transform`], [`object`]), local illumination ([`phong`]) with shadow rays, the
//! reflected and refracted rays ([`optics`]), and the recursion that ties them
//! together ([`tracer`]). Around them: scenes ([`scene`], [`scene_file`]), the
//! renderer ([`render`], [`image_file`]) and what the tracer reports ([`recorder`]).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod aabb;
pub mod accel;
pub mod aligned_box;
pub mod bvh;
pub mod camera;
pub mod chart;
pub mod diagram;
pub mod draw;
pub mod float;
pub mod generate;
pub mod hit;
pub mod image_diff;
pub mod image_file;
pub mod inspector;
pub mod light;
pub mod material;
pub mod mesh;
pub mod methods;
pub mod obj_file;
pub mod object;
pub mod optics;
pub mod phong;
pub mod plane;
pub mod projection;
pub mod ray;
pub mod ray_tree;
pub mod recorder;
pub mod render;
pub mod scene;
pub mod scene_file;
pub mod show;
pub mod sphere;
pub mod steps;
pub mod trace;
pub mod trace_text;
pub mod tracer;
pub mod transform;
pub mod triangle;
