//! h-segments, and the h-lines they span.

use glam::DVec3;

use crate::distance::distance;
use crate::error::GeomError;
use crate::mobius::add_raw;
use crate::point::Point;

/// A geodesic segment between two distinct h-points; its h-line is the whole
/// geodesic through them, oriented from `start` to `end`.
///
/// Invariant: `start != end` (their computed distance is positive); both
/// ends obey [`Point`]'s invariants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    start: Point,
    end: Point,
}

impl Segment {
    /// The segment from `start` to `end`.
    ///
    /// Errors: [`GeomError::Coincident`] if the points are equal or their
    /// distance rounds to 0.
    ///
    /// # Accuracy
    ///
    /// Exact: stores the two points.
    pub fn new(start: Point, end: Point) -> Result<Segment, GeomError> {
        if start.coords() == end.coords() || distance(&start, &end) == 0.0 {
            return Err(GeomError::Coincident);
        }
        Ok(Segment { start, end })
    }

    /// First end point.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored point.
    pub fn start(&self) -> Point {
        self.start
    }

    /// Second end point.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored point.
    pub fn end(&self) -> Point {
        self.end
    }

    /// Hyperbolic length.
    ///
    /// # Accuracy
    ///
    /// As [`Point::distance`]: relative error below 1e-13.
    pub fn length(&self) -> f64 {
        distance(&self.start, &self.end)
    }

    /// The unit tangent (in ball coordinates, a Euclidean unit vector: the
    /// model is conformal) of the geodesic at `start`, pointing towards `end`.
    ///
    /// The transvection `x -> start (+) x` carries the diameter towards
    /// `w = (-start) (+) end` onto this segment, and its differential at the
    /// origin is a positive multiple of the identity, so the direction is
    /// exactly `w / |w|`; Möbius addition keeps it accurate far out, where
    /// the hyperboloid form cancels.
    ///
    /// # Accuracy
    ///
    /// Within `1e-12 + 100 eps |X_start|^2` radians of the true tangent for
    /// segments of length 0.01..3 starting within 5 of the origin
    /// (`isometries_preserve_angles` in `tests/properties.rs`); in general
    /// the error of [`crate::mobius::add_raw`], about `eps / gap` of the
    /// ends divided by `tanh(len/2)`.
    pub fn direction_at_start(&self) -> DVec3 {
        let a = self.start;
        let (w, _) = add_raw(-a.coords(), a.gap(), self.end.coords(), self.end.gap());
        let len = w.length();
        if len > 0.0 && len.is_finite() {
            w / len
        } else {
            // Only for points a few ulps apart, where the chord is the tangent
            // to rounding.
            (self.end.coords() - a.coords()).normalize()
        }
    }
}
