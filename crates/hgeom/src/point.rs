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
///
/// The checked constructors are [`Point::new`], [`Point::from_coords`] and
/// [`Point::at_distance_from_origin`]; [`Point::new_unchecked`] is the hot-path
/// form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point {
    coords: DVec3,
    gap: f64,
}

impl Point {
    /// The centre of the ball (exact: coordinates 0, gap 1).
    pub const ORIGIN: Point = Point {
        coords: DVec3::ZERO,
        gap: 1.0,
    };

    /// The point with ball coordinates `(x, y, z)`, checked to lie strictly
    /// inside the ball: [`Point::from_coords`] of the vector.
    ///
    /// Errors: [`GeomError::NotFinite`], [`GeomError::NotInBall`].
    ///
    /// # Accuracy
    ///
    /// As [`Point::from_coords`]: the coordinates are stored exactly and the
    /// gap is within a few ulps of the exact `1 - |x|^2`.
    ///
    /// ```
    /// use hgeom::Point;
    /// let p = Point::new(0.5, 0.0, 0.0)?;
    /// assert_eq!(p.gap(), 0.75);
    /// assert!(Point::new(1.0, 0.0, 0.0).is_err());
    /// # Ok::<(), hgeom::GeomError>(())
    /// ```
    pub fn new(x: f64, y: f64, z: f64) -> Result<Point, GeomError> {
        Point::from_coords(DVec3::new(x, y, z))
    }

