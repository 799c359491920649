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

use pest::Parser as _;
use pest::error::{ErrorVariant, InputLocation};
use pest::iterators::Pair;
use pest_derive::Parser;

use crate::diagnostic::{Code, Diagnostic, Span};
use crate::syntax::{
    BrokenStatement, Clause, Ident, RefSigil, RefTarget, Reference, Section, SourceFile, Statement,
    Value,
};

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
    /// Syntax diagnostics, sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

impl Parsed {
    /// Whether any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(Diagnostic::is_error)
    }
}

/// Parses a scene. Never panics; always returns a tree (possibly partial)
/// and the diagnostics for everything that could not be parsed.
///
/// Statements that fail to parse are left out of the tree; sections keep
/// their good statements.
pub fn parse(source: &str) -> Parsed {
    let mut p = Scanner {
        src: source,
        pos: 0,
        diagnostics: Vec::new(),
        comment_unterminated: false,
        incomplete: false,
    };
    let file = p.file();
    let mut diagnostics = p.diagnostics;
    diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
    Parsed { file, diagnostics }
}

/// What the scanner distinguishes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Ident,
    LBrace,
    RBrace,
    LParen,
    RParen,
    Semi,
    /// Anything else: numbers, references, punctuation, stray characters.
    Other,
}

#[derive(Clone, Copy, Debug)]
struct Tok {
    kind: Kind,
    span: Span,
}

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_continue(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// The kind and end of the token starting at `pos` (which must be below
/// `src.len()` and on a char boundary). Ends are always char boundaries.
fn lex_at(src: &str, pos: usize) -> (Kind, usize) {
    let bytes = src.as_bytes();
    let run = |from: usize, pred: fn(u8) -> bool| {
        from + bytes[from..].iter().take_while(|&&b| pred(b)).count()
    };
    match bytes[pos] {
        b'{' => (Kind::LBrace, pos + 1),
        b'}' => (Kind::RBrace, pos + 1),
        b'(' => (Kind::LParen, pos + 1),
        b')' => (Kind::RParen, pos + 1),
        b';' => (Kind::Semi, pos + 1),
        b if is_ident_start(b) => (Kind::Ident, run(pos + 1, is_ident_continue)),
        b'0'..=b'9' | b'.' => (
            Kind::Other,
            run(pos + 1, |b| is_ident_continue(b) || b == b'.'),
        ),
        b'%' | b'#' | b'@' => (Kind::Other, run(pos + 1, is_ident_continue)),
        // A string runs to its closing quote; an unterminated one stops at
        // the line end, so a stray `"` cannot swallow the rest of the file.
        b'"' => {
            let rest = &bytes[pos + 1..];
            match rest.iter().position(|&b| matches!(b, b'"' | b'\n' | b'\r')) {
                Some(i) if rest[i] == b'"' => (Kind::Other, pos + 1 + i + 1),
                Some(i) => (Kind::Other, pos + 1 + i),
                None => (Kind::Other, src.len()),
            }
        }
        _ => {
            let len = src[pos..].chars().next().map_or(1, char::len_utf8);
            (Kind::Other, pos + len)
        }
    }
}

/// Quotes a piece of source for a message, shortened and with control
/// characters escaped.
fn snippet(text: &str) -> String {
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

/// The state of the statement being scanned inside a section body.
#[derive(Default)]
struct Stmt {
    /// Offset of the first token, if any.
    start: Option<usize>,
    /// End of the last token.
    end: usize,
    /// End of the token before the last one (or the start, if only one).
    prev_end: usize,
    /// The last token.
    last: Option<Tok>,
    parens: usize,
    braces: usize,
    /// The first `(` nested deeper than [`MAX_NESTING`].
    too_deep: Option<Span>,
}

impl Stmt {
    fn push(&mut self, tok: Tok) {
        if self.start.is_none() {
            self.start = Some(tok.span.start);
            self.prev_end = tok.span.start;
        } else {
            self.prev_end = self.end;
        }
        self.end = tok.span.end;
        self.last = Some(tok);
        match tok.kind {
            Kind::LParen => {
                self.parens += 1;
                if self.parens > MAX_NESTING && self.too_deep.is_none() {
                    self.too_deep = Some(tok.span);
                }
            }
            Kind::RParen => self.parens = self.parens.saturating_sub(1),
            Kind::LBrace => self.braces += 1,
            Kind::RBrace => self.braces = self.braces.saturating_sub(1),
            _ => {}
        }
    }
}

/// The statements of a section body, good and broken.
#[derive(Default)]
struct Body {
    statements: Vec<Statement>,
    broken: Vec<BrokenStatement>,
}

/// The next section header found while scanning: its name and its `{`.
type Header = (Ident, Span);

struct Scanner<'a> {
    src: &'a str,
    pos: usize,
    diagnostics: Vec<Diagnostic>,
    /// Set once an unterminated `/*` swallowed the rest of the file; the
    /// problems that follow from it (unclosed section, cut statement) are
    /// then not reported again.
    comment_unterminated: bool,
    /// Set when text was skipped whole (see [`SourceFile::incomplete`]).
    incomplete: bool,
}

impl Scanner<'_> {
    /// Skips whitespace and comments from `pos`; returns the new position and
    /// the start of an unterminated block comment, if one was hit.
    fn skip_trivia(src: &str, mut pos: usize) -> (usize, Option<usize>) {
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

    fn next_token(&mut self) -> Option<Tok> {
        let (pos, unterminated) = Self::skip_trivia(self.src, self.pos);
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
        Some(Tok { kind, span })
    }

    /// Describes what is at `pos` for "found ..." (after skipping trivia when
    /// `skip` is set).
    fn found_at(&self, pos: usize, skip: bool) -> String {
        let pos = if skip {
            Self::skip_trivia(self.src, pos).0
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

    fn ident(&self, tok: Tok) -> Ident {
        Ident {
            text: self.src[tok.span.start..tok.span.end].to_string(),
            span: tok.span,
        }
    }

    /// `file = section*`, with recovery from junk and malformed headers.
    fn file(&mut self) -> SourceFile {
        let mut sections = Vec::new();
        // Junk seen at top level since the last section, as one span.
        let mut junk: Option<Span> = None;
        // A name that may turn out to be a section header.
        let mut candidate: Option<Tok> = None;
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
                (Kind::LBrace, Some(name)) => {
                    self.report_junk(junk.take());
                    header = Some((self.ident(name), tok.span));
                }
                (Kind::LBrace, None) => {
                    let span = junk.take().map_or(tok.span, |j| j.to(tok.span));
                    let found = self.found_at(span.start, false);
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
                    if kind == Kind::Ident {
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
            let found = self.found_at(span.start, false);
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
        let mut end = open.end;
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
                Kind::Semi => {
                    stmt.push(tok);
                    self.flush(&stmt, tok.span.end, &mut statements);
                    end = tok.span.end;
                    stmt = Stmt::default();
                }
                Kind::RBrace if stmt.braces == 0 => {
                    self.flush(&stmt, stmt.end, &mut statements);
                    break (tok.span.end, None);
                }
                Kind::LBrace
                    if stmt.braces == 0
                        && stmt.parens == 0
                        && stmt.last.is_some_and(|t| t.kind == Kind::Ident) =>
                {
                    // `Name {` inside a body: this section lacks its `}`.
                    let Some(last) = stmt.last else {
                        break (end, None);
                    };
                    let new_name = self.ident(last);
                    if stmt.start.is_some_and(|s| s < last.span.start) {
                        self.flush(&stmt, stmt.prev_end, &mut statements);
                        end = stmt.prev_end;
                    }
                    self.report_unclosed(name.as_ref(), open, Some(&new_name));
                    break (end, Some((new_name, tok.span)));
                }
                _ => stmt.push(tok),
            }
        };
        let section = name.map(|name| Section {
            span: name.span.to(Span::new(close_end, close_end)),
            name,
            statements: statements.statements,
            broken: statements.broken,
        });
        (section, next)
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

    /// Parses the statement `stmt` (ending at `end`) and adds it to `out`,
    /// or reports why it cannot be parsed and keeps it as broken.
    fn flush(&mut self, stmt: &Stmt, end: usize, out: &mut Body) {
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
            out.broken.push(self.broken(start, end));
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
                            out.broken.push(self.broken(start, end));
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
                        out.broken.push(self.broken(start, end));
                        return;
                    }
                    self.report_pest_error(&err, start, end);
                    out.broken.push(self.broken(start, end));
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
                let text = &self.src[span.start..span.end];
                text.starts_with('"') && (text.len() == 1 || !text.ends_with('"'))
            })
    }

    /// The start of every token of `start..end`, with its end.
    fn tokens(&self, start: usize, end: usize) -> Vec<(Kind, Span)> {
        let mut out = Vec::new();
        let mut pos = start;
        loop {
            let (at, unterminated) = Self::skip_trivia(self.src, pos);
            if unterminated.is_some() || at >= end {
                return out;
            }
            let (kind, tok_end) = lex_at(self.src, at);
            let tok_end = tok_end.min(end);
            out.push((kind, Span::new(at, tok_end)));
            pos = tok_end;
        }
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
            .map(|(_, span)| span.end)
            .filter(|&e| e <= at)?;
        if !self.src[prev_end..at].contains('\n') {
            return None;
        }
        let text = format!("{};", &self.src[start..prev_end]);
        let pairs = SceneGrammar::parse(Rule::statement_only, &text).ok()?;
        let mut statement = self.build_statement(pairs, start)?;
        // The `;` is not in the source: the statement ends at its last token.
        statement.span.end = prev_end;
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
    fn broken(&self, start: usize, end: usize) -> BrokenStatement {
        let tokens = self.tokens(start, end);
        let text = |span: Span| &self.src[span.start..span.end];
        let (name, labelled) = match tokens.as_slice() {
            [(Kind::Ident, name), (Kind::Other, sep), ..] if matches!(text(*sep), ":" | "=") => (
                Some(self.ident(Tok {
                    kind: Kind::Ident,
                    span: *name,
                })),
                text(*sep) == ":",
            ),
            _ => (None, false),
        };
        let references = tokens
            .iter()
            .filter(|(kind, _)| *kind == Kind::Other)
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

    fn report_pest_error(&mut self, err: &pest::error::Error<Rule>, start: usize, end: usize) {
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
        let word = &self.src[span.start..span.end];
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
        let letter = self.src[at.min(end)..end]
            .chars()
            .next()
            .is_some_and(|c| !c.is_ascii() && c.is_alphanumeric());
        if letter {
            diag = diag.with_help("names may only use ASCII letters, digits and `_`");
        }
        self.diagnostics.push(diag);
    }

    fn statement(&mut self, pair: Pair<'_, Rule>, off: usize) -> Option<Statement> {
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
            clauses,
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
                        Rule::ident => key = Some(pair_ident(p, off)),
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
                    target,
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
                Some(Value::Tuple { items, span })
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
        text: pair.as_str().to_string(),
        span: offset(pair.as_span(), off),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    const APPENDIX: &str = include_str!("../../../scenes/thesis-appendix-a.hsc");

    const EXTENSIONS: &str = "\
Globals { from = (0,0,0); to = %target; up = (0,0.1,0); }
Points  { eye = (0,0,0); target = (0,0,0.3); (0.1,0,0.3); }
BRDFs   { glass: ambient = (0.1,0.1,0.1), diffuse = (0.2,0.2,0.2), specular = (1,1,1), alpha = 0.1, trans = 0.8, shininess = 80, refraction = 1.15; }
Objects { Sphere %target, 0.05, #glass; Polygon (%1, %2, %3, %4), #1; Rod %1, %2, 0.01, #1; Cylinder %1, %2, 0.02, #1; Dodecahedron 0.045, #2; }
Transformations { hline (%1,%5); %1->Rotate(%2,-0.7); %2->Translate(%1); }
";

    /// Parses `src` and asserts that there are no diagnostics.
    fn clean(src: &str) -> SourceFile {
        let parsed = parse(src);
        assert!(
            parsed.diagnostics.is_empty(),
            "unexpected diagnostics for {src:?}: {:#?}",
            parsed.diagnostics
        );
        parsed.file
    }

    /// The only statement of the only section.
    fn only_statement(src: &str) -> Statement {
        let mut file = clean(src);
        assert_eq!(file.sections.len(), 1);
        let mut section = file.sections.remove(0);
        assert_eq!(section.statements.len(), 1, "{src}");
        section.statements.remove(0)
    }

    fn text(src: &str, span: Span) -> &str {
        &src[span.start..span.end]
    }

    fn number(v: &Value) -> f64 {
        match v {
            Value::Number { value, .. } => *value,
            other => panic!("not a number: {other:?}"),
        }
    }

    fn reference(v: &Value) -> (RefSigil, RefTarget) {
        match v {
            Value::Reference(r) => (r.sigil, r.target.clone()),
            other => panic!("not a reference: {other:?}"),
        }
    }

    fn tuple(v: &Value) -> &[Value] {
        match v {
            Value::Tuple { items, .. } => items,
            other => panic!("not a tuple: {other:?}"),
        }
    }

    fn numbers(v: &Value) -> Vec<f64> {
        tuple(v).iter().map(number).collect()
    }

    fn codes(parsed: &Parsed) -> Vec<Code> {
        parsed.diagnostics.iter().map(|d| d.code).collect()
    }

    fn section<'f>(file: &'f SourceFile, name: &str) -> &'f Section {
        file.sections
            .iter()
            .find(|s| s.name.text == name)
            .unwrap_or_else(|| panic!("no section {name}"))
    }

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
            Clause::Apply { target: Some(Reference { target: RefTarget::Name(n), .. }), arg: None, .. } if n == "p"
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

    #[test]
    fn bare_identifiers_are_not_values_outside_tuples() {
        let p = parse("S { a = b; }");
        assert_eq!(codes(&p), [Code::Syntax]);
        assert_eq!(p.diagnostics[0].message, "expected a value, found `b`");
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
        let idx = crate::diagnostic::LineIndex::new(src);
        let d = &p.diagnostics;
        assert_eq!(d[0].message, "expected `,` or `;`, found `#1`");
        assert_eq!(idx.line_col(d[0].span.start), (3, 19));
        assert_eq!(text(src, d[0].span), "#1");
        assert_eq!(d[1].message, "expected `)` or `,`, found `;`");
        assert_eq!(idx.line_col(d[1].span.start), (5, 23));
        assert_eq!(d[2].message, "expected a value, found `=`");
        assert_eq!(idx.line_col(d[2].span.start), (7, 14));
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
        assert_eq!(p.diagnostics[1].message, "expected a value, found `;`");
        assert_eq!(p.file.sections.len(), 1);
        assert_eq!(p.file.sections[0].statements.len(), 1);
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
    fn braces_inside_a_statement_do_not_end_the_section() {
        let src = "S { a = {1}; b = 2; }";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax]);
        assert_eq!(text(src, p.diagnostics[0].span), "{");
        assert_eq!(p.file.sections[0].statements.len(), 1);
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
            p.diagnostics[0].span.start,
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
        assert_eq!(parse(&many).diagnostics.len(), 20_000);
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

    #[test]
    fn diagnostics_are_sorted_and_line_columns_count_chars() {
        let src = "// ünïcödé comment €€€\nPoints { (0,0,0); /* é€ */ `x`; }\nbad";
        let p = parse(src);
        assert_eq!(codes(&p), [Code::Syntax, Code::Syntax]);
        assert!(
            p.diagnostics
                .windows(2)
                .all(|w| w[0].span.start <= w[1].span.start)
        );
        let idx = crate::diagnostic::LineIndex::new(src);
        assert_eq!(idx.line_col(p.diagnostics[0].span.start), (2, 28));
        assert_eq!(idx.line_col(p.diagnostics[1].span.start), (3, 1));
    }

    mod props {
        use super::*;
        use proptest::prelude::*;

        fn check(src: &str) {
            let p = parse(src);
            for d in &p.diagnostics {
                assert!(
                    d.span.start <= d.span.end && d.span.end <= src.len(),
                    "{d:?}"
                );
                assert!(src.is_char_boundary(d.span.start), "{d:?}");
                assert!(src.is_char_boundary(d.span.end), "{d:?}");
            }
            for s in &p.file.sections {
                assert!(s.span.end <= src.len());
                assert_eq!(&src[s.name.span.start..s.name.span.end], s.name.text);
                for st in &s.statements {
                    // A statement that lacked its `;` at the end of a line
                    // ends at its last token.
                    let text = &src[st.span.start..st.span.end];
                    let after = src[st.span.end..].trim_start_matches([' ', '\t', '\r']);
                    assert!(
                        text.ends_with(';') || after.starts_with(['\n', '/']),
                        "{text:?}"
                    );
                }
                for b in &s.broken {
                    assert!(b.span.start <= b.span.end && b.span.end <= src.len());
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
                prop_assert_eq!(st.label.map(|l| l.text), label);
                let Clause::Value(v) = &st.clauses[0] else { panic!() };
                prop_assert_eq!(numbers(v), xs);
            }
        }
    }
}
