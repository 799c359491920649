//! Which of a honeycomb's horizon fills a horizon hit takes
//! (`horizon_fill.rs` makes them): the one for the rest of the way from the
//! hit to distance 12 from the eye, in steps of [`STEP`].

use hgeom::{DEFAULT_HORIZON, Hit};
use hscene_ir::Rgb;

/// The spacing of the lengths `Δ` the average is kept for.
pub const STEP: f64 = 0.5;

/// What a horizon hit draws for one remaining length `Δ`: the material of
/// the parts met on average, and the openness, the share of the light from
/// beyond (the sky, the background) that passes the rest of the way.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HorizonFill {
    /// The index of the average material among the scene's materials.
    pub material: usize,
    /// Per channel, the expected fraction of the way left unblocked
    /// (`docs/rendering.md`, "Beyond a honeycomb's horizon").
    pub open: Rgb,
}

/// The index, among `buckets` fills for `Δ = 0, STEP, ...`, of the one a
/// horizon hit takes.
pub fn bucket_of(hit: &Hit, buckets: usize) -> usize {
    // w = cosh of the distance from the eye (the frame's origin).
    let from_eye = hit.point.w.max(1.0).acosh();
    bucket_for_rest(DEFAULT_HORIZON - from_eye, buckets)
}

/// The index, among `buckets` fills for `Δ = 0, STEP, ...`, of the one
/// for the remaining length `rest` (a space's walk gives up at an arc
/// length, not a point: `space_fill.rs`).
pub fn bucket_for_rest(rest: f64, buckets: usize) -> usize {
    ((rest.max(0.0) / STEP).round() as usize).min(buckets.saturating_sub(1))
}

/// True for the `part` of a honeycomb's horizon hit.
pub(crate) fn is_horizon(part: u32) -> bool {
    hgeom::decode_honeycomb_part(part).0 == hgeom::HoneycombPart::Horizon
}
