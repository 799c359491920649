//! Property tests and hard cases for the quadric surfaces: h-cylinders, rods,
//! horospheres, and the h-lines they are built on.

use glam::DVec3;
use hgeom::{
    HCylinder, HLine, HPlane, Hit, Horosphere, IdealPoint, Isometry, Point, Ray, Rod, Vertex,
    lorentz,
};
use proptest::prelude::*;

fn config() -> ProptestConfig {
    ProptestConfig {
        failure_persistence: None,
        ..ProptestConfig::with_cases(256)
    }
}

fn unit() -> impl Strategy<Value = DVec3> {
    (-1.0f64..1.0, 0.0f64..std::f64::consts::TAU).prop_map(|(z, phi)| {
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    })
}

fn point(max: f64) -> impl Strategy<Value = Point> {
    (unit(), 0.0..max).prop_map(|(d, r)| Point::at_distance_from_origin(d, r).unwrap())
}

/// The hit is a point of the hyperboloid at arc length `t` along the ray,
/// with a unit normal tangent at it.
fn assert_hit_on_ray(ray: &Ray, hit: &Hit) {
    assert!(hit.t.is_finite());
    let x = hit.point;
    let scale = x.length();
    assert!(
        (lorentz::dot(x, x) + 1.0).abs() < 1e-12 * scale * scale,
        "off the hyperboloid"
    );
    assert!((lorentz::distance(ray.origin, x) - hit.t).abs() < 1e-9 * (1.0 + hit.t));
    // Lorentz products of vectors with large components round at the scale
    // of their Euclidean lengths (far hits have components ~e^t).
    let n = hit.normal;
    assert!(
        (lorentz::dot(n, n) - 1.0).abs() < 1e-12 * n.length_squared().max(1.0),
        "normal not unit"
    );
    assert!(
        lorentz::dot(n, x).abs() < 1e-12 * scale * n.length(),
        "normal not tangent"
    );
}

