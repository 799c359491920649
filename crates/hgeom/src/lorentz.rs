//! The hyperboloid (Lorentz) model: `R^{3,1}` with the time coordinate in `w`.
//!
//! Points of H^3 are future vectors with `<X,X> = -1`; tangent vectors at `X`
//! satisfy `<X,V> = 0` and the form is positive definite on them, so angles,
//! reflection and refraction in a tangent space are plain Euclidean formulas
//! with `<.,.>`. h-planes are `{X : <X,N> = 0}` for a unit spacelike `N`.

use glam::DVec4;

/// The Lorentz form `<a,b> = a.x b.x + a.y b.y + a.z b.z - a.w b.w`.
///
/// # Accuracy
///
/// Plain f64: absolute error at most about `4 eps |a| |b|` (Euclidean
/// lengths). When the result is much smaller than `|a| |b|` (points far
/// from the origin, where `<X,X> = -1` with `|X|^2 ~ e^{2d}`) that is a
/// large relative error; hgeom avoids such products or forms them from
/// differences (see `docs/geometry.md`).
#[inline]
pub fn dot(a: DVec4, b: DVec4) -> f64 {
    a.x * b.x + a.y * b.y + a.z * b.z - a.w * b.w
}

/// Lorentz norm of a spacelike vector, `sqrt(<v,v>)`; 0 for non-spacelike input.
///
/// # Accuracy
///
/// `sqrt` of [`dot`]`(v, v)`: absolute error of `<v,v>` about
/// `4 eps |v|^2`, so accurate to a few ulps when `|v|` is of the order of
/// the norm itself (tangent vectors near the origin), and meaningless once
/// `eps |v|^2` approaches `<v,v>` (normals of h-planes beyond distance ~18
/// from the origin).
#[inline]
pub fn norm(v: DVec4) -> f64 {
    // Not a silent clamp: 0 is the documented answer for a null or timelike
    // vector, and every caller treats it as a failure (`HPlane::from_normal`
    // returns `BadDirection`, `direction_towards` returns `None`, the polygon
    // and plane constructors report `Collinear`/`Coincident`, normals fall
    // back explicitly). For spacelike input <v,v> > 0 in exact arithmetic.
    dot(v, v).max(0.0).sqrt()
}

/// `<u,v>` for tangent vectors `u`, `v` at the point `x` of the
/// hyperboloid, from their space parts alone:
/// `(u.v + (x × u).(x × v)) / x_w^2`.
///
/// For a tangent `u_w = x.u / x_w`, so `<u,v> = u.v - (x.u)(x.v) / x_w^2`,
/// and with `x_w^2 = 1 + |x|^2` and the Binet-Cauchy identity
/// `|x|^2 u.v - (x.u)(x.v) = (x × u).(x × v)` it is the form above.
///
/// # Accuracy
///
/// [`dot`] of tangents at a point `d` from the origin cancels
/// `e^{2d}`-sized terms (absolute error `eps cosh^2 d`: 4e-5 at 14, where a
/// mirror bounce then loses its angle); here the only cancellation is in
/// the cross products, whose error `eps |x| |u|` is the rounding of `u`
/// across `x` itself, so the result is within a few `eps` plus that
/// rounding of the exact product of the given space parts
/// (`a_thousand_bounces_in_a_mirror_sphere_of_radius_14` in
/// `tests/stable_rays.rs`). The time parts of `u` and `v` are not read.
#[inline]
pub fn tangent_dot(x: DVec4, u: DVec4, v: DVec4) -> f64 {
    let (xs, us, vs) = (x.truncate(), u.truncate(), v.truncate());
    (us.dot(vs) + xs.cross(us).dot(xs.cross(vs))) / (x.w * x.w)
}

/// The unit tangent at the point `x` of the hyperboloid whose space part
/// is along that of `v` (its time part is set by `<x,v> = 0`, the length
/// by [`tangent_dot`]); `None` for a zero or non-finite result.
///
/// # Accuracy
///
/// As [`tangent_dot`]: unit in the tangent form to a few `eps` plus the
/// rounding of its space part across `x` (about `eps cosh d` at a point
/// `d` from the origin: 2.5e-12 at 14, `tangent_products_at_a_far_point`
/// in this module), where dividing by [`norm`] would leave it
/// `eps cosh^2 d` off unit (4e-5 at 14).
#[inline]
pub fn unit_tangent_at(x: DVec4, v: DVec4) -> Option<DVec4> {
    let vs = v.truncate();
    let t = vs.extend(x.truncate().dot(vs) / x.w);
    let len = tangent_dot(x, t, t).sqrt();
    (len > 0.0 && len.is_finite()).then(|| t / len)
}

