"""Pictures through Python equal the CLI's, bit for bit."""

import subprocess

import numpy as np
import pytest

import hscene

# A small scene with reflection, transparency and a light: every part of
# the Whitted path a picture goes through.
SCENE = """
Globals {
    resolution = (64, 48);
    from = (0.02, 0.03, 0.01);
    to = (0.05, 0.05, 0.4);
    fov = 80;
    background = (0.05, 0.05, 0.1);
    ambient = (0.2, 0.2, 0.2);
    recursion_depth = 3;
}
BRDFs {
    red: ambient = (0.4, 0.1, 0.1), diffuse = (0.9, 0.2, 0.15), specular = (0.6, 0.6, 0.6), shininess = 60;
    glass: diffuse = (0.1, 0.2, 0.3), trans = 0.7, refraction = 1.3;
}
Lights { (0.1, 0.2, -0.1), (1, 1, 1), (0.5, 0.5, 0.5); }
Objects {
    Sphere (0.1, 0.05, 0.45), 0.3, #red;
    Sphere (-0.2, -0.1, 0.5), 0.25, #glass;
}
"""


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "s.hsc"
    path.write_text(SCENE)
    return path


def cli(hscene_bin, scene, out, *flags):
    subprocess.run(
        [hscene_bin, "render", str(scene), "-o", str(out), *flags],
        check=True,
        capture_output=True,
        timeout=120,
    )


def read_png(path):
    """An 8-bit RGB PNG's pixels, by Python's zlib (no imaging library)."""
    import struct
    import zlib

    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos : pos + 4])
        kind, body = data[pos + 4 : pos + 8], data[pos + 8 : pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert (depth, colour) == (8, 2)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = 3 * width
    out = np.zeros((height, stride), dtype=np.uint8)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        f, line = raw[y * (stride + 1)], np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = cur[x - 3] if x >= 3 else 0
            b = prev[x]
            c = prev[x - 3] if x >= 3 else 0
            if f == 0:
                p = 0
            elif f == 1:
                p = a
            elif f == 2:
                p = b
            elif f == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (line[x] + p) & 0xFF
        out[y] = cur
        prev = cur
    return out.reshape(height, width, 3)


def test_display_picture_equals_the_cli_png(hscene_bin, scene_file, tmp_path):
    out = tmp_path / "cli.png"
    cli(hscene_bin, scene_file, out, "--samples", "4", "--seed", "7")
    theirs = read_png(out)
    ours = hscene.Scene.from_file(scene_file).render(samples=4, seed=7, display=True)
    assert ours.dtype == np.uint8 and ours.shape == (48, 64, 3)
    assert np.array_equal(ours, theirs)


def test_linear_picture_and_its_exr_equal_the_cli_s(hscene_bin, scene_file, tmp_path):
    out = tmp_path / "cli.exr"
    cli(hscene_bin, scene_file, out, "--resolution", "40x30", "--net", "1")
    scene = hscene.Scene.from_str(SCENE, name="s.hsc")
    ours = scene.render(resolution=(40, 30), net=1)
    assert ours.dtype == np.float32 and ours.shape == (30, 40, 3)
    # The same file written by Python is byte for byte the CLI's.
    mine = tmp_path / "py.exr"
    scene.save(mine, resolution=(40, 30), net=1)
    assert mine.read_bytes() == out.read_bytes()
    assert np.isfinite(ours).all() and ours.max() > 0


def test_picture_and_layers(scene_file):
    scene = hscene.Scene.from_file(scene_file)
    rgb, layers = scene.render(resolution=(16, 12), aov=["depth", "normal", "id", "cell"])
    assert rgb.shape == (12, 16, 3)
    assert layers["depth"].shape == (12, 16)
    assert layers["normal"].shape == (12, 16, 3)
    assert set(np.unique(layers["id"])) <= {0.0, 1.0, 2.0}
    assert layers["cell"].shape == (12, 16, 2)
    picture = scene.picture(resolution=(16, 12))
    png = picture._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    assert scene._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    assert picture.stats["rays"] > 0


def test_bad_keywords_are_value_errors(scene_file):
    scene = hscene.Scene.from_file(scene_file)
    for kwargs in [
        {"resolution": (0, 10)},
        {"resolution": (-1, 10)},
        {"resolution": (100000, 100000)},
        {"samples": 0},
        {"net": 9},
        {"integrator": "magic"},
        {"exposure": float("nan")},
        {"exposure": "bright"},
        {"frame": 3},
        {"aov": ["colour"]},
    ]:
        with pytest.raises(ValueError):
            scene.render(**kwargs)
    with pytest.raises(Exception):
        scene.save("/nonexistent-dir/x.png", resolution=(4, 4))
    with pytest.raises(ValueError):
        scene.save("x.bmp", resolution=(4, 4))
