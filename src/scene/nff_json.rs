//! An NFF scene, as read by [`crate::scene::nff`], written as raytree's
//! scene JSON: the header pretty, one material, light and object to a line,
//! so a converted SPD scene of thousands of objects stays readable.

use std::fmt::Write as _;

use glam::DVec3;
use serde_json::{Value, json};

/// What an NFF file holds, read and checked.
#[derive(Default)]
pub(super) struct NffScene {
    pub(super) view: Option<View>,
    pub(super) background: Option<DVec3>,
    /// Position and color, if given.
    pub(super) lights: Vec<(DVec3, Option<DVec3>)>,
    /// Materials by name, in the order first used, as JSON.
    pub(super) materials: Vec<(String, Value)>,
    pub(super) objects: Vec<Value>,
}

pub(super) struct View {
    pub(super) from: DVec3,
    pub(super) at: DVec3,
    pub(super) up: DVec3,
    pub(super) angle: f64,
    pub(super) resolution: (u32, u32),
}

/// `f`'s material as raytree's (see [`crate::scene::nff`]): Kd the diffuse
/// and ambient shares, Ks the highlight and the reflection, T the
/// transparency, with the color already made linear and the index checked.
pub(super) fn material_json(color: DVec3, kd: f64, ks: f64, shine: f64, t: f64, ior: f64) -> Value {
    json!({
        "color": xyz(color),
        "ambient": kd,
        "diffuse": kd,
        "specular": ks,
        "shininess": shine,
        "reflective": ks,
        "transparent": t,
        "ior": ior,
    })
}

/// A point or color as a JSON array.
pub(super) fn xyz(p: DVec3) -> Value {
    json!([p.x, p.y, p.z])
}

impl NffScene {
    /// The scene as raytree JSON: the header pretty, one object to a line.
    pub(super) fn json(&self, file: &str) -> String {
        let view = self.view.as_ref().expect("read() requires a view");
        let n = self.lights.len().max(1) as f64;
        let intensity = n.sqrt() / (2.0 * n);
        let name = std::path::Path::new(file)
            .file_name()
            .map_or_else(|| file.to_owned(), |f| f.to_string_lossy().into_owned());
        let background = self.background.unwrap_or(DVec3::ZERO);
        // The header in the order a reader wants it, one field to a line.
        let head = [
            (
                "description",
                json!(format!(
                    "{name}, an NFF scene (Standard Procedural Databases), as raytree reads it: colors made linear from sRGB, each light without a color and the ambient light √n/(2n) for n lights"
                )),
            ),
            (
                "camera",
                json!({
                    "eye": xyz(view.from),
                    "look_at": xyz(view.at),
                    "up": xyz(view.up),
                    "fov": view.angle,
                }),
            ),
            (
                "render",
                json!({ "width": view.resolution.0, "height": view.resolution.1 }),
            ),
            ("background", xyz(background)),
            ("ambient_light", xyz(DVec3::splat(intensity))),
        ];
        let mut out = String::from("{\n");
        for (key, value) in head {
            let _ = writeln!(out, "  {}: {value},", json!(key));
        }
        out.push_str("  \"materials\": {\n");
        for (k, (name, m)) in self.materials.iter().enumerate() {
            let comma = if k + 1 < self.materials.len() {
                ","
            } else {
                ""
            };
            let _ = writeln!(out, "    {}: {m}{comma}", json!(name));
        }
        out.push_str("  },\n  \"lights\": [\n");
        for (k, (position, color)) in self.lights.iter().enumerate() {
            let color = color.unwrap_or(DVec3::splat(intensity));
            let light = json!({ "position": xyz(*position), "color": xyz(color) });
            let comma = if k + 1 < self.lights.len() { "," } else { "" };
            let _ = writeln!(out, "    {light}{comma}");
        }
        out.push_str("  ],\n  \"objects\": [\n");
        for (k, o) in self.objects.iter().enumerate() {
            let comma = if k + 1 < self.objects.len() { "," } else { "" };
            let _ = writeln!(out, "    {o}{comma}");
        }
        out.push_str("  ]\n}\n");
        out
    }
}
