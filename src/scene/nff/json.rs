//! An NFF scene, as read by [`crate::scene::nff`], written as raytree's
//! scene JSON: the header pretty, one material, light and object to a line,
//! so a converted SPD scene of thousands of objects stays readable.
//!
//! Each entry is the scene format's own struct, serialised through
//! `serde_json::Value`, whose objects keep their keys sorted: a converted
//! file's fields read in that order (`"ambient"` before `"color"`), as they
//! always have, whatever the order the struct declares them in.

use std::fmt::Write as _;

use glam::DVec3;
use serde::Serialize;
use serde_json::{Value, json};

use crate::scene::format::LightFile;
use crate::scene::nff::NffScene;

/// `part` of the scene (a camera block, a material, an object) as JSON,
/// its keys sorted.
fn value(part: &impl Serialize) -> Value {
    serde_json::to_value(part).expect("the scene format's parts serialise to JSON")
}

impl NffScene {
    /// The scene as raytree JSON: the header pretty, one object to a line.
    pub(super) fn json(&self, file: &str) -> String {
        let mut out = self.header(file);
        out.push_str("  \"materials\": {\n");
        for (k, (name, m)) in self.materials.iter().enumerate() {
            let comma = if k + 1 < self.materials.len() {
                ","
            } else {
                ""
            };
            let _ = writeln!(out, "    {}: {}{comma}", json!(name), value(m));
        }
        out.push_str("  },\n  \"lights\": [\n");
        for (k, light) in self.lights.iter().enumerate() {
            let light = LightFile {
                name: light.name.clone(),
                position: light.position,
                color: light.color.or(Some(self.default_light())),
            };
            let comma = if k + 1 < self.lights.len() { "," } else { "" };
            let _ = writeln!(out, "    {}{comma}", value(&light));
        }
        out.push_str("  ],\n  \"objects\": [\n");
        for (k, o) in self.objects.iter().enumerate() {
            let comma = if k + 1 < self.objects.len() { "," } else { "" };
            let _ = writeln!(out, "    {}{comma}", value(o));
        }
        out.push_str("  ]\n}\n");
        out
    }

    /// The intensity the SPD's notes suggest for a light without a color,
    /// and for the ambient light: `√n / (2n)` for `n` lights, in white.
    fn default_light(&self) -> DVec3 {
        let n = self.lights.len().max(1) as f64;
        DVec3::splat(n.sqrt() / (2.0 * n))
    }

    /// The file's opening brace and its header, in the order a reader wants
    /// it, one field to a line: the description, the camera, the image size,
    /// the background and the ambient light.
    fn header(&self, file: &str) -> String {
        let (camera, render) = self.view.as_ref().expect("read() requires a view");
        let name = std::path::Path::new(file)
            .file_name()
            .map_or_else(|| file.to_owned(), |f| f.to_string_lossy().into_owned());
        let background = self.background.unwrap_or(DVec3::ZERO);
        let head = [
            (
                "description",
                json!(format!(
                    "{name}, an NFF scene (Standard Procedural Databases), as raytree reads it: colors made linear from sRGB, each light without a color and the ambient light √n/(2n) for n lights"
                )),
            ),
            ("camera", value(camera)),
            ("render", value(render)),
            ("background", value(&background)),
            ("ambient_light", value(&self.default_light())),
        ];
        let mut out = String::from("{\n");
        for (key, value) in head {
            let _ = writeln!(out, "  {}: {value},", json!(key));
        }
        out
    }
}
