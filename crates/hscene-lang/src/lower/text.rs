//! How user-written words appear in messages: shortened, quoted, counted
//! and listed.

use crate::syntax::{RefTarget, Reference};

/// A user-written name, shortened so that a very long one does not flood
/// the message.
pub(super) fn shorten(name: &str) -> String {
    const MAX: usize = 24;
    match name.char_indices().nth(MAX) {
        Some((i, _)) => format!("{}…", &name[..i]),
        None => name.to_string(),
    }
}

/// A user-written name in backticks, shortened like [`shorten`].
pub(super) fn quote(name: &str) -> String {
    format!("`{}`", shorten(name))
}

/// A reference as written, shortened like [`quote`] (without the backticks).
pub(super) fn reference_text(r: &Reference) -> String {
    let sigil = r.sigil.as_char();
    match &r.target {
        RefTarget::Index(n) => format!("{sigil}{n}"),
        RefTarget::Name(s) => format!("{sigil}{}", shorten(s)),
    }
}

/// A declaration as messages name it: `sigil` and its 1-based number,
/// which identifies it even when its name is declared twice, then its
/// name quoted if it has one ("%3 (`apex`)").
pub(super) fn numbered(sigil: char, number: usize, name: Option<&str>) -> String {
    match name {
        Some(n) => format!("{sigil}{number} ({})", quote(n)),
        None => format!("{sigil}{number}"),
    }
}

/// "1 value" / "3 values".
pub(super) fn count(n: usize, what: &str) -> String {
    if n == 1 {
        format!("1 {what}")
    } else {
        format!("{n} {what}s")
    }
}

/// "a, b and c": the items in order, the last two joined by "and".
pub(super) fn and_list<S: AsRef<str>>(items: &[S]) -> String {
    match items {
        [] => String::new(),
        [only] => only.as_ref().to_string(),
        [init @ .., last] => {
            let init: Vec<&str> = init.iter().map(AsRef::as_ref).collect();
            format!("{} and {}", init.join(", "), last.as_ref())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_and_counts() {
        assert_eq!(and_list(&["a", "b", "c"]), "a, b and c");
        assert_eq!(and_list(&["a"]), "a");
        assert_eq!(count(1, "point"), "1 point");
        assert_eq!(count(2, "point"), "2 points");
        assert_eq!(quote(&"x".repeat(30)), format!("`{}…`", "x".repeat(24)));
    }
}
