"""The plumbing of the course's Python tracer: everything that is not a formula
of the lecture. The starter (starter/tracer.py) and the teacher's solution
(teacher/solution.py) both import this module and hand it their own lecture
functions, so neither copies it.

What lives here:
- small vector helpers on 3-tuples;
- the scene reader: raytree's JSON scene format, the subset lessons 03-11 use
  (spheres and planes, transforms, solid and checker materials, point lights,
  a look-at or explicit camera), with raytree's defaults (scenes/README.md);
  anything else is refused with one line naming the file and the field;
- the tracer's bookkeeping: which object is closest (calling the learner's
  intersection functions), the surface at a hit, which side was hit and the
  refractive indices on either side (the stack of media);
- the PPM writer (8-bit sRGB, as raytree writes images), the learner-trace
  writer (docs/learner-trace.md), the command line, and the runner of the
  lessons' test vectors (lessons/NN-topic/vectors.json).

Standard library only, Python 3.9 or later.
"""

import json
import math
import os
import sys

# ---------------------------------------------------------------- vectors


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def mul(a, b):
    """Component by component: a color times a color."""
    return (a[0] * b[0], a[1] * b[1], a[2] * b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    n = length(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def neg(a):
    return (-a[0], -a[1], -a[2])


ZERO = (0.0, 0.0, 0.0)

# ---------------------------------------------------------------- errors


class InputError(Exception):
    """Bad input: one line naming the file and what is wrong; exit 2."""


# ---------------------------------------------------------------- scene


class Camera:
    """The lecture's camera: eye, frame u (right), v (up), n (backward), the
    image plane N in front of the eye with half-sizes W and H, N_c x N_r pixels."""

    def __init__(self, eye, u, v, n, half_width, half_height, distance, columns, rows):
        self.eye, self.u, self.v, self.n = eye, u, v, n
        self.half_width, self.half_height, self.distance = half_width, half_height, distance
        self.columns, self.rows = columns, rows


class Material:
    def __init__(self, name, raw, where):
        self.name = name
        known = {"color", "checker", "ambient", "diffuse", "specular", "shininess",
                 "reflective", "transparent", "ior"}
        _only(raw, known, where)
        if "color" in raw and "checker" in raw:
            raise InputError("%s: give color or checker, not both" % where)
        self.checker = None
        self.color = (0.8, 0.8, 0.8)
        if "color" in raw:
            self.color = _vec(raw["color"], where + ".color")
        if "checker" in raw:
            ch = raw["checker"]
            _only(ch, {"colors", "size"}, where + ".checker")
            colors = ch.get("colors")
            if not isinstance(colors, list) or len(colors) != 2:
                raise InputError("%s.checker.colors: expected two colors" % where)
            size = ch.get("size", 1.0)
            if isinstance(size, list):
                size = _vec(size, where + ".checker.size")
            else:
                size = (_num(size, where + ".checker.size"),) * 3
            self.checker = ([_vec(c, where + ".checker.colors") for c in colors], size)
        self.ambient = _num(raw.get("ambient", 0.1), where + ".ambient")
        self.diffuse = _num(raw.get("diffuse", 0.7), where + ".diffuse")
        self.specular = _num(raw.get("specular", 0.0), where + ".specular")
        self.shininess = _num(raw.get("shininess", 50.0), where + ".shininess")
        self.reflective = _num(raw.get("reflective", 0.0), where + ".reflective")
        self.transparent = _num(raw.get("transparent", 0.0), where + ".transparent")
        self.ior = _num(raw.get("ior", 1.0), where + ".ior")

    def color_at(self, p):
        """The material's color at pattern point p: its one color, or its
        checker's cell (cells alternate with the parity of floor(x)+floor(y)+floor(z))."""
        if self.checker is None:
            return self.color
        colors, size = self.checker
        cell = sum(math.floor(p[i] / size[i]) for i in range(3))
        return colors[cell & 1]


class Light:
    def __init__(self, name, position, color):
        self.name, self.position, self.color = name, position, color


class Object:
    """A sphere or a plane, perhaps placed by a transform. `inverse` is M^-1 as
    three rows [a, b, c, t] (an affine map), `None` when untransformed."""

    def __init__(self, name, kind, params, material, inverse, forward):
        self.name, self.kind, self.params = name, kind, params
        self.material = material
        self.inverse, self.forward = inverse, forward


class Settings:
    def __init__(self):
        self.width, self.height = 640, 480
        self.max_depth = 8
        self.cutoff = 1.0 / 1024.0


class Scene:
    def __init__(self, path):
        self.path = path
        try:
            with open(path, encoding="utf-8") as f:
                raw = json.load(f)
        except OSError as e:
            raise InputError("%s: cannot read: %s" % (path, e.strerror))
        except ValueError as e:
            raise InputError("%s: not JSON: %s" % (path, e))
        if not isinstance(raw, dict):
            raise InputError("%s: expected a JSON object" % path)
        try:
            self._read(raw)
        except (KeyError, TypeError, ValueError, AttributeError, ZeroDivisionError) as e:
            # What the checks below do not name: a missing field, a wrong type.
            raise InputError("%s: malformed scene (%s: %s)" % (path, type(e).__name__, e))

    def _read(self, raw):
        path = self.path
        _only(raw, {"description", "camera", "render", "background", "ambient_light",
                    "materials", "lights", "objects"}, path, outside_subset=True)
        self.settings = Settings()
        self._render(raw.get("render", {}))
        self.background = _vec(raw.get("background", [0, 0, 0]), path + ": background")
        self.ambient_light = _vec(raw.get("ambient_light", [1, 1, 1]), path + ": ambient_light")
        self.materials = {name: Material(name, m, "%s: materials.%s" % (path, name))
                          for name, m in raw.get("materials", {}).items()}
        self.lights = []
        for i, l in enumerate(raw.get("lights", [])):
            where = "%s: lights[%d]" % (path, i)
            _only(l, {"name", "position", "color"}, where)
            if "position" not in l:
                raise InputError("%s.position: missing" % where)
            self.lights.append(Light(l.get("name", "light%d" % i),
                                     _vec(l["position"], where + ".position"),
                                     _vec(l.get("color", [1, 1, 1]), where + ".color")))
        self.objects = [self._object(i, o) for i, o in enumerate(raw.get("objects", []))]
        self.camera_raw = raw.get("camera", {})
        self.camera()  # its errors now, not at the first pixel

    def _render(self, r):
        where = self.path + ": render"
        _only(r, {"width", "height", "spp", "max_depth", "cutoff", "accel", "offset",
                  "sphere", "weights", "aa"}, where, outside_subset=True)
        s = self.settings
        s.width = int(_num(r.get("width", s.width), where + ".width"))
        s.height = int(_num(r.get("height", s.height), where + ".height"))
        s.max_depth = int(_num(r.get("max_depth", s.max_depth), where + ".max_depth"))
        s.cutoff = _num(r.get("cutoff", s.cutoff), where + ".cutoff")
        if s.width < 2 or s.height < 2 or s.max_depth < 1:
            raise InputError("%s: width and height must be at least 2, max_depth at least 1" % where)
        # The tracer does the lecture's defaults only: one sample per pixel,
        # constant weights; the structures (accel) change no number.
        for key, default in (("spp", 1), ("offset", "robust"), ("sphere", "stable"),
                             ("weights", "constant"), ("aa", "grid")):
            if r.get(key, default) != default:
                raise InputError("%s.%s: this tracer does only %r (outside the lessons' subset)"
                                 % (where, key, default))

    def _object(self, i, o):
        where = "%s: objects[%d]" % (self.path, i)
        _only(o, {"name", "sphere", "plane", "material", "transform"}, where, outside_subset=True)
        material = o.get("material", "default")
        if material not in self.materials:
            if material != "default":
                raise InputError("%s.material: no material named '%s'" % (where, material))
            self.materials["default"] = Material("default", {}, where)
        if "sphere" in o and "plane" not in o:
            s = o["sphere"]
            _only(s, {"center", "radius"}, where + ".sphere")
            kind = "sphere"
            params = (_vec(s.get("center", [0, 0, 0]), where + ".sphere.center"),
                      _num(s.get("radius", 1.0), where + ".sphere.radius"))
        elif "plane" in o and "sphere" not in o:
            p = o["plane"]
            _only(p, {"point", "normal"}, where + ".plane")
            kind = "plane"
            params = (_vec(p.get("point", [0, 0, 0]), where + ".plane.point"),
                      normalize(_vec(p.get("normal", [0, 1, 0]), where + ".plane.normal")))
        else:
            raise InputError("%s: give exactly one shape, a sphere or a plane" % where)
        inverse = forward = None
        if o.get("transform"):
            forward = _transform(o["transform"], where + ".transform")
            inverse = _invert(forward)
        return Object(o.get("name", "%s%d" % (kind, i)), kind, params,
                      self.materials[material], inverse, forward)

    def camera(self, width=None, height=None):
        """The camera for an image of width x height (the scene's size by default)."""
        c = self.camera_raw
        where = self.path + ": camera"
        columns = width or self.settings.width
        rows = height or self.settings.height
        eye = _vec(c.get("eye", [0, 0, 5]), where + ".eye")
        if "u" in c:
            _only(c, {"eye", "u", "v", "n", "half_width", "half_height", "distance"}, where)
            return Camera(eye, normalize(_vec(c["u"], where)), normalize(_vec(c["v"], where)),
                          normalize(_vec(c["n"], where)), _num(c["half_width"], where),
                          _num(c["half_height"], where), _num(c.get("distance", 1.0), where),
                          columns, rows)
        _only(c, {"eye", "look_at", "up", "fov"}, where)
        look_at = _vec(c.get("look_at", [0, 0, 0]), where + ".look_at")
        up = _vec(c.get("up", [0, 1, 0]), where + ".up")
        fov = _num(c.get("fov", 60.0), where + ".fov")
        n = normalize(sub(eye, look_at))
        u = normalize(cross(up, n))
        v = cross(n, u)
        # N = 1; W from the field of view; H so that pixels are square: the
        # spacing 2W/(N_c - 1) is the same along both axes (lesson 03).
        half_width = math.tan(math.radians(fov) / 2.0)
        spacing = 2.0 * half_width / max(columns - 1, 1)
        half_height = spacing * (rows - 1) / 2.0
        return Camera(eye, u, v, n, half_width, half_height, 1.0, columns, rows)

    def object_named(self, name):
        for o in self.objects:
            if o.name == name:
                return o
        raise InputError("%s: no object named '%s'" % (self.path, name))


def _only(d, known, where, outside_subset=False):
    if not isinstance(d, dict):
        raise InputError("%s: expected a JSON object" % where)
    for key in d:
        if key not in known:
            why = " (outside the subset this tracer reads: spheres and planes)" if outside_subset else ""
            raise InputError("%s: unknown or unsupported field '%s'%s" % (where, key, why))


def _num(x, where):
    if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
        raise InputError("%s: expected a number, got %s" % (where, json.dumps(x)))
    return float(x)


def _vec(x, where):
    if not isinstance(x, list) or len(x) != 3:
        raise InputError("%s: expected three numbers, got %s" % (where, json.dumps(x)))
    return tuple(_num(v, where) for v in x)


def _matmul(a, b):
    """The affine maps a∘b, each three rows [x, y, z, t]."""
    out = []
    for i in range(3):
        row = [sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)]
        row.append(sum(a[i][k] * b[k][3] for k in range(3)) + a[i][3])
        out.append(row)
    return out


def _transform(steps, where):
    """The scene file's transform steps, applied in the order written:
    M = M_last ... M_first."""
    m = [[1.0, 0, 0, 0], [0, 1.0, 0, 0], [0, 0, 1.0, 0]]
    for k, step in enumerate(steps):
        if not isinstance(step, dict) or len(step) != 1:
            raise InputError("%s[%d]: expected one step" % (where, k))
        (key, value), = step.items()
        if key == "translate":
            t = _vec(value, where)
            s = [[1.0, 0, 0, t[0]], [0, 1.0, 0, t[1]], [0, 0, 1.0, t[2]]]
        elif key == "scale":
            v = _vec(value, where)
            s = [[v[0], 0, 0, 0], [0, v[1], 0, 0], [0, 0, v[2], 0]]
        elif key in ("rotate_x", "rotate_y", "rotate_z", "rotate"):
            if key == "rotate":
                axis = normalize(_vec(value["axis"], where))
                a = math.radians(_num(value["degrees"], where))
            else:
                axis = {"rotate_x": (1.0, 0, 0), "rotate_y": (0, 1.0, 0), "rotate_z": (0, 0, 1.0)}[key]
                a = math.radians(_num(value, where))
            s = _rotation(axis, a)
        else:
            raise InputError("%s[%d]: unknown step '%s'" % (where, k, key))
        m = _matmul(s, m)
    return m


def _rotation(axis, a):
    """Rodrigues' rotation by angle a (right-handed) about unit axis."""
    x, y, z = axis
    c, s = math.cos(a), math.sin(a)
    t = 1 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0.0],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0.0],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0.0]]


