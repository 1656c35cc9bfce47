//! Scenes made by program, for scaling runs and for the shipped `spheres.json`:
//! N random spheres, a grid of spheres, and a subdivided icosahedron mesh. Each is
//! written as an ordinary scene file (and OBJ file), so everything downstream
//! reads it like any other scene. Random choices come from a seeded generator:
//! the same arguments give the same file, byte for byte.

use std::fmt::Write;

use glam::DVec3;

/// The materials generated scenes pick from: a few diffuse colors, a mirror and glass.
const MATERIALS: &str = r#"  "materials": {
    "red": { "color": [0.8, 0.12, 0.1], "ambient": 0.1, "diffuse": 0.8, "specular": 0.3, "shininess": 30 },
    "green": { "color": [0.15, 0.65, 0.2], "ambient": 0.1, "diffuse": 0.8, "specular": 0.3, "shininess": 30 },
    "blue": { "color": [0.15, 0.3, 0.85], "ambient": 0.1, "diffuse": 0.8, "specular": 0.3, "shininess": 30 },
    "ivory": { "color": [0.9, 0.85, 0.7], "ambient": 0.1, "diffuse": 0.8, "specular": 0.3, "shininess": 30 },
    "mirror": { "color": [0.7, 0.7, 0.7], "ambient": 0.02, "diffuse": 0.08, "specular": 0.8, "shininess": 200, "reflective": 0.8 },
    "glass": { "color": [1, 1, 1], "ambient": 0.0, "diffuse": 0.02, "specular": 0.9, "shininess": 300, "reflective": 0.1, "transparent": 0.85, "ior": 1.5 },
    "floor": { "color": [0.6, 0.6, 0.6], "ambient": 0.1, "diffuse": 0.8, "specular": 0.0 }
  },
"#;

/// A material for one sphere: 60 % diffuse (four colors), 25 % mirror, 15 % glass.
fn pick_material(rng: &mut fastrand::Rng) -> &'static str {
    match rng.u32(0..100) {
        0..15 => "red",
        15..30 => "green",
        30..45 => "blue",
        45..60 => "ivory",
        60..85 => "mirror",
        _ => "glass",
    }
}

