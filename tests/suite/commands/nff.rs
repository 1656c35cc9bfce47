//! NFF scenes (issue 27): read strictly, converted to the same scene JSON,
//! mirrored into raytree's right-handed frame, and every bad input refused
//! in one line naming the file and the line.

use glam::DVec3;
use raytree::io::image::srgb_to_linear;
use raytree::scene::{loader, nff};

use crate::common::refused;
use crate::tools::{self, Need};

/// A small scene with every entity.
const SCENE: &str = "# a test scene\n\
v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\n\
b 0.1 0.2 0.3\n\
l 2 -3 4\nl -2 -3 4 1 0.5 0.25\n\
f 1 0.5 0.2 0.7 0.3 20 0 0\n\
p 4\n-2 -2 0\n2 -2 0\n2 2 0\n-2 2 0\n\
s 0 0 1 0.5\n\
f 0.9 0.9 1 0.1 0.1 100 0.8 1.5\n\
c\n1 0 0 0.3\n1 0 1 0.1\n\
pp 3\n-1 0 0.5 0 -1 0\n-0.5 0 0.5 0 -1 0\n-0.75 0 1 0 -1 0.2\n";

#[test]
fn an_nff_scene_reads_as_its_converted_json() {
    let from_nff = loader::parse_file(SCENE, "t.nff").unwrap_or_else(|e| panic!("{e}"));
    let json = nff::to_json(SCENE, "t.nff").unwrap();
    let from_json = loader::parse(&json, "t.nff").unwrap();
    assert_eq!(from_nff, from_json);
    assert_eq!(from_nff.objects.len(), 4);
    assert_eq!((from_nff.settings.width, from_nff.settings.height), (6, 4));
    // Colors are for a display: sRGB, made linear.
    let linear = |c: DVec3| c.to_array().map(srgb_to_linear).into();
    assert_eq!(from_nff.background, linear(DVec3::new(0.1, 0.2, 0.3)));
    // 0.214041 is the standard curve at 0.5 to six decimals, hence 1e-6.
    assert!((srgb_to_linear(0.5) - 0.214_041).abs() < 1e-6);
    // Two lights: the one without a color gets √n/(2n) = √2/4 in white, as
    // the SPD suggests, and so does the ambient light; the other keeps its own.
    let i = 2f64.sqrt() / 4.0;
    assert_eq!(from_nff.lights[0].color, DVec3::splat(i));
    assert_eq!(from_nff.lights[1].color, linear(DVec3::new(1.0, 0.5, 0.25)));
    assert_eq!(from_nff.ambient_light, DVec3::splat(i));
    // Taken as they are, in raytree's right-handed frame.
    assert_eq!(from_nff.lights[0].position, DVec3::new(2.0, -3.0, 4.0));
    // f R G B Kd Ks Shine T ior: Kd is the diffuse and ambient share, Ks the
    // highlight and the reflection; an opaque material's ior 0 becomes 1.
    let m = &from_nff.materials[from_nff.objects[0].material];
    assert_eq!(
        (
            m.ambient,
            m.diffuse,
            m.specular,
            m.shininess,
            m.reflective,
            m.transparent,
            m.ior
        ),
        (0.7, 0.7, 0.3, 20.0, 0.3, 0.0, 1.0)
    );
    let glass = &from_nff.materials[from_nff.objects[2].material];
    assert_eq!((glass.transparent, glass.ior), (0.8, 1.5));
}

#[test]
fn an_opaque_polygon_is_seen_from_its_front_only() {
    // The floor's vertices run counter-clockwise seen from above (+z), so its
    // front faces up, toward the eye. From below, the same one-sided floor is
    // not hit.
    let from = |z: f64| {
        format!(
            "v\nfrom 0.1 0.1 {z}\nat 0 0 0\nup 0 1 0\nangle 30\nhither 1\nresolution 1 1\n\
             l 0 0 5\nf 1 1 1 1 0 1 0 0\np 4\n-2 -2 0\n2 -2 0\n2 2 0\n-2 2 0\n"
        )
    };
    let hit = |z: f64| {
        let scene = loader::parse_file(&from(z), "floor.nff").unwrap();
        let tracer = raytree::trace::tracer::Tracer::new(&scene);
        let ray = scene.camera().pixel_ray(0.0, 0.0);
        tracer.intersect(&ray, &Default::default()).is_some()
    };
    assert!(hit(5.0), "seen from its front, the floor is hit");
    assert!(!hit(-5.0), "seen from its back, an opaque polygon is not");
}

