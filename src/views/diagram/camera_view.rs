//! The camera view: the lecture's image plane face-on, with a pixel's place on
//! it. Three panels from the trace's camera record and the pixel's camera
//! stages: the whole plane (`u` right, `v` up, half-sizes `W` and `H`, the
//! point `P(r, c)`), the pixels around the one traced (its column `c`, its row
//! `r` counted from the bottom, the samples inside it, the spacing
//! `2W/(N_c − 1)`), and the plane seen from the side (the eye, `N`, and the
//! ray reaching the plane at `t = 1`).

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::labels::{self, Label, PxRect};
use crate::figure::pen::{Pen, palette};
use crate::tree::arithmetic::{CameraRecord, CameraStage};
use crate::tree::document::TraceDocument;
use crate::views::diagram::style::Scale;
use crate::views::numbers::num;

/// The camera view of `trace`'s pixel, `width × height` pixels.
pub fn draw(trace: &TraceDocument, width: u32, height: u32) -> Result<Figure, String> {
    let cam = &trace.camera;
    let stages: Vec<&CameraStage> = trace
        .samples
        .iter()
        .filter_map(|s| s.camera.as_ref())
        .collect();
    let Some(&first) = stages.first() else {
        return Err("the camera view needs a pixel (--pixel X,Y), not a ray".to_owned());
    };
    let scale = Scale::of(width, height);
    let size = scale.text + 1.0;
    let [px, py] = first.pixel;
    let caption = format!(
        "camera view of pixel {px},{py} of {}: the image plane face-on (left: all of it, u right, v up; right: the pixels around it, rows r counted up from the bottom; below left: seen from the side)",
        trace.scene.file
    );
    let lines = Figure::wrap(&caption, size, width as f32 - 24.0);
    let top = (f64::from(size) * (1.3 * lines.len() as f64 + 0.9)) as i32 + 8;
    // Always recorded as SVG too: the view is three panels pasted onto a
    // page, and a page can hold its panels' vectors only if each has them.
    let mut page = Figure::page(width, height)
        .ok_or("the figure is too small")?
        .with_svg();
    let (w2, h_rest) = (width / 2, height.saturating_sub(top as u32));
    let (h_plane, h_side) = (h_rest * 62 / 100, h_rest - h_rest * 62 / 100);
    let plane = plane_panel(cam, first, w2, h_plane, &scale)?;
    let side = side_panel(cam, first, w2, h_side, &scale)?;
    let grid = grid_panel(cam, &stages, width - w2, h_rest, &scale)?;
    page.paste(&plane, 0, top);
    page.paste(&side, 0, top + h_plane as i32);
    page.paste(&grid, w2 as i32, top);
    page.caption_at(&lines, size, 12.0, f64::from(top) - f64::from(size) * 0.6);
    Ok(page)
}

fn panel(width: u32, height: u32, scale: &Scale) -> Result<Figure, String> {
    let m = (12.0 * scale.text / 15.0).max(6.0);
    Figure::new(width, height, m, m)
        .map(Figure::with_svg)
        .ok_or_else(|| "the figure is too small for the camera view".to_owned())
}

/// Labels on a panel, placed so none collides and none sits on `lines`
/// (diagram coordinates) where it can move off them.
fn place(fig: &mut Figure, labels: Vec<Label>, lines: &[[DVec2; 2]]) {
    let frame = PxRect::frame_of(fig);
    let px: Vec<[DVec2; 2]> = lines
        .iter()
        .map(|[a, b]| [fig.to_px(*a), fig.to_px(*b)])
        .collect();
    // Every line counts against a spot twice over, so a label prefers a clear one.
    let doubled: Vec<[DVec2; 2]> = px.iter().chain(px.iter()).copied().collect();
    for p in labels::place(labels, &[], &doubled, frame) {
        p.draw(fig, 1.0);
    }
}

fn label(fig: &Figure, text: String, at: DVec2, size: f32, clearance: f64) -> Label {
    Label::at_point(text, size, palette::INK, fig.to_px(at), clearance)
}

