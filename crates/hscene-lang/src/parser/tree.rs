//! pest's parse tree of one statement turned into [`syntax`](crate::syntax)
//! nodes, with spans moved from the statement's text to the file's. Numbers
//! that do not fit an f64 and reference indices that do not fit 64 bits are
//! reported here, and the statement is kept.

use pest::iterators::Pair;

use super::messages::snippet;
use super::{Rule, Scanner};
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::syntax::{Clause, Ident, RefSigil, RefTarget, Reference, Statement, Value};

impl Scanner<'_> {
    pub(super) fn statement(&mut self, pair: Pair<'_, Rule>, off: usize) -> Option<Statement> {
        let span = offset(pair.as_span(), off);
        let mut label = None;
        let mut clauses = Vec::new();
        for p in pair.into_inner() {
            match p.as_rule() {
                Rule::label => label = Some(pair_ident(p.into_inner().next()?, off)),
                Rule::clause => clauses.push(self.clause(p.into_inner().next()?, off)?),
                _ => {}
            }
        }
        if clauses.is_empty() {
            return None;
        }
        Some(Statement {
            label,
            clauses: clauses.into_boxed_slice(),
            span,
        })
    }

    fn clause(&mut self, pair: Pair<'_, Rule>, off: usize) -> Option<Clause> {
        let span = offset(pair.as_span(), off);
        match pair.as_rule() {
            Rule::assignment => {
                let mut key = None;
                let mut value = None;
                for p in pair.into_inner() {
                    match p.as_rule() {
                        Rule::ident if key.is_none() => key = Some(pair_ident(p, off)),
                        // A bare name as the value (`integrator = path`).
                        Rule::ident => value = Some(Value::Ident(pair_ident(p, off))),
                        Rule::value => value = Some(self.value(p, off)?),
                        _ => {}
                    }
                }
                Some(Clause::Assign {
                    key: key?,
                    value: value?,
                    span,
                })
            }
            Rule::application => {
                let mut target = None;
                let mut name = None;
                let mut arg = None;
                for p in pair.into_inner() {
                    match p.as_rule() {
                        Rule::reference => target = Some(self.reference(p, off)?),
                        Rule::ident => name = Some(pair_ident(p, off)),
                        Rule::value => arg = Some(self.value(p, off)?),
                        _ => {}
                    }
                }
                Some(Clause::Apply {
                    target: target.map(Box::new),
                    name: name?,
                    arg,
                    span,
                })
            }
            Rule::value => Some(Clause::Value(self.value(pair, off)?)),
            _ => None,
        }
    }

    /// Builds a value. Recursion is bounded: statements nested deeper than
    /// [`MAX_NESTING`] never reach pest.
    fn value(&mut self, pair: Pair<'_, Rule>, off: usize) -> Option<Value> {
        let span = offset(pair.as_span(), off);
        match pair.as_rule() {
            Rule::value => self.value(pair.into_inner().next()?, off),
            Rule::number => {
                let text = pair.as_str();
                let value = text.parse::<f64>().unwrap_or(f64::NAN);
                if crate::numbers::underflows(text, value) {
                    self.diagnostics
                        .push(crate::numbers::underflow(span, &snippet(text)));
                    return Some(Value::Number {
                        value: f64::NAN,
                        span,
                    });
                }
                if !value.is_finite() {
                    self.diagnostics.push(
                        Diagnostic::new(
                            Code::InvalidNumber,
                            span,
                            format!("number {} is out of range", snippet(text)),
                        )
                        .with_label("does not fit in a 64-bit float")
                        .with_help("numbers must lie between about -1.8e308 and 1.8e308"),
                    );
                }
                Some(Value::Number { value, span })
            }
            Rule::reference => Some(Value::Reference(self.reference(pair, off)?)),
            Rule::tuple => {
                let mut items = Vec::new();
                for p in pair.into_inner() {
                    if matches!(p.as_rule(), Rule::value | Rule::ident) {
                        items.push(self.value(p, off)?);
                    }
                }
                Some(Value::Tuple {
                    items: items.into_boxed_slice(),
                    span,
                })
            }
            Rule::symbol => {
                let mut entries = Vec::new();
                for p in pair.into_inner() {
                    if p.as_rule() == Rule::number {
                        entries.push(self.value(p, off)?);
                    }
                }
                Some(Value::Symbol {
                    entries: entries.into_boxed_slice(),
                    span,
                })
            }
            Rule::ident => Some(Value::Ident(pair_ident(pair, off))),
            Rule::string => Some(Value::Str {
                text: pair.into_inner().next()?.as_str().to_string(),
                span,
            }),
            _ => None,
        }
    }

    fn reference(&mut self, pair: Pair<'_, Rule>, off: usize) -> Option<Reference> {
        let span = offset(pair.as_span(), off);
        let mut sigil = None;
        let mut target = None;
        for p in pair.into_inner() {
            match p.as_rule() {
                Rule::sigil => {
                    sigil = Some(match p.as_str() {
                        "#" => RefSigil::Hash,
                        "@" => RefSigil::At,
                        _ => RefSigil::Percent,
                    });
                }
                Rule::ref_index => {
                    let index = p.as_str().parse::<u64>().unwrap_or_else(|_| {
                        self.diagnostics.push(
                            Diagnostic::new(
                                Code::InvalidNumber,
                                span,
                                format!("reference index {} is too large", snippet(p.as_str())),
                            )
                            .with_label("does not fit in 64 bits")
                            .with_help("indices count declarations from 1"),
                        );
                        u64::MAX
                    });
                    target = Some(RefTarget::Index(index));
                }
                Rule::ref_name => target = Some(RefTarget::Name(p.as_str().to_string())),
                _ => {}
            }
        }
        Some(Reference {
            sigil: sigil?,
            target: target?,
            span,
        })
    }
}