    /// A point from ball coordinates, checked to lie strictly inside the ball.
    ///
    /// Errors: [`GeomError::NotFinite`] for a NaN or infinite coordinate,
    /// [`GeomError::NotInBall`] when `1 - |x|^2 <= 0` (computed exactly
    /// enough that every f64 vector of norm below 1, down to
    /// `1 - |x| = 2^-53`, is accepted).
    ///
    /// # Accuracy
    ///
    /// The coordinates are stored exactly; the gap is
    /// [`accurate::one_minus_norm_sq`](crate::accurate::one_minus_norm_sq),
    /// within a few ulps of the exact `1 - |x|^2` of the given coordinates
    /// (to 1e-15 relative at `1 - |x| = 2^-52 .. 1e-15`: `boundary_gap_1e_15`
    /// in `tests/properties.rs`).
    ///
    /// ```
    /// use hgeom::Point;
    /// use glam::DVec3;
    /// assert!(Point::from_coords(DVec3::new(0.5, 0.0, 0.0)).is_ok());
    /// assert!(Point::from_coords(DVec3::new(1.0, 0.0, 0.0)).is_err());
    /// ```
    pub fn from_coords(coords: DVec3) -> Result<Point, GeomError> {
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

    /// A point from ball coordinates and their gap `1 - |coords|^2`, with
    /// nothing checked: the `_unchecked` form of [`Point::from_coords`] for hot
    /// paths that already hold an accurate gap (Möbius addition, isometries
    /// and the closed-form constructors all produce one from an exact
    /// identity, which is more precise than recomputing it from rounded
    /// coordinates).
    ///
    /// # Preconditions
    ///
    /// `coords` finite with `|coords| < 1`, and `gap > 0` equal to
    /// `1 - |x|^2` of the point meant, to a few ulps of `gap` itself. The gap
    /// may be *more* precise than the rounded coordinates (see the type
    /// docs). Nothing here is unsafe: a violated precondition gives
    /// meaningless geometry, never undefined behaviour, and
    /// [`Point::is_representable`] recognises a gap that underflowed.
    ///
    /// # Accuracy
    ///
    /// Exact: the arguments are stored as given. Given the compensated gap
    /// of `coords` it is identical to [`Point::from_coords`]; a gap from an
    /// exact identity differs from that one by the rounding of the
    /// coordinates themselves (a few eps, absolute), which is the precision
    /// it adds (`tests/constructors.rs`).
    ///
    /// ```
    /// use glam::DVec3;
    /// use hgeom::{accurate::one_minus_norm_sq, Point};
    /// let c = DVec3::new(0.6, 0.0, 0.0);
    /// let p = Point::new_unchecked(c, one_minus_norm_sq(c));
    /// assert_eq!(p, Point::from_coords(c).unwrap());
    /// ```
    #[inline]
    pub const fn new_unchecked(coords: DVec3, gap: f64) -> Point {
        Point { coords, gap }
    }

    /// True if the coordinates are finite and the gap is positive: the point
    /// is strictly inside the ball as f64 can represent it.
    ///
    /// Precisely: finite coordinates, `gap >= 2^-53` (ball points reach
    /// distance ~37.4 at most, where `1 - |x| = 2^-53`), and the coordinates
    /// themselves strictly inside the ball. Every point built by a checked
    /// constructor passes; a point pushed past the edge of f64 by an
    /// isometry ([`Isometry::apply`](crate::Isometry::apply)) fails.
    ///
    /// # Accuracy
    ///
    /// Exact predicate on the stored values.
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
    ///
    /// # Accuracy
    ///
    /// Exact: the stored coordinates (each a rounding of the true point's,
    /// so within half an ulp per component for points built by hgeom).
    #[inline]
    pub fn coords(&self) -> DVec3 {
        self.coords
    }

    /// `1 - |x|^2`, accurate to a few ulps of itself.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored gap, within a few ulps (relative) of the true
    /// point's `1 - |x|^2` for every point built by hgeom (compensated
    /// arithmetic or an exact identity; `gap_of_sum_is_exact_near_the_absolute`
    /// in `mobius.rs`, `boundary_gap_1e_15` in `tests/properties.rs`).
    #[inline]
    pub fn gap(&self) -> f64 {
        self.gap
    }

    /// Hyperbolic distance from the origin: `2 artanh |x|`, evaluated as
    /// `ln((1+|x|)^2 / (1-|x|^2))` through the accurate gap.
    ///
    /// # Accuracy
    ///
    /// Relative error below 1e-14 for every representable point, including
    /// `1 - |x|` down to 2^-52 (`boundary_gap_1e_15` and
    /// `distance_formulas_agree` in `tests/properties.rs`,
    /// `distance_from_origin_matches_the_reference` in `tests/derivations.rs`).
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
    ///
    /// Errors: [`GeomError::BadDirection`] for a zero or non-finite `dir`,
    /// [`GeomError::NotFinite`] for a negative, NaN or infinite `d`,
    /// [`GeomError::NotInBall`] when the point is beyond what f64 can place
    /// in the ball (`d` above ~38.1, where `tanh(d/2)` rounds to 1; the
    /// result always passes [`Point::is_representable`]).
    ///
    /// # Accuracy
    ///
    /// Radius and gap each within a few ulps (relative) of `tanh(d/2)` and
    /// `1/cosh^2(d/2)`, so `distance_from_origin` returns `d` to 1e-14
    /// relative (`at_distance_from_origin_inverts_distance` in this module;
    /// `at_distance_from_origin_matches_the_reference` in
    /// `tests/derivations.rs`).
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
        let p = Point {
            coords: dir / len * half.tanh(),
            gap,
        };
        // Past distance ~38.1 tanh(d/2) rounds to 1: the gap is still
        // positive but the coordinates lie on the absolute, which would break
        // the `|x| < 1` invariant. Reject rather than return such a point.
        if p.is_representable() {
            Ok(p)
        } else {
            Err(GeomError::NotInBall {
                norm: p.coords.length(),
            })
        }
    }

    /// The point on the hyperboloid `-x0^2 + |x|^2 = -1`, as a `DVec4` with the
    /// time coordinate in `w`: `((1+|p|^2), 2p) / (1-|p|^2)`.
    ///
    /// # Accuracy
    ///
    /// Each component within 2 ulps (relative) of the exact map applied to
    /// the stored point (`(2 - gap)/gap` and `2x/gap` with the accurate gap).
    /// Because the components grow like `2/gap` (about `e^d` at distance `d`),
    /// `<X,X> = -1` itself holds only to about `eps |X|^2`; beyond distance
    /// ~19 it is not resolved at all, which is why hgeom keeps far points in
    /// the ball (docs/geometry.md, section 16).
    #[inline]
    pub fn to_hyperboloid(&self) -> DVec4 {
        let inv = 1.0 / self.gap;
        (2.0 * self.coords * inv).extend((2.0 - self.gap) * inv)
    }

