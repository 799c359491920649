//! Replays the command-line fuzz corpus (`crates/hscene-lang/fuzz/corpus/cli/`)
//! through the binary's own clap definition, with the checks of
//! `fuzz/fuzz_targets/cli.rs`, so CI exercises it without libFuzzer.

use std::path::Path;

use clap::Parser;

#[path = "../src/cli.rs"]
#[allow(dead_code)]
mod cli;

#[test]
fn cli_fuzz_corpus_replays_without_panics() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/hscene-lang/fuzz/corpus/cli");
    let mut files = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let data = std::fs::read(entry.unwrap().path()).unwrap();
        files += 1;
        let args = std::iter::once("hscene".to_string()).chain(
            data.split(|&b| b == 0)
                .map(|a| String::from_utf8_lossy(a).into_owned()),
        );
        let Ok(parsed) = cli::Cli::try_parse_from(args) else {
            continue;
        };
        if let cli::Command::Render(r) = parsed.command {
            if let Some(t) = r.threads {
                assert!((1..=hrender::MAX_THREADS).contains(&usize::from(t)));
            }
            if let Some((w, h)) = r.resolution {
                assert!(u64::from(w) * u64::from(h) <= hscene_lang::MAX_PIXELS);
            }
            if let cli::ExposureArg::Stops(ev) = r.exposure {
                assert!(ev.abs() <= hrender::MAX_EXPOSURE);
            }
        }
    }
    assert!(files >= 5, "only {files} corpus files in {}", dir.display());
}
