//! Choosing one light per path vertex, with a probability that follows
//! what the light can contribute there (docs/rendering.md, "Light
//! selection").
//!
//! Sampling every light at every vertex costs one shadow ray per light: a
//! path in a scene of 64 lights traced 167 of them. Instead each vertex
//! draws one *light unit* (a point light, a spherical emitter, or one
//! triangle of an emissive polygon, polyhedron or mesh) with probability
//! `importance / total` (down a tree for an emitter of many triangles,
//! `light_tree.rs`) and divides what it brings by that probability:
//! the estimate stays unbiased as long as every unit that could bring
//! light gets a positive importance, and it is cheap because an importance
//! is a few multiplications (no transcendental function, no ray).
//!
//! The importance is a bound-like proxy of the irradiance a unit can send
//! to the point, in H³'s own fall-off (`1 / sinh² r`):
//!
//! - a point light of colour Φ: `|Φ| / (4 sinh² d)` (its exact irradiance
//!   on a facing surface);
//! - a sphere of radiance `L` and radius `a`: `π |L| sinh² a / sinh² d`
//!   (`π L sin² α` with `sin α = sinh a / sinh d`, again exact for a
//!   facing surface);
//! - a triangle of radiance `L` and area `A` within the ball `B(c, R)`:
//!   `|L| min(2π, A / sinh²(d - R))`, `d` the distance to `c` (a triangle
//!   of area `A` no nearer than `d - R` subtends at most about that solid
//!   angle; `2π` when the point is inside the ball).
//!
//! A unit gets importance 0 only when it cannot contribute: it lies wholly
//! below the shading point's tangent plane (next-event estimation only
//! takes directions with `cos θ > 0`), the point is inside it or on it
//! (the vertex's own emitter), or a point light's image is out of reach.
//! `sinh² d` comes from `cosh d = -<p, c>` without any `acosh`.

use std::f64::consts::{PI, TAU};

use hgeom::glam::DVec4;
use hgeom::lorentz;
use hscene_ir::Rgb;

use crate::light_tree::{LightTree, UnitBound, draw_by_weight};

/// A light unit's own kind of bound.
#[derive(Clone, Copy, Debug)]
enum Shape {
    /// A point light: `near_sinh2` floors its `sinh² d`, and beyond
    /// `cosh_reach` (quotient spaces) it lights nothing.
    Point { near_sinh2: f64, cosh_reach: f64 },
    /// A sphere of radius `a`: `sinh² a`.
    Sphere { sinh2: f64 },
    /// A triangle of this hyperbolic area.
    Triangle { area: f64 },
}

/// One thing that light selection can draw.
#[derive(Clone, Copy, Debug)]
pub struct LightUnit {
    /// The centre of its bounding ball (the light itself for a point).
    centre: DVec4,
    /// `cosh` and `sinh` of the bounding ball's radius.
    cosh_r: f64,
    sinh_r: f64,
    /// The sum of the absolute values of its colour channels: positive
    /// whenever it emits anything at all.
    strength: f64,
    shape: Shape,
    /// The scene object it belongs to: a vertex on that object does not
    /// sample it.
    pub object: Option<usize>,
}

/// `|r| + |g| + |b|`: zero only for black.
fn strength(c: Rgb) -> f64 {
    c.channels().into_iter().map(f64::abs).sum()
}

/// The smallest `sinh²` a point light's importance divides by, so a point
/// at the light (where it lights nothing) gives a finite importance.
const MIN_SINH2: f64 = 1e-12;

impl LightUnit {
    /// A point light of colour `colour` at `centre`.
    pub fn point(centre: DVec4, colour: Rgb, near_sinh2: f64, cosh_reach: f64) -> LightUnit {
        LightUnit {
            centre,
            cosh_r: 1.0,
            sinh_r: 0.0,
            strength: strength(colour) * 0.25,
            shape: Shape::Point {
                near_sinh2,
                cosh_reach,
            },
            object: None,
        }
    }

