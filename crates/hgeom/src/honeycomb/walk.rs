//! [`RegularHoneycomb`]: a regular honeycomb `{p,q,r}` traced by walking
//! the ray from cell to cell, or through the characteristic simplex.
//!
//! **The domain.** The walk steps through copies of one domain `C`, the
//! intersection of the half-spaces of its walls: the base cell, whose walls
//! are its faces, when the cells are finite; the characteristic simplex,
//! whose walls are the four mirrors, when they are horosphere-inscribed
//! (`domain.rs`). What follows is written for the simplex, whose parts the
//! cell's are made of; the cell walk is the same with `F` walls, every one
//! a face, and all the cell's edges and vertices as parts.
//!
//! **The walk.** The ray is moved into the honeycomb's frame and its start
//! folded into the domain `C = {X : <X,n_i> >= 0}` (reflect in a wall it
//! is behind until it is behind none: each reflection brings the point
//! strictly closer to `C`). Inside `C`, along `X(τ) = cosh τ O + sinh τ D`,
//! `<X(τ),n_i> = a_i cosh τ + b_i sinh τ` with `a_i = <O,n_i> >= 0`,
//! `b_i = <D,n_i>`, so the ray leaves through wall `i` at
//! `s_i = tanh τ_i = -a_i / b_i` (only walls with `b_i < 0` and `s_i < 1`):
//! the exit is the wall with the least `s_i`. The ray is then re-based at
//! the exit point, `(O + s D, s O + D)` (the unit pair times `cosh τ`), and
//! reflected in that wall, *the ray, not the scene*: it stays in the base
//! simplex, where all coordinates are of order 1. The common factor
//! `cosh τ` changes no ratio `a_i / b_i`, so the walk carries it along
//! (the part tests divide it out, `kernels.rs`) and
//! restores `<O,O> = -1`, `<D,D> = 1`, `<O,D> = 0` every few steps. Arc
//! lengths are kept as `e^{2τ} = (1 + s)/(1 - s)`, multiplied along the
//! walk: a step costs eight Lorentz products and a few divisions, no
//! square root and no logarithm. The product `M` of the reflections maps
//! the simplex to the chamber the ray is in; it carries normals back and
//! finds the cells of a part.
//!
//! **The parts in one chamber.** For a point `X` of `C` and any `g` of the
//! group, `d(X, gY) >= d(X, Y)` for `Y` in `C` (a geodesic from `X` to `gY`
//! folded back into `C` is no longer than it is). So the nearest edge,
//! vertex and face to a point of `C` are those of `C` itself: the edge
//! `v0 v1`, the vertex `v0`, the face piece `v0 v1 v2` in `m3`. Within `C`:
//!
//! - *edge*: the tube of radius `w` about the line `v0 v1 = m2 ∩ m3`. The
//!   foot of every point of `C` on that line lies on the segment: `m0` is
//!   orthogonal to the edge at `v1` with `C` on the `v0` side, and every
//!   direction of `C` at `v0` (towards `v1`, `v2`, `v3`) makes an angle
//!   below 90° with the edge (angles of right triangles), so no caps are
//!   needed, and the tube pieces of all chambers make up exactly the
//!   capped rods about all edges. With the orthonormal pair `N1 = n3`,
//!   `N2 = (n2 + cos(π/r) n3)/sin(π/r)` orthogonal to the line,
//!   `sinh² d = <X,N1>² + <X,N2>²`, and both products are combinations of
//!   the `a_i`, `b_i` already at hand: the tube is a quadratic in `e^{2τ}`
//!   ([`HCylinder`](crate::HCylinder)'s). An edge to an ideal vertex is the
//!   same tube, out to the absolute.
//! - *vertex*: the ball `-<X,v0> = cosh ρ`, a quadratic in `e^τ`; not drawn
//!   at an ideal `v0` (it would be a horoball).
//! - *face*: the face piece is the wall `m3` of `C` itself, so the ray
//!   meets a face exactly when it leaves `C` through `m3`: no test at all.
//!   The faces of horosphere-inscribed cells (infinitely many per cell) come
//!   out the same way. Faces are two-sided: the normal faces the ray.
//!
//! **Where the walk stops.** At `t_max`, at the *horizon* (distance
//! [`DEFAULT_HORIZON`] = 12 from the origin of the frame the shape is in,
//! which in a renderer is the eye; [`RegularHoneycomb::with_horizon`]
//! changes it), where a depth-limited honeycomb can reach no listed cell
//! any more (a ball about the base cell holding all of them), or after
//! [`MAX_WALK_STEPS`] steps. Nothing is met beyond: the ray misses, or,
//! with [`RegularHoneycomb::with_horizon_hits`], reports where the horizon
//! (or the step limit) stopped it, so that a renderer can draw the
//! honeycomb's average appearance there rather than a hole. At distance 12 a cell of size 1 subtends
//! `1/sinh 12 ≈ 1.2e-5` rad, a hundredth of a pixel of a 1000-pixel image
//! with a 90° field; [`RegularHoneycomb::horizon_for_pixel`] gives the
//! distance where a cell's features fall below a given pixel, and
//! [`RegularHoneycomb::with_view_horizon`] stops each ray from the eye
//! where they fall below its own pixel of a flat picture. Up the cusp
//! of an ideal vertex the rods widen (in the upper half-space with the
//! vertex at infinity they are cones about vertical lines) until they fill
//! it, so rays towards ideal vertices end on rods; a ray into the cusp of an
//! ideal cell centre is inside that cell and may reach the horizon.
//!
//! **Accuracy.** The hit point is the original ray's point at the walked
//! arc length, so only `t` carries the walk's rounding. Against a 320-bit
//! walk of the same f64 ray through the same walls
//! (`walk_drift_against_a_320_bit_walk` in `tests/honeycomb_walk.rs`,
//! worst of 6 rays for each of 6 honeycombs) the arc length and the point
//! in the simplex drift by 1e-11 at `t = 5`, 2e-7 at 10, 1e-5 at 12 and
//! 4e-3 at 15: about `3e-15 e^{2t}`, the growth of a 1e-13 change of the
//! ray's start under the same walk, so the walk adds a few ulps per step
//! and the folding of geodesics does the rest. Walks that agree on their
//! parts agree on `t` to 1e-9 within the horizon (`symmetries_…` and
//! `walk_matches_explicit_cells` in the same file: 3e-13 against explicit
//! `{4,3,5}` polygons, rods and balls). Normals are the local normal carried
//! by `M` and made tangent at the hit point again; they agree with the
//! explicit cells' to 1e-6. A ray that starts on a part far from the base
//! point (a shadow or reflected ray from a far hit) would meet that part
//! again within the two walks' drift, so parts within `1e-14 x0²` of a
//! ray's start are skipped (`x0` the cosh of the start's distance from the
//! base point: 1e-14 near it, 3e-4 at distance 12;
//! `rays_back_from_far_hits_are_clear`).

