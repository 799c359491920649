//! The volume of a convex polyhedron of finite volume, its vertices finite
//! or ideal, cut into orthoschemes from an interior point.
//!
//! **The cut.** From a point `O` inside (the origin, which every domain
//! contains), drop the perpendicular to each face's plane, foot `P`, and
//! from `P` the perpendicular to each edge line of the face, foot `Q` (by
//! the theorem of the three perpendiculars, `Q` is also the foot of `O`
//! on the edge line). For each end `V` of the edge, `V Q P O` is an
//! orthoscheme: `VQ ⟂ QP ⟂ PO`, with `VQ` perpendicular to the plane `QPO`
//! and `PO` to the plane `VQP`. The cone from `O` over the face is the sum
//! of these, signed: negative where `P` is outside the edge (on the far
//! side of the neighbouring face's plane) and where `V` is on the near
//! side of `Q` along the edge from the other end (the segment `[a1, a2]`
//! along the edge line, `Q` at 0, is `[0, a2] - [0, a1]`). The signs make
//! the sum exact whatever the shape of the faces.
//!
//! **An orthoscheme** `P0 P1 P2 P3` (here `V, Q, P, O`) has right dihedral
//! angles at `P0P2`, `P1P3` and `P1P2`, and three essential ones: `α1` at
//! `P2P3` (the angle `QPV` in the face), `α2` at `P0P3` (between the planes
//! `OVQ` and `OVP`) and `α3` at `P0P1` (the angle `PQO`). Its volume is
//! (Kellerhals, after Lobachevsky; valid with `P0` ideal)
//!
//! ```text
//! V = ¼ [ Л(α1+δ) - Л(α1-δ) + Л(α3+δ) - Л(α3-δ) - Л(π/2-α2+δ) + Л(π/2-α2-δ) + 2Л(π/2-δ) ]
//! tan δ = sqrt(cos²α2 - sin²α1 sin²α3) / (cos α1 cos α3),  0 <= δ < π/2,
//! ```
//!
//! with Lobachevsky's function `Л(x) = -∫₀ˣ log|2 sin t| dt = Cl₂(2x)/2`.
//! The angles are taken as `2 atan2(|a - b|, |a + b|)` of unit tangent
//! vectors, which keeps them exact near 0 and π.

use glam::{DVec3, DVec4};
use std::f64::consts::{FRAC_PI_2, PI};

use crate::lorentz;

use super::polyhedron::DomainPolyhedron;

/// Below this (`sinh` of a distance), a foot is on the line or point it
/// is dropped towards: the orthoscheme there is flat. Its volume tends to
/// 0 with the distance (like the distance itself), so leaving it out
/// costs less than rounding.
const DEGENERATE: f64 = 1e-14;

/// Clausen's function `Cl₂(θ) = -∫₀^θ log|2 sin(t/2)| dt`, odd and
/// 2π-periodic, from its series about 0 on `[-π, π]`:
/// `Cl₂(θ) = θ - θ log|θ| + Σ 2ζ(2n)/(2n(2n+1)) θ (θ/2π)^{2n}`, whose terms
/// fall at least by 4 each at `|θ| = π` (28 terms reach 1e-17).
pub fn clausen(theta: f64) -> f64 {
    // Odd: reduce |θ| alone, so that Cl₂(-θ) = -Cl₂(θ) to the last bit.
    if theta < 0.0 {
        return -clausen(-theta);
    }
    let mut t = theta.rem_euclid(2.0 * PI);
    if t > PI {
        t -= 2.0 * PI;
    }
    if t == 0.0 {
        return 0.0;
    }
    let zeta = |n: usize| -> f64 {
        match n {
            1 => PI.powi(2) / 6.0,
            2 => PI.powi(4) / 90.0,
            3 => PI.powi(6) / 945.0,
            4 => PI.powi(8) / 9450.0,
            5 => PI.powi(10) / 93555.0,
            // 30^-12 = 2e-18: the rest of the sum is below rounding.
            _ => (1..=30).map(|k| f64::from(k).powi(-2 * n as i32)).sum(),
        }
    };
    let x2 = (t / (2.0 * PI)).powi(2);
    let mut power = 1.0;
    let mut sum = 0.0;
    for n in 1..=40 {
        power *= x2;
        let term = 2.0 * zeta(n) / ((2 * n) as f64 * (2 * n + 1) as f64) * power;
        sum += term;
        if term < 1e-18 * sum {
            break;
        }
    }
    t - t * t.abs().ln() + t * sum
}

/// Lobachevsky's function `Л(x) = Cl₂(2x)/2`.
pub fn lobachevsky(x: f64) -> f64 {
    0.5 * clausen(2.0 * x)
}

/// The volume of the orthoscheme with essential angles `a1, a2, a3`
/// (module docs).
pub fn orthoscheme_volume(a1: f64, a2: f64, a3: f64) -> f64 {
    let l = lobachevsky;
    let radicand = (a2.cos().powi(2) - (a1.sin() * a3.sin()).powi(2)).max(0.0);
    let d = radicand.sqrt().atan2(a1.cos() * a3.cos());
    0.25 * (l(a1 + d) - l(a1 - d) + l(a3 + d) - l(a3 - d) - l(FRAC_PI_2 - a2 + d)
        + l(FRAC_PI_2 - a2 - d)
        + 2.0 * l(FRAC_PI_2 - d))
}

/// The angle between two spacelike vectors under the form `dot`.
fn angle_by(a: DVec4, b: DVec4, dot: impl Fn(DVec4, DVec4) -> f64) -> f64 {
    let na = dot(a, a).max(0.0).sqrt();
    let nb = dot(b, b).max(0.0).sqrt();
    if !(na > 0.0 && nb > 0.0) {
        return 0.0;
    }
    let (ua, ub) = (a / na, b / nb);
    let (d, s) = (ua - ub, ua + ub);
    2.0 * dot(d, d).max(0.0).sqrt().atan2(dot(s, s).max(0.0).sqrt())
}

