//! Operators: `Isometry * Point`, `Isometry * Isometry` and friends, as in
//! glam and nalgebra.
//!
//! Each operator is the named method spelled as algebra: `f * p` is
//! [`Isometry::apply`], `f * g` is [`Isometry::compose`] (first `g`, then
//! `f`, as for matrices), so the accuracy stated there is the accuracy here.

use std::ops::Mul;

use crate::isometry::Isometry;
use crate::point::{IdealPoint, Point, Vertex};

impl Mul<Point> for Isometry {
    type Output = Point;

    /// [`Isometry::apply`]. Use [`Isometry::checked_apply`] where the image
    /// may fall beyond what f64 can represent (points past distance ~37).
    #[inline]
    fn mul(self, p: Point) -> Point {
        self.apply(&p)
    }
}

impl Mul<IdealPoint> for Isometry {
    type Output = IdealPoint;

    /// [`Isometry::apply_ideal`].
    #[inline]
    fn mul(self, p: IdealPoint) -> IdealPoint {
        self.apply_ideal(&p)
    }
}

impl Mul<Vertex> for Isometry {
    type Output = Vertex;

    /// [`Isometry::apply_vertex`].
    #[inline]
    fn mul(self, v: Vertex) -> Vertex {
        self.apply_vertex(&v)
    }
}

impl Mul<Isometry> for Isometry {
    type Output = Isometry;

    /// [`Isometry::compose`]: `(f * g)(x) = f(g(x))`.
    #[inline]
    fn mul(self, other: Isometry) -> Isometry {
        self.compose(&other)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::segment::Segment;

    #[test]
    fn operators_are_the_named_methods() {
        let a = Point::new(0.1, -0.3, 0.2).unwrap();
        let b = Point::new(-0.4, 0.1, 0.5).unwrap();
        let f = Isometry::translation(&Segment::new(a, b).unwrap()).unwrap();
        let g = Isometry::transvection_from_origin(b);
        assert_eq!(f * a, f.apply(&a));
        assert_eq!(f * g, f.compose(&g));
        let e = IdealPoint::from_direction(glam::DVec3::X).unwrap();
        assert_eq!(f * e, f.apply_ideal(&e));
        assert_eq!(f * Vertex::from(a), f.apply_vertex(&Vertex::from(a)));
        // Composition reads right to left, as for matrices.
        let x = Point::new(0.3, 0.3, 0.3).unwrap();
        assert!(((f * g) * x).distance(f * (g * x)) < 1e-13);
    }
}
