//! Axis-aligned boxes in the Klein model, and rays as straight segments
//! there: the bounds of a Euclidean-style bounding-volume hierarchy.
//!
//! In the Klein model `k = x / w` (hyperboloid `X = (x, w)`) every geodesic
//! is a straight chord and every h-plane flat, so the convex hull of points
//! is their Euclidean convex hull in `k`, and the axis-aligned box of some
//! points contains every convex polygon and segment between them. A ray
//! becomes a segment `k(t) = P + λ(t) V` with `λ` increasing in the arc
//! length `t`, so the slab test of Euclidean tracers applies unchanged, and
//! its entry `λ` orders boxes front to back along the ray.
//!
//! Every box is padded ([`PAD`]) so that it also holds what the exact tests
//! accept by their tolerances and the rounding of its own corners; the slab
//! test pads its arc the same way. A ray that is not finite has no
//! trustworthy chord: [`KleinRay::is_finite`] says so, and a hierarchy then
//! hands every item to the exact test, which reports the failure.
//!
//! **The ray.** With `X(t) = cosh t O + sinh t D` and `τ = tanh t`,
//! `k = (o + τ d)/(o_w + τ d_w)`. Writing `P = o / o_w` and
//! `V = o_w d - d_w o`,
//!
//! `P + λ V = (o + τ d)/(o_w + τ d_w)` for `λ = τ / (o_w (o_w + τ d_w))`,
//!
//! (multiply out: `o (o_w + τ d_w) + τ (o_w d - d_w o) = o_w (o + τ d)`).
//! `o_w + τ d_w > 0` on the future sheet, and `dλ/dτ = 1/(o_w + τ d_w)^2 > 0`:
//! `λ` increases with `t`, from 0 at `t = 0` to `1/(o_w (o_w + d_w))` at the
//! absolute.
//!
//! **The ball.** The h-ball of radius `r` about `C = (c, c_w)` is
//! `{X : -<X,C> <= cosh r}`. On the hyperboloid `X = (k, 1)/sqrt(1 - |k|^2)`,
//! so with `κ = cosh r` the ball is the solid ellipsoid
//! `(c_w - k·c)^2 <= κ^2 (1 - |k|^2)`, i.e.
//! `k^T (κ^2 I + c c^T) k - 2 c_w c·k + c_w^2 - κ^2 <= 0`. With
//! `A = κ^2 I + c c^T`, `A^{-1} = (I - c c^T / Δ)/κ^2`, `Δ = κ^2 + |c|^2 =
//! sinh^2 r + c_w^2` (as `|c|^2 = c_w^2 - 1`), its centre is
//! `k_0 = A^{-1} c_w c = c_w c / Δ` and it is
//! `(k - k_0)^T A (k - k_0) <= ρ`, `ρ = c_w^2 |c|^2/Δ - c_w^2 + κ^2 =
//! κ^2 sinh^2 r / Δ`. The half-width along axis `i` is
//! `sqrt(ρ (A^{-1})_{ii}) = sinh r sqrt(Δ - c_i^2) / Δ`. At the origin
//! (`c = 0, c_w = 1`) this is `tanh r`, the Klein radius of the ball.
//!
//! **The tube.** A rod of radius `w` is the set of points within `w` of a
//! segment. For `d(p, q) <= w`, `|k(q) - k(p)| <= w sqrt(1 - s^2)` with
//! `s = max(0, |k(p)| - w)`: the Klein metric is
//! `ds^2 = |dk|^2/(1 - |k|^2) + (k·dk)^2/(1 - |k|^2)^2 >= |dk|^2/(1 - |k|^2)`,
//! so along the geodesic from `p` to `q` (a straight chord)
//! `|dk| <= sqrt(1 - |k|^2) ds`; that gives first `|k - k(p)| <= w` on it,
//! hence `|k| >= |k(p)| - w`, and then the bound. So the box of a piece of
//! the segment's chord, widened by that bound at the piece's point nearest
//! the Klein origin, holds the part of the rod within `w` of that piece:
//! thin where the rod is, `w / cosh(r - w)` at distance `r`, where a ball's
//! box stays a cube.

use glam::{DVec3, DVec4};

use crate::bound::BoundingBall;
use crate::point::Vertex;
use crate::ray::Ray;

