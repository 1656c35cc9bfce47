//! Triangle meshes: many triangles sharing vertices, one object to the scene,
//! with a bounding volume hierarchy of their own so a ray tests a few of them.

use std::ops::ControlFlow;

use glam::DVec3;

use crate::geometry::hit::{Roots, Search, Surface, TestCounts};
use crate::geometry::structures::bvh::Bvh;
use crate::geometry::triangle::{ShearedRay, Triangle, TriangleHit};
use crate::math::bounds::{Bounds, RayBox};
use crate::math::ray::Ray;
use crate::methods::TriangleMethod;

/// A triangle mesh in its own space.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Per-vertex unit normals, if the mesh has them (for smooth shading).
    pub normals: Vec<DVec3>,
    /// Vertex indices of each triangle, counter-clockwise seen from outside.
    pub faces: Vec<[u32; 3]>,
    /// Normal indices of each triangle, if the mesh has normals.
    pub face_normals: Vec<[u32; 3]>,
    /// The hierarchy over the faces; a leaf is a run of `leaf_triangles`.
    bvh: Bvh,
    /// Every face's corners, in the order the hierarchy's leaves list them, so a
    /// leaf's triangles lie side by side in memory and a test reads no indices.
    leaf_triangles: Vec<Triangle>,
    /// The face each entry of `leaf_triangles` is.
    leaf_faces: Vec<u32>,
}

impl Mesh {
    /// A mesh from its vertices and faces (indices known to be in range); builds
    /// its hierarchy. `face_normals` is empty or has one entry per face.
    pub fn new(
        positions: Vec<DVec3>,
        normals: Vec<DVec3>,
        faces: Vec<[u32; 3]>,
        face_normals: Vec<[u32; 3]>,
    ) -> Mesh {
        let mut mesh = Mesh {
            positions,
            normals,
            faces,
            face_normals,
            bvh: Bvh::build(&[]),
            leaf_triangles: Vec::new(),
            leaf_faces: Vec::new(),
        };
        let bounds: Vec<Bounds> = (0..mesh.faces.len())
            .map(|f| {
                let t = mesh.triangle(f);
                Bounds::around([t.a, t.b, t.c])
            })
            .collect();
        mesh.bvh = Bvh::build(&bounds);
        mesh.leaf_faces = mesh.bvh.leaf_order().to_vec();
        mesh.leaf_triangles = (mesh.leaf_faces.iter())
            .map(|&f| mesh.triangle(f as usize))
            .collect();
        mesh
    }

    /// Triangle `face`.
    #[inline]
    pub fn triangle(&self, face: usize) -> Triangle {
        let [a, b, c] = self.faces[face];
        Triangle {
            a: self.positions[a as usize],
            b: self.positions[b as usize],
            c: self.positions[c as usize],
        }
    }

    /// The box around the mesh.
    pub fn bounds(&self) -> Bounds {
        self.bvh.bounds()
    }

    /// The mesh's own hierarchy.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// The nearest hit in `(0, t_max)` as a root on its face; with
    /// [`Search::Any`], the first hit found (enough for a shadow ray).
    #[inline(never)]
    pub fn roots(
        &self,
        ray: &Ray,
        method: TriangleMethod,
        mut t_max: f64,
        search: Search,
        tested: &mut TestCounts,
    ) -> Roots {
        // The shear is prepared at the first leaf, out of line: many rays reach
        // no leaf (most primary rays miss the mesh), and inlined it slows the walk.
        let mut sheared = None;
        let mut nearest = None;
        let mut faces = 0;
        // A leaf is a run of `leaf_triangles`, tested in order, a hit shrinking `t_max` for the
        // next, so of equal `t`s the first found is kept.
        let _ =
            self.bvh
                .traverse_leaves(&RayBox::new(ray), 0.0, &mut t_max, tested, |leaf, t_max| {
                    let first = leaf.start;
                    let sheared = match sheared {
                        Some(s) => s,
                        None => *sheared.insert(prepare(ray)),
                    };
                    for (i, tri) in self.leaf_triangles[leaf].iter().enumerate() {
                        faces += 1;
                        let hit = match method {
                            TriangleMethod::Watertight => tri.watertight_t(&sheared, 0.0, *t_max),
                            TriangleMethod::MollerTrumbore => {
                                tri.moller_trumbore(ray, 0.0, *t_max).map(|h| h.t)
                            }
                        };
                        if let Some(t) = hit {
                            *t_max = t;
                            nearest = Some((t, first + i));
                            if search == Search::Any {
                                return ControlFlow::Break(());
                            }
                        }
                    }
                    ControlFlow::Continue(())
                });
        tested.primitives += faces;
        nearest.map_or(Roots::NONE, |(t, at)| {
            Roots::on_face(t, self.leaf_faces[at])
        })
    }

    #[inline]
    fn hit_face(
        &self,
        face: usize,
        ray: &Ray,
        sheared: &ShearedRay,
        method: TriangleMethod,
        t_max: f64,
    ) -> Option<TriangleHit> {
        hit_triangle(&self.triangle(face), ray, sheared, method, t_max)
    }

    /// The surface where `ray` meets face `face` at `t`.
    pub fn surface(&self, ray: &Ray, t: f64, face: usize, method: TriangleMethod) -> Surface {
        let tri = self.triangle(face);
        let hit = self
            .hit_face(face, ray, &ShearedRay::new(ray), method, f64::INFINITY)
            .filter(|h| h.t == t)
            .unwrap_or_else(|| TriangleHit {
                t,
                bary: tri.barycentric(ray.at(t)),
            });
        let normals = self.face_normals.get(face).map(|n| {
            [
                self.normals[n[0] as usize],
                self.normals[n[1] as usize],
                self.normals[n[2] as usize],
            ]
        });
        tri.surface(&hit, normals)
    }
}

