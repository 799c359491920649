//! `serde` support for the value types (the `serde` feature).
//!
//! Every value round-trips exactly: the stored f64s are written as they
//! are, and reading them back validates the same invariants the checked
//! constructors do, so a hand-edited or hostile document can never produce
//! a point outside the ball or an isometry that is not one. The formats:
//!
//! | type | form |
//! |---|---|
//! | [`Point`] | `{"coords": [x, y, z], "gap": g}`; `gap` (`1 - \|x\|^2`) may be left out, and is then computed |
//! | [`IdealPoint`] | `[x, y, z]`, a unit vector to 1e-15 |
//! | [`Vertex`] | `{"interior": Point}` or `{"ideal": IdealPoint}` |
//! | [`Isometry`] | `{"translation": Point, "linear": [[c0], [c1], [c2]]}` (columns of `Q`) |
//! | [`Segment`] | `{"start": Point, "end": Point}` |
//! | [`HPlane`] | `{"normal": [x, y, z, t], "place": Isometry, "local": [x, y, z, t]}`: the unit spacelike normal (to `1e-12 \|n\|^2`) and, optionally, the placement that carries the unit normal `local` onto it |
//! | [`HSphere`] | `{"center": Point, "radius": r}` |
//!
//! A stored gap is kept (far from the origin it is more precise than the
//! coordinates can express) when it agrees with the coordinates to their
//! own rounding: `|gap - (1 - |x|^2)| <= 8 eps`. Exact round trips need a
//! correctly rounding float parser (serde_json's `float_roundtrip` feature).

use glam::{DMat3, DVec3, DVec4};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::accurate::one_minus_norm_sq;
use crate::isometry::Isometry;
use crate::plane::HPlane;
use crate::point::{IdealPoint, Point, Vertex};
use crate::segment::Segment;
use crate::sphere::HSphere;

/// How far a stored gap may sit from the one the rounded coordinates give.
const GAP_SLACK: f64 = 8.0 * f64::EPSILON;

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PointForm {
    coords: [f64; 3],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    gap: Option<f64>,
}

impl Serialize for Point {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        PointForm {
            coords: self.coords().to_array(),
            gap: Some(self.gap()),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for Point {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Point, D::Error> {
        let form = PointForm::deserialize(d)?;
        let checked =
            Point::from_coords(DVec3::from_array(form.coords)).map_err(D::Error::custom)?;
        match form.gap {
            None => Ok(checked),
            Some(gap) => {
                let computed = one_minus_norm_sq(checked.coords());
                if gap > 0.0 && (gap - computed).abs() <= GAP_SLACK {
                    Ok(Point::new_unchecked(checked.coords(), gap))
                } else {
                    Err(D::Error::custom(format!(
                        "gap {gap:e} disagrees with the coordinates (1 - |x|^2 = {computed:e})"
                    )))
                }
            }
        }
    }
}

impl Serialize for IdealPoint {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.coords().to_array().serialize(s)
    }
}

impl<'de> Deserialize<'de> for IdealPoint {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<IdealPoint, D::Error> {
        let v = DVec3::from_array(<[f64; 3]>::deserialize(d)?);
        // Checked as `IdealPoint::new` does, but stored unnormalised so that
        // the round trip is exact.
        IdealPoint::new(v, 1e-15).map_err(D::Error::custom)?;
        Ok(IdealPoint::from_unit_unchecked(v))
    }
}

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
enum VertexForm {
    Interior(Point),
    Ideal(IdealPoint),
}

impl Serialize for Vertex {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match *self {
            Vertex::Interior(p) => VertexForm::Interior(p),
            Vertex::Ideal(e) => VertexForm::Ideal(e),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for Vertex {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Vertex, D::Error> {
        Ok(match VertexForm::deserialize(d)? {
            VertexForm::Interior(p) => Vertex::Interior(p),
            VertexForm::Ideal(e) => Vertex::Ideal(e),
        })
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct IsometryForm {
    translation: Point,
    linear: [[f64; 3]; 3],
}

impl Serialize for Isometry {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        IsometryForm {
            translation: self.translation_part(),
            linear: self.linear_part().to_cols_array_2d(),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for Isometry {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Isometry, D::Error> {
        let form = IsometryForm::deserialize(d)?;
        Isometry::from_parts(form.translation, DMat3::from_cols_array_2d(&form.linear))
            .map_err(D::Error::custom)
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct SegmentForm {
    start: Point,
    end: Point,
}

impl Serialize for Segment {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        SegmentForm {
            start: self.start(),
            end: self.end(),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for Segment {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Segment, D::Error> {
        let form = SegmentForm::deserialize(d)?;
        Segment::new(form.start, form.end).map_err(D::Error::custom)
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PlaneForm {
    normal: [f64; 4],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    place: Option<Isometry>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    local: Option<[f64; 4]>,
}

impl Serialize for HPlane {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let (place, local) = self.parts();
        PlaneForm {
            normal: self.normal().to_array(),
            place: Some(place),
            local: Some(local.to_array()),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for HPlane {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<HPlane, D::Error> {
        let form = PlaneForm::deserialize(d)?;
        let n = DVec4::from_array(form.normal);
        HPlane::from_normal(n).map_err(D::Error::custom)?;
        // Unit to the rounding of its own components: a plane far from the
        // origin has a normal of size ~e^d whose Lorentz square is 1 only to
        // about eps |n|^2.
        let unit = |v: DVec4| {
            (crate::lorentz::dot(v, v) - 1.0).abs() <= 1e-12 * v.length_squared().max(1.0)
        };
        if !unit(n) {
            return Err(D::Error::custom(format!(
                "plane normal must be a unit spacelike vector (<n,n> = {:e})",
                crate::lorentz::dot(n, n)
            )));
        }
        let (place, local) = match (form.place, form.local) {
            (None, None) => (Isometry::IDENTITY, n),
            (Some(place), Some(local)) => (place, DVec4::from_array(local)),
            _ => {
                return Err(D::Error::custom(
                    "a plane's `place` and `local` come together",
                ));
            }
        };
        // The placement must carry the local normal onto the normal, to the
        // rounding of the normal's own size.
        let carried = place.to_lorentz() * local;
        if !(unit(local) && (carried - n).length() <= 1e-9 * n.length().max(1.0)) {
            return Err(D::Error::custom(
                "the plane's `place` does not carry `local` onto `normal`",
            ));
        }
        Ok(HPlane::from_parts_unchecked(n, place, local))
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct SphereForm {
    center: Point,
    radius: f64,
}

impl Serialize for HSphere {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        SphereForm {
            center: self.center(),
            radius: self.radius(),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for HSphere {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<HSphere, D::Error> {
        let form = SphereForm::deserialize(d)?;
        HSphere::new(form.center, form.radius).map_err(D::Error::custom)
    }
}
