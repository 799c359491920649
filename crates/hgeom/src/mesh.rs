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
//! crossing itself is [`HPlane::crossing`] of the triangle's world plane.
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

use std::borrow::Cow;
use std::fmt;
use std::sync::Arc;

use glam::{DMat4, DVec3, DVec4};

use crate::accurate::two_prod;
use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::plane::HPlane;
use crate::point::Point;
use crate::ray::{Hit, Ray};

mod normals;

pub use normals::GivenNormals;

/// A triangle is dropped as degenerate when its Lorentz normal is below this
/// fraction of the size of the vectors it is formed from (the criterion of
/// [`HPlane::through`]): its three vertices lie on one h-line to rounding.
const DEGENERATE_TOLERANCE: f64 = 1e-14;
/// Bins of the SAH split search.
const BINS: usize = 16;
/// The SAH may keep up to this many triangles in a leaf.
const MAX_LEAF: usize = 8;
/// Below this depth splits are chosen by the SAH; deeper, by the median
/// (which halves the count, so the depth stays bounded however the SAH
/// splits went: 2^30 triangles need 30 more levels at most).
const SAH_DEPTH: usize = 32;
/// No node is deeper than this (a leaf is forced there).
const MAX_DEPTH: usize = 62;
/// The traversal stack: at most one entry per level, plus the root.
const STACK: usize = MAX_DEPTH + 2;
/// Points with a larger gap (within ~8 of the origin) are settled: their
/// gap is recomputed from their coordinates (see [`settled`]).
const SETTLE_GAP: f64 = 1e-3;

/// An immutable mesh of planar h-triangles with a Klein-coordinate BVH.
///
/// Invariants: at least one triangle; every vertex an interior h-point
/// ([`Point::is_representable`]), also in the local frame; every kept
/// triangle refers to three distinct vertices that span an h-plane (to a
/// relative 1e-14, the criterion of [`HPlane::through`]); the local data
/// (vertices, triangle planes, BVH) is shared between the meshes that
/// [`TriangleMesh::transformed`] makes from one another.
///
/// Orientation: a triangle's normal side is the side from which its
/// vertices, in the order of [`TriangleMesh::triangles`], run
/// counter-clockwise (the right-hand rule, as in OBJ and PLY files and
/// [`HPlane::through`]). For a closed, consistently wound mesh that is the
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
struct Shared {
    /// The vertices as given.
    input: Vec<Point>,
    /// The vertices in the local frame (what the intersection uses).
    local: Vec<Point>,
    /// The kept triangles, in the order given.
    triangles: Vec<[u32; 3]>,
    /// How many triangles were dropped as degenerate.
    dropped: usize,
    /// From the local frame to the frame of `input`.
    base: Isometry,
    /// The kept triangles in the local frame, in BVH leaf order.
    tris: Vec<Tri>,
    /// For each entry of `tris`, its index in `triangles`.
    order: Vec<u32>,
    /// The flattened BVH; `nodes[0]` is the root.
    nodes: Vec<Node>,
    /// The largest distance of a kept triangle's vertex from the local origin.
    radius: f64,
    /// The largest 1-norm of a kept triangle's local hyperboloid vertex: the
    /// scale of the rounding of a vertex's projection.
    scale: f64,
}

/// One triangle in the local frame.
#[derive(Clone, Copy)]
struct Tri {
    /// The hyperboloid vertices (copies of the shared local vertices, bit for
    /// bit, so every triangle projects a shared vertex identically).
    v: [DVec4; 3],
    /// The oriented plane (right-hand rule with `v`).
    plane: HPlane,
}

/// A BVH node: a Klein box, and either a leaf's triangle range
/// (`count > 0`, `tris[first .. first + count]`) or, for an interior node
/// (`count == 0`), the index of its second child (the first is next).
#[derive(Clone, Copy)]
struct Node {
    lo: DVec3,
    hi: DVec3,
    first: u32,
    count: u32,
}

