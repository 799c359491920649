//! Independent checks of the formulas derived in `docs/geometry.md`, in the
//! order the document derives them, and the measurements behind the
//! `# Accuracy` sections that are not already covered by
//! `tests/reference.rs`, `tests/properties.rs` or `tests/surfaces.rs`.
//!
//! Each check evaluates the formula a second, independent way (a 320-bit
//! reference, the complex-number form, the hyperboloid, a closed form of
//! hyperbolic trigonometry) and bounds the disagreement.
//!
//! The last three tests pin places where the code once disagreed with its
//! derivation (far transformed polygons and planes, spacelike vectors read
//! as points); they were fixed and are kept as regressions.

use std::f64::consts::{PI, TAU};

use glam::{DMat3, DVec3, DVec4};
use hgeom::accurate::one_minus_norm_sq;
use hgeom::{
    ConvexPolygon, HCylinder, HLine, HPlane, HSphere, Horosphere, IdealPoint, Isometry, Point, Ray,
    Segment, Vertex, lorentz, mobius,
};
use hscene_test_support::SplitMix64;
use hscene_test_support::reference::{self, R};

const EPS: f64 = f64::EPSILON;

// ---------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------

/// Points the 320-bit reference reads exactly.
trait ExactPoints {
    /// A point at hyperbolic distance in `[lo, hi)` from the origin, with
    /// its gap recomputed from the (rounded) coordinates, so that the point
    /// is exactly what its coordinates say (the reference reads coordinates).
    fn point(&mut self, lo: f64, hi: f64) -> Point;
}

impl ExactPoints for SplitMix64 {
    fn point(&mut self, lo: f64, hi: f64) -> Point {
        let d = self.range(lo, hi);
        let p = Point::at_distance_from_origin(self.direction(), d).unwrap();
        Point::from_coords(p.coords()).unwrap()
    }
}

/// The point at arc length `len` along the geodesic leaving `p` in the ball
/// direction `dir`.
fn step(p: &Point, dir: DVec3, len: f64) -> Point {
    Point::from_hyperboloid(Ray::from_ball_unchecked(p, dir).at(len)).unwrap()
}

fn max_of(xs: &[f64]) -> f64 {
    xs.iter().copied().fold(0.0, f64::max)
}

/// A ball vector in 320 bits.
type R3 = [R; 3];

fn r3(v: DVec3) -> R3 {
    [R::f(v.x), R::f(v.y), R::f(v.z)]
}

