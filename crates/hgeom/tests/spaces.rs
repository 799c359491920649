//! Quotient spaces: the gluings close up, rays carried across faces follow
//! the closed geodesics the geometry predicts, and long walks stay within
//! the honeycomb walk's own drift of a 320-bit reference.

use std::f64::consts::PI;

use glam::{DMat4, DVec3};
use hgeom::{HSphere, Point, QuotientSpace, Ray, Schlafli, SpaceKind};
use hscene_test_support::SplitMix64;
use hscene_test_support::reference::{R, V4, distance_h, ldot};

fn all_spaces() -> Vec<QuotientSpace> {
    let mut kinds = vec![
        SpaceKind::SeifertWeber,
        SpaceKind::FigureEight,
        SpaceKind::Whitehead,
    ];
    for (p, q, r) in [
        (4, 3, 5),
        (5, 3, 4),
        (5, 3, 5),
        (3, 5, 3),
        (3, 3, 6),
        (4, 3, 6),
        (5, 3, 6),
        (3, 4, 4),
        (6, 3, 3),
        (6, 3, 4),
        (6, 3, 5),
        (6, 3, 6),
        (4, 4, 3),
        (4, 4, 4),
        (3, 6, 3),
    ] {
        kinds.push(SpaceKind::Mirrors(Schlafli::new(p, q, r).unwrap()));
    }
    kinds
        .into_iter()
        .map(|k| QuotientSpace::new(k).unwrap_or_else(|e| panic!("{k}: {e}")))
        .collect()
}

fn max_entry(m: DMat4) -> f64 {
    [m.x_axis, m.y_axis, m.z_axis, m.w_axis]
        .iter()
        .map(|c| c.abs().max_element())
        .fold(0.0, f64::max)
}

/// Each pairing maps its face onto its partner (checked when built: the
/// vertices land on the partner's within 1e-9); here the figures: the
/// edge cycles' angle sums against 2π (manifolds) or 4π/r (mirrors) and
/// the holonomies against the identity.
#[test]
fn edge_cycles_close_up() {
    for s in all_spaces() {
        let cycles = s.edge_cycles().unwrap();
        let mut angle_error = 0.0f64;
        let mut holonomy_error = 0.0f64;
        for c in &cycles {
            let (target, h) = match s.kind() {
                SpaceKind::Mirrors(sym) => {
                    let r = sym.r();
                    let mut h = DMat4::IDENTITY;
                    for _ in 0..r {
                        h = c.holonomy * h;
                    }
                    (4.0 * PI / f64::from(r), h)
                }
                _ => (2.0 * PI, c.holonomy),
            };
            angle_error = angle_error.max((c.angle_sum - target).abs());
            holonomy_error = holonomy_error.max(max_entry(h - DMat4::IDENTITY));
        }
        println!(
            "{}: {} faces, {} edges in {} cycles; angle sums off by {angle_error:.1e}, holonomy by {holonomy_error:.1e}",
            s.kind(),
            s.faces().len(),
            s.domain().map_or(0, |d| d.edges().len()),
            cycles.len()
        );
        // The dodecahedral cells' dihedral angles inherit the rounding of
        // the simplex's f64 mirrors (Gram matrix to 1e-15), magnified by
        // cosh² of the inradius (2.4 for {5,3,5}): 2e-14 at worst.
        assert!(angle_error < 3e-14, "{}", s.kind());
        assert!(holonomy_error < 1e-11, "{}", s.kind());
        let expected = match s.kind() {
            SpaceKind::SeifertWeber => Some((12, 30, 6)),
            SpaceKind::FigureEight => Some((6, 9, 2)),
            SpaceKind::Whitehead => Some((8, 12, 3)),
            SpaceKind::Mirrors(_) | SpaceKind::Pairings => None,
        };
        if let Some((f, e, k)) = expected {
            assert_eq!(
                (
                    s.faces().len(),
                    s.domain().map_or(0, |d| d.edges().len()),
                    cycles.len()
                ),
                (f, e, k),
                "{}",
                s.kind()
            );
        }
        // Pairings preserve orientation in the manifolds and reverse it in
        // the mirrors.
        for f in 0..s.faces().len() {
            assert_eq!(
                s.pairing(f).preserves_orientation(),
                !s.kind().is_mirrored()
            );
        }
    }
}

