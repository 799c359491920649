//! Polyhedral surfaces, and the regular (Platonic) h-polyhedra.

use glam::{DVec3, DVec4};

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::point::{Point, Vertex};
use crate::polygon::ConvexPolygon;
use crate::ray::{Hit, Ray};

/// A polyhedral surface: a union of convex polygons (it may self-intersect
/// and need not be closed), with a reference centre.
///
/// Invariant: every face's normal points away from `center` (the outer side),
/// which is what refraction uses to tell entering from leaving.
#[derive(Clone, Debug, PartialEq)]
pub struct Polyhedron {
    faces: Vec<ConvexPolygon>,
    center: Point,
}

/// The five regular convex polyhedra.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Platonic {
    /// 4 triangles.
    Tetrahedron,
    /// 6 squares (the hexahedron).
    Cube,
    /// 8 triangles.
    Octahedron,
    /// 12 pentagons.
    Dodecahedron,
    /// 20 triangles.
    Icosahedron,
}

const PHI: f64 = 1.618_033_988_749_895;

impl Platonic {
    /// Every Platonic solid, in the order of their face counts.
    pub const ALL: [Platonic; 5] = [
        Platonic::Tetrahedron,
        Platonic::Cube,
        Platonic::Octahedron,
        Platonic::Dodecahedron,
        Platonic::Icosahedron,
    ];

    /// Vertex directions of the Euclidean solid centred at the origin
    /// (unnormalised; every vector has the same length).
    fn template(self) -> Vec<DVec3> {
        let mut out = Vec::new();
        match self {
            Platonic::Tetrahedron => {
                for v in [
                    (1.0, 1.0, 1.0),
                    (1.0, -1.0, -1.0),
                    (-1.0, 1.0, -1.0),
                    (-1.0, -1.0, 1.0),
                ] {
                    out.push(DVec3::from(v));
                }
            }
            Platonic::Cube => {
                for s in signs3() {
                    out.push(s);
                }
            }
            Platonic::Octahedron => {
                for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
                    out.push(axis);
                    out.push(-axis);
                }
            }
            Platonic::Dodecahedron => {
                out.extend(signs3());
                out.extend(golden(1.0 / PHI, PHI));
            }
            Platonic::Icosahedron => out.extend(golden(1.0, PHI)),
        }
        out
    }

    /// Directions of the face centres: the vertices of the dual solid, in
    /// the orientation that puts them over this solid's faces.
    fn face_directions(self) -> Vec<DVec3> {
        match self {
            Platonic::Tetrahedron => Platonic::Tetrahedron
                .template()
                .into_iter()
                .map(|v| -v)
                .collect(),
            Platonic::Cube => Platonic::Octahedron.template(),
            Platonic::Octahedron => Platonic::Cube.template(),
            Platonic::Dodecahedron => golden(PHI, 1.0),
            Platonic::Icosahedron => {
                let mut dirs = signs3();
                dirs.extend(golden(PHI, 1.0 / PHI));
                dirs
            }
        }
    }

    /// The solid's vertices as unit vectors, and its faces as index lists in
    /// counter-clockwise order seen from outside.
    pub fn combinatorics(self) -> (Vec<DVec3>, Vec<Vec<usize>>) {
        let verts: Vec<DVec3> = self.template().into_iter().map(DVec3::normalize).collect();
        let mut faces = Vec::new();
        for dir in self.face_directions() {
            let n = dir.normalize();
            let best = verts.iter().map(|v| v.dot(n)).fold(f64::MIN, f64::max);
            let mut face: Vec<usize> = (0..verts.len())
                .filter(|&i| verts[i].dot(n) > best - 1e-9)
                .collect();
            let u = (verts[face[0]] - n * verts[face[0]].dot(n)).normalize();
            let w = n.cross(u);
            face.sort_by(|&i, &j| {
                let ai = verts[i].dot(w).atan2(verts[i].dot(u));
                let aj = verts[j].dot(w).atan2(verts[j].dot(u));
                ai.total_cmp(&aj)
            });
            faces.push(face);
        }
        (verts, faces)
    }
}

fn signs3() -> Vec<DVec3> {
    let mut out = Vec::new();
    for x in [-1.0, 1.0] {
        for y in [-1.0, 1.0] {
            for z in [-1.0, 1.0] {
                out.push(DVec3::new(x, y, z));
            }
        }
    }
    out
}

/// The 12 points `(0, ±a, ±b)` and their cyclic permutations.
fn golden(a: f64, b: f64) -> Vec<DVec3> {
    let mut out = Vec::new();
    for s1 in [-1.0, 1.0] {
        for s2 in [-1.0, 1.0] {
            out.extend(cyclic(DVec3::new(0.0, s1 * a, s2 * b)));
        }
    }
    out
}

fn cyclic(v: DVec3) -> [DVec3; 3] {
    [v, DVec3::new(v.z, v.x, v.y), DVec3::new(v.y, v.z, v.x)]
}

