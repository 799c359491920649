//! A scene's text as miette's [`SourceCode`], located through a
//! [`LineIndex`].
//!
//! miette's own implementation for `str` finds a span's lines by scanning
//! the text from its first byte, so reporting `k` diagnostics of an `n`-byte
//! file costs `k * n`: on a 3 MB scene with a hundred warnings shown, more
//! than half of `check`'s time. Here the span's line is found by binary
//! search and miette's scan runs over a window that starts a few lines
//! before it, so a report costs what the lines it draws cost. The result is
//! the one miette computes on the whole text (same window, same line and
//! column numbers): see the tests, which compare the two on every span of
//! texts with every line-end convention.

use std::sync::Arc;

use miette::{MietteError, MietteSpanContents, SourceCode, SourceSpan, SpanContents};

use crate::line_index::LineIndex;

/// A named source text with its line index, shared cheaply between the
/// reports of one file.
#[derive(Clone, Debug)]
pub struct IndexedSource {
    name: Arc<str>,
    lines: Arc<LineIndex>,
}

impl IndexedSource {
    /// Indexes `text` (copied once) under `name`.
    pub fn new(name: &str, text: &str) -> Self {
        IndexedSource::from_index(name, Arc::new(LineIndex::new(text)))
    }

    /// A source over an index already built (the text is the index's).
    pub fn from_index(name: &str, lines: Arc<LineIndex>) -> Self {
        IndexedSource {
            name: Arc::from(name),
            lines,
        }
    }

    /// The line index, for positions of the same text.
    pub fn lines(&self) -> &LineIndex {
        &self.lines
    }
}

impl SourceCode for IndexedSource {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        context_lines_before: usize,
        context_lines_after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        let text = self.lines.text();
        // The window starts at a line start at least `before + 1` whole
        // lines above the span's line. miette's scan carries only the last
        // `before` line starts and the lines counted, so from there on it
        // computes what it would have from the text's start, offset by the
        // lines skipped; the extra line keeps the skipped text strictly
        // before the span, where the scan only counts lines.
        let line = self.lines.line_number(span.offset().min(text.len()));
        let first = line.saturating_sub(context_lines_before + 1);
        let start = self.lines.line_start(first);
        let shifted = SourceSpan::new(span.offset().saturating_sub(start).into(), span.len());
        let inner = <[u8] as SourceCode>::read_span(
            &text.as_bytes()[start..],
            &shifted,
            context_lines_before,
            context_lines_after,
        )?;
        let window = inner.span();
        let data: &'a [u8] = inner.data();
        let contents = MietteSpanContents::new_named(
            self.name.to_string(),
            data,
            SourceSpan::new((window.offset() + start).into(), window.len()),
            inner.line() + first,
            inner.column(),
            inner.line_count() + first,
        );
        Ok(Box::new(contents))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Everything a report reads of a span's contents.
    fn seen(contents: &dyn SpanContents<'_>) -> (Vec<u8>, usize, usize, usize, usize, usize) {
        (
            contents.data().to_vec(),
            contents.span().offset(),
            contents.span().len(),
            contents.line(),
            contents.column(),
            contents.line_count(),
        )
    }

    fn agree_on_every_span(text: &str) {
        let indexed = IndexedSource::new("s.hsc", text);
        for offset in 0..=text.len() {
            for len in [0, 1, 2, 5, 17] {
                if offset + len > text.len() {
                    continue;
                }
                let span = SourceSpan::new(offset.into(), len);
                for (before, after) in [(0, 0), (1, 1), (2, 0), (0, 3), (3, 2)] {
                    let ours = indexed.read_span(&span, before, after);
                    let theirs = text.as_bytes().read_span(&span, before, after);
                    match (ours, theirs) {
                        (Ok(a), Ok(b)) => assert_eq!(
                            seen(a.as_ref()),
                            seen(b.as_ref()),
                            "{text:?} at {offset}+{len}, context {before}/{after}"
                        ),
                        (a, b) => assert_eq!(a.is_ok(), b.is_ok(), "{text:?} at {offset}+{len}"),
                    }
                }
            }
        }
    }

    #[test]
    fn the_window_is_the_one_miette_finds_from_the_start() {
        agree_on_every_span("Objects {\n  Sphere %1, 0.1, #1;\n\n  Sphere %2;\n}\n");
        agree_on_every_span("a\r\nbb\r\n\r\nccc\r\nd");
        agree_on_every_span("a\rbb\r\rccc\rd\r");
        agree_on_every_span("\n\n\nx\n\n\ny\n");
        agree_on_every_span("é€\n😀 x\r\n  ž = 1;\n");
        agree_on_every_span("");
        agree_on_every_span("no line end at all");
    }

    #[test]
    fn the_name_is_kept() {
        let source = IndexedSource::new("scene.hsc", "a\nb\n");
        let span = SourceSpan::new(2.into(), 1);
        let contents = source.read_span(&span, 1, 1).map_err(|e| e.to_string());
        assert_eq!(
            contents
                .ok()
                .and_then(|c| c.name().map(str::to_owned))
                .as_deref(),
            Some("scene.hsc")
        );
    }
}
