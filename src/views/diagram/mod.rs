//! Ray diagrams: a pixel's ray tree drawn in 2D over the scene, as a lecture
//! slide draws it. The scene is projected onto a drawing plane
//! ([`projection`], [`section`]), the recorded rays laid out on it
//! ([`arrange`] into a [`layout::Layout`], framed by [`frame`], annotated by
//! [`marks`] and [`boxes`]), then drawn ([`draw`], with [`labels`] and a legend). The
//! camera's and an object's own space have views of their own.

pub mod options; // what the reader asks of a diagram: the fit, the labels, the plane
pub mod style; // pens and sizes every diagram shares
pub mod projection; // the scene projected onto a drawing plane
pub mod section; // what the drawing plane cuts, and what a ray only passes
pub mod boxes; // the hierarchy's boxes a ray was tested against, projected
pub mod layout; // a laid-out diagram: rays, hits and objects in drawing coordinates
pub mod frame; // what a ray diagram frames
pub mod marks; // the angles, indices and badges a slide puts on a diagram
pub mod arrange; // laying a recorded tree out on the drawing plane
pub mod reveal; // when each part of a diagram appears, tagged in its SVG for the players
pub mod labels; // what a ray diagram labels, and drawing the labels
mod legend; // the legend: only what is drawn, in the corner that hides the least
pub mod draw; // a ray diagram as a figure
pub mod camera_view; // the image plane face-on, with a pixel's place on it
pub mod object_view; // a transformed sphere's hit in its own space, beside the world
