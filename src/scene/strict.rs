//! The two holes serde leaves in a strict format, closed: a derived struct
//! also reads a JSON array of its fields in order (`"sphere": [[0, 0, 0], 1]`,
//! a whole scene as `[]`), and a map keeps the last of two equal keys. Every
//! struct of the scene file is read through these helpers (`deserialize_with`),
//! so it must be a JSON object, and a name given twice is an error.

use std::collections::BTreeMap;
use std::fmt;
use std::marker::PhantomData;

use serde::de::{DeserializeSeed, Deserializer, Error, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, forward_to_deserialize_any};

pub use crate::scene::quote::printable;
use crate::scene::quote::quote;

/// serde's message with the Rust type it expected (`f64`, `u32`, `struct
/// SceneFile`, `a sequence of 3 f64 values`) said in the format's words (`a
/// number`, `a whole number ≥ 0`, `a scene object`, `three numbers [x, y,
/// z]`). Only what follows the last "expected " is a type: a key or a value
/// the user wrote, quoted before it, is left as written.
pub fn in_users_words(message: &str) -> String {
    const EXPECTED: &str = "expected ";
    let Some(at) = message.rfind(EXPECTED) else {
        return message.to_owned();
    };
    let (head, tail) = message.split_at(at + EXPECTED.len());
    let number = |t: &str| match t {
        "f32" | "f64" => Some("a number"),
        "u8" | "u16" | "u32" | "u64" | "u128" | "usize" => Some("a whole number ≥ 0"),
        "i8" | "i16" | "i32" | "i64" | "i128" | "isize" => Some("a whole number"),
        _ => None,
    };
    let words = if let Some(words) = number(tail) {
        words.to_owned()
    } else if let Some(n) = tail
        .strip_prefix("a sequence of ")
        .and_then(|t| t.split_once(' '))
        .and_then(|(n, t)| number(t.strip_suffix(" values")?).map(|_| n))
    {
        match n {
            "3" => "three numbers [x, y, z]".to_owned(),
            n => format!("a list of {n} numbers"),
        }
    } else if let Some(name) = tail
        .strip_prefix("struct ")
        .or_else(|| tail.strip_prefix("tuple struct "))
    {
        // serde adds " with N elements" when an array stood for the struct.
        match name.split(' ').next().unwrap_or(name) {
            "SceneFile" | "Root" => "a scene object",
            "TraceDocument" => "a trace object",
            _ => "an object {…}",
        }
        .to_owned()
    } else if tail.starts_with("enum ") {
        "one of the names the format lists".to_owned()
    } else {
        return message.to_owned();
    };
    format!("{head}{words}")
}

/// Reads `T` (a struct) from a JSON object only.
pub fn object<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D) -> Result<T, D::Error> {
    T::deserialize(ObjectOnly(d))
}

/// As [`object`], for an optional field (`#[serde(default)]` covers its absence).
pub fn some_object<'de, D: Deserializer<'de>, T: Deserialize<'de>>(
    d: D,
) -> Result<Option<T>, D::Error> {
    object(d).map(Some)
}

/// A JSON array of objects.
pub fn objects<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D) -> Result<Vec<T>, D::Error> {
    d.deserialize_seq(Objects(PhantomData))
}

/// A JSON object of names to objects, each name once.
pub fn named_objects<'de, D: Deserializer<'de>, T: Deserialize<'de>>(
    d: D,
) -> Result<BTreeMap<String, T>, D::Error> {
    d.deserialize_map(Named(PhantomData))
}

/// Passes everything through, but asks for a map where a struct is wanted:
/// serde_json then refuses an array with "invalid type: sequence".
struct ObjectOnly<D>(D);

impl<'de, D: Deserializer<'de>> Deserializer<'de> for ObjectOnly<D> {
    type Error = D::Error;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, D::Error> {
        self.0.deserialize_any(visitor)
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, D::Error> {
        self.0.deserialize_map(visitor)
    }

    forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf option unit unit_struct newtype_struct seq tuple
        tuple_struct map enum identifier ignored_any
    }
}

/// One element or value read as an object.
struct AsObject<T>(PhantomData<T>);

impl<'de, T: Deserialize<'de>> DeserializeSeed<'de> for AsObject<T> {
    type Value = T;

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<T, D::Error> {
        object(d)
    }
}

struct Objects<T>(PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for Objects<T> {
    type Value = Vec<T>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an array of objects")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<T>, A::Error> {
        let mut out = Vec::new();
        while let Some(item) = seq.next_element_seed(AsObject(PhantomData))? {
            out.push(item);
        }
        Ok(out)
    }
}

struct Named<T>(PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for Named<T> {
    type Value = BTreeMap<String, T>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an object of names to objects")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        let mut out = BTreeMap::new();
        while let Some(name) = map.next_key::<String>()? {
            if out.contains_key(&name) {
                return Err(A::Error::custom(format_args!(
                    "the name {} is given twice",
                    quote(&name, "`")
                )));
            }
            let value = map.next_value_seed(AsObject(PhantomData))?;
            out.insert(name, value);
        }
        Ok(out)
    }
}
