//! The docs are tests: what README.md and docs/*.md show is what hscene
//! does.
//!
//! - every `hscene ...` command of a fenced `sh` block runs
//!   ([`commands`]), at a reduced size where it renders, in a temporary
//!   folder, and prints what the docs quote after it (`docs/README` in
//!   [`commands`] gives the convention);
//! - every fenced `hsc` block checks without errors (`hsc-error` blocks
//!   are the failing examples, checked by hscene-lang's `doc_examples.rs`);
//! - every picture under docs/ is listed in docs/pictures.txt, and each
//!   one made by `hscene render` is remade small from its scene and found
//!   near the published one ([`pictures`]).
//!
//! A new example in the docs is tested by being there: nothing lists it
//! twice.

mod commands;
mod markdown;
mod pictures;

use std::path::{Path, PathBuf};

/// The repository's root, where a reader runs the documented commands.
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The binary under test.
fn hscene() -> &'static Path {
    Path::new(env!("CARGO_BIN_EXE_hscene"))
}

/// README.md and every docs/*.md, as (path relative to the root, text).
fn documents() -> Vec<(String, String)> {
    let mut names = vec!["README.md".to_owned()];
    let mut docs: Vec<String> = std::fs::read_dir(root().join("docs"))
        .expect("docs/ is readable")
        .filter_map(|e| {
            let name = e.ok()?.file_name().into_string().ok()?;
            name.ends_with(".md").then(|| format!("docs/{name}"))
        })
        .collect();
    docs.sort();
    names.extend(docs);
    names
        .into_iter()
        .map(|n| {
            let text = std::fs::read_to_string(root().join(&n)).expect("a doc is readable");
            (n, text)
        })
        .collect()
}
