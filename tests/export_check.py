#!/usr/bin/env python3
"""Checks `hscene export` files with an independent reader (trimesh).

    python3 tests/export_check.py FILE [FILE ...]

For each STL, 3MF or glTF file: it loads, every connected body is
watertight with consistent winding and a positive volume, no triangle is
degenerate, and the vertices lie inside the ball of the file's size (the
largest distance from the origin is printed). Exits 1 on any failure.
"""
import sys

import numpy as np
import trimesh


def bodies(path):
    loaded = trimesh.load(path, force="scene")
    for name, geom in loaded.geometry.items():
        # Shells may overlap but never share vertices: split by connectivity.
        for body in geom.split(only_watertight=False):
            yield name, body


def check(path):
    count, failures, radius = 0, [], 0.0
    for name, body in bodies(path):
        count += 1
        radius = max(radius, float(np.linalg.norm(body.vertices, axis=1).max()))
        if not body.is_watertight:
            failures.append(f"{name}: a body is not watertight")
        if not body.is_winding_consistent:
            failures.append(f"{name}: a body's winding is inconsistent")
        if body.volume <= 0:
            failures.append(f"{name}: a body has volume {body.volume}")
        if (body.area_faces <= 0).any():
            failures.append(f"{name}: a degenerate triangle")
    print(f"{path}: {count} bodies, all closed: {not failures}, largest radius {radius:.6g}")
    return failures


def main():
    failures = []
    for path in sys.argv[1:]:
        failures += check(path)
    for f in failures[:20]:
        print("FAIL", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
