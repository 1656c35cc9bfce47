//! What light does at a hit: materials, the local Phong model, and the optics
//! of the secondary rays (reflection, Snell's law, media, Fresnel weights).

pub mod material;
pub mod optics;
pub mod phong;