impl TriangleMesh {
    /// Build a mesh from interior vertices and index triples.
    ///
    /// Triangles with a repeated index, or whose three vertices lie on one
    /// h-line (zero area, to a relative 1e-14), are dropped and counted
    /// ([`TriangleMesh::dropped_triangles`]).
    ///
    /// Errors: [`GeomError::EmptyMesh`] when there are no vertices, no
    /// triangles, or no triangle survives; [`GeomError::MeshIndexOutOfRange`]
    /// for an index past the vertex list; [`GeomError::NotFinite`] or
    /// [`GeomError::NotInBall`] for a vertex that is not a representable
    /// interior point, or one more than ~37 from the mesh's centre (which f64
    /// cannot place in the local frame).
    ///
    /// # Accuracy
    ///
    /// Each vertex is moved into the local frame by one isometry (a Möbius
    /// addition, a few `fuzz` of the vertex and of the centre), and each
    /// triangle's plane is computed there from vectors of moderate size, so
    /// its normal is accurate to a few ulps per component; hits then agree
    /// with [`ConvexPolygon`](crate::ConvexPolygon) triangles to 5e-12 in
    /// `t` (relative for `t > 1`; measured 2e-12) for rays from the origin
    /// to meshes up to 5 away (`mesh_hits_agree_with_convex_polygons` in
    /// `tests/mesh.rs`). Building is O(n log n) in the triangle count
    /// (0.45 ms for 2016 triangles, `benches/kernels.rs`).
    pub fn new(vertices: Vec<Point>, triangles: Vec<[u32; 3]>) -> Result<TriangleMesh, GeomError> {
        if vertices.is_empty() || triangles.is_empty() {
            return Err(GeomError::EmptyMesh { dropped: 0 });
        }
        for p in &vertices {
            if !p.coords().is_finite() {
                return Err(GeomError::NotFinite);
            }
            if !p.is_representable() {
                return Err(GeomError::NotInBall {
                    norm: p.coords().length(),
                });
            }
        }
        let n = vertices.len();
        for (triangle, t) in triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&k| k as usize >= n) {
                return Err(GeomError::MeshIndexOutOfRange {
                    triangle,
                    index,
                    vertices: n,
                });
            }
        }
        let base = local_frame(&vertices);
        let back = base.inverse();
        let mut points = Vec::with_capacity(n);
        let mut local = Vec::with_capacity(n);
        let mut distance = Vec::with_capacity(n);
        for p in &vertices {
            let q = settled(back.apply(p));
            if !q.is_representable() {
                return Err(GeomError::NotInBall {
                    norm: p.coords().length(),
                });
            }
            points.push(q);
            local.push(q.to_hyperboloid());
            distance.push(q.distance_from_origin());
        }
        let mut kept = Vec::with_capacity(triangles.len());
        let mut tris = Vec::with_capacity(triangles.len());
        let mut dropped = 0;
        for t in triangles {
            let v = t.map(|k| local[k as usize]);
            match local_plane(t, v) {
                Some(plane) => {
                    kept.push(t);
                    tris.push(Tri { v, plane });
                }
                None => dropped += 1,
            }
        }
        if kept.is_empty() {
            return Err(GeomError::EmptyMesh { dropped });
        }
        let (mut radius, mut scale) = (0.0f64, 0.0f64);
        for t in &kept {
            for &k in t {
                radius = radius.max(distance[k as usize]);
                scale = scale.max(local[k as usize].abs().element_sum());
            }
        }
        let (nodes, order) = build_bvh(&tris);
        let tris = order.iter().map(|&i| tris[i as usize]).collect();
        let shared = Shared {
            input: vertices,
            local: points,
            triangles: kept,
            dropped,
            base,
            tris,
            order,
            nodes,
            radius,
            scale,
        };
        Ok(TriangleMesh::placed(Arc::new(shared), Isometry::IDENTITY))
    }

    fn placed(shared: Arc<Shared>, moved: Isometry) -> TriangleMesh {
        let placement = settled_isometry(moved.compose(&shared.base));
        TriangleMesh {
            to_world: placement.to_lorentz(),
            to_local: placement.inverse().to_lorentz(),
            shared,
            moved,
            placement,
            smooth: None,
        }
    }

    /// The number of (kept) triangles.
    ///
    /// # Accuracy
    ///
    /// Exact.
    pub fn triangle_count(&self) -> usize {
        self.shared.triangles.len()
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
    /// criterion of [`HPlane::through`].
    pub fn dropped_triangles(&self) -> usize {
        self.shared.dropped
    }

    /// The vertices in the current world frame, in the order given.
    ///
    /// Borrowed (the very points given to [`TriangleMesh::new`]) until the
    /// mesh is moved; afterwards each is the image, under the placement, of
    /// the local vertex the intersection uses, computed here (O(n)). So a
    /// moved mesh's vertices are exactly as consistent with its hits as an
    /// unmoved mesh's are.
    ///
    /// # Accuracy
    ///
    /// Exact before any move. After, one [`Isometry::apply`] (a few `fuzz`
    /// of the image and of the placement's translation part) of a local
    /// vertex, which is itself within a few `fuzz` of the given point moved
    /// into the local frame: a mesh moved next to the origin reports its
    /// vertices to about 1e-15 (`long_chains_of_moves_stay_accurate` in
    /// `tests/mesh.rs`: 1e-9 after 1000 moves and back). A mesh given far
    /// out carries the `fuzz` of its given coordinates (about 1e-3 at
    /// `1 - |x| = 1e-12`) into the local frame once, and its moved images
    /// are consistent with its hits, not with a re-moved copy of the given
    /// points (`mesh_next_to_the_absolute`).
    pub fn vertices(&self) -> Cow<'_, [Point]> {
        if self.moved == Isometry::IDENTITY {
            Cow::Borrowed(&self.shared.input)
        } else {
            Cow::Owned(
                self.shared
                    .local
                    .iter()
                    .map(|p| self.placement.apply(p))
                    .collect(),
            )
        }
    }

    /// The kept triangles as index triples into [`TriangleMesh::vertices`],
    /// in the order given, wound so that the normal side follows the
    /// right-hand rule (reversed, `[a, c, b]`, after an orientation-reversing
    /// move; borrowed otherwise).
    ///
    /// # Accuracy
    ///
    /// Exact.
    pub fn triangles(&self) -> Cow<'_, [[u32; 3]]> {
        if self.moved.preserves_orientation() {
            Cow::Borrowed(&self.shared.triangles)
        } else {
            Cow::Owned(
                self.shared
                    .triangles
                    .iter()
                    .map(|&[a, b, c]| [a, c, b])
                    .collect(),
            )
        }
    }

    /// The isometry from the mesh's local frame (where it is centred on the
    /// origin) to the world frame.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored placement (a composition of the moves with the
    /// local frame, each to [`Isometry::compose`]'s accuracy).
    pub fn placement(&self) -> Isometry {
        self.placement
    }

    /// The image under an isometry, in O(1): the local data is shared and
    /// only the placement is composed.
    ///
    /// # Accuracy
    ///
    /// [`Isometry::compose`] of the move with the stored placement: drift
    /// over long chains is that of the gyrovector composition (1000 random
    /// moves and their inverses return hits to 1e-9,
    /// `long_chains_of_moves_stay_accurate` in `tests/mesh.rs`); a moved
    /// mesh intersects like the original intersected with the inversely
    /// moved ray (`moving_the_mesh_equals_moving_the_ray`).
    pub fn transformed(&self, iso: &Isometry) -> TriangleMesh {
        // The first move is stored as given (composing with the identity
        // would round it).
        let moved = if self.moved == Isometry::IDENTITY {
            *iso
        } else {
            iso.compose(&self.moved)
        };
        let mut mesh = TriangleMesh::placed(Arc::clone(&self.shared), moved);
        mesh.smooth.clone_from(&self.smooth);
        mesh
    }

    /// A ball containing the whole mesh: its centre on the hyperboloid (in
    /// the world frame) and its hyperbolic radius, the shape of a renderer's
    /// bounding h-sphere.
    ///
    /// # Accuracy
    ///
    /// The centre is the placement's image of the local origin; the radius
    /// is the largest local distance of a vertex of a kept triangle (1e-14
    /// relative), so the ball contains every triangle (h-balls are convex).
    /// It is padded by `1e-9 (1 + r) + 64 eps |C| e^r`, which covers the
    /// rounding of the placement and of the moved vertices, so it contains
    /// [`TriangleMesh::vertices`]; hit points lie in it up to their own
    /// error (see [`TriangleMesh::intersect`];
    /// `bounding_ball_contains_vertices_and_hits` in `tests/mesh.rs`).
    pub fn bounding_ball(&self) -> (DVec4, f64) {
        let center = self.placement.translation_part().to_hyperboloid();
        let r = self.shared.radius;
        // The rounding of the placement and of the moved vertices: a few
        // `fuzz` (eps / gap, about eps |X| / 2) of points up to r from the
        // centre.
        let pad = 1e-9 * (1.0 + r) + 64.0 * f64::EPSILON * center.length() * r.exp();
        (center, r + pad)
    }

    /// The first intersection with `t` in `(t_min, t_max)`, with the same
    /// contract as [`ConvexPolygon::intersect`](crate::ConvexPolygon::intersect):
    /// `None` for a miss, a ray parallel to a triangle's plane, or a
    /// non-finite ray. Triangles are two-sided; the hit normal is the unit
    /// normal of the triangle's plane on its counter-clockwise side (see the
    /// type docs), which is tangent at every point of the plane.
    ///
    /// The ray is carried into the local frame by the inverse placement's
    /// Lorentz matrix; the BVH and the inside test run there (see the module
    /// docs), and the crossing is solved with the triangle's plane carried
    /// out to the world frame ([`HPlane::crossing`], cancellation-free for
    /// rays from the origin), so `t`, the point ([`Ray::at`]) and the
    /// normal need no transformation back. Ties in `t` go to the triangle
    /// listed first.
    ///
    /// # Accuracy
    ///
    /// `t` as [`HPlane::crossing`] of the triangle's plane, whose normal is
    /// accurate to a few ulps per component: within 5e-12 (relative for
    /// `t > 1`; measured 2e-12) of the same triangle as a
    /// [`ConvexPolygon`](crate::ConvexPolygon) for rays from the origin to
    /// meshes up to 5 away, and within the polygon's own rounding scale
    /// (`plane_hit_tol`, measured 8e-12) for rays starting within 2 of the
    /// mesh (`mesh_hits_agree_with_convex_polygons` in `tests/mesh.rs`).
    /// Hit points lie on their plane to the rounding of [`Ray::at`]
    /// (`|<P,N>| / (|P| |N|)` measured 5e-15). The inside test is
    /// exact for the rounded projections, whose error is about
    /// `eps |X|^2 |A|` with `X` the ray origin in the local frame and `A` a
    /// vertex (so about `eps e^{2d}` for a ray starting `d` from the mesh's
    /// centre): a ray can count as hitting within that of an edge, but rays
    /// through shared edges and vertices of a closed mesh never miss
    /// (`rays_through_edges_and_vertices_never_miss`).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        self.intersect_indexed(ray, t_min, t_max)
            .map(|(hit, _)| hit)
    }

    /// [`TriangleMesh::intersect`], with the index of the triangle hit (into
    /// [`TriangleMesh::triangles`]).
    ///
    /// # Accuracy
    ///
    /// As [`TriangleMesh::intersect`].
    pub fn intersect_indexed(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(Hit, usize)> {
        let sh = &*self.shared;
        let local = self.local_ray(ray);
        let probe = Probe::new(&local, sh.scale)?;
        let s_lo = probe.lower(t_min);
        let mut s_hi = probe.upper(t_max);
        let mut best: Option<Candidate> = None;
        let mut best_t = t_max;
        let mut stack = [(0u32, 0.0f64); STACK];
        let mut sp = 0;
        if let Some(e) = probe.enter(&sh.nodes[0], s_lo, s_hi) {
            stack[0] = (0, e);
            sp = 1;
        }
        while sp > 0 {
            sp -= 1;
            let (index, entry) = stack[sp];
            if entry > s_hi {
                continue;
            }
            let node = &sh.nodes[index as usize];
            if node.count > 0 {
                let first = node.first as usize;
                for pos in first..first + node.count as usize {
                    let Some((t, normal)) = self.crossing(&probe, pos, ray, &local) else {
                        continue;
                    };
                    let triangle = sh.order[pos] as usize;
                    let closer =
                        t < best_t || (t == best_t && best.is_some_and(|b| triangle < b.triangle));
                    if t > t_min && closer {
                        best = Some(Candidate {
                            t,
                            normal,
                            triangle,
                        });
                        best_t = t;
                        s_hi = s_hi.min(probe.prune(t));
                    }
                }
            } else {
                let (a, b) = (index + 1, node.first);
                let ea = probe.enter(&sh.nodes[a as usize], s_lo, s_hi);
                let eb = probe.enter(&sh.nodes[b as usize], s_lo, s_hi);
                // Push the farther child first, so the nearer is visited first.
                let (near, far) = match (ea, eb) {
                    (Some(x), Some(y)) if y < x => (Some((b, y)), Some((a, x))),
                    _ => (ea.map(|x| (a, x)), eb.map(|y| (b, y))),
                };
                for item in [far, near].into_iter().flatten() {
                    stack[sp] = item;
                    sp += 1;
                }
            }
        }
        best.map(|c| (self.hit(ray, c), c.triangle))
    }

    /// Whether any triangle is met with `t` in `(t_min, t_max)`: the shadow
    /// ray form of [`TriangleMesh::intersect`], stopping at the first hit
    /// found (in no particular order).
    ///
    /// # Accuracy
    ///
    /// As [`TriangleMesh::intersect`]: true exactly when `intersect` would
    /// return a hit (`blocks_agrees_with_intersect` in this module).
    pub fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let sh = &*self.shared;
        let local = self.local_ray(ray);
        let Some(probe) = Probe::new(&local, sh.scale) else {
            return false;
        };
        let s_lo = probe.lower(t_min);
        let s_hi = probe.upper(t_max);
        let mut stack = [0u32; STACK];
        let mut sp = 0;
        if probe.enter(&sh.nodes[0], s_lo, s_hi).is_some() {
            sp = 1;
        }
        while sp > 0 {
            sp -= 1;
            let node = &sh.nodes[stack[sp] as usize];
            if node.count > 0 {
                let first = node.first as usize;
                for pos in first..first + node.count as usize {
                    let t = self.crossing(&probe, pos, ray, &local).map(|(t, _)| t);
                    if t.is_some_and(|t| t > t_min && t < t_max) {
                        return true;
                    }
                }
            } else {
                let index = stack[sp];
                for child in [index + 1, node.first] {
                    if probe.enter(&sh.nodes[child as usize], s_lo, s_hi).is_some() {
                        stack[sp] = child;
                        sp += 1;
                    }
                }
            }
        }
        false
    }

    /// [`TriangleMesh::intersect_indexed`] without the BVH: every triangle is
    /// tested. The reference the BVH is checked against, and the baseline
    /// of its benchmark; O(n) per ray.
    ///
    /// # Accuracy
    ///
    /// As [`TriangleMesh::intersect`], and identical to it: the same
    /// triangle, `t`, point and normal (`bvh_equals_brute_force` in this
    /// module, random meshes of 2000 triangles).
    pub fn intersect_exhaustive(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(Hit, usize)> {
        let sh = &*self.shared;
        let local = self.local_ray(ray);
        let probe = Probe::new(&local, sh.scale)?;
        let mut best: Option<Candidate> = None;
        for pos in 0..sh.tris.len() {
            let Some((t, normal)) = self.crossing(&probe, pos, ray, &local) else {
                continue;
            };
            let triangle = sh.order[pos] as usize;
            let closer = best.map_or(t < t_max, |b| {
                t < b.t || (t == b.t && triangle < b.triangle)
            });
            if t > t_min && closer {
                best = Some(Candidate {
                    t,
                    normal,
                    triangle,
                });
            }
        }
        best.map(|c| (self.hit(ray, c), c.triangle))
    }

    /// The ray carried into the local frame.
    #[inline]
    fn local_ray(&self, ray: &Ray) -> Ray {
        Ray {
            origin: self.to_local * ray.origin,
            dir: self.to_local * ray.dir,
        }
    }

    /// The exact test of the triangle at leaf position `pos`: if the ray's
    /// geodesic meets it, the arc length of the crossing (of either sign) and
    /// the world normal of its plane.
    #[inline]
    fn crossing(&self, probe: &Probe, pos: usize, ray: &Ray, local: &Ray) -> Option<(f64, DVec4)> {
        let tri = &self.shared.tris[pos];
        if !probe.crosses(tri) {
            return None;
        }
        // The world plane: its normal carried out by the Lorentz matrix and
        // renormalised, as `ConvexPolygon` does. Far out (beyond ~18) the
        // renormalisation cancels; the crossing is then solved in the local
        // frame, where it is as good as the local ray.
        let normal = self.to_world * tri.plane.normal();
        match HPlane::from_normal(normal) {
            Ok(plane) => plane.crossing(ray).map(|t| (t, plane.normal())),
            Err(_) => tri.plane.crossing(local).map(|t| (t, normal)),
        }
    }

    #[inline]
    fn hit(&self, ray: &Ray, c: Candidate) -> Hit {
        let point = ray.at(c.t);
        let shading = match &self.smooth {
            Some(smooth) => self.shading_normal(smooth, c.triangle, point, c.normal),
            None => c.normal,
        };
        Hit {
            t: c.t,
            point,
            normal: c.normal,
            shading,
        }
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
                || (a.input == b.input && a.triangles == b.triangles && a.dropped == b.dropped))
    }
}

