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

use hgeom::glam::{DVec3, DVec4};
use hgeom::{Isometry, Point, Rod, Vertex, lorentz};

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
        let iso = &self.to_origin;
        let here = DVec4::W;
        match shape {
            Shape::Sphere(s) => self.point.distance(s.center()) < s.radius(),
            Shape::Polygon(_) => false,
            Shape::Polyhedron(p) => {
                // Behind every face plane means inside only for a closed
                // surface (the golden rectangles are not one): there every
                // edge belongs to exactly two faces. For star polyhedra this
                // finds the core.
                let sides: usize = p.faces().iter().map(|f| f.vertices().len()).sum();
                let closed = !p.faces().is_empty() && sides == 2 * p.edges().len();
                closed
                    && p.faces()
                        .iter()
                        .all(|f| lorentz::dot(here, f.plane().transformed(iso).normal()) < 0.0)
            }
            // A plane bounds a half-space, not an object one can be inside of.
            Shape::Plane(_) => false,
            Shape::Rod(r) => r.transformed(iso).contains_hyperboloid(here),
            Shape::Cylinder(c) => c.transformed(iso).contains_hyperboloid(here),
            Shape::Horosphere(h) => h.transformed(iso).contains_hyperboloid(here),
            Shape::Wireframe(rods) => rods
                .iter()
                .any(|r| r.transformed(iso).contains_hyperboloid(here)),
            // Whether a mesh is closed, and so has an inside, is not checked.
            Shape::Mesh(_) => false,
        }
    }

    /// True if the object lies entirely on the far side of the plane
    /// through the point orthogonal to `view` (a unit ball direction at the
    /// point, from [`SeenFrom::direction_to`]): in the point's frame that
    /// plane is the flat one `x . view = 0`, and a point's side is the sign
    /// of `x . view`, its signed distance `asinh(2 x.view / g)`.
    pub(super) fn is_behind(&self, shape: &Shape, view: DVec3) -> bool {
        let iso = &self.to_origin;
        let sinh_ahead = |p: &Point| {
            let q = iso.apply(p);
            2.0 * q.coords().dot(view) / q.gap()
        };
        let vertex_behind = |v: &Vertex| iso.apply_vertex(v).coords().dot(view) < 0.0;
        match shape {
            Shape::Sphere(s) => sinh_ahead(&s.center()) < -s.radius().sinh(),
            Shape::Polygon(p) => p.vertices().iter().all(vertex_behind),
            Shape::Polyhedron(p) => p
                .faces()
                .iter()
                .all(|f| f.vertices().iter().all(vertex_behind)),
            // Unbounded surfaces always reach in front of the eye's plane.
            Shape::Plane(_) | Shape::Cylinder(_) | Shape::Horosphere(_) => false,
            Shape::Rod(r) => rod_behind(r, &sinh_ahead),
            Shape::Wireframe(rods) => rods.iter().all(|r| rod_behind(r, &sinh_ahead)),
            Shape::Mesh(m) => m.vertices().iter().all(|p| sinh_ahead(p) < 0.0),
        }
    }
}

/// A rod is behind the plane when both ends are, by more than its radius
/// (the rod lies within its radius of the segment, which is behind if its
/// ends are: half-spaces are convex).
fn rod_behind(rod: &Rod, sinh_ahead: &impl Fn(&Point) -> f64) -> bool {
    let end_behind = |v: Vertex| match v {
        Vertex::Interior(p) => sinh_ahead(&p) < -rod.radius().sinh(),
        // An ideal end: the rod's tube reaches the absolute there.
        Vertex::Ideal(_) => false,
    };
    end_behind(rod.start()) && end_behind(rod.end())
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::{HSphere, Horosphere, IdealPoint};

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
            Shape::Rod(rod.transformed(&far)),
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
