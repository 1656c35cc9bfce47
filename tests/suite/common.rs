//! Helpers shared by the integration tests.

use glam::DVec3;
use raytree::scene::Scene;
use raytree::trace::recorder::{HitEvent, RayKind, RayStart, Recorder, ShadowEvent};

/// Parses a scene written inline in a test.
pub fn scene(json: &str) -> Scene {
    raytree::scene::loader::parse(json, "test.json").unwrap_or_else(|e| panic!("{e}"))
}

/// The shipped scenes, by file name.
pub fn shipped() -> Vec<(&'static str, Scene)> {
    ["whitted.json", "nested.json", "ellipsoids.json"]
        .into_iter()
        .map(|name| {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("scenes")
                .join(name);
            (
                name,
                raytree::scene::loader::load(&path).unwrap_or_else(|e| panic!("{e}")),
            )
        })
        .collect()
}

/// Keeps every event of interest, flat, in the order the tracer sent them.
#[derive(Default)]
pub struct Log {
    pub rays: Vec<RayStart>,
    pub hits: Vec<HitEvent>,
    pub shadows: Vec<ShadowEvent>,
    pub branches: Vec<raytree::trace::recorder::BranchEvent>,
    pub colors: Vec<raytree::trace::recorder::SumEvent>,
}

impl Recorder for Log {
    const ENABLED: bool = true;
    fn ray_started(&mut self, start: &RayStart) {
        self.rays.push(*start);
    }
    fn hit(&mut self, hit: &HitEvent) {
        self.hits.push(*hit);
    }
    fn shadow_ray(&mut self, shadow: &ShadowEvent) {
        self.shadows.push(*shadow);
    }
    fn branch(&mut self, branch: &raytree::trace::recorder::BranchEvent) {
        self.branches.push(*branch);
    }
    fn ray_finished(&mut self, sum: &raytree::trace::recorder::SumEvent) {
        self.colors.push(*sum);
    }
}

impl Log {
    /// The rays of one kind.
    pub fn of_kind(&self, kind: RayKind) -> Vec<RayStart> {
        self.rays
            .iter()
            .filter(|r| r.kind == kind)
            .copied()
            .collect()
    }
}

/// Whether two colors agree to `tol` in every channel.
pub fn close(a: DVec3, b: DVec3, tol: f64) -> bool {
    (a - b).abs().max_element() <= tol
}