/// From the centre of the Seifert-Weber domain along a face's normal, the
/// geodesic leaves at the inradius ρ, re-enters at the centre of the
/// opposite face heading inward along its normal, and is back at the
/// centre after 2ρ: a ball on that axis at distance `s` behind the eye is
/// seen ahead at `2ρ - s`, with the angular radius `asin(sinh a /
/// sinh(2ρ - s))` of a ball of radius `a` at that distance.
#[test]
fn seifert_weber_closes_along_a_face_normal() {
    let s = QuotientSpace::seifert_weber().unwrap();
    let n = s.faces()[0];
    let u = -n.truncate().normalize();
    let inradius = (-n.w).asinh();
    let (behind, a) = (0.4, 0.1);
    let ball = HSphere::new(Point::at_distance_from_origin(-u, behind).unwrap(), a).unwrap();
    // Nearest hit along a ray, carried across at most 8 faces.
    let trace = |ray: Ray| -> Option<f64> {
        let mut ray = ray;
        let mut travelled = 0.0;
        for _ in 0..8 {
            let exit = s.exit(&ray);
            let end = exit.map_or(f64::INFINITY, |c| c.t);
            if let Some(hit) = ball.intersect(&ray, 1e-12, end) {
                return Some(travelled + hit.t);
            }
            let c = exit?;
            ray = s.carry(&ray, c);
            travelled += c.t;
        }
        None
    };
    let ahead = 2.0 * inradius - behind;
    let t = trace(Ray::from_origin(u).unwrap()).unwrap();
    assert!((t - (ahead - a)).abs() < 1e-13, "{t} against {}", ahead - a);
    // The angular radius, by bisection on the angle from the axis.
    let side = u.any_orthonormal_vector();
    let ray_at = |theta: f64| Ray::from_origin(u * theta.cos() + side * theta.sin()).unwrap();
    let (mut lo, mut hi) = (0.0, 0.5);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if trace(ray_at(mid)).is_some() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let expected = (a.sinh() / ahead.sinh()).asin();
    println!("angular radius {lo} against {expected}; inradius {inradius}");
    assert!((lo - expected).abs() < 1e-12);
}