/// The nearest crossing found so far.
#[derive(Clone, Copy)]
struct Candidate {
    t: f64,
    normal: DVec4,
    triangle: usize,
}

/// A ray prepared for the local frame: the projection along its geodesic
/// for the exact test, and its Klein segment for the boxes.
struct Probe {
    /// `<F,.>` and `<G,.>` vanish on `X` and `V`: the projection along the
    /// geodesic onto the quotient plane.
    f: DVec4,
    g: DVec4,
    /// The Klein segment from the ray's origin `p1` (s = 0) to its ideal end
    /// (s = 1); `inv` is `1 / (p2 - p1)` per axis.
    p1: DVec3,
    inv: DVec3,
    /// Absolute padding of every box (Klein units) and of the segment
    /// parameter when pruning: bounds on the rounding of the segment and of
    /// the exact test's projection.
    pad: f64,
    prune_pad: f64,
    /// `X0 / (X0 + V0)`, for the map from arc length to segment parameter.
    x0_over_a: f64,
    /// The segment could not be formed (a ray of f64's reach): every box
    /// is entered.
    all: bool,
}

impl Probe {
    fn new(local: &Ray, scale: f64) -> Option<Probe> {
        let (x, v) = (local.origin, local.dir);
        if !(x.is_finite() && v.is_finite()) {
            return None;
        }
        // A basis of the Lorentz complement of span(X, V): the complement of
        // (X, V, e) for the coordinate vector e that gives the longest one,
        // then the vector orthogonal to X, V and that.
        let mut f = DVec4::ZERO;
        let mut best = 0.0;
        for e in [DVec4::X, DVec4::Y, DVec4::Z, DVec4::W] {
            let c = lorentz::orthogonal_complement(x, v, e);
            let q = lorentz::dot(c, c);
            if q > best {
                best = q;
                f = c;
            }
        }
        if !(best > 0.0 && best.is_finite()) {
            return None;
        }
        let f = f / best.sqrt();
        let g = lorentz::orthogonal_complement(x, v, f);
        let gn = lorentz::norm(g);
        if !(gn > 0.0 && gn.is_finite()) {
            return None;
        }
        let g = g / gn;
        // The Klein segment: the origin's Klein point and the ideal end
        // (X + V, a future null vector, scaled to time 1).
        let end = x + v;
        let a = end.w;
        let p1 = x.truncate() / x.w;
        let p2 = end.truncate() / a;
        let d = p2 - p1;
        let size = x.abs().element_sum() + v.abs().element_sum();
        let pad = 64.0 * f64::EPSILON * size * size * (1.0 + scale);
        let all = !(x.w > 0.0 && a > 0.0 && pad.is_finite() && p1.is_finite() && d.is_finite());
        Some(Probe {
            f,
            g,
            p1,
            inv: d.recip(),
            pad,
            prune_pad: 1e-9 + 4.0 * pad / d.length(),
            x0_over_a: x.w / a,
            all,
        })
    }

