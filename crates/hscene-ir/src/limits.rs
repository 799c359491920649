//! The bounds every front end and renderer of a scene agree on
//! (docs/limits.md lists them with every other limit).

/// Most samples per pixel (`samples = N`, `--samples N`).
pub const MAX_SAMPLES: u32 = 4096;

/// Most frames of an animation (`frames = N`).
pub const MAX_FRAMES: u32 = 100_000;

/// Most pixels of an image, width times height (`2^27`: about 1.6 GB of
/// linear `f32` RGB samples).
pub const MAX_PIXELS: u64 = 1 << 27;
