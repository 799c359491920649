//! Sampling the directions in which a point sees a geodesic triangle,
//! uniformly by solid angle (Arvo 1995, "Stratified sampling of spherical
//! triangles").
//!
//! Seen from a point `p` of H³, a geodesic triangle `ABC` fills a spherical
//! triangle of directions: the geodesics from `p` through the points of the
//! edge `AB` sweep the h-plane through `p`, `A` and `B`, which meets the
//! sphere of directions at `p` in a great circle. So the directions are the
//! spherical triangle of the unit tangents towards `A`, `B` and `C`, in the
//! tangent space at `p` (Euclidean under the Lorentz form), and a direction
//! drawn uniformly from it meets the triangle: an emissive polygon is
//! sampled exactly by solid angle, density `1 / Ω`.

use hgeom::glam::{DVec3, DVec4};
use hgeom::lorentz;

use crate::light_sampling::tangent_basis;

/// The spherical triangle of directions from a point to a geodesic
/// triangle, in coordinates of an orthonormal basis of the tangent space.
pub struct SphericalTriangle {
    basis: [DVec4; 3],
    /// Unit direction vectors towards the vertices, in the basis.
    a: DVec3,
    b: DVec3,
    c: DVec3,
    /// The interior angle at `a`.
    alpha: f64,
    /// Its solid angle, `α + β + γ - π`.
    area: f64,
}

impl SphericalTriangle {
    /// The directions from `p` to the triangle with vertices `v` (points of
    /// the hyperboloid); `None` when the triangle is degenerate as seen
    /// from `p` (edge-on, or `p` a vertex).
    pub fn new(p: DVec4, v: [DVec4; 3]) -> Option<SphericalTriangle> {
        let towards = [
            lorentz::unit_tangent_towards(p, v[0])?,
            lorentz::unit_tangent_towards(p, v[1])?,
            lorentz::unit_tangent_towards(p, v[2])?,
        ];
        let e3 = towards[0];
        let (e1, e2) = tangent_basis(p, e3);
        let basis = [e1, e2, e3];
        let coords = |t: DVec4| {
            DVec3::new(
                lorentz::dot(t, e1),
                lorentz::dot(t, e2),
                lorentz::dot(t, e3),
            )
            .normalize()
        };
        let (a, b, c) = (coords(towards[0]), coords(towards[1]), coords(towards[2]));
        // The solid angle by Van Oosterom and Strackee (1983): `tan(Ω/2) =
        // |a·(b×c)| / (1 + a·b + b·c + c·a)`, one atan2 (exact, and stable
        // for small triangles where `α + β + γ - π` cancels); Arvo's
        // sampling needs the angle at `a` as well, itself one atan2 of the
        // sine and cosine of the angle between the two edge planes.
        // With `u = a×b`, `w = a×c`: `|u×w| = |a·(b×c)|` and `u·w = b·c -
        // (a·b)(a·c)` (Lagrange's identity).
        let triple = a.dot(b.cross(c)).abs();
        let (ab, bc, ca) = (a.dot(b), b.dot(c), c.dot(a));
        let area = 2.0 * triple.atan2(1.0 + ab + bc + ca);
        let alpha = triple.atan2(bc - ab * ca);
        if !(area > 1e-12 && area.is_finite()) {
            return None;
        }
        Some(SphericalTriangle {
            basis,
            a,
            b,
            c,
            alpha,
            area,
        })
    }

    /// Its solid angle.
    pub fn solid_angle(&self) -> f64 {
        self.area
    }

    /// A direction drawn uniformly from it with the uniforms `u1`, `u2`:
    /// a unit tangent at the point.
    pub fn sample(&self, u1: f64, u2: f64) -> DVec4 {
        let (a, b, c, alpha) = (self.a, self.b, self.c, self.alpha);
        // Arvo: the sub-triangle of area u1 * area shares the vertex A and
        // the edge through A and B; its third vertex lies on the arc AC.
        let area = u1 * self.area;
        let (s, t) = (area - alpha).sin_cos();
        let cos_c = a.dot(b);
        let u = t - alpha.cos();
        let v = s + alpha.sin() * cos_c;
        let q = ((v * t - u * s) * alpha.cos() - v) / ((v * s + u * t) * alpha.sin());
        let q = q.clamp(-1.0, 1.0);
        let towards_c = (c - a * c.dot(a)).normalize_or_zero();
        let c_hat = a * q + towards_c * (1.0 - q * q).max(0.0).sqrt();
        // Then uniformly in the cosine along the arc from B to C_hat.
        let z = 1.0 - u2 * (1.0 - c_hat.dot(b));
        let towards_c_hat = (c_hat - b * c_hat.dot(b)).normalize_or_zero();
        let d = b * z + towards_c_hat * (1.0 - z * z).max(0.0).sqrt();
        let [e1, e2, e3] = self.basis;
        e1 * d.x + e2 * d.y + e3 * d.z
    }

