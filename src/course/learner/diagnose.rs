//! The classic mistakes of a learner's tracer, each recognised from its
//! signature: the learner's number is recomputed with that one mistake from
//! raytree's own inputs (the camera, the recorded roots, the hit's normal and
//! indices, the light's terms) and must match within the comparison's
//! tolerance. Never guessed: no match, no diagnosis. Each names the lesson
//! that teaches the formula; the formulas are the lecture's
//! (`lecture-raytracing.md`: the ray through a pixel, the sphere's quadratic,
//! the shadow ray, `v = c − 2(n·c)n`, Snell's law, the recursive sum).

use glam::DVec3;

use crate::course::learner::format::{Kind, LearnerRay, LearnerShadow};
use crate::course::learner::measure::{
    Context, before_light, phong, same_color, same_direction, same_distance, shadow_roots,
    tolerance, unclamped_extra,
};
use crate::geometry::object::Shape;
use crate::shading::optics::{reflect, refract};
use crate::tree::ray_tree::{HitRecord, LocalRecord, RayNode, ShadowOutcomeRecord};

use crate::course::learner::mistake::found;
pub use crate::course::learner::mistake::{Diagnosis, MISTAKES};

/// [`found`](crate::course::learner::mistake::found) in another lesson than the table's: `not-normalized` is taught
/// wherever the vector is made (a reflected direction in lesson 9, a refracted
/// one in lesson 10, the Phong vectors in lesson 7).
fn found_in(id: &'static str, lesson: &'static str, words: String) -> Option<Diagnosis> {
    Some(Diagnosis { id, words, lesson })
}

/// The node's parent and the parent's hit, for a secondary ray.
fn parent_hit<'t>(ctx: &'t Context, i: usize) -> Option<(&'t RayNode, &'t HitRecord)> {
    let p = &ctx.tree().nodes[ctx.tree().nodes[i].parent?];
    Some((p, p.hit.as_ref()?))
}

/// A wrong primary or secondary direction.
pub fn direction(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let tol = tolerance(node.depth);
    let same =
        |d: Option<DVec3>| d.is_some_and(|d| d.is_finite() && same_direction(l.direction, d, tol));
    if i == 0 {
        let camera = ctx.scene.camera();
        let (x, y) = (f64::from(ctx.pixel.0), f64::from(ctx.pixel.1));
        let flipped = f64::from(ctx.scene.settings.height) - 1.0 - y;
        if same(Some(camera.pixel_ray(x, flipped).dir)) {
            return found(
                "rows-flipped",
                format!(
                    "your primary ray is raytree's for pixel ({x}, {flipped}): rows counted from the top where the lecture counts row r up from the bottom (r = N_r − 1 − y)"
                ),
            );
        }
        for (dx, dy, corner) in [
            (-0.5, 0.5, "lower left"),
            (0.5, 0.5, "lower right"),
            (-0.5, -0.5, "upper left"),
            (0.5, -0.5, "upper right"),
        ] {
            if same(Some(camera.pixel_ray(x + dx, y + dy).dir)) {
                return found(
                    "pixel-corner",
                    format!(
                        "your primary ray goes half a pixel toward the pixel's {corner} corner (P(r, c) at c {} ½, r {} ½): raytree takes P(r, c) at the whole c and r as the pixel's center, with no half-pixel shift",
                        if dx < 0.0 { "−" } else { "+" },
                        if dy > 0.0 { "−" } else { "+" },
                    ),
                );
            }
        }
        let size = (ctx.scene.settings.width, ctx.scene.settings.height);
        return crate::course::learner::pixel_grid::spacing(&camera, size, (x, y), &same);
    }
    let (_, h) = parent_hit(ctx, i)?;
    let (c, n) = (h.incoming, h.shading_normal);
    let radius = match &ctx.scene.objects[h.object] {
        o if o.transform.is_none() => match &o.shape {
            Shape::Sphere(s) if (s.radius - 1.0).abs() > 1e-3 => Some(s.radius),
            _ => None,
        },
        _ => None,
    };
    match l.kind {
        Kind::Reflected => {
            if same(Some(c + 2.0 * n.dot(c) * n)) {
                return found("reflection-sign", "your reflected direction is c + 2(n·c)n: the lecture's is v = c − 2(n·c)n (n·c < 0, so −2(n·c)n pushes away from the surface)".to_owned());
            }
            if let Some(r) = radius
                && same(Some(reflect(c, n * r)))
            {
                return found(
                    "not-normalized",
                    format!(
                        "your reflected direction is c − 2(n·c)n with n = P − center, of length r = {r}: the formula assumes a unit normal"
                    ),
                );
            }
        }
        Kind::Refracted => {
            let (n1, n2) = (h.n1, h.n2);
            if same(refract(c, n, n2 / n1)) {
                return found(
                    "eta-swapped",
                    format!(
                        "your refracted direction is Snell's with η = n₂/n₁ = {n2}/{n1}: the lecture's η is n₁/n₂ = {n1}/{n2} (from the side the ray comes from to the side it goes to)"
                    ),
                );
            }
            if let Some(d) = crate::course::learner::signs::refracted(c, n, n1 / n2, &same) {
                return Some(d);
            }
            let raw = ctx.tree().nodes[ctx.tree().nodes[i].parent?].direction;
            if (raw.length() - 1.0).abs() > 1e-3 && same(refract(raw, n, n1 / n2)) {
                return found_in(
                    "not-normalized",
                    "lessons/10-refraction",
                    format!(
                        "your refracted direction is Snell's formula applied to the incoming direction as it was, of length {:.4}: the formula assumes a unit c (cos θ₁ = −n·c)",
                        raw.length()
                    ),
                );
            }
            if !h.entering && same(refract(c, -n, n1 / n2)) {
                return found("normal-not-turned", "your refracted direction uses the outward normal where the ray leaves the object: turn n to face the incoming ray (n·c < 0) before Snell's law".to_owned());
            }
            if let Some(r) = radius
                && same(refract(c, n * r, n1 / n2))
            {
                return found_in(
                    "not-normalized",
                    "lessons/10-refraction",
                    format!(
                        "your refracted direction uses n = P − center, of length r = {r}: Snell's formula assumes a unit normal"
                    ),
                );
            }
            if let Some((a, b)) = other_indices(ctx, h, &same) {
                return found("wrong-medium", medium_words(a, b, n1, n2));
            }
        }
        Kind::Primary => {}
    }
    None
}

