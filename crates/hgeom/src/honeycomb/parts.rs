//! A honeycomb's parts listed one by one (vertices, edges, faces), for
//! whoever needs them as explicit pieces rather than walked: a mesh
//! exporter, a test that checks the walk against explicit shapes.
//!
//! **Enumeration.** Every chamber of the Coxeter group `[p,q,r]` is the
//! image `g C` of the characteristic simplex for one group element `g`, a
//! product of the reflections `R_i`; a breadth-first search on `g` (the
//! neighbours of `g C` are `g R_i C`) reaches the chambers in order of the
//! fewest reflections, so each `g` is a shortest word and carries the
//! least rounding. The caller says which chambers to go on to (by their
//! four vertices); chambers are told apart by their interior point `g c`,
//! `c` the normalised sum of the simplex's vertices (timelike: a sum of
//! future vectors).
//!
//! **The parts of one chamber** (Wythoff's construction, `uniform.rs`):
//! the vertex `g s`; for each ringed node `i` the edge `g [s, R_i s]`; for
//! each face pair `(i, j)` the polygon `g (<R_i, R_j> s)`, its vertices in
//! order round its centre. A part reached from several chambers is listed
//! once: vertices by position, edges by their midpoint (the normalised sum
//! of the ends, timelike even when both ends are ideal), faces by centre,
//! each compared by hyperbolic distance below [`SAME_PART`].
//!
//! **Which parts, in which class.** A regular honeycomb's part is drawn
//! when one of its cells is (a depth-limited honeycomb), and its class is
//! the least rank of its cells, exactly as the walk decides
//! (`RegularHoneycomb::present`, `RegularHoneycomb::class`): the cells of
//! the vertex `s = v0` are the orbit of `v3` under `<R1, R2, R3>`, of the
//! edge under `<R2, R3>`, of the face `v3` and `R3 v3`, each mapped by `g`.
//! Uniform honeycombs have no depth and one class.

use foldhash::{HashMap, HashMapExt};
use glam::{DMat4, DVec4};

use crate::error::GeomError;
use crate::lorentz;

use super::cells::orbit;
use super::simplex::CoxeterSimplex;
use super::style::{HoneycombPart, encode_part};
use super::uniform::{SeedParts, face_pairs};
use super::walk::RegularHoneycomb;

/// Two parts whose keys (position, midpoint or centre) are closer than
/// this hyperbolic distance are one part.
const SAME_PART: f64 = 1e-7;

/// Bucket size of the part look-up, in Klein coordinates.
const BUCKET: f64 = 1e-3;

/// One part of a honeycomb: its geometry in the world frame, on the
/// hyperboloid (finite points have `<x,x> = -1`; ideal ones are null with
/// time 1), and the code a hit on it reports ([`crate::Hit::part`]: its
/// kind and class, [`super::decode_honeycomb_part`]).
#[derive(Clone, Debug, PartialEq)]
pub struct HoneycombPiece<T> {
    /// The part's points.
    pub geometry: T,
    /// The part code, as a hit on this part reports it.
    pub part: u32,
}

/// The drawn parts of a honeycomb within the chambers searched
/// ([`RegularHoneycomb::explicit_parts`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct HoneycombPieces {
    /// Finite vertices, as points (drawn as balls of the style's radius).
    pub vertices: Vec<HoneycombPiece<DVec4>>,
    /// Edges, as their two ends (either may be ideal).
    pub edges: Vec<HoneycombPiece<[DVec4; 2]>>,
    /// Faces, as their vertices in order round the centre.
    pub faces: Vec<HoneycombPiece<Vec<DVec4>>>,
    /// How many chambers the search visited.
    pub chambers: usize,
}

/// A set of points of H³ (or ideal points) compared by distance.
struct PointSet {
    index: HashMap<[i64; 3], Vec<DVec4>>,
}

impl PointSet {
    fn new() -> PointSet {
        PointSet {
            index: HashMap::new(),
        }
    }

    fn bucket(x: DVec4) -> [i64; 3] {
        let k = x.truncate() / x.w / BUCKET;
        // Klein coordinates lie in the unit ball: far inside i64.
        [k.x.floor() as i64, k.y.floor() as i64, k.z.floor() as i64]
    }

