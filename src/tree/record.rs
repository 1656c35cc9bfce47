//! Recording: trace one pixel (or one ray) exactly as the renderer does, with a
//! recorder that builds the ray tree from the tracer's events, and wrap the
//! trees in a trace document.

use glam::DVec3;

use crate::geometry::hit::TestCounts;
use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::scene::source::SceneSource;
use crate::trace::pixel::pixel_color_at;
use crate::trace::recorder::{
    BranchEvent, HitEvent, LightEvent, RayKind, RayStart, Recorder, ShadowEvent, ShadowOutcome,
    SumEvent,
};
use crate::trace::tracer::Tracer;
use crate::tree::document::{GivenRay, Pixel, Sample, TraceDocument};
use crate::tree::ray_tree::{
    BranchRecord, HitRecord, LightRecord, LocalRecord, RayNode, RayTree, ShadowOutcomeRecord,
    ShadowRecord, SumRecord, TestRecord,
};

/// Why a trace could not be made.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum TraceError {
    /// The pixel is not in the image.
    #[error("pixel {x},{y} is outside the {width}×{height} image (x is 0 to {}, y is 0 to {})", width - 1, height - 1)]
    PixelOutside {
        /// Column asked for.
        x: u32,
        /// Row asked for.
        y: u32,
        /// Image width.
        width: u32,
        /// Image height.
        height: u32,
    },
    /// The sample is not one of the pixel's.
    #[error("sample {sample} does not exist: a pixel has {spp} samples (0 to {})", spp - 1)]
    SampleOutside {
        /// Sample asked for.
        sample: u32,
        /// Samples per pixel.
        spp: u32,
    },
    /// The ray cannot be traced.
    #[error("the ray's direction must be non-zero and every number finite")]
    BadRay,
}

/// Traces pixel `(x, y)` (image coordinates) exactly as the renderer does,
/// recording every sample, or only sample `only` if given.
pub fn pixel(
    scene: &Scene,
    source: SceneSource,
    x: u32,
    y: u32,
    only: Option<u32>,
) -> Result<TraceDocument, TraceError> {
    let s = scene.settings;
    if x >= s.width || y >= s.height {
        return Err(TraceError::PixelOutside {
            x,
            y,
            width: s.width,
            height: s.height,
        });
    }
    let mut rec = TreeRecorder::new(scene);
    let mut at = Vec::new();
    let color = pixel_color_at(
        &Tracer::new(scene),
        &scene.camera(),
        x,
        y,
        &mut rec,
        Some(&mut at),
    );
    if let Some(sample) = only.filter(|&k| k as usize >= at.len()) {
        return Err(TraceError::SampleOutside {
            sample,
            spp: at.len() as u32,
        });
    }
    let samples = at
        .into_iter()
        .zip(rec.trees)
        .enumerate()
        .map(|(k, ((sx, sy), tree))| Sample {
            index: k as u32,
            position: Some([sx, sy]),
            color: tree.nodes[0].color(),
            tree,
        })
        .filter(|sample| only.is_none_or(|k| k == sample.index))
        .collect();
    Ok(TraceDocument {
        pixel: Some(Pixel { x, y }),
        ..TraceDocument::new(scene, source, color, samples)
    })
}

/// Traces one ray as a primary ray (depth 1, weight 1, from the media around the eye).
pub fn ray(scene: &Scene, source: SceneSource, ray: Ray) -> Result<TraceDocument, TraceError> {
    if !(ray.origin.is_finite() && ray.dir.is_finite())
        || ray.dir.length_squared() == 0.0
        || !ray.dir.length_squared().is_finite()
    {
        return Err(TraceError::BadRay);
    }
    let mut rec = TreeRecorder::new(scene);
    let color = Tracer::new(scene).trace_primary(ray, &mut rec);
    let tree = rec.trees.pop().unwrap_or_default();
    let samples = vec![Sample {
        index: 0,
        position: None,
        color,
        tree,
    }];
    Ok(TraceDocument {
        ray: Some(GivenRay {
            origin: ray.origin,
            direction: ray.dir,
        }),
        ..TraceDocument::new(scene, source, color, samples)
    })
}

/// Builds a ray tree per primary ray from the tracer's events.
#[derive(Debug)]
pub struct TreeRecorder<'s> {
    scene: &'s Scene,
    /// One tree per primary ray traced, in order.
    pub trees: Vec<RayTree>,
    /// The open rays, innermost last.
    stack: Vec<usize>,
}

impl<'s> TreeRecorder<'s> {
    /// A recorder naming objects and lights from `scene`.
    pub fn new(scene: &'s Scene) -> Self {
        Self {
            scene,
            trees: Vec::new(),
            stack: Vec::new(),
        }
    }

