//! NFF, the Neutral File Format in which Eric Haines's Standard Procedural
//! Databases (1987) write their scenes, read into the scene format's own
//! parts ([`crate::scene::format`]: a camera block, materials, lights,
//! objects) and written as raytree's scene JSON, which the JSON loader then
//! reads as any scene file. So `raytree render balls.nff` and `raytree
//! convert balls.nff -o balls.json` then `raytree render balls.json` see the
//! very same scene: one reader of scenes, and a learner can open the
//! converted file, read it and edit it.
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

mod json; // the scene written as scene JSON, one entry to a line
mod materials; // `f`: a material, and an `f` met before named as before
mod reader; // the file as lines of words, each number read strictly
mod shapes; // the objects, refused in NFF's own terms
mod view; // the view block: the camera and the image size

use glam::DVec3;

use crate::scene::format::{CameraFile, LightFile, MaterialFile, ObjectFile};
use crate::scene::nff::materials::Materials;
use crate::scene::nff::reader::{Line, Reader};
use crate::scene::overrides::Overrides;
use crate::scene::quote::quote;
use crate::scene::scene_error::SceneError;

/// Most vertices one polygon may have: the SPD's largest has 144; a count
/// beyond this is refused before any vertex is read.
pub const MAX_POLYGON_VERTICES: usize = 65_536;

/// Most words (keywords and numbers) one NFF file may hold: about 4.2
/// million, some 800,000 spheres or 300,000 triangles (the SPD's scenes hold
/// under 300,000 words). Each object becomes a typed entry, then a line of
/// scene JSON of some hundred bytes, before the scene loads, so this bounds
/// the memory a file can take to a few hundred megabytes; the words are
/// counted before anything is built, and a file past the limit is refused.
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
    let scene = read(reader)?;
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

/// What an NFF file holds, read and checked, in the scene format's own
/// parts and in the file's order.
#[derive(Default)]
struct NffScene {
    /// The camera and the image size.
    view: Option<(CameraFile, Overrides)>,
    background: Option<DVec3>,
    /// Each light; a color left out is the SPD's, which depends on how many
    /// lights there are, so it is put in when the scene is written.
    lights: Vec<LightFile>,
    /// Materials by name, in the order first used.
    materials: Vec<(String, MaterialFile)>,
    objects: Vec<ObjectFile>,
}

/// Every entity of the file, in order.
fn read(mut reader: Reader) -> Result<NffScene, SceneError> {
    let mut scene = NffScene::default();
    let mut materials = Materials::default();
    while let Some(line) = reader.next_line() {
        let (column, keyword) = line.words[0];
        match keyword {
            "v" => {
                let view = reader.view(&line, scene.view.is_some())?;
                scene.view = Some(view);
            }
            "b" => {
                let background = reader.background(&line, scene.background.is_some())?;
                scene.background = Some(background);
            }
            "l" => scene.lights.push(reader.light(&line)?),
            "f" => reader.material(&line, &mut materials)?,
            "s" | "c" | "p" | "pp" => {
                let object = reader.object(&line, materials.current())?;
                scene.objects.push(object);
            }
            other => {
                return Err(reader.error(
                    line.number,
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
        return Err(reader.at_end("no view (v): an NFF scene needs one"));
    }
    scene.materials = materials.used();
    Ok(scene)
}

impl Reader<'_> {
    /// `b R G B`, the background, given once (`given`: it was before).
    fn background(&self, line: &Line, given: bool) -> Result<DVec3, SceneError> {
        let [r, g, b] = self.numbers(line)?;
        if given {
            let column = line.words[0].0;
            return Err(self.error(line.number, column, "a second background (b): give one"));
        }
        self.color(line, 1, DVec3::new(r, g, b))
    }

    /// `l X Y Z`, or `l X Y Z R G B` with its color.
    fn light(&self, line: &Line) -> Result<LightFile, SceneError> {
        let (position, color) = match line.words.len() {
            4 => (self.point(line, 1, "a light's position")?, None),
            7 => {
                let [_, _, _, r, g, b] = self.numbers(line)?;
                let color = self.color(line, 4, DVec3::new(r, g, b))?;
                (self.point(line, 1, "a light's position")?, Some(color))
            }
            _ => {
                return Err(self.error(
                    line.number,
                    line.words[0].0,
                    format!(
                        "a light (l) takes 3 numbers X Y Z, or 6 with a color R G B; got {}",
                        line.words.len() - 1
                    ),
                ));
            }
        };
        Ok(LightFile {
            name: None,
            position,
            color,
        })
    }

    /// An object (`s`, `c`, `p` or `pp`) in `material`, the current one (its
    /// name, and whether it transmits): an object before any `f` is refused.
    fn object(
        &mut self,
        line: &Line,
        material: Option<(&str, bool)>,
    ) -> Result<ObjectFile, SceneError> {
        let (column, keyword) = line.words[0];
        let Some((material, transparent)) = material else {
            return Err(self.error(
                line.number,
                column,
                format!("an object ({keyword}) before any material (f)"),
            ));
        };
        let mut object = match keyword {
            "s" => self.sphere(line)?,
            "c" => self.cone(line)?,
            _ => self.polygon(line, keyword == "pp", transparent)?,
        };
        object.material = Some(material.to_owned());
        Ok(object)
    }
}
