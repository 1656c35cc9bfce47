//! Recording: trace one pixel (or one ray) exactly as the renderer does, with a
//! recorder that builds the ray tree from the tracer's events, and wrap the
//! trees in a trace document.

use glam::DVec3;

use crate::geometry::bvh::Tested;
use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::scene::source::SceneRef;
use crate::trace::pixel::pixel_color_at;
use crate::trace::recorder::{
    BranchInfo, ColorSum, HitInfo, LightTerm, RayKind, RayStart, Recorder, ShadowInfo,
    ShadowOutcome,
};
use crate::trace::tracer::Tracer;
use crate::tree::document::{Pixel, RayRef, Sample, Trace};
use crate::tree::ray_tree::{
    Child, Hit, LightShare, Local, ObjectTest, Outcome, RayNode, RayTree, ShadowRay, Sum,
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
    source: SceneRef,
    x: u32,
    y: u32,
    only: Option<u32>,
) -> Result<Trace, TraceError> {
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
    Ok(Trace {
        pixel: Some(Pixel { x, y }),
        ..Trace::new(scene, source, color, samples)
    })
}

/// Traces one ray as a primary ray (depth 1, weight 1, from the media around the eye).
pub fn ray(scene: &Scene, source: SceneRef, ray: Ray) -> Result<Trace, TraceError> {
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
    Ok(Trace {
        ray: Some(RayRef {
            origin: ray.origin,
            direction: ray.dir,
        }),
        ..Trace::new(scene, source, color, samples)
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
            tested: Tested::default(),
            hit: None,
            shadow_rays: Vec::new(),
            local: None,
            reflected: None,
            refracted: None,
            sum: Sum::default(),
        });
        self.stack.push(index);
    }

    fn object_tested(&mut self, object: usize, roots: &crate::geometry::hit::Roots) {
        let name = self.scene.objects[object].name.clone();
        self.top().tests.push(ObjectTest {
            object,
            name,
            roots: roots.as_slice().to_vec(),
        });
    }

    fn tested(&mut self, tested: &Tested) {
        self.top().tested = *tested;
    }

    fn hit(&mut self, hit: &HitInfo) {
        let object = &self.scene.objects[hit.object];
        let h = Hit {
            object: hit.object,
            name: object.name.clone(),
            material: self.scene.materials[object.material].name.clone(),
            t: hit.t,
            face: matches!(object.shape, crate::geometry::object::Shape::Mesh(_))
                .then_some(hit.part),
            point: hit.point,
            normal: hit.normal,
            shading_normal: hit.shading_normal,
            entering: hit.entering,
            n1: hit.n1,
            n2: hit.n2,
        };
        let node = self.top();
        node.hit = Some(h);
        node.local = Some(Local {
            ambient: DVec3::ZERO,
            lights: Vec::new(),
            total: DVec3::ZERO,
        });
    }

    fn shadow_ray(&mut self, s: &ShadowInfo) {
        let outcome = match s.outcome {
            ShadowOutcome::FacesAway => Outcome::FacesAway,
            ShadowOutcome::Reaches { transmitted } => Outcome::Reaches { transmitted },
            ShadowOutcome::Blocked { object, t } => Outcome::Blocked {
                object,
                name: self.scene.objects[object].name.clone(),
                t,
            },
        };
        let name = self.scene.lights[s.light].name.clone();
        self.top().shadow_rays.push(ShadowRay {
            light: s.light,
            name,
            origin: s.ray.origin,
            direction: s.ray.dir,
            t_max: s.t_max,
            outcome,
            tested: s.tested,
        });
    }

    fn light_term(&mut self, term: &LightTerm) {
        let name = self.scene.lights[term.light].name.clone();
        if let Some(local) = &mut self.top().local {
            local.lights.push(LightShare {
                light: term.light,
                name,
                diffuse: term.diffuse,
                specular: term.specular,
            });
        }
    }

    fn branch(&mut self, b: &BranchInfo) {
        let child = Some(Child {
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

    fn ray_finished(&mut self, sum: &ColorSum) {
        let node = self.top();
        if let Some(local) = &mut node.local {
            local.ambient = sum.ambient;
            local.total = sum.local;
        }
        node.sum = Sum {
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
