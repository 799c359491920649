//! Möbius (gyrovector) addition in the unit ball, the algebra behind the
//! isometry representation.
//!
//! `u (+) v` is the image of `v` under the hyperbolic translation (transvection)
//! along the diameter through `u` that takes the origin to `u`. It is
//! non-commutative and non-associative; the defect is a rotation, the
//! *gyration* `gyr[u,v]`, with `u (+) (v (+) w) = (u (+) v) (+) gyr[u,v] w`.

use glam::{DMat3, DQuat, DVec3};

use crate::accurate::one_minus_norm_sq;
use crate::point::{IdealPoint, Point};

/// `u (+) v` on raw coordinates with their gaps; returns the sum and its gap.
///
/// `((1 + 2u.v + |v|^2) u + (1-|u|^2) v) / (1 + 2u.v + |u|^2|v|^2)`, with the
/// coefficient rewritten as `|u+v|^2 + gap_u` and the result's gap from the
/// exact identity `1 - |u(+)v|^2 = gap_u gap_v / D`. `v` may be ideal
/// (`gap_v = 0`): the result is then ideal too.
///
/// # Accuracy
///
/// The gap of the sum is a product and quotient of non-negative terms,
/// within a few ulps (relative) of the exact gap of the exact sum of the
/// given inputs (`gap_of_sum_is_exact_near_the_absolute` in this module;
/// `mobius_addition_matches_the_reference` in `tests/derivations.rs`). The
/// coordinates `((s + gap_u) u + gap_u v) / D` cancel when `u` and `v`
/// nearly annihilate far out (`v ~ -u`); their error, measured as
/// hyperbolic distance to the exact sum, is below
/// `10 eps (1/gap_u + 1/gap_v + 1/gap_sum)` (measured: 3.2 times that
/// scale at most, for inputs up to 12 from the origin, half of them nearly
/// cancelling): the hyperbolic size of a few coordinate ulps of the inputs
/// and of the result, which is all that rounded coordinates can resolve.
#[inline]
pub fn add_raw(u: DVec3, gap_u: f64, v: DVec3, gap_v: f64) -> (DVec3, f64) {
    let sum = u + v;
    let s = sum.length_squared();
    let d = s + gap_u * gap_v;
    let gap = gap_u * gap_v / d;
    // The sum as `u` plus its exact offset from `u`:
    // `((s + gap_u) u + gap_u v) / D - u = gap_u ((u + v) - gap_v u) / D`.
    let offset = gap_u * (sum - gap_v * u) / d;
    let coords = if 16.0 * offset.length_squared() < u.length_squared() {
        // The sum lies near `u` (a point moved 25 away lies next to the
        // translation's own point): the offset is small and formed to a few
        // ulps of itself, so the coordinates are rounded once, by the final
        // addition, where forming `s u + gap_u (u + v)` and dividing rounded
        // them 3-6 ulps (2e-5 of hyperbolic distance at 25;
        // `far_translation_rounds_once` in `tests/far.rs`).
        u + offset
    } else {
        // `(s + gap_u) u + gap_u v` written as `s u + gap_u (u + v)`: when
        // `u` and `v` nearly annihilate far out, `u + v` is formed exactly
        // (Sterbenz) and small, where `gap_u u + gap_u v` rounds both
        // products first and then cancels, and `u (+) -u` is exactly the
        // origin.
        (s * u + gap_u * sum) / d
    };
    (coords, gap)
}

/// [`add_raw`] for a point that will be used on the hyperboloid: where the
/// sum cancelled (it is nearer the origin than an input, `gap > 2 min(gap_u,
/// gap_v)`), the gap of the result's own coordinates instead of the
/// identity's.
///
/// There the coordinates carry the inputs' coordinate rounding, larger than
/// an ulp of the result, while the identity's gap carries their gaps; the
/// two disagree, and the hyperboloid image `(2x, 2 - g)/g` would leave the
/// sheet by `4 (g - g')/g^2` (sphere centres moved 25 away and back came out
/// 1e-6 .. 4e-5 off it). The coordinates' own gap keeps the point on the
/// sheet. Compositions keep the identity's gap ([`add_raw`]): it is the
/// point's extra precision there, and dropping it doubled the drift of long
/// chains of compositions (docs/geometry.md, section 4.1). The factor 2
/// keeps a sum with an input at the origin (`D` rounding just below 1) on
/// the identity.
///
/// # Accuracy
///
/// Position as [`add_raw`]; the gap within a few ulps where the identity's
/// is kept, else the coordinates' own (compensated), as accurate as the
/// position (`mobius_addition_matches_the_reference` in
/// `tests/derivations.rs`; `sum_far_and_back_is_on_the_sheet` in this
/// module).
#[inline]
pub fn add_raw_consistent(u: DVec3, gap_u: f64, v: DVec3, gap_v: f64) -> (DVec3, f64) {
    let (coords, gap) = add_raw(u, gap_u, v, gap_v);
    if gap_v > 0.0 && gap > 2.0 * gap_u.min(gap_v) {
        let own = one_minus_norm_sq(coords);
        if own > 0.0 {
            return (coords, own);
        }
    }
    (coords, gap)
}

/// Möbius addition of two h-points. The result's gap is exact up to rounding,
/// so precision survives even when the sum lands next to the absolute.
///
/// # Accuracy
///
/// As [`add_raw`]: gap within a few ulps, position within
/// `10 eps (1/gap_u + 1/gap_v + 1/gap_sum)` of the exact sum (hyperbolic
/// distance). The
/// result is not checked: a sum beyond distance ~37 fails
/// [`Point::is_representable`].
#[inline]
pub fn add(u: &Point, v: &Point) -> Point {
    let (c, g) = add_raw_consistent(u.coords(), u.gap(), v.coords(), v.gap());
    Point::new_unchecked(c, g)
}

