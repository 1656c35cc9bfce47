//! The lecture's recursive `raytrace(ray)`:
//!
//! ```text
//! P = closest intersection
//! color_local   = ambient + Σ over lights a shadow ray reaches (diffuse + specular)
//! color_reflect = raytrace(reflected ray)
//! color_refract = raytrace(refracted ray)
//! color = color_local + k_rfl·color_reflect + k_rfa·color_refract
//! ```
//!
//! One tracer serves rendering and recording: every step reports to a
//! [`Recorder`], which is free when it is [`crate::trace::recorder::NoRecorder`].
//!
//! Choices the lecture leaves open:
//! - **Transparent shadows.** A shadow ray passes through a transparent object and
//!   keeps `k_rfa` of the light per object crossed, without bending (as POV-Ray
//!   does without photons); an opaque object blocks it. A glass sphere so casts a
//!   lighter shadow, not a black one.
//! - **Total internal reflection** sends the refracted share to the reflected ray.
//! - **Recursion** stops at `max_depth` or when a branch's weight falls below the
//!   cutoff (Hall & Greenberg, "A Testbed for Realistic Image Synthesis", 1983).

#![cfg_attr(raytree_no_hooks, allow(unused_variables, unused_imports))]

use std::ops::ControlFlow;
use std::sync::Arc;

use glam::DVec3;

use crate::geometry::hit::TestCounts;
use crate::geometry::hit::{Search, Surface};
use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::shading::material::Material;
use crate::shading::optics::{self, Media, Shares};
use crate::shading::phong;
use crate::trace::accelerator::{Accelerator, Candidate};
use crate::trace::recent::RecentBlockers;
use crate::trace::recorder::{
    BoxVisit, Branch, BranchEvent, HitEvent, LightEvent, LocalEvent, NoRecorder, RayKind, RayStart,
    RecentTry, Recorder, ShadowEvent, ShadowOutcome, SumEvent,
};

/// A shadow ray ends at `t = 1 - SHADOW_EPSILON` of the way to its light, so a
/// surface the light sits exactly on does not shadow it. Relative, so it needs no
/// tuning to the scene's size.
pub const SHADOW_EPSILON: f64 = 1e-9;

/// Where a shadow ray ends: `t = 1` is the light.
const SHADOW_T_MAX: f64 = 1.0 - SHADOW_EPSILON;

/// Traces rays through one scene.
#[derive(Clone, Debug)]
pub struct Tracer<'s> {
    scene: &'s Scene,
    eye_media: Media,
    accel: Arc<Accelerator>,
    recent: RecentBlockers,
}

/// What a tracer makes of its scene's objects before the first ray: the
/// accelerator and the media around the eye. A caller that makes tracer after
/// tracer for the same objects keeps it (the inspector traces a pixel per key,
/// and a million objects' hierarchy takes most of a second to build).
#[derive(Clone, Debug)]
pub struct Prepared {
    eye_media: Media,
    accel: Arc<Accelerator>,
}

impl Prepared {
    /// Builds both for `scene`.
    pub fn new(scene: &Scene) -> Self {
        Self {
            eye_media: scene.media_at(scene.camera().eye),
            accel: Arc::new(Accelerator::new(scene)),
        }
    }

    /// For `scene`, which has the objects and structure settings this was
    /// prepared for but perhaps other materials or settings: the accelerator
    /// kept, the media around the eye found again (a transparency may have
    /// changed).
    pub fn for_edited(&self, scene: &Scene) -> Self {
        Self {
            eye_media: scene.media_at(scene.camera().eye),
            accel: Arc::clone(&self.accel),
        }
    }
}

impl<'s> Tracer<'s> {
    /// A tracer for `scene` with its current render settings.
    pub fn new(scene: &'s Scene) -> Self {
        Self::prepared(scene, &Prepared::new(scene))
    }

    /// A tracer for `scene`, for which `prepared` was made ([`Prepared::new`]
    /// or [`Prepared::for_edited`]), building nothing; it remembers no
    /// blockers yet, as a new tracer.
    pub fn prepared(scene: &'s Scene, prepared: &Prepared) -> Self {
        Self {
            scene,
            eye_media: prepared.eye_media,
            accel: Arc::clone(&prepared.accel),
            recent: RecentBlockers::new(),
        }
    }