/// A ray carried across 1,000 faces, against the same walk replayed at 320
/// bits (the same f64 pairings, the same faces). Two figures: the one-step
/// error (each crossing replayed at 320 bits from the f64 state), which is
/// what the walk adds, and the global drift, which the geodesic flow
/// amplifies like e^{2t} as it does for the honeycomb walk (nearby
/// geodesics part exponentially; by the shadowing lemma the f64 path stays
/// near a true geodesic within a multiple of the one-step error). The
/// drift is held to the honeycomb walk's own bound `3e-15 e^{2t}` up to
/// arc length 15, where it checks it; the one-step error to `1e-14 cosh² d`
/// at distance `d` from the domain's centre (deep in a cusp the hyperboloid
/// coordinates grow like `cosh d`, their rounding with them).
#[test]
fn a_thousand_crossings_drift_like_the_honeycomb_walk() {
    let mut rng = SplitMix64::new(38);
    for kind in [
        SpaceKind::SeifertWeber,
        SpaceKind::FigureEight,
        SpaceKind::Whitehead,
    ] {
        let s = QuotientSpace::new(kind).unwrap();
        let faces: Vec<V4> = s.faces().iter().map(|n| V4::from_f64(*n)).collect();
        let matrices: Vec<[[R; 4]; 4]> = (0..faces.len())
            .map(|f| {
                let m = s.pairing(f).to_lorentz();
                std::array::from_fn(|r| std::array::from_fn(|c| R::f(m.col(c)[r])))
            })
            .collect();
        let one = R::f(1.0);
        let cross = |o: &V4, v: &V4, face: usize| -> (V4, V4) {
            let n = &faces[face];
            let sr = -(ldot(o, n) / ldot(v, n));
            let k = one.clone() / (one.clone() - sr.clone() * &sr).sqrt();
            let x = o.add(&v.scale(&sr)).scale(&k);
            let w = o.scale(&sr).add(v).scale(&k);
            let m = &matrices[face];
            let apply = |p: &V4| {
                V4(std::array::from_fn(|r| {
                    (0..4).fold(R::f(0.0), |acc, col| acc + m[r][col].clone() * &p.0[col])
                }))
            };
            (apply(&x), apply(&w))
        };
        let mut one_step = 0.0f64;
        let mut along = 0.0f64;
        let mut scaled = 0.0f64;
        let mut drift: Vec<(f64, f64)> = Vec::new();
        let mut crossings = 0;
        for _ in 0..3 {
            let mut ray = Ray::from_origin(rng.direction()).unwrap();
            let (mut o, mut v) = (V4::from_f64(ray.origin), V4::from_f64(ray.dir));
            let mut t = 0.0;
            for _ in 0..1000 {
                let Some(c) = s.exit(&ray) else { break };
                let before = ray;
                ray = s.carry(&ray, c);
                t += c.t;
                crossings += 1;
                let (x1, w1) = cross(
                    &V4::from_f64(before.origin),
                    &V4::from_f64(before.dir),
                    c.face,
                );
                along = along.max(distance_h(&x1, &V4::from_f64(ray.origin)).to_f64());
                let off = off_line(&V4::from_f64(ray.origin), &x1, &w1);
                one_step = one_step.max(off);
                // Near a cusp the crossing point is far from the origin,
                // where f64 on the hyperboloid resolves eps cosh² of it.
                scaled = scaled.max(off / (ray.origin.w * ray.origin.w));
                if t <= 15.0 {
                    (o, v) = cross(&o, &v, c.face);
                    let dx = distance_h(&o, &V4::from_f64(ray.origin)).to_f64();
                    drift.push((t, dx));
                }
            }
        }
        let checkpoints: Vec<String> = [5.0, 10.0, 12.0, 15.0]
            .iter()
            .map(|&at| {
                let worst = drift
                    .iter()
                    .filter(|(t, _)| *t <= at && *t > at - 2.5)
                    .map(|(_, d)| *d)
                    .fold(0.0, f64::max);
                format!("t ≤ {at}: {worst:.1e}")
            })
            .collect();
        println!(
            "{kind}: {crossings} crossings, one-step error at most {one_step:.1e} off the geodesic \
             ({scaled:.1e} cosh² of the distance from the centre; {along:.1e} along it, grazing \
             exits); drift {checkpoints:?}"
        );
        assert_eq!(crossings, 3000, "{kind}: every ray crosses 1,000 faces");
        assert!(
            scaled < 1e-14,
            "{kind}: one step {one_step:e}, {scaled:e} scaled"
        );
        for (t, dx) in &drift {
            assert!(
                *dx < 3e-15 * (2.0 * t).exp().max(1.0),
                "{kind}: {dx:e} at {t}"
            );
        }
    }
}

/// The distance from `x` to the geodesic through `o` with unit tangent
/// `v`, at 320 bits: `sinh² d = <X,O>² - <X,V>² - 1` for `X` on the
/// hyperboloid (all three renormalised here, at 320 bits).
fn off_line(x: &V4, o: &V4, v: &V4) -> f64 {
    let unit = |p: &V4| p.scale(&(R::f(1.0) / (R::f(0.0) - ldot(p, p)).sqrt()));
    let (x, o) = (unit(x), unit(o));
    let v = v.add(&o.scale(&ldot(&o, v)));
    let v = v.scale(&(R::f(1.0) / ldot(&v, &v).sqrt()));
    let a = ldot(&x, &o);
    let b = ldot(&x, &v);
    let s2 = a.clone() * &a - b.clone() * &b - R::f(1.0);
    if s2.is_negative() {
        return 0.0;
    }
    s2.sqrt().asinh().to_f64()
}