def _invert(m):
    """The inverse of an affine map (rows [x, y, z, t])."""
    a = [row[:3] for row in m]
    det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
           - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
           + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    inv = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            r = [k for k in range(3) if k != j]
            c = [k for k in range(3) if k != i]
            minor = a[r[0]][c[0]] * a[r[1]][c[1]] - a[r[0]][c[1]] * a[r[1]][c[0]]
            inv[i][j] = (-1) ** (i + j) * minor / det
    t = [m[i][3] for i in range(3)]
    out = []
    for i in range(3):
        out.append(inv[i] + [-sum(inv[i][k] * t[k] for k in range(3))])
    return out


def apply_point(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3))


def apply_vector(m, d):
    return tuple(m[i][0] * d[0] + m[i][1] * d[1] + m[i][2] * d[2] for i in range(3))


def apply_transpose(m, d):
    """The transpose of m's linear part applied to d: for M^-1 this is the
    lecture's normal transform (M^-1)^T."""
    return tuple(m[0][i] * d[0] + m[1][i] * d[1] + m[2][i] * d[2] for i in range(3))


# ---------------------------------------------------------------- tracing


class Tracer:
    """The bookkeeping around the learner's functions (`lessons`, a module or
    any object with them as attributes): closest hits, surfaces, media."""

    def __init__(self, scene, lessons):
        self.scene = scene
        self.fn = lessons
        self.settings = scene.settings

    def roots(self, obj, origin, direction):
        """Every root of the ray's line with obj, ascending; for a transformed
        object, of the inverse-transformed ray with the plain primitive (lesson 06)."""
        if obj.inverse is not None:
            origin, direction = self.fn.to_object_ray(obj.inverse, origin, direction)
        if obj.kind == "sphere":
            center, radius = obj.params
            return list(self.fn.sphere_roots(center, radius, origin, direction))
        point, normal = obj.params
        t = self.fn.plane_root(point, normal, origin, direction)
        return [] if t is None else [t]

    def closest_hit(self, origin, direction, t_max=math.inf):
        """(object index, t) of the closest hit in (0, t_max), or None."""
        best = None
        for i, obj in enumerate(self.scene.objects):
            t = self.fn.first_root(self.roots(obj, origin, direction), 0.0, t_max)
            if t is not None and (best is None or t < best[1]):
                best = (i, t)
        return best

    def surface(self, i, origin, direction, t):
        """(point, outward unit normal, pattern point) where the ray meets object i.
        The point is placed on the surface, as raytree does (its trace's
        `placement`), so a secondary ray need start only a hair off it."""
        obj = self.scene.objects[i]
        o, d = origin, direction
        if obj.inverse is not None:
            o, d = self.fn.to_object_ray(obj.inverse, origin, direction)
        q = add(o, scale(d, t))
        if obj.kind == "sphere":
            center, radius = obj.params
            local = sub(q, center)
            local = scale(local, radius / length(local))
            point, normal = add(center, local), scale(local, 1.0 / radius)
            pattern = point
        else:
            p0, n = obj.params
            point = sub(q, scale(n, dot(sub(q, p0), n)))
            normal = n
            pattern = _flatten(point, n)
        if obj.inverse is not None:
            point = apply_point(obj.forward, point)
            normal = self.fn.normal_to_world(obj.inverse, normal)
        return point, normal, pattern

    def is_medium(self, i):
        return self.scene.objects[i].material.transparent > 0.0

    def media_at(self, p):
        """The transparent objects around point p, in file order (the lessons'
        scenes nest them properly, so file order is the order of entering)."""
        media = []
        for i, obj in enumerate(self.scene.objects):
            if self.is_medium(i) and _contains(obj, p):
                media.append(i)
        return tuple(media)

    def side(self, i, direction, normal, media):
        """Whether the ray enters object i, and n1, n2 on either side, and the
        media beyond the surface: a ray leaves only what it is inside (the stack
        of media says so), enters a transparent solid it is not inside, and for
        an opaque object the sign of n.c decides (lesson 10)."""
        inside = i in media
        if inside:
            entering = False
        elif self.is_medium(i):
            entering = True
        else:
            entering = dot(direction, normal) <= 0.0
        ior = lambda m: self.scene.objects[m[-1]].material.ior if m else 1.0
        if entering or inside:
            n1 = ior(media)
        else:
            n1 = self.scene.objects[i].material.ior
        if entering:
            beyond = media + (i,)
        else:
            beyond = list(media)
            if i in beyond:
                del beyond[len(beyond) - 1 - beyond[::-1].index(i)]
            beyond = tuple(beyond)
        return entering, n1, ior(beyond), beyond