    /// A sphere of `radius` about `centre` emitting `radiance`.
    pub fn sphere(centre: DVec4, radius: f64, radiance: Rgb, object: Option<usize>) -> LightUnit {
        let sinh_r = radius.sinh();
        LightUnit {
            centre,
            cosh_r: radius.cosh(),
            sinh_r,
            strength: strength(radiance) * PI,
            shape: Shape::Sphere {
                sinh2: sinh_r * sinh_r,
            },
            object,
        }
    }

    /// A geodesic triangle with corners `v` (hyperboloid points) emitting
    /// `radiance`; `None` when its corners are not three distinct points.
    pub fn triangle(v: [DVec4; 3], radiance: Rgb, object: usize) -> Option<LightUnit> {
        // The normalised sum of the corners is a point inside the triangle
        // (its Klein centroid), and the ball about it through the farthest
        // corner holds the triangle (balls are convex).
        let s = v[0] + v[1] + v[2];
        let centre = s / (-lorentz::dot(s, s)).sqrt();
        let cosh_r = v
            .iter()
            .map(|x| -lorentz::dot(centre, *x))
            .fold(1.0, f64::max);
        // The area is π less the angle sum (Gauss-Bonnet, curvature -1).
        let angle = |a: DVec4, b: DVec4, c: DVec4| -> Option<f64> {
            let (u, w) = (
                lorentz::unit_tangent_towards(a, b)?,
                lorentz::unit_tangent_towards(a, c)?,
            );
            Some(lorentz::dot(u, w).clamp(-1.0, 1.0).acos())
        };
        let sum = angle(v[0], v[1], v[2])? + angle(v[1], v[2], v[0])? + angle(v[2], v[0], v[1])?;
        let area = PI - sum;
        if !(cosh_r.is_finite() && centre.is_finite()) {
            return None;
        }
        Some(LightUnit {
            centre,
            cosh_r,
            sinh_r: (cosh_r * cosh_r - 1.0).max(0.0).sqrt(),
            strength: strength(radiance),
            // A sliver whose area rounds to nothing still gets a chance:
            // zero is for units that cannot contribute.
            shape: Shape::Triangle {
                area: area.max(1e-15),
            },
            object: Some(object),
        })
    }

    /// Its bounding ball and its importance times its fall-off, for the
    /// tree (`light_tree.rs`).
    fn bound(&self) -> UnitBound {
        let (power, cap, sinh_reach) = match self.shape {
            Shape::Point {
                near_sinh2,
                cosh_reach,
            } => (
                self.strength,
                self.strength / near_sinh2.max(MIN_SINH2),
                (cosh_reach * cosh_reach - 1.0).max(0.0).sqrt(),
            ),
            // `sinh² a / sinh² d < 1` outside the sphere.
            Shape::Sphere { sinh2 } => (self.strength * sinh2, self.strength, f64::INFINITY),
            Shape::Triangle { area } => (self.strength * area, self.strength * TAU, f64::INFINITY),
        };
        UnitBound {
            centre: self.centre,
            radius: self.sinh_r.asinh(),
            power,
            cap,
            sinh_reach,
        }
    }

    /// What the unit can bring to the point `p` with shading normal `n`
    /// (up to a common factor), 0 only when it brings nothing.
    #[inline]
    pub fn importance(&self, p: DVec4, n: DVec4) -> f64 {
        // The signed distance of the centre from the tangent plane at `p`
        // is `asinh <c, n>`: the ball lies below it when `<c, n> < -sinh R`
        // (with a margin for rounding, never the other way).
        let cosh_d = -lorentz::dot(p, self.centre);
        let height = lorentz::dot(self.centre, n);
        if height < -self.sinh_r * (1.0 + 1e-9) - 1e-12 * cosh_d {
            return 0.0;
        }
        let sinh2_d = (cosh_d * cosh_d - 1.0).max(0.0);
        match self.shape {
            Shape::Point {
                near_sinh2,
                cosh_reach,
            } => {
                if cosh_d > cosh_reach {
                    return 0.0;
                }
                self.strength / sinh2_d.max(near_sinh2).max(MIN_SINH2)
            }
            Shape::Sphere { sinh2 } => {
                // On or inside the sphere, nothing (its light leaves it).
                if !(cosh_d > self.cosh_r) {
                    return 0.0;
                }
                self.strength * sinh2 / sinh2_d
            }
            Shape::Triangle { area } => {
                if !(cosh_d > self.cosh_r) {
                    return self.strength * TAU;
                }
                // sinh(d - R) = sinh d cosh R - cosh d sinh R.
                let s = sinh2_d.sqrt() * self.cosh_r - cosh_d * self.sinh_r;
                self.strength * (area / (s * s)).min(TAU)
            }
        }
    }
}