/// The whole image plane in its own coordinates `(u, v)`: the plane with its
/// axes and half-sizes, then the pixel's point on it, then their names.
fn plane_panel(
    cam: &CameraRecord,
    stage: &CameraStage,
    w: u32,
    h: u32,
    scale: &Scale,
) -> Result<Figure, String> {
    let mut fig = panel(w, h, scale)?;
    let plane = PlaneMarks::of(cam, stage);
    let (lo, hi) = (plane.corners[0], plane.corners[2]);
    fig.fit(
        lo - (hi - lo) * DVec2::new(0.3, 0.2),
        hi + (hi - lo) * DVec2::new(0.05, 0.08),
        0.0,
    );
    plane.draw_plane(&mut fig, scale);
    plane.draw_pixel(&mut fig, scale);
    let labels = plane.labels(&fig, cam, stage, scale);
    place(&mut fig, labels, &plane.lines());
    fig.frame_border();
    Ok(fig)
}

/// Where the plane panel's marks go, in the plane's `(u, v)`.
struct PlaneMarks {
    /// The half-sizes `W` and `H`.
    half: DVec2,
    /// The plane's corners, counterclockwise from `(−W, −H)`.
    corners: [DVec2; 4],
    /// The length of the `u` and `v` arrows.
    reach: f64,
    /// The height of `W`'s dimension line, below the plane.
    below: f64,
    /// The abscissa of `H`'s dimension line, left of the plane.
    left: f64,
    /// The pixel's point `P(r, c) = (u_c, v_r)`.
    p: DVec2,
}

impl PlaneMarks {
    fn of(cam: &CameraRecord, stage: &CameraStage) -> Self {
        let (wd, ht) = (cam.half_width, cam.half_height);
        let (lo, hi) = (DVec2::new(-wd, -ht), DVec2::new(wd, ht));
        PlaneMarks {
            half: hi,
            corners: [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)],
            reach: 0.25 * wd,
            below: -ht - 0.09 * (2.0 * ht),
            left: -wd - 0.06 * (2.0 * wd),
            p: DVec2::new(stage.u_c, stage.v_r),
        }
    }

    /// The plane, its axes `u` and `v` from its center, and its half-sizes as
    /// dimension lines below and to the left of it.
    fn draw_plane(&self, fig: &mut Figure, scale: &Scale) {
        let (wd, ht) = (self.half.x, self.half.y);
        fig.polygon(
            &self.corners,
            Some(([220, 232, 245], 255)),
            Some(scale_pen(scale, Pen::solid(palette::OBJECT, 1.5))),
        );
        let axis = scale_pen(scale, Pen::solid(palette::INK, 1.8));
        fig.arrow(DVec2::ZERO, DVec2::new(self.reach, 0.0), axis);
        fig.arrow(DVec2::ZERO, DVec2::new(0.0, self.reach), axis);
        fig.dot(
            DVec2::ZERO,
            (scale.text * 0.3).max(3.0),
            palette::PAPER,
            Some(palette::INK),
        );
        let dim = scale_pen(scale, Pen::solid(palette::OBJECT, 1.0));
        fig.arrow(DVec2::new(0.0, self.below), DVec2::new(wd, self.below), dim);
        fig.arrow(DVec2::new(self.left, 0.0), DVec2::new(self.left, ht), dim);
    }

    /// The pixel's point, with its coordinates as guides to the axes: `u_c`
    /// along `u`, `v_r` along `v`.
    fn draw_pixel(&self, fig: &mut Figure, scale: &Scale) {
        let p = self.p;
        let guide = scale_pen(scale, Pen::dashed(palette::OBJECT, 1.0));
        fig.line(p, DVec2::new(p.x, 0.0), guide);
        fig.line(p, DVec2::new(0.0, p.y), guide);
        fig.dot(
            p,
            (scale.text * 0.35).max(3.0),
            palette::REFRACTED,
            Some(palette::INK),
        );
    }

    /// The names, most important first: the point and its coordinates, the
    /// axes, the half-sizes, the pixel count.
    fn labels(
        &self,
        fig: &Figure,
        cam: &CameraRecord,
        stage: &CameraStage,
        scale: &Scale,
    ) -> Vec<Label> {
        let (wd, ht, p, reach) = (self.half.x, self.half.y, self.p, self.reach);
        let s = scale.text - 1.0;
        let u_c = format!("u_c = {}", num(stage.u_c));
        let v_r = format!("v_r = {}", num(stage.v_r));
        let n = "n points at the eye".to_owned();
        let count = format!("N_c × N_r = {} × {} pixels", cam.columns, cam.rows);
        vec![
            label(fig, "P(r, c)".to_owned(), p, s, 6.0),
            label(fig, u_c, DVec2::new(p.x, 0.0), s - 1.0, 3.0),
            label(fig, v_r, DVec2::new(0.0, p.y), s - 1.0, 3.0),
            label(fig, "u".to_owned(), DVec2::new(reach, 0.0), s, 5.0),
            label(fig, "v".to_owned(), DVec2::new(0.0, reach), s, 5.0),
            label(fig, n, DVec2::ZERO, s - 2.0, 6.0),
            label(
                fig,
                format!("W = {}", num(wd)),
                DVec2::new(wd / 2.0, self.below),
                s,
                3.0,
            ),
            label(
                fig,
                format!("H = {}", num(ht)),
                DVec2::new(self.left, ht / 2.0),
                s,
                3.0,
            ),
            label(fig, count, DVec2::new(-wd, ht), s - 1.0, 2.0),
        ]
    }

    /// The lines the labels keep off: the axes, the guides, the dimension
    /// lines and the plane's edges.
    fn lines(&self) -> Vec<[DVec2; 2]> {
        let (wd, ht, p, reach) = (self.half.x, self.half.y, self.p, self.reach);
        let corners = self.corners;
        let mut lines = vec![
            [DVec2::ZERO, DVec2::new(reach, 0.0)],
            [DVec2::ZERO, DVec2::new(0.0, reach)],
            [p, DVec2::new(p.x, 0.0)],
            [p, DVec2::new(0.0, p.y)],
            [DVec2::new(0.0, self.below), DVec2::new(wd, self.below)],
            [DVec2::new(self.left, 0.0), DVec2::new(self.left, ht)],
        ];
        lines.extend((0..4).map(|k| [corners[k], corners[(k + 1) % 4]]));
        lines
    }
}

