//! Keyword tables (one row a word, in the order the help lists them) and
//! the `key = value` lists checked against them. Each section's table is
//! the one source of what it accepts, its help, its "did you mean"
//! candidates and its words in `vocabulary.rs`; these helpers keep the
//! tables' users from each re-implementing the lookups.

use std::collections::HashMap;

use super::suggest::did_you_mean;
use super::text::quote;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::syntax::Ident;

/// A row of a keyword table.
pub(super) trait Row {
    /// The word as a scene spells it.
    fn word(&self) -> &'static str;
}

impl<T> Row for (&'static str, T) {
    fn word(&self) -> &'static str {
        self.0
    }
}

impl<T, U> Row for (&'static str, T, U) {
    fn word(&self) -> &'static str {
        self.0
    }
}

/// The row of `table` for the word spelt exactly `word`.
pub(super) fn find<'t, R: Row>(table: &'t [R], word: &str) -> Option<&'t R> {
    table.iter().find(|row| row.word() == word)
}

/// The words of a keyword table, in its order, as a constant array:
/// `words!(TABLE, field)` where `field` names the word in a row (`0` for
/// tuple rows). A macro because a constant cannot call a trait method.
macro_rules! words {
    ($table:expr, $field:tt) => {{
        let mut words = [""; $table.len()];
        let mut i = 0;
        while i < $table.len() {
            words[i] = $table[i].$field;
            i += 1;
        }
        words
    }};
}
pub(super) use words;

/// The error for `word`, which is not in a table of `words` (a `what`):
/// `help`, after the nearest of `words` if it is a plausible typo.
pub(super) fn unknown_word(
    code: Code,
    word: &Ident,
    what: &str,
    words: &[&str],
    help: &str,
) -> Diagnostic {
    Diagnostic::new(
        code,
        word.span,
        format!("unknown {what} {}", quote(&word.text)),
    )
    .with_help(did_you_mean(&word.text, words, help))
}

/// The keys one `key = value` list has set so far.
#[derive(Default)]
pub(super) struct SeenKeys<'a>(HashMap<&'a str, Span>);

impl<'a> SeenKeys<'a> {
    /// Notes `key`; the warning that it is set twice when it was set before.
    pub(super) fn again(&mut self, key: &'a Ident) -> Option<Diagnostic> {
        self.0.insert(&key.text, key.span).map(|_| {
            Diagnostic::new(
                Code::DuplicateKey,
                key.span,
                format!("{} is set twice; the last value wins", quote(&key.text)),
            )
        })
    }

    /// Where `key` was set last, if it was.
    pub(super) fn get(&self, key: &str) -> Option<Span> {
        self.0.get(key).copied()
    }
}