/// A pair of the scene's indices, other than the hit's n₁ → n₂, whose
/// Snell's law gives the direction `same` accepts.
fn other_indices(
    ctx: &Context,
    h: &HitRecord,
    same: &dyn Fn(Option<DVec3>) -> bool,
) -> Option<(f64, f64)> {
    let (c, n, n1, n2) = (h.incoming, h.shading_normal, h.n1, h.n2);
    let mut indices: Vec<f64> = ctx
        .scene
        .materials
        .iter()
        .map(|m| m.ior)
        .chain([1.0])
        .collect();
    indices.sort_by(f64::total_cmp);
    indices.dedup();
    for &a in &indices {
        for &b in &indices {
            let usual = (a == n1 && b == n2) || (a == n2 && b == n1) || a == b && n1 == n2;
            if !usual && same(refract(c, n, a / b)) {
                return Some((a, b));
            }
        }
    }
    None
}

fn medium_words(a: f64, b: f64, n1: f64, n2: f64) -> String {
    format!(
        "your refracted direction is Snell's with n₁ = {a} → n₂ = {b}; here the ray goes from n₁ = {n1} to n₂ = {n2}: after leaving an object the ray is in the medium around it, not in air or the object's glass"
    )
}

/// A wrong hit: another root of the same quadratic, or the surface the ray starts on.
pub fn hit(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let h = l.hit.as_ref()?.as_ref()?;
    let t = h.t?;
    let name = h
        .object
        .as_deref()
        .or(node.hit.as_ref().map(|o| o.name.as_str()))?;
    let distance = t * l.direction.length();
    let tol = tolerance(node.depth);
    if let Some((_, ph)) = parent_hit(ctx, i)
        && ph.name == name
        && same_distance(distance, 0.0, node.origin, tol)
    {
        return found(
            "no-offset",
            format!(
                "your {} ray hits '{name}', the surface it starts on, at distance {distance:.3e}: start secondary rays a little off the surface (or ignore t ≈ 0), or they meet their own surface (acne)",
                l.kind.name()
            ),
        );
    }
    let test = node.tests.iter().find(|r| r.name == name)?;
    let ours = node.hit.as_ref().filter(|o| o.name == name).map(|o| o.t);
    // Distances along raytree's ray, compared as the hit's t is.
    let along = |t: f64| t * node.direction.length();
    let root = test.roots.iter().map(|r| r.t).find(|&r| {
        same_distance(distance, along(r), node.origin, tol)
            && ours.is_none_or(|o| !same_distance(along(o), along(r), node.origin, tol))
    })?;
    // The t here counts in raytree's direction; the report above, distances.
    let length = node.direction.length();
    let units = if (length - 1.0).abs() > 1e-9 {
        format!(
            " (t counts in units of raytree's direction, of length {length:.4}; the distances above are t·{length:.4})"
        )
    } else {
        String::new()
    };
    if root < 0.0 {
        found(
            "negative-root",
            format!(
                "your t = {root:.4} for '{name}' is its negative root, behind the ray's origin: only roots with t > 0 are hits (lecture: the smallest positive t){units}"
            ),
        )
    } else {
        found(
            "far-root",
            format!(
                "your t = {root:.4} for '{name}' is its far root; the closest hit is the smallest positive root{}{units}",
                ours.map_or(String::new(), |o| format!(", t = {o:.4}"))
            ),
        )
    }
}

