//! Bounding h-spheres and a bounding-volume hierarchy built from them.
//!
//! The thesis (§10.2) says the Poincaré model prevents bounding volumes; it
//! does not: an h-ball is convex, the ball about a set of points contains
//! their convex hull (so every convex polygon and every segment between its
//! points), and a ray meets a ball where a quadratic in `u = e^t` has a root,
//! the same closed form as the exact sphere test without the logarithms.
//!
//! Every test here is *conservative*: it may say "maybe" for a ray that
//! misses, never "no" for a ray that hits, and a NaN anywhere answers
//! "maybe", so the exact test downstream sees the ray and reports the
//! numeric failure instead of a bound hiding it.

use hgeom::Ray;
use hgeom::glam::{DVec3, DVec4};
use hgeom::lorentz;

/// Relative slack of every bound test: far above the rounding of the
/// quantities involved (a few ulps of `a + |b|`), far below anything that
/// would make culling less effective.
const SLACK: f64 = 1e-9;

/// A closed h-ball, on the hyperboloid: `{X : -<X,C> <= cosh r}`.
///
/// Invariants: `center` is on the hyperboloid (future, `<C,C> = -1` to
/// rounding), `radius >= 0`, both finite, `cosh_r = cosh radius`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bound {
    center: DVec4,
    radius: f64,
    cosh_r: f64,
}

impl Bound {
    /// The ball of `radius` about `center`; `None` unless both are finite
    /// (an unbounded primitive is then tested without a bound).
    pub fn new(center: DVec4, radius: f64) -> Option<Bound> {
        let cosh_r = radius.cosh();
        (center.is_finite() && center.w > 0.0 && radius >= 0.0 && cosh_r.is_finite()).then_some(
            Bound {
                center,
                radius,
                cosh_r,
            },
        )
    }

    /// True if the hyperboloid point lies in the ball, to a relative
    /// tolerance on `cosh r`.
    #[cfg(test)]
    pub fn contains(&self, x: DVec4, tolerance: f64) -> bool {
        -lorentz::dot(x, self.center) <= self.cosh_r * (1.0 + tolerance)
    }

    /// The smallest ball containing both.
    ///
    /// With `d` the distance between the centres: if one ball contains the
    /// other, that one; otherwise the ball of radius `(d + r1 + r2)/2`
    /// centred on the segment between the centres, at `R - r1` from the
    /// first (it touches both balls' far sides).
    pub fn union(&self, other: &Bound) -> Bound {
        let d = lorentz::distance(self.center, other.center);
        if d + other.radius <= self.radius {
            return *self;
        }
        if d + self.radius <= other.radius {
            return *other;
        }
        let big = 0.5 * (d + self.radius + other.radius);
        let Some(towards) = lorentz::unit_tangent_towards(self.center, other.center) else {
            // Coincident centres: the larger ball contains both.
            return if self.radius >= other.radius {
                *self
            } else {
                *other
            };
        };
        let center = lorentz::geodesic_point(self.center, towards, big - self.radius);
        // The new centre is a rounded point: pad by the rounding of its
        // distances so the children stay inside.
        let radius = big * (1.0 + SLACK) + SLACK;
        Bound::new(center, radius).unwrap_or(Bound {
            // Unreachable for finite children; keep a valid, larger ball.
            center: self.center,
            radius: d + other.radius + self.radius,
            cosh_r: (d + other.radius + self.radius).cosh(),
        })
    }

    /// A key for sorting bounds in space: the centre's Klein coordinates
    /// (geodesics are straight there, so a median split along one axis
    /// separates the centres by an h-plane).
    fn key(&self) -> DVec3 {
        self.center.truncate() / self.center.w
    }

    /// Whether the ray's arc `u_min < e^t < u_max` may meet the ball; if so,
    /// an estimate of `e^t` where it enters (for front-to-back ordering).
    ///
    /// Along the ray `-<X(t),C> = a cosh t + b sinh t`; the ball is where
    /// this is `<= cosh r`, i.e. between the roots `u1 <= u2` of
    /// `(a+b) u^2 - 2 cosh(r) u + (a-b) = 0`. The ray misses if the
    /// discriminant is negative or `[u1, u2]` does not overlap the arc.
    #[inline]
    pub fn entry(&self, ray: &Ray, u_min: f64, u_max: f64) -> Option<f64> {
        let a = -lorentz::dot(ray.origin, self.center);
        let b = -lorentz::dot(ray.dir, self.center);
        let k = self.cosh_r + SLACK * (self.cosh_r + a + b.abs());
        let disc = k * k - (a + b) * (a - b);
        if disc < 0.0 {
            return None;
        }
        let big = k + disc.max(0.0).sqrt();
        // u2 = big / (a + b) <= u_min: the ball lies behind the arc's start.
        if big <= u_min * (a + b) {
            return None;
        }
        // u1 = (a - b) / big >= u_max: the ball lies beyond the arc's end.
        let u1 = (a - b) / big;
        if u1 >= u_max {
            return None;
        }
        // NaN lands here too, as "maybe", entered at once.
        Some(if u1 >= 0.0 { u1 } else { 0.0 })
    }
}