def _contains(obj, p):
    if obj.inverse is not None:
        p = apply_point(obj.inverse, p)
    if obj.kind == "sphere":
        center, radius = obj.params
        d = sub(p, center)
        return dot(d, d) < radius * radius
    point, normal = obj.params
    return dot(sub(p, point), normal) < 0.0


def _flatten(p, n):
    """A plane's pattern point: the point with its coordinate along the
    normal's largest axis dropped, so rounding across the plane cannot flip
    a checker cell."""
    a = (abs(n[0]), abs(n[1]), abs(n[2]))
    if a[0] >= a[1] and a[0] >= a[2]:
        return (0.0, p[1], p[2])
    if a[1] >= a[2]:
        return (p[0], 0.0, p[2])
    return (p[0], p[1], 0.0)


def offset_origin(point, normal, direction):
    """A secondary ray's start: a hair off the surface, on the side the ray
    leaves into, so it cannot meet its own surface at t ~ 0 (lesson 08's acne;
    raytree moves just past the point's rounding error, lesson 13; a small
    fixed distance, scaled to the point's size, is the textbook way)."""
    eps = 1e-10 * max(1.0, abs(point[0]), abs(point[1]), abs(point[2]))
    side = eps if dot(direction, normal) >= 0.0 else -eps
    return add(point, scale(normal, side))


