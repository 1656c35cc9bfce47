//! Reading a learner trace strictly: a regular file of at most
//! [`MAX_BYTES`](crate::course::learner::format::MAX_BYTES), checked before
//! anything is read; JSON whose nesting serde_json bounds (128 levels, so a
//! tree a million deep is refused in one line, with no deep recursion); then
//! each field walked by hand, so that every error names its JSON path
//! (`ray.refracted.hit.t`), unknown keys are refused (a typo is not silently
//! ignored), every number is finite, and the rays are bounded in depth and
//! count. An error is one line naming the file.

use std::path::Path;

use glam::DVec3;
use serde_json::{Map, Value};

use crate::course::learner::format::{
    FORMAT, HIT_KEYS, KINDS, Key, Kind, LearnerHit, LearnerRay, LearnerShadow, LearnerTrace,
    MAX_BYTES, MAX_DEPTH, MAX_RAYS, RAY_KEYS, SHADOW_KEYS, TRACE_KEYS, VERSION,
};
use crate::io::input;
use crate::scene::quote::{printable, quote};

/// Reads the learner trace at `path`; the error is one line naming the file.
pub fn read(path: &Path) -> Result<LearnerTrace, String> {
    let file = path.display();
    let text = input::read_text(path, MAX_BYTES)
        .map_err(|reason| format!("cannot read learner trace {file}: {reason}"))?;
    parse(&text).map_err(|e| format!("{file}:{e}"))
}

/// Parses a learner trace's text. The error is one line to follow the file's
/// name: `L:C: …` for JSON syntax, else ` path: …`.
pub fn parse(text: &str) -> Result<LearnerTrace, String> {
    let Unique(value) = serde_json::from_str(text).map_err(|e| syntax(text, &e))?;
    let mut walk = Walk { rays: 0 };
    walk.trace(&value).map_err(|(path, message)| {
        let path = if path.is_empty() { "(document)" } else { &path };
        format!(" {path}: {}", printable(&message))
    })
}

/// A syntax error with its line and column, in words a learner knows: NaN
/// and Infinity (which Python's `json.dumps` writes) are named as such.
fn syntax(text: &str, e: &serde_json::Error) -> String {
    let message = e.to_string();
    let message = message
        .rfind(" at line ")
        .map_or(message.as_str(), |i| &message[..i]);
    let at = offset_of(text, e.line(), e.column());
    let rest = at.map_or("", |a| text[a..].trim_start_matches('-'));
    let message = if ["NaN", "Infinity", "nan", "inf"]
        .iter()
        .any(|w| rest.starts_with(w))
    {
        "NaN or Infinity is not a JSON number (every number must be finite; a NaN direction often means total internal reflection was not handled, lessons/10-refraction)".to_owned()
    } else if message.contains("recursion limit") {
        "nested too deep for a learner trace (at most 128 levels of JSON)".to_owned()
    } else if e.is_eof() {
        format!("the file ends early: {message}")
    } else {
        message.to_owned()
    };
    // Columns count from 1, as the scene reader's do (serde gives 0 at the
    // start of a line the file ends on).
    let kind = if message.starts_with(TWICE) {
        ""
    } else {
        "not JSON: "
    };
    format!(
        "{}:{}: {kind}{}",
        e.line(),
        e.column().max(1),
        printable(&message)
    )
}

/// How a key given twice in one object begins its error.
const TWICE: &str = "the key ";

/// A JSON value as serde_json reads it, except that a key given twice in one
/// object is refused (serde_json keeps the last): a learner's writer that
/// emits `"t"` twice has a bug the check must not hide by picking one.
struct Unique(Value);

impl<'de> serde::Deserialize<'de> for Unique {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(UniqueVisitor).map(Unique)
    }
}

struct UniqueVisitor;

impl<'de> serde::de::Visitor<'de> for UniqueVisitor {
    type Value = Value;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E>(self, b: bool) -> Result<Value, E> {
        Ok(Value::Bool(b))
    }
    fn visit_i64<E>(self, n: i64) -> Result<Value, E> {
        Ok(Value::from(n))
    }
    fn visit_u64<E>(self, n: u64) -> Result<Value, E> {
        Ok(Value::from(n))
    }
    fn visit_f64<E>(self, n: f64) -> Result<Value, E> {
        Ok(Value::from(n))
    }
    fn visit_str<E>(self, s: &str) -> Result<Value, E> {
        Ok(Value::from(s))
    }
    fn visit_string<E>(self, s: String) -> Result<Value, E> {
        Ok(Value::String(s))
    }
    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut out = Vec::new();
        while let Some(Unique(v)) = seq.next_element()? {
            out.push(v);
        }
        Ok(Value::Array(out))
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut out = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            if out.contains_key(&key) {
                return Err(serde::de::Error::custom(format_args!(
                    "{TWICE}{} is given twice in one object",
                    quote(&key, "`")
                )));
            }
            let Unique(v) = map.next_value()?;
            out.insert(key, v);
        }
        Ok(Value::Object(out))
    }
}

