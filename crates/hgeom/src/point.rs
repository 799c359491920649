//! h-points (inside the ball) and ideal points (on the absolute).

use glam::{DVec3, DVec4};

use crate::accurate::one_minus_norm_sq;
use crate::error::GeomError;
use crate::lorentz;

/// A point of hyperbolic 3-space in the Poincaré ball.
///
/// Invariants: the coordinates are finite, `|x| < 1`, and the cached `gap`
/// is `1 - |x|^2 > 0` of the represented point, correct to a few ulps *of the
/// gap itself* (computed with compensated arithmetic, or propagated exactly
/// through isometries). Far out (distance above ~18) the gap is more precise
/// than the rounded coordinates can express: it is the point's extra
/// precision, like the low word of a double-double, and distances are
/// computed from it, never from a naive `1 - |x|^2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point {
    coords: DVec3,
    gap: f64,
}

impl Point {
    /// The centre of the ball.
    pub const ORIGIN: Point = Point {
        coords: DVec3::ZERO,
        gap: 1.0,
    };

    /// A point from ball coordinates, checked to lie strictly inside the ball.
    ///
    /// ```
    /// use hgeom::Point;
    /// use glam::DVec3;
    /// assert!(Point::try_new(DVec3::new(0.5, 0.0, 0.0)).is_ok());
    /// assert!(Point::try_new(DVec3::new(1.0, 0.0, 0.0)).is_err());
    /// ```
    pub fn try_new(coords: DVec3) -> Result<Point, GeomError> {
        if !coords.is_finite() {
            return Err(GeomError::NotFinite);
        }
        let gap = one_minus_norm_sq(coords);
        if gap > 0.0 {
            Ok(Point { coords, gap })
        } else {
            Err(GeomError::NotInBall {
                norm: coords.length(),
            })
        }
    }

    /// Build from coordinates and a gap the caller has computed accurately
    /// (for example by an exact identity). The caller guarantees the invariants.
    ///
    /// Hot paths use this unchecked; a result whose gap underflowed to 0
    /// (a point pushed past distance ~37, beyond what f64 can hold) is then
    /// caught by [`Point::is_representable`] where it matters.
    #[inline]
    pub(crate) fn from_parts(coords: DVec3, gap: f64) -> Point {
        Point { coords, gap }
    }

    /// True if the coordinates are finite and the gap is positive: the point
    /// is strictly inside the ball as f64 can represent it.
    #[inline]
    pub fn is_representable(&self) -> bool {
        // The gap can stay positive past the point where the coordinates
        // themselves round onto the absolute (distance ~37); such a point no
        // longer has usable ball coordinates.
        // Ball coordinates reach distance ~37.4 at most (1 - |x| = 2^-53, gap
        // ~2^-52); a smaller gap belongs to a point f64 cannot place.
        self.coords.is_finite()
            && self.gap >= 0.5 * f64::EPSILON
            && one_minus_norm_sq(self.coords) > 0.0
    }

    /// Ball coordinates.
    #[inline]
    pub fn coords(&self) -> DVec3 {
        self.coords
    }

    /// `1 - |x|^2`, accurate to a few ulps of itself.
    #[inline]
    pub fn gap(&self) -> f64 {
        self.gap
    }

    /// Hyperbolic distance from the origin: `2 artanh |x|`, evaluated as
    /// `ln((1+|x|)^2 / (1-|x|^2))` through the accurate gap.
    pub fn distance_from_origin(&self) -> f64 {
        let r = self.coords.length();
        // 2 artanh r = ln((1 + r) / (1 - r)) = ln((1 + r)^2 / gap)
        if r < 0.5 {
            2.0 * r.atanh()
        } else {
            ((1.0 + r) * (1.0 + r) / self.gap).ln()
        }
    }

    /// The point on the ray from the origin in direction `dir` at hyperbolic
    /// distance `d >= 0`: Euclidean radius `tanh(d/2)`, with the gap computed
    /// as `1/cosh^2(d/2)` so it stays exact far beyond where `1 - tanh^2` fails.
    pub fn at_distance_from_origin(dir: DVec3, d: f64) -> Result<Point, GeomError> {
        let len = dir.length();
        if !(len.is_finite() && len > 0.0) {
            return Err(GeomError::BadDirection);
        }
        if !(d.is_finite() && d >= 0.0) {
            return Err(GeomError::NotFinite);
        }
        let half = 0.5 * d;
        let gap = 1.0 / (half.cosh() * half.cosh());
        if gap <= 0.0 {
            return Err(GeomError::NotInBall { norm: 1.0 });
        }
        Ok(Point {
            coords: dir / len * half.tanh(),
            gap,
        })
    }

    /// The point on the hyperboloid `-x0^2 + |x|^2 = -1`, as a `DVec4` with the
    /// time coordinate in `w`: `((1+|p|^2), 2p) / (1-|p|^2)`.
    #[inline]
    pub fn to_hyperboloid(&self) -> DVec4 {
        let inv = 1.0 / self.gap;
        (2.0 * self.coords * inv).extend((2.0 - self.gap) * inv)
    }

    /// Back from the hyperboloid: `p = x / (1 + x0)`. The gap is `2/(1+x0)`,
    /// exact in terms of `x0`.
    ///
    /// Returns `None` if the vector is not finite or not future-timelike.
    pub fn from_hyperboloid(x: DVec4) -> Option<Point> {
        if !x.is_finite() || x.w < 1.0 - 1e-12 {
            return None;
        }
        let x0 = x.w.max(1.0);
        let denom = 1.0 + x0;
        let coords = x.truncate() / denom;
        // 1 - |p|^2 = 1 - (x0^2 - 1)/(1+x0)^2 = 2/(1+x0), using the hyperboloid
        // identity; fall back to the compensated form if x is off the sheet.
        let on_sheet = (lorentz::dot(x, x) + 1.0).abs() <= 1e-9 * x0 * x0;
        let gap = if on_sheet {
            2.0 / denom
        } else {
            one_minus_norm_sq(coords)
        };
        (gap > 0.0).then_some(Point { coords, gap })
    }
}

