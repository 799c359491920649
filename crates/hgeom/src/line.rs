//! h-lines (complete geodesics), with an orthonormal Lorentz basis that makes
//! distances to the line and the equidistant surfaces around it cheap.

use glam::{DMat3, DMat4, DVec3, DVec4};

use crate::distance::distance;
use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::mobius::{add_ideal, add_raw};
use crate::point::{IdealPoint, Point, Vertex};

/// An oriented h-line: a complete geodesic of hyperbolic space.
///
/// It is stored as the isometry that carries the *canonical line* (the
/// diameter along the ball's z axis, oriented towards `+z`) onto it, with the
/// isometry's Lorentz matrix `M` cached. The columns of `M` are an orthonormal
/// basis of `R^{3,1}` adapted to the line:
/// `P = M e_w` is the line's base point, `U = M e_z` its unit tangent there,
/// and `N1 = M e_x`, `N2 = M e_y` span the Lorentz-orthogonal complement of
/// the line's plane, so for any point `X`
/// `sinh^2 d(X, line) = <X,N1>^2 + <X,N2>^2`.
///
/// Invariants: the Lorentz basis is the Lorentz matrix of `to_line` (orthonormal to
/// about `eps |M|^2`, `M`'s entries growing like `2/gap` of the base
/// point); the line passes through the base point in direction `U`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HLine {
    to_line: Isometry,
    lorentz_basis: DMat4,
}

impl HLine {
    /// The line through two distinct vertices (h-points or ideal points),
    /// oriented from `a` towards `b`.
    ///
    /// The base point is `a` when it is an h-point, `b` when only `b` is, and
    /// the point of the line nearest the origin when both are ideal.
    ///
    /// Errors: [`GeomError::Coincident`] for equal vertices, and
    /// [`HLine::from_point_direction`]'s errors.
    ///
    /// # Accuracy
    ///
    /// Both vertices lie on the line to 1e-14 for points near the origin
    /// (`line_passes_through_both_points` in this module), ideal ends are the
    /// line's ends to 1e-14, and the base point of an ideal-ideal line is
    /// exact to an ulp (`(u+v)/(2+|u-v|)` with gap `2|u-v|/(2+|u-v|)`,
    /// `ideal_line_base_is_the_foot_of_the_perpendicular` in
    /// `tests/derivations.rs`).
    pub fn through(a: &Vertex, b: &Vertex) -> Result<HLine, GeomError> {
        match (a, b) {
            (Vertex::Interior(p), Vertex::Interior(q)) => {
                if p.coords() == q.coords() || distance(p, q) == 0.0 {
                    return Err(GeomError::Coincident);
                }
                let (w, _) = add_raw(-p.coords(), p.gap(), q.coords(), q.gap());
                HLine::from_point_direction(p, w)
            }
            (Vertex::Interior(p), Vertex::Ideal(e)) => {
                HLine::from_point_direction(p, towards_ideal(p, e))
            }
            (Vertex::Ideal(e), Vertex::Interior(p)) => {
                HLine::from_point_direction(p, -towards_ideal(p, e))
            }
            (Vertex::Ideal(e1), Vertex::Ideal(e2)) => {
                let (u, v) = (e1.coords(), e2.coords());
                let delta = (u - v).length();
                if !(delta > 0.0) {
                    return Err(GeomError::Coincident);
                }
                // The midpoint of the two null vectors (u,1) + (v,1), scaled
                // onto the hyperboloid, is the foot of the perpendicular from
                // the origin; in the ball it is (u+v)/(2+delta), and
                // 1 - |p|^2 = 2 delta/(2 + delta) exactly (|u+v|^2 = 4 - delta^2).
                let base =
                    Point::new_unchecked((u + v) / (2.0 + delta), 2.0 * delta / (2.0 + delta));
                HLine::from_point_direction(&base, towards_ideal(&base, e2))
            }
        }
    }

