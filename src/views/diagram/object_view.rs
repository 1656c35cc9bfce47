//! The object-space view: a hit on a transformed sphere drawn twice, in the
//! world and in the sphere's own space, where the lecture intersects it: the
//! inverse-transformed ray `S' + t·c' = M⁻¹S + t·M⁻¹c` meets the untransformed
//! sphere at the same `t_h` the world ray uses. The object-space panel is drawn
//! in the plane through the sphere's center that holds the ray, so both the
//! ray and the sphere's great circle are exact there.

use glam::{DVec2, DVec3};

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::labels::{self, Label, PxRect};
use crate::figure::pen::{Pen, palette};
use crate::geometry::object::Shape;
use crate::scene::Scene;
use crate::tree::arithmetic::Fate;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{HitRecord, TestRecord};
use crate::views::diagram::arrange::layout;
use crate::views::diagram::draw::draw_with_labels;
use crate::views::diagram::options::Options;
use crate::views::diagram::style::Scale;
use crate::views::numbers::{num, vec3};

/// Where the object view put what a reader checks it by, in page pixels.
pub struct ObjectDrawn {
    /// The figure.
    pub figure: Figure,
    /// The normal at the hit as the inverse transpose gives it, and as the
    /// point rule would (`M·n'`), each from the hit to its arrow's tip: `None`
    /// where the hit has no point-rule normal or lies off the world panel.
    pub normals: Option<[(DVec2, DVec2); 2]>,
    /// The object's axes drawn in its own space.
    pub axes: Vec<Axis>,
    /// Where `P' = S' + t_h·c'` is drawn.
    pub hit: DVec2,
}

/// An object axis as drawn: its name (`x'`, …), the center and the tip.
pub type Axis = (String, DVec2, DVec2);

/// The world view of `trace` beside the first hit on a transformed sphere, in
/// that sphere's own space.
pub fn draw(trace: &TraceDocument, scene: &Scene, options: &Options) -> Result<Figure, String> {
    draw_marked(trace, scene, options).map(|d| d.figure)
}

/// [`draw`], also returning where its marks went.
pub fn draw_marked(
    trace: &TraceDocument,
    scene: &Scene,
    options: &Options,
) -> Result<ObjectDrawn, String> {
    let tree = &trace.samples[options.sample].tree;
    let found = tree.nodes.iter().find_map(|node| {
        let h = node.hit.as_ref()?;
        let object = &scene.objects[h.object];
        let test = node.tests.iter().find(|t| t.object == h.object)?;
        match (&object.shape, test.object_ray) {
            (Shape::Sphere(s), Some(r)) => Some((h, s, r, test)),
            _ => None,
        }
    });
    let Some((hit, sphere, ray, test)) = found else {
        return Err("--space object needs a hit on a transformed sphere, and no ray of this pixel makes one (try scenes/ellipsoids.json)".to_owned());
    };
    let scale = Scale::of(options.width, options.height);
    let size = scale.text + 1.0;
    let caption = format!(
        "left: the world, where the ray S + t·c meets '{}' at tₕ = {}; right: its own space, where it is a sphere of radius {} and the inverse-transformed ray S' + t·c' = M⁻¹S + t·M⁻¹c meets it at the same tₕ",
        hit.name,
        num(hit.t),
        num(sphere.radius)
    );
    let lines = Figure::wrap(&caption, size, options.width as f32 - 24.0);
    let top = (f64::from(size) * (1.3 * lines.len() as f64 + 0.9)) as i32 + 8;
    let half = options.width / 2;
    let height = options.height.saturating_sub(top as u32);
    let world = Options {
        width: half,
        height,
        ..*options
    };
    let mut left = draw_with_labels(trace, scene, &world)?.figure;
    let normals = point_rule_normal(&mut left, trace, scene, &world, hit)?;
    let space = OwnSpace {
        center: sphere.center,
        radius: sphere.radius,
        s: ray.origin,
        c: ray.direction,
        t_h: hit.t,
        test,
    };
    let (right, axes, hit_px) =
        own_space(&space, (options.width - half, height), &scale, options.svg)?;
    let mut page = Figure::page(options.width, options.height).ok_or("the figure is too small")?;
    if options.svg {
        page = page.with_svg();
    }
    page.paste(&left, 0, top);
    page.paste(&right, half as i32, top);
    page.caption_at(&lines, size, 12.0, f64::from(top) - f64::from(size) * 0.6);
    let on_left = |p: DVec2| p + DVec2::new(0.0, f64::from(top));
    let on_right = |p: DVec2| p + DVec2::new(f64::from(half), f64::from(top));
    Ok(ObjectDrawn {
        figure: page,
        normals: normals.map(|n| n.map(|(a, b)| (on_left(a), on_left(b)))),
        axes: axes
            .into_iter()
            .map(|(name, a, b)| (name, on_right(a), on_right(b)))
            .collect(),
        hit: on_right(hit_px),
    })
}

