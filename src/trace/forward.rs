//! Forward tracing, the way the lecture sets against backward tracing: rays
//! leave the lights and are followed until they reach the eye or are lost, to
//! count how few ever arrive. The scene's own optics decide every bounce: the
//! tracer finds each hit ([`Tracer::intersect`]) and [`optics::shares`] gives
//! the mirror and Snell directions and the weights `k_rfl` and `k_rfa`.
//!
//! A light ray is one photon, so at each surface it takes one way, at random
//! with the surface's weights: reflected with probability `k_rfl`, refracted
//! with `k_rfa` (after total internal reflection, all to the reflection), else
//! scattered by the diffuse term (probability `k_d` times the color's
//! brightest channel, at most what is left), else absorbed. As in the Whitted
//! model, diffuse surfaces are lit by the lights only: a ray scatters
//! diffusely at most once, and a diffuse surface absorbs it after that.
//!
//! The eye of the lecture's camera is a point, which no ray ever meets; here
//! it is a pupil, a ball of radius `pupil` around the eye. A ray whose path
//! passes through it, travelling toward the image plane's side, reaches the
//! pixel its direction points back through (the pixel whose primary ray runs
//! the opposite way); one that passes through outside the image is counted
//! apart. Every ray ends in exactly one [`Fate`], so the counts add up.
//!
//! Each ray draws its random numbers from its own generator, seeded by the
//! seed and its index, so the result is the same on any number of threads.

use std::sync::atomic::{AtomicU64, Ordering};

use glam::DVec3;
use rayon::prelude::*;

use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::scene::camera::Camera;
use crate::shading::optics;
use crate::trace::progress::Progress;
use crate::trace::tracer::Tracer;

/// How a light ray ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fate {
    /// It passed through the pupil and reached this pixel `(x, y)`.
    Reached(u32, u32),
    /// It passed through the pupil from outside the image's field of view.
    OutsideImage,
    /// It left the scene: nothing was in its way.
    LeftScene,
    /// A surface absorbed it.
    Absorbed,
    /// It was still bouncing at the render settings' maximum depth.
    MaxDepth,
}

/// What the light rays did, counted.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ForwardCounts {
    /// Rays shot from the lights.
    pub shot: u64,
    /// Rays that reached a pixel.
    pub reached: u64,
    /// Rays that entered the pupil from outside the image.
    pub outside_image: u64,
    /// Rays that left the scene.
    pub left_scene: u64,
    /// Rays absorbed by a surface.
    pub absorbed: u64,
    /// Rays stopped at the maximum depth.
    pub max_depth: u64,
    /// Segments traced: every ray–scene intersection search.
    pub segments: u64,
}

impl ForwardCounts {
    /// The fates counted, which add up to `shot`.
    pub fn ended(&self) -> u64 {
        self.reached + self.outside_image + self.left_scene + self.absorbed + self.max_depth
    }

    fn add(&mut self, fate: Fate, segments: u64) {
        self.shot += 1;
        self.segments += segments;
        match fate {
            Fate::Reached(..) => self.reached += 1,
            Fate::OutsideImage => self.outside_image += 1,
            Fate::LeftScene => self.left_scene += 1,
            Fate::Absorbed => self.absorbed += 1,
            Fate::MaxDepth => self.max_depth += 1,
        }
    }

    fn merge(mut self, o: ForwardCounts) -> Self {
        self.shot += o.shot;
        self.reached += o.reached;
        self.outside_image += o.outside_image;
        self.left_scene += o.left_scene;
        self.absorbed += o.absorbed;
        self.max_depth += o.max_depth;
        self.segments += o.segments;
        self
    }
}

/// A forward trace: the counts, and each ray that reached a pixel with the
/// color it carried (the light's, tinted by the surface that scattered it).
#[derive(Clone, Debug, PartialEq)]
pub struct Forward {
    /// What became of the rays.
    pub counts: ForwardCounts,
    /// `(x, y, color)` per ray that reached a pixel, in the order shot.
    pub arrivals: Vec<(u32, u32, DVec3)>,
}

