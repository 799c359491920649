//! Byte offsets (the compiler's spans) to LSP positions and back. LSP counts
//! columns in UTF-16 code units (the default `positionEncoding`), so a
//! character outside the Basic Multilingual Plane counts two. The document's
//! [`LineIndex`] is built once per edit, so each conversion is a binary
//! search, and lines end where `hscene check` ends them (LF, CRLF, lone CR).

use hscene_lang::{LineIndex, Span};
use lsp_types::{Position, Range};

/// The position of byte `offset` (clamped to the text, and moved back to a
/// character boundary).
pub fn position(lines: &LineIndex, offset: usize) -> Position {
    let (line, character) = lines.utf16_position(offset);
    Position::new(to_u32(line), to_u32(character))
}

fn to_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// The range of a span.
pub fn range(lines: &LineIndex, span: Span) -> Range {
    Range::new(position(lines, span.start()), position(lines, span.end()))
}

/// The byte offset of a position. A line past the end gives the end of the
/// text; a column past the line's end gives the line's end (without its
/// line break), as the protocol asks.
pub fn offset(lines: &LineIndex, pos: Position) -> usize {
    lines.utf16_offset(pos.line as usize, pos.character as usize)
}
