#!/usr/bin/env python3
"""Render the Euclidean twin of an hscene path-tracing bench scene with
Mitsuba 3 (variant scalar_rgb) and write it as an OpenEXR image.

Usage: mitsuba_twin.py SCENE.json OUT.exr

SCENE.json (written by benches/path.rs):
  {"resolution": [w, h], "fov": degrees (horizontal), "spp": n, "seed": s,
   "max_depth": d (or -1), "threads": t,
   "spheres": [{"center": [x,y,z], "radius": r, "albedo": [r,g,b],
                "emission": [r,g,b]}],
   "quads":   [{"corners": [[x,y,z] x4], "albedo": [r,g,b], "emission": [r,g,b]}],
   "points":  [{"position": [x,y,z], "intensity": [r,g,b]}],
   "triangles": [{"corners": [[x,y,z] x3], "emission": [r,g,b]}],
   "sampler": "independent" or "stratified"}

Each emissive triangle is a shape of its own (an OBJ file written beside
OUT.exr), emitting on the side of (b - a) x (c - a).

The camera sits at the origin looking along +z with +y up, the x axis to
the right of the image, as hscene's canonical frame; a box pixel filter.
"""

import json
import sys

import mitsuba as mi

mi.set_variant("scalar_rgb")


def bsdf(albedo):
    return {"type": "diffuse", "reflectance": {"type": "rgb", "value": albedo}}


def emitter(radiance):
    return {"type": "area", "radiance": {"type": "rgb", "value": radiance}}


def quad(corners):
    # A rectangle from its four corners in order: mitsuba's rectangle is
    # [-1,1]^2 at z=0, mapped by an affine transform.
    import numpy as np

    a, b, c, d = (np.array(p, dtype=float) for p in corners)
    centre = (a + b + c + d) / 4
    u = (b - a) / 2
    v = (d - a) / 2
    n = np.cross(u, v)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = u, v, n / np.linalg.norm(n), centre
    return mi.ScalarTransform4f(m.tolist())


def main():
    scene_file, out = sys.argv[1], sys.argv[2]
    with open(scene_file) as f:
        s = json.load(f)
    w, h = s["resolution"]
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": s.get("max_depth", -1)},
        "sensor": {
            "type": "perspective",
            "fov": s["fov"],
            "fov_axis": "x",
            # Mitsuba's image x runs along the camera frame's -x for a
            # right-handed look_at: looking along +z with +y up, hscene's
            # right (+x) is mitsuba's left, so the camera is mirrored.
            "to_world": mi.ScalarTransform4f().scale([-1, 1, 1])
            @ mi.ScalarTransform4f().look_at(origin=[0, 0, 0], target=[0, 0, 1], up=[0, 1, 0]),
            "film": {
                "type": "hdrfilm",
                "width": w,
                "height": h,
                "rfilter": {"type": "box"},
                "pixel_format": "rgb",
            },
            "sampler": {
                "type": s.get("sampler", "independent"),
                "sample_count": s["spp"],
                "seed": s.get("seed", 0),
            },
        },
    }
    for k, sp in enumerate(s.get("spheres", [])):
        shape = {
            "type": "sphere",
            "center": sp["center"],
            "radius": sp["radius"],
            "bsdf": bsdf(sp["albedo"]),
        }
        if any(sp.get("emission", [0, 0, 0])):
            shape["emitter"] = emitter(sp["emission"])
        d[f"sphere{k}"] = shape
    for k, q in enumerate(s.get("quads", [])):
        shape = {"type": "rectangle", "to_world": quad(q["corners"]), "bsdf": {"type": "twosided", "bsdf": bsdf(q["albedo"])}}
        if any(q.get("emission", [0, 0, 0])):
            shape["emitter"] = emitter(q["emission"])
        d[f"quad{k}"] = shape
    for k, p in enumerate(s.get("points", [])):
        d[f"point{k}"] = {
            "type": "point",
            "position": p["position"],
            "intensity": {"type": "rgb", "value": p["intensity"]},
        }
    for k, t in enumerate(s.get("triangles", [])):
        path = f"{out}.tri{k}.obj"
        with open(path, "w") as f:
            for v in t["corners"]:
                f.write("v {} {} {}\n".format(*v))
            f.write("f 1 2 3\n")
        d[f"triangle{k}"] = {
            "type": "obj",
            "filename": path,
            "face_normals": True,
            "bsdf": bsdf([0, 0, 0]),
            "emitter": emitter(t["emission"]),
        }
    scene = mi.load_dict(d)
    image = mi.render(scene, spp=s["spp"], seed=s.get("seed", 0))
    mi.Bitmap(image).write(out)


if __name__ == "__main__":
    main()
