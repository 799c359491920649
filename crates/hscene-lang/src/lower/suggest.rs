//! "Did you mean": the nearest word by edit distance, over keyword tables
//! and over the names a scene declares. A scene may declare thousands of
//! names and misspell thousands of references; collecting and comparing
//! every name for every error would be quadratic, so long name lists get
//! no suggestion and are not even collected.

/// Most candidates a "did you mean" compares.
pub(super) const MAX_CANDIDATES: usize = 1000;

/// The candidate nearest to `word` by edit distance (ignoring case), if it
/// is close enough to be a plausible typo.
///
/// Ties go to the alphabetically first candidate, so the answer does not
/// depend on the candidates' order. Long words and very long candidate lists
/// get no suggestion, which keeps the cost bounded.
pub(super) fn closest<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    const MAX_WORD: usize = 64;
    if word.len() > MAX_WORD || candidates.len() > MAX_CANDIDATES {
        return None;
    }
    let w = word.to_ascii_lowercase();
    // Another renderer's name for a field is no typo of ours, however far.
    if let Some(&(_, ours)) = SYNONYMS.iter().find(|(theirs, _)| *theirs == w)
        && let Some(c) = candidates.iter().find(|c| **c == ours)
    {
        return Some(c);
    }
    let limit = |c: &str| 2.max(c.len() / 4);
    candidates
        .iter()
        .filter(|c| c.len().abs_diff(w.len()) <= limit(c))
        .map(|c| (edit_distance(&w, &c.to_ascii_lowercase()), *c))
        .filter(|(d, c)| *d <= limit(c) && *d < c.len())
        .min_by_key(|&(d, c)| (d, c))
        .map(|(_, c)| c)
}

/// Names other renderers and languages give what hscene calls otherwise
/// (lower case): a user coming from them writes these.
const SYNONYMS: [(&str, &str); 8] = [
    ("ior", "refraction"),
    ("eta", "refraction"),
    ("index", "refraction"),
    ("colour", "diffuse"),
    ("color", "diffuse"),
    ("albedo", "diffuse"),
    ("transparency", "trans"),
    ("transmission", "trans"),
];

/// The candidate `word` was probably meant to be: one that differs from it
/// in case only (names are case-sensitive, and that is the likeliest slip),
/// else the nearest by [`closest`].
pub(super) fn meant<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    candidates
        .iter()
        .find(|c| c.eq_ignore_ascii_case(word))
        .copied()
        .or_else(|| closest(word, candidates))
}

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

/// `help`, preceded by "did you mean `X`?" when `word` is a near miss of
/// one of `candidates`.
pub(super) fn did_you_mean(word: &str, candidates: &[&str], help: &str) -> String {
    match closest(word, candidates) {
        Some(s) => format!("did you mean `{s}`? {help}"),
        None => help.to_string(),
    }
}

/// Levenshtein distance over bytes (names are ASCII identifiers).
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            cur[j + 1] = (prev[j] + usize::from(ca != cb))
                .min(prev[j + 1] + 1)
                .min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edit_distance_and_closest() {
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(closest("Spere", &["Sphere", "Polygon"]), Some("Sphere"));
        assert_eq!(
            closest("wirefrme", &["wireframe", "edges"]),
            Some("wireframe")
        );
        assert_eq!(closest("Xyz", &["Sphere", "Polygon"]), None);
    }

    /// Another renderer's word for a material field is suggested as
    /// ours (`ior` is 8 edits from `refraction`, `colour` 6 from
    /// `diffuse`); where ours is no candidate, spelling decides.
    #[test]
    fn other_renderers_words_suggest_ours() {
        let fields = ["diffuse", "trans", "refraction", "emission"];
        assert_eq!(closest("ior", &fields), Some("refraction"));
        assert_eq!(closest("IOR", &fields), Some("refraction"));
        assert_eq!(closest("colour", &fields), Some("diffuse"));
        assert_eq!(closest("transparency", &fields), Some("trans"));
        assert_eq!(closest("colour", &["edges", "colors"]), Some("colors"));
    }
}