    /// The line through `p` with tangent `dir` there (a ball vector; the
    /// model is conformal, so it is also the hyperbolic direction).
    ///
    /// Errors: [`GeomError::BadDirection`] for a zero or non-finite `dir`,
    /// [`GeomError::NotInBall`] for a point that fails
    /// [`Point::is_representable`].
    ///
    /// # Accuracy
    ///
    /// The stored isometry is exact up to the rounding of `dir/|dir|` and of
    /// the orthonormal pair completing it (a few ulps); the Lorentz basis is
    /// as accurate as [`Isometry::to_lorentz`] (Lorentz-orthonormal to 1e-13
    /// for base points within ~1 of the origin, `lorentz_basis_is_orthonormal`).
    pub fn from_point_direction(p: &Point, dir: DVec3) -> Result<HLine, GeomError> {
        let len = dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return Err(GeomError::BadDirection);
        }
        if !p.is_representable() {
            return Err(GeomError::NotInBall {
                norm: p.coords().length(),
            });
        }
        let w = dir / len;
        let (e1, _) = w.any_orthonormal_pair();
        // (e1, w x e1, w) is right-handed, so the rotation maps e_z to w.
        let rotation = DMat3::from_cols(e1, w.cross(e1), w);
        // The transvection x -> p (+) x has differential (1-|p|^2) I at the
        // origin, so it carries the direction w at 0 to the direction w at p.
        let to_line = Isometry::transvection_from_origin(*p)
            .compose(&Isometry::orthogonal_unchecked(rotation));
        Ok(HLine::from_isometry(to_line))
    }

    fn from_isometry(to_line: Isometry) -> HLine {
        HLine {
            to_line,
            lorentz_basis: to_line.to_lorentz(),
        }
    }

    /// The isometry carrying the canonical line (the z axis, towards `+z`)
    /// onto this one.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored isometry.
    pub fn to_line(&self) -> Isometry {
        self.to_line
    }

    /// The adapted Lorentz basis as the columns `[N1 | N2 | U | P]` of a
    /// matrix (see the type docs).
    ///
    /// # Accuracy
    ///
    /// Exact: the stored matrix (see the type's invariants for how
    /// orthonormal it is).
    #[inline]
    pub fn lorentz_basis(&self) -> DMat4 {
        self.lorentz_basis
    }

    /// The base point `P` (an h-point on the line).
    ///
    /// # Accuracy
    ///
    /// Exact: the stored translation part of [`HLine::to_line`].
    pub fn base(&self) -> Point {
        self.to_line.translation_part()
    }

    /// The point at signed arc length `s` from the base point, towards the
    /// line's orientation for `s > 0`.
    ///
    /// Errors: [`GeomError::NotInBall`] when the point is beyond what f64
    /// can hold (or `s` is not finite: [`GeomError::NotFinite`]).
    ///
    /// # Accuracy
    ///
    /// [`Point::at_distance_from_origin`] then [`Isometry::apply`]: within a
    /// few coordinate ulps of the result (`1e-14` near the origin,
    /// `line_passes_through_both_points`).
    pub fn point_at(&self, s: f64) -> Result<Point, GeomError> {
        let on_axis = Point::at_distance_from_origin(DVec3::Z * s.signum(), s.abs())?;
        self.to_line.checked_apply(&on_axis)
    }

    /// The two ideal end points, backward then forward.
    ///
    /// # Accuracy
    ///
    /// As [`Isometry::apply_ideal`]: a few ulps plus about `eps / gap` of
    /// the base point, in radians.
    pub fn ends(&self) -> (IdealPoint, IdealPoint) {
        let back = IdealPoint::from_unit_unchecked(DVec3::NEG_Z);
        let front = IdealPoint::from_unit_unchecked(DVec3::Z);
        (
            self.to_line.apply_ideal(&back),
            self.to_line.apply_ideal(&front),
        )
    }

    /// `sinh` of the hyperbolic distance from a hyperboloid point to the line:
    /// `sqrt(<X,N1>^2 + <X,N2>^2)`. The absolute error is about
    /// `1e-16 |X| |M|` (both grow like `e^d` with the distance from the origin).
    ///
    /// # Accuracy
    ///
    /// As stated: absolute error about `4 eps |X| |M|`; it agrees with
    /// `sinh` of [`HLine::distance_to`] to 1e-13 relative near the origin
    /// (`sinh_distance_to_a_line_is_the_lorentz_basis_formula` in
    /// `tests/derivations.rs`).
    #[inline]
    pub fn sinh_distance_h(&self, x: DVec4) -> f64 {
        let c1 = lorentz::dot(x, self.lorentz_basis.x_axis);
        let c2 = lorentz::dot(x, self.lorentz_basis.y_axis);
        c1.hypot(c2)
    }

    /// Hyperbolic distance from an h-point to the line.
    ///
    /// Computed in the line's canonical frame (the point moved by the inverse
    /// isometry, so the line is the z axis), where the distance of
    /// `q = (x, y, z)` to the axis is `asinh(2 sqrt(x^2+y^2) / (1 - |q|^2))`
    /// with the accurate gap: correct to a few ulps relative for points that
    /// f64 places accurately, even next to the absolute.
    ///
    /// # Accuracy
    ///
    /// As stated, plus the rounding of moving the point into the canonical
    /// frame (about `10 eps (1/gap_p + 1/gap_base)` of hyperbolic distance,
    /// see [`Isometry::apply`]); within 1e-12 of a 320-bit reference for
    /// points and axes within 4 of the origin (measured 1.1e-14,
    /// `line_distance_matches_the_reference` in `tests/derivations.rs`).
    pub fn distance_to(&self, p: &Point) -> f64 {
        let q = self.to_line.inverse().apply(p);
        let c = q.coords();
        (2.0 * c.x.hypot(c.y) / q.gap()).asinh()
    }

    /// Signed arc length of the foot of the perpendicular from `p`, measured
    /// from the base point along the line's orientation.
    ///
    /// # Accuracy
    ///
    /// `atanh(<X,U> / -<X,P>)` with products rounded at about
    /// `eps |X| |M|`; accurate to a few ulps relative near the origin, and
    /// `atanh` amplifies the error by `cosh^2 s` far along the line (used by
    /// tests only to pick the nearer end of a segment).
    pub fn foot_parameter(&self, p: &Point) -> f64 {
        let x = p.to_hyperboloid();
        // X = cosh(d) (cosh s P + sinh s U) + normal part: tanh s = <X,U> / -<X,P>.
        let u = lorentz::dot(x, self.lorentz_basis.z_axis);
        let t = -lorentz::dot(x, self.lorentz_basis.w_axis);
        (u / t).atanh()
    }

    /// The image of the line under an isometry (orientation carried along).
    ///
    /// # Accuracy
    ///
    /// As [`Isometry::compose`] for the stored isometry, then a fresh
    /// [`Isometry::to_lorentz`] for the Lorentz basis.
    pub fn transformed(&self, iso: &Isometry) -> HLine {
        HLine::from_isometry(iso.compose(&self.to_line))
    }
}

