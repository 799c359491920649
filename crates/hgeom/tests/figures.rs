//! Pins the geometry of the predefined figures: regular and ideal polygons,
//! Lambert and Saccheri quadrilaterals, the cuboctahedron, the small
//! stellated dodecahedron, the golden rectangles and the {4,3,5} honeycomb.
//! Angles are measured in tangent spaces on the hyperboloid, lengths with
//! the crate's distance, both independent of how the figures were built.

use std::f64::consts::{FRAC_PI_2, PI};

use glam::{DVec3, DVec4};
use hgeom::lorentz;
use hgeom::{
    CUBE_435_DIHEDRAL, ConvexPolygon, GeomError, Isometry, MAX_TESSELLATION_CELLS, Platonic, Point,
    Polyhedron, REGULAR_POLYGON_VERTICES, Segment, Vertex, cube_435, cube_435_circumradius,
    honeycomb_435, ideal_regular_polygon, lambert_quadrilateral, regular_polygon,
    regular_polygon_with_side, saccheri_quadrilateral, tessellate, unique_edges,
};

const PHI: f64 = 1.618_033_988_749_895;

fn interior(v: &Vertex) -> Point {
    match v {
        Vertex::Interior(p) => *p,
        Vertex::Ideal(_) => panic!("expected an interior vertex"),
    }
}

fn points(poly: &ConvexPolygon) -> Vec<Point> {
    poly.vertices().iter().map(interior).collect()
}

/// The angle at `v` between the geodesics towards `a` and `b`: move `v` to
/// the origin, where geodesics are diameters and (the model being conformal)
/// the angle is the Euclidean one between the images, taken with `atan2` so
/// that tiny and right angles keep their precision.
fn angle(v: &Point, a: &Point, b: &Point) -> f64 {
    let to_origin = Isometry::transvection_from_origin(*v).inverse();
    let (u, w) = (to_origin.apply(a).coords(), to_origin.apply(b).coords());
    u.cross(w).length().atan2(u.dot(w))
}

/// The same angle from unit tangent vectors on the hyperboloid, an
/// independent check near the origin (it loses precision far out).
fn angle_hyperboloid(v: &Point, a: &Point, b: &Point) -> f64 {
    let x = v.to_hyperboloid();
    let (ta, _) = lorentz::direction_towards(x, a.to_hyperboloid()).unwrap();
    let (tb, _) = lorentz::direction_towards(x, b.to_hyperboloid()).unwrap();
    lorentz::dot(ta, tb).clamp(-1.0, 1.0).acos()
}

/// Interior angles, vertex by vertex.
fn angles(ps: &[Point]) -> Vec<f64> {
    let n = ps.len();
    (0..n)
        .map(|i| angle(&ps[i], &ps[(i + n - 1) % n], &ps[(i + 1) % n]))
        .collect()
}

/// Side lengths, side `i` joining vertices `i` and `i + 1`.
fn sides(ps: &[Point]) -> Vec<f64> {
    let n = ps.len();
    (0..n).map(|i| ps[i].distance(ps[(i + 1) % n])).collect()
}

fn spread(xs: &[f64]) -> f64 {
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    hi - lo
}

fn minus_z() -> DVec4 {
    DVec4::new(0.0, 0.0, -1.0, 0.0)
}

// ---------------------------------------------------------------- polygons

#[test]
fn regular_polygons_are_regular() {
    for n in REGULAR_POLYGON_VERTICES {
        for r in [0.05, 0.4, 1.0, 3.0, 12.0] {
            let poly = regular_polygon(n, r).unwrap();
            let ps = points(&poly);
            assert_eq!(ps.len(), n);
            for p in &ps {
                assert!((p.distance_from_origin() - r).abs() <= 1e-14 * r, "{n} {r}");
                assert_eq!(p.coords().z, 0.0);
                assert!(poly.plane().signed_sinh_distance(p).abs() < 1e-12);
            }
            assert!((poly.plane().normal() - minus_z()).length() < 1e-12);
            // sinh(s/2) = sinh R sin(pi/n): the right triangle centre, vertex,
            // side midpoint.
            let s = sides(&ps);
            let expect_side = 2.0 * (r.sinh() * (PI / n as f64).sin()).asinh();
            for side in &s {
                assert!((side - expect_side).abs() <= 1e-13 * expect_side, "{n} {r}");
            }
            // tan(alpha/2) = cot(pi/n) / cosh R, from the same triangle.
            let expect_angle = 2.0 * ((PI / n as f64).tan().recip() / r.cosh()).atan();
            for a in angles(&ps) {
                assert!((a - expect_angle).abs() < 1e-12, "{n} {r}: {a}");
            }
            // Angle sum below the Euclidean (n - 2) pi.
            assert!(expect_angle * (n as f64) < (n as f64 - 2.0) * PI);
        }
    }
}

