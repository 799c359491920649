//! The checked constructors (`try_*`) and their `_unchecked` hot-path forms
//! agree on valid input, and the checked ones reject invalid input with a
//! typed error.

use std::f64::consts::PI;

use glam::{DMat3, DVec3};
use hgeom::accurate::one_minus_norm_sq;
use hgeom::{GeomError, HCylinder, HLine, HSphere, IdealPoint, Isometry, Point, Ray, Segment};

/// Points spread over the ball, from the origin to the edge of f64.
fn sample_points() -> Vec<Point> {
    let mut out = vec![Point::ORIGIN];
    for (i, d) in [1e-9, 0.3, 1.0, 4.0, 10.0, 20.0, 30.0, 37.0]
        .into_iter()
        .enumerate()
    {
        let a = 0.7 * i as f64;
        let dir = DVec3::new(a.cos(), a.sin(), 0.3 * (i as f64 - 3.0));
        out.push(Point::at_distance_from_origin(dir, d).unwrap());
    }
    out
}

#[test]
fn point_new_unchecked_agrees_with_new() {
    for p in sample_points() {
        let c = p.coords();
        let checked = Point::from_coords(c).unwrap();
        let unchecked = Point::new_unchecked(c, one_minus_norm_sq(c));
        assert_eq!(checked, unchecked);
        // A gap from an exact identity (here 1/cosh^2(d/2)) is more precise
        // than the rounded coordinates: it differs from the gap recomputed
        // from them by the coordinates' own rounding, a few eps absolute.
        let from_identity = Point::new_unchecked(c, p.gap());
        assert!(
            (from_identity.gap() - checked.gap()).abs() <= 8.0 * f64::EPSILON,
            "{:e} vs {:e}",
            from_identity.gap(),
            checked.gap()
        );
        let d = p.distance_from_origin();
        assert!((from_identity.distance(Point::ORIGIN) - d).abs() <= 1e-14 * d);
    }
}

#[test]
fn checked_point_constructors_reject_what_breaks_the_invariants() {
    assert_eq!(
        Point::from_coords(DVec3::new(f64::NAN, 0.0, 0.0)),
        Err(GeomError::NotFinite)
    );
    assert!(matches!(
        Point::from_coords(DVec3::X),
        Err(GeomError::NotInBall { .. })
    ));
    // Beyond distance ~37.4 tanh(d/2) rounds to 1: rejected, not returned
    // with coordinates on the absolute.
    for d in [38.5, 40.0, 100.0, 1e4] {
        assert!(
            matches!(
                Point::at_distance_from_origin(DVec3::X, d),
                Err(GeomError::NotInBall { .. })
            ),
            "{d}"
        );
    }
    let far = Point::at_distance_from_origin(DVec3::X, 37.0).unwrap();
    assert!(far.is_representable());
    assert!(Point::at_distance_from_origin(DVec3::ZERO, 1.0).is_err());
    assert!(Point::at_distance_from_origin(DVec3::X, f64::NAN).is_err());
    assert!(Point::at_distance_from_origin(DVec3::X, -1.0).is_err());
}

#[test]
fn ideal_point_unchecked_agrees_with_checked() {
    for dir in [
        DVec3::X,
        DVec3::new(0.6, 0.8, 0.0),
        DVec3::new(1.0, -2.0, 2.0) / 3.0,
    ] {
        let a = IdealPoint::from_unit_unchecked(dir);
        let b = IdealPoint::from_direction(dir).unwrap();
        let c = IdealPoint::new(dir, 1e-12).unwrap();
        assert!((a.coords() - b.coords()).length() <= 2.0 * f64::EPSILON);
        assert!((a.coords() - c.coords()).length() <= 2.0 * f64::EPSILON);
    }
    assert!(IdealPoint::from_direction(DVec3::ZERO).is_err());
    assert!(IdealPoint::new(DVec3::new(0.5, 0.0, 0.0), 1e-9).is_err());
    // A generous tolerance still cannot admit the zero vector, and a NaN
    // tolerance admits nothing.
    assert!(IdealPoint::new(DVec3::ZERO, 2.0).is_err());
    assert!(IdealPoint::new(DVec3::X, f64::NAN).is_err());
}

