//! The domain a honeycomb walk steps through, and the parts it tests there.
//!
//! A walk keeps the ray in one *domain* and reflects the ray (not the
//! scene) in the wall it leaves by, so it re-enters the same domain from
//! the other side (`walk.rs`). Two domains serve:
//!
//! - **The base cell** (honeycombs with finite cells: the four compact
//!   ones and `{3,3,6}`, `{4,3,6}`, `{5,3,6}`, `{3,4,4}`). Its walls are its
//!   `F` faces, the orbit of the face mirror `n3` under the cell's own group
//!   `<R0, R1, R2>`; the reflection in a face is a symmetry of the
//!   honeycomb that swaps the cell with its neighbour, so one step crosses
//!   a whole cell. A ray crosses one cell in the time the simplex walk
//!   crosses about four chambers of it, and every step enters a cell.
//! - **The characteristic simplex** (horosphere-inscribed cells, which have
//!   infinitely many faces: `{6,3,r}`, `{4,4,r}`, `{3,6,3}`). Its walls are
//!   the four mirrors `m0..m3`; only `m3` is a face plane.
//!
//! **The parts in the base cell.** For a point `X` of a cell the nearest
//! edge, vertex and face of the honeycomb are those of the chamber of the
//! cell that holds `X` (the simplex argument in `walk.rs`), so they are
//! the cell's own: a ray inside the cell need only be tested against the
//! cell's edges, vertices and faces. An edge is tested as the tube about
//! its whole line, which is exact because the foot on that line of every
//! point of the cell lies on the edge itself: at each vertex `v` of the
//! cell, the edges at `v` make angles of at most 90° with one another (the
//! vertex figure `{q,r}` seen from `v`: 63.4° for `{3,5}`, 90° for
//! `{3,4}`, 70.5° across a face of `{5,3}`; the vertices of `{3,6}` and
//! `{4,4}` are ideal), so the cell's tangent cone at `v`, and with it the
//! convex cell, lies on the edge's side of the plane through `v` orthogonal
//! to the edge. (`cell_and_simplex_walks_find_the_same_parts` checks this
//! against the simplex walk for all eight symbols.)
//!
//! **An edge's normals.** The edge on faces `f` and `g` (unit normals at
//! the cell's dihedral angle) is `f ∩ g`; `N1 = n_f` and
//! `N2 = (n_g - <n_g,n_f> n_f) / sqrt(1 - <n_g,n_f>²)` are an orthonormal
//! pair orthogonal to it, so `sinh² d(X, line) = <X,N1>² + <X,N2>²`, and
//! both products are combinations of the walls' products the walk has
//! already computed. In the simplex the same formula holds with `f = m3`
//! and `g = m2`, the other mirror through the edge.

use glam::{DVec3, DVec4};

use crate::error::GeomError;
use crate::klein_box::plain_min;
use crate::lorentz;

use super::cells::{orbit, orbit_maps};
use super::domain_ray::{DomainPart, DomainRay, MAX_WALLS};
use super::kernels::{ball_first_v, ball_normal, tube_normal, tube_roots, walls_through};
use super::simplex::{CoxeterSimplex, reflection_matrix};
use super::style::HoneycombStyle;
use super::uniform::{Rings, SeedParts};

/// An edge line of the domain: `N1 = walls[f]`,
/// `N2 = alpha walls[f] + beta walls[g]` (module docs), and the centres of
/// the cells around it.
#[derive(Clone, Debug)]
struct DomainEdge {
    f: usize,
    g: usize,
    alpha: f64,
    beta: f64,
    cells: Vec<DVec4>,
}

impl DomainEdge {
    fn new(walls: &[DVec4], f: usize, g: usize, cells: Vec<DVec4>) -> DomainEdge {
        let c = lorentz::dot(walls[g], walls[f]);
        // |c| = cos of a dihedral angle of at most 120°: never 1.
        let s = (1.0 - c * c).sqrt();
        DomainEdge {
            f,
            g,
            alpha: -c / s,
            beta: 1.0 / s,
            cells,
        }
    }

    fn normals(&self, walls: &[DVec4]) -> (DVec4, DVec4) {
        let n1 = walls[self.f];
        (n1, self.alpha * n1 + self.beta * walls[self.g])
    }
}

/// A finite vertex of the domain and the centres of the cells around it.
#[derive(Clone, Debug)]
struct DomainVertex {
    at: DVec4,
    /// The bits of the walls through it.
    walls: u32,
    cells: Vec<DVec4>,
}