use std::sync::Arc;

use glam::{DMat4, DVec4};

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::ray::{Hit, Ray};
use crate::roots::exp_roots_lazy;

use super::cells::{CellSet, Shells};
use super::crossings::{Crossings, Pending};
use super::domain::WalkDomain;
use super::domain_ray::{DomainPart, DomainRay, MAX_WALLS};
use super::kernels::{nearest_exit, reflect, renormalise};
use super::schlafli::Schlafli;
use super::simplex::CoxeterSimplex;
use super::style::{HoneycombStyle, encode_part};
use super::uniform::Rings;
use super::view_horizon::ViewHorizon;
use super::walk_record::{WalkStats, WalkStep};

mod faces;
mod settings;

pub use faces::FaceFrame;

/// The cell classes of [`RegularHoneycomb::with_rank_classes`]: far more
/// than any rank within reach (within distance 36 of the base cell the
/// shells number under 36 / 0.69 ≈ 52, twice the least inradius being
/// 0.69; a depth is at most 8), so a class is the rank itself.
pub const RANK_CLASSES: u32 = 720_720;

/// The default horizon: the walk stops at this distance from the origin of
/// the frame (module docs).
pub const DEFAULT_HORIZON: f64 = 12.0;

/// The most steps (cells, or chambers for horosphere-inscribed cells) one
/// ray may take; a ray that would take more (one aimed within `e^{-15}` of
/// an ideal vertex, spiralling up its cusp) misses.
pub const MAX_WALK_STEPS: u32 = 200_000;

