//! Which scene a trace was made from: the file's name and a hash of its text,
//! so a saved trace can find its scene again and tell whether it changed.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::scene::Scene;
use crate::scene::loader::{self, SceneError, WHITTED};

/// The name a trace gives the built-in scene.
pub const BUILT_IN: &str = "whitted.json (built in)";

/// The scene a trace came from.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSource {
    /// The scene file as given (`whitted.json (built in)` for the built-in scene).
    pub file: String,
    /// `fnv1a64:` and the 64-bit FNV-1a hash of the file's bytes, in hex.
    pub hash: String,
}

impl SceneSource {
    /// Names a scene file and hashes its text.
    pub fn new(file: &str, text: &str) -> Self {
        Self {
            file: file.to_owned(),
            hash: format!("fnv1a64:{:016x}", fnv1a64(text.as_bytes())),
        }
    }
}

/// 64-bit FNV-1a (Fowler, Noll, Vo): a small, stable content hash.
fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// Reads the scene file at `path`, or the built-in Whitted scene without one,
/// and names it for traces.
pub fn load(path: Option<&Path>) -> Result<(Scene, SceneSource), SceneError> {
    match path {
        Some(path) => {
            let text = loader::read(path)?;
            let name = path.display().to_string();
            Ok((
                loader::parse_file(&text, &name)?,
                SceneSource::new(&name, &text),
            ))
        }
        None => Ok((loader::whitted(), SceneSource::new(BUILT_IN, WHITTED))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a64_matches_the_reference_values() {
        // Test vectors from the FNV reference (isthe.com/chongo/tech/comp/fnv).
        assert_eq!(fnv1a64(b""), 0xcbf29ce484222325);
        assert_eq!(fnv1a64(b"a"), 0xaf63dc4c8601ec8c);
        assert_eq!(fnv1a64(b"foobar"), 0x85944171f73967e8);
    }
}
