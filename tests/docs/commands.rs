//! Every `hscene` command of the docs' `sh` blocks runs.
//!
//! The convention (docs/README in words, here in code):
//! - in a fenced `sh` block, a line that starts with `hscene`,
//!   `target/release/hscene` or `cargo run --release --` (after an optional
//!   `$ ` prompt; a trailing `\` continues it) is a command. It runs
//!   against the built binary from the repository's root, its outputs
//!   (`-o`, `--output`) moved into a temporary folder, a render or a
//!   headless view at 48 x 36 pixels and 1 sample, and must succeed;
//!   what follows a `|` or a `>` is left out (its stdout is read here);
//! - a command written with placeholders (`SCENE`, `OUT.png`, `WxH`,
//!   `[--net 0-4]`, `a|b`, `{}`, `$VAR`) is a synopsis and is not run;
//!   nor are `lsp` (it talks on stdin), the window of `view` (without
//!   `--headless`) and `-o` videos through ffmpeg (`.mp4`, `.webm`);
//! - after a command with a `$ ` prompt, the block's lines up to the next
//!   command or blank line are its documented output: each must appear in
//!   what it prints (stdout and stderr, colour off).

use std::path::Path;
use std::process::{Command, Stdio};

use super::markdown::blocks;
use super::{documents, hscene, root};

/// A command of the docs: where it is, its words, and its documented
/// output lines.
struct Documented {
    at: String,
    words: Vec<String>,
    output: Vec<String>,
}

/// The commands of the `sh` blocks of every document.
fn documented() -> Vec<Documented> {
    let mut out = Vec::new();
    for (name, text) in documents() {
        for block in blocks(&text).iter().filter(|b| b.info == "sh") {
            let mut k = 0;
            while k < block.lines.len() {
                let first = k;
                let mut line = block.lines[k].clone();
                while line.ends_with('\\') && k + 1 < block.lines.len() {
                    line.pop();
                    k += 1;
                    line.push_str(&block.lines[k]);
                }
                k += 1;
                let prompted = line.trim_start().starts_with("$ ");
                let command = line.trim_start().trim_start_matches("$ ");
                let Some(words) = hscene_words(command) else {
                    continue;
                };
                let mut output = Vec::new();
                while prompted && k < block.lines.len() {
                    let next = block.lines[k].trim();
                    if next.is_empty() || next.starts_with("$ ") {
                        break;
                    }
                    output.push(next.to_owned());
                    k += 1;
                }
                let at = format!("{name}:{}", block.line + 1 + first);
                out.push(Documented { at, words, output });
            }
        }
    }
    out
}

/// The arguments of `line` if it runs hscene: the words after the program,
/// up to a pipe or a redirection.
fn hscene_words(line: &str) -> Option<Vec<String>> {
    let words = shlex::split(line)?;
    let rest: &[String] = match words.as_slice() {
        [p, rest @ ..] if p == "hscene" || p == "target/release/hscene" => rest,
        [c, r, rel, dd, rest @ ..]
            if c == "cargo" && r == "run" && rel == "--release" && dd == "--" =>
        {
            rest
        }
        _ => return None,
    };
    let end = rest
        .iter()
        .position(|w| {
            w == "|" || w.starts_with('>') || w.starts_with("2>") || w == "&&" || w == ";"
        })
        .unwrap_or(rest.len());
    Some(rest[..end].to_vec())
}

/// True for a word that stands for something (a synopsis's placeholder).
fn is_placeholder(word: &str) -> bool {
    if ["[", "]", "|", "...", "{", "$"]
        .iter()
        .any(|p| word.contains(p))
    {
        return true;
    }
    word.split(['/', '-', ','])
        .map(|part| part.split('.').next().unwrap_or(part))
        .any(|part| {
            part == "WxH"
                || (!part.is_empty() && part.chars().all(|c| c.is_ascii_uppercase() || c == '_'))
        })
}

/// Whether the command is run, and if not, why.
fn skipped(words: &[String]) -> Option<&'static str> {
    if words.iter().any(|w| is_placeholder(w)) {
        return Some("a synopsis");
    }
    let has = |flag: &str| words.iter().any(|w| w == flag);
    match words.first().map(String::as_str) {
        Some("lsp") => Some("the language server talks on stdin"),
        Some("view") if !has("--headless") => Some("a window"),
        _ if words
            .iter()
            .any(|w| w.ends_with(".mp4") || w.ends_with(".webm")) =>
        {
            Some("a video through ffmpeg")
        }
        _ => None,
    }
}