/// Parts within `SELF_HIT x0²` of a ray's start are skipped, `x0` the
/// cosh of the start's distance from the base point: the drift of a walk
/// to distance `d` is about `1e-16 e^{2d}` (module docs), and a ray that
/// starts on a part found by another walk must not find it again. Near the
/// base point this is 1e-14; at distance 12, 3e-4 (a thousandth of a pixel
/// of a 1000-pixel image seen from the base point).
const SELF_HIT: f64 = 1e-14;

/// The walk restores `<O,O> = -1`, `<D,D> = 1`, `<O,D> = 0` every this
/// many steps (rounding drifts them by a few ulps per step, and the common
/// scale grows by the `cosh` of each step, at most about 4 for a cell).
const RENORMALISE_EVERY: u32 = 4;

/// The most reflections that fold a ray's start into the simplex.
const MAX_FOLD_STEPS: u32 = 100_000;

/// A regular honeycomb `{p,q,r}` of hyperbolic space as one surface: edges
/// as rods, faces as polygons, vertices as balls, found by walking each
/// ray from cell to cell (or, for horosphere-inscribed cells, through the
/// Coxeter group's fundamental simplex; module docs), so a ray costs the
/// cells it crosses, not the cells in the scene.
///
/// Invariants: `to_world` is the Lorentz matrix of `placement` and
/// `to_local` its inverse; `style` is valid; `cells` holds the
/// depth-limited set when `style.depth` is set.
#[derive(Clone, Debug)]
pub struct RegularHoneycomb {
    symbol: Schlafli,
    /// The characteristic simplex's vertices (its `v0..v3`), kept so that
    /// per-hit queries ([`RegularHoneycomb::face_frame`]) do not rebuild
    /// the simplex for every textured face hit.
    simplex_vertices: [DVec4; 4],
    rings: Rings,
    style: HoneycombStyle,
    domain: Arc<WalkDomain>,
    cells: Option<Arc<CellSet>>,
    shells: Shells,
    placement: Isometry,
    to_world: DMat4,
    to_local: DMat4,
    horizon: f64,
    cosh_horizon: f64,
    /// For rays from the origin, a nearer horizon by their direction
    /// ([`RegularHoneycomb::with_view_horizon`]).
    view: Option<ViewHorizon>,
    /// `cosh` of the radius of a ball about the base point holding every
    /// part of a depth-limited honeycomb with finite cells and vertices.
    cosh_reach: Option<f64>,
    /// How parts get their class.
    colouring: super::CellColouring,
    /// Report a ray that reaches the horizon as a hit on
    /// [`HoneycombPart::Horizon`](super::HoneycombPart::Horizon)
    /// ([`RegularHoneycomb::with_horizon_hits`]).
    horizon_hits: bool,
}

impl RegularHoneycomb {
    /// The honeycomb `symbol` with its base cell centred at the origin (the
    /// face centre when the cells are horosphere-inscribed; see
    /// [`CoxeterSimplex`]): for `{4,3,5}` the cell of
    /// [`cube_435`](super::cube_435), axis-aligned.
    ///
    /// Errors: those of [`HoneycombStyle::validate`]; with a depth,
    /// [`GeomError::TooManyCells`] when the cells within it number more
    /// than [`MAX_TESSELLATION_CELLS`](super::MAX_TESSELLATION_CELLS) (for
    /// `{4,3,5}`, depth 8 and beyond), or for any depth above 0 when the
    /// cells are horosphere-inscribed (each has infinitely many
    /// neighbours).
    pub fn new(symbol: Schlafli, style: HoneycombStyle) -> Result<RegularHoneycomb, GeomError> {
        style.validate()?;
        let simplex = CoxeterSimplex::new(symbol);
        let v = simplex.vertices();
        let domain = WalkDomain::new(&simplex, &style)?;
        let cells = match style.depth {
            Some(depth) => Some(Arc::new(CellSet::build(&simplex, depth)?)),
            None => None,
        };
        // Every part of a listed compact cell lies within its circumradius
        // (plus the radii) of its centre.
        let cosh_reach = match &cells {
            Some(set) if !simplex.ideal()[0] && !simplex.ideal()[3] => {
                let circum = lorentz::distance(v[3], v[0]);
                let pad = style
                    .edges
                    .unwrap_or(0.0)
                    .max(style.vertices.unwrap_or(0.0));
                Some((set.reach() + circum + pad).cosh())
            }
            _ => None,
        };
        Ok(RegularHoneycomb::in_base_placement(
            symbol,
            Rings::REGULAR,
            style,
            &simplex,
            domain,
            cells,
            cosh_reach,
        ))
    }

