//! Polyhedral surfaces, and the regular (Platonic) h-polyhedra.

use std::collections::{HashMap, HashSet};

use glam::{DVec3, DVec4};

use crate::error::{GeomError, positive_length};
use crate::isometry::Isometry;
use crate::lorentz;
use crate::point::{IdealPoint, Point, Vertex, representable};
use crate::polygon::ConvexPolygon;
use crate::polygons::from_hyperboloid_checked;
use crate::ray::{Hit, Ray};

/// A polyhedral surface: a union of convex polygons (it may self-intersect
/// and need not be closed), with a reference centre.
///
/// Invariant: every face's normal points away from `center` (the outer side),
/// which is what refraction uses to tell entering from leaving. The one
/// documented exception is [`Polyhedron::golden_rectangles`], whose centre
/// lies on all three face planes. Faces obey [`ConvexPolygon`]'s invariants.
#[derive(Clone, Debug, PartialEq)]
pub struct Polyhedron {
    faces: Vec<ConvexPolygon>,
    center: Point,
}

/// The five regular convex polyhedra (a plain tag: no invariants).
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
    ///
    /// # Accuracy
    ///
    /// The vertices are the textbook Euclidean coordinates (with `φ` rounded
    /// to f64) normalised: unit to 2 ulps. The combinatorics are exact
    /// (face and vertex counts in `platonic_counts`).
    pub fn combinatorics(self) -> (Vec<DVec3>, Vec<Vec<usize>>) {
        let verts: Vec<DVec3> = self.template().into_iter().map(DVec3::normalize).collect();
        let faces = supporting_faces(&verts, &self.face_directions());
        (verts, faces)
    }

    /// Cosine of the Euclidean solid's dihedral angle (exact constants).
    fn euclidean_dihedral_cos(self) -> f64 {
        match self {
            Platonic::Tetrahedron => 1.0 / 3.0,
            Platonic::Cube => 0.0,
            Platonic::Octahedron => -1.0 / 3.0,
            Platonic::Dodecahedron => -(5f64.sqrt()).recip(),
            Platonic::Icosahedron => -(5f64.sqrt()) / 3.0,
        }
    }

    /// The hyperbolic circumradius of the regular h-polyhedron of this kind
    /// whose dihedral angles all equal `dihedral` (radians).
    ///
    /// Derivation (Klein model, where h-planes are flat): put the faces at
    /// Klein distance `h` from the origin along the unit face directions
    /// `n_i`. Face `i` is `x·n_i = h w`, i.e. `<X, N_i> = 0` with outward
    /// normal `N_i = (n_i, h)` (time in `w`), `<N_i,N_i> = 1 - h²` and, for
    /// adjacent faces, `<N_i,N_j> = n_i·n_j - h² = -cos θ_E - h²` where `θ_E`
    /// is the Euclidean solid's dihedral angle. The interior dihedral angle
    /// `θ` has `cos θ = -<N_i,N_j>/(1 - h²) = (h² + cos θ_E)/(1 - h²)`, so
    /// `h² = (cos θ - cos θ_E)/(1 + cos θ)`. The vertices sit at Klein radius
    /// `ρ = h R_E/r_E` (the Euclidean circumradius over inradius,
    /// `tan(π/p) tan(π/q)` for `{p,q}`), and the hyperbolic circumradius is
    /// `artanh ρ`. For the cube at `θ = 2π/5` this gives `h² = √5 - 2` and
    /// `cosh R = φ²/√2` (see [`crate::cube_435_circumradius`]).
    ///
    /// Admissible angles: `θ_ideal < θ < θ_E`, where `θ_E` is the Euclidean
    /// angle (a vanishing solid) and `θ_ideal` the ideal solid's angle
    /// (`ρ = 1`: the angle `π(1 - 2/q)` of the Euclidean vertex figure, 60°
    /// for the tetrahedron, cube and dodecahedron, 90° for the octahedron,
    /// 108° for the icosahedron).
    /// Outside that range: [`GeomError::BadAngle`].
    ///
    /// # Accuracy
    ///
    /// A few ulps of `ρ`; `artanh` amplifies that by `1/(1 - ρ²)` near the
    /// ideal limit. The solids built with it have their dihedral angles to
    /// 1e-12 (`other_compact_honeycomb_cells_have_their_dihedral_angles` in
    /// `tests/figures.rs`) and agree with the closed form for {4,3,5} to
    /// 1e-14 (`closed_form_matches_the_general_dihedral_formula`).
    pub fn circumradius_for_dihedral(self, dihedral: f64) -> Result<f64, GeomError> {
        if !(dihedral.is_finite() && dihedral > 0.0 && dihedral < std::f64::consts::PI) {
            return Err(GeomError::BadAngle(dihedral));
        }
        let c = dihedral.cos();
        let h2 = (c - self.euclidean_dihedral_cos()) / (1.0 + c);
        let rho = h2.sqrt() * self.euclidean_radius_ratio();
        if !(h2 > 0.0 && rho < 1.0) {
            return Err(GeomError::BadAngle(dihedral));
        }
        Ok(rho.atanh())
    }

    /// Circumradius over inradius of the Euclidean solid (exact constants).
    fn euclidean_radius_ratio(self) -> f64 {
        match self {
            Platonic::Tetrahedron => 3.0,
            Platonic::Cube | Platonic::Octahedron => 3f64.sqrt(),
            // R/r = tan(pi/p) tan(pi/q) for {p,q}; both are {5,3} / {3,5}.
            Platonic::Dodecahedron | Platonic::Icosahedron => {
                (std::f64::consts::PI / 5.0).tan() * 3f64.sqrt()
            }
        }
    }
}

