//! # hgeom — exact geometry of hyperbolic 3-space in the Poincaré ball
//!
//! Points, ideal points, h-lines, h-planes, h-spheres, h-cylinders, rods,
//! horospheres, polygons and polyhedra, isometries (reflections,
//! translations, rotations and their compositions), distances, and ray
//! intersections — all exact formulas, evaluated with care for the hard
//! cases (points next to the absolute, tiny and huge distances, grazing
//! rays, long chains of isometries).
//!
//! The public face is the Poincaré ball: a [`Point`] is a Euclidean vector of
//! norm below 1. Internally each type uses whatever exact representation is
//! best conditioned: points carry their gap `1 - |x|^2` computed with
//! compensated arithmetic; isometries are kept in gyrovector form
//! `x -> a (+) Q x`; rays, planes and spheres are intersected on the
//! hyperboloid, where every quantity is a Lorentz inner product. Every
//! formula is derived in `docs/geometry.md`, and every public function states
//! its accuracy in an `# Accuracy` section, measured by the tests (against a
//! 320-bit reference in `tests/reference.rs`; run
//! `cargo run --release -p hgeom --example accuracy` for the full table).
//!
//! Invalid input is rejected with a typed [`GeomError`] by the `try_*`
//! constructors (and the named constructors that return `Result`, such as
//! [`HPlane::through`]); hot paths have `_unchecked` forms
//! ([`Point::new_unchecked`], [`HSphere::new_unchecked`],
//! [`HCylinder::new_unchecked`], [`IdealPoint::from_unit_unchecked`]) whose
//! preconditions are documented. Nothing is clamped into range silently.
//!
//! ```
//! use glam::DVec3;
//! use hgeom::{distance, HCylinder, HLine, HSphere, Isometry, Point, Ray, Segment};
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
//!
//! // The h-cylinder of radius 0.3 about the z axis (the h-line through the
//! // origin and c). A ray leaving the axis at angle theta to it reaches the
//! // surface where sinh r = sinh t sin theta (a right-angled triangle).
//! let axis = HLine::through(&Point::ORIGIN.into(), &c.into()).unwrap();
//! let tube = HCylinder::try_new(axis, 0.3).unwrap();
//! let theta = 0.6f64;
//! let ray = Ray::from_origin(DVec3::new(theta.sin(), 0.0, theta.cos()));
//! let hit = tube.intersect(&ray, 0.0, f64::INFINITY).unwrap();
//! assert!((hit.t - (0.3f64.sinh() / theta.sin()).asinh()).abs() < 1e-14);
//! ```
//!
//! ## Module map
//!
//! | module | contents |
//! |---|---|
//! | [`accurate`] | error-free products and sums; the compensated gap `1 - \|x\|^2` |
//! | `point` | [`Point`] (with its accurate gap), [`IdealPoint`], [`Vertex`] |
//! | `distance` | [`distance`] in the `2 asinh` form |
//! | [`mobius`] | Möbius addition and the gyration: the algebra of isometries |
//! | `isometry` | [`Isometry`] `x -> a (+) Qx`: reflections, translations, rotations, composition, inverse, Lorentz matrix |
//! | [`lorentz`] | the hyperboloid model: Lorentz form, orthogonal complement, geodesics |
//! | [`ray`] | [`Ray`], [`Hit`], reflection and refraction in the tangent space, ball/hyperboloid tangents |
//! | `segment` | [`Segment`] |
//! | `line` | [`HLine`] with its adapted Lorentz frame |
//! | `plane` | [`HPlane`] (unit spacelike normal), [`BallShape`] |
//! | `sphere` | [`HSphere`]: Euclidean form, closed-form ray intersection |
//! | `cylinder` | [`HCylinder`]: the equidistant surface of an h-line, closed form |
//! | `rod` | [`Rod`]: tube plus two caps, for wireframes |
//! | `horosphere` | [`Horosphere`] |
//! | `roots` | the cancellation-free roots of the `e^t` quadratic (crate-private) |
//! | `polygon` | [`ConvexPolygon`]: validation, edge planes, ray intersection |
//! | `polygons` | predefined polygons: regular, ideal, Lambert, Saccheri |
//! | `polyhedron` | [`Polyhedron`], [`Platonic`] solids, uniform and star figures, [`unique_edges`] |
//! | `mesh` | [`TriangleMesh`]: triangle meshes with a Klein-coordinate BVH and a watertight exact test |
//! | `honeycomb` | the {4,3,5} cube and tessellation by reflections |
//! | `error` | [`GeomError`] |
//! | `fermi` | [`fermi_coordinates`] about the origin and their inverse (solid textures) |

// `!(x > 0.0)` is deliberate throughout: it sends NaN down the failure path,
// which `x <= 0.0` would not.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
#![warn(missing_docs)]

pub mod accurate;
mod compact;
mod cylinder;
mod distance;
mod error;
mod fermi;
mod honeycomb;
mod horosphere;
mod isometry;
mod line;
pub mod lorentz;
mod mesh;
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

pub use compact::Compact;
pub use cylinder::HCylinder;
pub use distance::distance;
pub use error::GeomError;
pub use fermi::{fermi_coordinates, from_fermi_coordinates};
pub use honeycomb::{
    CUBE_435_DIHEDRAL, HoneycombCell, MAX_TESSELLATION_CELLS, SAME_CELL_DISTANCE, cube_435,
    cube_435_circumradius, honeycomb_435, tessellate,
};
pub use horosphere::Horosphere;
pub use isometry::Isometry;
pub use line::HLine;
pub use mesh::TriangleMesh;
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
