//! NFF's view, `v` and six lines of their own (`from`, `at`, `up`, `angle`,
//! `hither`, `resolution`, in that order), read as the scene file's camera
//! block (a look-at camera) and its image size.

use glam::DVec3;

use crate::scene::format::CameraFile;
use crate::scene::limits;
use crate::scene::nff::reader::{Line, Reader};
use crate::scene::overrides::Overrides;
use crate::scene::quote::quote;
use crate::scene::scene_error::SceneError;
use crate::scene::settings::RenderSettings;

/// The view block's lines, each read with its keyword checked and its count.
struct ViewLines<'t> {
    from: Line<'t>,
    at: Line<'t>,
    up: Line<'t>,
    angle: Line<'t>,
    hither: Line<'t>,
    resolution: Line<'t>,
}

impl<'t> Reader<'t> {
    /// `v` on `line` and the block after it, given once (`given`: it was
    /// before): the camera and the image size.
    pub(super) fn view(
        &mut self,
        line: &Line,
        given: bool,
    ) -> Result<(CameraFile, Overrides), SceneError> {
        self.count(line, 0)?;
        if given {
            let column = line.words[0].0;
            return Err(self.error(line.number, column, "a second view (v): give one"));
        }
        let lines = self.view_lines(line.number)?;
        let camera = self.camera(&lines)?;
        let [hither] = self.numbers_from(&lines.hither, 1)?;
        if hither < 0.0 {
            return Err(self.error(
                lines.hither.number,
                lines.hither.words[1].0,
                format!("'hither' must not be negative, got {}", limits::num(hither)),
            ));
        }
        let render = Overrides {
            width: Some(self.side(&lines.resolution, 1)?),
            height: Some(self.side(&lines.resolution, 2)?),
            ..Overrides::default()
        };
        Ok((camera, render))
    }

    /// The six lines of the view begun on line `start`, each its keyword and
    /// its numbers, in order.
    fn view_lines(&mut self, start: usize) -> Result<ViewLines<'t>, SceneError> {
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
        Ok(ViewLines {
            from: keyed("from", 3)?,
            at: keyed("at", 3)?,
            up: keyed("up", 3)?,
            angle: keyed("angle", 1)?,
            hither: keyed("hither", 1)?,
            resolution: keyed("resolution", 2)?,
        })
    }

    /// The camera the view's `from`, `at`, `up` and `angle` give: a view that
    /// looks somewhere, with an up that is not along it.
    fn camera(&self, lines: &ViewLines) -> Result<CameraFile, SceneError> {
        let from = self.point(&lines.from, 1, "'from'")?;
        let at = self.point(&lines.at, 1, "'at'")?;
        let up = self.point(&lines.up, 1, "'up'")?;
        // So close that their difference has no direction (its square
        // underflows) is as equal as equal: the view would look nowhere.
        if (at - from).try_normalize().is_none() {
            return Err(self.error(
                lines.at.number,
                1,
                "'at' must differ from 'from', and they are equal or so nearly equal that the view has no direction",
            ));
        }
        if up.cross(at - from).length() <= 1e-9 * up.length() * (at - from).length() {
            return Err(self.error(
                lines.up.number,
                1,
                "'up' must not be zero or parallel to the view direction",
            ));
        }
        let [angle] = self.numbers_from(&lines.angle, 1)?;
        let (low, high) = limits::FOV;
        if !(low..=high).contains(&angle) {
            return Err(self.error(
                lines.angle.number,
                lines.angle.words[1].0,
                format!(
                    "'angle' must be from {low} to {high} degrees, got {}",
                    limits::num(angle)
                ),
            ));
        }
        Ok(look_at(from, at, up, angle))
    }

    /// Word `k` of the `resolution` line: an image side.
    fn side(&self, resolution: &Line, k: usize) -> Result<u32, SceneError> {
        let (column, word) = resolution.words[k];
        word.parse::<u32>()
            .ok()
            .filter(|s| (1..=RenderSettings::MAX_SIDE).contains(s))
            .ok_or_else(|| {
                self.error(
                    resolution.number,
                    column,
                    format!(
                        "{} is not an image side (a whole number from 1 to {})",
                        quote(word, "'"),
                        RenderSettings::MAX_SIDE
                    ),
                )
            })
    }
}

/// The scene file's look-at camera: NFF's `from`, `at`, `up` and `angle`.
fn look_at(from: DVec3, at: DVec3, up: DVec3, angle: f64) -> CameraFile {
    CameraFile {
        eye: Some(from),
        look_at: Some(at),
        up: Some(up),
        fov: Some(angle),
        ..CameraFile::default()
    }
}
