#!/usr/bin/env python3
"""Mutants of the teacher's solution: each is ../teacher/solution.py with one
classic mistake of a learner's tracer applied (a textual substitution, made
in memory), the pixel that shows it, and what `raytree check` must say there
first: the diagnosis id and the ray. The suite runs them all
(tests/suite/tracer/mutants.rs) and the book shows one a lesson (03-11),
from the learner traces this tool writes (lessons/NN-topic/mutant.json).

    python3 lessons/python/tools/mutants.py table          # the table, as JSON
    python3 lessons/python/tools/mutants.py write DIR      # DIR/NAME.json for each mutant,
                                                           # DIR/NAME.clean.json unmutated
    python3 lessons/python/tools/mutants.py write DIR NAME ...

A substitution must apply exactly once: when the solution changes under it,
this tool stops with one line naming the mutant (exit 2), so a mutant never
silently becomes the solution.
"""

import json
import os
import sys
import types

TOOLS = os.path.dirname(os.path.abspath(__file__))
PYTHON = os.path.dirname(TOOLS)
# The solution mutated: the teacher's (another file only for the suite's
# test that a substitution which no longer applies stops the tool).
SOLUTION = os.environ.get("MUTANTS_SOLUTION") or os.path.join(PYTHON, "teacher", "solution.py")
sys.path.insert(0, PYTHON)

import learner_io  # noqa: E402  (the path is set just above)

WHITTED = "scenes/whitted.json"
# A floor pixel of the Whitted scene whose key light passes through the glass ball.
GLASS_SHADOW = (440, 376)

