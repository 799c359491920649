//! Triangle meshes: many planar h-triangles behind one bounding-volume
//! hierarchy in Klein coordinates.
//!
//! A [`TriangleMesh`] is a list of interior h-points and a list of index
//! triples. Each triple is the h-triangle spanned by its three vertices (their
//! convex hull): in the Klein model a Euclidean triangle, on the hyperboloid
//! the cone over it.
//!
//! **Local frame.** The geometry is stored once, in a frame centred on the
//! mesh (its hyperboloid barycentre moved to the origin), where Klein
//! coordinates and hyperboloid vectors are well conditioned; a placement
//! isometry (local to world) is kept beside it. [`TriangleMesh::transformed`]
//! only composes the placement and shares the local data through an [`Arc`],
//! so moving a 100,000-triangle mesh into a camera frame costs O(1).
//!
//! **Acceleration.** Geodesics are straight lines of the Klein model and
//! h-triangles are Euclidean triangles there, so the axis-aligned box of a
//! triangle's three Klein vertices contains the whole triangle: a BVH of such
//! boxes (binned SAH, flattened) bounds the mesh exactly, and a ray is a
//! straight segment through it. The box tests are padded by a bound on the
//! rounding of the ray's Klein segment, so they never cull a triangle the
//! exact test would accept (`docs/geometry.md`, section 13.1).
//!
//! **The exact test.** The ray's geodesic spans the 2-plane `span(X, V)` of
//! `R^{3,1}`. Projecting along it onto the quotient `R^{3,1} / span(X, V)`
//! (two linear forms `<F,.>`, `<G,.>` vanishing on `X` and `V`) sends every
//! vertex `A` to a point `a` of the plane, and `det(X, V, A, B)` is a fixed
//! positive multiple of the 2-D cross product `a x b`. The geodesic meets the
//! triangle iff the origin of that plane lies in the 2-D triangle `abc`,
//! i.e. iff the three cross products `a x b`, `b x c`, `c x a` agree in
//! sign. They are evaluated with an exact sign (an error-free product
//! fallback), each vertex projected once per ray, so a ray through a shared
//! edge or vertex of a closed mesh cannot slip between its triangles. The
//! crossing itself is [`HPlane::crossing`](crate::HPlane::crossing) of the triangle's world plane.
//!
//! ```
//! use glam::DVec3;
//! use hgeom::{lorentz, Point, Ray, TriangleMesh};
//!
//! // A regular tetrahedron of circumradius R about the origin, faces
//! // counter-clockwise seen from outside.
//! let r = 0.8f64;
//! let corners = [(1.0, 1.0, 1.0), (1.0, -1.0, -1.0), (-1.0, 1.0, -1.0), (-1.0, -1.0, 1.0)];
//! let vertices = corners
//!     .iter()
//!     .map(|&(x, y, z)| Point::at_distance_from_origin(DVec3::new(x, y, z), r).unwrap())
//!     .collect();
//! let faces = vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
//! let mesh = TriangleMesh::new(vertices, faces).unwrap();
//! assert_eq!(mesh.triangle_count(), 4);
//!
//! // From the centre towards the centre of face 0: the right-angled triangle
//! // (origin, face centre, vertex) gives tanh(inradius) = tanh(R) cos(angle),
//! // and the angle between a vertex and a face centre has cosine 1/3.
//! let ray = Ray::from_origin_unchecked(DVec3::new(1.0, 1.0, -1.0));
//! let hit = mesh.intersect(&ray, 0.0, f64::INFINITY).unwrap();
//! assert!((hit.t - (r.tanh() / 3.0).atanh()).abs() < 1e-14);
//! // The ray leaves through the outer side.
//! assert!(lorentz::dot(ray.tangent_at(hit.t), hit.normal) > 0.0);
//! assert!(mesh.blocks(&ray, 0.0, f64::INFINITY));
//! assert!(!mesh.blocks(&ray, 0.0, 0.5 * hit.t));
//! ```

use std::fmt;
use std::sync::Arc;

use glam::{DMat4, DVec4};

use crate::isometry::Isometry;
use crate::point::Point;
use bvh::Node;

mod build;
mod bvh;
mod exact;
mod intersect;
mod normals;
mod placement;
#[cfg(test)]
mod test_support;

pub use normals::GivenNormals;

