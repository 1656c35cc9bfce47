//! A learner's whole image beside raytree's render of it (made by the caller
//! at the learner's size with one ray through each pixel's center, what the
//! learner trace checks too: [`settings_for`]), compared in 8-bit levels, the
//! pixels off counted and the worst named, each with the command that checks
//! it ray by ray.

use std::fmt::Write;

use serde_json::json;

use crate::course::learner::mistakes::image::{Explained, explain};
use crate::io::image::diff::per_pixel;
use crate::io::image::{Image, to_rgb8};
use crate::methods::Antialiasing;
use crate::scene::settings::RenderSettings;

/// The largest learner image checked: a class's images are small, and a
/// render this size takes seconds; beyond it the check refuses up front.
pub const MAX_PIXELS: u64 = 4096 * 4096;

/// One pixel that is off.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Off {
    /// Its column, from the left.
    pub x: u32,
    /// Its row, from the top.
    pub y: u32,
    /// The largest of its three channels' differences, in 8-bit levels.
    pub levels: u8,
    /// The learner's color.
    pub yours: [u8; 3],
    /// raytree's.
    pub ours: [u8; 3],
}

/// The comparison of a learner's image with raytree's render of the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageCheck {
    /// The scene's file, as given.
    pub scene: String,
    /// The learner's file, as given.
    pub learner: String,
    /// The image's size.
    pub width: u32,
    /// The image's size.
    pub height: u32,
    /// A pixel is off when a channel differs by more than this many levels.
    pub tolerance: u8,
    /// How many pixels are off.
    pub off: u64,
    /// The largest difference of any channel.
    pub max: u8,
    /// The worst pixels, worst first (ties top to bottom, left to right).
    pub worst: Vec<Off>,
    /// raytree's render, 8-bit sRGB, rows from the top.
    pub ours: Vec<u8>,
    /// The whole-image mistakes that explain the learner's image, if any.
    pub explained: Option<Explained>,
}

/// The settings raytree renders the learner's image with: `settings` at the
/// image's size, one sample through each pixel's center. Refuses an image of
/// no pixels or more than [`MAX_PIXELS`], naming `learner`.
pub fn settings_for(
    settings: &RenderSettings,
    learner: &str,
    (width, height): (u32, u32),
) -> Result<RenderSettings, String> {
    if width == 0 || height == 0 {
        return Err(format!("{learner}: an image of no pixels"));
    }
    if u64::from(width) * u64::from(height) > MAX_PIXELS {
        return Err(format!(
            "{learner}: {width}×{height} pixels; the check renders at most {MAX_PIXELS} (render yours smaller)"
        ));
    }
    let mut out = one_ray_per_pixel(settings);
    out.width = width;
    out.height = height;
    Ok(out)
}

/// `settings` with one sample through each pixel's center, whatever the
/// scene's sampling: what a learner's tracer makes, for the image check and
/// the one-pixel check alike.
pub fn one_ray_per_pixel(settings: &RenderSettings) -> RenderSettings {
    let mut out = *settings;
    out.spp = 1;
    out.aa = Antialiasing::Grid;
    out
}

/// Compares the learner's image `yours` with raytree's render `render`
/// (linear RGB, the same size: it is written as 8-bit sRGB to compare, and
/// kept linear to recognise an image written without that encoding); `names`
/// are the scene's and the learner's files, `worst` caps the pixels listed.
pub fn check_image(
    names: (&str, &str),
    yours: &image::RgbImage,
    render: &Image,
    tolerance: u8,
    worst: usize,
) -> ImageCheck {
    let (width, height) = yours.dimensions();
    let theirs = yours.as_raw();
    let ours = to_rgb8(render);
    let diff = per_pixel(theirs, &ours);
    let mut off: Vec<Off> = diff
        .iter()
        .enumerate()
        .filter(|(_, d)| **d > tolerance)
        .map(|(i, &levels)| {
            let px = |rgb: &[u8]| [rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]];
            Off {
                x: (i % width as usize) as u32,
                y: (i / width as usize) as u32,
                levels,
                yours: px(theirs),
                ours: px(&ours),
            }
        })
        .collect();
    let count = off.len() as u64;
    let explained = explain(theirs, render, tolerance, count);
    off.sort_by_key(|o| (std::cmp::Reverse(o.levels), o.y, o.x));
    off.truncate(worst);
    ImageCheck {
        scene: names.0.to_owned(),
        learner: names.1.to_owned(),
        width,
        height,
        tolerance,
        off: count,
        max: diff.iter().copied().max().unwrap_or(0),
        worst: off,
        ours,
        explained,
    }
}

