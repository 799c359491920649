//! Fuzz target: the command line. Arbitrary bytes, split at NUL bytes into
//! arguments (lossily decoded), go through the binary's own clap definition
//! (`src/cli.rs`, included by path). Parsing must never panic, and every
//! accepted value must lie in its documented range (`docs/limits.md`).

#![no_main]

use clap::Parser;
use libfuzzer_sys::fuzz_target;

#[path = "../../../../src/cli.rs"]
#[allow(dead_code)]
mod cli;

fuzz_target!(|data: &[u8]| {
    let args = std::iter::once("hscene".to_string()).chain(
        data.split(|&b| b == 0)
            .map(|a| String::from_utf8_lossy(a).into_owned()),
    );
    let Ok(parsed) = cli::Cli::try_parse_from(args) else {
        return;
    };
    if let cli::Command::Render(r) = parsed.command {
        if let Some(t) = r.threads {
            assert!((1..=hrender::MAX_THREADS).contains(&usize::from(t)));
        }
        if let Some(s) = r.samples {
            assert!((1..=hrender::MAX_SAMPLES).contains(&s));
        }
        if let Some((w, h)) = r.resolution {
            assert!(w >= 1 && h >= 1 && u64::from(w) * u64::from(h) <= hscene_lang::MAX_PIXELS);
        }
        if let cli::ExposureArg::Stops(ev) = r.exposure {
            assert!(ev.is_finite() && ev.abs() <= hrender::MAX_EXPOSURE);
        }
    }
});
