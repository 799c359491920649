//! The bounding-volume hierarchy in Klein coordinates: the boxes of the
//! triangles' Klein vertices, a binned-SAH tree over them, and the ray's
//! Klein segment, padded so that no box test culls a triangle the exact
//! test would accept.

use glam::{DVec3, DVec4};

use crate::klein_box::round_outward_f32;
use crate::ray::Ray;

/// Bins of the SAH split search.
const BINS: usize = 16;
/// The SAH may keep up to this many triangles in a leaf.
const MAX_LEAF: usize = 8;
/// Sets of up to this many triangles are always leaves: splitting them
/// saves little work per ray (a triangle's exact test costs about two box
/// tests) and would add a node (32 bytes) for every two triangles or so.
const MIN_LEAF: usize = 4;
/// Below this depth splits are chosen by the SAH; deeper, by the median
/// (which halves the count, so the depth stays bounded however the SAH
/// splits went: 2^30 triangles need 30 more levels at most).
const SAH_DEPTH: usize = 32;
/// No node is deeper than this (a leaf is forced there).
pub(super) const MAX_DEPTH: usize = 62;

/// A BVH node (32 bytes): a Klein box, its corners rounded outwards to
/// `f32` (so it contains the `f64` box, and the padded tests stay
/// conservative), and either a leaf's triangle range (`count > 0`,
/// `tris[first .. first + count]`) or, for an interior node (`count == 0`),
/// the index of its second child (the first is next).
#[derive(Clone, Copy)]
pub(super) struct Node {
    lo: [f32; 3],
    hi: [f32; 3],
    pub(super) first: u32,
    pub(super) count: u32,
}

/// An `f32` corner back in `f64` (exactly).
#[inline]
fn wide(c: [f32; 3]) -> DVec3 {
    DVec3::new(f64::from(c[0]), f64::from(c[1]), f64::from(c[2]))
}

/// A ray's straight segment through the Klein model of the local frame,
/// for the box tests.
pub(super) struct KleinSegment {
    /// The Klein segment from the ray's origin `p1` (s = 0) to its ideal end
    /// (s = 1); `inv` is `1 / (p2 - p1)` per axis.
    p1: DVec3,
    inv: DVec3,
    /// Absolute padding of every box (Klein units) and of the segment
    /// parameter when pruning: bounds on the rounding of the segment and of
    /// the exact test's projection.
    pad: f64,
    prune_pad: f64,
    /// `X0 / (X0 + V0)`, for the map from arc length to segment parameter.
    x0_over_a: f64,
    /// The segment could not be formed (a ray of f64's reach): every box
    /// is entered.
    all: bool,
}

impl KleinSegment {
    /// The segment of a finite local ray; `scale` is the mesh's largest
    /// vertex 1-norm, which sets the rounding of the exact test's
    /// projections and so the padding.
    pub(super) fn new(local: &Ray, scale: f64) -> KleinSegment {
        let (x, v) = (local.origin, local.dir);
        // The origin's Klein point and the ideal end (X + V, a future null
        // vector, scaled to time 1).
        let end = x + v;
        let a = end.w;
        let p1 = x.truncate() / x.w;
        let p2 = end.truncate() / a;
        let d = p2 - p1;
        let size = x.abs().element_sum() + v.abs().element_sum();
        let pad = 64.0 * f64::EPSILON * size * size * (1.0 + scale);
        let all = !(x.w > 0.0 && a > 0.0 && pad.is_finite() && p1.is_finite() && d.is_finite());
        KleinSegment {
            p1,
            inv: d.recip(),
            pad,
            prune_pad: 1e-9 + 4.0 * pad / d.length(),
            x0_over_a: x.w / a,
            all,
        }
    }

    /// The segment parameter of the ray's point at arc length `t`: with
    /// `X(t) = e^{-t} X + sinh t (X + V)`, the Klein point is
    /// `p1 + s (p2 - p1)` with `s = 1 / (1 + 2 (X0/(X0+V0)) / expm1(2t))`,
    /// increasing from `0` at `t = 0` to `1` at `t = inf`.
    #[inline]
    fn param(&self, t: f64) -> f64 {
        1.0 / (1.0 + 2.0 * self.x0_over_a / (2.0 * t).exp_m1())
    }