/// Each bad input, the line the error must name, and a word it must say.
const BAD: &[(&str, &str, usize, &str)] = &[
    (
        "truncated polygon",
        "p 4\n0 0 0\n1 0 0\n",
        12,
        "ends inside the polygon",
    ),
    (
        "too few numbers in a vertex",
        "p 3\n0 0 0\n1 0\n0 1 0\n",
        12,
        "takes 3 numbers",
    ),
    (
        "a vertex count past the vertices",
        "p 3\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
        14,
        "keyword",
    ),
    ("NaN", "s 0 NaN 0 1\n", 10, "not a finite number"),
    ("infinity", "s 0 0 0 inf\n", 10, "not a finite number"),
    ("not a number", "s 0 0 zero 1\n", 10, "not a number"),
    ("huge vertex count", "p 4000000000\n", 10, "vertex count"),
    ("two vertices", "p 2\n0 0 0\n1 0 0\n", 10, "vertex count"),
    (
        "collinear polygon",
        "p 3\n0 0 0\n1 1 1\n2 2 2\n",
        13,
        "polygon",
    ),
    ("degenerate cone", "c\n0 0 0 0\n0 0 1 0\n", 10, "cone"),
    ("zero-length cylinder", "c 0 0 0 1 0 0 0 1\n", 10, "cone"),
    ("a cone of 7 numbers", "c 0 0 0 1 0 0 1\n", 10, "8 numbers"),
    ("negative radius", "c\n0 0 0 -1\n0 0 1 1\n", 11, "cone"),
    ("sphere of radius 0", "s 0 0 0 0\n", 10, "radius"),
    (
        "more light than arrives",
        "f 1 1 1 1 0.6 10 0.6 1.5\n",
        10,
        "Ks + T",
    ),
    (
        "a glass without an index",
        "f 1 1 1 1 0 10 0.5 0\n",
        10,
        "index of refraction",
    ),
    ("a light with two numbers", "l 1 2\n", 10, "light"),
    ("an unknown keyword", "q 1 2 3\n", 10, "not an NFF keyword"),
    ("a huge coordinate", "s 0 0 1e300 1\n", 10, "center"),
];

/// The view the bad inputs follow (lines 1 to 7), then a material (line 8)
/// and a light (line 9): their own line is 10.
const HEAD: &str = "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\n\
f 1 1 1 1 0 10 0 0\nl 1 1 1\n";

#[test]
fn every_bad_nff_input_is_one_line_naming_the_file_and_line() {
    for (name, tail, line, says) in BAD {
        let text = format!("{HEAD}{tail}");
        let message = refused(
            &name.replace(' ', "-"),
            &[("bad.nff", text.as_bytes())],
            &["render", "bad.nff", "-o", "out.png"],
        );
        assert!(
            message.contains(&format!("bad.nff:{line}:")),
            "{name}: names line {line}: {message}"
        );
        assert!(message.contains(says), "{name}: says '{says}': {message}");
    }
}

