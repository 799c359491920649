"""hscene.geom: hgeom through numpy, and hostile input refused."""

import math

import numpy as np
import pytest

from hscene import geom


def test_isometry_round_trips_through_numpy():
    axis = geom.Line(geom.Point(0.1, 0.0, 0.0), geom.Point(0.1, 0.5, 0.2))
    f = geom.Isometry.rotation(axis, 0.7) @ geom.Isometry.translation((0, 0, 0), (0.3, -0.2, 0.4))
    m = f.to_matrix()
    assert m.shape == (4, 4) and m.dtype == np.float64
    g = geom.Isometry.from_matrix(m)
    assert np.allclose(g.to_matrix(), m, atol=1e-12, rtol=0)
    # SnapPy's order (time first) round-trips too, and is a permutation.
    m0 = f.to_matrix(time="first")
    assert np.allclose(geom.Isometry.from_matrix(m0, time="first").to_matrix(), m, atol=1e-12, rtol=0)
    assert m0[0, 0] == m[3, 3]
    # Lorentz: M^T J M = J.
    J = np.diag([1.0, 1.0, 1.0, -1.0])
    assert np.allclose(m.T @ J @ m, J, atol=1e-12)
    p = geom.Point(0.2, 0.1, -0.3)
    q = f @ p
    assert np.allclose(m @ p.hyperboloid, q.hyperboloid, atol=1e-12)
    assert abs(geom.distance(f.inverse() @ q, p)) < 1e-12
    assert abs((f * f.inverse() @ p).distance(p)) < 1e-12


def test_points_lines_planes():
    o = geom.Point.origin()
    p = geom.Point.at_distance((1, 0, 0), 2.0)
    assert abs(geom.distance(o, p) - 2.0) < 1e-14
    assert abs(p.ball[0] - math.tanh(1.0)) < 1e-15
    assert np.allclose(geom.Point.from_hyperboloid(p.hyperboloid).ball, p.ball, atol=1e-15)
    m = geom.midpoint(o, p)
    assert abs(geom.distance(o, m) - 1.0) < 1e-14
    line = geom.Line(o, p)
    t = geom.Isometry.translation_along(line, 0.5)
    assert abs(geom.distance(t @ o, o) - 0.5) < 1e-14
    assert line.distance_to(t @ o) < 1e-14
    plane = geom.Plane.bisector(o, p)
    assert abs(plane.signed_distance(m)) < 1e-14
    r = plane.reflection()
    assert geom.distance(r @ o, p) < 1e-13
    spin = geom.Isometry.rotation_about_origin((0, 0, 1), math.pi / 2)
    assert np.allclose((spin @ geom.Point(0.5, 0, 0)).ball, [0, 0.5, 0], atol=1e-15)


def test_honeycomb_measures_and_cells():
    h = geom.Honeycomb(4, 3, 5)
    assert abs(h.dihedral_angle - 2 * math.pi / 5) < 1e-15
    v = h.cell_vertices()
    assert v.shape == (8, 3)
    radii = np.linalg.norm(v, axis=1)
    # Every vertex at the circumradius; the edge length between neighbours.
    assert np.allclose(2 * np.arctanh(radii), h.circumradius, atol=1e-12)
    d = geom.distance(np.repeat(v[:1], 8, axis=0), v)
    assert abs(sorted(d)[1] - h.edge_length) < 1e-12
    assert h.inradius < h.midradius < h.circumradius
    assert geom.Honeycomb(3, 3, 6).cell_vertices().shape == (4, 3)
    assert math.isinf(geom.Honeycomb(3, 3, 6).edge_length)
    with pytest.raises(ValueError):
        geom.Honeycomb(4, 3, 4)  # Euclidean
    with pytest.raises(ValueError):
        geom.Honeycomb(6, 3, 3).cell_vertices()


def test_vectorised_distance():
    rng = np.random.default_rng(5)
    a = rng.uniform(-0.5, 0.5, (1000, 3))
    b = rng.uniform(-0.5, 0.5, (1000, 3))
    d = geom.distance(a, b)
    assert d.shape == (1000,)
    one = [geom.distance(geom.Point(*x), geom.Point(*y)) for x, y in zip(a[:20], b[:20])]
    assert np.array_equal(d[:20], one)
    moved = geom.Isometry.translation((0, 0, 0), (0.2, 0.1, 0)).apply(a)
    assert moved.shape == (1000, 3)


@pytest.mark.parametrize(
    "bad",
    [
        np.zeros((4, 2)),
        np.zeros((2, 2, 3)),
        np.array([[0.0, 0.0, np.nan]]),
        np.array([[1.0, 0.0, 0.0]]),
        np.array([[2.0, 0.0, 0.0]]),
        np.array([[np.inf, 0.0, 0.0]]),
        "not numbers",
        [[0.1, 0.2]],
    ],
)
def test_hostile_input_is_a_value_error(bad):
    with pytest.raises(ValueError):
        geom.distance(bad, np.zeros((1, 3)) if not hasattr(bad, "shape") else np.zeros(bad.shape))


def test_hostile_scalars_are_value_errors():
    for call in [
        lambda: geom.Point(1.0, 0.0, 0.0),
        lambda: geom.Point(float("nan"), 0.0, 0.0),
        lambda: geom.Point.from_ball([0.1, 0.2]),
        lambda: geom.Point.from_hyperboloid([1.0, 0.0, 0.0, 0.5]),
        lambda: geom.Isometry.from_matrix(np.eye(3)),
        lambda: geom.Isometry.from_matrix(np.full((4, 4), np.nan)),
        lambda: geom.Isometry.from_matrix(np.ones((4, 4))),
        lambda: geom.Isometry.translation((0, 0, 0), (0, 0, 0)),
        lambda: geom.Isometry.rotation_about_origin((0, 0, 0), 1.0),
        lambda: geom.Line((0, 0, 0), (0, 0, 0)),
        lambda: geom.distance(np.zeros((3, 3)), np.zeros((2, 3))),
        lambda: geom.Space.from_pairings(np.eye(4)),
        lambda: geom.Space.from_pairings(np.stack([np.eye(4)] * 4)),
    ]:
        with pytest.raises(ValueError):
            call()
