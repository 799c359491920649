//! h-planes: planes through the origin, or spheres orthogonal to the absolute.

use glam::{DVec3, DVec4};

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::point::{Point, Vertex};
use crate::ray::{Hit, Ray};

/// An oriented h-plane.
///
/// Invariant: `normal` is a unit spacelike vector of `R^{3,1}`
/// (`<N,N> = 1`); the plane is `{X : <X,N> = 0}` and `N` picks its positive
/// side. At every point of the plane `N` is also the plane's unit normal in the
/// tangent space, which is what makes ray hits and shading cheap.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HPlane {
    normal: DVec4,
}

/// How an h-plane looks in the ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BallShape {
    /// A Euclidean plane through the origin with this unit normal.
    Flat {
        /// Unit normal.
        normal: DVec3,
    },
    /// A sphere orthogonal to the absolute: `|center|^2 = 1 + radius^2`.
    Sphere {
        /// Euclidean centre (outside the ball).
        center: DVec3,
        /// Euclidean radius.
        radius: f64,
    },
}

impl HPlane {
    /// A plane from a spacelike normal (normalised here).
    pub fn from_normal(n: DVec4) -> Result<HPlane, GeomError> {
        let len = lorentz::norm(n);
        if !(len.is_finite() && len > 0.0) {
            return Err(GeomError::BadDirection);
        }
        Ok(HPlane { normal: n / len })
    }

    /// The h-plane through three vertices (interior or ideal).
    ///
    /// Oriented so that, seen from the positive side, `a, b, c` run
    /// counter-clockwise... in the sense of the 4-D orientation; callers that
    /// need a particular side flip it with [`HPlane::flipped`].
    pub fn through(a: &Vertex, b: &Vertex, c: &Vertex) -> Result<HPlane, GeomError> {
        // Far from the origin the hyperboloid vectors are huge (~e^d) and the
        // 4-D cross product of their differences loses ~e^{2d} ulps. Moving
        // an interior vertex to the origin first (Möbius addition is exact to
        // rounding) and carrying the normal back with the Lorentz matrix keeps
        // the normal's components correct to a few ulps each.
        let anchor = [a, b, c].into_iter().find_map(|v| match v {
            Vertex::Interior(p) if p.coords() != DVec3::ZERO => Some(*p),
            _ => None,
        });
        let Some(anchor) = anchor else {
            return HPlane::through_near_origin(a, b, c);
        };
        let to_anchor = Isometry::transvection_from_origin(anchor);
        let back = to_anchor.inverse();
        let local = HPlane::through_near_origin(
            &back.apply_vertex(a),
            &back.apply_vertex(b),
            &back.apply_vertex(c),
        )?;
        HPlane::from_normal(to_anchor.to_lorentz() * local.normal)
    }

    fn through_near_origin(a: &Vertex, b: &Vertex, c: &Vertex) -> Result<HPlane, GeomError> {
        let (xa, xb, xc) = (a.to_hyperboloid(), b.to_hyperboloid(), c.to_hyperboloid());
        // Differences are better conditioned than the raw vectors for small
        // triangles; the determinant is unchanged.
        let n = lorentz::orthogonal_complement(xa, xb - xa, xc - xa);
        let scale = (xb - xa).length() * (xc - xa).length() * xa.length();
        if !(lorentz::norm(n) > 1e-14 * scale) {
            return Err(GeomError::Collinear);
        }
        HPlane::from_normal(n)
    }

    /// The plane through `start` orthogonal to the segment `start -> towards`,
    /// oriented so `towards` is on the positive side.
    pub fn orthogonal_at(start: &Point, towards: &Point) -> Result<HPlane, GeomError> {
        let (v, _) = lorentz::direction_towards(start.to_hyperboloid(), towards.to_hyperboloid())
            .ok_or(GeomError::Coincident)?;
        // v is a unit tangent at start, hence a unit spacelike vector with <start,v> = 0.
        HPlane::from_normal(v)
    }

