#!/usr/bin/env python3
"""The teacher's file: the complete Python tracer whose functions the starter
(../starter/tracer.py) leaves for the learner, one or two per lesson. Keep it
away from the learners; CI runs it against raytree (tools/compare.py) and
against the lessons' test vectors (`solution.py test`).

Where raytree uses a robust method, this file uses the textbook one the
lecture teaches and says so; its numbers agree with raytree's within the
tolerances of lessons/python/tools/compare.py.

    python3 solution.py scenes/whitted.json --width 64 --height 48 -o whitted.ppm
    python3 solution.py scenes/whitted.json --pixel 416,209 -o trace.json
    python3 solution.py test            # every lesson's vectors
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

from learner_io import (  # noqa: E402  (the path is set just above)
    add, sub, scale, mul, dot, normalize, neg, ZERO, vec_json,
    apply_point, apply_vector, apply_transpose, offset_origin, main,
)

# ------------------------------------------------------------ lesson 03: the camera


def image_plane_point(camera, x, y):
    """Pixel (x, y), counted from the image's top-left, to the point P(r, c) on
    the image plane. The lecture counts rows r up from the bottom, so
    r = N_r - 1 - y; pixel (c, r)'s point is u_c = -W + W*2c/(N_c - 1),
    v_r = -H + H*2r/(N_r - 1), so the outermost pixels sit on the plane's edges."""
    c, r = x, camera.rows - 1 - y
    u_c = -camera.half_width + camera.half_width * 2.0 * c / (camera.columns - 1)
    v_r = -camera.half_height + camera.half_height * 2.0 * r / (camera.rows - 1)
    centre = sub(camera.eye, scale(camera.n, camera.distance))
    return add(add(centre, scale(camera.u, u_c)), scale(camera.v, v_r))


# ------------------------------------------------------------ lesson 04: rays


def primary_ray(camera, x, y):
    """ray(t) = eye + t*(P - eye): the direction is not normalized, so t = 1
    lies on the image plane."""
    return camera.eye, sub(image_plane_point(camera, x, y), camera.eye)


def plane_root(point, normal, origin, direction):
    """The plane (P - P0).n = 0 met by S + t*c: t = (P0 - S).n / (c.n); None
    when the ray runs parallel to it."""
    denominator = dot(direction, normal)
    if denominator == 0.0:
        return None
    return dot(sub(point, origin), normal) / denominator


# ------------------------------------------------------------ lesson 05: the sphere


def sphere_roots(center, radius, origin, direction):
    """The lecture's quadratic A t^2 + 2B t + C = 0 with A = c.c, B = (S - C0).c,
    C = |S - C0|^2 - r^2: roots (-B -+ sqrt(B^2 - AC))/A, ascending. This is the
    textbook form; raytree's default is the stable one (lesson 13), which agrees
    here to about 1e-12."""
    f = sub(origin, center)
    a = dot(direction, direction)
    b = dot(f, direction)
    c = dot(f, f) - radius * radius
    disc = b * b - a * c
    if disc < 0.0:
        return []
    if disc == 0.0:
        return [-b / a]
    s = math.sqrt(disc)
    return [(-b - s) / a, (-b + s) / a]


def first_root(roots, t_min, t_max):
    """The hit: the smallest root strictly between t_min and t_max (roots at or
    behind the ray's start are not hits)."""
    for t in sorted(roots):
        if t_min < t < t_max:
            return t
    return None


# ------------------------------------------------------------ lesson 06: transforms


def to_object_ray(inverse, origin, direction):
    """The inverse-transformed ray S' + t*c': S' = M^-1 S (a point: moved too),
    c' = M^-1 c (a direction: not moved, and not normalized, so t is the same
    on both rays)."""
    return apply_point(inverse, origin), apply_vector(inverse, direction)


def normal_to_world(inverse, normal):
    """A normal goes back through the inverse transpose, N = (M^-1)^T n',
    normalized: carried like a point it would tilt wherever M scales unevenly."""
    return normalize(apply_transpose(inverse, normal))


# ------------------------------------------------------------ lesson 07: Phong


def phong(material, color, ambient_light, normal, to_viewer, lights):
    """I = k_a*color*ambient + sum over the lights that reach the point of
    k_d*(N.L)*color*light + k_s*(R.V)^shininess*light, R = 2(N.L)N - L. A light
    behind the surface (N.L <= 0) adds nothing; R.V is clamped at 0.
    `lights` is a list of (L, arriving light color)."""
    local = scale(mul(color, ambient_light), material.ambient)
    for to_light, arriving in lights:
        n_dot_l = dot(normal, to_light)
        if n_dot_l <= 0.0:
            continue
        local = add(local, scale(mul(color, arriving), material.diffuse * n_dot_l))
        mirrored = sub(scale(normal, 2.0 * n_dot_l), to_light)
        r_dot_v = max(dot(mirrored, to_viewer), 0.0)
        if material.specular > 0.0 and r_dot_v > 0.0:
            local = add(local, scale(arriving, material.specular * r_dot_v ** material.shininess))
    return local


# ------------------------------------------------------------ lesson 08: shadows

# A shadow ray S + t*(light - S) ends just short of t = 1, the light itself.
SHADOW_T_MAX = 1.0 - 1e-9


