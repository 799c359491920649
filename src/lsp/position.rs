//! Byte offsets (the compiler's spans) to LSP positions and back. LSP counts
//! columns in UTF-16 code units (the default `positionEncoding`), so a
//! character outside the Basic Multilingual Plane counts two.

use hscene_lang::Span;
use lsp_types::{Position, Range};

/// The position of byte `offset` of `text` (clamped to the text, and moved
/// back to a character boundary).
pub fn position(text: &str, offset: usize) -> Position {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let line = before.matches('\n').count();
    let character: usize = before[line_start..].chars().map(char::len_utf16).sum();
    Position::new(to_u32(line), to_u32(character))
}

fn to_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// The range of a span.
pub fn range(text: &str, span: Span) -> Range {
    Range::new(position(text, span.start), position(text, span.end))
}

/// The byte offset of a position. A line past the end gives the end of the
/// text; a column past the line's end gives the line's end (without its
/// line break), as the protocol asks.
pub fn offset(text: &str, pos: Position) -> usize {
    let mut line_start = 0;
    for _ in 0..pos.line {
        match text[line_start..].find('\n') {
            Some(i) => line_start += i + 1,
            None => return text.len(),
        }
    }
    let line_end = text[line_start..]
        .find('\n')
        .map_or(text.len(), |i| line_start + i);
    let mut units = 0;
    for (i, c) in text[line_start..line_end].char_indices() {
        if units >= pos.character as usize {
            return line_start + i;
        }
        units += c.len_utf16();
    }
    line_end
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf16_columns_round_trip() {
        // `é` is 2 bytes and 1 UTF-16 unit; `𝕏` is 4 bytes and 2 units.
        let text = "// é𝕏\nPoints { p: (0,0,0); }";
        let x = text.find('𝕏').unwrap();
        assert_eq!(position(text, x), Position::new(0, 4));
        assert_eq!(position(text, x + 4), Position::new(0, 6));
        assert_eq!(offset(text, Position::new(0, 6)), x + 4);
        let p = text.find("p:").unwrap();
        assert_eq!(position(text, p), Position::new(1, 9));
        assert_eq!(offset(text, Position::new(1, 9)), p);
        // Past the end of a line or of the text.
        assert_eq!(offset(text, Position::new(0, 99)), text.find('\n').unwrap());
        assert_eq!(offset(text, Position::new(9, 0)), text.len());
        // Inside a character: back to its start.
        assert_eq!(position(text, x + 1), Position::new(0, 4));
    }
}
