//! Uniform honeycombs by Wythoff's construction: the parts inside one
//! chamber of the Coxeter group `[p,q,r]` for a seed point set by the
//! ringed nodes of the diagram.
//!
//! **The seed.** Node `i` of the diagram is the mirror `m_i` of the
//! characteristic simplex `C` (opposite its vertex `v_i`,
//! [`CoxeterSimplex`]). The seed `s` lies on every mirror whose node is not
//! ringed and at one distance `δ` from every ringed one. With `v̂_i` the
//! vertex scaled so that `<v̂_i, n_i> = 1` (it is orthogonal to the other
//! three normals), `s = Σ_{i ringed} v̂_i` has `<s, n_j> = 1` for ringed `j`
//! and `0` for the others, and is future timelike (a sum of future
//! vectors), or null when one ideal vertex alone is ringed: then the
//! honeycomb's vertices are ideal. Normalised, `sinh δ = <s, n_i>`. Ringing
//! node 0 alone gives the regular honeycomb `{p,q,r}`, node 3 alone its
//! dual `{r,q,p}`.
//!
//! **The half-edges.** The vertices are the orbit of `s`; for each ringed
//! `i` the edge from `s` to `R_i s` crosses `m_i` at right angles at its
//! midpoint, the foot `f_i = s - <s,n_i> n_i` (normalised). `f_i` lies in
//! `C`: for `j != i`, `<f_i, n_j> ∝ <s,n_j> - <s,n_i> <n_i,n_j>`, and both
//! terms are `>= 0` (`<n_i,n_j> = -cos(π/m_ij) <= 0`). So every edge is two
//! half-edges, each `g [s, f_i]` inside the chamber `g C`.
//!
//! **The parts in one chamber.** Folding a point into `C` moves it no
//! farther from a point of `C` (`walk.rs`), so for `X` in `C` the nearest
//! vertex is `s` and the nearest half-edge of each kind is `C`'s own
//! `[s, f_i]` (fold a nearest point of `g [s, f_i]`: it lands on
//! `[s, f_i]`, no farther from `X`). The rods about all edges meet `C`
//! exactly in the capsules of radius `w` about the half-edges `[s, f_i]`:
//! the tube about the edge's line where the foot lies between `s` and
//! `f_i`, and the ball of radius `w` about `s` beyond. No cap is needed at
//! `f_i`: the plane through `f_i` orthogonal to the edge is `m_i`, with `C`
//! on the side of `s`. The end at `s` is the plane through `s` orthogonal
//! to the edge, `<X, U_i> = 0` with `U_i` the edge's unit tangent at `s`
//! towards `f_i`; a tube point counts where `<X, U_i> >= 0`. The first
//! point of a union of capsules is the least first point of each, and the
//! shared ball about `s` is one more test (or none: it lies inside a vertex
//! ball of a radius at least `w`, and at an ideal seed there is none).
//!
//! **The faces.** For each pair of mirrors `i < j` with one of them ringed
//! the dihedral group `<R_i, R_j>` moves `s` round a polygon (none when
//! `m_ij = 2` and only one is ringed: that "polygon" is an edge). It lies
//! in the plane `F` through `s` orthogonal to the line `L = m_i ∩ m_j`,
//! centred on the foot `c` of `s` on `L`, and its piece in `C` is bounded
//! by `m_i`, `m_j` and the half-edges of the ringed ones among `i`, `j`:
//! the quadrilateral `c f_i s f_j` when both are ringed, the triangle
//! `c f_i s` when only `i` is (then `s` and `c` lie on `m_j`). So inside
//! `C` a point of `F` is on the piece when it is on `c`'s side of the plane
//! through each such half-edge orthogonal to `F` (normal `B_k`, orthogonal
//! to `s`, `f_k` and `F`'s normal `P`). Faces are planes of no thickness,
//! so no other chamber's piece reaches into `C`.
//!
//! Ringing node 0 alone gives exactly the regular honeycomb's parts: the
//! seed `v0`, the half-edge `v0 v1`, the face piece `v2 v1 v0` in `m3`; the
//! tests check this walk against the regular one for all fifteen symbols,
//! and genuinely uniform ones against explicit rods, balls and polygons.

use glam::DVec4;

use crate::error::GeomError;
use crate::lorentz;

use super::domain_ray::{DomainPart, DomainRay};
use super::kernels::{ball_first_v, ball_normal, tube_normal, tube_roots, walls_through};
use super::simplex::CoxeterSimplex;
use super::style::HoneycombStyle;

