//! A space given by the face pairings of a Dirichlet domain, read from a
//! JSON file: `space = "m004.json";`. The format is what SnapPy gives
//! (`dirichlet_domain().pairing_matrices()`), `docs/manifolds.md` says how
//! to write one:
//!
//! ```json
//! { "pairings": [ [[t, ...], [...], [...], [...]], ... ], "time": "first" }
//! ```
//!
//! each pairing a 4 × 4 Lorentz matrix by rows, its time coordinate first
//! (SnapPy's order; `"time": "last"` for hgeom's). Checked here as a file;
//! as a gluing by [`hgeom::QuotientSpace::from_pairings`].

use std::path::Path;

use crate::bounded_read::{BoundedReadError, read_regular_file};

use hgeom::glam::DMat4;
use serde::Deserialize;

/// The largest space file read (a domain of 512 faces is under 100 KB).
pub const MAX_SPACE_FILE_BYTES: u64 = 4 << 20;

/// Why a space file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum SpaceFileError {
    /// Not a regular file.
    #[error("not a regular file")]
    NotAFile,
    /// Larger than [`MAX_SPACE_FILE_BYTES`].
    #[error(
        "the file has {size} bytes, more than the {MAX_SPACE_FILE_BYTES} a space file may have"
    )]
    TooLarge {
        /// Its size.
        size: u64,
    },
    /// Not the JSON expected (the parser's message has the line and
    /// column).
    #[error("{0}")]
    Format(String),
    /// Reading failed.
    #[error("{0}")]
    Io(#[from] std::io::Error),
}

/// The file's contents.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpaceFile {
    pairings: Vec<[[f64; 4]; 4]>,
    #[serde(default)]
    time: Option<String>,
    // Notes a tool may leave; not used.
    #[serde(default, rename = "name")]
    _name: Option<serde_json::Value>,
    #[serde(default, rename = "source")]
    _source: Option<serde_json::Value>,
    #[serde(default, rename = "volume")]
    _volume: Option<serde_json::Value>,
}

/// The pairings in `path`, as Lorentz matrices with the time coordinate
/// last.
pub fn load(path: &Path) -> Result<Vec<DMat4>, SpaceFileError> {
    let bytes = read_regular_file(path, MAX_SPACE_FILE_BYTES).map_err(|e| match e {
        BoundedReadError::NotAFile => SpaceFileError::NotAFile,
        BoundedReadError::TooLarge(size) => SpaceFileError::TooLarge { size },
        BoundedReadError::Io(e) => SpaceFileError::Io(e),
    })?;
    let text = String::from_utf8(bytes)
        .map_err(|e| SpaceFileError::Format(format!("not UTF-8 text: {e}")))?;
    parse(&text)
}

/// The pairings in a space file's text.
pub fn parse(text: &str) -> Result<Vec<DMat4>, SpaceFileError> {
    let file: SpaceFile =
        serde_json::from_str(text).map_err(|e| SpaceFileError::Format(e.to_string()))?;
    let time_first = match file.time.as_deref() {
        None | Some("first") => true,
        Some("last") => false,
        Some(other) => {
            return Err(SpaceFileError::Format(format!(
                "`time` is \"first\" or \"last\", not {other:?}"
            )));
        }
    };
    Ok(file
        .pairings
        .iter()
        .map(|rows| {
            // Row r, column c of the time-last matrix is row (r+1)%4,
            // column (c+1)%4 of the time-first one.
            let at = |r: usize, c: usize| {
                if time_first {
                    rows[(r + 1) % 4][(c + 1) % 4]
                } else {
                    rows[r][c]
                }
            };
            DMat4::from_cols_array_2d(&std::array::from_fn(|c| std::array::from_fn(|r| at(r, c))))
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_first_is_moved_last() {
        let text = r#"{"pairings": [[[2, 1, 0, 0], [1, 2, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]]}"#;
        let m = parse(text).unwrap()[0];
        // The boost mixes t and x: in time-last order, x and w.
        assert_eq!(m.w_axis.w, 2.0);
        assert_eq!(m.x_axis.x, 2.0);
        assert_eq!(m.x_axis.w, 1.0);
        assert_eq!(m.y_axis.y, 1.0);
    }

    #[test]
    fn malformed_files_say_where() {
        for text in [
            "{",
            r#"{"pairings": [[1, 2]]}"#,
            r#"{"pairings": [], "time": "middle"}"#,
            r#"{"pairings": [], "colour": 1}"#,
        ] {
            assert!(
                matches!(parse(text), Err(SpaceFileError::Format(_))),
                "{text}"
            );
        }
    }
}
