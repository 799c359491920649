"""A SnapPy manifold renders in one line, without JSON by hand."""

import os

import numpy as np
import pytest

import hscene


def snappy_or_skip():
    try:
        import snappy
    except ImportError:
        if os.environ.get("HSCENE_REQUIRE_SNAPPY") == "1":
            pytest.fail("HSCENE_REQUIRE_SNAPPY=1 but snappy is not installed")
        pytest.skip("snappy is not installed (pip install snappy)")
    return snappy


SCENE = """Globals {
    resolution = (32, 32);
    light_reach = 1.5;
    domain = 0.02, #brass;
    from = (0.01, 0.02, 0.0);
    to = (0.05, 0.03, 0.3);
    fov = 100;
    ambient = (0.15, 0.15, 0.15);
}
BRDFs { brass: ambient = (0.4, 0.32, 0.16), diffuse = (0.6, 0.45, 0.22); }
Lights { (-0.05, 0.08, -0.05), (1, 0.95, 0.85), (0.4, 0.4, 0.4); }
"""


def test_snappy_manifold_renders():
    snappy = snappy_or_skip()
    M = snappy.ManifoldHP("m003(-3,1)")  # the Weeks manifold
    space = hscene.Space.from_snappy(M)
    assert space.faces == len(M.dirichlet_domain().pairing_matrices())
    assert abs(space.volume - float(M.volume())) < 1e-9
    picture = hscene.Scene.from_str(SCENE, name="weeks", space=space).render()
    assert picture.shape == (32, 32, 3)
    # The domain's edges are seen: the picture is not background alone.
    assert picture.max() > 0.05


def test_double_precision_manifold_and_the_file_path_agree(root):
    snappy = snappy_or_skip()
    M = snappy.Manifold("m004")
    space = hscene.Space.from_snappy(M)
    assert abs(space.volume - float(M.volume())) < 1e-9
    # The pairings come back as SnapPy gave them, to rounding.
    ours = space.pairing_matrices(time="first")
    theirs = np.array([[[float(x) for x in row] for row in g] for g in M.dirichlet_domain().pairing_matrices()])
    assert ours.shape == theirs.shape


def test_a_scene_naming_a_space_refuses_a_second():
    snappy = snappy_or_skip()
    space = hscene.Space.from_snappy(snappy.Manifold("m004"))
    with pytest.raises(hscene.SceneError) as caught:
        hscene.Scene.from_str(SCENE.replace("Globals {", "Globals { space = seifert_weber;"), space=space)
    assert "given by its caller" in str(caught.value)
