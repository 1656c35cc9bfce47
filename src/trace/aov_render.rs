//! Rendering a per-pixel quantity ([`crate::trace::aov`]): every pixel traced
//! exactly as the renderer traces it, through a recorder that keeps, for each
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
use indicatif::ProgressBar;
use rayon::prelude::*;

use crate::geometry::hit::TestCounts;
use crate::geometry::object::Shape;
use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::trace::aov::{Aov, AovImage, MAX_COMBINED_LIGHTS, Value};
use crate::trace::pixel::pixel_color_at;
use crate::trace::recorder::{
    Branch, BranchEvent, HitEvent, LightEvent, LocalEvent, RayCounter, RayKind, RayStart, Recorder,
    ShadowEvent, ShadowOutcome, SumEvent,
};
use crate::trace::tracer::Tracer;

/// What one primary ray's tree was made of, as far as any quantity needs.
#[derive(Clone, Debug, Default)]
pub struct SampleRecord {
    /// Rays open now: the primary ray's own events come while this is 1.
    open: u32,
    /// The deepest ray started.
    pub depth: u32,
    /// Rays cast, by kind.
    pub rays: RayCounter,
    /// Box and primitive tests of every ray, shadow rays too.
    pub tests: u64,
    /// The primary ray.
    pub primary: Option<Ray>,
    /// The primary ray's hit.
    pub hit: Option<HitEvent>,
    /// The ambient term at that hit.
    pub ambient: DVec3,
    /// The diffuse terms there, summed over the lights.
    pub diffuse: DVec3,
    /// The specular terms there, summed over the lights.
    pub specular: DVec3,
    /// Each light's shadow ray from that hit, in the scene's order.
    pub shadows: Vec<ShadowOutcome>,
    /// Whether a total internal reflection happened anywhere in the tree.
    pub tir: bool,
    /// The primary ray's sum.
    pub sum: SumEvent,
    /// `B² − AC` against the chosen sphere.
    pub discriminant: f64,
}

/// Keeps a [`SampleRecord`] per primary ray.
#[derive(Debug)]
pub struct AovRecorder<'s> {
    scene: &'s Scene,
    /// The sphere whose discriminant is wanted.
    sphere: Option<usize>,
    /// One per primary ray, in the order traced.
    pub samples: Vec<SampleRecord>,
}

impl<'s> AovRecorder<'s> {
    /// A recorder for `aov` in `scene`.
    pub fn new(scene: &'s Scene, aov: Aov) -> Self {
        let sphere = match aov {
            Aov::Discriminant(i) => Some(i),
            _ => None,
        };
        Self {
            scene,
            sphere,
            samples: Vec::new(),
        }
    }

    fn now(&mut self) -> &mut SampleRecord {
        self.samples.last_mut().expect("a primary ray was started")
    }

    /// Whether the events now belong to the primary ray itself.
    fn at_primary(&mut self) -> bool {
        self.now().open == 1
    }

    /// The lecture's `B² − AC` for `ray` against the chosen sphere, through
    /// the inverse-transformed ray when the sphere is transformed.
    fn discriminant(&self, ray: &Ray) -> f64 {
        let Some(object) = self.sphere.map(|i| &self.scene.objects[i]) else {
            return 0.0;
        };
        let Shape::Sphere(sphere) = &object.shape else {
            return 0.0;
        };
        let own = object
            .transform
            .as_ref()
            .map_or(*ray, |t| t.ray_to_object(ray));
        sphere.unit_quadratic(&own).discriminant
    }
}

impl Recorder for AovRecorder<'_> {
    const ENABLED: bool = true;

    fn ray_started(&mut self, start: &RayStart) {
        if start.kind == RayKind::Primary {
            let discriminant = self.discriminant(&start.ray);
            self.samples.push(SampleRecord {
                primary: Some(start.ray),
                discriminant,
                ..SampleRecord::default()
            });
        }
        let now = self.now();
        now.open += 1;
        now.depth = now.depth.max(start.depth);
        now.rays.ray_started(start);
    }

    fn tested(&mut self, tested: &TestCounts) {
        self.now().tests += u64::from(tested.boxes) + u64::from(tested.primitives);
    }

    fn hit(&mut self, hit: &HitEvent) {
        if self.at_primary() {
            self.now().hit = Some(*hit);
        }
    }

    fn shadow_ray(&mut self, shadow: &ShadowEvent) {
        let now = self.now();
        now.rays.shadow_ray(shadow);
        now.tests += u64::from(shadow.tested.boxes) + u64::from(shadow.tested.primitives);
        if now.open == 1 {
            now.shadows.push(shadow.outcome);
        }
    }

    fn local(&mut self, local: &LocalEvent) {
        if self.at_primary() {
            self.now().ambient = local.ambient;
        }
    }

    fn light_term(&mut self, term: &LightEvent) {
        if let (true, Some(phong)) = (self.at_primary(), term.phong) {
            let now = self.now();
            now.diffuse += phong.diffuse;
            now.specular += phong.specular;
        }
    }

    fn branch(&mut self, branch: &BranchEvent) {
        if branch.branch == Branch::TotalInternalReflection {
            self.now().tir = true;
        }
    }

    fn ray_finished(&mut self, sum: &SumEvent) {
        let now = self.now();
        if now.open == 1 {
            now.sum = *sum;
        }
        now.open -= 1;
    }
}

/// Renders `aov` for every pixel of `scene` at its settings, on all cores of
/// the current thread pool, reporting finished rows to `progress`. The values
/// are the same whatever the number of threads: each pixel is its own.
pub fn render_aov(
    scene: &Scene,
    aov: Aov,
    progress: &ProgressBar,
) -> Result<AovImage, std::collections::TryReserveError> {
    let tracer = Tracer::new(scene);
    let camera = scene.camera();
    let (width, height) = (scene.settings.width, scene.settings.height);
    let mut values = Vec::new();
    values.try_reserve_exact(width as usize * height as usize)?;
    values.resize(width as usize * height as usize, Value::Undefined);
    progress.set_length(u64::from(height));
    values
        .par_chunks_mut(width as usize)
        .enumerate()
        .for_each(|(y, row)| {
            for (x, value) in row.iter_mut().enumerate() {
                let mut rec = AovRecorder::new(scene, aov);
                let mut at = Vec::new();
                let (x, y) = (x as u32, y as u32);
                // Each pixel starts with no remembered blocker, as `raytree
                // trace` does: its counts are its own, whatever the threads.
                tracer.forget_recent();
                pixel_color_at(&tracer, &camera, x, y, &mut rec, Some(&mut at));
                *value = pixel_value(aov, &rec.samples, &at, (x, y));
            }
            progress.inc(1);
        });
    Ok(AovImage {
        aov,
        name: aov.name(scene),
        title: aov.title(scene),
        key: aov.key(scene),
        undefined: aov.undefined(),
        note: aov.note(),
        width,
        height,
        values,
    })
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