    /// Adds the timelike point `x` unless it is already in; true if new.
    fn insert(&mut self, x: DVec4) -> bool {
        let [bx, by, bz] = PointSet::bucket(x);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(xs) = self.index.get(&[bx + dx, by + dy, bz + dz])
                        && xs.iter().any(|y| lorentz::distance(*y, x) < SAME_PART)
                    {
                        return false;
                    }
                }
            }
        }
        self.index.entry([bx, by, bz]).or_default().push(x);
        true
    }
}

/// `x` on the hyperboloid (timelike) or with time 1 (null).
fn normalised(x: DVec4) -> DVec4 {
    let n = lorentz::dot(x, x);
    if n < -1e-12 * x.w * x.w {
        x / (-n).sqrt()
    } else {
        x / x.w
    }
}

/// The normalised sum of points: a timelike midpoint or centre.
fn centre(points: &[DVec4]) -> DVec4 {
    let sum = points.iter().fold(DVec4::ZERO, |a, x| a + *x);
    sum / (-lorentz::dot(sum, sum)).sqrt()
}

/// The faces of the base chamber: for each face pair, the orbit of the
/// seed under `<R_i, R_j>` sorted by angle round its centre.
fn base_faces(simplex: &CoxeterSimplex, s: DVec4, rings: super::Rings) -> Option<Vec<Vec<DVec4>>> {
    let n = simplex.normals();
    let mut faces = Vec::new();
    for (i, j) in face_pairs(&n, rings) {
        let ring = orbit(s, &[simplex.reflection(i), simplex.reflection(j)])?;
        let c = centre(&ring);
        let e1 = ring[0] + lorentz::dot(ring[0], c) * c;
        let e1 = e1 / lorentz::dot(e1, e1).sqrt();
        let normal = lorentz::orthogonal_complement(ring[0], ring[1], ring[2]);
        let e2 = lorentz::orthogonal_complement(c, e1, normal);
        let e2 = e2 / lorentz::dot(e2, e2).sqrt();
        let angle = |x: &DVec4| lorentz::dot(*x, e2).atan2(lorentz::dot(*x, e1));
        let mut sorted = ring;
        sorted.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
        faces.push(sorted);
    }
    Some(faces)
}

impl RegularHoneycomb {
    /// The length of its edges (all edges of a uniform honeycomb have one
    /// length): twice the seed's distance `δ` from a ringed mirror,
    /// `sinh δ = <s, n_i>` (`uniform.rs`). `None` when the vertices are
    /// ideal (the edges are infinite).
    pub fn edge_length(&self) -> Option<f64> {
        let simplex = CoxeterSimplex::new(self.symbol());
        let rings = self.rings();
        if rings.seed_is_ideal(&simplex) {
            return None;
        }
        let (seed, _) = SeedParts::new(&simplex, rings, &self.style()).ok()?;
        let i = rings.nodes().next()?;
        Some(2.0 * lorentz::dot(seed.seed(), simplex.normals()[i]).asinh())
    }

