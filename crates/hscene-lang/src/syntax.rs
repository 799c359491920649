//! The concrete syntax tree of a scene file.
//!
//! The tree is deliberately generic: every section is a list of statements,
//! every statement a comma-separated list of clauses. What a clause means
//! depends on the section and is decided by the semantic layer.
//!
//! ```text
//! file       = section*
//! section    = Ident "{" statement* "}"
//! statement  = (Ident ":")? clause ("," clause)* ";"
//! clause     = Ident "=" value                     -- Clause::Assign
//!            | (reference "->")? Ident value?      -- Clause::Apply
//!            | value                               -- Clause::Value
//! value      = number | reference | tuple | string | symbol
//!                                                  -- (inside tuples also Ident)
//! string     = '"' (any character but '"' and line breaks)* '"'
//! tuple      = "(" item ("," item)* ")"
//! symbol     = "{" number ("," number)+ "}"        -- a Schläfli symbol
//! reference  = ("%" | "#" | "@") (digits | Ident)  -- no whitespace inside
//! ```
//!
//! All spans are byte offsets into the source given to [`crate::parse`].

use crate::diagnostic::Span;
pub use smol_str::SmolStr;

/// A whole scene file: its sections in source order.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct SourceFile {
    /// Sections in source order (duplicates and unknown names included).
    pub sections: Vec<Section>,
    /// Some text was skipped whole (an unterminated comment, a section
    /// without a name, text outside any section), so the tree may lack
    /// references the author wrote.
    pub incomplete: bool,
}

/// `Name { statement* }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    /// The section name, e.g. `Points`.
    pub name: Ident,
    /// The statements that parsed, in source order.
    pub statements: Vec<Statement>,
    /// The statements that did not parse (each already reported), in source
    /// order. The semantic layer uses them to keep the numbering of points
    /// and materials aligned and to know what they referred to.
    pub broken: Vec<BrokenStatement>,
    /// From the name to the closing `}` (or to the last statement when the
    /// section is not closed).
    pub span: Span,
}

/// An identifier: ASCII letter or `_`, then letters, digits and `_`.
#[derive(Clone, Debug, PartialEq)]
pub struct Ident {
    /// The identifier text, stored inline up to 23 bytes: a scene of many
    /// statements has several names per statement, and a heap block each
    /// was a tenth of its syntax tree.
    pub text: SmolStr,
    /// Where it is.
    pub span: Span,
}

impl Ident {
    /// The identifier text.
    pub fn as_str(&self) -> &str {
        &self.text
    }
}

/// `(label:)? clause, clause, ... ;`
#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    /// The optional `name:` prefix (e.g. a material's name).
    pub label: Option<Ident>,
    /// At least one clause (a boxed slice: no spare capacity, which in a
    /// scene of many statements was a third of the syntax tree).
    pub clauses: Box<[Clause]>,
    /// The whole statement, label and `;` included.
    pub span: Span,
}

/// What is known about a statement that failed to parse.
#[derive(Clone, Debug, PartialEq)]
pub struct BrokenStatement {
    /// A leading `name:` or `name =`, if the statement starts with one.
    pub name: Option<Ident>,
    /// Whether `name` was followed by `:` (a label) rather than `=`.
    pub labelled: bool,
    /// The well-formed `%` and `#` references in its text.
    pub references: Vec<Reference>,
    /// The whole statement as scanned.
    pub span: Span,
}

/// One comma-separated part of a statement.
#[derive(Clone, Debug, PartialEq)]
pub enum Clause {
    /// `key = value`, e.g. `resolution = (1200,1200)`, `to = %target`.
    Assign {
        /// The key.
        key: Ident,
        /// The value.
        value: Value,
        /// From the key to the end of the value.
        span: Span,
    },
    /// `(target ->)? Name arg?`, e.g. `Sphere %3`, `Dodecahedron 0.045`,
    /// `hline (%1,%2)`, `%1->Rotate(%2,-0.7)`, a bare `Cube`.
    Apply {
        /// The reference before `->`, if any.
        target: Option<Box<Reference>>,
        /// The keyword.
        name: Ident,
        /// The single argument (a tuple when there are several), if any.
        arg: Option<Value>,
        /// From the target (or name) to the end of the argument (or name).
        span: Span,
    },
    /// A bare value: `(0,0,0.16)`, `%1`, `0.05`, `#1`.
    Value(Value),
}

impl Clause {
    /// Where the clause is.
    pub fn span(&self) -> Span {
        match self {
            Clause::Assign { span, .. } | Clause::Apply { span, .. } => *span,
            Clause::Value(v) => v.span(),
        }
    }
}

