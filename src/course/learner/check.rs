//! `raytree check`, what it does from the learner's file to the report. One
//! pixel (`--pixel X,Y TRACE.json`): the learner's trace is read strictly
//! ([`crate::course::learner::read`]), raytree traces the pixel as a
//! learner's tracer does (one ray through its center), the two are compared
//! ray by ray ([`crate::course::learner::compare`]), each divergence
//! diagnosed where its numbers show a classic mistake
//! ([`crate::course::learner::diagnose`]), and the report made
//! ([`crate::course::learner::report`]). A whole image (`--image
//! YOURS.png`) is compared pixel by pixel with raytree's render in
//! [`crate::course::learner::image`]: the command renders it, as the course
//! layer traces single pixels only.

use std::path::Path;

use crate::course::learner::compare::compare;
use crate::course::learner::context::Context;
use crate::course::learner::format::LearnerTrace;
use crate::course::learner::image::one_ray_per_pixel;
use crate::course::learner::read;
use crate::course::learner::report::Report;
use crate::scene::Scene;
use crate::scene::source::SceneSource;
use crate::tree::document::TraceDocument;
use crate::tree::record;

/// Checks the learner's trace in file `learner` against raytree's trace of
/// `pixel` in `scene`. An error (a file that cannot be read, a trace of
/// another pixel) is bad input, one line naming the file.
pub fn pixel(
    scene: &Scene,
    source: SceneSource,
    pixel: (u32, u32),
    learner: &Path,
) -> Result<Report, String> {
    let trace = read::read(learner)?;
    if let Some([lx, ly]) = trace.pixel
        && (lx, ly) != pixel
    {
        return Err(format!(
            "{}: the trace is of pixel {lx},{ly}, and --pixel asks for {},{}",
            learner.display(),
            pixel.0,
            pixel.1
        ));
    }
    self::trace(scene, source, pixel, &trace)
}

/// Checks `learner` against raytree's trace of `pixel` in `scene`, traced as
/// a learner's tracer does: one ray through the pixel's center. An error
/// (a pixel outside the image, a trace of another pixel) is bad input.
pub fn trace(
    scene: &Scene,
    source: SceneSource,
    pixel: (u32, u32),
    learner: &LearnerTrace,
) -> Result<Report, String> {
    if let Some([x, y]) = learner.pixel
        && (x, y) != pixel
    {
        return Err(format!(
            "the learner trace is of pixel {x},{y}, and the pixel checked is {},{}",
            pixel.0, pixel.1
        ));
    }
    let trace = ours(scene, source, pixel)?;
    let mut one = scene.clone();
    one.settings = trace.settings;
    let ctx = Context {
        scene: &one,
        trace: &trace,
        pixel,
    };
    Ok(Report {
        scene: trace.scene.file.clone(),
        pixel,
        size: (trace.settings.width, trace.settings.height),
        rays: (learner.ray.count(), trace.samples[0].tree.nodes.len()),
        differences: compare(&ctx, learner),
    })
}

/// raytree's trace of `pixel` with one sample through its center, whatever
/// the scene's sampling: what a learner's tracer makes.
pub fn ours(
    scene: &Scene,
    source: SceneSource,
    pixel: (u32, u32),
) -> Result<TraceDocument, String> {
    let mut one = scene.clone();
    one.settings = one_ray_per_pixel(&scene.settings);
    record::pixel(&one, source, pixel.0, pixel.1, None).map_err(|e| e.to_string())
}
