//! The grammar of `grammar.pest` for one well-formed statement, by
//! recursive descent over its bytes: the fast path of [`Scanner::flush`].
//!
//! pest checks its call limit and the stack on every rule it enters and
//! tries whitespace and both comment forms between every two tokens; on a
//! large scene that was nine tenths of `check`'s time (about 1,100
//! instructions per byte). Almost every statement of a real scene is well
//! formed, so this parser takes those, and returns `None` for anything else
//! (a syntax error, a number out of range, an index past 64 bits), which
//! pest then parses as before, with its error positions and messages.
//!
//! It follows the grammar's ordered choices exactly, so where it accepts a
//! statement it builds the tree pest's parse would have built, spans
//! included (an application without an argument reaches over the
//! whitespace after its name, as pest's sequence does). The test
//! `the_direct_parser_builds_what_pest_builds` compares the two on every
//! statement of every scene shipped and on generated ones.

use super::Scanner;
use crate::diagnostic::Span;
use crate::syntax::{Clause, Ident, RefSigil, RefTarget, Reference, Statement, Value};
use smallvec::SmallVec;

/// A position in one statement's text; spans are shifted by `off` into the
/// file.
struct Cursor<'a> {
    text: &'a [u8],
    pos: usize,
    off: usize,
}

impl Scanner<'_> {
    /// The statement `self.src[start..end]`, when it is well formed and
    /// needs no diagnostic.
    pub(super) fn direct_statement(&self, start: usize, end: usize) -> Option<Statement> {
        let mut c = Cursor {
            text: self.src.as_bytes().get(start..end)?,
            pos: 0,
            off: start,
        };
        c.skip();
        let statement = c.statement()?;
        c.skip();
        (c.pos == c.text.len()).then_some(statement)
    }
}

