//! Isometries of H^3 in gyrovector form.
//!
//! Every isometry of the ball can be written uniquely as `x -> a (+) Q x`
//! with `a = f(0)` an h-point and `Q` in O(3) (`det Q = -1` for the
//! orientation-reversing ones, such as reflections). This is the
//! representation that drifts least under long chains (docs/geometry.md,
//! section 16.2): composition
//! goes through the gyration, the translation part carries an exact gap, and
//! the rotation part never mixes with it.

use glam::{DMat3, DMat4, DVec3};

use crate::accurate::one_minus_norm_sq;
use crate::error::GeomError;
use crate::mobius::{self, add_raw, add_raw_consistent};
use crate::point::{IdealPoint, Point, Vertex};
use crate::segment::Segment;

/// An isometry `x -> a (+) Q x` of hyperbolic space.
///
/// Invariants: `a` is an h-point (with its accurate gap), `Q` is orthogonal
/// to rounding (`|Q Q^T - I|` a few ulps; [`Isometry::orthogonal_unchecked`] is the
/// one public constructor that trusts its caller for this). Application,
/// composition and inversion are exact formulas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Isometry {
    a: Point,
    q: DMat3,
}

impl Default for Isometry {
    fn default() -> Self {
        Isometry::IDENTITY
    }
}

impl Isometry {
    /// The identity map (exact).
    pub const IDENTITY: Isometry = Isometry {
        a: Point::ORIGIN,
        q: DMat3::IDENTITY,
    };

    /// The transvection along the diameter through `a` that moves the origin
    /// to `a` (Möbius left addition `x -> a (+) x`).
    ///
    /// # Accuracy
    ///
    /// Exact: stores `a` (with its gap) and `Q = I`.
    pub fn transvection_from_origin(a: Point) -> Isometry {
        Isometry {
            a,
            q: DMat3::IDENTITY,
        }
    }

    /// A Euclidean orthogonal map of the ball fixing the origin (a rotation
    /// about the origin, or a reflection in a plane through it).
    ///
    /// The hot-path form of [`Isometry::orthogonal`]: nothing is
    /// checked. Precondition: `q` orthogonal to rounding; otherwise the
    /// result is not an isometry.
    ///
    /// # Accuracy
    ///
    /// Exact: stores `q` and `a = 0`.
    pub fn orthogonal_unchecked(q: DMat3) -> Isometry {
        Isometry {
            a: Point::ORIGIN,
            q,
        }
    }

    /// [`Isometry::orthogonal_unchecked`], checked: `q` must be finite and orthogonal
    /// to 1e-12 (`max |Q Q^T - I| <= 1e-12`, entrywise).
    ///
    /// Errors: [`GeomError::NotFinite`], [`GeomError::NotOrthogonal`].
    ///
    /// # Accuracy
    ///
    /// As [`Isometry::orthogonal_unchecked`]; identical to it on valid input
    /// (`tests/constructors.rs`).
    pub fn orthogonal(q: DMat3) -> Result<Isometry, GeomError> {
        if !q.is_finite() {
            return Err(GeomError::NotFinite);
        }
        let defect = orthogonality_defect(&q);
        if !(defect <= 1e-12) {
            return Err(GeomError::NotOrthogonal { defect });
        }
        Ok(Isometry::orthogonal_unchecked(q))
    }