/// The pairings of a Dirichlet domain as SnapPy gives them (time
/// coordinate first), from a file of `scenes/manifolds/`, in hgeom's
/// coordinates (time last).
fn snappy_pairings(file: &str) -> Vec<DMat4> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../scenes/manifolds")
        .join(file);
    let text = std::fs::read_to_string(path).unwrap();
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    doc["pairings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| {
            let e = |r: usize, c: usize| m[r][c].as_f64().unwrap();
            // Row r, column c of the time-last matrix is row (r+1)%4,
            // column (c+1)%4 of the time-first one.
            let at = |r: usize, c: usize| e((r + 1) % 4, (c + 1) % 4);
            DMat4::from_cols_array_2d(&std::array::from_fn(|c| std::array::from_fn(|r| at(r, c))))
        })
        .collect()
}

/// Manifolds from SnapPy's Dirichlet domains: the figure-eight knot
/// complement (m004, cusped) and the Weeks manifold (m003(-3,1), the
/// closed hyperbolic manifold of least volume). Their domains come out
/// with SnapPy's face, edge and vertex counts, every edge cycle closes to
/// 2π with the identity, and rays cross a thousand faces.
#[test]
fn snappy_dirichlet_domains_are_manifolds() {
    for (file, faces, edges, vertices, ideal) in
        [("m004.json", 12, 18, 8, 4), ("weeks.json", 18, 42, 26, 0)]
    {
        let s = QuotientSpace::from_pairings(&snappy_pairings(file)).unwrap();
        let d = s.domain().unwrap();
        assert_eq!(
            (
                d.faces().len(),
                d.edges().len(),
                d.vertices().len(),
                d.ideal().iter().filter(|i| **i).count()
            ),
            (faces, edges, vertices, ideal),
            "{file}"
        );
        let cycles = s.edge_cycles().unwrap();
        let worst = cycles
            .iter()
            .map(|c| (c.angle_sum - 2.0 * PI).abs())
            .fold(0.0, f64::max);
        println!(
            "{file}: {} cycles, angle sums off by {worst:.1e}",
            cycles.len()
        );
        assert!(worst < 1e-12, "{file}");
        let mut rng = SplitMix64::new(7);
        let mut ray = Ray::from_origin(rng.direction()).unwrap();
        let mut crossed = 0;
        for _ in 0..1000 {
            let Some(c) = s.exit(&ray) else { break };
            ray = s.carry(&ray, c);
            crossed += 1;
            assert!(
                s.contains(ray.origin, 1e-9),
                "{file}: carried out of the domain"
            );
        }
        assert!(crossed == 1000 || ideal > 0, "{file}: {crossed}");
    }
}

/// What is not a gluing is refused with the face it is about.
#[test]
fn bad_pairings_are_refused() {
    let good = snappy_pairings("weeks.json");
    let mut missing = good.clone();
    missing.remove(0);
    // Its partner's inverse is missing: the face is named, with how far
    // the nearest pairing is from its inverse and the tolerance.
    assert!(matches!(
        QuotientSpace::from_pairings(&missing),
        Err(hgeom::GeomError::InexactPairing { error, tolerance, .. }) if error > tolerance
    ));
    let mut skewed = good.clone();
    skewed[3].x_axis.x *= 1.01;
    assert!(matches!(
        QuotientSpace::from_pairings(&skewed),
        Err(hgeom::GeomError::InexactPairing { face: 4, .. })
    ));
    assert!(QuotientSpace::from_pairings(&good[..3]).is_err());
}

