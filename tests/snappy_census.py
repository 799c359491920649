#!/usr/bin/env python3
"""SnapPy's census against hscene: every domain accepted, its volume SnapPy's.

Samples manifolds from SnapPy's censuses (closed, cusped, knot and link
exteriors), writes each one's Dirichlet domain as docs/manifolds.md shows
(snappy.ManifoldHP, pairings as decimal strings, "volume" beside them),
runs `hscene check --emit ir` on a scene in each, and compares the
domain's volume hscene reports with SnapPy's `M.volume()`.

    python3 tests/snappy_census.py [--count 120] [--seed 51] [--hscene PATH]
    python3 tests/snappy_census.py --double       # snappy.Manifold's f64 data
    python3 tests/snappy_census.py --fixtures DIR  # write the committed set

Every `--render-every`-th accepted domain (default 3) is also rendered, a
small picture from inside it with a ball and a light (`render_scene`), and
must render with no failed pixel (hscene warns "numeric failure" for any).

Fails (exit 1) when more than 1 in 40 is refused, any accepted volume is
off by more than 1e-9 relative, or a render fails or has failed pixels; prints the reason and exits 0 only where
SnapPy cannot be installed.
"""

import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VOLUME_TOLERANCE = 1e-9


def import_snappy():
    """SnapPy, installed from PyPI if it is not there; None with the reason."""
    try:
        import snappy  # noqa: F401
        return snappy, None
    except ImportError:
        pass
    try:
        subprocess.run(
            [sys.executable, "-m", "pip", "install", "--quiet", "snappy"],
            check=True,
            timeout=900,
        )
        import snappy  # noqa: F401
        return snappy, None
    except Exception as e:  # any failure to install is a reason to skip
        return None, f"SnapPy cannot be installed here ({type(e).__name__}: {e})"


def sample(snappy, count, seed):
    """`count` manifold names: a third closed, a third cusped, a third knot
    and link exteriors, drawn with `seed`."""
    rng = random.Random(seed)
    closed = snappy.OrientableClosedCensus
    cusped = snappy.OrientableCuspedCensus
    links = snappy.LinkExteriors
    names = []
    for k in range(count):
        pool = (closed, cusped, links)[k % 3]
        start = 1 if pool is links else 0  # LinkExteriors[0] is the unknot
        names.append(str(pool[rng.randrange(start, len(pool))]))
    return names


def dirichlet(snappy, name, high_precision=True):
    """The manifold and its Dirichlet domain; SnapPy's construction fails
    for some triangulations, so a few others are tried."""
    M = (snappy.ManifoldHP if high_precision else snappy.Manifold)(name)
    for attempt in range(6):
        try:
            return M, M.dirichlet_domain()
        except Exception:
            M.randomize()
    return M, None


def domain_json(M, D, high_precision=True, digits=None):
    """The space file, as docs/manifolds.md writes it."""

    def entry(x):
        if not high_precision:
            return float(x)
        s = str(x).replace(" ", "")
        if digits is not None:
            s = _round(s, digits)
        return s

    return {
        "name": str(M),
        "pairings": [[[entry(x) for x in row] for row in g] for g in D.pairing_matrices()],
        "volume": entry(M.volume()),
    }


def _round(s, digits):
    """The decimal string `s` rounded to `digits` significant digits (for
    the committed fixtures, kept small), exactly, by Python's Decimal."""
    from decimal import Decimal, Context

    return format(Context(prec=digits).create_decimal(Decimal(s)), "e")


def check(hscene, json_path, scene_path):
    """hscene's verdict: (accepted, volume or None, message)."""
    with open(scene_path, "w") as f:
        f.write('Globals { space = "%s"; }\n' % os.path.basename(json_path))
    r = subprocess.run(
        [hscene, "check", "--emit", "ir", scene_path],
        capture_output=True,
        text=True,
        timeout=120,
    )
    if r.returncode != 0:
        lines = [l.strip() for l in r.stderr.splitlines() if "glue no manifold" in l or "not one" in l]
        return False, None, (lines[0] if lines else r.stderr.strip()[:300])
    ir = json.loads(r.stdout)
    space = ir["settings"].get("space") or {}
    return True, space.get("volume"), ""


RENDER_SCENE = """Globals {
    resolution = (32, 32);
    space = "%s";
    domain = 0.02, #frame;
    from = (0, 0, 0);
    to = (0.1, 0.03, 0.3);
    fov = 100;
    background = (0.02, 0.02, 0.05);
    ambient = (0.15, 0.15, 0.15);
    recursion_depth = 1;
}
BRDFs {
    frame: ambient = (0.5, 0.4, 0.2), diffuse = (0.8, 0.6, 0.3);
    ball: ambient = (0.5, 0.1, 0.1), diffuse = (0.9, 0.2, 0.15), specular = (0.6, 0.6, 0.6), shininess = 60;
}
Lights {
    (0.05, 0.1, -0.1), (1, 0.95, 0.85), (0.5, 0.5, 0.5), irradiance_at = 0.6;
}
Objects {
    Sphere (0.1, 0, 0.12), 0.05, #ball;
}
"""


