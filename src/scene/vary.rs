//! One numeric field of a scene file, varied: what a filmstrip (`raytree
//! strip --vary max_depth=1..5`) renders a frame of per value. The field is
//! named by its path in the scene file (`materials.glass.ior`,
//! `render.max_depth`, `lights[0].position[1]`; a render setting may drop its
//! `render.`), set in the file's JSON, and the whole scene is read again by
//! [`crate::scene::loader`], so a varied value is checked exactly as the same
//! value written in the file would be. The frames of a strip share one size:
//! the scene's shape, 320 pixels wide unless a width or a height is given.

use serde_json::Value as Json;

use crate::scene::Scene;
use crate::scene::loader::{self, SceneError};
use crate::scene::overrides::Overrides;
use crate::scene::settings::RenderSettings;

/// The most frames a filmstrip takes.
pub const MAX_VALUES: usize = 12;

/// Frames are this wide unless a width or a height is given.
pub const FRAME_WIDTH: u32 = 320;

/// A field and the values it takes in turn.
#[derive(Clone, Debug, PartialEq)]
pub struct Variation {
    /// The field's path in the scene file, as given.
    pub path: String,
    /// Its values, in order.
    pub values: Vec<f64>,
}

/// Reads `PATH=A..B` (whole numbers from A to B) or `PATH=V1,V2,…`.
pub fn parse(spec: &str) -> Result<Variation, String> {
    let (path, values) = spec
        .split_once('=')
        .ok_or("expected PATH=VALUES, e.g. max_depth=1..5 or materials.glass.ior=1.0,1.33,1.5")?;
    let path = path.trim();
    if path.is_empty() {
        return Err("the field's path is empty".into());
    }
    let number = |v: &str| {
        v.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| format!("'{}' is not a finite number", v.trim()))
    };
    let values: Vec<f64> = match values.split_once("..") {
        Some((a, b)) => {
            let (a, b) = (number(a)?, number(b)?);
            if a.fract() != 0.0 || b.fract() != 0.0 || b < a {
                return Err(format!(
                    "a range A..B counts whole numbers up from A to B, got {a}..{b}; list other values with commas"
                ));
            }
            if b - a >= MAX_VALUES as f64 {
                return Err(format!("{a}..{b} is more than {MAX_VALUES} frames"));
            }
            (a as i64..=b as i64).map(|v| v as f64).collect()
        }
        None => values.split(',').map(number).collect::<Result<_, _>>()?,
    };
    if values.len() > MAX_VALUES {
        return Err(format!(
            "{} values: a strip has at most {MAX_VALUES}",
            values.len()
        ));
    }
    Ok(Variation {
        path: path.to_owned(),
        values,
    })
}

impl Variation {
    /// The path as a word for a file name: `lights[0].position[1]` →
    /// `lights-0-position-1`.
    pub fn file_word(&self) -> String {
        self.path
            .split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .filter(|w| !w.is_empty())
            .collect::<Vec<_>>()
            .join("-")
    }

    /// Refuses a field the frames cannot differ in (their size) and one the
    /// settings given (`overrides`, the command line's) already set.
    pub fn check(&self, overrides: &Overrides) -> Result<(), String> {
        let path = &self.path;
        if ["width", "height", "render.width", "render.height"].contains(&path.as_str()) {
            return Err(format!(
                "--vary {path}: the frames of a strip share one size; give --width and --height instead"
            ));
        }
        let setting = path.strip_prefix("render.").unwrap_or(path);
        let given =
            serde_json::to_value(overrides).map_err(|e| format!("the settings given: {e}"))?;
        if given.get(setting).is_some() {
            return Err(format!(
                "--vary {path} and --{} both set {setting}: give one",
                setting.replace('_', "-")
            ));
        }
        Ok(())
    }
}

/// The frames' scenes: the scene of `text` (file `file`, whose own settings
/// are `own`) once per value of `variation`, with `overrides` applied and
/// every frame one size ([`frame_size`]). Errors are one line, as
/// [`Variation::check`] and [`scene_with`] give them.
pub fn frames(
    text: &str,
    file: &str,
    own: &RenderSettings,
    overrides: &Overrides,
    variation: &Variation,
) -> Result<Vec<Scene>, String> {
    variation.check(overrides)?;
    let overrides = frame_size(own, overrides);
    let path = &variation.path;
    variation
        .values
        .iter()
        .map(|&v| scene_with(text, file, &overrides, path, v))
        .collect()
}

