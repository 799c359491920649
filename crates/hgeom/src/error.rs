//! Typed errors for constructors that check invariants.

use thiserror::Error;

/// Why a geometric object could not be built.
///
/// Every fallible constructor in hgeom (the `try_*` functions and the
/// named constructors that return `Result`, such as
/// [`HPlane::through`](crate::HPlane::through)) reports one of these; no
/// constructor clamps its input into range instead.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum GeomError {
    /// A coordinate is NaN or infinite.
    #[error("coordinates must be finite")]
    NotFinite,
    /// An h-point must lie strictly inside the unit ball.
    #[error("point lies on the absolute or too close to it for f64 (|x| = {norm})")]
    NotInBall {
        /// Euclidean norm of the offending point.
        norm: f64,
    },
    /// An ideal point must lie on the unit sphere.
    #[error("ideal point is not on the absolute (|x| = {norm})")]
    NotOnAbsolute {
        /// Euclidean norm of the offending point.
        norm: f64,
    },
    /// Two points that must be distinct coincide (or are numerically indistinguishable).
    #[error("points coincide")]
    Coincident,
    /// Three or more points that must span a plane lie on one h-line.
    #[error("points are collinear")]
    Collinear,
    /// A radius or thickness must be positive and finite.
    #[error("radius must be positive and finite, got {}", crate::compact::Compact(*.0))]
    BadRadius(f64),
    /// A polygon needs at least three vertices.
    #[error("a polygon needs at least 3 vertices, got {0}")]
    TooFewVertices(usize),
    /// The polygon's vertices do not lie on one h-plane.
    #[error("vertex {index} is off the polygon's plane by {offset:e}")]
    NonPlanar {
        /// Zero-based index of the vertex farthest from the plane.
        index: usize,
        /// Its (hyperboloid) offset from the plane.
        offset: f64,
    },
    /// The polygon is not convex, or its vertices are not in cyclic order.
    #[error("polygon is not convex at vertex {index}")]
    NonConvex {
        /// Zero-based index of the vertex where convexity fails.
        index: usize,
    },
    /// A direction vector must be non-zero and finite.
    #[error("direction must be a non-zero finite vector")]
    BadDirection,
    /// A crease angle (in degrees) must be a number in `0..=180`.
    #[error("crease angle {0} is outside 0..=180 degrees")]
    BadCreaseAngle(f64),
    /// A predefined figure was asked for with a vertex count it does not support.
    #[error("vertex count {got} is outside {min}..={max}")]
    VertexCountOutOfRange {
        /// The requested count.
        got: usize,
        /// Smallest supported count.
        min: usize,
        /// Largest supported count.
        max: usize,
    },
    /// A Lambert quadrilateral with sides `a`, `b` at its right-angled vertex
    /// closes only when `sinh a sinh b < 1`.
    #[error("no Lambert quadrilateral: sinh a sinh b = {sinh_product} >= 1")]
    LambertOpen {
        /// `sinh a * sinh b`.
        sinh_product: f64,
    },
    /// An angle outside the range a construction admits.
    #[error("angle {} rad is outside the admissible range", crate::compact::Compact(*.0))]
    BadAngle(f64),
    /// A matrix that must be orthogonal is not (to the stated tolerance).
    #[error("matrix is not orthogonal (max |Q Q^T - I| = {defect:e})")]
    NotOrthogonal {
        /// The largest entry of `Q Q^T - I` in absolute value.
        defect: f64,
    },
    /// A tessellation would exceed the cell budget.
    #[error("tessellation exceeds {limit} cells")]
    TooManyCells {
        /// The cell budget.
        limit: usize,
    },
    /// A honeycomb's colouring needs at least one class.
    #[error("a honeycomb needs at least 1 cell class, got 0")]
    NoCellClasses,
    /// The ringed nodes of a Coxeter diagram are some of 0, 1, 2 and 3,
    /// at least one.
    #[error("the ringed nodes must be some of 0, 1, 2 and 3, at least one")]
    BadRings,
    /// A depth or cell colours were asked of a uniform honeycomb other than
    /// the regular one: its cells are of several kinds, and neither is
    /// defined for them.
    #[error("depth and cell colours are for regular honeycombs (node 0 ringed alone)")]
    UniformWithCells,
    /// Colouring by parity asked of a honeycomb with an odd number `r` of
    /// cells round each edge: that cycle of neighbours cannot alternate.
    #[error(
        "{{p,q,{r}}} has {r} cells round each edge, an odd cycle: its cells have no two-colouring"
    )]
    OddEdgeCycle {
        /// The number of cells round an edge.
        r: u32,
    },
    /// A fundamental domain that is not one: infinite volume, or faces
    /// that do not close up.
    #[error("not a fundamental domain: {0}")]
    BadDomain(String),
    /// A face pairing that does not map its face onto its partner, or
    /// whose partner's pairing is not its inverse.
    #[error("the pairing of face {face} {problem}")]
    BadPairing {
        /// The face (1-based).
        face: usize,
        /// What is wrong, in words.
        problem: String,
    },
    /// A face pairing that fails a test by more than its tolerance (each
    /// tolerance scales with the size of what it compares:
    /// docs/manifolds.md): the measured error and the tolerance are given.
    #[error(
        "the pairing of face {face} {problem} (measured error {error:.2e}, tolerance {tolerance:.2e})"
    )]
    InexactPairing {
        /// The face (1-based, the pairing's place in the file).
        face: usize,
        /// What it fails to do, in words.
        problem: &'static str,
        /// The measured error.
        error: f64,
        /// The tolerance it exceeded.
        tolerance: f64,
    },
    /// The dihedral angles around an edge cycle do not close up (a
    /// manifold needs 2π and the identity; a mirror needs the Coxeter
    /// relation).
    #[error(
        "the edge cycle of faces {faces:?} has angle sum {degrees} degrees and does not close (measured error {error:.2e}, tolerance {tolerance:.2e})"
    )]
    EdgeCycle {
        /// The faces crossed around the cycle (1-based).
        faces: Vec<usize>,
        /// The sum of its dihedral angles, in degrees.
        degrees: f64,
        /// The larger of the angle sum's distance from its target (in
        /// radians) and the holonomy's from the identity, each over its
        /// own tolerance times `tolerance`.
        error: f64,
        /// The tolerance of the larger one.
        tolerance: f64,
    },
    /// More copies of an object or light than the limit would be needed
    /// (an object too large for the domain, or one deep in a cusp).
    #[error("more than {limit} copies of it would be needed to show it whole in the space")]
    TooManyCopies {
        /// The limit.
        limit: usize,
    },
    /// A mesh triangle refers to a vertex that does not exist.
    #[error("triangle {triangle} refers to vertex {index}, but the mesh has {vertices} vertices")]
    MeshIndexOutOfRange {
        /// Zero-based index of the offending triangle.
        triangle: usize,
        /// The vertex index it gives.
        index: u32,
        /// How many vertices there are.
        vertices: usize,
    },
    /// A mesh needs vertices and at least one triangle of non-zero area.
    #[error("the mesh has no triangle of non-zero area ({dropped} degenerate triangles dropped)")]
    EmptyMesh {
        /// How many degenerate triangles were dropped.
        dropped: usize,
    },
}

/// `Ok` for a positive finite length (a radius, side or circumradius), else
/// [`GeomError::BadRadius`].
pub(crate) fn positive_length(x: f64) -> Result<(), GeomError> {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        Err(GeomError::BadRadius(x))
    }
}