    /// A lower bound on the segment parameter of `t_min`: none for
    /// `t_min < 0` (what lies behind the origin is not worth culling), and
    /// `param(0) = 0` for the tiny `t_min` of secondary rays (`param` is
    /// increasing, so that is a lower bound, and it saves an `expm1`).
    #[inline]
    pub(super) fn lower(&self, t_min: f64) -> f64 {
        if self.all || !(t_min >= 0.0) {
            f64::NEG_INFINITY
        } else if t_min < 1e-6 {
            -self.prune_pad
        } else {
            self.param(t_min) - self.prune_pad
        }
    }

    /// An upper bound on the segment parameter of `t_max`.
    #[inline]
    pub(super) fn upper(&self, t_max: f64) -> f64 {
        if self.all {
            f64::INFINITY
        } else {
            self.param(t_max) + self.prune_pad
        }
    }

    /// An upper bound on the segment parameter up to which a crossing
    /// nearer than `t` can still lie.
    #[inline]
    pub(super) fn prune(&self, t: f64) -> f64 {
        self.upper(t)
    }

    /// Where the segment, restricted to `[s_lo, s_hi]`, enters the node's
    /// padded box; `None` if it misses it.
    #[inline]
    pub(super) fn enter(&self, node: &Node, s_lo: f64, s_hi: f64) -> Option<f64> {
        if self.all {
            return Some(s_lo);
        }
        let lo = (wide(node.lo) - self.pad - self.p1) * self.inv;
        let hi = (wide(node.hi) + self.pad - self.p1) * self.inv;
        let mut near = s_lo;
        let mut far = s_hi;
        for (a, b) in [(lo.x, hi.x), (lo.y, hi.y), (lo.z, hi.z)] {
            near = near.max(a.min(b));
            far = far.min(a.max(b));
        }
        (near <= far).then_some(near)
    }
}

/// Half the surface area of a box (zero for an empty or inverted one).
fn half_area(lo: DVec3, hi: DVec3) -> f64 {
    let e = (hi - lo).max(DVec3::ZERO);
    e.x * e.y + e.y * e.z + e.z * e.x
}

/// The BVH over `triangles` (indices into the local hyperboloid vertices
/// `local`): the nodes and the leaf order of the triangles.
///
/// Each triangle's Klein box is kept in `f32` rounded outwards (24 bytes a
/// triangle while building); its centre is taken from that box. Both only
/// steer the build: any box that contains the triangle gives the same hits.
pub(super) fn build_bvh(local: &[DVec4], triangles: &[[u32; 3]]) -> (Vec<Node>, Vec<u32>) {
    let boxes: Vec<([f32; 3], [f32; 3])> = triangles
        .iter()
        .map(|t| {
            let k = t.map(|i| {
                let v = local[i as usize];
                v.truncate() / v.w
            });
            round_outward_f32(k[0].min(k[1]).min(k[2]), k[0].max(k[1]).max(k[2]))
        })
        .collect();
    let mut order: Vec<u32> = (0..triangles.len() as u32).collect();
    let mut nodes = Vec::new();
    let builder = Builder { boxes: &boxes };
    builder.node(&mut nodes, &mut order, 0, 0);
    nodes.shrink_to_fit();
    (nodes, order)
}

struct Builder<'a> {
    boxes: &'a [([f32; 3], [f32; 3])],
}

