//! "Did you mean" over the names a scene declares. A scene may declare
//! thousands of names and misspell thousands of references; collecting and
//! comparing every name for every error would be quadratic, so long name
//! lists get no suggestion and are not even collected.

use super::objects::{MAX_CANDIDATES, closest};

/// The declared name nearest to `word`, if the scene declares at most
/// [`MAX_CANDIDATES`] names (counted without collecting them).
pub(super) fn closest_declared<'a>(
    word: &str,
    names: impl ExactSizeIterator<Item = &'a str>,
) -> Option<&'a str> {
    if names.len() > MAX_CANDIDATES {
        return None;
    }
    let names: Vec<&str> = names.collect();
    closest(word, &names)
}