/// The scene around a set of spheres: camera, lights, materials, the floor.
fn scene_text(
    description: &str,
    camera: &str,
    lights: [(DVec3, f64); 2],
    floor_y: f64,
    spheres: &[(DVec3, f64, &str)],
) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{{");
    let _ = writeln!(s, "  \"description\": \"{description}\",");
    let _ = writeln!(s, "  \"camera\": {camera},");
    let _ = writeln!(s, "  \"background\": [0.18, 0.36, 0.75],");
    s.push_str(MATERIALS);
    let _ = writeln!(s, "  \"lights\": [");
    for (i, (p, c)) in lights.iter().enumerate() {
        let comma = if i == 0 { "," } else { "" };
        let _ = writeln!(
            s,
            "    {{ \"position\": [{}, {}, {}], \"color\": [{c}, {c}, {c}] }}{comma}",
            p.x, p.y, p.z
        );
    }
    let _ = writeln!(s, "  ],");
    let _ = writeln!(s, "  \"objects\": [");
    let _ = write!(
        s,
        "    {{ \"name\": \"floor\", \"plane\": {{ \"point\": [0, {floor_y}, 0], \"normal\": [0, 1, 0] }}, \"material\": \"floor\" }}"
    );
    for (c, r, m) in spheres {
        let _ = write!(
            s,
            ",\n    {{ \"sphere\": {{ \"center\": [{}, {}, {}], \"radius\": {r} }}, \"material\": \"{m}\" }}",
            c.x, c.y, c.z
        );
    }
    let _ = writeln!(s, "\n  ]");
    let _ = writeln!(s, "}}");
    s
}

/// Rounds to 4 decimals: a scene file people read, with no false precision.
fn r4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

/// `n` spheres at random in a cube sized so their density stays the same
/// whatever `n` (about one per 8 units³), radii 0.3–0.7, over a floor; the camera
/// sees the whole cube. For timing how the cost per ray grows with `n`.
pub fn random_spheres(n: usize, seed: u64) -> String {
    let mut rng = fastrand::Rng::with_seed(seed);
    let side = 2.0 * (n.max(1) as f64).cbrt();
    let spheres: Vec<(DVec3, f64, &str)> = (0..n)
        .map(|_| {
            let c = DVec3::new(
                r4((rng.f64() - 0.5) * side),
                r4(rng.f64() * side + 0.7),
                r4((rng.f64() - 0.5) * side),
            );
            (c, r4(0.3 + 0.4 * rng.f64()), pick_material(&mut rng))
        })
        .collect();
    let d = side * 1.6 + 4.0;
    let camera = format!(
        "{{ \"eye\": [{}, {}, {}], \"look_at\": [0, {}, 0], \"up\": [0, 1, 0], \"fov\": 50 }}",
        r4(0.35 * d),
        r4(0.5 * side + 0.45 * d),
        r4(d),
        r4(0.5 * side)
    );
    let lights = [
        (DVec3::new(r4(-d), r4(side + d), r4(d)), 0.7),
        (DVec3::new(r4(d), r4(side + 0.5 * d), r4(0.5 * d)), 0.45),
    ];
    scene_text(
        &format!("{n} random spheres (seed {seed}), made by `raytree generate spheres`."),
        &camera,
        lights,
        0.0,
        &spheres,
    )
}

/// `nx × ny × nz` spheres of radius 0.4 on a grid of spacing 1 (x across, y up,
/// z deep), each with a random material, over a floor, lit by two lights.
/// `scenes/spheres.json` is `sphere_grid([20, 5, 20], 2026)`.
pub fn sphere_grid(size: [u32; 3], seed: u64) -> String {
    let mut rng = fastrand::Rng::with_seed(seed);
    let [nx, ny, nz] = size;
    let mut spheres = Vec::new();
    for j in 0..ny {
        for k in 0..nz {
            for i in 0..nx {
                let c = DVec3::new(
                    f64::from(i) - 0.5 * f64::from(nx - 1),
                    0.4 + f64::from(j),
                    f64::from(k) - 0.5 * f64::from(nz - 1),
                );
                spheres.push((c, 0.4, pick_material(&mut rng)));
            }
        }
    }
    let w = f64::from(nx.max(nz));
    let camera = format!(
        "{{ \"eye\": [0, {}, {}], \"look_at\": [0, {}, 0], \"up\": [0, 1, 0], \"fov\": 50 }}",
        r4(0.75 * w + f64::from(ny)),
        r4(1.3 * w),
        r4(0.25 * f64::from(ny))
    );
    let lights = [
        (DVec3::new(r4(-0.6 * w), r4(w), r4(0.8 * w)), 0.7),
        (DVec3::new(r4(0.7 * w), r4(0.6 * w), r4(0.4 * w)), 0.45),
    ];
    scene_text(
        &format!(
            "{} spheres in a {nx} × {nz} × {ny} grid with a random mix (seed {seed}) of diffuse, mirror and glass materials, over a floor, two lights. Made by `raytree generate grid`.",
            nx * ny * nz
        ),
        &camera,
        lights,
        0.0,
        &spheres,
    )
}

/// A unit sphere approximated by an icosahedron whose faces are split in four
/// `levels` times (20·4^levels triangles), the new vertices pushed out onto the
/// sphere. Counter-clockwise seen from outside.
pub fn icosphere(levels: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let mut positions: Vec<DVec3> = [
        (-1.0, g, 0.0),
        (1.0, g, 0.0),
        (-1.0, -g, 0.0),
        (1.0, -g, 0.0),
        (0.0, -1.0, g),
        (0.0, 1.0, g),
        (0.0, -1.0, -g),
        (0.0, 1.0, -g),
        (g, 0.0, -1.0),
        (g, 0.0, 1.0),
        (-g, 0.0, -1.0),
        (-g, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| DVec3::new(x, y, z).normalize())
    .collect();
    let mut faces: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..levels {
        // One midpoint per edge, shared by the edge's two faces.
        let mut midpoints = std::collections::HashMap::new();
        let mut midpoint = |a: u32, b: u32, positions: &mut Vec<DVec3>| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let m = (positions[a as usize] + positions[b as usize]).normalize();
                positions.push(m);
                (positions.len() - 1) as u32
            })
        };
        faces = faces
            .iter()
            .flat_map(|&[a, b, c]| {
                let ab = midpoint(a, b, &mut positions);
                let bc = midpoint(b, c, &mut positions);
                let ca = midpoint(c, a, &mut positions);
                [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
            })
            .collect();
    }
    (positions, faces)
}

/// About how many bytes making `count` spheres takes at its peak: each sphere's
/// entry (48 bytes) and its line of the scene text (about 100 bytes), the text
/// counted twice for the copy a growing string makes. An estimate to refuse
/// sizes the machine cannot hold before starting, not a measurement.
pub fn memory_for_spheres(count: u64) -> u64 {
    count.saturating_mul(48 + 2 * 100) + (1 << 20)
}

/// About how many bytes making an icosphere of `levels` subdivisions takes at
/// its peak, per `4^levels` (a twentieth of the triangles): the vertices (10
/// of 24 bytes), the faces of the last two levels (25 of 12 bytes), the table
/// of edge midpoints (7.5 entries of about 32 bytes with the table's slack) and
/// the OBJ text (10 `v` and 10 `vn` lines of about 60 bytes, 20 `f` lines of
/// about 55), the text counted twice for the copy a growing string makes.
pub fn memory_for_icosphere(levels: u32) -> u64 {
    let per_unit = 10 * 24 + 25 * 12 + 240 + 2 * (20 * 60 + 20 * 55);
    (per_unit << (2 * levels.min(30))) + (1 << 20)
}

