//! NFF, the Neutral File Format in which Eric Haines's Standard Procedural
//! Databases (1987) write their scenes, read into raytree's own scene JSON,
//! which the JSON loader then reads as any scene file. So `raytree render
//! balls.nff` and `raytree convert balls.nff -o balls.json` then `raytree
//! render balls.json` see the very same scene: one reader of scenes, and a
//! learner can open the converted file, read it and edit it.
//!
//! The format (the SPD's `NFF.txt`, summarised in `scenes/README.md`) is a
//! list of entities, each a keyword and numbers: the view (`v`, then `from`,
//! `at`, `up`, `angle`, `hither`, `resolution` on lines of their own, in that
//! order), the background (`b`), positional lights (`l`), the material of the
//! objects that follow (`f`), spheres (`s`), open cylinders and cones (`c`),
//! polygons (`p`) and polygonal patches (`pp`). Read strictly: every line
//! must have exactly its numbers, finite and within the ranges of
//! [`crate::scene::limits`]; an error names the file, the line and the
//! column.
//!
//! What NFF leaves to the renderer, raytree decides so:
//! - **Handedness.** The SPD's documents call its frame left-handed, yet its
//!   reference pictures are what a right-handed camera sees from `from`,
//!   `at` and `up` (the teapot's spout points left, as in the picture), and
//!   NFF's polygons face where their vertices run counter-clockwise in a
//!   right-handed frame. So the numbers are taken as they are, in raytree's
//!   right-handed frame; mirroring them would mirror every picture.
//! - **Colors** are for a display, as the SPD's renderers showed them (and
//!   as its POV-Ray files pass them on): sRGB, made linear on reading, so the
//!   image written back in sRGB shows them as given.
//! - **Lights** without a color get the intensity the SPD's notes suggest,
//!   `√n / (2n)` for `n` lights, in white; the ambient light is the same.
//! - **Materials.** `f R G B Kd Ks Shine T ior` becomes color `(R, G, B)`,
//!   `diffuse = Kd`, `ambient = Kd` (the SPD asks for an ambient term on
//!   every object), `specular = reflective = Ks` (NFF's Ks weights both the
//!   highlight and the reflected ray), `shininess = Shine`,
//!   `transparent = T`, and `ior` (an opaque material's index never matters,
//!   and the SPD writes 0 there: it becomes 1).
//! - **Sides.** NFF polygons are one-sided: an opaque polygon seen from its
//!   back is not hit. Transmitting polygons are two-sided, and so are
//!   polygonal patches: the SPD uses them only for the teapot, whose protocol
//!   asks for a two-sided teapot (its lid does not fit, so its inside shows).
//! - `hither` is read and checked but unused: a ray tracer has no near plane.
//! - **Inside-only objects** (a negative radius, NFF's sphere or cone seen
//!   only from inside) are refused: raytree has no one-sided quadrics.

use std::collections::HashMap;

use glam::DVec3;
use serde_json::{Value, json};

use crate::io::image::srgb_to_linear;
use crate::scene::limits;
use crate::scene::nff_json::{NffScene, View, material_json};
use crate::scene::quote::{printable, quote};
use crate::scene::scene_error::SceneError;
use crate::scene::settings::RenderSettings;

/// Most vertices one polygon may have: the SPD's largest has 144; a count
/// beyond this is refused before any vertex is read.
pub const MAX_POLYGON_VERTICES: usize = 65_536;

/// Most words (keywords and numbers) an NFF file may hold, some 800,000
/// spheres (the SPD's scenes hold under 300,000): each object is a JSON value
/// of some hundred bytes before the scene loads, so memory stays bounded.
pub const MAX_WORDS: usize = 1 << 22;

/// Whether `file` names an NFF file (by its extension, in any case).
pub fn is_nff(file: &str) -> bool {
    std::path::Path::new(file)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("nff"))
}

/// The NFF text `text` of file `file` as raytree scene JSON, one object to
/// a line; errors name `file` and the line.
pub fn to_json(text: &str, file: &str) -> Result<String, SceneError> {
    let reader = Reader::new(text, file);
    if let Some(line) = past_word_limit(text) {
        let limit = format!(
            "the file holds more than {MAX_WORDS} words (keywords and numbers), more than raytree reads from an NFF file"
        );
        return Err(reader.error(line, 1, limit));
    }
    let scene = reader.read()?;
    Ok(scene.json(file))
}

