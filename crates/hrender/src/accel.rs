//! The scene's one acceleration structure: a bounding-volume hierarchy of
//! axis-aligned boxes in the Klein model over every bounded surface (each
//! part of a composite is a surface of its own), plus the short list of
//! unbounded surfaces every ray tests.
//!
//! In the Klein model every ray is a straight chord and every bounded
//! surface has an exact box ([`hgeom::KleinBox`]), so this is the standard
//! machinery of Euclidean tracers: a binned surface-area-heuristic build
//! ([`build`]) collapsed into four-wide nodes ([`wide`]), boxes stored in
//! `f32` rounded outwards (half the memory traffic of `f64`, never smaller
//! than the `f64` box), the slab test in four `f32` lanes widened by more
//! than its rounding ([`chord32`]), nearest-first traversal ordered by the
//! chord parameter `λ` (which increases with hyperbolic distance along the
//! ray), and any-hit traversal for shadow rays. Exactness stays with the
//! leaves: every box test is conservative, and the exact `f64` intersection
//! decides.

/// `$body` with `$o` a constant: the chord octant `$octant` (0 to 7), so
/// that a traversal generic over it is compiled once per octant
/// (`WideNode::entries`) and chosen once per ray.
macro_rules! by_octant {
    ($octant:expr, $o:ident => $body:expr) => {
        by_octant!(@arms $octant, $o, $body, 0 1 2 3 4 5 6)
    };
    (@arms $octant:expr, $o:ident, $body:expr, $($n:literal)*) => {
        match $octant {
            $($n => {
                const $o: usize = $n;
                $body
            })*
            _ => {
                const $o: usize = 7;
                $body
            }
        }
    };
}

mod build;
mod chord32;
mod stack;
mod wide;

use hgeom::{Hit, KleinRay, Ray};

pub use build::Leaf;
use chord32::Chord32;
use stack::Stack;
use wide::{WIDTH, WideNode};

/// What a visit asks the traversal to do next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Keep going.
    Continue,
    /// Stop the traversal (a shadow ray found an opaque blocker).
    Stop,
}

/// The hierarchy over items `0..n` and the items without a box.
#[derive(Clone, Debug, Default)]
pub struct Accel {
    nodes: Vec<WideNode>,
    /// Leaf contents, in node order.
    items: Vec<u32>,
    /// Items every ray tests: those without a box, and all of them when
    /// there are too few for a hierarchy to pay.
    direct: Vec<u32>,
}

/// At most this many leaves are tested directly, without a hierarchy.
const DIRECT_LEAVES: usize = 2;

/// The deepest a hierarchy may be: the build stops splitting there (the
/// binned build halves the item count at least every few levels, so real
/// scenes stay far below), which bounds the build's recursion.
const MAX_DEPTH: usize = 60;

impl Accel {
    /// From leaves: each a box and the item it bounds (an item may have
    /// several boxes; its exact test then runs at most once per box the ray
    /// enters, which is harmless: a repeated test finds nothing nearer), and
    /// the items with no box at all.
    pub fn new(leaves: Vec<Leaf>, mut unbounded: Vec<u32>) -> Accel {
        if leaves.len() <= DIRECT_LEAVES || leaves.len() >= wide::MAX_LEAVES {
            // Culling a ray against so few boxes costs more than it saves
            // (the chord's set-up alone is six divisions): test directly.
            // Past `MAX_LEAVES` the nodes could not name the items.
            let mut items: Vec<u32> = leaves.iter().map(Leaf::item).collect();
            items.dedup();
            unbounded.extend(items);
            return Accel {
                nodes: Vec::new(),
                items: Vec::new(),
                direct: unbounded,
            };
        }
        let (binary, items) = build::build(leaves);
        Accel {
            nodes: wide::collapse(&binary),
            items,
            direct: unbounded,
        }
    }

