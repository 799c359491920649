//! The ranges of lengths and colours, each stated once (here and in
//! `docs/limits.md`) and enforced by `check`, so a scene `check` accepts
//! never fails later in the renderer for a value out of range.

use crate::diagnostic::{Code, Diagnostic};
use crate::ir::Rgb;
use crate::syntax::Value;

use super::Lowerer;

/// Longest length in an object (radii, sizes): f64 holds ball points out to
/// distance ~37.4 from the origin, so a sphere of radius 36 about the eye
/// still has a surface the renderer can reach; past it a surface would
/// vanish or its construction overflow.
pub(super) const MAX_LENGTH: f64 = 36.0;

/// Largest mesh `size`: a mesh is built in a frame at its centre, where two
/// opposite vertices are `2 * size` apart, which must stay within the
/// ~37 that f64 can place.
pub(super) const MAX_MESH_SIZE: f64 = 18.0;

/// Largest colour component: radiance is stored as f32 (at most 3.4e38),
/// and the exposure correction may multiply it by up to 2^64 (1.8e19).
pub(super) const MAX_COLOUR: f64 = 1e18;

impl Lowerer<'_> {
    /// A positive length of at most [`MAX_LENGTH`].
    pub(super) fn length(&mut self, value: &Value, what: &str) -> Option<f64> {
        let x = self.positive(value, what)?;
        if x <= MAX_LENGTH {
            return Some(x);
        }
        self.report(
            Diagnostic::new(
                Code::InvalidValue,
                value.span(),
                format!("{what} must be at most {MAX_LENGTH}, got {}", hgeom::Compact(x)),
            )
            .with_help("f64 holds ball points out to about distance 37 from the origin; lengths are hyperbolic"),
        );
        None
    }

    /// A colour whose components are from 0 to [`MAX_COLOUR`].
    pub(super) fn colour_in_range(&mut self, value: &Value, c: [f64; 3]) -> Option<Rgb> {
        if c.iter().all(|x| (0.0..=MAX_COLOUR).contains(x)) {
            return Some(Rgb::new(c[0], c[1], c[2]));
        }
        let message = if c.iter().any(|x| *x < 0.0) {
            "colour components must be non-negative".to_string()
        } else {
            format!(
                "colour components must be at most {}",
                hgeom::Compact(MAX_COLOUR)
            )
        };
        self.report(
            Diagnostic::new(Code::InvalidValue, value.span(), message)
                .with_help("components are linear radiance from 0 (none); 1 is full brightness"),
        );
        None
    }
}
