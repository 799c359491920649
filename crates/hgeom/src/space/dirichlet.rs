//! A manifold from the face pairings of a Dirichlet domain, the form in
//! which SnapPy (`dirichlet_domain().pairing_matrices()`) and other tools
//! give a hyperbolic manifold.
//!
//! The Dirichlet domain about the origin `O` is the set of points nearer to
//! `O` than to any image `γO`; its faces are the bisectors of `O` and
//! `γ_i O` for the face pairings `γ_i`. The bisector of `O` and `P` is the
//! plane `<X, O - P> = 0` (`<X,O> = <X,P>` says `cosh d(X,O) = cosh
//! d(X,P)`), with `<O, O - P> = cosh d(O,P) - 1 > 0`, so `(O - P)/|O - P|`
//! is its inward unit normal. The tile across the face of `γ_i` is `γ_i D`,
//! so the pairing the walk applies there is `γ_i⁻¹`, and the face's partner
//! is the face of `γ_i⁻¹`, which must be among the given pairings.
//!
//! **What is accepted.** A tool computes its pairings in floating point,
//! and its errors grow with the size of the matrices (SnapPy's double
//! precision pairings keep `<X,Y>` to about `1e-11 |M|²`). So each test
//! compares with a tolerance `τ = PAIRING_TOLERANCE` times the size of
//! what it compares (`|M|`, the largest entry of a matrix, at least 1 for a
//! Lorentz matrix): `|MᵀJM - J| <= τ|M|²`; a pairing and its partner's,
//! `|M_k M_i - I| <= τ |M_k| |M_i|`. Each pairing is then moved onto the
//! Lorentz group (`project`) and each partner made the exact inverse of its
//! face's pairing (the two averaged), so that the domain, its faces and
//! its edge cycles are those of one exact group near the given one.

use glam::{DMat4, DVec4};

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;

use super::{QuotientSpace, SpaceKind};

/// The most pairings (faces) a domain may have.
pub const MAX_PAIRINGS: usize = 512;

/// The largest entry a pairing's matrix may have: `cosh d` for a pairing
/// that moves the origin by `d`, so at most `acosh 1e6 = 14.5` (census
/// domains have entries below 100). Larger ones lose the digits the
/// domain's vertices need.
pub const MAX_PAIRING_ENTRY: f64 = 1e6;

/// The relative tolerance of every test of a gluing (module docs).
pub const PAIRING_TOLERANCE: f64 = 1e-8;

/// `J = diag(1, 1, 1, -1)`.
fn j() -> DMat4 {
    DMat4::from_diagonal(DVec4::new(1.0, 1.0, 1.0, -1.0))
}

/// The Lorentz adjoint `M# = J Mᵀ J`, the inverse of a Lorentz matrix.
pub(super) fn adjoint(m: &DMat4) -> DMat4 {
    j() * m.transpose() * j()
}

/// The largest absolute entry.
pub(super) fn size(m: &DMat4) -> f64 {
    [m.x_axis, m.y_axis, m.z_axis, m.w_axis]
        .iter()
        .map(|c| c.abs().max_element())
        .fold(0.0, f64::max)
}

/// `m` moved onto the Lorentz group, keeping its image of the origin:
/// `m = B R` for the translation `B` that takes the origin where `m` does
/// and `R = B⁻¹ m`, which fixes the origin; `R`'s rotation block is made
/// orthonormal by Gram-Schmidt ([`Isometry::from_lorentz`]). The image of
/// the origin (the face) is kept to the last bit, and the rotation moves
/// by its own defect (about `1e-16 |M|²`). A polar step `X (3I - X#X)/2`
/// would move the image of the origin too, by the rounding of `X#X`
/// (`1e-16 |M|³`: 5e-8 for SnapPy's `|M| = 779`), which misplaces the
/// domain's deep vertices by more than their gaps.
///
/// Errors: [`GeomError::NotOrthogonal`] for a rotation part further than
/// `τ |M|²` from orthogonal; [`GeomError::NotFinite`] for one that is not
/// finite.
pub(super) fn project(m: &DMat4) -> Result<DMat4, GeomError> {
    let s = size(m);
    Isometry::from_lorentz_within(*m, (PAIRING_TOLERANCE * s * s).max(1e-9)).map(|g| g.to_lorentz())
}