/// Absolute padding of every box, in Klein coordinates: far above the
/// rounding of coordinates of size at most 1 and of the exact tests'
/// tolerances (a polygon accepts hits `1e-10` outside its edges, a distance
/// that shrinks, never grows, on the way to Klein coordinates), far below a
/// size that would make culling less effective.
pub const PAD: f64 = 1e-9;

/// The least magnitude of a chord direction's component (see
/// [`KleinRay::new`]).
const TINY: f64 = 1e-200;

/// Arc starts up to this are taken as 0 by [`KleinRay::arc`].
pub const NEAR_START: f64 = 1e-6;

/// Relative padding of a ray's arc `[λ_min, λ_max]`.
const ARC_SLACK: f64 = 1e-9;

/// A closed axis-aligned box in Klein coordinates.
///
/// Invariant: `lo <= hi` componentwise, both finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KleinBox {
    lo: DVec3,
    hi: DVec3,
}

impl KleinBox {
    /// The box from `lo` to `hi`; `None` unless both are finite with
    /// `lo <= hi`.
    pub fn new(lo: DVec3, hi: DVec3) -> Option<KleinBox> {
        (lo.is_finite() && hi.is_finite() && lo.cmple(hi).all()).then_some(KleinBox { lo, hi })
    }

    /// The least corner.
    pub fn lo(&self) -> DVec3 {
        self.lo
    }

    /// The greatest corner.
    pub fn hi(&self) -> DVec3 {
        self.hi
    }

    /// The box around an h-ball (the ellipsoid's exact extent, padded; see
    /// the module docs); `None` if it is not finite.
    pub fn around_ball(ball: &BoundingBall) -> Option<KleinBox> {
        let c = ball.center();
        let s = ball.radius().sinh();
        let delta = s * s + c.w * c.w;
        let centre = c.truncate() * (c.w / delta);
        let cc = c.truncate() * c.truncate();
        let half = (DVec3::splat(delta) - cc).max(DVec3::ZERO).sqrt() * (s / delta);
        let pad = half * 1e-12 + DVec3::splat(PAD);
        KleinBox::new(centre - half - pad, centre + half + pad)
    }

