#!/usr/bin/env python3
"""Your ray tracer. The plumbing (reading scenes, writing images and traces,
finding the closest object, running the tests) is done in ../learner_io.py;
the lecture's formulas are yours to write, one or two per lesson, below.

Each function raises NotImplementedError until you write it. After each
lesson, run its test vectors (made by raytree from the lesson's own scene):

    python3 lessons/python/starter/tracer.py test 03     # lesson 03's cases
    python3 lessons/python/starter/tracer.py test        # all of them
    python3 lessons/python/starter/tracer.py test FILE.json   # `raytree vectors SCENE -o FILE.json`

When raytrace() (lesson 11) is written too, render and check a pixel:

    python3 lessons/python/starter/tracer.py scenes/whitted.json --width 64 --height 48 -o mine.ppm
    python3 lessons/python/starter/tracer.py scenes/whitted.json --pixel 416,209 -o mine.json
    raytree check scenes/whitted.json --pixel 416,209 mine.json

Vectors are 3-tuples; learner_io has add, sub, scale, mul (color times
color), dot, cross, length, normalize, neg and ZERO.
"""

import math  # noqa: F401  (you will want it)
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

from learner_io import (  # noqa: E402,F401  (the path is set just above)
    add, sub, scale, mul, dot, cross, length, normalize, neg, ZERO, vec_json,
    apply_point, apply_vector, apply_transpose, offset_origin, main,
)


def todo(lesson, what):
    raise NotImplementedError("%s: write it (book/src/lessons/%s.md, vectors: `tracer.py test %s`)"
                              % (what, lesson, lesson[:2]))


# ------------------------------------------------------------ lesson 03: the camera


def image_plane_point(camera, x, y):
    """The point P(r, c) on the image plane for pixel (x, y).

    x counts columns from the left, y rows from the TOP (as image files do);
    the lecture counts its rows r from the bottom. camera has eye, u, v, n,
    half_width (W), half_height (H), distance (N), columns (N_c), rows (N_r).
    Returns a 3-tuple."""
    todo("03-camera", "image_plane_point")


# ------------------------------------------------------------ lesson 04: rays


def primary_ray(camera, x, y):
    """The ray from the eye through pixel (x, y): returns (origin, direction),
    with the direction P - eye, not normalized (so t = 1 is on the image plane)."""
    todo("04-rays", "primary_ray")


def plane_root(point, normal, origin, direction):
    """Where the ray origin + t*direction meets the plane through `point`
    with unit `normal`: t, or None when the ray runs parallel to it."""
    todo("04-rays", "plane_root")


# ------------------------------------------------------------ lesson 05: the sphere


def sphere_roots(center, radius, origin, direction):
    """Every t where the ray's line meets the sphere, ascending: [], [t] or
    [t1, t2]. The direction may have any length."""
    todo("05-sphere", "sphere_roots")


def first_root(roots, t_min, t_max):
    """Which root is the hit: the smallest t with t_min < t < t_max, or None."""
    todo("05-sphere", "first_root")


# ------------------------------------------------------------ lesson 06: transforms


def to_object_ray(inverse, origin, direction):
    """The ray carried into the object's own space by M^-1, given as three rows
    [a, b, c, t] of an affine map: returns (origin', direction').
    (learner_io.apply_point and apply_vector may help.)"""
    todo("06-transforms", "to_object_ray")


def normal_to_world(inverse, normal):
    """The object-space unit normal carried back into the world, unit length.
    `inverse` is M^-1 as above. (learner_io.apply_transpose may help.)"""
    todo("06-transforms", "normal_to_world")


# ------------------------------------------------------------ lesson 07: Phong


def phong(material, color, ambient_light, normal, to_viewer, lights):
    """The local color: ambient plus, for each (L, arriving) in `lights` (the
    unit direction to a light its shadow ray reached, and that light's color
    as it arrives), the diffuse and specular terms. material has ambient,
    diffuse, specular, shininess; normal faces the viewer; all unit."""
    todo("07-phong", "phong")


# ------------------------------------------------------------ lesson 08: shadows


def shadow_ray(tracer, point, normal, light):
    """The shadow ray from a hit `point` (unit `normal` facing the incoming ray)
    toward scene light number `light` (tracer.scene.lights[light].position).

    Returns a dict: blocked (True/False), by (the name of the opaque object in
    the way, or None), transmitted (1.0, times the `transparent` share of each
    transparent object crossed; 0.0 when blocked), faces_away (True when the
    light is behind the surface: no ray is cast, and blocked is True),
    origin and direction of the shadow ray (None when faces_away).
    tracer.scene.objects are the objects (.name, .material.transparent);
    tracer.roots(obj, origin, direction) gives a ray's roots with one of them."""
    todo("08-shadows", "shadow_ray")


# ------------------------------------------------------------ lesson 09: reflection


def reflect(c, n):
    """The mirror direction of incoming direction c about unit normal n."""
    todo("09-reflection", "reflect")


# ------------------------------------------------------------ lesson 10: refraction


def refract(c, n, n1, n2):
    """The refracted direction for unit incoming c and unit normal n facing
    it (n.c < 0), from index n1 into index n2; None for total internal reflection."""
    todo("10-refraction", "refract")


# ------------------------------------------------------------ lesson 11: recursion


def combine(local, k_rfl, reflected, k_rfa, refracted):
    """A ray's color from its local color and its children's colors."""
    todo("11-recursion", "combine")


def raytrace(tracer, kind, origin, direction, depth, weight, media):
    """The lecture's raytrace(): returns (color, node), node being this ray in
    the learner trace format (docs/learner-trace.md):

        {"kind": kind, "origin": [...], "direction": [...],
         "hit": None or {"object": name, "t": t, "point": [...], "normal": [...], "entering": bool},
         "shadows": [{"light": name, "blocked": bool, "by": name or None,
                      "transmitted": share, "origin": [...], "direction": [...]}, ...],
         "local": [...], "k_rfl": k, "k_rfa": k, "tir": bool,
         "reflected": node or None, "refracted": node or None, "color": [...]}

    (vec_json turns a tuple into a list; a shadow ray's origin and direction
    may be left out, and with them written the check compares them first.) The plumbing gives you:
    tracer.closest_hit(origin, direction) -> (object index, t) or None;
    tracer.surface(i, origin, direction, t) -> (point, outward normal, pattern point);
    tracer.side(i, direction, outward normal, media) -> (entering, n1, n2, media beyond);
    tracer.scene.background, .lights, .objects[i].material (.color_at(pattern point),
    .reflective = k_rfl, .transparent = k_rfa), .ambient_light;
    tracer.settings.max_depth, .cutoff; offset_origin(point, normal, direction)
    for a secondary ray's start. The reflected ray travels in `media`, the
    refracted one in the media beyond."""
    todo("11-recursion", "raytrace")


if __name__ == "__main__":
    sys.exit(main(sys.modules[__name__]))