/// `overrides` with both sides of the frames given, keeping the scene's shape
/// (`own`): one side given, the other follows; none, [`FRAME_WIDTH`] wide.
pub fn frame_size(own: &RenderSettings, overrides: &Overrides) -> Overrides {
    let mut out = *overrides;
    let aspect = f64::from(own.height) / f64::from(own.width);
    let side = |v: f64| v.round().max(1.0) as u32;
    match (out.width, out.height) {
        (None, None) => {
            out.width = Some(FRAME_WIDTH);
            out.height = Some(side(f64::from(FRAME_WIDTH) * aspect));
        }
        (Some(w), None) => out.height = Some(side(f64::from(w) * aspect)),
        (None, Some(h)) => out.width = Some(side(f64::from(h) / aspect)),
        (Some(_), Some(_)) => {}
    }
    out
}

/// The scene of `text` (file `file`) with `overrides` applied to its render
/// settings and then the field at `path` set to `value`. Errors are one line
/// naming the field and the value.
pub fn scene_with(
    text: &str,
    file: &str,
    overrides: &Overrides,
    path: &str,
    value: f64,
) -> Result<Scene, String> {
    let fail = |m: String| format!("--vary {path}={value}: {m}");
    let mut json: Json = serde_json::from_str(text).map_err(|e| fail(e.to_string()))?;
    let render = object_at(&mut json, "render")?;
    if let Json::Object(given) = serde_json::to_value(overrides).map_err(|e| fail(e.to_string()))? {
        render.extend(given);
    }
    let segments = segments(&full_path(path)).map_err(fail)?;
    if let Some(Segment::Field(first)) = segments.first() {
        unknown_first_step(first, &json).map_err(fail)?;
    }
    set(&mut json, &segments, value).map_err(fail)?;
    let text = serde_json::to_string(&json).map_err(|e| fail(e.to_string()))?;
    loader::parse(&text, file).map_err(|e| {
        fail(match e {
            // The line and column are of the rewritten text, not the file: leave them out.
            SceneError::Syntax { message, .. } => message,
            SceneError::Invalid { field, message, .. } => format!("{field}: {message}"),
            other => other.to_string(),
        })
    })
}

/// The path with `render.` put before a render setting's bare name.
fn full_path(path: &str) -> String {
    let settings = serde_json::to_value(RenderSettings::default()).unwrap_or_default();
    let first = path.split(['.', '[']).next().unwrap_or("");
    match settings.get(first) {
        Some(_) => format!("render.{path}"),
        None => path.to_owned(),
    }
}

/// Refuses a path whose first step is neither a render setting nor a field
/// the scene file has (the scene's top level holds no number a file may
/// leave out), offering both lists, or the name one slip away from it: a
/// learner who mistypes `max_depth` should not be told only the file's keys.
fn unknown_first_step(first: &str, json: &Json) -> Result<(), String> {
    let top: Vec<String> = json
        .as_object()
        .map_or_else(Vec::new, |o| o.keys().cloned().collect());
    if first == "render" || top.iter().any(|k| k == first) {
        return Ok(());
    }
    let settings = serde_json::to_value(RenderSettings::default()).unwrap_or_default();
    let numeric: Vec<String> = settings
        .as_object()
        .map(|o| {
            (o.iter()
                .filter(|(_, v)| v.is_number())
                .map(|(k, _)| k.clone()))
            .collect()
        })
        .unwrap_or_default();
    let near = (numeric.iter().chain(&top))
        .map(|k| (edits(first, k), k))
        .filter(|&(d, k)| d <= 2 && d < k.chars().count())
        .min_by_key(|&(d, _)| d);
    Err(match near {
        Some((_, k)) => format!("no render setting or scene field '{first}': did you mean {k}?"),
        None => format!(
            "no render setting or scene field '{first}': the settings are {}; the scene's fields are {}",
            numeric.join(", "),
            top.join(", ")
        ),
    })
}

/// Levenshtein distance: the fewest inserted, deleted or replaced characters
/// that turn `a` into `b`.
fn edits(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let replaced = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = replaced.min(row[j] + 1).min(diagonal + 1);
        }
    }
    row[b.len()]
}

/// A step along a path: a field, or an index into a list.
#[derive(Clone, Debug, PartialEq)]
enum Segment {
    Field(String),
    Index(usize),
}

/// `a.b[2].c` as its steps.
fn segments(path: &str) -> Result<Vec<Segment>, String> {
    let mut out = Vec::new();
    for part in path.split('.') {
        let (name, mut rest) = part.split_once('[').map_or((part, ""), |(n, r)| (n, r));
        if name.is_empty() && rest.is_empty() {
            return Err(format!("'{path}' has an empty step"));
        }
        if !name.is_empty() {
            out.push(Segment::Field(name.to_owned()));
        }
        while !rest.is_empty() {
            let (index, after) = rest
                .split_once(']')
                .ok_or(format!("'{path}': a [ is not closed"))?;
            let index = index
                .parse()
                .map_err(|_| format!("'{path}': [{index}] is not an index"))?;
            out.push(Segment::Index(index));
            rest = after.strip_prefix('[').unwrap_or(after);
            if !after.is_empty() && !after.starts_with('[') {
                return Err(format!("'{path}': expected . or [ after ]"));
            }
        }
    }
    Ok(out)
}