/// A normal not turned to face the ray where it leaves an object, or a
/// transformed object's normal carried to the world like a point (by `M`) or
/// by `M⁻¹` itself, where the lecture's rule is the inverse transpose
/// `(M⁻¹)ᵀ`: for a rotation and a scale together the three differ.
pub fn normal(ctx: &Context, n: DVec3, i: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let h = node.hit.as_ref()?;
    let tol = tolerance(node.depth);
    if let (Some(object_normal), Some(t)) = (
        h.object_normal,
        ctx.scene
            .objects
            .get(h.object)
            .and_then(|o| o.transform.as_deref()),
    ) {
        let by_point = t.to_world.matrix3 * object_normal;
        let by_inverse = t.to_object.matrix3 * object_normal;
        let correct = h.shading_normal;
        for (wrong, how) in [(by_point, "M, like a point"), (by_inverse, "M⁻¹")] {
            let wrong = wrong.normalize_or_zero();
            if !same_direction(wrong, correct, tol)
                && !same_direction(wrong, -correct, tol)
                && (same_direction(n, wrong, tol) || same_direction(n, -wrong, tol))
            {
                return found(
                    "normal-transform",
                    format!(
                        "your normal at '{}' is its object-space normal carried by {how}: a normal goes to the world by the inverse transpose (M⁻¹)ᵀ, so that it stays perpendicular to the stretched surface",
                        h.name
                    ),
                );
            }
        }
    }
    if same_direction(n, -h.shading_normal, tol) {
        return if h.entering {
            found(
                "normal-inward",
                format!(
                    "your normal points into '{}', away from the ray: a ray arriving from outside meets the outward normal N, which faces it (n·c < 0); only a ray leaving the object needs it turned",
                    h.name
                ),
            )
        } else {
            found(
                "normal-not-turned",
                format!(
                    "your normal is the outward one, but the ray leaves '{}' from inside: the formulas need n turned to face the ray (n = −N, so that n·c < 0)",
                    h.name
                ),
            )
        };
    }
    None
}

/// A shadow ray blocked where raytree's reaches the light.
pub fn shadow(ctx: &Context, s: &LearnerShadow, i: usize, k: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let h = node.hit.as_ref()?;
    let by = s.by.clone().flatten()?;
    if !s.blocked {
        return None;
    }
    if by == h.name {
        return found(
            "no-offset",
            format!(
                "your shadow ray toward '{}' is blocked by '{by}', the surface it starts from: start it a little off the surface, or ignore t ≈ 0 (acne)",
                s.light
            ),
        );
    }
    let ours = &node.shadow_rays[k];
    let index = ctx.scene.objects.iter().position(|o| o.name == by)?;
    let roots = shadow_roots(ctx, index, ours);
    let before = roots.as_slice().iter().any(|&t| before_light(t, ours));
    let beyond = roots.as_slice().iter().any(|&t| t >= 1.0);
    if beyond && !before {
        return found(
            "shadow-beyond-light",
            format!(
                "'{by}' meets your shadow ray toward '{}' only beyond the light (t > 1 with t = 1 at the light): only objects between the point and the light cast a shadow",
                s.light
            ),
        );
    }
    let k_rfa = ctx.scene.material_of(index).transparent;
    if before && k_rfa > 0.0 && matches!(ours.outcome, ShadowOutcomeRecord::Reaches { .. }) {
        return found(
            "transparent-blocks",
            format!(
                "your shadow ray toward '{}' stops at '{by}', which is transparent (k_rfa = {k_rfa}): a transparent object lets its share of the light through (the light arriving is multiplied by k_rfa) and the shadow ray goes on",
                s.light
            ),
        );
    }
    None
}