impl Polyhedron {
    /// A surface from faces and a centre; faces are re-oriented to point
    /// away from the centre.
    pub fn new(faces: Vec<ConvexPolygon>, center: Point) -> Polyhedron {
        let c = center.to_hyperboloid();
        let faces = faces
            .into_iter()
            .map(|f| {
                if lorentz::dot(c, f.plane().normal()) > 0.0 {
                    let mut vs = f.vertices().to_vec();
                    vs.reverse();
                    ConvexPolygon::try_new(vs).unwrap_or(f)
                } else {
                    f
                }
            })
            .collect();
        Polyhedron { faces, center }
    }

    /// The regular h-polyhedron centred at the origin whose vertices lie at
    /// hyperbolic distance `circumradius` from it.
    ///
    /// Vertices of a Euclidean regular solid centred at the origin are also
    /// the vertices of a regular h-polyhedron: the symmetry group of the solid
    /// fixes the origin, so it acts by hyperbolic isometries, and each face's
    /// vertices are concyclic, hence lie on one h-plane.
    pub fn platonic(kind: Platonic, circumradius: f64) -> Result<Polyhedron, GeomError> {
        if !(circumradius.is_finite() && circumradius > 0.0) {
            return Err(GeomError::BadRadius(circumradius));
        }
        let (dirs, faces) = kind.combinatorics();
        let points = dirs
            .iter()
            .map(|d| Point::at_distance_from_origin(*d, circumradius))
            .collect::<Result<Vec<_>, _>>()?;
        let polys = faces
            .iter()
            .map(|f| {
                ConvexPolygon::try_new(f.iter().map(|&i| Vertex::Interior(points[i])).collect())
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Polyhedron::new(polys, Point::ORIGIN))
    }

    /// The faces.
    pub fn faces(&self) -> &[ConvexPolygon] {
        &self.faces
    }

    /// The reference centre.
    pub fn center(&self) -> Point {
        self.center
    }

    /// The image under an isometry.
    pub fn transformed(&self, iso: &Isometry) -> Polyhedron {
        Polyhedron {
            faces: self.faces.iter().map(|f| f.transformed(iso)).collect(),
            center: iso.apply(&self.center),
        }
    }

    /// The nearest intersection with any face in `(t_min, t_max)`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut limit = t_max;
        for face in &self.faces {
            if let Some(hit) = face.intersect(ray, t_min, limit) {
                limit = hit.t;
                best = Some(hit);
            }
        }
        best
    }

    /// Hyperboloid vector of the centre.
    pub fn center_h(&self) -> DVec4 {
        self.center.to_hyperboloid()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distance::distance;

    #[test]
    fn platonic_counts() {
        let expect = [(4, 4, 3), (8, 6, 4), (6, 8, 3), (20, 12, 5), (12, 20, 3)];
        for (kind, (nv, nf, per_face)) in Platonic::ALL.iter().zip(expect) {
            let (v, f) = kind.combinatorics();
            assert_eq!(v.len(), nv, "{kind:?}");
            assert_eq!(f.len(), nf, "{kind:?}");
            assert!(f.iter().all(|face| face.len() == per_face), "{kind:?}");
        }
    }

    #[test]
    fn faces_point_outward_and_edges_are_equal() {
        for kind in Platonic::ALL {
            let p = Polyhedron::platonic(kind, 0.8).unwrap();
            let mut lengths = Vec::new();
            for face in p.faces() {
                // The centre (origin, hyperboloid e_w) is on the negative side.
                assert!(face.plane().normal().w > 0.0, "{kind:?}");
                let vs = face.vertices();
                for i in 0..vs.len() {
                    if let (Vertex::Interior(a), Vertex::Interior(b)) =
                        (vs[i], vs[(i + 1) % vs.len()])
                    {
                        lengths.push(distance(&a, &b));
                    }
                }
            }
            let (lo, hi) = lengths
                .iter()
                .fold((f64::MAX, f64::MIN), |(lo, hi), &l| (lo.min(l), hi.max(l)));
            assert!(hi - lo < 1e-13, "{kind:?}: {lo} {hi}");
        }
    }

    #[test]
    fn ray_from_the_centre_hits_a_face_from_inside() {
        let p = Polyhedron::platonic(Platonic::Dodecahedron, 0.3).unwrap();
        for dir in [DVec3::X, DVec3::new(0.3, -0.2, 0.9), -DVec3::Z] {
            let hit = p
                .intersect(&Ray::from_origin(dir), 0.0, f64::INFINITY)
                .unwrap();
            assert!(hit.t > 0.0 && hit.t <= 0.3 + 1e-12);
            // Leaving: direction and outward normal agree.
            assert!(lorentz::dot(Ray::from_origin(dir).tangent_at(hit.t), hit.normal) > 0.0);
        }
    }
}