/// An immutable mesh of planar h-triangles with a Klein-coordinate BVH.
///
/// Invariants: at least one triangle; every vertex an interior h-point
/// ([`Point::is_representable`]), also in the local frame; every kept
/// triangle refers to three distinct vertices that span an h-plane (to a
/// relative 1e-14, the criterion of [`HPlane::through`](crate::HPlane::through)); the local data
/// (vertices, triangle planes, BVH) is shared between the meshes that
/// [`TriangleMesh::transformed`] makes from one another.
///
/// Orientation: a triangle's normal side is the side from which its
/// vertices, in the order of [`TriangleMesh::triangles`], run
/// counter-clockwise (the right-hand rule, as in OBJ and PLY files and
/// [`HPlane::through`](crate::HPlane::through)). For a closed, consistently wound mesh that is the
/// outside. After an orientation-reversing move the normals are the images
/// of the old normals (outside stays outside) and `triangles` reports each
/// winding reversed, so the rule keeps holding.
///
/// Two meshes are equal when they were built from equal vertex and triangle
/// lists and moved by equal isometries.
#[derive(Clone)]
pub struct TriangleMesh {
    shared: Arc<Shared>,
    /// From the frame of the vertices given to [`TriangleMesh::new`] to the
    /// current world frame (the product of every `transformed`).
    moved: Isometry,
    /// From the local frame to the current world frame: `moved ∘ base`.
    placement: Isometry,
    /// The placement's Lorentz matrix (local to world).
    to_world: DMat4,
    /// The inverse placement's Lorentz matrix (world to local).
    to_local: DMat4,
    /// Vertex normals for smooth shading ([`TriangleMesh::smoothed`]).
    smooth: Option<Arc<normals::Smooth>>,
}

/// What every moved copy of a mesh shares.
///
/// Memory: per vertex 64 bytes (`input`, `local`), per kept triangle 16
/// (`tris`, `order`) and about 20 of BVH nodes. Nothing per triangle is
/// copied from its vertices: the exact test reads the shared local
/// vertices through the indices, and a triangle's plane is recomputed from
/// them, bit for bit as the build computed it, only for the few triangles
/// the geodesic meets. The local vertices as points (for
/// [`TriangleMesh::vertices`] after a move) and the kept triangles in the
/// given order are likewise recomputed when asked for, not stored.
struct Shared {
    /// The vertices as given.
    input: Vec<Point>,
    /// The vertices in the local frame, on the hyperboloid (what the
    /// intersection uses; every triangle reads a shared vertex from here,
    /// so it projects identically for all of them).
    local: Vec<DVec4>,
    /// The kept triangles (indices into `input` and `local`, wound as
    /// given), in BVH leaf order.
    tris: Vec<[u32; 3]>,
    /// For each entry of `tris`, its index among the kept triangles in the
    /// order given.
    order: Vec<u32>,
    /// How many triangles were dropped as degenerate.
    dropped: usize,
    /// From the local frame to the frame of `input`.
    base: Isometry,
    /// The flattened BVH; `nodes[0]` is the root.
    nodes: Vec<Node>,
    /// The largest distance of a kept triangle's vertex from the local origin.
    radius: f64,
    /// The largest 1-norm of a kept triangle's local hyperboloid vertex: the
    /// scale of the rounding of a vertex's projection.
    scale: f64,
}

impl Shared {
    /// The local hyperboloid vertices of the triangle at leaf position `pos`.
    #[inline]
    fn corners(&self, pos: usize) -> [DVec4; 3] {
        self.tris[pos].map(|k| self.local[k as usize])
    }

    /// The vertex `k` as a point of the local frame: the given point moved
    /// by the inverse of `base`, computed as the build computed it (so its
    /// hyperboloid image is `local[k]` bit for bit).
    fn local_point(&self, back: &Isometry, k: usize) -> Point {
        placement::settled(back.apply(&self.input[k]))
    }

    /// The kept triangles in the order given.
    fn given_order(&self) -> Vec<[u32; 3]> {
        let mut triangles = vec![[0u32; 3]; self.tris.len()];
        for (t, &k) in self.tris.iter().zip(&self.order) {
            triangles[k as usize] = *t;
        }
        triangles
    }
}

impl TriangleMesh {
    /// The number of (kept) triangles.
    ///
    /// # Accuracy
    ///
    /// Exact.
    pub fn triangle_count(&self) -> usize {
        self.shared.tris.len()
    }

    /// The number of vertices (as given, used or not).
    ///
    /// # Accuracy
    ///
    /// Exact.
    pub fn vertex_count(&self) -> usize {
        self.shared.input.len()
    }

    /// How many of the given triangles were dropped as degenerate (a
    /// repeated index, or three vertices on one h-line).
    ///
    /// # Accuracy
    ///
    /// Exact: counted by [`TriangleMesh::new`] with the relative 1e-14
    /// criterion of [`HPlane::through`](crate::HPlane::through).
    pub fn dropped_triangles(&self) -> usize {
        self.shared.dropped
    }
}

impl fmt::Debug for TriangleMesh {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TriangleMesh")
            .field("vertices", &self.vertex_count())
            .field("triangles", &self.triangle_count())
            .field("dropped", &self.dropped_triangles())
            .field("placement", &self.placement)
            .finish()
    }
}

impl PartialEq for TriangleMesh {
    fn eq(&self, other: &TriangleMesh) -> bool {
        let (a, b) = (&*self.shared, &*other.shared);
        self.moved == other.moved
            && self.smooth == other.smooth
            && (Arc::ptr_eq(&self.shared, &other.shared)
                || (a.input == b.input
                    && a.tris == b.tris
                    && a.order == b.order
                    && a.dropped == b.dropped))
    }
}
