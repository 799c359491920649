//! Printing diagnostics: human (miette), short (gcc-style) and JSON.

use std::path::Path;

use hscene_lang::{Diagnostic, LineIndex};
use miette::{GraphicalReportHandler, GraphicalTheme, NamedSource};

use crate::cli::Format;

/// Render one file's diagnostics in the chosen format.
pub fn format_diagnostics(
    path: &Path,
    source: &str,
    diagnostics: &[Diagnostic],
    format: Format,
    color: bool,
) -> String {
    let name = path.display().to_string();
    let mut out = String::new();
    match format {
        Format::Human => {
            let theme = if color {
                GraphicalTheme::unicode()
            } else {
                GraphicalTheme::unicode_nocolor()
            };
            let handler = GraphicalReportHandler::new_themed(theme);
            for d in diagnostics {
                let report = miette::Report::new(d.clone())
                    .with_source_code(NamedSource::new(&name, source.to_string()));
                // Writing into a String cannot fail.
                let _ = handler.render_report(&mut out, report.as_ref());
                out.push('\n');
            }
        }
        Format::Short => {
            let index = LineIndex::new(source);
            for d in diagnostics {
                let (line, col) = index.line_col(d.span.start);
                out.push_str(&format!(
                    "{name}:{line}:{col}: {}: {} [{}]\n",
                    d.severity.as_str(),
                    d.message,
                    d.code.as_str()
                ));
            }
        }
        Format::Json => {
            let index = LineIndex::new(source);
            for d in diagnostics {
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
    out
}