#[test]
fn regular_polygon_by_side() {
    for n in REGULAR_POLYGON_VERTICES {
        let poly = regular_polygon_with_side(n, 0.7).unwrap();
        for s in sides(&points(&poly)) {
            assert!((s - 0.7).abs() < 1e-14);
        }
    }
}

#[test]
fn ideal_polygons_have_vertices_on_the_absolute() {
    for n in REGULAR_POLYGON_VERTICES {
        let poly = ideal_regular_polygon(n).unwrap();
        assert_eq!(poly.vertices().len(), n);
        for v in poly.vertices() {
            assert!(v.is_ideal());
            assert!((v.coords().length() - 1.0).abs() < 1e-15);
            assert_eq!(v.coords().z, 0.0);
        }
        assert!((poly.plane().normal() - minus_z()).length() < 1e-12);
    }
    assert!(matches!(
        ideal_regular_polygon(7),
        Err(GeomError::VertexCountOutOfRange { got: 7, .. })
    ));
}

#[test]
fn lambert_quadrilateral_has_three_right_angles() {
    for (a, b) in [
        (0.3, 0.4),
        (0.8, 0.5),
        (2.0, 0.1),
        (0.05, 0.02),
        (0.88, 0.88),
    ] {
        let poly = lambert_quadrilateral(a, b).unwrap();
        assert!((poly.plane().normal() - minus_z()).length() < 1e-12);
        let ps = points(&poly);
        // Order O, B, C, A.
        let (o, vb, c, va) = (ps[0], ps[1], ps[2], ps[3]);
        assert_eq!(o.coords(), DVec3::ZERO);
        assert!((o.distance(va) - a).abs() < 1e-14 * a.max(1.0));
        assert!((o.distance(vb) - b).abs() < 1e-14 * b.max(1.0));
        assert!(va.coords().x > 0.0 && vb.coords().y > 0.0);
        let ang = angles(&ps);
        for i in [0, 1, 3] {
            assert!((ang[i] - FRAC_PI_2).abs() < 1e-12, "{a} {b}: {ang:?}");
            let n = ps.len();
            let alt = angle_hyperboloid(&ps[i], &ps[(i + n - 1) % n], &ps[(i + 1) % n]);
            assert!((alt - FRAC_PI_2).abs() < 1e-12, "{a} {b}: {alt}");
        }
        // The fourth angle is acute with cos phi = sinh a sinh b.
        assert!(ang[2] < FRAC_PI_2);
        assert!((ang[2].cos() - a.sinh() * b.sinh()).abs() < 1e-12);
        // tanh(AC) = tanh(b) cosh(a), tanh(BC) = tanh(a) cosh(b).
        assert!((va.distance(c).tanh() - b.tanh() * a.cosh()).abs() < 1e-13);
        assert!((vb.distance(c).tanh() - a.tanh() * b.cosh()).abs() < 1e-13);
    }
}

#[test]
fn lambert_quadrilateral_that_does_not_close_is_an_error() {
    assert!(matches!(
        lambert_quadrilateral(1.0, 1.0),
        Err(GeomError::LambertOpen { .. })
    ));
    // sinh a sinh b = 2 * 0.5 = 1 exactly at the limit: the fourth vertex is ideal.
    let (a, b) = (2f64.asinh(), 0.5f64.asinh());
    let p = a.sinh() * b.sinh();
    let result = lambert_quadrilateral(a, b);
    if p >= 1.0 {
        assert!(matches!(result, Err(GeomError::LambertOpen { .. })));
    } else if let Ok(q) = result {
        // Rounded just below 1: the fourth vertex is far out, near the absolute.
        assert!(points(&q)[2].distance_from_origin() > 15.0);
    }
    assert!(matches!(
        lambert_quadrilateral(3.0, 0.2),
        Err(GeomError::LambertOpen { .. })
    ));
    assert_eq!(
        lambert_quadrilateral(0.0, 0.3),
        Err(GeomError::BadRadius(0.0))
    );
}

