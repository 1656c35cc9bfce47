//! Ray–object intersection: each primitive's roots and the surface at a hit,
//! transformed primitives, the object that ties a shape to its material, and the
//! bounding volume hierarchy that avoids most tests.

pub mod hit; // what a test returns: the roots along the ray, the surface at a hit
pub mod sphere; // the lecture's quadratic and its stable form
pub mod plane; // ray–plane
pub mod cuboid; // ray–box by slabs
pub mod triangle; // watertight and Möller–Trumbore
pub mod polygon; // planar polygons and patches, any number of vertices: the crossing-number test in the watertight frame
pub mod polygon_plane; // a polygon's plane (the first three vertices, every vertex on it) and the Newell normal
pub mod mesh; // many triangles, one object, a hierarchy of their own
pub mod transform; // transformed primitives: the inverse-transformed ray
pub mod unit_cone; // the open cylinder and cone in its own space: a quadratic, roots kept for 0 ≤ z ≤ 1
pub mod object; // a shape, its transform and its material
pub mod cone; // the open cylinder or cone between two points: the unit cone placed by a transform
pub mod bvh; // avoiding intersection tests: a bounding volume hierarchy (node layout, build, traversal)
pub mod mailbox; // a primitive listed in several cells is handed to a ray once
pub mod grid; // avoiding intersection tests another way: a uniform grid of cells, walked by the 3D-DDA
pub mod octree; // the lecture's octree: a cube split in eight, cells walked nearest first
pub mod kdtree; // the axis-aligned BSP tree: a k-d tree built by the surface area heuristic, walked front to back
#[cfg(test)]
mod walk_tests; // what the structures' tests share: cubes, a whole walk, a reference sphere hit