    /// The segment parameter of the ray's point at arc length `t`: with
    /// `X(t) = e^{-t} X + sinh t (X + V)`, the Klein point is
    /// `p1 + s (p2 - p1)` with `s = 1 / (1 + 2 (X0/(X0+V0)) / expm1(2t))`,
    /// increasing from `0` at `t = 0` to `1` at `t = inf`.
    #[inline]
    fn param(&self, t: f64) -> f64 {
        1.0 / (1.0 + 2.0 * self.x0_over_a / (2.0 * t).exp_m1())
    }

    /// A lower bound on the segment parameter of `t_min`: none for
    /// `t_min < 0` (what lies behind the origin is not worth culling), and
    /// `param(0) = 0` for the tiny `t_min` of secondary rays (`param` is
    /// increasing, so that is a lower bound, and it saves an `expm1`).
    #[inline]
    fn lower(&self, t_min: f64) -> f64 {
        if self.all || !(t_min >= 0.0) {
            f64::NEG_INFINITY
        } else if t_min < 1e-6 {
            -self.prune_pad
        } else {
            self.param(t_min) - self.prune_pad
        }
    }

    /// An upper bound on the segment parameter of `t_max`.
    #[inline]
    fn upper(&self, t_max: f64) -> f64 {
        if self.all {
            f64::INFINITY
        } else {
            self.param(t_max) + self.prune_pad
        }
    }

    /// An upper bound on the segment parameter up to which a crossing
    /// nearer than `t` can still lie.
    #[inline]
    fn prune(&self, t: f64) -> f64 {
        self.upper(t)
    }

    /// Where the segment, restricted to `[s_lo, s_hi]`, enters the node's
    /// padded box; `None` if it misses it.
    #[inline]
    fn enter(&self, node: &Node, s_lo: f64, s_hi: f64) -> Option<f64> {
        if self.all {
            return Some(s_lo);
        }
        let lo = (node.lo - self.pad - self.p1) * self.inv;
        let hi = (node.hi + self.pad - self.p1) * self.inv;
        let mut near = s_lo;
        let mut far = s_hi;
        for (a, b) in [(lo.x, hi.x), (lo.y, hi.y), (lo.z, hi.z)] {
            near = near.max(a.min(b));
            far = far.min(a.max(b));
        }
        (near <= far).then_some(near)
    }

    /// The vertex projected along the geodesic.
    #[inline]
    fn project(&self, a: DVec4) -> (f64, f64) {
        (lorentz::dot(self.f, a), lorentz::dot(self.g, a))
    }