/// The ringed nodes of the Coxeter diagram `[p,q,r]`: node `i` is the
/// mirror opposite vertex `v_i` of the characteristic simplex (`v0` a
/// vertex of `{p,q,r}`, `v3` a cell centre). Ringing node 0 alone gives
/// `{p,q,r}` itself; `(0, 1)` its truncation, `(1)` its rectification,
/// `(0, 3)` its runcination, all four its omnitruncation. Written `t0,3`
/// and so on, after the mathematicians' `t_{0,3}{p,q,r}`.
///
/// Invariant: a non-empty subset of `{0, 1, 2, 3}`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rings(u8);

impl Rings {
    /// Node 0 alone: the regular honeycomb.
    pub const REGULAR: Rings = Rings(1);

    /// Node 3 alone: the dual regular honeycomb `{r,q,p}`, with a vertex
    /// where `{p,q,r}` has a cell centre.
    pub const DUAL: Rings = Rings(1 << 3);

    /// The rings on these nodes (each 0 to 3, in any order; repeats are
    /// one ring).
    ///
    /// Errors: [`GeomError::BadRings`] for no node or a node beyond 3.
    pub fn new(nodes: &[u32]) -> Result<Rings, GeomError> {
        let mut bits = 0u8;
        for &n in nodes {
            if n > 3 {
                return Err(GeomError::BadRings);
            }
            bits |= 1 << n;
        }
        if bits == 0 {
            return Err(GeomError::BadRings);
        }
        Ok(Rings(bits))
    }

    /// True if node `i` is ringed.
    pub fn contains(self, i: usize) -> bool {
        i < 4 && self.0 & (1 << i) != 0
    }

    /// The ringed nodes, in increasing order.
    pub fn nodes(self) -> impl Iterator<Item = usize> {
        (0..4).filter(move |&i| self.contains(i))
    }

    /// True for node 0 alone (the regular honeycomb).
    pub fn is_regular(self) -> bool {
        self == Rings::REGULAR
    }

    /// True if the uniform honeycomb of these rings in `simplex` has ideal
    /// vertices: one ideal vertex of the simplex alone is ringed.
    pub fn seed_is_ideal(self, simplex: &CoxeterSimplex) -> bool {
        let mut nodes = self.nodes();
        match (nodes.next(), nodes.next()) {
            (Some(k), None) => simplex.ideal()[k],
            _ => false,
        }
    }
}

impl std::fmt::Display for Rings {
    /// `t0,3`: the ringed nodes after a `t`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let nodes: Vec<String> = self.nodes().map(|i| i.to_string()).collect();
        write!(f, "t{}", nodes.join(","))
    }
}

/// How far (as `<X,B>/x0`, about the sinh of a distance) a point may lie
/// past the end plane of a half-edge or the edge of a face piece and still
/// count: the rods and balls cover those seams.
const SEAM_SLACK: f64 = 1e-9;

/// How far past the exit (in `tanh τ`) a face piece's plane crossing may
/// round and still be taken as the exit point: far above the rounding of
/// `-α/β` and of the exit's own quotient, far below any feature.
const SEAM_ROUNDING: f64 = 1e-12;

/// The tube about one half-edge `[s, f_i]`: the orthonormal pair `n1`, `n2`
/// orthogonal to its line, and its unit tangent `u` at `s` towards `f_i`
/// (`None` at an ideal seed: the tube runs out to the absolute).
///
/// `walls`: the bits of the mirrors holding the whole line (the unringed
/// mirrors orthogonal to `m_i`): a point within the edge radius of the
/// line is within it of each of them, so a ray that does not come that
/// near all of them in the chamber cannot meet the tube there.
#[derive(Clone, Debug)]
struct HalfEdge {
    n1: DVec4,
    n2: DVec4,
    u: Option<DVec4>,
    walls: u32,
    /// The ringed node whose mirror the edge crosses: its colour class.
    node: usize,
}

/// One face piece: the normal `p` of its plane, the normals `bounds` of
/// the planes through its half-edges, positive on the piece's side, and
/// the wall it lies in, if any (a regular face lies in `m3`): such a piece
/// is met where the ray leaves through that wall, as the walk computes it,
/// not where a plane crossing computed apart rounds to.
#[derive(Clone, Debug)]
struct FacePiece {
    p: DVec4,
    bounds: Vec<DVec4>,
    wall: Option<usize>,
    /// The kind of cell on each side, where `<X, p>` is positive and where
    /// it is negative: the simplex vertices `v_k`, `v_l` on the line `L`
    /// the face is orthogonal to are the cells' centres, one on each side;
    /// where the plane passes through one of them (a square of the
    /// rectified `{4,3,5}` is centred on the cube's face centre `v2`), no
    /// cell is centred there, and the other kind is on both sides.
    sides: [usize; 2],
}