fn dot3(a: &R3, b: &R3) -> R {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn gap3(a: &R3) -> R {
    R::f(1.0) - dot3(a, a)
}

/// Möbius addition, textbook form, in 320 bits:
/// `((1 + 2u.v + |v|^2) u + (1 - |u|^2) v) / (1 + 2u.v + |u|^2 |v|^2)`.
fn mobius_r(u: &R3, v: &R3) -> R3 {
    let one = R::f(1.0);
    let two = R::f(2.0);
    let uv = dot3(u, v);
    let (uu, vv) = (dot3(u, u), dot3(v, v));
    let cu = &one + &(&two * &uv) + vv.clone();
    let cv = &one - &uu;
    let den = &one + &(&two * &uv) + &uu * &vv;
    std::array::from_fn(|i| (&cu * &u[i] + &cv * &v[i]) / &den)
}

/// Hyperbolic distance between a rounded f64 ball point (taken exactly) and
/// a 320-bit one.
fn distance_r(x: DVec3, y: &R3) -> f64 {
    let xr = r3(x);
    let d: R3 = std::array::from_fn(|i| &xr[i] - &y[i]);
    let chord = dot3(&d, &d).sqrt();
    (R::f(2.0) * (chord / (gap3(&xr) * gap3(y)).sqrt()).asinh()).to_f64()
}

fn rel(got: f64, want: &R) -> f64 {
    let w = want.to_f64();
    if w == 0.0 {
        got.abs()
    } else {
        ((got - w) / w).abs()
    }
}

/// The hyperbolic midpoint-like point `normalise(sum w_i X_i)` of
/// hyperboloid vectors: a point of their plane.
fn from_timelike(x: DVec4) -> Point {
    let q = -lorentz::dot(x, x);
    Point::from_hyperboloid(x / q.sqrt()).unwrap()
}

// ---------------------------------------------------------------------------
// 1. The ball, the hyperboloid and the gap
// ---------------------------------------------------------------------------

/// Naive `1 - |x|^2` loses all digits next to the absolute; the compensated
/// gap keeps them (docs/geometry.md, "The gap").
#[test]
fn compensated_gap_against_naive() {
    let x = 1.0 - 1e-15;
    let v = DVec3::new(x, 0.0, 0.0);
    // 1 - x is exact (Sterbenz), so (1-x)(1+x) is correct to an ulp.
    let exact = (1.0 - x) * (1.0 + x);
    assert!(((one_minus_norm_sq(v) - exact) / exact).abs() < 2.0 * EPS);
    // Off-axis, where no factorisation helps, against 320 bits.
    let mut rng = SplitMix64::new(41);
    let (mut worst, mut naive_worst) = (0.0f64, 0.0f64);
    for _ in 0..500 {
        let g = 10f64.powf(rng.range(-15.5, 0.0));
        let c = rng.direction() * (1.0 - g);
        if c.length_squared() >= 1.0 {
            continue;
        }
        let want = reference::gap(c);
        worst = worst.max(rel(one_minus_norm_sq(c), &want));
        naive_worst = naive_worst.max(rel(1.0 - c.length_squared(), &want));
    }
    eprintln!("naive 1 - |x|^2: max relative error {naive_worst:e}");
    assert!(naive_worst > 0.1, "{naive_worst:e}");
    eprintln!("compensated gap: max relative error {worst:e}");
    assert!(worst < 4.0 * EPS, "{worst:e}");
}

/// The two maps between ball and hyperboloid are inverse, and the gap is
/// `2/(1 + x0)` on the sheet.
#[test]
fn ball_and_hyperboloid_maps_are_inverse() {
    let mut rng = SplitMix64::new(1);
    for _ in 0..200 {
        let p = rng.point(0.0, 15.0);
        let x = p.to_hyperboloid();
        assert!((x.w - (1.0 + p.coords().length_squared()) / p.gap()).abs() <= 4.0 * EPS * x.w);
        let q = Point::from_hyperboloid(x).unwrap();
        assert!((q.gap() - 2.0 / (1.0 + x.w)).abs() <= 2.0 * EPS * q.gap());
        assert!(((q.gap() - p.gap()) / p.gap()).abs() < 8.0 * EPS);
        assert!((q.coords() - p.coords()).length() < 4.0 * EPS);
    }
}

/// `distance_from_origin`'s contract: relative error below 1e-14.
#[test]
fn distance_from_origin_matches_the_reference() {
    let mut rng = SplitMix64::new(2);
    let mut errs = Vec::new();
    for _ in 0..400 {
        let g = 10f64.powf(rng.range(-15.0, 0.0));
        let c = rng.direction() * (1.0 - g);
        let Ok(p) = Point::from_coords(c) else {
            continue;
        };
        let want = reference::distance(DVec3::ZERO, c);
        errs.push(rel(p.distance_from_origin(), &want));
    }
    eprintln!(
        "distance_from_origin: max relative error {:e}",
        max_of(&errs)
    );
    assert!(max_of(&errs) < 1e-14);
}

/// `at_distance_from_origin`: radius `tanh(d/2)` and gap `1/cosh^2(d/2)` to a
/// few ulps, out to the edge of f64.
#[test]
fn at_distance_from_origin_matches_the_reference() {
    let mut rng = SplitMix64::new(3);
    let (mut er, mut eg, mut ed) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..400 {
        let d = rng.range(0.0, 37.0);
        let p = Point::at_distance_from_origin(rng.direction(), d).unwrap();
        let half = R::f(0.5 * d);
        let (sh, ch) = (half.sinh(), half.cosh());
        er = er.max(rel(p.coords().length(), &(sh / ch.clone())));
        eg = eg.max(rel(p.gap(), &(R::f(1.0) / (&ch * &ch))));
        if d > 0.0 {
            ed = ed.max(((p.distance_from_origin() - d) / d).abs());
        }
    }
    eprintln!("at_distance_from_origin: radius {er:e}, gap {eg:e}, round trip {ed:e}");
    assert!(er < 4.0 * EPS && eg < 8.0 * EPS && ed < 1e-14);
}

// ---------------------------------------------------------------------------
// 2. Distance
// ---------------------------------------------------------------------------

/// `acosh(1 + t)` loses everything for tiny distances; `2 asinh` does not.
#[test]
fn acosh_form_fails_for_tiny_distances_and_asinh_does_not() {
    let a = Point::from_coords(DVec3::new(0.3, 0.0, 0.0)).unwrap();
    let b = Point::from_coords(DVec3::new(0.3 + 1e-10, 0.0, 0.0)).unwrap();
    let h = b.coords().x - a.coords().x;
    let want = 2.0 * h / (1.0 - 0.3 * (0.3 + h));
    let t = 2.0 * (a.coords() - b.coords()).length_squared() / (a.gap() * b.gap());
    let acosh_form = (1.0 + t).acosh();
    let got = a.distance(b);
    assert!(((got - want) / want).abs() < 1e-12, "{got:e} vs {want:e}");
    assert!(((acosh_form - want) / want).abs() > 1e-8, "{acosh_form:e}");
}

// ---------------------------------------------------------------------------
// 3. Möbius addition and the gyration
// ---------------------------------------------------------------------------

/// In the plane of `u` and `v`, Möbius addition is `(u+v)/(1 + conj(u) v)`.
#[test]
fn mobius_addition_is_the_complex_formula_in_a_plane() {
    let mut rng = SplitMix64::new(4);
    for _ in 0..200 {
        let (a, b) = (rng.range(0.0, TAU), rng.range(0.0, TAU));
        let (ru, rv) = (rng.range(0.0, 0.95), rng.range(0.0, 0.95));
        let (u, v) = ((ru * a.cos(), ru * a.sin()), (rv * b.cos(), rv * b.sin()));
        // (u + v) / (1 + conj(u) v), complex arithmetic by hand.
        let num = (u.0 + v.0, u.1 + v.1);
        let den = (1.0 + u.0 * v.0 + u.1 * v.1, u.0 * v.1 - u.1 * v.0);
        let n2 = den.0 * den.0 + den.1 * den.1;
        let w = (
            (num.0 * den.0 + num.1 * den.1) / n2,
            (num.1 * den.0 - num.0 * den.1) / n2,
        );
        let pu = Point::from_coords(DVec3::new(u.0, u.1, 0.0)).unwrap();
        let pv = Point::from_coords(DVec3::new(v.0, v.1, 0.0)).unwrap();
        let s = mobius::add(&pu, &pv);
        assert!((s.coords() - DVec3::new(w.0, w.1, 0.0)).length() < 1e-14);
        // The gap identity: 1 - |u (+) v|^2 = gap_u gap_v / |1 + conj(u) v|^2
        // (a sum nearer the origin than an input takes its coordinates' own
        // gap instead, within a few ulps of the coordinates: 1e-13 here).
        assert!((s.gap() - pu.gap() * pv.gap() / n2).abs() < 1e-13 * s.gap().max(1e-300) + 1e-16);
    }
}

/// `add_raw`'s contract, against 320 bits: the gap within a few ulps (for a
/// sum nearer the origin than an input, the gap of its coordinates, within
/// `1000 eps (1/gap_u + 1/gap_v + 1/gap_sum)` relative, scored as 1e-14 per
/// unit of that), the position within `10 eps (1/gap_u + 1/gap_v + 1/gap_sum)`.
#[test]
fn mobius_addition_matches_the_reference() {
    let mut rng = SplitMix64::new(5);
    let (mut worst_gap, mut worst_ratio) = (0.0f64, 0.0f64);
    for k in 0..400 {
        let u = rng.point(0.0, 12.0);
        // Half the cases nearly cancel: v close to -u.
        let v = if k % 2 == 0 {
            rng.point(0.0, 12.0)
        } else {
            let back = Point::from_coords(-u.coords()).unwrap();
            Point::from_coords(step(&back, rng.direction(), rng.range(1e-6, 1.0)).coords()).unwrap()
        };
        let s = mobius::add(&u, &v);
        let exact = mobius_r(&r3(u.coords()), &r3(v.coords()));
        let g_exact = gap3(&exact);
        let scale = EPS * (1.0 / u.gap() + 1.0 / v.gap() + 1.0 / s.gap());
        // A sum nearer the origin than its inputs carries its coordinates'
        // own gap (consistent with them), so its gap is as accurate as its
        // position: relative error within the position's scale.
        let own = s.gap() > 2.0 * u.gap().min(v.gap());
        let unit = if own { 1e-14 / (1e3 * scale) } else { 1.0 };
        worst_gap = worst_gap.max(rel(s.gap(), &g_exact) * unit);
        worst_ratio = worst_ratio.max(distance_r(s.coords(), &exact) / scale);
    }
    eprintln!(
        "mobius add: gap max relative error {worst_gap:e}; position error / (eps (1/gu + 1/gv + 1/gs)) max {worst_ratio:.3}"
    );
    assert!(worst_gap < 1e-14, "{worst_gap:e}");
    assert!(worst_ratio < 10.0, "{worst_ratio}");
}

/// In the plane of `u` and `v` the gyration is multiplication by
/// `(1 + u conj(v)) / (1 + conj(u) v)`, and it is `-(u(+)v) (+) (u (+) (v (+) w))`.
#[test]
fn gyration_is_the_complex_rotation() {
    let mut rng = SplitMix64::new(6);
    for _ in 0..200 {
        let u = Point::from_coords(DVec3::new(rng.range(-0.6, 0.6), rng.range(-0.6, 0.6), 0.0))
            .unwrap();
        let v = Point::from_coords(DVec3::new(rng.range(-0.6, 0.6), rng.range(-0.6, 0.6), 0.0))
            .unwrap();
        let g = mobius::gyration(u.coords(), u.gap(), v.coords(), v.gap());
        let (uc, vc) = (u.coords(), v.coords());
        // z = 1 + conj(u) v; gyr = conj(z) / z.
        let z = (1.0 + uc.x * vc.x + uc.y * vc.y, uc.x * vc.y - uc.y * vc.x);
        let z2 = z.0 * z.0 + z.1 * z.1;
        let rot = ((z.0 * z.0 - z.1 * z.1) / z2, -2.0 * z.0 * z.1 / z2);
        let w = DVec3::new(0.3, -0.2, 0.0);
        let want = DVec3::new(rot.0 * w.x - rot.1 * w.y, rot.1 * w.x + rot.0 * w.y, 0.0);
        assert!((g * w - want).length() < 1e-15);
        // Vectors along the axis u x v are fixed.
        assert!((g * DVec3::Z - DVec3::Z).length() < 1e-15);
        // The definition, with points off the plane too.
        let w3 = Point::from_coords(DVec3::new(0.1, 0.2, 0.3)).unwrap();
        let uv = mobius::add(&u, &v);
        let minus_uv = Point::from_coords(-uv.coords()).unwrap();
        let lhs = mobius::add(&minus_uv, &mobius::add(&u, &mobius::add(&v, &w3)));
        assert!((g * w3.coords() - lhs.coords()).length() < 1e-14);
    }
}

// ---------------------------------------------------------------------------
// 4. Isometries
// ---------------------------------------------------------------------------

/// `Isometry::apply`'s contract against 320 bits: the image within
/// `10 eps (1/gap_a + 1/gap_x + 1/gap_image)` of the exact `a (+) Qx`.
#[test]
fn isometry_apply_matches_the_reference() {
    let mut rng = SplitMix64::new(7);
    let mut worst: f64 = 0.0;
    for _ in 0..300 {
        let a = rng.point(0.0, 12.0);
        let q = DMat3::from_axis_angle(rng.direction(), rng.range(-PI, PI));
        let f = Isometry::transvection_from_origin(a).compose(&Isometry::orthogonal_unchecked(q));
        let x = rng.point(0.0, 12.0);
        let img = f.apply(&x);
        let qx: R3 = {
            let xr = r3(x.coords());
            let m = |i: usize| [R::f(q.x_axis[i]), R::f(q.y_axis[i]), R::f(q.z_axis[i])];
            std::array::from_fn(|i| dot3(&m(i), &xr))
        };
        let exact = mobius_r(&r3(a.coords()), &qx);
        let scale = EPS * (1.0 / a.gap() + 1.0 / x.gap() + 1.0 / img.gap());
        worst = worst.max(distance_r(img.coords(), &exact) / scale);
    }
    eprintln!("Isometry::apply: error / (eps (1/ga + 1/gx + 1/gimg)) max {worst:.3}");
    assert!(worst < 10.0, "{worst}");
}

/// The reflection `x -> a (+) Qx` with `a = n_t n/|n|^2`, `Q = I - 2 n n^T/|n|^2`
/// is the hyperboloid mirror `X -> X - 2<X,N>N`.
#[test]
fn reflection_is_the_hyperboloid_mirror() {
    let mut rng = SplitMix64::new(8);
    for _ in 0..200 {
        let pts: Vec<Vertex> = (0..3).map(|_| rng.point(0.0, 2.0).into()).collect();
        let Ok(plane) = HPlane::through(&pts[0], &pts[1], &pts[2]) else {
            continue;
        };
        let r = Isometry::reflection(&plane);
        let n = plane.normal();
        let nn = n.truncate();
        assert!((r.translation_part().gap() - 1.0 / nn.length_squared()).abs() < 1e-15);
        let x = rng.point(0.0, 3.0);
        let xh = x.to_hyperboloid();
        let mirrored = Point::from_hyperboloid(xh - 2.0 * lorentz::dot(xh, n) * n).unwrap();
        let d = r.apply(&x).distance(mirrored);
        assert!(d < 1e-12, "{d:e}");
    }
}

/// The thesis defines the translation as two reflections (in the plane
/// orthogonal to the segment at its start, then in the bisector); hgeom
/// evaluates `tau_A tau_w tau_{-A}`. They are the same map.
#[test]
fn translation_equals_the_two_reflection_definition() {
    let mut rng = SplitMix64::new(9);
    let mut worst: f64 = 0.0;
    for _ in 0..300 {
        let a = rng.point(0.0, 1.5);
        let b = step(&a, rng.direction(), rng.range(0.05, 3.0));
        let seg = Segment::new(a, b).unwrap();
        let t = Isometry::translation(&seg).unwrap();
        let s = Isometry::translation_by_reflections(&seg).unwrap();
        assert!(t.preserves_orientation() && s.preserves_orientation());
        for _ in 0..3 {
            let x = rng.point(0.0, 3.0);
            worst = worst.max(t.apply(&x).distance(s.apply(&x)));
        }
        worst = worst.max(s.apply(&a).distance(b));
    }
    eprintln!("translation vs two reflections: max {worst:e}");
    assert!(worst < 1e-12, "{worst:e}");
}

/// The rotation about an h-line turns tangent vectors orthogonal to the
/// axis by the right-hand rule about the direction `start -> end`:
/// `w -> cos(theta) w + sin(theta) (u x w)` at the start point.
#[test]
fn rotation_follows_the_right_hand_rule_about_any_axis() {
    let mut rng = SplitMix64::new(10);
    for _ in 0..200 {
        let a = rng.point(0.0, 2.0);
        let b = step(&a, rng.direction(), rng.range(0.1, 2.0));
        let seg = Segment::new(a, b).unwrap();
        let theta = rng.range(-PI, PI);
        let rot = Isometry::rotation_about_segment_unchecked(&seg, theta);
        let u = seg.direction_at_start();
        let w = u.any_orthonormal_vector();
        let want = theta.cos() * w + theta.sin() * u.cross(w);
        let got = rot.apply_direction(&a, w);
        assert!((got - want).length() < 1e-10, "{:e}", (got - want).length());
        assert!((rot.apply_direction(&a, u) - u).length() < 1e-10);
    }
}

/// The Lorentz matrix of `(a, Q)` carries `X(p)` to `X(f(p))`.
#[test]
fn lorentz_matrix_agrees_with_apply() {
    let mut rng = SplitMix64::new(11);
    for _ in 0..200 {
        let a = rng.point(0.0, 3.0);
        let q = DMat3::from_axis_angle(rng.direction(), rng.range(-PI, PI));
        let f = Isometry::transvection_from_origin(a).compose(&Isometry::orthogonal_unchecked(q));
        let m = f.to_lorentz();
        let x = rng.point(0.0, 3.0);
        let want = f.apply(&x).to_hyperboloid();
        let got = m * x.to_hyperboloid();
        assert!(
            (got - want).length() < 1e-13 * want.length(),
            "{got:?} vs {want:?}"
        );
        // M^T eta M = eta.
        let cols = [m.x_axis, m.y_axis, m.z_axis, m.w_axis];
        for i in 0..4 {
            for j in 0..4 {
                let want = if i != j {
                    0.0
                } else if i == 3 {
                    -1.0
                } else {
                    1.0
                };
                assert!((lorentz::dot(cols[i], cols[j]) - want).abs() < 1e-12);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// 5. h-planes
// ---------------------------------------------------------------------------

/// `HPlane::through` orients the normal by the right-hand rule: at `a`, the
/// normal's ball direction is on the side of `(b - a) x (c - a)` for a small
/// triangle, anywhere in the ball.
#[test]
fn plane_through_three_points_follows_the_right_hand_rule() {
    let mut rng = SplitMix64::new(12);
    for _ in 0..300 {
        let a = rng.point(0.0, 6.0);
        let (u, v) = (rng.direction(), rng.direction());
        if u.cross(v).length() < 0.1 {
            continue;
        }
        let b = step(&a, u, 0.01);
        let c = step(&a, v, 0.01);
        let plane = HPlane::through(&a.into(), &b.into(), &c.into()).unwrap();
        let n_ball = hgeom::ray::ball_direction(a.to_hyperboloid(), plane.normal());
        assert!(n_ball.dot(u.cross(v)) > 0.0);
    }
    // The documented example: counter-clockwise in the xy plane seen from +z.
    let p = |x: f64, y: f64, z: f64| Vertex::from(Point::from_coords(DVec3::new(x, y, z)).unwrap());
    let plane = HPlane::through(&p(0.1, 0.0, 0.3), &p(0.0, 0.1, 0.3), &p(-0.1, -0.1, 0.3)).unwrap();
    assert!(plane.normal().z > 0.0);
}

/// The ball shape of `<X,N> = 0`: centre `n/n_t`, radius `1/|n_t|`, with
/// `|c|^2 = 1 + r^2` (the thesis prints `1 + r^2 = sqrt(|c|^2)`, which fails).
#[test]
fn ball_shape_is_orthogonal_to_the_absolute() {
    let mut rng = SplitMix64::new(13);
    for _ in 0..200 {
        let pts: Vec<Point> = (0..3).map(|_| rng.point(0.1, 3.0)).collect();
        let vs: Vec<Vertex> = pts.iter().map(|&p| p.into()).collect();
        let Ok(plane) = HPlane::through(&vs[0], &vs[1], &vs[2]) else {
            continue;
        };
        let hgeom::BallShape::Sphere { center, radius } = plane.ball_shape() else {
            continue;
        };
        let c2 = center.length_squared();
        assert!((c2 - (1.0 + radius * radius)).abs() < 1e-12 * c2);
        if radius > 0.1 {
            // The thesis's version is off by a visible amount.
            assert!(((1.0 + radius * radius) - c2.sqrt()).abs() > 1e-3);
        }
        for q in &pts {
            let d = (q.coords() - center).length();
            assert!((d - radius).abs() < 1e-11 * c2, "{d} vs {radius}");
        }
    }
}

/// `<X,N>` is `sinh` of the signed distance: from a point `Y` of the plane,
/// `cosh s Y + sinh s N` is at signed distance `s`.
#[test]
fn signed_distance_is_the_distance_to_the_foot() {
    let mut rng = SplitMix64::new(14);
    for _ in 0..200 {
        let pts: Vec<Point> = (0..3).map(|_| rng.point(0.0, 2.0)).collect();
        let vs: Vec<Vertex> = pts.iter().map(|&p| p.into()).collect();
        let Ok(plane) = HPlane::through(&vs[0], &vs[1], &vs[2]) else {
            continue;
        };
        let y = from_timelike(
            pts[0].to_hyperboloid() + 2.0 * pts[1].to_hyperboloid() + pts[2].to_hyperboloid(),
        )
        .to_hyperboloid();
        let n = plane.normal();
        for s in [-2.0f64, -0.3, 1e-6, 0.5, 3.0] {
            let x = Point::from_hyperboloid(s.cosh() * y + s.sinh() * n).unwrap();
            let got = plane.signed_distance(&x);
            assert!(
                (got - s).abs() < 1e-12 * s.abs().max(1.0) + 1e-14,
                "{got} vs {s}"
            );
        }
    }
}

/// The crossing with a plane from the origin (cancellation-free) is the
/// same root as the textbook `tanh t = -<X,N>/<V,N>`.
#[test]
fn crossing_from_origin_equals_the_general_formula() {
    let mut rng = SplitMix64::new(15);
    let mut n = 0;
    for _ in 0..400 {
        let pts: Vec<Vertex> = (0..3).map(|_| rng.point(0.0, 3.0).into()).collect();
        let Ok(plane) = HPlane::through(&pts[0], &pts[1], &pts[2]) else {
            continue;
        };
        let ray = Ray::from_origin_unchecked(rng.direction());
        let (o, d) = (
            lorentz::dot(ray.origin, plane.normal()),
            lorentz::dot(ray.dir, plane.normal()),
        );
        let tau = -o / d;
        let textbook = (tau.abs() < 1.0).then(|| tau.atanh());
        match (plane.crossing(&ray), textbook) {
            (Some(t), Some(want)) => {
                n += 1;
                // atanh amplifies the rounding of tau by cosh^2 t.
                let tol = 1e-14 * t.abs().max(1.0) + 10.0 * EPS * t.cosh().powi(2);
                assert!((t - want).abs() < tol, "{t} vs {want}");
            }
            (None, None) => {}
            (got, want) => {
                // Only a ray meeting the plane at the absolute itself may
                // differ (|tau| within rounding of 1).
                assert!(
                    (tau.abs() - 1.0).abs() < 1e-12,
                    "{got:?} vs {want:?}, tau {tau}"
                );
            }
        }
    }
    assert!(n > 100);
}

// ---------------------------------------------------------------------------
// 6. h-spheres
// ---------------------------------------------------------------------------

/// `HSphere::euclidean` against the closed form (docs/geometry.md) evaluated in 320 bits:
/// centre factor `(1-T^2)/(1-a^2T^2)`, radius `T(1-a^2)/(1-a^2T^2)`.
#[test]
fn euclidean_sphere_matches_the_reference() {
    let mut rng = SplitMix64::new(16);
    let (mut ec, mut er) = (0.0f64, 0.0f64);
    for _ in 0..400 {
        let c = rng.point(0.0, 30.0);
        let r = rng.range(1e-6, 20.0);
        let s = HSphere::new(c, r).unwrap();
        let (centre, radius) = s.euclidean();
        let half = R::f(0.5 * r);
        let t = half.sinh() / half.cosh();
        let t2 = &t * &t;
        let g = reference::gap(c.coords());
        let one = R::f(1.0);
        let den = &one - &(&(&one - &g) * &t2);
        let factor = (&one - &t2) / den.clone();
        er = er.max(rel(radius, &(&t * &g / den)));
        if c.coords() != DVec3::ZERO {
            let a = c.coords().length();
            ec = ec.max(rel(centre.length() / a, &factor));
        }
    }
    eprintln!("HSphere::euclidean: centre {ec:e}, radius {er:e} (max relative)");
    assert!(ec < 1e-14 && er < 1e-14);
}

/// The extreme points of the Euclidean sphere on the diameter through the
/// centre are at `tanh((D -+ r)/2)`, `D` the centre's distance from the
/// origin: the derivation of the formula above.
#[test]
fn euclidean_sphere_extremes_are_at_distance_d_plus_minus_r() {
    let mut rng = SplitMix64::new(17);
    for _ in 0..200 {
        let c = rng.point(0.1, 5.0);
        let r = rng.range(0.01, 3.0);
        let (centre, radius) = HSphere::new(c, r).unwrap().euclidean();
        let dist = c.distance_from_origin();
        let u = c.coords().normalize();
        let far = (centre + radius * u).dot(u);
        let near = (centre - radius * u).dot(u);
        assert!((far - (0.5 * (dist + r)).tanh()).abs() < 1e-14);
        assert!((near - (0.5 * (dist - r)).tanh()).abs() < 1e-14);
    }
}

/// Both roots of the `e^t` quadratic lie on the sphere.
#[test]
fn sphere_roots_solve_the_level_equation() {
    let mut rng = SplitMix64::new(18);
    for _ in 0..200 {
        let c = rng.point(0.0, 3.0);
        let r = rng.range(0.05, 2.0);
        let s = HSphere::new(c, r).unwrap();
        let ray = Ray::from_origin_unchecked(rng.direction());
        let Some((near, far)) = s.roots(&ray) else {
            continue;
        };
        for t in [near, far] {
            let d = lorentz::distance(ray.at(t), c.to_hyperboloid());
            assert!((d - r).abs() < 1e-10, "{d} vs {r}");
        }
    }
}

// ---------------------------------------------------------------------------
// 7. h-lines and h-cylinders
// ---------------------------------------------------------------------------

/// `sinh^2 d(X, line) = <X,N1>^2 + <X,N2>^2` in the adapted Lorentz basis, against
/// the canonical-frame distance.
#[test]
fn sinh_distance_to_a_line_is_the_lorentz_basis_formula() {
    let mut rng = SplitMix64::new(19);
    for _ in 0..200 {
        let (a, b) = (rng.point(0.0, 2.0), rng.point(0.0, 2.0));
        let Ok(line) = HLine::through(&a.into(), &b.into()) else {
            continue;
        };
        let x = rng.point(0.0, 3.0);
        let want = line.distance_to(&x).sinh();
        let got = line.sinh_distance_h(x.to_hyperboloid());
        assert!(
            (got - want).abs() < 1e-13 * want.max(1.0),
            "{got} vs {want}"
        );
    }
}

/// `HLine::distance_to` against a 320-bit reference (the Gram-matrix form).
#[test]
fn line_distance_matches_the_reference() {
    let mut rng = SplitMix64::new(20);
    let mut worst: f64 = 0.0;
    for _ in 0..300 {
        let (a, b) = (rng.point(0.0, 4.0), rng.point(0.0, 4.0));
        let Ok(line) = HLine::through(&a.into(), &b.into()) else {
            continue;
        };
        let x = rng.point(0.0, 4.0);
        let s2 = reference::sinh2_to_line(
            &reference::hyperboloid(x.coords()),
            &reference::hyperboloid(a.coords()),
            &reference::hyperboloid(b.coords()),
        );
        let want = s2.sqrt().asinh().to_f64();
        worst = worst.max((line.distance_to(&x) - want).abs());
    }
    eprintln!("HLine::distance_to: max absolute error {worst:e}");
    assert!(worst < 1e-12, "{worst:e}");
}

/// The two ends of an ideal-ideal line, and its base point: the foot of the
/// perpendicular from the origin, `(u+v)/(2+|u-v|)` with gap
/// `2|u-v|/(2+|u-v|)`.
#[test]
fn ideal_line_base_is_the_foot_of_the_perpendicular() {
    let mut rng = SplitMix64::new(21);
    for _ in 0..200 {
        let (u, v) = (rng.direction(), rng.direction());
        if (u - v).length() < 1e-3 {
            continue;
        }
        let e1 = IdealPoint::from_direction(u).unwrap();
        let e2 = IdealPoint::from_direction(v).unwrap();
        let line = HLine::through(&e1.into(), &e2.into()).unwrap();
        let base = line.base();
        let delta = (u - v).length();
        assert!((base.coords() - (u + v) / (2.0 + delta)).length() < 4.0 * EPS);
        assert!(((base.gap() - one_minus_norm_sq(base.coords())) / base.gap()).abs() < 1e-13);
        let d0 = base.distance_from_origin();
        for s in [-1e-3, 1e-3, 0.5] {
            assert!(line.point_at(s).unwrap().distance_from_origin() > d0);
        }
    }
}

/// Both roots of the cylinder's quadratic in `e^{2t}` lie at distance `r`
/// from the axis.
#[test]
fn cylinder_roots_solve_the_quadric() {
    let mut rng = SplitMix64::new(22);
    let mut n = 0;
    for _ in 0..300 {
        let (a, b) = (rng.point(0.0, 2.0), rng.point(0.0, 2.0));
        let Ok(line) = HLine::through(&a.into(), &b.into()) else {
            continue;
        };
        let r = rng.range(0.05, 1.0);
        let cyl = HCylinder::new(line, r).unwrap();
        let ray = Ray::from_origin_unchecked(rng.direction());
        let Some((near, far)) = cyl.roots(&ray) else {
            continue;
        };
        for t in [near, far] {
            if t.is_finite() && t.abs() < 8.0 {
                n += 1;
                let p = Point::from_hyperboloid(ray.at(t)).unwrap();
                let d = line.distance_to(&p);
                assert!(
                    (d - r).abs() < 1e-10 * t.cosh().powi(2),
                    "{d} vs {r} at t {t}"
                );
            }
        }
    }
    assert!(n > 50);
}

// ---------------------------------------------------------------------------
// 8. Horospheres
// ---------------------------------------------------------------------------

/// The level `-<X,L> = |p - xi|^2 / (1 - |p|^2)` is constant on the Euclidean
/// sphere with centre `xi/(1+k)` and radius `k/(1+k)`.
#[test]
fn horosphere_level_is_the_euclidean_sphere() {
    let mut rng = SplitMix64::new(23);
    for _ in 0..200 {
        let xi = IdealPoint::from_direction(rng.direction()).unwrap();
        let q = rng.point(0.0, 4.0);
        let h = Horosphere::new(xi, &q).unwrap();
        let l = xi.to_hyperboloid();
        let k = -lorentz::dot(q.to_hyperboloid(), l);
        let (c, r) = h.euclidean();
        assert!((c - xi.coords() / (1.0 + k)).length() < 1e-12);
        assert!((r - k / (1.0 + k)).abs() < 1e-12);
        for _ in 0..5 {
            let p = Point::from_coords(c + r * rng.direction()).unwrap_or(q);
            let level = (p.coords() - xi.coords()).length_squared() / p.gap();
            let xp = p.to_hyperboloid();
            assert!((level - k).abs() < 1e-9 * k.max(1.0), "{level} vs {k}");
            assert!((-lorentz::dot(xp, l) - level).abs() < 1e-9 * level.max(1.0));
        }
    }
}

// ---------------------------------------------------------------------------
// 9. Polygons and figures
// ---------------------------------------------------------------------------

/// The {4,3,5} cube: Klein half-width `h^2 = sqrt5 - 2` gives the dihedral
/// angle `2pi/5`, and `cosh R = phi^2/sqrt2`.
#[test]
fn cube_435_closed_forms() {
    let h2 = 5f64.sqrt() - 2.0;
    let cos_theta = h2 / (1.0 - h2);
    assert!((cos_theta - (2.0 * PI / 5.0).cos()).abs() < 1e-15);
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let r = hgeom::cube_435_circumradius();
    assert!((r.tanh().powi(2) - 3.0 * h2).abs() < 1e-15);
    assert!((r.cosh() - phi * phi / 2f64.sqrt()).abs() < 1e-15);
    // The edge: cosh e = (1 - h^2)/(1 - 3h^2) = phi^2.
    assert!(((1.0 - h2) / (1.0 - 3.0 * h2) - phi * phi).abs() < 1e-14);
}

// ---------------------------------------------------------------------------
// Former contradictions, fixed; kept as regressions
// ---------------------------------------------------------------------------

/// `Point::from_hyperboloid` documents `None` for a vector that is "not
/// future-timelike", but it only checks `x0 >= 1 - 1e-12` and that the
/// projection lands in the ball: the spacelike `(1.5, 0, 0, 1)`
/// (`<X,X> = 1.25`) comes back as the point `(0.75, 0, 0)`.
#[test]
fn from_hyperboloid_rejects_spacelike_vectors() {
    let x = DVec4::new(1.5, 0.0, 0.0, 1.0);
    assert!(lorentz::dot(x, x) > 0.0);
    assert_eq!(Point::from_hyperboloid(x), None);
}

/// `ConvexPolygon::transformed` rebuilds the moved polygon; far out
/// (distance ~17 and beyond) rounding of the moved vertices used to trip the
/// planarity check, and the plane must never be the old one left in place.
/// The tolerance now follows the vertices' own rounding, so the polygon 18
/// away is rebuilt; its normal agrees with the old one carried by the
/// isometry (`L N`) to the rounding of `L` (`eps |L|`, 1.4e-8 relative at
/// 18), and moving it back gives the original plane to the rounding of the
/// far vertices (`eps e^18 / 4 = 3.6e-9`; measured 3.7e-9).
#[test]
fn far_polygon_gets_its_new_plane() {
    let v = |x: f64, y: f64| Vertex::from(Point::from_coords(DVec3::new(x, y, 0.0)).unwrap());
    let square =
        ConvexPolygon::new(vec![v(0.3, 0.3), v(-0.3, 0.3), v(-0.3, -0.3), v(0.3, -0.3)]).unwrap();
    let shift = Isometry::transvection_from_origin(
        Point::at_distance_from_origin(DVec3::new(0.3, 0.2, 1.0), 18.0).unwrap(),
    );
    let moved = square.transformed(&shift);
    let carried = shift.to_lorentz() * square.plane().normal();
    let n = moved.plane().normal();
    assert!(n.is_finite());
    assert!(
        (n - carried).length() <= 1e-7 * carried.length(),
        "{n:?} vs {carried:?}"
    );
    // The old plane z = 0 passes through the origin; the moved one is ~18 away.
    assert!(lorentz::dot(DVec4::W, n).abs() > 1e6);
    let back = moved.transformed(&shift.inverse());
    assert!(
        (back.plane().normal() - square.plane().normal()).length() < 1e-8,
        "{:?}",
        back.plane().normal()
    );
}

/// `HPlane::transformed` renormalises the carried normal by its computed
/// Lorentz norm, guarded by `max(f64::MIN_POSITIVE)`. For an image plane
/// ~20 from the origin `<n,n>` (exactly 1) is the difference of numbers
/// ~1e17 and rounds to 0 or below; the guard then divides by 2.2e-308 and
/// the normal becomes infinite (no error is reported).
#[test]
fn far_plane_transforms_to_a_finite_normal() {
    let plane = HPlane::from_normal(DVec4::new(0.0, 0.0, 1.0, 0.0)).unwrap();
    let mut bad = Vec::new();
    for d in [18.0, 19.0, 20.0, 21.0, 22.0] {
        let shift = Isometry::transvection_from_origin(
            Point::at_distance_from_origin(DVec3::new(0.3, 0.2, 1.0), d).unwrap(),
        )
        .compose(&Isometry::orthogonal_unchecked(DMat3::from_axis_angle(
            DVec3::new(1.0, 2.0, 3.0).normalize(),
            0.7,
        )));
        let moved = plane.transformed(&shift);
        if !moved.normal().is_finite() {
            bad.push(format!("distance {d}: normal {:?}", moved.normal()));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
