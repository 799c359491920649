//! The canonical layout of a scene (`hscene fmt`, and formatting in the
//! language server).
//!
//! The formatter works on the lossless token stream ([`crate::tokens`]), so
//! it sees every comment, and it only changes whitespace: the tokens come out
//! in the same order with the same text, which is why it cannot change what a
//! scene means. The layout (documented in `docs/formatting.md`):
//!
//! - one section after another, a blank line between them, `Name {` ... `}`;
//! - one statement per line, indented by four spaces;
//! - a statement whose first clause is `key = value` and that has several
//!   clauses (a material) puts each clause on its own line, as the thesis
//!   writes its `BRDFs`, the second and later one level deeper than the
//!   first, so that each material's first line (with its label) stands out;
//! - `, ` after commas, ` = ` around `=`, `: ` after a label, no space inside
//!   parentheses, around `->` or before the `(` of an application;
//! - a Schläfli symbol inside a statement is written `{4,3,5}`, as
//!   mathematicians write it: no space inside its braces;
//! - comments stay where they were: a comment that ended a line still ends
//!   it, a comment on its own line stays on its own line (re-indented), and
//!   one blank line is kept where the author left one or more.
//!
//! A file with syntax errors is not formatted: its structure is not known.

use crate::diagnostic::Diagnostic;
use crate::tokens::{Token, TokenKind, tokenize};

/// Why a scene could not be formatted.
#[derive(Clone, Debug, PartialEq)]
pub enum FormatError {
    /// The scene has syntax errors (the parser's diagnostics, all errors).
    Syntax(Vec<Diagnostic>),
}

impl std::fmt::Display for FormatError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FormatError::Syntax(d) => write!(
                f,
                "the scene has {} syntax error(s); fix them before formatting",
                d.len()
            ),
        }
    }
}

impl std::error::Error for FormatError {}

/// The indentation of one level.
const INDENT: &str = "    ";

/// Formats a scene into the canonical layout. The result ends with exactly
/// one line break (or is empty for a file of only whitespace), uses `\n`
/// line breaks, and formatting it again gives it back unchanged.
pub fn format(source: &str) -> Result<String, FormatError> {
    let parsed = crate::parser::parse(source);
    let errors: Vec<Diagnostic> = parsed
        .diagnostics
        .into_iter()
        .filter(Diagnostic::is_error)
        .collect();
    if !errors.is_empty() {
        return Err(FormatError::Syntax(errors));
    }
    let tokens = tokenize(source);
    let mut w = Writer {
        source,
        tokens: &tokens,
        out: String::with_capacity(source.len() + source.len() / 8),
        pending: Pending::Start,
        prev: None,
        in_section: false,
        statement: None,
        paren_depth: 0,
        in_symbol: false,
    };
    for i in 0..tokens.len() {
        w.token(i);
    }
    if !w.out.is_empty() {
        w.out.push('\n');
    }
    Ok(w.out)
}

/// What separates the next token from the text written so far.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Pending {
    /// Nothing written yet.
    Start,
    /// The spacing rules between the previous and next token decide.
    Inline,
    /// A single space (after a block comment inside a line).
    Space,
    /// A line break (after `{`, `;`, `}` and line comments, and between the
    /// clauses of a material).
    Break,
    /// A line break where the source had one, else a space (after a block
    /// comment on its own line).
    Soft,
}

/// The statement being written.
#[derive(Clone, Copy, Debug)]
struct Statement {
    /// One clause per line.
    clause_per_line: bool,
    /// Some of its tokens (not comments) are written.
    started: bool,
    /// The last token written, not counting comments, is a comma that ends
    /// a clause of a one-clause-per-line statement.
    at_clause_start: bool,
}

struct Writer<'a> {
    source: &'a str,
    tokens: &'a [Token],
    out: String,
    pending: Pending,
    /// The last token written (comments included).
    prev: Option<TokenKind>,
    in_section: bool,
    statement: Option<Statement>,
    paren_depth: usize,
    /// Between the braces of a Schläfli symbol (`{4,3,5}`): braces inside a
    /// section are only ever those, and they do not nest.
    in_symbol: bool,
}

