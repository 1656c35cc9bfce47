"""Embree's side of benches/embree/compare.sh: cast a ray set on the Gaspra mesh.

    python embree_rays.py DIR SET [--check]

Reads DIR/triangles.f32 (9 float32 per triangle, world space) and DIR/SET.f64
(6 float64 per ray: origin, direction), both written by raytree's
`closest_hit export`, builds an Embree scene (embreex, the Python binding from
PyPI) and times the closest hit of every ray, single-threaded (embreex casts
one ray after another with rtcIntersect1 on the calling thread). Prints
`seconds=<time> rays=<n> hits=<n> t_sum=<sum of t over hits>`, the time the
fastest of 3 passes, as measured. With --check it only prints the hits and
t_sum, for comparing against raytree's.
"""

import sys
import time

import numpy as np
from embreex import rtcore_scene as rtcs
from embreex.mesh_construction import TriangleMesh


def scene_of(triangles):
    scene = rtcs.EmbreeScene()
    TriangleMesh(scene, triangles)
    return scene


def main():
    folder, ray_set = sys.argv[1], sys.argv[2]
    triangles = np.fromfile(f"{folder}/triangles.f32", dtype="<f4").reshape(-1, 3, 3)
    rays = np.fromfile(f"{folder}/{ray_set}.f64", dtype="<f8").reshape(-1, 6)
    origins = np.ascontiguousarray(rays[:, :3], dtype=np.float32)
    directions = np.ascontiguousarray(rays[:, 3:], dtype=np.float32)
    scene = scene_of(triangles)
    result = scene.run(origins, directions, output=1)
    hit = result["geomID"] >= 0
    hits = int(hit.sum())
    t_sum = float(result["tfar"][hit].astype(np.float64).sum())
    if "--check" in sys.argv:
        print(f"hits={hits} t_sum={t_sum:.6f}")
        return
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        scene.run(origins, directions)
        best = min(best, time.perf_counter() - start)
    print(f"seconds={best:.6f} rays={len(rays)} hits={hits} t_sum={t_sum:.6f}")


if __name__ == "__main__":
    main()
