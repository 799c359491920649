//! The arithmetic of one step of the honeycomb walk, kept apart from the
//! walk's bookkeeping.
//!
//! **A common scale.** The walk carries the ray's start and direction as
//! `(λ O, λ D)` with an unknown `λ >= 1` between renormalisations (each step
//! multiplies it by the `cosh τ` of the step). The exit ratios `a_i / b_i`
//! ignore it; the tube equation `c_1² + c_2² = sinh² w` with
//! `c_i = o_i cosh τ + v_i sinh τ` is homogeneous of degree 2 in
//! `(o, v, sinh w)`, and the ball's `α cosh τ + β sinh τ = cosh ρ` of degree
//! 1 in `(α, β, cosh ρ)`, so their roots are those of the unit ray once
//! `sinh² w` is multiplied by `λ² = -<λO,λO>` and `cosh ρ` by `λ`.

use std::hint::select_unpredictable;

use glam::{DMat4, DVec4};

use crate::klein_box::plain_max;
use crate::lorentz;
use crate::roots::exp_roots_lazy;

use super::domain_ray::MAX_WALLS;

pub(super) use crate::lorentz::inverse as lorentz_inverse;

/// `x - 2 <x,n> n`.
#[inline]
pub(super) fn reflect(x: DVec4, n: DVec4) -> DVec4 {
    x - 2.0 * lorentz::dot(x, n) * n
}

/// `M R` for the reflection `R` in the unit normal `n`:
/// `M (X - 2 <X,n> n) = M X - 2 (M n) (J n)ᵀ X`, a rank-one update.
#[inline]
pub(super) fn times_reflection(m: &DMat4, n: DVec4) -> DMat4 {
    let mn = 2.0 * (*m * n);
    DMat4::from_cols(
        m.x_axis - n.x * mn,
        m.y_axis - n.y * mn,
        m.z_axis - n.z * mn,
        m.w_axis + n.w * mn,
    )
}

pub(super) use crate::lorentz::renormalise;

/// The roots of `c_1(τ)² + c_2(τ)² = sinh² w` with
/// `c_i = o_i cosh τ + v_i sinh τ` (the tube), as values of `e^{2τ}`, from
/// [`HCylinder::roots`](crate::HCylinder::roots)'s quadratic.
#[inline]
pub(super) fn tube_roots(o: [f64; 2], v: [f64; 2], sinh2: f64) -> Option<(f64, f64)> {
    let p = [o[0] + v[0], o[1] + v[1]];
    let q = [o[0] - v[0], o[1] - v[1]];
    let a = p[0] * p[0] + p[1] * p[1];
    let c = q[0] * q[0] + q[1] * q[1];
    let pq = (o[0] * o[0] + o[1] * o[1]) - (v[0] * v[0] + v[1] * v[1]);
    let k = 2.0 * sinh2 - pq;
    if !(k > 0.0) {
        return None;
    }
    exp_roots_plain(a, k, c)
}

/// The first crossing beyond `floor`, as `v = e^{2τ}`, of the domain ray
/// `(o, d)` into the ball `-<X,c> = k` (`k` the ball's `cosh` radius
/// scaled by the ray's `λ`): `-<X(τ),c> = α cosh τ + β sinh τ` is a
/// quadratic in `e^τ`. `None` if the ray's line misses the ball.
#[inline]
pub(super) fn ball_first_v(o: DVec4, d: DVec4, c: DVec4, k: f64, floor: f64) -> Option<f64> {
    let alpha = -lorentz::dot(o, c);
    let beta = -lorentz::dot(d, c);
    let (near, far) = exp_roots_plain(alpha + beta, k, alpha - beta)?;
    let (near, far) = (near * near, far * far);
    Some(if near > floor { near } else { far })
}

/// The outward normal at `x` of the ball about `c` (tangent, not unit).
pub(super) fn ball_normal(c: DVec4, x: DVec4) -> DVec4 {
    -(c + lorentz::dot(c, x) * x)
}

/// The outward normal at `x` of the tube about the line orthogonal to the
/// orthonormal pair `n1`, `n2`: the gradient of `<X,n1>² + <X,n2>²` made
/// tangent at `x` (not unit).
pub(super) fn tube_normal(n1: DVec4, n2: DVec4, x: DVec4) -> DVec4 {
    let g = lorentz::dot(x, n1) * n1 + lorentz::dot(x, n2) * n2;
    g + lorentz::dot(g, x) * x
}

/// The bits of the walls through the point or ideal point `x` (timelike or
/// null, future), tested at time 1 so that the tolerance does not depend
/// on `x`'s scale.
pub(super) fn walls_through(x: DVec4, walls: &[DVec4]) -> u32 {
    let x = x / x.w;
    walls
        .iter()
        .enumerate()
        .filter(|(_, n)| lorentz::dot(x, **n).abs() < 1e-9)
        .fold(0, |bits, (i, _)| bits | (1 << i))
}

/// The roots `u_near <= u_far` of `alpha u² - 2 k u + beta = 0` for
/// `alpha, beta >= 0`, `k > 0`: [`exp_roots`] without the logarithms.
#[inline]
pub(super) fn exp_roots_plain(alpha: f64, k: f64, beta: f64) -> Option<(f64, f64)> {
    exp_roots_lazy(alpha, k, beta).map(|r| r.exp())
}

