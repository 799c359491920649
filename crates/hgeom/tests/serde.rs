//! The `serde` feature: every value type round-trips exactly, and input that
//! breaks an invariant is refused. The test support crate turns the feature on,
//! so `cargo test -p hgeom` (and the workspace's tests) run these.
#![cfg(feature = "serde")]

use hgeom::glam::{DMat3, DVec3};
use hgeom::{HPlane, HSphere, IdealPoint, Isometry, Point, Segment, Vertex};
use serde::{Serialize, de::DeserializeOwned};

fn round_trip<T: Serialize + DeserializeOwned + PartialEq + std::fmt::Debug>(value: &T) {
    let text = serde_json::to_string(value).unwrap();
    let back: T = serde_json::from_str(&text).unwrap();
    assert_eq!(&back, value, "{text}");
}

fn points() -> Vec<Point> {
    vec![
        Point::ORIGIN,
        Point::new(0.1, -0.2, 0.3).unwrap(),
        Point::new(1.0 - 1e-15, 0.0, 0.0).unwrap(),
        // Far out, where the gap holds more precision than the coordinates.
        Isometry::transvection_from_origin(Point::new(0.0, 0.0, 0.9).unwrap())
            .compose(&Isometry::transvection_from_origin(
                Point::new(0.0, 0.0, 0.999_999).unwrap(),
            ))
            .translation_part(),
    ]
}

#[test]
fn every_value_type_round_trips_exactly() {
    for p in points() {
        round_trip(&p);
        round_trip(&Vertex::Interior(p));
        round_trip(&HSphere::new(p, 0.7).unwrap());
        round_trip(
            &Isometry::transvection_from_origin(p)
                .compose(&Isometry::orthogonal_unchecked(DMat3::from_rotation_y(0.3))),
        );
        if p != Point::ORIGIN {
            round_trip(&Segment::new(Point::ORIGIN, p).unwrap());
            round_trip(&HPlane::bisector(&Point::ORIGIN, &p).unwrap());
        }
    }
    let e = IdealPoint::from_direction(DVec3::new(1.0, 2.0, -2.0)).unwrap();
    round_trip(&e);
    round_trip(&Vertex::Ideal(e));
    round_trip(&Isometry::IDENTITY);
}

#[test]
fn the_format_is_readable_and_the_gap_optional() {
    let p: Point = serde_json::from_str(r#"{"coords": [0.5, 0.0, 0.0]}"#).unwrap();
    assert_eq!(p, Point::new(0.5, 0.0, 0.0).unwrap());
    let text = serde_json::to_string(&p).unwrap();
    assert_eq!(text, r#"{"coords":[0.5,0.0,0.0],"gap":0.75}"#);
    let v: Vertex = serde_json::from_str(r#"{"ideal": [0.0, 0.0, 1.0]}"#).unwrap();
    assert!(v.is_ideal());
}

#[test]
fn input_that_breaks_an_invariant_is_refused() {
    let bad = [
        // Points: outside the ball, on it, a gap that contradicts the coordinates.
        (r#"{"coords": [1.0, 0.0, 0.0]}"#, "point"),
        (r#"{"coords": [0.6, 0.8, 0.1]}"#, "point"),
        (r#"{"coords": [0.5, 0.0, 0.0], "gap": 0.5}"#, "point"),
        (r#"{"coords": [0.5, 0.0, 0.0], "gap": -0.75}"#, "point"),
        (r#"{"coords": [0.5, 0.0, 0.0], "extra": 1}"#, "point"),
        (r#"{"coords": [0.5, 0.0]}"#, "point"),
    ];
    for (text, what) in bad {
        assert!(
            serde_json::from_str::<Point>(text).is_err(),
            "{what}: {text}"
        );
    }
    assert!(serde_json::from_str::<IdealPoint>("[0.5, 0.0, 0.0]").is_err());
    assert!(serde_json::from_str::<IdealPoint>("[0.0, 0.0, 0.0]").is_err());
    let not_orthogonal =
        r#"{"translation": {"coords": [0,0,0]}, "linear": [[2,0,0],[0,1,0],[0,0,1]]}"#;
    assert!(serde_json::from_str::<Isometry>(not_orthogonal).is_err());
    assert!(serde_json::from_str::<HPlane>(r#"{"normal": [0, 0, 0, 1]}"#).is_err());
    assert!(serde_json::from_str::<HPlane>(r#"{"normal": [0, 0, 2, 0]}"#).is_err());
    assert!(
        serde_json::from_str::<HSphere>(r#"{"center": {"coords": [0,0,0]}, "radius": -1}"#)
            .is_err()
    );
    let same = r#"{"start": {"coords": [0.1,0,0]}, "end": {"coords": [0.1,0,0]}}"#;
    assert!(serde_json::from_str::<Segment>(same).is_err());
}