def render(hscene, json_path, folder):
    """A small picture from inside the domain: "" when it rendered with no
    failed pixel, else why not."""
    scene = os.path.join(folder, "render.hsc")
    with open(scene, "w") as f:
        f.write(RENDER_SCENE % os.path.basename(json_path))
    r = subprocess.run(
        [hscene, "render", scene, "-o", os.path.join(folder, "render.png"), "--force"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    if r.returncode != 0:
        return "render exited %d: %s" % (r.returncode, r.stderr.strip()[:300])
    failures = [l.strip() for l in r.stderr.splitlines() if "numeric failure" in l]
    return failures[0] if failures else ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--count", type=int, default=120)
    ap.add_argument("--seed", type=int, default=51)
    ap.add_argument("--hscene", default=None)
    ap.add_argument("--render-every", type=int, default=3, help="render every K-th accepted domain (0: none)")
    ap.add_argument("--double", action="store_true", help="snappy.Manifold (f64), not ManifoldHP")
    ap.add_argument("--fixtures", default=None, help="write a small committed set to this folder")
    args = ap.parse_args()

    snappy, reason = import_snappy()
    if snappy is None:
        print(f"snappy_census: skipped: {reason}")
        return 0

    if args.fixtures:
        return write_fixtures(snappy, args.fixtures)

    hscene = args.hscene
    if hscene is None:
        # The newer of the two builds.
        built = [
            os.path.join(ROOT, "target", profile, "hscene")
            for profile in ("release", "debug")
            if os.path.exists(os.path.join(ROOT, "target", profile, "hscene"))
        ]
        hscene = max(built, key=os.path.getmtime) if built else None
    if hscene is None:
        print("snappy_census: no hscene binary: build it (cargo build --release) or pass --hscene")
        return 1

    started = time.time()
    names = sample(snappy, args.count, args.seed)
    accepted, refused, no_domain, worst = 0, [], [], (0.0, None)
    rendered, bad_renders = 0, []
    with tempfile.TemporaryDirectory() as tmp:
        for k, name in enumerate(names):
            M, D = dirichlet(snappy, name, not args.double)
            if D is None:
                no_domain.append(name)
                continue
            data = domain_json(M, D, not args.double)
            json_path = os.path.join(tmp, f"m{k}.json")
            with open(json_path, "w") as f:
                json.dump(data, f)
            ok, volume, message = check(hscene, json_path, os.path.join(tmp, f"m{k}.hsc"))
            if not ok:
                refused.append((name, message))
                continue
            accepted += 1
            if args.render_every > 0 and accepted % args.render_every == 1 % args.render_every:
                why = render(hscene, json_path, tmp)
                rendered += 1
                if why:
                    bad_renders.append((name, why))
            expected = float(M.volume())
            error = abs(volume - expected) / expected if volume is not None else float("inf")
            if error > worst[0] or worst[1] is None:
                worst = (error, name)
    tried = len(names) - len(no_domain)
    print(
        f"snappy_census: {accepted} of {tried} accepted "
        f"({'f64' if args.double else 'high precision'}, seed {args.seed}); "
        f"worst volume error {worst[0]:.2e} relative ({worst[1]}); "
        f"{rendered} rendered, {len(bad_renders)} with failures; "
        f"{time.time() - started:.0f} s"
    )
    for name, why in bad_renders:
        print(f"  render of {name}: {why}")
    for name, message in refused:
        print(f"  refused {name}: {message}")
    for name in no_domain:
        print(f"  SnapPy built no Dirichlet domain for {name} (not counted)")
    failed = len(refused) * 40 > tried or worst[0] > VOLUME_TOLERANCE or bad_renders
    return 1 if failed else 0


def write_fixtures(snappy, folder):
    """The committed set: small domains (at most 30 faces) of each kind,
    their entries rounded to 25 digits (more than f64 holds)."""
    picks = {
        "closed": ["m003(-3,1)", "m004(6,1)", "m009(4,1)", "m015(-3,1)", "m017(-3,2)", "s779(-3,1)"],
        "cusped": ["m004", "m003", "m006", "m009", "m015", "m129", "s776"],
        "knot": ["4_1", "5_2", "6_1", "7_4", "8_20"],
        "link": ["5^2_1", "6^2_2", "6^3_2", "7^2_8"],
    }
    os.makedirs(folder, exist_ok=True)
    index = []
    for kind, names in picks.items():
        for name in names:
            M, D = dirichlet(snappy, name)
            if D is None:
                continue
            data = domain_json(M, D, digits=25)
            data["source"] = f"SnapPy {snappy.__version__}: ManifoldHP('{name}').dirichlet_domain()"
            if len(data["pairings"]) > 30:
                continue
            file = name.replace("(", "_").replace(")", "").replace(",", "_").replace("^", "-")
            file = f"{kind}-{file}.json"
            with open(os.path.join(folder, file), "w") as f:
                json.dump(data, f, indent=None)
                f.write("\n")
            index.append((file, len(data["pairings"]), data["volume"]))
    for row in index:
        print(*row)
    return 0


if __name__ == "__main__":
    sys.exit(main())
