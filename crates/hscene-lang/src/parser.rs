//! The parser: source text to [`SourceFile`] plus diagnostics. It never fails.
//!
//! Parsing runs in two layers:
//!
//! 1. A hand-written, linear scanner splits the source into sections and
//!    statements. It understands only whitespace, comments, identifiers and
//!    the structural characters `{ } ( ) ;`, which makes recovery simple: a
//!    statement ends at the next `;` (or before a `}`), a section at its `}`,
//!    and a name followed by `{` inside a section starts a new section (the
//!    previous one lacked its `}`). It also guards the nesting depth of
//!    parentheses so that pest's recursive descent can never run out of stack.
//! 2. Each statement's text is parsed alone by pest (`statement_only` in
//!    `grammar.pest`), and a failure becomes one diagnostic at pest's exact
//!    position with its expected tokens put into words.
//!
//! Every byte is looked at a bounded number of times, so parsing is linear.
//!
//! The scanner's tokens are in `lexer`, sections and their recovery in
//! `sections`, one statement through pest and its recovery in `statements`,
//! pest's tree to syntax nodes in `tree`, and the wording of parse errors in
//! `messages`.

mod direct;
#[cfg(test)]
mod fixtures;
mod lexer;
mod messages;
mod sections;
mod statements;
mod tree;

use pest_derive::Parser;

use crate::diagnostic::{Code, Diagnostic, MAX_SOURCE_LEN, Span};
use crate::diagnostic_list::DiagnosticList;
use crate::syntax::SourceFile;

#[derive(Parser)]
#[grammar = "grammar.pest"]
struct SceneGrammar;

/// The deepest parenthesis nesting a statement may have. Deeper statements
/// are reported (`NestingTooDeep`) and skipped without being given to pest.
pub const MAX_NESTING: usize = 64;

/// The result of [`parse`]: a possibly partial syntax tree and every problem found.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Parsed {
    /// The sections and statements that could be parsed.
    pub file: SourceFile,
    /// Syntax diagnostics, sorted by position: the first
    /// [`crate::MAX_KEPT_DIAGNOSTICS`] found.
    pub diagnostics: Vec<Diagnostic>,
    /// How many more were found and not kept.
    pub omitted: crate::Omitted,
}

impl Parsed {
    /// Whether any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.omitted.errors > 0 || self.diagnostics.iter().any(Diagnostic::is_error)
    }
}

/// Parses a scene. Never panics; always returns a tree (possibly partial)
/// and the diagnostics for everything that could not be parsed.
///
/// Statements that fail to parse are left out of the tree; sections keep
/// their good statements.
pub fn parse(source: &str) -> Parsed {
    parse_with(source, true)
}

/// [`parse`] with every statement through pest, to test the direct parser
/// against it.
#[cfg(test)]
fn parse_with_pest_only(source: &str) -> Parsed {
    parse_with(source, false)
}

fn parse_with(source: &str, direct: bool) -> Parsed {
    if let Some(refused) = too_long(source.len()) {
        // Nothing is scanned: no offset past `MAX_SOURCE_LEN` fits a span.
        return Parsed {
            file: SourceFile {
                sections: Vec::new(),
                incomplete: true,
            },
            diagnostics: vec![refused],
            omitted: crate::Omitted::default(),
        };
    }
    let mut p = Scanner {
        src: source,
        pos: 0,
        diagnostics: DiagnosticList::default(),
        comment_unterminated: false,
        incomplete: false,
        direct,
    };
    let file = p.file();
    let (mut diagnostics, omitted) = p.diagnostics.into_parts();
    diagnostics.sort_by_key(|d| (d.span.start(), d.span.end()));
    Parsed {
        file,
        diagnostics,
        omitted,
    }
}

/// The error for a source too long for its offsets to fit a [`Span`]
/// ([`MAX_SOURCE_LEN`]); `None` for one that fits.
fn too_long(len: usize) -> Option<Diagnostic> {
    (len > MAX_SOURCE_LEN).then(|| {
        Diagnostic::new(
            Code::Syntax,
            Span::new(0, 0),
            format!("the scene is {len} bytes; at most {MAX_SOURCE_LEN} (4 GiB) can be read"),
        )
    })
}

/// The state of one parse: where the scanner is, and what it has found
/// wrong so far. Its methods are spread over the submodules by concern.
struct Scanner<'a> {
    src: &'a str,
    pos: usize,
    diagnostics: DiagnosticList,
    /// Set once an unterminated `/*` swallowed the rest of the file; the
    /// problems that follow from it (unclosed section, cut statement) are
    /// then not reported again.
    comment_unterminated: bool,
    /// Set when text was skipped whole (see [`SourceFile::incomplete`]).
    incomplete: bool,
    /// Whether well-formed statements take the direct parser
    /// (`parser/direct.rs`); off only to test it against pest.
    direct: bool,
}

