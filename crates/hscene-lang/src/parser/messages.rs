//! How parse errors are put into words: what was found (a quoted, shortened
//! piece of source), what was expected (pest's rules named as tokens), and
//! the one diagnostic a statement that pest refused gets.

use pest::error::{ErrorVariant, InputLocation};

use super::lexer::{lex_at, skip_trivia};
use super::{Rule, Scanner};
use crate::diagnostic::{Code, Diagnostic, Span};

/// Quotes a piece of source for a message, shortened and with control
/// characters escaped.
pub(super) fn snippet(text: &str) -> String {
    const MAX: usize = 24;
    let mut out = String::from("`");
    for (i, c) in text.chars().enumerate() {
        if i == MAX {
            out.push('…');
            break;
        }
        if c.is_control() {
            out.extend(c.escape_default());
        } else if crate::source::is_invisible(c) {
            out.push_str(&format!("<U+{:04X}>", u32::from(c)));
        } else {
            out.push(c);
        }
    }
    out.push('`');
    out
}

/// Joins alternatives: "a", "a or b", "a, b or c".
fn one_of(items: &[&str]) -> String {
    match items {
        [] => String::new(),
        [one] => (*one).to_string(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    }
}

/// How a grammar rule is named in "expected ..." messages.
fn rule_words(rule: Rule) -> &'static str {
    match rule {
        Rule::semicolon => "`;`",
        Rule::comma => "`,`",
        Rule::colon => "`:`",
        Rule::equals => "`=`",
        Rule::arrow => "`->`",
        Rule::lparen => "`(`",
        Rule::rparen => "`)`",
        Rule::lbrace => "`{`",
        Rule::rbrace => "`}`",
        Rule::value | Rule::clause => "a value",
        Rule::number => "a number",
        Rule::reference => "a reference",
        Rule::tuple => "a tuple",
        Rule::symbol => "a Schläfli symbol",
        Rule::string | Rule::string_inner => "a string",
        Rule::ident | Rule::label | Rule::assignment | Rule::application => "a name",
        Rule::sigil => "`%`, `#` or `@`",
        Rule::ref_index | Rule::ref_name => "an index or a name after the sigil",
        Rule::statement | Rule::statement_only => "a statement",
        Rule::section => "a section",
        Rule::EOI => "end of statement",
        _ => "something else",
    }
}

impl Scanner<'_> {
    /// Describes what is at `pos` for "found ..." (after skipping trivia when
    /// `skip` is set).
    pub(super) fn found_at(&self, pos: usize, skip: bool) -> String {
        let pos = if skip {
            skip_trivia(self.src, pos).0
        } else {
            pos
        };
        let Some(c) = self.src.get(pos..).and_then(|s| s.chars().next()) else {
            return "end of file".to_string();
        };
        if matches!(c, ' ' | '\t' | '\r' | '\n') {
            return "whitespace".to_string();
        }
        if self.src[pos..].starts_with("//") || self.src[pos..].starts_with("/*") {
            return "a comment".to_string();
        }
        let (_, end) = lex_at(self.src, pos);
        snippet(&self.src[pos..end])
    }

    pub(super) fn report_pest_error(
        &mut self,
        err: &pest::error::Error<Rule>,
        start: usize,
        end: usize,
    ) {
        let local = match err.location {
            InputLocation::Pos(p) => p,
            InputLocation::Span((p, _)) => p,
        };
        let at = (start + local).min(end);
        let expected = match &err.variant {
            ErrorVariant::ParsingError { positives, .. } => {
                let mut words: Vec<&str> = Vec::new();
                for &rule in positives {
                    let w = rule_words(rule);
                    if !words.contains(&w) {
                        words.push(w);
                    }
                }
                // `->` after a reference is only worth mentioning when the
                // statement could not simply end there.
                if words.contains(&"`;`") {
                    words.retain(|w| *w != "`->`");
                }
                words.sort_by_key(|w| !w.starts_with('`'));
                one_of(&words)
            }
            ErrorVariant::CustomError { message } => {
                // Only pest's resource limits ("stack limit reached") end up here.
                self.diagnostics.push(
                    Diagnostic::new(
                        Code::Syntax,
                        Span::new(start, end),
                        format!("statement could not be parsed: {message}"),
                    )
                    .with_help("split the statement into simpler ones"),
                );
                return;
            }
        };
        let (span, found) = if at < end {
            let (_, tok_end) = lex_at(self.src, at);
            (Span::new(at, tok_end.min(end)), self.found_at(at, false))
        } else {
            // The statement was cut off (by `}`, a new section or the end of
            // the file): point just after its last token.
            (Span::new(at, at), self.found_at(at, true))
        };
        let message = if expected.is_empty() {
            format!("unexpected {found}")
        } else {
            format!("expected {expected}, found {found}")
        };
        let word = &self.src[span.start()..span.end()];
        if crate::numbers::is_non_finite_word(word) {
            self.diagnostics
                .push(crate::numbers::non_finite(span, word));
            return;
        }
        let mut diag = Diagnostic::new(Code::Syntax, span, message);
        if at >= end && expected.contains("`;`") {
            diag = diag
                .with_label("expected `;` here")
                .with_help("every statement ends with `;`");
        } else if !expected.is_empty() {
            diag = diag.with_label(format!("expected {expected}"));
        }
        if let Some(path) = unquoted_path(self.src, span.start()) {
            diag = diag.with_help(format!("a file name is a string: quote it, \"{path}\""));
        }
        let letter = self.src[at.min(end)..end]
            .chars()
            .next()
            .is_some_and(|c| !c.is_ascii() && c.is_alphanumeric());
        if letter {
            diag = diag.with_help("names may only use ASCII letters, digits and `_`");
        }
        self.diagnostics.push(diag);
    }
}