/// The wall a ray leaves its domain by, and `s = tanh τ` of that exit: the
/// least `s_i = max(a_i, 0) / -b_i` over the walls ahead (`b_i < 0`) but
/// `last` (the wall just crossed), if it is below 1, from the products
/// `a_i = <o, n_i>`, `b_i = <d, n_i>` of the first `walls` walls; the first
/// such wall on a tie.
///
/// Without branches: which wall is nearest changes from step to step, and
/// a branch per wall was mispredicted about three times per step, a
/// quarter of the walk's time. The quotients are independent, so the
/// divisions overlap.
#[inline(always)]
pub(super) fn nearest_exit(
    a: &[f64; MAX_WALLS],
    b: &[f64; MAX_WALLS],
    walls: usize,
    last: usize,
) -> Option<(usize, f64)> {
    // Non-negative floats order as their bits do, so the least quotient is
    // found in integers: `select_unpredictable` on integers compiles to
    // conditional moves, where a float selection would still branch.
    let mut least = 1.0f64.to_bits();
    let mut exit = usize::MAX;
    for i in 0..walls.min(MAX_WALLS) {
        // Rounding can leave the start a hair behind a wall
        // (a_i ~ -1e-17): that exit is immediate. A NaN `a_i` gives 0,
        // and a NaN `b_i` is not ahead.
        let s = plain_max(a[i], 0.0) / -b[i];
        let ahead = (b[i] < 0.0) & (i != last);
        let key = select_unpredictable(ahead, s.to_bits(), u64::MAX);
        let nearer = key < least;
        least = select_unpredictable(nearer, key, least);
        exit = select_unpredictable(nearer, i, exit);
    }
    let least = f64::from_bits(least);
    (exit < walls).then_some((exit, least))
}

#[cfg(test)]
mod tests {
    use super::*;
    use hscene_test_support::SplitMix64;

    /// The exit as the walk first chose it: fractions compared one by one.
    fn exit_by_fractions(a: &[f64], b: &[f64], last: usize) -> Option<(usize, f64)> {
        let (mut num, mut den) = (1.0, 1.0);
        let mut exit = None;
        for i in 0..a.len() {
            let ahead = plain_max(a[i], 0.0);
            if i != last && b[i] < 0.0 && ahead * den < -b[i] * num {
                (num, den) = (ahead, -b[i]);
                exit = Some(i);
            }
        }
        exit.map(|i| (i, num / den))
    }

    #[test]
    fn nearest_exit_is_the_least_quotient_ahead() {
        let mut rng = SplitMix64::new(7);
        for case in 0..20_000 {
            let walls = 1 + case % MAX_WALLS;
            let (mut a, mut b) = ([0.0; MAX_WALLS], [0.0; MAX_WALLS]);
            for i in 0..walls {
                // Some starts a hair behind a wall, some walls parallel,
                // some ties.
                a[i] = match rng.next_u64() % 8 {
                    0 => -1e-17,
                    1 => 0.0,
                    _ => rng.range(0.0, 2.0),
                };
                b[i] = match rng.next_u64() % 8 {
                    0 => 0.0,
                    1 => -a[i],
                    _ => rng.range(-2.0, 2.0),
                };
            }
            let last = (rng.next_u64() % (walls as u64 + 1)) as usize;
            let got = nearest_exit(&a, &b, walls, last);
            let want = exit_by_fractions(&a[..walls], &b[..walls], last);
            match (got, want) {
                (None, None) => {}
                (Some((i, s)), Some((j, t))) => {
                    // Fractions and quotients round apart only on near ties,
                    // where either wall is the exit within an ulp.
                    assert!(
                        s.to_bits().abs_diff(t.to_bits()) <= 2,
                        "case {case}: {s} vs {t}"
                    );
                    if i != j {
                        let (si, sj) = (a[i].max(0.0) / -b[i], a[j].max(0.0) / -b[j]);
                        assert!(si.to_bits().abs_diff(sj.to_bits()) <= 2, "case {case}");
                    }
                    assert!(b[i] < 0.0 && i != last && s < 1.0);
                }
                other => panic!("case {case}: {other:?}"),
            }
        }
    }

    #[test]
    fn nearest_exit_takes_the_first_of_equal_walls_and_none_past_one() {
        let mut a = [0.0; MAX_WALLS];
        let mut b = [0.0; MAX_WALLS];
        a[..4].copy_from_slice(&[0.5, 0.25, 0.25, 0.0]);
        b[..4].copy_from_slice(&[-1.0, -1.0, -1.0, 1.0]);
        assert_eq!(nearest_exit(&a, &b, 4, usize::MAX), Some((1, 0.25)));
        // The wall just crossed is never the exit.
        assert_eq!(nearest_exit(&a, &b, 4, 1), Some((2, 0.25)));
        // A NaN product is never the exit.
        b[1] = f64::NAN;
        a[2] = f64::NAN;
        assert_eq!(nearest_exit(&a, &b, 4, usize::MAX), Some((2, 0.0)));
        // tanh τ >= 1: the wall is never reached.
        let (a, b) = ([1.0; MAX_WALLS], [-1.0; MAX_WALLS]);
        assert_eq!(nearest_exit(&a, &b, 6, usize::MAX), None);
    }
}
