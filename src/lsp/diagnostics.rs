//! The compiler's diagnostics as LSP diagnostics: code, severity, the hint
//! appended to the message, and as related information the declaration a
//! diagnostic's references point to (or the earlier one of a duplicate name).

use hscene_lang::symbols::SymbolIndex;
use hscene_lang::{Code, Severity};
use lsp_types::{
    Diagnostic, DiagnosticRelatedInformation, DiagnosticSeverity, Location, NumberOrString, Uri,
};

use super::documents::Document;
use super::position::range;

pub fn to_lsp(uri: &Uri, doc: &Document) -> Vec<Diagnostic> {
    doc.compiled
        .diagnostics
        .iter()
        .map(|d| {
            let message = match &d.help {
                Some(help) => format!("{}\nhelp: {help}", d.message),
                None => d.message.clone(),
            };
            let related: Vec<DiagnosticRelatedInformation> = related(&doc.symbols, d)
                .into_iter()
                .map(|(span, message)| DiagnosticRelatedInformation {
                    location: Location::new(uri.clone(), range(&doc.text, span)),
                    message,
                })
                .collect();
            Diagnostic {
                range: range(&doc.text, d.span),
                severity: Some(match d.severity {
                    Severity::Error => DiagnosticSeverity::ERROR,
                    Severity::Warning => DiagnosticSeverity::WARNING,
                }),
                code: Some(NumberOrString::String(d.code.as_str().into())),
                source: Some("hscene".into()),
                message,
                related_information: (!related.is_empty()).then_some(related),
                ..Diagnostic::default()
            }
        })
        .collect()
}

/// Places worth showing beside a diagnostic.
fn related(symbols: &SymbolIndex, d: &hscene_lang::Diagnostic) -> Vec<(hscene_lang::Span, String)> {
    let inside = |s: hscene_lang::Span| d.span.start <= s.start && s.end <= d.span.end;
    if d.code == Code::DuplicateName {
        // The declarations with the name the diagnostic is at, other than itself.
        let Some(name) = symbols
            .definitions
            .iter()
            .filter_map(|def| def.name.as_ref())
            .find(|n| inside(n.span) || (n.span.start <= d.span.start && d.span.end <= n.span.end))
        else {
            return Vec::new();
        };
        return symbols
            .definitions
            .iter()
            .filter_map(|def| def.name.as_ref())
            .filter(|n| n.text == name.text && n.span != name.span)
            .map(|n| (n.span, format!("`{}` is also declared here", n.text)))
            .collect();
    }
    symbols
        .uses
        .iter()
        .filter(|u| inside(u.reference.span))
        .filter_map(|u| {
            let def = &symbols.definitions[u.definition?];
            Some((
                def.span,
                format!(
                    "`{}` is declared here ({} {})",
                    u.reference,
                    def.kind.as_str(),
                    def.label()
                ),
            ))
        })
        .collect()
}