/// The parts of a uniform honeycomb inside the characteristic simplex
/// (module docs). The ball about the seed in the vertices' material is the
/// walk's ordinary vertex ([`super::domain::WalkDomain`]); this holds the
/// rest.
#[derive(Clone, Debug)]
pub(super) struct SeedParts {
    seed: DVec4,
    half_edges: Vec<HalfEdge>,
    /// `sinh²` of the edge radius.
    sinh2_edge: f64,
    /// `cosh` of the edge radius, for the ball about the seed that caps
    /// the half-edges; `None` where it is not tested (no edges, an ideal
    /// seed, or inside a vertex ball at least as wide).
    cap_cosh: Option<f64>,
    /// The bits of the mirrors through the seed (the unringed ones): the
    /// cap's points are within the edge radius of each.
    cap_walls: u32,
    /// The union of the tubes' walls and (with a cap) the cap's.
    culling_walls: u32,
    pieces: Vec<FacePiece>,
}

impl SeedParts {
    /// The seed of `rings` in `simplex` and the parts `style` draws.
    ///
    /// Errors: [`GeomError::BadRings`] if the seed is not a point or an
    /// ideal point of the space (it always is for a hyperbolic symbol).
    pub(super) fn new(
        simplex: &CoxeterSimplex,
        rings: Rings,
        style: &HoneycombStyle,
    ) -> Result<(SeedParts, Option<DVec4>), GeomError> {
        let n = simplex.normals();
        let v = simplex.vertices();
        let mut s = DVec4::ZERO;
        for i in rings.nodes() {
            s += v[i] / lorentz::dot(v[i], n[i]);
        }
        let ss = lorentz::dot(s, s);
        let ideal = rings.seed_is_ideal(simplex);
        if ideal {
            // A null vector at time 1, as the simplex keeps ideal vertices.
            s /= s.w;
        } else if ss < 0.0 && s.w > 0.0 {
            s /= (-ss).sqrt();
        } else {
            return Err(GeomError::BadRings);
        }
        let half_edges: Vec<HalfEdge> = rings
            .nodes()
            .map(|i| half_edge(s, ideal, &n, i))
            .collect::<Option<_>>()
            .ok_or(GeomError::BadRings)?;
        let pieces = if style.faces {
            face_pieces(s, &n, &v, rings).ok_or(GeomError::BadRings)?
        } else {
            Vec::new()
        };
        let edges = style.edges;
        let cap_cosh = match (edges, style.vertices) {
            (Some(w), vertex) if !ideal && vertex.is_none_or(|r| r < w) => Some(w.cosh()),
            _ => None,
        };
        let vertex_ball = (!ideal && style.vertices.is_some()).then_some(s);
        let half_edges = if edges.is_some() {
            half_edges
        } else {
            Vec::new()
        };
        let cap_walls = walls_through(s, &n);
        let culling_walls = half_edges
            .iter()
            .fold(if cap_cosh.is_some() { cap_walls } else { 0 }, |bits, e| {
                bits | e.walls
            });
        Ok((
            SeedParts {
                seed: s,
                half_edges,
                sinh2_edge: edges.map_or(0.0, |w| w.sinh() * w.sinh()),
                cap_cosh,
                cap_walls,
                culling_walls,
                pieces,
            },
            vertex_ball,
        ))
    }

    /// The seed: a hyperboloid point, or null with time 1 when ideal.
    pub(super) fn seed(&self) -> DVec4 {
        self.seed
    }

    /// `sinh²` of the edge radius (0 without edges).
    pub(super) fn sinh2_edge(&self) -> f64 {
        self.sinh2_edge
    }

    /// The bits of the walls whose nearness decides whether a tube or the
    /// cap is tested: 0 when nothing is culled (no edges, or every mirror
    /// ringed), and then the walls need not be measured.
    pub(super) fn culling_walls(&self) -> u32 {
        self.culling_walls
    }