/// The tangent at the hyperboloid point `p` towards `x` (a hyperboloid
/// point or a null vector): `x + <x,p> p`, orthogonal to `p`.
fn towards(p: DVec4, x: DVec4) -> DVec4 {
    x + lorentz::dot(x, p) * p
}

/// The foot of the perpendicular from the hyperboloid point `x` to the
/// plane with unit normal `n`: `x + <x,n> ... ` normalised,
/// `(x - <x,n> n) / sqrt(1 + <x,n>²)`.
fn foot_on_plane(x: DVec4, n: DVec4) -> DVec4 {
    let s = lorentz::dot(x, n);
    (x - s * n) / (1.0 + s * s).sqrt()
}

/// The volume of the polyhedron, by the orthoschemes from the origin
/// (module docs). The origin must be inside.
pub(super) fn domain_volume(domain: &DomainPolyhedron) -> f64 {
    let o = DVec4::W;
    let faces = domain.faces();
    let vertices = domain.vertices();
    let mut total = 0.0;
    for edge in domain.edges() {
        for (side, &f) in edge.faces.iter().enumerate() {
            let g = edge.faces[1 - side];
            let p = foot_on_plane(o, faces[f]);
            // The foot on the edge line: the foot of P on the plane
            // through the edge perpendicular to face f, whose normal is
            // g's made orthogonal to f's (the foot stays in face f).
            let ng = faces[g] - lorentz::dot(faces[g], faces[f]) * faces[f];
            let len = lorentz::dot(ng, ng).sqrt();
            if !(len > 0.0) {
                continue;
            }
            let q = foot_on_plane(p, ng / len);
            // P on the inner side of the edge (g's side) counts +.
            // P on (or within rounding of) the edge line: its orthoschemes
            // are flat, their volume 0, and their angles undefined.
            let inside = lorentz::dot(p, faces[g]);
            if !(inside.abs() > DEGENERATE) {
                continue;
            }
            let ends = edge.vertices.map(|k| vertices[k]);
            let ideal = edge.vertices.map(|k| domain.ideal()[k]);
            // Each end's side of Q along the edge line, and which is the
            // farther: a segment with both ends on one side of Q is the
            // orthoscheme to the far end less the one to the near end.
            let e = lorentz::orthogonal_complement(q, faces[f], faces[g]);
            let at = ends.map(|v| lorentz::dot(v, e));
            let signs = if at[0].signum() != at[1].signum() {
                [1.0, 1.0]
            } else if ideal[0] || (!ideal[1] && at[0].abs() > at[1].abs()) {
                [1.0, -1.0]
            } else {
                [-1.0, 1.0]
            };
            let a3 = angle_by(towards(q, p), towards(q, o), lorentz::dot);
            for ((v, sign), at) in ends.iter().zip(signs).zip(at) {
                // Q at the end V: a flat orthoscheme.
                if !(at.abs() > DEGENERATE) {
                    continue;
                }
                let a1 = angle_by(towards(p, q), towards(p, *v), lorentz::dot);
                let a2 = dihedral_at_origin(v.truncate(), q.truncate(), p.truncate());
                total += inside.signum() * sign * orthoscheme_volume(a1, a2, a3);
            }
        }
    }
    total
}

/// The dihedral angle along the ray from the origin towards `v`, between
/// the half-planes towards `q` and `p`: at the origin the model is
/// conformal, so it is the angle between the directions to `q` and `p`
/// with their parts along `v` removed.
fn dihedral_at_origin(v: DVec3, q: DVec3, p: DVec3) -> f64 {
    let u = v.normalize();
    let qq = q - q.dot(u) * u;
    let pp = p - p.dot(u) * u;
    angle_by(qq.extend(0.0), pp.extend(0.0), |a, b| a.dot(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lobachevsky_function_values() {
        // Л(π/6) = (3/2) Л(π/3) and Л(π/3) = 0.3383...; Л(π/4) = G/2
        // (Catalan's constant); Л(π/2) = 0; odd, π-periodic.
        let catalan = 0.915_965_594_177_219;
        assert!((lobachevsky(PI / 4.0) - catalan / 2.0).abs() < 1e-15);
        assert!((lobachevsky(PI / 6.0) - 1.5 * lobachevsky(PI / 3.0)).abs() < 1e-15);
        assert!(lobachevsky(FRAC_PI_2).abs() < 1e-15);
        assert!((lobachevsky(-0.3) + lobachevsky(0.3)).abs() < 1e-16);
        assert!((lobachevsky(0.3 + PI) - lobachevsky(0.3)).abs() < 1e-14);
        // The regular ideal tetrahedron: 3 Л(π/3) = 1.0149416064096536.
        assert!((3.0 * lobachevsky(PI / 3.0) - 1.014_941_606_409_653_6).abs() < 1e-15);
    }

    #[test]
    fn clausen_matches_its_defining_integral() {
        // Simpson on -log|2 sin(t/2)|, away from the log singularity.
        for theta in [0.7, 1.9, 3.0, 4.4] {
            let (a, n) = (0.5, 20000);
            let h = (theta - a) / f64::from(n);
            let f = |t: f64| -(2.0 * (t / 2.0).sin()).abs().ln();
            let mut s = f(a) + f(theta);
            for k in 1..n {
                s += f(a + f64::from(k) * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
            }
            let integral = s * h / 3.0;
            let expected = clausen(a) + integral;
            assert!((clausen(theta) - expected).abs() < 1e-12, "{theta}");
        }
    }
}