/// A vector Lorentz-orthogonal to `a`, `b` and `c` (the 4-D cross product
/// with the time sign flipped). It is zero iff the three are linearly dependent.
///
/// Its Lorentz products with `a`, `b` and `c` vanish, and its orientation
/// follows the right-hand rule used by [`HPlane::through`](crate::HPlane::through).
///
/// # Accuracy
///
/// Each component is a 3x3 minor expanded in plain f64: absolute error about
/// `10 eps |a| |b| |c|`. Callers pass small, well-conditioned vectors (points
/// moved near the origin first, differences of nearby points) so that this
/// is a small relative error (`complement_is_orthogonal_to_all_three` in
/// this module: products below 1e-15).
pub fn orthogonal_complement(a: DVec4, b: DVec4, c: DVec4) -> DVec4 {
    // Euclidean generalised cross product: cofactor expansion of det[e; a; b; c].
    let m_xy = b.x * c.y - b.y * c.x;
    let m_xz = b.x * c.z - b.z * c.x;
    let m_xw = b.x * c.w - b.w * c.x;
    let m_yz = b.y * c.z - b.z * c.y;
    let m_yw = b.y * c.w - b.w * c.y;
    let m_zw = b.z * c.w - b.w * c.z;
    let e = DVec4::new(
        a.y * m_zw - a.z * m_yw + a.w * m_yz,
        -(a.x * m_zw - a.z * m_xw + a.w * m_xz),
        a.x * m_yw - a.y * m_xw + a.w * m_xy,
        -(a.x * m_yz - a.y * m_xz + a.z * m_xy),
    );
    // Euclidean-orthogonal e becomes Lorentz-orthogonal after flipping time.
    DVec4::new(e.x, e.y, e.z, -e.w)
}

/// The inverse of a Lorentz matrix: `J Lᵀ J` with `J = diag(1, 1, 1, -1)`.
pub(crate) fn inverse(l: glam::DMat4) -> glam::DMat4 {
    let j = glam::DMat4::from_diagonal(DVec4::new(1.0, 1.0, 1.0, -1.0));
    j * l.transpose() * j
}

/// The Lorentz matrix of the reflection `X -> X - 2 <X,n> n` in the plane
/// with unit spacelike normal `n`.
pub(crate) fn reflection_matrix(n: DVec4) -> glam::DMat4 {
    // Column j is the image of e_j: e_j - 2 <e_j,n> n, with <e_j,n> = n_j
    // for space and -n_w for time.
    let jn = DVec4::new(n.x, n.y, n.z, -n.w);
    glam::DMat4::from_cols(
        DVec4::X - 2.0 * jn.x * n,
        DVec4::Y - 2.0 * jn.y * n,
        DVec4::Z - 2.0 * jn.z * n,
        DVec4::W - 2.0 * jn.w * n,
    )
}

/// Restores `<O,O> = -1`, `<D,D> = 1`, `<O,D> = 0` for a point and a
/// tangent there after rounding (either may carry any positive scale).
#[inline]
pub(crate) fn renormalise(o: &mut DVec4, d: &mut DVec4) {
    *o /= (-dot(*o, *o)).sqrt();
    *d += dot(*o, *d) * *o;
    *d /= dot(*d, *d).sqrt();
}

/// Distance between two hyperboloid points. Uses `2 asinh(|X-Y|_L / 2)`, which
/// is well conditioned for small distances where `acosh(-<X,Y>)` is not.
///
/// # Accuracy
///
/// The difference `X - Y` is formed exactly enough for nearby points, but
/// its Lorentz square has absolute error about `4 eps |X - Y| (|X| + |Y|)`:
/// relative error about `eps (|X| + |Y|)^2` for the distance, a few ulps
/// near the origin and useless beyond distance ~18. For ball points use
/// [`Point::distance`](crate::Point::distance), which is accurate everywhere.
#[inline]
pub fn distance(x: DVec4, y: DVec4) -> f64 {
    Separation::between(x, y).distance()
}