impl DomainVertex {
    fn new(walls: &[DVec4], at: DVec4, cells: Vec<DVec4>) -> DomainVertex {
        DomainVertex {
            at,
            walls: walls_through(at, walls),
            cells,
        }
    }
}

/// How a step computes the walls' products with the ray.
#[derive(Clone, Debug)]
enum WallProducts {
    /// Each a Lorentz product.
    General,
    /// The faces of a cell centred at the origin, in antipodal pairs:
    /// walls `2i` and `2i+1` have spatial parts `u_i` and `-u_i` and the
    /// same time part `c` (the cell's group fixes the origin), so
    /// `<X,n> = ±X·u_i - X.w c`: one 3-vector product per pair.
    Antipodal { half: Vec<DVec3>, time: f64 },
}

impl WallProducts {
    /// Orders `walls` in antipodal pairs when they come in such pairs
    /// with one time part (every cell but the tetrahedron).
    fn pair(walls: &mut Vec<DVec4>) -> WallProducts {
        let time = walls[0].w;
        let mut paired = Vec::with_capacity(walls.len());
        let mut rest = walls.clone();
        while let Some(n) = rest.pop() {
            let opposite = DVec4::new(-n.x, -n.y, -n.z, n.w);
            let Some(k) = rest.iter().position(|m| (*m - opposite).length() < 1e-12) else {
                return WallProducts::General;
            };
            let m = rest.swap_remove(k);
            paired.extend([n, m]);
        }
        if paired.iter().any(|n| (n.w - time).abs() > 1e-15) {
            return WallProducts::General;
        }
        // Each pair exactly antipodal, one time part for all.
        let half: Vec<DVec3> = paired.chunks(2).map(|p| p[0].truncate()).collect();
        *walls = half
            .iter()
            .flat_map(|u| [u.extend(time), (-*u).extend(time)])
            .collect();
        WallProducts::Antipodal { half, time }
    }
}

/// The walls of a walk's domain and the parts inside it (module docs).
///
/// Invariants: `walls` are unit spacelike inward normals, at most
/// [`MAX_WALLS`], and the domain is `{X : <X,walls[i]> >= 0}`;
/// `face_cells[i]` is set exactly for the walls that are face planes;
/// edges and vertices index into `walls`.
#[derive(Clone, Debug)]
pub(super) struct WalkDomain {
    walls: Vec<DVec4>,
    products: WallProducts,
    face_cells: Vec<Option<[DVec4; 2]>>,
    edges: Vec<DomainEdge>,
    /// `edge_between[f * walls + g]`: the edge on walls `f` and `g`, or
    /// [`NO_EDGE`].
    edge_between: Vec<u8>,
    vertices: Vec<DomainVertex>,
    /// `sinh²` of the edge radius; `None`: no edges drawn.
    sinh2_edge: Option<f64>,
    /// `cosh` and `sinh` of the vertex radius (used when `vertices` is not
    /// empty).
    cosh_vertex: f64,
    sinh_vertex: f64,
    faces: bool,
    /// A uniform honeycomb's parts other than its vertex ball.
    seed: Option<SeedParts>,
}

impl WalkDomain {
    /// The base cell when the cells are finite, else the simplex.
    ///
    /// Errors: [`GeomError::TooManyCells`] if an orbit is not finite (it is
    /// for every hyperbolic symbol).
    pub(super) fn new(
        simplex: &CoxeterSimplex,
        style: &HoneycombStyle,
    ) -> Result<WalkDomain, GeomError> {
        if simplex.ideal()[3] {
            Self::simplex(simplex, style)
        } else {
            Self::cell(simplex, style)
        }
    }

