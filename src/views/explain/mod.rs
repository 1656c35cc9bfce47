//! The lecture's arithmetic written out with a ray's own numbers, so each step
//! of a trace can be checked with a calculator: the camera stage, the quadratic
//! and what became of each root, the inverse-transformed ray, `n·c` and the
//! mirror direction, Snell's angles, and the Phong terms with `N·L` and `R·V`.
//! The text trace and the inspector both write from here.

use glam::DVec3;

use crate::geometry::cuboid::{SlabSpan, overlap};
use crate::tree::arithmetic::{
    Arithmetic, CameraRecord, CameraStage, Fate, RootRecord, Slab, TUnit, TestMethod,
};
use crate::tree::ray_tree::{
    HitRecord, LightRecord, LocalRecord, RayNode, ShadowOutcomeRecord, ShadowRecord, TestRecord,
};
use crate::views::numbers::{color, degrees, factor, num, vec3};

mod shapes; // the polygon's and the cone's tests, written out
use shapes::{cone_quadratic, cone_roots, polygon};

/// A step's headline and the lines that show its arithmetic.
pub type Lines = (String, Vec<String>);

/// How the sample's primary ray was made: pixel → (c, r) → (u_c, v_r) → P(r, c).
pub fn camera(cam: &CameraRecord, stage: &CameraStage, which: &str) -> Lines {
    let [px, py] = stage.pixel;
    let at = if stage.offset == [0.0, 0.0] {
        "its center".to_owned()
    } else {
        format!(
            "({}, {}), offset ({}, {}) from its center",
            num(stage.x),
            num(stage.y),
            num(stage.offset[0]),
            num(stage.offset[1])
        )
    };
    let headline = format!("camera: {which}pixel {px},{py} at {at}");
    let (w, h) = (cam.half_width, cam.half_height);
    let details = vec![
        format!(
            "column c = x = {}, row r = N_r − 1 − y = {} − 1 − {} = {} (the lecture counts rows up from the bottom)",
            num(stage.c),
            cam.rows,
            num(stage.y),
            num(stage.r)
        ),
        format!(
            "u_c = −W + W·2c/(N_c − 1) = −{} + {} × 2 × {}/{} = {}",
            num(w),
            num(w),
            num(stage.c),
            cam.columns.saturating_sub(1),
            num(stage.u_c)
        ),
        format!(
            "v_r = −H + H·2r/(N_r − 1) = −{} + {} × 2 × {}/{} = {}",
            num(h),
            num(h),
            num(stage.r),
            cam.rows.saturating_sub(1),
            num(stage.v_r)
        ),
        format!(
            "P(r, c) = eye − N·n + u_c·u + v_r·v = {} − {} × {} + {} × {} + {} × {} = {}",
            vec3(cam.eye),
            num(cam.distance),
            vec3(cam.n),
            factor(stage.u_c),
            vec3(cam.u),
            factor(stage.v_r),
            vec3(cam.v),
            vec3(stage.point)
        ),
    ];
    (headline, details)
}

/// What `t` counts along the ray.
pub fn t_unit(node: &RayNode) -> String {
    match node.t_unit {
        TUnit::ImagePlane => "c = P(r, c) − eye, so t = 1 on the image plane".to_owned(),
        TUnit::Direction => format!(
            "t counts lengths of c (|c| = {})",
            num(node.direction.length())
        ),
        TUnit::Distance => "c is a unit vector, so t is the distance".to_owned(),
    }
}

/// One object test of the ray `node`: the method's numbers, then each root and
/// what became of it.
pub fn test(test: &TestRecord, kind: &str, node: &RayNode) -> Lines {
    let hit_found = node.hit.is_some();
    let mut details = Vec::new();
    if let Some(r) = &test.object_ray {
        details.push(format!(
            "the inverse-transformed ray: S' = M⁻¹S = {}, c' = M⁻¹c = {}; t is the same on both",
            vec3(r.origin),
            vec3(r.direction)
        ));
    }
    let method = match test.method {
        TestMethod::LectureQuadratic => " (the lecture's quadratic)",
        TestMethod::MollerTrumbore => " (Möller–Trumbore)",
        _ => "",
    };
    let found = found(test, node, &fates(&test.roots, hit_found), &mut details);
    (
        format!("test {kind} '{}'{method}: {found}", test.name),
        details,
    )
}

