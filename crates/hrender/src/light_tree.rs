//! A bounding-ball hierarchy over the light units, so that drawing one unit
//! at a vertex costs the depth of the tree, not the number of lights
//! (docs/rendering.md, "Light selection"; the idea of pbrt-v4's
//! `BVHLightSampler` and of Cycles' light tree, with H³'s fall-off and
//! balls for bounds).
//!
//! It holds the triangles of one emissive mesh: close together, so that
//! balls bound them tightly (`light_select.rs` says why lights far apart
//! are not put under one).
//!
//! **Shape.** Units are split at the median of their centres' Klein
//! coordinates along the widest axis until at most [`MAX_LEAF`] remain: a
//! leaf is drawn from by each unit's own importance, as the selector's
//! linear pass draws.
//!
//! **Descending.** Each inner node has a ball `B(c, R)` holding its units'
//! balls and their total *power* (what a unit's importance is over its
//! fall-off: `|Φ|/4` for a point, `π |L| sinh² a` for a sphere, `|L| A`
//! for a patch). A child's importance at a point `p` with normal `n` is
//! its power over `sinh²(d - R)` (`d` the distance to `c`: none of its
//! units is nearer than `d - R`), at most the sum of its units' largest
//! importances (`π |L|` for a sphere, `2π |L|` for a patch, a point's at
//! its `near` distance), so a node that holds `p` gets that sum: an upper
//! bound, as each unit's own is. (In H³'s exponential fall-off a looser
//! guess for the inside, pbrt's distance clamped to half the box, starves
//! the units nearest `p`.) It is scaled by roughly the share of the ball
//! above the tangent plane: a branch mostly below it holds units that
//! mostly cannot light `p` (without the scale, four draws in ten at a mesh
//! straddling the plane ended in a leaf with nothing to draw).
//!
//! It is 0 only when the ball lies wholly below the tangent plane, or
//! when even its nearest possible unit lies beyond the farthest reach of
//! its units (a point light's images in a quotient space light only within
//! their reach): then none of its units can light `p`. So every unit that
//! can bring light keeps a positive probability, the condition for an
//! unbiased estimate. The draw goes down one child in proportion to the
//! two importances, the uniform number rescaled at each step; the
//! probability of a unit is the product of the steps' and the leaf's.

use hgeom::glam::DVec4;
use hgeom::lorentz;

/// The most units of a leaf.
pub const MAX_LEAF: usize = 8;

/// The smallest `sinh` of a distance a node's importance divides by.
const MIN_SINH: f64 = 1e-3;

/// The first item whose running sum of weights exceeds `target` (a
/// uniform number times their total): with its weight and the running sum
/// through it. Items of weight 0 are never drawn; rounding may leave
/// `target` at or past the whole sum, and then the last item with any
/// weight takes it. The selector's pass over its groups and a leaf's over
/// its units both draw with it.
pub(crate) fn draw_by_weight<T>(
    items: impl IntoIterator<Item = (T, f64)>,
    target: f64,
) -> Option<(T, f64, f64)> {
    let mut sum = 0.0;
    let mut last = None;
    for (item, w) in items {
        if w > 0.0 {
            sum += w;
            last = Some((item, w));
            if target < sum {
                break;
            }
        }
    }
    last.map(|(item, w)| (item, w, sum))
}

/// The bounding ball and power of one unit, as the tree is built from.
#[derive(Clone, Copy, Debug)]
pub struct UnitBound {
    /// The ball's centre, on the hyperboloid.
    pub centre: DVec4,
    /// The ball's radius.
    pub radius: f64,
    /// Its importance times its fall-off (module docs).
    pub power: f64,
    /// The most importance it can have anywhere.
    pub cap: f64,
    /// `sinh` of the distance beyond which it lights nothing (a point
    /// light's image in a quotient space); infinite for the rest.
    pub sinh_reach: f64,
}

#[derive(Clone, Copy, Debug)]
enum Kind {
    Inner { left: u32, right: u32 },
    Leaf { first: u32, len: u32 },
}