/// The file name `name.ext` when the error at `at` is the `.ext` of an
/// unquoted `key = name.ext` (`texture = swirl.png`): the scanner stops
/// at the dot.
fn unquoted_path(src: &str, at: usize) -> Option<String> {
    let before = src.get(..at)?;
    let is_name = |c: char| c.is_ascii_alphanumeric() || "_-/".contains(c);
    let stem_start = before.trim_end_matches(is_name).len();
    let stem = &before[stem_start..];
    let assigned = before[..stem_start].trim_end().ends_with('=');
    let ext: String = src
        .get(at..)?
        .strip_prefix('.')?
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric())
        .collect();
    (assigned
        && !stem.is_empty()
        && !ext.is_empty()
        && !stem.starts_with(|c: char| c.is_ascii_digit()))
    .then(|| format!("{stem}.{ext}"))
}

#[cfg(test)]
mod tests {
    use crate::diagnostic::{Code, Span};
    use crate::parser::fixtures::codes;
    use crate::parser::parse;

    /// `texture = swirl.png` unquoted: the help says to quote it.
    #[test]
    fn an_unquoted_file_name_is_told_to_be_quoted() {
        let p = parse("S { m: diffuse = (1, 1, 1), texture = swirl.png; }");
        assert_eq!(p.diagnostics.len(), 1);
        let help = p.diagnostics[0].help.as_deref().unwrap_or("");
        assert!(help.contains("\"swirl.png\""), "{help}");
        let p = parse("S { a = 0.5.5; }");
        assert!(
            p.diagnostics
                .iter()
                .all(|d| !d.help.as_deref().unwrap_or("").contains("quote")),
        );
    }

    #[test]
    fn messages_name_tokens_not_rules() {
        for (src, msg) in [
            (
                "S { Sphere %3, 0.05, #1 }",
                "expected `,` or `;`, found `}`",
            ),
            ("S { a = (1,2 }", "expected `)` or `,`, found `}`"),
            ("S { (); }", "expected a value or a name, found `)`"),
            ("S { %1->; }", "expected a name, found `;`"),
            ("S { x: ; }", "expected a value, found `;`"),
            (
                "S { % 1; }",
                "expected an index or a name after the sigil, found whitespace",
            ),
            ("S { é; }", "expected a statement, found `é`"),
            ("S { \u{7}; }", "expected a statement, found `\\u{7}`"),
        ] {
            let p = parse(src);
            assert_eq!(p.diagnostics.len(), 1, "{src}");
            assert_eq!(p.diagnostics[0].message, msg, "{src}");
        }
        let p = parse("S { Sphäre %1; }");
        assert_eq!(
            p.diagnostics[0].help.as_deref(),
            Some("names may only use ASCII letters, digits and `_`")
        );
    }

    #[test]
    fn missing_semicolon_before_closing_brace() {
        let src = "Points { (0,0,0); (1,1,1) }\nObjects { Cube; }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax]);
        let d = &p.diagnostics[0];
        assert_eq!(d.message, "expected `,` or `;`, found `}`");
        // Points right after the last token, where the `;` belongs.
        assert_eq!(d.span, Span::new(25, 25));
        assert_eq!(d.label.as_deref(), Some("expected `;` here"));
        assert_eq!(p.file.sections.len(), 2);
        assert_eq!(p.file.sections[0].statements.len(), 1);
        assert_eq!(p.file.sections[1].statements.len(), 1);
    }

    #[test]
    fn malformed_numbers_are_syntax_errors() {
        for bad in [
            "S { - 1; }",
            "S { 1e; }",
            "S { 1.2.3; }",
            "S { .; }",
            "S { 1x; }",
            "S { ++1; }",
        ] {
            let p = parse(bad);
            assert_eq!(codes(&p), [Code::Syntax], "{bad}");
            assert!(p.file.sections[0].statements.is_empty(), "{bad}");
        }
    }
}