    fn nodes(&mut self) -> &mut Vec<RayNode> {
        &mut self
            .trees
            .last_mut()
            .expect("a primary ray was started")
            .nodes
    }

    fn top(&mut self) -> &mut RayNode {
        let i = *self.stack.last().expect("inside a ray");
        &mut self.nodes()[i]
    }
}

impl Recorder for TreeRecorder<'_> {
    const ENABLED: bool = true;

    fn ray_started(&mut self, start: &RayStart) {
        if start.kind == RayKind::Primary {
            self.trees.push(RayTree::default());
            self.stack.clear();
        }
        let parent = self.stack.last().copied();
        let index = self.nodes().len();
        if let Some(p) = parent {
            let node = &mut self.nodes()[p];
            let branch = if start.kind == RayKind::Reflected {
                &mut node.reflected
            } else {
                &mut node.refracted
            };
            if let Some(child) = branch {
                child.node = Some(index);
            }
        }
        self.nodes().push(RayNode {
            kind: start.kind,
            depth: start.depth,
            parent,
            origin: start.ray.origin,
            direction: start.ray.dir,
            weight: start.weight,
            t_min: start.t_min,
            t_max: start.t_max.is_finite().then_some(start.t_max),
            tests: Vec::new(),
            tested: TestCounts::default(),
            hit: None,
            shadow_rays: Vec::new(),
            local: None,
            reflected: None,
            refracted: None,
            sum: SumRecord::default(),
        });
        self.stack.push(index);
    }

    fn object_tested(&mut self, object: usize, roots: &crate::geometry::hit::Roots) {
        let name = self.scene.objects[object].name.clone();
        self.top().tests.push(TestRecord {
            object,
            name,
            roots: roots.as_slice().to_vec(),
        });
    }

    fn tested(&mut self, tested: &TestCounts) {
        self.top().tested = *tested;
    }

    fn hit(&mut self, hit: &HitEvent) {
        let object = &self.scene.objects[hit.object];
        let h = HitRecord {
            object: hit.object,
            name: object.name.clone(),
            material: self.scene.materials[object.material].name.clone(),
            t: hit.t,
            face: matches!(object.shape, crate::geometry::object::Shape::Mesh(_))
                .then_some(hit.face),
            point: hit.point,
            normal: hit.normal,
            shading_normal: hit.shading_normal,
            entering: hit.entering,
            n1: hit.n1,
            n2: hit.n2,
        };
        let node = self.top();
        node.hit = Some(h);
        node.local = Some(LocalRecord {
            ambient: DVec3::ZERO,
            lights: Vec::new(),
            total: DVec3::ZERO,
        });
    }

    fn shadow_ray(&mut self, s: &ShadowEvent) {
        let outcome = match s.outcome {
            ShadowOutcome::FacesAway => ShadowOutcomeRecord::FacesAway,
            ShadowOutcome::Reaches { transmitted } => ShadowOutcomeRecord::Reaches { transmitted },
            ShadowOutcome::Blocked { object, t } => ShadowOutcomeRecord::Blocked {
                object,
                name: self.scene.objects[object].name.clone(),
                t,
            },
        };
        let name = self.scene.lights[s.light].name.clone();
        self.top().shadow_rays.push(ShadowRecord {
            light: s.light,
            name,
            origin: s.ray.origin,
            direction: s.ray.dir,
            t_max: s.t_max,
            outcome,
            tested: s.tested,
        });
    }

    fn light_term(&mut self, term: &LightEvent) {
        let name = self.scene.lights[term.light].name.clone();
        if let Some(local) = &mut self.top().local {
            local.lights.push(LightRecord {
                light: term.light,
                name,
                diffuse: term.diffuse,
                specular: term.specular,
            });
        }
    }

    fn branch(&mut self, b: &BranchEvent) {
        let child = Some(BranchRecord {
            coefficient: b.coefficient,
            outcome: b.branch,
            node: None,
        });
        let node = self.top();
        match b.kind {
            RayKind::Reflected => node.reflected = child,
            _ => node.refracted = child,
        }
    }

    fn ray_finished(&mut self, sum: &SumEvent) {
        let node = self.top();
        if let Some(local) = &mut node.local {
            local.ambient = sum.ambient;
            local.total = sum.local;
        }
        node.sum = SumRecord {
            local: sum.local,
            k_rfl: sum.k_rfl,
            reflected: sum.reflected,
            k_rfa: sum.k_rfa,
            refracted: sum.refracted,
            color: sum.color,
        };
        self.stack.pop();
    }
}