impl Cursor<'_> {
    /// `parse`, with the position put back where it was when it fails (as
    /// a failed pest rule leaves it).
    fn attempt<T>(&mut self, parse: impl FnOnce(&mut Self) -> Option<T>) -> Option<T> {
        let from = self.pos;
        let parsed = parse(self);
        if parsed.is_none() {
            self.pos = from;
        }
        parsed
    }

    fn peek(&self) -> Option<u8> {
        self.text.get(self.pos).copied()
    }

    fn span(&self, from: usize) -> Span {
        Span::new(self.off + from, self.off + self.pos)
    }

    fn eat(&mut self, byte: u8) -> bool {
        let found = self.peek() == Some(byte);
        if found {
            self.pos += 1;
        }
        found
    }

    /// Whitespace and complete comments (pest's implicit `skip`). An
    /// unterminated block comment is left in place, where the next token
    /// then fails, as in pest.
    fn skip(&mut self) {
        loop {
            match self.peek() {
                Some(b' ' | b'\t' | b'\r' | b'\n') => self.pos += 1,
                Some(b'/') if self.text.get(self.pos + 1) == Some(&b'/') => {
                    while !matches!(self.peek(), None | Some(b'\n' | b'\r')) {
                        self.pos += 1;
                    }
                }
                Some(b'/') if self.text.get(self.pos + 1) == Some(&b'*') => {
                    let rest = &self.text[self.pos + 2..];
                    match rest.windows(2).position(|w| w == b"*/") {
                        Some(i) => self.pos += 2 + i + 2,
                        None => return,
                    }
                }
                _ => return,
            }
        }
    }

    /// `(label ~ colon)? ~ clause ~ (comma ~ clause)* ~ semicolon`.
    fn statement(&mut self) -> Option<Statement> {
        let from = self.pos;
        let mut label = None;
        if let Some(name) = self.ident() {
            self.skip();
            if self.eat(b':') {
                label = Some(name);
                self.skip();
            } else {
                self.pos = from;
            }
        }
        let mut clauses: SmallVec<[Clause; 8]> = SmallVec::new();
        clauses.push(self.clause()?);
        loop {
            self.skip();
            if self.eat(b';') {
                break;
            }
            if !self.eat(b',') {
                return None;
            }
            self.skip();
            clauses.push(self.clause()?);
        }
        Some(Statement {
            label,
            clauses: clauses.into_iter().collect(),
            span: self.span(from),
        })
    }

    /// `assignment | application | value`, in that order.
    fn clause(&mut self) -> Option<Clause> {
        let from = self.pos;
        if let Some(key) = self.ident() {
            self.skip();
            if self.eat(b'=') {
                self.skip();
                let value = match self.value() {
                    Some(v) => v,
                    None => Value::Ident(self.ident()?),
                };
                return Some(Clause::Assign {
                    key,
                    value,
                    span: self.span(from),
                });
            }
            // An application without a target: `Name value?`. The
            // whitespace skipped before a missing argument stays in its
            // span, as pest's sequence keeps it.
            let arg = self.value();
            return Some(Clause::Apply {
                target: None,
                name: key,
                arg,
                span: self.span(from),
            });
        }
        if let Some(target) = self.attempt(Self::reference) {
            let after = self.pos;
            self.skip();
            if self.eat(b'-') && self.eat(b'>') {
                self.skip();
                let name = self.ident()?;
                self.skip();
                let arg = self.value();
                return Some(Clause::Apply {
                    target: Some(Box::new(target)),
                    name,
                    arg,
                    span: self.span(from),
                });
            }
            self.pos = after;
            return Some(Clause::Value(Value::Reference(target)));
        }
        self.value().map(Clause::Value)
    }

    /// `number | reference | tuple | string | symbol`; on failure the
    /// position is where it was.
    fn value(&mut self) -> Option<Value> {
        self.attempt(|c| match c.peek()? {
            b'+' | b'-' | b'.' | b'0'..=b'9' => c.number(),
            b'%' | b'#' | b'@' => c.reference().map(Value::Reference),
            b'(' => c.tuple(),
            b'"' => c.string(),
            b'{' => c.symbol(),
            _ => None,
        })
    }

    /// An ASCII letter or `_`, then letters, digits and `_`.
    fn ident(&mut self) -> Option<Ident> {
        let from = self.pos;
        if !matches!(self.peek(), Some(b) if b.is_ascii_alphabetic() || b == b'_') {
            return None;
        }
        while matches!(self.peek(), Some(b) if b.is_ascii_alphanumeric() || b == b'_') {
            self.pos += 1;
        }
        Some(Ident {
            text: self.str_from(from).into(),
            span: self.span(from),
        })
    }

    fn str_from(&self, from: usize) -> &str {
        // Only ASCII bytes were consumed since `from`, both ends are
        // character boundaries.
        std::str::from_utf8(&self.text[from..self.pos]).unwrap_or_default()
    }

    fn digits(&mut self) -> usize {
        let from = self.pos;
        while matches!(self.peek(), Some(b'0'..=b'9')) {
            self.pos += 1;
        }
        self.pos - from
    }

    /// `("+" | "-")? ~ (digits ~ ("." ~ digits?)? | "." ~ digits) ~
    /// (^"e" ~ ("+" | "-")? ~ digits)?`; `None` for a number that would
    /// need a diagnostic (out of range, or a non-zero that underflows).
    fn number(&mut self) -> Option<Value> {
        let from = self.pos;
        if matches!(self.peek(), Some(b'+' | b'-')) {
            self.pos += 1;
        }
        if self.digits() > 0 {
            if self.eat(b'.') {
                self.digits();
            }
        } else if !(self.eat(b'.') && self.digits() > 0) {
            return None;
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            let mantissa_end = self.pos;
            self.pos += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.pos += 1;
            }
            if self.digits() == 0 {
                self.pos = mantissa_end;
            }
        }
        let text = self.str_from(from);
        let value = text.parse::<f64>().ok()?;
        if !value.is_finite() || crate::numbers::underflows(text, value) {
            return None;
        }
        Some(Value::Number {
            value,
            span: self.span(from),
        })
    }

    /// `sigil ~ (digits | name)`, no whitespace inside; `None` for an
    /// index past 64 bits.
    fn reference(&mut self) -> Option<Reference> {
        let from = self.pos;
        let sigil = match self.peek()? {
            b'%' => RefSigil::Percent,
            b'#' => RefSigil::Hash,
            b'@' => RefSigil::At,
            _ => return None,
        };
        self.pos += 1;
        let digits_from = self.pos;
        let target = if self.digits() > 0 {
            RefTarget::Index(self.str_from(digits_from).parse().ok()?)
        } else {
            RefTarget::Name(self.ident()?.text.to_string())
        };
        Some(Reference {
            sigil,
            target,
            span: self.span(from),
        })
    }

    /// `"(" ~ item ~ ("," ~ item)* ~ ")"`, an item a value or a name.
    fn tuple(&mut self) -> Option<Value> {
        let from = self.pos;
        self.eat(b'(').then_some(())?;
        let mut items: SmallVec<[Value; 4]> = SmallVec::new();
        loop {
            self.skip();
            let item = match self.value() {
                Some(v) => v,
                None => Value::Ident(self.ident()?),
            };
            items.push(item);
            self.skip();
            if self.eat(b')') {
                break;
            }
            self.eat(b',').then_some(())?;
        }
        Some(Value::Tuple {
            items: items.into_iter().collect(),
            span: self.span(from),
        })
    }

    /// `"` then anything but `"` and line breaks, then `"`.
    fn string(&mut self) -> Option<Value> {
        let from = self.pos;
        self.eat(b'"').then_some(())?;
        let inner = self.pos;
        while !matches!(self.peek(), None | Some(b'"' | b'\n' | b'\r')) {
            self.pos += 1;
        }
        let text = std::str::from_utf8(&self.text[inner..self.pos])
            .ok()?
            .to_owned();
        self.eat(b'"').then_some(())?;
        Some(Value::Str {
            text,
            span: self.span(from),
        })
    }

    /// `"{" ~ number ~ ("," ~ number)+ ~ "}"`.
    fn symbol(&mut self) -> Option<Value> {
        let from = self.pos;
        self.eat(b'{').then_some(())?;
        let mut entries = Vec::new();
        loop {
            self.skip();
            entries.push(self.number()?);
            self.skip();
            if self.eat(b'}') {
                break;
            }
            self.eat(b',').then_some(())?;
        }
        (entries.len() >= 2).then_some(Value::Symbol {
            entries: entries.into_boxed_slice(),
            span: self.span(from),
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::parser::{parse, parse_with_pest_only};
    use hscene_test_support::SplitMix64;

    /// Compared through `Debug`, where NaN (a number already reported)
    /// equals NaN.
    fn same_as_pest(source: &str) {
        assert_eq!(
            format!("{:?}", parse(source)),
            format!("{:?}", parse_with_pest_only(source)),
            "{source:?}"
        );
    }

    /// Every scene shipped in `scenes/` and every scene block of the docs'
    /// fixtures parses to the same tree and diagnostics either way.
    #[test]
    fn the_direct_parser_builds_what_pest_builds() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes");
        let mut stack = vec![root];
        let mut files = 0;
        while let Some(dir) = stack.pop() {
            let Ok(entries) = std::fs::read_dir(&dir) else {
                continue;
            };
            for entry in entries.flatten() {
                let path = entry.path();
                if path.is_dir() {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "hsc")
                    && let Ok(text) = std::fs::read_to_string(&path)
                {
                    same_as_pest(&text);
                    files += 1;
                }
            }
        }
        assert!(files > 50, "only {files} scenes found");
    }

    /// The corners of the grammar: spans reaching over whitespace and
    /// comments, numbers in every form, references glued to names, labels,
    /// symbols, strings, and near misses that must fall back to pest.
    #[test]
    fn grammar_corners_agree() {
        for statement in [
            "Cube;",
            "Cube ;",
            "Cube /* c */ ;",
            "Cube // c\n;",
            "Sphere%3,0.05,#1;",
            "Sphere %3 , 0.05 , #glass ;",
            "glass : ambient = (0.1, .2, 3.), trans = 1e-3;",
            "a = +3, b = -0.5E+2, c = 1e, d = 1.e5;",
            "%1->Rotate(%2,-0.7);",
            "%1 -> Rotate ( %2 , -0.7 ) ;",
            "%1 -0.7;",
            "%1 ->;",
            "@ball->Reflect(%m);",
            "Honeycomb {5,3,4}, #gold, edges = 0.025;",
            "Honeycomb { 5 , 3 };",
            "Honeycomb {5};",
            "Mesh \"meshes/bunny.ply\", 0.8, #clay;",
            "Mesh \"unterminated, 0.8;",
            "integrator = path;",
            "colors = (#a, #b, name, (1, 2));",
            "x = ;",
            "x = 1e999;",
            "x = 1e-400;",
            "x = 0e-400;",
            "Sphere %99999999999999999999999;",
            "a, b c;",
            "(1,2,3);",
            "((1,2),(3,4));",
            "( );",
            "1..2;",
            "- 1;",
            "a: b: c;",
            "é = 1;",
            "s = \"é€😀\";",
            "a = 1 /* unterminated ;",
            "a = 1; b = 2;",
        ] {
            same_as_pest(&format!("Objects {{\n  {statement}\n}}\n"));
        }
    }

    /// Random statements from the grammar's tokens, glued with and without
    /// whitespace and comments: most are errors (pest's path), some parse;
    /// both paths agree on all of them.
    #[test]
    fn generated_statements_agree() {
        const TOKENS: &[&str] = &[
            "Sphere",
            "a",
            "_x1",
            "=",
            ":",
            ",",
            "->",
            "(",
            ")",
            "{",
            "}",
            "1",
            "-2.5",
            ".5",
            "3.",
            "1e3",
            "2E-2",
            "1e",
            "+7",
            "%1",
            "#g",
            "@b",
            "%",
            "\"f.ply\"",
            "\"",
            ";",
            " ",
            "\n",
            "\t",
            "/* c */",
            "// c\n",
            "\r\n",
        ];
        let mut rng = SplitMix64::new(48);
        let mut parsed = 0;
        for _ in 0..20_000 {
            let n = 1 + rng.below(12);
            let mut statement = String::new();
            for _ in 0..n {
                statement.push_str(TOKENS[rng.below(TOKENS.len())]);
                if rng.below(3) == 0 {
                    statement.push(' ');
                }
            }
            statement.push(';');
            let source = format!("S {{ {statement} }}");
            same_as_pest(&source);
            parsed += parse(&source)
                .file
                .sections
                .iter()
                .map(|s| s.statements.len())
                .sum::<usize>();
        }
        // Enough of them are well formed to test the direct path itself.
        assert!(parsed > 1_000, "{parsed}");
    }
}