# ---------------------------------------------------------------- output


def srgb8(v):
    """Linear to 8-bit sRGB: clamp to [0, 1], the sRGB transfer function, round."""
    v = 0.0 if v != v else min(max(v, 0.0), 1.0)
    s = 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1.0 / 2.4) - 0.055
    return int(math.floor(s * 255.0 + 0.5))


def write_atomically(path, data):
    """Writes bytes to path through a temporary file beside it, so a reader
    never sees half a file."""
    tmp = "%s.tmp%d" % (path, os.getpid())
    try:
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except OSError as e:
        try:
            os.remove(tmp)
        except OSError:
            pass
        raise InputError("%s: cannot write: %s" % (path, e.strerror))


def ppm(width, height, colors):
    """A binary PPM (P6) of rows from the top: the colors given are linear RGB
    (what the tracer computes), each channel written as 8-bit sRGB."""
    body = bytearray()
    for c in colors:
        body += bytes(srgb8(x) for x in c)
    return b"P6\n%d %d\n255\n" % (width, height) + bytes(body)


def learner_trace(scene_path, pixel, ray):
    """The learner trace document (docs/learner-trace.md, version 1)."""
    doc = {"format": "raytree-learner-trace", "version": 1, "scene": scene_path,
           "pixel": list(pixel), "ray": ray}
    return (json.dumps(doc, indent=1, allow_nan=False) + "\n").encode()