/// What a leaf visit asks the traversal to do next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Keep going.
    Continue,
    /// Stop the traversal (a shadow ray found an opaque blocker).
    Stop,
}

/// A node: a bound, and either two children or one item.
#[derive(Clone, Copy, Debug)]
struct Node {
    bound: Bound,
    /// First child, or the item for a leaf.
    left: u32,
    /// Second child, or `LEAF` for a leaf.
    right: u32,
}

const LEAF: u32 = u32::MAX;

/// A binary hierarchy of bounds over items `0..n`, one item per leaf.
///
/// Built top-down by median splits of the bound centres (Klein
/// coordinates) along the axis of largest spread; every inner node's
/// bound is the union of its children's, so a ray that misses a node
/// misses everything below it.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
}

impl Bvh {
    /// Build over `(item, bound)` pairs.
    pub fn build(items: &[(u32, Bound)]) -> Bvh {
        let mut work: Vec<(u32, Bound, DVec3)> =
            items.iter().map(|(i, b)| (*i, *b, b.key())).collect();
        let mut nodes = Vec::with_capacity(2 * items.len());
        if !work.is_empty() {
            build_into(&mut nodes, &mut work);
        }
        Bvh { nodes }
    }

    /// The root's bound: a ball around every item.
    pub fn bound(&self) -> Option<Bound> {
        self.nodes.first().map(|n| n.bound)
    }

    /// True if there are no items.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Visit, front to back as far as the bounds tell, every item whose
    /// bound may meet the ray's arc `u_min < e^t < *u_max`. `leaf` gets the
    /// item and may shrink `*u_max` (a nearer hit was found) or stop.
    #[inline]
    pub fn traverse(
        &self,
        ray: &Ray,
        u_min: f64,
        u_max: &mut f64,
        mut leaf: impl FnMut(u32, &mut f64) -> Step,
    ) {
        let Some(root) = self.nodes.first() else {
            return;
        };
        if root.bound.entry(ray, u_min, *u_max).is_none() {
            return;
        }
        // Depth of a median-split tree is log2(n) + 1; 64 levels hold any
        // item count that fits in memory.
        let mut stack = [0u32; 64];
        let mut top = 1usize;
        while top > 0 {
            top -= 1;
            let node = self.nodes[stack[top] as usize];
            if node.right == LEAF {
                if leaf(node.left, u_max) == Step::Stop {
                    return;
                }
                continue;
            }
            let l = self.nodes[node.left as usize]
                .bound
                .entry(ray, u_min, *u_max);
            let r = self.nodes[node.right as usize]
                .bound
                .entry(ray, u_min, *u_max);
            // Push the farther child first so the nearer one is popped
            // first and can shrink the arc for the other.
            match (l, r) {
                (Some(el), Some(er)) => {
                    let (near, far) = if el <= er {
                        (node.left, node.right)
                    } else {
                        (node.right, node.left)
                    };
                    stack[top] = far;
                    stack[top + 1] = near;
                    top += 2;
                }
                (Some(_), None) => {
                    stack[top] = node.left;
                    top += 1;
                }
                (None, Some(_)) => {
                    stack[top] = node.right;
                    top += 1;
                }
                (None, None) => {}
            }
        }
    }
}

fn build_into(nodes: &mut Vec<Node>, work: &mut [(u32, Bound, DVec3)]) -> u32 {
    let index = nodes.len() as u32;
    if let [(item, bound, _)] = work {
        nodes.push(Node {
            bound: *bound,
            left: *item,
            right: LEAF,
        });
        return index;
    }
    // Reserve this node; fill it once the children are known.
    nodes.push(Node {
        bound: work[0].1,
        left: 0,
        right: 0,
    });
    let (lo, hi) = work.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), (_, _, k)| (lo.min(*k), hi.max(*k)),
    );
    let extent = hi - lo;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = work.len() / 2;
    work.select_nth_unstable_by(mid, |a, b| a.2[axis].total_cmp(&b.2[axis]));
    let (left_items, right_items) = work.split_at_mut(mid);
    let left = build_into(nodes, left_items);
    let right = build_into(nodes, right_items);
    let bound = nodes[left as usize]
        .bound
        .union(&nodes[right as usize].bound);
    nodes[index as usize] = Node { bound, left, right };
    index
}

