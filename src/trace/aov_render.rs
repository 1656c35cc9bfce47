//! Rendering a per-pixel quantity ([`crate::trace::aov`]): every pixel traced
//! exactly as the renderer traces it, through the one pixel loop, with the
//! per-pixel record ([`crate::trace::pixel_record`]) that keeps, for each
//! primary ray, what the quantities are made of. The plain renderer keeps its
//! no-op recorder and pays nothing for this.
//!
//! With several samples per pixel, colors are averaged as the image's are (so
//! `local + reflected + refracted` still sums to the image), counts are summed
//! over the pixel's rays, the depth is the deepest of them, a total internal
//! reflection in any counts, and what belongs to the first hit (its normal,
//! distance, object, shadow rays, the discriminant) is the sample's nearest
//! the pixel's center (the center itself with an odd grid).

use glam::DVec3;

use crate::methods::Accel;
use crate::scene::Scene;
use crate::trace::aov::{Aov, AovImage, MAX_COMBINED_LIGHTS, Value};
use crate::trace::pixel_record::{SampleRecord, record_pixel};
use crate::trace::progress::Progress;
use crate::trace::recorder::{RayCounter, RayKind, ShadowOutcome};
use crate::trace::render::{Pixels, Stopped, trace_pixels};
use crate::trace::tracer::Tracer;

/// Renders `aov` for every pixel of `scene` at its settings through the one
/// pixel loop, each pixel recorded on its own ([`record_pixel`]), reporting
/// rows done to `progress`. The values are the same whatever the number of
/// threads.
pub fn render_aov(
    scene: &Scene,
    aov: Aov,
    progress: &Progress,
) -> Result<AovImage, std::collections::TryReserveError> {
    let tracer = Tracer::new(scene);
    let camera = scene.camera();
    let (width, height) = (scene.settings.width, scene.settings.height);
    let sphere = match aov {
        Aov::Discriminant(i) => Some(i),
        _ => None,
    };
    let traced = trace_pixels(
        scene,
        Pixels::All,
        || (),
        |_, x, y| {
            let record = record_pixel(&tracer, &camera, x, y, sphere);
            pixel_value(aov, &record.samples, &record.at, (x, y))
        },
        &Progress::reporting(&|done, total| progress.report(done, total)),
    )
    .map_err(|stopped| match stopped {
        Stopped::NoMemory(e) => e,
        Stopped::Cancelled => unreachable!("an AOV render reports but is never cancelled"),
    })?;
    let values = traced.cells;
    Ok(AovImage {
        aov,
        name: aov.name(scene),
        title: match aov {
            // What the counts count depends on the structure built.
            Aov::Tests => tests_title(scene.settings.accel, tracer.accelerator().kind()),
            _ => aov.title(scene),
        },
        key: aov.key(scene),
        undefined: aov.undefined(),
        note: aov.note(),
        width,
        height,
        values,
    })
}

/// The tests map's title, naming the method the counts come from: the
/// structure actually built (`auto` resolved), so a map made without a
/// hierarchy can never read as one made with it.
pub fn tests_title(requested: Accel, built: Accel) -> String {
    let how = if requested == Accel::Auto {
        format!("--accel auto: {}", built.name())
    } else {
        format!("--accel {}", built.name())
    };
    // Short enough for the title line of a narrow map.
    let what = match built {
        Accel::None | Accel::Auto => "every object",
        Accel::Bvh => "box tests + objects",
        Accel::Grid => "cells + objects",
        Accel::Octree | Accel::Bsp => "nodes + objects",
    };
    format!("intersection tests per pixel ({how}; {what})")
}