/// Half the Lorentz separation of two hyperboloid points,
/// `h = |X - Y|_L / 2 = sinh(d/2)`, and the functions of their distance `d`
/// that follow from it by algebra: a point light's shading needs the
/// distance, its hyperbolic tangent and `sinh^2 d`, and this gives them for
/// one logarithm instead of four transcendental calls.
///
/// # Accuracy
///
/// `h` as in [`distance`]; each function of it is a few ulps relative, as
/// every term of its formula is positive (no cancellation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Separation {
    half: f64,
    /// `sqrt(1 + h^2) = cosh(d/2)`, which the distance and the tangent
    /// both need (infinite past `h ~ 1e154`, where neither uses it).
    cosh_half: f64,
}

impl Separation {
    /// The separation of `x` and `y`.
    #[inline]
    pub fn between(x: DVec4, y: DVec4) -> Separation {
        Separation::of_half(0.5 * norm(x - y))
    }

    #[inline]
    fn of_half(half: f64) -> Separation {
        Separation {
            half,
            cosh_half: (1.0 + half * half).sqrt(),
        }
    }

    /// `sinh(d/2)`.
    #[inline]
    pub fn sinh_half(self) -> f64 {
        self.half
    }

    /// The distance `d = 2 asinh h`, with
    /// `asinh h = log1p(h + h^2 / (1 + sqrt(1 + h^2)))` (as
    /// `h + sqrt(1 + h^2) - 1 = h + h^2 / (1 + sqrt(1 + h^2))`): `f64::asinh`
    /// to a few ulps, without the `hypot` it calls (which costs as much as
    /// the logarithm). Past `h = 1e150`, where `h^2` would overflow,
    /// `asinh h = ln 2h` to far below an ulp.
    #[inline]
    pub fn distance(self) -> f64 {
        let h = self.half;
        let asinh = if h > 1e150 {
            h.ln() + std::f64::consts::LN_2
        } else {
            (h + h * h / (1.0 + self.cosh_half)).ln_1p()
        };
        2.0 * asinh
    }

    /// `tanh d = 2 sinh(d/2) cosh(d/2) / (cosh^2(d/2) + sinh^2(d/2))
    /// = 2 h sqrt(1 + h^2) / (1 + 2 h^2)`, at most 1; past `h = 1e150`
    /// (`d` near 692), where the products would overflow, it is 1 in `f64`.
    #[inline]
    pub fn tanh(self) -> f64 {
        let h = self.half;
        if h > 1e150 {
            return 1.0;
        }
        (2.0 * h * self.cosh_half / (1.0 + 2.0 * h * h)).min(1.0)
    }

    /// `sinh^2 d = 4 h^2 (1 + h^2)`: the area of the sphere of radius `d`
    /// over `4 pi`.
    #[inline]
    pub fn sinh_squared(self) -> f64 {
        let h = self.half;
        4.0 * h * h * (1.0 + h * h)
    }
}

/// The unit tangent vector at `x` pointing along the geodesic towards `y`,
/// with the distance between them. `None` if they coincide numerically.
///
/// # Accuracy
///
/// The tangent is formed from the difference `d = y - x` as
/// `d + <x,d> x` (no cancellation between `y` and `<x,y> x`), then
/// normalised by its computed Lorentz norm: direction and unit length to
/// about `eps |X|^2 / sinh d(x,y)`. Accurate near the origin; the tangent
/// of a short segment far out inherits the rounding of `X` and `Y`
/// (`orthogonal_plane_contains_start` in `plane.rs`).
pub fn direction_towards(x: DVec4, y: DVec4) -> Option<(DVec4, f64)> {
    unit_tangent_towards(x, y).map(|t| (t, distance(x, y)))
}

/// [`direction_towards`] without the distance, for hot paths (surface
/// normals) that need only the tangent. Same accuracy.
#[inline]
pub fn unit_tangent_towards(x: DVec4, y: DVec4) -> Option<DVec4> {
    // Component of y orthogonal to x: y + <x,y> x. Written via the difference
    // d = y - x as d + <x,d> x (since <x,x> = -1), which avoids cancellation
    // for nearby points.
    let d = y - x;
    let t = d + dot(x, d) * x;
    let len = norm(t);
    (len > 0.0 && len.is_finite()).then(|| t / len)
}