impl ImageCheck {
    /// Every pixel within the tolerance.
    pub fn agrees(&self) -> bool {
        self.off == 0
    }

    /// The share of pixels off, 0 to 1.
    pub fn share(&self) -> f64 {
        self.off as f64 / (u64::from(self.width) * u64::from(self.height)) as f64
    }

    /// The command that checks pixel `o` ray by ray (the learner writes its trace first).
    fn command(&self, o: &Off) -> String {
        format!(
            "raytree check {} --pixel {},{} --width {} --height {} TRACE.json",
            self.scene, o.x, o.y, self.width, self.height
        )
    }

    /// The report as text.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let total = u64::from(self.width) * u64::from(self.height);
        let _ = writeln!(
            out,
            "raytree check: {} against {} at {}×{} (one ray through each pixel's center)",
            self.learner, self.scene, self.width, self.height
        );
        if self.agrees() {
            let _ = writeln!(
                out,
                "every pixel agrees within {} level{} (largest difference {})",
                self.tolerance,
                if self.tolerance == 1 { "" } else { "s" },
                self.max
            );
            return out;
        }
        let _ = writeln!(
            out,
            "{} of {total} pixels ({:.2} %) differ by more than {} level{} in some channel (largest {})",
            self.off,
            100.0 * self.share(),
            self.tolerance,
            if self.tolerance == 1 { "" } else { "s" },
            self.max
        );
        if let Some(e) = &self.explained {
            for m in &e.mistakes {
                let _ = writeln!(out, "{}.", m.words());
            }
            let _ = writeln!(
                out,
                "With {} fixed, {} of {total} pixels would still be off{}",
                if e.mistakes.len() == 1 {
                    "that"
                } else {
                    "those"
                },
                e.off,
                if e.off == 0 {
                    "."
                } else {
                    "; after fixing, check the image again."
                }
            );
        }
        let _ = writeln!(
            out,
            "the worst, each with the command that checks its rays (write the pixel's learner trace first{}):",
            if self.explained.is_some() {
                "; a trace shows the mistakes above only where they are in the camera, not in writing the image"
            } else {
                ""
            }
        );
        for o in &self.worst {
            let _ = writeln!(
                out,
                "  ({}, {}): {} levels off, yours ({}, {}, {}), raytree's ({}, {}, {})\n    {}",
                o.x,
                o.y,
                o.levels,
                o.yours[0],
                o.yours[1],
                o.yours[2],
                o.ours[0],
                o.ours[1],
                o.ours[2],
                self.command(o)
            );
        }
        out
    }

    /// The report for an autograder (`raytree-image-check`, version 1).
    pub fn json(&self) -> String {
        let worst: Vec<_> = self
            .worst
            .iter()
            .map(|o| {
                json!({
                    "x": o.x, "y": o.y, "levels": o.levels,
                    "yours": o.yours, "raytree": o.ours,
                    "command": self.command(o),
                })
            })
            .collect();
        let mistakes: Vec<_> = self
            .explained
            .iter()
            .flat_map(|e| {
                e.mistakes
                    .iter()
                    .map(|m| json!({"id": m, "words": m.words()}))
            })
            .collect();
        let doc = json!({
            "format": "raytree-image-check",
            "version": 1,
            "scene": self.scene,
            "learner": self.learner,
            "width": self.width,
            "height": self.height,
            "tolerance": self.tolerance,
            "pixels_off": self.off,
            "share_off": self.share(),
            "max": self.max,
            "agree": self.agrees(),
            "worst": worst,
            "mistakes": mistakes,
            "off_if_fixed": self.explained.as_ref().map(|e| e.off),
        });
        serde_json::to_string_pretty(&doc).expect("a JSON value prints") + "\n"
    }
}