    /// Back from the hyperboloid: `p = x / (1 + x0)`. The gap is `2/(1+x0)`,
    /// exact in terms of `x0`.
    ///
    /// Returns `None` if the vector is not finite or not future-timelike.
    /// Spacelike and null vectors are rejected: `<X,X>` must not exceed
    /// `1e-9 x0^2` (a valid point has `<X,X> = -1`, rounded at the scale
    /// `eps x0^2`, so the margin never rejects a point the hyperboloid can
    /// hold).
    ///
    /// # Accuracy
    ///
    /// For a vector on the sheet to rounding (`|<X,X> + 1| <= 1e-9 x0^2`,
    /// which every hit point and isometry image satisfies), the coordinates
    /// are within 2 ulps of `x/(1+x0)` and the gap within 2 ulps of
    /// `2/(1+x0)`; the result is as accurate as `X` itself
    /// (`hyperboloid_round_trip` in this module). Off the sheet the gap is
    /// recomputed from the coordinates with compensated arithmetic.
    pub fn from_hyperboloid(x: DVec4) -> Option<Point> {
        if !x.is_finite() || x.w < 1.0 - 1e-12 || lorentz::dot(x, x) > 1e-9 * x.w * x.w {
            return None;
        }
        // Not a silent clamp of user input: a future-timelike vector has
        // x0 >= 1 exactly, and the only vectors let through below 1 are
        // within 1e-12 of it, i.e. rounded images of points next to the
        // origin (x0 = 1 + 2|p|^2 / gap). Reading them as x0 = 1 moves the
        // point by less than that rounding.
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

/// A point that f64 can hold with usable ball coordinates, or the reason it
/// cannot (a figure so large that a vertex lies beyond distance ~37).
pub(crate) fn representable(p: Point) -> Result<Point, GeomError> {
    if p.is_representable() {
        Ok(p)
    } else {
        Err(GeomError::NotInBall {
            norm: p.coords().length(),
        })
    }
}

/// A point on the absolute (the unit sphere): an ideal point.
///
/// Invariant: `dir` is a unit vector (to a few ulps: `||dir| - 1| <= 4 eps`
/// for every constructor except [`IdealPoint::from_unit_unchecked`], whose
/// caller promises it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IdealPoint {
    dir: DVec3,
}

impl IdealPoint {
    /// An ideal point from coordinates that must lie on the unit sphere within
    /// `tolerance` (Euclidean); they are then normalised.
    ///
    /// Errors: [`GeomError::NotFinite`], or [`GeomError::NotOnAbsolute`]
    /// when `||coords| - 1| > tolerance`, the tolerance is NaN, or `coords`
    /// is zero.
    ///
    /// # Accuracy
    ///
    /// The stored direction is `coords / |coords|`, a unit vector to within
    /// 2 ulps; the normalisation moves an accepted point by at most
    /// `tolerance` (Euclidean) along its ray.
    pub fn new(coords: DVec3, tolerance: f64) -> Result<IdealPoint, GeomError> {
        if !coords.is_finite() {
            return Err(GeomError::NotFinite);
        }
        let norm = coords.length();
        // Written so that a NaN tolerance rejects, and so that a tolerance
        // of 1 or more cannot let the zero vector through (it has no
        // direction to normalise).
        if !((norm - 1.0).abs() <= tolerance && norm > 0.0) {
            return Err(GeomError::NotOnAbsolute { norm });
        }
        Ok(IdealPoint { dir: coords / norm })
    }

    /// An ideal point from a vector the caller guarantees to be a unit vector
    /// (to rounding). For hot paths and constants; nothing is checked.
    ///
    /// # Preconditions
    ///
    /// `dir` finite with `|dir| = 1` to a few ulps. [`IdealPoint::new`]
    /// and [`IdealPoint::from_direction`] are the checked forms.
    ///
    /// # Accuracy
    ///
    /// Exact: stored as given. On unit input it agrees with
    /// [`IdealPoint::from_direction`] to 2 ulps (`tests/constructors.rs`).
    #[inline]
    pub const fn from_unit_unchecked(dir: DVec3) -> IdealPoint {
        IdealPoint { dir }
    }