def vec_json(v):
    return [float(x) for x in v]


# ---------------------------------------------------------------- command line

USAGE = """usage:
  {prog} SCENE [--width W --height H] [-o IMAGE.ppm]     render the scene
  {prog} SCENE --pixel X,Y [--width W --height H] [-o TRACE.json]
                                                     write pixel X,Y's learner trace
  {prog} test [LESSON ...]                           run the lessons' test vectors
"""


def main(lessons, argv=None):
    """The command line both tracers share; `lessons` holds the lecture's functions."""
    argv = sys.argv[1:] if argv is None else argv
    prog = os.path.basename(sys.argv[0])
    try:
        if argv and argv[0] == "test":
            return run_vectors(lessons, argv[1:])
        return _run(lessons, argv, prog)
    except InputError as e:
        sys.stderr.write("error: %s\n" % e)
        return 2
    except NotImplementedError as e:
        sys.stderr.write("not written yet: %s\n" % e)
        return 1
    except BrokenPipeError:
        return 0


def _run(lessons, argv, prog):
    scene_path, out, pixel, width, height = None, None, None, None, None
    it = iter(argv)
    for a in it:
        if a in ("-h", "--help"):
            sys.stdout.write(USAGE.format(prog=prog))
            return 0
        if a in ("-o", "--pixel", "--width", "--height"):
            value = next(it, None)
            if value is None:
                raise InputError("%s needs a value (see --help)" % a)
            try:
                if a == "-o":
                    out = value
                elif a == "--pixel":
                    x, y = value.split(",")
                    pixel = (int(x), int(y))
                elif a == "--width":
                    width = int(value)
                else:
                    height = int(value)
            except ValueError:
                raise InputError("%s: '%s' is not valid (see --help)" % (a, value))
        elif scene_path is None and not a.startswith("-"):
            scene_path = a
        else:
            raise InputError("unexpected argument '%s' (see --help)" % a)
    if scene_path is None:
        raise InputError("no scene given (see --help)")
    scene = Scene(scene_path)
    for flag, value in (("--width", width), ("--height", height)):
        if value is not None and value < 2:
            raise InputError("%s: at least 2 pixels, got %d" % (flag, value))
    if width:
        scene.settings.width = width
    if height:
        scene.settings.height = height
    camera = scene.camera()
    tracer = Tracer(scene, lessons)
    if pixel is not None:
        x, y = pixel
        if not (0 <= x < camera.columns and 0 <= y < camera.rows):
            raise InputError("--pixel %d,%d: outside the %dx%d image" % (x, y, camera.columns, camera.rows))
        origin, direction = lessons.primary_ray(camera, x, y)
        _, node = lessons.raytrace(tracer, "primary", origin, direction, 1, 1.0,
                                   tracer.media_at(origin))
        data = learner_trace(scene_path, pixel, node)
        if out:
            write_atomically(out, data)
        else:
            sys.stdout.buffer.write(data)
        return 0
    colors = []
    media = tracer.media_at(camera.eye)
    for y in range(camera.rows):
        for x in range(camera.columns):
            origin, direction = lessons.primary_ray(camera, x, y)
            color, _ = lessons.raytrace(tracer, "primary", origin, direction, 1, 1.0, media)
            colors.append(color)
    write_atomically(out or "out.ppm", ppm(camera.columns, camera.rows, colors))
    return 0