#[test]
fn sphere_new_unchecked_agrees_with_new() {
    for c in sample_points() {
        for r in [1e-6, 0.1, 2.0, 20.0, 700.0] {
            let checked = HSphere::new(c, r).unwrap();
            let unchecked = HSphere::new_unchecked(c, r);
            assert_eq!(checked, unchecked);
            let ray = Ray::from_origin_unchecked(DVec3::new(0.3, 0.1, 1.0));
            assert_eq!(checked.roots(&ray), unchecked.roots(&ray));
        }
    }
    for r in [0.0, -1.0, f64::NAN, f64::INFINITY, 711.0] {
        assert!(matches!(
            HSphere::new(Point::ORIGIN, r),
            Err(GeomError::BadRadius(_))
        ));
    }
}

#[test]
fn cylinder_new_unchecked_agrees_with_new() {
    let points = sample_points();
    for pair in points.windows(2) {
        let line = HLine::through(&pair[0].into(), &pair[1].into()).unwrap();
        for r in [1e-6, 0.1, 2.0, 300.0] {
            let checked = HCylinder::new(line, r).unwrap();
            let unchecked = HCylinder::new_unchecked(line, r);
            assert_eq!(checked, unchecked);
        }
        for r in [0.0, -0.5, f64::NAN, 400.0] {
            assert!(matches!(
                HCylinder::new(line, r),
                Err(GeomError::BadRadius(_))
            ));
        }
    }
}

#[test]
fn ray_constructors_agree_and_reject_bad_directions() {
    let dir = DVec3::new(0.3, -0.4, 1.2);
    assert_eq!(
        Ray::from_origin(dir).unwrap(),
        Ray::from_origin_unchecked(dir)
    );
    for p in sample_points() {
        assert_eq!(
            Ray::from_ball(&p, dir).unwrap(),
            Ray::from_ball_unchecked(&p, dir)
        );
    }
    for bad in [DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 1.0), DVec3::INFINITY] {
        assert_eq!(Ray::from_origin(bad), Err(GeomError::BadDirection));
        assert_eq!(
            Ray::from_ball(&Point::ORIGIN, bad),
            Err(GeomError::BadDirection)
        );
    }
    // A point whose gap underflowed (pushed past what f64 holds) is rejected.
    let far = Point::at_distance_from_origin(DVec3::X, 30.0).unwrap();
    let beyond = Isometry::transvection_from_origin(far).apply(&far);
    assert!(!beyond.is_representable());
    assert!(matches!(
        Ray::from_ball(&beyond, DVec3::Y),
        Err(GeomError::NotInBall { .. })
    ));
}

#[test]
fn isometry_checked_forms_agree_with_unchecked() {
    let q = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 0.9);
    assert_eq!(
        Isometry::orthogonal(q).unwrap(),
        Isometry::orthogonal_unchecked(q)
    );
    let mirror = DMat3::from_diagonal(DVec3::new(1.0, -1.0, 1.0));
    assert_eq!(
        Isometry::orthogonal(mirror).unwrap(),
        Isometry::orthogonal_unchecked(mirror)
    );
    assert!(matches!(
        Isometry::orthogonal(DMat3::from_diagonal(DVec3::new(1.0, 2.0, 1.0))),
        Err(GeomError::NotOrthogonal { .. })
    ));
    assert_eq!(
        Isometry::orthogonal(DMat3::from_diagonal(DVec3::new(f64::NAN, 1.0, 1.0))),
        Err(GeomError::NotFinite)
    );
    let axis = Segment::new(
        Point::from_coords(DVec3::new(0.1, 0.2, 0.0)).unwrap(),
        Point::from_coords(DVec3::new(-0.3, 0.1, 0.4)).unwrap(),
    )
    .unwrap();
    for angle in [0.0, 1e-9, 0.7, PI, -2.0] {
        assert_eq!(
            Isometry::rotation_about_segment(&axis, angle).unwrap(),
            Isometry::rotation_about_segment_unchecked(&axis, angle)
        );
    }
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(
            Isometry::rotation_about_segment(&axis, bad),
            Err(GeomError::BadAngle(_))
        ));
    }
}