impl QuotientSpace {
    /// The manifold whose Dirichlet domain about the origin has the face
    /// pairings `pairings` (Lorentz matrices, time coordinate last; each
    /// `γ` gives the face bisecting the origin and `γ(origin)`), checked
    /// as every space is: the domain has finite volume, each pairing maps
    /// its face onto its partner's, and every edge cycle sums to 2π with
    /// the identity. Each test's tolerance scales with the sizes of the
    /// matrices it compares (module docs, docs/manifolds.md).
    ///
    /// Errors: [`GeomError::BadDomain`] for fewer than 4 or more than
    /// [`MAX_PAIRINGS`] pairings or a domain of infinite volume;
    /// [`GeomError::BadPairing`] (1-based face numbers, in the order
    /// given) for a matrix that is not finite, has an entry over
    /// [`MAX_PAIRING_ENTRY`], is not future-preserving, fixes the origin,
    /// or whose inverse is not among the pairings;
    /// [`GeomError::InexactPairing`] for one that is not Lorentz, or not
    /// undone by its partner's, to the tolerance (both given);
    /// [`GeomError::EdgeCycle`] for a gluing that does not close up.
    pub fn from_pairings(pairings: &[DMat4]) -> Result<QuotientSpace, GeomError> {
        if pairings.len() < 4 || pairings.len() > MAX_PAIRINGS {
            return Err(GeomError::BadDomain(format!(
                "a domain needs from 4 to {MAX_PAIRINGS} face pairings, got {}",
                pairings.len()
            )));
        }
        for (i, m) in pairings.iter().enumerate() {
            check_matrix(i, m)?;
        }
        let partner = partners(pairings)?;
        // Each pair made exact inverses, their average moved onto the
        // Lorentz group.
        let mut exact = vec![DMat4::ZERO; pairings.len()];
        for (i, &k) in partner.iter().enumerate() {
            if k < i {
                continue;
            }
            let m = project(&((pairings[i] + adjoint(&pairings[k])) * 0.5))?;
            exact[i] = m;
            exact[k] = if k == i { m } else { adjoint(&m) };
        }
        let faces = exact
            .iter()
            .map(|m| {
                let diff = DVec4::W - *m * DVec4::W;
                diff / lorentz::dot(diff, diff).sqrt()
            })
            .collect();
        // The walk applies γ_i⁻¹ at face i: the partner's matrix.
        let walk: Vec<DMat4> = partner.iter().map(|&k| exact[k]).collect();
        QuotientSpace::glued(SpaceKind::Pairings, faces, partner, &walk)
    }
}

/// The tests of one matrix alone: finite, of bounded size, Lorentz to the
/// tolerance, keeping the sheet, moving the origin.
fn check_matrix(i: usize, m: &DMat4) -> Result<(), GeomError> {
    let bad = |problem: String| GeomError::BadPairing {
        face: i + 1,
        problem,
    };
    if !m.is_finite() {
        return Err(bad("is not finite".into()));
    }
    let s = size(m);
    if !(s <= MAX_PAIRING_ENTRY) {
        return Err(bad(format!(
            "has an entry of size {s:.1e}, more than the {MAX_PAIRING_ENTRY:.0e} a pairing may \
             have (a pairing that moves the origin by more than 14.5)"
        )));
    }
    let defect = size(&(m.transpose() * j() * *m - j()));
    let tolerance = PAIRING_TOLERANCE * s * s;
    if !(defect <= tolerance) {
        return Err(GeomError::InexactPairing {
            face: i + 1,
            problem: "is not a Lorentz matrix (it does not keep <X,Y>)",
            error: defect,
            tolerance,
        });
    }
    let p = *m * DVec4::W;
    if !(p.w > 0.0) {
        return Err(bad("exchanges the two sheets of the hyperboloid".into()));
    }
    // cosh d - 1 for the distance d it moves the origin, against the
    // error of its Lorentz form.
    if !(p.w - 1.0 > tolerance) {
        return Err(bad(format!(
            "fixes the origin to the tolerance (cosh d - 1 = {:.2e}, tolerance {tolerance:.2e}), \
             so it bounds no face",
            p.w - 1.0
        )));
    }
    Ok(())
}

