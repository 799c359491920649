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

use glam::{DMat4, DVec4};

use crate::error::GeomError;
use crate::lorentz;

use super::{QuotientSpace, SpaceKind};

/// The most pairings (faces) a domain may have.
pub const MAX_PAIRINGS: usize = 512;

/// `J = diag(1, 1, 1, -1)`.
fn j() -> DMat4 {
    DMat4::from_diagonal(DVec4::new(1.0, 1.0, 1.0, -1.0))
}

impl QuotientSpace {
    /// The manifold whose Dirichlet domain about the origin has the face
    /// pairings `pairings` (Lorentz matrices, time coordinate last; each
    /// `γ` gives the face bisecting the origin and `γ(origin)`), checked
    /// as every space is: the domain has finite volume, each pairing maps
    /// its face onto its partner's, and every edge cycle sums to 2π with
    /// the identity.
    ///
    /// Errors: [`GeomError::BadDomain`] for fewer than 4 or more than
    /// [`MAX_PAIRINGS`] pairings or a domain of infinite volume;
    /// [`GeomError::BadPairing`] (1-based face numbers, in the order
    /// given) for a matrix that is not finite, not Lorentz to 1e-9, not
    /// future-preserving, fixes the origin, or whose inverse is not among
    /// the pairings; [`GeomError::EdgeCycle`] for a gluing that does not
    /// close up.
    pub fn from_pairings(pairings: &[DMat4]) -> Result<QuotientSpace, GeomError> {
        if pairings.len() < 4 || pairings.len() > MAX_PAIRINGS {
            return Err(GeomError::BadDomain(format!(
                "a domain needs from 4 to {MAX_PAIRINGS} face pairings, got {}",
                pairings.len()
            )));
        }
        let bad = |face: usize, problem: &str| GeomError::BadPairing {
            face: face + 1,
            problem: problem.to_string(),
        };
        let mut images = Vec::with_capacity(pairings.len());
        let mut faces = Vec::with_capacity(pairings.len());
        for (i, m) in pairings.iter().enumerate() {
            if !m.is_finite() {
                return Err(bad(i, "is not finite"));
            }
            let defect = m.transpose() * j() * *m - j();
            let scale = m.x_axis.length().max(m.w_axis.length()).powi(2);
            let off = [defect.x_axis, defect.y_axis, defect.z_axis, defect.w_axis]
                .iter()
                .map(|c| c.abs().max_element())
                .fold(0.0, f64::max);
            if !(off <= 1e-9 * scale.max(1.0)) {
                return Err(bad(i, "is not a Lorentz matrix (it does not keep <X,Y>)"));
            }
            let p = *m * DVec4::W;
            if !(p.w > 0.0) {
                return Err(bad(i, "exchanges the two sheets of the hyperboloid"));
            }
            let diff = DVec4::W - p;
            let norm2 = lorentz::dot(diff, diff);
            if !(norm2 > 1e-18) {
                return Err(bad(i, "fixes the origin, so it bounds no face"));
            }
            images.push(p);
            faces.push(diff / norm2.sqrt());
        }
        // The partner is the face of the inverse, which sends the origin
        // where γ⁻¹ does.
        let mut partner = Vec::with_capacity(pairings.len());
        let mut walk = Vec::with_capacity(pairings.len());
        for (i, m) in pairings.iter().enumerate() {
            let inverse = lorentz::inverse(*m);
            let target = inverse * DVec4::W;
            let found = images
                .iter()
                .position(|p| (*p - target).abs().max_element() <= 1e-9 * target.w);
            let Some(k) = found else {
                return Err(bad(i, "has no inverse among the pairings"));
            };
            partner.push(k);
            walk.push(inverse);
        }
        QuotientSpace::glued(SpaceKind::Pairings, faces, partner, &walk)
    }
}