/// The words as run: outputs moved into `dir`, renders made small.
fn as_run(words: &[String], dir: &Path) -> Vec<String> {
    let small = matches!(words.first().map(String::as_str), Some("render" | "view"));
    let mut out = Vec::new();
    let mut k = 0;
    while k < words.len() {
        let w = &words[k];
        let value = words.get(k + 1);
        match (w.as_str(), value) {
            ("-o" | "--output", Some(v)) => {
                let name = Path::new(v)
                    .file_name()
                    .map_or(v.clone(), |n| n.to_string_lossy().into_owned());
                out.push(w.clone());
                out.push(dir.join(name).to_string_lossy().into_owned());
                k += 2;
            }
            ("--resolution" | "--samples" | "--noise" | "--frames", Some(_)) if small => k += 2,
            _ => {
                out.push(w.clone());
                k += 1;
            }
        }
    }
    if small {
        out.extend(["--resolution", "48x36", "--samples", "1"].map(String::from));
    }
    if words.first().is_some_and(|w| w == "view") {
        out.extend(["--frames", "2"].map(String::from));
    }
    out
}

/// Every documented command runs and succeeds, and prints what the docs
/// quote of its output.
#[test]
fn every_documented_command_runs() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut ran = 0;
    let mut failures = Vec::new();
    for doc in documented() {
        if skipped(&doc.words).is_some() {
            continue;
        }
        let args = as_run(&doc.words, dir.path());
        let result = Command::new(hscene())
            .args(&args)
            .current_dir(root())
            .env("NO_COLOR", "1")
            .stdin(Stdio::null())
            .output()
            .expect("hscene starts");
        ran += 1;
        let printed = format!(
            "{}{}",
            String::from_utf8_lossy(&result.stdout),
            String::from_utf8_lossy(&result.stderr)
        );
        if !result.status.success() {
            failures.push(format!(
                "{}: hscene {}: {}\n{printed}",
                doc.at,
                args.join(" "),
                result.status
            ));
            continue;
        }
        for line in &doc.output {
            if !printed.contains(line.as_str()) {
                failures.push(format!(
                    "{}: `{line}` not in what it printed:\n{printed}",
                    doc.at
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    // The README alone has a dozen; a parser that finds none tests nothing.
    assert!(ran >= 20, "only {ran} documented commands found");
}

#[test]
fn synopses_are_told_from_commands() {
    let words = |s: &str| hscene_words(s).expect("an hscene command");
    assert!(skipped(&words("hscene render SCENE -o OUT.png [--net 0-4]")).is_some());
    assert!(skipped(&words("hscene completions bash|zsh")).is_some());
    assert!(
        skipped(&words(
            "target/release/hscene render scenes/showcase/NAME.hsc -o x.png"
        ))
        .is_some()
    );
    assert!(skipped(&words("hscene explain HSC0305")).is_none());
    assert!(
        skipped(&words(
            "cargo run --release -- render scenes/orbit.hsc -o orbit.gif  # GIF"
        ))
        .is_none()
    );
    assert_eq!(words("hscene man > out.1"), ["man"]);
    assert_eq!(hscene_words("cargo install --path ."), None);
}

/// Every `hsc` block of README.md and docs/*.md checks without errors
/// (hscene-lang's `doc_examples.rs` compiles language.md's; this runs the
/// binary's `check` on all of them, from the repository's root, where a
/// reader's relative paths resolve).
#[test]
fn every_scene_block_checks_clean() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for (name, text) in documents() {
        for block in blocks(&text).iter().filter(|b| b.info == "hsc") {
            let source = block.lines.join("\n");
            let mut child = Command::new(hscene())
                .args(["check", "--color", "never", "-"])
                .current_dir(root())
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .expect("hscene starts");
            use std::io::Write;
            child
                .stdin
                .take()
                .expect("stdin")
                .write_all(source.as_bytes())
                .expect("the block is written");
            let result = child.wait_with_output().expect("hscene check ends");
            checked += 1;
            if !result.status.success() {
                failures.push(format!(
                    "{name}:{}: {}",
                    block.line,
                    String::from_utf8_lossy(&result.stderr)
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(checked >= 30, "only {checked} scene blocks found");
}