/// What the test's arithmetic found, in words, with the lines that show its
/// numbers added to `details`; `fates` are its roots with what became of each.
fn found(
    test: &TestRecord,
    node: &RayNode,
    fates: &[(f64, &'static str)],
    details: &mut Vec<String>,
) -> String {
    let roots = fates
        .iter()
        .map(|(t, why)| format!("t = {} ({why})", num(*t)))
        .collect::<Vec<_>>()
        .join(", ");
    match &test.arithmetic {
        Some(Arithmetic::Quadratic {
            origin,
            direction,
            a,
            b,
            c,
            discriminant,
        }) => {
            let (s, c_) = sphere_names(test, node, (*origin, *direction), details);
            details.push(format!(
                "A = |{c_}|² = {}, B = {s}·{c_} = {}, C = |{s}|² − 1 = {}",
                num(*a),
                num(*b),
                num(*c)
            ));
            sphere_roots(test, *discriminant, &roots)
        }
        Some(Arithmetic::Plane { n_dot_c, numerator }) if *n_dot_c != 0.0 => {
            let root = fates
                .first()
                .map_or(String::new(), |(t, why)| format!(" = {} ({why})", num(*t)));
            format!(
                "n·c = {}, t = (P₀ − S)·n / (n·c) = {} / {}{root}",
                num(*n_dot_c),
                num(*numerator),
                factor(*n_dot_c)
            )
        }
        Some(Arithmetic::Plane { .. }) => "n·c = 0: the ray runs parallel, no root".to_owned(),
        Some(Arithmetic::Slabs { axes }) => {
            details.push(slabs(axes));
            slabs_roots(axes, &roots)
        }
        Some(Arithmetic::Barycentric { weights }) => format!(
            "{roots}, barycentric weights {}",
            vec3(DVec3::from_array(*weights))
        ),
        Some(Arithmetic::Polygon {
            n_dot_c,
            numerator,
            one_sided,
            crossings,
            on_edge,
        }) => polygon(
            (*n_dot_c, *numerator, *one_sided),
            (*crossings, *on_edge),
            &roots,
        ),
        Some(Arithmetic::Face { face, weights }) => format!(
            "nearest face {face}: {roots}, barycentric weights {}",
            vec3(DVec3::from_array(*weights))
        ),
        Some(Arithmetic::ConeQuadratic {
            ratio,
            a,
            b,
            c,
            discriminant,
            crossings,
            ..
        }) => {
            details.extend(cone_quadratic(*ratio, [*a, *b, *c], ray_names(test)));
            cone_roots(*ratio, [*a, *b], *discriminant, crossings, fates)
        }
        None => "miss".to_owned(),
    }
}

/// The ray's names in the test's formulas: `S'` and `c'` for the
/// inverse-transformed ray, else `S` and `c`.
fn ray_names(test: &TestRecord) -> (&'static str, &'static str) {
    if test.object_ray.is_some() {
        ("S'", "c'")
    } else {
        ("S", "c")
    }
}

/// The ray's names in the sphere's quadratic: the test's own, or `S₁` and
/// `c₁` when the sphere was moved to the origin and scaled to radius 1 (a
/// detail line then says so).
fn sphere_names(
    test: &TestRecord,
    node: &RayNode,
    (origin, direction): (DVec3, DVec3),
    details: &mut Vec<String>,
) -> (&'static str, &'static str) {
    let (s, c_) = ray_names(test);
    let (seen_from, seen_along) = test
        .object_ray
        .map_or((node.origin, node.direction), |r| (r.origin, r.direction));
    if (origin, direction) == (seen_from, seen_along) {
        return (s, c_);
    }
    details.push(format!(
        "the sphere moved to the origin and scaled to radius 1 ({s} → ({s} − center)/r, {c_} → {c_}/r): S₁ = {}, c₁ = {}",
        vec3(origin),
        vec3(direction)
    ));
    ("S₁", "c₁")
}

/// The sphere's roots by the sign of `B² − AC` (`d`), or, where the stable
/// form found other roots than the lecture's would, both.
fn sphere_roots(test: &TestRecord, d: f64, roots: &str) -> String {
    let lecture_count = if d < 0.0 {
        0
    } else if d == 0.0 {
        1
    } else {
        2
    };
    if test.method == TestMethod::StableQuadratic && test.roots.len() != lecture_count {
        // B² − AC cancels where B² and AC are huge and nearly equal (a far
        // sphere); the stable form computes it without the subtraction.
        let found = match test.roots.len() {
            0 => "no root: the ray misses".to_owned(),
            1 => format!("one root: {roots}"),
            n => format!("{n} roots: {roots}"),
        };
        format!(
            "B² − AC = {} as the lecture writes it (nearly equal numbers subtracted: rounding decides); the stable form (Ray Tracing Gems ch. 7) finds {found}",
            num(d)
        )
    } else if d < 0.0 {
        format!("B² − AC = {} < 0: no root, the ray misses", num(d))
    } else if d == 0.0 {
        format!("B² − AC = 0: one root, t = −B/A: {roots}")
    } else {
        format!(
            "B² − AC = {} > 0: two roots, t = (−B ± √(B² − AC))/A: {roots}",
            num(d)
        )
    }
}

/// The box's roots: where the slabs' intervals overlap, if they do.
fn slabs_roots(axes: &[Slab; 3], roots: &str) -> String {
    match slabs_overlap(axes) {
        None => "the slabs' intervals do not overlap: no root".to_owned(),
        Some(leave) if !leave.is_finite() => {
            "the slabs' intervals overlap without end: no root".to_owned()
        }
        Some(_) => format!(
            "the slabs' intervals overlap: enters at the last slab's start, leaves at the first's end: {roots}"
        ),
    }
}

/// The verdict read off the intervals the trace prints, by the box test's own
/// rule ([`overlap`]): where they all overlap, up to the end returned.
fn slabs_overlap(axes: &[Slab; 3]) -> Option<f64> {
    let spans = axes.map(|slab| match slab {
        Slab::Crossing { near, far } => SlabSpan::Crossing { near, far },
        Slab::Parallel { inside } => SlabSpan::Parallel { inside },
    });
    overlap(&spans).map(|(_, leave)| leave)
}

fn slabs(axes: &[Slab; 3]) -> String {
    let each: Vec<String> = ["x", "y", "z"]
        .iter()
        .zip(axes)
        .map(|(name, slab)| match slab {
            Slab::Crossing { near, far } => format!("{name} [{}, {}]", num(*near), num(*far)),
            Slab::Parallel { inside: true } => format!("{name} parallel, inside"),
            Slab::Parallel { inside: false } => format!("{name} parallel, outside"),
        })
        .collect();
    format!("slabs: {}", each.join(", "))
}

/// Each root with its fate: the lecture's "first intersection?" answered.
fn fates(roots: &[RootRecord], hit_found: bool) -> Vec<(f64, &'static str)> {
    roots
        .iter()
        .map(|r| {
            let why = match (r.fate, r.at_start) {
                (Fate::Chosen, false) => "the closest hit",
                (Fate::Chosen, true) => {
                    "the surface the ray starts on, taken as the hit: shadow acne"
                }
                (Fate::Farther, _) if hit_found => "farther than the closest hit",
                (Fate::Farther, _) => "ahead",
                (Fate::Behind, true) => "the surface the ray starts on: ignored",
                (Fate::Behind, false) => "behind the origin: ignored",
                (Fate::Beyond, _) => "past the ray's end: ignored",
            };
            (r.t, why)
        })
        .collect()
}

/// The closest hit: where, which side, the indices, and the normal the formulas use.
pub fn hit(hit: &HitRecord, searched: &str) -> Lines {
    let side = if hit.entering { "entering" } else { "leaving" };
    let headline = format!(
        "closest hit: '{}' at t = {}, {}, {side}, n₁ = {} → n₂ = {} ({searched})",
        hit.name,
        num(hit.t),
        hit_point(hit),
        num(hit.n1),
        num(hit.n2),
    );
    let normal = if hit.shading_normal == hit.normal {
        "the formulas use it as it is, n = N".to_owned()
    } else if hit.shading_normal == -hit.normal {
        format!(
            "the ray arrives from inside, so the formulas use n = −N = {}, turned to face it",
            vec3(hit.shading_normal)
        )
    } else {
        format!(
            "the formulas use n = {}, the vertex normals interpolated and turned to face the ray",
            vec3(hit.shading_normal)
        )
    };
    let mut details = vec![format!(
        "the normal N = {} points out of the object; {normal}: n·c = {} with c = {}",
        vec3(hit.normal),
        num(hit.n_dot_c),
        vec3(hit.incoming)
    )];
    if vec3(hit.on_ray) != vec3(hit.point) {
        details.push(format!(
            "P is {} from S + t·c: put on the surface, P is off it by a few ULPs of its own size however far the ray came, so a secondary ray need only start just past that (pbrt-v4 §6.8.5)",
            num((hit.point - hit.on_ray).length())
        ));
    }
    if let Some(p) = hit.object_point {
        details.push(format!(
            "on the untransformed primitive: P' = M⁻¹P = {}",
            vec3(p)
        ));
    }
    if let (Some(n), Some(wrong), Some(off)) = (
        hit.object_normal,
        hit.normal_like_point,
        normal_like_point_error(hit),
    ) {
        let verdict = if off < 1e-9 {
            "the same direction: M keeps angles".to_owned()
        } else {
            format!(
                "{} away from N, the normal at right angles to the surface",
                degrees(off)
            )
        };
        details.push(format!(
            "its normal there, n' = {}, comes back through the inverse transpose: N = (M⁻¹)ᵀn' normalized = {}; transformed like a point instead, M·n' normalized = {}: {verdict}",
            vec3(n),
            vec3(hit.normal),
            vec3(wrong),
        ));
    }
    (headline, details)
}

/// The hit point as the tracer made it: the lecture's `S + t·c`, and where the
/// tracer then put it on the surface, when that moved it.
fn hit_point(hit: &HitRecord) -> String {
    use crate::tree::ray_tree::Placement;
    if hit.point == hit.on_ray {
        return format!("P = S + t·c = {}", vec3(hit.point));
    }
    let how = match hit.placement {
        Placement::OntoSphere => "projected onto the sphere",
        Placement::OntoPlane => "projected onto the plane",
        Placement::OntoBoxFace => "put on the box's face",
        Placement::FromCorners => "made from the triangle's corners",
        Placement::OntoCone => "put at the cone's radius at its height",
    };
    if hit.object_point.is_some() {
        format!(
            "S + t·c = {}; P = {}, found in the object's own space ({how} there) and carried back",
            vec3(hit.on_ray),
            vec3(hit.point)
        )
    } else {
        format!(
            "S + t·c = {}, {how}: P = {}",
            vec3(hit.on_ray),
            vec3(hit.point)
        )
    }
}

/// For a transformed object, the angle in degrees between the normal
/// transformed like a point, `M·n'`, and the right one, `(M⁻¹)ᵀn'`: zero when `M`
/// keeps angles (rotations, even scales), up to 90° for a very flat object.
pub fn normal_like_point_error(hit: &HitRecord) -> Option<f64> {
    let wrong = hit.normal_like_point?;
    let n = hit.normal;
    Some(crate::math::angle::angle_between(n, wrong).to_degrees())
}

/// A shadow ray's outcome; `t = 1` is the light.
pub fn shadow(s: &ShadowRecord) -> String {
    let what = match &s.outcome {
        ShadowOutcomeRecord::FacesAway => "the light is behind the surface: no ray cast".to_owned(),
        ShadowOutcomeRecord::Reaches { transmitted } if *transmitted == 1.0 => {
            "reaches the light".to_owned()
        }
        ShadowOutcomeRecord::Reaches { transmitted } => format!(
            "reaches the light through transparent objects, keeping {}",
            num(*transmitted)
        ),
        ShadowOutcomeRecord::Blocked { name, t, .. } => format!(
            "blocked by '{name}' at t = {} (t = 1 at the light)",
            num(*t)
        ),
    };
    let recent = match &s.recent {
        Some(r) if r.blocks => format!(
            " (tried '{}' first, the last blocker of this light: the only test)",
            r.name
        ),
        Some(r) => format!(
            " (tried '{}' first, the last blocker of this light: not in the way now)",
            r.name
        ),
        None => String::new(),
    };
    format!("shadow ray to light '{}': {what}{recent}", s.name)
}

/// The local color: the ambient term, then each light's diffuse and specular
/// terms with the vectors and dot products they came from.
pub fn local(local: &LocalRecord) -> Lines {
    let lights: String = local
        .lights
        .iter()
        .map(|l| {
            format!(
                " + '{}' (diffuse {} + specular {})",
                l.name,
                color(l.diffuse),
                color(l.specular)
            )
        })
        .collect();
    let headline = format!(
        "local = ambient {}{lights} = {}",
        color(local.ambient),
        color(local.total)
    );
    let mut details = vec![format!(
        "ambient = k_a·color·ambient light = {} × {} × {} = {}",
        num(local.k_a),
        color(local.color),
        color(local.ambient_light),
        color(local.ambient)
    )];
    for l in &local.lights {
        details.extend(light(l, local));
    }
    (headline, details)
}

fn light(l: &LightRecord, local: &LocalRecord) -> Vec<String> {
    let Some(p) = &l.phong else {
        return vec![format!("'{}': no light arrives, it adds nothing", l.name)];
    };
    vec![
        format!(
            "'{}': L = {}, N·L = {}; diffuse = k_d·(N·L)·color·light = {} × {} × {} × {} = {}",
            l.name,
            vec3(p.l),
            num(p.n_dot_l),
            num(local.k_d),
            num(p.n_dot_l),
            color(local.color),
            color(p.arriving),
            color(l.diffuse)
        ),
        format!(
            "'{}': R = 2(N·L)N − L = {}, V = {}, R·V = {}; specular = k_s·(R·V)^shininess·light = {} × {}^{} × {} = {}",
            l.name,
            vec3(p.r),
            vec3(p.v),
            num(p.r_dot_v),
            num(local.k_s),
            num(p.r_dot_v),
            num(local.shininess),
            color(p.arriving),
            color(l.specular)
        ),
    ]
}

/// The mirror direction with its numbers.
pub fn reflection(hit: &HitRecord) -> String {
    format!(
        "v = c − 2(n·c)n = {} − 2 × {} × {} = {}",
        vec3(hit.incoming),
        factor(hit.n_dot_c),
        vec3(hit.shading_normal),
        vec3(hit.mirror)
    )
}

/// Snell's law at the hit, or why it has no solution (total internal reflection).
pub fn refraction(hit: &HitRecord) -> Vec<String> {
    let Some(r) = &hit.refraction else {
        return Vec::new();
    };
    let snell = format!(
        "Snell: n₁ sin θ₁ = n₂ sin θ₂ with θ₁ = atan2(|n × c|, −n·c) = {}: sin θ₂ = (n₁/n₂)·sin θ₁ = ({}/{}) × {} = {}",
        degrees(r.theta1),
        num(hit.n1),
        num(hit.n2),
        num(r.sin_theta1),
        num(r.sin_theta2)
    );
    match (r.theta2, r.cos_theta2, r.direction) {
        (Some(theta2), Some(cos_theta2), Some(dir)) => {
            vec![
                format!("{snell}, θ₂ = {}", degrees(theta2)),
                format!(
                    "direction = η·c + (η cos θ₁ − cos θ₂)·n with η = n₁/n₂ = {}: {} × {} + ({} × {} − {}) × {} = {}",
                    num(r.eta),
                    num(r.eta),
                    vec3(hit.incoming),
                    num(r.eta),
                    num(r.cos_theta1),
                    num(cos_theta2),
                    vec3(hit.shading_normal),
                    vec3(dir)
                ),
            ]
        }
        _ => {
            let critical = r.critical.map_or(String::new(), |c| {
                format!(
                    "; θ₁ is beyond the critical angle asin(n₂/n₁) = asin({}/{}) = {}",
                    num(hit.n2),
                    num(hit.n1),
                    degrees(c)
                )
            });
            vec![format!("{snell} > 1: no angle has that sine{critical}")]
        }
    }
}
