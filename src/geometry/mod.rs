//! Ray–object intersection: each primitive's roots and the surface at a hit,
//! transformed primitives, the object that ties a shape to its material, and the
//! efficiency slide's structures that avoid most tests.

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
pub mod structures; // avoiding intersection tests: the BVH, the grid, the octree and the BSP tree behind one trait