/// The byte offset of 1-based line `line`, column `column` (serde_json's
/// column is the byte just read, so the offending value starts one before).
fn offset_of(text: &str, line: usize, column: usize) -> Option<usize> {
    let start: usize = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1))
        .map(str::len)
        .sum();
    let at = start + column.saturating_sub(1);
    text.get(at..).map(|_| at)
}

/// A field's error: its path and what is wrong.
type Failure = (String, String);

struct Walk {
    rays: usize,
}

fn at(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_owned()
    } else {
        format!("{path}.{key}")
    }
}

fn fail<T>(path: &str, message: impl Into<String>) -> Result<T, Failure> {
    Err((path.to_owned(), message.into()))
}

fn kind_of(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "true or false",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// `v` as an object whose keys are all in `keys`, with the required ones there.
fn object<'v>(v: &'v Value, path: &str, keys: &[Key]) -> Result<&'v Map<String, Value>, Failure> {
    let Value::Object(m) = v else {
        return fail(path, format!("expected an object, found {}", kind_of(v)));
    };
    if let Some(unknown) = m.keys().find(|k| !keys.iter().any(|(name, _)| name == k)) {
        let known: Vec<&str> = keys.iter().map(|(k, _)| *k).collect();
        return fail(
            &at(path, &quote(unknown, "")),
            format!("unknown field (known: {})", known.join(", ")),
        );
    }
    if let Some((missing, _)) = keys.iter().find(|(k, req)| *req && !m.contains_key(*k)) {
        return fail(&at(path, missing), "missing (it is required)");
    }
    Ok(m)
}

fn number(v: &Value, path: &str) -> Result<f64, Failure> {
    match v.as_f64() {
        Some(x) if x.is_finite() => Ok(x),
        _ => fail(
            path,
            format!("expected a finite number, found {}", kind_of(v)),
        ),
    }
}

fn vector(v: &Value, path: &str) -> Result<DVec3, Failure> {
    match v {
        Value::Array(a) if a.len() == 3 => Ok(DVec3::new(
            number(&a[0], &format!("{path}[0]"))?,
            number(&a[1], &format!("{path}[1]"))?,
            number(&a[2], &format!("{path}[2]"))?,
        )),
        Value::Array(a) => fail(
            path,
            format!("expected [x, y, z], found {} numbers", a.len()),
        ),
        _ => fail(path, format!("expected [x, y, z], found {}", kind_of(v))),
    }
}

fn nonzero(v: &Value, path: &str) -> Result<DVec3, Failure> {
    let d = vector(v, path)?;
    if !(d.length_squared() > 0.0 && d.length_squared().is_finite()) {
        return fail(path, "a direction must have a nonzero, finite length");
    }
    Ok(d)
}

fn boolean(v: &Value, path: &str) -> Result<bool, Failure> {
    v.as_bool().map_or_else(
        || {
            fail(
                path,
                format!("expected true or false, found {}", kind_of(v)),
            )
        },
        Ok,
    )
}

fn string(v: &Value, path: &str) -> Result<String, Failure> {
    v.as_str().map_or_else(
        || fail(path, format!("expected a string, found {}", kind_of(v))),
        |s| Ok(s.to_owned()),
    )
}

/// A number (every channel) or `[r, g, b]`, each at least 0.
fn coefficient(v: &Value, path: &str) -> Result<DVec3, Failure> {
    let k = if v.is_number() {
        DVec3::splat(number(v, path)?)
    } else {
        vector(v, path)?
    };
    if k.min_element() < 0.0 {
        return fail(path, "a coefficient is at least 0");
    }
    Ok(k)
}

/// A color: `[r, g, b]`, linear. A negative channel is accepted: it is a
/// mistake the check diagnoses (a term not clamped at 0), not bad input.
fn color(v: &Value, path: &str) -> Result<DVec3, Failure> {
    vector(v, path)
}

fn optional<T>(
    m: &Map<String, Value>,
    key: &str,
    path: &str,
    read: impl FnOnce(&Value, &str) -> Result<T, Failure>,
) -> Result<Option<T>, Failure> {
    m.get(key).map(|v| read(v, &at(path, key))).transpose()
}

/// An optional field that may be null: `None` absent, `Some(None)` null.
fn nullable<T>(
    m: &Map<String, Value>,
    key: &str,
    path: &str,
    read: impl FnOnce(&Value, &str) -> Result<T, Failure>,
) -> Result<Option<Option<T>>, Failure> {
    optional(m, key, path, |v, p| {
        if v.is_null() {
            Ok(None)
        } else {
            read(v, p).map(Some)
        }
    })
}