    /// The box around points given on the hyperboloid or at infinity
    /// (hull vertices): it contains their convex hull. `None` for no
    /// points or a non-finite one.
    pub fn around_vertices<'a>(vertices: impl IntoIterator<Item = &'a Vertex>) -> Option<KleinBox> {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for v in vertices {
            let k = match v {
                Vertex::Interior(p) => {
                    let x = p.to_hyperboloid();
                    x.truncate() / x.w
                }
                // An ideal point is its unit direction in the Klein model.
                Vertex::Ideal(i) => i.coords(),
            };
            lo = lo.min(k);
            hi = hi.max(k);
        }
        let pad = DVec3::splat(PAD);
        KleinBox::new(lo - pad, hi + pad)
    }

    /// The box around points on the hyperboloid; `None` for none or a
    /// non-finite one.
    pub fn around_points(points: impl IntoIterator<Item = DVec4>) -> Option<KleinBox> {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for x in points {
            let k = x.truncate() / x.w;
            lo = lo.min(k);
            hi = hi.max(k);
        }
        let pad = DVec3::splat(PAD);
        KleinBox::new(lo - pad, hi + pad)
    }

    /// Boxes whose union holds the rod of radius `w` about the segment
    /// from `a` to `b` (hyperboloid points; module docs, "The tube"): the
    /// chord cut into at most `max_pieces` equal pieces, fewer where a
    /// piece would be shorter than `piece_widths` times the rod's Klein
    /// width. Empty if an end is not finite.
    pub fn around_tube(
        a: DVec4,
        b: DVec4,
        w: f64,
        piece_widths: f64,
        max_pieces: u32,
    ) -> Vec<KleinBox> {
        let (ka, kb) = (a.truncate() / a.w, b.truncate() / b.w);
        if !(ka.is_finite() && kb.is_finite() && w.is_finite() && w >= 0.0) {
            return Vec::new();
        }
        // The Klein half-width of the rod about a piece whose nearest point
        // to the origin is at `near`.
        let width = |near: f64| {
            let s = (near - w).max(0.0);
            w * (1.0 - s * s).max(0.0).sqrt()
        };
        let length = (kb - ka).length();
        let widest = width(nearest_to_origin(ka, kb));
        let pieces = if widest > 0.0 {
            (length / (piece_widths * widest))
                .ceil()
                .clamp(1.0, f64::from(max_pieces.max(1)))
        } else {
            1.0
        };
        // `pieces` is a whole number from 1 to max_pieces.
        let n = pieces as u32;
        (0..n)
            .filter_map(|i| {
                let p = ka + (kb - ka) * (f64::from(i) / pieces);
                let q = if i + 1 == n {
                    kb
                } else {
                    ka + (kb - ka) * (f64::from(i + 1) / pieces)
                };
                let e = DVec3::splat(width(nearest_to_origin(p, q)));
                let pad = (e + p.abs().max(q.abs())) * 1e-12 + DVec3::splat(PAD);
                KleinBox::new(p.min(q) - e - pad, p.max(q) + e + pad)
            })
            .collect()
    }

    /// The smallest box containing both.
    pub fn union(&self, other: &KleinBox) -> KleinBox {
        KleinBox {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }

    /// The smaller box of the two, where they overlap; `None` if they do
    /// not (for bounds that are each conservative, so is their
    /// intersection).
    pub fn intersection(&self, other: &KleinBox) -> Option<KleinBox> {
        KleinBox::new(self.lo.max(other.lo), self.hi.min(other.hi))
    }

    /// The centre.
    pub fn centre(&self) -> DVec3 {
        0.5 * (self.lo + self.hi)
    }

    /// Half the Euclidean surface area: the cost weight of the surface-area
    /// heuristic (rays are chords, so the chance that one crossing a box
    /// also crosses a box inside it is, for rays spread evenly, about the
    /// ratio of their areas).
    pub fn half_area(&self) -> f64 {
        let e = self.hi - self.lo;
        e.x * e.y + e.y * e.z + e.z * e.x
    }

    /// True if the hyperboloid point lies in the box.
    pub fn contains(&self, x: DVec4) -> bool {
        let k = x.truncate() / x.w;
        k.cmpge(self.lo).all() && k.cmple(self.hi).all()
    }
}

/// The lesser of two numbers by one comparison (one instruction), for
/// hot loops over numbers that are never NaN; `f64::min` also handles NaN
/// and compiles to a compare-and-blend sequence. With a NaN it returns `b`.
#[inline(always)]
pub fn plain_min(a: f64, b: f64) -> f64 {
    if a < b { a } else { b }
}

