//! The scene file's shape as serde reads it: every field optional where the
//! format has a default, unknown fields refused, every struct a JSON object and
//! every name given once ([`crate::scene::strict`]). [`crate::scene::loader`]
//! turns it into a checked [`crate::scene::Scene`]; `scenes/README.md`
//! documents it. Its parts also serialise, leaving out what is not given: the
//! NFF reader builds them ([`crate::scene::nff`]) and writes them as JSON.

use std::collections::BTreeMap;

use glam::DVec3;
use serde::{Deserialize, Deserializer, Serialize};

use crate::scene::overrides::Overrides;
use crate::scene::strict;

/// A whole scene file, which must be a JSON object.
pub(super) struct Root(pub(super) SceneFile);

impl<'de> Deserialize<'de> for Root {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        strict::object(d).map(Root)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    #[serde(default)]
    pub(super) description: Option<String>,
    #[serde(default, deserialize_with = "strict::object")]
    pub(super) camera: CameraFile,
    #[serde(default, deserialize_with = "strict::object")]
    pub(super) render: Overrides,
    #[serde(default)]
    pub(super) background: Option<DVec3>,
    #[serde(default)]
    pub(super) ambient_light: Option<DVec3>,
    #[serde(default, deserialize_with = "strict::named_objects")]
    pub(super) materials: BTreeMap<String, MaterialFile>,
    #[serde(default, deserialize_with = "strict::objects")]
    pub(super) lights: Vec<LightFile>,
    #[serde(default, deserialize_with = "strict::objects")]
    pub(super) objects: Vec<ObjectFile>,
}

#[derive(Deserialize, Serialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct CameraFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) eye: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) look_at: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) up: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) fov: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) u: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) v: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) n: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) half_width: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) half_height: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) distance: Option<f64>,
}

#[derive(Deserialize, Serialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct MaterialFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) color: Option<DVec3>,
    #[serde(
        default,
        deserialize_with = "strict::some_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) checker: Option<CheckerFile>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) ambient: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) diffuse: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) specular: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) shininess: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) reflective: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) transparent: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) ior: Option<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CheckerFile {
    pub(super) colors: [DVec3; 2],
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) size: Option<CellSize>,
}

/// A checker cell's side: one length (cubes), or one per axis, for a pattern
/// whose cells are longer one way (lesson 14's floor is 7 by 9).
#[derive(Deserialize, Serialize)]
#[serde(untagged, expecting = "expected a length, or three lengths [x, y, z]")]
pub(super) enum CellSize {
    Cube(f64),
    Sides(DVec3),
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LightFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) name: Option<String>,
    pub(super) position: DVec3,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) color: Option<DVec3>,
}

#[derive(Deserialize, Serialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct ObjectFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) name: Option<String>,
    #[serde(
        default,
        deserialize_with = "strict::some_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) sphere: Option<SphereFile>,
    #[serde(
        default,
        deserialize_with = "strict::some_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) plane: Option<PlaneFile>,
    #[serde(
        default,
        rename = "box",
        deserialize_with = "strict::some_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) aligned_box: Option<BoxFile>,
    #[serde(
        default,
        deserialize_with = "strict::some_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) triangle: Option<TriangleFile>,
    #[serde(
        default,
        deserialize_with = "strict::some_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) mesh: Option<MeshFile>,
    #[serde(
        default,
        deserialize_with = "strict::some_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) polygon: Option<PolygonFile>,
    #[serde(
        default,
        deserialize_with = "strict::some_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) cone: Option<ConeFile>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) material: Option<String>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(super) transform: Vec<TransformStep>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SphereFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) center: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) radius: Option<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct PlaneFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) point: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) normal: Option<DVec3>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct BoxFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) min: Option<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) max: Option<DVec3>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct TriangleFile {
    pub(super) vertices: [DVec3; 3],
}

/// An open cylinder or cone from `base` to `apex`, with a radius at each end.
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ConeFile {
    pub(super) base: DVec3,
    pub(super) base_radius: f64,
    pub(super) apex: DVec3,
    pub(super) apex_radius: f64,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct PolygonFile {
    pub(super) vertices: Vec<DVec3>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) normals: Option<Vec<DVec3>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) one_sided: Option<bool>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MeshFile {
    pub(super) file: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) smooth: Option<bool>,
}

#[derive(Deserialize, Serialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum TransformStep {
    Translate(DVec3),
    Scale(DVec3),
    RotateX(f64),
    RotateY(f64),
    RotateZ(f64),
    #[serde(deserialize_with = "strict::object")]
    Rotate(RotateFile),
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RotateFile {
    pub(super) axis: DVec3,
    pub(super) degrees: f64,
}
