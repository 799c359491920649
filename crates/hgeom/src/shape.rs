//! The interface every surface shares: ray intersection (nearest and any),
//! moving by an isometry, a bounding ball, and whether it is representable
//! in f64; plus the inside test for the closed ones.
//!
//! The inherent methods of each shape are the same functions (and document
//! their own accuracy); the traits let generic code, such as a renderer's
//! list of objects or a test over every shape, treat them alike. The trait
//! is dyn-compatible: a renderer can hold `Box<dyn Shape + Send + Sync>`.

use glam::DVec4;

use crate::bound::{self, BoundingBall};
use crate::cylinder::HCylinder;
use crate::honeycomb::RegularHoneycomb;
use crate::horosphere::Horosphere;
use crate::isometry::Isometry;
use crate::klein_box::KleinBox;
use crate::lorentz;
use crate::mesh::TriangleMesh;
use crate::plane::HPlane;
use crate::point::{Point, Vertex};
use crate::polygon::ConvexPolygon;
use crate::polyhedron::Polyhedron;
use crate::ray::{Hit, Ray};
use crate::rod::Rod;
use crate::sphere::HSphere;

/// A surface a geodesic ray can hit, that isometries carry to a surface of
/// the same kind.
///
/// ```
/// use hgeom::{HSphere, Isometry, Point, Ray, Shape};
///
/// fn nearest(shapes: &[Box<dyn Shape>], ray: &Ray) -> Option<f64> {
///     shapes
///         .iter()
///         .filter_map(|s| s.intersect(ray, 0.0, f64::INFINITY))
///         .map(|hit| hit.t)
///         .min_by(f64::total_cmp)
/// }
///
/// let near = HSphere::new(Point::new(0.0, 0.0, 0.3)?, 0.1)?;
/// let far = HSphere::new(Point::new(0.0, 0.0, 0.8)?, 0.1)?;
/// let ray = Ray::from_origin(glam::DVec3::Z)?;
/// let t = nearest(&[Box::new(far), Box::new(near)], &ray).unwrap();
/// assert!((t - (near.center().distance(Point::ORIGIN) - 0.1)).abs() < 1e-14);
/// assert!(near.bound().is_some() && near.is_representable());
/// # Ok::<(), hgeom::GeomError>(())
/// ```
pub trait Shape {
    /// The first intersection with the ray at an arc length `t` strictly
    /// inside `(t_min, t_max)`, with the outward unit normal there.
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit>;

    /// True if the ray meets the surface anywhere in `(t_min, t_max)`: the
    /// shadow-ray test, which may stop at the first hit it finds.
    #[inline]
    fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.intersect(ray, t_min, t_max).is_some()
    }

    /// The image of the surface under `iso`.
    fn transformed(&self, iso: &Isometry) -> Self
    where
        Self: Sized;

    /// A closed h-ball containing the surface (and every hit its exact test
    /// accepts); `None` if it is unbounded: it reaches the absolute (planes,
    /// cylinders, horospheres, anything with an ideal point).
    fn bound(&self) -> Option<BoundingBall>;

    /// Balls whose union contains the surface, for the leaves of a bounding
    /// hierarchy; empty if it is unbounded. Long thin surfaces give several
    /// small balls, which hug them far better than one ball can.
    fn bound_pieces(&self) -> Vec<BoundingBall> {
        self.bound().into_iter().collect()
    }

    /// Klein-model boxes whose union contains the surface (and every hit
    /// its exact test accepts), for the leaves of a box hierarchy; empty if
    /// no finite box is known. By default the boxes of
    /// [`Shape::bound_pieces`]; flat shapes give the box of their vertices,
    /// which is exact (their hull is straight in the Klein model) and
    /// exists even with ideal vertices.
    fn klein_boxes(&self) -> Vec<KleinBox> {
        self.bound_pieces()
            .iter()
            .filter_map(KleinBox::around_ball)
            .collect()
    }

    /// True if every quantity that defines the surface is finite and usable
    /// in f64 here: its points have ball coordinates with a positive gap,
    /// its normals and frames are finite. A surface moved too far from the
    /// origin fails this; the exact tests need it.
    fn is_representable(&self) -> bool;

    /// [`Shape::is_representable`], and in addition well conditioned enough
    /// in this frame for the exact tests to be right: a plane's normal must
    /// still be unit (one carried far by a Lorentz matrix loses
    /// `eps e^{2d}` of it and would meet rays at the wrong place). Asked of
    /// surfaces already moved near the eye; far from it, a surface can be
    /// representable and not traceable until moved.
    fn is_traceable(&self) -> bool {
        self.is_representable()
    }
}

/// A shape that bounds a region: points can be inside it.
pub trait Solid: Shape {
    /// True if the h-point lies strictly inside.
    fn contains(&self, p: &Point) -> bool;
}

