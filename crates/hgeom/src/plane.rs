//! h-planes: planes through the origin, or spheres orthogonal to the absolute.

use glam::{DMat3, DVec3, DVec4};

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::point::{Point, Vertex};
use crate::ray::{Hit, Ray};
use crate::segment::Segment;

/// An oriented h-plane.
///
/// Invariant: `normal` is a unit spacelike vector of `R^{3,1}`
/// (`<N,N> = 1`); the plane is `{X : <X,N> = 0}` and `N` picks its positive
/// side. At every point of the plane `N` is also the plane's unit normal in the
/// tangent space, which is what makes ray hits and shading cheap.
///
/// Representable range: `N`'s components are about `cosh` of the plane's
/// distance from the origin, and `<N,N> = 1` is resolved in f64 only while
/// that distance is below ~18 (the same limit as the hyperboloid's). So the
/// plane also keeps where it came from: an isometry `place` (gyrovector
/// form, exact to the rounding of its translation part wherever it lies)
/// and the unit normal `local` in `place`'s frame, where the plane is near
/// the origin, with `N = place.to_lorentz() local`. Moving the plane
/// composes isometries and derives `N` afresh, so a plane carried far out
/// and back (a scene moved by a translation of 25, then into the eye's
/// frame) returns exact to the rounding of its input, where carrying `N`
/// itself would lose `eps e^{2d}` (`docs/geometry.md`, section 6.5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HPlane {
    normal: DVec4,
    place: Isometry,
    local: DVec4,
}