    /// Whether the geodesic meets the triangle: the origin of the quotient
    /// plane lies in the projected triangle (closed), i.e. the three cross
    /// products agree in sign (zeros agree with both).
    #[inline]
    fn crosses(&self, tri: &Tri) -> bool {
        let [a, b, c] = tri.v.map(|p| self.project(p));
        let u = cross(a, b);
        let v = cross(b, c);
        let w = cross(c, a);
        (u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0)
    }
}

/// `a.x b.y - a.y b.x` with the exact sign (or zero) of that expression in
/// the given floats, and exactly antisymmetric: `cross(b, a) == -cross(a, b)`.
///
/// The plain difference is returned when it exceeds its rounding
/// (`4 eps (|p| + |q|)`); otherwise `p` and `q` are within a factor 2 of each
/// other, so `p - q` is exact (Sterbenz), and the low parts of the products
/// (error-free, [`two_prod`]) decide. Rounding can only turn a nonzero value
/// into zero, never flip its sign.
#[inline]
fn cross(a: (f64, f64), b: (f64, f64)) -> f64 {
    let p = a.0 * b.1;
    let q = a.1 * b.0;
    let d = p - q;
    if d.abs() > 4.0 * f64::EPSILON * (p.abs() + q.abs()) {
        return d;
    }
    let (p, ep) = two_prod(a.0, b.1);
    let (q, eq) = two_prod(a.1, b.0);
    (p - q) + (ep - eq)
}

/// The point with its gap recomputed from its coordinates, if it is within
/// ~8 of the origin.
///
/// A Möbius sum of two far points that lands near the origin (a far mesh
/// moved into its own frame, or into the frame of an eye next to it) has
/// coordinates and a gap that are each within the far operands' `fuzz` of
/// the exact result, but not consistent with each other: `1 - |x|^2` and the
/// gap differ by about that fuzz (1e-5 relative at `1 - |x| ~ 1e-12`). Then
/// the point's Möbius and hyperboloid readings differ by as much, and so
/// would the mesh's vertices and its hits. Near the origin the coordinates
/// determine the gap to a few ulps, so recomputing it loses nothing and makes
/// both readings the same point. Farther out the gap is the more precise
/// quantity and is kept.
fn settled(p: Point) -> Point {
    if p.gap() >= SETTLE_GAP {
        Point::from_coords(p.coords()).unwrap_or(p)
    } else {
        p
    }
}

/// The isometry with its translation part [`settled`], so that its Möbius
/// form and its Lorentz matrix are the same map.
fn settled_isometry(iso: Isometry) -> Isometry {
    let a = iso.translation_part();
    let b = settled(a);
    if (b.gap() - a.gap()).abs() <= 8.0 * f64::EPSILON * a.gap() {
        iso
    } else {
        Isometry::transvection_from_origin(b)
            .compose(&Isometry::orthogonal_unchecked(iso.linear_part()))
    }
}

/// The local frame: the hyperboloid barycentre of the vertices, found with
/// the first vertex moved to the origin (so far-out meshes sum moderate
/// vectors), moved to the origin. Any frame is correct; this one only sets
/// the conditioning, so a failure falls back to the first vertex.
fn local_frame(points: &[Point]) -> Isometry {
    let Some(first) = points.first() else {
        return Isometry::IDENTITY;
    };
    let anchor = Isometry::transvection_from_origin(*first);
    let back = anchor.inverse();
    let sum: DVec4 = points.iter().map(|p| back.apply(p).to_hyperboloid()).sum();
    let mean = sum / points.len() as f64;
    // -<m,m> >= 1 for a mean of hyperboloid points; a rounded value below
    // that (a mesh spanning ~18 or more) only loses the better centre.
    let q = -lorentz::dot(mean, mean);
    let centre = (q.is_finite() && q >= 0.5)
        .then(|| Point::from_hyperboloid(mean / q.sqrt()))
        .flatten()
        .filter(Point::is_representable);
    match centre {
        Some(c) => anchor.compose(&Isometry::transvection_from_origin(c)),
        None => anchor,
    }
}

/// The oriented plane of a triangle in the local frame, or `None` if it is
/// degenerate (a repeated index, or collinear vertices to a relative 1e-14).
fn local_plane(t: [u32; 3], [a, b, c]: [DVec4; 3]) -> Option<HPlane> {
    if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] {
        return None;
    }
    // As `HPlane::through`: differences are better conditioned than the raw
    // vectors, and the right-hand rule orients the normal.
    let n = lorentz::orthogonal_complement(a, b - a, c - a);
    let scale = (b - a).length() * (c - a).length() * a.length();
    if !(lorentz::norm(n) > DEGENERATE_TOLERANCE * scale) {
        return None;
    }
    HPlane::from_normal(n).ok()
}

/// Half the surface area of a box (zero for an empty or inverted one).
fn half_area(lo: DVec3, hi: DVec3) -> f64 {
    let e = (hi - lo).max(DVec3::ZERO);
    e.x * e.y + e.y * e.z + e.z * e.x
}

/// The Klein boxes and their centres, and the BVH over them: the nodes and
/// the leaf order of the triangles.
fn build_bvh(tris: &[Tri]) -> (Vec<Node>, Vec<u32>) {
    let boxes: Vec<(DVec3, DVec3)> = tris
        .iter()
        .map(|t| {
            let k = t.v.map(|v| v.truncate() / v.w);
            (k[0].min(k[1]).min(k[2]), k[0].max(k[1]).max(k[2]))
        })
        .collect();
    let centres: Vec<DVec3> = boxes.iter().map(|(lo, hi)| 0.5 * (*lo + *hi)).collect();
    let mut order: Vec<u32> = (0..tris.len() as u32).collect();
    let mut nodes = Vec::with_capacity(2 * tris.len());
    let builder = Builder {
        boxes: &boxes,
        centres: &centres,
    };
    builder.node(&mut nodes, &mut order, 0, 0);
    (nodes, order)
}

struct Builder<'a> {
    boxes: &'a [(DVec3, DVec3)],
    centres: &'a [DVec3],
}