/// `intersect` and `transformed` of a shape, forwarded to its inherent
/// methods of the same names.
macro_rules! forward_intersect_and_move {
    ($t:ty) => {
        #[inline]
        fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
            <$t>::intersect(self, ray, t_min, t_max)
        }
        #[inline]
        fn transformed(&self, iso: &Isometry) -> Self {
            <$t>::transformed(self, iso)
        }
    };
}

/// True if a polygon's or rod's defining point is usable: an h-point with
/// ball coordinates, or an ideal point with a finite direction.
fn vertex_ok(v: &Vertex) -> bool {
    match v {
        Vertex::Interior(p) => p.is_representable(),
        Vertex::Ideal(i) => i.coords().is_finite(),
    }
}

/// True if a plane's normal is finite and still unit to `1e-6`.
fn normal_is_unit(n: DVec4) -> bool {
    n.is_finite() && (lorentz::dot(n, n) - 1.0).abs() <= 1e-6
}

impl Shape for HSphere {
    forward_intersect_and_move!(HSphere);
    #[inline]
    fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        HSphere::blocks(self, ray, t_min, t_max)
    }
    fn bound(&self) -> Option<BoundingBall> {
        BoundingBall::new(self.center().to_hyperboloid(), self.radius())
    }
    fn is_representable(&self) -> bool {
        self.center().is_representable()
    }
}

impl Shape for HPlane {
    forward_intersect_and_move!(HPlane);
    fn bound(&self) -> Option<BoundingBall> {
        None
    }
    fn is_representable(&self) -> bool {
        self.normal().is_finite()
    }
    fn is_traceable(&self) -> bool {
        normal_is_unit(self.normal())
    }
}

impl Shape for HCylinder {
    forward_intersect_and_move!(HCylinder);
    fn bound(&self) -> Option<BoundingBall> {
        None
    }
    fn is_representable(&self) -> bool {
        self.line().base().is_representable() && self.line().lorentz_basis().is_finite()
    }
}

impl Shape for Horosphere {
    forward_intersect_and_move!(Horosphere);
    fn bound(&self) -> Option<BoundingBall> {
        None
    }
    fn is_representable(&self) -> bool {
        let (c, r) = self.euclidean();
        c.is_finite() && r.is_finite() && r > 0.0
    }
}

impl Shape for Rod {
    forward_intersect_and_move!(Rod);
    #[inline]
    fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        Rod::blocks(self, ray, t_min, t_max)
    }
    fn bound(&self) -> Option<BoundingBall> {
        bound::rod_ball(self)
    }
    fn bound_pieces(&self) -> Vec<BoundingBall> {
        bound::rod_pieces(self)
    }
    /// The tube's own Klein boxes (thin where the rod is; see
    /// [`KleinBox::around_tube`]); none with an ideal end. A rod of one
    /// piece also lies in the ball about it, whose box is the exact extent
    /// of an ellipsoid and, for a short thick rod far from the origin,
    /// thinner along the line of sight than the tube's: it gets the
    /// intersection of the two (each holds the rod, so their common part
    /// does).
    fn klein_boxes(&self) -> Vec<KleinBox> {
        let (Vertex::Interior(a), Vertex::Interior(b)) = (self.start(), self.end()) else {
            return Vec::new();
        };
        let mut boxes = KleinBox::around_tube(
            a.to_hyperboloid(),
            b.to_hyperboloid(),
            self.radius(),
            bound::ROD_PIECE_RADII,
            bound::ROD_MAX_PIECES as u32,
        );
        if let [only] = boxes.as_mut_slice()
            && let Some(ball) = bound::rod_ball(self)
                .as_ref()
                .and_then(KleinBox::around_ball)
            && let Some(both) = only.intersection(&ball)
        {
            *only = both;
        }
        boxes
    }
    fn is_representable(&self) -> bool {
        vertex_ok(&self.start())
            && vertex_ok(&self.end())
            && self.tube().line().lorentz_basis().is_finite()
    }
}

impl Shape for ConvexPolygon {
    forward_intersect_and_move!(ConvexPolygon);
    fn bound(&self) -> Option<BoundingBall> {
        bound::vertices_ball(self.vertices())
    }
    fn klein_boxes(&self) -> Vec<KleinBox> {
        KleinBox::around_vertices(self.vertices())
            .into_iter()
            .collect()
    }
    fn is_representable(&self) -> bool {
        self.vertices().iter().all(vertex_ok)
    }
    fn is_traceable(&self) -> bool {
        self.is_representable() && normal_is_unit(self.plane().normal())
    }
}