    /// The first of these parts the domain ray meets at
    /// `floor < v <= window` (in `v = e^{2τ}`), if before `found`'s;
    /// `near_walls` holds the bits of the walls the ray may come within the
    /// edge radius of in the chamber (`WalkDomain::walls_within`), at least
    /// those of [`Self::culling_walls`].
    pub(super) fn first_part(
        &self,
        ray: &DomainRay,
        floor: f64,
        window: f64,
        lambda2: f64,
        near_walls: u32,
        found: &mut Option<(f64, DomainPart)>,
    ) {
        let better = |v: f64, found: &Option<(f64, DomainPart)>| {
            v > floor && v <= window && found.is_none_or(|(best, _)| v < best)
        };
        // The point at v, up to the positive factor cosh τ: o + tanh τ d.
        let at = |v: f64| {
            let tanh = (v - 1.0) / (v + 1.0);
            ray.o + tanh * ray.d
        };
        let k = self.sinh2_edge * lambda2;
        for (i, e) in self.half_edges.iter().enumerate() {
            if near_walls & e.walls != e.walls {
                continue;
            }
            let o = [lorentz::dot(ray.o, e.n1), lorentz::dot(ray.o, e.n2)];
            let d = [lorentz::dot(ray.d, e.n1), lorentz::dot(ray.d, e.n2)];
            let Some((near, far)) = tube_roots(o, d, k) else {
                continue;
            };
            for v in [near, far] {
                if !better(v, found) {
                    continue;
                }
                let x = at(v);
                if e.u
                    .is_none_or(|u| lorentz::dot(x, u) >= -SEAM_SLACK * x.w.abs())
                {
                    *found = Some((v, DomainPart::HalfEdge(i)));
                }
            }
        }
        if let Some(cosh_w) = self.cap_cosh
            && near_walls & self.cap_walls == self.cap_walls
            && let Some(v) = ball_first_v(ray.o, ray.d, self.seed, cosh_w * lambda2.sqrt(), floor)
            && better(v, found)
        {
            *found = Some((v, DomainPart::Cap));
        }
        for (i, piece) in self.pieces.iter().enumerate() {
            let (tanh, v) = match piece.wall {
                Some(wall) if ray.exit == Some(wall) => (ray.s_exit, ray.v_exit),
                Some(_) => continue,
                None => {
                    // <X(τ),P> = 0 at tanh τ = -α/β, inside the domain when
                    // that is in [0, s_exit].
                    let alpha = lorentz::dot(ray.o, piece.p);
                    let beta = lorentz::dot(ray.d, piece.p);
                    let tanh = -alpha / beta;
                    // A crossing on the piece's seam in the exit wall may
                    // round past the exit; it is the exit point, or the
                    // ray would slip through the seam in both chambers.
                    if tanh > ray.s_exit && tanh <= ray.s_exit + SEAM_ROUNDING {
                        (ray.s_exit, ray.v_exit)
                    } else if tanh >= 0.0 && tanh <= ray.s_exit && tanh < 1.0 {
                        (tanh, (1.0 + tanh) / (1.0 - tanh))
                    } else {
                        continue;
                    }
                }
            };
            if !better(v, found) {
                continue;
            }
            let x = ray.o + tanh * ray.d;
            let slack = SEAM_SLACK * x.w.abs();
            if piece.bounds.iter().all(|b| lorentz::dot(x, *b) >= -slack) {
                *found = Some((v, DomainPart::Piece(i)));
            }
        }
    }

    /// The colour class of a part met by a ray that is at `o` in the
    /// chamber (before the hit): a face takes the kind of cell on the ray's
    /// side, the index `k` of the simplex vertex `v_k` that is its centre
    /// (0: the cells around a vertex of `{p,q,r}`, 3: those of its own
    /// cells); an edge the ringed node whose mirror it crosses; the seed's
    /// ball 0.
    pub(super) fn kind_class(&self, part: DomainPart, o: DVec4) -> u32 {
        let class = match part {
            DomainPart::HalfEdge(i) => self.half_edges[i].node,
            DomainPart::Piece(i) => {
                let piece = &self.pieces[i];
                if lorentz::dot(o, piece.p) > 0.0 {
                    piece.sides[0]
                } else {
                    piece.sides[1]
                }
            }
            _ => 0,
        };
        // A node or vertex index, 0 to 3.
        class as u32
    }

    /// The outward normal of one of these parts at `x` (tangent there, not
    /// unit); a face's is its plane's normal.
    pub(super) fn local_normal(&self, part: DomainPart, x: DVec4) -> DVec4 {
        match part {
            DomainPart::HalfEdge(i) => {
                let e = &self.half_edges[i];
                tube_normal(e.n1, e.n2, x)
            }
            DomainPart::Piece(i) => self.pieces[i].p,
            // The cap, the one other part this holds.
            _ => ball_normal(self.seed, x),
        }
    }
}

/// Unit spacelike, or `None` for a vector too short to be a direction.
fn unit(x: DVec4) -> Option<DVec4> {
    let n = lorentz::dot(x, x);
    (n > 1e-24).then(|| x / n.sqrt())
}