/// The pixels around the traced one, in the lecture's (c, r): the cells and
/// their centers, the samples, then the words.
fn grid_panel(
    cam: &CameraRecord,
    stages: &[&CameraStage],
    w: u32,
    h: u32,
    scale: &Scale,
) -> Result<Figure, String> {
    let mut fig = panel(w, h, scale)?;
    let grid = Around::pixel(cam, stages[0]);
    fig.fit(
        grid.lo - DVec2::new(1.4, 1.6),
        grid.hi + DVec2::new(0.4, 2.2),
        0.0,
    );
    grid.draw_cells(&mut fig, scale);
    grid.draw_centers(&mut fig, stages, scale);
    grid.write_notes(&mut fig, cam, stages, scale);
    fig.frame_border();
    Ok(fig)
}

/// The window of pixels around the traced one, in `(c, r)`: a few columns
/// and rows either side, within the image.
struct Around {
    /// The traced pixel, `x right, y down`.
    pixel: [u32; 2],
    /// Its column `c`.
    c0: f64,
    /// Its row `r`, counted up from the bottom.
    r0: f64,
    /// The first column shown.
    c_lo: f64,
    /// The last column shown.
    c_hi: f64,
    /// The first row shown.
    r_lo: f64,
    /// The last row shown.
    r_hi: f64,
    /// The window's lower-left corner: the shown cells' outer edges.
    lo: DVec2,
    /// Its upper-right corner.
    hi: DVec2,
}

