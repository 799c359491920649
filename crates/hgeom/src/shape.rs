//! The interface every surface shares: ray intersection and moving by an
//! isometry, plus the inside test for the closed ones.
//!
//! The inherent methods of each shape are the same functions (and document
//! their own accuracy); the traits let generic code, such as a renderer's
//! list of objects or a test over every shape, treat them alike.

use crate::cylinder::HCylinder;
use crate::horosphere::Horosphere;
use crate::isometry::Isometry;
use crate::mesh::TriangleMesh;
use crate::plane::HPlane;
use crate::point::Point;
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
/// fn nearest<S: Shape>(shapes: &[S], ray: &Ray) -> Option<f64> {
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
/// let t = nearest(&[far, near], &ray).unwrap();
/// assert!((t - (near.center().distance(Point::ORIGIN) - 0.1)).abs() < 1e-14);
/// # Ok::<(), hgeom::GeomError>(())
/// ```
pub trait Shape {
    /// The first intersection with the ray at an arc length `t` strictly
    /// inside `(t_min, t_max)`, with the outward unit normal there.
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit>;

    /// The image of the surface under `iso`.
    fn transformed(&self, iso: &Isometry) -> Self
    where
        Self: Sized;
}

/// A shape that bounds a region: points can be inside it.
pub trait Solid: Shape {
    /// True if the h-point lies strictly inside.
    fn contains(&self, p: &Point) -> bool;
}

macro_rules! impl_shape {
    ($($t:ty),*) => {$(
        impl Shape for $t {
            #[inline]
            fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
                <$t>::intersect(self, ray, t_min, t_max)
            }
            #[inline]
            fn transformed(&self, iso: &Isometry) -> Self {
                <$t>::transformed(self, iso)
            }
        }
    )*};
}

impl_shape!(
    HSphere,
    HPlane,
    HCylinder,
    Horosphere,
    Rod,
    ConvexPolygon,
    Polyhedron,
    TriangleMesh
);

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