/// The lesson's wrong normal beside the right one at the hit, in the world
/// panel: the object normal carried like a point, by M (dashed), against the
/// inverse transpose's N, which the diagram draws as it draws every normal.
fn point_rule_normal(
    fig: &mut Figure,
    trace: &TraceDocument,
    scene: &Scene,
    world: &Options,
    hit: &HitRecord,
) -> Result<Option<[(DVec2, DVec2); 2]>, String> {
    let Some(wrong) = hit.normal_like_point else {
        return Ok(None);
    };
    // The drawn normal faces the ray; the wrong one is turned the same way.
    let wrong = if hit.shading_normal.dot(hit.normal) < 0.0 {
        -wrong
    } else {
        wrong
    };
    let proj = layout(trace, scene, world)?.proj;
    let scale = Scale::of(world.width, world.height);
    let at = proj.point(hit.point);
    if !fig.shows(at) {
        return Ok(None);
    }
    // As long as the diagram's normal arrows (draw.rs), so the two compare.
    let length = scale.px(45.0) / fig.scale();
    let tip = at + proj.vector(wrong) * length;
    let right_tip = at + proj.vector(hit.shading_normal) * length;
    fig.arrow(
        at,
        tip,
        scale.pen(Pen::pattern(palette::SHADOW_BLOCKED, 1.6, &[4.0, 3.0])),
    );
    // Each label beside its tip, on the outer side of the pair, so neither
    // crosses the other's arrow; kept inside the panel.
    let size = scale.text;
    let (width, _) = fig.size();
    let mut pair = [
        (right_tip, "N = (M⁻¹)ᵀn'", palette::NORMAL),
        (tip, "M·n': the point rule, wrong", palette::SHADOW_BLOCKED),
    ];
    pair.sort_by(|a, b| a.0.x.total_cmp(&b.0.x));
    for (k, (end, text, color)) in pair.into_iter().enumerate() {
        let w = f64::from(Figure::text_width(text, size));
        let gap = f64::from(size) * 0.5;
        let px = fig.to_px(end) - DVec2::new(0.0, f64::from(size) * 0.6);
        let beside = if k == 0 { px.x - gap - w } else { px.x + gap };
        let room = 6.0..=f64::from(width) - w - 6.0;
        // No room beside the tip: above it (the first) or below it (the second).
        let at = if room.contains(&beside) {
            DVec2::new(beside, px.y)
        } else {
            let up = if k == 0 { -1.6 } else { 1.8 };
            DVec2::new(
                (px.x - w / 2.0).clamp(*room.start(), room.end().max(*room.start())),
                px.y + up * f64::from(size),
            )
        };
        fig.text_px(at, text, size, color, Anchor::Left, false);
    }
    let px = |p: DVec2| fig.to_px(p);
    Ok(Some([(px(at), px(right_tip)), (px(at), px(tip))]))
}

/// The drawing plane of the object-space panel: the plane through the center
/// that holds the ray (`c'` and `rel = S' − center`), as in-plane axes `e1`
/// (right), `e2` (up) and its normal. It is seen from the side of +z' (else
/// +y', else +x') and turned so x' runs to the right (else y' up), so a ray in
/// the plane z' = 0 reads as a front view: +x' right, +y' up.
pub fn object_axes_plane(c: DVec3, rel: DVec3) -> (DVec3, DVec3, DVec3) {
    let n = c
        .cross(rel)
        .try_normalize()
        .or_else(|| c.cross(DVec3::Z).try_normalize())
        .or_else(|| c.cross(DVec3::Y).try_normalize())
        .unwrap_or(DVec3::Z);
    let side = [n.z, n.y, n.x]
        .into_iter()
        .find(|v| v.abs() > 1e-9)
        .unwrap_or(1.0);
    let n = n * side.signum();
    let e1 = (DVec3::X - DVec3::X.dot(n) * n)
        .try_normalize()
        .unwrap_or_else(|| DVec3::Y.cross(n).normalize());
    (e1, n.cross(e1), n)
}

/// The sphere and the inverse-transformed ray `S' + t·c'` in its own space:
/// what the object-space panel draws.
struct OwnSpace<'a> {
    /// The sphere's center in its own space.
    center: DVec3,
    /// Its radius there.
    radius: f64,
    /// `S'`.
    s: DVec3,
    /// `c'`.
    c: DVec3,
    /// The hit's `t`, the same as the world ray's.
    t_h: f64,
    /// The test of the sphere, with every root.
    test: &'a TestRecord,
}