    /// The characteristic simplex as the domain, forced (for comparing the
    /// two walks).
    pub(super) fn simplex(
        simplex: &CoxeterSimplex,
        style: &HoneycombStyle,
    ) -> Result<WalkDomain, GeomError> {
        let n = simplex.normals();
        let v = simplex.vertices();
        let refl = [0, 1, 2, 3].map(|i| simplex.reflection(i));
        let walls = n.to_vec();
        let products = WallProducts::General;
        let edge = DomainEdge::new(&walls, 3, 2, orbit(v[3], &refl[2..]).ok_or_else(too_many)?);
        let vertices = match (style.vertices, simplex.ideal()[0]) {
            (Some(_), false) => vec![DomainVertex::new(
                &walls,
                v[0],
                orbit(v[3], &refl[1..]).ok_or_else(too_many)?,
            )],
            _ => Vec::new(),
        };
        Ok(WalkDomain {
            walls,
            products,
            face_cells: vec![None, None, None, Some([v[3], refl[3] * v[3]])],
            edge_between: edge_table(4, std::slice::from_ref(&edge)),
            edges: vec![edge],
            vertices,
            sinh2_edge: style.edges.map(|w| w.sinh() * w.sinh()),
            cosh_vertex: style.vertices.map_or(1.0, f64::cosh),
            sinh_vertex: style.vertices.map_or(0.0, f64::sinh),
            faces: style.faces,
            seed: None,
        })
    }

    /// The characteristic simplex with the parts of the uniform honeycomb
    /// of `rings` (`uniform.rs`).
    ///
    /// Errors: those of [`SeedParts::new`].
    pub(super) fn uniform(
        simplex: &CoxeterSimplex,
        rings: Rings,
        style: &HoneycombStyle,
    ) -> Result<WalkDomain, GeomError> {
        let walls = simplex.normals().to_vec();
        let (seed, ball) = SeedParts::new(simplex, rings, style)?;
        let vertices = ball
            .map(|at| DomainVertex::new(&walls, at, Vec::new()))
            .into_iter()
            .collect();
        Ok(WalkDomain {
            face_cells: vec![None; walls.len()],
            edge_between: edge_table(walls.len(), &[]),
            walls,
            products: WallProducts::General,
            edges: Vec::new(),
            vertices,
            sinh2_edge: None,
            cosh_vertex: style.vertices.map_or(1.0, f64::cosh),
            sinh_vertex: style.vertices.map_or(0.0, f64::sinh),
            faces: false,
            seed: Some(seed),
        })
    }

    fn cell(simplex: &CoxeterSimplex, style: &HoneycombStyle) -> Result<WalkDomain, GeomError> {
        let n = simplex.normals();
        let v = simplex.vertices();
        let refl = [0, 1, 2, 3].map(|i| simplex.reflection(i));
        let cell_group = &refl[..3];
        let walls = orbit(n[3], cell_group).ok_or_else(too_many)?;
        if walls.len() > MAX_WALLS {
            return Err(too_many());
        }
        let mut walls = walls;
        let products = WallProducts::pair(&mut walls);
        let wall_of = |x: DVec4| {
            (0..walls.len())
                .min_by(|&i, &j| (walls[i] - x).length().total_cmp(&(walls[j] - x).length()))
                .unwrap_or(0)
        };
        // The chamber's edge v0 v1 lies on m3 and on R2 m3, the face across
        // it; g maps it to each edge of the cell.
        let across = refl[2] * n[3];
        let edge_cells = orbit(v[3], &refl[2..]).ok_or_else(too_many)?;
        let edges: Vec<DomainEdge> = orbit_maps(v[1], cell_group)
            .ok_or_else(too_many)?
            .into_iter()
            .map(|(_, g)| {
                let cells = edge_cells.iter().map(|c| g * *c).collect();
                DomainEdge::new(&walls, wall_of(g * n[3]), wall_of(g * across), cells)
            })
            .collect();
        let vertices = match (style.vertices, simplex.ideal()[0]) {
            (Some(_), false) => {
                let vertex_cells = orbit(v[3], &refl[1..]).ok_or_else(too_many)?;
                orbit_maps(v[0], cell_group)
                    .ok_or_else(too_many)?
                    .into_iter()
                    .map(|(at, g)| {
                        let cells = vertex_cells.iter().map(|c| g * *c).collect();
                        DomainVertex::new(&walls, at, cells)
                    })
                    .collect()
            }
            _ => Vec::new(),
        };
        let edge_between = edge_table(walls.len(), &edges);
        let face_cells = walls
            .iter()
            .map(|nf| Some([v[3], reflection_matrix(*nf) * v[3]]))
            .collect();
        Ok(WalkDomain {
            walls,
            products,
            face_cells,
            edge_between,
            edges,
            vertices,
            sinh2_edge: style.edges.map(|w| w.sinh() * w.sinh()),
            cosh_vertex: style.vertices.map_or(1.0, f64::cosh),
            sinh_vertex: style.vertices.map_or(0.0, f64::sinh),
            faces: style.faces,
            seed: None,
        })
    }