fn offset(span: pest::Span<'_>, off: usize) -> Span {
    Span::new(off + span.start(), off + span.end())
}

fn pair_ident(pair: Pair<'_, Rule>, off: usize) -> Ident {
    Ident {
        text: pair.as_str().into(),
        span: offset(pair.as_span(), off),
    }
}

#[cfg(test)]
mod tests {
    use crate::diagnostic::{Code, Span};
    use crate::parser::fixtures::{codes, numbers, only_statement, reference, text, tuple};
    use crate::parser::parse;
    use crate::syntax::{Clause, RefSigil, RefTarget, Reference, Value};

    #[test]
    fn clause_shapes() {
        let src = "S { Cube; }";
        let st = only_statement(src);
        let Clause::Apply {
            target: None,
            name,
            arg: None,
            span,
        } = &st.clauses[0]
        else {
            panic!("{st:?}")
        };
        assert_eq!(name.text, "Cube");
        assert_eq!(*span, name.span);

        let src = "S { k = 1, Dodecahedron 0.045, hline (%1, %2), %1->Rotate(%2, -0.7), (1,2), %3, #4, 5; }";
        let st = only_statement(src);
        assert_eq!(st.clauses.len(), 8);
        let spans: Vec<&str> = st.clauses.iter().map(|c| text(src, c.span())).collect();
        assert_eq!(
            spans,
            [
                "k = 1",
                "Dodecahedron 0.045",
                "hline (%1, %2)",
                "%1->Rotate(%2, -0.7)",
                "(1,2)",
                "%3",
                "#4",
                "5"
            ]
        );
        assert!(matches!(&st.clauses[0], Clause::Assign { key, .. } if key.text == "k"));
        assert!(
            matches!(&st.clauses[1], Clause::Apply { arg: Some(Value::Number { value, .. }), .. } if *value == 0.045)
        );
        assert!(matches!(
            &st.clauses[3],
            Clause::Apply {
                target: Some(_),
                ..
            }
        ));
        assert!(matches!(&st.clauses[4], Clause::Value(Value::Tuple { .. })));
        assert!(matches!(&st.clauses[6], Clause::Value(Value::Reference(_))));

        // `->` may be surrounded by whitespace; the argument may be absent.
        let st = only_statement("S { %p -> Reflect; }");
        assert!(matches!(
            &st.clauses[0],
            Clause::Apply { target: Some(r), arg: None, .. }
                if matches!(&**r, Reference { target: RefTarget::Name(n), .. } if n == "p")
        ));

        // Bare identifiers inside tuples, nested tuples.
        let src = "S { mesh = (bunny, (1, 2), %1); }";
        let st = only_statement(src);
        let Clause::Assign { value, .. } = &st.clauses[0] else {
            panic!()
        };
        let items = tuple(value);
        assert!(
            matches!(&items[0], Value::Ident(i) if i.text == "bunny" && text(src, i.span) == "bunny")
        );
        assert_eq!(numbers(&items[1]), [1.0, 2.0]);
        assert_eq!(items[0].describe(), "a name");
        assert_eq!(items[1].describe(), "a tuple");
        assert_eq!(items[2].describe(), "a point reference");

        // A label applies to the whole statement.
        let st = only_statement("S { target: (0,0,0.3); }");
        assert_eq!(st.label.map(|l| l.text).as_deref(), Some("target"));
        assert!(matches!(&st.clauses[0], Clause::Value(Value::Tuple { .. })));
    }

