//! The compiler's diagnostics as LSP diagnostics: code, severity, the hint
//! appended to the message, and as related information the declaration a
//! diagnostic's references point to (or the earlier one of a duplicate name).

use std::collections::HashMap;

use hscene_lang::symbols::SymbolIndex;
use hscene_lang::syntax::Ident;
use hscene_lang::{Code, Severity, Span};
use lsp_types::{
    Diagnostic, DiagnosticRelatedInformation, DiagnosticSeverity, Location, NumberOrString, Uri,
};

use super::documents::Document;
use super::position::range;

pub fn to_lsp(uri: &Uri, doc: &Document) -> Vec<Diagnostic> {
    if doc.too_large() {
        return vec![Diagnostic {
            range: lsp_types::Range::default(),
            severity: Some(DiagnosticSeverity::ERROR),
            source: Some("hscene".into()),
            message: format!(
                "this document is {} bytes, larger than the limit of {} bytes for a scene file: it is not analysed",
                doc.text.len(),
                crate::input::MAX_SCENE_BYTES
            ),
            ..Diagnostic::default()
        }];
    }
    let omitted = doc.compiled.omitted;
    let related = Related::new(&doc.symbols);
    let mut all: Vec<Diagnostic> = doc
        .compiled
        .diagnostics
        .iter()
        .map(|d| {
            let message = match &d.help {
                Some(help) => format!("{}\nhelp: {help}", d.message),
                None => d.message.clone(),
            };
            let related: Vec<DiagnosticRelatedInformation> = related
                .of(d)
                .into_iter()
                .map(|(span, message)| DiagnosticRelatedInformation {
                    location: Location::new(uri.clone(), range(&doc.lines, span)),
                    message,
                })
                .collect();
            Diagnostic {
                range: range(&doc.lines, d.span),
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
        .collect();
    if omitted.total() > 0 {
        // Past the compiler's cap: one line says how many more there are.
        all.push(Diagnostic {
            range: lsp_types::Range::default(),
            severity: Some(DiagnosticSeverity::INFORMATION),
            source: Some("hscene".into()),
            message: format!(
                "{} more diagnostic(s) ({} error(s), {} warning(s)) were found and not kept: at most {} are kept",
                omitted.total(),
                omitted.errors,
                omitted.warnings,
                hscene_lang::MAX_KEPT_DIAGNOSTICS
            ),
            ..Diagnostic::default()
        });
    }
    all
}

/// The declarations and references of a document, indexed once per
/// publication, so that the related places of every diagnostic are found
/// by binary search: 10,000 diagnostics against 100,000 references stay
/// linear-logarithmic.
struct Related<'s> {
    symbols: &'s SymbolIndex,
    /// Indices into `symbols.uses`, by the start of the reference.
    uses: Vec<usize>,
    /// Declared names, by position.
    names: Vec<&'s Ident>,
    /// Where each name is declared.
    by_text: HashMap<&'s str, Vec<Span>>,
}

impl<'s> Related<'s> {
    fn new(symbols: &'s SymbolIndex) -> Self {
        let mut uses: Vec<usize> = (0..symbols.uses.len()).collect();
        uses.sort_by_key(|&i| symbols.uses[i].reference.span.start());
        let mut names: Vec<&Ident> = symbols
            .definitions
            .iter()
            .filter_map(|def| def.name.as_ref())
            .collect();
        names.sort_by_key(|n| n.span.start());
        let mut by_text: HashMap<&str, Vec<Span>> = HashMap::new();
        for n in &names {
            by_text.entry(n.text.as_str()).or_default().push(n.span);
        }
        Related {
            symbols,
            uses,
            names,
            by_text,
        }
    }

    /// Places worth showing beside a diagnostic: for a duplicate name the
    /// other declarations of the name, else the declarations the
    /// references inside the diagnostic name.
    fn of(&self, d: &hscene_lang::Diagnostic) -> Vec<(Span, String)> {
        let inside = |s: Span| d.span.start() <= s.start() && s.end() <= d.span.end();
        if d.code == Code::DuplicateName {
            // The first declared name, in source order, inside the
            // diagnostic or holding it.
            let at = self
                .names
                .partition_point(|n| n.span.start() < d.span.start());
            let holds =
                |n: &&Ident| n.span.start() <= d.span.start() && d.span.end() <= n.span.end();
            let before = at.checked_sub(1).map(|i| self.names[i]).filter(holds);
            let here = self
                .names
                .get(at)
                .copied()
                .filter(|n| inside(n.span) || holds(n));
            let Some(name) = before.or(here) else {
                return Vec::new();
            };
            return self.by_text[name.text.as_str()]
                .iter()
                .filter(|&&span| span != name.span)
                .map(|&span| (span, format!("`{}` is also declared here", name.text)))
                .collect();
        }
        let uses = &self.symbols.uses;
        let first = self
            .uses
            .partition_point(|&i| uses[i].reference.span.start() < d.span.start());
        self.uses[first..]
            .iter()
            .map(|&i| &uses[i])
            .take_while(|u| u.reference.span.start() <= d.span.end())
            .filter(|u| inside(u.reference.span))
            .filter_map(|u| {
                let def = &self.symbols.definitions[u.definition?];
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
}

#[cfg(test)]
mod tests {
    use std::str::FromStr;

    use proptest::prelude::*;

    use super::*;
    use crate::cli::Format;
    use crate::lsp::documents::Documents;

    /// Pieces of scenes, right and wrong, with every kind of line end and
    /// characters of 1 to 4 UTF-8 bytes (1 or 2 UTF-16 units).
    const PIECES: &[&str] = &[
        "Points { p = (0,0,0); q = (0.5,0,0); }",
        "Points { é = (0,0,0); }",
        "// 𝕏 é comment\n",
        "BRDFs { m: diffuse = (1,1,1); }",
        "Objects { Sphere %p, 0.1, #m; }",
        "Objects { Sphere %nowhere, 0.1, #missing; }",
        "Objects { Sphere %p, -1, #m; }",
        "Globals { from = %p; to = %q; fov = 1e308; }",
        "Lights { %q, (1,1,1), (0,0,0); }",
        "Bogus { x = 1; }",
        "Points { a = (1,1,1); }",
        "{",
        "}",
        ";",
        "\n",
        "\r\n",
        "\r",
        "  ",
        "\"𝕏\"",
    ];

    /// A lone CR ends a line for `check` (files are decoded so); the
    /// server analyses an editor's buffer the same way (proptest found a
    /// string cut by a lone CR reported once by the server, twice by
    /// `check`).
    #[test]
    fn a_lone_cr_is_a_line_end_for_the_server_as_for_check() {
        let text = "{\"\u{1d54f}\"\r\"\u{1d54f}\"".to_string();
        let uri = lsp_types::Uri::from_str("untitled:cr").unwrap();
        let mut docs = Documents::default();
        docs.open(uri.clone(), text.clone(), 1);
        let served = docs.get(&uri).unwrap().compiled.diagnostics.clone();
        let decoded = hscene_lang::source::decode(text.into_bytes()).unwrap();
        let checked = hscene_lang::compile(&decoded).diagnostics;
        assert_eq!(served, checked);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// `check --format json` and the language server put every
        /// diagnostic at the same place: the server's UTF-16 position is
        /// the check's line and character column, converted.
        #[test]
        fn check_and_the_server_agree_on_positions(picks in proptest::collection::vec(0..PIECES.len(), 1..40)) {
            let text: String = picks.iter().map(|&i| PIECES[i]).collect();
            let uri = lsp_types::Uri::from_str("untitled:prop").unwrap();
            let mut docs = Documents::default();
            docs.open(uri.clone(), text.clone(), 1);
            let doc = docs.get(&uri).unwrap();
            let ours = to_lsp(&uri, doc);
            // `check` reads files decoded (lone CR and CRLF as they are
            // counted, the text otherwise unchanged).
            let decoded = hscene_lang::source::decode(text.clone().into_bytes()).unwrap();
            let compiled = hscene_lang::compile(&decoded);
            let report = crate::report::format_diagnostics(
                std::path::Path::new("prop.hsc"),
                &decoded,
                &compiled.diagnostics,
                compiled.omitted,
                Format::Json,
                false,
            );
            let checked: Vec<serde_json::Value> = report
                .lines()
                .map(|l| serde_json::from_str(l).unwrap())
                .filter(|v: &serde_json::Value| v["severity"] != "note")
                .collect();
            prop_assert!(checked.len() <= ours.len());
            let lines: Vec<&str> = decoded.split('\n').collect();
            for (c, d) in checked.iter().zip(&ours) {
                prop_assert_eq!(c["code"].as_str(), d.code.as_ref().map(|code| match code {
                    NumberOrString::String(s) => s.as_str(),
                    NumberOrString::Number(_) => "",
                }));
                let line = c["line"].as_u64().unwrap() as usize;
                let column = c["column"].as_u64().unwrap() as usize;
                prop_assert_eq!(d.range.start.line as usize, line - 1);
                let units: usize = lines[line - 1].chars().take(column - 1).map(char::len_utf16).sum();
                prop_assert_eq!(d.range.start.character as usize, units);
            }
        }
    }
}
