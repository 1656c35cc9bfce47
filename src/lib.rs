//! raytree: a Whitted-style ray tracer that can show its work.
//!
//! Data flows one way, and the folders follow it: a scene file is read into a
//! [`scene`], the [`trace`] folder runs the lecture's recursive `raytrace` over it
//! (rendering every pixel, or recording one pixel's rays into a [`tree`]), and the
//! [`views`] and the [`inspector`] show that tree; [`io`] writes the images.
//! Underneath, [`math`], [`geometry`] and [`shading`] hold the lecture's formulas.
//!
//! Read in the lecture's order (`shared/lecture-raytracing.md`):
//! - the camera and the ray through a pixel: [`scene::camera`], [`math::ray`];
//! - ray–object intersection: [`geometry::sphere`], [`geometry::plane`],
//!   [`geometry::cuboid`], [`geometry::triangle`], [`geometry::mesh`];
//! - transformed primitives and the inverse-transformed ray: [`geometry::transform`];
//! - local illumination: [`shading::phong`], with shadow rays in [`trace::tracer`];
//! - reflected and refracted rays, Snell's law: [`shading::optics`];
//! - the recursion that ties them together: [`trace::tracer`];
//! - efficiency, avoiding intersection tests: [`geometry::bvh`], [`trace::accelerator`].
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod geometry;
pub mod inspector;
pub mod io;
pub mod math;
pub mod methods;
pub mod scene;
pub mod shading;
pub mod trace;
pub mod tree;
pub mod views;