proptest! {
    #![proptest_config(config())]

    /// Hits on an h-cylinder are at distance r from its axis, and the normal
    /// points straight away from the axis (it is the tangent of the
    /// perpendicular from the axis, so moving along it increases the distance
    /// at unit rate).
    #[test]
    fn cylinder_hits_lie_on_the_surface(
        a in point(3.0), b in point(3.0), r in 0.01f64..1.0, eye in point(3.0), dir in unit()
    ) {
        prop_assume!(a.distance(b) > 1e-3);
        let line = HLine::through(&a.into(), &b.into()).unwrap();
        let cyl = HCylinder::new(line, r).unwrap();
        let ray = Ray::from_ball_unchecked(&eye, dir);
        if let Some(hit) = cyl.intersect(&ray, 1e-9, f64::INFINITY) {
            assert_hit_on_ray(&ray, &hit);
            let p = hit.ball_point().unwrap();
            prop_assert!((line.distance_to(&p) - r).abs() < 1e-9, "{} vs {r}", line.distance_to(&p));
            let out = Point::from_hyperboloid(lorentz::geodesic_point(hit.point, hit.normal, 1e-4)).unwrap();
            prop_assert!((line.distance_to(&out) - r - 1e-4).abs() < 1e-8);
        }
    }

    /// A ray from a point of the axis reaches the cylinder after
    /// `asinh(sinh r / sin theta)`, theta the angle to the axis.
    #[test]
    fn cylinder_from_the_axis_obeys_trigonometry(
        a in point(4.0), b in point(4.0), r in 0.01f64..2.0, along in -1.0f64..1.0, theta in 0.05f64..3.09, spin in 0.0f64..std::f64::consts::TAU
    ) {
        prop_assume!(a.distance(b) > 1e-2);
        let line = HLine::through(&a.into(), &b.into()).unwrap();
        let cyl = HCylinder::new(line, r).unwrap();
        let start = line.point_at(along).unwrap();
        // The direction at angle theta to the axis, in the canonical frame.
        let local = DVec3::new(theta.sin() * spin.cos(), theta.sin() * spin.sin(), theta.cos());
        let canonical_start = line.to_line().inverse().apply(&start);
        let dir = line.to_line().apply_direction(&canonical_start, local);
        let ray = Ray::from_ball_unchecked(&start, dir);
        let hit = cyl.intersect(&ray, 1e-9, f64::INFINITY).unwrap();
        let want = (r.sinh() / theta.sin()).asinh();
        prop_assert!((hit.t - want).abs() < 1e-9 * (1.0 + want), "{} vs {want}", hit.t);
    }

    /// Rod hits are within r of the segment (at exactly r), from outside and inside.
    #[test]
    fn rod_hits_are_at_distance_r_from_the_segment(
        a in point(3.0), b in point(3.0), r in 0.01f64..0.5, eye in point(3.0), dir in unit()
    ) {
        prop_assume!(a.distance(b) > 1e-3);
        let rod = Rod::new(a.into(), b.into(), r).unwrap();
        let ray = Ray::from_ball_unchecked(&eye, dir);
        if let Some(hit) = rod.intersect(&ray, 1e-9, f64::INFINITY) {
            assert_hit_on_ray(&ray, &hit);
            let p = hit.ball_point().unwrap();
            let d = segment_distance(&a, &b, &p);
            prop_assert!((d - r).abs() < 1e-9, "{d} vs {r}");
            // Just outside along the normal is outside the rod.
            let out = lorentz::geodesic_point(hit.point, hit.normal, 1e-6);
            prop_assert!(!rod.contains_hyperboloid(out));
        }
    }

    /// Horosphere hits satisfy the horosphere's equation, and every point of it
    /// is reached by the horosphere through it.
    #[test]
    fn horosphere_hits_lie_on_the_surface(
        xi in unit(), q in point(4.0), eye in point(3.0), dir in unit()
    ) {
        let centre = IdealPoint::from_direction(xi).unwrap();
        let h = Horosphere::new(centre, &q).unwrap();
        let ray = Ray::from_ball_unchecked(&eye, dir);
        if let Some(hit) = h.intersect(&ray, 1e-9, f64::INFINITY) {
            assert_hit_on_ray(&ray, &hit);
            let p = hit.ball_point().unwrap();
            let through_hit = Horosphere::new(centre, &p).unwrap();
            let (c1, r1) = h.euclidean();
            let (c2, r2) = through_hit.euclidean();
            prop_assert!((c1 - c2).length() < 1e-9 && (r1 - r2).abs() < 1e-9);
        }
    }

    /// Isometries carry cylinders, rods and horospheres to the same surfaces
    /// through the image points: intersecting the moved ray with the moved
    /// surface gives the same arc length.
    #[test]
    fn isometries_preserve_hits(
        a in point(2.0), b in point(2.0), r in 0.05f64..0.5, eye in point(1.0), dir in unit(),
        shift in point(3.0), axis in unit(), angle in -3.0f64..3.0
    ) {
        prop_assume!(a.distance(b) > 1e-2);
        let iso = Isometry::transvection_from_origin(shift)
            .compose(&Isometry::orthogonal_unchecked(glam::DMat3::from_axis_angle(axis, angle)));
        let ray = Ray::from_ball_unchecked(&eye, dir);
        let moved_ray = Ray::from_ball_unchecked(&iso.apply(&eye), iso.apply_direction(&eye, dir));
        let cyl = HCylinder::new(HLine::through(&a.into(), &b.into()).unwrap(), r).unwrap();
        let rod = Rod::new(a.into(), b.into(), r).unwrap();
        let pairs = [
            (cyl.intersect(&ray, 1e-9, 1e3), cyl.transformed(&iso).intersect(&moved_ray, 1e-9, 1e3)),
            (rod.intersect(&ray, 1e-9, 1e3), rod.transformed(&iso).intersect(&moved_ray, 1e-9, 1e3)),
        ];
        for (h1, h2) in pairs {
            match (h1, h2) {
                (Some(x), Some(y)) => prop_assert!((x.t - y.t).abs() < 1e-8 * (1.0 + x.t)),
                (None, None) => {}
                // Only a grazing ray may flip between hit and miss under rounding.
                (Some(x), None) => prop_assert!(grazing(&ray, &x)),
                (None, Some(y)) => prop_assert!(grazing(&moved_ray, &y)),
            }
        }
    }
}

/// True if the ray meets the surface so nearly tangentially that rounding
/// can decide between a hit and a miss.
fn grazing(ray: &Ray, hit: &Hit) -> bool {
    lorentz::dot(ray.tangent_at(hit.t), hit.normal).abs() < 1e-4
}

/// Hyperbolic distance from `p` to the segment `a b`.
fn segment_distance(a: &Point, b: &Point, p: &Point) -> f64 {
    let line = HLine::through(&(*a).into(), &(*b).into()).unwrap();
    let s = line.foot_parameter(p);
    let len = (*a).distance(*b);
    if s < 0.0 {
        (*a).distance(*p)
    } else if s > len {
        (*b).distance(*p)
    } else {
        line.distance_to(p)
    }
}

/// A ray tangent to a cylinder touches it once, a hair outside misses and a
/// hair inside meets it twice; no answer is NaN.
#[test]
fn tangent_and_grazing_rays_to_a_cylinder() {
    let line = HLine::from_point_direction(&Point::ORIGIN, DVec3::Z).unwrap();
    let r = 0.4;
    let cyl = HCylinder::new(line, r).unwrap();
    for offset in [0.0, 1e-12, -1e-12, 1e-6, -1e-6] {
        // The point at distance r + offset from the axis on the x axis, and
        // the geodesic through it along +y, started one unit back.
        let p = Point::at_distance_from_origin(DVec3::X, r + offset).unwrap();
        let back = Ray::from_ball_unchecked(&p, -DVec3::Y);
        let start = Point::from_hyperboloid(back.at(1.0)).unwrap();
        let ray = Ray {
            origin: start.to_hyperboloid(),
            dir: -back.tangent_at(1.0),
        };
        let roots = cyl.roots(&ray);
        if let Some((n, f)) = roots {
            assert!(!n.is_nan() && !f.is_nan());
        }
        let hit = cyl.intersect(&ray, 1e-9, f64::INFINITY);
        if offset > 1e-9 {
            assert!(hit.is_none(), "offset {offset}: {hit:?}");
        }
        if offset < -1e-9 {
            let h = hit.expect("a ray through the tube hits it");
            assert!((h.t - 1.0).abs() < 1e-2);
        }
        if let Some(h) = hit {
            assert!(h.t.is_finite() && h.normal.is_finite());
        }
    }
}

