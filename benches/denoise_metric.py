#!/usr/bin/env python3
"""Errors of noisy, denoised and converged pictures against a reference.

Usage (docs/performance.md, "Denoising"):

    python3 benches/denoise_metric.py REF.tif NAME=PICTURE ...

PICTURE is a 32-bit TIFF or an OpenEXR file (its RGB layer), as `hscene
render --depth 32f` writes them. For each picture it prints: the relative
RMSE over all pixels (root of the summed squared differences over the
summed squared reference), the same with the emitter's pixels and their
neighbours left out (reference above 2 in some channel, grown by one
pixel), the mean per-pixel relative MSE `(x - r)^2 / (r^2 + 0.01)` of the
denoising literature, the RMSE of the displayed picture (linear values
clipped to [0, 1], sRGB-encoded), and the share of the squared error that
lies on the emitter and its edge.
"""
import sys

import numpy as np


def load(path):
    if path.endswith(".exr"):
        import OpenEXR

        with OpenEXR.File(path) as f:
            return f.channels()["RGB"].pixels.astype(np.float64)
    import tifffile

    return tifffile.imread(path).astype(np.float64)[..., :3]


def srgb(x):
    x = np.clip(x, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * x ** (1 / 2.4) - 0.055)


def main():
    ref = load(sys.argv[1])
    bright = ref.max(-1) > 2.0
    near = bright.copy()
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            near |= np.roll(np.roll(bright, dy, 0), dx, 1)
    print(f"emitter and its edge: {near.mean() * 100:.2f} % of the pixels")
    print("| picture | relative RMSE | without the emitter's edge | relMSE per pixel | display RMSE | error on the emitter's edge |")
    print("|---|---:|---:|---:|---:|---:|")
    for arg in sys.argv[2:]:
        name, path = arg.split("=", 1)
        x = load(path)
        e = ((x - ref) ** 2).sum(-1)
        rel = np.sqrt(e.sum() / (ref**2).sum())
        off = np.sqrt(e[~near].sum() / (ref[~near] ** 2).sum())
        per_pixel = np.mean((x - ref) ** 2 / (ref**2 + 0.01))
        display = np.sqrt(np.mean((srgb(x) - srgb(ref)) ** 2))
        print(f"| {name} | {rel:.4f} | {off:.4f} | {per_pixel:.5f} | {display:.4f} | {e[near].sum() / e.sum() * 100:.1f} % |")


if __name__ == "__main__":
    main()