/// How an h-plane looks in the ball.
///
/// Invariants: `Flat::normal` is a unit vector; for `Sphere`,
/// `|center|^2 = 1 + radius^2` to rounding (the sphere meets the absolute at
/// right angles).
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
    ///
    /// Errors: [`GeomError::BadDirection`] for a non-finite, null or
    /// timelike `n` (including one whose `<n,n>` rounds to 0 or below).
    ///
    /// # Accuracy
    ///
    /// `n / sqrt(<n,n>)`: the plane `{<X,n> = 0}` is exactly the given one
    /// (scaling does not move it); the unit length holds to about
    /// `eps |n|^2 / <n,n>` ([`lorentz::norm`]).
    pub fn from_normal(n: DVec4) -> Result<HPlane, GeomError> {
        let len = lorentz::norm(n);
        if !(len.is_finite() && len > 0.0) {
            return Err(GeomError::BadDirection);
        }
        let normal = n / len;
        Ok(HPlane {
            normal,
            place: Isometry::IDENTITY,
            local: normal,
        })
    }

    /// A plane from its stored parts, bit for bit (so that a serialised
    /// plane reads back identical); the caller has checked them.
    #[cfg(feature = "serde")]
    pub(crate) fn from_parts_unchecked(normal: DVec4, place: Isometry, local: DVec4) -> HPlane {
        HPlane {
            normal,
            place,
            local,
        }
    }

    /// The placement and the unit normal in its frame (see the type docs).
    #[cfg(feature = "serde")]
    pub(crate) fn parts(&self) -> (Isometry, DVec4) {
        (self.place, self.local)
    }

    /// The h-plane through three vertices (interior or ideal).
    ///
    /// Oriented by the right-hand rule: seen from the side `N` points to,
    /// `a, b, c` run counter-clockwise (for three points of the `xy` plane
    /// counter-clockwise seen from `+z`, `N = +z`;
    /// `plane_through_three_points_follows_the_right_hand_rule` in
    /// `tests/derivations.rs`). Callers that need the other side use
    /// [`HPlane::flipped`].
    ///
    /// Errors: [`GeomError::Collinear`] when the three vertices lie on one
    /// h-line (to a relative 1e-14 of the triangle's size), or propagated
    /// from [`HPlane::from_normal`].
    ///
    /// # Accuracy
    ///
    /// The normal is computed with an interior vertex moved to the origin
    /// and carried back by a Lorentz matrix, so each component is within a
    /// few ulps of `|N|`: the given vertices satisfy `<X,N> = 0` to 1e-12
    /// relative to `|X| |N|` (`reflections_are_involutions_fixing_their_plane`
    /// in `tests/properties.rs`). Against a 320-bit reference, ray hits on
    /// planes through points up to 10 away are within 2e-10 (measured
    /// 7e-11; the `ray-plane` family of `tests/reference.rs`).
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
        // Carried, not renormalised: far out `<N,N>` of the carried normal
        // rounds at `eps |N|^2` and can come out 0 or negative, which would
        // read as collinear points; `L` preserves the unit length exactly.
        Ok(local.transformed(&to_anchor))
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
    ///
    /// Errors: [`GeomError::Coincident`] when the points coincide
    /// numerically.
    ///
    /// # Accuracy
    ///
    /// The normal is [`lorentz::direction_towards`]: `start` lies on the
    /// plane to 1e-15 and `towards` at the segment's length from it to 1e-13
    /// near the origin (`orthogonal_plane_contains_start` in this module);
    /// far out it inherits the rounding of the hyperboloid vectors, about
    /// `eps |X|^2 / sinh(len)`.
    pub fn orthogonal_at(start: &Point, towards: &Point) -> Result<HPlane, GeomError> {
        // In the frame where `start` is the origin the plane is the flat one
        // orthogonal to the diameter towards the image of `towards`.
        let to_start = Isometry::transvection_from_origin(*start);
        let w = to_start.inverse().apply(towards).coords();
        let len = w.length();
        if !(len > 0.0 && len.is_finite()) {
            return Err(GeomError::Coincident);
        }
        Ok(HPlane::from_normal((w / len).extend(0.0))?.transformed(&to_start))
    }

    /// The perpendicular bisector plane of the segment `a b`: the points
    /// equidistant from both; `b` is on the positive side.
    ///
    /// Errors: [`GeomError::Coincident`] when the points coincide
    /// numerically.
    ///
    /// # Accuracy
    ///
    /// The normal `X_b - X_a` carries the absolute rounding of both vectors
    /// (about `eps |X|`) against a Lorentz length `2 sinh(len/2)`: the plane
    /// is displaced by about `eps |X|^2 / len`. Fine near the origin
    /// (the midpoint is on it to 1e-14, `bisector_points_are_equidistant` in
    /// this module); poor for short segments far out, which is why
    /// [`Isometry::translation`] does not use it.
    pub fn bisector(a: &Point, b: &Point) -> Result<HPlane, GeomError> {
        // <Y,Xa> = <Y,Xb>  <=>  <Y, Xb - Xa> = 0; <Xb - Xa, Xb - Xa> = 4 sinh^2(d/2) > 0.
        // Orientation: <Xb, Xb - Xa> = -1 - <Xb,Xa> = cosh d - 1 > 0.
        let n = b.to_hyperboloid() - a.to_hyperboloid();
        HPlane::from_normal(n).map_err(|_| GeomError::Coincident)
    }

    /// The unit spacelike normal `N`.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored normal.
    #[inline]
    pub fn normal(&self) -> DVec4 {
        self.normal
    }

    /// The same plane with the opposite orientation.
    ///
    /// # Accuracy
    ///
    /// Exact (a sign change).
    pub fn flipped(&self) -> HPlane {
        HPlane {
            normal: -self.normal,
            place: self.place,
            local: -self.local,
        }
    }

    /// `<X,N>` for the point's hyperboloid vector `X`: zero on the plane,
    /// `sinh` of the signed distance to the plane in general.
    ///
    /// # Accuracy
    ///
    /// Plain [`lorentz::dot`]: absolute error about `4 eps |X| |N|`, a few
    /// ulps for points and planes near the origin
    /// (`signed_distance_is_the_distance_to_the_foot` in
    /// `tests/derivations.rs`).
    #[inline]
    pub fn signed_sinh_distance(&self, p: &Point) -> f64 {
        lorentz::dot(p.to_hyperboloid(), self.normal)
    }

    /// Signed hyperbolic distance from the point to the plane.
    ///
    /// # Accuracy
    ///
    /// `asinh` of [`HPlane::signed_sinh_distance`]: absolute error about
    /// `4 eps |X| |N| / cosh(distance)`.
    pub fn signed_distance(&self, p: &Point) -> f64 {
        self.signed_sinh_distance(p).asinh()
    }

    /// The image under an isometry (the normal is carried by its Lorentz matrix).
    ///
    /// # Accuracy
    ///
    /// Each component of the new normal within about `eps |M| |N|` (`M` the
    /// Lorentz matrix, entries up to `2 / gap` of the translation part):
    /// no renormalisation, so the normal stays finite however far the image
    /// plane lies (`far_plane_transforms_to_a_finite_normal` in
    /// `tests/derivations.rs`).
    pub fn transformed(&self, iso: &Isometry) -> HPlane {
        // Lorentz maps preserve <N,N> = 1, so the image is already a unit
        // normal up to rounding, and every use of N is linear in it: no
        // renormalisation (it would cancel far out). The matrix is that of
        // the composed placement, whose entries are of the size of the
        // plane's own distance from the origin, so a plane carried far out
        // and back is exact again.
        let place = iso.compose(&self.place);
        HPlane {
            normal: place.to_lorentz() * self.local,
            place,
            local: self.local,
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
    ///
    /// # Accuracy
    ///
    /// See [`HPlane::crossing`]; the hit point is [`Ray::at`] of the root.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let t = self.crossing(ray)?;
        if !(t > t_min && t < t_max) {
            return None;
        }
        Some(Hit {
            t,
            point: ray.at(t),
            normal: self.normal,
            shading: self.normal,
            part: 0,
        })
    }

    /// The arc length at which the ray's geodesic crosses the plane (of
    /// either sign), if it does.
    ///
    /// # Accuracy
    ///
    /// For rays from the origin (the renderer's primary rays) the crossing
    /// is computed without cancellation: against a 320-bit reference, planes
    /// through points up to 10 away give `t` within 2e-10 (measured 7e-11;
    /// `tests/reference.rs`). For other rays `<X,N>` and `<V,N>` carry
    /// absolute errors of about `eps |X| |N|`, so the hit moves by that
    /// over the sine of the incidence angle, amplified by `cosh^2 t`
    /// (`polygon_hits_lie_on_the_polygon` and `grazing_rays_to_a_polygon` in
    /// `tests/properties.rs`; `crossing_from_origin_equals_the_general_formula`
    /// in `tests/derivations.rs`).
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
    ///
    /// # Accuracy
    ///
    /// Centre `n/n_t` and radius `1/|n_t|` are within an ulp of the formula
    /// for the stored normal; `|c|^2 = 1 + r^2` holds to the normal's own
    /// unit-length rounding (`plane_through_three_points_contains_them` in
    /// this module: 1e-12; `ball_shape_is_orthogonal_to_the_absolute` in
    /// `tests/derivations.rs`). A plane through the origin to rounding
    /// (`n_t` of order `eps`) comes out as a huge sphere rather than `Flat`.
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

// The isometries defined by planes live with the plane, so that `isometry`
// does not depend on `plane` (which stores an isometry).
impl Isometry {
    /// The reflection in an h-plane: inversion in its sphere, or the Euclidean
    /// mirror in a plane through the origin.
    ///
    /// With `N = (n, n_t)`: the image of the origin is `n_t n / |n|^2` (gap
    /// `1/|n|^2`) and the linear part is the mirror `I - 2 n n^T / |n|^2`.
    ///
    /// # Accuracy
    ///
    /// `a` and `Q` are within a few ulps of the formula for the stored
    /// normal, and the gap `1/|n|^2` is exact for `<N,N> = 1`. Applied twice
    /// it returns points to within 2e-12 (measured 4e-13; the `reflection`
    /// family of `tests/reference.rs`, points up to 6 away and planes through
    /// points up to 4 away), and it fixes its plane to 1e-11
    /// (`reflections_are_involutions_fixing_their_plane` in
    /// `tests/properties.rs`; `reflection_is_the_hyperboloid_mirror` in
    /// `tests/derivations.rs`).
    pub fn reflection(plane: &HPlane) -> Isometry {
        let nv = plane.normal();
        let n = nv.truncate();
        let n2 = n.length_squared();
        let a = Point::new_unchecked(n * (nv.w / n2), 1.0 / n2);
        let u = n / n2.sqrt();
        let q = DMat3::IDENTITY - 2.0 * DMat3::from_cols(u * u.x, u * u.y, u * u.z);
        Isometry::from_parts_unchecked(a, q)
    }

    /// The translation built literally as the thesis defines it, from two
    /// reflections. Equal to [`Isometry::translation`]; kept as its reference.
    ///
    /// Errors: [`GeomError::Coincident`] from either plane constructor.
    ///
    /// # Accuracy
    ///
    /// Good for segments near the origin of length well above `eps |X|^2`
    /// (agrees with [`Isometry::translation`] to 1e-12 for ends within 1.5
    /// and lengths 0.05..3, `tests/derivations.rs`); the bisector's normal
    /// `X_b - X_a` cancels for short or far segments (a segment of length
    /// 1e-12 can come out as the identity), which is why
    /// [`Isometry::translation`] does not use it.
    pub fn translation_by_reflections(segment: &Segment) -> Result<Isometry, GeomError> {
        let first = HPlane::orthogonal_at(&segment.start(), &segment.end())?;
        let second = HPlane::bisector(&segment.start(), &segment.end())?;
        Ok(Isometry::reflection(&second).compose(&Isometry::reflection(&first)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distance::distance;

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
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

    #[test]
    fn reflection_is_an_involution_and_fixes_its_plane() {
        let (a, b, c) = (p(0.1, 0.2, 0.3), p(-0.4, 0.1, 0.0), p(0.3, -0.5, 0.5));
        let plane = HPlane::through(&a.into(), &b.into(), &c.into()).unwrap();
        let r = Isometry::reflection(&plane);
        assert!(!r.preserves_orientation());
        for q in [a, b, c] {
            assert!((r.apply(&q).coords() - q.coords()).length() < 1e-14);
        }
        let x = p(0.5, 0.5, -0.1);
        let back = r.apply(&r.apply(&x));
        assert!((back.coords() - x.coords()).length() < 1e-14);
        let rr = r.compose(&r);
        assert!(rr.translation_part().coords().length() < 1e-14);
    }
}
