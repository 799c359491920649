//! Spaces other than H³: quotients `H³/Γ` of hyperbolic space by a
//! discrete group, each given by a fundamental polyhedron (the *domain*)
//! and the *face pairings* that generate `Γ`.
//!
//! A ray in such a space is traced in the domain; where it leaves through
//! face `i` it is in the tile across that face, which the pairing `g_i`
//! maps back onto the domain, entering through the partner face
//! `partner(i)` ([`QuotientSpace::carry`]). So every computation stays in
//! the domain, near the origin, however far the ray goes: the error of a
//! long path is that of its steps (`tests/spaces.rs` measures it against a
//! 320-bit walk), not that of far coordinates.
//!
//! - `polyhedron`: the domain from its planes (vertices, edges);
//!   `face_polygons`: each face's polygon, its plane clipped by the
//!   others in the Klein model.
//! - `gluing`: pairings from vertex correspondences, and the checks of a
//!   gluing (each pairing maps its face onto its partner; every edge cycle
//!   closes up: 2π and the identity for a manifold, the Coxeter relation
//!   for a mirror).
//! - `builtin`: the named spaces (Seifert-Weber, the figure-eight knot
//!   and Whitehead link complements, the mirrored cells of the regular
//!   honeycombs).
//! - `dirichlet`: a manifold from the pairings of a Dirichlet domain (as
//!   SnapPy gives them), its faces the bisectors they imply.
//! - `horocell`: the cell of a honeycomb inscribed in a horosphere, whose
//!   faces are infinitely many, walked through its chambers.
//! - `tiles`: the images of a point or ball near the domain (the copies of
//!   an object or light a ray in the domain can meet), and folding a point
//!   into the domain.

mod builtin;
mod dirichlet;
mod face_polygons;
mod gluing;
mod horocell;
mod polyhedron;
mod tiles;
mod volume;

use glam::{DMat4, DVec4};

use crate::honeycomb::Schlafli;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::ray::Ray;

pub use builtin::{SPACE_NAMES, SpaceKind};
pub use dirichlet::{MAX_PAIRING_ENTRY, MAX_PAIRINGS, PAIRING_TOLERANCE};
pub use face_polygons::{MAX_VERTICES as MAX_DOMAIN_VERTICES, MERGE as VERTEX_MERGE};
pub use gluing::EdgeCycle;
pub use horocell::{MAX_CHAMBER_STEPS, NEAR_FACES as HOROSPHERE_CELL_REACH};
pub use polyhedron::{DomainEdge, DomainPolyhedron};
pub use tiles::MAX_COPIES;
pub use volume::{clausen, lobachevsky, orthoscheme_volume};

/// Where a ray leaves the domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// The face it leaves by, an index into [`QuotientSpace::faces`];
    /// `usize::MAX` for a face of a horosphere-inscribed cell, which has
    /// too many to list (its `normal` then says which).
    pub face: usize,
    /// The inward unit normal of that face.
    pub normal: DVec4,
    /// The arc length along the ray to the face.
    pub t: f64,
    /// `tanh t`, from which the crossing point is formed without cosh
    /// and sinh.
    pub tanh_t: f64,
}

/// A quotient space `H³/Γ`: a fundamental polyhedron and its face pairings,
/// placed in some frame (the base placement has the domain's centre at the
/// origin).
///
/// Invariants: `pairings[i]` maps the tile across face `i` onto the
/// domain and face `i` onto face `partner[i]`; `partner` is an involution
/// and `pairings[partner[i]]` the inverse of `pairings[i]`; `matrices` are
/// their Lorentz matrices; every edge cycle closes up (`gluing.rs`). All
/// checked when a space is built.
///
/// A horosphere-inscribed cell with mirror walls has infinitely many
/// faces: `faces` then lists those near the base point (for the searches
/// over tiles) and the exit is found by walking the cell's chambers
/// (`horocell.rs`).
#[derive(Clone, Debug)]
pub struct QuotientSpace {
    kind: SpaceKind,
    domain: Option<DomainPolyhedron>,
    faces: Vec<DVec4>,
    partner: Vec<usize>,
    pairings: Vec<Isometry>,
    matrices: Vec<DMat4>,
    horo: Option<horocell::HoroCell>,
    placement: Isometry,
}

impl QuotientSpace {
    /// What space it is.
    pub fn kind(&self) -> SpaceKind {
        self.kind
    }

    /// The regular honeycomb whose cells tile the domain: the tiles of the
    /// space's universal cover are unions of its cells, so its edges are
    /// the domain's edges and their images. `None` for a domain given by
    /// its pairings.
    pub fn symbol(&self) -> Option<Schlafli> {
        self.kind.symbol()
    }

    /// The domain, in the current placement; `None` for a
    /// horosphere-inscribed cell, which has infinitely many faces.
    pub fn domain(&self) -> Option<&DomainPolyhedron> {
        self.domain.as_ref()
    }

    /// The inward unit normals of the domain's faces (of a
    /// horosphere-inscribed cell, those within 5 of the base point).
    pub fn faces(&self) -> &[DVec4] {
        &self.faces
    }

    /// The face each face is glued to.
    pub fn partner(&self, face: usize) -> usize {
        self.partner[face]
    }

    /// The pairing of face `face`: it maps the tile across that face onto
    /// the domain.
    pub fn pairing(&self, face: usize) -> &Isometry {
        &self.pairings[face]
    }

