//! Numbers under everything: floating-point error bounds, the ray `S + t·c`,
//! bounding boxes. Knows nothing of scenes.

pub mod bounds;
pub mod float;
pub mod ray;