/// A value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A number literal. Always finite unless an `InvalidNumber` diagnostic
    /// was reported for its span (then it is `±inf`).
    Number {
        /// The value.
        value: f64,
        /// The literal.
        span: Span,
    },
    /// `%N`, `%name`, `#N`, `#name`.
    Reference(Reference),
    /// `(a, b, ...)`, at least one item.
    Tuple {
        /// The items (a boxed slice, without spare capacity).
        items: Box<[Value]>,
        /// From `(` to `)`.
        span: Span,
    },
    /// A bare identifier; only occurs as a tuple item.
    Ident(Ident),
    /// `"text"`: a string literal (file names). No escapes, one line.
    Str {
        /// The text between the quotes.
        text: String,
        /// From the opening to the closing quote.
        span: Span,
    },
    /// `{4,3,5}`: a Schläfli symbol, at least two numbers in braces (each a
    /// [`Value::Number`]; the lowering checks they are whole).
    Symbol {
        /// The entries.
        entries: Box<[Value]>,
        /// From `{` to `}`.
        span: Span,
    },
}

impl Value {
    /// Where the value is.
    pub fn span(&self) -> Span {
        match self {
            Value::Number { span, .. }
            | Value::Tuple { span, .. }
            | Value::Str { span, .. }
            | Value::Symbol { span, .. } => *span,
            Value::Reference(r) => r.span,
            Value::Ident(i) => i.span,
        }
    }

    /// A short description for messages: "a number", "a point reference",
    /// "a material reference", "a tuple", "a name".
    pub fn describe(&self) -> &'static str {
        match self {
            Value::Number { .. } => "a number",
            Value::Reference(r) => match r.sigil {
                RefSigil::Percent => "a point reference",
                RefSigil::Hash => "a material reference",
                RefSigil::At => "an object reference",
            },
            Value::Tuple { .. } => "a tuple",
            Value::Ident(_) => "a name",
            Value::Str { .. } => "a string",
            Value::Symbol { .. } => "a Schläfli symbol",
        }
    }
}

/// The sigil of a reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefSigil {
    /// `%`: points (and, as `Rotate`/`Translate` arguments, h-lines).
    Percent,
    /// `#`: materials.
    Hash,
    /// `@`: named objects and lights, and `@camera` (transformation targets).
    At,
}

impl RefSigil {
    /// `'%'` or `'#'`.
    pub fn as_char(self) -> char {
        match self {
            RefSigil::Percent => '%',
            RefSigil::Hash => '#',
            RefSigil::At => '@',
        }
    }
}

/// What a reference names.
#[derive(Clone, Debug, PartialEq)]
pub enum RefTarget {
    /// `%3`: a 1-based index as written (`%0` is kept; the semantic layer
    /// rejects it). An index too large for `u64` is `u64::MAX`, with an
    /// `InvalidNumber` diagnostic at the reference.
    Index(u64),
    /// `%eye`: a name.
    Name(String),
}

/// `%1`, `%eye`, `#2`, `#glass`.
#[derive(Clone, Debug, PartialEq)]
pub struct Reference {
    /// `%` or `#`.
    pub sigil: RefSigil,
    /// Index or name.
    pub target: RefTarget,
    /// From the sigil to the end of the reference.
    pub span: Span,
}

impl std::fmt::Display for Reference {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.target {
            RefTarget::Index(i) => write!(f, "{}{i}", self.sigil.as_char()),
            RefTarget::Name(n) => write!(f, "{}{n}", self.sigil.as_char()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(v: f64, s: usize, e: usize) -> Value {
        Value::Number {
            value: v,
            span: Span::new(s, e),
        }
    }

    #[test]
    fn spans_and_descriptions() {
        let r = Reference {
            sigil: RefSigil::Hash,
            target: RefTarget::Name("glass".into()),
            span: Span::new(10, 16),
        };
        assert_eq!(r.to_string(), "#glass");
        let v = Value::Reference(r.clone());
        assert_eq!(v.span(), Span::new(10, 16));
        assert_eq!(v.describe(), "a material reference");
        let p = Value::Reference(Reference {
            sigil: RefSigil::Percent,
            target: RefTarget::Index(3),
            span: Span::new(0, 2),
        });
        assert_eq!(p.describe(), "a point reference");
        if let Value::Reference(r) = &p {
            assert_eq!(r.to_string(), "%3");
        }
        assert_eq!(num(1.0, 2, 3).describe(), "a number");
        let t = Value::Tuple {
            items: Box::new([num(1.0, 1, 2)]),
            span: Span::new(0, 3),
        };
        assert_eq!(t.describe(), "a tuple");
        assert_eq!(t.span(), Span::new(0, 3));
        let id = Ident {
            text: "x".into(),
            span: Span::new(7, 8),
        };
        assert_eq!(Value::Ident(id.clone()).describe(), "a name");
        assert_eq!(Value::Ident(id.clone()).span(), Span::new(7, 8));

        let c = Clause::Assign {
            key: id.clone(),
            value: num(2.0, 11, 12),
            span: Span::new(7, 12),
        };
        assert_eq!(c.span(), Span::new(7, 12));
        assert_eq!(Clause::Value(num(2.0, 11, 12)).span(), Span::new(11, 12));
        let a = Clause::Apply {
            target: None,
            name: id,
            arg: None,
            span: Span::new(7, 8),
        };
        assert_eq!(a.span(), Span::new(7, 8));
    }
}
