//! Where objects stand as seen from one point (the eye, a light), decided in
//! that point's own frame.
//!
//! The lints ask whether the eye or a light is inside an object, and whether
//! an object lies entirely behind the eye. Answered with hyperboloid
//! products in the scene's frame, they fail far from the origin: at distance
//! `d` both vectors are of size `e^d`, their product rounds at
//! `eps e^{2d} / 4`, and a scene moved 25 away drew false "eye inside this
//! object" and "light inside an opaque object" warnings. Moved by the
//! transvection that takes the point to the origin (Möbius addition, exact
//! to the rounding of the inputs), every object is near and every product
//! small; the point itself is the origin `E`. Spheres need no move at all:
//! the ball distance `2 asinh(|x - c| / sqrt(g_x g_c))` is good to a few
//! ulps anywhere.

use hgeom::glam::DVec3;
use hgeom::{Isometry, Point};

use crate::ir::Shape;

/// The frame of one point: everything moved so that it is the origin.
pub(super) struct SeenFrom {
    point: Point,
    to_origin: Isometry,
}

impl SeenFrom {
    pub(super) fn new(point: Point) -> SeenFrom {
        SeenFrom {
            point,
            to_origin: Isometry::transvection_from_origin(point).inverse(),
        }
    }

    /// The unit ball direction, at the point, towards `other`; `None` if
    /// they coincide.
    pub(super) fn direction_to(&self, other: &Point) -> Option<DVec3> {
        let w = self.to_origin.apply(other).coords();
        let len = w.length();
        (len > 0.0 && len.is_finite()).then(|| w / len)
    }

    /// True if the point is strictly inside a closed object.
    pub(super) fn is_inside(&self, shape: &Shape) -> bool {
        shape.encloses(&self.point, &self.to_origin)
    }

    /// True if the object lies entirely on the far side of the plane
    /// through the point orthogonal to `view` (a unit ball direction at the
    /// point, from [`SeenFrom::direction_to`]).
    pub(super) fn is_behind(&self, shape: &Shape, view: DVec3) -> bool {
        shape.lies_behind(&self.to_origin, view)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::{HSphere, Horosphere, IdealPoint, Rod};

    fn at(dir: DVec3, d: f64) -> Point {
        Point::at_distance_from_origin(dir, d).unwrap()
    }

    /// A scene 25 from the origin: the eye 0.3 outside a sphere, rod and
    /// horosphere, and a light inside them. The world-frame products used
    /// before round at `eps e^50 / 4 ~ 3e5` and drew false warnings; in the
    /// point's frame every answer is right.
    #[test]
    fn far_points_inside_and_outside() {
        let far = Isometry::transvection_from_origin(at(DVec3::new(0.3, -0.5, 0.8), 25.0));
        let centre = at(DVec3::Z, 1.0);
        let ball = HSphere::new(centre, 0.5).unwrap();
        let rod = Rod::new(
            centre.into(),
            at(DVec3::new(0.2, 0.0, 1.0), 1.5).into(),
            0.3,
        )
        .unwrap();
        let horo = Horosphere::new(IdealPoint::from_direction(DVec3::Z).unwrap(), &centre).unwrap();
        let shapes = [
            Shape::Sphere(ball.transformed(&far)),
            Shape::Rod(Box::new(rod.transformed(&far))),
            Shape::Horosphere(horo.transformed(&far)),
        ];
        let eye = SeenFrom::new(far.apply(&Point::ORIGIN));
        let light = SeenFrom::new(far.apply(&at(DVec3::Z, 1.05)));
        for s in &shapes {
            assert!(!eye.is_inside(s), "{s:?}");
            assert!(light.is_inside(s), "{s:?}");
        }
        // Behind: the sphere is ahead of the eye looking along +z, behind it
        // looking along -z.
        let ahead = eye.direction_to(&far.apply(&at(DVec3::Z, 0.1))).unwrap();
        assert!(!eye.is_behind(&shapes[0], ahead));
        assert!(eye.is_behind(&shapes[0], -ahead));
    }
}
