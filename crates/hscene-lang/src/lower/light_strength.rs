//! `irradiance_at = D` on a light: its colours are then the irradiance it
//! delivers at hyperbolic distance `D` (to a surface facing it, before the
//! material's reflectances), rather than its intensity. Light keeps the
//! physical fall-off `1 / (4 pi sinh^2 r)` (the area of the hyperbolic
//! sphere of radius `r`), so the intensity is the colour times
//! `4 pi sinh^2 D`. `docs/language.md#lights` documents it.

use std::f64::consts::PI;

use super::Lowerer;
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::Rgb;
use crate::syntax::{Ident, Value};

/// The option's key.
pub(super) const KEY: &str = "irradiance_at";

/// Largest distance accepted: `4 pi sinh^2 30` is about 3.6e26, far beyond
/// any scene the renderer can represent (distance ~37 from the eye).
const MAX_DISTANCE: f64 = 30.0;

/// A light's `key = value` option, as written.
pub(super) type LightOption<'v> = (&'v Ident, &'v Value);

/// How a light's colours are meant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Strength {
    /// As intensities (no `irradiance_at`).
    Intensity,
    /// As the irradiance delivered at this distance.
    IrradianceAt(f64),
    /// `irradiance_at` was refused (already reported).
    Refused,
}

impl Strength {
    /// The light's diffuse and specular intensities from its colours;
    /// `None` when refused.
    pub(super) fn apply(self, diffuse: Rgb, specular: Rgb) -> Option<(Rgb, Rgb)> {
        match self {
            Strength::Intensity => Some((diffuse, specular)),
            Strength::IrradianceAt(d) => Some((
                intensity_for_irradiance(diffuse, d),
                intensity_for_irradiance(specular, d),
            )),
            Strength::Refused => None,
        }
    }
}

/// The intensity that delivers irradiance `e` at distance `d`.
pub fn intensity_for_irradiance(e: Rgb, d: f64) -> Rgb {
    let k = 4.0 * PI * d.sinh() * d.sinh();
    Rgb::new(e.r * k, e.g * k, e.b * k)
}

impl Lowerer<'_> {
    /// Takes `irradiance_at = D` out of a light's options: the others, and
    /// how the colours are meant.
    pub(super) fn take_irradiance_at<'v>(
        &mut self,
        options: Vec<LightOption<'v>>,
    ) -> (Vec<LightOption<'v>>, Strength) {
        let (ours, rest): (Vec<_>, Vec<_>) = options.into_iter().partition(|(k, _)| k.text == KEY);
        let mut result = Strength::Intensity;
        for (key, value) in &ours {
            if result != Strength::Intensity {
                self.report(Diagnostic::new(
                    Code::DuplicateKey,
                    key.span,
                    format!("`{KEY}` is set twice; the last value wins"),
                ));
            }
            result = match self.number(value) {
                Some(d) if d > 0.0 && d <= MAX_DISTANCE => Strength::IrradianceAt(d),
                Some(d) => {
                    self.report(
                        Diagnostic::new(
                            Code::InvalidValue,
                            value.span(),
                            format!("`{KEY}` must be a hyperbolic distance from 0 (exclusive) to {MAX_DISTANCE}, got {}", hgeom::Compact(d)),
                        )
                        .with_help("`irradiance_at = 1` makes the colours the light a surface receives at distance 1"),
                    );
                    Strength::Refused
                }
                None => Strength::Refused,
            };
        }
        (rest, result)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At the chosen distance the fall-off gives back the colour given.
    #[test]
    fn the_fall_off_returns_the_given_irradiance() {
        let e = Rgb::new(1.0, 0.5, 0.25);
        for d in [0.1, 1.0, 3.0, 10.0] {
            let i = intensity_for_irradiance(e, d);
            let back = i.r / (4.0 * PI * d.sinh().powi(2));
            assert!((back - 1.0).abs() < 1e-14, "{d}");
            assert!((i.g / i.r - 0.5).abs() < 1e-15);
        }
    }
}