#[cfg(test)]
mod tests {
    use super::*;

    fn around(points: &[DVec4]) -> Bound {
        let ball = hgeom::BoundingBall::around(points, 0.0).unwrap();
        Bound::new(ball.center(), ball.radius()).unwrap()
    }
    use hgeom::Point;

    fn h(x: f64, y: f64, z: f64) -> DVec4 {
        Point::from_coords(DVec3::new(x, y, z))
            .unwrap()
            .to_hyperboloid()
    }

    #[test]
    fn around_contains_its_points_and_union_contains_both() {
        let pts = [h(0.1, 0.2, 0.3), h(-0.4, 0.1, 0.5), h(0.2, -0.6, 0.1)];
        let b = around(&pts);
        for x in pts {
            assert!(lorentz::distance(b.center, x) <= b.radius * (1.0 + 1e-12));
        }
        let other = Bound::new(h(0.7, 0.0, 0.0), 0.3).unwrap();
        let u = b.union(&other);
        for (c, r) in [(b.center, b.radius), (other.center, other.radius)] {
            assert!(lorentz::distance(u.center, c) + r <= u.radius * (1.0 + 1e-12));
        }
        // Two points: the centre is the midpoint.
        let two = around(&[h(0.5, 0.0, 0.0), h(-0.5, 0.0, 0.0)]);
        assert!((two.center - DVec4::W).length() < 1e-15);
    }

    #[test]
    fn entry_agrees_with_the_exact_sphere_test() {
        let c = Point::from_coords(DVec3::new(0.2, -0.1, 0.5)).unwrap();
        let sphere = hgeom::HSphere::new(c, 0.3).unwrap();
        let bound = Bound::new(c.to_hyperboloid(), 0.3).unwrap();
        for i in 0..200 {
            let a = i as f64 * 0.618_033_988_749_895;
            let ray = Ray::from_origin_unchecked(DVec3::new(0.8 * a.sin(), 0.8 * a.cos(), 1.0));
            for t_max in [f64::INFINITY, 0.5, 1.0] {
                let exact = sphere.intersect(&ray, 0.0, t_max).is_some();
                let maybe = bound.entry(&ray, 1.0, t_max.exp()).is_some();
                assert!(maybe || !exact, "bound culled a hit");
            }
        }
        // A ray away from the ball is culled.
        assert!(
            bound
                .entry(&Ray::from_origin_unchecked(-DVec3::Z), 1.0, f64::INFINITY)
                .is_none()
        );
    }

    #[test]
    fn nan_rays_are_never_culled() {
        let bound = Bound::new(h(0.2, 0.0, 0.5), 0.1).unwrap();
        let ray = Ray {
            origin: DVec4::new(f64::NAN, 0.0, 0.0, 1.0),
            dir: DVec4::X,
        };
        assert!(bound.entry(&ray, 1.0, f64::INFINITY).is_some());
    }

    #[test]
    fn traversal_finds_every_item_a_ray_meets() {
        let mut items = Vec::new();
        let mut spheres = Vec::new();
        for i in 0..50u32 {
            let a = f64::from(i) * 2.399_963;
            let c = Point::from_coords(DVec3::new(
                0.6 * a.cos() * (f64::from(i) / 50.0),
                0.6 * a.sin() * (f64::from(i) / 50.0),
                0.3 + 0.01 * f64::from(i),
            ))
            .unwrap();
            spheres.push(hgeom::HSphere::new(c, 0.05).unwrap());
            items.push((i, Bound::new(c.to_hyperboloid(), 0.05).unwrap()));
        }
        let bvh = Bvh::build(&items);
        for k in 0..300 {
            let a = f64::from(k) * 0.618_033_988_749_895;
            let ray = Ray::from_origin_unchecked(DVec3::new(0.7 * a.sin(), 0.7 * a.cos(), 1.0));
            let want: Vec<u32> = (0..50u32)
                .filter(|&i| {
                    spheres[i as usize]
                        .intersect(&ray, 0.0, f64::INFINITY)
                        .is_some()
                })
                .collect();
            let mut seen = Vec::new();
            let mut u_max = f64::INFINITY;
            bvh.traverse(&ray, 1.0, &mut u_max, |i, _| {
                seen.push(i);
                Step::Continue
            });
            for i in want {
                assert!(seen.contains(&i), "ray {k} missed item {i}");
            }
        }
    }
}