    /// A uniform honeycomb's seed parts.
    pub(super) fn seed(&self) -> Option<&SeedParts> {
        self.seed.as_ref()
    }

    /// True for a uniform honeycomb's domain (with seed parts).
    pub(super) fn is_seeded(&self) -> bool {
        self.seed.is_some()
    }

    /// The walls (inward unit normals).
    pub(super) fn walls(&self) -> &[DVec4] {
        &self.walls
    }

    /// `a[i] = <o, walls[i]>` and `b[i] = <d, walls[i]>`.
    #[inline(always)]
    pub(super) fn products(
        &self,
        o: DVec4,
        d: DVec4,
        a: &mut [f64; MAX_WALLS],
        b: &mut [f64; MAX_WALLS],
    ) {
        match &self.products {
            WallProducts::General => {
                for (i, n) in self.walls.iter().enumerate() {
                    a[i] = lorentz::dot(o, *n);
                    b[i] = lorentz::dot(d, *n);
                }
            }
            WallProducts::Antipodal { half, time } => {
                let (o3, d3) = (o.truncate(), d.truncate());
                let (ot, dt) = (o.w * time, d.w * time);
                for (i, u) in half.iter().enumerate() {
                    let (po, pd) = (o3.dot(*u), d3.dot(*u));
                    a[2 * i] = po - ot;
                    a[2 * i + 1] = -po - ot;
                    b[2 * i] = pd - dt;
                    b[2 * i + 1] = -pd - dt;
                }
            }
        }
    }

    /// True if crossing wall `i` enters another cell.
    pub(super) fn is_face(&self, i: usize) -> bool {
        self.face_cells.get(i).is_some_and(Option::is_some)
    }

    /// The domain without parts: the bare walk.
    pub(super) fn bare(&self) -> WalkDomain {
        WalkDomain {
            sinh2_edge: None,
            vertices: Vec::new(),
            faces: false,
            seed: None,
            ..self.clone()
        }
    }

    /// The first part met in this domain at `floor < v <= window`, in
    /// `v = e^{2τ}` from the ray's start here; `present` says whether a
    /// part with these cells is drawn.
    /// `SEEDED`: whether to test a uniform honeycomb's seed parts.
    #[inline(always)]
    pub(super) fn first_part<const SEEDED: bool>(
        &self,
        ray: &DomainRay,
        floor: f64,
        window: f64,
        present: impl Fn(&[DVec4]) -> bool,
    ) -> Option<(f64, DomainPart)> {
        let (a, b) = (ray.a, ray.b);
        let mut found: Option<(f64, DomainPart)> = None;
        let in_window = |v: f64, found: &Option<(f64, DomainPart)>| {
            v > floor && v <= window && found.is_none_or(|(best, _)| v < best)
        };
        let first_root = |(near, far): (f64, f64)| if near > floor { near } else { far };
        // o and d carry a common scale λ, λ² = -<o,o>: the tube's
        // quadratic is homogeneous of degree 2 in (o, d, sinh w), the ball's
        // of degree 1 in (o, d, cosh ρ), and their roots do not change.
        let lambda2 = -lorentz::dot(ray.o, ray.o);
        if let Some(sinh2) = self.sinh2_edge {
            let k = sinh2 * lambda2;
            let limit2 = wall_limit2(ray, k);
            let near = self.walls_within(ray, limit2);
            let bound = limit2.sqrt();
            // Few walls are near (the entry and the exit, mostly): test the
            // edges on pairs of them.
            let nw = self.walls.len();
            let mut rest = near;
            while rest != 0 {
                let f = rest.trailing_zeros() as usize;
                rest &= rest - 1;
                let mut others = rest;
                while others != 0 {
                    let g = others.trailing_zeros() as usize;
                    others &= others - 1;
                    let i = usize::from(self.edge_between[f * nw + g]);
                    let Some(e) = self.edges.get(i) else {
                        continue;
                    };
                    if !may_near_both(a[f], b[f], a[g], b[g], bound) {
                        continue;
                    }
                    let o = [a[e.f], e.alpha * a[e.f] + e.beta * a[e.g]];
                    let v = [b[e.f], e.alpha * b[e.f] + e.beta * b[e.g]];
                    if let Some(v) = tube_roots(o, v, k).map(first_root)
                        && in_window(v, &found)
                        && present(&e.cells)
                    {
                        found = Some((v, DomainPart::Edge(i)));
                    }
                }
            }
        }
        if !self.vertices.is_empty() {
            let lambda = lambda2.sqrt();
            let k = self.cosh_vertex * lambda;
            let sigma = self.sinh_vertex * lambda;
            let near = self.walls_within(ray, wall_limit2(ray, sigma * sigma));
            for (i, vertex) in self.vertices.iter().enumerate() {
                if near & vertex.walls != vertex.walls {
                    continue;
                }
                if let Some(v) = ball_first_v(ray.o, ray.d, vertex.at, k, floor)
                    && in_window(v, &found)
                    && present(&vertex.cells)
                {
                    found = Some((v, DomainPart::Vertex(i)));
                }
            }
        }
        if self.faces
            && let Some(exit) = ray.exit
            && let Some(Some(cells)) = self.face_cells.get(exit)
            && in_window(ray.v_exit, &found)
            && present(cells)
        {
            found = Some((ray.v_exit, DomainPart::Face(exit)));
        }
        if SEEDED && let Some(seed) = &self.seed {
            // Only the walls of some tube or of the cap are asked for:
            // a part no wall culls is always tested.
            let near_walls = if seed.culling_walls() != 0 {
                self.walls_within(ray, wall_limit2(ray, seed.sinh2_edge() * lambda2))
            } else {
                0
            };
            seed.first_part(ray, floor, window, lambda2, near_walls, &mut found);
        }
        found
    }