    /// The perpendicular bisector plane of the segment `a b`: the points
    /// equidistant from both; `b` is on the positive side.
    pub fn bisector(a: &Point, b: &Point) -> Result<HPlane, GeomError> {
        // <Y,Xa> = <Y,Xb>  <=>  <Y, Xb - Xa> = 0; <Xb - Xa, Xb - Xa> = 4 sinh^2(d/2) > 0.
        // Orientation: <Xb, Xb - Xa> = -1 - <Xb,Xa> = cosh d - 1 > 0.
        let n = b.to_hyperboloid() - a.to_hyperboloid();
        HPlane::from_normal(n).map_err(|_| GeomError::Coincident)
    }

    /// The unit spacelike normal `N`.
    #[inline]
    pub fn normal(&self) -> DVec4 {
        self.normal
    }

    /// The same plane with the opposite orientation.
    pub fn flipped(&self) -> HPlane {
        HPlane {
            normal: -self.normal,
        }
    }

    /// `<X,N>` for the point's hyperboloid vector `X`: zero on the plane,
    /// `sinh` of the signed distance to the plane in general.
    #[inline]
    pub fn signed_sinh_distance(&self, p: &Point) -> f64 {
        lorentz::dot(p.to_hyperboloid(), self.normal)
    }

    /// Signed hyperbolic distance from the point to the plane.
    pub fn signed_distance(&self, p: &Point) -> f64 {
        self.signed_sinh_distance(p).asinh()
    }

    /// The image under an isometry (the normal is carried by its Lorentz matrix).
    pub fn transformed(&self, iso: &Isometry) -> HPlane {
        let n = iso.to_lorentz() * self.normal;
        // Lorentz maps preserve <N,N> = 1; renormalising only removes rounding.
        HPlane {
            normal: n / lorentz::norm(n).max(f64::MIN_POSITIVE),
        }
    }

