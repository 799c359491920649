//! Predefined planar h-polygons: regular polygons (finite and ideal), and the
//! Lambert and Saccheri quadrilaterals.
//!
//! Every figure lies in the h-plane `z = 0` (a Euclidean plane through the
//! origin), is symmetric about the `y` axis or has a vertex at the origin as
//! documented, and is built from closed-form hyperbolic trigonometry, so the
//! only error is floating-point rounding (a few ulps of each coordinate).
//!
//! **Orientation.** Vertices run clockwise in the `xy` plane (seen from
//! `+z`, with `x` to the right and `y` up), so the polygon's normal (right-hand
//! rule on the vertex order, see [`ConvexPolygon`]) is `-z`: it faces a camera
//! on the `-z` side looking along `+z`, which is where the default camera
//! (at the origin, looking along `+z`) sees the figure once it has been
//! translated in front of it.

use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::ops::RangeInclusive;

use glam::{DVec3, DVec4};

use crate::error::{GeomError, positive_length};
use crate::point::{IdealPoint, Point, Vertex, representable};
use crate::polygon::ConvexPolygon;

/// The vertex counts the predefined regular polygons support (the thesis's
/// triangle, square, pentagon and hexagon).
pub const REGULAR_POLYGON_VERTICES: RangeInclusive<usize> = 3..=6;

fn check_count(n: usize) -> Result<(), GeomError> {
    if REGULAR_POLYGON_VERTICES.contains(&n) {
        Ok(())
    } else {
        Err(GeomError::VertexCountOutOfRange {
            got: n,
            min: *REGULAR_POLYGON_VERTICES.start(),
            max: *REGULAR_POLYGON_VERTICES.end(),
        })
    }
}

/// A hyperboloid vector (time in `w`) as a ball point, failing if it is not a
/// representable h-point.
pub(crate) fn from_hyperboloid_checked(x: DVec4) -> Result<Point, GeomError> {
    let p = Point::from_hyperboloid(x).ok_or(GeomError::NotInBall { norm: 1.0 })?;
    representable(p)
}

/// Unit directions of a regular `n`-gon's vertices in the `xy` plane: one edge
/// is horizontal at the bottom (so the pentagon and triangle point up and the
/// square is axis-aligned), and the order is clockwise (normal `-z`).
fn regular_directions(n: usize) -> Vec<DVec3> {
    let step = TAU / n as f64;
    let start = -FRAC_PI_2 - PI / n as f64;
    (0..n)
        .map(|k| {
            let angle = start - step * k as f64;
            DVec3::new(angle.cos(), angle.sin(), 0.0)
        })
        .collect()
}

/// The regular h-polygon with `n` vertices (`n` in
/// [`REGULAR_POLYGON_VERTICES`]) and hyperbolic circumradius `circumradius`,
/// centred at the origin in the plane `z = 0`.
///
/// Exact: the rotations about the `z` axis by `2π/n` fix the origin, so they
/// are hyperbolic isometries and the `n` points at hyperbolic distance
/// `circumradius` on equally spaced rays are the vertices of a regular
/// h-polygon. Its side `s` satisfies `sinh(s/2) = sinh(R) sin(π/n)`.
/// Vertices are accurate to a few ulps; one edge is parallel to the `x` axis
/// at the bottom; the normal is `-z` (see the module docs).
///
/// Errors: [`GeomError::VertexCountOutOfRange`], [`GeomError::BadRadius`] for
/// a non-positive or non-finite radius, [`GeomError::NotInBall`] when the
/// vertices are too far out for f64 (radius above ~37).
///
/// # Accuracy
///
/// Each vertex is [`Point::at_distance_from_origin`]: its distance from the
/// origin is the circumradius to 1e-14 relative, sides equal the closed form
/// `2 asinh(sinh R sin(π/n))` to 1e-13 relative and angles the regular
/// polygon's to 1e-12 (`regular_polygons_are_regular` in
/// `tests/figures.rs`).
///
/// ```
/// use hgeom::{regular_polygon, Vertex};
/// let pentagon = regular_polygon(5, 0.8).unwrap();
/// let Vertex::Interior(v) = pentagon.vertices()[0] else { unreachable!() };
/// assert!((v.distance_from_origin() - 0.8).abs() < 1e-15);
/// ```
pub fn regular_polygon(n: usize, circumradius: f64) -> Result<ConvexPolygon, GeomError> {
    check_count(n)?;
    positive_length(circumradius)?;
    let vertices = regular_directions(n)
        .into_iter()
        .map(|d| Point::at_distance_from_origin(d, circumradius).and_then(representable))
        .map(|p| p.map(Vertex::Interior))
        .collect::<Result<Vec<_>, _>>()?;
    ConvexPolygon::new(vertices)
}