def shadow_ray(tracer, point, normal, light):
    """The shadow ray from `point` (normal: the one facing the incoming ray)
    toward light number `light`. No ray when the light is behind the surface.
    An opaque object before the light blocks it; a transparent one lets
    through its k_rfa share (raytree's choice: no bending). Starts a hair off
    the surface, else it finds its own surface at t ~ 0 (acne).
    Returns {"blocked", "by", "transmitted", "faces_away", "origin", "direction"}."""
    position = tracer.scene.lights[light].position
    out = {"blocked": True, "by": None, "transmitted": 0.0, "faces_away": True,
           "origin": None, "direction": None}
    if dot(normal, sub(position, point)) <= 0.0:
        return out
    origin = offset_origin(point, normal, sub(position, point))
    direction = sub(position, origin)
    out.update(faces_away=False, blocked=False, transmitted=1.0, origin=origin, direction=direction)
    for obj in tracer.scene.objects:
        if first_root(tracer.roots(obj, origin, direction), 0.0, SHADOW_T_MAX) is None:
            continue
        if obj.material.transparent == 0.0:
            out.update(blocked=True, by=obj.name, transmitted=0.0)
            break
        out["transmitted"] *= obj.material.transparent
    return out


# ------------------------------------------------------------ lesson 09: reflection


def reflect(c, n):
    """The lecture's mirror direction v = c - 2(n.c)n (n unit, either side)."""
    return sub(c, scale(n, 2.0 * dot(n, c)))


# ------------------------------------------------------------ lesson 10: refraction


def refract(c, n, n1, n2):
    """Snell's law n1 sin(theta1) = n2 sin(theta2) for unit c and unit n facing
    it: with eta = n1/n2, t = eta*c + (eta*cos(theta1) - cos(theta2))*n. None is
    total internal reflection (sin(theta2) would exceed 1)."""
    eta = n1 / n2
    cos1 = -dot(n, c)
    sin2_sq = eta * eta * max(1.0 - cos1 * cos1, 0.0)
    if sin2_sq > 1.0:
        return None
    cos2 = math.sqrt(1.0 - sin2_sq)
    return add(scale(c, eta), scale(n, eta * cos1 - cos2))


# ------------------------------------------------------------ lesson 11: recursion


def combine(local, k_rfl, reflected, k_rfa, refracted):
    """color = local + k_rfl*reflected + k_rfa*refracted."""
    return add(local, add(scale(reflected, k_rfl), scale(refracted, k_rfa)))


def raytrace(tracer, kind, origin, direction, depth, weight, media):
    """The lecture's raytrace(): the closest hit, its local color, the
    reflected and refracted rays, their sum. Returns (color, node), node being
    this ray in the learner trace format. `media`: the transparent objects the
    ray is inside (indices, innermost last)."""
    scene, settings = tracer.scene, tracer.settings
    node = {"kind": kind, "origin": vec_json(origin), "direction": vec_json(direction)}
    found = tracer.closest_hit(origin, direction)
    if found is None:
        node.update(hit=None, color=vec_json(scene.background))
        return scene.background, node
    i, t = found
    obj = scene.objects[i]
    material = obj.material
    point, outward, pattern = tracer.surface(i, origin, direction, t)
    # Which side: a ray leaving glass meets the outward normal from behind,
    # so every formula below takes the normal turned toward it, and n1, n2
    # are the media on either side (the glass's index, then the air's, or
    # the glass's again leaving the cavity): lesson 10.
    entering, n1, n2, beyond = tracer.side(i, direction, outward, media)
    n = outward if entering else neg(outward)
    node["hit"] = {"object": obj.name, "t": t, "point": vec_json(point),
                   "normal": vec_json(n), "entering": entering}
    # Local color: ambient, and each light its shadow ray reaches (lessons 07, 08).
    color = material.color_at(pattern)
    to_viewer = neg(normalize(direction))
    lit, shadows = [], []
    for k, light in enumerate(scene.lights):
        s = shadow_ray(tracer, point, n, k)
        shadows.append({"light": light.name, "blocked": s["blocked"], "by": s["by"],
                        "transmitted": s["transmitted"]})
        if not s["faces_away"]:
            shadows[-1].update(origin=vec_json(s["origin"]), direction=vec_json(s["direction"]))
        if not s["blocked"]:
            lit.append((normalize(sub(light.position, point)), scale(light.color, s["transmitted"])))
    local = phong(material, color, scene.ambient_light, n, to_viewer, lit)
    node["shadows"] = shadows
    node["local"] = vec_json(local)
    # The shares (lesson 11): total internal reflection hands k_rfa to the
    # reflected ray, as raytree does, so the light is neither lost nor doubled.
    c = normalize(direction)
    k_rfl, k_rfa = material.reflective, material.transparent
    refracted_dir = refract(c, n, n1, n2) if k_rfa > 0.0 else None
    tir = k_rfa > 0.0 and refracted_dir is None
    if tir:
        k_rfl, k_rfa = k_rfl + k_rfa, 0.0
    node["k_rfl"], node["k_rfa"], node["tir"] = k_rfl, k_rfa, tir
    colors = {}
    for name, k, d, child_media in (("reflected", k_rfl, reflect(c, n), media),
                                    ("refracted", k_rfa, refracted_dir, beyond)):
        # A child is traced unless its coefficient is 0, the parent is at the
        # deepest level, or its weight would fall below the cutoff (Hall &
        # Greenberg 1983).
        if d is None or k == 0.0 or depth >= settings.max_depth or weight * k < settings.cutoff:
            node[name] = None
            colors[name] = ZERO
            continue
        start = offset_origin(point, outward, d)
        colors[name], node[name] = raytrace(tracer, name, start, d, depth + 1, weight * k, child_media)
    total = combine(local, k_rfl, colors["reflected"], k_rfa, colors["refracted"])
    node["color"] = vec_json(total)
    return total, node


if __name__ == "__main__":
    sys.exit(main(sys.modules[__name__]))
