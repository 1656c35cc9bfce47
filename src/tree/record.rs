//! Recording: trace one pixel (or one ray) exactly as the renderer does, with a
//! recorder that builds the ray tree from the tracer's events, and wrap the
//! trees in a trace document.

use std::sync::Arc;

use glam::DVec3;

use crate::geometry::hit::{Roots, TestCounts};
use crate::geometry::object::Shape;
use crate::math::ray::Ray;
use crate::methods::{Antialiasing, Offset};
use crate::scene::Scene;
use crate::scene::settings::{RenderSettings, ray_count};
use crate::scene::source::SceneSource;
use crate::trace::pixel::pixel_color_at;
use crate::trace::recorder::{
    BoxVisit, BranchEvent, HitEvent, LightEvent, LocalEvent, RayKind, RayStart, Recorder,
    ShadowEvent, ShadowOutcome, SumEvent,
};
use crate::trace::tracer::Tracer;
use crate::tree::arithmetic::{Fate, RootRecord, TUnit, camera_stage, fates, hit_optics};
use crate::tree::document::{GivenRay, ObjectEntry, Pixel, Sample, TraceDocument, object_entries};
use crate::tree::ray_tree::{
    BoxRecord, BranchRecord, HitRecord, LightRecord, LocalRecord, PhongRecord, Placement, RayNode,
    RayTree, RecentRecord, ShadowOutcomeRecord, ShadowRecord, SumRecord, TestRecord,
};
use crate::tree::shape_arithmetic::object_test;
use crate::tree::trace_check::MAX_TRACE_RAYS;

/// Why a trace could not be made.
#[derive(Debug, thiserror::Error, PartialEq)]
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
    #[error("sample {} does not exist: {}", index + 1, if *spp == 1 { "a pixel has 1 sample".to_owned() } else { format!("a pixel has {spp} samples (1 to {spp})") })]
    SampleOutside {
        /// Index of the sample asked for (0 is the first).
        index: u32,
        /// Samples per pixel.
        spp: u32,
    },
    /// The ray cannot be traced.
    #[error("the ray's direction must be non-zero and every number finite")]
    BadRay,
    /// The trees may grow beyond what a trace document holds.
    #[error("{}", too_many_rays(what, *samples, *rays, lower))]
    TooManyRays {
        /// `pixel X,Y` or `the ray`.
        what: String,
        /// Samples recorded.
        samples: u32,
        /// The most rays they may trace in all.
        rays: f64,
        /// The settings to lower (the cutoff may be raised instead).
        lower: &'static str,
    },
}

fn too_many_rays(what: &str, samples: u32, rays: f64, lower: &str) -> String {
    let each = if samples == 1 {
        String::new()
    } else {
        let each = ray_count(rays / f64::from(samples));
        format!(" ({samples} samples of up to {each})")
    };
    format!(
        "{what} may record up to {} rays{each}, more than the {MAX_TRACE_RAYS} a trace holds (and raytree reads back); lower {lower}, or raise the cutoff",
        ray_count(rays)
    )
}

/// The most rays recording `samples` samples under `settings` may make, in
/// the worst case ([`RenderSettings::worst_case_rays`] each), refused when
/// beyond what a trace document holds ([`MAX_TRACE_RAYS`], the reader's
/// limit): checked before tracing, so a request that could fill the memory
/// or write a trace raytree cannot read back ends at once with the estimate.
pub fn worst_case_rays(
    settings: &RenderSettings,
    samples: u32,
    what: impl FnOnce() -> String,
) -> Result<f64, TraceError> {
    let rays = f64::from(samples) * settings.worst_case_rays();
    if rays > MAX_TRACE_RAYS as f64 {
        let lower = match settings.aa {
            _ if samples == 1 => "max_depth",
            Antialiasing::Grid => "spp or max_depth",
            Antialiasing::Corners => "max_depth",
            Antialiasing::Adaptive { .. } => "the adaptive levels or max_depth",
        };
        return Err(TraceError::TooManyRays {
            what: what(),
            samples,
            rays,
            lower,
        });
    }
    Ok(rays)
}

/// Traces pixel `(x, y)` (image coordinates) exactly as the renderer does,
/// recording every sample, or only the one of index `only` (0 is the first).
pub fn pixel(
    scene: &Scene,
    source: SceneSource,
    x: u32,
    y: u32,
    only: Option<u32>,
) -> Result<TraceDocument, TraceError> {
    pixel_with(
        &Tracer::new(scene),
        object_entries(scene),
        source,
        x,
        y,
        only,
    )
}

