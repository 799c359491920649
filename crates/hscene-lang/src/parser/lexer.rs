//! The scanner's tokens: whitespace and comments skipped, and the few kinds
//! of token that section and statement boundaries depend on. Every token
//! ends on a char boundary and on its own line (an unterminated string stops
//! at the line end).

use super::Scanner;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::syntax::Ident;

/// What the scanner distinguishes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ScanKind {
    Ident,
    LBrace,
    RBrace,
    LParen,
    RParen,
    Semi,
    /// Anything else: numbers, references, punctuation, stray characters.
    Other,
}

/// One token of the scanner: its kind and where it is.
#[derive(Clone, Copy, Debug)]
pub(super) struct ScanToken {
    pub(super) kind: ScanKind,
    pub(super) span: Span,
}

pub(super) fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_continue(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// The kind and end of the token starting at `pos` (which must be below
/// `src.len()` and on a char boundary). Ends are always char boundaries.
pub(super) fn lex_at(src: &str, pos: usize) -> (ScanKind, usize) {
    let bytes = src.as_bytes();
    let run = |from: usize, pred: fn(u8) -> bool| {
        from + bytes[from..].iter().take_while(|&&b| pred(b)).count()
    };
    match bytes[pos] {
        b'{' => (ScanKind::LBrace, pos + 1),
        b'}' => (ScanKind::RBrace, pos + 1),
        b'(' => (ScanKind::LParen, pos + 1),
        b')' => (ScanKind::RParen, pos + 1),
        b';' => (ScanKind::Semi, pos + 1),
        b if is_ident_start(b) => (ScanKind::Ident, run(pos + 1, is_ident_continue)),
        b'0'..=b'9' | b'.' => (
            ScanKind::Other,
            run(pos + 1, |b| is_ident_continue(b) || b == b'.'),
        ),
        b'%' | b'#' | b'@' => (ScanKind::Other, run(pos + 1, is_ident_continue)),
        // A string runs to its closing quote; an unterminated one stops at
        // the line end, so a stray `"` cannot swallow the rest of the file.
        b'"' => {
            let rest = &bytes[pos + 1..];
            match rest.iter().position(|&b| matches!(b, b'"' | b'\n' | b'\r')) {
                Some(i) if rest[i] == b'"' => (ScanKind::Other, pos + 1 + i + 1),
                Some(i) => (ScanKind::Other, pos + 1 + i),
                None => (ScanKind::Other, src.len()),
            }
        }
        _ => {
            let len = src[pos..].chars().next().map_or(1, char::len_utf8);
            (ScanKind::Other, pos + len)
        }
    }
}

/// Skips whitespace and comments from `pos`; returns the new position and
/// the start of an unterminated block comment, if one was hit.
pub(super) fn skip_trivia(src: &str, mut pos: usize) -> (usize, Option<usize>) {
    let bytes = src.as_bytes();
    while pos < bytes.len() {
        match bytes[pos] {
            b' ' | b'\t' | b'\r' | b'\n' => pos += 1,
            // A line comment ends at any line end, CR included, so a
            // file with old Mac line ends is not one long comment.
            b'/' if bytes.get(pos + 1) == Some(&b'/') => {
                pos = bytes[pos..]
                    .iter()
                    .position(|&b| crate::source::is_line_end(b))
                    .map_or(src.len(), |i| pos + i);
            }
            // A byte-order mark at the very start is not text.
            0xEF if pos == 0 && src.starts_with('\u{feff}') => pos += 3,
            b'/' if bytes.get(pos + 1) == Some(&b'*') => match src[pos + 2..].find("*/") {
                Some(i) => pos = pos + 2 + i + 2,
                None => return (src.len(), Some(pos)),
            },
            _ => break,
        }
    }
    (pos, None)
}

impl Scanner<'_> {
    pub(super) fn next_token(&mut self) -> Option<ScanToken> {
        let (pos, unterminated) = skip_trivia(self.src, self.pos);
        self.pos = pos;
        if let Some(at) = unterminated {
            self.comment_unterminated = true;
            self.incomplete = true;
            self.diagnostics.push(
                Diagnostic::new(
                    Code::UnterminatedComment,
                    Span::new(at, at + 2),
                    "unterminated block comment",
                )
                .with_label("this comment is never closed")
                .with_help("close the comment with `*/`"),
            );
        }
        if self.pos >= self.src.len() {
            return None;
        }
        let (kind, end) = lex_at(self.src, self.pos);
        let span = Span::new(self.pos, end);
        self.pos = end;
        Some(ScanToken { kind, span })
    }

    pub(super) fn ident(&self, tok: ScanToken) -> Ident {
        Ident {
            text: self.src[tok.span.start()..tok.span.end()].into(),
            span: tok.span,
        }
    }

    /// The start of every token of `start..end`, with its end.
    pub(super) fn tokens(&self, start: usize, end: usize) -> Vec<(ScanKind, Span)> {
        let mut out = Vec::new();
        let mut pos = start;
        loop {
            let (at, unterminated) = skip_trivia(self.src, pos);
            if unterminated.is_some() || at >= end {
                return out;
            }
            let (kind, tok_end) = lex_at(self.src, at);
            let tok_end = tok_end.min(end);
            out.push((kind, Span::new(at, tok_end)));
            pos = tok_end;
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::diagnostic::Code;
    use crate::parser::fixtures::{clean, codes, numbers, only_statement, section, text};
    use crate::parser::parse;
    use crate::syntax::{Clause, Value};

    #[test]
    fn comments_of_both_kinds() {
        let src = "// leading comment\n\
                   Points /* before brace */ { // after brace\n\
                   (0, /* inside ; } { */ 0, 0); // trailing ; }\n\
                   /* between\n statements */ (1,\n// line comment inside a tuple\n2,3);\n\
                   }\n\
                   /* after */ Objects{Cube;}// no final newline";
        let file = clean(src);
        assert_eq!(file.sections.len(), 2);
        let points = &file.sections[0];
        assert_eq!(points.statements.len(), 2);
        let Clause::Value(v) = &points.statements[1].clauses[0] else {
            panic!()
        };
        assert_eq!(numbers(v), [1.0, 2.0, 3.0]);
        assert_eq!(
            text(src, points.statements[0].span),
            "(0, /* inside ; } { */ 0, 0);"
        );
        assert_eq!(file.sections[1].statements.len(), 1);
        // `/` alone is not a comment.
        assert_eq!(codes(&parse("S { 1 / 2; }")), [Code::Syntax]);
    }

    #[test]
    fn unterminated_comment_is_one_diagnostic() {
        let src = "Points { (0,0,0); /* the rest is commented out (1,1,1); }\nObjects { Cube; }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::UnterminatedComment]);
        assert_eq!(text(src, p.diagnostics[0].span), "/*");
        assert_eq!(p.file.sections.len(), 1);
        assert_eq!(p.file.sections[0].statements.len(), 1);

        let p = parse("/*");
        assert_eq!(codes(&p), [Code::UnterminatedComment]);
        assert!(p.file.sections.is_empty());
        let p = parse("S { a = 1 /* x */ /*/ }");
        assert_eq!(codes(&p), [Code::UnterminatedComment]);
    }

    #[test]
    fn strings_are_values_and_may_hold_any_punctuation() {
        let st = only_statement("Objects { Mesh \"dir/a b;{}(%1)//.ply\", 0.5, #1; }");
        let Clause::Apply {
            arg: Some(Value::Str { text, .. }),
            ..
        } = &st.clauses[0]
        else {
            panic!("{st:?}")
        };
        assert_eq!(text, "dir/a b;{}(%1)//.ply");
        // An unterminated string ends at its line, so it cannot swallow the
        // rest of the file: one diagnostic for the statement it breaks.
        let src = "Objects { Mesh \"a.obj, 1, #1;\nSphere (0,0,0), 0.1, #1; }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax]);
        assert_eq!(section(&p.file, "Objects").broken.len(), 1);
    }
}