impl Walk {
    fn trace(&mut self, v: &Value) -> Result<LearnerTrace, Failure> {
        let m = object(v, "", TRACE_KEYS)?;
        let format = string(&m["format"], "format")?;
        if format != FORMAT {
            let found = quote(&format, "\"");
            return fail("format", format!("expected \"{FORMAT}\", found {found}"));
        }
        if m["version"].as_u64() != Some(VERSION) {
            return fail(
                "version",
                format!(
                    "this raytree reads version {VERSION}, found {}",
                    m["version"]
                ),
            );
        }
        let pixel = optional(m, "pixel", "", |v, p| {
            match v.as_array().map(Vec::as_slice) {
                Some([x, y]) => match (x.as_u64(), y.as_u64()) {
                    (Some(x), Some(y)) if x <= u64::from(u32::MAX) && y <= u64::from(u32::MAX) => {
                        Ok([x as u32, y as u32])
                    }
                    _ => fail(p, "expected [x, y], two whole numbers ≥ 0"),
                },
                _ => fail(p, format!("expected [x, y], found {}", kind_of(v))),
            }
        })?;
        let ray = self.ray(&m["ray"], "ray", 1)?;
        if ray.kind != Kind::Primary {
            return fail(
                "ray.kind",
                "the document's ray is the primary ray: \"primary\"",
            );
        }
        Ok(LearnerTrace {
            scene: optional(m, "scene", "", string)?,
            pixel,
            ray,
        })
    }

    fn ray(&mut self, v: &Value, path: &str, depth: u32) -> Result<LearnerRay, Failure> {
        if depth > MAX_DEPTH {
            return fail(
                path,
                format!("deeper than the {MAX_DEPTH} rays a learner trace holds"),
            );
        }
        self.rays += 1;
        if self.rays > MAX_RAYS {
            return fail(
                path,
                format!("more than the {MAX_RAYS} rays a learner trace holds"),
            );
        }
        let m = object(v, path, RAY_KEYS)?;
        let kind_path = at(path, "kind");
        let name = string(&m["kind"], &kind_path)?;
        let Some(kind) = Kind::named(&name) else {
            return fail(
                &kind_path,
                format!(
                    "expected one of {}, found {}",
                    KINDS.join(", "),
                    quote(&name, "\"")
                ),
            );
        };
        let mut ray = LearnerRay::new(
            kind,
            vector(&m["origin"], &at(path, "origin"))?,
            nonzero(&m["direction"], &at(path, "direction"))?,
        );
        ray.hit = nullable(m, "hit", path, hit)?;
        ray.shadows = optional(m, "shadows", path, |v, p| match v {
            Value::Array(a) => a
                .iter()
                .enumerate()
                .map(|(i, s)| shadow(s, &format!("{p}[{i}]")))
                .collect(),
            _ => fail(p, format!("expected an array, found {}", kind_of(v))),
        })?;
        ray.local = optional(m, "local", path, color)?;
        ray.k_rfl = optional(m, "k_rfl", path, coefficient)?;
        ray.k_rfa = optional(m, "k_rfa", path, coefficient)?;
        for (key, want) in [
            ("reflected", Kind::Reflected),
            ("refracted", Kind::Refracted),
        ] {
            let child = nullable(m, key, path, |v, p| {
                let child = self.ray(v, p, depth + 1)?;
                if child.kind != want {
                    return fail(
                        &at(p, "kind"),
                        format!("a {key} child is of kind \"{key}\""),
                    );
                }
                Ok(Box::new(child))
            })?;
            match key {
                "reflected" => ray.reflected = child,
                _ => ray.refracted = child,
            }
        }
        ray.tir = optional(m, "tir", path, boolean)?;
        ray.color = optional(m, "color", path, color)?;
        Ok(ray)
    }
}

fn hit(v: &Value, path: &str) -> Result<LearnerHit, Failure> {
    let m = object(v, path, HIT_KEYS)?;
    Ok(LearnerHit {
        object: optional(m, "object", path, string)?,
        t: optional(m, "t", path, number)?,
        point: optional(m, "point", path, vector)?,
        normal: optional(m, "normal", path, nonzero)?,
        entering: optional(m, "entering", path, boolean)?,
    })
}

fn shadow(v: &Value, path: &str) -> Result<LearnerShadow, Failure> {
    let m = object(v, path, SHADOW_KEYS)?;
    let transmitted = optional(m, "transmitted", path, |v, p| {
        let x = number(v, p)?;
        if !(0.0..=1.0).contains(&x) {
            return fail(p, "a share from 0 to 1");
        }
        Ok(x)
    })?;
    Ok(LearnerShadow {
        light: string(&m["light"], &at(path, "light"))?,
        blocked: boolean(&m["blocked"], &at(path, "blocked"))?,
        by: nullable(m, "by", path, string)?,
        transmitted,
        origin: optional(m, "origin", path, vector)?,
        direction: optional(m, "direction", path, nonzero)?,
    })
}
