//! The quadratic behind every curved surface: along a ray, `-<X(t),C>` for a
//! fixed vector `C` is `a cosh t + b sinh t`, so a level set becomes a
//! quadratic in `u = e^t` (or in `e^{2t}` for the equidistant surface).

use glam::DVec4;

use crate::ray::{Hit, Ray};

/// The roots `u_near <= u_far` of `alpha u^2 - 2 k u + beta = 0`, returned as
/// `(ln u_near, ln u_far)`, for `alpha, beta >= 0` and `k > 0`.
///
/// Uses the cancellation-free pair `u_near = beta / (k + sqrt(disc))`,
/// `u_far = (k + sqrt(disc)) / alpha`; `alpha = 0` (the ray heads for an
/// ideal point of the surface) gives `u_far = inf` and `beta = 0` gives
/// `u_near = 0`, so the logs are `+-inf`, never NaN. A zero discriminant
/// (a tangent ray) gives the double root; a negative one, `None`.
#[inline]
pub(crate) fn exp_roots(alpha: f64, k: f64, beta: f64) -> Option<(f64, f64)> {
    exp_roots_lazy(alpha, k, beta).map(|r| (r.near(), r.far()))
}

/// [`exp_roots`] before its logarithms: each is taken only when asked for,
/// with the same arithmetic, so a caller that needs only the near root
/// pays one logarithm and gets the same bits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ExpRoots {
    alpha: f64,
    beta: f64,
    big: f64,
}

impl ExpRoots {
    /// `ln u_near`.
    #[inline]
    pub(crate) fn near(&self) -> f64 {
        (self.beta / self.big).ln()
    }

    /// `ln u_far`.
    #[inline]
    pub(crate) fn far(&self) -> f64 {
        (self.big / self.alpha).ln()
    }

    /// [`first_in_range`] of the two roots, taking the far one's logarithm
    /// only if the near one is not past `t_min`, and neither where its
    /// root is plainly not past `t_min` ([`plainly_not_past`]): a shadow
    /// ray leaving a sphere has both roots at or behind its start, and
    /// needed two logarithms to say so.
    #[inline]
    pub(crate) fn first_in_range(&self, t_min: f64, t_max: f64) -> Option<f64> {
        let (u_near, u_far) = self.exp();
        if !plainly_not_past(u_near, t_min) {
            let near = u_near.ln();
            if near > t_min {
                return (near < t_max).then_some(near);
            }
        }
        if plainly_not_past(u_far, t_min) {
            return None;
        }
        let far = u_far.ln();
        (far > t_min && far < t_max).then_some(far)
    }
}

/// True only if `ln u <= t_min`, decided without the logarithm; false
/// where that takes it. For `|t_min| <= 1e-6`,
/// `1 + t_min <= e^{t_min}` (and `1 + t_min` rounds by an ulp of 1), so
/// `u < 1 + t_min - 1e-15` puts `ln u` at least `8e-16` below `t_min`,
/// far more than the error of a logarithm near `t_min` (an ulp of
/// `1e-6`): the logarithm would say the same.
#[inline]
fn plainly_not_past(u: f64, t_min: f64) -> bool {
    t_min.abs() <= 1e-6 && u < (1.0 + t_min) - 1e-15
}

/// [`exp_roots`] with the logarithms left to the caller.
#[inline]
pub(crate) fn exp_roots_lazy(alpha: f64, k: f64, beta: f64) -> Option<ExpRoots> {
    let disc = k * k - alpha * beta;
    if !(disc >= 0.0) {
        return None;
    }
    let big = k + disc.sqrt();
    if !(big > 0.0) {
        return None;
    }
    Some(ExpRoots { alpha, beta, big })
}

impl ExpRoots {
    /// The roots themselves, `(u_near, u_far)`, without logarithms.
    #[inline]
    pub(crate) fn exp(&self) -> (f64, f64) {
        (self.beta / self.big, self.big / self.alpha)
    }
}

/// The hit at arc length `t`, with the surface's normal there.
#[inline]
pub(crate) fn hit_at(ray: &Ray, t: f64, normal_at: impl Fn(DVec4) -> DVec4) -> Hit {
    let point = ray.at(t);
    Hit::on_surface(t, point, normal_at(point))
}