#[test]
fn saccheri_quadrilateral_has_right_base_angles_and_equal_summit_angles() {
    for (base, leg) in [(0.5, 0.7), (1.5, 0.3), (0.1, 2.5), (3.0, 3.0)] {
        let poly = saccheri_quadrilateral(base, leg).unwrap();
        assert!((poly.plane().normal() - minus_z()).length() < 1e-12);
        let ps = points(&poly);
        // Order P-, Q-, Q+, P+.
        let (pm, qm, qp, pp) = (ps[0], ps[1], ps[2], ps[3]);
        assert!((pm.distance(pp) - base).abs() < 1e-13 * base.max(1.0));
        assert!((pm.distance(qm) - leg).abs() < 1e-13 * leg.max(1.0));
        assert!((pp.distance(qp) - leg).abs() < 1e-13 * leg.max(1.0));
        assert!(pm.coords().y == 0.0 && pp.coords().y == 0.0);
        assert!((pm.coords() + pp.coords()).length() < 1e-16);
        assert!(qm.coords().y > 0.0 && qp.coords().y > 0.0);
        let ang = angles(&ps);
        assert!((ang[0] - FRAC_PI_2).abs() < 1e-12, "{ang:?}");
        assert!((ang[3] - FRAC_PI_2).abs() < 1e-12, "{ang:?}");
        assert!((ang[1] - ang[2]).abs() < 1e-12, "{ang:?}");
        assert!(ang[1] < FRAC_PI_2);
        // Halving it gives a Lambert quadrilateral with sides base/2 and the
        // height h, where tanh(leg) = tanh(h) cosh(base/2) and the summit
        // angle has cos = sinh(base/2) sinh(h).
        let h = (leg.tanh() / (0.5 * base).cosh()).atanh();
        assert!((ang[1].cos() - (0.5 * base).sinh() * h.sinh()).abs() < 1e-12);
        let lambert = lambert_quadrilateral(0.5 * base, h).unwrap();
        let lam = angles(&points(&lambert));
        assert!((lam[2] - ang[1]).abs() < 1e-11);
    }
}

// -------------------------------------------------------------- polyhedra

fn unique_points(poly: &Polyhedron) -> Vec<Point> {
    let mut out: Vec<Point> = Vec::new();
    for f in poly.faces() {
        for v in f.vertices() {
            let p = interior(v);
            if !out.iter().any(|q| (*q).distance(p) < 1e-9) {
                out.push(p);
            }
        }
    }
    out
}

/// Every edge's length.
fn edge_lengths(poly: &Polyhedron) -> Vec<f64> {
    poly.edges()
        .iter()
        .map(|(a, b)| interior(a).distance(interior(b)))
        .collect()
}

#[test]
fn cuboctahedron_is_uniform() {
    for r in [0.3, 1.0, 2.5] {
        let c = Polyhedron::cuboctahedron(r).unwrap();
        let verts = unique_points(&c);
        assert_eq!(verts.len(), 12);
        for p in &verts {
            assert!((p.distance_from_origin() - r).abs() < 1e-14 * r.max(1.0));
        }
        assert_eq!(c.faces().len(), 14);
        let tri = c.faces().iter().filter(|f| f.vertices().len() == 3).count();
        let sq = c.faces().iter().filter(|f| f.vertices().len() == 4).count();
        assert_eq!((tri, sq), (8, 6));
        let lengths = edge_lengths(&c);
        assert_eq!(lengths.len(), 24);
        assert!(spread(&lengths) < 1e-13, "{lengths:?}");
        // Four faces at every vertex, and outward normals.
        for p in &verts {
            let around = c
                .faces()
                .iter()
                .filter(|f| {
                    f.vertices()
                        .iter()
                        .any(|v| interior(v).distance(*p) < 1e-12)
                })
                .count();
            assert_eq!(around, 4);
        }
        for f in c.faces() {
            assert!(f.plane().normal().w > 0.0);
        }
    }
}

