//! What-if: change the selected hit's material or a method choice inside the
//! inspector and see what the pixel does. Edits are made to the scene file's
//! JSON and read again by the scene loader, so an edit is checked exactly as a
//! scene file would be, and the edited scene can be written out as a file
//! that raytree reads back the same. An edit never touches an object, so the
//! JSON kept and read again is the file's without its objects: a scene of a
//! million objects took 18 s to edit when the whole file was (issue 29).

use std::path::Path;
use std::sync::Arc;

use glam::DVec3;
use serde::Deserializer;
use serde::de::{IgnoredAny, MapAccess, Visitor};
use serde_json::{Map, Value};

use crate::io::output::PendingFile;
use crate::scene::Scene;
use crate::scene::scene_error::SceneError;
use crate::scene::settings::RenderSettings;
use crate::scene::source::SceneSource;

/// The material fields an edit may change, as the scene file names them.
pub const MATERIAL_FIELDS: &[&str] = &[
    "color",
    "ambient",
    "diffuse",
    "specular",
    "shininess",
    "reflective",
    "transparent",
    "ior",
];

/// A method choice an edit may change: its name among the scene file's
/// `render` fields, how the edited file's setting is copied into the scene's
/// (whose other settings keep the command line's overrides), and whether it
/// takes a number or a word. One table, so a field cannot be accepted and
/// then change nothing.
struct MethodField {
    name: &'static str,
    copy: fn(&mut RenderSettings, &RenderSettings),
    number: bool,
}

/// The method choices an edit may change.
const METHOD_FIELDS: &[MethodField] = &[
    MethodField {
        name: "sphere",
        copy: |to, from| to.sphere = from.sphere,
        number: false,
    },
    MethodField {
        name: "offset",
        copy: |to, from| to.offset = from.offset,
        number: false,
    },
    MethodField {
        name: "weights",
        copy: |to, from| to.weights = from.weights,
        number: false,
    },
    MethodField {
        name: "max_depth",
        copy: |to, from| to.max_depth = from.max_depth,
        number: true,
    },
    MethodField {
        name: "cutoff",
        copy: |to, from| to.cutoff = from.cutoff,
        number: true,
    },
];

/// The method field named `field`, if it is one.
fn method_field(field: &str) -> Option<&'static MethodField> {
    METHOD_FIELDS.iter().find(|m| m.name == field)
}

