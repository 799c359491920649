#![doc = include_str!("../README.md")]
//!
//! ## Module map
//!
//! | module | contents |
//! |---|---|
//! | [`accurate`] | error-free products and sums; the compensated gap `1 - \|x\|^2` |
//! | `point` | [`Point`] (with its accurate gap), [`IdealPoint`], [`Vertex`] |
//! | `distance` | [`Point::distance`] in the `2 asinh` form |
//! | [`mobius`] | Möbius addition and the gyration: the algebra of isometries |
//! | `isometry` | [`Isometry`] `x -> a (+) Qx`: translations, rotations about segments, composition, inverse, Lorentz matrix |
//! | [`lorentz`] | the hyperboloid model: Lorentz form, orthogonal complement, geodesics |
//! | [`ray`] | [`Ray`], [`Hit`], reflection and refraction in the tangent space, ball/hyperboloid tangents |
//! | `segment` | [`Segment`] |
//! | `line` | [`HLine`] with its adapted Lorentz basis; [`Isometry::rotation`] about it |
//! | `plane` | [`HPlane`] (unit spacelike normal), [`BallShape`]; [`Isometry::reflection`] in it |
//! | `sphere` | [`HSphere`]: Euclidean form, closed-form ray intersection |
//! | `cylinder` | [`HCylinder`]: the equidistant surface of an h-line, closed form |
//! | `rod` | [`Rod`]: tube plus two caps, for wireframes |
//! | `horosphere` | [`Horosphere`] |
//! | `roots` | the cancellation-free roots of the `e^t` quadratic (crate-private) |
//! | `polygon` | [`ConvexPolygon`]: validation, edge planes, ray intersection |
//! | `polygons` | predefined polygons: regular, ideal, Lambert, Saccheri |
//! | `polyhedron` | [`Polyhedron`], [`Platonic`] solids, uniform and star figures, [`unique_edges`] |
//! | `mesh` | [`TriangleMesh`]: triangle meshes with a Klein-coordinate BVH and a watertight exact test |
//! | `honeycomb` | the {4,3,5} cube and tessellation by reflections; [`Schlafli`] symbols; [`RegularHoneycomb`], any of the 15 regular honeycombs traced by walking the Coxeter simplex |
//! | `error` | [`GeomError`] |
//! | `shape` | the [`Shape`] and [`Solid`] traits every surface implements |
//! | `ops` | `Isometry * Point`, `Isometry * Isometry` |
//! | `serde_impls` | the `serde` feature's exact, validating forms |
//! | `fermi` | [`fermi_coordinates`] about the origin and their inverse (solid textures) |
//!
//! ## Module layering
//!
//! The modules import one another in one direction only, never in a cycle.
//! The leaves import nothing of the crate: `accurate`, `compact` and
//! `lorentz`; `error` imports only `compact` (to print numbers in its
//! messages). Above them come `point`; then `distance`, `mobius` and `ray`;
//! `roots` and `segment`; `isometry`; and on top the surfaces and figures
//! (`plane`, `line`, `sphere`, `horosphere`, `cylinder`, `polygon`, `rod`,
//! `mesh`, `polygons`, `polyhedron`, `honeycomb`), with `fermi`, `ops` and
//! `serde_impls`. An isometry built from a surface is defined with that
//! surface (the reflection in `plane`, the rotation about a line in `line`),
//! since the surface already depends on `isometry`. `shape` only imports:
//! it implements the shared traits for every surface, so nothing but the
//! crate root refers to it.

pub mod accurate;
mod bound;
mod compact;
mod cylinder;
mod distance;
mod error;
mod fermi;
mod honeycomb;
mod horosphere;
mod isometry;
mod klein_box;
mod line;
pub mod lorentz;
mod mesh;
pub mod mobius;
mod ops;
mod plane;
mod point;
mod polygon;
mod polygons;
mod polyhedron;
pub mod ray;
mod rod;
mod roots;
mod segment;
#[cfg(feature = "serde")]
mod serde_impls;
mod shape;
mod space;
mod sphere;
#[cfg(test)]
mod test_rng;

pub use bound::BoundingBall;
pub use compact::Compact;
pub use cylinder::HCylinder;
pub use error::GeomError;
pub use fermi::{fermi_coordinates, from_fermi_coordinates};
pub use honeycomb::{
    CUBE_435_DIHEDRAL, CellColouring, CoxeterSimplex, DEFAULT_HORIZON, FaceFrame, HoneycombCell,
    HoneycombPart, HoneycombPiece, HoneycombPieces, HoneycombStyle, MAX_TESSELLATION_CELLS,
    MAX_WALK_STEPS, RANK_CLASSES, RegularHoneycomb, Rings, SAME_CELL_DISTANCE, Schlafli,
    SchlafliError, WalkStats, WalkStep, cube_435, cube_435_circumradius, decode_honeycomb_part,
    honeycomb_435, tessellate, tessellation_placements,
};
pub use horosphere::Horosphere;
pub use isometry::Isometry;
pub use klein_box::{
    KleinBox, KleinRay, nearest_to_origin, plain_max, plain_min, round_outward_f32,
};
pub use line::HLine;
pub use mesh::{GivenNormals, TriangleMesh};
pub use plane::{BallShape, HPlane};
pub use point::{IdealPoint, Point, Vertex};
pub use polygon::ConvexPolygon;
pub use polygons::{
    REGULAR_POLYGON_VERTICES, ideal_regular_polygon, lambert_quadrilateral, regular_polygon,
    regular_polygon_with_side, saccheri_quadrilateral,
};
pub use polyhedron::{Platonic, Polyhedron, unique_edges};
pub use ray::{CHORD_FROM, Hit, Ray, on_hyperboloid};
pub use rod::Rod;
pub use segment::Segment;
pub use shape::{Shape, Solid};
pub use space::{
    Crossing, DomainEdge, DomainPolyhedron, EdgeCycle, HOROSPHERE_CELL_REACH, MAX_CHAMBER_STEPS,
    MAX_COPIES, MAX_DOMAIN_VERTICES, MAX_PAIRING_ENTRY, MAX_PAIRINGS, PAIRING_TOLERANCE,
    QuotientSpace, SPACE_NAMES, SpaceKind, VERTEX_MERGE, clausen, lobachevsky, orthoscheme_volume,
};
pub use sphere::HSphere;

pub use glam;
