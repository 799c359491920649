//! `textDocument/documentSymbol`: sections, each with what it declares.

use hscene_lang::symbols::SymbolKind as Kind;
use lsp_types::{DocumentSymbol, DocumentSymbolParams, DocumentSymbolResponse, SymbolKind};

use super::documents::Documents;
use super::position::range;
use super::request_error::RequestError;

pub fn document_symbols(
    docs: &Documents,
    p: DocumentSymbolParams,
) -> Result<Option<DocumentSymbolResponse>, RequestError> {
    let doc = docs.require(&p.text_document.uri)?;
    let file = hscene_lang::parse(&doc.text).file;
    let symbols = file
        .sections
        .iter()
        .map(|section| {
            let children: Vec<DocumentSymbol> = doc
                .symbols
                .definitions
                .iter()
                .filter(|d| {
                    section.span.start() <= d.span.start() && d.span.end() <= section.span.end()
                })
                .map(|d| {
                    let selection = d.name.as_ref().map_or(d.span, |n| n.span);
                    #[allow(deprecated)] // `deprecated` is a required field of the type.
                    DocumentSymbol {
                        name: d.label(),
                        detail: Some(d.kind.as_str().into()),
                        kind: match d.kind {
                            Kind::Point => SymbolKind::CONSTANT,
                            Kind::Material => SymbolKind::STRUCT,
                            Kind::Line | Kind::Plane => SymbolKind::FIELD,
                            Kind::Object => SymbolKind::OBJECT,
                            Kind::Light => SymbolKind::EVENT,
                        },
                        tags: None,
                        deprecated: None,
                        range: range(&doc.lines, d.span),
                        selection_range: range(&doc.lines, selection),
                        children: None,
                    }
                })
                .collect();
            #[allow(deprecated)]
            DocumentSymbol {
                name: section.name.text.to_string(),
                detail: None,
                kind: SymbolKind::NAMESPACE,
                tags: None,
                deprecated: None,
                range: range(&doc.lines, section.span),
                selection_range: range(&doc.lines, section.name.span),
                children: Some(children),
            }
        })
        .collect();
    Ok(Some(DocumentSymbolResponse::Nested(symbols)))
}
