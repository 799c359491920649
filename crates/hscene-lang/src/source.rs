//! Turning the bytes of a scene file into the text the parser reads.
//!
//! Scene files are UTF-8. A leading byte-order mark is skipped, and every
//! line-end convention is accepted: LF, CRLF and a lone CR (old Mac files).
//! A lone CR becomes LF, which keeps every byte offset (both are one byte), so
//! line numbers and spans agree with any editor's view of the file.

use std::fmt;

/// The UTF-8 encoding of U+FEFF, the byte-order mark.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Why bytes are not scene text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct InvalidUtf8 {
    /// Byte offset, in the file as given (a skipped BOM included), of the
    /// first byte that is not valid UTF-8.
    pub offset: usize,
}

impl fmt::Display for InvalidUtf8 {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the file is not valid UTF-8 (first invalid byte at offset {})",
            self.offset
        )
    }
}

impl std::error::Error for InvalidUtf8 {}

/// Decodes a scene file: skips a UTF-8 byte-order mark, checks UTF-8 and
/// turns each lone CR into LF (CRLF stays as it is).
pub fn decode(bytes: Vec<u8>) -> Result<String, InvalidUtf8> {
    let skipped = if bytes.starts_with(BOM) { BOM.len() } else { 0 };
    let mut bytes = bytes;
    bytes.drain(..skipped);
    normalize_line_ends(&mut bytes);
    String::from_utf8(bytes).map_err(|e| InvalidUtf8 {
        offset: skipped + e.utf8_error().valid_up_to(),
    })
}

/// `text` with each lone CR turned into LF (CRLF stays as it is), as
/// [`decode`] reads files: for text that arrives already decoded (an
/// editor's buffer in the language server), so that it is analysed as
/// `check` analyses the same file. Byte offsets do not move.
pub fn lone_crs_as_lf(text: &str) -> String {
    let mut bytes = text.as_bytes().to_vec();
    normalize_line_ends(&mut bytes);
    // CR and LF are ASCII: the bytes are still the UTF-8 they were.
    String::from_utf8(bytes).unwrap_or_else(|_| text.to_owned())
}

/// Replaces every CR not followed by LF with LF, in place. CR and LF are
/// ASCII, so this never breaks UTF-8 and never moves a byte.
fn normalize_line_ends(bytes: &mut [u8]) {
    for i in 0..bytes.len() {
        if bytes[i] == b'\r' && bytes.get(i + 1) != Some(&b'\n') {
            bytes[i] = b'\n';
        }
    }
}

/// True for a line end: LF, or a CR (alone or before LF).
pub(crate) fn is_line_end(b: u8) -> bool {
    b == b'\n' || b == b'\r'
}

/// Characters that print as nothing or as a plain blank, and so must be
/// named by code point in a message: Unicode spaces other than U+0020, and
/// the zero-width and direction formatting characters.
pub(crate) fn is_invisible(c: char) -> bool {
    (c.is_whitespace() && c != ' ')
        || matches!(
            c,
            '\u{00AD}'
                | '\u{034F}'
                | '\u{061C}'
                | '\u{115F}'
                | '\u{1160}'
                | '\u{180E}'
                | '\u{200B}'..='\u{200F}'
                | '\u{202A}'..='\u{202E}'
                | '\u{2060}'..='\u{206F}'
                | '\u{3164}'
                | '\u{FE00}'..='\u{FE0F}'
                | '\u{FEFF}'
                | '\u{FFA0}'
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_line_end_convention_becomes_lf_or_crlf() {
        let text = decode(b"a\rb\r\nc\nd\r".to_vec()).unwrap();
        assert_eq!(text, "a\nb\r\nc\nd\n");
    }

    #[test]
    fn a_bom_is_skipped_and_offsets_count_it() {
        assert_eq!(
            decode(b"\xEF\xBB\xBFPoints {}".to_vec()).unwrap(),
            "Points {}"
        );
        assert_eq!(
            decode(b"\xEF\xBB\xBFab\xFFc".to_vec()),
            Err(InvalidUtf8 { offset: 5 })
        );
        assert_eq!(decode(b"\xC3".to_vec()), Err(InvalidUtf8 { offset: 0 }));
    }

    #[test]
    fn invisible_characters_are_recognised() {
        for c in ['\u{00A0}', '\u{200B}', '\u{FEFF}', '\u{3000}', '\u{2060}'] {
            assert!(is_invisible(c), "{c:?}");
        }
        for c in [' ', 'a', 'é', '€'] {
            assert!(!is_invisible(c), "{c:?}");
        }
    }
}
