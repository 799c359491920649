//! Refuses objects and lights too far from the eye to be drawn
//! (`HSC0308`): the renderer traces in the camera's canonical frame (eye at
//! the origin), and what lies farther than f64 can hold from there cannot
//! be carried into it. Points are kept within 36 of the ball's origin, and
//! the eye may be as far on the other side; the renderer asks the same
//! questions (`hscene_ir::light_in_frame`, `traceable_in_frame`), so a
//! scene `check` passes renders.

use super::Lowerer;
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::{Camera, light_in_frame, surely_traceable_near, traceable_in_frame};
use crate::view::canonical_frame;

const HELP: &str = "f64 holds points up to about 36 from the eye, and the eye and this may each be 36 from the origin on opposite sides: move one nearer the other";

impl Lowerer<'_> {
    pub(super) fn refuse_too_far_from_eye(&mut self, camera: &Camera) {
        // A space folds everything into its domain, near the eye.
        if self.settings.space.is_some() {
            return;
        }
        // A degenerate camera is reported where it is built.
        let Some(frame) = canonical_frame(camera) else {
            return;
        };
        let eye = camera.eye.to_hyperboloid();
        let mut found = Vec::new();
        for (object, span) in &self.objects {
            if !surely_traceable_near(&object.shape, eye)
                && !traceable_in_frame(&object.shape, &frame.stages)
            {
                found.push(
                    Diagnostic::new(
                        Code::NumericFailure,
                        *span,
                        "this object is too far from the eye to be drawn: moved to the eye, it leaves what f64 can represent",
                    )
                    .with_help(HELP),
                );
            }
        }
        for (light, span) in &self.lights {
            if light_in_frame(light, &frame.stages).is_none() {
                found.push(
                    Diagnostic::new(
                        Code::NumericFailure,
                        *span,
                        "this light is too far from the eye to shine: moved to the eye, it leaves what f64 can represent",
                    )
                    .with_help(HELP),
                );
            }
        }
        for d in found {
            self.report(d);
        }
    }
}