/// Rays along the axis, parallel to it through the ideal ends, and starting
/// on the surface: all defined.
#[test]
fn degenerate_rays_to_a_cylinder_are_defined() {
    let e1 = IdealPoint::from_direction(DVec3::new(1.0, 0.0, 1.0)).unwrap();
    let e2 = IdealPoint::from_direction(DVec3::new(-1.0, 0.0, 1.0)).unwrap();
    let line = HLine::through(&e1.into(), &e2.into()).unwrap();
    let cyl = HCylinder::new(line, 0.3).unwrap();
    let base = line.base();
    let along = Ray::from_ball_unchecked(
        &base,
        line.to_line().apply_direction(&Point::ORIGIN, DVec3::Z),
    );
    assert!(cyl.intersect(&along, 1e-9, f64::INFINITY).is_none());
    // Towards one ideal end of the axis from off the axis: the coefficient of
    // e^{4t} vanishes; the answer is still finite or a miss.
    let off = Point::from_coords(DVec3::new(0.0, 0.5, 0.3)).unwrap();
    let towards_end = Ray::from_ball_unchecked(&off, e1.coords() - off.coords());
    if let Some(h) = cyl.intersect(&towards_end, 1e-9, f64::INFINITY) {
        assert!(h.t.is_finite());
    }
}

/// The rod's seam (where the tube meets a cap) is watertight: rays aimed at
/// the seam circle hit something.
#[test]
fn rod_seam_is_watertight() {
    let a = Point::from_coords(DVec3::new(-0.3, 0.0, 0.0)).unwrap();
    let b = Point::from_coords(DVec3::new(0.3, 0.0, 0.0)).unwrap();
    let r = 0.1;
    let rod = Rod::new(a.into(), b.into(), r).unwrap();
    let seam_plane = HPlane::orthogonal_at(&b, &a).unwrap();
    let eye = Point::from_coords(DVec3::new(0.0, 0.0, -0.8)).unwrap();
    let mut misses = 0;
    for k in 0..360 {
        let phi = f64::from(k).to_radians();
        // The seam point: distance r from b, on the plane orthogonal at b.
        let p = Point::at_distance_from_origin(DVec3::new(0.0, phi.cos(), phi.sin()), r).unwrap();
        let seam = Isometry::transvection_from_origin(b).apply(&p);
        assert!(seam_plane.signed_distance(&seam).abs() < 1e-12);
        let dir = hgeom::Segment::new(eye, seam).unwrap().direction_at_start();
        let ray = Ray::from_ball_unchecked(&eye, dir);
        match rod.intersect(&ray, 1e-9, f64::INFINITY) {
            Some(h) => assert!(
                h.t <= eye.distance(seam) + 1e-9,
                "phi {k}: hit at {} beyond the seam at {}",
                h.t,
                eye.distance(seam)
            ),
            None => misses += 1,
        }
    }
    // Rays aimed exactly at the silhouette part of the seam graze; the rest hit.
    assert!(misses < 20, "{misses} of 360 rays through the seam missed");
}

/// The ends of a rod between ideal points are the absolute: it behaves as a
/// whole cylinder.
#[test]
fn rod_between_ideal_points_is_a_cylinder() {
    let e1 = IdealPoint::from_direction(DVec3::X).unwrap();
    let e2 = IdealPoint::from_direction(-DVec3::X).unwrap();
    let rod = Rod::new(e1.into(), e2.into(), 0.2).unwrap();
    let cyl = HCylinder::new(
        HLine::through(&Vertex::from(e1), &Vertex::from(e2)).unwrap(),
        0.2,
    )
    .unwrap();
    for x in [-0.99, -0.5, 0.0, 0.7, 0.999] {
        let eye = Point::from_coords(DVec3::new(x, 0.0, -0.9 * (1.0 - x * x).sqrt())).unwrap();
        let ray = Ray::from_ball_unchecked(&eye, DVec3::Z);
        let (h1, h2) = (
            rod.intersect(&ray, 1e-9, f64::INFINITY),
            cyl.intersect(&ray, 1e-9, f64::INFINITY),
        );
        assert_eq!(h1.map(|h| h.t), h2.map(|h| h.t));
    }
}