    /// The walls the ray comes within `σ` of (`λ sinh` of a distance)
    /// inside the domain, as bits, given [`wall_limit2`] of `σ²`: a
    /// necessary condition for meeting a part on a wall (the part's points
    /// are at most its radius from every wall through it). In the domain
    /// `<X(τ),n> = cosh τ (a + b tanh τ) >= 0`, so `<X(τ),n> <= σ` needs
    /// `a + b tanh τ <= σ` somewhere on `0 <= tanh τ <= s_exit`, where that
    /// linear function is least at an end.
    fn walls_within(&self, ray: &DomainRay, limit2: f64) -> u32 {
        let mut bits = 0;
        for (i, (a, b)) in ray.a.iter().zip(ray.b).enumerate() {
            // m <= 0 or m² <= limit², in one comparison (`plain_min`:
            // `f64::min`'s NaN rule costs a third of the loop, and a NaN
            // product fails the comparison either way).
            let m = plain_min(a + b * ray.s_exit, *a);
            bits |= u32::from(m * m.abs() <= limit2) << i;
        }
        bits
    }

    /// The centres of the cells a part belongs to.
    pub(super) fn cells_of(&self, part: DomainPart) -> &[DVec4] {
        match part {
            DomainPart::Edge(i) => &self.edges[i].cells,
            DomainPart::Vertex(i) => &self.vertices[i].cells,
            DomainPart::Face(i) => match &self.face_cells[i] {
                Some(cells) => cells,
                None => &[],
            },
            // A uniform honeycomb's parts have no cell classes.
            DomainPart::HalfEdge(_) | DomainPart::Cap | DomainPart::Piece(_) => &[],
        }
    }

    /// The outward normal of a part at its point `x` (in the base frame),
    /// tangent at `x` but not unit; a face's is its wall's normal.
    pub(super) fn local_normal(&self, part: DomainPart, x: DVec4) -> DVec4 {
        match part {
            DomainPart::Face(i) => self.walls[i],
            DomainPart::Edge(i) => {
                let (n1, n2) = self.edges[i].normals(&self.walls);
                tube_normal(n1, n2, x)
            }
            DomainPart::Vertex(i) => ball_normal(self.vertices[i].at, x),
            DomainPart::HalfEdge(_) | DomainPart::Cap | DomainPart::Piece(_) => match &self.seed {
                Some(seed) => seed.local_normal(part, x),
                None => x,
            },
        }
    }
}

/// The square of a bound `L >= σ + ε` on `a + b tanh τ` near a wall, given
/// `σ²`, with `ε` the rounding of `a` and `b` (ulps of `o.w`, which is at
/// least `λ`): `(σ + ε)² <= 2σ² + 2ε²`, a looser bound that needs no
/// square root.
fn wall_limit2(ray: &DomainRay, sigma2: f64) -> f64 {
    let eps = 1e-12 * ray.o.w.abs();
    2.0 * (sigma2 + eps * eps)
}

