//! The shipped scenes load, and the generated one is what the generator writes.

use std::path::Path;

fn scenes() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

#[test]
fn every_shipped_scene_loads() {
    let mut names = Vec::new();
    for entry in std::fs::read_dir(scenes()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "json") {
            raytree::scene::loader::load(&path).unwrap_or_else(|e| panic!("{e}"));
            names.push(path.file_name().unwrap().to_string_lossy().into_owned());
        }
    }
    names.sort();
    assert!(
        names.contains(&"spheres.json".to_owned()) && names.contains(&"gaspra.json".to_owned()),
        "{names:?}"
    );
}

/// `scenes/spheres.json` is `raytree generate grid` with its defaults, so anyone
/// can make it again (or a bigger one) and the POV-Ray twin can trust its layout.
#[test]
fn spheres_json_is_the_generators_grid() {
    let shipped = std::fs::read_to_string(scenes().join("spheres.json")).unwrap();
    assert!(
        shipped == raytree::scene::generate::sphere_grid([20, 5, 20], 2026),
        "scenes/spheres.json differs from `raytree generate grid`"
    );
    let scene = raytree::scene::loader::parse(&shipped, "spheres.json").unwrap();
    // 2,000 spheres and the floor.
    assert_eq!(scene.objects.len(), 2001);
}

#[test]
fn the_gaspra_mesh_has_its_triangles_and_normals() {
    let scene = raytree::scene::loader::load(&scenes().join("gaspra.json")).unwrap();
    let mesh = scene
        .objects
        .iter()
        .find_map(|o| match &o.shape {
            raytree::geometry::object::Shape::Mesh(m) => Some(m.clone()),
            _ => None,
        })
        .unwrap();
    assert_eq!(mesh.faces.len(), 32_040);
    assert_eq!(mesh.positions.len(), 16_022);
    assert_eq!(mesh.face_normals.len(), 32_040);
}
