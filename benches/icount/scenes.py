"""The scenes of the instruction-count guard (`.ci/icount`): small versions
of the speed-at-scale scenes (docs/performance.md), generated from a fixed
seed so that the same script always writes the same bytes.

Each scene is small enough that the whole guard runs under valgrind in
about a minute, and large enough that its work is dominated by what it
stands for (the bounding hierarchy, the rods' tubes, a mesh's BVH, the
honeycomb walk, reflections, and the front end with warnings).
"""

import math
import random
import struct

FOV = 60.0


def _v(p):
    return "(%.6f, %.6f, %.6f)" % tuple(p)


def _normalise(p):
    n = math.sqrt(sum(c * c for c in p))
    return tuple(c / n for c in p)


def _globals(res, depth=1, extra=""):
    return (
        "Globals { recursion_depth = %d; resolution = (%d, %d); fov = %g; net_type = 0; "
        "background = (0.05, 0.05, 0.1); ambient = (0.2, 0.2, 0.2);%s }\n" % (depth, res, res, FOV, extra)
    )


LIGHTS = "Lights {\n  (-0.15, 0.15, 0.0), (30, 30, 30), (1, 1, 1);\n  (0.15, 0.1, -0.05), (30, 30, 30), (1, 1, 1);\n}\n"


def _direction(rng, outside):
    """A direction from the eye (at the origin, looking along +z): in the
    picture, or (`outside`) behind the eye, where check warns (HSC1005)."""
    t = math.tan(math.radians(FOV / 2))
    if outside:
        return _normalise((rng.uniform(-1, 1), rng.uniform(-1, 1), -1.0))
    return _normalise((t * rng.uniform(-1, 1), t * rng.uniform(-1, 1), 1.0))


def _at(direction, distance):
    return tuple(c * math.tanh(distance / 2) for c in direction)


def _material(rng, mirror):
    c = [rng.uniform(0.2, 1.0) for _ in range(3)]
    return "  ambient = (%.3f, %.3f, %.3f), diffuse = (%.3f, %.3f, %.3f), specular = (0.3, 0.3, 0.3), shininess = 20, alpha = %s;\n" % (
        tuple(x * 0.5 for x in c) + tuple(c) + (mirror,)
    )


def spheres(n, res, depth, mirror, outside):
    """`n` overlapping spheres at distances 0.5 to 4, a fraction `outside`
    of them behind the eye."""
    rng = random.Random(14)
    t = math.tan(math.radians(FOV / 2))
    theta0 = 2.0 * math.sqrt(1.2 * 4 * t * t / (1.08 * math.pi * n))
    mats, objs = ["BRDFs {\n"], ["Objects {\n"]
    for k in range(1, n + 1):
        mats.append(_material(rng, mirror))
        d = rng.uniform(0.5, 4.0)
        direction = _direction(rng, rng.random() < outside)
        r = math.asinh(math.sinh(d) * math.sin(theta0 * rng.uniform(0.5, 1.5)))
        objs.append("  Sphere %s, %.6f, #%d;\n" % (_v(_at(direction, d)), r, k))
    return _globals(res, depth) + LIGHTS + "".join(mats) + "}\n" + "".join(objs) + "}\n"


def rods(n, res):
    rng = random.Random(15)
    t = math.tan(math.radians(FOV / 2))
    theta0 = math.sqrt(1.2 * 4 * t * t / (1.08 * 15.1 * n))
    mats, objs = ["BRDFs {\n"], ["Objects {\n"]
    for k in range(1, n + 1):
        mats.append(_material(rng, "0.2"))
        d = rng.uniform(0.5, 4.0)
        direction = _direction(rng, rng.random() < 0.03)
        theta = theta0 * rng.uniform(0.5, 1.5)
        a = _normalise((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)))
        across = _normalise(tuple(
            direction[(i + 1) % 3] * a[(i + 2) % 3] - direction[(i + 2) % 3] * a[(i + 1) % 3] for i in range(3)
        ))
        across = tuple(c * math.tan(3 * theta) for c in across)
        da, db = d + rng.uniform(-0.25, 0.25), d + rng.uniform(-0.25, 0.25)
        pa = _at(_normalise(tuple(p - q for p, q in zip(direction, across))), da)
        pb = _at(_normalise(tuple(p + q for p, q in zip(direction, across))), db)
        r = math.asinh(math.sinh(min(da, db)) * math.sin(theta))
        objs.append("  Rod %s, %s, %.6f, #%d;\n" % (_v(pa), _v(pb), r, k))
    return _globals(res) + LIGHTS + "".join(mats) + "}\n" + "".join(objs) + "}\n"