/// The pupil's default radius: a tenth of the image plane's half-width
/// `W` at distance `N`, taken at the distance from the eye to the scene's
/// look-at point: far larger than an eye (a third of a unit for the Whitted
/// scene, whose balls have radii about 1), so that a million rays form an image
/// at all; a lesson shrinks it with `--pupil` to watch the count fall with
/// the pupil's area.
pub fn default_pupil(scene: &Scene) -> f64 {
    let camera = scene.camera();
    let target = match scene.camera {
        crate::scene::camera::CameraSpec::LookAt { eye, look_at, .. } => (look_at - eye).length(),
        crate::scene::camera::CameraSpec::Frame { distance, .. } => distance,
    };
    camera.half_width / camera.distance * target / 10.0
}

/// Rays per work item: big enough to keep the cores busy, small enough for a
/// progress bar that moves.
const CHUNK: u64 = 1 << 14;

/// Shoots `photons` rays from the scene's lights (an equal share each, in
/// uniformly random directions) and follows them; `pupil` is the eye's radius.
pub fn trace(scene: &Scene, photons: u64, seed: u64, pupil: f64, progress: &Progress) -> Forward {
    let tracer = Tracer::new(scene);
    let camera = scene.camera();
    let done = AtomicU64::new(0);
    let chunks: Vec<Forward> = (0..photons.div_ceil(CHUNK))
        .into_par_iter()
        .map(|chunk| {
            let mut counts = ForwardCounts::default();
            let mut arrivals = Vec::new();
            let (start, end) = (chunk * CHUNK, ((chunk + 1) * CHUNK).min(photons));
            for i in start..end {
                let mut rng = fastrand::Rng::with_seed(mix(seed, i));
                let (fate, segments, color) = follow(&tracer, &camera, i, pupil, &mut rng);
                if let Fate::Reached(x, y) = fate {
                    arrivals.push((x, y, color));
                }
                counts.add(fate, segments);
            }
            let finished = done.fetch_add(end - start, Ordering::Relaxed) + (end - start);
            progress.report(finished, photons);
            Forward { counts, arrivals }
        })
        .collect();
    let mut out = Forward {
        counts: ForwardCounts::default(),
        arrivals: Vec::new(),
    };
    for chunk in chunks {
        out.counts = out.counts.merge(chunk.counts);
        out.arrivals.extend(chunk.arrivals);
    }
    out
}

/// Follows light ray `i` to its end: its fate, the segments traced, and the
/// color it carries.
fn follow(
    tracer: &Tracer,
    camera: &Camera,
    i: u64,
    pupil: f64,
    rng: &mut fastrand::Rng,
) -> (Fate, u64, DVec3) {
    let scene = tracer.scene();
    let light = &scene.lights[(i % scene.lights.len() as u64) as usize];
    let mut ray = Ray::new(light.position, uniform_direction(rng));
    let mut media = scene.media_at(light.position);
    let mut color = light.color;
    let mut scattered = false;
    let settings = &scene.settings;
    for depth in 1..=u64::from(settings.max_depth) {
        let found = tracer.intersect(&ray, &media);
        let t_hit = found.as_ref().map_or(f64::INFINITY, |(hit, _)| hit.t);
        if let Some(fate) = through_pupil(camera, &ray, t_hit, pupil) {
            return (fate, depth, color);
        }
        let Some((hit, surface)) = found else {
            return (Fate::LeftScene, depth, color);
        };
        let material = scene.material_of(hit.object);
        let c = ray.dir.normalize();
        let n = hit.shading_normal;
        let shares = optics::shares(c, n, (hit.n1, hit.n2), material, settings.weights);
        let surface_color = material.pattern.color_at(surface.pattern_point);
        let diffuse = if scattered {
            0.0
        } else {
            (material.diffuse * surface_color.max_element())
                .min(1.0 - shares.k_rfl - shares.k_rfa)
                .max(0.0)
        };
        let u = rng.f64();
        let dir = if u < shares.k_rfl {
            shares.reflected
        } else if u < shares.k_rfl + shares.k_rfa {
            media = media.crossed(hit.object, hit.entering);
            shares.refracted.unwrap_or(shares.reflected)
        } else if u < shares.k_rfl + shares.k_rfa + diffuse {
            scattered = true;
            color *= surface_color;
            cosine_direction(n, rng)
        } else {
            return (Fate::Absorbed, depth, color);
        };
        ray = Ray::new(surface.ray_origin(settings.offset, dir), dir);
    }
    (Fate::MaxDepth, u64::from(settings.max_depth), color)
}

