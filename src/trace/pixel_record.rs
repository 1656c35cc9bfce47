//! One pixel's record: what each of its primary rays' trees was made of, as
//! far as any per-pixel quantity needs (the AOVs, the inspector's overlays and
//! finds). One recorder for all of them, so a count shown in two places is the
//! same count. A pixel is recorded as `raytree trace` records it: with no
//! shadow blocker remembered from the pixel before, so its counts are its own
//! whatever the threads.

use glam::DVec3;

use crate::geometry::hit::TestCounts;
use crate::geometry::object::Shape;
use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::scene::camera::Camera;
use crate::trace::pixel::pixel_color_at;
use crate::trace::recorder::{
    Branch, BranchEvent, HitEvent, LightEvent, LocalEvent, RayCounter, RayKind, RayStart, Recorder,
    ShadowEvent, ShadowOutcome, SumEvent,
};
use crate::trace::tracer::Tracer;

/// A pixel's samples and where each went (image coordinates), in the order traced.
#[derive(Clone, Debug, Default)]
pub struct PixelRecord {
    /// One per primary ray.
    pub samples: Vec<SampleRecord>,
    /// Where each primary ray went.
    pub at: Vec<(f64, f64)>,
}

/// Records pixel `(x, y)` from scratch (no remembered blocker); `sphere` as
/// for [`PixelRecorder::new`].
pub fn record_pixel(
    tracer: &Tracer,
    camera: &Camera,
    x: u32,
    y: u32,
    sphere: Option<usize>,
) -> PixelRecord {
    let mut rec = PixelRecorder::new(tracer.scene(), sphere);
    let mut at = Vec::new();
    tracer.forget_recent();
    pixel_color_at(tracer, camera, x, y, &mut rec, Some(&mut at));
    PixelRecord {
        samples: rec.samples,
        at,
    }
}

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
    /// Whether a shadow ray was blocked anywhere in the tree.
    pub blocked: bool,
    /// Whether a refracted ray was traced anywhere in the tree.
    pub refraction: bool,
    /// Whether the weight cutoff skipped a branch anywhere in the tree.
    pub cutoff: bool,
    /// The primary ray's sum.
    pub sum: SumEvent,
    /// `B² − AC` against the chosen sphere.
    pub discriminant: f64,
}

/// Keeps a [`SampleRecord`] per primary ray.
#[derive(Debug)]
pub struct PixelRecorder<'s> {
    scene: &'s Scene,
    /// The sphere whose discriminant is wanted.
    sphere: Option<usize>,
    /// One per primary ray, in the order traced.
    pub samples: Vec<SampleRecord>,
}

impl<'s> PixelRecorder<'s> {
    /// A recorder in `scene`, working out `B² − AC` against object `sphere`
    /// when it is a sphere.
    pub fn new(scene: &'s Scene, sphere: Option<usize>) -> Self {
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

impl Recorder for PixelRecorder<'_> {
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
        now.blocked |= matches!(shadow.outcome, ShadowOutcome::Blocked { .. });
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
        let now = self.now();
        match branch.branch {
            Branch::TotalInternalReflection => now.tir = true,
            Branch::WeightCutoff => now.cutoff = true,
            Branch::Traced if branch.kind == RayKind::Refracted => now.refraction = true,
            _ => {}
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
