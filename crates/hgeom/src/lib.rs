//! # hgeom — exact geometry of hyperbolic 3-space in the Poincaré ball
//!
//! Points, ideal points, h-planes, h-spheres, polygons and polyhedra,
//! isometries (reflections, translations, rotations and their compositions),
//! distances, and ray intersections — all exact formulas, evaluated with care
//! for the hard cases (points next to the absolute, tiny and huge distances,
//! grazing rays, long chains of isometries).
//!
//! The public face is the Poincaré ball: a [`Point`] is a Euclidean vector of
//! norm below 1. Internally each type uses whatever exact representation is
//! best conditioned: points carry their gap `1 - |x|^2` computed with
//! compensated arithmetic; isometries are kept in gyrovector form
//! `x -> a (+) Q x`; rays, planes and spheres are intersected on the
//! hyperboloid, where every quantity is a Lorentz inner product.
//!
//! ```
//! use glam::DVec3;
//! use hgeom::{distance, HSphere, Isometry, Point, Ray, Segment};
//!
//! // Distance between two points.
//! let a = Point::try_new(DVec3::new(0.5, 0.0, 0.0)).unwrap();
//! let b = Point::try_new(DVec3::new(0.0, 0.5, 0.0)).unwrap();
//! let d = distance(&a, &b);
//!
//! // Moving a point: the translation along a->b maps a to b, and preserves distances.
//! let t = Isometry::translation(&Segment::try_new(a, b).unwrap()).unwrap();
//! assert!((t.apply(&a).coords() - b.coords()).length() < 1e-15);
//! assert!((distance(&t.apply(&a), &t.apply(&b)) - d).abs() < 1e-14);
//!
//! // A ray from the origin along +z meets a sphere of radius 0.2 about a point on the z axis.
//! let c = Point::try_new(DVec3::new(0.0, 0.0, 0.5)).unwrap();
//! let sphere = HSphere::try_new(c, 0.2).unwrap();
//! let hit = sphere.intersect(&Ray::from_origin(DVec3::Z), 0.0, f64::INFINITY).unwrap();
//! assert!((hit.t - (c.distance_from_origin() - 0.2)).abs() < 1e-14);
//! ```

// `!(x > 0.0)` is deliberate throughout: it sends NaN down the failure path,
// which `x <= 0.0` would not.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod accurate;
mod cylinder;
mod distance;
mod error;
mod honeycomb;
mod horosphere;
mod isometry;
mod line;
pub mod lorentz;
pub mod mobius;
mod plane;
mod point;
mod polygon;
mod polygons;
mod polyhedron;
pub mod ray;
mod rod;
mod roots;
mod segment;
mod sphere;

pub use cylinder::HCylinder;
pub use distance::distance;
pub use error::GeomError;
pub use honeycomb::{
    CUBE_435_DIHEDRAL, HoneycombCell, MAX_TESSELLATION_CELLS, SAME_CELL_DISTANCE, cube_435,
    cube_435_circumradius, honeycomb_435, tessellate,
};
pub use horosphere::Horosphere;
pub use isometry::Isometry;
pub use line::HLine;
pub use plane::{BallShape, HPlane};
pub use point::{IdealPoint, Point, Vertex};
pub use polygon::ConvexPolygon;
pub use polygons::{
    REGULAR_POLYGON_VERTICES, ideal_regular_polygon, lambert_quadrilateral, regular_polygon,
    regular_polygon_with_side, saccheri_quadrilateral,
};
pub use polyhedron::{Platonic, Polyhedron, unique_edges};
pub use ray::{Hit, Ray};
pub use rod::Rod;
pub use segment::Segment;
pub use sphere::HSphere;

pub use glam;
