//! Golden tests of the diagnostics: every scene in `tests/broken/` has one
//! mistake (or, for the files that say so, several), and the snapshot in
//! `tests/snapshots/` shows every diagnostic `compile` reports for it, as a
//! user would read it: position, severity, code, message, label, help and the
//! source text the span covers.
//!
//! Each broken scene starts with comment lines: the first says what is wrong,
//! and a line `// expect: HSCxxxx ...` lists codes that must be among the
//! diagnostics (so a regression fails with a clear message even before the
//! snapshot is looked at).
//!
//! Update the snapshots with `INSTA_UPDATE=always cargo test -p hscene-lang
//! --test golden` (or `cargo insta review`) and review every changed `.snap`
//! file: the span must cover exactly the offending token and the message and
//! help must make the fix obvious.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::Path;

use hscene_lang::diagnostic::CODES;
use hscene_lang::{Compiled, LineIndex, Options, compile_with};

/// Compiles a broken scene as `hscene check` would: mesh files relative to
/// the scene's directory.
fn compile(src: &str) -> Compiled {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/broken");
    compile_with(
        src,
        &Options {
            base_dir: Some(dir),
            frame: 0,
            ..Options::default()
        },
    )
}

/// At most this many source lines are shown for a multi-line span.
const MAX_EXCERPT_LINES: usize = 4;

/// The text of line `line` (1-based) without its line terminator.
fn line_text(src: &str, line: usize) -> &str {
    src.split('\n')
        .nth(line - 1)
        .unwrap_or_default()
        .trim_end_matches('\r')
}

/// Renders every diagnostic of `compiled` against `src`, with the crate's
/// folder (named by messages about files) as `$CRATE`, the same on every
/// machine.
fn render(src: &str, compiled: &Compiled) -> String {
    render_here(src, compiled).replace(env!("CARGO_MANIFEST_DIR"), "$CRATE")
}

fn render_here(src: &str, compiled: &Compiled) -> String {
    let index = LineIndex::new(src);
    let errors = compiled.diagnostics.iter().filter(|d| d.is_error()).count();
    let warnings = compiled.diagnostics.len() - errors;
    let mut out = String::new();
    writeln!(
        out,
        "{errors} error(s), {warnings} warning(s); scene {}",
        if compiled.scene.is_some() {
            "produced"
        } else {
            "not produced"
        }
    )
    .unwrap();
    for d in &compiled.diagnostics {
        let (l1, c1) = index.line_col(d.span.start());
        let (l2, c2) = index.line_col(d.span.end());
        writeln!(out).unwrap();
        writeln!(
            out,
            "{l1}:{c1}-{l2}:{c2} {} {} {}",
            d.severity,
            d.code.as_str(),
            d.message
        )
        .unwrap();
        if let Some(label) = &d.label {
            writeln!(out, "  label: {label}").unwrap();
        }
        if let Some(help) = &d.help {
            writeln!(out, "  help: {help}").unwrap();
        }
        let shown = (l2 - l1 + 1).min(MAX_EXCERPT_LINES);
        for line in l1..l1 + shown {
            let text = line_text(src, line).replace('\t', " ");
            let width = text.chars().count();
            let from = if line == l1 { c1 - 1 } else { 0 };
            let to = if line == l2 { c2 - 1 } else { width };
            writeln!(out, "  {line:>3} | {text}").unwrap();
            let carets = if to > from {
                "^".repeat(to - from)
            } else {
                // An empty span: a point between two characters.
                "^".to_string()
            };
            writeln!(out, "      | {}{carets}", " ".repeat(from)).unwrap();
        }
        if l2 - l1 + 1 > shown {
            writeln!(out, "      | ... ({} more lines)", l2 - l1 + 1 - shown).unwrap();
        }
    }
    out
}

/// The codes named on the file's `// expect:` line.
fn expected_codes(src: &str) -> Vec<&str> {
    src.lines()
        .filter_map(|l| l.strip_prefix("// expect:"))
        .flat_map(str::split_whitespace)
        .collect()
}

/// The first comment line: what is wrong with the scene.
fn description(src: &str) -> String {
    src.lines()
        .next()
        .and_then(|l| l.strip_prefix("// "))
        .unwrap_or_default()
        .to_string()
}

#[test]
fn broken_scenes() {
    // Failed expectations are collected, so that every snapshot is still
    // written and compared before the test fails.
    let failures = std::cell::RefCell::new(Vec::new());
    insta::glob!("broken/*.hsc", |path| {
        let src = std::fs::read_to_string(path).unwrap();
        let compiled = compile(&src);
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let fail = |msg: String| failures.borrow_mut().push(format!("{name}: {msg}"));
        if !src.starts_with("// ") {
            fail("the first line must be a comment saying what is wrong".into());
        }
        if compiled.diagnostics.is_empty() {
            fail("a broken scene must give at least one diagnostic".into());
        }
        let found: BTreeSet<&str> = compiled
            .diagnostics
            .iter()
            .map(|d| d.code.as_str())
            .collect();
        let expected = expected_codes(&src);
        if expected.is_empty() {
            fail("no `// expect:` line".into());
        }
        for code in expected {
            if !found.contains(code) {
                fail(format!("expected {code} among {found:?}"));
            }
        }
        insta::with_settings!({
            description => description(&src),
            omit_expression => true,
            prepend_module_to_snapshot => false,
        }, {
            insta::assert_snapshot!("diagnostics", render(&src, &compiled));
        });
    });
    let failures = failures.into_inner();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Every code in the table is triggered by some broken scene: a new code
/// needs a new file in `tests/broken/`.
#[test]
fn broken_scenes_cover_every_code() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/broken");
    let mut found = BTreeSet::new();
    let mut files = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "hsc") {
            files += 1;
            let src = std::fs::read_to_string(&path).unwrap();
            for d in compile(&src).diagnostics {
                found.insert(d.code.as_str());
            }
        }
    }
    assert!(files >= 35, "only {files} broken scenes");
    let missing: Vec<&str> = CODES
        .iter()
        .filter(|(_, s, _, _)| !found.contains(s))
        .map(|(_, s, _, _)| *s)
        .collect();
    assert!(
        missing.is_empty(),
        "no broken scene triggers {missing:?}; add one to tests/broken/"
    );
}