    /// The translation along the segment's h-line that maps its start to its
    /// end.
    ///
    /// The thesis defines it as the reflection in the plane orthogonal to the
    /// segment at its start followed by the reflection in its bisector plane
    /// (see [`Isometry::translation_by_reflections`]). We evaluate the same map
    /// as `tau_a tau_w tau_(-a)` with `w = (-a) (+) b`: a transvection
    /// conjugated to the segment's line. Möbius addition keeps exact gaps,
    /// where the bisector's normal `X_b - X_a` cancels for short segments.
    ///
    /// Errors: [`GeomError::Coincident`] if the end moved to the origin
    /// rounds to the origin (ends a few ulps apart).
    ///
    /// # Accuracy
    ///
    /// Maps `start` to within 5e-9 of `end` for ends up to 8 from the origin
    /// (measured 1.5e-9; the `translation` family of `tests/reference.rs`):
    /// the intermediate point `w` lies up to 16 out, where one coordinate ulp
    /// is about `2 eps / gap ~ 1e-9` of hyperbolic distance. Near the origin
    /// the error is about `1e-12 max(len, 1)`
    /// (`translation_moves_start_to_end_along_its_line`), and segments as
    /// short as 1e-12 translate correctly to 1% of their length
    /// (`translation_along_a_segment_of_length_1e_12`). Agrees with
    /// [`Isometry::translation_by_reflections`] to 1e-12 near the origin
    /// (`translation_equals_the_two_reflection_definition` in
    /// `tests/derivations.rs`).
    pub fn translation(segment: &Segment) -> Result<Isometry, GeomError> {
        let a = segment.start();
        let to_origin = Isometry::transvection_from_origin(a).inverse();
        let w = to_origin.apply(&segment.end());
        if w.coords() == DVec3::ZERO {
            return Err(GeomError::Coincident);
        }
        Ok(to_origin
            .inverse()
            .compose(&Isometry::transvection_from_origin(w))
            .compose(&to_origin))
    }

    /// The rotation by `angle` radians about the h-line through the segment,
    /// counter-clockwise when looking from `end` back towards `start`
    /// (right-hand rule about the direction `start -> end`).
    ///
    /// The hot-path form of [`Isometry::rotation_about_segment`]: a NaN or infinite
    /// angle is not checked and gives a NaN map.
    ///
    /// # Accuracy
    ///
    /// Fixes its axis points to 1e-12 and preserves distances to
    /// `1e-12 d` (axes within 1.5 of the origin,
    /// `rotations_fix_their_axis_and_undo` in `tests/properties.rs`); the
    /// turn about the axis equals `angle` to 1e-9 there. For a far axis
    /// (distance 8) it moves its own axis points by less than 1e-9
    /// (`composing_reflections_in_far_planes`).
    pub fn rotation_about_segment_unchecked(axis: &Segment, angle: f64) -> Isometry {
        // Conjugate a rotation about a diameter: move start to the origin; the
        // differential of a transvection at the origin is a positive multiple of
        // the identity, so the axis direction and handedness carry over.
        let to_origin = Isometry::transvection_from_origin(axis.start()).inverse();
        let end = to_origin.apply(&axis.end());
        let u = end.coords().normalize();
        let spin = Isometry::orthogonal_unchecked(DMat3::from_axis_angle(u, angle));
        to_origin.inverse().compose(&spin).compose(&to_origin)
    }

    /// [`Isometry::rotation_about_segment_unchecked`], checked: the angle must be finite.
    ///
    /// Errors: [`GeomError::BadAngle`] for a NaN or infinite angle.
    ///
    /// # Accuracy
    ///
    /// As [`Isometry::rotation_about_segment_unchecked`]; identical to it on valid input
    /// (`tests/constructors.rs`).
    pub fn rotation_about_segment(axis: &Segment, angle: f64) -> Result<Isometry, GeomError> {
        if !angle.is_finite() {
            return Err(GeomError::BadAngle(angle));
        }
        Ok(Isometry::rotation_about_segment_unchecked(axis, angle))
    }

    /// The isometry `x -> a (+) Qx` from its parts: the image `a` of the
    /// origin ([`Isometry::translation_part`]) and the orthogonal linear
    /// part ([`Isometry::linear_part`]), which must be finite and orthogonal
    /// to 1e-12 as for [`Isometry::orthogonal_unchecked`].
    ///
    /// Errors: [`GeomError::NotFinite`], [`GeomError::NotOrthogonal`].
    ///
    /// # Accuracy
    ///
    /// Exact: the parts are stored as given, so
    /// `Isometry::from_parts(f.translation_part(), f.linear_part())` is `f`.
    pub fn from_parts(translation: Point, linear: DMat3) -> Result<Isometry, GeomError> {
        let q = Isometry::orthogonal(linear)?.q;
        Ok(Isometry { a: translation, q })
    }