impl Writer<'_> {
    fn text(&self, t: &Token) -> &str {
        &self.source[t.span.start()..t.span.end()]
    }

    fn token(&mut self, i: usize) {
        let t = self.tokens[i];
        if t.kind.is_comment() {
            self.comment(&t);
            return;
        }
        if self.in_section && self.statement.is_none() && t.kind != TokenKind::RBrace {
            self.statement = Some(Statement {
                clause_per_line: self.is_material_like(i),
                started: false,
                at_clause_start: false,
            });
        }
        let brk = match self.pending {
            Pending::Start => false,
            Pending::Break => true,
            Pending::Soft => t.newlines_before > 0,
            Pending::Inline | Pending::Space => false,
        };
        if brk {
            self.line_break(&t);
        } else if self.pending == Pending::Space || self.space_between(t.kind) {
            self.out.push(' ');
        }
        let text = self.text(&t).to_owned();
        self.out.push_str(&text);
        self.prev = Some(t.kind);
        self.pending = Pending::Inline;
        if let Some(s) = &mut self.statement {
            s.started = true;
            s.at_clause_start = false;
        }
        match t.kind {
            TokenKind::LBrace if self.in_section => self.in_symbol = true,
            TokenKind::RBrace if self.in_symbol => self.in_symbol = false,
            TokenKind::LBrace => {
                self.in_section = true;
                self.pending = Pending::Break;
            }
            TokenKind::RBrace => {
                self.in_section = false;
                self.statement = None;
                self.pending = Pending::Break;
            }
            TokenKind::Semi => {
                self.statement = None;
                self.paren_depth = 0;
                self.pending = Pending::Break;
            }
            TokenKind::LParen => self.paren_depth += 1,
            TokenKind::RParen => self.paren_depth = self.paren_depth.saturating_sub(1),
            TokenKind::Comma if self.paren_depth == 0 && !self.in_symbol => {
                if let Some(s) = &mut self.statement
                    && s.clause_per_line
                {
                    s.at_clause_start = true;
                    self.pending = Pending::Break;
                }
            }
            _ => {}
        }
    }

    fn comment(&mut self, t: &Token) {
        let text = match t.kind {
            TokenKind::LineComment => self.text(t).trim_end().to_owned(),
            _ => self.text(t).to_owned(),
        };
        let trailing = t.newlines_before == 0 && self.pending != Pending::Start;
        if trailing {
            self.out.push(' ');
        } else if self.pending != Pending::Start {
            self.line_break(t);
        }
        self.out.push_str(&text);
        self.prev = Some(t.kind);
        self.pending = match (t.kind, trailing, self.pending) {
            (TokenKind::LineComment, _, _) => Pending::Break,
            (_, true, Pending::Break) => Pending::Break,
            (_, true, _) => Pending::Space,
            (_, false, _) => Pending::Soft,
        };
    }

    /// Ends the line and indents for `t`, keeping one blank line where the
    /// source had any between statements, sections and comments.
    fn line_break(&mut self, t: &Token) {
        self.out.push('\n');
        // Inside a statement, a line that does not start one of a material's
        // clauses continues the one before.
        let continuation = self
            .statement
            .is_some_and(|s| s.started && !s.at_clause_start);
        // A material's second and later clauses are indented under its
        // first, so that one material does not run into the next.
        let later_clause = self
            .statement
            .is_some_and(|s| s.started && s.at_clause_start && s.clause_per_line);
        let blank = if !self.in_section && t.kind != TokenKind::RBrace {
            // Between sections (and the comments around them).
            self.prev == Some(TokenKind::RBrace) || t.newlines_before >= 2
        } else {
            t.newlines_before >= 2
                && t.kind != TokenKind::RBrace
                && self.prev != Some(TokenKind::LBrace)
                && !continuation
        };
        if blank {
            self.out.push('\n');
        }
        if self.in_section && t.kind != TokenKind::RBrace {
            self.out.push_str(INDENT);
            if continuation || later_clause {
                self.out.push_str(INDENT);
            }
        }
    }

    /// Whether the statement starting at token `i` has several clauses and
    /// begins with `key = value` (after an optional label).
    fn is_material_like(&self, i: usize) -> bool {
        let code: Vec<TokenKind> = self.tokens[i..]
            .iter()
            .map(|t| t.kind)
            .filter(|k| !k.is_comment())
            .take_while(|k| !matches!(k, TokenKind::Semi | TokenKind::RBrace))
            .collect();
        let rest = match code.as_slice() {
            [TokenKind::Ident, TokenKind::Colon, rest @ ..] => rest,
            all => all,
        };
        let starts_with_assign = matches!(rest, [TokenKind::Ident, TokenKind::Equals, ..]);
        let mut depth = 0usize;
        let mut commas = 0;
        for k in rest {
            match k {
                TokenKind::LParen => depth += 1,
                TokenKind::RParen => depth = depth.saturating_sub(1),
                TokenKind::Comma if depth == 0 => commas += 1,
                _ => {}
            }
        }
        starts_with_assign && commas > 0
    }

    /// Whether a space goes between the previous token and one of `next`
    /// on the same line.
    fn space_between(&self, next: TokenKind) -> bool {
        use TokenKind::*;
        let Some(prev) = self.prev else {
            return false;
        };
        if self.in_symbol {
            return false;
        }
        !matches!(
            (prev, next),
            (_, Comma | Semi | RParen | Colon) | (LParen | Arrow, _) | (_, Arrow) | (Ident, LParen)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fmt(src: &str) -> String {
        let out = format(src).unwrap();
        assert_eq!(format(&out).unwrap(), out, "not idempotent on {src:?}");
        out
    }

    #[test]
    fn canonical_layout() {
        let src = "Globals{resolution=(800 ,600);to=(0,0,0.1) ;}Points{eye=(0,0,0.2);(0.1,0,0);}\
                   Objects{Sphere %1,0.1,#1;%1->Rotate(%2,-0.7);}";
        assert_eq!(
            fmt(src),
            "Globals {\n    resolution = (800, 600);\n    to = (0, 0, 0.1);\n}\n\n\
             Points {\n    eye = (0, 0, 0.2);\n    (0.1, 0, 0);\n}\n\n\
             Objects {\n    Sphere %1, 0.1, #1;\n    %1->Rotate(%2, -0.7);\n}\n"
        );
    }

    #[test]
    fn materials_one_clause_per_line() {
        let src = "BRDFs { glass: ambient=(1,1,1), alpha = 0.5;\n\n\n  diffuse = (1,0,0); }";
        assert_eq!(
            fmt(src),
            "BRDFs {\n    glass: ambient = (1, 1, 1),\n        alpha = 0.5;\n\n    diffuse = (1, 0, 0);\n}\n"
        );
    }

    /// The trap: two labelled materials, each over several lines; the
    /// later fields of each are indented under its label's line, so the
    /// second material's label starts a line of its own at the outer level.
    #[test]
    fn a_materials_later_fields_are_indented_under_its_first() {
        let src = "BRDFs { floor: ambient = (0.3, 0.3, 0.3), diffuse = (0.9, 0.9, 0.85),\nspecular = (0.2, 0.2, 0.2); ball: diffuse = (1, 0, 0),\nalpha = 0.2; }";
        assert_eq!(
            fmt(src),
            "BRDFs {\n    floor: ambient = (0.3, 0.3, 0.3),\n        diffuse = (0.9, 0.9, 0.85),\n        specular = (0.2, 0.2, 0.2);\n    ball: diffuse = (1, 0, 0),\n        alpha = 0.2;\n}\n"
        );
    }

    #[test]
    fn comments_stay_where_they_were() {
        let src = "// head\n\n\nPoints { // after brace\n  (0,0,0); // trailing\n\n  // own line\n  /* block */ (1,\n  // inside\n  0,0); /* after */\n}\n// tail\n";
        assert_eq!(
            fmt(src),
            "// head\n\nPoints { // after brace\n    (0, 0, 0); // trailing\n\n    // own line\n    /* block */ (1,\n        // inside\n        0, 0); /* after */\n}\n\n// tail\n"
        );
    }

    #[test]
    fn material_with_comments_between_clauses() {
        let src = "BRDFs {\n ambient = (1,1,1), // a\n diffuse = (1,0,0), /* b */\n alpha = 1;\n}";
        assert_eq!(
            fmt(src),
            "BRDFs {\n    ambient = (1, 1, 1), // a\n        diffuse = (1, 0, 0), /* b */\n        alpha = 1;\n}\n"
        );
    }

    #[test]
    fn syntax_errors_are_refused() {
        let err = format("Objects { Sphere %3, 0.05 #1; }").unwrap_err();
        let FormatError::Syntax(d) = err;
        assert!(!d.is_empty());
        assert!(format("Points { (0,0,0); /* open").is_err());
    }

    #[test]
    fn empty_and_comment_only_files() {
        assert_eq!(fmt("  \n\n"), "");
        assert_eq!(fmt("// only\n"), "// only\n");
        assert_eq!(fmt("Points {\n\n}"), "Points {\n}\n");
    }

    #[test]
    fn schlafli_symbols_keep_their_braces_tight() {
        let src = "Objects{Honeycomb { 4 , 3,5 },#1,depth=2;\nTessellation435 1, #1;}";
        assert_eq!(
            fmt(src),
            "Objects {\n    Honeycomb {4,3,5}, #1, depth = 2;\n    Tessellation435 1, #1;\n}\n"
        );
        // A material-like statement is not split inside a symbol.
        let src = "Objects { Honeycomb {5,3,4}, #1, edges = 0.01, faces = #2; }";
        assert_eq!(
            fmt(src),
            "Objects {\n    Honeycomb {5,3,4}, #1, edges = 0.01, faces = #2;\n}\n"
        );
    }

    #[test]
    fn same_tokens_out_as_in() {
        let src = "Objects { Polygon (%1,%2,%3), #1, wireframe = .01; Mesh \"a b.ply\", #glass; }";
        let out = fmt(src);
        let texts = |s: &str| -> Vec<String> {
            tokenize(s)
                .iter()
                .map(|t| s[t.span.start()..t.span.end()].to_owned())
                .collect()
        };
        assert_eq!(texts(src), texts(&out));
    }
}