# ---------------------------------------------------------------- test vectors

HERE = os.path.dirname(os.path.abspath(__file__))
LESSONS_DIR = os.path.dirname(HERE)
REPO = os.path.dirname(LESSONS_DIR)


def vector_files(wanted):
    """The committed vectors.json of lessons 03-11 (those whose number or
    folder name is in `wanted`, or all), and any file `wanted` names by its
    path (the output of `raytree vectors SCENE`)."""
    found = [w for w in wanted if w.endswith(".json") and os.path.isfile(w)]
    wanted = [w for w in wanted if w not in found]
    if found and not wanted:
        return found
    for name in sorted(os.listdir(LESSONS_DIR)):
        path = os.path.join(LESSONS_DIR, name, "vectors.json")
        if os.path.isfile(path) and (not wanted or name[:2] in wanted or name in wanted):
            found.append(path)
    return found


def run_vectors(lessons, wanted):
    """Runs every case of the lessons' vectors against the learner's functions;
    prints one line per failing case and a summary. Exit 0 all pass, 1 not."""
    wanted = [w.zfill(2) if w.isdigit() else w for w in wanted]
    files = vector_files(wanted)
    missing = [w for w in wanted if w.endswith(".json") and not os.path.isfile(w)]
    if missing:
        raise InputError("%s: no such vectors file" % missing[0])
    if not files:
        raise InputError("no vectors.json found for %s" % (" ".join(wanted) or "any lesson"))
    passed = failed = 0
    for path in files:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
        scenes = {}
        before = (passed, failed)
        for case in doc["cases"]:
            try:
                ok, why = check_case(lessons, case, doc, scenes)
            except NotImplementedError as e:
                ok, why = False, "not written yet: %s" % (e or "NotImplementedError")
            except Exception as e:  # a learner's bug, reported and counted
                ok, why = False, "raised %s: %s" % (type(e).__name__, e)
            if ok:
                passed += 1
            else:
                failed += 1
                sys.stdout.write("FAIL %s %s: %s\n" % (doc["lesson"], case["name"], why))
        sys.stdout.write("%s: %d passed, %d failed\n"
                         % (doc["lesson"], passed - before[0], failed - before[1]))
    sys.stdout.write("%d passed, %d failed\n" % (passed, failed))
    return 0 if failed == 0 else 1


