//! What the workspace's tests, examples and benchmarks share, in one place
//! instead of copies and `#[path]` includes:
//!
//! - [`SplitMix64`], the seeded generator every test stream is drawn from,
//!   and [`FuzzClock`], how long a fuzz target runs;
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
mod fuzz_clock;
mod icosphere;
pub mod reference;
mod rng;
#[cfg(feature = "render")]
pub mod scenes;

pub use fuzz_clock::FuzzClock;
pub use icosphere::icosphere;
pub use rng::SplitMix64;

/// The value a fixture builder built from its caller's constants.
///
/// This crate builds only what tests, examples and benchmarks ask for
/// from their own literals and seeded streams; none of it sees user input.
/// A fixture that cannot be built is therefore a bug in its caller, and
/// the test must stop there rather than measure something else.
///
/// # Panics
///
/// If `built` is an error, with the fixture's name and the error.
pub fn fixture<T, E: std::fmt::Debug>(built: Result<T, E>, what: &str) -> T {
    match built {
        Ok(value) => value,
        Err(e) => panic!("test fixture {what} could not be built: {e:?}"),
    }
}
