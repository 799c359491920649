#!/usr/bin/env python3
"""hscene through Python against the CLI: CPU per render, and bulk distances.

    python benches/python/bench.py [--hscene target/release/hscene] [--repeat 3]

1. CPU seconds (user + system, all threads) to read, compile, render and
   write a PNG: `hscene render` in a child process (getrusage of the
   child), and `hscene.Scene.from_file(...).save(...)` in a child Python
   (time.process_time around the same work, so the interpreter's start
   and imports are left out, as the CLI has none). Best of --repeat.
2. geom.distance on a million pairs of points from numpy, against a
   Python loop of single calls (timed on --loop pairs and scaled).

Build both the same way first: `cargo build --release` and
`maturin develop --release` (docs/python.md).
"""

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

SCENES = [
    ("scenes/thesis-appendix-a.hsc", "1200x1200"),
    ("scenes/honeycomb-4-3-5.hsc", "400x400"),
]

PY_CHILD = r"""
import sys, time, hscene
scene_path, out, w, h = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
t0 = time.process_time()
hscene.Scene.from_file(scene_path).save(out, resolution=(w, h))
print(time.process_time() - t0)
"""


def cli_cpu(hscene, scene, resolution, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(
        [hscene, "render", scene, "-o", out, "--resolution", resolution, "--force"],
        check=True,
        capture_output=True,
    )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def python_cpu(scene, resolution, out):
    w, h = resolution.split("x")
    r = subprocess.run(
        [sys.executable, "-c", PY_CHILD, scene, out, w, h],
        check=True,
        capture_output=True,
        text=True,
    )
    return float(r.stdout.strip())


def renders(hscene, repeat):
    print(f"{'scene':34} {'pixels':>9} {'CLI cpu s':>10} {'Python cpu s':>13} {'Python/CLI':>11}")
    with tempfile.TemporaryDirectory() as tmp:
        for scene, resolution in SCENES:
            path = os.path.join(ROOT, scene)
            a = os.path.join(tmp, "cli.png")
            b = os.path.join(tmp, "py.png")
            cli = min(cli_cpu(hscene, path, resolution, a) for _ in range(repeat))
            py = min(python_cpu(path, resolution, b) for _ in range(repeat))
            same = open(a, "rb").read() == open(b, "rb").read()
            print(
                f"{scene:34} {resolution:>9} {cli:10.3f} {py:13.3f} {py / cli:11.3f}"
                f"{'' if same else '  (files differ!)'}"
            )


def distances(loop):
    import numpy as np

    from hscene import geom

    rng = np.random.default_rng(1)
    n = 1_000_000
    a = rng.uniform(-0.55, 0.55, (n, 3))
    b = rng.uniform(-0.55, 0.55, (n, 3))
    t0 = time.perf_counter()
    d = geom.distance(a, b)
    bulk = time.perf_counter() - t0
    t0 = time.perf_counter()
    one = [geom.distance(geom.Point(*x), geom.Point(*y)) for x, y in zip(a[:loop].tolist(), b[:loop].tolist())]
    looped = (time.perf_counter() - t0) * n / loop
    assert np.array_equal(d[:loop], one)
    print(
        f"geom.distance, {n} pairs: numpy {bulk:.3f} s, Python loop {looped:.2f} s "
        f"(timed on {loop}, scaled): {looped / bulk:.0f}x faster"
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--hscene", default=os.path.join(ROOT, "target", "release", "hscene"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--loop", type=int, default=100_000)
    args = ap.parse_args()
    print(f"{os.cpu_count()} cores")
    renders(args.hscene, args.repeat)
    distances(args.loop)


if __name__ == "__main__":
    main()
