//! Fermi coordinates about the origin: three signed hyperbolic lengths that
//! name every h-point, the coordinates of solid textures.
//!
//! With hyperboloid coordinates `X = (x1, x2, x3; x0)` (time `x0`, see
//! [`Point::to_hyperboloid`]), the point with Fermi coordinates `(x, y, z)` is
//!
//! ```text
//! x1 = cosh z cosh y sinh x,  x2 = cosh z sinh y,  x3 = sinh z,
//! x0 = cosh z cosh y cosh x,
//! ```
//!
//! the image of the origin under `T_x(x) ∘ T_y(y) ∘ T_z(z)`, where `T_a(s)`
//! is the translation by `s` along the `a` axis (a boost in the `(x_a, x0)`
//! plane). Geometrically: `z` is the signed distance from the h-plane
//! `{x3 = 0}`; the foot of the perpendicular on that plane lies at signed
//! distance `y` from the `x` axis inside the plane; and `x` is the arc
//! length along the `x` axis to the foot of that second perpendicular. The
//! metric is `dz^2 + cosh^2 z dy^2 + cosh^2 z cosh^2 y dx^2`, so each
//! coordinate changes by at most the hyperbolic distance moved, and
//! translating along the `x` axis by `d` adds exactly `d` to `x`.
//!
//! Inverting, `z = asinh x3`, `y = asinh(x2 / cosh z)`,
//! `x = asinh(x1 / (cosh z cosh y))`, with `cosh z = sqrt(1 + x3^2)` and
//! `cosh z cosh y = sqrt(1 + x2^2 + x3^2)`.

use glam::DVec3;

use crate::point::Point;

/// The Fermi coordinates `(x, y, z)` of an h-point about the origin (see
/// the module docs): `z = asinh x3`, `y = asinh(x2 / cosh z)`,
/// `x = asinh(x1 / (cosh z cosh y))`, for the point's hyperboloid
/// coordinates `(x1, x2, x3) = 2p / (1 - |p|^2)`.
///
/// The spatial hyperboloid coordinates are formed from the ball coordinates
/// and the point's accurate gap (no `x0` is needed, and nothing cancels):
/// `cosh z = sqrt(1 + x3^2)` and `cosh z cosh y = sqrt(1 + x2^2 + x3^2)`.
/// Every representable point (distance up to ~37 from the origin) has
/// finite coordinates; a point that fails [`Point::is_representable`] may
/// give non-finite ones.
///
/// # Accuracy
///
/// Each coordinate within about 10 ulps (relative, component by
/// component, so a tiny coordinate keeps its relative precision next to
/// large ones) of the exact Fermi coordinates of the stored point: `2p/gap`
/// costs 2 roundings, the square roots and quotients a few more, and `asinh`
/// has condition number at most 1. The stored point itself is a rounding of
/// the one meant, by about `eps / gap` of hyperbolic distance, and no
/// coordinate moves by more than the distance moved
/// (`round_trip_from_coordinates`, `round_trip_from_points`,
/// `translation_along_x_adds_to_x` in this module).
///
/// ```
/// use glam::DVec3;
/// use hgeom::{Isometry, Point, fermi_coordinates};
/// // A point 1.5 along the x axis, then moved 0.7 along the x axis.
/// let p = Point::at_distance_from_origin(DVec3::X, 1.5).unwrap();
/// let c = fermi_coordinates(&p);
/// assert!((c - DVec3::new(1.5, 0.0, 0.0)).abs().max_element() < 1e-15);
/// let shift = Isometry::transvection_from_origin(
///     Point::at_distance_from_origin(DVec3::X, 0.7).unwrap(),
/// );
/// let moved = fermi_coordinates(&shift.apply(&p));
/// assert!((moved.x - 2.2).abs() < 1e-14);
/// // The point 0.4 above the plane {x3 = 0}, i.e. along the z axis.
/// let q = Point::at_distance_from_origin(DVec3::Z, 0.4).unwrap();
/// assert!((fermi_coordinates(&q) - DVec3::new(0.0, 0.0, 0.4)).length() < 1e-15);
/// ```
pub fn fermi_coordinates(p: &Point) -> DVec3 {
    let s = p.coords() * (2.0 / p.gap());
    let cosh_z = (1.0 + s.z * s.z).sqrt();
    let cosh_zy = (1.0 + s.y * s.y + s.z * s.z).sqrt();
    DVec3::new((s.x / cosh_zy).asinh(), (s.y / cosh_z).asinh(), s.z.asinh())
}

