//! What the workspace's tests, examples and benchmarks share, in one place
//! instead of copies and `#[path]` includes:
//!
//! - [`SplitMix64`], the seeded generator every test stream is drawn from;
//! - [`reference`], hgeom's operations recomputed with 320-bit floats;
//! - [`accuracy`], the families of cases that measure hgeom against it;
//! - with the `render` feature, [`scenes`] (renderer test scenes built from
//!   the IR) and [`far`] (a scene moved far from the origin, rendered and
//!   compared with the unmoved one).
//!
//! hgeom's own tests use this crate while it depends on hgeom: cargo allows
//! that cycle for a dev-dependency, and integration tests link the one hgeom
//! both sides see. Unit tests inside hgeom see a second build of hgeom, so
//! only what is made of glam types ([`SplitMix64`]) fits them.

pub mod accuracy;
#[cfg(feature = "render")]
pub mod far;
mod icosphere;
pub mod reference;
mod rng;
#[cfg(feature = "render")]
pub mod scenes;

pub use icosphere::icosphere;
pub use rng::SplitMix64;
