//! Polygons, honeycomb faces and planes, which a render draws with no
//! thickness, printed as plates: the points `cosh t X + sinh t n` for `X`
//! in the flat piece and `|t| <= h`, with `n` the plane's unit normal (so
//! each face of the plate is the equidistant surface at `±h`, and the rim
//! is made of the geodesic segments of length `2h` orthogonal to the
//! plane at the piece's boundary).
//!
//! **Exact points of the piece.** A polygon is flat in the Klein model, so
//! the point a fraction `λ` of the way from its Klein centre to a boundary
//! point, itself linear along an edge in Klein coordinates, is exactly in
//! the polygon. A disc (the piece of a whole plane that is printed) is
//! `cosh(λR) C + sinh(λR) (cos φ E1 + sin φ E2)`.
//!
//! **The grid.** `u` runs over the top (`λ` from 0 to 1 at `t = h`), the
//! rim (`t` from `h` to `-h`) and the bottom; `v` runs round the boundary,
//! with a crease at each corner of a polygon.

use std::f64::consts::TAU;

use hgeom::glam::{DVec3, DVec4};
use hgeom::lorentz;

use crate::grid::PoleSurface;
use crate::measure::to_ball;

/// The flat piece of a plate.
#[derive(Clone, Debug)]
pub enum Outline {
    /// A convex polygon: its corners in Klein coordinates, in order, and
    /// their mean (inside it).
    Polygon {
        /// The corners.
        corners: Vec<DVec3>,
        /// Their mean.
        centre: DVec3,
        /// Points along each side sit at fractions `f + warp f (1 - f)` of
        /// it (smooth and increasing for `|warp| < 1`): a
        /// different spacing for each plate (from its corners), so that
        /// plates meeting along a side (faces of a polyhedron, coplanar
        /// faces of a honeycomb) never share a grid edge. STL keeps no
        /// connectivity; readers weld equal points, and two shells sharing
        /// an edge would no longer be 2-manifold.
        warp: f64,
    },
    /// A disc of hyperbolic radius `radius` about `centre` in the plane
    /// spanned by the orthonormal tangents `e1`, `e2`.
    Disc {
        /// The centre, on the hyperboloid.
        centre: DVec4,
        /// A unit tangent of the plane at the centre.
        e1: DVec4,
        /// The other.
        e2: DVec4,
        /// The hyperbolic radius.
        radius: f64,
    },
}

impl Outline {
    /// A polygon from its finite corners on the hyperboloid, in order.
    pub fn polygon(corners: &[DVec4]) -> Outline {
        let corners: Vec<DVec3> = corners.iter().map(|x| x.truncate() / x.w).collect();
        let centre = corners.iter().fold(DVec3::ZERO, |a, c| a + *c) / corners.len() as f64;
        let seed = corners
            .iter()
            .enumerate()
            .map(|(k, c)| c.dot(DVec3::new(12.9898, 78.233, 37.719)) * (k as f64 + 1.618))
            .sum::<f64>();
        let warp = 0.6 * ((seed * 43_758.545_3).rem_euclid(1.0) - 0.5);
        Outline::Polygon {
            corners,
            centre,
            warp,
        }
    }

    /// The point of the piece at fraction `lambda` from the centre towards
    /// the boundary point at `v`.
    pub fn point(&self, lambda: f64, v: f64) -> DVec4 {
        match self {
            Outline::Polygon {
                corners,
                centre,
                warp,
            } => {
                let n = corners.len();
                let x = v.rem_euclid(1.0) * n as f64;
                // x is in [0, n): its floor indexes a corner.
                let k = (x.floor() as usize).min(n - 1);
                let f = (x - k as f64).clamp(0.0, 1.0);
                let f = f + warp * f * (1.0 - f);
                let edge = along(corners[k], corners[(k + 1) % n], f);
                from_klein(along(*centre, edge, lambda))
            }
            Outline::Disc {
                centre,
                e1,
                e2,
                radius,
            } => {
                let r = lambda * radius;
                let phi = TAU * v;
                r.cosh() * *centre + r.sinh() * (phi.cos() * *e1 + phi.sin() * *e2)
            }
        }
    }

    /// The spacing parameter of a polygon's grid (0 for a disc).
    fn warp(&self) -> f64 {
        match self {
            Outline::Polygon { warp, .. } => *warp,
            Outline::Disc { .. } => 0.0,
        }
    }

    /// The parameters `v` of the corners (one for a disc).
    fn corners(&self) -> Vec<f64> {
        match self {
            Outline::Polygon { corners, .. } => {
                let n = corners.len();
                (0..n).map(|k| k as f64 / n as f64).collect()
            }
            Outline::Disc { .. } => vec![0.0],
        }
    }