/// The point at arc length `t` along the geodesic from `x` with unit tangent `v`.
///
/// # Accuracy
///
/// `cosh t x + sinh t v`: absolute error about `eps e^|t| (|x| + |v|)` per
/// component (see [`Ray::at`](crate::Ray::at)).
#[inline]
pub fn geodesic_point(x: DVec4, v: DVec4, t: f64) -> DVec4 {
    t.cosh() * x + t.sinh() * v
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At a point 14 out along `n` the radial unit tangent `(cosh 14 n,
    /// sinh 14)` and a transverse one `(u, 0)`: [`tangent_dot`] gives the
    /// unit lengths to 1e-15, their product to the rounding of the radial
    /// one across `x` (`eps cosh 14`), and [`unit_tangent_at`] a unit tangent
    /// (where [`dot`] is off by the rounding of `cosh^2 14`); near the
    /// origin it agrees with [`dot`].
    #[test]
    fn tangent_products_at_a_far_point() {
        let n = DVec4::new(0.48, -0.64, 0.6, 0.0);
        let u = DVec4::new(0.8, 0.6, 0.0, 0.0);
        for d in [0.3, 14.0] {
            let (c, s) = (f64::cosh(d), f64::sinh(d));
            let x = s * n + c * DVec4::W;
            let radial = c * n + s * DVec4::W;
            assert!((tangent_dot(x, radial, radial) - 1.0).abs() < 1e-15);
            assert!((tangent_dot(x, u, u) - 1.0).abs() < 1e-15);
            // The rounding of `radial` across `x`: `eps cosh d`, relative.
            assert!(tangent_dot(x, radial, u).abs() < 1e-15 * c);
            let v = unit_tangent_at(x, 3.0 * radial + u).unwrap();
            // Measured 2.5e-12 at 14: the cross products' rounding again.
            assert!((tangent_dot(x, v, v) - 1.0).abs() < 1e-15 * c);
            if d < 1.0 {
                let w = 0.2 * radial + u;
                assert!((tangent_dot(x, w, w) - dot(w, w)).abs() < 1e-15);
            }
        }
    }

    /// The separation's distance and tangent agree with the library's
    /// `asinh` and `tanh` to a few ulps, from coincident points to the far
    /// end of `f64` (the algebra has no cancellation to lose them to).
    #[test]
    fn separation_functions_match_the_transcendental_ones() {
        let mut h = 1e-300;
        while h < 1e300 {
            for h in [h, h * 1.3, h * 2.9] {
                let s = Separation::of_half(h);
                let d = 2.0 * h.asinh();
                assert!((s.distance() - d).abs() <= 4.0 * f64::EPSILON * d, "h {h}");
                let t = d.tanh();
                assert!((s.tanh() - t).abs() <= 4.0 * f64::EPSILON * t, "h {h}");
                // `sinh` of the rounded `d` carries `d`'s rounding times
                // `d` (its condition number), twice over when squared.
                let sinh = d.sinh();
                if (sinh * sinh).is_finite() && sinh > 1e-150 {
                    let sq = sinh * sinh;
                    let tol = (8.0 + 4.0 * d) * f64::EPSILON * sq;
                    assert!((s.sinh_squared() - sq).abs() <= tol, "h {h}");
                }
            }
            h *= 10.0;
        }
        let s = Separation::between(DVec4::W, DVec4::W);
        assert_eq!((s.distance(), s.tanh(), s.sinh_squared()), (0.0, 0.0, 0.0));
        let far = Separation::of_half(f64::MAX);
        assert_eq!(far.tanh(), 1.0);
        // `ln 2h`, where `f64::asinh` itself overflows to infinity.
        let ln_2h = f64::MAX.ln() + std::f64::consts::LN_2;
        assert!((far.distance() - 2.0 * ln_2h).abs() < 1e-12);
    }

    #[test]
    fn complement_is_orthogonal_to_all_three() {
        let a = DVec4::new(0.1, 0.2, 0.3, 1.2);
        let b = DVec4::new(-0.4, 0.1, 0.0, 1.1);
        let c = DVec4::new(0.3, -0.5, 0.7, 1.5);
        let n = orthogonal_complement(a, b, c);
        for v in [a, b, c] {
            assert!(dot(n, v).abs() < 1e-15, "{}", dot(n, v));
        }
        assert!(n.length() > 0.1);
    }

    #[test]
    fn complement_of_dependent_vectors_is_zero() {
        let a = DVec4::new(0.1, 0.2, 0.3, 1.2);
        let b = DVec4::new(-0.4, 0.1, 0.0, 1.1);
        assert!(orthogonal_complement(a, b, a + b).length() < 1e-15);
    }
}