/// The regular h-polygon with `n` vertices and hyperbolic side length `side`,
/// placed as in [`regular_polygon`].
///
/// The right triangle formed by the centre, a vertex and the midpoint of an
/// adjacent side has hypotenuse `R`, angle `π/n` at the centre and opposite
/// leg `side/2`, so `sinh R = sinh(side/2) / sin(π/n)`.
///
/// Errors: as [`regular_polygon`].
///
/// # Accuracy
///
/// As [`regular_polygon`]; the sides equal `side` to 1e-14
/// (`regular_polygon_by_side` in `tests/figures.rs`).
pub fn regular_polygon_with_side(n: usize, side: f64) -> Result<ConvexPolygon, GeomError> {
    check_count(n)?;
    positive_length(side)?;
    let circumradius = ((0.5 * side).sinh() / (PI / n as f64).sin()).asinh();
    regular_polygon(n, circumradius)
}

/// The ideal regular h-polygon with `n` vertices (`n` in
/// [`REGULAR_POLYGON_VERTICES`]): all vertices on the absolute, on the unit
/// circle of the plane `z = 0`, placed and oriented as in
/// [`regular_polygon`]. All its angles are 0.
///
/// Errors: [`GeomError::VertexCountOutOfRange`].
///
/// # Accuracy
///
/// The vertices are unit vectors to 1e-15 with `z = 0` exactly
/// (`ideal_polygons_have_vertices_on_the_absolute` in `tests/figures.rs`).
pub fn ideal_regular_polygon(n: usize) -> Result<ConvexPolygon, GeomError> {
    check_count(n)?;
    let vertices = regular_directions(n)
        .into_iter()
        .map(|d| IdealPoint::from_direction(d).map(Vertex::Ideal))
        .collect::<Result<Vec<_>, _>>()?;
    ConvexPolygon::new(vertices)
}

/// The Lambert quadrilateral (three right angles) with sides `a` and `b` at
/// its right-angled vertex `O` at the origin: `A` at distance `a` along `+x`,
/// `B` at distance `b` along `+y`, and the fourth vertex `C` where the
/// perpendiculars to `OA` at `A` and to `OB` at `B` meet. Vertex order
/// `O, B, C, A` (normal `-z`, see the module docs).
///
/// Derivation (Klein model, where geodesics are straight and a line
/// perpendicular to a diameter is perpendicular to it in the Euclidean sense):
/// the perpendiculars are `x = tanh a` and `y = tanh b`, so `C` has Klein
/// coordinates `(tanh a, tanh b)`; on the hyperboloid that is
/// `(sinh a cosh b, cosh a sinh b, 0, cosh a cosh b) / sqrt(1 - sinh²a sinh²b)`.
/// The point exists iff `tanh²a + tanh²b < 1`, i.e. iff `sinh a sinh b < 1`.
/// The acute angle `φ` at `C` satisfies `cos φ = sinh a sinh b`. Vertices are
/// accurate to a few ulps away from the limit `sinh a sinh b -> 1`, where `C`
/// runs off to the absolute and its position is inherently ill-conditioned.
///
/// Errors: [`GeomError::BadRadius`] for a non-positive or non-finite side,
/// [`GeomError::LambertOpen`] when `sinh a sinh b >= 1`,
/// [`GeomError::NotInBall`] when `C` is too far out for f64.
///
/// # Accuracy
///
/// The three right angles are right to 1e-12, `cos φ = sinh a sinh b` to
/// 1e-12, and the sides `OA`, `OB` are `a`, `b` to 1e-14 relative
/// (`lambert_quadrilateral_has_three_right_angles` in `tests/figures.rs`).
pub fn lambert_quadrilateral(a: f64, b: f64) -> Result<ConvexPolygon, GeomError> {
    positive_length(a)?;
    positive_length(b)?;
    let p = a.sinh() * b.sinh();
    if !(p < 1.0) {
        return Err(GeomError::LambertOpen { sinh_product: p });
    }
    // (1 - p)(1 + p) rather than 1 - p^2 keeps the small factor exact.
    let s = ((1.0 - p) * (1.0 + p)).sqrt();
    let (ca, cb) = (a.cosh(), b.cosh());
    let c = DVec4::new(a.sinh() * cb, ca * b.sinh(), 0.0, ca * cb) / s;
    let c = from_hyperboloid_checked(c)?;
    let va = representable(Point::at_distance_from_origin(DVec3::X, a)?)?;
    let vb = representable(Point::at_distance_from_origin(DVec3::Y, b)?)?;
    ConvexPolygon::new(vec![
        Vertex::Interior(Point::ORIGIN),
        Vertex::Interior(vb),
        Vertex::Interior(c),
        Vertex::Interior(va),
    ])
}