#[derive(Clone, Copy, Debug)]
struct Node {
    centre: DVec4,
    cosh_r: f64,
    sinh_r: f64,
    power: f64,
    /// The sum of the units' caps.
    cap: f64,
    /// The largest of the units' `sinh_reach`.
    sinh_reach: f64,
    parent: u32,
    kind: Kind,
}

/// The hierarchy (module docs). Node 0 is the root.
#[derive(Clone, Debug, Default)]
pub struct LightTree {
    nodes: Vec<Node>,
    /// The units in leaf order (the selector's indices): a leaf holds
    /// `order[first..first + len]`.
    order: Vec<u32>,
    /// The leaf of each unit, from the first unit's index on.
    leaf_of: Vec<u32>,
    /// The selector's index of the first unit.
    offset: usize,
}

/// A node's ball: the normalised sum of the centres (a timelike vector:
/// future points add up to one), through the farthest unit ball.
fn bound(units: &[UnitBound], members: &[u32]) -> (DVec4, f64, f64, f64, f64) {
    let sum = members
        .iter()
        .fold(DVec4::ZERO, |s, &k| s + units[k as usize].centre);
    let centre = sum / (-lorentz::dot(sum, sum)).sqrt();
    let radius = members
        .iter()
        .map(|&k| lorentz::distance(centre, units[k as usize].centre) + units[k as usize].radius)
        .fold(0.0, f64::max);
    let power = members.iter().map(|&k| units[k as usize].power).sum();
    let cap = members.iter().map(|&k| units[k as usize].cap).sum();
    let reach = members
        .iter()
        .map(|&k| units[k as usize].sinh_reach)
        .fold(0.0, f64::max);
    (centre, radius, power, cap, reach)
}

impl LightTree {
    /// The tree over `units`, the selector's units from index `offset` on.
    pub fn build(units: &[UnitBound], offset: usize) -> LightTree {
        let mut tree = LightTree {
            nodes: Vec::new(),
            order: (0..units.len() as u32).collect(),
            leaf_of: vec![0; units.len()],
            offset,
        };
        if !units.is_empty() {
            tree.split(units, 0, units.len(), u32::MAX);
        }
        tree
    }

    /// Adds the node over `order[first..first + len]` and its subtree;
    /// returns its index.
    fn split(&mut self, units: &[UnitBound], first: usize, len: usize, parent: u32) -> u32 {
        let members = &mut self.order[first..first + len];
        let (centre, radius, power, cap, sinh_reach) = bound(units, members);
        let index = self.nodes.len() as u32;
        self.nodes.push(Node {
            centre,
            cosh_r: radius.cosh(),
            sinh_r: radius.sinh(),
            power,
            cap,
            sinh_reach,
            parent,
            kind: Kind::Leaf {
                first: first as u32,
                len: len as u32,
            },
        });
        if len <= MAX_LEAF {
            for &k in &self.order[first..first + len] {
                self.leaf_of[k as usize] = index;
            }
            return index;
        }
        // The widest axis of the centres in Klein coordinates, and its
        // median.
        let klein = |k: u32| {
            let c = units[k as usize].centre;
            c.truncate() / c.w
        };
        let (lo, hi) = members.iter().fold(
            (
                hgeom::glam::DVec3::splat(f64::INFINITY),
                hgeom::glam::DVec3::splat(f64::NEG_INFINITY),
            ),
            |(lo, hi), &k| (lo.min(klein(k)), hi.max(klein(k))),
        );
        let extent = hi - lo;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        let half = len / 2;
        members.select_nth_unstable_by(half, |&a, &b| klein(a)[axis].total_cmp(&klein(b)[axis]));
        let left = self.split(units, first, half, index);
        let right = self.split(units, first + half, len - half, index);
        self.nodes[index as usize].kind = Kind::Inner { left, right };
        index
    }

    /// What the whole tree can bring to `p` with normal `n`.
    #[inline]
    pub fn root_importance(&self, p: DVec4, n: DVec4) -> f64 {
        if self.nodes.is_empty() {
            return 0.0;
        }
        self.importance(0, p, n)
    }