impl Around {
    fn pixel(cam: &CameraRecord, first: &CameraStage) -> Self {
        let [px, py] = first.pixel;
        let (c0, r0) = (f64::from(px), f64::from(cam.rows) - 1.0 - f64::from(py));
        let (span_c, span_r) = (4.0, 3.0);
        let clamp = |v: f64, n: u32| v.clamp(0.0, f64::from(n.max(1)) - 1.0);
        let (c_lo, c_hi) = (
            clamp(c0 - span_c, cam.columns),
            clamp(c0 + span_c, cam.columns),
        );
        let (r_lo, r_hi) = (clamp(r0 - span_r, cam.rows), clamp(r0 + span_r, cam.rows));
        Around {
            pixel: first.pixel,
            c0,
            r0,
            c_lo,
            c_hi,
            r_lo,
            r_hi,
            lo: DVec2::new(c_lo - 0.5, r_lo - 0.5),
            hi: DVec2::new(c_hi + 0.5, r_hi + 0.5),
        }
    }

    /// The traced cell filled, and the grid of pixel edges.
    fn draw_cells(&self, fig: &mut Figure, scale: &Scale) {
        let (c0, r0, lo, hi) = (self.c0, self.r0, self.lo, self.hi);
        let cell = [
            DVec2::new(c0 - 0.5, r0 - 0.5),
            DVec2::new(c0 + 0.5, r0 - 0.5),
            DVec2::new(c0 + 0.5, r0 + 0.5),
            DVec2::new(c0 - 0.5, r0 + 0.5),
        ];
        fig.polygon(&cell, Some(([220, 232, 245], 255)), None);
        let grid = scale_pen(scale, Pen::solid([170, 170, 170], 1.0));
        let mut c = self.c_lo - 0.5;
        while c <= self.c_hi + 0.5 {
            fig.line(DVec2::new(c, lo.y), DVec2::new(c, hi.y), grid);
            c += 1.0;
        }
        let mut r = self.r_lo - 0.5;
        while r <= self.r_hi + 0.5 {
            fig.line(DVec2::new(lo.x, r), DVec2::new(hi.x, r), grid);
            r += 1.0;
        }
    }

    /// Each pixel's center, and the traced pixel's samples on top.
    fn draw_centers(&self, fig: &mut Figure, stages: &[&CameraStage], scale: &Scale) {
        let dot = (scale.text * 0.18).max(2.0);
        let mut r = self.r_lo;
        while r <= self.r_hi {
            let mut c = self.c_lo;
            while c <= self.c_hi {
                fig.dot(DVec2::new(c, r), dot, [150, 150, 150], None);
                c += 1.0;
            }
            r += 1.0;
        }
        for s in stages {
            fig.dot(
                DVec2::new(s.c, s.r),
                dot * 1.8,
                palette::REFRACTED,
                Some(palette::INK),
            );
        }
    }

    /// The traced column's c under the grid, its row's r to the left, how
    /// the pixel became them and the spacing above, the samples' count below.
    fn write_notes(
        &self,
        fig: &mut Figure,
        cam: &CameraRecord,
        stages: &[&CameraStage],
        scale: &Scale,
    ) {
        let (c0, r0, lo, hi) = (self.c0, self.r0, self.lo, self.hi);
        let [px, py] = self.pixel;
        let spacing = 2.0 * cam.half_width / f64::from(cam.columns.saturating_sub(1).max(1));
        let sz = scale.text - 1.0;
        let ink = palette::INK;
        let under = fig.to_px(DVec2::new(c0, lo.y)) + DVec2::new(0.0, f64::from(sz) * 1.4);
        let c_is = format!("c = {}", num(c0));
        fig.text_px(under, &c_is, sz, ink, Anchor::Center, false);
        let beside = fig.to_px(DVec2::new(lo.x, r0)) + DVec2::new(-6.0, f64::from(sz) * 0.35);
        let r_is = format!("r = {}", num(r0));
        fig.text_px(beside, &r_is, sz, ink, Anchor::Right, false);
        let above = fig.to_px(DVec2::new((lo.x + hi.x) / 2.0, hi.y));
        let notes = [
            format!(
                "pixel {px},{py} (x right, y down) is column c = x = {}",
                num(c0)
            ),
            format!(
                "and row r = N_r − 1 − y = {} − 1 − {py} = {}",
                cam.rows,
                num(r0)
            ),
            format!("pixel centers are 2W/(N_c − 1) = {} apart", num(spacing)),
        ];
        let step = f64::from(sz) * 1.35;
        for (k, note) in notes.iter().enumerate() {
            let at = above - DVec2::new(0.0, step * (notes.len() - k) as f64 - step * 0.2);
            fig.text_px(at, note, sz, ink, Anchor::Center, false);
        }
        if stages.len() > 1 {
            let at = fig.to_px(DVec2::new((lo.x + hi.x) / 2.0, lo.y))
                + DVec2::new(0.0, f64::from(sz) * 3.0);
            let note = format!("{} samples inside the pixel (orange)", stages.len());
            fig.text_px(at, &note, sz, ink, Anchor::Center, false);
        }
    }
}