/// False if no point of the ray's line is within `bound` of walls `f` and
/// `g` at once (in `a + b tanh τ`, as [`WalkDomain::walls_within`]), so
/// that it cannot meet the edge on both. Each wall alone is near at one
/// end of the ray's way through the domain, mostly the way in and the way
/// out; both at once only where the way passes close by the edge.
///
/// When `b_f` and `b_g` have opposite signs, the greater of the two linear
/// functions is least where they cross, at
/// `(|b_f| a_g + |b_g| a_f) / (|b_f| + |b_g|)`; otherwise they may both be
/// small at one end, and the pair is kept. The rounding of these few
/// products is far below the `ε` already in `bound`.
#[inline(always)]
fn may_near_both(a_f: f64, b_f: f64, a_g: f64, b_g: f64, bound: f64) -> bool {
    let (wf, wg) = (b_f.abs(), b_g.abs());
    !(b_f * b_g < 0.0 && wf * a_g + wg * a_f > bound * (wf + wg))
}

/// No edge between two walls.
const NO_EDGE: u8 = u8::MAX;

/// The [`WalkDomain::edge_between`] table of these edges.
fn edge_table(walls: usize, edges: &[DomainEdge]) -> Vec<u8> {
    let mut table = vec![NO_EDGE; walls * walls];
    for (i, e) in edges.iter().enumerate() {
        // At most 30 edges: the index fits a u8 below NO_EDGE.
        let i = i as u8;
        table[e.f * walls + e.g] = i;
        table[e.g * walls + e.f] = i;
    }
    table
}

fn too_many() -> GeomError {
    GeomError::TooManyCells {
        limit: super::MAX_TESSELLATION_CELLS,
    }
}