#[test]
fn small_stellated_dodecahedron_has_sixty_spike_triangles() {
    for r in [0.4, 1.2, 3.0] {
        let s = Polyhedron::small_stellated_dodecahedron(r).unwrap();
        assert_eq!(s.faces().len(), 60);
        let mut tips: Vec<Point> = Vec::new();
        let mut core: Vec<Point> = Vec::new();
        let mut spike_sides = Vec::new();
        for f in s.faces() {
            let ps = points(f);
            assert_eq!(ps.len(), 3);
            // Exactly one vertex (the tip) is at the circumradius.
            let at_r: Vec<usize> = (0..3)
                .filter(|&i| (ps[i].distance_from_origin() - r).abs() < 1e-12 * r.max(1.0))
                .collect();
            assert_eq!(at_r.len(), 1, "{r}");
            let t = at_r[0];
            let (b1, b2) = (ps[(t + 1) % 3], ps[(t + 2) % 3]);
            // Isosceles spike: both sides from the tip are equal.
            let (s1, s2) = (ps[t].distance(b1), ps[t].distance(b2));
            assert!((s1 - s2).abs() < 1e-12);
            spike_sides.push(s1);
            for (is_tip, p) in [(true, ps[t]), (false, b1), (false, b2)] {
                let list = if is_tip { &mut tips } else { &mut core };
                if !list.iter().any(|q| (*q).distance(p) < 1e-9) {
                    list.push(p);
                }
            }
            assert!(
                f.plane().normal().w > 0.0,
                "faces point away from the centre"
            );
        }
        // All spikes congruent; 12 tips; the 20 base points (computed from
        // different pentagram diagonals) coincide: the core dodecahedron.
        assert!(spread(&spike_sides) < 1e-12);
        assert_eq!(tips.len(), 12);
        assert_eq!(core.len(), 20);
        let core_r: Vec<f64> = core.iter().map(Point::distance_from_origin).collect();
        assert!(spread(&core_r) < 1e-12);
        // The tips are the icosahedron's vertices.
        let ico = unique_points(&Polyhedron::platonic(Platonic::Icosahedron, r).unwrap());
        for t in &tips {
            assert!(ico.iter().any(|q| (*q).distance(*t) < 1e-12));
        }
        // 12 pentagram planes, 5 triangles in each.
        let mut planes: Vec<(DVec4, usize)> = Vec::new();
        for f in s.faces() {
            let n = f.plane().normal();
            match planes.iter_mut().find(|(m, _)| (*m - n).length() < 1e-9) {
                Some((_, count)) => *count += 1,
                None => planes.push((n, 1)),
            }
        }
        assert_eq!(planes.len(), 12);
        assert!(planes.iter().all(|(_, c)| *c == 5));
        // Tip, base point, and the next tip of the pentagram are collinear:
        // every triangle side lies on a pentagram edge (h-line through two
        // tips). Check via the edge count: 60 tip-to-core + 30 core edges.
        assert_eq!(s.edges().len(), 90);
    }
}

#[test]
fn golden_rectangles_are_three_orthogonal_quadrilaterals() {
    for r in [0.5, 1.5] {
        let g = Polyhedron::golden_rectangles(r).unwrap();
        assert_eq!(g.faces().len(), 3);
        let ico = unique_points(&Polyhedron::platonic(Platonic::Icosahedron, r).unwrap());
        let mut all = Vec::new();
        for (k, f) in g.faces().iter().enumerate() {
            let ps = points(f);
            assert_eq!(ps.len(), 4);
            // The plane passes through the origin, normal along -axis k.
            let n = f.plane().normal();
            assert!(n.w.abs() < 1e-15);
            let mut axis = DVec4::ZERO;
            axis[k] = -1.0;
            assert!((n - axis).length() < 1e-14);
            // Opposite sides equal; the two side lengths differ.
            let s = sides(&ps);
            assert!((s[0] - s[2]).abs() < 1e-13 && (s[1] - s[3]).abs() < 1e-13);
            assert!((s[0] - s[1]).abs() > 0.1);
            // Four equal acute angles (a rectangle only in the Euclidean limit).
            let a = angles(&ps);
            assert!(spread(&a) < 1e-12);
            assert!(a[0] < FRAC_PI_2);
            // Diagonals through the centre.
            assert!((ps[0].coords() + ps[2].coords()).length() < 1e-15);
            assert!((ps[1].coords() + ps[3].coords()).length() < 1e-15);
            all.extend(ps);
        }
        for (i, f) in g.faces().iter().enumerate() {
            for h in &g.faces()[i + 1..] {
                assert!(lorentz::dot(f.plane().normal(), h.plane().normal()).abs() < 1e-15);
            }
        }
        // Their 12 vertices are the icosahedron's.
        assert_eq!(all.len(), 12);
        for p in &ico {
            assert!(all.iter().any(|q| (*p).distance(*q) < 1e-13));
        }
    }
}