    /// A bare name is the value of an assignment (`integrator = path`),
    /// and the key stays the key.
    #[test]
    fn bare_identifiers_are_values_of_assignments() {
        let st = only_statement("S { a = b; }");
        let Clause::Assign { key, value, .. } = &st.clauses[0] else {
            panic!("{:?}", st.clauses)
        };
        assert_eq!(key.text, "a");
        assert!(matches!(value, Value::Ident(i) if i.text == "b"));
        assert_eq!(value.describe(), "a name");
    }

    #[test]
    fn numbers_in_all_forms() {
        let src =
            "S { (1, -0.7, .5, 1., 2e-3, +3, 1E+2, -.25, 0.07071067811865, 007, 1.5e3, +0); }";
        let st = only_statement(src);
        let Clause::Value(v) = &st.clauses[0] else {
            panic!()
        };
        assert_eq!(
            numbers(v),
            [
                1.0,
                -0.7,
                0.5,
                1.0,
                0.002,
                3.0,
                100.0,
                -0.25,
                0.07071067811865,
                7.0,
                1500.0,
                0.0
            ]
        );
        let spans: Vec<&str> = tuple(v).iter().map(|i| text(src, i.span())).collect();
        assert_eq!(spans[..6], ["1", "-0.7", ".5", "1.", "2e-3", "+3"]);
    }

    #[test]
    fn overflowing_number_is_invalid_number_and_keeps_the_statement() {
        let src = "S { (1e999, -1e400, 1e-400); }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::InvalidNumber; 3]);
        assert_eq!(text(src, p.diagnostics[0].span), "1e999");
        assert_eq!(text(src, p.diagnostics[1].span), "-1e400");
        assert!(
            p.diagnostics[2].message.contains("too small"),
            "{:?}",
            p.diagnostics[2]
        );
        let Clause::Value(v) = &p.file.sections[0].statements[0].clauses[0] else {
            panic!()
        };
        let n = numbers(v);
        assert_eq!(n[0], f64::INFINITY);
        assert_eq!(n[1], f64::NEG_INFINITY);
        // Underflow is reported, never silently zero.
        assert!(n[2].is_nan());
    }

    #[test]
    fn references() {
        let src = "S { %1, %0, %eye, #2, #glass, %_x1, %007; }";
        let st = only_statement(src);
        let refs: Vec<_> = st
            .clauses
            .iter()
            .map(|c| match c {
                Clause::Value(v) => reference(v),
                other => panic!("{other:?}"),
            })
            .collect();
        assert_eq!(
            refs,
            [
                (RefSigil::Percent, RefTarget::Index(1)),
                (RefSigil::Percent, RefTarget::Index(0)),
                (RefSigil::Percent, RefTarget::Name("eye".into())),
                (RefSigil::Hash, RefTarget::Index(2)),
                (RefSigil::Hash, RefTarget::Name("glass".into())),
                (RefSigil::Percent, RefTarget::Name("_x1".into())),
                (RefSigil::Percent, RefTarget::Index(7)),
            ]
        );
        assert_eq!(text(src, st.clauses[4].span()), "#glass");

        // No whitespace inside a reference.
        let p = parse("S { % 1; }");
        assert_eq!(codes(&p), [Code::Syntax]);
        assert_eq!(p.diagnostics[0].span, Span::new(5, 6));
        assert!(parse("S { %; }").has_errors());
        assert!(parse("S { %-1; }").has_errors());
        assert!(parse("S { %1abc; }").has_errors());
    }

    #[test]
    fn huge_reference_index_is_reported_and_the_statement_kept() {
        let src = "S { Sphere %99999999999999999999, 0.1, #1; }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::InvalidNumber]);
        assert_eq!(text(src, p.diagnostics[0].span), "%99999999999999999999");
        let st = &p.file.sections[0].statements[0];
        let Clause::Apply { arg: Some(arg), .. } = &st.clauses[0] else {
            panic!()
        };
        assert_eq!(
            reference(arg),
            (RefSigil::Percent, RefTarget::Index(u64::MAX))
        );
        // u64::MAX itself fits.
        let st = only_statement("S { %18446744073709551615; }");
        let Clause::Value(v) = &st.clauses[0] else {
            panic!()
        };
        assert_eq!(reference(v).1, RefTarget::Index(u64::MAX));
    }
}