/// One pixel's value from its samples (see the module's documentation), `at`
/// holding where each sample went.
pub fn pixel_value(
    aov: Aov,
    samples: &[SampleRecord],
    at: &[(f64, f64)],
    (x, y): (u32, u32),
) -> Value {
    let mean = |term: fn(&SampleRecord) -> DVec3| {
        Value::Color(samples.iter().map(term).sum::<DVec3>() / samples.len().max(1) as f64)
    };
    let sum = |count: fn(&SampleRecord) -> u64| {
        Value::Number(samples.iter().map(count).sum::<u64>() as f64)
    };
    let centre = at
        .iter()
        .map(|&(sx, sy)| (sx - f64::from(x)).powi(2) + (sy - f64::from(y)).powi(2))
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map_or(0, |(i, _)| i);
    let Some(first) = samples.get(centre) else {
        return Value::Undefined;
    };
    match aov {
        Aov::Local => mean(|s| s.sum.local),
        Aov::Reflected => mean(|s| s.sum.k_rfl * s.sum.reflected),
        Aov::Refracted => mean(|s| s.sum.k_rfa * s.sum.refracted),
        Aov::Ambient | Aov::Diffuse | Aov::Specular => hit_mean(aov, samples),
        Aov::Depth => Value::Number(f64::from(
            samples.iter().map(|s| s.depth).max().unwrap_or(0),
        )),
        Aov::Rays(kind) => {
            Value::Number(samples.iter().map(|s| count(&s.rays, kind)).sum::<u64>() as f64)
        }
        Aov::Tests => sum(|s| s.tests),
        Aov::Tir => Value::Category(u32::from(samples.iter().any(|s| s.tir))),
        Aov::Discriminant(_) => Value::Number(first.discriminant),
        _ => first_hit_value(aov, first),
    }
}

/// The mean of a Phong term over the samples that hit something.
fn hit_mean(aov: Aov, samples: &[SampleRecord]) -> Value {
    let hits: Vec<&SampleRecord> = samples.iter().filter(|s| s.hit.is_some()).collect();
    if hits.is_empty() {
        return Value::Undefined;
    }
    let term = |s: &SampleRecord| match aov {
        Aov::Ambient => s.ambient,
        Aov::Diffuse => s.diffuse,
        _ => s.specular,
    };
    Value::Color(hits.iter().map(|s| term(s)).sum::<DVec3>() / hits.len() as f64)
}

/// A quantity of the primary ray's hit, from one sample.
fn first_hit_value(aov: Aov, s: &SampleRecord) -> Value {
    let (Some(hit), Some(ray)) = (s.hit, s.primary) else {
        return Value::Undefined;
    };
    match aov {
        Aov::Normal => Value::Color(hit.shading_normal),
        Aov::T => Value::Number(hit.t * ray.dir.length()),
        Aov::Object => Value::Category(hit.object as u32),
        Aov::Shadow(Some(light)) => Value::Category(match s.shadows[light] {
            ShadowOutcome::Reaches { transmitted } if transmitted >= 1.0 => 0,
            ShadowOutcome::Reaches { .. } => 1,
            ShadowOutcome::Blocked { .. } => 2,
            ShadowOutcome::FacesAway => 3,
        }),
        Aov::Shadow(None) => {
            let reached = |o: &ShadowOutcome| matches!(o, ShadowOutcome::Reaches { .. });
            let mask = (s.shadows.iter().enumerate())
                .filter(|(_, o)| reached(o))
                .fold(0u32, |m, (i, _)| m | 1 << i.min(31));
            if s.shadows.len() > MAX_COMBINED_LIGHTS {
                Value::Number(f64::from(mask.count_ones()))
            } else {
                Value::Category(mask)
            }
        }
        _ => Value::Undefined,
    }
}

fn count(rays: &RayCounter, kind: Option<RayKind>) -> u64 {
    match kind {
        None => rays.total(),
        Some(RayKind::Primary) => rays.primary,
        Some(RayKind::Reflected) => rays.reflected,
        Some(RayKind::Refracted) => rays.refracted,
        Some(RayKind::Shadow) => rays.shadow,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tests_title_names_the_structure_built() {
        let none = tests_title(Accel::None, Accel::None);
        assert!(
            none.contains("--accel none") && !none.contains("bvh"),
            "{none}"
        );
        let bvh = tests_title(Accel::Bvh, Accel::Bvh);
        assert!(bvh.contains("--accel bvh; box tests"), "{bvh}");
        let auto = tests_title(Accel::Auto, Accel::Bvh);
        assert!(auto.contains("--accel auto: bvh"), "{auto}");
        let grid = tests_title(Accel::Grid, Accel::Grid);
        assert!(grid.contains("--accel grid; cells + objects"), "{grid}");
        // The longest must fit a 640-pixel figure's title line, which cuts
        // "tests: " and the title at about 78 characters.
        for kind in [
            Accel::None,
            Accel::Bvh,
            Accel::Grid,
            Accel::Octree,
            Accel::Bsp,
        ] {
            let t = tests_title(Accel::Auto, kind);
            assert!(t.chars().count() <= 70, "{t}");
        }
    }
}
