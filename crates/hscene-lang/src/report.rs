//! Diagnostics as people read them: miette's graphical report (the one
//! `hscene check` prints), or one `file:line:col:` line each. Here rather
//! than in the binary so that every front end (the CLI, the Python
//! binding's `SceneError`) shows the same text.
//!
//! Output is bounded whatever the input: at most [`MAX_SHOWN`] diagnostics
//! are shown in full, then one line counts the rest (as rustc does), and
//! the graphical report is used only for spans on lines it can draw (see
//! [`fits_graphical`]). `docs/limits.md` states both limits.

use std::sync::Arc;

use miette::{GraphicalReportHandler, GraphicalTheme};

use crate::{Diagnostic, IndexedSource, LineIndex, Omitted, Severity};

/// Diagnostics shown in full per file; the rest are counted.
pub const MAX_SHOWN: usize = 100;

/// Longest source line (in bytes) the graphical report draws: it repeats
/// the line and pads its labels to the column, and it cannot represent
/// columns past 65535 at all. Longer lines get the short format.
const MAX_GRAPHICAL_LINE: usize = 1000;

/// Most lines a span may cover and still be drawn graphically.
const MAX_GRAPHICAL_LINES: usize = 40;

/// The graphical report of the first [`MAX_SHOWN`] of `diagnostics` of
/// the file `name` (whose text is `source`), each followed by a blank
/// line, then [`omitted_note`] if any were left out. `color`: ANSI
/// colours, for a terminal.
pub fn human_report(
    name: &str,
    source: &str,
    diagnostics: &[Diagnostic],
    omitted: Omitted,
    color: bool,
) -> String {
    let index = Arc::new(LineIndex::new(source));
    let shown = &diagnostics[..diagnostics.len().min(MAX_SHOWN)];
    let theme = if color {
        GraphicalTheme::unicode()
    } else {
        GraphicalTheme::unicode_nocolor()
    };
    let handler = GraphicalReportHandler::new_themed(theme);
    // One index of the text for every report: miette finds each span's
    // lines through it by binary search.
    let indexed = IndexedSource::from_index(name, Arc::clone(&index));
    let mut out = String::new();
    for d in shown {
        if fits_graphical(&index, d) {
            let report = miette::Report::new(d.clone()).with_source_code(indexed.clone());
            // Writing into a String cannot fail.
            let _ = handler.render_report(&mut out, report.as_ref());
        } else {
            out.push_str(&short_line(name, &index, d));
            if let Some(help) = &d.help {
                out.push_str(&format!("  help: {help}\n"));
            }
        }
        out.push('\n');
    }
    if let Some((message, _, _)) = omitted_note(diagnostics, omitted) {
        out.push_str(&format!("{name}: note: {message}\n"));
    }
    out
}

/// `path:line:col: severity: message [CODE]` and a line end.
pub fn short_line(name: &str, index: &LineIndex, d: &Diagnostic) -> String {
    let (line, col) = index.line_col(d.span.start());
    format!(
        "{name}:{line}:{col}: {}: {} [{}]\n",
        d.severity.as_str(),
        d.message,
        d.code.as_str()
    )
}

/// The note counting what is not shown: those past [`MAX_SHOWN`] and
/// those the compiler counted without keeping; with the errors and the
/// warnings among them. `None` when everything is shown.
pub fn omitted_note(
    diagnostics: &[Diagnostic],
    omitted: Omitted,
) -> Option<(String, usize, usize)> {
    let rest = &diagnostics[diagnostics.len().min(MAX_SHOWN)..];
    if rest.is_empty() && omitted.total() == 0 {
        return None;
    }
    let errors = rest
        .iter()
        .filter(|d| d.severity == Severity::Error)
        .count()
        + omitted.errors;
    let warnings = rest.len() + omitted.total() - errors;
    let message = format!(
        "{} more diagnostic(s) not shown ({errors} error(s), {warnings} warning(s)); at most {MAX_SHOWN} are shown per file",
        errors + warnings
    );
    Some((message, errors, warnings))
}

/// Whether miette's graphical report can draw the span: both of its end
/// lines are at most [`MAX_GRAPHICAL_LINE`] bytes long and it covers at
/// most [`MAX_GRAPHICAL_LINES`] lines.
fn fits_graphical(index: &LineIndex, d: &Diagnostic) -> bool {
    let first = index.line_bounds(d.span.start());
    let last = index.line_bounds(d.span.end());
    let lines = index.line_col(last.start()).0 - index.line_col(first.start()).0 + 1;
    first.len() <= MAX_GRAPHICAL_LINE
        && last.len() <= MAX_GRAPHICAL_LINE
        && lines <= MAX_GRAPHICAL_LINES
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Code, Span};

    /// miette cannot draw columns past 65535; such spans get the short
    /// format instead of a panic.
    #[test]
    fn far_columns_fall_back_to_the_short_format() {
        let source = format!("{}@", " ".repeat(70_000));
        let d = Diagnostic::new(Code::Syntax, Span::new(70_000, 70_001), "bad");
        let text = human_report("s.hsc", &source, &[d], Default::default(), false);
        assert!(
            text.starts_with("s.hsc:1:70001: error: bad [HSC0001]"),
            "{text}"
        );
    }
}