    /// What node `i` can bring to `p` with normal `n` (module docs).
    #[inline]
    fn importance(&self, i: u32, p: DVec4, n: DVec4) -> f64 {
        let node = &self.nodes[i as usize];
        let cosh_d = -lorentz::dot(p, node.centre);
        let height = lorentz::dot(node.centre, n);
        let floor = -node.sinh_r * (1.0 + 1e-9) - 1e-12 * cosh_d;
        if height < floor {
            return 0.0;
        }
        // The share of the ball above the tangent plane, roughly: 1 when
        // the centre is `sinh R` above it, falling to a sliver where only a
        // cap pokes out (never 0 there: its units may light `p`).
        let above = if node.sinh_r > 0.0 {
            ((height - floor) / (2.0 * node.sinh_r)).clamp(1e-3, 1.0)
        } else {
            1.0
        };
        let sinh_d = (cosh_d * cosh_d - 1.0).max(0.0).sqrt();
        // sinh(d - R), negative inside the ball; past every unit's reach
        // nothing of the node lights `p`.
        let s = sinh_d * node.cosh_r - cosh_d * node.sinh_r;
        if s > node.sinh_reach {
            return 0.0;
        }
        let s = s.max(MIN_SINH);
        above * (node.power / (s * s)).min(node.cap)
    }

    /// One unit drawn with the uniform `u` at `p` (normal `n`), and its
    /// probability; `unit(k)` is unit `k`'s own importance there. `None`
    /// when the branch taken holds no unit that can contribute.
    pub fn select(
        &self,
        p: DVec4,
        n: DVec4,
        u: f64,
        unit: impl Fn(usize) -> f64,
    ) -> Option<(usize, f64)> {
        let mut node = 0u32;
        let mut pmf = 1.0;
        let mut u = u;
        loop {
            match self.nodes.get(node as usize)?.kind {
                Kind::Inner { left, right } => {
                    let (a, b) = (self.importance(left, p, n), self.importance(right, p, n));
                    let sum = a + b;
                    if !(sum > 0.0 && sum.is_finite()) {
                        return None;
                    }
                    let pa = a / sum;
                    if u < pa {
                        u /= pa;
                        pmf *= pa;
                        node = left;
                    } else {
                        let pb = b / sum;
                        u = (u - pa) / pb;
                        pmf *= pb;
                        node = right;
                    }
                    // Rescaling may round up to 1; the draw below needs
                    // `u < 1`.
                    u = u.min(1.0 - f64::EPSILON);
                }
                Kind::Leaf { first, len } => {
                    let members = &self.order[first as usize..(first + len) as usize];
                    let unit = |k: u32| unit(k as usize + self.offset);
                    let total: f64 = members.iter().map(|&k| unit(k)).sum();
                    if !(total > 0.0 && total.is_finite()) {
                        return None;
                    }
                    let (k, w, _) =
                        draw_by_weight(members.iter().map(|&k| (k, unit(k))), u * total)?;
                    let k = k as usize + self.offset;
                    return Some((k, pmf * (w / total)));
                }
            }
        }
    }

    /// The probability that [`LightTree::select`] draws unit `k` at `p`.
    pub fn pmf(&self, k: usize, p: DVec4, n: DVec4, unit: impl Fn(usize) -> f64) -> f64 {
        let Some(&leaf) = k.checked_sub(self.offset).and_then(|j| self.leaf_of.get(j)) else {
            return 0.0;
        };
        let w = unit(k);
        if !(w > 0.0) {
            return 0.0;
        }
        let Kind::Leaf { first, len } = self.nodes[leaf as usize].kind else {
            return 0.0;
        };
        let total: f64 = self.order[first as usize..(first + len) as usize]
            .iter()
            .map(|&j| unit(j as usize + self.offset))
            .sum();
        if !(total > 0.0 && total.is_finite()) {
            return 0.0;
        }
        let mut pmf = w / total;
        let mut node = leaf;
        while let Some(parent) = self.nodes.get(self.nodes[node as usize].parent as usize) {
            let Kind::Inner { left, right } = parent.kind else {
                return 0.0;
            };
            let (a, b) = (self.importance(left, p, n), self.importance(right, p, n));
            let sum = a + b;
            if !(sum > 0.0 && sum.is_finite()) {
                return 0.0;
            }
            pmf *= if node == left { a / sum } else { b / sum };
            node = self.nodes[node as usize].parent;
        }
        pmf
    }
}
