//! The structure of a file: sections found by their name and `{`, their
//! bodies cut into statements at `;`, and the recovery from what does not
//! fit (junk between sections, a header without a name, a `}` that never
//! comes). The nesting depth of parentheses is counted here, before pest
//! sees a statement.

use super::lexer::{ScanKind, ScanToken, skip_trivia};
use super::{MAX_NESTING, Scanner};
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::syntax::{BrokenStatement, Ident, Section, SourceFile, Statement};

/// The state of the statement being scanned inside a section body.
#[derive(Default)]
pub(super) struct Stmt {
    /// Offset of the first token, if any.
    pub(super) start: Option<usize>,
    /// End of the last token.
    end: usize,
    /// End of the token before the last one (or the start, if only one).
    prev_end: usize,
    /// The last token.
    last: Option<ScanToken>,
    parens: usize,
    braces: usize,
    /// The first `(` nested deeper than [`MAX_NESTING`].
    pub(super) too_deep: Option<Span>,
}

impl Stmt {
    fn push(&mut self, tok: ScanToken) {
        if self.start.is_none() {
            self.start = Some(tok.span.start());
            self.prev_end = tok.span.start();
        } else {
            self.prev_end = self.end;
        }
        self.end = tok.span.end();
        self.last = Some(tok);
        match tok.kind {
            ScanKind::LParen => {
                self.parens += 1;
                if self.parens > MAX_NESTING && self.too_deep.is_none() {
                    self.too_deep = Some(tok.span);
                }
            }
            ScanKind::RParen => self.parens = self.parens.saturating_sub(1),
            ScanKind::LBrace => self.braces += 1,
            ScanKind::RBrace => self.braces = self.braces.saturating_sub(1),
            _ => {}
        }
    }
}

/// The statements of a section body, good and broken.
#[derive(Default)]
pub(super) struct Body {
    pub(super) statements: Vec<Statement>,
    pub(super) broken: Vec<BrokenStatement>,
}

/// The next section header found while scanning: its name and its `{`.
type Header = (Ident, Span);