/// A point on the absolute (the unit sphere): an ideal point.
///
/// Invariant: `dir` is a unit vector (to rounding).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IdealPoint {
    dir: DVec3,
}

impl IdealPoint {
    /// An ideal point from coordinates that must lie on the unit sphere within
    /// `tolerance` (Euclidean); they are then normalised.
    pub fn try_new(coords: DVec3, tolerance: f64) -> Result<IdealPoint, GeomError> {
        if !coords.is_finite() {
            return Err(GeomError::NotFinite);
        }
        let norm = coords.length();
        if (norm - 1.0).abs() > tolerance {
            return Err(GeomError::NotOnAbsolute { norm });
        }
        Ok(IdealPoint { dir: coords / norm })
    }

    /// An ideal point from a vector the caller guarantees to be a unit vector
    /// (to rounding). For hot paths and constants; nothing is checked.
    #[inline]
    pub const fn from_unit_unchecked(dir: DVec3) -> IdealPoint {
        IdealPoint { dir }
    }

    /// The ideal point at the end of the ray from the origin in direction `dir`.
    pub fn from_direction(dir: DVec3) -> Result<IdealPoint, GeomError> {
        let len = dir.length();
        if !(len.is_finite() && len > 0.0) {
            return Err(GeomError::BadDirection);
        }
        Ok(IdealPoint { dir: dir / len })
    }

    /// Unit vector of the point on the absolute.
    #[inline]
    pub fn coords(&self) -> DVec3 {
        self.dir
    }

    /// A representative of the null ray on the light cone: `(dir, 1)`.
    #[inline]
    pub fn to_hyperboloid(&self) -> DVec4 {
        self.dir.extend(1.0)
    }
}

/// A polygon vertex or geodesic end: an h-point or an ideal point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Vertex {
    /// A point inside the ball.
    Interior(Point),
    /// A point on the absolute.
    Ideal(IdealPoint),
}

impl Vertex {
    /// Ball coordinates.
    pub fn coords(&self) -> DVec3 {
        match self {
            Vertex::Interior(p) => p.coords(),
            Vertex::Ideal(p) => p.coords(),
        }
    }

    /// Hyperboloid vector (timelike for interior points, null for ideal ones).
    pub fn to_hyperboloid(&self) -> DVec4 {
        match self {
            Vertex::Interior(p) => p.to_hyperboloid(),
            Vertex::Ideal(p) => p.to_hyperboloid(),
        }
    }

    /// True for a point on the absolute.
    pub fn is_ideal(&self) -> bool {
        matches!(self, Vertex::Ideal(_))
    }
}

impl From<Point> for Vertex {
    fn from(p: Point) -> Self {
        Vertex::Interior(p)
    }
}

impl From<IdealPoint> for Vertex {
    fn from(p: IdealPoint) -> Self {
        Vertex::Ideal(p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_points_on_and_outside_the_absolute() {
        assert!(matches!(
            Point::try_new(DVec3::new(0.0, 0.0, 1.2)),
            Err(GeomError::NotInBall { .. })
        ));
        assert!(Point::try_new(DVec3::X).is_err());
        assert!(Point::try_new(DVec3::new(f64::NAN, 0.0, 0.0)).is_err());
        assert!(Point::try_new(DVec3::new(1.0 - f64::EPSILON, 0.0, 0.0)).is_ok());
    }

    #[test]
    fn hyperboloid_round_trip() {
        let p = Point::try_new(DVec3::new(0.3, -0.2, 0.5)).unwrap();
        let x = p.to_hyperboloid();
        assert!((lorentz::dot(x, x) + 1.0).abs() < 1e-14);
        let q = Point::from_hyperboloid(x).unwrap();
        assert!((q.coords() - p.coords()).length() < 1e-15);
        assert!((q.gap() - p.gap()).abs() < 1e-15);
    }

    #[test]
    fn distance_from_origin_matches_closed_form() {
        for &r in &[1e-12, 0.1, 0.5, 0.9, 1.0 - 1e-10] {
            let p = Point::try_new(DVec3::new(0.0, r, 0.0)).unwrap();
            let expect = 2.0 * r.atanh();
            let got = p.distance_from_origin();
            assert!(
                (got - expect).abs() <= 1e-13 * expect.max(1e-300),
                "{r}: {got} vs {expect}"
            );
        }
    }

    #[test]
    fn at_distance_from_origin_inverts_distance() {
        for &d in &[1e-9, 0.3, 5.0, 20.0, 35.0] {
            let p = Point::at_distance_from_origin(DVec3::new(1.0, 2.0, 2.0), d).unwrap();
            let back = p.distance_from_origin();
            assert!((back - d).abs() <= 1e-13 * d, "{d}: {back}");
        }
    }

    #[test]
    fn ideal_points_are_normalised_and_null() {
        let p = IdealPoint::try_new(DVec3::new(0.0, 0.6, 0.8), 1e-12).unwrap();
        assert!((lorentz::dot(p.to_hyperboloid(), p.to_hyperboloid())).abs() < 1e-15);
        assert!(IdealPoint::try_new(DVec3::new(0.0, 0.6, 0.7), 1e-9).is_err());
    }
}
