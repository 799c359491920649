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

use glam::{DMat4, DVec4};

use crate::lorentz;
use crate::roots::exp_roots_lazy;

/// The inverse of a Lorentz matrix: `J Lᵀ J`.
pub(super) fn lorentz_inverse(l: DMat4) -> DMat4 {
    let j = DMat4::from_diagonal(DVec4::new(1.0, 1.0, 1.0, -1.0));
    j * l.transpose() * j
}

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

/// Restores `<O,O> = -1`, `<D,D> = 1`, `<O,D> = 0` after rounding.
#[inline]
pub(super) fn renormalise(o: &mut DVec4, d: &mut DVec4) {
    *o /= (-lorentz::dot(*o, *o)).sqrt();
    *d += lorentz::dot(*o, *d) * *o;
    *d /= lorentz::dot(*d, *d).sqrt();
}

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

/// The roots `u_near <= u_far` of `alpha u² - 2 k u + beta = 0` for
/// `alpha, beta >= 0`, `k > 0`: [`exp_roots`] without the logarithms.
#[inline]
pub(super) fn exp_roots_plain(alpha: f64, k: f64, beta: f64) -> Option<(f64, f64)> {
    exp_roots_lazy(alpha, k, beta).map(|r| r.exp())
}