/// The eye, the image plane at distance `N` and the ray, seen along `u`.
fn side_panel(
    cam: &CameraRecord,
    stage: &CameraStage,
    w: u32,
    h: u32,
    scale: &Scale,
) -> Result<Figure, String> {
    let mut fig = panel(w, h, scale)?;
    let (n, ht) = (cam.distance, cam.half_height);
    fig.fit(
        DVec2::new(-0.15 * n, -1.25 * ht),
        DVec2::new(1.65 * n, 1.25 * ht),
        0.0,
    );
    let plane = scale_pen(scale, Pen::solid(palette::INK, 2.0));
    fig.line(DVec2::new(n, -ht), DVec2::new(n, ht), plane);
    let eye = DVec2::ZERO;
    let p = DVec2::new(n, stage.v_r);
    let dim = scale_pen(scale, Pen::solid(palette::OBJECT, 1.0));
    // The view direction −n, the axis through the image plane's center.
    let axis = DVec2::new(1.5 * n, 0.0);
    fig.arrow(eye, axis, dim);
    // The ray runs on past P to at most 1.1 half-heights off the axis, so
    // a corner pixel's ray stays in the panel.
    let beyond = 1.5_f64.min(1.1 * ht / stage.v_r.abs().max(f64::MIN_POSITIVE));
    let end = eye + (p - eye) * beyond;
    fig.arrow(
        eye,
        end,
        scale_pen(scale, Pen::solid(palette::PRIMARY, 2.2)),
    );
    fig.dot(eye, (scale.text * 0.35).max(3.0), palette::INK, None);
    fig.dot(
        p,
        (scale.text * 0.3).max(3.0),
        palette::REFRACTED,
        Some(palette::INK),
    );
    // N is measured on the side the ray does not take.
    let y_dim = if stage.v_r < 0.0 { 1.1 * ht } else { -1.1 * ht };
    fig.arrow(DVec2::new(0.0, y_dim), DVec2::new(n, y_dim), dim);
    let sz = scale.text - 1.0;
    let labels = vec![
        label(&fig, "eye".to_owned(), eye, sz, 6.0),
        label(
            &fig,
            format!("N = {}", num(n)),
            DVec2::new(n / 2.0, y_dim),
            sz,
            3.0,
        ),
        label(
            &fig,
            "image plane, n = −N".to_owned(),
            DVec2::new(n, if stage.v_r < 0.0 { -ht } else { ht }),
            sz,
            3.0,
        ),
        label(&fig, "t = 1: P(r, c)".to_owned(), p, sz, 6.0),
        label(&fig, "−n".to_owned(), axis, sz, 3.0),
    ];
    let lines = [
        [DVec2::new(n, -ht), DVec2::new(n, ht)],
        [eye, end],
        [eye, axis],
        [DVec2::new(0.0, y_dim), DVec2::new(n, y_dim)],
    ];
    place(&mut fig, labels, &lines);
    fig.frame_border();
    Ok(fig)
}

fn scale_pen(scale: &Scale, pen: Pen) -> Pen {
    pen.scaled(scale.k as f32)
}
