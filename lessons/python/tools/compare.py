#!/usr/bin/env python3
"""Compares the Python solution (teacher/solution.py) with raytree, ray by ray
and pixel by pixel: the proof that the course's Python tracer reproduces the
oracle's numbers.

    python3 lessons/python/tools/compare.py scenes/whitted.json --width 64 --height 48 --all --image
    python3 lessons/python/tools/compare.py scenes/whitted.json --pixel 416,209 --pixel 386,242
    python3 lessons/python/tools/compare.py scenes/whitted.json --width 64 --height 48 --all --check

For each pixel it runs `raytree trace SCENE --pixel X,Y --json`, traces the
same pixel with the solution in this process, walks both trees side by side
(primary ray, then reflected and refracted children in order) and compares
every quantity of the learner trace format; with --image it renders both
images and compares their bytes; with --check it also hands each pixel's
learner trace to `raytree check` and counts those that check clean. It prints, per quantity, the largest
difference seen and where, and exits 1 when any exceeds its tolerance or the
trees differ in shape (a hit object, a side, a shadow's outcome, a branch).

raytree is `raytree` on PATH, or $RAYTREE.
"""

import importlib.util
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))

import learner_io  # noqa: E402

# Tolerances, absolute unless said otherwise. The two tracers differ in method
# only where the solution takes the textbook way: the textbook quadratic
# (relative error ~1e-15 here, far from cancellation) and a fixed offset of
# 1e-10 (times the point's size) instead of raytree's one past the rounding
# error (~1e-15). A child ray's origin so differs by ~1e-10; through a few
# bounces on curved glass that grows by the curvature's magnification (at
# most ~10 per bounce in these scenes), so 1e-6 leaves a wide margin. Origins
# are compared relative to their size (at least 1), hit points relative to
# the distance the ray travelled (a floor point 600 units away moves with the
# ray's direction times 600); directions are unit vectors compared
# component-wise; t as a distance (t*|direction|), relative to the distance. Colors are sums of terms of size
# ~1 whose inputs agree to ~1e-9, so 1e-6 is far below an 8-bit step (~4e-3).
TOLERANCE = {
    "origin": 1e-6,
    "direction": 1e-6,
    "t": 1e-6,
    "point": 1e-6,
    "normal": 1e-6,
    "local": 1e-6,
    "k_rfl": 1e-12,
    "k_rfa": 1e-12,
    "color": 1e-6,
}