/// The object at `key` of the scene's top level, made if missing.
fn object_at<'a>(
    json: &'a mut Json,
    key: &str,
) -> Result<&'a mut serde_json::Map<String, Json>, String> {
    let top = json
        .as_object_mut()
        .ok_or("the scene is not a JSON object")?;
    top.entry(key)
        .or_insert_with(|| Json::Object(Default::default()))
        .as_object_mut()
        .ok_or_else(|| format!("'{key}' is not an object"))
}

/// Sets the number at `path`. Every step but the last must exist (the scene
/// has the material, the light, the object); the last may be a field the
/// file leaves at its default, which the loader then checks by name.
fn set(json: &mut Json, path: &[Segment], value: f64) -> Result<(), String> {
    let Some((last, steps)) = path.split_last() else {
        return Err("the path is empty".into());
    };
    let mut here = json;
    let mut walked = String::new();
    for step in steps {
        here = match step {
            Segment::Field(f) => {
                let known = keys(here);
                let next = here.get_mut(f.as_str());
                walked = join(&walked, step);
                next.ok_or_else(|| format!("the scene has no '{walked}' ({known})"))?
            }
            Segment::Index(i) => {
                let len = here.as_array().map_or(0, Vec::len);
                walked = join(&walked, step);
                here.get_mut(*i)
                    .ok_or_else(|| format!("the scene has no '{walked}' (the list has {len})"))?
            }
        };
    }
    let number = if value.fract() == 0.0 && value.abs() < 9e15 {
        Json::from(value as i64)
    } else {
        Json::from(value)
    };
    let target = match last {
        Segment::Field(f) => here
            .as_object_mut()
            .map(|o| o.entry(f.as_str()).or_insert(Json::Null)),
        Segment::Index(i) => here.get_mut(*i),
    };
    let walked = join(&walked, last);
    match target {
        Some(t) if t.is_null() || t.is_number() => {
            *t = number;
            Ok(())
        }
        Some(_) => Err(format!("'{walked}' is not a number")),
        None => Err(format!("the scene has no '{walked}'")),
    }
}

/// The path walked so far, one step longer.
fn join(walked: &str, step: &Segment) -> String {
    match step {
        Segment::Field(f) if walked.is_empty() => f.clone(),
        Segment::Field(f) => format!("{walked}.{f}"),
        Segment::Index(i) => format!("{walked}[{i}]"),
    }
}