impl Scanner<'_> {
    /// `file = section*`, with recovery from junk and malformed headers.
    pub(super) fn file(&mut self) -> SourceFile {
        let mut sections = Vec::new();
        // Junk seen at top level since the last section, as one span.
        let mut junk: Option<Span> = None;
        // A name that may turn out to be a section header.
        let mut candidate: Option<ScanToken> = None;
        let mut header: Option<Header> = None;
        loop {
            if let Some((name, open)) = header.take() {
                let (section, next) = self.section(Some(name), open);
                sections.extend(section);
                header = next;
                continue;
            }
            let Some(tok) = self.next_token() else { break };
            match (tok.kind, candidate.take()) {
                (ScanKind::LBrace, Some(name)) => {
                    self.report_junk(junk.take());
                    header = Some((self.ident(name), tok.span));
                }
                (ScanKind::LBrace, None) => {
                    let span = junk.take().map_or(tok.span, |j| j.to(tok.span));
                    let found = self.found_at(span.start(), false);
                    self.diagnostics.push(
                        Diagnostic::new(
                            Code::Syntax,
                            span,
                            format!("expected a section name before `{{`, found {found}"),
                        )
                        .with_label("malformed section header")
                        .with_help("a section starts with its name, e.g. `Points {`"),
                    );
                    // Parse the body anyway, to report its syntax errors.
                    self.incomplete = true;
                    let (_, next) = self.section(None, tok.span);
                    header = next;
                }
                (kind, previous) => {
                    if let Some(prev) = previous {
                        junk = Some(junk.map_or(prev.span, |j| j.to(prev.span)));
                    }
                    if kind == ScanKind::Ident {
                        candidate = Some(tok);
                    } else {
                        junk = Some(junk.map_or(tok.span, |j| j.to(tok.span)));
                    }
                }
            }
        }
        if let Some(prev) = candidate {
            junk = Some(junk.map_or(prev.span, |j| j.to(prev.span)));
        }
        self.report_junk(junk);
        SourceFile {
            sections,
            incomplete: self.incomplete,
        }
    }

    fn report_junk(&mut self, junk: Option<Span>) {
        if let Some(span) = junk {
            self.incomplete = true;
            let found = self.found_at(span.start(), false);
            self.diagnostics.push(
                Diagnostic::new(
                    Code::Syntax,
                    span,
                    format!("expected a section, found {found}"),
                )
                .with_label("not inside any section")
                .with_help("statements belong inside a section, e.g. `Points { (0,0,0); }`"),
            );
        }
    }

    /// A section body, after its `{`. Returns the section (`None` when it had
    /// no name) and the header of the next section when one started before
    /// this one was closed.
    fn section(&mut self, name: Option<Ident>, open: Span) -> (Option<Section>, Option<Header>) {
        let mut statements = Body::default();
        let mut stmt = Stmt::default();
        let mut end = open.end();
        let (close_end, next) = loop {
            let Some(tok) = self.next_token() else {
                if !self.comment_unterminated {
                    self.flush(&stmt, stmt.end, &mut statements);
                    end = end.max(stmt.end);
                    self.report_unclosed(name.as_ref(), open, None);
                }
                break (end, None);
            };
            match tok.kind {
                ScanKind::Semi => {
                    stmt.push(tok);
                    self.flush(&stmt, tok.span.end(), &mut statements);
                    end = tok.span.end();
                    stmt = Stmt::default();
                }
                ScanKind::RBrace if stmt.braces == 0 => {
                    self.flush(&stmt, stmt.end, &mut statements);
                    break (tok.span.end(), None);
                }
                ScanKind::LBrace
                    if stmt.braces == 0
                        && stmt.parens == 0
                        && stmt.last.is_some_and(|t| t.kind == ScanKind::Ident)
                        && !self.symbol_at(tok.span.end()) =>
                {
                    // `Name {` inside a body: this section lacks its `}`.
                    let Some(last) = stmt.last else {
                        break (end, None);
                    };
                    let new_name = self.ident(last);
                    if stmt.start.is_some_and(|s| s < last.span.start()) {
                        self.flush(&stmt, stmt.prev_end, &mut statements);
                        end = stmt.prev_end;
                    }
                    self.report_unclosed(name.as_ref(), open, Some(&new_name));
                    break (end, Some((new_name, tok.span)));
                }
                _ => stmt.push(tok),
            }
        };
        // Grown by doubling; the whole tree is alive until lowering starts.
        statements.statements.shrink_to_fit();
        let section = name.map(|name| Section {
            span: name.span.to(Span::new(close_end, close_end)),
            name,
            statements: statements.statements,
            broken: statements.broken,
        });
        (section, next)
    }

    /// Whether the `{` ending just before `pos` opens a Schläfli symbol
    /// (`Honeycomb {4,3,5}`) rather than a section: its first token is a
    /// number (a digit, or a sign or point before one: `{-4,3,5}` is a
    /// symbol the lowering refuses by name). No section body starts with
    /// one (statements start with a name, a reference, a label or a tuple),
    /// so `Name {` followed by a number is a value, and a missing `}` before
    /// a section is still found.
    fn symbol_at(&self, pos: usize) -> bool {
        let (at, unterminated) = skip_trivia(self.src, pos);
        let bytes = self.src.as_bytes();
        let digit = |i: usize| bytes.get(i).is_some_and(u8::is_ascii_digit);
        let number_at = |i: usize| match bytes.get(i) {
            Some(b'0'..=b'9') => true,
            Some(b'.') => digit(i + 1),
            Some(b'+' | b'-') => digit(i + 1) || (bytes.get(i + 1) == Some(&b'.') && digit(i + 2)),
            _ => false,
        };
        unterminated.is_none() && number_at(at)
    }

    fn report_unclosed(&mut self, name: Option<&Ident>, open: Span, next: Option<&Ident>) {
        let what = match name {
            Some(n) => format!("section `{}`", n.text),
            None => "this section".to_string(),
        };
        let before = match next {
            Some(n) => format!("section `{}`", n.text),
            None => "end of file".to_string(),
        };
        self.diagnostics.push(
            Diagnostic::new(
                Code::Syntax,
                open,
                format!("{what} is not closed: expected `}}` before {before}"),
            )
            .with_label("this `{` is never closed")
            .with_help("add `}` after the last statement of the section"),
        );
    }
}

#[cfg(test)]
mod tests {
    use std::time::{Duration, Instant};

    use crate::diagnostic::{Code, Span};
    use crate::parser::fixtures::{codes, text};
    use crate::parser::{MAX_NESTING, parse};
    use crate::syntax::{Clause, Value};