/// [`pixel`], traced by `tracer` (made beforehand for the scene from what it
/// keeps, [`crate::trace::tracer::Prepared`]) and naming the scene's
/// `objects` (its [`object_entries`], made beforehand), so that recording
/// costs the pixel alone: the inspector records a pixel per key.
pub fn pixel_with(
    tracer: &Tracer,
    objects: Arc<[ObjectEntry]>,
    source: SceneSource,
    x: u32,
    y: u32,
    only: Option<u32>,
) -> Result<TraceDocument, TraceError> {
    let scene = tracer.scene();
    let s = scene.settings;
    if x >= s.width || y >= s.height {
        return Err(TraceError::PixelOutside {
            x,
            y,
            width: s.width,
            height: s.height,
        });
    }
    // Every sample is recorded, the one kept with `only` among them.
    worst_case_rays(&s, s.max_samples(), || format!("pixel {x},{y}"))?;
    let mut rec = TreeRecorder::new(scene, TUnit::ImagePlane);
    let mut at = Vec::new();
    let camera = scene.camera();
    let color = pixel_color_at(tracer, &camera, x, y, &mut rec, Some(&mut at));
    if let Some(sample) = only.filter(|&k| k as usize >= at.len()) {
        return Err(TraceError::SampleOutside {
            index: sample,
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
            camera: Some(camera_stage(&camera, (x, y), (sx, sy))),
            color: tree.nodes[0].color(),
            tree,
        })
        .filter(|sample| only.is_none_or(|k| k == sample.index))
        .collect();
    Ok(TraceDocument {
        pixel: Some(Pixel { x, y }),
        ..TraceDocument::sharing(
            objects,
            scene,
            tracer.accelerator().kind(),
            source,
            color,
            samples,
        )
    })
}

/// Traces one ray as a primary ray (depth 1, weight 1), starting in the media
/// around its origin (inside a glass ball, in glass).
pub fn ray(scene: &Scene, source: SceneSource, ray: Ray) -> Result<TraceDocument, TraceError> {
    if !(ray.origin.is_finite() && ray.dir.is_finite())
        || ray.dir.length_squared() == 0.0
        || !ray.dir.length_squared().is_finite()
    {
        return Err(TraceError::BadRay);
    }
    worst_case_rays(&scene.settings, 1, || "the ray".to_owned())?;
    let mut rec = TreeRecorder::new(scene, TUnit::Direction);
    let tracer = Tracer::new(scene);
    let color = tracer.trace_given(ray, &mut rec);
    let tree = rec.trees.pop().unwrap_or_default();
    let samples = vec![Sample {
        index: 0,
        position: None,
        camera: None,
        color,
        tree,
    }];
    Ok(TraceDocument {
        ray: Some(GivenRay {
            origin: ray.origin,
            direction: ray.dir,
        }),
        ..TraceDocument::new(scene, tracer.accelerator().kind(), source, color, samples)
    })
}

/// Builds a ray tree per primary ray from the tracer's events, working out the
/// lecture's arithmetic of each step as it goes ([`crate::tree::arithmetic`]).
#[derive(Debug)]
pub struct TreeRecorder<'s> {
    scene: &'s Scene,
    /// What `t` counts along the primary rays.
    primary_unit: TUnit,
    /// One tree per primary ray traced, in order.
    pub trees: Vec<RayTree>,
    /// The open rays, innermost last.
    stack: Vec<usize>,
}