/// The review of issue 27's reader: each refusal in NFF's own terms, at the
/// line (and column) a reader of the file looks at: vertices counted from 1
/// on their own lines, numbers short, negative radii named as NFF's
/// inside-only objects, an entity cut short by the next keyword said so.
#[test]
fn refusals_speak_nff_at_the_line_at_fault() {
    for (tail, want) in [
        (
            "p 4\n2 -1 0\n1 0 0\n2 1 0\n0 0 0\n",
            "12:1: the polygon (p) on line 10 has a reflex first corner, at vertex 2: NFF takes the normal from the first two edges, which must make a convex angle, and these turn it away from the outline's own winding (start the outline at a convex corner)",
        ),
        (
            "p 3\n0 0 0\n1 1 1\n2 2 2\n",
            "13:1: vertices 1 to 3 of the polygon (p) on line 10 lie on one line: they give it no plane (NFF takes the plane from them)",
        ),
        (
            "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 1\n",
            "14:1: vertex 4 of the polygon (p) on line 10 lies 1 off the plane of vertices 1 to 3 (allowed: 1e-5)",
        ),
        (
            "pp 3\n0 0 0 0 0 0\n1 0 0 0 0 1\n0 1 0 0 0 1\n",
            "11:7: the normal of vertex 1 of 3 of the polygonal patch (pp) on line 10 must not be zero",
        ),
        (
            "pp 3\n0 0 0 0 0 1e300\n1 0 0 0 0 1\n0 1 0 0 0 1\n",
            "11:7: a normal: every coordinate must be within ±1e9, got [0, 0, 1e300]",
        ),
        (
            "p 3\n0 0 0\n1 0 0\ns 0 0 0 1\n",
            "13:1: expected vertex 3 of 3 of the polygon (p) on line 10, found the keyword 's'",
        ),
        (
            "c\n0 0 0 1\nf 1 1 1 1 0 10 0 0\n",
            "12:1: expected the apex X Y Z R of the cone (c) on line 10, found the keyword 'f'",
        ),
        (
            "f 1 1 1 1 0 1e300 0 0\n",
            "10:13: Shine must be from 0 to 1e6, got 1e300",
        ),
        (
            "s 0 0 0 -2\n",
            "10:9: a negative radius makes NFF's inside-only sphere (s), seen only from inside, which raytree does not support",
        ),
        (
            "c\n0 0 0 1\n0 0 1 -0.5\n",
            "12:7: a negative apex radius makes NFF's inside-only cylinder or cone (c), seen only from inside, which raytree does not support",
        ),
        (
            "c 0 0 0 0 0 0 1 0\n",
            "10:1: the base and apex radii of the cone (c) are both 0: it would be a line",
        ),
        // A light's color is named at its R, after the position.
        (
            "l 1 2 3 -1 0 0\n",
            "10:9: a color: a color's components must be from 0 to ",
        ),
    ] {
        let text = format!("{HEAD}{tail}");
        let e = loader::parse_file(&text, "bad.nff")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with(&format!("bad.nff:{want}")), "{tail}: {e}");
    }
    // The arrow begun at a convex corner is the same outline, accepted, and
    // faces +z as its winding says.
    let arrow = format!("{HEAD}p 4\n0 0 0\n2 -1 0\n1 0 0\n2 1 0\n");
    let json = nff::to_json(&arrow, "arrow.nff").unwrap();
    assert!(json.contains("one_sided"), "{json}");
    assert!(loader::parse_file(&arrow, "arrow.nff").is_ok());
    // From and at so close their difference has no direction: named as the
    // view's fault, not up's.
    let view = "v\nfrom 1e-300 0 0\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 6 4\n";
    let e = loader::parse_file(view, "v.nff").unwrap_err().to_string();
    assert_eq!(
        e,
        "v.nff:3:1: 'at' must differ from 'from', and they are equal or so nearly equal that the view has no direction"
    );
}

/// NFF puts the view and the lights before the objects; raytree does not
/// enforce it (docs/spd.md says so): moved after the objects, they make the
/// same view and lights.
#[test]
fn the_view_and_lights_may_follow_the_objects() {
    let view = "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\n";
    let (light, objects) = ("l 1 2 3\n", "f 1 1 1 1 0 10 0 0\ns 0 0 0 1\n");
    let first = loader::parse_file(&format!("{view}{light}{objects}"), "a.nff").unwrap();
    let last = loader::parse_file(&format!("{objects}{light}{view}"), "b.nff").unwrap();
    assert_eq!(first.lights, last.lights);
    assert_eq!(first.camera(), last.camera());
    assert_eq!(first.settings, last.settings);
    assert_eq!(first.objects.len(), last.objects.len());
}