/// The hit at the first of the two roots inside `(t_min, t_max)`, with the
/// surface's normal there: what every `e^t`-quadric's `intersect` returns.
#[inline]
pub(crate) fn hit_at_first_root(
    ray: &Ray,
    roots: (f64, f64),
    t_min: f64,
    t_max: f64,
    normal_at: impl Fn(DVec4) -> DVec4,
) -> Option<Hit> {
    let t = first_in_range(roots.0, roots.1, t_min, t_max)?;
    Some(hit_at(ray, t, normal_at))
}

/// The first of the two roots strictly inside `(t_min, t_max)`.
#[inline]
pub(crate) fn first_in_range(near: f64, far: f64, t_min: f64, t_max: f64) -> Option<f64> {
    let t = if near > t_min {
        near
    } else if far > t_min {
        far
    } else {
        return None;
    };
    (t < t_max).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`ExpRoots::first_in_range`] as it was, with both logarithms.
    fn first_in_range_by_logs(r: &ExpRoots, t_min: f64, t_max: f64) -> Option<f64> {
        first_in_range(r.near(), r.far(), t_min, t_max)
    }

    /// The shortcut never changes an answer: roots placed just before,
    /// at and after the arc's start (to a few ulps), for the starts the
    /// renderer uses and others.
    #[test]
    fn roots_behind_the_start_are_passed_over_as_the_logarithms_would() {
        let mut rng = hscene_test_support::SplitMix64::new(3);
        let mut skipped = 0;
        for case in 0..200_000 {
            let t_min = [0.0, 1e-9, -1e-9, 1e-6, 2e-6, 0.3][case % 6];
            let near_root = |rng: &mut hscene_test_support::SplitMix64| match rng.next_u64() % 4 {
                0 => t_min + rng.range(-1e-15, 1e-15),
                1 => t_min * (1.0 + rng.range(-1e-12, 1e-12)),
                2 => rng.range(-3.0, 3.0),
                _ => rng.range(-1e-12, 1e-12),
            };
            let (mut a, mut b) = (near_root(&mut rng), near_root(&mut rng));
            if a > b {
                std::mem::swap(&mut a, &mut b);
            }
            // alpha u² - 2 k u + beta with roots e^a, e^b.
            let (ua, ub) = (a.exp(), b.exp());
            let alpha = rng.range(0.1, 10.0);
            let (k, beta) = (0.5 * alpha * (ua + ub), alpha * ua * ub);
            let Some(r) = exp_roots_lazy(alpha, k, beta) else {
                continue;
            };
            let t_max = [f64::INFINITY, 0.5, t_min][case % 3];
            assert_eq!(
                r.first_in_range(t_min, t_max),
                first_in_range_by_logs(&r, t_min, t_max),
                "case {case}: roots {a}, {b}, t_min {t_min}"
            );
            let (un, uf) = r.exp();
            skipped += usize::from(plainly_not_past(un, t_min) || plainly_not_past(uf, t_min));
        }
        assert!(skipped > 10_000, "{skipped}");
    }

    #[test]
    fn roots_solve_the_quadratic() {
        let (alpha, k, beta) = (2.0, 3.0, 1.5);
        let (n, f) = exp_roots(alpha, k, beta).unwrap();
        for t in [n, f] {
            let u = t.exp();
            assert!((alpha * u * u - 2.0 * k * u + beta).abs() < 1e-14);
        }
        assert!(n < f);
    }

    #[test]
    fn degenerate_coefficients_give_infinities_not_nan() {
        let (n, f) = exp_roots(0.0, 1.0, 1.0).unwrap();
        assert_eq!(f, f64::INFINITY);
        assert!((n - 0.5f64.ln()).abs() < 1e-15);
        let (n, _) = exp_roots(1.0, 1.0, 0.0).unwrap();
        assert_eq!(n, f64::NEG_INFINITY);
        assert!(exp_roots(1.0, 0.5, 1.0).is_none());
        assert!(exp_roots(f64::NAN, 1.0, 1.0).is_none());
    }
}
