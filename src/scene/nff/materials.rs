//! NFF's `f R G B Kd Ks Shine T ior`, the material of the objects that
//! follow, read as the scene file's material (the mapping is in
//! [`crate::scene::nff`]'s header). The SPD repeats an `f` before each group
//! of objects: an `f` equal to one before names the same material, so a
//! converted scene lists each material once.

use std::collections::HashMap;

use glam::DVec3;

use crate::scene::format::MaterialFile;
use crate::scene::limits;
use crate::scene::nff::reader::{Line, Reader};
use crate::scene::scene_error::SceneError;

/// The materials met so far, and the current one.
#[derive(Default)]
pub(super) struct Materials {
    /// Each material by name, in the order first used.
    used: Vec<(String, MaterialFile)>,
    /// The name of the material each `f` met gave, by its eight numbers' bits.
    known: HashMap<[u64; 8], String>,
    /// The current material's name, and whether it transmits.
    current: Option<(String, bool)>,
}

impl Materials {
    /// The current material's name, and whether it transmits; `None` before
    /// the first `f`.
    pub(super) fn current(&self) -> Option<(&str, bool)> {
        self.current.as_ref().map(|(name, t)| (name.as_str(), *t))
    }

    /// Every material by name, in the order first used.
    pub(super) fn used(self) -> Vec<(String, MaterialFile)> {
        self.used
    }
}

impl Reader<'_> {
    /// `f` on `line`: the current material from now on, read and checked
    /// the first time its numbers are met.
    pub(super) fn material(
        &self,
        line: &Line,
        materials: &mut Materials,
    ) -> Result<(), SceneError> {
        let values: [f64; 8] = self.numbers(line)?;
        let key = values.map(f64::to_bits);
        let transmits = values[6] > 0.0;
        let name = match materials.known.get(&key) {
            Some(name) => name.clone(),
            None => {
                let name = format!("f at line {}", line.number);
                let m = self.checked_material(line, values)?;
                materials.used.push((name.clone(), m));
                materials.known.insert(key, name.clone());
                name
            }
        };
        materials.current = Some((name, transmits));
        Ok(())
    }

    /// `f`'s numbers `v`, each within its range, as the scene file's material.
    fn checked_material(&self, line: &Line, v: [f64; 8]) -> Result<MaterialFile, SceneError> {
        let [r, g, b, kd, ks, shine, t, ior] = v;
        let color = self.color(line, 1, DVec3::new(r, g, b))?;
        let at = |k: usize| line.words[k].0;
        let coefficient = |k: usize, name: &str, x: f64, max: f64| {
            if (0.0..=max).contains(&x) {
                Ok(x)
            } else {
                Err(self.error(
                    line.number,
                    at(k),
                    format!(
                        "{name} must be from 0 to {}, got {}",
                        limits::num(max),
                        limits::num(x)
                    ),
                ))
            }
        };
        let max = limits::MAX_COEFFICIENT;
        let kd = coefficient(4, "Kd", kd, max)?;
        let ks = coefficient(5, "Ks", ks, 1.0)?;
        let shine = coefficient(6, "Shine", shine, max)?;
        let t = coefficient(7, "T", t, 1.0)?;
        if ks + t > 1.0 {
            return Err(self.error(
                line.number,
                at(5),
                format!("Ks + T must be at most 1 (a surface passes on no more light than arrives), got {} + {}", limits::num(ks), limits::num(t)),
            ));
        }
        let ior = if t == 0.0 {
            1.0
        } else {
            let (low, high) = limits::IOR;
            if !(low..=high).contains(&ior) {
                return Err(self.error(
                    line.number,
                    at(8),
                    format!("a transmitting material's index of refraction must be from {low} to {high}, got {}", limits::num(ior)),
                ));
            }
            ior
        };
        Ok(material(color, kd, ks, shine, t, ior))
    }
}

/// `f`'s material as raytree's (see [`crate::scene::nff`]): Kd the diffuse
/// and ambient shares, Ks the highlight and the reflection, T the
/// transparency, with the color already made linear and the index checked.
fn material(color: DVec3, kd: f64, ks: f64, shine: f64, t: f64, ior: f64) -> MaterialFile {
    MaterialFile {
        color: Some(color),
        checker: None,
        ambient: Some(kd),
        diffuse: Some(kd),
        specular: Some(ks),
        shininess: Some(shine),
        reflective: Some(ks),
        transparent: Some(t),
        ior: Some(ior),
    }
}
