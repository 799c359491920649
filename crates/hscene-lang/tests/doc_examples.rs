//! Every example in `docs/language.md` is checked here, so the reference
//! cannot drift from the implementation:
//!
//! - a ```` ```hsc ```` block must compile without errors (warnings are
//!   allowed: some examples show a lint);
//! - a ```` ```hsc-error ```` block must produce at least one error, and if
//!   its first line is a comment `// error: HSCxxxx`, an error with that code.
//!
//! The example scenes in `scenes/` must compile without errors too.

use std::path::Path;

use hscene_lang::{Compiled, Options, compile_with};

/// Compiles a documentation example: mesh file names in the docs are
/// relative to the repository root, where a reader runs `hscene`.
fn compile(source: &str) -> Compiled {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    compile_with(
        source,
        &Options {
            base_dir: Some(root),
            ..Options::default()
        },
    )
}

const LANGUAGE: &str = include_str!("../../../docs/language.md");

/// A fenced block: its info string, first line number (1-based) and text.
struct Block<'a> {
    info: &'a str,
    line: usize,
    text: String,
}

/// The fenced code blocks of a Markdown text (``` fences only).
fn blocks(md: &str) -> Vec<Block<'_>> {
    let mut out = Vec::new();
    let mut current: Option<Block<'_>> = None;
    for (i, line) in md.lines().enumerate() {
        let trimmed = line.trim_start();
        match &mut current {
            None => {
                if let Some(info) = trimmed.strip_prefix("```") {
                    current = Some(Block {
                        info: info.trim(),
                        line: i + 2,
                        text: String::new(),
                    });
                }
            }
            Some(block) => {
                if trimmed.starts_with("```") {
                    out.extend(current.take());
                } else {
                    block.text.push_str(line);
                    block.text.push('\n');
                }
            }
        }
    }
    assert!(current.is_none(), "unclosed code block in docs/language.md");
    out
}

#[test]
fn every_hsc_example_in_the_language_reference_compiles() {
    let examples: Vec<Block<'_>> = blocks(LANGUAGE)
        .into_iter()
        .filter(|b| b.info == "hsc")
        .collect();
    assert!(examples.len() >= 25, "only {} examples", examples.len());
    let mut failures = Vec::new();
    for b in &examples {
        let c = compile(&b.text);
        let errors: Vec<String> = c
            .diagnostics
            .iter()
            .filter(|d| d.is_error())
            .map(|d| {
                format!(
                    "{} {} at {:?}",
                    d.code,
                    d.message,
                    &b.text[d.span.start()..d.span.end()]
                )
            })
            .collect();
        if !errors.is_empty() {
            failures.push(format!("example at line {}: {errors:#?}", b.line));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_error_example_in_the_language_reference_fails_as_announced() {
    let examples: Vec<Block<'_>> = blocks(LANGUAGE)
        .into_iter()
        .filter(|b| b.info == "hsc-error")
        .collect();
    assert!(!examples.is_empty());
    for b in &examples {
        let c = compile(&b.text);
        assert!(
            c.has_errors(),
            "error example at line {} compiles cleanly",
            b.line
        );
        let announced = b
            .text
            .lines()
            .next()
            .and_then(|l| l.trim().strip_prefix("// error: "))
            .map(str::trim);
        if let Some(code) = announced {
            assert!(
                c.diagnostics
                    .iter()
                    .any(|d| d.is_error() && d.code.as_str() == code),
                "error example at line {} does not report {code}: {:#?}",
                b.line,
                c.diagnostics
            );
        }
    }
}

#[test]
fn only_known_languages_are_fenced() {
    // A typo in an info string (```hcs) would silently skip an example.
    for b in blocks(LANGUAGE) {
        assert!(
            matches!(b.info, "hsc" | "hsc-error" | "text" | "sh" | "json"),
            "unexpected code block language {:?} at line {}",
            b.info,
            b.line
        );
    }
}

#[test]
fn example_scenes_compile_without_errors() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "hsc") {
            let src = std::fs::read_to_string(&path).unwrap();
            let options = Options {
                base_dir: path.parent().map(Path::to_path_buf),
                ..Options::default()
            };
            let c = compile_with(&src, &options);
            assert!(!c.has_errors(), "{}: {:#?}", path.display(), c.diagnostics);
            checked += 1;
        }
    }
    assert!(checked >= 4, "only {checked} scenes");
}

/// A blank line inside a markdown table ends it: the rows after it fall
/// out (the `checker` rows of the BRDF table once did). No table of
/// language.md is followed, after one blank line, by rows of the same
/// width without a header of their own.
#[test]
fn no_table_is_split_by_a_blank_line() {
    let md = include_str!("../../../docs/language.md");
    let lines: Vec<&str> = md.lines().collect();
    let cells = |l: &str| l.matches('|').count();
    for k in 2..lines.len() {
        let (before, blank, row) = (lines[k - 2], lines[k - 1], lines[k]);
        let continues = before.starts_with('|')
            && blank.trim().is_empty()
            && row.starts_with('|')
            && cells(before) == cells(row)
            && !lines
                .get(k + 1)
                .is_some_and(|l| l.starts_with("|--") || l.starts_with("|-"));
        assert!(
            !continues,
            "a table is split by the blank line before line {}: {row}",
            k + 1
        );
    }
}
