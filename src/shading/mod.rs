//! What light does at a hit: materials, the local Phong model, and the optics
//! of the secondary rays (reflection, Snell's law, media, Fresnel weights).

pub mod material; // colors and the coefficients of the local model and the recursion
pub mod phong; // I = ambient + diffuse + specular
pub mod optics; // reflection, Snell's law, total internal reflection, Fresnel, media