    /// The honeycomb in its base placement, walked to the default horizon.
    fn in_base_placement(
        symbol: Schlafli,
        rings: Rings,
        style: HoneycombStyle,
        simplex: &CoxeterSimplex,
        domain: WalkDomain,
        cells: Option<Arc<CellSet>>,
        cosh_reach: Option<f64>,
    ) -> RegularHoneycomb {
        RegularHoneycomb {
            symbol,
            simplex_vertices: simplex.vertices(),
            rings,
            style,
            domain: Arc::new(domain),
            cells,
            shells: Shells::new(simplex),
            placement: Isometry::IDENTITY,
            to_world: DMat4::IDENTITY,
            to_local: DMat4::IDENTITY,
            horizon: DEFAULT_HORIZON,
            cosh_horizon: DEFAULT_HORIZON.cosh(),
            view: None,
            cosh_reach,
            colouring: super::CellColouring::Rank,
            horizon_hits: false,
        }
    }

    /// The uniform honeycomb of the Coxeter group `[p,q,r]` with these
    /// rings (Wythoff's construction, `uniform.rs`), walked through the
    /// characteristic simplex in its base placement; node 0 ringed alone is
    /// [`RegularHoneycomb::new`]. Its edges all have one length, and every
    /// vertex sees the same arrangement of cells.
    ///
    /// Errors: those of [`HoneycombStyle::validate`];
    /// [`GeomError::UniformWithCells`] for a depth or more than one cell
    /// class with other rings.
    pub fn uniform(
        symbol: Schlafli,
        rings: Rings,
        style: HoneycombStyle,
    ) -> Result<RegularHoneycomb, GeomError> {
        if rings.is_regular() {
            return RegularHoneycomb::new(symbol, style);
        }
        RegularHoneycomb::wythoff(symbol, rings, style)
    }

    /// [`RegularHoneycomb::uniform`] by the seed's parts whatever the
    /// rings, node 0 alone included (which the tests check against the
    /// regular walk).
    pub(super) fn wythoff(
        symbol: Schlafli,
        rings: Rings,
        style: HoneycombStyle,
    ) -> Result<RegularHoneycomb, GeomError> {
        style.validate()?;
        if style.depth.is_some() || style.cell_classes > 1 {
            return Err(GeomError::UniformWithCells);
        }
        let simplex = CoxeterSimplex::new(symbol);
        let domain = WalkDomain::uniform(&simplex, rings, &style)?;
        Ok(RegularHoneycomb::in_base_placement(
            symbol, rings, style, &simplex, domain, None, None,
        ))
    }