#[test]
fn edges_are_unique_and_survive_isometries() {
    let expect = [6, 12, 12, 30, 30];
    for (kind, n) in Platonic::ALL.into_iter().zip(expect) {
        let p = Polyhedron::platonic(kind, 0.7).unwrap();
        assert_eq!(p.edges().len(), n, "{kind:?}");
        let iso = Isometry::translation(
            &Segment::new(
                Point::ORIGIN,
                Point::from_coords(DVec3::new(0.3, 0.2, 0.1)).unwrap(),
            )
            .unwrap(),
        )
        .unwrap();
        assert_eq!(p.transformed(&iso).edges().len(), n, "{kind:?}");
        for (a, b) in p.edges() {
            assert!(interior(&a).distance(interior(&b)) > 0.1);
        }
        let ideal = Polyhedron::ideal_platonic(kind).unwrap();
        assert_eq!(ideal.edges().len(), n, "{kind:?}");
        assert!(
            ideal
                .faces()
                .iter()
                .flat_map(|f| f.vertices())
                .all(Vertex::is_ideal)
        );
    }
    let pent = regular_polygon(5, 0.5).unwrap();
    assert_eq!(unique_edges(std::slice::from_ref(&pent)).len(), 5);
}

// ---------------------------------------------------------------- {4,3,5}

/// Cosines of the interior dihedral angles between faces sharing an edge.
fn dihedral_cosines(p: &Polyhedron) -> Vec<f64> {
    let faces = p.faces();
    let mut out = Vec::new();
    for i in 0..faces.len() {
        for j in i + 1..faces.len() {
            let shared = faces[i]
                .vertices()
                .iter()
                .filter(|v| {
                    faces[j]
                        .vertices()
                        .iter()
                        .any(|w| interior(v).distance(interior(w)) < 1e-12)
                })
                .count();
            if shared == 2 {
                // Outward normals: the interior angle is pi minus their angle.
                out.push(-lorentz::dot(
                    faces[i].plane().normal(),
                    faces[j].plane().normal(),
                ));
            }
        }
    }
    out
}

#[test]
fn cube_435_has_dihedral_angles_of_72_degrees() {
    let cube = cube_435().unwrap();
    let cosines = dihedral_cosines(&cube);
    assert_eq!(cosines.len(), 12);
    for c in &cosines {
        assert!(
            (c.acos() - CUBE_435_DIHEDRAL).abs() < 1e-12,
            "{}",
            c.acos().to_degrees()
        );
    }
    // cosh R = phi^2 / sqrt 2.
    let r = cube_435_circumradius();
    assert!((r.cosh() - PHI * PHI / 2f64.sqrt()).abs() < 1e-14);
    assert!((r - 1.226_456_8).abs() < 1e-7);
    // Square faces with equal edges, cosh e = phi^2, face angle with cos 1/sqrt 5.
    let lengths = edge_lengths(&cube);
    assert_eq!(lengths.len(), 12);
    for e in &lengths {
        assert!((e.cosh() - PHI * PHI).abs() < 1e-13);
    }
    for f in cube.faces() {
        let ps = points(f);
        assert_eq!(ps.len(), 4);
        for a in angles(&ps) {
            assert!((a.cos() - 5f64.sqrt().recip()).abs() < 1e-13);
        }
        for p in &ps {
            assert!((p.distance_from_origin() - r).abs() < 1e-14);
        }
    }
}

