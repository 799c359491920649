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

use hscene_ir::bounded_read::{BoundedReadError, read_regular_file};

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

/// A number as a JSON number or a decimal string of any length (SnapPy's
/// high-precision pairings, `str(x)` of a `ManifoldHP`'s entries), rounded
/// to the nearest f64 either way (serde_json's `float_roundtrip` and
/// `str::parse` both round correctly).
#[derive(Clone, Copy, Debug)]
struct Entry(f64);

impl<'de> Deserialize<'de> for Entry {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Entry, D::Error> {
        struct Visit;
        impl serde::de::Visitor<'_> for Visit {
            type Value = Entry;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a number, or a decimal number in a string")
            }
            fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<Entry, E> {
                Ok(Entry(x))
            }
            fn visit_i64<E: serde::de::Error>(self, x: i64) -> Result<Entry, E> {
                Ok(Entry(x as f64))
            }
            fn visit_u64<E: serde::de::Error>(self, x: u64) -> Result<Entry, E> {
                Ok(Entry(x as f64))
            }
            fn visit_str<E: serde::de::Error>(self, s: &str) -> Result<Entry, E> {
                // Only decimal numbers: not "inf" or "NaN", which Rust's
                // parser takes. Spaces are dropped: SnapPy writes small
                // high-precision numbers as "1.25 E-5".
                let t: String = s.chars().filter(|c| *c != ' ').collect();
                let decimal = !t.is_empty()
                    && t.len() <= MAX_DIGITS
                    && t.bytes()
                        .all(|b| b.is_ascii_digit() || b"+-.eE".contains(&b))
                    && t.bytes().any(|b| b.is_ascii_digit());
                match t.parse::<f64>() {
                    Ok(x) if decimal && x.is_finite() => Ok(Entry(x)),
                    _ => Err(E::custom(format!(
                        "expected a decimal number in a string of at most {MAX_DIGITS} characters"
                    ))),
                }
            }
        }
        d.deserialize_any(Visit)
    }
}

/// How far (relative) the domain's volume may be from the file's
/// `"volume"` before a warning: SnapPy's high-precision domains agree to
/// 1e-13.
pub const VOLUME_TOLERANCE: f64 = 1e-9;

/// The longest decimal string an entry may be (ManifoldHP's have 66).
pub const MAX_DIGITS: usize = 1024;

/// The file's contents.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpaceFile {
    pairings: Vec<[[Entry; 4]; 4]>,
    #[serde(default)]
    time: Option<String>,
    // Notes a tool may leave; not used.
    #[serde(default, rename = "name")]
    _name: Option<serde_json::Value>,
    #[serde(default, rename = "source")]
    _source: Option<serde_json::Value>,
    #[serde(default)]
    volume: Option<Entry>,
}

/// What a space file holds: the pairings, and the manifold's volume where
/// the file gives it (SnapPy's `M.volume()`), to compare with the domain's.
#[derive(Clone, Debug)]
pub struct SpaceFileData {
    /// The pairings, Lorentz matrices with the time coordinate last.
    pub pairings: Vec<DMat4>,
    /// The volume the file gives.
    pub volume: Option<f64>,
}

/// The pairings in `path`, as Lorentz matrices with the time coordinate
/// last.
pub fn load(path: &Path) -> Result<Vec<DMat4>, SpaceFileError> {
    load_data(path).map(|d| d.pairings)
}

/// The pairings and the volume in `path`.
pub fn load_data(path: &Path) -> Result<SpaceFileData, SpaceFileError> {
    let bytes = read_regular_file(path, MAX_SPACE_FILE_BYTES).map_err(|e| match e {
        BoundedReadError::NotAFile => SpaceFileError::NotAFile,
        BoundedReadError::TooLarge(size) => SpaceFileError::TooLarge { size },
        BoundedReadError::Io(e) => SpaceFileError::Io(e),
    })?;
    let text = String::from_utf8(bytes).map_err(|e| {
        SpaceFileError::Format(format!(
            "not UTF-8 text (byte {} is not)",
            e.utf8_error().valid_up_to()
        ))
    })?;
    parse_data(&text)
}