/// All the light units of a scene, and the draw among them: a linear pass
/// over *groups*, each one unit or the triangles of one emissive mesh
/// under a bounding-ball tree (`light_tree.rs`), then, in a tree, a walk
/// down it. A linear pass over every unit looks at each at each vertex;
/// a tree over a light's images in a quotient space, or over lights far
/// apart, judges whole branches by their balls, which H³'s exponential
/// fall-off makes too coarse (measured: 2.6 times the noise of the
/// linear pass on a space's light images), so only a mesh's triangles, close
/// together, share one.
#[derive(Debug, Default)]
pub struct LightSelector {
    units: Vec<LightUnit>,
    groups: Vec<Group>,
    /// The group of each unit.
    group_of: Vec<u32>,
}

#[derive(Debug)]
enum Group {
    /// One unit.
    Single(usize),
    /// Units of one object under a tree.
    Tree {
        tree: LightTree,
        object: Option<usize>,
    },
}

/// The fewest triangles of one emitter that get a tree.
pub const TREE_MIN_UNITS: usize = 64;

/// A unit drawn at a vertex.
#[derive(Clone, Copy, Debug)]
pub struct Choice {
    /// Its index in the selector.
    pub unit: usize,
    /// The probability it was drawn with.
    pub pmf: f64,
}

impl LightSelector {
    /// The selector over `units`, those of each range of `trees` (first
    /// unit, count: the triangles of one object) under a tree when there
    /// are at least [`TREE_MIN_UNITS`] of them.
    pub fn new(units: Vec<LightUnit>, trees: &[(usize, usize)]) -> LightSelector {
        let mut groups = Vec::new();
        let mut group_of = vec![0u32; units.len()];
        let mut k = 0;
        let mut ranges = trees
            .iter()
            .filter(|(_, len)| *len >= TREE_MIN_UNITS)
            .copied()
            .peekable();
        while k < units.len() {
            let g = groups.len() as u32;
            match ranges.peek() {
                Some(&(first, len)) if first == k && first + len <= units.len() => {
                    ranges.next();
                    let bounds: Vec<UnitBound> = units[first..first + len]
                        .iter()
                        .map(LightUnit::bound)
                        .collect();
                    groups.push(Group::Tree {
                        tree: LightTree::build(&bounds, first),
                        object: units[first].object,
                    });
                    group_of[first..first + len].fill(g);
                    k += len;
                }
                _ => {
                    groups.push(Group::Single(k));
                    group_of[k] = g;
                    k += 1;
                }
            }
        }
        LightSelector {
            units,
            groups,
            group_of,
        }
    }

    /// The importance of unit `k` at `p` (normal `n`) for a vertex on
    /// object `own`.
    #[inline]
    pub fn importance(&self, k: usize, p: DVec4, n: DVec4, own: usize) -> f64 {
        let u = &self.units[k];
        if u.object == Some(own) {
            return 0.0;
        }
        u.importance(p, n)
    }

    /// The importance of group `g` at the vertex.
    #[inline]
    fn group_importance(&self, g: &Group, p: DVec4, n: DVec4, own: usize) -> f64 {
        match g {
            Group::Single(k) => self.importance(*k, p, n, own),
            Group::Tree { object, .. } if *object == Some(own) => 0.0,
            Group::Tree { tree, .. } => tree.root_importance(p, n),
        }
    }