/// The half-edge from the seed `s` to its foot on mirror `i`.
fn half_edge(s: DVec4, ideal: bool, n: &[DVec4; 4], i: usize) -> Option<HalfEdge> {
    // The line lies in span{s, n_i}; its foot f on m_i is timelike and
    // Lorentz-orthogonal to n_i, so {f, n_i} is an orthonormal basis of it.
    let f = s - lorentz::dot(s, n[i]) * n[i];
    let f = f / (-lorentz::dot(f, f)).sqrt();
    let off_line = |x: DVec4| x + lorentz::dot(x, f) * f - lorentz::dot(x, n[i]) * n[i];
    // The other normals, off the line, span the plane orthogonal to it:
    // the longest of them, then the longest of the rest once it is taken
    // out (the two most independent of the three).
    let rest: Vec<DVec4> = (0..4).filter(|&j| j != i).map(|j| off_line(n[j])).collect();
    let longest = |xs: &[DVec4]| {
        xs.iter()
            .copied()
            .max_by(|a, b| lorentz::dot(*a, *a).total_cmp(&lorentz::dot(*b, *b)))
    };
    let n1 = unit(longest(&rest)?)?;
    let residuals: Vec<DVec4> = rest
        .iter()
        .map(|x| *x - lorentz::dot(*x, n1) * n1)
        .collect();
    let n2 = unit(longest(&residuals)?)?;
    let u = if ideal {
        None
    } else {
        // The tangent at s pointing away from n_i's side: towards m_i.
        Some(unit(-(n[i] + lorentz::dot(n[i], s) * s))?)
    };
    Some(HalfEdge {
        n1,
        n2,
        u,
        walls: walls_through(s, n) & walls_through(f, n),
        node: i,
    })
}

/// The pairs of mirrors `i < j` whose rotations carry the seed round a
/// face: one of them ringed, and not orthogonal mirrors with only one
/// ringed (that "polygon" is an edge).
pub(super) fn face_pairs(
    n: &[DVec4; 4],
    rings: Rings,
) -> impl Iterator<Item = (usize, usize)> + '_ {
    (0..4)
        .flat_map(|i| (i + 1..4).map(move |j| (i, j)))
        .filter(move |&(i, j)| {
            let (ri, rj) = (rings.contains(i), rings.contains(j));
            let orthogonal = lorentz::dot(n[i], n[j]).abs() < 1e-12;
            (ri || rj) && !(orthogonal && ri != rj)
        })
}

/// The face pieces in the simplex (module docs).
fn face_pieces(s: DVec4, n: &[DVec4; 4], v: &[DVec4; 4], rings: Rings) -> Option<Vec<FacePiece>> {
    let mut pieces = Vec::new();
    for (i, j) in face_pairs(n, rings) {
        let g = lorentz::dot(n[i], n[j]);
        // The foot c of s on L = m_i ∩ m_j: s minus its part in
        // span{n_i, n_j}, solved with the Gram matrix [[1, g], [g, 1]].
        let (si, sj) = (lorentz::dot(s, n[i]), lorentz::dot(s, n[j]));
        let det = 1.0 - g * g;
        let alpha = (si - g * sj) / det;
        let beta = (sj - g * si) / det;
        let c = s - alpha * n[i] - beta * n[j];
        // L holds the other two vertices; P is the direction of L at c.
        let (k, l) = match (0..4).filter(|&x| x != i && x != j).collect::<Vec<_>>()[..] {
            [k, l] => (k, l),
            _ => return None,
        };
        let mu = -lorentz::dot(c, v[k]) / lorentz::dot(c, v[l]);
        let p = unit(v[k] + mu * v[l])?;
        let mut bounds = Vec::new();
        for ringed in [i, j].into_iter().filter(|&x| rings.contains(x)) {
            let f = s - lorentz::dot(s, n[ringed]) * n[ringed];
            let b = lorentz::orthogonal_complement(s, f, p);
            let b = unit(b)?;
            bounds.push(if lorentz::dot(c, b) >= 0.0 { b } else { -b });
        }
        // The plane is a wall's when its normal is that wall's, up to sign
        // (|<p,n>| = 1 alone also holds for planes meeting at the absolute).
        let wall = (0..4).find(|&w| (p - n[w]).length().min((p + n[w]).length()) < 1e-9);
        let p = wall.map_or(p, |w| n[w]);
        pieces.push(FacePiece {
            p,
            bounds,
            wall,
            sides: sides_of(p, v, k, l),
        });
    }
    Some(pieces)
}