/// The pairings in a space file's text.
pub fn parse(text: &str) -> Result<Vec<DMat4>, SpaceFileError> {
    parse_data(text).map(|d| d.pairings)
}

/// serde_json's message without what it quotes from the file: only its
/// kind and place (a file's content is not repeated back, as mesh errors
/// do not).
fn json_error(e: &serde_json::Error) -> String {
    use serde_json::error::Category;
    let what = match e.classify() {
        Category::Io => "cannot be read",
        Category::Syntax => "is not valid JSON",
        Category::Eof => "ends before its JSON does",
        Category::Data => {
            "is not a space file's JSON ({\"pairings\": [4 × 4 matrices of numbers]})"
        }
    };
    format!("the file {what} at line {} column {}", e.line(), e.column())
}

/// The pairings and volume in a space file's text.
pub fn parse_data(text: &str) -> Result<SpaceFileData, SpaceFileError> {
    let file: SpaceFile =
        serde_json::from_str(text).map_err(|e| SpaceFileError::Format(json_error(&e)))?;
    let time_first = match file.time.as_deref() {
        None | Some("first") => true,
        Some("last") => false,
        Some(_) => {
            return Err(SpaceFileError::Format(
                "`time` is \"first\" or \"last\"".into(),
            ));
        }
    };
    let pairings = file
        .pairings
        .iter()
        .map(|rows| {
            // Row r, column c of the time-last matrix is row (r+1)%4,
            // column (c+1)%4 of the time-first one.
            let at = |r: usize, c: usize| {
                if time_first {
                    rows[(r + 1) % 4][(c + 1) % 4].0
                } else {
                    rows[r][c].0
                }
            };
            DMat4::from_cols_array_2d(&std::array::from_fn(|c| std::array::from_fn(|r| at(r, c))))
        })
        .collect();
    Ok(SpaceFileData {
        pairings,
        volume: file.volume.map(|v| v.0),
    })
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
    fn decimal_strings_longer_than_f64_round_to_nearest() {
        // 1 + 2^-53 + a little rounds up to the next f64 after 1 only if
        // every digit is read.
        let up = "1.00000000000000011102230246251565404236316680908203125000000001";
        let text = format!(
            r#"{{"pairings": [[["{up}", "0", 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "-1e-400"]]], "volume": "2.029883212819307250042405108549040571883378615060599584034978214"}}"#
        );
        let d = parse_data(&text).unwrap();
        assert_eq!(d.pairings[0].w_axis.w, 1.0 + f64::EPSILON);
        assert_eq!(d.pairings[0].z_axis.z, -0.0);
        assert_eq!(d.volume, Some(2.029_883_212_819_307_4));
        // The old files, numbers only, read as before.
        let old = r#"{"pairings": [[[2, 1, 0, 0], [1, 2, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]]}"#;
        assert_eq!(parse(old).unwrap()[0].w_axis.w, 2.0);
        // SnapPy's form of a small high-precision number.
        let small =
            r#"{"pairings": [[["1.5 E-5", 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]]}"#;
        assert_eq!(parse(small).unwrap()[0].w_axis.w, 1.5e-5);
    }

    #[test]
    fn strings_that_are_not_decimal_numbers_are_refused() {
        for bad in ["inf", "NaN", "", "1e400", "0x10", "1,5"] {
            let text = format!(
                r#"{{"pairings": [[["{bad}", 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]]}}"#
            );
            assert!(
                matches!(parse(&text), Err(SpaceFileError::Format(_))),
                "{bad}"
            );
        }
    }

    #[test]
    fn errors_do_not_quote_the_file() {
        let text = r#"{"pairings": [], "secret-key-123": 1}"#;
        let e = parse(text).unwrap_err().to_string();
        assert!(!e.contains("secret"), "{e}");
        assert!(e.contains("line 1"), "{e}");
        let e = parse(r#"{"pairings": [], "time": "password"}"#)
            .unwrap_err()
            .to_string();
        assert!(!e.contains("password"), "{e}");
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
