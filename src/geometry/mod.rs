//! Ray–object intersection: each primitive's roots and the surface at a hit,
//! transformed primitives, the object that ties a shape to its material, and the
//! bounding volume hierarchy that avoids most tests.

pub mod bvh;
pub mod cuboid;
pub mod hit;
pub mod mesh;
pub mod object;
pub mod plane;
pub mod sphere;
pub mod transform;
pub mod triangle;
