//! Byte offsets to lines and columns, in characters (for people) and in
//! UTF-16 code units (for the language server protocol), and back.
//!
//! Built once per text; every lookup is a binary search, so reporting
//! every diagnostic of a large file stays linear in the file, however many
//! diagnostics there are or however long a line is.

use crate::diagnostic::Span;

/// Maps byte offsets to line and column numbers.
///
/// LF, CRLF and a lone CR each end a line, as in [`crate::source`] (a `\r`
/// before `\n` counts as part of the line).
#[derive(Clone, Debug)]
pub struct LineIndex {
    source: Box<str>,
    /// Byte offset at which each line starts; the first is always 0.
    line_starts: Vec<usize>,
    /// Every character of more than one byte: where it starts, and the
    /// bytes beyond its count in characters and in UTF-16 units of it and
    /// of every such character before it.
    wide: Vec<Wide>,
}

#[derive(Clone, Copy, Debug)]
struct Wide {
    start: usize,
    /// Sum over this and earlier wide characters of `len_utf8 - 1`.
    extra_over_chars: usize,
    /// Sum over this and earlier wide characters of `len_utf8 - len_utf16`.
    extra_over_utf16: usize,
}

impl LineIndex {
    /// Indexes `source` (the text is copied).
    pub fn new(source: &str) -> Self {
        let bytes = source.as_bytes();
        let mut line_starts = vec![0];
        line_starts.extend(
            bytes
                .iter()
                .enumerate()
                .filter(|&(i, &b)| b == b'\n' || (b == b'\r' && bytes.get(i + 1) != Some(&b'\n')))
                .map(|(i, _)| i + 1),
        );
        let mut wide = Vec::new();
        if !source.is_ascii() {
            let (mut over_chars, mut over_utf16) = (0, 0);
            for (start, c) in source.char_indices().filter(|(_, c)| !c.is_ascii()) {
                over_chars += c.len_utf8() - 1;
                over_utf16 += c.len_utf8() - c.len_utf16();
                wide.push(Wide {
                    start,
                    extra_over_chars: over_chars,
                    extra_over_utf16: over_utf16,
                });
            }
        }
        LineIndex {
            source: source.into(),
            line_starts,
            wide,
        }
    }

    /// `offset` clamped to the source and moved back to a character start.
    fn char_start(&self, offset: usize) -> usize {
        let mut offset = offset.min(self.source.len());
        while !self.source.is_char_boundary(offset) {
            offset -= 1;
        }
        offset
    }

    /// The 0-based line holding byte `offset` (a character start) and the
    /// line's first byte.
    fn line_of(&self, offset: usize) -> (usize, usize) {
        // `line_starts[0] == 0 <= offset`, so the partition point is at least 1.
        let line = self.line_starts.partition_point(|&s| s <= offset);
        (line - 1, self.line_starts[line - 1])
    }

    /// The extra bytes (over characters, over UTF-16 units) of the wide
    /// characters that start before byte `offset`.
    fn extra_before(&self, offset: usize) -> (usize, usize) {
        match self.wide.partition_point(|w| w.start < offset) {
            0 => (0, 0),
            n => (
                self.wide[n - 1].extra_over_chars,
                self.wide[n - 1].extra_over_utf16,
            ),
        }
    }