#[cfg(test)]
mod tests {
    use std::time::{Duration, Instant};

    use pest::Parser as _;

    use super::*;
    use crate::parser::fixtures::{
        clean, codes, number, numbers, only_statement, reference, section, text, tuple,
    };
    use crate::syntax::{Clause, RefSigil, RefTarget};

    #[test]
    fn a_source_whose_offsets_fit_a_span_is_read_and_a_longer_one_refused() {
        assert!(too_long(0).is_none());
        assert!(too_long(MAX_SOURCE_LEN).is_none());
        let refused = too_long(MAX_SOURCE_LEN + 1).map(|d| (d.code, d.span));
        assert_eq!(refused, Some((Code::Syntax, Span::new(0, 0))));
        // The largest offset survives the round trip through a span.
        let end = Span::new(0, MAX_SOURCE_LEN);
        assert_eq!(end.end(), MAX_SOURCE_LEN);
        assert_eq!(end.len(), MAX_SOURCE_LEN);
    }

    const APPENDIX: &str = include_str!("../../../scenes/thesis-appendix-a.hsc");

    const EXTENSIONS: &str = "\
Globals { from = (0,0,0); to = %target; up = (0,0.1,0); }
Points  { eye = (0,0,0); target = (0,0,0.3); (0.1,0,0.3); }
BRDFs   { glass: ambient = (0.1,0.1,0.1), diffuse = (0.2,0.2,0.2), specular = (1,1,1), alpha = 0.1, trans = 0.8, shininess = 80, refraction = 1.15; }
Objects { Sphere %target, 0.05, #glass; Polygon (%1, %2, %3, %4), #1; Rod %1, %2, 0.01, #1; Cylinder %1, %2, 0.02, #1; Dodecahedron 0.045, #2; }
Transformations { hline (%1,%5); %1->Rotate(%2,-0.7); %2->Translate(%1); }
";

    #[test]
    fn appendix_parses_cleanly_with_the_expected_shape() {
        let file = clean(APPENDIX);
        let names: Vec<&str> = file.sections.iter().map(|s| s.name.text.as_str()).collect();
        assert_eq!(
            names,
            [
                "Globals",
                "BRDFs",
                "Points",
                "Lights",
                "Objects",
                "Transformations"
            ]
        );
        let counts: Vec<usize> = file.sections.iter().map(|s| s.statements.len()).collect();
        // The transcribed file has 2 `hline`, 10 `Rotate` and 11 `Translate`.
        assert_eq!(counts, [7, 2, 12, 5, 11, 23]);

        // BRDFs: two unnamed materials of seven assignments each.
        let brdfs = section(&file, "BRDFs");
        for m in &brdfs.statements {
            assert!(m.label.is_none());
            assert_eq!(m.clauses.len(), 7);
            assert!(m.clauses.iter().all(|c| matches!(c, Clause::Assign { .. })));
        }
        let Clause::Assign { key, value, .. } = &brdfs.statements[1].clauses[6] else {
            panic!()
        };
        assert_eq!(key.text, "refraction");
        assert_eq!(number(value), 2.5);

        // Points: bare 3-tuples; the fourth one's coordinates.
        let points = section(&file, "Points");
        let Clause::Value(p4) = &points.statements[3].clauses[0] else {
            panic!()
        };
        assert_eq!(numbers(p4), [0.07071067811865, 0.07071067811865, 0.0]);

        // Lights: a reference and two colours.
        let light = &section(&file, "Lights").statements[1];
        assert_eq!(light.clauses.len(), 3);
        let Clause::Value(at) = &light.clauses[0] else {
            panic!()
        };
        assert_eq!(reference(at), (RefSigil::Percent, RefTarget::Index(4)));

        // Objects: `Sphere %3, 0.05, #1;` and `Dodecahedron 0.045, #2;`.
        let objects = section(&file, "Objects");
        let s = &objects.statements[0];
        assert_eq!(text(APPENDIX, s.span), "Sphere %3, 0.05, #1;");
        let Clause::Apply {
            target: None,
            name,
            arg: Some(arg),
            span,
        } = &s.clauses[0]
        else {
            panic!("{:?}", s.clauses[0])
        };
        assert_eq!(name.text, "Sphere");
        assert_eq!(text(APPENDIX, *span), "Sphere %3");
        assert_eq!(reference(arg), (RefSigil::Percent, RefTarget::Index(3)));
        let Clause::Value(material) = &s.clauses[2] else {
            panic!()
        };
        assert_eq!(reference(material), (RefSigil::Hash, RefTarget::Index(1)));
        let d = &objects.statements[10];
        assert_eq!(text(APPENDIX, d.span), "Dodecahedron 0.045, #2;");

        // Transformations.
        let tr = section(&file, "Transformations");
        assert_eq!(text(APPENDIX, tr.statements[0].span), "hline (%1,%2);");
        let rot = &tr.statements[2];
        assert_eq!(text(APPENDIX, rot.span), "%1->Rotate(%2,-0.7);");
        let Clause::Apply {
            target: Some(t),
            name,
            arg: Some(arg),
            ..
        } = &rot.clauses[0]
        else {
            panic!()
        };
        assert_eq!(t.target, RefTarget::Index(1));
        assert_eq!(text(APPENDIX, t.span), "%1");
        assert_eq!(name.text, "Rotate");
        let items = tuple(arg);
        assert_eq!(
            reference(&items[0]),
            (RefSigil::Percent, RefTarget::Index(2))
        );
        assert_eq!(number(&items[1]), -0.7);
        assert_eq!(text(APPENDIX, arg.span()), "(%2,-0.7)");
        assert_eq!(
            text(APPENDIX, tr.statements[22].span),
            "%11->Translate(%1);"
        );

        // Section spans run from the name to the closing brace.
        let g = &file.sections[0];
        assert_eq!(text(APPENDIX, g.name.span), "Globals");
        let g_text = text(APPENDIX, g.span);
        assert!(g_text.starts_with("Globals {") && g_text.ends_with("(0.1,0.1,0.1);\n}"));
        assert!(text(APPENDIX, file.sections[5].span).ends_with("%11->Translate(%1);\n}"));
    }

    #[test]
    fn whole_file_grammar_agrees_with_the_scanner() {
        for src in [APPENDIX, EXTENSIONS] {
            assert!(SceneGrammar::parse(Rule::file, src).is_ok());
        }
        assert!(SceneGrammar::parse(Rule::file, "Points { (0,0,0) }").is_err());
    }

    #[test]
    fn extension_syntax_parses() {
        let file = clean(EXTENSIONS);
        let counts: Vec<usize> = file.sections.iter().map(|s| s.statements.len()).collect();
        assert_eq!(counts, [3, 3, 1, 5, 3]);

        let Clause::Assign { key, value, .. } = &file.sections[0].statements[1].clauses[0] else {
            panic!()
        };
        assert_eq!(key.text, "to");
        assert_eq!(
            reference(value),
            (RefSigil::Percent, RefTarget::Name("target".into()))
        );

        let glass = &file.sections[2].statements[0];
        let label = glass.label.as_ref().expect("label");
        assert_eq!(label.text, "glass");
        assert_eq!(text(EXTENSIONS, label.span), "glass");
        assert!(text(EXTENSIONS, glass.span).starts_with("glass: ambient"));
        assert!(text(EXTENSIONS, glass.span).ends_with("refraction = 1.15;"));
        assert_eq!(glass.clauses.len(), 7);

        let objects = &file.sections[3];
        let sphere = &objects.statements[0];
        let Clause::Apply {
            arg: Some(centre), ..
        } = &sphere.clauses[0]
        else {
            panic!()
        };
        assert_eq!(
            reference(centre),
            (RefSigil::Percent, RefTarget::Name("target".into()))
        );
        let Clause::Value(m) = &sphere.clauses[2] else {
            panic!()
        };
        assert_eq!(
            reference(m),
            (RefSigil::Hash, RefTarget::Name("glass".into()))
        );
        let polygon = &objects.statements[1];
        let Clause::Apply {
            name,
            arg: Some(vs),
            ..
        } = &polygon.clauses[0]
        else {
            panic!()
        };
        assert_eq!(name.text, "Polygon");
        assert_eq!(tuple(vs).len(), 4);
        assert_eq!(objects.statements[2].clauses.len(), 4); // Rod %1, %2, 0.01, #1
    }

    #[test]
    fn empty_and_trivial_inputs() {
        assert_eq!(parse(""), Parsed::default());
        assert_eq!(parse("  \n// c\n/* c */ "), Parsed::default());
        let file = clean("A{}B { } C{\n}");
        assert_eq!(file.sections.len(), 3);
        assert!(file.sections.iter().all(|s| s.statements.is_empty()));
        // A statement has at least one clause: a lone `;` is an error.
        let p = parse("C { Cube;; }");
        assert_eq!(codes(&p), [Code::Syntax]);
        assert_eq!(p.diagnostics[0].message, "expected a statement, found `;`");
        assert_eq!(p.file.sections[0].statements.len(), 1);
    }

    #[test]
    fn large_inputs_parse_in_linear_time() {
        let one = "Sphere %3, 0.05, #1; ";
        let time = |n: usize| {
            let src = format!("Objects {{ {} }}", one.repeat(n));
            let started = Instant::now();
            let p = parse(&src);
            let elapsed = started.elapsed();
            assert!(p.diagnostics.is_empty());
            assert_eq!(p.file.sections[0].statements.len(), n);
            elapsed
        };
        let small = time(2_000);
        let large = time(40_000);
        // 20 times the input; allow generous noise, but not quadratic growth (400x).
        assert!(
            large < small * 100 + Duration::from_secs(1),
            "{small:?} -> {large:?}"
        );

        // One huge broken statement, and many small broken ones.
        let big = format!("S {{ ({} }}", "1,".repeat(200_000));
        assert_eq!(codes(&parse(&big)), [Code::Syntax]);
        let many = format!("S {{ {} }}", "x y; ".repeat(20_000));
        let parsed = parse(&many);
        // The first 10,000 kept, the rest counted.
        assert_eq!(parsed.diagnostics.len(), crate::MAX_KEPT_DIAGNOSTICS);
        assert_eq!(parsed.omitted.errors, 20_000 - crate::MAX_KEPT_DIAGNOSTICS);
    }

    #[test]
    fn diagnostics_are_sorted_and_line_columns_count_chars() {
        let src = "// ünïcödé comment €€€\nPoints { (0,0,0); /* é€ */ `x`; }\nbad";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax, Code::Syntax]);
        assert!(
            p.diagnostics
                .windows(2)
                .all(|w| w[0].span.start() <= w[1].span.start())
        );
        let idx = crate::line_index::LineIndex::new(src);
        assert_eq!(idx.line_col(p.diagnostics[0].span.start()), (2, 28));
        assert_eq!(idx.line_col(p.diagnostics[1].span.start()), (3, 1));
    }

    mod props {
        use super::*;
        use proptest::prelude::*;

        fn check(src: &str) {
            let p = parse(src);
            for d in &p.diagnostics {
                assert!(
                    d.span.start() <= d.span.end() && d.span.end() <= src.len(),
                    "{d:?}"
                );
                assert!(src.is_char_boundary(d.span.start()), "{d:?}");
                assert!(src.is_char_boundary(d.span.end()), "{d:?}");
            }
            for s in &p.file.sections {
                assert!(s.span.end() <= src.len());
                assert_eq!(&src[s.name.span.start()..s.name.span.end()], s.name.text);
                for st in &s.statements {
                    // A statement that lacked its `;` at the end of a line
                    // ends at its last token.
                    let text = &src[st.span.start()..st.span.end()];
                    let after = src[st.span.end()..].trim_start_matches([' ', '\t', '\r']);
                    assert!(
                        text.ends_with(';') || after.starts_with(['\n', '/']),
                        "{text:?}"
                    );
                }
                for b in &s.broken {
                    assert!(b.span.start() <= b.span.end() && b.span.end() <= src.len());
                }
            }
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(512))]

            #[test]
            fn never_panics_on_arbitrary_strings(src in any::<String>()) {
                check(&src);
            }

            #[test]
            fn never_panics_on_scene_like_strings(
                src in "([A-Za-z_]{1,3}|[0-9.eE+-]{1,4}|[%#][a-z0-9]{0,2}|[(){};,:= \n]|->|//|/\\*|\\*/|é|€){0,80}"
            ) {
                check(&src);
            }

            #[test]
            fn valid_statements_parse_back(
                xs in proptest::collection::vec(-1.0e6f64..1.0e6, 1..6),
                label in proptest::option::of("[a-z_][a-z0-9_]{0,5}"),
            ) {
                let items: Vec<String> = xs.iter().map(|x| format!("{x:?}")).collect();
                let prefix = label.as_ref().map(|l| format!("{l}: ")).unwrap_or_default();
                let src = format!("S {{ {prefix}({}); }}", items.join(", "));
                let st = only_statement(&src);
                prop_assert_eq!(st.label.map(|l| l.text.to_string()), label);
                let Clause::Value(v) = &st.clauses[0] else { panic!() };
                prop_assert_eq!(numbers(v), xs);
            }
        }
    }
}
