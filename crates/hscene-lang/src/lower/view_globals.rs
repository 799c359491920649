//! The `Globals` keys of the view beyond the thesis: `fov = DEGREES` (the
//! alternative to `window_size`) and fog (`fog_color`, `fog_distance`).
//! Their meaning is in `docs/language.md#globals` and
//! `docs/rendering.md#fog`.

use super::Lowerer;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{Camera, Fog, Rgb};
use crate::syntax::Value;
use crate::view::{FovError, fov_window, max_fov_degrees};

/// The view keys as given, settled once the whole section is read.
#[derive(Default)]
pub(super) struct ViewParts {
    /// `fov` and its value's span.
    fov: Option<(f64, Span)>,
    /// Where `window_size` was given, if it was.
    pub(super) window_span: Option<Span>,
    fog_color: Option<(Rgb, Span)>,
    fog_distance: Option<f64>,
    /// `fog_distance` was given but refused (already reported): a lint
    /// about `fog_color` would only cascade.
    fog_distance_failed: bool,
}

/// The view keys this module handles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ViewKey {
    /// `fov`.
    Fov,
    /// `fog_color`.
    FogColor,
    /// `fog_distance`.
    FogDistance,
}

impl Lowerer<'_> {
    /// One of the view keys.
    pub(super) fn view_global(&mut self, key: ViewKey, value: &Value) {
        match key {
            ViewKey::Fov => {
                let Some(x) = self.number(value) else { return };
                if x > 0.0 && x < 180.0 {
                    self.view.fov = Some((x, value.span()));
                } else {
                    self.report(
                        Diagnostic::new(
                            Code::InvalidValue,
                            value.span(),
                            format!("the field of view must be between 0 and 180 degrees, not {}", hgeom::Compact(x)),
                        )
                        .with_help("`fov` is the horizontal opening angle at the eye in degrees, e.g. `fov = 60;`"),
                    );
                }
            }
            ViewKey::FogColor => {
                if let Some(c) = self.rgb(value) {
                    self.view.fog_color = Some((c, value.span()));
                }
            }
            ViewKey::FogDistance => {
                self.view.fog_distance_failed = true;
                let Some(x) = self.number(value) else { return };
                if x > 0.0 && x.is_finite() {
                    self.view.fog_distance = Some(x);
                    self.view.fog_distance_failed = false;
                } else {
                    self.report(
                        Diagnostic::new(
                            Code::InvalidValue,
                            value.span(),
                            format!("the fog distance must be positive, not {}", hgeom::Compact(x)),
                        )
                        .with_help("`fog_distance = D` is the hyperbolic length over which light keeps 1/e of itself, e.g. `fog_distance = 3;`"),
                    );
                }
            }
        }
    }

    /// Settle the view keys into the settings: `fov` excludes
    /// `window_size`, and must fit the scene's net; fog takes the
    /// background colour unless `fog_color` says otherwise.
    pub(super) fn settle_view(&mut self, camera: Option<&Camera>) {
        if let Some((fov, span)) = self.view.fov {
            if self.view.window_span.is_some() {
                self.report(
                    Diagnostic::new(
                        Code::ConflictingOptions,
                        span,
                        "`fov` and `window_size` cannot both be given",
                    )
                    .with_help("`fov` sets the window from an angle; keep one of the two"),
                );
            } else if let Some(camera) = camera {
                let f = (camera.eye.distance(camera.target) / 2.0).tanh();
                let net = self.settings.net;
                if let Err(FovError::BeyondViewPlane(max)) =
                    fov_window(fov, net, self.settings.resolution, f)
                {
                    self.report(
                        Diagnostic::new(
                            Code::InvalidValue,
                            span,
                            format!(
                                "net {} shows the view h-plane, which the eye sees under less than {max:.1} degrees from here",
                                net.index()
                            ),
                        )
                        .with_help(format!(
                            "use `fov` below {:.1} (twice the angle of parallelism of the distance to `to`), move `to` closer to the eye, or use net_type 0",
                            max_fov_degrees(net, f)
                        )),
                    );
                }
            }
            self.settings.fov = Some(fov);
        }
        match (self.view.fog_distance, self.view.fog_color) {
            (Some(distance), color) => {
                self.settings.fog = Some(Fog {
                    color: color.map_or(self.settings.background, |(c, _)| c),
                    distance,
                });
            }
            (None, Some((_, span))) if !self.view.fog_distance_failed => self.report(
                Diagnostic::new(
                    Code::IneffectiveOption,
                    span,
                    "`fog_color` has no effect without `fog_distance`",
                )
                .with_help(
                    "add `fog_distance = 3;` (say) to turn the fog on, or remove `fog_color`",
                ),
            ),
            (None, _) => {}
        }
    }
}