    /// The isometry whose Lorentz matrix is `m` (a future-preserving
    /// matrix with `mᵀ J m = J`, `J = diag(1,1,1,-1)`): the translation part
    /// is the image of the origin, the linear part what is left after
    /// undoing the pure translation to it, orthonormalised (Gram-Schmidt,
    /// its handedness kept) so that a matrix built from rounded products
    /// still gives an exact isometry.
    ///
    /// Errors: [`GeomError::NotFinite`] for a matrix that is not finite or
    /// does not send the origin into the ball; [`GeomError::NotOrthogonal`]
    /// when the linear part is off O(3) by more than 1e-9 (not a Lorentz
    /// matrix).
    ///
    /// # Accuracy
    ///
    /// The inverse of [`Isometry::to_lorentz`] to rounding for translation
    /// parts near the origin (`from_lorentz_inverts_to_lorentz`); a matrix
    /// good to `ε` gives an isometry good to about `ε cosh² d` at distance
    /// `d` of its translation.
    pub fn from_lorentz(m: DMat4) -> Result<Isometry, GeomError> {
        Isometry::from_lorentz_within(m, 1e-9)
    }

    /// [`Isometry::from_lorentz`] with the orthogonality tolerance given:
    /// a space's pairings have one that scales with their size.
    pub(crate) fn from_lorentz_within(m: DMat4, tolerance: f64) -> Result<Isometry, GeomError> {
        if !m.is_finite() {
            return Err(GeomError::NotFinite);
        }
        let a = Point::from_hyperboloid(m.w_axis).ok_or(GeomError::NotFinite)?;
        let boost = Isometry::transvection_from_origin(a).to_lorentz();
        let rest = crate::lorentz::inverse(boost) * m;
        let q = DMat3::from_cols(
            rest.x_axis.truncate(),
            rest.y_axis.truncate(),
            rest.z_axis.truncate(),
        );
        let defect = orthogonality_defect(&q);
        if !(defect <= tolerance) {
            return Err(GeomError::NotOrthogonal { defect });
        }
        let x = q.x_axis.normalize();
        let y = (q.y_axis - x * x.dot(q.y_axis)).normalize();
        let z = x.cross(y) * q.z_axis.dot(x.cross(y)).signum();
        Ok(Isometry {
            a,
            q: DMat3::from_cols(x, y, z),
        })
    }

    /// [`Isometry::from_parts`] unchecked, for the constructors elsewhere in
    /// the crate that compute an orthogonal `linear` themselves (the
    /// reflection in a plane).
    pub(crate) fn from_parts_unchecked(translation: Point, linear: DMat3) -> Isometry {
        Isometry {
            a: translation,
            q: linear,
        }
    }

    /// The image of the origin, `f(0) = a`.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored point.
    pub fn translation_part(&self) -> Point {
        self.a
    }

    /// The orthogonal part `Q`.
    ///
    /// # Accuracy
    ///
    /// Exact: the stored matrix.
    pub fn linear_part(&self) -> DMat3 {
        self.q
    }

    /// True unless the map reverses orientation.
    ///
    /// # Accuracy
    ///
    /// Exact for every isometry built by hgeom: `det Q` is `+-1` to a few
    /// ulps, so its sign is never in doubt.
    pub fn preserves_orientation(&self) -> bool {
        self.q.determinant() > 0.0
    }

    /// Apply to an h-point.
    ///
    /// # Accuracy
    ///
    /// One Möbius addition ([`mobius::add_raw`]): the image's gap within a
    /// few ulps, its position within `10 eps (1/gap_a + 1/gap_x + 1/gap_image)`
    /// of the exact image (hyperbolic distance; measured 2.4 times that scale
    /// at most for translation parts and points up to 12 from the origin,
    /// `isometry_apply_matches_the_reference` in `tests/derivations.rs`),
    /// i.e. a few coordinate ulps of the translation part, the point and the
    /// image. Distances are preserved to
    /// `1e-12 d + 1e-14` (`isometries_preserve_distance`). Not checked: an
    /// image beyond distance ~37 fails [`Point::is_representable`]; use
    /// [`Isometry::checked_apply`] where that can happen.
    #[inline]
    pub fn apply(&self, p: &Point) -> Point {
        if self.a.coords() == DVec3::ZERO {
            // A pure rotation: `0 (+) Qx = Qx` with the gap unchanged, without
            // the rounding of `D = |Qx|^2 + gap` (an ulp of a far point).
            return Point::new_unchecked(self.q * p.coords(), p.gap());
        }
        let (c, g) =
            add_raw_consistent(self.a.coords(), self.a.gap(), self.q * p.coords(), p.gap());
        Point::new_unchecked(c, g)
    }