def load_solution():
    path = os.path.join(os.path.dirname(HERE), "teacher", "solution.py")
    spec = importlib.util.spec_from_file_location("solution", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def raytree_bin():
    return os.environ.get("RAYTREE", "raytree")


def size_flags(width, height):
    flags = []
    if width:
        flags += ["--width", str(width)]
    if height:
        flags += ["--height", str(height)]
    return flags


def raytree_trace(scene, pixel, width, height):
    cmd = [raytree_bin(), "trace", scene, "--pixel", "%d,%d" % pixel, "--json"] + size_flags(width, height)
    out = subprocess.run(cmd, check=True, stdout=subprocess.PIPE).stdout
    return json.loads(out)


def reduce(doc):
    """raytree's trace of one sample, as a learner trace's primary RAY."""
    sample = doc["samples"][0]
    nodes = sample["tree"]["nodes"]
    lights = [l["name"] for l in doc["lights"]]

    def ray(i):
        node = nodes[i]
        out = {"kind": node["kind"], "origin": node["origin"], "direction": node["direction"]}
        hit = node["hit"]
        if hit is None:
            out["hit"] = None
            out["color"] = node["sum"]["color"]
            return out
        out["hit"] = {"object": hit["name"], "t": hit["t"], "point": hit["point"],
                      "normal": hit["shading_normal"], "entering": hit["entering"]}
        shadows = []
        for s in node["shadow_rays"]:
            o = s["outcome"]
            shadows.append({"light": lights[s["light"]], "blocked": o["kind"] != "reaches",
                            "by": o.get("name")})
        out["shadows"] = shadows
        out["local"] = node["local"]["total"]
        out["k_rfl"] = node["reflected"]["coefficient"]
        out["k_rfa"] = node["sum"]["k_rfa"]
        out["tir"] = node["refracted"]["outcome"] == "total_internal_reflection"
        for kind in ("reflected", "refracted"):
            child = node[kind]["node"]
            out[kind] = None if child is None else ray(child)
        out["color"] = node["sum"]["color"]
        return out

    return ray(0)


class Report:
    def __init__(self):
        self.worst = {k: (0.0, None) for k in TOLERANCE}
        self.failures = []
        self.rays = 0

    def number(self, quantity, diff, where):
        if diff > self.worst[quantity][0] or self.worst[quantity][1] is None:
            self.worst[quantity] = (diff, where)
        if not diff <= TOLERANCE[quantity]:
            self.failures.append("%s: %s differs by %.3g (tolerance %g)" % (where, quantity, diff, TOLERANCE[quantity]))

    def shape(self, where, what, ours, theirs):
        self.failures.append("%s: %s: raytree %s, solution %s" % (where, what, json.dumps(theirs), json.dumps(ours)))


def vdiff(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


def size(p):
    """The scale an error in point p is measured against: |p|, at least 1."""
    return max(1.0, math.sqrt(sum(x * x for x in p)))


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def compare_ray(ours, theirs, where, report):
    report.rays += 1
    report.number("origin", vdiff(ours["origin"], theirs["origin"]) / size(theirs["origin"]), where)
    report.number("direction", vdiff(unit(ours["direction"]), unit(theirs["direction"])), where)
    a, b = ours.get("hit"), theirs.get("hit")
    if (a is None) != (b is None) or (a and a["object"] != b["object"]):
        report.shape(where, "hit", a and a["object"], b and b["object"])
        return
    if a is not None:
        da = a["t"] * math.sqrt(sum(x * x for x in ours["direction"]))
        db = b["t"] * math.sqrt(sum(x * x for x in theirs["direction"]))
        # A ray meeting a surface at a glancing angle finds its t and point
        # 1/|n·c| times less well determined than its start and direction
        # (a floor hit 600 units away at |n·c| = 8e-4 here): the errors are
        # weighed by |n·c|, which measures them as the surface sees them.
        cos = abs(sum(n * d for n, d in zip(b["normal"], unit(theirs["direction"]))))
        report.number("t", abs(da - db) / max(1.0, abs(db)) * cos, where)
        report.number("point", vdiff(a["point"], b["point"]) / max(1.0, db) * cos, where)
        report.number("normal", vdiff(a["normal"], b["normal"]), where)
        if a["entering"] != b["entering"]:
            report.shape(where, "entering", a["entering"], b["entering"])
        for s, t in zip(ours["shadows"], theirs["shadows"]):
            if (s["blocked"], s["by"]) != (t["blocked"], t["by"]):
                report.shape(where, "shadow ray to %s" % t["light"], s, t)
        report.number("local", vdiff(ours["local"], theirs["local"]), where)
        report.number("k_rfl", abs(ours["k_rfl"] - theirs["k_rfl"]), where)
        report.number("k_rfa", abs(ours["k_rfa"] - theirs["k_rfa"]), where)
        if ours["tir"] != theirs["tir"]:
            report.shape(where, "total internal reflection", ours["tir"], theirs["tir"])
        for kind in ("reflected", "refracted"):
            x, y = ours.get(kind), theirs.get(kind)
            if (x is None) != (y is None):
                report.shape(where, kind + " ray", x is not None, y is not None)
            elif x is not None:
                compare_ray(x, y, "%s → %s" % (where, kind), report)
    report.number("color", vdiff(ours["color"], theirs["color"]), where)


def solution_trace(solution, scene_path, pixel, width, height):
    scene = learner_io.Scene(scene_path)
    if width:
        scene.settings.width = width
    if height:
        scene.settings.height = height
    camera = scene.camera()
    tracer = learner_io.Tracer(scene, solution)
    origin, direction = solution.primary_ray(camera, *pixel)
    _, node = solution.raytrace(tracer, "primary", origin, direction, 1, 1.0, tracer.media_at(origin))
    return json.loads(json.dumps(node))


def raytree_check(scene, pixel, width, height, node, report):
    """`raytree check` on the solution's learner trace of `pixel`: the
    oracle's own verdict, beside this tool's. Its exit status says: 0 agree,
    1 a divergence (its report is kept), 2 the file was refused."""
    doc = learner_io.learner_trace(scene, pixel, node)
    with tempfile.NamedTemporaryFile(suffix=".json") as f:
        f.write(doc)
        f.flush()
        cmd = [raytree_bin(), "check", scene, "--pixel", "%d,%d" % pixel, f.name] + size_flags(width, height)
        out = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    if out.returncode != 0:
        said = (out.stdout + out.stderr).decode(errors="replace").strip().splitlines()
        report.failures.append("pixel %d,%d: raytree check exits %d: %s"
                               % (pixel + (out.returncode, " / ".join(said[:3]))))
    return out.returncode == 0


def compare_images(scene, width, height, report):
    """Both tracers' 8-bit images, byte by byte; returns (pixels, pixels off, largest step)."""
    with tempfile.TemporaryDirectory() as tmp:
        ours, theirs = os.path.join(tmp, "ours.ppm"), os.path.join(tmp, "theirs.ppm")
        solution = os.path.join(os.path.dirname(HERE), "teacher", "solution.py")
        subprocess.run([sys.executable, solution, scene, "-o", ours] + size_flags(width, height), check=True)
        subprocess.run([raytree_bin(), "render", scene, "-o", theirs, "--quiet"] + size_flags(width, height),
                       check=True, stdout=subprocess.DEVNULL)
        a, b = read_ppm(ours), read_ppm(theirs)
    if a[:2] != b[:2]:
        report.failures.append("image: sizes differ: %s and %s" % (a[:2], b[:2]))
        return 0, 0, 0
    w, h, pa, pb = a[0], a[1], a[2], b[2]
    off, step = 0, 0
    for i in range(w * h):
        d = max(abs(pa[3 * i + k] - pb[3 * i + k]) for k in range(3))
        if d:
            off += 1
            step = max(step, d)
            if len(report.failures) < 20:
                report.failures.append("image: pixel %d,%d differs by %d" % (i % w, i // w, d))
    return w * h, off, step


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts = data.split(maxsplit=4)
    if parts[0] != b"P6":
        raise SystemExit("%s: not a binary PPM" % path)
    return int(parts[1]), int(parts[2]), parts[4]


def main(argv):
    scene, width, height, pixels, every, image, stride = None, None, None, [], False, False, 1
    check = False
    it = iter(argv)
    for a in it:
        if a == "--width":
            width = int(next(it))
        elif a == "--height":
            height = int(next(it))
        elif a == "--pixel":
            x, y = next(it).split(",")
            pixels.append((int(x), int(y)))
        elif a == "--all":
            every = True
        elif a == "--stride":
            every, stride = True, int(next(it))
        elif a == "--image":
            image = True
        elif a == "--check":
            check = True
        elif scene is None and not a.startswith("-"):
            scene = a
        else:
            sys.stderr.write("usage: compare.py SCENE [--width W --height H] [--pixel X,Y ...] [--all | --stride N] [--image] [--check]\n")
            return 2
    if scene is None:
        sys.stderr.write("compare.py: no scene given\n")
        return 2
    solution = load_solution()
    report = Report()
    if every:
        s = learner_io.Scene(scene)
        w, h = width or s.settings.width, height or s.settings.height
        pixels += [(x, y) for y in range(0, h, stride) for x in range(0, w, stride)]
    clean = 0
    for p in pixels:
        theirs = reduce(raytree_trace(scene, p, width, height))
        ours = solution_trace(solution, scene, p, width, height)
        compare_ray(ours, theirs, "pixel %d,%d primary" % p, report)
        if check:
            clean += raytree_check(scene, p, width, height, ours, report)
    print("%s: %d pixels, %d rays compared" % (scene, len(pixels), report.rays))
    if check:
        print("  raytree check: %d of %d pixels check clean" % (clean, len(pixels)))
    for quantity, (diff, where) in report.worst.items():
        if where is not None:
            print("  %-9s max difference %.3g (tolerance %g) at %s" % (quantity, diff, TOLERANCE[quantity], where))
    if image:
        total, off, step = compare_images(scene, width, height, report)
        print("  image: %d pixels, %d differ (largest step %d of 255)" % (total, off, step))
    for f in report.failures[:20]:
        print("FAIL " + f)
    if len(report.failures) > 20:
        print("FAIL … and %d more" % (len(report.failures) - 20))
    return 1 if report.failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