    /// The nearest hit among the items on the ray's arc `(t_min, t_max)`:
    /// `test(item, t_min, t_max)` is the item's exact test, called with the
    /// nearest hit so far as `t_max`.
    #[inline]
    pub fn nearest(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        mut test: impl FnMut(u32, f64, f64) -> Option<Hit>,
    ) -> Option<(Hit, u32)> {
        let mut best = None;
        let mut limit = t_max;
        for &i in &self.direct {
            if let Some(hit) = test(i, t_min, limit) {
                limit = hit.t;
                best = Some((hit, i));
            }
        }
        if self.nodes.is_empty() {
            return best;
        }
        let chord = KleinRay::new(ray);
        if !chord.is_finite() {
            // No chord to cull with: every item gets its exact test.
            for i in self.items.iter().copied() {
                if let Some(hit) = test(i, t_min, limit) {
                    limit = hit.t;
                    best = Some((hit, i));
                }
            }
            return best;
        }
        let (lo, hi) = chord.arc(t_min, limit);
        let c32 = Chord32::new(&chord);
        let search = Search {
            chord: &chord,
            c32: &c32,
            lo: c32.lambda_below(lo),
            hi: c32.lambda_above(hi),
            t_min,
            limit,
        };
        // One copy of the traversal per octant of the chord's direction.
        by_octant!(c32.octant(), O => self.nearest_in::<O>(search, best, test))
    }

    /// [`Accel::nearest`]'s traversal for a chord in `OCTANT`, from the
    /// hit `best` found in the direct list.
    #[inline(always)]
    fn nearest_in<const OCTANT: usize>(
        &self,
        search: Search<'_>,
        mut best: Option<(Hit, u32)>,
        mut test: impl FnMut(u32, f64, f64) -> Option<Hit>,
    ) -> Option<(Hit, u32)> {
        let Search {
            chord,
            c32,
            lo,
            mut hi,
            t_min,
            mut limit,
        } = search;
        let mut stack = Stack::with((0u32, lo));
        let mut last = u32::MAX;
        while let Some((mut n, enter)) = stack.pop() {
            if enter > hi {
                continue;
            }
            // Down the tree: leaves entered are tested at once; of the inner
            // children entered, the nearest is visited next and the others
            // wait on the stack, the farthest lowest.
            loop {
                let node = &self.nodes[n as usize];
                let (leaves, inner, entries) = node.entries::<OCTANT>(c32, lo, hi);
                for k in lanes(leaves) {
                    if entries[k] > hi {
                        continue;
                    }
                    for &i in node.items(k, &self.items) {
                        // Consecutive boxes of one item (a rod's pieces)
                        // need one exact test.
                        if i == last {
                            continue;
                        }
                        last = i;
                        if let Some(hit) = test(i, t_min, limit) {
                            limit = hit.t;
                            hi = c32.lambda_above(chord.arc_end_at(hit.point));
                            best = Some((hit, i));
                        }
                    }
                }
                if inner == 0 {
                    break;
                }
                let first = inner.trailing_zeros() as usize;
                let rest = inner & (inner - 1);
                if rest == 0 {
                    // A leaf above may have brought the end of the arc
                    // before this child's box.
                    if entries[first] > hi {
                        break;
                    }
                    n = node.child[first];
                    continue;
                }
                // Two or more: sort them (at most four) by entry.
                let mut order = [(0u32, 0f32); WIDTH];
                let mut count = 0;
                for k in lanes(inner) {
                    let e = entries[k];
                    let mut j = count;
                    while j > 0 && order[j - 1].1 < e {
                        order[j] = order[j - 1];
                        j -= 1;
                    }
                    order[j] = (node.child[k], e);
                    count += 1;
                }
                // `order` is farthest first: all but the nearest wait.
                for &p in &order[..count - 1] {
                    stack.push(p);
                }
                let (nearest, entry) = order[count - 1];
                if entry > hi {
                    break;
                }
                n = nearest;
            }
        }
        best
    }

    /// Visit every item that may meet the ray's arc `(t_min, t_max)`, in no
    /// particular order, until `visit` says stop. The arc's end is given as
    /// `tanh(t_max)` (1 for the absolute): culling needs nothing else, and
    /// a shadow ray knows it without computing a hyperbolic tangent.
    #[inline]
    pub fn any(&self, ray: &Ray, t_min: f64, tanh_t_max: f64, mut visit: impl FnMut(u32) -> Step) {
        for &i in &self.direct {
            if visit(i) == Step::Stop {
                return;
            }
        }
        if self.nodes.is_empty() {
            return;
        }
        let chord = KleinRay::new(ray);
        if !chord.is_finite() {
            for i in self.items.iter().copied() {
                if visit(i) == Step::Stop {
                    return;
                }
            }
            return;
        }
        let (lo, hi) = chord.arc_to_tanh(t_min, tanh_t_max);
        let c32 = Chord32::new(&chord);
        let (lo, hi) = (c32.lambda_below(lo), c32.lambda_above(hi));
        by_octant!(c32.octant(), O => self.any_in::<O>(&c32, lo, hi, visit))
    }