def _close(got, want, tol):
    """Whether got equals want within tolerance tol (absolute, per component,
    scaled by max(1, |want|): the vectors' files say why)."""
    if want is None or got is None:
        return want is None and got is None
    if isinstance(want, bool):
        return got is want or got == want
    if isinstance(want, str):
        return got == want
    if isinstance(want, (int, float)):
        return isinstance(got, (int, float)) and abs(got - want) <= tol * max(1.0, abs(want))
    if isinstance(want, dict):
        return isinstance(got, dict) and all(_close(got.get(k), v, tol) for k, v in want.items())
    got = list(got)
    return len(got) == len(want) and all(_close(g, w, tol) for g, w in zip(got, want))


def check_case(lessons, case, doc, scenes):
    """(passed, why) for one case: calls the function the case names."""
    f, i = case["function"], case["input"]
    tol = case.get("tolerance", doc.get("tolerance", 1e-9))
    want = case["expected"]
    if f in ("image_plane_point", "primary_ray"):
        c = i["camera"]
        camera = Camera(tuple(c["eye"]), tuple(c["u"]), tuple(c["v"]), tuple(c["n"]),
                        c["half_width"], c["half_height"], c["distance"], c["columns"], c["rows"])
        got = getattr(lessons, f)(camera, i["x"], i["y"])
        if f == "primary_ray":
            got = {"origin": got[0], "direction": got[1]}
    elif f == "plane_root":
        got = lessons.plane_root(tuple(i["point"]), tuple(i["normal"]), tuple(i["origin"]), tuple(i["direction"]))
    elif f == "sphere_roots":
        got = lessons.sphere_roots(tuple(i["center"]), i["radius"], tuple(i["origin"]), tuple(i["direction"]))
    elif f == "first_root":
        got = lessons.first_root(i["roots"], i["t_min"], math.inf if i["t_max"] is None else i["t_max"])
    elif f == "to_object_ray":
        got = lessons.to_object_ray(i["inverse"], tuple(i["origin"]), tuple(i["direction"]))
        got = {"origin": got[0], "direction": got[1]}
    elif f == "normal_to_world":
        got = lessons.normal_to_world(i["inverse"], tuple(i["normal"]))
    elif f == "phong":
        m = Material("case", i["material"], "case")
        lights = [(tuple(l["l"]), tuple(l["arriving"])) for l in i["lights"]]
        got = lessons.phong(m, tuple(i["color"]), tuple(i["ambient_light"]), tuple(i["normal"]),
                            tuple(i["v"]), lights)
    elif f == "shadow_ray":
        path = os.path.join(REPO, i["scene"])
        if path not in scenes:
            scenes[path] = Tracer(Scene(path), lessons)
        tracer = scenes[path]
        got = lessons.shadow_ray(tracer, tuple(i["point"]), tuple(i["normal"]), i["light"])
        got = {k: got[k] for k in want}
    elif f == "reflect":
        got = lessons.reflect(tuple(i["c"]), tuple(i["n"]))
    elif f == "refract":
        got = lessons.refract(tuple(i["c"]), tuple(i["n"]), i["n1"], i["n2"])
    elif f == "combine":
        got = lessons.combine(tuple(i["local"]), i["k_rfl"], tuple(i["reflected"]), i["k_rfa"],
                              tuple(i["refracted"]))
    else:
        return False, "unknown function '%s' (a newer vectors file?)" % f
    if _close(got, want, tol):
        return True, ""
    return False, "expected %s, got %s (tolerance %g)" % (json.dumps(want), json.dumps(_plain(got)), tol)


def _plain(x):
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    return x
