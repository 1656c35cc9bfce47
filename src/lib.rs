//! raytree: a Whitted-style ray tracer that can show its work.
//!
//! Data flows one way, and the folders follow it: a scene file is read into a
//! [`scene`], the [`trace`] folder runs the lecture's recursive `raytrace` over it
//! (rendering every pixel in the one pixel loop, or recording one pixel's rays
//! into a [`tree`]), the [`views`] show that tree (drawing with [`figure`]), the
//! [`course`] teaches with it and the [`inspector`] walks it; [`io`] writes the
//! images. Underneath, [`math`], [`geometry`] and [`shading`] hold the lecture's
//! formulas. `ARCHITECTURE.md` maps every folder.
//!
//! Read in the lecture's order (`shared/lecture-raytracing.md`):
//! - the camera and the ray through a pixel: [`scene::camera`], [`math::ray`];
//! - ray–object intersection: [`geometry::sphere`], [`geometry::plane`],
//!   [`geometry::cuboid`], [`geometry::triangle`], [`geometry::mesh`];
//! - transformed primitives and the inverse-transformed ray: [`geometry::transform`];
//! - local illumination: [`shading::phong`], with shadow rays in [`trace::tracer`];
//! - reflected and refracted rays, Snell's law: [`shading::optics`];
//! - the recursion that ties them together: [`trace::tracer`];
//! - efficiency, avoiding intersection tests: [`geometry::structures`], [`trace::accelerator`].
//!
//! The types a program drives are re-exported here: load a [`Scene`], [`render`]
//! it into an [`Image`], or [`record`] one pixel's [`RayTree`].
#![forbid(unsafe_code)]
#![warn(missing_docs)]

// The lecture's formulas, bottom up.
pub mod math; // the ray S + t·c, floating-point error bounds, bounding boxes, angles
pub mod geometry; // ray–object intersection, transformed primitives, the hierarchy
pub mod shading; // local illumination, reflection, refraction
pub mod scene; // the camera and image plane, lights, materials, objects, scene files

// Running the algorithm, and showing its work.
pub mod trace; // raytrace(): the recursion, its recorder, every pixel on all cores
pub mod tree; // the ray tree of one pixel, its steps, the trace document
pub mod views; // the text trace, ray diagrams, figures that explain an image
pub mod course; // the lessons, their specs and guided step-throughs
pub mod inspector; // the terminal inspector

// Anyone's.
pub mod methods; // the selectable methods: the lecture's and the robust ones
pub mod io; // images and output files
pub mod figure; // the drawing toolkit: canvas, pens, text, labels, legend

// The few types and functions a program drives.
pub use io::image::Image;
pub use scene::Scene;
pub use trace::progress::Progress;
pub use trace::render::render;
pub use tree::ray_tree::RayTree;
pub use tree::record;