impl Builder<'_> {
    /// Build the subtree over `items` (which start at leaf position
    /// `first`), reordering them; returns its root's index.
    fn node(&self, nodes: &mut Vec<Node>, items: &mut [u32], first: usize, depth: usize) -> u32 {
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &i in items.iter() {
            let (l, h) = self.boxes[i as usize];
            lo = lo.min(l);
            hi = hi.max(h);
        }
        let me = nodes.len();
        nodes.push(Node {
            lo,
            hi,
            first: first as u32,
            count: items.len() as u32,
        });
        let split = if depth >= MAX_DEPTH {
            None
        } else {
            self.split(items, depth, half_area(lo, hi))
        };
        if let Some(mid) = split {
            let (left, right) = items.split_at_mut(mid);
            self.node(nodes, left, first, depth + 1);
            let second = self.node(nodes, right, first + mid, depth + 1);
            nodes[me].first = second;
            nodes[me].count = 0;
        }
        me as u32
    }

    /// Where to split `items` (after reordering them), or `None` for a leaf.
    fn split(&self, items: &mut [u32], depth: usize, area: f64) -> Option<usize> {
        let n = items.len();
        if n <= 2 {
            return None;
        }
        let (mut clo, mut chi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &i in items.iter() {
            let c = self.centres[i as usize];
            clo = clo.min(c);
            chi = chi.max(c);
        }
        let extent = chi - clo;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        if !(extent[axis] > 0.0) {
            // Every centre in one place: split by count if a leaf would be
            // too big.
            return (n > MAX_LEAF).then_some(n / 2);
        }
        if depth >= SAH_DEPTH {
            return Some(self.median(items, axis));
        }
        // Binned SAH along the widest axis of the centres.
        let scale = BINS as f64 / extent[axis];
        let bin = |i: u32| {
            (((self.centres[i as usize][axis] - clo[axis]) * scale) as usize).min(BINS - 1)
        };
        let mut counts = [0usize; BINS];
        let mut bounds = [(DVec3::INFINITY, DVec3::NEG_INFINITY); BINS];
        for &i in items.iter() {
            let b = bin(i);
            let (l, h) = self.boxes[i as usize];
            counts[b] += 1;
            bounds[b] = (bounds[b].0.min(l), bounds[b].1.max(h));
        }
        // Cost of a split after bin k: area-weighted counts of both sides.
        let mut right_cost = [0.0f64; BINS];
        let (mut lo, mut hi, mut count) = (DVec3::INFINITY, DVec3::NEG_INFINITY, 0usize);
        for k in (1..BINS).rev() {
            lo = lo.min(bounds[k].0);
            hi = hi.max(bounds[k].1);
            count += counts[k];
            right_cost[k] = half_area(lo, hi) * count as f64;
        }
        let (mut lo, mut hi, mut count) = (DVec3::INFINITY, DVec3::NEG_INFINITY, 0usize);
        let mut best: Option<(f64, usize)> = None;
        for k in 0..BINS - 1 {
            lo = lo.min(bounds[k].0);
            hi = hi.max(bounds[k].1);
            count += counts[k];
            if count == 0 || count == n {
                continue;
            }
            let cost = half_area(lo, hi) * count as f64 + right_cost[k + 1];
            if best.is_none_or(|(c, _)| cost < c) {
                best = Some((cost, k));
            }
        }
        let Some((cost, k)) = best else {
            return Some(self.median(items, axis));
        };
        // A node costs about one triangle test; keep small sets as leaves
        // when splitting does not pay.
        if n <= MAX_LEAF && area + cost >= area * n as f64 {
            return None;
        }
        // Partition: bins up to k go first.
        let mut mid = 0;
        for j in 0..n {
            if bin(items[j]) <= k {
                items.swap(mid, j);
                mid += 1;
            }
        }
        if mid == 0 || mid == n {
            return Some(self.median(items, axis));
        }
        Some(mid)
    }

    /// Split at the median centre along `axis`.
    fn median(&self, items: &mut [u32], axis: usize) -> usize {
        let mid = items.len() / 2;
        items.select_nth_unstable_by(mid, |a, b| {
            self.centres[*a as usize][axis].total_cmp(&self.centres[*b as usize][axis])
        });
        mid
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::polygon::ConvexPolygon;
    use std::f64::consts::TAU;

    /// SplitMix64, for reproducible random meshes.
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        }

        fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * ((self.next() >> 11) as f64 / (1u64 << 53) as f64)
        }

        fn dir(&mut self) -> DVec3 {
            let z = self.uniform(-1.0, 1.0);
            let phi = self.uniform(0.0, TAU);
            let s = (1.0 - z * z).max(0.0).sqrt();
            DVec3::new(s * phi.cos(), s * phi.sin(), z)
        }

        fn point(&mut self, max: f64) -> Point {
            let d = self.dir();
            Point::at_distance_from_origin(d, self.uniform(0.0, max)).unwrap()
        }
    }

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    /// Triangles scattered through a ball of radius `reach`, each with
    /// sides up to about `size`.
    fn soup(rng: &mut Rng, count: usize, reach: f64, size: f64) -> TriangleMesh {
        let mut vertices = Vec::with_capacity(3 * count);
        let mut triangles = Vec::with_capacity(count);
        for i in 0..count as u32 {
            let c = rng.point(reach);
            for _ in 0..3 {
                let dir = rng.dir();
                vertices.push(Isometry::transvection_from_origin(c).apply(
                    &Point::at_distance_from_origin(dir, rng.uniform(0.1, 1.0) * size).unwrap(),
                ));
            }
            triangles.push([3 * i, 3 * i + 1, 3 * i + 2]);
        }
        TriangleMesh::new(vertices, triangles).unwrap()
    }

    #[test]
    fn bvh_equals_brute_force() {
        let mut rng = Rng(7);
        for (reach, size) in [(1.5, 0.15), (3.0, 0.4), (0.5, 0.05)] {
            let mesh = soup(&mut rng, 2000, reach, size);
            let mut hits = 0;
            for k in 0..600 {
                let ray = if k % 2 == 0 {
                    Ray::from_origin_unchecked(rng.dir())
                } else {
                    Ray::from_ball_unchecked(&rng.point(reach + 1.0), rng.dir())
                };
                let t_min = if k % 3 == 0 { 0.0 } else { 1e-9 };
                let t_max = if k % 5 == 0 { 1.0 } else { f64::INFINITY };
                let fast = mesh.intersect_indexed(&ray, t_min, t_max);
                let slow = mesh.intersect_exhaustive(&ray, t_min, t_max);
                assert_eq!(fast, slow, "ray {k}: {ray:?}");
                assert_eq!(mesh.blocks(&ray, t_min, t_max), slow.is_some());
                hits += usize::from(slow.is_some());
            }
            assert!(hits > 100, "only {hits} hits");
        }
    }

    /// The octahedron subdivided `levels` times (8 * 4^levels triangles),
    /// vertices at distance `radius`, wound outward.
    fn octasphere(levels: usize, radius: f64) -> (Vec<Point>, Vec<[u32; 3]>) {
        let mut dirs = vec![
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
            -DVec3::X,
            -DVec3::Y,
            -DVec3::Z,
        ];
        let mut faces: Vec<[u32; 3]> = vec![
            [0, 1, 2],
            [1, 3, 2],
            [3, 4, 2],
            [4, 0, 2],
            [1, 0, 5],
            [3, 1, 5],
            [4, 3, 5],
            [0, 4, 5],
        ];
        for _ in 0..levels {
            let mut mid = std::collections::HashMap::new();
            let mut next = Vec::with_capacity(4 * faces.len());
            for [a, b, c] in faces {
                let mut m = |u: u32, v: u32| {
                    *mid.entry((u.min(v), u.max(v))).or_insert_with(|| {
                        dirs.push((dirs[u as usize] + dirs[v as usize]).normalize());
                        dirs.len() as u32 - 1
                    })
                };
                let (ab, bc, ca) = (m(a, b), m(b, c), m(c, a));
                next.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
            }
            faces = next;
        }
        for f in &faces {
            let [a, b, c] = f.map(|k| dirs[k as usize]);
            assert!((b - a).cross(c - a).dot(a + b + c) > 0.0);
        }
        let points = dirs
            .iter()
            .map(|d| Point::at_distance_from_origin(*d, radius).unwrap())
            .collect();
        (points, faces)
    }

    /// On a closed mesh, with rays aimed at its vertices and edges (where a
    /// box test that is not conservative would cull the triangle the exact
    /// test accepts), the BVH finds exactly what testing every triangle
    /// finds, and no ray escapes.
    #[test]
    fn bvh_equals_brute_force_at_edges_and_vertices() {
        let (points, faces) = octasphere(4, 1.2);
        let mut rng = Rng(13);
        let f = Isometry::transvection_from_origin(rng.point(2.0)).compose(
            &Isometry::rotation_about_segment_unchecked(
                &crate::segment::Segment::new(Point::ORIGIN, rng.point(1.0)).unwrap(),
                1.0,
            ),
        );
        let mesh = TriangleMesh::new(points.clone(), faces.clone())
            .unwrap()
            .transformed(&f);
        assert_eq!(mesh.triangle_count(), 2048);
        let centre = f.apply(&Point::ORIGIN);
        let l = f.to_lorentz();
        let mut targets: Vec<DVec4> = points.iter().map(|p| l * p.to_hyperboloid()).collect();
        for [a, b, _] in &faces {
            let (x, y) = (
                points[*a as usize].to_hyperboloid(),
                points[*b as usize].to_hyperboloid(),
            );
            targets.push(l * (0.5 * (x + y)));
            targets.push(l * (0.9 * x + 0.1 * y));
        }
        for x in &targets {
            let target = Point::from_hyperboloid(*x / (-lorentz::dot(*x, *x)).sqrt()).unwrap();
            let outside = f.apply(&rng.point(0.4)).coords();
            let starts = [centre, Point::from_coords(outside).unwrap()];
            for start in starts {
                let dir = crate::segment::Segment::new(start, target)
                    .unwrap()
                    .direction_at_start();
                let ray = Ray::from_ball_unchecked(&start, dir);
                let fast = mesh.intersect_indexed(&ray, 0.0, f64::INFINITY);
                assert_eq!(fast, mesh.intersect_exhaustive(&ray, 0.0, f64::INFINITY));
                assert!(fast.is_some(), "escaped through {x:?}");
            }
        }
    }

    #[test]
    fn blocks_agrees_with_intersect() {
        let mut rng = Rng(3);
        let mesh = soup(&mut rng, 300, 1.0, 0.3);
        for _ in 0..500 {
            let ray = Ray::from_ball_unchecked(&rng.point(2.0), rng.dir());
            let hit = mesh.intersect(&ray, 0.0, f64::INFINITY);
            assert_eq!(mesh.blocks(&ray, 0.0, f64::INFINITY), hit.is_some());
            if let Some(h) = hit {
                assert!(!mesh.blocks(&ray, 0.0, h.t));
                assert!(mesh.blocks(&ray, 0.0, h.t * (1.0 + 1e-12) + 1e-300));
            }
        }
    }

    #[test]
    fn cross_is_exactly_antisymmetric_and_exact_in_sign() {
        let mut rng = Rng(5);
        for _ in 0..10_000 {
            let a = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
            // Nearly parallel vectors: the naive difference cancels.
            let s = rng.uniform(0.5, 2.0);
            let b = (a.0 * s + rng.uniform(-1e-16, 1e-16), a.1 * s);
            assert_eq!(cross(a, b), -cross(b, a));
            assert_eq!(cross(a, a), 0.0);
        }
        // 3 * (1 + 2^-52) - (3 + 2^-51) * 1 = 3 * 2^-52 - 2^-51 = 2^-52 > 0.
        let e = f64::EPSILON;
        assert!(cross((3.0, 1.0), (1.0, 1.0 + e)) > 0.0);
        assert!(cross((1.0 + e, 1.0 + e), (1.0 - e, 1.0 - e)) == 0.0);
    }

    #[test]
    fn degenerate_triangles_are_dropped_and_counted() {
        let vs = vec![
            p(0.0, 0.0, 0.0),
            p(0.3, 0.0, 0.0),
            p(0.0, 0.3, 0.0),
            p(-0.3, 0.0, 0.0),
        ];
        let mesh = TriangleMesh::new(vs.clone(), vec![[0, 1, 2], [0, 0, 1], [1, 0, 3], [1, 2, 2]])
            .unwrap();
        assert_eq!(mesh.triangle_count(), 1);
        assert_eq!(mesh.dropped_triangles(), 3);
        assert_eq!(mesh.vertex_count(), 4);
        assert_eq!(&*mesh.triangles(), &[[0, 1, 2]]);
        assert_eq!(&*mesh.vertices(), vs.as_slice());
        assert_eq!(
            TriangleMesh::new(vs.clone(), vec![[0, 1, 3]]),
            Err(GeomError::EmptyMesh { dropped: 1 })
        );
        assert_eq!(
            TriangleMesh::new(vs.clone(), vec![[0, 1, 4]]),
            Err(GeomError::MeshIndexOutOfRange {
                triangle: 0,
                index: 4,
                vertices: 4
            })
        );
        assert_eq!(
            TriangleMesh::new(vs, vec![]),
            Err(GeomError::EmptyMesh { dropped: 0 })
        );
        assert_eq!(
            TriangleMesh::new(vec![], vec![[0, 1, 2]]),
            Err(GeomError::EmptyMesh { dropped: 0 })
        );
        let far = Point::new_unchecked(DVec3::new(1.0, 0.0, 0.0), 1e-300);
        assert!(matches!(
            TriangleMesh::new(
                vec![far, p(0.1, 0.0, 0.0), p(0.0, 0.1, 0.0)],
                vec![[0, 1, 2]]
            ),
            Err(GeomError::NotInBall { .. })
        ));
        let nan = Point::new_unchecked(DVec3::new(f64::NAN, 0.0, 0.0), 1.0);
        assert_eq!(
            TriangleMesh::new(
                vec![nan, p(0.1, 0.0, 0.0), p(0.0, 0.1, 0.0)],
                vec![[0, 1, 2]]
            ),
            Err(GeomError::NotFinite)
        );
    }

    /// Barycentric coordinates of a point of a triangle's plane, in Klein
    /// coordinates (where the triangle is Euclidean).
    fn barycentric(x: DVec4, [a, b, c]: [DVec4; 3]) -> [f64; 3] {
        let k = |v: DVec4| v.truncate() / v.w;
        let (ka, kb, kc, kx) = (k(a), k(b), k(c), k(x));
        let n = (kb - ka).cross(kc - ka);
        let w = |u: DVec3, v: DVec3| (u - kx).cross(v - kx).dot(n) / n.length_squared();
        [w(kb, kc), w(kc, ka), w(ka, kb)]
    }

    #[test]
    fn single_triangle_matches_the_polygon_and_its_orientation() {
        let (a, b, c) = (p(0.3, -0.1, 0.2), p(-0.2, 0.4, 0.1), p(-0.1, -0.3, 0.25));
        let mesh = TriangleMesh::new(vec![a, b, c], vec![[0, 1, 2]]).unwrap();
        let poly = ConvexPolygon::new(vec![a.into(), b.into(), c.into()]).unwrap();
        let corners = [a, b, c].map(|v| v.to_hyperboloid());
        let mut rng = Rng(9);
        let (mut hits, mut disagree) = (0, 0);
        for k in 0..4000 {
            // Aim at the triangle and around it, so edges are crossed often.
            let w = [0, 1, 2].map(|_| rng.uniform(-0.2, 1.0));
            let aim = w[0] * corners[0] + w[1] * corners[1] + w[2] * corners[2];
            let ray = if k % 2 == 0 || !(aim.w > 0.0 && lorentz::dot(aim, aim) < 0.0) {
                Ray::from_origin_unchecked(rng.dir())
            } else {
                Ray::from_origin_unchecked(aim.truncate())
            };
            let m = mesh.intersect(&ray, 0.0, f64::INFINITY);
            let q = poly.intersect(&ray, 0.0, f64::INFINITY);
            match (m, q) {
                (Some(m), Some(q)) => {
                    hits += 1;
                    assert!((m.t - q.t).abs() < 1e-14, "{} vs {}", m.t, q.t);
                    assert!((m.normal - q.normal).length() < 1e-14);
                }
                (None, None) => {}
                (m, q) => {
                    // Only within rounding of an edge may the two disagree.
                    disagree += 1;
                    let h = m.or(q).unwrap();
                    let w = barycentric(h.point, corners);
                    let edge = w.iter().map(|x| x.abs()).fold(f64::INFINITY, f64::min);
                    assert!(edge < 1e-9, "disagree away from an edge: {w:?}");
                }
            }
        }
        assert!(hits > 1000, "{hits} hits, {disagree} disagreements");
        assert!(disagree < 10, "{disagree} disagreements");
        // Orientation: the normal follows the right-hand rule, like the plane's.
        let n = HPlane::through(&a.into(), &b.into(), &c.into())
            .unwrap()
            .normal();
        let hit = mesh
            .intersect(
                &Ray::from_origin_unchecked(corners.iter().sum::<DVec4>().truncate()),
                0.0,
                f64::INFINITY,
            )
            .unwrap();
        assert!((hit.normal - n).length() < 1e-14);
    }

    #[test]
    fn moves_share_the_data_and_reverse_the_winding_of_reflections() {
        let mut rng = Rng(1);
        let mesh = soup(&mut rng, 50, 1.0, 0.3);
        let plane = HPlane::through(
            &p(0.1, 0.0, 0.0).into(),
            &p(0.0, 0.2, 0.0).into(),
            &p(0.0, 0.0, 0.3).into(),
        )
        .unwrap();
        let mirror = Isometry::reflection(&plane);
        let moved = mesh.transformed(&mirror);
        assert!(Arc::ptr_eq(&mesh.shared, &moved.shared));
        assert_ne!(moved, mesh);
        assert_eq!(moved, mesh.transformed(&mirror));
        assert_eq!(mesh.clone(), mesh);
        assert_eq!(mesh.transformed(&Isometry::IDENTITY), mesh);
        let tris = moved.triangles();
        for (t, u) in tris.iter().zip(mesh.triangles().iter()) {
            assert_eq!(*t, [u[0], u[2], u[1]]);
        }
        // The moved normals follow the right-hand rule with the reported
        // winding.
        let vs = moved.vertices();
        for _ in 0..300 {
            let ray = Ray::from_ball_unchecked(&rng.point(2.0), rng.dir());
            if let Some((hit, i)) = moved.intersect_indexed(&ray, 0.0, f64::INFINITY) {
                let [a, b, c] = tris[i].map(|k| crate::point::Vertex::from(vs[k as usize]));
                let n = HPlane::through(&a, &b, &c).unwrap().normal();
                assert!(lorentz::dot(n, hit.normal) > 0.99, "{n} vs {}", hit.normal);
            }
        }
    }

    #[test]
    fn translated_mesh_builds_its_frame_far_out() {
        // A small mesh 20 from the origin: the local frame keeps its planes
        // accurate even though the world vectors are ~1e9 long.
        let centre = Point::at_distance_from_origin(DVec3::new(0.3, 0.4, 1.0), 20.0).unwrap();
        let there = Isometry::transvection_from_origin(centre);
        let corners = [p(0.2, 0.0, 0.0), p(0.0, 0.2, 0.0), p(0.0, 0.0, 0.2)];
        let mesh = TriangleMesh::new(
            corners.iter().map(|c| there.apply(c)).collect(),
            vec![[0, 1, 2]],
        )
        .unwrap();
        let (c, r) = mesh.bounding_ball();
        let c = Point::from_hyperboloid(c).unwrap();
        // The barycentre of the corners is 0.226 from the origin (before the
        // move), and the corners 0.34 from it.
        let offset = crate::distance::distance(&c, &centre);
        assert!((offset - 0.226).abs() < 1e-3, "{offset}");
        assert!((r - 0.34).abs() < 0.01, "{r}");
        // Carried back next to the origin, it is the triangle it was.
        let back = mesh.transformed(&there.inverse());
        let direct = TriangleMesh::new(corners.to_vec(), vec![[0, 1, 2]]).unwrap();
        let mut rng = Rng(2);
        for _ in 0..200 {
            let ray = Ray::from_origin_unchecked(rng.dir() + DVec3::splat(0.8));
            let (a, b) = (
                back.intersect(&ray, 0.0, f64::INFINITY),
                direct.intersect(&ray, 0.0, f64::INFINITY),
            );
            assert_eq!(a.is_some(), b.is_some());
            if let (Some(a), Some(b)) = (a, b) {
                assert!((a.t - b.t).abs() < 1e-6, "{} vs {}", a.t, b.t);
            }
        }
    }
}
