//! The scene-wide cap on primitives: memory and preparation time grow with
//! the number of faces, triangles and rods, and a few bytes of scene text
//! (`Tessellation435 7` is 41511 cubes) can ask for gigabytes. Figures and
//! meshes whose size is known before they are built are refused before
//! anything is allocated; every object is counted once it exists.

use crate::diagnostic::{Code, Diagnostic, Span};

use super::Lowerer;

/// Most primitives (faces of polygons and polyhedra, mesh triangles, rods,
/// and one for each other shape) in one scene. A scene at the cap needs
/// about 300 MB to lower (measured with two `Tessellation435 7`);
/// `docs/limits.md` has the table of limits.
pub const MAX_PRIMITIVES: u64 = 500_000;

/// Most lights in one scene: every shading point sends a shadow ray to
/// each, and the lint for lights inside objects compares each light with
/// each object, so lights multiply every other cost.
pub const MAX_LIGHTS: usize = 1000;

impl Lowerer<'_> {
    /// Whether `more` primitives still fit; reports the first statement
    /// that does not fit (once per scene).
    pub(super) fn fits(&mut self, more: u64, span: Span) -> bool {
        if self.primitives.saturating_add(more) <= MAX_PRIMITIVES {
            return true;
        }
        if !std::mem::replace(&mut self.primitive_cap_reported, true) {
            self.report(
                Diagnostic::new(
                    Code::TooManyPrimitives,
                    span,
                    format!(
                        "this would bring the scene to {} primitives (faces, triangles and rods), past the limit of {MAX_PRIMITIVES}",
                        self.primitives.saturating_add(more)
                    ),
                )
                .with_help("use fewer or smaller figures, a lower tessellation depth, or a coarser mesh"),
            );
        }
        false
    }

    /// Whether one more light fits; reports the first that does not.
    pub(super) fn light_fits(&mut self, span: Span) -> bool {
        if self.lights.len() < MAX_LIGHTS {
            return true;
        }
        if !std::mem::replace(&mut self.light_cap_reported, true) {
            self.report(
                Diagnostic::new(
                    Code::TooManyPrimitives,
                    span,
                    format!("a scene may have at most {MAX_LIGHTS} lights; this is one more"),
                )
                .with_help("every light costs a shadow ray at every shading point; merge nearby lights or use an area light"),
            );
        }
        false
    }

    /// Counts primitives that now exist; `false` (reported) past the cap.
    pub(super) fn charge(&mut self, more: u64, span: Span) -> bool {
        let ok = self.fits(more, span);
        self.primitives = self.primitives.saturating_add(more);
        ok
    }
}