    /// Apply to an h-point, failing if the image is too close to the absolute
    /// for f64 to represent (its gap underflows; distance beyond about 37).
    ///
    /// Errors: [`GeomError::NotInBall`] when the image fails
    /// [`Point::is_representable`].
    ///
    /// # Accuracy
    ///
    /// As [`Isometry::apply`].
    pub fn checked_apply(&self, p: &Point) -> Result<Point, GeomError> {
        let q = self.apply(p);
        if q.is_representable() {
            Ok(q)
        } else {
            Err(GeomError::NotInBall {
                norm: q.coords().length(),
            })
        }
    }

    /// Apply to an ideal point.
    ///
    /// # Accuracy
    ///
    /// As [`mobius::add_ideal`]: a few ulps plus about `eps / gap_a` radians
    /// (`ideal_ends_are_the_lines_ends` in `line.rs`: 1e-15 near the origin).
    pub fn apply_ideal(&self, p: &IdealPoint) -> IdealPoint {
        // Q p is a unit vector for orthogonal Q; from_direction only fails on
        // a zero or non-finite vector, which orthogonal Q cannot produce.
        let rotated = IdealPoint::from_direction(self.q * p.coords()).unwrap_or(*p);
        mobius::add_ideal(&self.a, &rotated)
    }

    /// Apply to a vertex of either kind.
    ///
    /// # Accuracy
    ///
    /// As [`Isometry::apply`] or [`Isometry::apply_ideal`].
    pub fn apply_vertex(&self, v: &Vertex) -> Vertex {
        match v {
            Vertex::Interior(p) => Vertex::Interior(self.apply(p)),
            Vertex::Ideal(p) => Vertex::Ideal(self.apply_ideal(p)),
        }
    }

    /// Map a unit tangent direction `dir` (a ball vector) at `p` to the unit
    /// tangent direction at the image of `p`. Exact: computed with the
    /// isometry's Lorentz matrix, on which tangent vectors transform linearly.
    ///
    /// # Accuracy
    ///
    /// Through [`Isometry::to_lorentz`] and [`crate::ray::ball_direction`]:
    /// angles between mapped directions are preserved to
    /// `1e-12 + 100 eps (|X_p|^2 + |X_f(p)|^2)` (`isometries_preserve_angles`
    /// in `tests/properties.rs`): a few ulps near the origin, degrading like
    /// `e^{2d}` with the distance of `p` and its image from the origin.
    pub fn apply_direction(&self, p: &Point, dir: DVec3) -> DVec3 {
        let l = self.to_lorentz();
        let x = l * p.to_hyperboloid();
        let v = l * crate::ray::hyperboloid_direction(p, dir);
        crate::ray::ball_direction(x, v)
    }

    /// The same isometry as a 4x4 Lorentz matrix acting on hyperboloid vectors
    /// (time in `w`): the boost taking the origin to `a`, after `diag(Q, 1)`.
    ///
    /// # Accuracy
    ///
    /// Each entry within a few ulps of the exact matrix for the stored
    /// `(a, Q)`; entries are as large as `2/gap_a`, so `M^T eta M = eta`
    /// holds to about `eps (2/gap_a)^2` and the matrix is only useful while
    /// the translation part is within ~18 of the origin
    /// (`lorentz_matrix_agrees_with_apply` in `tests/derivations.rs`;
    /// `lorentz_basis_is_orthonormal` in `line.rs`). Composed Lorentz matrices
    /// drift 100 to 10^6 times faster than the gyrovector form
    /// (docs/geometry.md, section 16.2), which is why they are derived, never stored.
    pub fn to_lorentz(&self) -> DMat4 {
        // The boost is a Lorentz matrix exactly when `A` is on the sheet:
        // derive `A` from the coordinates and their own gap. A composed
        // translation part that cancelled near the origin keeps the gap of
        // the identity (its extra precision, see `mobius::add_raw_consistent`),
        // which disagrees with its coordinates there; far out the matrix is
        // only good to `eps |M|^2` either way.
        let own = one_minus_norm_sq(self.a.coords());
        let a = if own > 0.0 {
            Point::new_unchecked(self.a.coords(), own).to_hyperboloid()
        } else {
            self.a.to_hyperboloid()
        };
        let s = a.truncate();
        let k = 1.0 / (1.0 + a.w);
        let boost = DMat4::from_cols(
            (DVec3::X + s * (s.x * k)).extend(s.x),
            (DVec3::Y + s * (s.y * k)).extend(s.y),
            (DVec3::Z + s * (s.z * k)).extend(s.z),
            a,
        );
        boost * DMat4::from_mat3(self.q)
    }

