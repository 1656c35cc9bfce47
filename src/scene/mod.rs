//! The scene model: what the tracer reads. Built and validated by
//! [`crate::scene::loader`], so everything here is known to be well formed.

pub mod camera; // eye, u, v, n, W, H, N: the image plane and its pixels
pub mod light; // point lights
pub mod settings; // image size, sampling, recursion limits, methods
pub mod overrides; // the settings a scene file or the command line changes
pub mod format; // the scene file's shape, as serde reads it
pub mod quote; // the user's words in an error: printable, and cut when long
pub mod strict; // JSON objects only, each name once
pub mod limits; // the ranges that keep every computed number finite
pub mod camera_file; // the camera block, checked (right-handed frames only)
pub mod names; // names printable, mesh files within the scene's folder
pub mod scene_error; // why a scene file could not be read, in one line
pub mod loader; // the scene file, checked, into a Scene
mod object_file; // its objects: shapes, transforms, mesh files
pub mod obj; // OBJ meshes
pub mod nff; // NFF scenes (the Standard Procedural Databases), read into the format's parts, written as scene JSON
pub mod source; // which scene file, by name and hash
pub mod generate; // scenes made by program
pub mod vary; // one numeric field of a scene file, varied (filmstrips)

use glam::DVec3;

use crate::geometry::object::Object;
use crate::math::ray::Ray;
use crate::scene::camera::{Camera, CameraSpec};
use crate::scene::light::PointLight;
use crate::scene::settings::RenderSettings;
use crate::shading::material::Material;
use crate::shading::optics::Media;

/// The direction of the ray [`Scene::media_at`] sorts the media along. Any
/// gives nested media the same order.
const OUTWARD: DVec3 = DVec3::new(1.0, 2.0, 3.0);

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

    /// The transparent objects that contain `p`, outermost first: the media a
    /// ray starting at `p` travels through, stacked as the tracer stacks them
    /// (the medium entered last is the innermost, [`Media`]).
    ///
    /// The order is containment's, whatever the file's: along every ray from
    /// `p`, an object inside another is left no later than the one around it.
    /// So the media are sorted by where one ray from `p` leaves them, farthest
    /// first: the order in which a ray coming the opposite way would have
    /// entered them, by the tracer's own rule. For objects that overlap, neither
    /// inside the other, that ray's order is the one taken. Two objects left at
    /// the same point (they touch there) are told apart by the ray the other
    /// way, and then by the file's order.
    pub fn media_at(&self, p: DVec3) -> Media {
        let methods = self.settings.intersection_methods();
        // Where the ray from `p` along `dir` leaves object `i`, which holds `p`:
        // its last root ahead, or never (a half-space it runs deeper into).
        let leaves = |i: usize, dir: DVec3| {
            let roots = self.objects[i].roots(&Ray::new(p, dir), methods);
            roots
                .as_slice()
                .iter()
                .copied()
                .filter(|&t| t > 0.0)
                .reduce(f64::max)
                .unwrap_or(f64::INFINITY)
        };
        let mut inside: Vec<(f64, f64, usize)> = (0..self.objects.len())
            .filter(|&i| self.is_solid_medium(i) && self.objects[i].contains(p))
            .map(|i| (leaves(i, OUTWARD), leaves(i, -OUTWARD), i))
            .collect();
        inside.sort_by(|a, b| {
            b.0.total_cmp(&a.0)
                .then(b.1.total_cmp(&a.1))
                .then(a.2.cmp(&b.2))
        });
        inside
            .into_iter()
            .fold(Media::default(), |m, (_, _, i)| m.entered(i))
    }

    /// Whether object `object` is a transparent solid: a medium whose inside
    /// [`Scene::media_at`] finds, so a ray's stack of media holds it exactly
    /// when the ray is inside it (a mesh is entered only by crossing it).
    pub fn is_solid_medium(&self, object: usize) -> bool {
        self.material_of(object).transparent > 0.0 && self.objects[object].shape.is_solid()
    }

    /// The material of object `object`.
    pub fn material_of(&self, object: usize) -> &Material {
        &self.materials[self.objects[object].material]
    }
}
