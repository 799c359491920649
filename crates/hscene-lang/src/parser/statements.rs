//! One statement at a time: its text parsed alone by pest, and what is
//! done when that fails: a statement missing its `;` at a line end is split
//! there, an unterminated string is named as such, anything else gets
//! pest's error in words, and what can be salvaged (a leading name, the
//! references) is kept as a broken statement.

use pest::Parser as _;
use pest::error::{ErrorVariant, InputLocation};

use super::lexer::{ScanKind, ScanToken, is_ident_start};
use super::sections::{Body, Stmt};
use super::{MAX_NESTING, Rule, Scanner, SceneGrammar};
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::syntax::{BrokenStatement, RefSigil, RefTarget, Reference, Statement};

impl Scanner<'_> {
    /// Parses the statement `stmt` (ending at `end`) and adds it to `out`,
    /// or reports why it cannot be parsed and keeps it as broken.
    pub(super) fn flush(&mut self, stmt: &Stmt, end: usize, out: &mut Body) {
        let Some(mut start) = stmt.start else { return };
        if let Some(span) = stmt.too_deep {
            self.diagnostics.push(
                Diagnostic::new(
                    Code::NestingTooDeep,
                    span,
                    format!("parentheses nested more than {MAX_NESTING} levels deep"),
                )
                .with_label("too deep")
                .with_help(
                    "tuples are at most one or two levels deep; remove the extra parentheses",
                ),
            );
            self.keep_broken(out, start, end);
            return;
        }
        if self.direct
            && let Some(statement) = self.direct_statement(start, end)
        {
            out.statements.push(statement);
            return;
        }
        // A statement missing its `;` at the end of a line is split there
        // and parsing goes on with the next line; each round consumes at
        // least one line, and pest stops at the first error, so this stays
        // linear.
        loop {
            let text = &self.src[start..end];
            match SceneGrammar::parse(Rule::statement_only, text) {
                Ok(pairs) => {
                    match self.build_statement(pairs, start) {
                        Some(s) => out.statements.push(s),
                        None => {
                            self.diagnostics.push(Diagnostic::new(
                                Code::Syntax,
                                Span::new(start, end),
                                "internal error: unexpected parse tree for this statement",
                            ));
                            self.keep_broken(out, start, end);
                        }
                    }
                    return;
                }
                Err(err) => {
                    if let Some(next) = self.split_at_line_end(&err, start, end, out) {
                        start = next;
                        continue;
                    }
                    if let Some(open) = self.unterminated_string(start, end) {
                        self.diagnostics.push(
                            Diagnostic::new(Code::Syntax, open, "unterminated string")
                                .with_label("this string has no closing `\"` on its line")
                                .with_help(
                                    "end the file name with `\"`; a string cannot span lines",
                                ),
                        );
                        self.keep_broken(out, start, end);
                        return;
                    }
                    self.report_pest_error(&err, start, end);
                    self.keep_broken(out, start, end);
                    return;
                }
            }
        }
    }

    fn build_statement(
        &mut self,
        mut pairs: pest::iterators::Pairs<'_, Rule>,
        start: usize,
    ) -> Option<Statement> {
        pairs
            .next()
            .and_then(|p| p.into_inner().find(|p| p.as_rule() == Rule::statement))
            .and_then(|p| self.statement(p, start))
    }

    /// The first string token of `start..end` without its closing quote.
    fn unterminated_string(&self, start: usize, end: usize) -> Option<Span> {
        self.tokens(start, end)
            .into_iter()
            .map(|(_, span)| span)
            .find(|span| {
                let text = &self.src[span.start()..span.end()];
                text.starts_with('"') && (text.len() == 1 || !text.ends_with('"'))
            })
    }

    /// When pest expected `;` at a token that starts a new line, the
    /// statement most likely lacks its `;` at the end of the previous line:
    /// reports that (just after the previous token), keeps the first part as
    /// a statement and returns where the rest starts.
    fn split_at_line_end(
        &mut self,
        err: &pest::error::Error<Rule>,
        start: usize,
        end: usize,
        out: &mut Body,
    ) -> Option<usize> {
        let ErrorVariant::ParsingError { positives, .. } = &err.variant else {
            return None;
        };
        if !positives.contains(&Rule::semicolon) {
            return None;
        }
        let local = match err.location {
            InputLocation::Pos(p) => p,
            InputLocation::Span((p, _)) => p,
        };
        let at = start + local;
        if at >= end {
            return None;
        }
        let prev_end = self
            .tokens(start, at)
            .last()
            .map(|(_, span)| span.end())
            .filter(|&e| e <= at)?;
        if !self.src[prev_end..at].contains('\n') {
            return None;
        }
        let text = format!("{};", &self.src[start..prev_end]);
        let pairs = SceneGrammar::parse(Rule::statement_only, &text).ok()?;
        let mut statement = self.build_statement(pairs, start)?;
        // The `;` is not in the source: the statement ends at its last token.
        statement.span = Span::new(statement.span.start(), prev_end);
        let found = self.found_at(at, false);
        self.diagnostics.push(
            Diagnostic::new(
                Code::Syntax,
                Span::new(prev_end, prev_end),
                format!("expected `;` at the end of the line, found {found} on the next line"),
            )
            .with_label("expected `;` here")
            .with_help("every statement ends with `;`"),
        );
        out.statements.push(statement);
        Some(at)
    }

    /// What can be salvaged from a statement that did not parse: a leading
    /// name and its references.
    /// Keeps the broken statement `start..end` for the lowering (its name
    /// and references, so they do not cascade into more errors), while the
    /// diagnostics are under their cap: past it, a file of millions of
    /// broken statements (16 MiB of `;`) would hold one record each, for
    /// errors that are only counted.
    fn keep_broken(&mut self, out: &mut Body, start: usize, end: usize) {
        if !self.diagnostics.is_full() {
            out.broken.push(self.broken(start, end));
        }
    }

    fn broken(&self, start: usize, end: usize) -> BrokenStatement {
        let tokens = self.tokens(start, end);
        let text = |span: Span| &self.src[span.start()..span.end()];
        let (name, labelled) = match tokens.as_slice() {
            [(ScanKind::Ident, name), (ScanKind::Other, sep), ..]
                if matches!(text(*sep), ":" | "=") =>
            {
                (
                    Some(self.ident(ScanToken {
                        kind: ScanKind::Ident,
                        span: *name,
                    })),
                    text(*sep) == ":",
                )
            }
            _ => (None, false),
        };
        let references = tokens
            .iter()
            .filter(|(kind, _)| *kind == ScanKind::Other)
            .filter_map(|&(_, span)| {
                let t = text(span);
                let sigil = match t.as_bytes().first() {
                    Some(b'%') => RefSigil::Percent,
                    Some(b'#') => RefSigil::Hash,
                    _ => return None,
                };
                let rest = &t[1..];
                let first = *rest.as_bytes().first()?;
                let target = if first.is_ascii_digit() {
                    RefTarget::Index(rest.parse().ok()?)
                } else if is_ident_start(first) {
                    RefTarget::Name(rest.to_string())
                } else {
                    return None;
                };
                Some(Reference {
                    sigil,
                    target,
                    span,
                })
            })
            .collect();
        BrokenStatement {
            name,
            labelled,
            references,
            span: Span::new(start, end),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::diagnostic::{Code, Span};
    use crate::parser::fixtures::{codes, text};
    use crate::parser::parse;

    #[test]
    fn three_broken_statements_give_three_diagnostics() {
        let src = "\
Objects {
  Sphere %3, 0.05, #1;
  Sphere %4, 0.05 #1;
  Sphere %5, 0.05, #1;
  Sphere (%6, 0.05, #1;
  Sphere %7, 0.05, #1;
  Sphere %8, = 0.05, #1;
  Sphere %9, 0.05, #1;
}";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax; 3]);
        let objects = &p.file.sections[0];
        let kept: Vec<&str> = objects
            .statements
            .iter()
            .map(|s| text(src, s.span))
            .collect();
        assert_eq!(
            kept,
            [
                "Sphere %3, 0.05, #1;",
                "Sphere %5, 0.05, #1;",
                "Sphere %7, 0.05, #1;",
                "Sphere %9, 0.05, #1;"
            ]
        );
        let idx = crate::line_index::LineIndex::new(src);
        let d = &p.diagnostics;
        assert_eq!(d[0].message, "expected `,` or `;`, found `#1`");
        assert_eq!(idx.line_col(d[0].span.start()), (3, 19));
        assert_eq!(text(src, d[0].span), "#1");
        assert_eq!(d[1].message, "expected `)` or `,`, found `;`");
        assert_eq!(idx.line_col(d[1].span.start()), (5, 23));
        assert_eq!(d[2].message, "expected a value, found `=`");
        assert_eq!(idx.line_col(d[2].span.start()), (7, 14));
    }

    #[test]
    fn missing_semicolon_at_end_of_line_splits_the_statement() {
        let src = "Points {\n  a = (0,0,0)\n  (1,1,1);\n  (0,0,0) // c\n  (2,2,2)\n}";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax, Code::Syntax, Code::Syntax]);
        let d = &p.diagnostics[0];
        assert_eq!(d.label.as_deref(), Some("expected `;` here"));
        // Just after `(0,0,0)` on line 2, not at the next line's `(`.
        assert_eq!(d.span, Span::new(22, 22));
        assert!(d.message.starts_with("expected `;`"), "{}", d.message);
        let points = &p.file.sections[0];
        let kept: Vec<&str> = points
            .statements
            .iter()
            .map(|s| text(src, s.span))
            .collect();
        assert_eq!(kept, ["a = (0,0,0)", "(1,1,1);", "(0,0,0)"]);
        // The last one is cut off by `}`: reported as before, and kept broken.
        assert!(p.diagnostics[2].message.contains("found `}`"));
        assert_eq!(points.broken.len(), 1);
        assert!(points.broken[0].name.is_none());
    }

    #[test]
    fn broken_statements_keep_their_name_and_references() {
        let src = "Points { a = (0,0 0); b: (1,1,1) 2; } Objects { Sphere %a, #glass 0.1 %7; }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax; 3]);
        let points = &p.file.sections[0];
        assert!(points.statements.is_empty());
        let names: Vec<(&str, bool)> = points
            .broken
            .iter()
            .map(|b| (b.name.as_ref().map_or("", |n| n.as_str()), b.labelled))
            .collect();
        assert_eq!(names, [("a", false), ("b", true)]);
        let refs: Vec<String> = p.file.sections[1].broken[0]
            .references
            .iter()
            .map(ToString::to_string)
            .collect();
        assert_eq!(refs, ["%a", "#glass", "%7"]);
    }
}
