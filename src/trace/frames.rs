//! A filmstrip's frames, rendered one after the other (each on all cores),
//! each with how much it changed from the frame before: the share of pixels
//! where some channel moved by more than 3 of 255 levels, as `raytree diff`
//! counts ([`crate::io::image::diff`]).

use crate::io::image::diff;
use crate::io::image::to_rgb8;
use crate::scene::Scene;
use crate::trace::progress::Progress;
use crate::trace::render;

/// One frame rendered.
#[derive(Clone, Debug, PartialEq)]
pub struct Rendered {
    /// 8-bit sRGB, rows top first.
    pub rgb: Vec<u8>,
    /// The share of pixels (0 to 1) that changed by more than 3/255 from the
    /// frame before; `None` for the first frame.
    pub changed: Option<f64>,
}

/// The frames of `scenes` (all of one size), each rendered when asked for:
/// a caller can show each as soon as it is done, and run each on a pool of
/// its choosing.
pub fn render_each(scenes: &[Scene]) -> Frames<'_> {
    Frames {
        scenes: scenes.iter(),
        previous: None,
    }
}

/// The iterator of [`render_each`]: a frame, or why it could not be made
/// (one line).
pub struct Frames<'a> {
    scenes: std::slice::Iter<'a, Scene>,
    previous: Option<image::RgbImage>,
}

impl Iterator for Frames<'_> {
    type Item = Result<Rendered, String>;

    fn next(&mut self) -> Option<Self::Item> {
        let scene = self.scenes.next()?;
        Some(self.frame(scene))
    }
}

impl Frames<'_> {
    fn frame(&mut self, scene: &Scene) -> Result<Rendered, String> {
        let (width, height) = (scene.settings.width, scene.settings.height);
        let image = render::render(scene, &Progress::QUIET)
            .map_err(|_| format!("not enough memory for a {width}×{height} image"))?;
        let rgb = to_rgb8(&image);
        let now = image::RgbImage::from_raw(width, height, rgb.clone())
            .ok_or_else(|| "frame size".to_owned())?;
        let changed = match &self.previous {
            None => None,
            Some(before) => Some(
                diff::difference(before, &now)
                    .map_err(|e| format!("{e:#}"))?
                    .share_over_3,
            ),
        };
        self.previous = Some(now);
        Ok(Rendered { rgb, changed })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::loader::{self, WHITTED};

    #[test]
    fn each_frame_is_measured_against_the_one_before() {
        let scene = |depth: u32| {
            let mut s = loader::parse(WHITTED, "whitted.json").unwrap();
            (s.settings.width, s.settings.height, s.settings.max_depth) = (40, 30, depth);
            s
        };
        let scenes = [scene(1), scene(1), scene(3)];
        let frames: Vec<Rendered> = render_each(&scenes).map(Result::unwrap).collect();
        assert_eq!(frames.len(), 3);
        assert!(frames.iter().all(|f| f.rgb.len() == 40 * 30 * 3));
        assert_eq!(frames[0].changed, None);
        // The same scene twice is the same image; depth 3 shows the glass.
        assert_eq!(frames[1].changed, Some(0.0));
        assert!(frames[2].changed.is_some_and(|c| c > 0.0));
    }
}