/// The ray prepared for the watertight test, out of the traversal's loop.
#[cold]
#[inline(never)]
fn prepare(ray: &Ray) -> ShearedRay {
    ShearedRay::new(ray)
}

/// The hit of `ray` with `tri` in `(0, t_max)` by `method`.
#[inline]
fn hit_triangle(
    tri: &Triangle,
    ray: &Ray,
    sheared: &ShearedRay,
    method: TriangleMethod,
    t_max: f64,
) -> Option<TriangleHit> {
    match method {
        TriangleMethod::Watertight => tri.watertight(sheared, 0.0, t_max),
        TriangleMethod::MollerTrumbore => tri.moller_trumbore(ray, 0.0, t_max),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit square in z = 0 as two triangles.
    fn square() -> Mesh {
        Mesh::new(
            vec![
                DVec3::new(0.0, 0.0, 0.0),
                DVec3::new(1.0, 0.0, 0.0),
                DVec3::new(1.0, 1.0, 0.0),
                DVec3::new(0.0, 1.0, 0.0),
            ],
            vec![],
            vec![[0, 1, 2], [0, 2, 3]],
            vec![],
        )
    }

    #[test]
    fn finds_the_face_and_its_surface() {
        let m = square();
        let ray = Ray::new(DVec3::new(0.2, 0.7, 1.0), DVec3::NEG_Z);
        let mut tested = TestCounts::default();
        let roots = m.roots(
            &ray,
            TriangleMethod::Watertight,
            f64::INFINITY,
            Search::Closest,
            &mut tested,
        );
        assert_eq!(roots.as_slice(), &[1.0]);
        assert_eq!(roots.face(), 1);
        assert!(tested.primitives >= 1 && tested.boxes >= 1);
        let s = m.surface(&ray, 1.0, 1, TriangleMethod::Watertight);
        assert_eq!(s.normal, DVec3::Z);
        assert!((s.point - DVec3::new(0.2, 0.7, 0.0)).length() < 1e-16);
    }

    /// The nearest hit of rays through a bumpy sheet of triangles, shared
    /// edges and vertices included, is the least `t` over every face, bit for
    /// bit, and the face named meets the ray there; a shadow-ray search finds
    /// a hit when there is one.
    #[test]
    fn the_walk_finds_the_nearest_face_of_all() {
        let n = 24;
        let height = |i: usize, j: usize| ((i * 7 + j * 13) % 5) as f64 * 0.05;
        let positions: Vec<DVec3> = (0..=n)
            .flat_map(|j| (0..=n).map(move |i| (i, j)))
            .map(|(i, j)| DVec3::new(i as f64, j as f64, height(i, j)))
            .collect();
        let at = |i: usize, j: usize| (j * (n + 1) + i) as u32;
        let faces: Vec<[u32; 3]> = (0..n)
            .flat_map(|j| (0..n).map(move |i| (i, j)))
            .flat_map(|(i, j)| {
                [
                    [at(i, j), at(i + 1, j), at(i + 1, j + 1)],
                    [at(i, j), at(i + 1, j + 1), at(i, j + 1)],
                ]
            })
            .collect();
        let m = Mesh::new(positions, vec![], faces, vec![]);
        let mut rng = fastrand::Rng::with_seed(11);
        let mut hits = 0;
        for k in 0..3000 {
            let origin = DVec3::new(rng.f64() * 30.0 - 3.0, rng.f64() * 30.0 - 3.0, 3.0);
            // Every third ray aimed at a vertex, where faces meet.
            let target = if k % 3 == 0 {
                let (i, j) = (rng.usize(..=n), rng.usize(..=n));
                DVec3::new(i as f64, j as f64, height(i, j))
            } else {
                DVec3::new(rng.f64() * 24.0, rng.f64() * 24.0, 0.0)
            };
            let ray = Ray::new(origin, target - origin);
            for method in [TriangleMethod::Watertight, TriangleMethod::MollerTrumbore] {
                let each = |f: usize| {
                    hit_triangle(
                        &m.triangle(f),
                        &ray,
                        &ShearedRay::new(&ray),
                        method,
                        f64::INFINITY,
                    )
                    .map(|h| h.t)
                };
                let least = (0..m.faces.len()).filter_map(each).reduce(f64::min);
                let mut tested = TestCounts::default();
                let roots = m.roots(&ray, method, f64::INFINITY, Search::Closest, &mut tested);
                assert_eq!(roots.as_slice().first().copied(), least, "ray {k}");
                if let Some(t) = least {
                    hits += 1;
                    assert_eq!(each(roots.face() as usize), Some(t), "ray {k}");
                }
                let any = m.roots(&ray, method, f64::INFINITY, Search::Any, &mut tested);
                assert_eq!(any.as_slice().is_empty(), least.is_none(), "ray {k}");
            }
        }
        assert!(hits > 3000, "{hits} hits");
    }

    #[test]
    fn t_max_cuts_the_search() {
        let m = square();
        let ray = Ray::new(DVec3::new(0.2, 0.7, 1.0), DVec3::NEG_Z);
        let mut tested = TestCounts::default();
        let roots = m.roots(
            &ray,
            TriangleMethod::Watertight,
            0.5,
            Search::Closest,
            &mut tested,
        );
        assert!(roots.as_slice().is_empty());
    }
}