    /// `self ∘ other`: first `other`, then `self`.
    ///
    /// `(a,Q) ∘ (b,S) = (a (+) Qb, gyr[a,Qb] Q S)`, since Möbius addition
    /// commutes with orthogonal maps and `a (+) (c (+) x) = (a (+) c) (+) gyr[a,c] x`.
    ///
    /// # Accuracy
    ///
    /// `(f ∘ g)(x)` agrees with `f(g(x))` to
    /// `1e-13 + 1000 (fuzz(g(x)) + fuzz(f(g(x))) + (fuzz(a_f) + fuzz(a_g)) / gap_x)`
    /// with `fuzz(p) = eps / gap_p` (`composition_and_inverse` in
    /// `tests/properties.rs`). Drift: 1000 random compositions and their
    /// inverses leave a translation below 1e-8 (measured 4.7e-10, peak ~12;
    /// `tests/reference.rs`), and 10,000 below 2e-9 (measured 4e-10 .. 1.05e-9
    /// over six walks; `ten_thousand_step_drift_stays_below_2e_9`).
    pub fn compose(&self, other: &Isometry) -> Isometry {
        let qb = self.q * other.a.coords();
        if self.a.coords() == DVec3::ZERO {
            // A rotation after `other`: `(0, Q) ∘ (b, S) = (Qb, QS)` exactly
            // (the gyration with the origin is the identity).
            return Isometry {
                a: Point::new_unchecked(qb, other.a.gap()),
                q: self.q * other.q,
            };
        }
        let gyr = mobius::gyration(self.a.coords(), self.a.gap(), qb, other.a.gap());
        let (c, g) = add_raw(self.a.coords(), self.a.gap(), qb, other.a.gap());
        Isometry {
            a: Point::new_unchecked(c, g),
            q: gyr * self.q * other.q,
        }
    }

    /// The inverse: `y = a (+) Qx  <=>  x = Q^T(-a) (+) Q^T y`.
    ///
    /// # Accuracy
    ///
    /// `-Q^T a` is a few ulps of each coordinate, the gap is copied exactly,
    /// `Q^T` is exact; `f ∘ f^-1` is the identity to about
    /// `1000 (1 + defect) fuzz(a)` where `defect` is `Q`'s distance from
    /// O(3) in ulps (`composition_and_inverse` in `tests/properties.rs`).
    pub fn inverse(&self) -> Isometry {
        let qt = self.q.transpose();
        Isometry {
            a: Point::new_unchecked(-(qt * self.a.coords()), self.a.gap()),
            q: qt,
        }
    }
}