impl Shape for Polyhedron {
    forward_intersect_and_move!(Polyhedron);
    /// The ball about every vertex; `None` if a vertex is ideal.
    fn bound(&self) -> Option<BoundingBall> {
        bound::vertices_ball(self.faces().iter().flat_map(|f| f.vertices()))
    }
    fn klein_boxes(&self) -> Vec<KleinBox> {
        KleinBox::around_vertices(self.faces().iter().flat_map(|f| f.vertices()))
            .into_iter()
            .collect()
    }
    fn is_representable(&self) -> bool {
        self.center().is_representable() && self.faces().iter().all(Shape::is_representable)
    }
    fn is_traceable(&self) -> bool {
        self.faces().iter().all(Shape::is_traceable)
    }
}

impl Shape for TriangleMesh {
    forward_intersect_and_move!(TriangleMesh);
    #[inline]
    fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        TriangleMesh::blocks(self, ray, t_min, t_max)
    }
    fn bound(&self) -> Option<BoundingBall> {
        let (centre, radius) = self.bounding_ball();
        BoundingBall::new(centre, radius)
    }
    /// The placement's translation part is the mesh's centre; the vertices
    /// are within the bounding radius of it.
    fn is_representable(&self) -> bool {
        let (centre, radius) = self.bounding_ball();
        self.placement().translation_part().is_representable()
            && centre.is_finite()
            && radius.is_finite()
    }
}

impl Shape for RegularHoneycomb {
    forward_intersect_and_move!(RegularHoneycomb);
    /// The walk stops at the first part it finds.
    #[inline]
    fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        RegularHoneycomb::blocks(self, ray, t_min, t_max)
    }
    /// Unbounded: the honeycomb fills space (even a depth-limited one may
    /// reach the absolute at ideal vertices); the walk bounds itself.
    fn bound(&self) -> Option<BoundingBall> {
        None
    }
    fn is_representable(&self) -> bool {
        RegularHoneycomb::is_representable(self)
    }
}

macro_rules! impl_solid {
    ($($t:ty),*) => {$(
        impl Solid for $t {
            #[inline]
            fn contains(&self, p: &Point) -> bool {
                <$t>::contains(self, p)
            }
        }
    )*};
}

impl_solid!(HSphere, HCylinder, Horosphere, Rod);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::line::HLine;
    use crate::point::Vertex;
    use glam::DVec3;

    fn every_solid() -> (HSphere, HCylinder, Horosphere, Rod) {
        let c = Point::new(0.0, 0.0, 0.4).unwrap();
        let axis = HLine::through(&Point::ORIGIN.into(), &Vertex::from(c)).unwrap();
        let ideal = crate::point::IdealPoint::from_direction(DVec3::Y).unwrap();
        (
            HSphere::new(c, 0.3).unwrap(),
            HCylinder::new(axis, 0.2).unwrap(),
            Horosphere::new(ideal, &Point::new(0.0, 0.5, 0.0).unwrap()).unwrap(),
            Rod::new(Point::ORIGIN.into(), c.into(), 0.1).unwrap(),
        )
    }

    fn check<S: Solid>(s: &S, inside: Point, outside: Point) {
        assert!(s.contains(&inside));
        assert!(!s.contains(&outside));
        // Moving the solid and the points together keeps the answers.
        let f = Isometry::transvection_from_origin(Point::new(0.2, -0.5, 0.1).unwrap());
        let moved = s.transformed(&f);
        assert!(moved.contains(&(f * inside)));
        assert!(!moved.contains(&(f * outside)));
    }

    #[test]
    fn solids_agree_with_their_hyperboloid_tests_and_move_with_isometries() {
        let (sphere, tube, horo, rod) = every_solid();
        let far = Point::new(-0.9, 0.0, 0.0).unwrap();
        check(&sphere, Point::new(0.0, 0.0, 0.4).unwrap(), far);
        check(&tube, Point::new(0.0, 0.0, -0.3).unwrap(), far);
        check(&horo, Point::new(0.0, 0.7, 0.0).unwrap(), far);
        check(&rod, Point::new(0.0, 0.0, 0.2).unwrap(), far);
        let p = Point::new(0.01, 0.0, 0.39).unwrap();
        assert_eq!(
            sphere.contains(&p),
            sphere.contains_hyperboloid(p.to_hyperboloid())
        );
    }

    #[test]
    fn the_trait_finds_the_same_hits_as_the_methods() {
        let (sphere, tube, _, rod) = every_solid();
        let ray = Ray::from_origin(DVec3::new(0.05, 0.02, 1.0)).unwrap();
        let via_trait = |s: &dyn Shape| s.intersect(&ray, 1e-9, f64::INFINITY);
        assert_eq!(
            via_trait(&sphere),
            sphere.intersect(&ray, 1e-9, f64::INFINITY)
        );
        assert_eq!(via_trait(&tube), tube.intersect(&ray, 1e-9, f64::INFINITY));
        assert_eq!(via_trait(&rod), rod.intersect(&ray, 1e-9, f64::INFINITY));
    }
}