    /// The sum of every group's importance at the vertex.
    pub fn total(&self, p: DVec4, n: DVec4, own: usize) -> f64 {
        self.groups
            .iter()
            .map(|g| self.group_importance(g, p, n, own))
            .sum()
    }

    /// One unit drawn with the uniform `u` in proportion to its group's
    /// importance (then down the group's tree), given the vertex's `total`
    /// ([`LightSelector::total`]); `None` when no unit can contribute.
    pub fn select(&self, p: DVec4, n: DVec4, own: usize, total: f64, u: f64) -> Option<Choice> {
        if !(total > 0.0 && total.is_finite()) {
            return None;
        }
        let target = u * total;
        let (g, w, sum) = draw_by_weight(
            self.groups
                .iter()
                .map(|g| (g, self.group_importance(g, p, n, own))),
            target,
        )?;
        let pmf = w / total;
        match g {
            Group::Single(unit) => Some(Choice { unit: *unit, pmf }),
            Group::Tree { tree, .. } => {
                // Where `target` fell within the group, as a new uniform.
                let rest = ((target - (sum - w)) / w).clamp(0.0, 1.0 - f64::EPSILON);
                tree.select(p, n, rest, |k| self.importance(k, p, n, own))
                    .map(|(unit, q)| Choice { unit, pmf: pmf * q })
            }
        }
    }

