//! Printing diagnostics: human (miette), short (gcc-style) and JSON.
//!
//! The human and short forms are `hscene_lang::report`'s (shared with the
//! Python binding); this adds the JSON one. Output is bounded whatever the
//! input: at most [`MAX_SHOWN`] diagnostics per file are printed in full,
//! then one line counts the rest.

use std::path::Path;

use hscene_lang::report::{MAX_SHOWN, human_report, omitted_note, short_line};
use hscene_lang::{Diagnostic, LineIndex};

use crate::cli::Format;

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
    if format == Format::Human {
        return human_report(&name, source, diagnostics, omitted, color);
    }
    let index = LineIndex::new(source);
    let shown = &diagnostics[..diagnostics.len().min(MAX_SHOWN)];
    let mut out = String::new();
    for d in shown {
        if format == Format::Short {
            out.push_str(&short_line(&name, &index, d));
            continue;
        }
        let (line, column) = index.line_col(d.span.start());
        let (end_line, end_column) = index.line_col(d.span.end());
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
    if let Some((message, errors, warnings)) = omitted_note(diagnostics, omitted) {
        if format == Format::Json {
            let obj = serde_json::json!({
                "file": name,
                "severity": "note",
                "message": message,
                "omitted_errors": errors,
                "omitted_warnings": warnings,
            });
            out.push_str(&obj.to_string());
            out.push('\n');
        } else {
            out.push_str(&format!("{name}: note: {message}\n"));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use hscene_lang::{Code, Span};

    fn error_at(start: usize, end: usize) -> Diagnostic {
        Diagnostic::new(Code::Syntax, Span::new(start, end), "bad")
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