#[test]
fn other_compact_honeycomb_cells_have_their_dihedral_angles() {
    // {5,3,4}, {5,3,5}, {3,5,3}.
    for (kind, r) in [
        (Platonic::Dodecahedron, 4.0),
        (Platonic::Dodecahedron, 5.0),
        (Platonic::Icosahedron, 3.0),
    ] {
        let theta = 2.0 * PI / r;
        let cell = Polyhedron::platonic_with_dihedral(kind, theta).unwrap();
        let cosines = dihedral_cosines(&cell);
        assert_eq!(cosines.len(), 30);
        for c in cosines {
            assert!((c.acos() - theta).abs() < 1e-12, "{kind:?}");
        }
    }
    // A cube needs 60 < theta < 90 degrees.
    for bad in [1.6, 1.7, 59f64.to_radians(), 0.0, f64::NAN] {
        assert!(matches!(
            Platonic::Cube.circumradius_for_dihedral(bad),
            Err(GeomError::BadAngle(_))
        ));
    }
}

/// True if the two faces have the same vertices (as sets, to `tol`).
fn same_face(a: &ConvexPolygon, b: &ConvexPolygon, tol: f64) -> bool {
    a.vertices().len() == b.vertices().len()
        && a.vertices().iter().all(|v| {
            b.vertices()
                .iter()
                .any(|w| (v.coords() - w.coords()).length() < tol)
        })
}

#[test]
fn honeycomb_435_cell_counts_and_face_to_face_fit() {
    let counts: Vec<usize> = (0..=3).map(|d| honeycomb_435(d).unwrap().len()).collect();
    // 1; + 6 neighbours; + 2 cells around each of the 12 edges (5 per edge)
    // and one cell beyond each neighbour's far face: 24 + 6 = 30 more.
    assert_eq!(&counts[..3], &[1, 7, 37]);
    // Found by the search itself (1 + 6 + 30 + 126), pinned against regressions.
    assert_eq!(counts[3], 163);

    let cells = tessellate(&cube_435().unwrap(), 2).unwrap();
    let centre = &cells[0].polyhedron;
    assert_eq!(cells[0].depth, 0);
    // Every depth-1 cell shares exactly one face with the centre cell, vertex
    // for vertex, and is its mirror image in that face.
    for c in cells.iter().filter(|c| c.depth == 1) {
        let shared = centre
            .faces()
            .iter()
            .filter(|f| c.polyhedron.faces().iter().any(|g| same_face(f, g, 1e-12)))
            .count();
        assert_eq!(shared, 1);
        assert!(!c.placement.preserves_orientation());
    }
    // No two cells coincide: centres at least twice the inradius apart, and
    // exactly that far for face neighbours.
    let inradius = (1.0 / (5f64.sqrt() + 2.0)).sqrt().atanh();
    // Twice the inradius is the edge of the dual honeycomb {5,3,4}, tabulated
    // as 1.0612750619.
    assert!((2.0 * inradius - 1.061_275_061_9).abs() < 1e-10);
    for (i, a) in cells.iter().enumerate() {
        for b in &cells[i + 1..] {
            let d = a.polyhedron.center().distance(b.polyhedron.center());
            assert!(d > 2.0 * inradius - 1e-12, "{d}");
        }
        // The placement maps the generating cell onto this one.
        let moved = centre.transformed(&a.placement);
        for (f, g) in moved.faces().iter().zip(a.polyhedron.faces()) {
            assert!(same_face(f, g, 1e-14));
        }
    }
    // Five cells around every edge of the centre cell: the 72 degree
    // dihedral angles close up to a full turn.
    for (a, b) in centre.edges() {
        let around = cells
            .iter()
            .filter(|c| {
                let has = |p: &Vertex| {
                    c.polyhedron
                        .faces()
                        .iter()
                        .flat_map(|f| f.vertices())
                        .any(|v| (v.coords() - p.coords()).length() < 1e-12)
                };
                has(&a) && has(&b)
            })
            .count();
        assert_eq!(around, 5);
    }
}

#[test]
fn honeycomb_depth_is_bounded() {
    assert_eq!(
        honeycomb_435(40),
        Err(GeomError::TooManyCells {
            limit: MAX_TESSELLATION_CELLS
        })
    );
}
