//! The integrator interface: how the light arriving along a primary ray is
//! computed. The render loop (`lib.rs`) turns pixels into primary rays and
//! averages what an integrator returns for them; the integrator decides how
//! light travels (which rays it traces, how surfaces scatter, how shadow
//! rays treat glass), asking the scene only geometric questions
//! ([`PreparedScene::nearest`], [`PreparedScene::transmittance`]).
//!
//! Adding one: a file under `integrator/` with a type that implements
//! [`Integrator`], a variant of the IR's [`IntegratorKind`] (its name) and
//! its row in this module's table (docs/ARCHITECTURE.md, "Adding an
//! integrator").

mod next_event;
mod path;
mod whitted;

use hgeom::Ray;
use hscene_ir::{IntegratorKind, Rgb};

use crate::sampling::SampleStream;
use crate::scene::PreparedScene;
use crate::trace_stats::TraceStats;

pub use path::{MAX_PATH_LENGTH, PathTracer};
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

/// Builds an integrator over a prepared scene.
type Build = for<'s> fn(&'s PreparedScene) -> Box<dyn Integrator + 's>;

/// Every integrator and how it is built. `IntegratorKind` (in the IR,
/// where the scene language names it) lists the kinds; this table holds
/// one row per kind.
const TABLE: &[(IntegratorKind, Build)] = &[
    (IntegratorKind::Whitted, |s| Box::new(Whitted::new(s))),
    (IntegratorKind::Path, |s| Box::new(PathTracer::new(s))),
];

/// The integrator of `kind` over `scene`.
pub fn build(kind: IntegratorKind, scene: &PreparedScene) -> Box<dyn Integrator + '_> {
    match TABLE.iter().find(|row| row.0 == kind) {
        Some(row) => (row.1)(scene),
        // Every kind has its row (the test below checks it).
        None => Box::new(Whitted::new(scene)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each kind has exactly one row.
    #[test]
    fn every_kind_has_one_row() {
        for (kind, name) in IntegratorKind::ALL {
            let rows = TABLE.iter().filter(|r| r.0 == kind).count();
            assert_eq!(rows, 1, "{name}");
        }
        assert_eq!(TABLE.len(), IntegratorKind::ALL.len());
    }
}
