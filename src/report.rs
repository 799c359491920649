//! Printing diagnostics: human (miette), short (gcc-style) and JSON.
//!
//! Output is bounded whatever the input: at most [`MAX_SHOWN`] diagnostics
//! per file are printed in full, then one line counts the rest (as rustc
//! does), and the graphical report is used only for spans on lines it can
//! draw (see [`fits_graphical`]). `docs/limits.md` states both limits.

use std::path::Path;
use std::sync::Arc;

use hscene_lang::{Diagnostic, IndexedSource, LineIndex, Severity};
use miette::{GraphicalReportHandler, GraphicalTheme};

use crate::cli::Format;

/// Diagnostics printed in full per file; the rest are counted.
pub const MAX_SHOWN: usize = 100;

/// Longest source line (in bytes) the graphical report draws: it repeats
/// the line and pads its labels to the column, and it cannot represent
/// columns past 65535 at all. Longer lines get the short format.
const MAX_GRAPHICAL_LINE: usize = 1000;

/// Most lines a span may cover and still be drawn graphically.
const MAX_GRAPHICAL_LINES: usize = 40;

/// Render one file's diagnostics in the chosen format.
pub fn format_diagnostics(
    path: &Path,
    source: &str,
    diagnostics: &[Diagnostic],
    omitted: hscene_lang::Omitted,
    format: Format,
    color: bool,
) -> String {
    let name = path.display().to_string();
    let index = Arc::new(LineIndex::new(source));
    let shown = &diagnostics[..diagnostics.len().min(MAX_SHOWN)];
    let mut out = String::new();
    match format {
        Format::Human => {
            let theme = if color {
                GraphicalTheme::unicode()
            } else {
                GraphicalTheme::unicode_nocolor()
            };
            let handler = GraphicalReportHandler::new_themed(theme);
            // One index of the text for every report: miette finds each
            // span's lines through it by binary search.
            let indexed = IndexedSource::from_index(&name, Arc::clone(&index));
            for d in shown {
                if fits_graphical(&index, d) {
                    let report = miette::Report::new(d.clone()).with_source_code(indexed.clone());
                    // Writing into a String cannot fail.
                    let _ = handler.render_report(&mut out, report.as_ref());
                } else {
                    out.push_str(&short_line(&name, &index, d));
                    if let Some(help) = &d.help {
                        out.push_str(&format!("  help: {help}\n"));
                    }
                }
                out.push('\n');
            }
        }
        Format::Short => {
            for d in shown {
                out.push_str(&short_line(&name, &index, d));
            }
        }
        Format::Json => {
            for d in shown {
                let (line, column) = index.line_col(d.span.start);
                let (end_line, end_column) = index.line_col(d.span.end);
                let obj = serde_json::json!({
                    "file": name,
                    "line": line,
                    "column": column,
                    "end_line": end_line,
                    "end_column": end_column,
                    "severity": d.severity.as_str(),
                    "code": d.code.as_str(),
                    "message": d.message,
                    "help": d.help,
                });
                out.push_str(&obj.to_string());
                out.push('\n');
            }
        }
    }
    // Past the shown ones: those kept and not shown, and those the
    // compiler counted without keeping (`hscene_lang::Omitted`).
    let rest = &diagnostics[shown.len()..];
    if !rest.is_empty() || omitted.total() > 0 {
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
        match format {
            Format::Json => {
                let obj = serde_json::json!({
                    "file": name,
                    "severity": "note",
                    "message": message,
                    "omitted_errors": errors,
                    "omitted_warnings": warnings,
                });
                out.push_str(&obj.to_string());
                out.push('\n');
            }
            Format::Human | Format::Short => {
                out.push_str(&format!("{name}: note: {message}\n"));
            }
        }
    }
    out
}

/// `path:line:col: severity: message [CODE]`.
fn short_line(name: &str, index: &LineIndex, d: &Diagnostic) -> String {
    let (line, col) = index.line_col(d.span.start);
    format!(
        "{name}:{line}:{col}: {}: {} [{}]\n",
        d.severity.as_str(),
        d.message,
        d.code.as_str()
    )
}

/// Whether miette's graphical report can draw the span: both of its end
/// lines are at most [`MAX_GRAPHICAL_LINE`] bytes long and it covers at
/// most [`MAX_GRAPHICAL_LINES`] lines.
fn fits_graphical(index: &LineIndex, d: &Diagnostic) -> bool {
    let first = index.line_bounds(d.span.start);
    let last = index.line_bounds(d.span.end);
    let lines = index.line_col(last.start).0 - index.line_col(first.start).0 + 1;
    first.len() <= MAX_GRAPHICAL_LINE
        && last.len() <= MAX_GRAPHICAL_LINE
        && lines <= MAX_GRAPHICAL_LINES
}

#[cfg(test)]
mod tests {
    use super::*;
    use hscene_lang::{Code, Span};

    fn error_at(start: usize, end: usize) -> Diagnostic {
        Diagnostic::new(Code::Syntax, Span::new(start, end), "bad")
    }

    /// miette cannot draw columns past 65535; such spans get the short
    /// format instead of a panic.
    #[test]
    fn far_columns_fall_back_to_the_short_format() {
        let source = format!("{}@", " ".repeat(70_000));
        let d = error_at(70_000, 70_001);
        let text = format_diagnostics(
            Path::new("s.hsc"),
            &source,
            &[d],
            Default::default(),
            Format::Human,
            false,
        );
        assert!(
            text.starts_with("s.hsc:1:70001: error: bad [HSC0001]"),
            "{text}"
        );
    }

    #[test]
    fn at_most_max_shown_then_a_count() {
        let source = ";".repeat(1000);
        let all: Vec<_> = (0..1000).map(|i| error_at(i, i + 1)).collect();
        for format in [Format::Human, Format::Short, Format::Json] {
            let text = format_diagnostics(
                Path::new("s.hsc"),
                &source,
                &all,
                Default::default(),
                format,
                false,
            );
            assert_eq!(text.matches("HSC0001").count(), MAX_SHOWN, "{format:?}");
            assert!(text.contains("900 more diagnostic(s) not shown (900 error(s), 0 warning(s))"));
        }
    }
}