    /// The ideal point at the end of the ray from the origin in direction `dir`.
    ///
    /// Errors: [`GeomError::BadDirection`] for a zero or non-finite `dir`.
    ///
    /// # Accuracy
    ///
    /// `dir / |dir|`: a unit vector to within 2 ulps.
    pub fn from_direction(dir: DVec3) -> Result<IdealPoint, GeomError> {
        let len = dir.length();
        if !(len.is_finite() && len > 0.0) {
            return Err(GeomError::BadDirection);
        }
        Ok(IdealPoint { dir: dir / len })
    }

    /// Unit vector of the point on the absolute.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored unit vector.
    #[inline]
    pub fn coords(&self) -> DVec3 {
        self.dir
    }

    /// A representative of the null ray on the light cone: `(dir, 1)`.
    ///
    /// # Accuracy
    ///
    /// Exact (no arithmetic); null to the accuracy of the unit vector,
    /// `|<L,L>| <= 4 eps`.
    #[inline]
    pub fn to_hyperboloid(&self) -> DVec4 {
        self.dir.extend(1.0)
    }
}

/// A polygon vertex or geodesic end: an h-point or an ideal point.
///
/// Invariants: those of the wrapped [`Point`] or [`IdealPoint`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Vertex {
    /// A point inside the ball.
    Interior(Point),
    /// A point on the absolute.
    Ideal(IdealPoint),
}

impl Vertex {
    /// Ball coordinates.
    ///
    /// # Accuracy
    ///
    /// Exact: the wrapped point's stored coordinates.
    pub fn coords(&self) -> DVec3 {
        match self {
            Vertex::Interior(p) => p.coords(),
            Vertex::Ideal(p) => p.coords(),
        }
    }

    /// Hyperboloid vector (timelike for interior points, null for ideal ones).
    ///
    /// # Accuracy
    ///
    /// As [`Point::to_hyperboloid`] (2 ulps per component) or
    /// [`IdealPoint::to_hyperboloid`] (exact).
    pub fn to_hyperboloid(&self) -> DVec4 {
        match self {
            Vertex::Interior(p) => p.to_hyperboloid(),
            Vertex::Ideal(p) => p.to_hyperboloid(),
        }
    }

    /// True for a point on the absolute.
    ///
    /// # Accuracy
    ///
    /// Exact: decided by the variant, never by a tolerance.
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
            Point::from_coords(DVec3::new(0.0, 0.0, 1.2)),
            Err(GeomError::NotInBall { .. })
        ));
        assert!(Point::from_coords(DVec3::X).is_err());
        assert!(Point::from_coords(DVec3::new(f64::NAN, 0.0, 0.0)).is_err());
        assert!(Point::from_coords(DVec3::new(1.0 - f64::EPSILON, 0.0, 0.0)).is_ok());
    }

    #[test]
    fn hyperboloid_round_trip() {
        let p = Point::from_coords(DVec3::new(0.3, -0.2, 0.5)).unwrap();
        let x = p.to_hyperboloid();
        assert!((lorentz::dot(x, x) + 1.0).abs() < 1e-14);
        let q = Point::from_hyperboloid(x).unwrap();
        assert!((q.coords() - p.coords()).length() < 1e-15);
        assert!((q.gap() - p.gap()).abs() < 1e-15);
    }

    #[test]
    fn distance_from_origin_matches_closed_form() {
        for &r in &[1e-12, 0.1, 0.5, 0.9, 1.0 - 1e-10] {
            let p = Point::from_coords(DVec3::new(0.0, r, 0.0)).unwrap();
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
        let p = IdealPoint::new(DVec3::new(0.0, 0.6, 0.8), 1e-12).unwrap();
        assert!((lorentz::dot(p.to_hyperboloid(), p.to_hyperboloid())).abs() < 1e-15);
        assert!(IdealPoint::new(DVec3::new(0.0, 0.6, 0.7), 1e-9).is_err());
    }
}