# name, the lesson whose "Build it yourself" shows it (or None), the text
# replaced, its replacement, the scene and pixel, the diagnosis id (None: the
# check names the number but no classic mistake) and the ray of the first
# divergence.
MUTANTS = [
    ("rows-flipped", "03-camera",
     "c, r = x, camera.rows - 1 - y", "c, r = x, y",
     WHITTED, (416, 209), "rows-flipped", "primary"),
    ("pixel-corner", "04-rays",
     "c, r = x, camera.rows - 1 - y", "c, r = x + 0.5, camera.rows - 1 - y + 0.5",
     WHITTED, (416, 209), "pixel-corner", "primary"),
    ("pixel-spacing", None,
     "camera.half_width * 2.0 * c / (camera.columns - 1)\n"
     "    v_r = -camera.half_height + camera.half_height * 2.0 * r / (camera.rows - 1)",
     "camera.half_width * 2.0 * c / camera.columns\n"
     "    v_r = -camera.half_height + camera.half_height * 2.0 * r / camera.rows",
     WHITTED, (416, 209), "pixel-spacing", "primary"),
    ("far-root", "05-sphere",
     "for t in sorted(roots):", "for t in sorted(roots, reverse=True):",
     WHITTED, (416, 209), "far-root", "primary"),
    ("negative-root", None,
     "if t_min < t < t_max:", "if t < t_max:",
     "lessons/05-sphere/behind.json", (160, 120), "negative-root", "primary"),
    ("normal-as-point", "06-transforms",
     "return normalize(apply_transpose(inverse, normal))",
     "return normalize(apply_vector(inverse, normal))",
     "lessons/06-transforms/ellipsoid.json", (200, 70), "normal-transform", "primary"),
    ("rv-not-clamped", "07-phong",
     "r_dot_v = max(dot(mirrored, to_viewer), 0.0)\n"
     "        if material.specular > 0.0 and r_dot_v > 0.0:",
     "r_dot_v = dot(mirrored, to_viewer)\n"
     "        if material.specular > 0.0:",
     "lessons/07-phong/broad.json", (145, 35), "not-clamped", "primary"),
    ("ambient-forgotten", None,
     "local = scale(mul(color, ambient_light), material.ambient)", "local = ZERO",
     "lessons/07-phong/ball.json", (135, 83), "ambient-forgotten", "primary"),
    ("specular-colored", None,
     "scale(arriving, material.specular * r_dot_v", "scale(mul(color, arriving), material.specular * r_dot_v",
     "lessons/07-phong/ball.json", (135, 83), "specular-colored", "primary"),
    ("transparent-per-surface", None,
     'out["transmitted"] *= obj.material.transparent\n',
     'out["transmitted"] *= obj.material.transparent ** len(\n'
     '            [t for t in tracer.roots(obj, origin, direction) if 0.0 < t < SHADOW_T_MAX])\n',
     WHITTED, GLASS_SHADOW, "transparent-per-surface", "primary"),
    ("shadow-beyond-light", "08-shadows",
     "SHADOW_T_MAX = 1.0 - 1e-9", "SHADOW_T_MAX = math.inf",
     "lessons/08-shadows/ceiling.json", (130, 90), "shadow-beyond-light", "primary"),
    ("shadow-reversed", None,
     "direction = sub(position, origin)", "direction = sub(origin, position)",
     WHITTED, (168, 120), "shadow-reversed", "primary"),
    ("shadow-no-offset", None,
     "origin = offset_origin(point, normal, sub(position, point))", "origin = point",
     WHITTED, (168, 120), "no-offset", "primary"),
    ("child-no-offset", None,
     "start = offset_origin(point, outward, d)", "start = point",
     WHITTED, (168, 120), "no-offset", "primary → reflected d2"),
    ("reflection-sign", "09-reflection",
     "return sub(c, scale(n, 2.0 * dot(n, c)))", "return add(c, scale(n, 2.0 * dot(n, c)))",
     WHITTED, (200, 280), "reflection-sign", "primary → reflected d2"),
    ("eta-swapped", "10-refraction",
     "eta = n1 / n2", "eta = n2 / n1",
     WHITTED, (416, 209), "eta-swapped", "primary → refracted d2"),
    ("refraction-root-sign", None,
     "scale(n, eta * cos1 - cos2)", "scale(n, eta * cos1 + cos2)",
     WHITTED, (416, 209), "refraction-root-sign", "primary → refracted d2"),
    ("refraction-cos-sign", None,
     "cos1 = -dot(n, c)", "cos1 = dot(n, c)",
     WHITTED, (416, 209), "refraction-cos-sign", "primary → refracted d2"),
    ("normal-not-turned", None,
     "n = outward if entering else neg(outward)", "n = outward",
     WHITTED, (416, 209), "normal-not-turned", "primary → refracted d2 → reflected d3"),
    ("normal-inward", None,
     "n = outward if entering else neg(outward)", "n = neg(outward) if entering else outward",
     WHITTED, (416, 209), "normal-inward", "primary"),
    ("normal-not-unit", None,
     "return normalize(apply_transpose(inverse, normal))",
     "return apply_transpose(inverse, normal)",
     "lessons/06-transforms/ellipsoid.json", (200, 70), "not-normalized", "primary"),
    ("view-sign", None,
     "to_viewer = neg(normalize(direction))", "to_viewer = normalize(direction)",
     "lessons/07-phong/ball.json", (135, 83), "view-sign", "primary"),
    ("view-not-normalized", None,
     "to_viewer = neg(normalize(direction))", "to_viewer = neg(direction)",
     "lessons/07-phong/ball.json", (135, 83), "not-normalized", "primary"),
    ("light-not-normalized", None,
     "lit.append((normalize(sub(light.position, point)),",
     "lit.append((sub(light.position, point),",
     "lessons/07-phong/ball.json", (135, 83), "not-normalized", "primary"),
    ("glass-blocks-light", None,
     "if obj.material.transparent == 0.0:", "if True:",
     WHITTED, GLASS_SHADOW, "transparent-blocks", "primary"),
    ("direction-not-normalized", None,
     "c = normalize(direction)", "c = direction",
     WHITTED, (416, 209), "not-normalized", "primary → refracted d2"),
    ("air-outside", None,
     "entering, n1, n2, beyond = tracer.side(i, direction, outward, media)",
     "entering, n1, n2, beyond = tracer.side(i, direction, outward, media)\n"
     "    n1, n2 = (1.0, material.ior) if entering else (material.ior, 1.0)",
     WHITTED, (416, 209), "wrong-medium", "primary → refracted d2"),
    ("tir-clamped", None,
     "if sin2_sq > 1.0:\n        return None\n    cos2 = math.sqrt(1.0 - sin2_sq)",
     "cos2 = math.sqrt(max(1.0 - sin2_sq, 0.0))",
     WHITTED, (416, 209), "tir-not-handled", "primary → refracted d2"),
    ("tir-share-lost", None,
     "        k_rfl, k_rfa = k_rfl + k_rfa, 0.0\n", "        k_rfa = 0.0\n",
     WHITTED, (416, 209), "tir-not-handled", "primary → refracted d2"),
    ("coefficients-missing", "11-recursion",
     "return add(local, add(scale(reflected, k_rfl), scale(refracted, k_rfa)))",
     "return add(local, add(reflected, refracted))",
     WHITTED, (190, 110), "coefficients", "primary"),
    ("coefficients-twice", None,
     "colors[name], node[name] = raytrace(tracer, name, start, d, depth + 1, weight * k, child_media)",
     "colors[name], node[name] = raytrace(tracer, name, start, d, depth + 1, weight * k, child_media)\n"
     "        colors[name] = scale(colors[name], k)",
     WHITTED, (190, 110), "coefficients", "primary"),
]