    /// A tracer for `scene`, which has this tracer's objects and structure
    /// settings (`accel`, `grid_res`, `tree_depth`) but other render settings, sharing this one's accelerator
    /// instead of building it again (a sweep over settings builds it once).
    pub fn with_settings<'t>(&self, scene: &'t Scene) -> Tracer<'t> {
        debug_assert!(scene.objects.len() == self.scene.objects.len());
        let structure = |s: &Scene| (s.settings.accel, s.settings.grid_res, s.settings.tree_depth);
        debug_assert!(structure(scene) == structure(self.scene));
        Tracer {
            scene,
            eye_media: self.eye_media,
            accel: Arc::clone(&self.accel),
            recent: RecentBlockers::new(),
        }
    }

    /// How the objects are arranged for the rays.
    pub fn accelerator(&self) -> &Accelerator {
        &self.accel
    }

    /// The scene being traced.
    pub fn scene(&self) -> &'s Scene {
        self.scene
    }

    /// Traces a ray from the eye: depth 1, weight 1, in the media around the eye.
    pub fn trace_primary<R: Recorder>(&self, ray: Ray, rec: &mut R) -> DVec3 {
        self.raytrace(&primary(ray), &self.eye_media, rec)
    }

    /// Traces a ray given by hand as a primary ray (depth 1, weight 1), in the
    /// media around its own origin: a ray started inside glass is in glass.
    pub fn trace_given<R: Recorder>(&self, ray: Ray, rec: &mut R) -> DVec3 {
        let media = self.scene.media_at(ray.origin);
        self.raytrace(&primary(ray), &media, rec)
    }

    /// Forgets the blockers this thread remembered ("try the recent hit
    /// first"), so the next pixel's test counts are its own.
    pub fn forget_recent(&self) {
        self.recent.forget();
    }

    /// The lecture's `raytrace(ray)`, one line of its pseudo-code (in the module
    /// documentation) per comment below; `media` are the transparent objects the
    /// ray travels inside, for the refractive indices at its hit.
    pub fn raytrace<R: Recorder>(&self, start: &RayStart, media: &Media, rec: &mut R) -> DVec3 {
        crate::record!(rec.ray_started(start));
        // P = closest intersection; no hit returns the background.
        let Some(found) = self.closest_hit(&start.ray, start.t_min, start.t_max, rec) else {
            return self.background(rec);
        };
        let (hit, surface, beyond) = self.hit_at(&start.ray, found, media);
        crate::record!(rec.hit(&hit));
        let material = self.scene.material_of(hit.object);
        // color_local = ambient + what each light's shadow ray lets through.
        let local = self.local_color(&start.ray, &hit, &surface, material, rec);
        // k_rfl and k_rfa; total internal reflection hands k_rfa to the reflection.
        let (c, n) = (start.ray.dir.normalize(), hit.shading_normal);
        let shares = optics::shares(
            c,
            n,
            (hit.n1, hit.n2),
            material,
            self.scene.settings.weights,
        );
        // color_reflect = raytrace(reflected ray).
        let reflected = self.spawn(RayKind::Reflected, &shares, start, &surface, *media, rec);
        // color_refract = raytrace(refracted ray), in the media beyond the surface.
        let refracted = self.spawn(RayKind::Refracted, &shares, start, &surface, beyond, rec);
        // color = color_local + k_rfl·color_reflect + k_rfa·color_refract.
        let color = local + shares.k_rfl * reflected + shares.k_rfa * refracted;
        crate::record!(rec.ray_finished(&SumEvent {
            local,
            k_rfl: shares.k_rfl,
            reflected,
            k_rfa: shares.k_rfa,
            refracted,
            color,
        }));
        color
    }

    /// The closest hit of `ray` travelling in `media`, and the surface there:
    /// how the forward tracer ([`crate::trace::forward`]) follows light with
    /// this tracer's own intersection code.
    pub fn intersect(&self, ray: &Ray, media: &Media) -> Option<(HitEvent, Surface)> {
        let found = self.closest_hit(ray, 0.0, f64::INFINITY, &mut NoRecorder)?;
        let (hit, surface, _) = self.hit_at(ray, found, media);
        Some((hit, surface))
    }

    /// What a ray that hits nothing returns: the scene's background.
    fn background<R: Recorder>(&self, rec: &mut R) -> DVec3 {
        crate::record!(rec.missed());
        let sum = SumEvent {
            local: self.scene.background,
            color: self.scene.background,
            ..SumEvent::default()
        };
        crate::record!(rec.ray_finished(&sum));
        sum.color
    }

    /// The object with the smallest root in `(t_min, t_max)`, that root, and the
    /// root's mesh face (0 for other shapes).
    #[inline]
    pub fn closest_hit<R: Recorder>(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        rec: &mut R,
    ) -> Option<(usize, f64, u32)> {
        let methods = self.scene.settings.intersection_methods();
        let mut closest = None;
        let mut t_closest = t_max;
        // The hierarchy counts its boxes, the objects their own tests (a mesh's boxes too).
        let (mut outer, mut inner) = (TestCounts::default(), TestCounts::default());
        // The hierarchy's boxes, kept only when recording (a diagram draws them).
        let mut boxes = Vec::new();
        // Tests made so far, shared by the two closures below.
        let tests_made = std::cell::Cell::new(0usize);
        let seen = |bounds, met| {
            if R::ENABLED {
                boxes.push(BoxVisit {
                    bounds,
                    met,
                    after_tests: tests_made.get(),
                });
            }
        };
        let _ = self.accel.visit_seeing(
            ray,
            t_min,
            &mut t_closest,
            &mut outer,
            seen,
            // Inlined into each traversal, as the shape tests are: out of
            // line, a call per object tested was 8 % of a render's
            // instructions on a scene of four objects.
            #[inline(always)]
            |candidate, t_closest| {
                let i = candidate.object();
                let roots = self.accel.roots(
                    candidate,
                    &self.scene.objects,
                    ray,
                    methods,
                    *t_closest,
                    Search::Closest,
                    &mut inner,
                );
                if R::ENABLED {
                    crate::record!(rec.object_tested(i, &roots));
                    tests_made.set(tests_made.get() + 1);
                }
                if let Some(t) = roots.first_in(t_min, *t_closest) {
                    closest = Some((i, roots.face()));
                    *t_closest = t;
                }
                ControlFlow::Continue(())
            },
        );
        // Reported to every recorder, so the renderer's ray counter can count
        // them too (`render --stats`); the no-op recorder drops it.
        outer.add(inner);
        crate::record!(rec.tested(&outer));
        if R::ENABLED {
            crate::record!(rec.boxes_visited(&boxes));
        }
        closest.map(|(i, face)| (i, t_closest, face))
    }

    /// The surface at a found hit, which side the ray hit, the refractive
    /// indices on either side of it, and the media beyond it.
    #[inline(always)]
    fn hit_at(
        &self,
        ray: &Ray,
        (object, t, face): (usize, f64, u32),
        media: &Media,
    ) -> (HitEvent, Surface, Media) {
        let methods = self.scene.settings.intersection_methods();
        let surface = self.scene.objects[object].surface(ray, t, face, methods);
        let inside = media.holds(object);
        let entering = self.enters(object, inside, media, ray.dir.dot(surface.normal));
        let medium = self.medium_bounded(object, inside, entering, media);
        // The media rule: n₁ is the innermost medium the ray travels in, n₂ the
        // innermost on the far side; so leaving one of two overlapping objects
        // while inside the other changes nothing. A ray leaving an object its
        // stack lacks (nested deeper than the stack holds) was inside it all the same.
        let ior_of = |m: Option<usize>| m.map_or(1.0, |o| self.scene.material_of(o).ior);
        let n1 = if entering || inside {
            ior_of(media.innermost())
        } else {
            self.scene.material_of(object).ior
        };
        let beyond = media.crossed(medium, entering);
        let n2 = ior_of(beyond.innermost());
        // Which side was hit is the geometric normal's business; lighting uses the
        // shading normal (interpolated on smooth meshes), turned the same way.
        let shading_normal = if entering {
            surface.shading_normal
        } else {
            -surface.shading_normal
        };
        let hit = HitEvent {
            object,
            t,
            face,
            point: surface.point,
            normal: surface.normal,
            shading_normal,
            entering,
            n1,
            n2,
        };
        (hit, surface, beyond)
    }

    /// The medium whose boundary the ray crosses at `object`: the object
    /// itself, but for a surface of separate faces (polygons, triangles) that
    /// the ray leaves through a face it did not enter by. A closed glass solid
    /// made of such faces is entered through one and left through another; the
    /// medium left is the innermost one of the same material on the stack (the
    /// face the ray came in by), so the ray is back in what was around it.
    #[inline(always)]
    fn medium_bounded(&self, object: usize, inside: bool, entering: bool, media: &Media) -> usize {
        if entering || inside || self.scene.objects[object].shape.is_solid() {
            return object;
        }
        let material = self.scene.objects[object].material;
        media
            .as_slice()
            .iter()
            .rev()
            .map(|&o| o as usize)
            .find(|&o| self.scene.objects[o].material == material)
            .unwrap_or(object)
    }

    /// Whether a ray crossing `object`'s surface with `n·c = n_dot_c` (outward
    /// normal) enters it or leaves it. A ray leaves only what it is inside: the
    /// stack of media says so for every object it holds (`inside`), and that it
    /// is outside a transparent solid it lacks, unless it is full. The sign of
    /// `n·c` decides only for the rest (opaque objects, meshes, a full stack);
    /// it is 0 at a tangent touch, and near one rounding can flip it, so for a
    /// glass ball from the air it would say "leaving" where the ray never went in.
    /// A touch with nothing to say the ray is inside enters.
    #[inline(always)]
    fn enters(&self, object: usize, inside: bool, media: &Media, n_dot_c: f64) -> bool {
        if inside {
            false
        } else if self.scene.is_solid_medium(object) && !media.is_full() {
            true
        } else {
            n_dot_c <= 0.0
        }
    }

    /// `ambient + Σ (diffuse + specular)` over the lights a shadow ray reaches.
    fn local_color<R: Recorder>(
        &self,
        ray: &Ray,
        hit: &HitEvent,
        surface: &Surface,
        material: &Material,
        rec: &mut R,
    ) -> DVec3 {
        let color = material.pattern.color_at(surface.pattern_point);
        let ambient = phong::ambient(material, color, self.scene.ambient_light);
        crate::record!(rec.local(&LocalEvent { color, ambient }));
        let to_eye = -ray.dir.normalize();
        let mut local = ambient;
        for (i, light) in self.scene.lights.iter().enumerate() {
            let shadow = self.shadow_ray(i, hit, surface);
            crate::record!(rec.shadow_ray(&shadow));
            let phong = match shadow.outcome {
                ShadowOutcome::Reaches { transmitted } => {
                    let to_light = (light.position - surface.point).normalize();
                    let arriving = transmitted * light.color;
                    let n = hit.shading_normal;
                    Some(phong::direct(
                        material, color, n, to_light, to_eye, arriving,
                    ))
                }
                _ => None,
            };
            if R::ENABLED {
                crate::record!(rec.light_term(&LightEvent { light: i, phong }));
            }
            if let Some(terms) = phong {
                local += terms.diffuse + terms.specular;
            }
        }
        local
    }

    /// The lecture's shadow ray from the hit toward light `light`: blocked by the
    /// first opaque object found before the light, dimmed by transparent ones.
    fn shadow_ray(&self, light: usize, hit: &HitEvent, surface: &Surface) -> ShadowEvent {
        let position = self.scene.lights[light].position;
        let mut event = ShadowEvent {
            light,
            ray: Ray::new(surface.point, position - surface.point),
            t_max: SHADOW_T_MAX,
            outcome: ShadowOutcome::FacesAway,
            tested: TestCounts::default(),
            recent: None,
        };
        if hit.shading_normal.dot(position - surface.point) <= 0.0 {
            return event;
        }
        let origin = surface.ray_origin(self.scene.settings.offset, position - surface.point);
        event.ray = Ray::new(origin, position - origin);
        // Try the recent hit first: the object that last blocked this light
        // (on this thread; see `crate::trace::recent`).
        let recent = self.recent.get(light).map(|object| {
            (
                object,
                self.shadow_test(
                    &Candidate::Object(object as u32),
                    &event.ray,
                    &mut event.tested,
                ),
            )
        });
        event.recent = recent.map(|(object, t)| RecentTry {
            object,
            blocks: t.is_some(),
        });
        event.outcome = match recent {
            Some((object, Some(t))) => ShadowOutcome::Blocked { object, t },
            _ => {
                let skip = recent.map(|(object, _)| object);
                let outcome = self.first_blocker(&event.ray, skip, &mut event.tested);
                if let ShadowOutcome::Blocked { object, .. } = outcome {
                    self.recent.set(light, object);
                }
                outcome
            }
        };
        event
    }

    /// Where a shadow ray meets the candidate's object before its light, if it does.
    #[inline]
    fn shadow_test(
        &self,
        candidate: &Candidate,
        ray: &Ray,
        tested: &mut TestCounts,
    ) -> Option<f64> {
        let (objects, methods) = (
            &self.scene.objects,
            self.scene.settings.intersection_methods(),
        );
        (self.accel)
            .roots(
                candidate,
                objects,
                ray,
                methods,
                SHADOW_T_MAX,
                Search::Any,
                tested,
            )
            .first_in(0.0, SHADOW_T_MAX)
    }

    /// The first opaque object a shadow ray meets before its light (the search
    /// stops there), or else the light it keeps through the transparent ones.
    /// Object `skip` was tested already.
    #[inline(always)]
    fn first_blocker(
        &self,
        ray: &Ray,
        skip: Option<usize>,
        tested: &mut TestCounts,
    ) -> ShadowOutcome {
        let mut transmitted = 1.0;
        let mut blocked = None;
        let mut inner = TestCounts::default();
        let _ = self.accel.visit_any(
            ray,
            0.0,
            &mut SHADOW_T_MAX.clone(),
            tested,
            #[inline(always)]
            |candidate, _| {
                let i = candidate.object();
                if Some(i) == skip {
                    return ControlFlow::Continue(());
                }
                if let Some(t) = self.shadow_test(candidate, ray, &mut inner) {
                    let k = self.scene.material_of(i).transparent;
                    if k == 0.0 {
                        blocked = Some(ShadowOutcome::Blocked { object: i, t });
                        return ControlFlow::Break(());
                    }
                    transmitted *= k;
                }
                ControlFlow::Continue(())
            },
        );
        tested.add(inner);
        blocked.unwrap_or(ShadowOutcome::Reaches { transmitted })
    }

    /// Traces the reflected or refracted child at a hit, unless there is none:
    /// refraction is impossible (total internal reflection), its coefficient is
    /// zero, the parent is at the maximum depth, or its weight would fall below
    /// the cutoff. It starts just off the surface, on the side it travels into.
    #[inline(always)]
    fn spawn<R: Recorder>(
        &self,
        kind: RayKind,
        shares: &Shares,
        parent: &RayStart,
        surface: &Surface,
        media: Media,
        rec: &mut R,
    ) -> DVec3 {
        let settings = &self.scene.settings;
        let (k, dir) = match kind {
            RayKind::Reflected => (shares.k_rfl, shares.reflected),
            _ => (shares.k_rfa, shares.refracted.unwrap_or_default()),
        };
        let weight = parent.weight * k;
        let (coefficient, branch) = if kind == RayKind::Refracted && shares.total_internal {
            (shares.transmitted, Branch::TotalInternalReflection)
        } else if k == 0.0 {
            (k, Branch::NoCoefficient)
        } else if parent.depth >= settings.max_depth {
            (k, Branch::MaxDepth)
        } else if weight < settings.cutoff {
            (k, Branch::WeightCutoff)
        } else {
            (k, Branch::Traced)
        };
        crate::record!(rec.branch(&BranchEvent {
            kind,
            coefficient,
            branch,
        }));
        if branch != Branch::Traced {
            return DVec3::ZERO;
        }
        let child = RayStart {
            kind,
            depth: parent.depth + 1,
            ray: Ray::new(surface.ray_origin(settings.offset, dir), dir),
            weight,
            t_min: 0.0,
            t_max: f64::INFINITY,
        };
        self.raytrace(&child, &media, rec)
    }
}

/// A primary ray's start: depth 1, weight 1, unbounded.
fn primary(ray: Ray) -> RayStart {
    RayStart {
        kind: RayKind::Primary,
        depth: 1,
        ray,
        weight: 1.0,
        t_min: 0.0,
        t_max: f64::INFINITY,
    }
}