def icosphere_ply(subdivisions):
    """A geodesic icosphere as a binary little-endian PLY file."""
    p = (1 + math.sqrt(5)) / 2
    verts = [_normalise(v) for v in [
        (-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p),
        (0, -1, -p), (0, 1, -p), (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                verts.append(_normalise(tuple((x + y) / 2 for x, y in zip(verts[a], verts[b]))))
                middle[key] = len(verts) - 1
            return middle[key]

        faces = [f for a, b, c in faces for f in (
            (a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)),
            (c, mid(c, a), mid(b, c)), (mid(a, b), mid(b, c), mid(c, a)))]
    header = (
        "ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
        "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(verts), len(faces))
    ).encode()
    body = b"".join(struct.pack("<3f", *v) for v in verts)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in faces)
    return header + body


def mesh(res, file_name):
    return (
        _globals(res) + LIGHTS
        + "BRDFs {\n  ambient = (0.3, 0.2, 0.1), diffuse = (0.8, 0.6, 0.3), specular = (0.3, 0.3, 0.3), shininess = 20;\n}\n"
        + "Objects {\n  Mesh \"%s\", 1.5, #1, at = (0, 0, 0.5);\n}\n" % file_name
    )


def honeycomb(res):
    return (
        "Globals { resolution = (%d, %d); from = (0.02, 0.03, 0.01); to = (0.06, 0.09, 0.4); fov = 100;\n"
        "  background = (0, 0, 0); ambient = (0.35, 0.35, 0.35); recursion_depth = 6; }\n" % (res, res)
        + "BRDFs {\n  glass: ambient = (0.01, 0.02, 0.04), diffuse = (0.03, 0.06, 0.12), specular = (0.4, 0.4, 0.4), shininess = 80, trans = 0.88;\n"
        "  gold: ambient = (0.4, 0.3, 0.12), diffuse = (0.95, 0.75, 0.35), specular = (1, 1, 1), shininess = 40;\n}\n"
        "Lights {\n  (0.1, 0.2, -0.1), (4, 4, 4), (3, 3, 3);\n}\n"
        "Objects {\n  Honeycomb {5,3,4}, #gold, edges = 0.025, vertices = 0.045, faces = #glass;\n}\n"
    )


def write_all(directory):
    """Writes every scene (and the mesh file) into `directory`; returns the
    cases as (name, arguments after `hscene`)."""
    import os

    files = {
        "spheres.hsc": spheres(2000, 96, 1, "0.2", 0.03),
        "mirrors.hsc": spheres(400, 64, 4, "0.8", 0.1),
        "rods.hsc": rods(1000, 96),
        "mesh.hsc": mesh(48, "icosphere.ply"),
        "honeycomb.hsc": honeycomb(40),
    }
    for name, text in files.items():
        with open(os.path.join(directory, name), "w") as f:
            f.write(text)
    with open(os.path.join(directory, "icosphere.ply"), "wb") as f:
        f.write(icosphere_ply(4))
    cases = [("check-spheres", ["check", "spheres.hsc"])]
    for name in ["spheres", "mirrors", "rods", "mesh", "honeycomb"]:
        cases.append(("render-" + name, ["render", name + ".hsc", "-o", name + ".png", "--threads", "1"]))
    return cases
