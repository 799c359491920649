//! `format` over every shipped scene: idempotent, and the lowered IR is the
//! same before and after (so formatting never changes what a scene means).

use std::path::{Path, PathBuf};

use hscene_lang::tokens::tokenize;
use hscene_lang::{Options, compile_with, format};

fn scenes(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            scenes(&path, out);
        } else if path.extension().is_some_and(|e| e == "hsc") {
            out.push(path);
        }
    }
}

fn token_texts(s: &str) -> Vec<&str> {
    tokenize(s)
        .iter()
        .map(|t| {
            let text = &s[t.span.start()..t.span.end()];
            // Line comments lose trailing blanks only.
            if t.kind == hscene_lang::tokens::TokenKind::LineComment {
                text.trim_end()
            } else {
                text
            }
        })
        .collect()
}

#[test]
fn every_shipped_scene_formats_idempotently_to_the_same_ir() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes");
    let mut all = Vec::new();
    scenes(&root, &mut all);
    assert!(all.len() >= 20, "found only {} scenes", all.len());
    for path in &all {
        let source = std::fs::read_to_string(path).unwrap();
        let formatted = format(&source).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(
            format(&formatted).unwrap(),
            formatted,
            "{}: not idempotent",
            path.display()
        );
        assert_eq!(
            token_texts(&source),
            token_texts(&formatted),
            "{}",
            path.display()
        );
        let options = |frame| Options {
            base_dir: path.parent().map(Path::to_path_buf),
            frame,
            ..Options::default()
        };
        let before = compile_with(&source, &options(0));
        let frames = before.scene.as_ref().map_or(1, |s| s.settings.frames);
        for frame in [0, 1, frames.saturating_sub(1)] {
            let a = compile_with(&source, &options(frame));
            let b = compile_with(&formatted, &options(frame));
            assert!(
                a.scene.is_some(),
                "{}: shipped scene has errors",
                path.display()
            );
            assert_eq!(
                a.scene,
                b.scene,
                "{} frame {frame}: IR changed",
                path.display()
            );
            let codes = |c: &hscene_lang::Compiled| -> Vec<_> {
                c.diagnostics
                    .iter()
                    .map(|d| (d.code, d.message.clone()))
                    .collect()
            };
            assert_eq!(
                codes(&a),
                codes(&b),
                "{}: diagnostics changed",
                path.display()
            );
        }
    }
}

/// Every input of the fuzz corpus (odd but often valid text: comments in
/// every position, odd numbers, deep nesting): formatting never panics, and
/// whenever it succeeds it keeps the tokens, is idempotent, and the scene
/// compiles to the same IR and diagnostic codes.
#[test]
fn fuzz_corpus_formats_safely() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus");
    let mut formatted_count = 0;
    let mut seen = 0;
    for sub in std::fs::read_dir(&dir).unwrap() {
        let sub = sub.unwrap().path();
        if !sub.is_dir() {
            continue;
        }
        for entry in std::fs::read_dir(&sub).unwrap() {
            let path = entry.unwrap().path();
            let Ok(source) = std::fs::read_to_string(&path) else {
                continue; // not UTF-8: not a scene
            };
            seen += 1;
            let Ok(formatted) = format(&source) else {
                continue;
            };
            formatted_count += 1;
            assert_eq!(
                token_texts(&source),
                token_texts(&formatted),
                "{}",
                path.display()
            );
            assert_eq!(format(&formatted).unwrap(), formatted, "{}", path.display());
            let codes = |s: &str| -> Vec<_> {
                hscene_lang::compile(s)
                    .diagnostics
                    .iter()
                    .map(|d| d.code)
                    .collect()
            };
            let (a, b) = (
                hscene_lang::compile(&source),
                hscene_lang::compile(&formatted),
            );
            assert_eq!(a.scene, b.scene, "{}: IR changed", path.display());
            assert_eq!(codes(&source), codes(&formatted), "{}", path.display());
        }
    }
    assert!(seen > 500, "corpus not found: {seen} files");
    assert!(
        formatted_count > 40,
        "only {formatted_count} corpus files formatted"
    );
}