/// The Saccheri quadrilateral with base `base` and legs `leg`: the base is
/// centred at the origin on the `x` axis (ends `P± `at distance `base/2`
/// along `±x`), the legs are perpendicular to it at both ends, of length
/// `leg`, towards `+y`, and the summit joins their ends `Q±`. Vertex order
/// `P-, Q-, Q+, P+` (normal `-z`, see the module docs).
///
/// Derivation (hyperboloid, time in `w`): `P± = (±sinh(base/2), 0, 0,
/// cosh(base/2))`; the unit tangent at `P±` orthogonal to the base and in the
/// plane `z = 0` is `(0, 1, 0, 0)`, so the geodesic of length `leg` ends at
/// `Q± = cosh(leg) P± + sinh(leg) (0,1,0,0)`. The base angles are right by
/// construction; the reflection in the `y` axis swaps the legs, so the summit
/// angles are equal (and acute). Vertices are accurate to a few ulps.
///
/// Errors: [`GeomError::BadRadius`] for a non-positive or non-finite length,
/// [`GeomError::NotInBall`] when a vertex is too far out for f64.
///
/// # Accuracy
///
/// Base and legs have the given lengths to 1e-13 relative, the base angles
/// are right to 1e-12 and the summit angles equal to 1e-12
/// (`saccheri_quadrilateral_has_right_base_angles_and_equal_summit_angles`
/// in `tests/figures.rs`).
pub fn saccheri_quadrilateral(base: f64, leg: f64) -> Result<ConvexPolygon, GeomError> {
    positive_length(base)?;
    positive_length(leg)?;
    let half = 0.5 * base;
    let (sh, ch) = (half.sinh(), half.cosh());
    let (sl, cl) = (leg.sinh(), leg.cosh());
    let summit = |sign: f64| from_hyperboloid_checked(DVec4::new(sign * cl * sh, sl, 0.0, cl * ch));
    let p_minus = representable(Point::at_distance_from_origin(-DVec3::X, half)?)?;
    let p_plus = representable(Point::at_distance_from_origin(DVec3::X, half)?)?;
    ConvexPolygon::new(vec![
        Vertex::Interior(p_minus),
        Vertex::Interior(summit(-1.0)?),
        Vertex::Interior(summit(1.0)?),
        Vertex::Interior(p_plus),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_is_minus_z() {
        for n in REGULAR_POLYGON_VERTICES {
            let p = regular_polygon(n, 0.5).unwrap();
            assert!((p.plane().normal() - DVec4::new(0.0, 0.0, -1.0, 0.0)).length() < 1e-12);
            let q = ideal_regular_polygon(n).unwrap();
            assert!((q.plane().normal() - DVec4::new(0.0, 0.0, -1.0, 0.0)).length() < 1e-12);
        }
        for q in [
            lambert_quadrilateral(0.5, 0.7).unwrap(),
            saccheri_quadrilateral(0.5, 0.7).unwrap(),
        ] {
            assert!((q.plane().normal() - DVec4::new(0.0, 0.0, -1.0, 0.0)).length() < 1e-12);
        }
    }

    #[test]
    fn bottom_edge_is_horizontal() {
        for n in REGULAR_POLYGON_VERTICES {
            let d = regular_directions(n);
            assert!((d[0].y - d[n - 1].y).abs() < 1e-14, "{n}");
            assert!(d[0].y < 0.0 && d[0].x < 0.0);
        }
    }

    #[test]
    fn bad_inputs_are_typed_errors() {
        assert!(matches!(
            regular_polygon(7, 0.5),
            Err(GeomError::VertexCountOutOfRange { got: 7, .. })
        ));
        assert!(matches!(
            ideal_regular_polygon(2),
            Err(GeomError::VertexCountOutOfRange { got: 2, .. })
        ));
        assert_eq!(regular_polygon(3, -1.0), Err(GeomError::BadRadius(-1.0)));
        assert!(regular_polygon(3, f64::NAN).is_err());
        assert!(matches!(
            regular_polygon(3, 60.0),
            Err(GeomError::NotInBall { .. })
        ));
        assert!(saccheri_quadrilateral(0.0, 1.0).is_err());
    }
}