#[test]
fn the_view_is_strict() {
    for (name, text, says) in [
        ("no view", "f 1 1 1 1 0 10 0 0\ns 0 0 0 1\n", "no view"),
        (
            "view out of order",
            "v\nat 0 0 0\nfrom 0 -5 1\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\n",
            "expects 'from'",
        ),
        (
            "up along the view",
            "v\nfrom 0 0 5\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\n",
            "parallel",
        ),
        (
            "a field of view of 180°",
            "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 180\nhither 1\nresolution 6 4\n",
            "angle",
        ),
        (
            "no pixels",
            "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 0 4\n",
            "image side",
        ),
        (
            "an object before its material",
            "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\ns 0 0 0 1\n",
            "before any material",
        ),
    ] {
        let e = loader::parse_file(text, "v.nff").unwrap_err().to_string();
        assert!(e.starts_with("v.nff:"), "{name}: {e}");
        assert!(e.contains(says), "{name}: {e}");
        assert!(!e.contains('\n'), "{name}: {e}");
    }
}

#[test]
fn convert_writes_the_scene_render_reads() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("t.nff"), SCENE).unwrap();
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(args)
            .current_dir(dir.path())
            .output()
            .unwrap()
    };
    let out = run(&["convert", "t.nff"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json = std::fs::read_to_string(dir.path().join("t.json")).unwrap();
    assert_eq!(json, nff::to_json(SCENE, "t.nff").unwrap());
    for (input, png) in [("t.nff", "a.png"), ("t.json", "b.png")] {
        let out = run(&["render", input, "-q", "-o", png]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    assert_eq!(
        std::fs::read(dir.path().join("a.png")).unwrap(),
        std::fs::read(dir.path().join("b.png")).unwrap(),
        "the NFF file and its conversion render alike"
    );
    // Never over its input, never from a JSON scene.
    let refusal = crate::common::refused_with(
        2,
        "convert-over-input",
        &[("t.nff", SCENE.as_bytes())],
        &["convert", "t.nff", "-o", "t.nff"],
    );
    assert!(refusal.contains(".json"), "{refusal}");
    let refusal = crate::common::refused_with(
        2,
        "convert-json",
        &[("t.json", b"{}")],
        &["convert", "t.json"],
    );
    assert!(refusal.contains("NFF"), "{refusal}");
}

/// The seven SPD scenes with as many objects as their NFF files hold entities
/// (a `s`, `c`, `p` or `pp` each): the SPD README's totals for the default
/// size, but for the teapot, generated here with 2,256 patches (the README's
/// 9,264 is a finer tessellation).
#[test]
fn the_seven_spd_scenes_read_with_their_primitives() {
    if !tools::available("", &[Need::Spd], "the SPD scenes are read from it") {
        return;
    }
    let dir = tools::spd().unwrap();
    for (name, objects, lights) in [
        ("balls", 7_382, 3),
        ("gears", 9_345, 5),
        ("mount", 8_196, 1),
        ("rings", 8_401, 3),
        ("teapot", 2_292, 2),
        ("tetra", 4_096, 1),
        ("tree", 8_191, 7),
    ] {
        let scene =
            loader::load(&dir.join(format!("{name}.nff"))).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            (scene.objects.len(), scene.lights.len()),
            (objects, lights),
            "{name}"
        );
        assert_eq!(
            (scene.settings.width, scene.settings.height),
            (512, 512),
            "{name}"
        );
    }
}

#[test]
fn the_frame_is_taken_as_it_is_so_pictures_are_not_mirrored() {
    // Seen from −y with z up, +x is to the right in a right-handed camera, as
    // the SPD's reference pictures show their scenes (the teapot's spout,
    // at −x in teapot.nff, points left there). A ball at x = +1.5 must be
    // right of the middle column.
    let text = "v\nfrom 0 -10 0\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 9 3\n\
                l 0 -10 0\nf 1 1 1 1 0 1 0 0\ns 1.5 0 0 0.8\n";
    let scene = loader::parse_file(text, "ball.nff").unwrap();
    let tracer = raytree::trace::tracer::Tracer::new(&scene);
    let camera = scene.camera();
    let hit_columns: Vec<u32> = (0..9)
        .filter(|&x| {
            let ray = camera.pixel_ray(f64::from(x), 1.0);
            tracer.intersect(&ray, &Default::default()).is_some()
        })
        .collect();
    assert!(!hit_columns.is_empty());
    assert!(hit_columns.iter().all(|&x| x > 4), "{hit_columns:?}");
}

/// The seven renders in `docs/spd/` are what `raytree render
/// ../shared/spd/NAME.nff --protocol spd` makes today; with `RAYTREE_BLESS`
/// set, they are made again.
#[test]
fn the_spd_renders_in_docs_are_current() {
    use raytree::io::image;
    use raytree::scene::overrides::Protocol;
    if !tools::available("", &[Need::Spd], "the SPD scenes are read from it") {
        return;
    }
    let dir = tools::spd().unwrap();
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/spd");
    for name in [
        "balls", "gears", "mount", "rings", "teapot", "tetra", "tree",
    ] {
        let mut scene = loader::load(&dir.join(format!("{name}.nff"))).unwrap();
        scene.settings = Protocol::Spd.overrides().apply(&scene.settings);
        let made =
            raytree::trace::render::render(&scene, &raytree::trace::progress::Progress::QUIET)
                .unwrap();
        let path = docs.join(format!("{name}.png"));
        if std::env::var_os("RAYTREE_BLESS").is_some() {
            std::fs::create_dir_all(&docs).unwrap();
            std::fs::write(
                &path,
                image::file::encode(&made, image::file::Format::Png).unwrap(),
            )
            .unwrap();
            continue;
        }
        let committed = image::file::read_rgb8(&path)
            .unwrap_or_else(|e| panic!("{}: {e}; bless with RAYTREE_BLESS=1", path.display()))
            .into_raw();
        // One 8-bit level: the same arithmetic, but `powf` (Phong's exponent)
        // may round its last bit differently on another machine's libm, which
        // can move a pixel across a level's boundary; a changed scene or
        // method moves many levels.
        assert!(
            crate::common::worst_difference(&image::to_rgb8(&made), &committed) <= 1,
            "{} is stale: bless with RAYTREE_BLESS=1 cargo test --release spd_renders",
            path.display()
        );
    }
}

#[test]
fn a_file_of_too_many_words_is_refused_as_the_limit_is_reached() {
    // One sphere a line, five words each: the limit falls on the line where
    // the count passes it, and nothing past it is read.
    let lines = nff::MAX_WORDS / 5 + 10;
    let mut text = String::from(
        "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\nf 1 1 1 1 0 1 0 0\n",
    );
    for _ in 0..lines {
        text.push_str("s 0 0 0 1\n");
    }
    let e = loader::parse_file(&text, "big.nff")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("big.nff:"), "{e}");
    assert!(e.contains("more than 4194304 words"), "{e}");
    // The header takes 8 lines and 29 words; the limit is passed on the
    // sphere line that brings the count over 4,194,304.
    let line: usize = e.split(':').nth(1).unwrap().parse().unwrap();
    assert_eq!(line, 8 + (nff::MAX_WORDS - 29) / 5 + 1, "{e}");
}

#[test]
#[cfg(target_os = "linux")]
fn a_file_past_the_word_limit_is_refused_before_its_scene_is_built() {
    // 8.4 MB of spheres, just past the limit: counted before any is built,
    // it is refused within 128 MiB (built first, its objects took 1.4 GB).
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from(
        "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\nf 1 1 1 1 0 1 0 0\n",
    );
    text.push_str(&"s 0 0 0 1\n".repeat(nff::MAX_WORDS / 5 + 10));
    std::fs::write(dir.path().join("big.nff"), text).unwrap();
    let args = ["render", "big.nff", "-o", "o.png"];
    let (code, err, _) = crate::common::within_memory(dir.path(), 128, &args);
    assert_eq!(code, Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("more than 4194304 words"), "{err}");
}