    #[test]
    fn missing_closing_brace_at_end_of_file() {
        let src = "Points { (0,0,0); (1,1,1);\n";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax]);
        let d = &p.diagnostics[0];
        assert_eq!(d.span, Span::new(7, 8));
        assert!(
            d.message.contains("section `Points` is not closed"),
            "{}",
            d.message
        );
        assert!(d.message.contains("end of file"));
        let points = &p.file.sections[0];
        assert_eq!(points.statements.len(), 2);
        assert_eq!(text(src, points.span), "Points { (0,0,0); (1,1,1);");

        // An unterminated last statement as well: two problems, two diagnostics.
        let p = parse("Points { (0,0,0); (1,1,1)");
        assert_eq!(codes(&p), [Code::Syntax, Code::Syntax]);
        assert!(p.diagnostics[1].message.contains("found end of file"));
        assert_eq!(p.file.sections[0].statements.len(), 1);
    }

    #[test]
    fn missing_closing_brace_before_next_section() {
        let src = "Points { (0,0,0);\nObjects { Cube; }\nLights { %1, (1,1,1), (1,1,1); }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax]);
        assert!(
            p.diagnostics[0]
                .message
                .contains("before section `Objects`")
        );
        let names: Vec<&str> = p
            .file
            .sections
            .iter()
            .map(|s| s.name.text.as_str())
            .collect();
        assert_eq!(names, ["Points", "Objects", "Lights"]);
        assert_eq!(text(src, p.file.sections[0].span), "Points { (0,0,0);");
        assert!(p.file.sections.iter().all(|s| s.statements.len() == 1));
    }

    #[test]
    fn junk_between_sections_and_at_the_end() {
        let src = "Points { (0,0,0); } junk 12 ; }\nObjects { Cube; } trailing";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax, Code::Syntax]);
        assert_eq!(text(src, p.diagnostics[0].span), "junk 12 ; }");
        assert_eq!(p.diagnostics[0].message, "expected a section, found `junk`");
        assert_eq!(text(src, p.diagnostics[1].span), "trailing");
        let names: Vec<&str> = p
            .file
            .sections
            .iter()
            .map(|s| s.name.text.as_str())
            .collect();
        assert_eq!(names, ["Points", "Objects"]);
        assert!(p.file.sections.iter().all(|s| s.statements.len() == 1));

        // A name before the header is junk; the header itself is kept.
        let src = "Poin Points { (0,0,0); }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax]);
        assert_eq!(text(src, p.diagnostics[0].span), "Poin");
        assert_eq!(p.file.sections[0].name.text, "Points");
    }

    #[test]
    fn malformed_section_header() {
        let src = "12 { a = ; } Points { (0,0,0); }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax, Code::Syntax]);
        assert_eq!(text(src, p.diagnostics[0].span), "12 {");
        assert!(
            p.diagnostics[0]
                .message
                .starts_with("expected a section name")
        );
        // The nameless body is still checked, but not kept.
        assert_eq!(
            p.diagnostics[1].message,
            "expected a value or a name, found `;`"
        );
        assert_eq!(p.file.sections.len(), 1);
        assert_eq!(p.file.sections[0].statements.len(), 1);
    }

    #[test]
    fn braces_inside_a_statement_do_not_end_the_section() {
        let src = "S { a = {1}; b = 2; }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax]);
        // A Schläfli symbol has at least two entries: pest stops at the `}`.
        assert_eq!(text(src, p.diagnostics[0].span), "}");
        assert_eq!(p.file.sections[0].statements.len(), 1);
    }

    #[test]
    fn schlafli_symbol_is_a_value_not_a_section() {
        use crate::parser::fixtures::{clean, number};
        let src = "Objects { Honeycomb {4,3,5}, #1, depth = 2;\n\
                   Honeycomb { 5 , /* c */ 3,\n 4 }, #1; Sphere %1, 0.1, #1; }";
        let file = clean(src);
        let objects = &file.sections[0];
        assert_eq!(objects.statements.len(), 3);
        for (st, entries, written) in [
            (&objects.statements[0], [4.0, 3.0, 5.0], "{4,3,5}"),
            (
                &objects.statements[1],
                [5.0, 3.0, 4.0],
                "{ 5 , /* c */ 3,\n 4 }",
            ),
        ] {
            let Clause::Apply {
                name,
                arg: Some(Value::Symbol { entries: e, span }),
                ..
            } = &st.clauses[0]
            else {
                panic!("{st:?}")
            };
            assert_eq!(name.text, "Honeycomb");
            assert_eq!(text(src, *span), written);
            let got: Vec<f64> = e.iter().map(number).collect();
            assert_eq!(got, entries);
        }
        // As an option's value too, and in the whole-file grammar.
        clean("S { a = {3,5,3}; }");
        use pest::Parser as _;
        assert!(crate::parser::SceneGrammar::parse(crate::parser::Rule::file, src).is_ok());

        // A section that lacks its `}` before one with a symbol is still
        // found, and the symbol's braces close nothing.
        let src = "Points { (0,0,0);\nObjects { Honeycomb {4,3,5}, #1; }\nLights { %1, (1,1,1), (1,1,1); }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax]);
        assert!(
            p.diagnostics[0]
                .message
                .contains("before section `Objects`")
        );
        assert_eq!(p.file.sections.len(), 3);
        assert!(p.file.sections.iter().all(|s| s.statements.len() == 1));
    }

    #[test]
    fn a_signed_first_entry_is_still_a_symbol() {
        for src in [
            "S { Honeycomb {-4,3,5}, #1; }",
            "S { Honeycomb { +4,3,5}, #1; }",
            "S { Honeycomb {.5,3,5}, #1; }",
        ] {
            let p = parse(src);
            assert!(p.diagnostics.is_empty(), "{src}: {:?}", p.diagnostics);
            assert_eq!(p.file.sections.len(), 1, "{src}");
        }
    }

    #[test]
    fn malformed_symbols_are_one_error_each() {
        for (src, at, message) in [
            ("S { Honeycomb {4}, #1; b = 2; }", "}", "expected `,`"),
            ("S { Honeycomb {4,3,5, #1; b = 2; }", "#1", "expected"),
            ("S { Honeycomb {4,,5}, #1; b = 2; }", ",", "expected"),
        ] {
            let p = parse(src);
            assert_eq!(codes(&p), [Code::Syntax], "{src}");
            let d = &p.diagnostics[0];
            assert_eq!(text(src, d.span), at, "{src}: {}", d.message);
            assert!(d.message.contains(message), "{}", d.message);
            assert_eq!(p.file.sections.len(), 1, "{src}");
            assert_eq!(p.file.sections[0].statements.len(), 1, "{src}");
        }
    }

    #[test]
    fn nesting_at_the_limit_parses() {
        // Runs in a thread with a small stack to show the limit is safe.
        let handle = std::thread::Builder::new()
            .stack_size(1 << 20)
            .spawn(|| {
                let src = format!(
                    "S {{ {}1{}; }}",
                    "(".repeat(MAX_NESTING),
                    ")".repeat(MAX_NESTING)
                );
                parse(&src)
            })
            .unwrap();
        let p = handle.join().expect("no stack overflow");
        assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
        let mut v = match &p.file.sections[0].statements[0].clauses[0] {
            Clause::Value(v) => v,
            other => panic!("{other:?}"),
        };
        let mut depth = 0;
        while let Value::Tuple { items, .. } = v {
            depth += 1;
            v = &items[0];
        }
        assert_eq!(depth, MAX_NESTING);
    }

    #[test]
    fn deep_nesting_is_rejected_quickly() {
        let src = format!(
            "S {{ a = 1; {} ; b = 2; }}\nT {{ c = 3; }}",
            "(".repeat(100_000)
        );
        let started = Instant::now();
        let p = parse(&src);
        assert!(started.elapsed() < Duration::from_secs(2));
        assert_eq!(codes(&p), [Code::NestingTooDeep]);
        // The span is the first `(` past the limit.
        assert_eq!(p.diagnostics[0].span.len(), 1);
        assert_eq!(
            p.diagnostics[0].span.start(),
            src.find('(').unwrap() + MAX_NESTING
        );
        assert_eq!(p.file.sections[0].statements.len(), 2);
        assert_eq!(p.file.sections[1].statements.len(), 1);

        // Unclosed, to the end of the file.
        let p = parse(&format!("S {{ {}", "(".repeat(100_000)));
        assert_eq!(codes(&p), [Code::Syntax, Code::NestingTooDeep]);
        assert!(p.diagnostics[0].message.contains("not closed"));
        // Braces and junk at top level are not recursive either.
        let p = parse(&"{".repeat(100_000));
        assert!(!p.diagnostics.is_empty());
        let p = parse(&"A{".repeat(50_000));
        assert_eq!(p.file.sections.len(), 50_000);
    }
}