    /// The 1-based line and 1-based character column of byte `offset`.
    ///
    /// Offsets past the end clamp to the end of the source; an offset inside a
    /// multi-byte character counts as that character.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = self.char_start(offset);
        let (line, start) = self.line_of(offset);
        let (a, _) = self.extra_before(start);
        let (b, _) = self.extra_before(offset);
        (line + 1, offset - start - (b - a) + 1)
    }

    /// The 0-based line and 0-based column in UTF-16 code units of byte
    /// `offset` (clamped, and moved back to a character start), as the
    /// language server protocol counts positions by default.
    pub fn utf16_position(&self, offset: usize) -> (usize, usize) {
        let offset = self.char_start(offset);
        let (line, start) = self.line_of(offset);
        let (_, a) = self.extra_before(start);
        let (_, b) = self.extra_before(offset);
        (line, offset - start - (b - a))
    }

    /// The byte offset of 0-based `line` and UTF-16 `column`. A line past
    /// the end gives the end of the text; a column past the line's end, or
    /// inside a character, gives the line's end or the character's start.
    pub fn utf16_offset(&self, line: usize, column: usize) -> usize {
        let Some(&start) = self.line_starts.get(line) else {
            return self.source.len();
        };
        let end = self.line_bounds(start).end();
        let (_, a) = self.extra_before(start);
        let (_, b) = self.extra_before(end);
        if a == b {
            // No wide character on the line: units are bytes.
            return (start + column).min(end);
        }
        let mut units = 0;
        for (i, c) in self.source[start..end].char_indices() {
            units += c.len_utf16();
            if units > column {
                return start + i;
            }
        }
        end
    }

    /// The byte range of the line holding byte `offset` (clamped to the
    /// source), without its line end.
    pub fn line_bounds(&self, offset: usize) -> Span {
        let offset = offset.min(self.source.len());
        let line = self.line_starts.partition_point(|&s| s <= offset);
        let start = self.line_starts[line - 1];
        let end = self
            .line_starts
            .get(line)
            .map_or(self.source.len(), |&next| next);
        let text = &self.source.as_bytes()[start..end];
        let trimmed = text
            .iter()
            .rposition(|&b| b != b'\n' && b != b'\r')
            .map_or(0, |i| i + 1);
        Span::new(start, start + trimmed)
    }

    /// The indexed text.
    pub fn text(&self) -> &str {
        &self.source
    }

    /// The 0-based line holding byte `offset` (clamped to the source).
    pub fn line_number(&self, offset: usize) -> usize {
        let offset = offset.min(self.source.len());
        self.line_starts.partition_point(|&s| s <= offset) - 1
    }

    /// The first byte of 0-based `line`; a line past the last gives the
    /// text's end.
    pub fn line_start(&self, line: usize) -> usize {
        self.line_starts
            .get(line)
            .copied()
            .unwrap_or(self.source.len())
    }

    /// Number of lines (at least 1, even for an empty source).
    pub fn line_count(&self) -> usize {
        self.line_starts.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_ascii() {
        let idx = LineIndex::new("ab\ncd\n\nx");
        assert_eq!(idx.line_count(), 4);
        assert_eq!(idx.line_col(0), (1, 1));
        assert_eq!(idx.line_col(2), (1, 3)); // the newline itself
        assert_eq!(idx.line_col(3), (2, 1));
        assert_eq!(idx.line_col(6), (3, 1));
        assert_eq!(idx.line_col(7), (4, 1));
        assert_eq!(idx.line_col(8), (4, 2)); // end of source
        assert_eq!(idx.line_col(1000), (4, 2)); // clamped
    }

    #[test]
    fn line_col_counts_chars_not_bytes() {
        // "é" is 2 bytes, "€" is 3, "😀" is 4.
        let src = "é€😀x\n  ž = 1;";
        let idx = LineIndex::new(src);
        let x = src.find('x').unwrap();
        assert_eq!(x, 9);
        assert_eq!(idx.line_col(x), (1, 4));
        let eq = src.find('=').unwrap();
        assert_eq!(idx.line_col(eq), (2, 5));
        // Inside a multi-byte char: the char's own column.
        assert_eq!(idx.line_col(4), (1, 2));
        assert_eq!(idx.line_col(src.len()), (2, 9));
    }

    #[test]
    fn every_line_end_convention_counts_once() {
        let idx = LineIndex::new("a\rb\r\nc\nd");
        assert_eq!(idx.line_count(), 4);
        assert_eq!(idx.line_col(2), (2, 1));
        assert_eq!(idx.line_col(5), (3, 1));
        assert_eq!(idx.line_col(7), (4, 1));
    }

    #[test]
    fn line_bounds_exclude_the_line_end() {
        let idx = LineIndex::new("ab\r\ncd\ne");
        assert_eq!(idx.line_bounds(1), Span::new(0, 2));
        assert_eq!(idx.line_bounds(4), Span::new(4, 6));
        assert_eq!(idx.line_bounds(99), Span::new(7, 8));
    }

    #[test]
    fn line_col_empty_source() {
        let idx = LineIndex::new("");
        assert_eq!(idx.line_col(0), (1, 1));
        assert_eq!(idx.line_col(5), (1, 1));
    }

    #[test]
    fn utf16_columns_round_trip() {
        // `é` is 2 bytes and 1 UTF-16 unit; `𝕏` is 4 bytes and 2 units.
        let text = "// é𝕏\nPoints { p: (0,0,0); }";
        let idx = LineIndex::new(text);
        let x = text.find('𝕏').unwrap();
        assert_eq!(idx.utf16_position(x), (0, 4));
        assert_eq!(idx.utf16_position(x + 4), (0, 6));
        assert_eq!(idx.utf16_offset(0, 6), x + 4);
        assert_eq!(idx.utf16_offset(0, 4), x);
        // Inside the surrogate pair: the character's start.
        assert_eq!(idx.utf16_offset(0, 5), x);
        let p = text.find("p:").unwrap();
        assert_eq!(idx.utf16_position(p), (1, 9));
        assert_eq!(idx.utf16_offset(1, 9), p);
        // Past the end of a line or of the text.
        assert_eq!(idx.utf16_offset(0, 99), text.find('\n').unwrap());
        assert_eq!(idx.utf16_offset(9, 0), text.len());
        // Inside a character: back to its start.
        assert_eq!(idx.utf16_position(x + 1), (0, 4));
    }

    #[test]
    fn a_lone_cr_ends_a_line_for_utf16_positions_too() {
        let text = "a\rbc\r\nd";
        let idx = LineIndex::new(text);
        assert_eq!(idx.utf16_position(3), (1, 1));
        assert_eq!(idx.utf16_offset(1, 1), 3);
        assert_eq!(idx.utf16_position(6), (2, 0));
        assert_eq!(idx.utf16_offset(1, 9), 4);
    }

    /// The index agrees with counting from the start of the text, on text
    /// of every kind of character and line end.
    #[test]
    fn lookups_agree_with_counting_from_the_start() {
        let pieces = ["a", "é", "€", "😀", "\n", "\r", "\r\n", "  ", "x;"];
        let mut seed = 12345u64;
        for _ in 0..200 {
            let mut text = String::new();
            for _ in 0..40 {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                text.push_str(pieces[(seed >> 33) as usize % pieces.len()]);
            }
            let idx = LineIndex::new(&text);
            for offset in (0..=text.len()).filter(|&o| text.is_char_boundary(o)) {
                let before = &text[..offset];
                let mut line = 0;
                let mut start = 0;
                let bytes = before.as_bytes();
                for (i, &b) in bytes.iter().enumerate() {
                    let ends =
                        b == b'\n' || (b == b'\r' && text.as_bytes().get(i + 1) != Some(&b'\n'));
                    if ends {
                        line += 1;
                        start = i + 1;
                    }
                }
                let chars = text[start..offset].chars().count();
                let units: usize = text[start..offset].chars().map(char::len_utf16).sum();
                assert_eq!(
                    idx.line_col(offset),
                    (line + 1, chars + 1),
                    "{text:?} at {offset}"
                );
                assert_eq!(
                    idx.utf16_position(offset),
                    (line, units),
                    "{text:?} at {offset}"
                );
                // The `\n` of a CRLF is part of the line end, which a
                // column cannot name.
                if !(before.ends_with('\r') && text[offset..].starts_with('\n')) {
                    assert_eq!(
                        idx.utf16_offset(line, units),
                        offset,
                        "{text:?} at {offset}"
                    );
                }
            }
        }
    }
}
