//! The scene model: what the tracer reads. Built and validated by
//! [`crate::scene::loader`], so everything here is known to be well formed.

pub mod camera; // eye, u, v, n, W, H, N: the image plane and its pixels
pub mod light; // point lights
pub mod settings; // image size, sampling, recursion limits, methods
pub mod overrides; // the settings a scene file or the command line changes
pub mod format; // the scene file's shape, as serde reads it
pub mod strict; // JSON objects only, each name once
pub mod limits; // the ranges that keep every computed number finite
pub mod camera_file; // the camera block, checked (right-handed frames only)
pub mod loader; // the scene file, checked, into a Scene
pub mod obj; // OBJ meshes
pub mod source; // which scene file, by name and hash
pub mod generate; // scenes made by program
pub mod vary; // one numeric field of a scene file, varied (filmstrips)

use glam::DVec3;

use crate::geometry::object::Object;
use crate::scene::camera::{Camera, CameraSpec};
use crate::scene::light::PointLight;
use crate::scene::settings::RenderSettings;
use crate::shading::material::Material;
use crate::shading::optics::Media;

/// Everything the tracer needs.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The camera, before the image size is known.
    pub camera: CameraSpec,
    /// Render settings from the scene file, overridable from the command line.
    pub settings: RenderSettings,
    /// What a ray that hits nothing returns (linear RGB).
    pub background: DVec3,
    /// The global ambient light (linear RGB).
    pub ambient_light: DVec3,
    /// Materials, referenced by index from the objects.
    pub materials: Vec<Material>,
    /// The lights.
    pub lights: Vec<PointLight>,
    /// The objects.
    pub objects: Vec<Object>,
    /// The OBJ files the meshes were read from: inputs no output may replace.
    pub mesh_files: Vec<std::path::PathBuf>,
}

impl Scene {
    /// The camera for the current image size.
    pub fn camera(&self) -> Camera {
        Camera::new(&self.camera, self.settings.width, self.settings.height)
    }

    /// The transparent objects that contain `p`, outermost (largest) first:
    /// the media a ray starting at `p` travels through.
    pub fn media_at(&self, p: DVec3) -> Media {
        let inside: Vec<usize> = (0..self.objects.len())
            .filter(|&i| self.material_of(i).transparent > 0.0 && self.objects[i].contains(p))
            .collect();
        // An object that contains another's center encloses it: it goes first.
        let mut ranked: Vec<(usize, usize)> = inside
            .iter()
            .map(|&i| {
                (
                    inside
                        .iter()
                        .filter(|&&j| j != i && self.encloses(i, j))
                        .count(),
                    i,
                )
            })
            .collect();
        ranked.sort_by_key(|&(encloses, i)| (std::cmp::Reverse(encloses), i));
        ranked
            .into_iter()
            .fold(Media::default(), |m, (_, i)| m.entered(i))
    }

    fn encloses(&self, outer: usize, inner: usize) -> bool {
        self.objects[outer].contains(self.objects[inner].center())
    }

    /// The material of object `object`.
    pub fn material_of(&self, object: usize) -> &Material {
        &self.materials[self.objects[object].material]
    }
}