    /// True when the unit tangent `d` (at the same point) lies in the
    /// spherical triangle, up to rounding at its edges.
    pub fn contains(&self, d: DVec4) -> bool {
        let [e1, e2, e3] = self.basis;
        let x = DVec3::new(
            lorentz::dot(d, e1),
            lorentz::dot(d, e2),
            lorentz::dot(d, e3),
        );
        let orientation = self.a.cross(self.b).dot(self.c).signum();
        [(self.a, self.b), (self.b, self.c), (self.c, self.a)]
            .iter()
            .all(|(p, q)| p.cross(*q).dot(x) * orientation >= -1e-12)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::SampleStream;
    use hgeom::{ConvexPolygon, Point, Ray, Vertex};
    use std::f64::consts::PI;

    /// One atan2 (Van Oosterom-Strackee) gives the angle excess `α + β +
    /// γ - π` of the three `acos` it replaces, and the angle at `a`,
    /// against the same quantities from the angles in f64 (a triangle
    /// large enough that the excess does not cancel).
    #[test]
    fn one_atan2_is_the_angle_excess() {
        let v = [at(0.3, 0.1, 0.5), at(-0.2, 0.25, 0.6), at(0.05, -0.3, 0.55)]
            .map(|q| q.to_hyperboloid());
        for p in [at(0.02, -0.05, 0.0), at(0.5, 0.4, -0.3), at(0.0, 0.0, 0.9)] {
            let st = SphericalTriangle::new(p.to_hyperboloid(), v).unwrap();
            let angle_at = |x: DVec3, y: DVec3, z: DVec3| {
                let (u, w) = (y - x * x.dot(y), z - x * x.dot(z));
                u.angle_between(w)
            };
            let (alpha, beta, gamma) = (
                angle_at(st.a, st.b, st.c),
                angle_at(st.b, st.c, st.a),
                angle_at(st.c, st.a, st.b),
            );
            let excess = alpha + beta + gamma - PI;
            assert!((st.solid_angle() - excess).abs() < 1e-12 * excess.max(1e-3));
            assert!((st.alpha - alpha).abs() < 1e-12);
        }
    }

    fn at(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    /// Every drawn direction meets the geodesic triangle and lies in the
    /// spherical one; the solid angle is what uniform directions measure
    /// (the fraction of them that meet the triangle, times 4π).
    #[test]
    fn samples_meet_the_triangle_and_the_solid_angle_is_measured() {
        let v = [at(0.3, 0.1, 0.5), at(-0.2, 0.25, 0.6), at(0.05, -0.3, 0.55)];
        let triangle =
            ConvexPolygon::new(v.iter().map(|p| Vertex::Interior(*p)).collect()).unwrap();
        let p = at(0.02, -0.05, 0.0).to_hyperboloid();
        let st = SphericalTriangle::new(p, v.map(|q| q.to_hyperboloid())).unwrap();
        let mut stream = SampleStream::new(17);
        for _ in 0..2000 {
            let d = st.sample(stream.next_unit(), stream.next_unit());
            assert!((lorentz::dot(d, d) - 1.0).abs() < 1e-12);
            assert!(st.contains(d));
            let ray = Ray { origin: p, dir: d };
            assert!(triangle.intersect(&ray, 0.0, f64::INFINITY).is_some());
        }
        // Uniform directions from p: the share that meets the triangle.
        let from = Point::from_hyperboloid(p).unwrap();
        let n = 400_000;
        let mut hits = 0;
        for _ in 0..n {
            let z = 2.0 * stream.next_unit() - 1.0;
            let phi = std::f64::consts::TAU * stream.next_unit();
            let r = (1.0 - z * z).sqrt();
            let ray = Ray::from_ball_unchecked(&from, DVec3::new(r * phi.cos(), r * phi.sin(), z));
            hits += usize::from(triangle.intersect(&ray, 0.0, f64::INFINITY).is_some());
        }
        let share = hits as f64 / f64::from(n);
        let expected = st.solid_angle() / (4.0 * PI);
        let sigma = (expected * (1.0 - expected) / f64::from(n)).sqrt();
        assert!(
            (share - expected).abs() < 5.0 * sigma,
            "{share} vs {expected}"
        );
    }

    /// Uniform by solid angle: the draws fall in the two halves of the
    /// triangle (split through a vertex) in proportion to their solid
    /// angles.
    #[test]
    fn draws_are_uniform_by_solid_angle() {
        let v = [at(0.4, 0.0, 0.4), at(-0.3, 0.3, 0.5), at(-0.1, -0.4, 0.45)]
            .map(|q| q.to_hyperboloid());
        let p = DVec4::new(0.0, 0.0, 0.0, 1.0);
        let st = SphericalTriangle::new(p, v).unwrap();
        // The midpoint of the edge BC (a point of the geodesic, up to the
        // normalisation that keeps it on the hyperboloid).
        let m = v[1] + v[2];
        let m = m / (-lorentz::dot(m, m)).sqrt();
        let half = SphericalTriangle::new(p, [v[0], v[1], m]).unwrap();
        let mut stream = SampleStream::new(5);
        let n = 200_000;
        let inside = (0..n)
            .filter(|_| half.contains(st.sample(stream.next_unit(), stream.next_unit())))
            .count();
        let share = inside as f64 / f64::from(n);
        let expected = half.solid_angle() / st.solid_angle();
        let sigma = (expected * (1.0 - expected) / f64::from(n)).sqrt();
        assert!(
            (share - expected).abs() < 5.0 * sigma,
            "{share} vs {expected}"
        );
    }
}
