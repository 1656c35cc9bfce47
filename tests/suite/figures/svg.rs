//! `raytree diagram -o FIG.svg`: the same figure as vectors. Recording the
//! SVG leaves the PNG as it was; every label drawn is text in the SVG; and,
//! drawn as pixels by librsvg, the SVG is the PNG up to anti-aliasing and the
//! fonts' hinting.

use std::path::Path;
use std::process::Command;

use raytree::scene::source::SceneSource;
use raytree::views::diagram::draw::draw_with_labels;
use raytree::views::diagram::options::Options;

use crate::commands::cli::{raytree, workdir};
use crate::tools::{Need, available};

fn glass() -> (
    raytree::scene::Scene,
    raytree::tree::document::TraceDocument,
) {
    let scene = raytree::scene::loader::whitted();
    let source = SceneSource::new("scenes/whitted.json", "");
    let trace = raytree::tree::record::pixel(&scene, source, 416, 209, None).unwrap();
    (scene, trace)
}

/// The figure's layout does not depend on recording it: the same PNG bytes,
/// and every label placed is a text element of the SVG. Fails if the SVG
/// recording moved, dropped or renamed anything a reader sees.
#[test]
fn the_svg_holds_every_label_of_the_png_and_changes_nothing() {
    let (scene, trace) = glass();
    let options = Options {
        depth: Some(3),
        ..Options::default()
    };
    let plain = draw_with_labels(&trace, &scene, &options).unwrap();
    let recorded = draw_with_labels(
        &trace,
        &scene,
        &Options {
            svg: true,
            ..options
        },
    )
    .unwrap();
    assert!(
        plain.figure.png() == recorded.figure.png(),
        "recording changed the PNG"
    );
    let svg = recorded.figure.svg().expect("recording was on");
    let (w, h) = recorded.figure.size();
    assert!(
        svg.starts_with(&format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\""
        )),
        "{}",
        &svg[..200]
    );
    assert!(!recorded.labels.is_empty());
    for placed in &recorded.labels {
        let text = placed
            .label
            .text
            .replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;");
        assert!(
            svg.contains(&format!(">{text}</text>")),
            "label '{}' is not text in the SVG",
            placed.label.text
        );
    }
    for entry in &recorded.legend_entries {
        assert!(
            svg.contains(&format!(">{entry}</text>")),
            "legend entry '{entry}' missing"
        );
    }
}

/// The command writes an SVG for a .svg name, for the plane of the rays and
/// for the camera's view (three panels on a page), and the SVG drawn by
/// librsvg matches the PNG: at most 2 % of the pixels differ by more than a
/// quarter of the range (edges and glyphs are anti-aliased and hinted
/// differently; a shape out of place would move far more).
#[test]
fn diagram_writes_svg_that_draws_as_its_png() {
    let dir = workdir("diagram-svg");
    let w = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json");
    let w = w.to_str().unwrap();
    let views: [(&str, &[&str]); 2] =
        [("glass", &["--depth", "3"]), ("cam", &["--view", "camera"])];
    for (name, view) in views {
        for ext in ["svg", "png"] {
            let out_name = format!("{name}.{ext}");
            let mut args = vec!["diagram", w, "--pixel", "416,209", "-o", &out_name];
            args.extend(view);
            let out = raytree(&args, &dir);
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
        let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
        assert!(svg.starts_with("<svg ") && svg.trim_end().ends_with("</svg>"));
    }
    if !available(
        "the SVG drawn as pixels",
        &[Need::Rsvg],
        "draws the SVG to compare with the PNG",
    ) {
        return;
    }
    for (name, _) in views {
        let drawn = dir.join(format!("{name}-from-svg.png"));
        let status = Command::new("rsvg-convert")
            .arg(dir.join(format!("{name}.svg")))
            .arg("-o")
            .arg(&drawn)
            .status()
            .expect("rsvg-convert runs");
        assert!(status.success());
        let a = image::open(dir.join(format!("{name}.png")))
            .unwrap()
            .to_rgb8();
        let b = image::open(&drawn).unwrap().to_rgb8();
        assert_eq!(a.dimensions(), b.dimensions());
        let off = a
            .pixels()
            .zip(b.pixels())
            .filter(|(p, q)| (0..3).any(|c| p[c].abs_diff(q[c]) > 64))
            .count();
        let share = off as f64 / f64::from(a.width() * a.height());
        assert!(
            share < 0.02,
            "{name}: {:.2} % of the pixels differ by more than 64 levels",
            100.0 * share
        );
    }
}
