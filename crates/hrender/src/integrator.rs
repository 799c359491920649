//! The integrator interface: how the light arriving along a primary ray is
//! computed. The render loop (`lib.rs`) turns pixels into primary rays and
//! averages what an integrator returns for them; the integrator decides how
//! light travels (which rays it traces, how surfaces scatter, how shadow
//! rays treat glass), asking the scene only geometric questions
//! ([`PreparedScene::nearest`], [`PreparedScene::transmittance`]).
//!
//! Adding one: a file under `integrator/` with a type that implements
//! [`Integrator`], a variant of [`IntegratorKind`] and its row in
//! [`IntegratorKind::TABLE`] (docs/ARCHITECTURE.md, "Adding an
//! integrator").

mod whitted;

use hgeom::Ray;
use hscene_ir::Rgb;

use crate::sampling::SampleStream;
use crate::scene::PreparedScene;
use crate::trace_stats::TraceStats;

pub use whitted::Whitted;

/// Computes the radiance arriving at the eye along primary rays.
///
/// Implementations are shared by every worker thread of a render, so they
/// hold no state that changes while tracing; each primary ray's random
/// decisions draw from its own `stream`, so an image does not depend on the
/// number of threads.
pub trait Integrator: Sync {
    /// The radiance arriving at the eye against the direction of `ray`, a
    /// primary ray from the eye in the canonical frame. Every ray traced is
    /// counted in `stats`; a numeric failure is counted in
    /// `stats.failures` and shows the background, so the result is always
    /// finite.
    fn radiance(&self, ray: &Ray, stream: &mut SampleStream, stats: &mut TraceStats) -> Rgb;
}

/// Which integrator a render uses (`RenderOptions::integrator`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum IntegratorKind {
    /// Whitted's recursive ray tracing with the thesis's Phong model:
    /// point and spherical area lights, an ambient term, mirror reflection
    /// and refraction ([`Whitted`]).
    #[default]
    Whitted,
}

/// Builds an integrator over a prepared scene.
type Build = for<'s> fn(&'s PreparedScene) -> Box<dyn Integrator + 's>;

impl IntegratorKind {
    /// Every integrator: its kind, its name (as `--integrator` and the
    /// scene's `integrator` key spell it) and how it is built.
    pub const TABLE: &'static [(IntegratorKind, &'static str, Build)] =
        &[(IntegratorKind::Whitted, "whitted", |s| {
            Box::new(Whitted::new(s))
        })];

    /// Its name.
    pub fn name(self) -> &'static str {
        Self::row(self).1
    }

    /// The integrator called `name`, if there is one.
    pub fn from_name(name: &str) -> Option<IntegratorKind> {
        Self::TABLE
            .iter()
            .find(|row| row.1 == name)
            .map(|row| row.0)
    }

    /// The integrator of this kind over `scene`.
    pub fn build(self, scene: &PreparedScene) -> Box<dyn Integrator + '_> {
        (Self::row(self).2)(scene)
    }

    fn row(self) -> &'static (IntegratorKind, &'static str, Build) {
        // Every kind has its row (the test below checks it); the first row
        // stands in rather than a panic.
        Self::TABLE
            .iter()
            .find(|row| row.0 == self)
            .unwrap_or(&Self::TABLE[0])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each kind has exactly one row, and its name finds it again.
    #[test]
    fn every_kind_has_one_row() {
        for (kind, name, _) in IntegratorKind::TABLE {
            assert_eq!(IntegratorKind::from_name(name), Some(*kind));
            assert_eq!(kind.name(), *name);
            let rows = IntegratorKind::TABLE
                .iter()
                .filter(|r| r.0 == *kind)
                .count();
            assert_eq!(rows, 1, "{name}");
        }
        // The exhaustive match fails to compile when a variant is added, as
        // a reminder of its row.
        match IntegratorKind::default() {
            IntegratorKind::Whitted => {}
        }
        assert_eq!(IntegratorKind::from_name("nonesuch"), None);
    }
}
