//! How long a fuzz target runs: `HSCENE_FUZZ_SECONDS` seconds when set (CI
//! sets it), else a fixed number of inputs, so `cargo test` stays quick.

use std::time::Instant;

/// Counts a fuzz target's inputs and says when to stop.
#[derive(Debug)]
pub struct FuzzClock {
    seconds: Option<u64>,
    default_runs: u64,
    runs: u64,
    started: Instant,
}

impl FuzzClock {
    /// Runs for `HSCENE_FUZZ_SECONDS` if it is set to a number, else for
    /// `default_runs` inputs.
    pub fn new(default_runs: u64) -> FuzzClock {
        FuzzClock {
            seconds: std::env::var("HSCENE_FUZZ_SECONDS")
                .ok()
                .and_then(|s| s.parse().ok())
                .filter(|&s| s > 0),
            default_runs,
            runs: 0,
            started: Instant::now(),
        }
    }

    /// Whether to try one more input (and counts it).
    pub fn next_input(&mut self) -> bool {
        let more = match self.seconds {
            Some(s) => self.started.elapsed().as_secs() < s,
            None => self.runs < self.default_runs,
        };
        self.runs += u64::from(more);
        more
    }

    /// The inputs tried so far.
    pub fn runs(&self) -> u64 {
        self.runs
    }
}