/// The greater of two numbers, as [`plain_min`].
#[inline(always)]
pub fn plain_max(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// The Euclidean distance from the origin to the segment from `p` to `q`
/// (Klein points, where the geodesic segment is this straight one; the
/// hyperbolic distance from the origin to it is the `artanh` of this, the
/// Klein radius growing with the distance).
///
/// # Accuracy
///
/// A few ulps of `|p| + |q|`; 0 for `p = q` at the origin.
pub fn nearest_to_origin(p: DVec3, q: DVec3) -> f64 {
    let d = q - p;
    let dd = d.length_squared();
    let t = if dd > 0.0 {
        (-p.dot(d) / dd).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p + d * t).length()
}

/// The box from `lo` to `hi` rounded outwards to `f32`, for compact
/// hierarchy nodes: every `f32` is exactly an `f64`, so the stored box
/// contains the given one.
pub fn round_outward_f32(lo: DVec3, hi: DVec3) -> ([f32; 3], [f32; 3]) {
    let down = |x: f64| {
        let f = x as f32;
        if f64::from(f) > x { f.next_down() } else { f }
    };
    let up = |x: f64| {
        let f = x as f32;
        if f64::from(f) < x { f.next_up() } else { f }
    };
    (lo.to_array().map(down), hi.to_array().map(up))
}

/// A ray as a straight segment in the Klein model (module docs).
#[derive(Clone, Copy, Debug)]
pub struct KleinRay {
    origin: DVec3,
    dir: DVec3,
    o_w: f64,
    d_w: f64,
}

impl KleinRay {
    /// The ray's chord.
    #[inline]
    pub fn new(ray: &Ray) -> KleinRay {
        let (o, d) = (ray.origin, ray.dir);
        let mut dir = d.truncate() * o.w - o.truncate() * d.w;
        // A zero component would give an infinite inverse and, on a box
        // face, 0 * inf = NaN; the chord turned by 1e-200 moves less than
        // 1e-190 over its whole length, far inside every box's padding, and
        // keeps the slab test free of NaN for finite rays.
        for k in 0..3 {
            if dir[k].abs() < TINY {
                dir[k] = TINY.copysign(dir[k]);
            }
        }
        KleinRay {
            // One division for three: the start moves by an ulp at most,
            // far inside the arc's and the boxes' padding.
            origin: o.truncate() * o.w.recip(),
            dir,
            o_w: o.w,
            d_w: d.w,
        }
    }

    /// The chord's start `P`, in Klein coordinates.
    #[inline]
    pub fn origin(&self) -> DVec3 {
        self.origin
    }

    /// The chord's direction `V` (no component below `1e-200` in
    /// magnitude; see [`KleinRay::new`]).
    #[inline]
    pub fn dir(&self) -> DVec3 {
        self.dir
    }

    /// `1/V` per component (each finite for a finite ray; see
    /// [`KleinRay::new`]).
    #[inline]
    pub fn inv_dir(&self) -> DVec3 {
        DVec3::ONE / self.dir
    }

    /// True if the chord is finite: the ray was. A hierarchy must not trust
    /// the slab test of a chord that is not (it would answer "miss").
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.origin.is_finite()
            && self.dir.is_finite()
            && self.o_w.is_finite()
            && self.d_w.is_finite()
    }

    /// `λ` at arc length `t` (`t = ∞` gives the absolute's).
    #[inline]
    pub fn lambda(&self, t: f64) -> f64 {
        let tau = if t == f64::INFINITY { 1.0 } else { t.tanh() };
        self.lambda_of_tanh(tau)
    }

    /// `λ` at the arc length whose hyperbolic tangent is `tau` (1 at the
    /// absolute): for callers who know `tanh t` without computing `t`.
    #[inline]
    pub fn lambda_of_tanh(&self, tau: f64) -> f64 {
        tau / (self.o_w * (self.o_w + tau * self.d_w))
    }

    /// `λ` of a point on the ray (a hyperboloid point, such as a hit), read
    /// off its Klein coordinates along the chord's longest axis: no
    /// transcendental call, and as exact as the point (the chord's
    /// direction has a component of at least `|V|/√3` there).
    #[inline]
    pub fn lambda_at(&self, x: DVec4) -> f64 {
        let k = x.truncate() / x.w;
        let a = self.dir.abs();
        let axis = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        (k[axis] - self.origin[axis]) / self.dir[axis]
    }

    /// `λ` of a point on the ray, padded upwards by the slack of
    /// [`KleinRay::arc`]: the end of an arc that must keep the point.
    #[inline]
    pub fn arc_end_at(&self, x: DVec4) -> f64 {
        let hi = self.lambda_at(x);
        hi + ARC_SLACK * hi.abs() + f64::MIN_POSITIVE
    }

    /// The arc `(t_min, t_max)` as a padded `λ` interval. A start below
    /// `NEAR_START` = 1e-6 (the usual offset of secondary rays from their
    /// surface) is taken as 0: `λ(0) = 0 <= λ(t_min)` keeps the arc
    /// conservative and saves a hyperbolic tangent per ray.
    #[inline]
    pub fn arc(&self, t_min: f64, t_max: f64) -> (f64, f64) {
        let tau = if t_max == f64::INFINITY {
            1.0
        } else {
            t_max.tanh()
        };
        self.arc_to_tanh(t_min, tau)
    }

    /// [`KleinRay::arc`] with its end given as `tanh(t_max)` (1 for an arc
    /// to the absolute), same bits: a shadow ray knows the tangent of its
    /// light's distance by algebra
    /// ([`Separation::tanh`](crate::lorentz::Separation::tanh)).
    #[inline]
    pub fn arc_to_tanh(&self, t_min: f64, tanh_t_max: f64) -> (f64, f64) {
        let lo = if t_min <= NEAR_START {
            0.0
        } else {
            let lo = self.lambda(t_min);
            lo - ARC_SLACK * lo.abs()
        };
        let hi = self.lambda_of_tanh(tanh_t_max);
        (
            lo - f64::MIN_POSITIVE,
            hi + ARC_SLACK * hi.abs() + f64::MIN_POSITIVE,
        )
    }

    /// Where the chord enters the box within `[lo, hi]` (`λ`), or `None` if
    /// it misses. Only for a finite chord ([`KleinRay::is_finite`]).
    #[inline]
    pub fn entry(&self, b: &KleinBox, lo: f64, hi: f64) -> Option<f64> {
        self.slab_entry(b.lo, b.hi, lo, hi)
    }

    /// [`KleinRay::entry`] for the box from `b_lo` to `b_hi`, unchecked, for
    /// boxes valid by construction. It forms `1/V` on each call (the chord
    /// keeps no reciprocals): a loop over many boxes is faster with its own
    /// slab set-up, as hscene's renderer has.
    #[inline(always)]
    pub fn slab_entry(&self, b_lo: DVec3, b_hi: DVec3, lo: f64, hi: f64) -> Option<f64> {
        // Plain comparisons (one instruction each): the chord of a finite
        // ray has finite inverse components, so nothing here is NaN.
        let (min, max) = (plain_min, plain_max);
        let inv_dir = self.inv_dir();
        let a = (b_lo - self.origin) * inv_dir;
        let z = (b_hi - self.origin) * inv_dir;
        let enter = max(max(max(min(a.x, z.x), min(a.y, z.y)), min(a.z, z.z)), lo);
        let leave = min(min(min(max(a.x, z.x), max(a.y, z.y)), max(a.z, z.z)), hi);
        (enter <= leave).then_some(enter)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lorentz;
    use crate::point::Point;
    use crate::test_rng::Rng;

    fn ball(c: DVec3, r: f64) -> BoundingBall {
        BoundingBall::new(Point::from_coords(c).unwrap().to_hyperboloid(), r).unwrap()
    }

    /// Every point within `w` of the segment lies in one of its tube boxes:
    /// rods near the origin and far from it (Klein radius up to 0.9993),
    /// thin and thick, short and long, sampled on their surface and inside,
    /// end caps included; and a rod near the origin gets boxes far thinner
    /// than the cube of a ball around it.
    #[test]
    fn tube_boxes_hold_the_rod() {
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        let (unit, dir) = (|r: &mut Rng| r.unit(), |r: &mut Rng| r.direction());
        for _ in 0..300 {
            let (da, db) = (dir(&mut rng), dir(&mut rng));
            let (ra, rb) = (unit(&mut rng) * 4.0, unit(&mut rng) * 4.0);
            let w = 0.005 + unit(&mut rng) * 0.3;
            let a = Point::at_distance_from_origin(da, ra)
                .unwrap()
                .to_hyperboloid();
            let b = Point::at_distance_from_origin(db, rb)
                .unwrap()
                .to_hyperboloid();
            let boxes = KleinBox::around_tube(a, b, w, 16.0, 8);
            assert!(!boxes.is_empty() && boxes.len() <= 8);
            let Some((towards, len)) = lorentz::direction_towards(a, b) else {
                continue;
            };
            for k in 0..200 {
                let p = lorentz::geodesic_point(a, towards, unit(&mut rng) * len);
                // A unit tangent at p in a random direction.
                let v = dir(&mut rng).extend(0.0);
                let mut t = v + lorentz::dot(v, p) * p;
                t /= lorentz::norm(t);
                // Half on the surface, half inside.
                let d = if k % 2 == 0 {
                    w
                } else {
                    w * unit(&mut rng).sqrt()
                };
                let q = lorentz::geodesic_point(p, t, d);
                assert!(boxes.iter().any(|b| b.contains(q)), "{a} {b} {w}: {q}");
            }
        }
        // Near the origin, a long thin rod's boxes are thin across it.
        let a = Point::new(-0.5, 0.0, 0.0).unwrap().to_hyperboloid();
        let b = Point::new(0.5, 0.0, 0.0).unwrap().to_hyperboloid();
        let boxes = KleinBox::around_tube(a, b, 0.01, 16.0, 8);
        assert_eq!(boxes.len(), 8);
        for bx in &boxes {
            assert!((bx.hi().y - bx.lo().y) < 0.021 && (bx.hi().z - bx.lo().z) < 0.021);
        }
    }

    /// The box around a ball at the origin is the cube of half-width
    /// `tanh r`.
    #[test]
    fn ball_at_origin_is_the_tanh_cube() {
        let b = KleinBox::around_ball(&ball(DVec3::ZERO, 0.7)).unwrap();
        let t = 0.7f64.tanh();
        assert!((b.hi() - DVec3::splat(t)).abs().max_element() < 2e-9);
        assert!((b.lo() + DVec3::splat(t)).abs().max_element() < 2e-9);
    }

    /// Points on the sphere's surface fall in its box, and the box is
    /// tight: along each axis some surface point reaches its face.
    #[test]
    fn ball_box_is_exact_extent() {
        for (c, r) in [
            (DVec3::new(0.3, -0.2, 0.5), 0.4),
            (DVec3::new(-0.9, 0.1, 0.3), 0.05),
            (DVec3::new(0.0, 0.99, 0.0), 1.5),
        ] {
            let b = ball(c, r);
            let kb = KleinBox::around_ball(&b).unwrap();
            let centre = Point::from_coords(c).unwrap();
            let mut reach_lo = DVec3::splat(f64::INFINITY);
            let mut reach_hi = DVec3::splat(f64::NEG_INFINITY);
            for i in 0..4000 {
                let z = 1.0 - 2.0 * (f64::from(i) + 0.5) / 4000.0;
                let a = f64::from(i) * 2.399_963_229_728_653;
                let s = (1.0 - z * z).sqrt();
                let dir = DVec3::new(s * a.cos(), s * a.sin(), z);
                let ray = Ray::from_ball_unchecked(&centre, dir);
                let x = ray.at(r);
                assert!(kb.contains(x), "{c} {r}: {x}");
                let k = x.truncate() / x.w;
                reach_lo = reach_lo.min(k);
                reach_hi = reach_hi.max(k);
            }
            let slack = (kb.hi() - kb.lo()) * 2e-3;
            assert!((reach_lo - kb.lo()).cmple(slack).all(), "{c} {r}");
            assert!((kb.hi() - reach_hi).cmple(slack).all(), "{c} {r}");
        }
    }

    /// `P + λ(t) V` is the Klein image of the ray's point at `t`, for rays
    /// that start away from the origin too.
    #[test]
    fn chord_parameter_matches_the_ray() {
        let start = Point::new(0.4, -0.3, 0.2).unwrap();
        let ray = Ray::from_ball_unchecked(&start, DVec3::new(-0.2, 0.9, 0.3));
        let k = KleinRay::new(&ray);
        let dir = ray.dir.truncate() * ray.origin.w - ray.origin.truncate() * ray.dir.w;
        let mut last = -1.0;
        for t in [0.0, 0.1, 0.5, 1.0, 3.0, 8.0] {
            let x = ray.at(t);
            let want = x.truncate() / x.w;
            let lam = k.lambda(t);
            assert!(lam > last);
            last = lam;
            let got = k.origin + lam * dir;
            assert!((got - want).length() < 1e-12, "t {t}: {got} vs {want}");
            assert!(
                (k.lambda_at(x) - lam).abs() <= 1e-12 * lam.max(1e-3),
                "t {t}"
            );
        }
        assert!(k.lambda(f64::INFINITY) > last);
    }

    /// The slab test finds a box the ray crosses, misses one it passes,
    /// and respects the arc.
    #[test]
    fn slab_entry() {
        let ray = Ray::from_origin_unchecked(DVec3::Z);
        let k = KleinRay::new(&ray);
        let on = KleinBox::new(DVec3::new(-0.1, -0.1, 0.4), DVec3::new(0.1, 0.1, 0.5)).unwrap();
        let off = KleinBox::new(DVec3::new(0.2, 0.2, 0.4), DVec3::new(0.3, 0.3, 0.5)).unwrap();
        let (lo, hi) = k.arc(0.0, f64::INFINITY);
        let e = k.entry(&on, lo, hi).unwrap();
        assert!((e - 0.4).abs() < 1e-12);
        assert!(k.entry(&off, lo, hi).is_none());
        // The box lies beyond an arc that ends at Klein 0.3 (t = atanh 0.3).
        let (lo, hi) = k.arc(0.0, 0.3f64.atanh());
        assert!(k.entry(&on, lo, hi).is_none());
    }
}