/// What an object holds, for an error message.
fn keys(json: &Json) -> String {
    match json.as_object() {
        Some(o) if o.is_empty() => "it is empty".into(),
        Some(o) => format!(
            "it has {}",
            o.keys().cloned().collect::<Vec<_>>().join(", ")
        ),
        None => "it is not an object".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::loader::WHITTED;

    fn with(path: &str, value: f64) -> Result<Scene, String> {
        scene_with(WHITTED, "whitted.json", &Overrides::default(), path, value)
    }

    #[test]
    fn ranges_and_lists_read_as_values() {
        assert_eq!(
            parse("max_depth=1..5").unwrap().values,
            [1.0, 2.0, 3.0, 4.0, 5.0]
        );
        let v = parse("materials.glass.ior=1.0, 1.33,1.5").unwrap();
        assert_eq!(
            (v.path.as_str(), v.values),
            ("materials.glass.ior", vec![1.0, 1.33, 1.5])
        );
        assert!(
            parse("max_depth=1.5..3")
                .unwrap_err()
                .contains("whole numbers")
        );
        assert!(
            parse("max_depth=1..40")
                .unwrap_err()
                .contains("more than 12")
        );
        assert!(parse("max_depth").is_err());
        assert!(
            parse("ior=a,b")
                .unwrap_err()
                .contains("'a' is not a finite number")
        );
    }

    #[test]
    fn a_varied_field_reaches_the_scene() {
        assert_eq!(with("max_depth", 3.0).unwrap().settings.max_depth, 3);
        let glass = |s: &Scene| s.materials.iter().find(|m| m.name == "glass").unwrap().ior;
        assert_eq!(glass(&with("materials.glass.ior", 1.33).unwrap()), 1.33);
        // A field the file leaves at its default can be varied too.
        let s = with("materials.air.shininess", 7.0).unwrap();
        assert_eq!(
            s.materials
                .iter()
                .find(|m| m.name == "air")
                .unwrap()
                .shininess,
            7.0
        );
        assert_eq!(
            with("lights[1].position[0]", 2.0).unwrap().lights[1]
                .position
                .x,
            2.0
        );
        // The command line's settings apply, and the varied one wins.
        let o = Overrides {
            width: Some(40),
            max_depth: Some(7),
            ..Overrides::default()
        };
        let s = scene_with(WHITTED, "w.json", &o, "render.max_depth", 2.0).unwrap();
        assert_eq!((s.settings.width, s.settings.max_depth), (40, 2));
    }

    #[test]
    fn frames_share_one_size_in_the_scene_s_shape() {
        let own = loader::parse(WHITTED, "whitted.json").unwrap().settings;
        let v = parse("max_depth=1..3").unwrap();
        let size = |o: &Overrides| {
            let scenes = frames(WHITTED, "whitted.json", &own, o, &v).unwrap();
            assert_eq!(scenes.len(), 3);
            let sizes: Vec<(u32, u32)> = scenes
                .iter()
                .map(|s| (s.settings.width, s.settings.height))
                .collect();
            assert!(sizes.iter().all(|&s| s == sizes[0]), "{sizes:?}");
            let depths: Vec<u32> = scenes.iter().map(|s| s.settings.max_depth).collect();
            assert_eq!(depths, [1, 2, 3]);
            (scenes[0].settings.width, scenes[0].settings.height)
        };
        let aspect =
            |w: u32| (f64::from(w) * f64::from(own.height) / f64::from(own.width)).round() as u32;
        assert_eq!(
            size(&Overrides::default()),
            (FRAME_WIDTH, aspect(FRAME_WIDTH))
        );
        let given = |width, height| Overrides {
            width,
            height,
            ..Overrides::default()
        };
        assert_eq!(size(&given(Some(64), None)), (64, aspect(64)));
        assert_eq!(size(&given(Some(64), Some(10))), (64, 10));
        let (w, h) = size(&given(None, Some(48)));
        assert_eq!((aspect(w).abs_diff(48) <= 1, h), (true, 48));
    }

    #[test]
    fn a_strip_varies_neither_its_size_nor_a_setting_given() {
        let own = RenderSettings::default();
        let refused = |spec: &str, o: &Overrides| {
            frames(WHITTED, "whitted.json", &own, o, &parse(spec).unwrap()).unwrap_err()
        };
        assert_eq!(
            refused("render.width=64,128", &Overrides::default()),
            "--vary render.width: the frames of a strip share one size; give --width and --height instead"
        );
        let o = Overrides {
            max_depth: Some(3),
            ..Overrides::default()
        };
        assert_eq!(
            refused("render.max_depth=1..2", &o),
            "--vary render.max_depth and --max-depth both set max_depth: give one"
        );
        assert_eq!(
            parse("lights[0].position[1]=1,2").unwrap().file_word(),
            "lights-0-position-1"
        );
    }

    #[test]
    fn a_mistyped_field_is_offered_the_settings_too() {
        let e = with("max_dept", 2.0).unwrap_err();
        assert!(
            e.ends_with("no render setting or scene field 'max_dept': did you mean max_depth?"),
            "{e}"
        );
        let e = with("glow", 2.0).unwrap_err();
        assert!(
            e.contains("the settings are ") && e.contains("max_depth") && e.contains("spp"),
            "{e}"
        );
        assert!(
            e.contains("the scene's fields are ") && e.contains("materials"),
            "{e}"
        );
        assert_eq!(
            (
                edits("kitten", "sitting"),
                edits("", "ab"),
                edits("ab", "ab")
            ),
            (3, 2, 0)
        );
    }

    #[test]
    fn a_missing_field_or_a_bad_value_is_one_line() {
        let e = with("materials.steel.ior", 1.5).unwrap_err();
        assert_eq!(
            e,
            "--vary materials.steel.ior=1.5: the scene has no 'materials.steel' (it has air, checker, glass, mirror)"
        );
        let e = with("max_depth", 0.0).unwrap_err();
        assert_eq!(
            e,
            "--vary max_depth=0: render.max_depth: must be 1 to 1000, got 0"
        );
        assert!(
            with("materials.glass.ior", -1.0).unwrap_err().contains(
                "materials.glass.ior: a refractive index must be from 0.01 to 100, got -1"
            )
        );
        assert!(
            with("materials.glass.iior", 1.0)
                .unwrap_err()
                .contains("unknown field `iior`")
        );
        assert!(with("max_depth", 2.5).unwrap_err().contains("max_depth"));
        assert!(
            with("sphere", 1.0)
                .unwrap_err()
                .starts_with("--vary sphere=1: render.sphere: ")
        );
        assert!(
            with("materials.glass", 1.0)
                .unwrap_err()
                .contains("'materials.glass' is not a number")
        );
        assert!(
            with("lights[5].color", 1.0)
                .unwrap_err()
                .contains("the list has 2")
        );
    }
}