/// The kinds of cell on the positive and negative sides of the face plane
/// `p` orthogonal to the line through `v_k` and `v_l` (see `FacePiece`).
fn sides_of(p: DVec4, v: &[DVec4; 4], k: usize, l: usize) -> [usize; 2] {
    // The vertices are unit timelike or null with time 1: comparable.
    const ON_PLANE: f64 = 1e-9;
    let (dk, dl) = (lorentz::dot(v[k], p), lorentz::dot(v[l], p));
    if dk.abs() < ON_PLANE {
        [l, l]
    } else if dl.abs() < ON_PLANE {
        [k, k]
    } else if dk > 0.0 {
        [k, l]
    } else {
        [l, k]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::honeycomb::domain::assert_walks_agree;
    use crate::honeycomb::{RegularHoneycomb, Schlafli, decode_honeycomb_part};
    use crate::point::Point;
    use crate::ray::Ray;
    use crate::test_rng::Rng;

    fn all_symbols() -> Vec<Schlafli> {
        Schlafli::ALL
            .iter()
            .map(|&(p, q, r)| Schlafli::new(p, q, r).unwrap())
            .collect()
    }

    #[test]
    fn rings_are_some_of_the_four_nodes() {
        assert_eq!(Rings::new(&[0]).unwrap(), Rings::REGULAR);
        assert!(Rings::REGULAR.is_regular());
        let r = Rings::new(&[3, 0, 3]).unwrap();
        assert_eq!(r.nodes().collect::<Vec<_>>(), vec![0, 3]);
        assert_eq!(r.to_string(), "t0,3");
        assert!(!r.is_regular() && r.contains(3) && !r.contains(1) && !r.contains(9));
        assert_eq!(Rings::new(&[]), Err(GeomError::BadRings));
        assert_eq!(Rings::new(&[4]), Err(GeomError::BadRings));
    }

    /// The seed lies on the mirrors of the nodes not ringed and at one
    /// distance from the others; each foot lies on its mirror and in the
    /// simplex, every half-edge's tube normals are orthonormal and
    /// orthogonal to its line, the walls that cull a tube or the cap are
    /// the mirrors that hold it, and each face piece's plane holds the
    /// seed and the feet of its half-edges: for every symbol and all
    /// fifteen ring sets.
    #[test]
    fn seeds_feet_and_pieces_are_where_the_construction_puts_them() {
        let style = HoneycombStyle {
            edges: Some(0.05),
            faces: true,
            vertices: Some(0.1),
            ..HoneycombStyle::default()
        };
        for symbol in all_symbols() {
            let simplex = CoxeterSimplex::new(symbol);
            let n = simplex.normals();
            for bits in 1u32..16 {
                let nodes: Vec<u32> = (0..4).filter(|i| bits & (1 << i) != 0).collect();
                let rings = Rings::new(&nodes).unwrap();
                let (parts, _) = SeedParts::new(&simplex, rings, &style).unwrap();
                let s = parts.seed;
                let dist: Vec<f64> = rings.nodes().map(|i| lorentz::dot(s, n[i])).collect();
                for j in (0..4).filter(|&j| !rings.contains(j)) {
                    assert!(lorentz::dot(s, n[j]).abs() < 1e-12, "{symbol} {rings}");
                }
                for d in &dist {
                    assert!(
                        *d > 0.0 && (d - dist[0]).abs() < 1e-12,
                        "{symbol} {rings} {dist:?}"
                    );
                }
                for (e, i) in parts.half_edges.iter().zip(rings.nodes()) {
                    let f = s - lorentz::dot(s, n[i]) * n[i];
                    assert!(lorentz::dot(f, n[i]).abs() < 1e-12);
                    for nj in n {
                        assert!(
                            lorentz::dot(f, nj) > -1e-12,
                            "{symbol} {rings}: foot outside"
                        );
                    }
                    for (a, b, want) in [(e.n1, e.n1, 1.0), (e.n2, e.n2, 1.0), (e.n1, e.n2, 0.0)] {
                        assert!((lorentz::dot(a, b) - want).abs() < 1e-12);
                    }
                    for x in [s, f, n[i]] {
                        let scale = x.length();
                        assert!(lorentz::dot(x, e.n1).abs() < 1e-12 * scale);
                        assert!(lorentz::dot(x, e.n2).abs() < 1e-12 * scale);
                    }
                    // The walls that cull the tube: the unringed mirrors
                    // orthogonal to m_i, which hold its whole line.
                    for j in 0..4 {
                        let holds = !rings.contains(j) && lorentz::dot(n[i], n[j]).abs() < 1e-12;
                        assert_eq!(e.walls & (1 << j) != 0, holds, "{symbol} {rings} {i} {j}");
                    }
                }
                let unringed = (0..4)
                    .filter(|&j| !rings.contains(j))
                    .fold(0, |b, j| b | (1 << j));
                assert_eq!(parts.cap_walls, unringed, "{symbol} {rings}");
                for piece in &parts.pieces {
                    assert!(lorentz::dot(s, piece.p).abs() < 1e-12, "{symbol} {rings}");
                    for b in &piece.bounds {
                        assert!(lorentz::dot(s, *b).abs() < 1e-12);
                        assert!(lorentz::dot(piece.p, *b).abs() < 1e-12);
                    }
                }
            }
        }
    }

    /// Node 0 ringed alone, built from the seed's parts, is the regular
    /// honeycomb: the same nearest hit (arc length and kind) as the regular
    /// walk for rays from around the base cell, for all fifteen symbols,
    /// with vertex balls wider and narrower than the rods, and faces.
    #[test]
    fn node_zero_alone_is_the_regular_honeycomb() {
        let mut rng = Rng(0x51ED_2701_9A3C_55E1);
        let styles = [
            HoneycombStyle {
                edges: Some(0.06),
                faces: true,
                vertices: Some(0.15),
                ..HoneycombStyle::default()
            },
            HoneycombStyle {
                edges: Some(0.05),
                faces: false,
                vertices: Some(0.03),
                ..HoneycombStyle::default()
            },
            HoneycombStyle {
                edges: Some(0.02),
                ..HoneycombStyle::default()
            },
        ];
        for symbol in all_symbols() {
            for style in styles {
                // The simplex walk, which the cell walk is checked against
                // (`domain.rs`): a ray that starts inside a rod leaves the
                // union of the rods where the simplex walks say, while the
                // cell walk reports where it leaves one of them.
                let regular = RegularHoneycomb::new(symbol, style)
                    .unwrap()
                    .walked_by_simplex();
                let seeded = RegularHoneycomb::wythoff(symbol, Rings::REGULAR, style).unwrap();
                assert_walks_agree(
                    &regular,
                    &seeded,
                    &mut rng,
                    false,
                    50,
                    &format!("{symbol} {style:?}"),
                );
            }
        }
    }

    /// The explicit parts of the uniform honeycomb of `rings` near the
    /// base point: every chamber whose interior point lies within `reach`
    /// of it gives its vertex ball, the rods of its edges and the polygons
    /// of its faces, each once ([`RegularHoneycomb::explicit_parts`]).
    fn explicit_parts(
        symbol: Schlafli,
        rings: Rings,
        style: &HoneycombStyle,
        reach: f64,
    ) -> Vec<(
        crate::honeycomb::HoneycombPart,
        Box<dyn crate::shape::Shape>,
    )> {
        use crate::honeycomb::HoneycombPart;
        use crate::point::{IdealPoint, Vertex};
        use crate::{ConvexPolygon, HSphere, Rod};
        let honeycomb = RegularHoneycomb::wythoff(symbol, rings, *style).unwrap();
        let pieces = honeycomb
            .explicit_parts(
                |c| {
                    let x = c.iter().fold(DVec4::ZERO, |a, v| a + *v);
                    lorentz::distance(x / (-lorentz::dot(x, x)).sqrt(), DVec4::W) < reach
                },
                1_000_000,
            )
            .unwrap();
        let point = |x: DVec4| -> Vertex {
            match Point::from_hyperboloid(x) {
                Some(p) if lorentz::dot(x, x) < -0.5 => p.into(),
                _ => IdealPoint::from_direction(x.truncate()).unwrap().into(),
            }
        };
        let mut out: Vec<(HoneycombPart, Box<dyn crate::shape::Shape>)> = Vec::new();
        for v in &pieces.vertices {
            let rho = style.vertices.unwrap();
            let ball = HSphere::new(Point::from_hyperboloid(v.geometry).unwrap(), rho);
            out.push((HoneycombPart::Vertex, Box::new(ball.unwrap())));
        }
        for e in &pieces.edges {
            let [a, b] = e.geometry.map(point);
            let rod = Rod::new(a, b, style.edges.unwrap()).unwrap();
            out.push((HoneycombPart::Edge, Box::new(rod)));
        }
        for f in &pieces.faces {
            let polygon = ConvexPolygon::new(f.geometry.iter().map(|x| point(*x)).collect());
            out.push((HoneycombPart::Face, Box::new(polygon.unwrap())));
        }
        out
    }

    /// Uniform honeycombs that are not regular: the walk finds the nearest
    /// of their explicit parts (balls, rods and polygons of every chamber
    /// near the base point) for rays from near the base point, for the
    /// truncation, rectification, cantellation, runcination and
    /// omnitruncation of `{4,3,5}` and others, paracompact ones among them,
    /// with faces and vertex balls, and with edges alone (their caps about
    /// the seed then drawn, and culled by the mirrors through it).
    /// The rectified `{4,3,5}` has cuboctahedra about the cube centres
    /// (`v3`) and icosahedra about the cubes' vertices (`v0`): a face met
    /// from inside one takes that cell's kind, 3 or 0; edges take their
    /// ringed node, 1.
    #[test]
    fn parts_are_classed_by_kind() {
        let symbol = Schlafli::new(4, 3, 5).unwrap();
        let style = HoneycombStyle {
            edges: Some(0.02),
            faces: true,
            vertices: None,
            ..HoneycombStyle::default()
        };
        let h = RegularHoneycomb::uniform(symbol, Rings::new(&[1]).unwrap(), style).unwrap();
        let v = CoxeterSimplex::new(symbol).vertices();
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for (centre, kind) in [(v[3], 3), (v[0], 0)] {
            let mut faces = 0;
            for _ in 0..200 {
                let w = rng.direction().extend(rng.unit());
                let d = w + lorentz::dot(w, centre) * centre;
                let d = d / lorentz::norm(d);
                let ray = Ray {
                    origin: centre,
                    dir: d,
                };
                let hit = h
                    .intersect(&ray, 0.0, f64::INFINITY)
                    .expect("inside a cell");
                let (part, class) = decode_honeycomb_part(hit.part);
                match part {
                    crate::honeycomb::HoneycombPart::Face => {
                        faces += 1;
                        assert_eq!(class, kind, "a face seen from a cell of kind {kind}");
                    }
                    _ => assert_eq!(class, 1, "an edge"),
                }
            }
            assert!(faces > 100, "{faces} faces met from kind {kind}");
        }
    }

    #[test]
    fn uniform_walks_meet_the_nearest_explicit_part() {
        let with_faces = HoneycombStyle {
            edges: Some(0.04),
            faces: true,
            vertices: Some(0.07),
            ..HoneycombStyle::default()
        };
        let edges_only = HoneycombStyle {
            edges: Some(0.09),
            faces: false,
            vertices: None,
            ..HoneycombStyle::default()
        };
        meet_the_nearest_explicit_part(with_faces, 40);
        meet_the_nearest_explicit_part(edges_only, 20);
    }

    /// The walk against the explicit parts for `style`, with more than
    /// `min_hits` hits a honeycomb among 150 rays.
    fn meet_the_nearest_explicit_part(style: HoneycombStyle, min_hits: u32) {
        use crate::honeycomb::HoneycombPart;
        let mut rng = Rng(0xC0FF_EE12_3456_789A);
        type Case = ((u32, u32, u32), &'static [u32]);
        let cases: [Case; 10] = [
            ((4, 3, 5), &[0, 1]),
            ((4, 3, 5), &[1]),
            ((4, 3, 5), &[0, 2]),
            ((4, 3, 5), &[0, 3]),
            ((4, 3, 5), &[0, 1, 2, 3]),
            ((5, 3, 4), &[1, 2]),
            ((3, 5, 3), &[0, 1]),
            // Paracompact: horosphere-inscribed cells, ideal vertices.
            ((6, 3, 3), &[0, 1]),
            ((4, 4, 3), &[1]),
            ((3, 3, 6), &[0, 1]),
        ];
        for ((p, q, r), nodes) in cases {
            let symbol = Schlafli::new(p, q, r).unwrap();
            let rings = Rings::new(nodes).unwrap();
            let walked = RegularHoneycomb::uniform(symbol, rings, style).unwrap();
            let parts = explicit_parts(symbol, rings, &style, 3.2);
            let mut hits = 0;
            for _ in 0..150 {
                let start =
                    Point::at_distance_from_origin(rng.direction(), rng.unit() * 0.3).unwrap();
                // Rays from inside a part leave the union of the parts, not
                // the part: start outside them all.
                if parts.iter().any(|(_, s)| {
                    s.intersect(
                        &Ray::from_ball(&start, glam::DVec3::Z).unwrap(),
                        -1e-9,
                        1e-9,
                    )
                    .is_some()
                }) {
                    continue;
                }
                let ray = Ray::from_ball(&start, rng.direction()).unwrap();
                let t_max = 1.0;
                let explicit = parts
                    .iter()
                    .filter_map(|(kind, s)| s.intersect(&ray, 1e-9, t_max).map(|h| (h.t, *kind)))
                    .min_by(|a, b| a.0.total_cmp(&b.0));
                let walk = walked
                    .intersect(&ray, 1e-9, t_max)
                    .map(|h| (h.t, decode_honeycomb_part(h.part).0));
                match (explicit, walk) {
                    (None, None) => {}
                    (Some(a), Some(b)) => {
                        hits += 1;
                        // Measured: within 1e-11 (the explicit parts are
                        // moved by shortest words of reflections).
                        assert!((a.0 - b.0).abs() < 1e-9, "{symbol} {rings}: {a:?} {b:?}");
                        if a.1 != b.1 {
                            // Only where two parts' surfaces meet.
                            assert!(a.1 != HoneycombPart::Face || (a.0 - b.0).abs() < 1e-12);
                        }
                    }
                    (a, b) => panic!("{symbol} {rings}: explicit {a:?}, walk {b:?}"),
                }
            }
            eprintln!("{symbol} {rings}: {hits} hits");
            assert!(hits > min_hits, "{symbol} {rings}: {hits} hits");
        }
    }
}
