//! The `Globals` keys of depth of field: `aperture = A` (the lens radius,
//! hyperbolic) and `focus = D` (the distance from the eye seen sharp; the
//! distance to `to` when absent). What they mean is derived in
//! `hscene_ir::Lens` and described in `docs/rendering.md#depth-of-field`.

use super::Lowerer;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{Camera, Lens, MAX_APERTURE, MAX_FOCUS};
use crate::syntax::Value;

/// The lens keys as given, settled once the camera is known.
#[derive(Default)]
pub(super) struct LensParts {
    aperture: Option<f64>,
    focus: Option<(f64, Span)>,
    /// A lens key was refused (already reported).
    failed: bool,
}

/// The lens keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum LensKey {
    /// `aperture`.
    Aperture,
    /// `focus`.
    Focus,
}

impl Lowerer<'_> {
    /// `aperture = A` or `focus = D`.
    pub(super) fn lens_global(&mut self, key: LensKey, value: &Value) {
        let Some(x) = self.number(value) else {
            self.lens.failed = true;
            return;
        };
        let (max, what, help) = match key {
            LensKey::Aperture => (
                MAX_APERTURE,
                "the aperture (the lens radius)",
                "`aperture` is a hyperbolic length; 0.02 gives a gentle blur at a few units",
            ),
            LensKey::Focus => (
                MAX_FOCUS,
                "the focus distance",
                "`focus` is the hyperbolic distance from the eye of what is seen sharp",
            ),
        };
        if !(x > 0.0 && x <= max) {
            self.lens.failed = true;
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    value.span(),
                    format!(
                        "{what} must be above 0 and at most {max}, got {}",
                        hgeom::Compact(x)
                    ),
                )
                .with_help(help),
            );
            return;
        }
        match key {
            LensKey::Aperture => self.lens.aperture = Some(x),
            LensKey::Focus => self.lens.focus = Some((x, value.span())),
        }
    }

    /// The lens, once the camera is known: `focus` defaults to the distance
    /// from the eye to `to`; `focus` without `aperture` is a warning.
    pub(super) fn settle_lens(&mut self, camera: Option<&Camera>) {
        if self.lens.failed {
            return;
        }
        match (self.lens.aperture, self.lens.focus) {
            (None, Some((_, span))) => self.report(
                Diagnostic::new(
                    Code::IneffectiveOption,
                    span,
                    "`focus` has no effect without `aperture`: the camera is a pinhole",
                )
                .with_help("add `aperture = 0.02` (a hyperbolic lens radius) for depth of field"),
            ),
            (Some(aperture), focus) => {
                let focus = match (focus, camera) {
                    (Some((d, _)), _) => d,
                    (None, Some(c)) => c.eye.distance(c.target).clamp(f64::MIN_POSITIVE, MAX_FOCUS),
                    (None, None) => return,
                };
                self.settings.lens = Some(Lens { aperture, focus });
            }
            (None, None) => {}
        }
    }
}