/// About how many bytes the OBJ file of an icosphere of `levels` subdivisions
/// takes, a little more than it does: `10·4^levels + 2` vertices, each a `v`
/// and a `vn` line of three numbers of up to 22 characters (a sign, `0.00`
/// and 17 significant digits: the shortest that reads back, for coordinates
/// down to 1e-3), and `20·4^levels` faces, each an `f` line of three
/// `i//i` pairs of indices as long as the vertex count. So a level whose OBJ
/// the mesh reader would refuse can be refused before it is made.
pub fn icosphere_obj_bytes(levels: u32) -> u64 {
    let levels = levels.min(30);
    let vertices = (10u64 << (2 * levels)) + 2;
    let faces = 20u64 << (2 * levels);
    let digits = u64::from(vertices.ilog10() + 1);
    let v_line = 2 + 3 * 22 + 2 + 1;
    let f_line = 2 + 3 * (2 * digits + 2) + 2 + 1;
    200 + vertices * (v_line + v_line + 1) + faces * f_line
}

/// The number of subdivision levels whose triangle count `20·4^levels` is nearest `n`.
pub fn icosphere_levels(n: u64) -> u32 {
    (0..12)
        .min_by_key(|&l| (20u64 << (2 * l)).abs_diff(n))
        .unwrap_or(0)
}

/// An OBJ file of the mesh, with the vertex normals of the sphere it approximates.
pub fn icosphere_obj(levels: u32) -> String {
    let (positions, faces) = icosphere(levels);
    let mut s = format!(
        "# A unit icosphere: an icosahedron subdivided {levels} times, {} triangles.\n# Made by `raytree generate icosphere`.\n",
        faces.len()
    );
    for p in &positions {
        let _ = writeln!(s, "v {} {} {}", p.x, p.y, p.z);
    }
    for p in &positions {
        let _ = writeln!(s, "vn {} {} {}", p.x, p.y, p.z);
    }
    for [a, b, c] in &faces {
        let _ = writeln!(s, "f {0}//{0} {1}//{1} {2}//{2}", a + 1, b + 1, c + 1);
    }
    s
}

/// A scene showing the icosphere in `obj_file` (relative to the scene file) as a
/// glass ball beside a mirror copy, over a floor.
pub fn icosphere_scene(obj_file: &str, triangles: usize) -> String {
    format!(
        r#"{{
  "description": "An icosphere mesh of {triangles} triangles, twice: mirror and ivory. Made by `raytree generate icosphere`.",
  "camera": {{ "eye": [0, 1.8, 6], "look_at": [0, 1, 0], "up": [0, 1, 0], "fov": 45 }},
  "background": [0.18, 0.36, 0.75],
{MATERIALS}  "lights": [
    {{ "position": [-4, 7, 6], "color": [0.7, 0.7, 0.7] }},
    {{ "position": [5, 5, 4], "color": [0.45, 0.45, 0.45] }}
  ],
  "objects": [
    {{ "name": "floor", "plane": {{ "point": [0, 0, 0], "normal": [0, 1, 0] }}, "material": "floor" }},
    {{ "name": "left", "mesh": {{ "file": "{obj_file}" }}, "material": "mirror", "transform": [{{ "translate": [-1.2, 1, 0] }}] }},
    {{ "name": "right", "mesh": {{ "file": "{obj_file}" }}, "material": "ivory", "transform": [{{ "translate": [1.2, 1, 0] }}] }}
  ]
}}
"#
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn icosphere_is_closed_and_counts_right() {
        for levels in 0..4 {
            let (p, f) = icosphere(levels);
            assert_eq!(f.len(), 20 << (2 * levels));
            // Euler: V - E + F = 2 for a closed genus-0 surface, with E = 3F/2.
            assert_eq!(p.len() as i64 - 3 * f.len() as i64 / 2 + f.len() as i64, 2);
            // Outward winding: every face normal points away from the center.
            for [a, b, c] in f {
                let (a, b, c) = (p[a as usize], p[b as usize], p[c as usize]);
                assert!((b - a).cross(c - a).dot(a + b + c) > 0.0);
            }
        }
        assert_eq!(icosphere_levels(20_000), 5);
        // The estimate covers the text with room for its growth, and the arrays.
        for levels in [3, 5] {
            let (p, f) = icosphere(levels);
            let arrays = (p.len() * 24 + f.len() * 12 * 5 / 4) as u64;
            let text = icosphere_obj(levels).len() as u64;
            assert!(
                memory_for_icosphere(levels) >= arrays + 2 * text,
                "{levels}"
            );
        }
        // The OBJ size estimate is above the size, and from a few hundred
        // triangles up (longer numbers) within a fifth of it.
        for levels in 0..8 {
            let size = icosphere_obj(levels).len() as u64;
            let estimate = icosphere_obj_bytes(levels);
            assert!(size <= estimate, "{levels}: {size} > {estimate}");
            assert!(
                levels < 4 || estimate <= size + size / 5,
                "{levels}: {size} {estimate}"
            );
        }
        let text = random_spheres(1000, 1).len() as u64;
        assert!(memory_for_spheres(1000) >= 2 * text + 48 * 1000);
        assert_eq!(icosphere_levels(1), 0);
    }

    #[test]
    fn generated_scenes_parse() {
        for text in [random_spheres(50, 1), sphere_grid([3, 2, 3], 1)] {
            crate::scene::loader::parse(&text, "generated.json").unwrap();
        }
        assert_eq!(random_spheres(20, 3), random_spheres(20, 3));
    }
}