/// Where the object-space panel draws the ray, in its drawing plane.
struct OwnRay {
    /// Where the ray is drawn from: `S'` itself, or the frame's edge on the
    /// way from it.
    start: DVec2,
    /// `S'` is near enough to be in the frame.
    near_s: bool,
    /// `P' = S' + t_h·c'`.
    hit: DVec2,
    /// The farthest root, where the line through the sphere ends.
    far: DVec2,
}

/// The sphere's own space, in the plane of its center and the ray: the
/// sphere, its axes, the ray and its roots, their names, the title.
fn own_space(
    space: &OwnSpace,
    (width, height): (u32, u32),
    scale: &Scale,
    svg: bool,
) -> Result<(Figure, Vec<Axis>, DVec2), String> {
    let m = (12.0 * scale.text / 15.0).max(6.0);
    let mut fig =
        Figure::new(width, height, m + scale.text * 1.6, m).ok_or("the figure is too small")?;
    if svg {
        fig = fig.with_svg();
    }
    let (e1, e2, normal) = object_axes_plane(space.c, space.s - space.center);
    let at = |p: DVec3| DVec2::new((p - space.center).dot(e1), (p - space.center).dot(e2));
    let drawn = frame_own_space(&mut fig, space, &at);
    fig.ellipse(
        DVec2::ZERO,
        [DVec2::X * space.radius, DVec2::Y * space.radius],
        Some(([244, 226, 190], 255)),
        Some(Pen::solid(palette::OBJECT, 1.6).scaled(scale.k as f32)),
    );
    let axes = draw_own_axes(&mut fig, (e1, e2, normal), space.radius, scale);
    draw_own_ray(&mut fig, &drawn, scale);
    let mut labels = ray_labels(&fig, space, &drawn, scale);
    labels.extend((axes.iter()).map(|(tip, name)| own_label(&fig, name.clone(), *tip, 3.0, scale)));
    let mut dots = vec![PxRect::around(fig.to_px(drawn.hit), 6.0 * scale.k)];
    if drawn.near_s {
        dots.push(PxRect::around(fig.to_px(drawn.start), 6.0 * scale.k));
    }
    let (root_labels, root_dots) = draw_other_roots(&mut fig, space, &at, scale);
    labels.extend(root_labels);
    dots.extend(root_dots);
    let lines = own_lines(&fig, &drawn, space.radius, &axes);
    for p in labels::place_weighted(labels, &dots, &lines, PxRect::frame_of(&fig)) {
        p.draw(&mut fig, 1.0);
    }
    let (vlo, vhi) = fig.visible();
    let sz = scale.text - 1.0;
    let title = fig.to_px(DVec2::new(vlo.x, vhi.y)) + DVec2::new(4.0, -f64::from(sz) * 0.6);
    let words = format!(
        "object space: the untransformed sphere; c' = M⁻¹c = {}",
        vec3(space.c)
    );
    fig.text_px(title, &words, sz, palette::INK, Anchor::Left, false);
    fig.frame_border();
    let axes = axes
        .into_iter()
        .map(|(tip, name)| (name, fig.to_px(DVec2::ZERO), fig.to_px(tip)))
        .collect();
    let hit = fig.to_px(drawn.hit);
    Ok((fig, axes, hit))
}

/// Frames the panel on the sphere, with the hit and the farthest root; `S'`
/// joins the frame only when it is near. Returns where the ray's marks go.
fn frame_own_space(fig: &mut Figure, space: &OwnSpace, at: &impl Fn(DVec3) -> DVec2) -> OwnRay {
    let (s, c, radius) = (space.s, space.c, space.radius);
    let far_root = space
        .test
        .roots
        .iter()
        .map(|r| r.t)
        .fold(space.t_h, f64::max);
    let hit = at(s + space.t_h * c);
    let near_s = at(s).length() <= 3.5 * radius;
    let mut pts = vec![DVec2::splat(-1.6 * radius), DVec2::splat(1.6 * radius)];
    pts.extend([hit, at(s + far_root * c)]);
    if near_s {
        pts.push(at(s));
    }
    let lo = pts
        .iter()
        .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
    let hi = pts
        .iter()
        .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
    let pad = (hi - lo).max_element() * 0.08;
    fig.fit(lo - pad, hi + pad, 0.0);
    let (vlo, vhi) = fig.visible();
    let start = if near_s {
        at(s)
    } else {
        crate::figure::clip::clip_segment(at(s), hit, vlo, vhi).map_or(at(s), |(a, _)| a)
    };
    OwnRay {
        start,
        near_s,
        hit,
        far: at(s + far_root * c),
    }
}