/// A local color off by the negative terms a clamp at 0 removes, or made with
/// a Phong vector pointing the wrong way or not of unit length.
pub fn local(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let (h, rec, got) = (node.hit.as_ref()?, node.local.as_ref()?, l.local?);
    let (n, v) = (h.shading_normal, -h.incoming);
    let (mut diffuse, mut specular) = (DVec3::ZERO, DVec3::ZERO);
    for light in &ctx.scene.lights {
        let lv = (light.position - h.point).normalize();
        let nl = n.dot(lv);
        let r = 2.0 * nl * n - lv;
        let (d, s) = unclamped_extra(rec, nl, r.dot(v), light.color);
        diffuse += d;
        specular += s;
    }
    // The learner's number is this mistake's, and the mistake changes it.
    let matches = |c: DVec3| !same_color(c, rec.total) && same_color(got, c);
    let view_sign = matches(phong_with(ctx, h, rec, |n, l, v, _| (n, l, -v)));
    for (extra, what) in [
        (diffuse, "N·L"),
        (specular, "R·V"),
        (diffuse + specular, "N·L and R·V"),
    ] {
        if extra.abs().max_element() > 0.0 && matches(rec.total + extra) {
            let or = if view_sign {
                " (or V points along the ray, V = c, where it should point back to the viewer, V = −c: here both give these numbers)"
            } else {
                ""
            };
            return found(
                "not-clamped",
                format!(
                    "your local color adds the terms of negative {what}: clamp them at 0 (max(0, N·L), max(0, R·V)); a light behind the surface, or a highlight pointing away, adds nothing{or}"
                ),
            );
        }
    }
    if view_sign {
        return found(
            "view-sign",
            "your local color is Phong's with V along the ray, V = c: V points from the hit back to the viewer, V = −c, so the highlight is where R, the mirrored light, comes toward the eye".to_owned(),
        );
    }
    let length = l.direction.length();
    if (length - 1.0).abs() > 1e-3
        && matches(phong_with(ctx, h, rec, |n, l, v, _| (n, l, v * length)))
    {
        return found_in(
            "not-normalized",
            "lessons/07-phong",
            format!(
                "your local color is Phong's with V = −c where c, your ray's direction, has length {length:.4}: V must be a unit vector, −c/|c|, or R·V is no cosine"
            ),
        );
    }
    if matches(phong_with(ctx, h, rec, |n, l, v, d| (n, l * d, v))) {
        return found_in(
            "not-normalized",
            "lessons/07-phong",
            "your local color is Phong's with L = light − P unnormalized: L must be a unit vector, (light − P)/|light − P|, or N·L and R·V are no cosines".to_owned(),
        );
    }
    if let Some(d) = crate::course::learner::terms::local(rec, got) {
        return Some(d);
    }
    // The normal the learner wrote, if it is not of unit length: used as it is?
    let normal = l.hit.as_ref()?.as_ref()?.normal?.length();
    if (normal - 1.0).abs() > 1e-3
        && matches(phong_with(ctx, h, rec, |n, l, v, _| (n * normal, l, v)))
    {
        let transformed = ctx
            .scene
            .objects
            .get(h.object)
            .is_some_and(|o| o.transform.is_some());
        let (lesson, why) = if transformed {
            (
                "lessons/06-transforms",
                "the inverse transpose (M⁻¹)ᵀ changes a normal's length, so normalize it after",
            )
        } else {
            (
                "lessons/07-phong",
                "N·L and R·V are cosines only between unit vectors",
            )
        };
        return found_in(
            "not-normalized",
            lesson,
            format!(
                "your local color is Phong's with your normal at '{}' as it is, of length {normal:.4}: divide it by its length ({why})",
                h.name
            ),
        );
    }
    None
}