    /// Boundary points to measure the plate's thinnest place at: the
    /// corners of a polygon (the points farthest from the ball's centre
    /// are corners: the distance from a point is convex along geodesics),
    /// and points round a disc.
    pub fn rim_samples(&self) -> Vec<DVec4> {
        match self {
            Outline::Polygon { corners, .. } => corners.iter().map(|k| from_klein(*k)).collect(),
            Outline::Disc { .. } => (0..64).map(|k| self.point(1.0, k as f64 / 64.0)).collect(),
        }
    }
}

/// The hyperboloid point of a Klein point.
fn from_klein(k: DVec3) -> DVec4 {
    k.extend(1.0) / (1.0 - k.length_squared()).sqrt()
}

/// The Klein point on the segment from `a` to `b` whose ball image lies
/// the fraction `f` of the way along the chord of the segment's image
/// (the image is an arc of a circle, less than a half, so the distance
/// from its start grows along it and bisection finds the point). Spacing
/// by the ball's lengths rather than the Klein model's keeps a grid as
/// fine near the boundary as in the middle, where the Klein model
/// squeezes lengths.
fn along(a: DVec3, b: DVec3, f: f64) -> DVec3 {
    if f <= 0.0 {
        return a;
    }
    if f >= 1.0 {
        return b;
    }
    let ball = |k: DVec3| to_ball(from_klein(k));
    let (pa, pb) = (ball(a), ball(b));
    let total = (pb - pa).length();
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..52 {
        let mid = 0.5 * (lo + hi);
        if (ball(a + (b - a) * mid) - pa).length() < f * total {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    a + (b - a) * (0.5 * (lo + hi))
}

/// A plate: a flat piece thickened by `half` on either side.
pub struct Plate {
    /// The piece.
    pub outline: Outline,
    /// The unit normal of its plane.
    pub normal: DVec4,
    /// The hyperbolic half-thickness.
    pub half: f64,
}

impl Plate {
    /// The printed thickness (ball units) at the point `x` of the piece:
    /// the chord between its two offsets.
    pub fn thickness_at(&self, x: DVec4) -> f64 {
        let off = |t: f64| to_ball(t.cosh() * x + t.sinh() * self.normal);
        (off(self.half) - off(-self.half)).length()
    }

    /// The least printed thickness over the rim samples.
    pub fn thinnest(&self) -> f64 {
        self.outline
            .rim_samples()
            .into_iter()
            .map(|x| self.thickness_at(x))
            .fold(f64::INFINITY, f64::min)
    }
}

impl PoleSurface for Plate {
    fn point(&self, u: f64, v: f64) -> DVec3 {
        let h = self.half;
        // The plate's own spacing (see `Outline::Polygon::warp`) across
        // the faces and the rim too: two plates on one polygon (faces two
        // solids share) then meet in isolated points only.
        let w = self.outline.warp();
        let warped = |f: f64| f + w * f * (1.0 - f);
        let (lambda, t) = if u <= 1.0 / 3.0 {
            (warped(3.0 * u), h)
        } else if u <= 2.0 / 3.0 {
            (1.0, h - warped(3.0 * u - 1.0) * 2.0 * h)
        } else {
            (warped(3.0 - 3.0 * u), -h)
        };
        let x = self.outline.point(lambda, v);
        to_ball(t.cosh() * x + t.sinh() * self.normal)
    }

    fn u_creases(&self) -> Vec<f64> {
        vec![0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
    }

    fn v_creases(&self) -> Vec<f64> {
        self.outline.corners()
    }
}

/// The disc of a whole plane (unit normal `n`) about the plane's point
/// nearest the ball's centre, of hyperbolic radius `radius`.
pub fn plane_disc(n: DVec4, radius: f64) -> Outline {
    let o = DVec4::W;
    let c = o - lorentz::dot(o, n) * n;
    let centre = c / (-lorentz::dot(c, c)).sqrt();
    // A spatial axis far from n's spatial part, made orthogonal to the
    // centre and the normal.
    let spatial = n.truncate();
    let axis = if spatial.x.abs() < 0.6 * spatial.length() {
        DVec4::X
    } else {
        DVec4::Y
    };
    let orth = |x: DVec4, basis: &[DVec4]| {
        basis.iter().fold(x, |x, b| {
            let bb = lorentz::dot(*b, *b);
            x - lorentz::dot(x, *b) / bb * *b
        })
    };
    let e1 = orth(axis, &[centre, n]);
    let e1 = e1 / lorentz::dot(e1, e1).sqrt();
    let e2 = lorentz::orthogonal_complement(centre, n, e1);
    let e2 = e2 / lorentz::dot(e2, e2).sqrt();
    Outline::Disc {
        centre,
        e1,
        e2,
        radius,
    }
}
