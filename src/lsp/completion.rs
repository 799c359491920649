//! `textDocument/completion`: section names outside sections, the keys,
//! keywords and options a section takes, and after `%`, `#` or `@` the
//! names and numbers declared. The words come from the compiler's own
//! tables (`hscene_lang::vocabulary`).

use hscene_lang::syntax::RefSigil;
use hscene_lang::tokens::{TokenKind, tokenize};
use hscene_lang::vocabulary;
use lsp_types::{CompletionItem, CompletionItemKind, CompletionParams, CompletionResponse};

use super::documents::{Document, Documents};
use super::request_error::RequestError;

pub fn complete(
    docs: &Documents,
    p: CompletionParams,
) -> Result<Option<CompletionResponse>, RequestError> {
    let (doc, offset) = docs.at(&p.text_document_position)?;
    Ok(Some(CompletionResponse::Array(items(doc, offset))))
}

/// Where the cursor is, as far as completion cares.
#[derive(Debug, PartialEq)]
enum Context<'a> {
    /// Outside every section.
    TopLevel,
    /// Right after a sigil, or inside a reference being typed.
    Reference(RefSigil),
    /// At the start of a statement of the named section.
    StatementStart(&'a str),
    /// After a comma of a statement of the named section.
    AfterComma(&'a str),
    /// Anywhere else (inside a value): nothing to offer.
    Elsewhere,
}

fn context(text: &str, offset: usize) -> Context<'_> {
    let tokens = tokenize(text);
    let before: Vec<_> = tokens
        .iter()
        .filter(|t| t.span.start() < offset && !t.kind.is_comment())
        .collect();
    // A reference the cursor is in (or just after).
    if let Some(last) = before.last()
        && last.kind == TokenKind::Reference
        && offset <= last.span.end()
    {
        return Context::Reference(match text.as_bytes()[last.span.start()] {
            b'%' => RefSigil::Percent,
            b'#' => RefSigil::Hash,
            _ => RefSigil::At,
        });
    }
    let mut section: Option<&str> = None;
    let mut pending_name: Option<&str> = None;
    let mut parens = 0usize;
    for t in &before {
        let s = &text[t.span.start()..t.span.end()];
        match t.kind {
            TokenKind::Ident if section.is_none() => pending_name = Some(s),
            TokenKind::LBrace => section = pending_name.take().or(Some("")),
            TokenKind::RBrace => section = None,
            TokenKind::LParen => parens += 1,
            TokenKind::RParen => parens = parens.saturating_sub(1),
            TokenKind::Semi => parens = 0,
            _ => {}
        }
    }
    if section.is_some() && parens > 0 {
        return Context::Elsewhere;
    }
    // The token being typed does not count as "before".
    let prev = before
        .iter()
        .rev()
        .find(|t| !(t.kind == TokenKind::Ident && t.span.end() >= offset));
    match (section, prev.map(|t| t.kind)) {
        (None, _) => Context::TopLevel,
        (Some(s), Some(TokenKind::LBrace | TokenKind::Semi)) => Context::StatementStart(s),
        (Some(s), Some(TokenKind::Comma)) => Context::AfterComma(s),
        _ => Context::Elsewhere,
    }
}

fn items(doc: &Document, offset: usize) -> Vec<CompletionItem> {
    let words = |words: &[&str], kind| -> Vec<CompletionItem> {
        words
            .iter()
            .map(|w| CompletionItem {
                label: (*w).to_owned(),
                kind: Some(kind),
                ..CompletionItem::default()
            })
            .collect()
    };
    match context(&doc.text, offset) {
        Context::TopLevel => words(vocabulary::sections(), CompletionItemKind::MODULE),
        Context::Reference(sigil) => names(doc, sigil),
        Context::StatementStart("Globals") => {
            words(vocabulary::global_keys(), CompletionItemKind::PROPERTY)
        }
        Context::StatementStart("BRDFs") | Context::AfterComma("BRDFs") => {
            words(vocabulary::material_fields(), CompletionItemKind::PROPERTY)
        }
        Context::StatementStart("Objects") => {
            words(vocabulary::object_keywords(), CompletionItemKind::KEYWORD)
        }
        Context::AfterComma("Objects") => {
            words(vocabulary::object_options(), CompletionItemKind::PROPERTY)
        }
        Context::AfterComma("Lights") => {
            words(vocabulary::light_options(), CompletionItemKind::PROPERTY)
        }
        Context::StatementStart("Transformations") => {
            words(vocabulary::transformations(), CompletionItemKind::KEYWORD)
        }
        _ => Vec::new(),
    }
}

/// The declared names and numbers a reference with `sigil` can name.
fn names(doc: &Document, sigil: RefSigil) -> Vec<CompletionItem> {
    let mut out: Vec<CompletionItem> = doc
        .symbols
        .definitions
        .iter()
        .filter(|d| d.kind.sigil() == sigil)
        .flat_map(|d| {
            let detail = format!("{} {}", d.kind.as_str(), d.label());
            let name = d.name.as_ref().map(|n| n.text.to_string());
            let number = d.number.map(|k| k.to_string());
            name.into_iter()
                .chain(number)
                .map(move |label| CompletionItem {
                    label,
                    kind: Some(CompletionItemKind::VARIABLE),
                    detail: Some(detail.clone()),
                    ..CompletionItem::default()
                })
        })
        .collect();
    if sigil == RefSigil::At {
        out.push(CompletionItem {
            label: "camera".into(),
            kind: Some(CompletionItemKind::VARIABLE),
            detail: Some("the camera".into()),
            ..CompletionItem::default()
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ctx(text: &str) -> Context<'_> {
        let at = text.find('|').unwrap();
        // The cursor marker is not part of the text the server sees.
        let owned: &'static str = Box::leak(text.replacen('|', "", 1).into_boxed_str());
        context(owned, at)
    }

    #[test]
    fn contexts() {
        assert_eq!(ctx("|"), Context::TopLevel);
        assert_eq!(ctx("Points { } Ob|"), Context::TopLevel);
        assert_eq!(ctx("Objects { Sph|"), Context::StatementStart("Objects"));
        assert_eq!(
            ctx("Objects { Sphere %1, 0.1, #1, wire| }"),
            Context::AfterComma("Objects")
        );
        assert_eq!(
            ctx("Objects { Sphere %|"),
            Context::Reference(RefSigil::Percent)
        );
        assert_eq!(
            ctx("Objects { Sphere %1, 0.1, #gl|"),
            Context::Reference(RefSigil::Hash)
        );
        assert_eq!(ctx("Globals { to = (0,|"), Context::Elsewhere);
        assert_eq!(
            ctx("BRDFs { ambient = (1,1,1),|"),
            Context::AfterComma("BRDFs")
        );
        assert_eq!(ctx("Globals { to = |"), Context::Elsewhere);
    }
}
