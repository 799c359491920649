//! Each face's polygon, found by clipping its plane by every other face's
//! half-space in the Klein model, where planes are flat: the vertices of
//! a domain of `F` faces in `O(F² k)` steps for faces of `k` vertices,
//! instead of trying all `F³` triples of planes against all `F` planes.
//!
//! In Klein coordinates `k = x/x.w` the inner side `<X,n> >= 0` of a face
//! with unit normal `n = (a, b)` (spatial part `a`, time `b < 0` for a
//! face the origin is inside) is `u·k <= h` with `u = -a/|a|` and
//! `h = -b/|a| = tanh` of the face's distance from the origin. A face's
//! polygon starts as a square about the plane's disk in the ball and is
//! cut by each other half-space (Sutherland-Hodgman), each polygon edge
//! remembering the face that cut it, so each corner knows the three
//! faces it lies on. Corners nearer than [`MERGE`] are one vertex (a
//! vertex where more than three faces meet is cut many times, and the
//! cuts differ by rounding).

use glam::{DVec2, DVec3, DVec4};

use crate::error::GeomError;

/// Corners nearer than this, in Klein coordinates, are one vertex.
/// Domains computed in double precision place a vertex shared by several
/// faces to about `1e-10`; their distinct vertices are farther apart
/// than `1e-6`.
pub const MERGE: f64 = 1e-8;

/// The most vertices a domain may have: every face a polygon of at most
/// `F + 4` corners bounds the work; a domain of 512 faces has at most
/// `2·512 - 4 = 1020` vertices where three faces meet at each.
pub const MAX_VERTICES: usize = 4096;

/// No face cuts this edge of the starting square.
const NONE: usize = usize::MAX;

/// A corner of a face polygon: its Klein coordinates and the face that
/// cut the edge from it to the next corner.
#[derive(Clone, Copy, Debug)]
struct Corner {
    at: DVec2,
    edge: usize,
}

/// A face's plane in the Klein model: `u·k = h`, with a basis of the
/// plane.
#[derive(Clone, Copy, Debug)]
pub(super) struct KleinPlane {
    u: DVec3,
    h: f64,
    e1: DVec3,
    e2: DVec3,
}

impl KleinPlane {
    /// The plane of a face with inward unit normal `n` (time last).
    pub(super) fn new(n: DVec4) -> Option<KleinPlane> {
        let a = n.truncate();
        let len = a.length();
        if !(len > 0.0) || !(n.w <= 0.0) {
            return None;
        }
        let u = -a / len;
        let e1 = u.any_orthonormal_vector();
        Some(KleinPlane {
            u,
            h: -n.w / len,
            e1,
            e2: u.cross(e1),
        })
    }

    fn point(&self, p: DVec2) -> DVec3 {
        self.h * self.u + p.x * self.e1 + p.y * self.e2
    }
}

/// One vertex of a face polygon: Klein coordinates and the faces through
/// it that the clipping found.
#[derive(Clone, Debug)]
pub(super) struct PolygonVertex {
    pub at: DVec3,
    pub faces: Vec<usize>,
}