class Refused(Exception):
    pass


def table():
    return [{"name": m[0], "lesson": m[1], "find": m[2], "replace": m[3], "scene": m[4],
             "pixel": list(m[5]), "diagnosis": m[6], "ray": m[7]} for m in MUTANTS]


def module(name, source):
    """The solution's source as a module of its own (never written to disk)."""
    mod = types.ModuleType("mutant_" + name.replace("-", "_"))
    mod.__file__ = SOLUTION
    exec(compile(source, "%s [mutant %s]" % (SOLUTION, name), "exec"), mod.__dict__)
    return mod


def mutate(source, m):
    count = source.count(m["find"])
    if count != 1:
        raise Refused("mutant %s: its text is found %d times in %s, not once: update the table "
                      "in lessons/python/tools/mutants.py" % (m["name"], count, SOLUTION))
    return source.replace(m["find"], m["replace"])


def trace(mod, m, out):
    x, y = m["pixel"]
    code = learner_io.main(mod, [m["scene"], "--pixel", "%d,%d" % (x, y), "-o", out])
    if code != 0:
        raise Refused("mutant %s: the tracer stopped (exit %d)" % (m["name"], code))


def write(folder, names):
    with open(SOLUTION, encoding="utf-8") as f:
        source = f.read()
    known = [m["name"] for m in table()]
    for n in names:
        if n not in known:
            raise Refused("no mutant named '%s'; the mutants: %s" % (n, ", ".join(known)))
    os.makedirs(folder, exist_ok=True)
    clean = module("clean", source)
    for m in table():
        if names and m["name"] not in names:
            continue
        trace(module(m["name"], mutate(source, m)), m, os.path.join(folder, m["name"] + ".json"))
        trace(clean, m, os.path.join(folder, m["name"] + ".clean.json"))


def run(argv):
    try:
        if argv[:1] == ["table"] and len(argv) == 1:
            sys.stdout.write(json.dumps(table(), indent=1) + "\n")
            return 0
        if argv[:1] == ["write"] and len(argv) >= 2:
            folder = os.path.abspath(argv[1])
            # The scenes are named from the repository's root.
            os.chdir(os.path.dirname(os.path.dirname(PYTHON)))
            write(folder, argv[2:])
            return 0
        sys.stderr.write(__doc__.split("\n\n")[1] + "\n")
        return 2
    except Refused as e:
        sys.stderr.write("error: %s\n" % e)
        return 2


if __name__ == "__main__":
    sys.exit(run(sys.argv[1:]))
