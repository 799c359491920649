//! What the parser's tests share: parsing that must be clean, and taking
//! the resulting tree apart.

use super::{Parsed, parse};
use crate::diagnostic::{Code, Span};
use crate::syntax::{RefSigil, RefTarget, Section, SourceFile, Statement, Value};

/// Parses `src` and asserts that there are no diagnostics.
pub(super) fn clean(src: &str) -> SourceFile {
    let parsed = parse(src);
    assert!(
        parsed.diagnostics.is_empty(),
        "unexpected diagnostics for {src:?}: {:#?}",
        parsed.diagnostics
    );
    parsed.file
}

/// The only statement of the only section.
pub(super) fn only_statement(src: &str) -> Statement {
    let mut file = clean(src);
    assert_eq!(file.sections.len(), 1);
    let mut section = file.sections.remove(0);
    assert_eq!(section.statements.len(), 1, "{src}");
    section.statements.remove(0)
}

pub(super) fn text(src: &str, span: Span) -> &str {
    &src[span.start()..span.end()]
}

pub(super) fn number(v: &Value) -> f64 {
    match v {
        Value::Number { value, .. } => *value,
        other => panic!("not a number: {other:?}"),
    }
}

pub(super) fn reference(v: &Value) -> (RefSigil, RefTarget) {
    match v {
        Value::Reference(r) => (r.sigil, r.target.clone()),
        other => panic!("not a reference: {other:?}"),
    }
}

pub(super) fn tuple(v: &Value) -> &[Value] {
    match v {
        Value::Tuple { items, .. } => items,
        other => panic!("not a tuple: {other:?}"),
    }
}

pub(super) fn numbers(v: &Value) -> Vec<f64> {
    tuple(v).iter().map(number).collect()
}

pub(super) fn codes(parsed: &Parsed) -> Vec<Code> {
    parsed.diagnostics.iter().map(|d| d.code).collect()
}

pub(super) fn section<'f>(file: &'f SourceFile, name: &str) -> &'f Section {
    file.sections
        .iter()
        .find(|s| s.name.text == name)
        .unwrap_or_else(|| panic!("no section {name}"))
}
