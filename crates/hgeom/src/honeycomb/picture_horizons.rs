//! A picture's two honeycomb horizons set at once: the farthest any of its
//! pixels resolves the cells, and on a flat image plane each ray's own
//! ([`super::view_horizon`]).

use glam::DVec3;

use super::walk::RegularHoneycomb;
use crate::error::GeomError;

impl RegularHoneycomb {
    /// The honeycomb as a picture draws it: walked no farther than where
    /// its cells fall below the picture's smallest pixel (`smallest`
    /// radians, [`RegularHoneycomb::horizon_for_pixel`]), and on a flat
    /// image plane, given as its axis and the pixel angle at its middle,
    /// each ray from the eye no farther than where they fall below its own
    /// pixel ([`RegularHoneycomb::with_view_horizon`]). Never farther than
    /// its horizon already is.
    ///
    /// Errors: those of [`RegularHoneycomb::with_horizon`] and
    /// [`RegularHoneycomb::with_view_horizon`].
    pub fn for_pixels(
        self,
        smallest: f64,
        plane: Option<(DVec3, f64)>,
    ) -> Result<RegularHoneycomb, GeomError> {
        let horizon = self.horizon_for_pixel(smallest);
        let mut walked = if horizon < self.horizon() {
            self.with_horizon(horizon)?
        } else {
            self
        };
        if let Some((axis, angle)) = plane {
            walked = walked.with_view_horizon(axis, angle)?;
        }
        Ok(walked)
    }
}