/// The object's own axes from its center, as they fall on the drawing plane
/// `(e1, e2, normal)`, longest first: an axis nearly on end, or drawn over a
/// longer one, would only confuse. Returns each tip with its name.
fn draw_own_axes(
    fig: &mut Figure,
    (e1, e2, normal): (DVec3, DVec3, DVec3),
    radius: f64,
    scale: &Scale,
) -> Vec<(DVec2, String)> {
    let axis_pen = Pen::solid(palette::INK, 1.2).scaled(scale.k as f32);
    let mut axes: Vec<(DVec2, String)> = Vec::new();
    let mut onto: Vec<(DVec3, &str, DVec2)> =
        [(DVec3::X, "x'"), (DVec3::Y, "y'"), (DVec3::Z, "z'")]
            .into_iter()
            .map(|(axis, name)| (axis, name, DVec2::new(axis.dot(e1), axis.dot(e2))))
            .collect();
    onto.sort_by(|a, b| b.2.length().total_cmp(&a.2.length()));
    for (axis, name, v) in onto {
        let along_drawn = axes
            .iter()
            .any(|(tip, _)| tip.normalize().dot(v.normalize()) > 0.98);
        if v.length() < 0.3 || along_drawn {
            continue;
        }
        let tip = v * 1.4 * radius;
        fig.arrow(DVec2::ZERO, tip, axis_pen);
        // Within 1e-3 of the plane, the drawn length is true to 1e-6.
        let exact = axis.dot(normal).abs() < 1e-3;
        axes.push((
            tip,
            format!("{name}{}", if exact { "" } else { " (foreshortened)" }),
        ));
    }
    axes
}

/// The ray to the hit, on through the sphere to the farthest root, with `S'`
/// (when near) and the hit as dots.
fn draw_own_ray(fig: &mut Figure, drawn: &OwnRay, scale: &Scale) {
    let pen = Pen::solid(palette::PRIMARY, 2.5).scaled(scale.k as f32);
    fig.arrow(drawn.start, drawn.hit, pen);
    fig.line(drawn.hit, drawn.far, pen.passing());
    let r = (scale.text * 0.3).max(3.0);
    if drawn.near_s {
        fig.dot(drawn.start, r, palette::INK, None);
    }
    fig.dot(drawn.hit, r, palette::PRIMARY, Some(palette::INK));
}

/// A plain label at `p` (drawing units) in the panel's ink.
fn own_label(fig: &Figure, text: String, p: DVec2, r: f64, scale: &Scale) -> Label {
    Label::at_point(
        text,
        scale.text - 1.0,
        palette::INK,
        fig.to_px(p),
        r * scale.k,
    )
}

/// The names of `S'` and of the hit with its `t`.
fn ray_labels(fig: &Figure, space: &OwnSpace, drawn: &OwnRay, scale: &Scale) -> Vec<Label> {
    let (s, c, t_h) = (space.s, space.c, space.t_h);
    let off = if drawn.near_s { "" } else { " (off the frame)" };
    vec![
        own_label(
            fig,
            format!("S' = M⁻¹S = {}", vec3(s)) + off,
            drawn.start,
            6.0,
            scale,
        ),
        own_label(
            fig,
            format!("tₕ = {}: P' = S' + tₕ·c' = {}", num(t_h), vec3(s + t_h * c)),
            drawn.hit,
            6.0,
            scale,
        ),
    ]
}

/// The sphere's roots that are not the hit, as open dots; returns their
/// labels (left out where there is no room) and their dots' boxes.
fn draw_other_roots(
    fig: &mut Figure,
    space: &OwnSpace,
    at: &impl Fn(DVec3) -> DVec2,
    scale: &Scale,
) -> (Vec<Label>, Vec<PxRect>) {
    let (mut labels, mut dots) = (Vec::new(), Vec::new());
    for r in space.test.roots.iter().filter(|r| r.fate != Fate::Chosen) {
        let p = at(space.s + r.t * space.c);
        fig.dot(
            p,
            (scale.text * 0.25).max(2.5),
            palette::PAPER,
            Some(palette::INK),
        );
        labels.push(Label {
            size: scale.text - 2.0,
            optional: true,
            ..own_label(fig, format!("t = {}", num(r.t)), p, 5.0, scale)
        });
        dots.push(PxRect::around(fig.to_px(p), 5.0 * scale.k));
    }
    (labels, dots)
}

/// The lines labels keep off: the ray most, the sphere's outline and the axes less.
fn own_lines(
    fig: &Figure,
    drawn: &OwnRay,
    radius: f64,
    axes: &[(DVec2, String)],
) -> Vec<([DVec2; 2], usize)> {
    let mut lines = vec![([fig.to_px(drawn.start), fig.to_px(drawn.far)], 4)];
    let rim = |k: u32| {
        let a = std::f64::consts::TAU * f64::from(k) / 48.0;
        fig.to_px(DVec2::new(a.cos(), a.sin()) * radius)
    };
    lines.extend((0..48).map(|k| ([rim(k), rim(k + 1)], 2)));
    lines.extend(
        axes.iter()
            .map(|(tip, _)| ([fig.to_px(DVec2::ZERO), fig.to_px(*tip)], 2)),
    );
    lines
}