/// The line on which the words (keywords and numbers) pass [`MAX_WORDS`],
/// counted before anything is built: the scene made of them would take some
/// hundred times their bytes.
fn past_word_limit(text: &str) -> Option<usize> {
    let mut words = 0;
    let mut lines = text.lines().map(|l| l.split('#').next().unwrap_or(""));
    let past = lines.position(|l| {
        words += l.split_whitespace().count();
        words > MAX_WORDS
    });
    past.map(|i| i + 1)
}

/// The words that begin a line of an NFF file: the entities' keywords and
/// the view's lines.
const KEYWORDS: [&str; 14] = [
    "v",
    "b",
    "l",
    "f",
    "s",
    "c",
    "p",
    "pp",
    "from",
    "at",
    "up",
    "angle",
    "hither",
    "resolution",
];

/// A line of the file: its number and its words with their columns.
pub(super) struct Line<'t> {
    pub(super) number: usize,
    pub(super) words: Vec<(usize, &'t str)>,
}

pub(super) struct Reader<'t> {
    file: &'t str,
    lines: Box<dyn Iterator<Item = Line<'t>> + 't>,
    /// The line the file ended after, for "ends early" errors.
    last: usize,
}

impl<'t> Reader<'t> {
    fn new(text: &'t str, file: &'t str) -> Self {
        let lines = text.lines().enumerate().filter_map(|(i, line)| {
            let line = line.split('#').next().unwrap_or("");
            let mut words = Vec::new();
            let mut column = 1;
            for piece in line.split_inclusive(char::is_whitespace) {
                let word = piece.trim_end();
                if !word.is_empty() {
                    words.push((column, word));
                }
                column += piece.chars().count();
            }
            (!words.is_empty()).then_some(Line {
                number: i + 1,
                words,
            })
        });
        let last = text.lines().count();
        Reader {
            file,
            lines: Box::new(lines),
            last,
        }
    }

    pub(super) fn error(
        &self,
        line: usize,
        column: usize,
        message: impl Into<String>,
    ) -> SceneError {
        SceneError::Syntax {
            file: self.file.to_owned(),
            line,
            column,
            message: printable(&message.into()),
        }
    }