/// raytree's local color at hit `h` made again with each arriving light's N, L
/// and V changed by `change(N, L, V, distance to the light)`: the ambient term,
/// plus each light's [`phong`] terms with R = 2(N·L)N − L.
fn phong_with(
    ctx: &Context,
    h: &HitRecord,
    rec: &LocalRecord,
    change: impl Fn(DVec3, DVec3, DVec3, f64) -> (DVec3, DVec3, DVec3),
) -> DVec3 {
    let mut total = rec.ambient;
    for light in &rec.lights {
        let (Some(p), Some(at)) = (&light.phong, ctx.scene.lights.get(light.light)) else {
            continue;
        };
        let d = (at.position - h.point).length();
        let (n, l, v) = change(h.shading_normal, p.l, p.v, d);
        let n_dot_l = n.dot(l);
        let r_dot_v = (2.0 * n_dot_l * n - l).dot(v);
        let (diffuse, specular) = phong(rec, n_dot_l, r_dot_v, p.arriving);
        total += diffuse;
        total += specular;
    }
    total
}

/// Total internal reflection not handled at node `i`'s hit, where the
/// learner refracted along `refracted`: unless that direction is Snell's
/// with the wrong medium's index, which has no total internal reflection here.
pub fn tir(ctx: &Context, i: usize, refracted: Option<DVec3>) -> Diagnosis {
    let node = &ctx.tree().nodes[i];
    if let (Some(d), Some(h)) = (refracted, node.hit.as_ref()) {
        let tol = tolerance(node.depth + 1);
        let same = |r: Option<DVec3>| r.is_some_and(|r| d.is_finite() && same_direction(d, r, tol));
        if let Some((a, b)) = other_indices(ctx, h, &same) {
            return found("wrong-medium", medium_words(a, b, h.n1, h.n2)).expect("a known mistake");
        }
    }
    let sin = node
        .hit
        .as_ref()
        .and_then(|h| h.refraction.as_ref())
        .map(|r| r.sin_theta2);
    found("tir-not-handled", format!(
        "raytree finds total internal reflection here{}: there is no refracted ray, and its share goes to the reflected one",
        sin.map_or(String::new(), |s| format!(" (sin θ₂ = (n₁/n₂)·sin θ₁ = {s:.4} > 1)"))))
    .expect("a known mistake")
}

/// A coefficient off: after total internal reflection raytree's reflected
/// ray carries the whole share, which a tracer that refracts anyway does not.
pub fn coefficient(ctx: &Context, i: usize, refracted: Option<DVec3>) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let b = node.refracted.as_ref()?;
    (b.outcome == crate::trace::recorder::Branch::TotalInternalReflection)
        .then(|| tir(ctx, i, refracted))
}

/// A color summed without its coefficients, or with them twice.
pub fn color(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    let tree = ctx.tree();
    let node = &tree.nodes[i];
    let got = l.color?;
    node.hit.as_ref()?;
    let child = |mine: &Option<Option<Box<LearnerRay>>>,
                 b: &Option<crate::tree::ray_tree::BranchRecord>| {
        mine.as_ref()
            .and_then(|c| c.as_ref())
            .and_then(|c| c.color)
            .or_else(|| b.as_ref()?.node.map(|j| tree.nodes[j].color()))
            .unwrap_or(DVec3::ZERO)
    };
    let local = l.local.unwrap_or(node.sum.local);
    let (rfl, rfa) = (
        child(&l.reflected, &node.reflected),
        child(&l.refracted, &node.refracted),
    );
    let (k1, k2) = (node.sum.k_rfl, node.sum.k_rfa);
    // A sum the lecture's way from the learner's own terms is no mistake in the
    // sum: a wrong local color or child shows there already (and a ray with no
    // children gives the same sum every way).
    if same_color(got, local + k1 * rfl + k2 * rfa) {
        return None;
    }
    for (sum, what) in [
        (
            local + rfl + rfa,
            "without k_rfl and k_rfa: local + reflected + refracted",
        ),
        (
            local + k1 * k1 * rfl + k2 * k2 * rfa,
            "with k_rfl and k_rfa applied twice (once to the child's color, once in the sum)",
        ),
    ] {
        if !same_color(sum, node.color()) && same_color(got, sum) {
            return found(
                "coefficients",
                format!(
                    "your color is summed {what}; the lecture's is color = local + k_rfl·reflected + k_rfa·refracted, each child's color weighted once"
                ),
            );
        }
    }
    None
}