/// The domain's volume is the manifold's: the built-in spaces against
/// their known volumes (Seifert-Weber 11.1990..., the figure-eight knot
/// complement 2 × 1.01494..., the Whitehead link complement 3.66386...),
/// the SnapPy domains against SnapPy's `M.volume()`, and the mirrored
/// cells against the honeycombs' cells (the regular ideal tetrahedron
/// `{3,3,6}` 3Л(π/3) = 1.01494..., octahedron `{3,4,4}` 3.66386..., the
/// right-angled dodecahedron `{5,3,4}` 4.30620... and the cube of
/// `{4,3,5}` 1.72248...).
#[test]
fn domain_volumes_are_the_manifolds_volumes() {
    let cases: [(QuotientSpace, f64); 9] = [
        (
            QuotientSpace::seifert_weber().unwrap(),
            11.199_064_740_814_68,
        ),
        (
            QuotientSpace::new(hgeom::SpaceKind::FigureEight).unwrap(),
            2.029_883_212_819_307_3,
        ),
        (
            QuotientSpace::new(hgeom::SpaceKind::Whitehead).unwrap(),
            3.663_862_376_708_876,
        ),
        (
            QuotientSpace::from_pairings(&snappy_pairings("m004.json")).unwrap(),
            2.029_883_212_819_307_3,
        ),
        (
            QuotientSpace::from_pairings(&snappy_pairings("weeks.json")).unwrap(),
            0.942_707_362_776_927_7,
        ),
        (
            QuotientSpace::new(hgeom::SpaceKind::Mirrors(
                hgeom::Schlafli::new(3, 3, 6).unwrap(),
            ))
            .unwrap(),
            1.014_941_606_409_653_6,
        ),
        // Finite regular cells: the right-angled dodecahedron and the
        // cube of {4,3,5}, 120 and 48 characteristic orthoschemes (the
        // values from their angles in 30-digit arithmetic).
        (
            QuotientSpace::new(hgeom::SpaceKind::Mirrors(
                hgeom::Schlafli::new(5, 3, 4).unwrap(),
            ))
            .unwrap(),
            4.306_207_600_730_809,
        ),
        (
            QuotientSpace::new(hgeom::SpaceKind::Mirrors(
                hgeom::Schlafli::new(4, 3, 5).unwrap(),
            ))
            .unwrap(),
            1.722_483_040_292_323,
        ),
        (
            QuotientSpace::new(hgeom::SpaceKind::Mirrors(
                hgeom::Schlafli::new(3, 4, 4).unwrap(),
            ))
            .unwrap(),
            3.663_862_376_708_876,
        ),
    ];
    let mut worst = 0.0f64;
    for (space, expected) in cases {
        let v = space.volume().unwrap();
        let error = (v - expected).abs() / expected;
        println!("{}: {v:.15} ({error:.1e} relative)", space.kind());
        worst = worst.max(error);
    }
    assert!(worst < 1e-12, "{worst:e}");
}

/// The translation from the origin to the hyperboloid point `y` (time
/// last): `[[I + y yᵀ/(1+y₀), y], [yᵀ, y₀]]`.
fn translation_to(y: DVec3) -> DMat4 {
    let y0 = (1.0 + y.length_squared()).sqrt();
    let k = 1.0 / (1.0 + y0);
    DMat4::from_cols(
        (DVec3::X + y * (y.x * k)).extend(y.x),
        (DVec3::Y + y * (y.y * k)).extend(y.y),
        (DVec3::Z + y * (y.z * k)).extend(y.z),
        y.extend(y0),
    )
}

/// 512 faces, 256 of them through one vertex (the bisectors of the origin
/// and 256 points on a circle of a sphere about that vertex through the
/// origin) and 256 through its opposite: the vertex search once tried
/// every triple of faces against every face (O(F⁴), 3 s in release, 19-37 s
/// for the file of issue 49); each face's polygon now costs O(F k).
#[test]
fn five_hundred_and_twelve_faces_through_one_vertex_are_checked_quickly() {
    let a: f64 = 0.8;
    let t = 0.5;
    let y0 = 1.0 + t * a.tanh();
    let r = (y0 * y0 - 1.0 - t * t).sqrt();
    let mut pairings = Vec::new();
    for k in 0..256 {
        let phi = 2.0 * PI * f64::from(k) / 256.0;
        let y = DVec3::new(r * phi.cos(), r * phi.sin(), t);
        pairings.push(translation_to(y));
        pairings.push(translation_to(-y));
    }
    let started = std::time::Instant::now();
    let result = QuotientSpace::from_pairings(&pairings);
    let took = started.elapsed();
    println!("512 faces: {took:?}, {:?}", result.as_ref().err());
    // Not a manifold (a translation group of this shape has no such
    // domain): refused, with a face named.
    assert!(result.unwrap_err().to_string().contains("face"));
    assert!(took.as_secs_f64() < 3.0, "{took:?}");
}