/// Each face's partner: the face whose pairing is nearest the inverse of
/// its own, accepted where `|M_k M_i - I| <= τ |M_k| |M_i|`.
fn partners(pairings: &[DMat4]) -> Result<Vec<usize>, GeomError> {
    let mut partner = Vec::with_capacity(pairings.len());
    for (i, m) in pairings.iter().enumerate() {
        let inverse = adjoint(m);
        let nearest = pairings
            .iter()
            .map(|g| size(&(*g - inverse)))
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map_or(0, |(k, _)| k);
        let g = &pairings[nearest];
        let error = size(&(*g * *m - DMat4::IDENTITY));
        let tolerance = PAIRING_TOLERANCE * size(g) * size(m);
        if !(error <= tolerance) {
            return Err(GeomError::InexactPairing {
                face: i + 1,
                problem: "has no inverse among the pairings (the nearest is undone only so far)",
                error,
                tolerance,
            });
        }
        partner.push(nearest);
    }
    for (i, &k) in partner.iter().enumerate() {
        if partner[k] != i {
            return Err(GeomError::BadPairing {
                face: i + 1,
                problem: format!(
                    "has the inverse of face {}, whose own inverse is face {}: two faces have \
                     the same pairing",
                    k + 1,
                    partner[k] + 1
                ),
            });
        }
    }
    Ok(partner)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::point::Point;
    use glam::DVec3;

    fn boost() -> DMat4 {
        let a = Point::new(0.3, -0.4, 0.5).unwrap();
        Isometry::transvection_from_origin(a)
            .compose(&Isometry::orthogonal_unchecked(
                glam::DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 2.0).normalize(), 0.7),
            ))
            .to_lorentz()
    }

    #[test]
    fn projection_takes_a_perturbed_matrix_to_the_lorentz_group() {
        let m = boost();
        let mut noisy = m;
        noisy.x_axis.y += 3e-9;
        noisy.z_axis.x -= 2e-9;
        let p = project(&noisy).unwrap();
        let defect = size(&(p.transpose() * j() * p - j()));
        assert!(defect < 1e-14, "{defect:e}");
        // Near the given matrix: it moves by the size of its defect, and
        // the image of the origin not at all.
        assert!(size(&(p - m)) < 3e-8, "{:e}", size(&(p - m)));
        assert!((p.w_axis - noisy.w_axis).abs().max_element() < 1e-15);
    }

    #[test]
    fn a_matrix_scaled_far_is_refused_for_its_size_not_as_fixing_the_origin() {
        for scale in [1e300, 1e200, 1e7] {
            let m = boost() * scale;
            let e = check_matrix(2, &m).unwrap_err().to_string();
            assert!(e.contains("face 3") && e.contains("more than"), "{e}");
        }
        // A translation by 40 has cosh 40 = 1.2e17 in its entries.
        let (c, s) = (40.0f64.cosh(), 40.0f64.sinh());
        let far = DMat4::from_cols(
            DVec4::new(c, 0.0, 0.0, s),
            DVec4::Y,
            DVec4::Z,
            DVec4::new(s, 0.0, 0.0, c),
        );
        assert!(
            check_matrix(0, &far)
                .unwrap_err()
                .to_string()
                .contains("more than")
        );
    }

    #[test]
    fn a_rotation_fixes_the_origin() {
        let r = Isometry::orthogonal_unchecked(glam::DMat3::from_rotation_z(0.5)).to_lorentz();
        let e = check_matrix(0, &r).unwrap_err().to_string();
        assert!(e.contains("fixes the origin"), "{e}");
    }

    #[test]
    fn a_matrix_far_from_lorentz_names_its_error_and_tolerance() {
        let mut m = boost();
        m.x_axis.x *= 1.01;
        match check_matrix(4, &m) {
            Err(GeomError::InexactPairing {
                face: 5,
                error,
                tolerance,
                ..
            }) => assert!(error > tolerance && tolerance > 0.0),
            other => panic!("{other:?}"),
        }
    }
}