/// The polygon of face `a` in order round it, its corners merged within
/// [`MERGE`].
///
/// Errors: [`GeomError::BadDomain`] naming the face (1-based) when the
/// other faces cut its plane away (a redundant face), leave less than a
/// polygon (one that touches the domain in an edge or a vertex, or a
/// face smaller than [`MERGE`]), or leave it reaching the sphere at
/// infinity other than in isolated ideal vertices (a domain of infinite
/// volume).
pub(super) fn face_polygon(
    planes: &[KleinPlane],
    a: usize,
) -> Result<Vec<PolygonVertex>, GeomError> {
    let plane = planes[a];
    let square = [(-2.0, -2.0), (2.0, -2.0), (2.0, 2.0), (-2.0, 2.0)];
    let mut poly: Vec<Corner> = square
        .iter()
        .map(|&(x, y)| Corner {
            at: DVec2::new(x, y),
            edge: NONE,
        })
        .collect();
    let mut next = Vec::with_capacity(8);
    for (j, other) in planes.iter().enumerate() {
        if j == a || poly.is_empty() {
            continue;
        }
        // u_j·(c + x e1 + y e2) <= h_j.
        let normal = DVec2::new(other.u.dot(plane.e1), other.u.dot(plane.e2));
        let offset = other.h - other.u.dot(plane.h * plane.u);
        let scale = normal.length();
        if !(scale > 1e-12) {
            if (offset).abs() <= MERGE {
                return Err(GeomError::BadDomain(format!(
                    "faces {} and {} lie in the same plane",
                    a.min(j) + 1,
                    a.max(j) + 1
                )));
            }
            if offset < 0.0 {
                poly.clear();
            }
            continue;
        }
        let side = |p: DVec2| (normal.dot(p) - offset) / scale;
        next.clear();
        for i in 0..poly.len() {
            let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
            let (sp, sq) = (side(p.at), side(q.at));
            let crossing = || {
                let t = sp / (sp - sq);
                p.at + (q.at - p.at) * t
            };
            match (sp <= 0.0, sq <= 0.0) {
                (true, true) => next.push(p),
                (true, false) => {
                    next.push(p);
                    next.push(Corner {
                        at: crossing(),
                        edge: j,
                    });
                }
                (false, true) => next.push(Corner {
                    at: crossing(),
                    edge: p.edge,
                }),
                (false, false) => {}
            }
        }
        std::mem::swap(&mut poly, &mut next);
        if poly.len() > MAX_VERTICES {
            return Err(GeomError::BadDomain(format!(
                "face {} has more than {MAX_VERTICES} vertices",
                a + 1
            )));
        }
    }
    if poly.is_empty() {
        return Err(GeomError::BadDomain(format!(
            "face {} does not bound the domain: the other faces cut its plane away (a redundant \
             pairing)",
            a + 1
        )));
    }
    if poly.iter().any(|c| c.edge == NONE) {
        return Err(GeomError::BadDomain(format!(
            "face {} reaches the sphere at infinity along an arc: the domain is open to the \
             absolute there (infinite volume)",
            a + 1
        )));
    }
    let merged = merge_corners(&plane, &poly);
    if merged.len() < 3 {
        let diameter = poly
            .iter()
            .flat_map(|p| poly.iter().map(move |q| (p.at - q.at).length()))
            .fold(0.0, f64::max);
        return Err(GeomError::BadDomain(if diameter <= 4.0 * MERGE {
            format!(
                "face {} is smaller than {MERGE:e} (in the Klein model): the domain is too \
                 small to tell its vertices apart",
                a + 1
            )
        } else {
            format!(
                "face {} meets the domain only in an edge or a vertex (a redundant pairing)",
                a + 1
            )
        }));
    }
    for v in &merged {
        let r = v.at.length();
        if r > 1.0 + 4.0 * MERGE {
            return Err(GeomError::BadDomain(format!(
                "face {} has a vertex beyond the sphere at infinity (at Klein radius {r:.9}): the \
                 domain is open to the absolute there (infinite volume)",
                a + 1
            )));
        }
    }
    Ok(merged)
}

/// The polygon's corners, runs of corners within [`MERGE`] of each other
/// made one vertex with all their faces.
fn merge_corners(plane: &KleinPlane, poly: &[Corner]) -> Vec<PolygonVertex> {
    let n = poly.len();
    // Start after a gap, so that no run wraps round the end.
    let start = (0..n)
        .find(|&i| (poly[i].at - poly[(i + n - 1) % n].at).length() > MERGE)
        .unwrap_or(0);
    let mut out: Vec<PolygonVertex> = Vec::new();
    let mut last = DVec2::splat(f64::INFINITY);
    for s in 0..n {
        let i = (start + s) % n;
        let c = poly[i];
        let before = poly[(i + n - 1) % n].edge;
        if (c.at - last).length() <= MERGE
            && let Some(v) = out.last_mut()
        {
            v.faces.extend([before, c.edge]);
        } else {
            out.push(PolygonVertex {
                at: plane.point(c.at),
                faces: vec![before, c.edge],
            });
        }
        last = c.at;
    }
    for v in &mut out {
        v.faces.sort_unstable();
        v.faces.dedup();
    }
    out
}