/// Two walks of the same honeycomb through different walls, `first` and
/// `second`, on 300 rays from within 1.5 of the base point: each ray hits
/// in both or in neither (and `blocks` says so), and more than `min_hits`
/// hit. Where both hit, the same arc length within their drift (they
/// drift apart like the walk from the exact ray, `walk.rs`, "Accuracy"),
/// the same kind of part (and class, if `class_too`), and normals turned
/// by no more than the drift moves a point on a rod of radius at least
/// 0.01 (`δ / w`).
#[cfg(test)]
pub(super) fn assert_walks_agree(
    first: &super::RegularHoneycomb,
    second: &super::RegularHoneycomb,
    rng: &mut crate::test_rng::Rng,
    class_too: bool,
    min_hits: u32,
    what: &str,
) {
    use super::decode_honeycomb_part;
    use crate::point::Point;
    use crate::ray::Ray;
    let (mut hits, mut misses) = (0, 0);
    for _ in 0..300 {
        let start = Point::at_distance_from_origin(rng.direction(), rng.unit() * 1.5).unwrap();
        let ray = Ray::from_ball(&start, rng.direction()).unwrap();
        let a = first.intersect(&ray, 1e-9, f64::INFINITY);
        let b = second.intersect(&ray, 1e-9, f64::INFINITY);
        assert_eq!(
            first.blocks(&ray, 1e-9, f64::INFINITY),
            a.is_some(),
            "{what}"
        );
        assert_eq!(
            second.blocks(&ray, 1e-9, f64::INFINITY),
            b.is_some(),
            "{what}"
        );
        let (a, b) = match (a, b) {
            (None, None) => {
                misses += 1;
                continue;
            }
            (Some(a), Some(b)) => (a, b),
            (a, b) => panic!("{what}: {a:?} against {b:?}"),
        };
        hits += 1;
        let drift = 3e-15 * (2.0 * a.t).exp();
        assert!((a.t - b.t).abs() < 1e-9 + drift, "{what}: {} {}", a.t, b.t);
        let (pa, pb) = (decode_honeycomb_part(a.part), decode_honeycomb_part(b.part));
        if class_too {
            assert_eq!(pa, pb, "{what} t {}", a.t);
        } else {
            assert_eq!(pa.0, pb.0, "{what} t {}", a.t);
        }
        assert!(
            (a.normal - b.normal).length() < (1e-6 + 100.0 * drift) * a.point.w,
            "{what} {pa:?} t {}: normals {} {}",
            a.t,
            a.normal,
            b.normal
        );
    }
    assert!(hits > min_hits, "{what}: {hits} hits, {misses} misses");
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::honeycomb::{RegularHoneycomb, Schlafli};
    use crate::test_rng::Rng;

    /// `may_near_both` never drops a pair that some point of the line
    /// has within the bound of both walls: checked on a fine grid of
    /// `s = tanh τ` and at the exact crossing.
    #[test]
    fn edges_are_skipped_only_where_both_walls_are_never_near() {
        let mut rng = Rng(11);
        let mut skipped = 0;
        for case in 0..20_000 {
            let mut v = || 4.0 * rng.unit() - 2.0;
            let (af, bf, ag, bg) = (v(), v(), v(), v());
            let bound = 0.05 + rng.unit();
            if may_near_both(af, bf, ag, bg, bound) {
                continue;
            }
            skipped += 1;
            let worse = |s: f64| (af + bf * s).max(ag + bg * s);
            let crossing = (ag - af) / (bf - bg);
            assert!(worse(crossing) > bound * (1.0 - 1e-12), "case {case}");
            for k in -400..=400 {
                let s = f64::from(k) / 100.0;
                assert!(worse(s) > bound, "case {case} at {s}");
            }
        }
        // Most random pairs of opposite slopes are far apart.
        assert!(skipped > 2_000, "{skipped}");
    }

    fn finite_cell_symbols() -> Vec<Schlafli> {
        Schlafli::ALL
            .iter()
            .map(|&(p, q, r)| Schlafli::new(p, q, r).unwrap())
            .filter(|s| !s.has_ideal_cells())
            .collect()
    }

    #[test]
    fn cells_have_the_faces_edges_and_vertices_of_p_q() {
        for symbol in finite_cell_symbols() {
            let style = HoneycombStyle {
                vertices: Some(0.1),
                ..HoneycombStyle::default()
            };
            let d = WalkDomain::new(&CoxeterSimplex::new(symbol), &style).unwrap();
            let (f, e, v) = match (symbol.p(), symbol.q()) {
                (3, 3) => (4, 6, 4),
                (4, 3) => (6, 12, 8),
                (3, 4) => (8, 12, 6),
                (5, 3) => (12, 30, 20),
                (3, 5) => (20, 30, 12),
                pq => panic!("{pq:?}"),
            };
            let finite = !symbol.has_ideal_vertices();
            assert_eq!(d.walls.len(), f, "{symbol}");
            // Every cell but the tetrahedron has antipodal faces.
            let paired = matches!(d.products, WallProducts::Antipodal { .. });
            assert_eq!(paired, f != 4, "{symbol}");
            assert_eq!(d.edges.len(), e, "{symbol}");
            assert_eq!(d.vertices.len(), if finite { v } else { 0 }, "{symbol}");
            for edge in &d.edges {
                // Two distinct faces whose normals meet at the dihedral
                // angle 2π/r, and an orthonormal pair.
                assert_ne!(edge.f, edge.g);
                let cos = -lorentz::dot(d.walls[edge.f], d.walls[edge.g]);
                let dihedral = 2.0 * std::f64::consts::PI / f64::from(symbol.r());
                assert!((cos - dihedral.cos()).abs() < 1e-12, "{symbol}");
                let (n1, n2) = edge.normals(&d.walls);
                assert!(lorentz::dot(n1, n2).abs() < 1e-12);
                assert!((lorentz::dot(n2, n2) - 1.0).abs() < 1e-12);
                assert_eq!(edge.cells.len(), symbol.r() as usize);
            }
        }
    }

    /// The cell walk and the simplex walk draw the same parts: the same
    /// nearest hit (arc length, kind, class) for rays from around the base
    /// cell, with every part drawn, with edges alone (long walks) and with
    /// a depth limit.
    #[test]
    fn cell_and_simplex_walks_find_the_same_parts() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let styles = [
            HoneycombStyle {
                edges: Some(0.06),
                faces: true,
                vertices: Some(0.15),
                depth: None,
                cell_classes: 3,
            },
            HoneycombStyle {
                edges: Some(0.01),
                cell_classes: 2,
                ..HoneycombStyle::default()
            },
            HoneycombStyle {
                edges: Some(0.04),
                faces: true,
                vertices: Some(0.1),
                depth: Some(2),
                cell_classes: 3,
            },
        ];
        for symbol in finite_cell_symbols() {
            for style in styles {
                let cells = RegularHoneycomb::new(symbol, style).unwrap();
                let simplex = cells.clone().walked_by_simplex();
                assert_walks_agree(
                    &cells,
                    &simplex,
                    &mut rng,
                    true,
                    30,
                    &format!("{symbol} {style:?}"),
                );
            }
        }
    }
}
