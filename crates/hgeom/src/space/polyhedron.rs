//! A fundamental polyhedron given by its face planes: its vertices (finite
//! or ideal), the vertices of each face and its edges, found from the
//! planes alone so that a domain read from a file and a built-in one are
//! checked the same way.
//!
//! **Vertices.** Three face planes with unit normals `n_a, n_b, n_c` meet in
//! the line spanned by their Lorentz-orthogonal complement `x`
//! ([`lorentz::orthogonal_complement`]): a point of the hyperboloid when `x`
//! is timelike, an ideal point when it is null (the three planes are
//! tangent to one horosphere's centre), and a point beyond the absolute
//! (no vertex of a finite-volume domain) when it is spacelike. A vertex of
//! the polyhedron is such a point on the inner side of every other plane.

use glam::DVec4;

use crate::error::GeomError;
use crate::lorentz;

/// How far off a plane (`|<x,n>| / x.w`) a vertex may be and still lie on
/// it: the built-in domains' vertices are within 1e-14 of their planes;
/// the next vertex of any domain is farther than this by many orders.
const ON_PLANE: f64 = 1e-9;

/// An edge of the domain: the two faces that meet in it and its two
/// end vertices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DomainEdge {
    /// The faces meeting in it, lower index first.
    pub faces: [usize; 2],
    /// Its end vertices (indices into [`DomainPolyhedron::vertices`]).
    pub vertices: [usize; 2],
}

/// A convex polyhedron of finite volume, as the intersection of the inner
/// sides `<X,n> >= 0` of its face planes.
///
/// Invariants: `faces` are unit spacelike normals; every vertex lies on at
/// least three faces and on the inner side of all; each face has at least
/// three vertices; each edge joins two vertices on both its faces.
#[derive(Clone, Debug, PartialEq)]
pub struct DomainPolyhedron {
    faces: Vec<DVec4>,
    vertices: Vec<DVec4>,
    ideal: Vec<bool>,
    face_vertices: Vec<Vec<usize>>,
    edges: Vec<DomainEdge>,
}

impl DomainPolyhedron {
    /// The polyhedron bounded by the planes with inward unit normals
    /// `faces`.
    ///
    /// Errors: [`GeomError::NotFinite`] for a normal that is not finite or
    /// not unit spacelike; [`GeomError::BadDomain`] for a domain of
    /// infinite volume (a vertex beyond the absolute, or a face with fewer
    /// than three vertices, which leaves it open to the absolute).
    pub fn from_faces(faces: Vec<DVec4>) -> Result<DomainPolyhedron, GeomError> {
        if faces.len() < 4 {
            return Err(GeomError::BadDomain(format!(
                "a domain needs at least 4 faces, got {}",
                faces.len()
            )));
        }
        for n in &faces {
            if !n.is_finite() || (lorentz::dot(*n, *n) - 1.0).abs() > 1e-9 {
                return Err(GeomError::NotFinite);
            }
        }
        let mut vertices: Vec<DVec4> = Vec::new();
        let mut ideal = Vec::new();
        let m = faces.len();
        for a in 0..m {
            for b in a + 1..m {
                for c in b + 1..m {
                    let Some((v, at_infinity)) = meeting_point(faces[a], faces[b], faces[c]) else {
                        continue;
                    };
                    if !faces.iter().all(|n| lorentz::dot(v, *n) >= -ON_PLANE * v.w) {
                        continue;
                    }
                    if vertices
                        .iter()
                        .any(|u| (u.truncate() / u.w - v.truncate() / v.w).length() < 1e-7)
                    {
                        continue;
                    }
                    vertices.push(v);
                    ideal.push(at_infinity);
                }
            }
        }
        let face_vertices: Vec<Vec<usize>> = faces
            .iter()
            .map(|n| {
                (0..vertices.len())
                    .filter(|&k| lorentz::dot(vertices[k], *n).abs() <= ON_PLANE * vertices[k].w)
                    .collect()
            })
            .collect();
        if let Some(face) = face_vertices.iter().position(|v| v.len() < 3) {
            return Err(GeomError::BadDomain(format!(
                "face {} has {} vertices: the domain is open to the absolute there",
                face + 1,
                face_vertices[face].len()
            )));
        }
        let mut edges = Vec::new();
        for a in 0..m {
            for b in a + 1..m {
                let shared: Vec<usize> = face_vertices[a]
                    .iter()
                    .copied()
                    .filter(|k| face_vertices[b].contains(k))
                    .collect();
                if let [u, v] = shared[..] {
                    edges.push(DomainEdge {
                        faces: [a, b],
                        vertices: [u, v],
                    });
                }
            }
        }
        Ok(DomainPolyhedron {
            faces,
            vertices,
            ideal,
            face_vertices,
            edges,
        })
    }

    /// The inward unit normals of the faces.
    pub fn faces(&self) -> &[DVec4] {
        &self.faces
    }

    /// The vertices: hyperboloid points, or null vectors with time 1 for
    /// ideal vertices.
    pub fn vertices(&self) -> &[DVec4] {
        &self.vertices
    }

    /// Which vertices are ideal.
    pub fn ideal(&self) -> &[bool] {
        &self.ideal
    }

    /// The vertices of face `i`.
    pub fn face_vertices(&self, i: usize) -> &[usize] {
        &self.face_vertices[i]
    }

    /// The edges.
    pub fn edges(&self) -> &[DomainEdge] {
        &self.edges
    }

    /// The interior dihedral angle at an edge, in radians: π minus the angle
    /// between the inward normals, `acos(-<n_a,n_b>)`.
    pub fn dihedral(&self, edge: &DomainEdge) -> f64 {
        let c = lorentz::dot(self.faces[edge.faces[0]], self.faces[edge.faces[1]]);
        (-c).clamp(-1.0, 1.0).acos()
    }

    /// The vertex at `x` (projectively: an ideal vertex matches any positive
    /// multiple), if there is one.
    pub fn vertex_at(&self, x: DVec4) -> Option<usize> {
        if !(x.w > 0.0) {
            return None;
        }
        let p = x.truncate() / x.w;
        self.vertices
            .iter()
            .position(|v| (v.truncate() / v.w - p).length() < 1e-7)
    }

    /// The polyhedron moved by the Lorentz matrix `m`.
    pub fn transformed(&self, m: &glam::DMat4) -> DomainPolyhedron {
        let vertices = self
            .vertices
            .iter()
            .zip(&self.ideal)
            .map(|(v, &at_infinity)| {
                let x = *m * *v;
                if at_infinity { x / x.w } else { x }
            })
            .collect();
        DomainPolyhedron {
            faces: self.faces.iter().map(|n| *m * *n).collect(),
            vertices,
            ..self.clone()
        }
    }
}

/// The point where three planes meet, and whether it is ideal; `None`
/// when they meet beyond the absolute or share a line.
fn meeting_point(a: DVec4, b: DVec4, c: DVec4) -> Option<(DVec4, bool)> {
    let mut x = lorentz::orthogonal_complement(a, b, c);
    let scale = x.abs().max_element();
    if !(scale > 1e-12) {
        return None;
    }
    x /= scale;
    if x.w < 0.0 {
        x = -x;
    }
    let q = lorentz::dot(x, x) / (x.w * x.w);
    if !q.is_finite() {
        return None;
    }
    if q.abs() <= 1e-9 {
        // Null: the spatial part has length w; scaling it to 1 keeps it
        // exactly null.
        Some((x.truncate().normalize().extend(1.0), true))
    } else if q < 0.0 {
        Some((x / (-lorentz::dot(x, x)).sqrt(), false))
    } else {
        None
    }
}
