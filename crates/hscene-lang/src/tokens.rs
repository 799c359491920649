//! A lossless token stream of a scene: every token with its span, comments
//! included, and the number of line breaks before each.
//!
//! The parser works statement by statement and drops comments; the
//! formatter and editor tooling need the comments and the exact layout, so
//! they work from these tokens. Whitespace is the only text not covered by a
//! token.

use crate::diagnostic::Span;

/// What a token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokenKind {
    /// A name or keyword: `Points`, `radius`, `Sphere`.
    Ident,
    /// A number literal, sign included: `-0.7`, `2e-3`.
    Number,
    /// `"file.ply"`.
    Str,
    /// `%1`, `#glass`, `@ball`.
    Reference,
    /// `// ...` up to the end of the line (the line break excluded).
    LineComment,
    /// `/* ... */`.
    BlockComment,
    /// `{`
    LBrace,
    /// `}`
    RBrace,
    /// `(`
    LParen,
    /// `)`
    RParen,
    /// `,`
    Comma,
    /// `;`
    Semi,
    /// `:`
    Colon,
    /// `=`
    Equals,
    /// `->`
    Arrow,
    /// A character that starts no token (a syntax error for the parser).
    Unknown,
}

impl TokenKind {
    /// Whether this is a comment.
    pub fn is_comment(self) -> bool {
        matches!(self, TokenKind::LineComment | TokenKind::BlockComment)
    }
}

/// One token.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    /// What it is.
    pub kind: TokenKind,
    /// Where it is (byte offsets).
    pub span: Span,
    /// Line breaks (`\n`) in the whitespace between the previous token and
    /// this one (for the first token: since the start of the file).
    pub newlines_before: usize,
}

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_continue(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// Splits `source` into tokens. Never fails: text that starts no token
/// becomes an [`TokenKind::Unknown`] token of one character, and an
/// unterminated block comment or string runs to the end of the file or line.
pub fn tokenize(source: &str) -> Vec<Token> {
    let bytes = source.as_bytes();
    let mut tokens = Vec::new();
    let mut pos = 0;
    let mut newlines = 0;
    while pos < bytes.len() {
        let b = bytes[pos];
        if b.is_ascii_whitespace() {
            if b == b'\n' {
                newlines += 1;
            }
            pos += 1;
            continue;
        }
        let (kind, end) = lex_one(source, pos);
        tokens.push(Token {
            kind,
            span: Span::new(pos, end),
            newlines_before: newlines,
        });
        newlines = 0;
        pos = end;
    }
    tokens
}

/// The kind and end of the token at `pos` (not whitespace, on a char boundary).
fn lex_one(source: &str, pos: usize) -> (TokenKind, usize) {
    let bytes = source.as_bytes();
    let run = |from: usize, pred: fn(u8) -> bool| {
        from + bytes[from..].iter().take_while(|&&b| pred(b)).count()
    };
    let next = bytes.get(pos + 1).copied();
    match bytes[pos] {
        b'/' if next == Some(b'/') => {
            let end = bytes[pos..]
                .iter()
                .position(|&b| b == b'\n')
                .map_or(bytes.len(), |i| pos + i);
            (TokenKind::LineComment, end)
        }
        b'/' if next == Some(b'*') => {
            let end = source[pos + 2..]
                .find("*/")
                .map_or(bytes.len(), |i| pos + 2 + i + 2);
            (TokenKind::BlockComment, end)
        }
        b'"' => {
            let rest = &bytes[pos + 1..];
            let end = match rest.iter().position(|&b| matches!(b, b'"' | b'\n' | b'\r')) {
                Some(i) if rest[i] == b'"' => pos + 1 + i + 1,
                Some(i) => pos + 1 + i,
                None => bytes.len(),
            };
            (TokenKind::Str, end)
        }
        b'{' => (TokenKind::LBrace, pos + 1),
        b'}' => (TokenKind::RBrace, pos + 1),
        b'(' => (TokenKind::LParen, pos + 1),
        b')' => (TokenKind::RParen, pos + 1),
        b',' => (TokenKind::Comma, pos + 1),
        b';' => (TokenKind::Semi, pos + 1),
        b':' => (TokenKind::Colon, pos + 1),
        b'=' => (TokenKind::Equals, pos + 1),
        b'-' if next == Some(b'>') => (TokenKind::Arrow, pos + 2),
        b'%' | b'#' | b'@' => (TokenKind::Reference, run(pos + 1, is_ident_continue)),
        b if is_ident_start(b) => (TokenKind::Ident, run(pos + 1, is_ident_continue)),
        b'+' | b'-' | b'.' | b'0'..=b'9' => (TokenKind::Number, number_end(bytes, pos)),
        _ => {
            let len = source[pos..].chars().next().map_or(1, char::len_utf8);
            (TokenKind::Unknown, pos + len)
        }
    }
}

/// The end of the number literal at `pos`: sign, digits and dots, then an
/// exponent if one follows (`2e-3`).
fn number_end(bytes: &[u8], pos: usize) -> usize {
    let mut end = pos;
    if matches!(bytes[end], b'+' | b'-') {
        end += 1;
    }
    while end < bytes.len() && (bytes[end].is_ascii_digit() || bytes[end] == b'.') {
        end += 1;
    }
    if end < bytes.len() && matches!(bytes[end], b'e' | b'E') {
        let mut e = end + 1;
        if e < bytes.len() && matches!(bytes[e], b'+' | b'-') {
            e += 1;
        }
        if e < bytes.len() && bytes[e].is_ascii_digit() {
            while e < bytes.len() && bytes[e].is_ascii_digit() {
                e += 1;
            }
            end = e;
        }
    }
    end.max(pos + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(src: &str) -> Vec<(TokenKind, &str, usize)> {
        tokenize(src)
            .into_iter()
            .map(|t| {
                (
                    t.kind,
                    &src[t.span.start()..t.span.end()],
                    t.newlines_before,
                )
            })
            .collect()
    }

    #[test]
    fn every_kind_with_line_breaks() {
        use TokenKind::*;
        let src =
            "Objects { // c\n\n  a: %1->Rotate(%2,-0.7), at = 2e-3; /* b\n */ \"m.ply\" #x @y ? }";
        assert_eq!(
            kinds(src),
            vec![
                (Ident, "Objects", 0),
                (LBrace, "{", 0),
                (LineComment, "// c", 0),
                (Ident, "a", 2),
                (Colon, ":", 0),
                (Reference, "%1", 0),
                (Arrow, "->", 0),
                (Ident, "Rotate", 0),
                (LParen, "(", 0),
                (Reference, "%2", 0),
                (Comma, ",", 0),
                (Number, "-0.7", 0),
                (RParen, ")", 0),
                (Comma, ",", 0),
                (Ident, "at", 0),
                (Equals, "=", 0),
                (Number, "2e-3", 0),
                (Semi, ";", 0),
                (BlockComment, "/* b\n */", 0),
                (Str, "\"m.ply\"", 0),
                (Reference, "#x", 0),
                (Reference, "@y", 0),
                (Unknown, "?", 0),
                (RBrace, "}", 0),
            ]
        );
    }

    #[test]
    fn unterminated_things_run_to_the_end() {
        assert_eq!(
            kinds("/* open"),
            vec![(TokenKind::BlockComment, "/* open", 0)]
        );
        assert_eq!(
            kinds("\"open\nx"),
            vec![(TokenKind::Str, "\"open", 0), (TokenKind::Ident, "x", 1)]
        );
        assert_eq!(kinds("é"), vec![(TokenKind::Unknown, "é", 0)]);
    }
}