/// The h-point with Fermi coordinates `c = (x, y, z)` about the origin (the
/// inverse of [`fermi_coordinates`]): hyperboloid coordinates
/// `(cosh z cosh y sinh x, cosh z sinh y, sinh z; cosh z cosh y cosh x)`,
/// taken to the ball as `p = (x1, x2, x3) / (1 + x0)` with the exact gap
/// `2 / (1 + x0)`.
///
/// Not checked: a point farther from the origin than f64 can place in the
/// ball (`x0` beyond about `2/eps`, e.g. `|x| + |y| + |z|` above ~37) or a
/// non-finite `c` gives a point that fails [`Point::is_representable`];
/// check it where that can happen.
///
/// # Accuracy
///
/// Each ball coordinate within a few ulps (relative, component by
/// component) and the gap within a few ulps of the exact map; together with
/// [`fermi_coordinates`] the round trip returns `c` to 1e-13 relative per
/// component (`round_trip_from_coordinates` in this module).
///
/// ```
/// use glam::DVec3;
/// use hgeom::{Point, fermi_coordinates, from_fermi_coordinates};
/// let c = DVec3::new(0.3, -1.2, 2.5);
/// let p = from_fermi_coordinates(c);
/// assert!(p.is_representable());
/// assert!((fermi_coordinates(&p) - c).length() < 1e-14);
/// ```
pub fn from_fermi_coordinates(c: DVec3) -> Point {
    let (ch_z, ch_y) = (c.z.cosh(), c.y.cosh());
    let ch_zy = ch_z * ch_y;
    let x0 = ch_zy * c.x.cosh();
    let s = DVec3::new(ch_zy * c.x.sinh(), ch_z * c.y.sinh(), c.z.sinh());
    let denom = 1.0 + x0;
    Point::new_unchecked(s / denom, 2.0 / denom)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::isometry::Isometry;
    use proptest::prelude::*;

    fn config() -> ProptestConfig {
        ProptestConfig {
            // Never write regression files next to the sources.
            failure_persistence: None,
            ..ProptestConfig::with_cases(512)
        }
    }

    fn unit() -> impl Strategy<Value = DVec3> {
        (-1.0f64..=1.0, 0.0..std::f64::consts::TAU).prop_map(|(z, phi)| {
            let s = (1.0 - z * z).max(0.0).sqrt();
            DVec3::new(s * phi.cos(), s * phi.sin(), z)
        })
    }

    /// A coordinate: sign, and a magnitude spread over many scales (down to
    /// 1e-12) so tiny coordinates next to large ones are exercised.
    fn coordinate(max: f64) -> impl Strategy<Value = f64> {
        (any::<bool>(), -12.0f64..=max.log10()).prop_map(|(neg, e)| {
            let v = 10f64.powf(e);
            if neg { -v } else { v }
        })
    }

    fn rel_close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * a.abs().max(b.abs()) + 1e-300
    }

    #[test]
    fn the_axes_carry_their_own_coordinate() {
        for (axis, d) in [(DVec3::X, 2.0f64), (DVec3::Y, -0.3), (DVec3::Z, 7.5)] {
            let p = Point::at_distance_from_origin(axis * d.signum(), d.abs()).unwrap();
            let c = fermi_coordinates(&p);
            let expect = axis * d;
            assert!((c - expect).abs().max_element() <= 1e-14 * d.abs(), "{c}");
        }
        assert_eq!(fermi_coordinates(&Point::ORIGIN), DVec3::ZERO);
    }

    #[test]
    fn far_points_have_finite_coordinates() {
        let p = Point::at_distance_from_origin(DVec3::new(1.0, -2.0, 0.5), 37.0).unwrap();
        let c = fermi_coordinates(&p);
        assert!(c.is_finite());
        // |z| <= d, and the point is far from the origin in some coordinate.
        assert!(c.abs().max_element() <= 37.0 + 1e-12);
        assert!(c.abs().element_sum() >= 37.0 - 1e-9);
    }

    /// The cell convention the renderer's checker uses: the middle of the
    /// first cell has even parity.
    #[test]
    fn the_middle_of_the_first_cell_is_even() {
        let s = 0.25;
        let c = fermi_coordinates(&from_fermi_coordinates(DVec3::splat(0.5 * s)));
        let cell = (c / s).floor();
        assert_eq!(cell, DVec3::ZERO);
    }

    proptest! {
        #![proptest_config(config())]

        /// Coordinates -> point -> coordinates, component by component
        /// relative (a tiny coordinate keeps its precision).
        #[test]
        fn round_trip_from_coordinates(
            x in coordinate(12.0), y in coordinate(12.0), z in coordinate(12.0)
        ) {
            let c = DVec3::new(x, y, z);
            let p = from_fermi_coordinates(c);
            prop_assert!(p.is_representable());
            let back = fermi_coordinates(&p);
            for i in 0..3 {
                prop_assert!(rel_close(back[i], c[i], 1e-13), "{c} -> {back}");
            }
        }

        /// Point -> coordinates -> point: ball coordinates (per component)
        /// and the gap within 1e-13 relative, out to distance 30.
        #[test]
        fn round_trip_from_points(u in unit(), d in 0.0f64..30.0) {
            let p = Point::at_distance_from_origin(u, d).unwrap();
            let c = fermi_coordinates(&p);
            prop_assert!(c.is_finite());
            let q = from_fermi_coordinates(c);
            prop_assert!(q.is_representable());
            for i in 0..3 {
                prop_assert!(
                    rel_close(q.coords()[i], p.coords()[i], 1e-13),
                    "{:?} -> {c} -> {:?}", p, q
                );
            }
            prop_assert!(rel_close(q.gap(), p.gap(), 1e-13));
        }

        /// Translating by `d` along the x axis adds `d` to `x` and leaves
        /// `y` and `z` alone (`T_x(d) T_x(x) T_y(y) T_z(z) = T_x(x+d) ...`).
        /// Tolerance: the isometry's own rounding, about `10 eps / gap` for
        /// points and translations within 5 of the origin.
        #[test]
        fn translation_along_x_adds_to_x(
            x in -2.5f64..2.5, y in -2.5f64..2.5, z in -2.5f64..2.5, d in -5.0f64..5.0
        ) {
            let c = DVec3::new(x, y, z);
            let p = from_fermi_coordinates(c);
            let dir = if d < 0.0 { -DVec3::X } else { DVec3::X };
            let shift = Isometry::transvection_from_origin(
                Point::at_distance_from_origin(dir, d.abs()).unwrap(),
            );
            let moved = fermi_coordinates(&shift.apply(&p));
            let expect = DVec3::new(x + d, y, z);
            prop_assert!(
                (moved - expect).abs().max_element() <= 1e-11,
                "{c} moved by {d}: {moved}"
            );
        }

        /// Each coordinate changes by at most the distance moved (the
        /// metric `dz^2 + cosh^2 z dy^2 + cosh^2 z cosh^2 y dx^2`).
        #[test]
        fn coordinates_are_one_lipschitz(u in unit(), v in unit(), d in 0.0f64..6.0, e in 0.0f64..4.0) {
            let p = Point::at_distance_from_origin(u, d).unwrap();
            let q = Point::at_distance_from_origin(v, e).unwrap();
            let dist = crate::distance::distance(&p, &q);
            let diff = (fermi_coordinates(&p) - fermi_coordinates(&q)).abs();
            prop_assert!(diff.max_element() <= dist * (1.0 + 1e-12) + 1e-13, "{diff} > {dist}");
        }
    }
}
