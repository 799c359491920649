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
//! (no vertex of a finite-volume domain) when it is spacelike. Which
//! planes meet at each vertex is found by clipping each face's plane by
//! the others (`face_polygons.rs`, `O(F²)` for `F` faces); the vertex is
//! then computed from three of them, the most transversal.

use glam::{DVec3, DVec4};

use crate::error::GeomError;
use crate::lorentz;

use super::face_polygons::{KleinPlane, MAX_VERTICES, MERGE, face_polygon};

/// How near the sphere at infinity (in `|k|² - 1` for the Klein point `k`)
/// a vertex is ideal: a finite vertex this near would be farther than 9
/// from the origin.
const IDEAL: f64 = 4.0 * MERGE;

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
        let mut planes = Vec::with_capacity(faces.len());
        for (i, n) in faces.iter().enumerate() {
            let plane = (n.is_finite() && (lorentz::dot(*n, *n) - 1.0).abs() <= 1e-9)
                .then(|| KleinPlane::new(*n))
                .flatten();
            let Some(plane) = plane else {
                return Err(GeomError::BadDomain(format!(
                    "face {} is not a plane with the origin on its inner side",
                    i + 1
                )));
            };
            planes.push(plane);
        }
        let mut grid = VertexGrid::default();
        let mut faces_at: Vec<Vec<usize>> = Vec::new();
        let mut face_vertices = Vec::with_capacity(faces.len());
        for a in 0..faces.len() {
            let polygon = face_polygon(&planes, a)?;
            let mut ids = Vec::with_capacity(polygon.len());
            for corner in polygon {
                let id = grid.find_or_insert(corner.at);
                if id == faces_at.len() {
                    faces_at.push(Vec::new());
                }
                faces_at[id].push(a);
                faces_at[id].extend(corner.faces);
                if ids.last() != Some(&id) && ids.first() != Some(&id) {
                    ids.push(id);
                }
            }
            if ids.len() < 3 {
                return Err(GeomError::BadDomain(format!(
                    "face {} meets the domain only in an edge or a vertex (a redundant pairing)",
                    a + 1
                )));
            }
            face_vertices.push(ids);
            if faces_at.len() > MAX_VERTICES {
                return Err(GeomError::BadDomain(format!(
                    "the domain has more than {MAX_VERTICES} vertices"
                )));
            }
        }
        let mut vertices = Vec::with_capacity(faces_at.len());
        let mut ideal = Vec::with_capacity(faces_at.len());
        for (k, through) in faces_at.iter_mut().enumerate() {
            through.sort_unstable();
            through.dedup();
            let (v, at_infinity) = vertex_from_faces(&faces, through).ok_or_else(|| {
                GeomError::BadDomain(format!(
                    "the vertex of faces {:?} lies beyond the sphere at infinity: the domain is \
                     open to the absolute there (infinite volume)",
                    through.iter().map(|f| f + 1).collect::<Vec<_>>()
                ))
            })?;
            debug_assert!(k == vertices.len());
            vertices.push(v);
            ideal.push(at_infinity);
        }
        let edges = edges_of(&face_vertices)?;
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
            .map(|v| (v.truncate() / v.w - p).length())
            .enumerate()
            .filter(|(_, d)| *d < 1e-7)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(k, _)| k)
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

/// The vertex on the planes `through` (three or more), from the three
/// of them that meet most transversally (a greedy choice: the first, the
/// one least parallel to it, the one farthest from their line), as the
/// line of their Lorentz-orthogonal complement: a hyperboloid point, or an
/// ideal point (time 1) where the complement is null to [`IDEAL`]; `None`
/// beyond the absolute.
fn vertex_from_faces(faces: &[DVec4], through: &[usize]) -> Option<(DVec4, bool)> {
    let unit = |f: usize| faces[f] / faces[f].length();
    let a = unit(*through.first()?);
    let b = through
        .iter()
        .map(|&f| unit(f))
        .min_by(|x, y| x.dot(a).abs().total_cmp(&y.dot(a).abs()))?;
    let c = through.iter().map(|&f| unit(f)).max_by(|x, y| {
        let gx = lorentz::orthogonal_complement(a, b, *x).length();
        let gy = lorentz::orthogonal_complement(a, b, *y).length();
        gx.total_cmp(&gy)
    })?;
    let mut x = lorentz::orthogonal_complement(a, b, c);
    let scale = x.abs().max_element();
    if !(scale > 0.0) || !scale.is_finite() {
        return None;
    }
    x /= scale;
    if x.w < 0.0 {
        x = -x;
    }
    // |k|² - 1 for the Klein point k = x / x.w.
    let q = lorentz::dot(x, x) / (x.w * x.w);
    if !q.is_finite() || q > IDEAL {
        None
    } else if q >= -IDEAL {
        // Null: the spatial part has length w; scaling it to 1 keeps it
        // exactly null.
        Some((x.truncate().normalize().extend(1.0), true))
    } else {
        Some((x / (-lorentz::dot(x, x)).sqrt(), false))
    }
}

/// The edges: pairs of vertices adjacent on a face polygon, each on
/// exactly two faces (a domain whose faces do not close up along an edge
/// is refused).
fn edges_of(face_vertices: &[Vec<usize>]) -> Result<Vec<DomainEdge>, GeomError> {
    let mut by_ends: std::collections::BTreeMap<(usize, usize), Vec<usize>> = Default::default();
    for (f, ids) in face_vertices.iter().enumerate() {
        for (i, &u) in ids.iter().enumerate() {
            let v = ids[(i + 1) % ids.len()];
            by_ends.entry((u.min(v), u.max(v))).or_default().push(f);
        }
    }
    let mut edges = Vec::with_capacity(by_ends.len());
    for ((u, v), on) in by_ends {
        let [a, b] = on[..] else {
            return Err(GeomError::BadDomain(format!(
                "the edge between vertices {} and {} lies on faces {:?}, not on two: the faces \
                 do not close up there",
                u + 1,
                v + 1,
                on.iter().map(|f| f + 1).collect::<Vec<_>>()
            )));
        };
        edges.push(DomainEdge {
            faces: [a.min(b), a.max(b)],
            vertices: [u, v],
        });
    }
    edges.sort_by_key(|e| e.faces);
    Ok(edges)
}

/// Vertices found so far, looked up by Klein coordinates in a grid of
/// cells of side `4 MERGE`, so that each lookup costs a few cells, not
/// all vertices.
#[derive(Default)]
struct VertexGrid {
    cells: std::collections::HashMap<[i64; 3], Vec<usize>>,
    points: Vec<DVec3>,
}

impl VertexGrid {
    const CELL: f64 = 4.0 * MERGE;

    fn key(p: DVec3) -> [i64; 3] {
        (p / Self::CELL).floor().to_array().map(|x| x as i64)
    }

    /// The vertex within `2 MERGE` of `p`, or a new one.
    fn find_or_insert(&mut self, p: DVec3) -> usize {
        let [x, y, z] = Self::key(p);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(ids) = self.cells.get(&[x + dx, y + dy, z + dz])
                        && let Some(&k) = ids
                            .iter()
                            .find(|&&k| (self.points[k] - p).length() <= 2.0 * MERGE)
                    {
                        return k;
                    }
                }
            }
        }
        let k = self.points.len();
        self.points.push(p);
        self.cells.entry([x, y, z]).or_default().push(k);
        k
    }
}
