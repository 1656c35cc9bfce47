//! The object-space view: a hit on a transformed sphere drawn twice, in the
//! world and in the sphere's own space, where the lecture intersects it: the
//! inverse-transformed ray `S' + t·c' = M⁻¹S + t·M⁻¹c` meets the untransformed
//! sphere at the same `t_h` the world ray uses. The object-space panel is drawn
//! in the plane through the sphere's center that holds the ray, so both the
//! ray and the sphere's great circle are exact there.

use glam::{DVec2, DVec3};

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::labels::{self, Label, PxRect, Target};
use crate::figure::pen::{Pen, palette};
use crate::geometry::object::Shape;
use crate::scene::Scene;
use crate::tree::arithmetic::Fate;
use crate::tree::document::TraceDocument;
use crate::views::diagram::draw::draw_with_labels;
use crate::views::diagram::options::Options;
use crate::views::diagram::style::Scale;
use crate::views::numbers::{num, vec3};

/// The world view of `trace` beside the first hit on a transformed sphere, in
/// that sphere's own space.
pub fn draw(trace: &TraceDocument, scene: &Scene, options: &Options) -> Result<Figure, String> {
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
    let left = draw_with_labels(trace, scene, &world)?.figure;
    let right = own_space(
        sphere.center,
        sphere.radius,
        (ray.origin, ray.direction),
        hit.t,
        test,
        options.width - half,
        height,
        &scale,
        options.svg,
    )?;
    let mut page = Figure::page(options.width, options.height).ok_or("the figure is too small")?;
    if options.svg {
        page = page.with_svg();
    }
    page.paste(&left, 0, top);
    page.paste(&right, half as i32, top);
    page.caption_at(&lines, size, 12.0, f64::from(top) - f64::from(size) * 0.6);
    Ok(page)
}

/// The sphere's own space, in the plane of its center and the ray.
#[allow(clippy::too_many_arguments)]
fn own_space(
    center: DVec3,
    radius: f64,
    (s, c): (DVec3, DVec3),
    t_h: f64,
    test: &crate::tree::ray_tree::TestRecord,
    width: u32,
    height: u32,
    scale: &Scale,
    svg: bool,
) -> Result<Figure, String> {
    let m = (12.0 * scale.text / 15.0).max(6.0);
    let mut fig =
        Figure::new(width, height, m + scale.text * 1.6, m).ok_or("the figure is too small")?;
    if svg {
        fig = fig.with_svg();
    }
    // The plane through the center holding the ray: e1 along c', e2 toward S'.
    let e1 = c.normalize();
    let rel = s - center;
    let e2 = (rel - rel.dot(e1) * e1)
        .try_normalize()
        .unwrap_or_else(|| e1.any_orthonormal_vector());
    let at = |p: DVec3| DVec2::new((p - center).dot(e1), (p - center).dot(e2));
    let far_root = test.roots.iter().map(|r| r.t).fold(t_h, f64::max);
    // Framed on the sphere; S' joins the frame only when it is near.
    let near_s = at(s).length() <= 3.5 * radius;
    let mut pts = vec![DVec2::splat(-1.6 * radius), DVec2::splat(1.6 * radius)];
    pts.extend([at(s + t_h * c), at(s + far_root * c)]);
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
    // Where the ray comes into view: S' itself, or the frame's edge on the way from it.
    let start = if near_s {
        at(s)
    } else {
        crate::figure::clip::clip_segment(at(s), at(s + t_h * c), vlo, vhi)
            .map_or(at(s), |(a, _)| a)
    };
    fig.ellipse(
        DVec2::ZERO,
        [DVec2::X * radius, DVec2::Y * radius],
        Some(([244, 226, 190], 255)),
        Some(Pen::solid(palette::OBJECT, 1.6).scaled(scale.k as f32)),
    );
    let pen = Pen::solid(palette::PRIMARY, 2.5).scaled(scale.k as f32);
    let hit = at(s + t_h * c);
    fig.arrow(start, hit, pen);
    fig.line(hit, at(s + far_root * c), pen.passing());
    if near_s {
        fig.dot(at(s), (scale.text * 0.3).max(3.0), palette::INK, None);
    }
    fig.dot(
        hit,
        (scale.text * 0.3).max(3.0),
        palette::PRIMARY,
        Some(palette::INK),
    );
    let sz = scale.text - 1.0;
    let k = scale.k;
    let point = |fig: &Figure, p: DVec2, r: f64| Target::Point {
        at: fig.to_px(p),
        clearance: r * k,
    };
    let label = |text: String, target: Target, optional: bool| Label {
        text,
        size: sz,
        color: palette::INK,
        target,
        boxed: false,
        optional,
        tag: String::new(),
    };
    let mut labels = vec![
        label(
            format!("S' = M⁻¹S = {}", vec3(s)) + if near_s { "" } else { " (off the frame)" },
            point(&fig, start, 6.0),
            false,
        ),
        label(
            format!("tₕ = {}: P' = S' + tₕ·c' = {}", num(t_h), vec3(s + t_h * c)),
            point(&fig, hit, 6.0),
            false,
        ),
    ];
    let mut dots = vec![PxRect::around(fig.to_px(hit), 6.0 * k)];
    if near_s {
        dots.push(PxRect::around(fig.to_px(start), 6.0 * k));
    }
    for r in test.roots.iter().filter(|r| r.fate != Fate::Chosen) {
        let p = at(s + r.t * c);
        fig.dot(
            p,
            (scale.text * 0.25).max(2.5),
            palette::PAPER,
            Some(palette::INK),
        );
        labels.push(Label {
            size: sz - 1.0,
            ..label(format!("t = {}", num(r.t)), point(&fig, p, 5.0), true)
        });
        dots.push(PxRect::around(fig.to_px(p), 5.0 * k));
    }
    let f = fig.frame();
    let frame = PxRect {
        min: DVec2::new(f64::from(f.left()), f64::from(f.top())),
        max: DVec2::new(f64::from(f.right()), f64::from(f.bottom())),
    };
    // Labels keep off the ray (most) and the sphere's outline, and off the dots.
    let mut lines = vec![([fig.to_px(start), fig.to_px(at(s + far_root * c))], 4)];
    let rim = |k: u32| {
        let a = std::f64::consts::TAU * f64::from(k) / 48.0;
        fig.to_px(DVec2::new(a.cos(), a.sin()) * radius)
    };
    lines.extend((0..48).map(|k| ([rim(k), rim(k + 1)], 2)));
    for p in labels::place_weighted(labels, &dots, &lines, frame) {
        p.draw(&mut fig, 1.0);
    }
    let title = fig.to_px(DVec2::new(vlo.x, vhi.y)) + DVec2::new(4.0, -f64::from(sz) * 0.6);
    fig.text_px(
        title,
        &format!(
            "object space: the untransformed sphere; c' = M⁻¹c = {}",
            vec3(c)
        ),
        sz,
        palette::INK,
        Anchor::Left,
        false,
    );
    fig.frame_border();
    Ok(fig)
}