impl<'s> TreeRecorder<'s> {
    /// A recorder naming objects and lights from `scene`; `primary_unit` says
    /// what `t` counts along the primary rays (the image plane for a pixel).
    pub fn new(scene: &'s Scene, primary_unit: TUnit) -> Self {
        Self {
            scene,
            primary_unit,
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

    /// The object the current ray leaves: its parent's hit (none for a primary ray).
    fn leaving(&mut self) -> Option<usize> {
        let parent = self.top().parent?;
        self.nodes()[parent].hit.as_ref().map(|h| h.object)
    }

    /// How close to its origin a root must be to lie on the surface the ray
    /// leaves: the origin sits just past that surface, by the point's error bound
    /// (about 1e-15 of its size) or by the epsilon the settings ask for.
    fn start_tolerance(&self, origin: DVec3) -> f64 {
        let epsilon = match self.scene.settings.offset {
            Offset::Epsilon(e) => 2.0 * e,
            Offset::None | Offset::Robust => 0.0,
        };
        epsilon + 1e-9 * (1.0 + origin.abs().max_element())
    }

    /// Marks what became of every root of the current ray's tests.
    fn settle_roots(&mut self) {
        let start = self.leaving();
        let origin = self.top().origin;
        let tolerance = self.start_tolerance(origin);
        let node = self.top();
        let hit = node.hit.as_ref().map(|h| (h.object, h.t));
        let interval = (node.t_min, node.t_max);
        let length = node.direction.length();
        for test in &mut node.tests {
            let ts: Vec<f64> = test.roots.iter().map(|r| r.t).collect();
            test.roots = fates(&ts, test.object, hit, interval, start, (length, tolerance));
        }
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
        let t_unit = if start.kind == RayKind::Primary {
            self.primary_unit
        } else {
            TUnit::Distance
        };
        self.nodes().push(RayNode {
            kind: start.kind,
            depth: start.depth,
            parent,
            origin: start.ray.origin,
            direction: start.ray.dir,
            t_unit,
            weight: start.weight,
            t_min: start.t_min,
            t_max: start.t_max.is_finite().then_some(start.t_max),
            tests: Vec::new(),
            tested: TestCounts::default(),
            boxes: Vec::new(),
            hit: None,
            shadow_rays: Vec::new(),
            local: None,
            reflected: None,
            refracted: None,
            sum: SumRecord::default(),
        });
        self.stack.push(index);
    }

    fn object_tested(&mut self, object: usize, roots: &Roots) {
        let scene = self.scene;
        let node = self.top();
        let ray = Ray::new(node.origin, node.direction);
        let methods = scene.settings.intersection_methods();
        let (method, object_ray, arithmetic) =
            object_test(&scene.objects[object], &ray, methods, roots);
        let roots = roots
            .as_slice()
            .iter()
            .map(|&t| RootRecord {
                t,
                fate: Fate::Farther,
                at_start: false,
            })
            .collect();
        node.tests.push(TestRecord {
            object,
            name: scene.objects[object].name.clone(),
            method,
            object_ray,
            arithmetic,
            roots,
        });
    }

    fn tested(&mut self, tested: &TestCounts) {
        self.top().tested = *tested;
    }

    fn boxes_visited(&mut self, boxes: &[BoxVisit]) {
        self.top().boxes = boxes
            .iter()
            .map(|b| BoxRecord {
                min: b.bounds.min,
                max: b.bounds.max,
                met: b.met,
                after_tests: b.after_tests,
            })
            .collect();
    }

    fn hit(&mut self, hit: &HitEvent) {
        let scene = self.scene;
        let object = &scene.objects[hit.object];
        let material = &scene.materials[object.material];
        let node = self.top();
        let (incoming, n_dot_c, mirror, refraction) = hit_optics(
            node.direction,
            hit.shading_normal,
            (hit.n1, hit.n2),
            material.transparent > 0.0,
        );
        let transform = object.transform.as_deref();
        // N ∝ (M⁻¹)ᵀn', so n' ∝ MᵀN: the object normal back from the world one.
        let object_normal =
            transform.map(|tf| (tf.to_world.matrix3.transpose() * hit.normal).normalize());
        let normal_like_point = transform
            .zip(object_normal)
            .map(|(tf, n)| (tf.to_world.matrix3 * n).normalize());
        node.hit = Some(HitRecord {
            object: hit.object,
            name: object.name.clone(),
            material: material.name.clone(),
            t: hit.t,
            face: matches!(object.shape, Shape::Mesh(_)).then_some(hit.face),
            on_ray: Ray::new(node.origin, node.direction).at(hit.t),
            placement: match object.shape {
                Shape::Sphere(_) => Placement::OntoSphere,
                Shape::Plane(_) | Shape::Polygon(_) => Placement::OntoPlane,
                Shape::Box(_) => Placement::OntoBoxFace,
                Shape::Triangle(_) | Shape::Mesh(_) => Placement::FromCorners,
                Shape::Cone(_) => Placement::OntoCone,
            },
            point: hit.point,
            object_point: transform.map(|tf| tf.to_object.transform_point3(hit.point)),
            object_normal,
            normal_like_point,
            normal: hit.normal,
            shading_normal: hit.shading_normal,
            entering: hit.entering,
            n1: hit.n1,
            n2: hit.n2,
            incoming,
            n_dot_c,
            mirror,
            refraction,
        });
    }

    fn local(&mut self, local: &LocalEvent) {
        let scene = self.scene;
        let node = self.top();
        let Some(hit) = &node.hit else { return };
        let material = scene.material_of(hit.object);
        node.local = Some(LocalRecord {
            color: local.color,
            k_a: material.ambient,
            k_d: material.diffuse,
            k_s: material.specular,
            shininess: material.shininess,
            ambient_light: scene.ambient_light,
            ambient: local.ambient,
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
        let recent = s.recent.map(|r| RecentRecord {
            object: r.object,
            name: self.scene.objects[r.object].name.clone(),
            blocks: r.blocks,
        });
        self.top().shadow_rays.push(ShadowRecord {
            light: s.light,
            name,
            origin: s.ray.origin,
            direction: s.ray.dir,
            t_max: s.t_max,
            outcome,
            tested: s.tested,
            recent,
        });
    }

    fn light_term(&mut self, term: &LightEvent) {
        let name = self.scene.lights[term.light].name.clone();
        let phong = term.phong.map(|d| PhongRecord {
            l: d.to_light,
            n_dot_l: d.n_dot_l,
            r: d.mirrored,
            v: d.to_viewer,
            r_dot_v: d.r_dot_v,
            arriving: d.light,
        });
        let (diffuse, specular) = term
            .phong
            .map_or((DVec3::ZERO, DVec3::ZERO), |d| (d.diffuse, d.specular));
        if let Some(local) = &mut self.top().local {
            local.lights.push(LightRecord {
                light: term.light,
                name,
                phong,
                diffuse,
                specular,
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
        self.settle_roots();
        let node = self.top();
        if let Some(local) = &mut node.local {
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