    /// The parts this honeycomb draws (its style's vertices, edges and
    /// faces, within its depth), in the world frame, found by a
    /// breadth-first search of the chambers of its Coxeter group from the
    /// base chamber (module docs): the search goes on to a chamber when
    /// `go_on(corners)` holds for its vertices (world frame: hyperboloid
    /// points, or null with time 1 where ideal), and lists the parts of
    /// every chamber it visits. The
    /// order is that of the search, so the same honeycomb and rule give the
    /// same list. A depth-limited honeycomb with finite cells and vertices
    /// needs no rule: the search ends past its last cell by itself.
    ///
    /// Errors: [`GeomError::TooManyCells`] when more than `max_chambers`
    /// chambers would be visited; [`GeomError::BadRings`] if the seed's
    /// faces cannot be formed (never for a valid honeycomb).
    pub fn explicit_parts(
        &self,
        mut go_on: impl FnMut(&[DVec4; 4]) -> bool,
        max_chambers: usize,
    ) -> Result<HoneycombPieces, GeomError> {
        let style = self.style();
        let simplex = CoxeterSimplex::new(self.symbol());
        let rings = self.rings();
        let (seed, _) = SeedParts::new(&simplex, rings, &style)?;
        let s = seed.seed();
        let ideal_seed = rings.seed_is_ideal(&simplex);
        let v = simplex.vertices();
        let refl = [0, 1, 2, 3].map(|i| simplex.reflection(i));
        let faces = if style.faces {
            base_faces(&simplex, s, rings).ok_or(GeomError::BadRings)?
        } else {
            Vec::new()
        };
        // The cells of each kind of part, in the base chamber (regular
        // honeycombs only; uniform ones draw everything in class 0).
        let regular = rings.is_regular();
        let cells_of = |gens: &[DMat4]| -> Vec<DVec4> {
            if regular {
                orbit(v[3], gens).unwrap_or_else(|| vec![v[3]])
            } else {
                Vec::new()
            }
        };
        let vertex_cells = if ideal_seed {
            Vec::new()
        } else {
            cells_of(&refl[1..])
        };
        let edge_cells = cells_of(&refl[2..]);
        let face_cells = if regular {
            vec![v[3], refl[3] * v[3]]
        } else {
            Vec::new()
        };
        let inner = centre(&v);
        // A depth-limited honeycomb with finite cells stops by itself: a
        // chamber holding a piece of a drawn part has its interior point
        // within a cell's diameter of that part, and every drawn part lies
        // within `reach` of the base point.
        let within_reach = self.reach().map(|cosh_reach| {
            let diameter = 2.0 * lorentz::distance(v[3], v[0]);
            (cosh_reach.acosh() + diameter).cosh()
        });
        let to_world = self.placement().to_lorentz();
        let mut out = HoneycombPieces::default();
        let (mut chambers, mut vertices, mut edges, mut face_keys) = (
            PointSet::new(),
            PointSet::new(),
            PointSet::new(),
            PointSet::new(),
        );
        let too_many = GeomError::TooManyCells {
            limit: max_chambers,
        };
        let mut queue = std::collections::VecDeque::from([DMat4::IDENTITY]);
        chambers.insert(inner);
        while let Some(g) = queue.pop_front() {
            out.chambers += 1;
            let world = |x: DVec4| normalised(to_world * x);
            let listed = |cells: &[DVec4]| !regular || self.present(cells, &g);
            let part = |kind: HoneycombPart, cells: &[DVec4]| {
                let class = if regular { self.class(cells, &g) } else { 0 };
                encode_part(kind, class)
            };
            let gs = g * s;
            if style.vertices.is_some()
                && !ideal_seed
                && listed(&vertex_cells)
                && vertices.insert(gs)
            {
                out.vertices.push(HoneycombPiece {
                    geometry: world(gs),
                    part: part(HoneycombPart::Vertex, &vertex_cells),
                });
            }
            if style.edges.is_some() && listed(&edge_cells) {
                for i in rings.nodes() {
                    let other = g * (refl[i] * s);
                    if edges.insert(centre(&[gs, other])) {
                        // The ringed node's edge has the cells of the
                        // regular edge only when it is node 0.
                        out.edges.push(HoneycombPiece {
                            geometry: [world(gs), world(other)],
                            part: part(HoneycombPart::Edge, &edge_cells),
                        });
                    }
                }
            }
            if listed(&face_cells) {
                for ring in &faces {
                    let ring: Vec<DVec4> = ring.iter().map(|x| g * *x).collect();
                    if face_keys.insert(centre(&ring)) {
                        out.faces.push(HoneycombPiece {
                            geometry: ring.iter().map(|x| world(*x)).collect(),
                            part: part(HoneycombPart::Face, &face_cells),
                        });
                    }
                }
            }
            for r in &refl {
                let h = g * *r;
                let x = centre(&[h * inner]);
                if !x.is_finite() {
                    return Err(too_many);
                }
                let reachable = within_reach.is_none_or(|c| x.w <= c);
                if reachable && go_on(&v.map(|c| world(h * c))) && chambers.insert(x) {
                    if out.chambers + queue.len() >= max_chambers {
                        return Err(too_many);
                    }
                    queue.push_back(h);
                }
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::honeycomb::{HoneycombStyle, Schlafli, decode_honeycomb_part};

    /// A chamber's interior point (`centre` drops ideal corners' scale).
    fn inner(corners: &[DVec4; 4]) -> DVec4 {
        centre(corners)
    }

    fn everything(depth: Option<u32>, classes: u32) -> HoneycombStyle {
        HoneycombStyle {
            edges: Some(0.05),
            faces: true,
            vertices: Some(0.08),
            depth,
            cell_classes: classes,
        }
    }

    /// The base cell alone is the cell's polyhedron: a cube for `{4,3,5}`,
    /// a dodecahedron for `{5,3,4}`, an icosahedron for `{3,5,3}`.
    #[test]
    fn the_base_cell_has_its_polyhedrons_vertices_edges_and_faces() {
        for ((p, q, r), counts) in [
            ((4, 3, 5), (8, 12, 6)),
            ((5, 3, 4), (20, 30, 12)),
            ((3, 5, 3), (12, 30, 20)),
        ] {
            let h = RegularHoneycomb::new(Schlafli::new(p, q, r).unwrap(), everything(Some(0), 1))
                .unwrap();
            let parts = h.explicit_parts(|c| inner(c).w < 20.0, 100_000).unwrap();
            let got = (parts.vertices.len(), parts.edges.len(), parts.faces.len());
            assert_eq!(got, counts, "{{{p},{q},{r}}}");
            for f in &parts.faces {
                assert_eq!(f.geometry.len(), p as usize);
            }
        }
    }

    /// Depth 1 of `{4,3,5}` is seven cubes: 6 + 6 * 5 faces, of which the
    /// base cube's six rank 0 and the rest 1, as the walk colours them.
    #[test]
    fn classes_are_the_least_rank_of_the_parts_cells() {
        let h =
            RegularHoneycomb::new(Schlafli::new(4, 3, 5).unwrap(), everything(Some(1), 2)).unwrap();
        let parts = h.explicit_parts(|c| inner(c).w < 20.0, 100_000).unwrap();
        assert_eq!(parts.faces.len(), 36);
        let class = |code: u32| decode_honeycomb_part(code).1;
        let ones = parts.faces.iter().filter(|f| class(f.part) == 1).count();
        assert_eq!(ones, 30);
        // The base cube's vertices and edges belong to it: class 0.
        let zero_edges = parts.edges.iter().filter(|e| class(e.part) == 0).count();
        assert_eq!(zero_edges, 12);
    }

    /// The edge length is the distance between a listed edge's ends.
    #[test]
    fn edge_length_is_the_distance_between_an_edges_ends() {
        for (p, q, r) in [(4, 3, 5), (5, 3, 4), (3, 5, 3), (4, 4, 3)] {
            let h = RegularHoneycomb::new(Schlafli::new(p, q, r).unwrap(), everything(Some(0), 1))
                .unwrap();
            let parts = h.explicit_parts(|c| inner(c).w < 20.0, 100_000).unwrap();
            let [a, b] = parts.edges[0].geometry;
            let l = h.edge_length().unwrap();
            assert!((lorentz::distance(a, b) - l).abs() < 1e-12, "{p}{q}{r}");
        }
        let ideal = RegularHoneycomb::new(Schlafli::new(3, 3, 6).unwrap(), everything(Some(0), 1));
        assert_eq!(ideal.unwrap().edge_length(), None);
    }

    /// Placement moves every part: the listed points are the placed ones.
    #[test]
    fn parts_follow_the_placement() {
        let h =
            RegularHoneycomb::new(Schlafli::new(5, 3, 4).unwrap(), everything(Some(0), 1)).unwrap();
        let to = crate::Point::new(0.3, -0.2, 0.1).unwrap();
        let iso = crate::Isometry::transvection_from_origin(to);
        let moved = h.transformed(&iso);
        let a = h.explicit_parts(|_| true, 100_000).unwrap();
        let b = moved.explicit_parts(|_| true, 100_000).unwrap();
        let m = iso.to_lorentz();
        for (x, y) in a.vertices.iter().zip(&b.vertices) {
            assert!(lorentz::distance(m * x.geometry, y.geometry) < 1e-12);
        }
    }

    /// The search stops where it is told, and refuses to run past its
    /// budget.
    #[test]
    fn the_search_is_bounded() {
        let h =
            RegularHoneycomb::new(Schlafli::new(4, 3, 5).unwrap(), everything(None, 1)).unwrap();
        let near = h.explicit_parts(|c| inner(c).w < 3.0, 1_000_000).unwrap();
        let far = h.explicit_parts(|c| inner(c).w < 6.0, 1_000_000).unwrap();
        assert!(near.chambers < far.chambers);
        assert!(matches!(
            h.explicit_parts(|_| true, 1000),
            Err(GeomError::TooManyCells { .. })
        ));
    }
}