/// Möbius addition of an h-point and an ideal point: the image of the ideal
/// point under the transvection taking the origin to `u`.
///
/// # Accuracy
///
/// The direction is [`add_raw`] with `gap_v = 0`, renormalised: within a
/// few ulps plus about `eps / gap_u` radians of the exact image (the
/// angular size, seen from the origin, of one coordinate ulp of `u`).
pub fn add_ideal(u: &Point, v: &IdealPoint) -> IdealPoint {
    let (c, _) = add_raw(u.coords(), u.gap(), v.coords(), 0.0);
    // c is a unit vector up to rounding; from_direction renormalises. It
    // fails only for a zero or non-finite c, which needs non-finite input
    // (|c| = 1 exactly in exact arithmetic, and |c|^2 D rounds nowhere near
    // 0 since D >= gap_u^2 > 0); the fallback is unreachable for points that
    // satisfy their invariants.
    IdealPoint::from_direction(c).unwrap_or(*v)
}

/// The gyration `gyr[u,v]` as a rotation matrix (an element of SO(3)).
///
/// In the plane of `u` and `v` Möbius addition is complex: `u (+) v =
/// (u+v)/(1 + conj(u) v)`, so `gyr[u,v] = conj(z)/z` with `z = 1 + conj(u) v`,
/// a rotation by `-2 arg z` about `u x v`. As a quaternion that is
/// `(1 + u.v, -(u x v))`, normalised. With `2(1 + u.v) = |u+v|^2 + gap_u + gap_v`
/// (a sum of non-negative terms) this stays accurate where Ungar's matrix form
/// `I + (2/D)(u a^T + v b^T)` cancels catastrophically (far, nearly opposite
/// `u` and `v`), and the result is orthogonal by construction.
///
/// # Accuracy
///
/// Orthogonal with determinant 1 to a few ulps whatever the inputs. The
/// rotation angle `2 atan2(|u x v|, 1 + u.v)` is accurate to a few ulps of
/// `|u x v| / (1 + u.v)`; its absolute error is about
/// `eps (1/gap_u + 1/gap_v)` in the worst case (far, nearly opposite
/// arguments), the angular size of an input's coordinate ulp
/// (`gyration_matches_its_definition` in this module;
/// `gyration_is_the_complex_rotation` in `tests/derivations.rs`). A zero
/// quaternion (`u = -v` with both ideal) gives the identity.
pub fn gyration(u: DVec3, gap_u: f64, v: DVec3, gap_v: f64) -> DMat3 {
    let w = 0.5 * ((u + v).length_squared() + gap_u + gap_v);
    let c = u.cross(v);
    let q = DQuat::from_xyzw(-c.x, -c.y, -c.z, w);
    let len = q.length();
    if len > 0.0 && len.is_finite() {
        DMat3::from_quat(q / len)
    } else {
        DMat3::IDENTITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64, z: f64) -> Point {
        Point::from_coords(DVec3::new(x, y, z)).unwrap()
    }

    #[test]
    fn identity_and_inverse() {
        let u = p(0.3, -0.4, 0.2);
        let z = Point::ORIGIN;
        assert!((add(&u, &z).coords() - u.coords()).length() < 1e-16);
        assert!((add(&z, &u).coords() - u.coords()).length() < 1e-16);
        let minus = Point::from_coords(-u.coords()).unwrap();
        assert!(add(&minus, &u).coords().length() < 1e-16);
    }

    #[test]
    fn left_cancellation() {
        let u = p(0.5, 0.1, -0.3);
        let v = p(-0.2, 0.6, 0.1);
        let minus_u = Point::from_coords(-u.coords()).unwrap();
        let back = add(&minus_u, &add(&u, &v));
        assert!((back.coords() - v.coords()).length() < 1e-15);
    }

    #[test]
    fn gyration_matches_its_definition() {
        // gyr[u,v] w = -(u (+) v) (+) (u (+) (v (+) w))
        let u = p(0.5, 0.1, -0.3);
        let v = p(-0.2, 0.6, 0.1);
        let w = p(0.1, 0.2, 0.3);
        let uv = add(&u, &v);
        let minus_uv = Point::from_coords(-uv.coords()).unwrap();
        let lhs = add(&minus_uv, &add(&u, &add(&v, &w)));
        let g = gyration(u.coords(), u.gap(), v.coords(), v.gap());
        assert!((g * w.coords() - lhs.coords()).length() < 1e-14);
        assert!((g.determinant() - 1.0).abs() < 1e-14);
        assert!((g * g.transpose() - DMat3::IDENTITY).abs_diff_eq(DMat3::ZERO, 1e-14));
    }

    #[test]
    fn gap_of_sum_is_exact_near_the_absolute() {
        // Two points at distance ~17.3 from the origin in the same direction:
        // the sum is at ~34.6, where 1 - |x| ~ 1e-15.
        let a = Point::at_distance_from_origin(DVec3::X, 17.3).unwrap();
        let s = add(&a, &a);
        let expect = Point::at_distance_from_origin(DVec3::X, 34.6).unwrap();
        assert!(((s.gap() - expect.gap()) / expect.gap()).abs() < 1e-13);
    }
}