/// For each face direction (any length), the vertices (unit vectors) that
/// maximise the dot product with it, sorted counter-clockwise seen from
/// outside (right-hand rule gives the outward normal).
fn supporting_faces(verts: &[DVec3], directions: &[DVec3]) -> Vec<Vec<usize>> {
    let mut faces = Vec::new();
    for dir in directions {
        let n = dir.normalize();
        let best = verts.iter().map(|v| v.dot(n)).fold(f64::MIN, f64::max);
        let face: Vec<usize> = (0..verts.len())
            .filter(|&i| verts[i].dot(n) > best - 1e-9)
            .collect();
        faces.push(counter_clockwise(verts, face, n));
    }
    faces
}

/// The indexed points sorted counter-clockwise about the unit axis `n`.
fn counter_clockwise(verts: &[DVec3], mut idx: Vec<usize>, n: DVec3) -> Vec<usize> {
    let Some(&first) = idx.first() else {
        return idx;
    };
    let u = (verts[first] - n * verts[first].dot(n)).normalize();
    let w = n.cross(u);
    idx.sort_by(|&i, &j| {
        let ai = verts[i].dot(w).atan2(verts[i].dot(u));
        let aj = verts[j].dot(w).atan2(verts[j].dot(u));
        ai.total_cmp(&aj)
    });
    idx
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

/// The polygons with the given vertex index lists.
fn polygons(verts: &[Vertex], faces: &[Vec<usize>]) -> Result<Vec<ConvexPolygon>, GeomError> {
    faces
        .iter()
        .map(|f| ConvexPolygon::new(f.iter().map(|&i| verts[i]).collect()))
        .collect()
}

/// The solid with vertices on the rays `dirs` at hyperbolic distance
/// `circumradius` and the given faces, centred at the origin.
fn solid(dirs: &[DVec3], faces: &[Vec<usize>], circumradius: f64) -> Result<Polyhedron, GeomError> {
    positive_length(circumradius)?;
    let verts = dirs
        .iter()
        .map(|d| {
            Point::at_distance_from_origin(*d, circumradius)
                .and_then(representable)
                .map(Vertex::Interior)
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Polyhedron::new(polygons(&verts, faces)?, Point::ORIGIN))
}

/// The unique undirected edges of a set of polygons (one polygon, or the
/// faces of a polyhedral surface), as pairs of vertices in the order they are
/// first met walking the faces; what a wireframe of rods is built from.
///
/// Two vertices are the same when they are of the same kind and their ball
/// coordinates are equal as f64 values (`-0.0 == 0.0`). Faces built from
/// shared points, and their images under one isometry, share vertices exactly
/// in this sense; vertices that only agree to rounding are kept apart, which
/// draws a duplicate (coincident) rod rather than a wrong one.
///
/// # Accuracy
///
/// Exact: a comparison of bit patterns, no tolerance (edge counts for every
/// solid, moved or not, in `edges_are_unique_and_survive_isometries`).
pub fn unique_edges(faces: &[ConvexPolygon]) -> Vec<(Vertex, Vertex)> {
    let mut ids: HashMap<(bool, [u64; 3]), usize> = HashMap::new();
    let mut id = |v: &Vertex| {
        let c = v.coords() + DVec3::ZERO;
        let key = (v.is_ideal(), [c.x.to_bits(), c.y.to_bits(), c.z.to_bits()]);
        let next = ids.len();
        *ids.entry(key).or_insert(next)
    };
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    for face in faces {
        let vs = face.vertices();
        for (i, a) in vs.iter().enumerate() {
            let b = &vs[(i + 1) % vs.len()];
            let (ia, ib) = (id(a), id(b));
            if ia != ib && seen.insert((ia.min(ib), ia.max(ib))) {
                out.push((*a, *b));
            }
        }
    }
    out
}

impl Polyhedron {
    /// A surface from faces and a centre; faces are re-oriented to point
    /// away from the centre.
    ///
    /// Infallible: a face whose plane passes through the centre is kept as
    /// given, and a face that cannot be rebuilt reversed (a tolerance check
    /// failing on the reversed order, which does not happen for faces that
    /// passed [`ConvexPolygon::new`]) is kept unreversed.
    ///
    /// # Accuracy
    ///
    /// Exact: faces are stored (or rebuilt reversed); orientation is decided
    /// by the sign of `<C, N>`, reliable unless the centre is within rounding
    /// of a face plane.
    pub fn new(faces: Vec<ConvexPolygon>, center: Point) -> Polyhedron {
        let c = center.to_hyperboloid();
        let faces = faces
            .into_iter()
            .map(|f| {
                if lorentz::dot(c, f.plane().normal()) > 0.0 {
                    let mut vs = f.vertices().to_vec();
                    vs.reverse();
                    ConvexPolygon::new(vs).unwrap_or(f)
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
    ///
    /// Errors: [`GeomError::BadRadius`] for a non-positive or non-finite
    /// radius, [`GeomError::NotInBall`] when the vertices are too far out for
    /// f64 (radius above ~37), and face construction errors.
    ///
    /// # Accuracy
    ///
    /// Vertices at the circumradius to 1e-14 relative; all edges equal to
    /// 1e-13 (`faces_point_outward_and_edges_are_equal` in this module).
    pub fn platonic(kind: Platonic, circumradius: f64) -> Result<Polyhedron, GeomError> {
        let (dirs, faces) = kind.combinatorics();
        solid(&dirs, &faces, circumradius)
    }

    /// The regular h-polyhedron of the given kind, centred at the origin, all
    /// of whose dihedral angles equal `dihedral` (radians); see
    /// [`Platonic::circumradius_for_dihedral`] for the derivation and the
    /// admissible range. The {4,3,5} honeycomb cell is
    /// `platonic_with_dihedral(Platonic::Cube, 2π/5)`.
    ///
    /// Errors: [`GeomError::BadAngle`] outside the admissible range, and
    /// [`Polyhedron::platonic`]'s.
    ///
    /// # Accuracy
    ///
    /// Dihedral angles equal `dihedral` to 1e-12
    /// (`other_compact_honeycomb_cells_have_their_dihedral_angles`).
    pub fn platonic_with_dihedral(kind: Platonic, dihedral: f64) -> Result<Polyhedron, GeomError> {
        Polyhedron::platonic(kind, kind.circumradius_for_dihedral(dihedral)?)
    }

    /// The ideal regular polyhedron: the vertices of the Euclidean solid
    /// centred at the origin, pushed onto the absolute. Every dihedral angle
    /// is `π(1 - 2/q)` for `{p,q}`, the lower end of
    /// [`Platonic::circumradius_for_dihedral`]'s range.
    ///
    /// Errors: face construction errors (none for the five solids).
    ///
    /// # Accuracy
    ///
    /// Vertices are unit vectors to 2 ulps; the edge count survives
    /// (`edges_are_unique_and_survive_isometries`).
    pub fn ideal_platonic(kind: Platonic) -> Result<Polyhedron, GeomError> {
        let (dirs, faces) = kind.combinatorics();
        let verts = dirs
            .iter()
            .map(|d| IdealPoint::from_direction(*d).map(Vertex::Ideal))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Polyhedron::new(polygons(&verts, &faces)?, Point::ORIGIN))
    }

    /// The cuboctahedron (Wythoff symbol `2 | 3 4`: 12 vertices, 8 triangles,
    /// 6 squares, two triangles and two squares alternating at each vertex),
    /// centred at the origin with its vertices at hyperbolic distance
    /// `circumradius`, on the rays through `(±1, ±1, 0)` and their cyclic
    /// permutations.
    ///
    /// Exact for the same reason as [`Polyhedron::platonic`]: the octahedral
    /// group fixes the origin, so it acts by hyperbolic isometries and is
    /// transitive on vertices and edges (all edges equal); the vertices of a
    /// Euclidean face lie on a plane, and pushing equal-norm points radially
    /// keeps them coplanar in the Klein model, hence on one h-plane.
    ///
    /// Errors: as [`Polyhedron::platonic`].
    ///
    /// # Accuracy
    ///
    /// Vertices at the circumradius to 1e-14 relative, the 24 edges equal to
    /// 1e-13 (`cuboctahedron_is_uniform` in `tests/figures.rs`).
    pub fn cuboctahedron(circumradius: f64) -> Result<Polyhedron, GeomError> {
        let mut dirs = Vec::new();
        for s1 in [-1.0, 1.0] {
            for s2 in [-1.0, 1.0] {
                dirs.extend(cyclic(DVec3::new(s1, s2, 0.0)));
            }
        }
        let dirs: Vec<DVec3> = dirs.into_iter().map(DVec3::normalize).collect();
        let mut face_dirs = signs3();
        face_dirs.extend(Platonic::Octahedron.template());
        let faces = supporting_faces(&dirs, &face_dirs);
        solid(&dirs, &faces, circumradius)
    }

    /// The small stellated dodecahedron `{5/2, 5}` as the union of its 60
    /// visible spike triangles (12 spikes of 5), centred at the origin, with
    /// its 12 tips at hyperbolic distance `circumradius`.
    ///
    /// Derivation (Klein model, where h-lines and h-planes are straight, so
    /// the stellation is the Euclidean one): the tips are an icosahedron's
    /// vertices; the 5 neighbours `p_0..p_4` of a tip `w` span a regular
    /// pentagon whose plane carries one pentagram face. The spike triangle at
    /// `p_i` has base the middle part of the diagonal `p_(i-1) p_(i+1)`, cut by
    /// the pentagram edges `p_i p_(i±2)` at fractions `1/φ²` and `1 - 1/φ²`
    /// (a pentagon diagonal is divided as `1/φ² : 1/φ³ : 1/φ²`). Klein-affine
    /// combinations of points with the same time coordinate are the same
    /// linear combinations of their hyperboloid vectors; each is renormalised
    /// with `-<Y,Y> = (1-t)² + t² + 2t(1-t) cosh d` (no cancellation), so
    /// vertices are accurate to a few ulps. Faces point away from the centre;
    /// the surface self-intersects only along the spikes' shared edges.
    ///
    /// Errors: as [`Polyhedron::platonic`].
    ///
    /// # Accuracy
    ///
    /// Spike sides equal to 1e-12, the 20 core vertices equidistant from the
    /// centre to 1e-12, and the tips the icosahedron's vertices to 1e-12
    /// (`small_stellated_dodecahedron_has_sixty_spike_triangles` in
    /// `tests/figures.rs`).
    pub fn small_stellated_dodecahedron(circumradius: f64) -> Result<Polyhedron, GeomError> {
        positive_length(circumradius)?;
        let tips: Vec<DVec3> = Platonic::Icosahedron
            .template()
            .into_iter()
            .map(DVec3::normalize)
            .collect();
        let (sh, ch) = (circumradius.sinh(), circumradius.cosh());
        let tip_points = tips
            .iter()
            .map(|d| Point::at_distance_from_origin(*d, circumradius).and_then(representable))
            .collect::<Result<Vec<_>, _>>()?;
        // The point at Klein-affine parameter t from tip a towards tip b.
        let between = |a: DVec3, b: DVec3, t: f64| {
            let y = (1.0 - t) * (a * sh).extend(ch) + t * (b * sh).extend(ch);
            let cosh_d = 1.0 + sh * sh * 0.5 * (a - b).length_squared();
            let n2 = (1.0 - t) * (1.0 - t) + t * t + 2.0 * t * (1.0 - t) * cosh_d;
            from_hyperboloid_checked(y / n2.sqrt())
        };
        let t = 1.0 / (PHI + 1.0);
        let neighbour_dot = 5f64.sqrt().recip();
        // Each of the 20 core vertices is met from several diagonals; keep the
        // first evaluation so that shared vertices are identical and
        // `edges()` sees the spikes' shared edges as one.
        let mut core: Vec<Point> = Vec::with_capacity(20);
        let mut canonical = |p: Point| {
            let dir = p.coords().normalize();
            match core
                .iter()
                .find(|q| q.coords().normalize().dot(dir) > 1.0 - 1e-9)
            {
                Some(q) => *q,
                None => {
                    core.push(p);
                    p
                }
            }
        };
        let mut faces = Vec::with_capacity(60);
        for w in &tips {
            let ring: Vec<usize> = (0..tips.len())
                .filter(|&i| (tips[i].dot(*w) - neighbour_dot).abs() < 1e-9)
                .collect();
            let ring = counter_clockwise(&tips, ring, *w);
            let m = ring.len();
            for i in 0..m {
                let (prev, tip, next) = (ring[(i + m - 1) % m], ring[i], ring[(i + 1) % m]);
                let near_next = canonical(between(tips[next], tips[prev], t)?);
                let near_prev = canonical(between(tips[prev], tips[next], t)?);
                faces.push(ConvexPolygon::new(vec![
                    Vertex::Interior(tip_points[tip]),
                    Vertex::Interior(near_next),
                    Vertex::Interior(near_prev),
                ])?);
            }
        }
        Ok(Polyhedron::new(faces, Point::ORIGIN))
    }

    /// The three golden rectangles of the icosahedron of hyperbolic
    /// circumradius `circumradius` centred at the origin: the quadrilaterals
    /// with vertices `(0, ±1, ±φ)`, `(±φ, 0, ±1)` and `(±1, ±φ, 0)` (directions),
    /// lying in the mutually orthogonal h-planes `x = 0`, `y = 0`, `z = 0`.
    ///
    /// In H³ they are not rectangles: each has two pairs of equal opposite
    /// sides and four equal acute angles (its symmetry group, the reflections
    /// in two coordinate planes, is transitive on its vertices; the angle sum
    /// of an h-quadrilateral is below 2π). Their 12 vertices are those of
    /// [`Polyhedron::platonic`]`(Platonic::Icosahedron, circumradius)`.
    ///
    /// The centre lies on all three face planes, so "pointing away from the
    /// centre" does not orient them; the face in the plane normal to axis
    /// `e` has normal `-e` (the polygons' convention: the `z = 0` one faces a
    /// camera on the `-z` side).
    ///
    /// Errors: as [`Polyhedron::platonic`].
    ///
    /// # Accuracy
    ///
    /// Opposite sides equal to 1e-13, the four angles equal to 1e-12, the
    /// three planes orthogonal to 1e-15 and the vertices the icosahedron's
    /// to 1e-13 (`golden_rectangles_are_three_orthogonal_quadrilaterals`).
    pub fn golden_rectangles(circumradius: f64) -> Result<Polyhedron, GeomError> {
        positive_length(circumradius)?;
        let corners = [
            DVec3::new(0.0, 1.0, PHI),
            DVec3::new(0.0, -1.0, PHI),
            DVec3::new(0.0, -1.0, -PHI),
            DVec3::new(0.0, 1.0, -PHI),
        ];
        let mut faces = Vec::with_capacity(3);
        for (k, axis) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
            let mut verts = corners
                .iter()
                .map(|c| {
                    Point::at_distance_from_origin(cyclic(*c)[k], circumradius)
                        .and_then(representable)
                        .map(Vertex::Interior)
                })
                .collect::<Result<Vec<_>, _>>()?;
            let face = ConvexPolygon::new(verts.clone())?;
            let face = if face.plane().normal().truncate().dot(axis) > 0.0 {
                verts.reverse();
                ConvexPolygon::new(verts)?
            } else {
                face
            };
            faces.push(face);
        }
        Ok(Polyhedron {
            faces,
            center: Point::ORIGIN,
        })
    }

    /// The unique undirected edges of all faces, as pairs of vertices in the
    /// order they are first met walking the faces; see [`unique_edges`].
    ///
    /// # Accuracy
    ///
    /// Exact (see [`unique_edges`]).
    pub fn edges(&self) -> Vec<(Vertex, Vertex)> {
        unique_edges(&self.faces)
    }

    /// The faces.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored faces.
    pub fn faces(&self) -> &[ConvexPolygon] {
        &self.faces
    }

    /// The faces, taken out of the polyhedron (no copy).
    pub fn into_faces(self) -> Vec<ConvexPolygon> {
        self.faces
    }

    /// The reference centre.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored point.
    pub fn center(&self) -> Point {
        self.center
    }

    /// The image under an isometry.
    ///
    /// # Accuracy
    ///
    /// As [`ConvexPolygon::transformed`] for each face and
    /// [`Isometry::apply`] for the centre (hits agree with the original's to
    /// 1e-10 relative, `platonic_hits_lie_on_faces` in
    /// `tests/properties.rs`; the same far-out limitation applies).
    pub fn transformed(&self, iso: &Isometry) -> Polyhedron {
        Polyhedron {
            faces: self.faces.iter().map(|f| f.transformed(iso)).collect(),
            center: iso.apply(&self.center),
        }
    }

    /// The nearest intersection with any face in `(t_min, t_max)`.
    ///
    /// # Accuracy
    ///
    /// As [`ConvexPolygon::intersect`] for the face hit; shared edges are
    /// watertight (`rays_through_shared_edges_hit_the_solid`).
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
    ///
    /// # Accuracy
    ///
    /// As [`Point::to_hyperboloid`]: 2 ulps per component.
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
                .intersect(&Ray::from_origin_unchecked(dir), 0.0, f64::INFINITY)
                .unwrap();
            assert!(hit.t > 0.0 && hit.t <= 0.3 + 1e-12);
            // Leaving: direction and outward normal agree.
            assert!(
                lorentz::dot(
                    Ray::from_origin_unchecked(dir).tangent_at(hit.t),
                    hit.normal
                ) > 0.0
            );
        }
    }
}