    /// The probability that a vertex with the given `total` draws unit `k`.
    #[inline]
    pub fn pmf(&self, k: usize, p: DVec4, n: DVec4, own: usize, total: f64) -> f64 {
        if !(total > 0.0 && total.is_finite()) {
            return 0.0;
        }
        let Some(g) = self
            .group_of
            .get(k)
            .and_then(|&g| self.groups.get(g as usize))
        else {
            return 0.0;
        };
        match g {
            Group::Single(_) => self.importance(k, p, n, own) / total,
            Group::Tree { tree, .. } => {
                let w = self.group_importance(g, p, n, own);
                if !(w > 0.0) {
                    return 0.0;
                }
                (w / total) * tree.pmf(k, p, n, |j| self.importance(j, p, n, own))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::SampleStream;
    use hgeom::Point;
    use hgeom::glam::DVec3;
    use std::f64::consts::PI;

    fn at(dir: DVec3, d: f64) -> DVec4 {
        Point::at_distance_from_origin(dir, d)
            .expect("a point")
            .to_hyperboloid()
    }

    /// 64 units of every kind around the origin, then `mesh` triangles of
    /// one emitter (object 1000) near one another, under a tree.
    fn many(mesh: usize) -> LightSelector {
        let mut stream = SampleStream::new(5);
        let mut units = Vec::new();
        let dir = |s: &mut SampleStream| {
            DVec3::new(
                s.next_unit() - 0.5,
                s.next_unit() - 0.5,
                s.next_unit() - 0.5,
            )
        };
        for k in 0..64 {
            let c = at(dir(&mut stream), 0.5 + 2.0 * stream.next_unit());
            let colour = Rgb::new(1.0, 0.5, 0.25 * (k % 4) as f64);
            units.push(match k % 3 {
                0 => LightUnit::point(c, colour, 0.0, f64::INFINITY),
                1 => LightUnit::sphere(c, 0.2, colour, Some(k)),
                _ => {
                    let v = [
                        at(dir(&mut stream), 1.0),
                        at(dir(&mut stream), 1.5),
                        at(dir(&mut stream), 2.0),
                    ];
                    LightUnit::triangle(v, colour, k).expect("a triangle")
                }
            });
        }
        // The mesh: a latitude-longitude sphere of radius 0.3 (as a
        // scanned lamp would be), two triangles a cell.
        let first = units.len();
        let centre = DVec3::new(0.3, -0.2, 0.5);
        let (rows, columns) = (10, mesh / 20);
        let corner = |i: usize, j: usize| {
            let (theta, phi) = (PI * i as f64 / rows as f64, TAU * j as f64 / columns as f64);
            let c = centre
                + 0.3
                    * DVec3::new(
                        theta.sin() * phi.cos(),
                        theta.sin() * phi.sin(),
                        theta.cos(),
                    );
            at(c, c.length())
        };
        let colour = Rgb::new(2.0, 1.0, 0.5);
        for i in 0..rows {
            for j in 0..columns {
                let (a, b, c, d) = (
                    corner(i, j),
                    corner(i + 1, j),
                    corner(i + 1, j + 1),
                    corner(i, j + 1),
                );
                // The poles' cells have one corner twice: a degenerate
                // triangle keeps its place as a unit that is never drawn.
                for v in [[a, b, c], [a, c, d]] {
                    units.push(
                        LightUnit::triangle(v, colour, 1000).unwrap_or_else(|| {
                            LightUnit::sphere(v[0], 0.0, Rgb::BLACK, Some(1000))
                        }),
                    );
                }
            }
        }
        LightSelector::new(units, &[(first, mesh)])
    }

    /// The draw picks each unit as often as its probability says, every
    /// unit that can bring light has a positive probability, and the
    /// probabilities sum to at most 1 (exactly 1 without a tree, where no
    /// branch can come up empty): for 64 single units, and with a mesh of
    /// 600 triangles under a tree.
    fn check_draws(mesh: usize) {
        let sel = many(mesh);
        let count = 64 + mesh;
        assert_eq!(sel.units.len(), count);
        let p = at(DVec3::new(0.1, 0.2, 0.3), 0.3);
        let n = hgeom::ray::hyperboloid_direction(
            &Point::from_hyperboloid(p).expect("a point"),
            DVec3::new(0.0, 1.0, 0.2),
        );
        let own = 7;
        let total = sel.total(p, n, own);
        let pmf: Vec<f64> = (0..count).map(|k| sel.pmf(k, p, n, own, total)).collect();
        let sum: f64 = pmf.iter().sum();
        // A branch whose ball pokes above the tangent plane while its
        // units lie below comes up empty: a lost draw, never a bias.
        assert!(sum <= 1.0 + 1e-12 && sum > 0.7, "{sum}");
        if mesh == 0 {
            assert!((sum - 1.0).abs() < 1e-12, "{sum}");
        }
        assert_eq!(pmf[7], 0.0, "the vertex's own object");
        for (k, q) in pmf.iter().enumerate() {
            assert_eq!(*q > 0.0, sel.importance(k, p, n, own) > 0.0, "unit {k}");
        }
        // Units below the tangent plane are never drawn.
        assert!((0..count).any(|k| pmf[k] == 0.0 && k != 7));
        let draws = 400_000;
        let mut counts = vec![0u32; count];
        let mut stream = SampleStream::new(9);
        let mut none = 0u32;
        for _ in 0..draws {
            match sel.select(p, n, own, total, stream.next_unit()) {
                Some(c) => {
                    assert!((c.pmf - pmf[c.unit]).abs() <= 1e-12 * pmf[c.unit]);
                    counts[c.unit] += 1;
                }
                None => none += 1,
            }
        }
        for (k, &count) in counts.iter().enumerate() {
            let q = pmf[k];
            let expect = q * f64::from(draws);
            let sigma = (expect * (1.0 - q)).sqrt().max(1.0);
            assert!(
                (f64::from(count) - expect).abs() < 5.0 * sigma,
                "unit {k}: {count} vs {expect}"
            );
        }
        let expect_none = (1.0 - sum) * f64::from(draws);
        assert!((f64::from(none) - expect_none).abs() < 5.0 * expect_none.sqrt().max(1.0));
    }

    #[test]
    fn the_pmf_is_what_is_drawn() {
        check_draws(0);
    }

    #[test]
    fn the_pmf_is_what_is_drawn_down_a_meshs_tree() {
        check_draws(600);
    }

    /// Drawing down a mesh's tree is unbiased: the mean of a unit's
    /// importance over its probability is the sum of the importances
    /// (the estimate of any light the units bring has the right mean).
    #[test]
    fn drawing_down_a_tree_is_unbiased() {
        let sel = many(2000);
        let p = at(DVec3::new(-0.2, 0.1, 0.1), 0.2);
        let n = hgeom::ray::hyperboloid_direction(
            &Point::from_hyperboloid(p).expect("a point"),
            DVec3::new(0.3, 0.1, 1.0),
        );
        let own = 0;
        let total = sel.total(p, n, own);
        let exact: f64 = (0..sel.units.len())
            .map(|k| sel.importance(k, p, n, own))
            .sum();
        let draws = 400_000;
        let mut stream = SampleStream::new(3);
        let (mut sum, mut sum2) = (0.0, 0.0);
        for _ in 0..draws {
            if let Some(c) = sel.select(p, n, own, total, stream.next_unit()) {
                let x = sel.importance(c.unit, p, n, own) / c.pmf;
                sum += x;
                sum2 += x * x;
            }
        }
        let mean = sum / f64::from(draws);
        let sigma = ((sum2 / f64::from(draws) - mean * mean) / f64::from(draws)).sqrt();
        assert!(
            (mean - exact).abs() < 5.0 * sigma,
            "{mean} vs {exact} ± {sigma}"
        );
    }

    /// A point light's importance is its exact irradiance on a surface
    /// facing it, `Φ / (4 sinh² d)`, against the distance from
    /// `lorentz::distance`.
    #[test]
    fn point_importance_is_its_irradiance() {
        let c = at(DVec3::new(0.0, 0.0, 1.0), 1.3);
        let unit = LightUnit::point(c, Rgb::new(1.0, 1.0, 2.0), 0.0, f64::INFINITY);
        let p = Point::ORIGIN.to_hyperboloid();
        let n = DVec4::new(0.0, 0.0, 1.0, 0.0);
        let d = lorentz::distance(p, c);
        let exact = 4.0 / (4.0 * d.sinh().powi(2));
        assert!((unit.importance(p, n) - exact).abs() < 1e-12 * exact);
        assert_eq!(unit.importance(p, -n), 0.0, "behind the surface");
    }

    /// A sphere's importance is `π |L| sin² α` with `sin α = sinh a /
    /// sinh d`; a triangle's never exceeds `2π |L|`, and both are 0 only
    /// wholly below the plane.
    #[test]
    fn area_importances_follow_the_bounds() {
        let c = at(DVec3::new(1.0, 0.0, 0.0), 2.0);
        let s = LightUnit::sphere(c, 0.5, Rgb::new(1.0, 0.0, 0.0), None);
        let p = Point::ORIGIN.to_hyperboloid();
        let n = DVec4::new(1.0, 0.0, 0.0, 0.0);
        let sin_a = 0.5f64.sinh() / 2.0f64.sinh();
        let exact = PI * sin_a * sin_a;
        assert!((s.importance(p, n) - exact).abs() < 1e-12 * exact);
        // The centre's height over a plane through the origin tilted by
        // `deg` is `sinh 2 sin(deg)`: the sphere pokes above it down to
        // `sin(deg) = -sinh 0.5 / sinh 2` (about -8.3°), and lies wholly
        // below past that.
        let tilt = |deg: f64| {
            let a = deg.to_radians();
            DVec4::new(a.sin(), a.cos(), 0.0, 0.0)
        };
        assert!(s.importance(p, tilt(-5.0)) > 0.0, "the cap pokes above");
        assert_eq!(s.importance(p, tilt(-60.0)), 0.0, "wholly below");
        let t = LightUnit::triangle(
            [
                at(DVec3::new(1.0, 0.0, 0.0), 0.01),
                at(DVec3::new(0.0, 1.0, 0.0), 0.01),
                at(DVec3::new(0.0, 0.0, 1.0), 0.01),
            ],
            Rgb::new(1.0, 1.0, 1.0),
            0,
        )
        .expect("a triangle");
        // Seen from nearly on it: the cap of 2π.
        assert!(t.importance(p, DVec4::new(1.0, 1.0, 1.0, 0.0) / 3f64.sqrt()) <= 3.0 * TAU);
    }
}