/// `max |Q Qᵀ - I|`, entrywise.
fn orthogonality_defect(q: &DMat3) -> f64 {
    let d = *q * q.transpose() - DMat3::IDENTITY;
    d.x_axis
        .abs()
        .max(d.y_axis.abs())
        .max(d.z_axis.abs())
        .max_element()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distance::distance;

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    #[test]
    fn from_lorentz_inverts_to_lorentz() {
        let f = Isometry::translation(&Segment::new(p(0.1, 0.2, 0.3), p(-0.4, 0.1, 0.0)).unwrap())
            .unwrap()
            .compose(&Isometry::orthogonal_unchecked(DMat3::from_axis_angle(
                DVec3::new(1.0, 2.0, 2.0).normalize(),
                0.7,
            )));
        for g in [
            f,
            f.compose(&Isometry::orthogonal_unchecked(DMat3::from_diagonal(
                DVec3::new(1.0, 1.0, -1.0),
            ))),
        ] {
            let back = Isometry::from_lorentz(g.to_lorentz()).unwrap();
            assert_eq!(back.preserves_orientation(), g.preserves_orientation());
            for x in [p(0.3, -0.2, 0.5), p(-0.7, 0.1, 0.2)] {
                assert!(distance(&back.apply(&x), &g.apply(&x)) < 1e-13);
            }
        }
    }

    #[test]
    fn from_parts_rebuilds_an_isometry_exactly() {
        let f = Isometry::translation(&Segment::new(p(0.1, 0.2, 0.3), p(-0.4, 0.1, 0.0)).unwrap())
            .unwrap()
            .compose(&Isometry::orthogonal_unchecked(DMat3::from_rotation_x(0.4)));
        assert_eq!(
            Isometry::from_parts(f.translation_part(), f.linear_part()),
            Ok(f)
        );
        assert!(
            Isometry::from_parts(Point::ORIGIN, DMat3::from_diagonal(DVec3::splat(2.0))).is_err()
        );
    }

    #[test]
    fn translation_maps_start_to_end_and_fixes_the_line() {
        let (a, b) = (p(0.1, 0.2, 0.3), p(-0.4, 0.1, 0.0));
        let t = Isometry::translation(&Segment::new(a, b).unwrap()).unwrap();
        assert!((t.apply(&a).coords() - b.coords()).length() < 1e-14);
        assert!(t.preserves_orientation());
        // Transvection along AB equals the Möbius conjugate tau_A tau_w tau_{-A}.
        let ta = Isometry::transvection_from_origin(a);
        let w = ta.inverse().apply(&b);
        let alt = ta
            .compose(&Isometry::transvection_from_origin(w))
            .compose(&ta.inverse());
        let probe = p(0.3, -0.3, 0.2);
        assert!((t.apply(&probe).coords() - alt.apply(&probe).coords()).length() < 1e-14);
    }

    #[test]
    fn rotation_about_the_y_axis_follows_the_right_hand_rule() {
        let axis = Segment::new(Point::ORIGIN, p(0.0, 0.1, 0.0)).unwrap();
        let rot = Isometry::rotation_about_segment_unchecked(&axis, std::f64::consts::FRAC_PI_2);
        // Right-hand rule about +y takes +z to +x.
        let img = rot.apply(&p(0.0, 0.0, 0.5));
        assert!((img.coords() - DVec3::new(0.5, 0.0, 0.0)).length() < 1e-15);
    }

    #[test]
    fn rotation_fixes_its_axis_and_preserves_distances() {
        let axis = Segment::new(p(0.2, 0.1, 0.0), p(-0.1, 0.4, 0.3)).unwrap();
        let rot = Isometry::rotation_about_segment_unchecked(&axis, 1.234);
        for q in [axis.start(), axis.end()] {
            assert!((rot.apply(&q).coords() - q.coords()).length() < 1e-14);
        }
        let (x, y) = (p(0.5, 0.1, -0.2), p(-0.3, -0.3, 0.6));
        let before = distance(&x, &y);
        let after = distance(&rot.apply(&x), &rot.apply(&y));
        assert!((before - after).abs() < 1e-13);
    }

    #[test]
    fn inverse_undoes() {
        let axis = Segment::new(p(0.2, 0.1, 0.0), p(-0.1, 0.4, 0.3)).unwrap();
        let m = Isometry::rotation_about_segment_unchecked(&axis, 0.7).compose(
            &Isometry::translation(&Segment::new(p(0.0, 0.0, 0.0), p(0.0, 0.0, 0.16)).unwrap())
                .unwrap(),
        );
        let x = p(0.5, 0.1, -0.2);
        let back = m.inverse().apply(&m.apply(&x));
        assert!((back.coords() - x.coords()).length() < 1e-14);
        let id = m.compose(&m.inverse());
        assert!(id.translation_part().coords().length() < 1e-14);
        assert!((id.linear_part() - DMat3::IDENTITY).abs_diff_eq(DMat3::ZERO, 1e-14));
    }
}