    /// The first intersection with `t` in `(t_min, t_max)`; the hit normal is
    /// the plane's own `N` (on its positive side).
    ///
    /// Along the ray `<X(t),N> = o cosh t + d sinh t` with `o = <X,N>`,
    /// `d = <V,N>`, so the plane is met at `tanh t = -o/d`. Near the ray's
    /// origin `t = atanh(-o/d)`; once `|tanh t| > 1/2` the same root is taken
    /// as `t = ln((d-o)/(d+o))/2` with `d -+ o = <V -+ X, N>` formed directly,
    /// so `1 - tanh t` is never computed by cancellation. A ray parallel to
    /// the plane, or meeting it only beyond the absolute, misses.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let t = self.crossing(ray)?;
        if !(t > t_min && t < t_max) {
            return None;
        }
        Some(Hit {
            t,
            point: ray.at(t),
            normal: self.normal,
        })
    }

    /// The arc length at which the ray's geodesic crosses the plane (of
    /// either sign), if it does.
    pub fn crossing(&self, ray: &Ray) -> Option<f64> {
        if ray.origin == DVec4::W {
            return self.crossing_from_origin(ray.dir.truncate());
        }
        let o = lorentz::dot(ray.origin, self.normal);
        let d = lorentz::dot(ray.dir, self.normal);
        let tau = -o / d;
        if !(tau.abs() < 1.0) {
            return None;
        }
        if tau.abs() <= 0.5 {
            return Some(tau.atanh());
        }
        let minus = lorentz::dot(ray.dir - ray.origin, self.normal);
        let plus = lorentz::dot(ray.dir + ray.origin, self.normal);
        let t = 0.5 * (minus / plus).ln();
        t.is_finite().then_some(t)
    }

    /// [`HPlane::crossing`] for a ray from the origin along the unit vector
    /// `dir` (every primary ray of the renderer).
    ///
    /// With `N = (n, w)`, `|n| = sqrt(1 + w^2)` and `c = dir . n/|n|`, the two
    /// factors are `<V -+ X, N> = |n| c +- w`. For a far plane one of them is
    /// tiny, and forming it as a difference of two large numbers would lose
    /// about `e^{2 d}` ulps (`d` the plane's distance from the origin). It is
    /// rewritten without cancellation as
    /// `|n| |c| - |w| = |c| / (|n| + |w|) - |w| (1 - |c|)`, with
    /// `1 - |c| = |dir -+ n/|n||^2 / 2` from a chord.
    fn crossing_from_origin(&self, dir: DVec3) -> Option<f64> {
        let n = self.normal.truncate();
        let w = self.normal.w;
        let len = (1.0 + w * w).sqrt();
        let unit = n / n.length();
        let c = dir.dot(unit);
        let chord = if c >= 0.0 { dir - unit } else { dir + unit };
        let one_minus_abs_c = 0.5 * chord.length_squared();
        // |n||c| - |w|, the factor that would cancel.
        let small = c.abs() / (len + w.abs()) - w.abs() * one_minus_abs_c;
        let large = len * c.abs() + w.abs();
        // minus = <V - X, N> = |n| c + w and plus = <V + X, N> = |n| c - w;
        // the one whose terms have opposite signs is sign(c) * small.
        let sc = if c >= 0.0 { 1.0 } else { -1.0 };
        let (minus, plus) = if (c >= 0.0) == (w >= 0.0) {
            (sc * large, sc * small)
        } else {
            (sc * small, sc * large)
        };
        let ratio = minus / plus;
        if !(ratio > 0.0) {
            return None;
        }
        let t = 0.5 * ratio.ln();
        t.is_finite().then_some(t)
    }

    /// The plane as a Euclidean object in the ball. With `N = (n, n_t)`:
    /// `<X,N> = 0` becomes `|p - n/n_t|^2 = 1/n_t^2`.
    pub fn ball_shape(&self) -> BallShape {
        let n = self.normal.truncate();
        let nt = self.normal.w;
        if nt == 0.0 {
            BallShape::Flat {
                normal: n.normalize(),
            }
        } else {
            BallShape::Sphere {
                center: n / nt,
                radius: 1.0 / nt.abs(),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distance::distance;

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::try_new(DVec3::new(x, y, z)).unwrap()
    }

    #[test]
    fn plane_through_three_points_contains_them() {
        let (a, b, c) = (p(0.1, 0.2, 0.3), p(-0.4, 0.1, 0.0), p(0.3, -0.5, 0.5));
        let pl = HPlane::through(&a.into(), &b.into(), &c.into()).unwrap();
        for q in [a, b, c] {
            assert!(pl.signed_sinh_distance(&q).abs() < 1e-14);
        }
        match pl.ball_shape() {
            BallShape::Sphere { center, radius } => {
                assert!((center.length_squared() - 1.0 - radius * radius).abs() < 1e-12);
                for q in [a, b, c] {
                    assert!(((q.coords() - center).length() - radius).abs() < 1e-12);
                }
            }
            BallShape::Flat { .. } => panic!("expected a sphere"),
        }
    }

    #[test]
    fn collinear_points_are_rejected() {
        let (a, b, c) = (p(0.1, 0.0, 0.0), p(0.2, 0.0, 0.0), p(-0.3, 0.0, 0.0));
        assert_eq!(
            HPlane::through(&a.into(), &b.into(), &c.into()),
            Err(GeomError::Collinear)
        );
    }

    #[test]
    fn bisector_points_are_equidistant() {
        let (a, b) = (p(0.1, 0.2, 0.3), p(-0.4, 0.1, 0.0));
        let bis = HPlane::bisector(&a, &b).unwrap();
        assert!(bis.signed_distance(&b) > 0.0);
        // The hyperbolic midpoint lies on it.
        let mid_x = a.to_hyperboloid() + b.to_hyperboloid();
        let mid = Point::from_hyperboloid(mid_x / lorentz::dot(mid_x, mid_x).abs().sqrt()).unwrap();
        assert!(bis.signed_distance(&mid).abs() < 1e-14);
        assert!((distance(&a, &mid) - distance(&b, &mid)).abs() < 1e-14);
    }

    #[test]
    fn orthogonal_plane_contains_start() {
        let (a, b) = (p(0.1, 0.2, 0.3), p(-0.4, 0.1, 0.0));
        let pl = HPlane::orthogonal_at(&a, &b).unwrap();
        assert!(pl.signed_distance(&a).abs() < 1e-15);
        assert!(pl.signed_distance(&b) > 0.0);
        // The distance from b to the plane equals d(a,b) since ab is orthogonal to it.
        assert!((pl.signed_distance(&b) - distance(&a, &b)).abs() < 1e-13);
    }
}
