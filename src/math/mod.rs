//! Numbers under everything: floating-point error bounds, the ray `S + t·c`,
//! bounding boxes, angles. Knows nothing of scenes.

pub mod ray; // the ray S + t·c
pub mod float; // floating-point error bounds and the robust ray-origin offset
pub mod bounds; // axis-aligned bounding boxes and the slab test
pub mod angle; // the angle between two directions, accurate at every angle
