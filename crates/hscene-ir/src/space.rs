//! The space a scene is in (`space = NAME;`): H³ itself, or a quotient
//! `H³/Γ` given by a fundamental domain and face pairings
//! ([`hgeom::QuotientSpace`]). What each space is and how rays, objects and
//! lights behave in it is described in `docs/manifolds.md`.

use std::sync::Arc;

use hgeom::glam::DMat4;
use hgeom::{GeomError, QuotientSpace, SpaceKind};

use crate::material::MaterialId;

/// How far from the domain's centre a light's images light the scene,
/// unless `light_reach` says otherwise.
pub const DEFAULT_LIGHT_REACH: f64 = 2.5;

/// The largest `light_reach`: the images within it grow like `e^{2R}`.
pub const MAX_LIGHT_REACH: f64 = 6.0;

/// The most images of one light kept (the nearest the domain's centre):
/// those within the light reach of some point of the domain.
pub const MAX_LIGHT_IMAGES: usize = 1024;

/// The most lights a scene in a space may have: each is traced through
/// its images (hundreds within the reach of the domain), at every shading
/// point.
pub const MAX_SPACE_LIGHTS: usize = 16;

/// The most faces a ray crosses before it stops at the horizon.
pub const MAX_SPACE_CROSSINGS: u32 = 1024;

/// The domain's edges drawn as rods (`domain = w, #M`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DomainEdges {
    /// The rods' hyperbolic radius. Invariant: positive and finite.
    pub width: f64,
    /// Their material.
    pub material: MaterialId,
}

/// A scene's space other than H³.
#[derive(Clone, Debug, PartialEq)]
pub struct Space {
    /// Which space.
    pub kind: SpaceKind,
    /// For [`SpaceKind::Pairings`], the face pairings of its Dirichlet
    /// domain about the origin (Lorentz matrices, time coordinate last:
    /// [`QuotientSpace::from_pairings`]); `None` for the others.
    pub pairings: Option<Arc<[DMat4]>>,
    /// The domain's edges, if drawn.
    pub domain: Option<DomainEdges>,
    /// Each image of a light lights the points within this distance of
    /// it, faded out smoothly over the last unit, so the lighting is
    /// continuous across the faces; the images kept are those within this
    /// distance of the domain (at most [`MAX_LIGHT_IMAGES`]).
    /// Invariant: in `(0, MAX_LIGHT_REACH]`.
    pub light_reach: f64,
}

impl Space {
    /// The space, built and checked (a built-in one from its kind, one read
    /// from a file from its pairings).
    ///
    /// Errors: those of [`QuotientSpace::new`] and
    /// [`QuotientSpace::from_pairings`] (the language has checked both).
    pub fn build(&self) -> Result<QuotientSpace, GeomError> {
        match &self.pairings {
            Some(pairings) => QuotientSpace::from_pairings(pairings),
            None => QuotientSpace::new(self.kind),
        }
    }
}