impl Builder<'_> {
    /// The box of item `i`, in `f64`.
    #[inline]
    fn bounds(&self, i: u32) -> (DVec3, DVec3) {
        let (lo, hi) = self.boxes[i as usize];
        (wide(lo), wide(hi))
    }

    /// The centre of item `i`'s box.
    #[inline]
    fn centre(&self, i: u32) -> DVec3 {
        let (lo, hi) = self.bounds(i);
        0.5 * (lo + hi)
    }

    /// Build the subtree over `items` (which start at leaf position
    /// `first`), reordering them; returns its root's index.
    fn node(&self, nodes: &mut Vec<Node>, items: &mut [u32], first: usize, depth: usize) -> u32 {
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &i in items.iter() {
            let (l, h) = self.bounds(i);
            lo = lo.min(l);
            hi = hi.max(h);
        }
        let me = nodes.len();
        // The union of `f32` boxes is exactly representable.
        let (flo, fhi) = round_outward_f32(lo, hi);
        nodes.push(Node {
            lo: flo,
            hi: fhi,
            first: first as u32,
            count: items.len() as u32,
        });
        let split = if depth >= MAX_DEPTH {
            None
        } else {
            self.split(items, depth, half_area(lo, hi))
        };
        if let Some(mid) = split {
            let (left, right) = items.split_at_mut(mid);
            self.node(nodes, left, first, depth + 1);
            let second = self.node(nodes, right, first + mid, depth + 1);
            nodes[me].first = second;
            nodes[me].count = 0;
        }
        me as u32
    }

    /// Where to split `items` (after reordering them), or `None` for a leaf.
    fn split(&self, items: &mut [u32], depth: usize, area: f64) -> Option<usize> {
        let n = items.len();
        if n <= MIN_LEAF {
            return None;
        }
        let (mut clo, mut chi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &i in items.iter() {
            let c = self.centre(i);
            clo = clo.min(c);
            chi = chi.max(c);
        }
        let extent = chi - clo;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        if !(extent[axis] > 0.0) {
            // Every centre in one place: split by count if a leaf would be
            // too big.
            return (n > MAX_LEAF).then_some(n / 2);
        }
        if depth >= SAH_DEPTH {
            return Some(self.median(items, axis));
        }
        // Binned SAH along the widest axis of the centres.
        let scale = BINS as f64 / extent[axis];
        let bin = |i: u32| (((self.centre(i)[axis] - clo[axis]) * scale) as usize).min(BINS - 1);
        let mut counts = [0usize; BINS];
        let mut bounds = [(DVec3::INFINITY, DVec3::NEG_INFINITY); BINS];
        for &i in items.iter() {
            let b = bin(i);
            let (l, h) = self.bounds(i);
            counts[b] += 1;
            bounds[b] = (bounds[b].0.min(l), bounds[b].1.max(h));
        }
        // Cost of a split after bin k: area-weighted counts of both sides.
        let mut right_cost = [0.0f64; BINS];
        let (mut lo, mut hi, mut count) = (DVec3::INFINITY, DVec3::NEG_INFINITY, 0usize);
        for k in (1..BINS).rev() {
            lo = lo.min(bounds[k].0);
            hi = hi.max(bounds[k].1);
            count += counts[k];
            right_cost[k] = half_area(lo, hi) * count as f64;
        }
        let (mut lo, mut hi, mut count) = (DVec3::INFINITY, DVec3::NEG_INFINITY, 0usize);
        let mut best: Option<(f64, usize)> = None;
        for k in 0..BINS - 1 {
            lo = lo.min(bounds[k].0);
            hi = hi.max(bounds[k].1);
            count += counts[k];
            if count == 0 || count == n {
                continue;
            }
            let cost = half_area(lo, hi) * count as f64 + right_cost[k + 1];
            if best.is_none_or(|(c, _)| cost < c) {
                best = Some((cost, k));
            }
        }
        let Some((cost, k)) = best else {
            return Some(self.median(items, axis));
        };
        // A node costs about one triangle test; keep small sets as leaves
        // when splitting does not pay.
        if n <= MAX_LEAF && area + cost >= area * n as f64 {
            return None;
        }
        // Partition: bins up to k go first.
        let mut mid = 0;
        for j in 0..n {
            if bin(items[j]) <= k {
                items.swap(mid, j);
                mid += 1;
            }
        }
        if mid == 0 || mid == n {
            return Some(self.median(items, axis));
        }
        Some(mid)
    }

    /// Split at the median centre along `axis`.
    fn median(&self, items: &mut [u32], axis: usize) -> usize {
        let mid = items.len() / 2;
        items.select_nth_unstable_by(mid, |a, b| {
            self.centre(*a)[axis].total_cmp(&self.centre(*b)[axis])
        });
        mid
    }
}