    /// [`Accel::any`]'s traversal for a chord in `OCTANT` over `[lo, hi]`.
    #[inline(always)]
    fn any_in<const OCTANT: usize>(
        &self,
        c32: &Chord32,
        lo: f32,
        hi: f32,
        mut visit: impl FnMut(u32) -> Step,
    ) {
        let mut stack = Stack::with(0u32);
        let mut last = u32::MAX;
        while let Some(mut n) = stack.pop() {
            loop {
                let node = &self.nodes[n as usize];
                let (leaves, inner, _) = node.entries::<OCTANT>(c32, lo, hi);
                for k in lanes(leaves) {
                    for &i in node.items(k, &self.items) {
                        if i == last {
                            continue;
                        }
                        last = i;
                        if visit(i) == Step::Stop {
                            return;
                        }
                    }
                }
                let mut inner = lanes(inner).map(|k| node.child[k]);
                let Some(next) = inner.next() else {
                    break;
                };
                n = next;
                for child in inner {
                    stack.push(child);
                }
            }
        }
    }
}

/// A ray's chord and the part of it a nearest-hit search covers: `lo` to
/// `hi` in the `f32` chord's units, `t_min` to `limit` in arc length.
#[derive(Clone, Copy)]
struct Search<'a> {
    chord: &'a KleinRay,
    c32: &'a Chord32,
    lo: f32,
    hi: f32,
    t_min: f64,
    limit: f64,
}

/// The lanes whose bits are set in `mask`, lowest first.
#[inline(always)]
fn lanes(mut mask: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (mask != 0).then(|| {
            let k = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            k
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;
    use hgeom::{HSphere, Point, Shape};

    /// Random small spheres: the hierarchy's nearest hit equals the
    /// exhaustive search's, and its any-hit visits every sphere the ray
    /// meets.
    #[test]
    fn hierarchy_agrees_with_exhaustive_search() {
        let mut state = 7u64;
        let mut rnd = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64) / ((1u64 << 53) as f64) * 2.0 - 1.0
        };
        let mut spheres = Vec::new();
        while spheres.len() < 500 {
            let c = DVec3::new(rnd(), rnd(), rnd()) * 0.9;
            if c.length() < 0.9 {
                spheres.push(
                    HSphere::new(Point::from_coords(c).unwrap(), 0.02 + 0.1 * rnd().abs()).unwrap(),
                );
            }
        }
        let leaves: Vec<Leaf> = spheres
            .iter()
            .enumerate()
            .flat_map(|(i, s)| {
                s.klein_boxes()
                    .into_iter()
                    .map(move |b| Leaf::new(b, i as u32))
            })
            .collect();
        let accel = Accel::new(leaves, Vec::new());
        let mut hits = 0;
        for k in 0..3000 {
            let dir = DVec3::new(rnd(), rnd(), rnd());
            let start = Point::from_coords(DVec3::new(rnd(), rnd(), rnd()) * 0.3).unwrap();
            let ray = Ray::from_ball_unchecked(&start, dir);
            let exhaustive = spheres
                .iter()
                .enumerate()
                .filter_map(|(i, s)| s.intersect(&ray, 1e-9, f64::INFINITY).map(|h| (h.t, i)))
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let found = accel
                .nearest(&ray, 1e-9, f64::INFINITY, |i, lo, hi| {
                    spheres[i as usize].intersect(&ray, lo, hi)
                })
                .map(|(h, i)| (h.t, i as usize));
            assert_eq!(found, exhaustive, "ray {k}");
            if let Some((t, _)) = exhaustive {
                hits += 1;
                let mut seen = vec![false; spheres.len()];
                accel.any(&ray, 1e-9, (t * 2.0).tanh(), |i| {
                    seen[i as usize] = true;
                    Step::Continue
                });
                for (i, s) in spheres.iter().enumerate() {
                    if s.blocks(&ray, 1e-9, t * 2.0) {
                        assert!(seen[i], "ray {k}: any-hit skipped sphere {i}");
                    }
                }
            }
        }
        assert!(hits > 500, "{hits}");
    }
}