/// The unit ball direction at `p` of the geodesic towards the ideal point `e`:
/// the transvection by `-p` takes `p` to the origin and `e` to `(-p) (+) e`,
/// and its differential at `p` is a positive multiple of the identity.
fn towards_ideal(p: &Point, e: &IdealPoint) -> DVec3 {
    let minus_p = Point::new_unchecked(-p.coords(), p.gap());
    add_ideal(&minus_p, e).coords()
}

impl Isometry {
    /// The rotation by `angle` radians about the h-line `axis`, right-handed
    /// about the line's direction (counter-clockwise seen from the end the
    /// line runs towards).
    ///
    /// It is `T R T^-1` with `T` = [`HLine::to_line`] (which carries the z
    /// axis onto the line, keeping its direction) and `R` the Euclidean
    /// rotation about the z axis.
    ///
    /// Errors: [`GeomError::BadAngle`] for a NaN or infinite angle.
    ///
    /// # Accuracy
    ///
    /// Agrees with [`Isometry::rotation_about_segment`] about a segment of
    /// the same line and direction to 1e-13 (axes within 1.5 of the origin,
    /// `rotation_about_a_line_matches_the_segment_form` in this module); it
    /// fixes the line's points to the same 1e-12.
    ///
    /// ```
    /// use hgeom::{HLine, Isometry, Point};
    /// let (a, b) = (Point::new(0.1, 0.0, 0.0)?, Point::new(0.1, 0.5, 0.0)?);
    /// let axis = HLine::through(&a.into(), &b.into())?;
    /// let quarter = Isometry::rotation(&axis, std::f64::consts::FRAC_PI_2)?;
    /// assert!((quarter * a).distance(a) < 1e-14);   // the axis stays put
    /// let p = Point::new(0.4, 0.0, 0.0)?;
    /// assert!(((quarter * quarter * quarter * quarter) * p).distance(p) < 1e-13);
    /// # Ok::<(), hgeom::GeomError>(())
    /// ```
    pub fn rotation(axis: &HLine, angle: f64) -> Result<Isometry, GeomError> {
        if !angle.is_finite() {
            return Err(GeomError::BadAngle(angle));
        }
        let to_line = axis.to_line();
        let spin = Isometry::orthogonal_unchecked(DMat3::from_rotation_z(angle));
        Ok(to_line.compose(&spin).compose(&to_line.inverse()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::segment::Segment;

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    #[test]
    fn rotation_about_a_line_matches_the_segment_form() {
        for (a, b) in [
            (p(0.1, 0.2, 0.3), p(-0.4, 0.1, 0.0)),
            (p(0.0, 0.0, 0.0), p(0.0, 0.0, 0.5)),
            (p(0.6, -0.2, 0.1), p(0.5, 0.3, -0.4)),
        ] {
            let line = HLine::through(&a.into(), &b.into()).unwrap();
            let seg = Segment::new(a, b).unwrap();
            for angle in [0.3, -1.7, 3.0] {
                let r = Isometry::rotation(&line, angle).unwrap();
                let s = Isometry::rotation_about_segment(&seg, angle).unwrap();
                for x in [p(0.2, -0.3, 0.4), p(-0.5, 0.5, 0.1), a, b] {
                    assert!((r * x).distance(s * x) < 1e-13);
                }
                assert!((r * a).distance(a) < 1e-12 && (r * b).distance(b) < 1e-12);
            }
        }
        assert!(
            Isometry::rotation(
                &HLine::through(&p(0.0, 0.0, 0.0).into(), &p(0.1, 0.0, 0.0).into()).unwrap(),
                f64::NAN
            )
            .is_err()
        );
    }

    #[test]
    fn line_passes_through_both_points() {
        let (a, b) = (p(0.1, 0.2, -0.3), p(-0.4, 0.3, 0.2));
        let line = HLine::through(&a.into(), &b.into()).unwrap();
        assert!(line.distance_to(&a) < 1e-15);
        assert!(line.distance_to(&b) < 1e-14);
        let d = distance(&a, &b);
        let end = line.point_at(d).unwrap();
        assert!(distance(&end, &b) < 1e-14);
        assert!(line.foot_parameter(&b) > 0.0);
    }

    #[test]
    fn lorentz_basis_is_orthonormal() {
        let line = HLine::through(&p(0.7, 0.1, 0.0).into(), &p(0.2, -0.6, 0.3).into()).unwrap();
        let m = line.lorentz_basis();
        let cols = [m.x_axis, m.y_axis, m.z_axis, m.w_axis];
        let eta = [1.0, 1.0, 1.0, -1.0];
        for i in 0..4 {
            for j in 0..4 {
                let want = if i == j { eta[i] } else { 0.0 };
                assert!((lorentz::dot(cols[i], cols[j]) - want).abs() < 1e-13);
            }
        }
    }

    #[test]
    fn ideal_ends_are_the_lines_ends() {
        let e1 = IdealPoint::from_direction(DVec3::new(1.0, 0.0, 0.0)).unwrap();
        let e2 = IdealPoint::from_direction(DVec3::new(0.0, 1.0, 0.0)).unwrap();
        let line = HLine::through(&e1.into(), &e2.into()).unwrap();
        let (back, front) = line.ends();
        assert!((back.coords() - e1.coords()).length() < 1e-15);
        assert!((front.coords() - e2.coords()).length() < 1e-15);
        // The base point is the foot of the perpendicular from the origin:
        // for ends 90 degrees apart the distance is asinh(1)... in the ball the
        // point (u+v)/(2+sqrt 2).
        let want = (e1.coords() + e2.coords()) / (2.0 + 2f64.sqrt());
        assert!((line.base().coords() - want).length() < 1e-16);
    }

    #[test]
    fn mixed_ends() {
        let a = p(0.2, 0.0, 0.1);
        let e = IdealPoint::from_direction(DVec3::new(0.0, -1.0, 1.0)).unwrap();
        let forward = HLine::through(&a.into(), &e.into()).unwrap();
        assert!((forward.ends().1.coords() - e.coords()).length() < 1e-14);
        let backward = HLine::through(&e.into(), &a.into()).unwrap();
        assert!((backward.ends().0.coords() - e.coords()).length() < 1e-14);
        assert!(backward.distance_to(&a) < 1e-15);
    }

    #[test]
    fn degenerate_lines_are_rejected() {
        let a = p(0.2, 0.0, 0.1);
        assert_eq!(
            HLine::through(&a.into(), &a.into()),
            Err(GeomError::Coincident)
        );
        assert_eq!(
            HLine::from_point_direction(&a, DVec3::ZERO),
            Err(GeomError::BadDirection)
        );
    }
}