    /// The nearest hit in `(t_min, t_max)`.
    ///
    /// # Accuracy
    ///
    /// The hit point is the ray's point at `t`; `t` agrees with explicit
    /// polygons, rods and balls of the same cells to 1e-9
    /// (`walk_matches_explicit_cells` in `tests/honeycomb_walk.rs`).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        self.walk(ray, t_min, t_max, false, &mut WalkStats::default(), None)
    }

    /// True if the ray meets a part in `(t_min, t_max)` (the shadow test:
    /// the walk stops at the first part found).
    pub fn blocks(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.walk(ray, t_min, t_max, true, &mut WalkStats::default(), None)
            .is_some()
    }

    /// [`RegularHoneycomb::intersect`] with the counts of the walk.
    pub fn intersect_with_stats(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
    ) -> (Option<Hit>, WalkStats) {
        let mut stats = WalkStats::default();
        let hit = self.walk(ray, t_min, t_max, false, &mut stats, None);
        (hit, stats)
    }

    /// The walk of a ray that meets nothing (parts are ignored), step by
    /// step, for at most `max_steps` walls: for measuring the drift of the
    /// walk against a high-precision one. The start is the ray's origin
    /// (`t = 0`); it must lie in the base simplex (`<X,n_i> >= 0`, e.g. the
    /// base point) for the steps to be comparable.
    pub fn walk_steps(&self, ray: &Ray, max_steps: usize) -> Vec<WalkStep> {
        let bare = RegularHoneycomb {
            style: HoneycombStyle {
                edges: None,
                faces: false,
                vertices: None,
                ..self.style
            },
            domain: Arc::new(self.domain.bare()),
            ..self.clone()
        };
        let mut steps = Vec::new();
        bare.walk(
            ray,
            0.0,
            f64::INFINITY,
            false,
            &mut WalkStats::default(),
            Some((&mut steps, max_steps)),
        );
        steps
    }

    /// The arc lengths of the original ray inside the horizon and (with a
    /// depth) the ball that holds every listed cell, clipped to
    /// `(t_min, t_max)`, as `(e^lo, e^hi)`: the walk needs no logarithm
    /// of them; and whether the horizon is what ends it.
    fn window(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, f64, bool)> {
        let mut lo = if t_min > 0.0 { t_min.exp() } else { 1.0 };
        // A primary ray's arc is unbounded: e^inf is inf, without the call.
        let mut hi = if t_max == f64::INFINITY {
            f64::INFINITY
        } else {
            t_max.exp()
        };
        // -<X(t),C> = a cosh t + b sinh t = k is (a+b) u² - 2k u + (a-b) = 0
        // in u = e^t; a ± b > 0 for a future C (<O ± D, C> of null vectors).
        let roots = |c: DVec4, k: f64| {
            let a = -lorentz::dot(ray.origin, c);
            let b = -lorentz::dot(ray.dir, c);
            exp_roots_lazy(a + b, k, a - b).map(|r| r.exp())
        };
        let cosh_horizon = match &self.view {
            Some(view) => view.cosh_for(ray, self.cosh_horizon),
            None => self.cosh_horizon,
        };
        let (u_in, u_out) = roots(DVec4::W, cosh_horizon)?;
        lo = lo.max(u_in);
        let mut at_horizon = u_out < hi;
        hi = hi.min(u_out);
        if let Some(k) = self.cosh_reach {
            let (u_in, u_out) = roots(self.to_world.col(3), k)?;
            lo = lo.max(u_in);
            at_horizon &= u_out >= hi;
            hi = hi.min(u_out);
        }
        (lo < hi).then_some((lo, hi, at_horizon))
    }

    /// The walk, compiled apart for a uniform honeycomb's seed parts: in
    /// the regular walk's loop their test, though never taken, cost 2 % of
    /// its instructions (the step's products were no longer inlined).
    fn walk(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        any: bool,
        stats: &mut WalkStats,
        trace: Option<(&mut Vec<WalkStep>, usize)>,
    ) -> Option<Hit> {
        if self.domain.is_seeded() {
            self.walk_in::<true>(ray, t_min, t_max, any, stats, trace)
        } else {
            self.walk_in::<false>(ray, t_min, t_max, any, stats, trace)
        }
    }

    // Not inlined into its callers: each copy of the loop alone keeps the
    // step's products inlined (measured: 0.5 % more instructions otherwise).
    #[inline(never)]
    fn walk_in<const SEEDED: bool>(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        any: bool,
        stats: &mut WalkStats,
        mut trace: Option<(&mut Vec<WalkStep>, usize)>,
    ) -> Option<Hit> {
        let (u_lo, u_hi, at_horizon) = self.window(ray, t_min, t_max)?;
        // Where the horizon stops the walk, a horizon hit if asked for.
        let report = self.horizon_hits && at_horizon && !any && trace.is_none();
        let beyond = |t: f64| report.then(|| horizon_hit(ray, t));
        let domain = &*self.domain;
        let walls = domain.walls();
        let nw = walls.len();
        let (ch, sh) = (0.5 * (u_lo + 1.0 / u_lo), 0.5 * (u_lo - 1.0 / u_lo));
        let mut o = self.to_local * (ch * ray.origin + sh * ray.dir);
        // A ray that starts on a part far from the base point (a shadow or
        // reflected ray from a far hit) would meet that part again within
        // the drift of the two walks; parts nearer than this to the start
        // are skipped (module docs, "Accuracy").
        let v_guard = (2.0 * SELF_HIT * o.w * o.w).exp();
        let mut d = self.to_local * (sh * ray.origin + ch * ray.dir);
        renormalise(&mut o, &mut d);
        let mut m = DMat4::IDENTITY;
        // The domain matrix: a depth-limited honeycomb asks at every step
        // which cells are drawn; otherwise only a primary hit needs it (for
        // its normal and class), so the walls crossed are kept and folded
        // into `m` in batches or at the hit, and a miss or a shadow ray of
        // an unlimited honeycomb never builds it.
        let mut fold_faces: u32 = 0;
        let mut pending = Pending::new(if self.cells.is_some() {
            Crossings::Eager
        } else if any {
            Crossings::Unused
        } else {
            Crossings::Deferred
        });
        loop {
            let (i, a) = walls
                .iter()
                .map(|n| lorentz::dot(o, *n))
                .enumerate()
                .fold((0, f64::INFINITY), |b, x| if x.1 < b.1 { x } else { b });
            if a >= 0.0 {
                break;
            }
            if stats.folds >= MAX_FOLD_STEPS {
                return None;
            }
            stats.folds += 1;
            // Folding across a face moves the ray's start to the
            // neighbouring cell: one more crossing for the parity.
            if domain.is_face(i) {
                fold_faces += 1;
            }
            o = reflect(o, walls[i]);
            d = reflect(d, walls[i]);
            pending.cross(i, &mut m, walls);
        }
        // Arc lengths are kept as v = e^{2τ} (a product along the walk),
        // which the exits give without a logarithm: e^{2 atanh s} =
        // (1+s)/(1-s). Only a hit takes the one logarithm.
        let mut u_acc = 1.0;
        let v_span = (u_hi / u_lo) * (u_hi / u_lo);
        // The arc length at v (from the start of the window): e^{2t} = u_lo² v.
        let arc = |v: f64| 0.5 * (u_lo * u_lo * v).ln();
        let mut last = usize::MAX;
        let mut a = [0.0; MAX_WALLS];
        let mut b = [0.0; MAX_WALLS];
        stats.cells = 1;
        while stats.steps < MAX_WALK_STEPS {
            stats.steps += 1;
            domain.products(o, d, &mut a, &mut b);
            let (exit, s_min) = match nearest_exit(&a, &b, nw, last) {
                Some((i, s)) => (Some(i), s),
                None => (None, 1.0),
            };
            let span = v_span / u_acc;
            let v_exit = match exit {
                Some(_) => (1.0 + s_min) / (1.0 - s_min),
                None => f64::INFINITY,
            };
            let here = DomainRay {
                o,
                d,
                a: &a[..nw],
                b: &b[..nw],
                exit,
                s_exit: s_min,
                v_exit,
            };
            let floor = (v_guard / u_acc).max(1.0);
            if let Some((v, part)) =
                domain.first_part::<SEEDED>(&here, floor, v_exit.min(span), |c| self.present(c, &m))
            {
                let t = arc(u_acc * v);
                // The normal needs one vector moved by the crossings; the
                // class of the cells (several classes) needs the matrix.
                if !any && self.style.cell_classes > 1 {
                    pending.fold_into(&mut m, walls);
                }
                // Faces crossed from the base cell to this one: the folds
                // and the exits so far (`stats.cells` counts 1 + exits).
                let crossed = u64::from(fold_faces) + u64::from(stats.cells.saturating_sub(1));
                let cell = (&m, &pending, crossed);
                return Some(self.hit(ray, t, &here, v, cell, part, any));
            }
            let Some(exit) = exit.filter(|_| v_exit < span) else {
                // Out of the window: past t_max or the depth's reach (a
                // miss), or at the horizon. A ray with no exit runs inside
                // this cell to its ideal centre, beyond any horizon.
                return beyond(arc(v_span));
            };
            // The exit point and tangent, both scaled by cosh τ: the walk
            // keeps o and d with a common scale λ (`<o,o> = -λ²`), which
            // the exit ratios ignore and the part tests divide out, and
            // restores λ = 1 every few steps.
            let n = walls[exit];
            let mut o2 = o + s_min * d;
            // The exit point lies on the wall: put it there exactly.
            o2 -= lorentz::dot(o2, n) * n;
            d = reflect(s_min * o + d, n);
            o = o2;
            if stats.steps.is_multiple_of(RENORMALISE_EVERY) {
                renormalise(&mut o, &mut d);
            }
            pending.cross(exit, &mut m, walls);
            u_acc *= v_exit;
            last = exit;
            let face = domain.is_face(exit);
            if face {
                stats.cells += 1;
            }
            if let Some((steps, max)) = trace.as_mut() {
                if steps.len() >= *max {
                    return None;
                }
                pending.fold_into(&mut m, walls);
                let (mut o, mut d) = (o, d);
                renormalise(&mut o, &mut d);
                steps.push(WalkStep {
                    wall: exit,
                    face,
                    t: arc(u_acc),
                    origin: o,
                    dir: d,
                    chamber: m,
                });
            }
        }
        beyond(arc(u_acc))
    }

    /// True if one of the cells (local centres mapped by `m`) is drawn.
    pub(super) fn present(&self, cells: &[DVec4], m: &DMat4) -> bool {
        match &self.cells {
            None => true,
            Some(set) => cells.iter().any(|c| set.layer(*m * *c).is_some()),
        }
    }

    /// The class of a part with these cells: the least rank of its drawn
    /// cells, modulo the number of classes.
    pub(super) fn class(&self, cells: &[DVec4], m: &DMat4) -> u32 {
        let k = self.style.cell_classes;
        if k <= 1 {
            return 0;
        }
        let rank = cells
            .iter()
            .filter_map(|c| {
                let c = *m * *c;
                match &self.cells {
                    Some(set) => set.layer(c).map(i64::from),
                    None => Some(self.shells.rank(c)),
                }
            })
            .min()
            .unwrap_or(0);
        // rem_euclid by a positive k is in 0..k, which fits u32.
        rank.rem_euclid(i64::from(k)) as u32
    }

    /// The hit on `part` at `v = e^{2τ}` from the start of the domain ray
    /// `c` (`t` along the original ray); a shadow ray's class is 0. The
    /// domain matrix is `m` with the `pending` reflections folded in (none
    /// are pending when the class needs it).
    #[allow(clippy::too_many_arguments)]
    fn hit(
        &self,
        ray: &Ray,
        t: f64,
        c: &DomainRay,
        v: f64,
        (m, pending, crossed): (&DMat4, &Pending, u64),
        part: DomainPart,
        shadow: bool,
    ) -> Hit {
        let (mut o, mut d) = (c.o, c.d);
        renormalise(&mut o, &mut d);
        // e^τ = sqrt v.
        let e = v.sqrt();
        let x = (0.5 * (e + 1.0 / e)) * o + (0.5 * (e - 1.0 / e)) * d;
        let local_normal = self.domain.local_normal(part, x);
        let point = ray.at(t);
        let walls = self.domain.walls();
        let mut normal = self.to_world * (*m * pending.unfold(local_normal, walls));
        normal += lorentz::dot(normal, point) * point;
        let len = lorentz::norm(normal);
        if len > 0.0 && len.is_finite() {
            normal /= len;
        }
        let class = match self.domain.seed() {
            _ if shadow => 0,
            // A uniform honeycomb colours by kind (`uniform.rs`): the ray's
            // side of a face, in the chamber, says which kind of cell.
            Some(seed) if part.is_seeded() => seed.kind_class(part, c.o),
            _ if self.colouring == super::CellColouring::Parity => (crossed % 2) as u32,
            _ => self.class(self.domain.cells_of(part), m),
        };
        Hit {
            t,
            point,
            normal,
            shading: normal,
            part: encode_part(part.kind(), class),
        }
    }
}

/// The hit a ray that the horizon stopped at arc length `t` reports: the
/// ray's point there, the normal facing back along it.
fn horizon_hit(ray: &Ray, t: f64) -> Hit {
    let facing = -ray.tangent_at(t);
    Hit {
        t,
        point: ray.at(t),
        normal: facing,
        shading: facing,
        part: encode_part(super::HoneycombPart::Horizon, 0),
    }
}