    /// The volume of the space: that of its domain, cut into orthoschemes
    /// from the base point (`volume.rs`; accurate to about 1e-14
    /// relative on the built-in spaces, `tests/spaces.rs`). `None` for a
    /// mirrored horosphere-inscribed cell, whose domain has infinitely
    /// many faces (it has finite volume, but no list of faces to sum).
    pub fn volume(&self) -> Option<f64> {
        let base = self
            .domain
            .as_ref()?
            .transformed(&self.placement.inverse().to_lorentz());
        Some(volume::domain_volume(&base))
    }

    /// The placement: from the base placement to this one.
    pub fn placement(&self) -> &Isometry {
        &self.placement
    }

    /// The domain's centre (the origin of the base placement).
    pub fn centre(&self) -> DVec4 {
        self.placement.translation_part().to_hyperboloid()
    }

    /// The space seen in another frame: the domain moved by `iso`, each
    /// pairing conjugated by it.
    pub fn transformed(&self, iso: &Isometry) -> QuotientSpace {
        let inverse = iso.inverse();
        let pairings: Vec<Isometry> = self
            .pairings
            .iter()
            .map(|g| iso.compose(&g.compose(&inverse)))
            .collect();
        let m = iso.to_lorentz();
        QuotientSpace {
            kind: self.kind,
            domain: self.domain.as_ref().map(|d| d.transformed(&m)),
            faces: self.faces.iter().map(|n| m * *n).collect(),
            partner: self.partner.clone(),
            matrices: pairings.iter().map(Isometry::to_lorentz).collect(),
            pairings,
            horo: self.horo.as_ref().map(|h| h.transformed(&m)),
            placement: iso.compose(&self.placement),
        }
    }

    /// True if `x` (a hyperboloid point) lies in the domain, to `tolerance`
    /// in `sinh` of the distance outside a face.
    pub fn contains(&self, x: DVec4, tolerance: f64) -> bool {
        match &self.horo {
            Some(h) => h.contains(x, tolerance),
            None => self.faces.iter().all(|n| lorentz::dot(x, *n) >= -tolerance),
        }
    }

    /// The first face the ray leaves the domain by, from its origin (which
    /// must be in the domain); `None` when it never leaves (a ray running
    /// into an ideal vertex of the domain, a cusp).
    ///
    /// Along `X(t) = cosh t O + sinh t D`, `<X,n> = a cosh t + b sinh t`
    /// with `a = <O,n> >= 0`: it reaches the plane where `tanh t = a/(-b)`,
    /// for `b < 0` and `a < -b`. A face the origin lies just outside of
    /// (rounding, after a crossing at an edge) is left at `t = 0`.
    #[inline]
    pub fn exit(&self, ray: &Ray) -> Option<Crossing> {
        if let Some(h) = &self.horo {
            return h.exit(ray);
        }
        let mut best: Option<(usize, f64)> = None;
        for (i, n) in self.faces.iter().enumerate() {
            let b = lorentz::dot(ray.dir, *n);
            if !(b < 0.0) {
                continue;
            }
            let s = lorentz::dot(ray.origin, *n).max(0.0) / -b;
            if best.is_none_or(|(_, bs)| s < bs) {
                best = Some((i, s));
            }
        }
        let (face, s) = best?;
        (s < 1.0).then(|| Crossing {
            face,
            normal: self.faces[face],
            t: s.atanh(),
            tanh_t: s,
        })
    }

    /// The ray from where it crosses `crossing` on, moved into the domain
    /// by that face's pairing: its origin on the partner face, arc length
    /// counted from there.
    #[inline]
    pub fn carry(&self, ray: &Ray, crossing: Crossing) -> Ray {
        let s = crossing.tanh_t;
        let (x, d) = if s < 0.9 {
            // X = cosh t O + sinh t D = (O + s D) / sqrt(1 - s²) for
            // s = tanh t; the common scale is restored below.
            (ray.origin + s * ray.dir, s * ray.origin + ray.dir)
        } else {
            // Far along, s near 1 fixes t only to eps / (1 - s²): use t.
            let (ct, st) = (crossing.t.cosh(), crossing.t.sinh());
            (
                ct * ray.origin + st * ray.dir,
                st * ray.origin + ct * ray.dir,
            )
        };
        let mirror;
        let m = match self.matrices.get(crossing.face) {
            Some(m) => m,
            None => {
                mirror = horocell::reflection(crossing.normal);
                &mirror
            }
        };
        let mut o = *m * x;
        let mut v = *m * d;
        lorentz::renormalise(&mut o, &mut v);
        Ray { origin: o, dir: v }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ray_from_the_centre_leaves_by_the_face_it_points_at() {
        let s = QuotientSpace::seifert_weber().unwrap();
        for (i, n) in s.faces().iter().enumerate() {
            let ray = Ray::from_origin(-n.truncate()).unwrap();
            let c = s.exit(&ray).unwrap();
            assert_eq!(c.face, i);
            // The inradius: <O,n> = -n.w = sinh ρ.
            assert!((c.t - (-n.w).asinh()).abs() < 1e-14);
            let next = s.carry(&ray, c);
            let j = s.partner(i);
            assert!(lorentz::dot(next.origin, s.faces()[j]).abs() < 1e-14);
            assert!(lorentz::dot(next.dir, s.faces()[j]) > 0.0);
        }
    }
}
