//! `textDocument/formatting` through the formatter of `hscene fmt`.

use lsp_types::{DocumentFormattingParams, Range, TextEdit};

use super::documents::Documents;
use super::position::position;
use super::request_error::RequestError;

/// One edit replacing the whole text, or none when it is already formatted.
/// A scene with syntax errors is not formatted (the diagnostics say why).
pub fn format(
    docs: &Documents,
    p: DocumentFormattingParams,
) -> Result<Option<Vec<TextEdit>>, RequestError> {
    let doc = docs.require(&p.text_document.uri)?;
    let Ok(formatted) = hscene_lang::format(&doc.text) else {
        return Ok(None);
    };
    if formatted == doc.text {
        return Ok(Some(Vec::new()));
    }
    let whole = Range::new(
        position(&doc.lines, 0),
        position(&doc.lines, doc.text.len()),
    );
    Ok(Some(vec![TextEdit::new(whole, formatted)]))
}