/// Applies `field=value` to material `material` (or, for a method field, to the
/// render settings) in `json` (the scene file's, without its objects:
/// [`skeleton`]), and returns `scene` with that material or setting as the
/// edited JSON reads. `scene`'s other settings (the command line's overrides
/// included) and materials are kept. Errors are one line saying what is wrong.
pub fn apply(
    json: &mut Value,
    material: Option<&str>,
    typed: &str,
    scene: &Scene,
    file: &str,
) -> Result<Scene, String> {
    let (field, raw) = typed
        .split_once('=')
        .map(|(f, v)| (f.trim(), v.trim()))
        .ok_or_else(|| format!("'{typed}': type field=value, e.g. ior=1.0"))?;
    let value = parse_value(raw);
    let mut edited = json.clone();
    let method = method_field(field);
    if method.is_some() {
        let render = edited
            .as_object_mut()
            .ok_or("the scene is not a JSON object")?
            .entry("render")
            .or_insert_with(|| Value::Object(Default::default()));
        render
            .as_object_mut()
            .ok_or("the scene's render is not an object")?
            .insert(field.to_owned(), value.clone());
    } else if MATERIAL_FIELDS.contains(&field) {
        let name = material.ok_or("select a ray that hit something to edit its material")?;
        let m = edited
            .get_mut("materials")
            .and_then(|ms| ms.get_mut(name))
            .and_then(Value::as_object_mut)
            .ok_or_else(|| format!("material '{name}' is not in the scene file"))?;
        if field == "color" {
            m.remove("checker");
        }
        m.insert(field.to_owned(), value.clone());
    } else {
        return Err(format!(
            "'{field}' cannot be edited: try one of {}, {}",
            MATERIAL_FIELDS.join(", "),
            METHOD_FIELDS
                .iter()
                .map(|m| m.name)
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    let text = serde_json::to_string(&edited).map_err(|e| e.to_string())?;
    let read =
        crate::scene::loader::parse(&text, file).map_err(|e| refused(field, raw, &value, e))?;
    let mut settings = scene.settings;
    if let Some(m) = method {
        (m.copy)(&mut settings, &read.settings);
    }
    let mut materials = scene.materials.clone();
    if let Some(name) = material.filter(|_| MATERIAL_FIELDS.contains(&field)) {
        let now = read.materials.iter().find(|m| m.name == name);
        let was = materials.iter_mut().find(|m| m.name == name);
        match (now, was) {
            (Some(now), Some(was)) => *was = now.clone(),
            _ => return Err(format!("material '{name}' is not in the scene")),
        }
    }
    *json = edited;
    Ok(Scene {
        settings,
        materials,
        ..scene.clone()
    })
}

/// Whether `field` takes a number: every material field but the color
/// (r,g,b), and the methods their table says.
fn takes_a_number(field: &str) -> bool {
    match method_field(field) {
        Some(m) => m.number,
        None => field != "color" && MATERIAL_FIELDS.contains(&field),
    }
}

/// Why the edit `field=raw` (read as `value`) was refused, in terms of the
/// edit: the loader's line and column are of the JSON made from the edit, a
/// place the learner never typed and the scene file does not have.
fn refused(field: &str, raw: &str, value: &Value, e: SceneError) -> String {
    let reason = match e {
        _ if value.is_string() && takes_a_number(field) => "not a number".to_owned(),
        _ if value.is_string() && field == "color" => {
            "not a color: type r,g,b, e.g. 1,0.5,0".to_owned()
        }
        SceneError::Syntax { message, .. } => message,
        SceneError::Invalid { field, message, .. } => format!("{field}: {message}"),
        other => other.to_string(),
    };
    format!("{field}={raw}: {reason}")
}

/// A typed value as JSON: a number, a color `r,g,b`, or a word (`lecture`).
fn parse_value(raw: &str) -> Value {
    if let Ok(v) = serde_json::from_str::<Value>(raw) {
        return v;
    }
    let parts: Vec<&str> = raw.split(',').map(str::trim).collect();
    if parts.len() == 3
        && let Ok(c) = parts
            .iter()
            .map(|p| p.parse::<f64>())
            .collect::<Result<Vec<_>, _>>()
    {
        return serde_json::json!(c);
    }
    Value::String(raw.to_owned())
}

/// Writes the scene file `source` names with the top-level fields of `edited`
/// (its JSON without its objects, edited) to `path`, which must not exist yet
/// (an edit never replaces a file, least of all the scene it came from);
/// atomically, and removed if a signal ends the inspector while it is written.
pub fn write(source: &SceneSource, edited: &Value, path: &Path) -> Result<(), String> {
    if path.exists() {
        return Err(format!("{} exists: give a new file name", path.display()));
    }
    let mut json: Value =
        serde_json::from_str(&read_text(source)?).map_err(|e| format!("{}: {e}", source.file))?;
    let (Some(whole), Some(edited)) = (json.as_object_mut(), edited.as_object()) else {
        return Err(format!("{}: the scene is not a JSON object", source.file));
    };
    for (field, value) in edited {
        whole.insert(field.clone(), value.clone());
    }
    let mut text = serde_json::to_string_pretty(&json).map_err(|e| e.to_string())?;
    text.push('\n');
    PendingFile::create(path)
        .and_then(|file| file.commit_new(text.as_bytes()))
        .map_err(|e| e.to_string())
}

/// The pixel's color and tree before the first what-if edit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Before {
    /// The pixel.
    pub pixel: (u32, u32),
    /// Its color.
    pub color: DVec3,
    /// Rays in its first sample's tree.
    pub rays: usize,
}

/// The what-if edits in effect, the scene file's JSON they were made to, the
/// scene as loaded (to undo them) and the pixel before the first.
#[derive(Debug, Default)]
pub(in crate::inspector) struct WhatIf {
    /// The scene file's JSON without its objects (read on the first edit).
    json: Option<Value>,
    /// The scene as loaded, while edits are in effect.
    loaded: Option<Arc<Scene>>,
    /// The edits, as typed (a material's with its name).
    edits: Vec<String>,
    /// The pixel before the first edit.
    before: Option<Before>,
    /// The edits in effect were written to a file since the last one.
    written: bool,
}

impl WhatIf {
    /// The edits in effect, as typed.
    pub fn edits(&self) -> &[String] {
        &self.edits
    }

    /// The pixel before the first edit, while edits are in effect.
    pub fn before(&self) -> Option<&Before> {
        self.before.as_ref()
    }

    /// Applies a typed edit (`ior=1.0`) to `material` (the selected hit's) or
    /// a method of `scene`, which `source` names; `before` is the pixel now,
    /// kept if this is the first edit. Returns the edited scene.
    pub fn edit(
        &mut self,
        scene: &Arc<Scene>,
        source: &SceneSource,
        material: Option<&str>,
        typed: &str,
        before: Option<Before>,
    ) -> Result<Arc<Scene>, String> {
        if self.json.is_none() {
            let mut text = read_text(source)?;
            if crate::scene::nff::is_nff(&source.file) {
                // An NFF scene is edited in its JSON form, which the loader reads.
                text =
                    crate::scene::nff::to_json(&text, &source.file).map_err(|e| e.to_string())?;
            }
            self.json = Some(skeleton(&text, &source.file)?);
        }
        let json = self.json.as_mut().expect("read above");
        let edited = apply(json, material, typed, scene, &source.file)?;
        if self.before.is_none() {
            self.before = before;
        }
        if self.loaded.is_none() {
            self.loaded = Some(Arc::clone(scene));
        }
        let label = match material {
            Some(m)
                if MATERIAL_FIELDS
                    .iter()
                    .any(|f| typed.trim_start().starts_with(f)) =>
            {
                format!("{m}: {}", typed.trim())
            }
            _ => typed.trim().to_owned(),
        };
        self.edits.push(label);
        self.written = false;
        Ok(Arc::new(edited))
    }

    /// What the edits are, for the status line.
    pub fn told(&self) -> String {
        format!("what if {}  (u: undo all, w: write)", self.edits.join("; "))
    }

    /// Forgets every edit, giving the scene as loaded (none without edits).
    pub fn undo(&mut self) -> Option<Arc<Scene>> {
        let loaded = self.loaded.take()?;
        self.edits.clear();
        self.before = None;
        self.json = None;
        self.written = false;
        Some(loaded)
    }

    /// Whether edits are in effect that no file holds: quitting loses them.
    pub fn unsaved(&self) -> bool {
        !self.edits.is_empty() && !self.written
    }

    /// Writes the edited scene, which `source` names, to a new file `name`;
    /// what to tell. An error is one the name can fix (the file exists, its
    /// folder does not): the name is then edited again, not lost.
    pub fn write(&mut self, source: &SceneSource, name: &str) -> Result<String, String> {
        let Some(json) = self.json.as_ref().filter(|_| !self.edits.is_empty()) else {
            return Ok("no edits to write (m: edit the selected hit's material)".to_owned());
        };
        write(source, json, Path::new(name.trim()))?;
        self.written = true;
        Ok(format!("wrote {}", name.trim()))
    }
}

/// A name for the edited scene beside the original: `whitted-edited.json`.
pub fn default_name(source: &SceneSource) -> String {
    let file = source.file.trim_end_matches(crate::scene::source::BUILT_IN);
    let path = Path::new(if file.is_empty() {
        "whitted.json"
    } else {
        file
    });
    let stem = path
        .file_stem()
        .map_or("scene".into(), |s| s.to_string_lossy());
    path.with_file_name(format!("{stem}-edited.json"))
        .display()
        .to_string()
}

/// The scene file's text (the built-in scene's, for the built-in scene).
fn read_text(source: &SceneSource) -> Result<String, String> {
    if source.file == crate::scene::source::BUILT_IN {
        Ok(crate::scene::loader::WHITTED.to_owned())
    } else {
        crate::scene::loader::read(Path::new(&source.file)).map_err(|e| e.to_string())
    }
}

/// A scene file's JSON without its `objects`, which are read past and never
/// kept: all an edit changes, and all it needs to read again.
pub fn skeleton(text: &str, file: &str) -> Result<Value, String> {
    struct Fields;
    impl<'de> Visitor<'de> for Fields {
        type Value = Map<String, Value>;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("a scene object")
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
            let mut fields = Map::new();
            while let Some(field) = map.next_key::<String>()? {
                if field == "objects" {
                    map.next_value::<IgnoredAny>()?;
                } else {
                    fields.insert(field, map.next_value()?);
                }
            }
            Ok(fields)
        }
    }
    let mut de = serde_json::Deserializer::from_str(text);
    let fields = de
        .deserialize_map(Fields)
        .and_then(|fields| de.end().map(|()| fields))
        .map_err(|e| format!("{file}: {e}"))?;
    Ok(Value::Object(fields))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::loader::{WHITTED, parse, whitted};

    fn whitted_json() -> Value {
        skeleton(WHITTED, "whitted.json").unwrap()
    }

    #[test]
    fn the_skeleton_is_the_file_without_its_objects() {
        let mut whole: Value = serde_json::from_str(WHITTED).unwrap();
        assert!(whole["objects"].as_array().is_some_and(|o| o.len() > 2));
        whole.as_object_mut().unwrap().remove("objects");
        assert_eq!(whitted_json(), whole);
        assert!(
            skeleton("[1]", "x.json")
                .unwrap_err()
                .starts_with("x.json: ")
        );
        assert!(skeleton("{} {", "x.json").is_err());
    }

    #[test]
    fn an_edit_changes_the_material_and_keeps_the_settings() {
        let mut json = whitted_json();
        let mut loaded = whitted();
        loaded.settings.width = 64;
        let scene = apply(
            &mut json,
            Some("glass"),
            "ior = 1.0",
            &loaded,
            "whitted.json",
        )
        .unwrap();
        let glass = scene.materials.iter().find(|m| m.name == "glass").unwrap();
        assert_eq!(glass.ior, 1.0);
        assert_eq!(scene.settings.width, 64);
        assert_eq!(json["materials"]["glass"]["ior"], serde_json::json!(1.0));
        // The same scene as the whole file edited and read again.
        let mut whole: Value = serde_json::from_str(WHITTED).unwrap();
        whole["materials"]["glass"]["ior"] = serde_json::json!(1.0);
        let mut read = parse(&whole.to_string(), "whitted.json").unwrap();
        read.settings.width = 64;
        assert_eq!(scene, read);
    }

    #[test]
    fn bad_edits_say_what_is_wrong_and_change_nothing() {
        let mut json = whitted_json();
        let before = json.clone();
        let loaded = whitted();
        for (typed, want) in [
            ("ior", "type field=value"),
            ("wobble=1", "'wobble' cannot be edited"),
            ("ior=-1", "ior"),
            ("sphere=sideways", "sphere=sideways: "),
            ("ior=abc", "ior=abc: not a number"),
            ("color=red", "color=red: not a color"),
            (
                "reflective=0.5",
                "reflective=0.5: materials.glass: reflective + transparent must be at most 1",
            ),
        ] {
            let e = apply(&mut json, Some("glass"), typed, &loaded, "whitted.json").unwrap_err();
            assert!(e.contains(want), "{typed}: {e}");
            assert!(!e.contains('\n'));
            // The place is the edit's, never a line and column of the file.
            assert!(!e.contains("whitted.json"), "{typed}: {e}");
        }
        assert_eq!(json, before);
        let scene = apply(&mut json, None, "sphere=lecture", &loaded, "whitted.json").unwrap();
        assert_eq!(scene.settings.sphere, crate::methods::SphereMethod::Lecture);
        assert_eq!(
            (&scene.objects, &scene.materials),
            (&loaded.objects, &loaded.materials)
        );
    }

    /// Every method field the edit accepts changes the scene's setting: none
    /// is taken and then dropped.
    #[test]
    fn every_method_field_accepted_changes_the_setting() {
        let loaded = whitted();
        for (typed, number) in [
            ("sphere=lecture", false),
            ("offset=none", false),
            ("weights=fresnel", false),
            ("max_depth=3", true),
            ("cutoff=0.25", true),
        ] {
            let field = typed.split('=').next().unwrap();
            let mut json = whitted_json();
            let scene = apply(&mut json, None, typed, &loaded, "whitted.json").unwrap();
            assert_ne!(scene.settings, loaded.settings, "{typed}");
            assert_eq!(takes_a_number(field), number, "{typed}");
        }
        assert_eq!(METHOD_FIELDS.len(), 5);
    }
}
