//! Go to definition, find references and rename, from the compiler's
//! symbol index (`hscene_lang::symbols`).

use std::collections::HashMap;

use hscene_lang::Span;
use hscene_lang::symbols::SymbolIndex;
use hscene_lang::syntax::RefTarget;
use lsp_types::{
    GotoDefinitionParams, GotoDefinitionResponse, Location, ReferenceParams, RenameParams,
    TextEdit, WorkspaceEdit,
};

use super::documents::Documents;
use super::position::range;
use super::request_error::RequestError;

/// The declaration of the reference (or declared name) under the cursor.
pub fn definition(
    docs: &Documents,
    p: GotoDefinitionParams,
) -> Result<Option<GotoDefinitionResponse>, RequestError> {
    let (doc, offset) = docs.at(&p.text_document_position_params)?;
    let uri = &p.text_document_position_params.text_document.uri;
    let Some(d) = doc.symbols.definition_at(offset) else {
        return Ok(None);
    };
    let def = &doc.symbols.definitions[d];
    let span = def.name.as_ref().map_or(def.span, |n| n.span);
    Ok(Some(GotoDefinitionResponse::Scalar(Location::new(
        uri.clone(),
        range(&doc.lines, span),
    ))))
}

/// Every reference to the declaration under the cursor (and the
/// declaration itself when the client asks for it).
pub fn references(
    docs: &Documents,
    p: ReferenceParams,
) -> Result<Option<Vec<Location>>, RequestError> {
    let (doc, offset) = docs.at(&p.text_document_position)?;
    let uri = &p.text_document_position.text_document.uri;
    let Some(d) = doc.symbols.definition_at(offset) else {
        return Ok(None);
    };
    let def = &doc.symbols.definitions[d];
    let mut spans: Vec<Span> = Vec::new();
    if p.context.include_declaration {
        spans.push(def.name.as_ref().map_or(def.span, |n| n.span));
    }
    spans.extend(doc.symbols.uses_of(d).map(|u| u.reference.span));
    Ok(Some(
        spans
            .into_iter()
            .map(|s| Location::new(uri.clone(), range(&doc.lines, s)))
            .collect(),
    ))
}

/// Renames a named point, material, line, plane, object or light: its
/// declaration and every `%name`/`#name`/`@name` that refers to it.
/// Numbered references stay as they are (they remain valid).
pub fn rename(docs: &Documents, p: RenameParams) -> Result<Option<WorkspaceEdit>, RequestError> {
    let (doc, offset) = docs.at(&p.text_document_position)?;
    let uri = p.text_document_position.text_document.uri.clone();
    let symbols = &doc.symbols;
    let d = symbols
        .definition_at(offset)
        .ok_or_else(|| RequestError::failed("there is no declared name here"))?;
    let def = &symbols.definitions[d];
    let Some(old) = &def.name else {
        return Err(RequestError::failed(format!(
            "{} has no name to rename; give it one with `name:`",
            def.label()
        )));
    };
    let sigil = def.kind.sigil().as_char();
    let new = p.new_name.strip_prefix(sigil).unwrap_or(&p.new_name);
    check_name(symbols, d, new)?;
    let mut edits = vec![TextEdit::new(range(&doc.lines, old.span), new.to_owned())];
    for u in symbols.uses_of(d) {
        if matches!(u.reference.target, RefTarget::Name(_)) {
            // Keep the sigil; replace the name after it.
            let name = Span::new(u.reference.span.start() + 1, u.reference.span.end());
            edits.push(TextEdit::new(range(&doc.lines, name), new.to_owned()));
        }
    }
    Ok(Some(WorkspaceEdit::new(HashMap::from([(uri, edits)]))))
}

/// A new name must be an identifier, not `camera`, and not taken by
/// another declaration its references could also mean.
fn check_name(symbols: &SymbolIndex, d: usize, new: &str) -> Result<(), RequestError> {
    let mut chars = new.chars();
    let valid = chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid {
        return Err(RequestError::failed(format!(
            "`{new}` is not a name: use letters, digits and `_`, not starting with a digit"
        )));
    }
    let kind = symbols.definitions[d].kind;
    if new == "camera" && kind.sigil() == hscene_lang::syntax::RefSigil::At {
        return Err(RequestError::failed("`@camera` is reserved for the camera"));
    }
    let taken = symbols.definitions.iter().enumerate().any(|(i, other)| {
        i != d
            && other.kind.sigil() == kind.sigil()
            && other.name.as_ref().is_some_and(|n| n.text == new)
    });
    if taken {
        return Err(RequestError::failed(format!("`{new}` is already declared")));
    }
    Ok(())
}
