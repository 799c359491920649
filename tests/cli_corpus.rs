//! The command line as a user meets it, through the built binary: the
//! command-line fuzz corpus (`crates/hscene-lang/fuzz/corpus/cli/`) replayed
//! so CI exercises it without libFuzzer, every subcommand's help (building
//! it runs clap's own consistency checks of the definitions in a debug
//! build), and the ranges the fuzz target (`fuzz/fuzz_targets/cli.rs`)
//! asserts on parsed values, seen from outside as accepted or refused.

use std::path::Path;
use std::process::Output;
use std::time::Duration;

use assert_cmd::Command;

/// Far above any run here: each one stops at a missing scene file or a
/// usage error.
const TIMEOUT: Duration = Duration::from_secs(60);

/// Runs `hscene args` in an empty directory with an empty stdin, so that no
/// argument the corpus makes up can name an existing file.
fn run<I, S>(args: I) -> Output
where
    I: IntoIterator<Item = S>,
    S: AsRef<std::ffi::OsStr>,
{
    let dir = tempfile::tempdir().unwrap();
    Command::cargo_bin("hscene")
        .expect("binary is built by cargo test")
        .args(args)
        .current_dir(dir.path())
        .write_stdin("")
        .timeout(TIMEOUT)
        .output()
        .unwrap()
}

/// Exit status 0, 1 or 2: the process ended by itself (not by the timeout
/// or a signal) and did not panic (101).
fn assert_ended_cleanly(out: &Output, what: &str) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        matches!(out.status.code(), Some(0..=2)),
        "{what}: {:?}\n{stderr}",
        out.status
    );
    assert!(!stderr.contains("panicked"), "{what}: {stderr}");
}

#[test]
fn cli_fuzz_corpus_replays_without_panics() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/hscene-lang/fuzz/corpus/cli");
    let mut files = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let data = std::fs::read(&path).unwrap();
        files += 1;
        // As the fuzz target splits its input: arguments at NUL bytes,
        // lossily decoded.
        let args: Vec<String> = data
            .split(|&b| b == 0)
            .map(|a| String::from_utf8_lossy(a).into_owned())
            .collect();
        assert_ended_cleanly(&run(&args), &format!("{} {args:?}", path.display()));
    }
    assert!(files >= 5, "only {files} corpus files in {}", dir.display());
}

/// The subcommands `hscene --help` lists, read from its `Commands:` section.
fn subcommands() -> Vec<String> {
    let out = run(["--help"]);
    assert!(out.status.success());
    let help = String::from_utf8(out.stdout).unwrap();
    help.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .map(str::to_owned)
        .collect()
}

#[test]
fn every_subcommand_prints_its_help() {
    let commands = subcommands();
    for expected in ["render", "check", "fmt", "lsp", "explain", "completions"] {
        assert!(
            commands.iter().any(|c| c == expected),
            "{expected} missing from {commands:?}"
        );
    }
    for command in &commands {
        // clap's own `help` takes the command to describe, not `--help`.
        let args = if command == "help" {
            vec!["help"]
        } else {
            vec![command.as_str(), "--help"]
        };
        let out = run(args);
        assert!(out.status.success(), "{command} --help: {out:?}");
        let help = String::from_utf8(out.stdout).unwrap();
        assert!(help.contains("Usage: hscene"), "{command}: {help}");
    }
}

/// Whether clap refused `render scene.hsc -o a.png OPTION VALUE` as a usage
/// error naming the value. An accepted value goes on to fail on the missing
/// scene file instead.
fn refused(option: &str, value: &str) -> bool {
    let out = run(["render", "scene.hsc", "-o", "a.png", option, value]);
    assert_ended_cleanly(&out, &format!("{option} {value}"));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let invalid = stderr.contains(&format!("invalid value '{value}' for '{option}"));
    if invalid {
        assert_eq!(out.status.code(), Some(2), "{option} {value}: {stderr}");
    }
    invalid
}

#[test]
fn values_outside_their_ranges_are_refused() {
    let threads = hrender::MAX_THREADS;
    let samples = hrender::MAX_SAMPLES;
    let ev = hrender::MAX_EXPOSURE;
    // Two sides whose product is one more pixel than allowed, and exactly
    // the limit (1 << 27 = 16384 x 8192).
    let side = 16_384u64;
    let most = hscene_lang::MAX_PIXELS / side;
    assert_eq!(side * most, hscene_lang::MAX_PIXELS);
    let cases: Vec<(&str, String, bool)> = vec![
        ("--threads", "0".into(), true),
        ("--threads", "1".into(), false),
        ("--threads", threads.to_string(), false),
        ("--threads", (threads + 1).to_string(), true),
        ("--samples", "0".into(), true),
        ("--samples", "1".into(), false),
        ("--samples", samples.to_string(), false),
        ("--samples", (samples + 1).to_string(), true),
        ("--resolution", "0x10".into(), true),
        ("--resolution", "1x1".into(), false),
        ("--resolution", format!("{side}x{most}"), false),
        ("--resolution", format!("{side}x{}", most + 1), true),
        ("--exposure", ev.to_string(), false),
        ("--exposure", (-ev).to_string(), false),
        ("--exposure", (ev + 1.0).to_string(), true),
        ("--exposure", (-ev - 1.0).to_string(), true),
        ("--exposure", "NaN".into(), true),
        ("--exposure", "inf".into(), true),
    ];
    for (option, value, want_refused) in cases {
        assert_eq!(
            refused(option, &value),
            want_refused,
            "{option} {value}: refused should be {want_refused}"
        );
    }
}