/// Whether `ray` passes through the pupil before `t_hit`, and if so where it
/// lands: the pixel whose primary ray runs opposite to it.
fn through_pupil(camera: &Camera, ray: &Ray, t_hit: f64, pupil: f64) -> Option<Fate> {
    let d = ray.dir;
    let t = (camera.eye - ray.origin).dot(d) / d.length_squared();
    if t <= 0.0 || t >= t_hit || (ray.at(t) - camera.eye).length() > pupil {
        return None;
    }
    // The primary ray toward -d meets the image plane (n = -N) at eye - s·d.
    let toward_n = d.dot(camera.n);
    if toward_n <= 0.0 {
        return Some(Fate::OutsideImage);
    }
    let on_plane = -d * (camera.distance / toward_n);
    let (uc, vr) = (on_plane.dot(camera.u), on_plane.dot(camera.v));
    // Invert u_c = -W + W·2c/(N_c - 1) (and v_r likewise) to the nearest pixel center.
    let index = |coord: f64, half: f64, count: u32| {
        let i = ((coord + half) * f64::from(count.saturating_sub(1)) / (2.0 * half)).round();
        (i >= 0.0 && i < f64::from(count)).then_some(i as u32)
    };
    match (
        index(uc, camera.half_width, camera.columns),
        index(vr, camera.half_height, camera.rows),
    ) {
        (Some(c), Some(r)) => Some(Fate::Reached(c, camera.rows - 1 - r)),
        _ => Some(Fate::OutsideImage),
    }
}

/// A direction uniform over the sphere (Archimedes: `z` uniform in [-1, 1]).
fn uniform_direction(rng: &mut fastrand::Rng) -> DVec3 {
    let z = 1.0 - 2.0 * rng.f64();
    let phi = std::f64::consts::TAU * rng.f64();
    let r = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// A direction about unit normal `n` with density proportional to the cosine
/// to it (Lambert's law; Malley's method, pbrt-v4 §A.5.3).
fn cosine_direction(n: DVec3, rng: &mut fastrand::Rng) -> DVec3 {
    let (r, phi) = (rng.f64().sqrt(), std::f64::consts::TAU * rng.f64());
    let (a, b) = n.any_orthonormal_pair();
    let (x, y) = (r * phi.cos(), r * phi.sin());
    (x * a + y * b + (1.0 - x * x - y * y).max(0.0).sqrt() * n).normalize()
}

/// The seed of ray `i`'s generator: SplitMix64's finalizer of the two
/// (Steele, Lea & Flood 2014), so neighboring rays draw unrelated numbers.
fn mix(seed: u64, i: u64) -> u64 {
    let mut z = seed ^ i.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ray_aimed_back_along_a_primary_ray_lands_on_its_pixel() {
        let scene = crate::scene::loader::whitted();
        let camera = scene.camera();
        let primary = camera.pixel_ray(264.0, 200.0);
        // From a point down the primary ray, straight back toward the eye.
        let from = primary.at(3.0);
        let back = Ray::new(from, -primary.dir);
        assert_eq!(
            through_pupil(&camera, &back, f64::INFINITY, 1e-3),
            Some(Fate::Reached(264, 200))
        );
        // Blocked before the eye, or passing wide of it: no arrival.
        assert_eq!(through_pupil(&camera, &back, 1.0, 1e-3), None);
        let wide = Ray::new(from + camera.u, -primary.dir);
        assert_eq!(through_pupil(&camera, &wide, f64::INFINITY, 1e-3), None);
    }
}
