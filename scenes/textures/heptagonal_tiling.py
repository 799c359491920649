#!/usr/bin/env python3
"""Draws the {7,3} tiling in the Poincare disc inscribed in a square image
(writes tiling-7-3.ppm; convert it to PNG with any tool). Each disc point is
folded into the central heptagon by reflections in its edges, then coloured
by its distance to the nearest edge: dark edges, and cells tinted by the
ring their centre lies in (the distance from the middle, in steps of twice
the inradius).
    python3 heptagonal_tiling.py 1024 && convert tiling-7-3.ppm tiling-7-3.png
"""
import math
import sys

SIZE = int(sys.argv[1]) if len(sys.argv) > 1 else 1024
HALF_WIDTH = 0.04
h = math.acosh(math.cos(math.pi / 3) / math.sin(math.pi / 7))
EDGES = [(math.cosh(h) * math.cos(t), math.cosh(h) * math.sin(t), math.sinh(h))
         for t in (math.pi / 2 + 2 * math.pi * k / 7 for k in range(7))]
TINTS = [(240, 200, 120), (130, 190, 230), (230, 140, 160)]


def dot(p, n):
    return p[0] * n[0] + p[1] * n[1] - p[2] * n[2]


def pixel(x, y):
    r2 = x * x + y * y
    if r2 >= 1:
        return (255, 255, 255)
    p = [2 * x / (1 - r2), 2 * y / (1 - r2), (1 + r2) / (1 - r2)]
    used = []
    for _ in range(200):
        out = [n for n in EDGES if dot(p, n) > 1e-12]
        if not out:
            break
        n = out[0]
        k = 2 * dot(p, n)
        p = [p[0] - k * n[0], p[1] - k * n[1], p[2] - k * n[2]]
        used.append(n)
    d = min(math.asinh(abs(dot(p, n))) for n in EDGES)
    if d < HALF_WIDTH:
        return (20, 20, 30)
    # The cell's centre: the middle moved back by the reflections.
    c = [0.0, 0.0, 1.0]
    for n in reversed(used):
        k = 2 * dot(c, n)
        c = [c[0] - k * n[0], c[1] - k * n[1], c[2] - k * n[2]]
    ring = round(math.acosh(max(c[2], 1.0)) / (2 * h))
    return TINTS[ring % 3]


with open("tiling-7-3.ppm", "wb") as f:
    f.write(b"P6 %d %d 255\n" % (SIZE, SIZE))
    for j in range(SIZE):
        row = bytearray()
        for i in range(SIZE):
            x = (i + 0.5) / SIZE * 2 - 1
            y = 1 - (j + 0.5) / SIZE * 2
            row.extend(pixel(x, y))
        f.write(row)