    /// The next line, which entity `what` (begun on line `from`) needs.
    pub(super) fn next_for(&mut self, what: &str, from: usize) -> Result<Line<'t>, SceneError> {
        self.lines.next().ok_or_else(|| {
            self.error(
                self.last.max(1),
                1,
                format!("the file ends inside the {what} begun on line {from}"),
            )
        })
    }

    fn read(mut self) -> Result<NffScene, SceneError> {
        let mut scene = NffScene::default();
        // The current material's name, and whether it transmits.
        let mut material: Option<(String, bool)> = None;
        let mut known: HashMap<[u64; 8], String> = HashMap::new();
        while let Some(line) = self.lines.next() {
            let (column, keyword) = line.words[0];
            let n = line.number;
            match keyword {
                "v" => {
                    self.count(&line, 0)?;
                    if scene.view.is_some() {
                        return Err(self.error(n, column, "a second view (v): give one"));
                    }
                    scene.view = Some(self.view(n)?);
                }
                "b" => {
                    let [r, g, b] = self.numbers(&line)?;
                    if scene.background.is_some() {
                        return Err(self.error(n, column, "a second background (b): give one"));
                    }
                    scene.background = Some(self.color(&line, 1, DVec3::new(r, g, b))?);
                }
                "l" => {
                    let (position, color) = match line.words.len() {
                        4 => (self.point(&line, 1, "a light's position")?, None),
                        7 => {
                            let [_, _, _, r, g, b] = self.numbers(&line)?;
                            let color = self.color(&line, 4, DVec3::new(r, g, b))?;
                            (self.point(&line, 1, "a light's position")?, Some(color))
                        }
                        _ => {
                            return Err(self.error(
                                n,
                                column,
                                format!(
                                    "a light (l) takes 3 numbers X Y Z, or 6 with a color R G B; got {}",
                                    line.words.len() - 1
                                ),
                            ));
                        }
                    };
                    scene.lights.push((position, color));
                }
                "f" => {
                    let values: [f64; 8] = self.numbers(&line)?;
                    let key = values.map(f64::to_bits);
                    let transmits = values[6] > 0.0;
                    let name = match known.get(&key) {
                        Some(name) => name.clone(),
                        None => {
                            let name = format!("f at line {n}");
                            let m = self.material(&line, values)?;
                            scene.materials.push((name.clone(), m));
                            known.insert(key, name.clone());
                            name
                        }
                    };
                    material = Some((name, transmits));
                }
                "s" | "c" | "p" | "pp" => {
                    let Some((material, transparent)) = material.clone() else {
                        return Err(self.error(
                            n,
                            column,
                            format!("an object ({keyword}) before any material (f)"),
                        ));
                    };
                    let object = match keyword {
                        "s" => self.sphere(&line)?,
                        "c" => self.cone(&line)?,
                        _ => self.polygon(&line, keyword == "pp", transparent)?,
                    };
                    let mut object = object;
                    object["material"] = json!(material);
                    scene.objects.push(object);
                }
                other => {
                    return Err(self.error(
                        n,
                        column,
                        format!(
                            "{} is not an NFF keyword (expected v, b, l, f, s, c, p or pp)",
                            quote(other, "'")
                        ),
                    ));
                }
            }
        }
        if scene.view.is_none() {
            return Err(self.error(self.last.max(1), 1, "no view (v): an NFF scene needs one"));
        }
        Ok(scene)
    }

    /// Checks that `line` holds its keyword and `n` more words.
    pub(super) fn count(&self, line: &Line, n: usize) -> Result<(), SceneError> {
        let (column, keyword) = line.words[0];
        let got = line.words.len() - 1;
        if got != n {
            let what = match n {
                0 => "nothing".to_owned(),
                1 => "1 number".to_owned(),
                n => format!("{n} numbers"),
            };
            return Err(self.error(
                line.number,
                column,
                format!("'{keyword}' takes {what} after it, got {got}"),
            ));
        }
        Ok(())
    }

    /// The `N` numbers after `line`'s keyword: finite, and exactly `N`.
    pub(super) fn numbers<const N: usize>(&self, line: &Line) -> Result<[f64; N], SceneError> {
        self.count(line, N)?;
        self.numbers_from(line, 1)
    }

    /// `N` finite numbers of `line` from word `first` on (the words must be there).
    pub(super) fn numbers_from<const N: usize>(
        &self,
        line: &Line,
        first: usize,
    ) -> Result<[f64; N], SceneError> {
        let mut out = [0.0; N];
        for (k, value) in out.iter_mut().enumerate() {
            let (column, word) = line.words[first + k];
            *value = match word.parse::<f64>() {
                Ok(x) if x.is_finite() => x,
                Ok(_) => {
                    return Err(self.error(
                        line.number,
                        column,
                        format!("{} is not a finite number", quote(word, "'")),
                    ));
                }
                Err(_) => {
                    return Err(self.error(
                        line.number,
                        column,
                        format!("{} is not a number", quote(word, "'")),
                    ));
                }
            };
        }
        Ok(out)
    }

    /// The three numbers of words `first..first + 3` of `line`, within the
    /// limits of a point; `what` they are (a vertex, a normal) names them.
    pub(super) fn point(&self, line: &Line, first: usize, what: &str) -> Result<DVec3, SceneError> {
        let [x, y, z] = self.numbers_from(line, first)?;
        limits::point(DVec3::new(x, y, z))
            .map_err(|e| self.error(line.number, line.words[first].0, format!("{what}: {e}")))
    }

    /// Checks that `line`, which must hold `what` (an end of a cone, a
    /// vertex), holds `n` numbers: a keyword there means the entity before
    /// it was cut short, and says so.
    pub(super) fn expect_numbers(
        &self,
        line: &Line,
        n: usize,
        what: &str,
    ) -> Result<(), SceneError> {
        let (column, first) = line.words[0];
        if KEYWORDS.contains(&first) {
            return Err(self.error(
                line.number,
                column,
                format!("expected {what}, found the keyword '{first}'"),
            ));
        }
        if line.words.len() != n {
            return Err(self.error(
                line.number,
                column,
                format!(
                    "{what} takes {n} numbers, got {} (a wrong count?)",
                    line.words.len()
                ),
            ));
        }
        Ok(())
    }

    /// A color as NFF gives it, for a display (sRGB), checked and made linear;
    /// an error names word `first`, its R, where the color begins on the line
    /// (a light's `l X Y Z R G B` puts it after the position).
    fn color(&self, line: &Line, first: usize, c: DVec3) -> Result<DVec3, SceneError> {
        let c = limits::color(c)
            .map_err(|e| self.error(line.number, line.words[first].0, format!("a color: {e}")))?;
        Ok(DVec3::new(
            srgb_to_linear(c.x),
            srgb_to_linear(c.y),
            srgb_to_linear(c.z),
        ))
    }

    /// The view block: six lines, each its keyword and its numbers, in order.
    fn view(&mut self, start: usize) -> Result<View, SceneError> {
        let mut keyed = |key: &str, n: usize| -> Result<Line<'t>, SceneError> {
            let line = self.next_for("view (v)", start)?;
            let (column, word) = line.words[0];
            if word != key {
                return Err(self.error(
                    line.number,
                    column,
                    format!(
                        "the view (v) begun on line {start} expects '{key}' here (from, at, up, angle, hither, resolution, in that order), got {}",
                        quote(word, "'")
                    ),
                ));
            }
            self.count(&line, n)?;
            Ok(line)
        };
        let from_line = keyed("from", 3)?;
        let at_line = keyed("at", 3)?;
        let up_line = keyed("up", 3)?;
        let angle_line = keyed("angle", 1)?;
        let hither_line = keyed("hither", 1)?;
        let resolution_line = keyed("resolution", 2)?;
        let from = self.point(&from_line, 1, "'from'")?;
        let at = self.point(&at_line, 1, "'at'")?;
        let up = self.point(&up_line, 1, "'up'")?;
        // So close that their difference has no direction (its square
        // underflows) is as equal as equal: the view would look nowhere.
        if (at - from).try_normalize().is_none() {
            return Err(self.error(
                at_line.number,
                1,
                "'at' must differ from 'from', and they are equal or so nearly equal that the view has no direction",
            ));
        }
        if up.cross(at - from).length() <= 1e-9 * up.length() * (at - from).length() {
            return Err(self.error(
                up_line.number,
                1,
                "'up' must not be zero or parallel to the view direction",
            ));
        }
        let [angle] = self.numbers_from(&angle_line, 1)?;
        let (low, high) = limits::FOV;
        if !(low..=high).contains(&angle) {
            return Err(self.error(
                angle_line.number,
                angle_line.words[1].0,
                format!(
                    "'angle' must be from {low} to {high} degrees, got {}",
                    limits::num(angle)
                ),
            ));
        }
        let [hither] = self.numbers_from(&hither_line, 1)?;
        if hither < 0.0 {
            return Err(self.error(
                hither_line.number,
                hither_line.words[1].0,
                format!("'hither' must not be negative, got {}", limits::num(hither)),
            ));
        }
        let side = |k: usize| -> Result<u32, SceneError> {
            let (column, word) = resolution_line.words[k];
            word.parse::<u32>()
                .ok()
                .filter(|s| (1..=RenderSettings::MAX_SIDE).contains(s))
                .ok_or_else(|| {
                    self.error(
                        resolution_line.number,
                        column,
                        format!(
                            "{} is not an image side (a whole number from 1 to {})",
                            quote(word, "'"),
                            RenderSettings::MAX_SIDE
                        ),
                    )
                })
        };
        let resolution = (side(1)?, side(2)?);
        Ok(View {
            from,
            at,
            up,
            angle,
            resolution,
        })
    }

    fn material(&self, line: &Line, v: [f64; 8]) -> Result<Value, SceneError> {
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
        Ok(material_json(color, kd, ks, shine, t, ior))
    }
}
