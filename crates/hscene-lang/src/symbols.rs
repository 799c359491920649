//! Where each point, material, line, plane, object and light is declared,
//! and every reference to it: the symbol table editors need (go to
//! definition, find references, rename, outline).
//!
//! It follows the numbering rules of the language (`docs/language.md`,
//! "References"): points, materials, h-lines and h-planes are numbered from 1
//! in declaration order, each kind separately; a statement of `Points` or
//! `BRDFs` that did not parse still takes its number. A `%` reference is a
//! point, except as the line of `Rotate`/`Translate` or the plane of
//! `Reflect`; `@` names objects and lights, which share one namespace.

use crate::diagnostic::Span;
use crate::syntax::{Clause, Ident, RefSigil, RefTarget, Reference, SourceFile, Statement, Value};

/// What kind of thing a declaration declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SymbolKind {
    /// A statement of `Points`.
    Point,
    /// A statement of `BRDFs`.
    Material,
    /// An `hline` in `Transformations`.
    Line,
    /// An `hplane` in `Transformations`.
    Plane,
    /// A named statement of `Objects`.
    Object,
    /// A named statement of `Lights`.
    Light,
}

impl SymbolKind {
    /// `"point"`, `"material"`, ...
    pub fn as_str(self) -> &'static str {
        match self {
            SymbolKind::Point => "point",
            SymbolKind::Material => "material",
            SymbolKind::Line => "h-line",
            SymbolKind::Plane => "h-plane",
            SymbolKind::Object => "object",
            SymbolKind::Light => "light",
        }
    }

    /// The sigil that refers to this kind.
    pub fn sigil(self) -> RefSigil {
        match self {
            SymbolKind::Point | SymbolKind::Line | SymbolKind::Plane => RefSigil::Percent,
            SymbolKind::Material => RefSigil::Hash,
            SymbolKind::Object | SymbolKind::Light => RefSigil::At,
        }
    }
}

/// One declaration.
#[derive(Clone, Debug, PartialEq)]
pub struct Definition {
    /// What it declares.
    pub kind: SymbolKind,
    /// Its 1-based number (points, materials, lines, planes); `None` for
    /// objects and lights, which are referred to by name only.
    pub number: Option<usize>,
    /// Its name, if it has one.
    pub name: Option<Ident>,
    /// The whole declaring statement.
    pub span: Span,
}

impl Definition {
    /// How a reference to it is written: `%eye`, or `%3` when unnamed.
    pub fn label(&self) -> String {
        let sigil = self.kind.sigil().as_char();
        match (&self.name, self.number) {
            (Some(n), _) => format!("{sigil}{}", n.text),
            (None, Some(k)) => format!("{sigil}{k}"),
            (None, None) => String::new(),
        }
    }
}

/// One reference in the source and what it refers to.
#[derive(Clone, Debug, PartialEq)]
pub struct Use {
    /// The reference as written.
    pub reference: Reference,
    /// The kinds it may name here (`@` names an object or a light).
    pub kinds: &'static [SymbolKind],
    /// The index into [`SymbolIndex::definitions`], if it resolves.
    pub definition: Option<usize>,
}

/// What is at a position of the source.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hit {
    /// The name of a declaration (index into `definitions`).
    Declaration(usize),
    /// A reference (index into `uses`).
    Use(usize),
}

/// Every declaration and reference of a scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SymbolIndex {
    /// Declarations in source order.
    pub definitions: Vec<Definition>,
    /// References in source order.
    pub uses: Vec<Use>,
}

const POINT: &[SymbolKind] = &[SymbolKind::Point];
const MATERIAL: &[SymbolKind] = &[SymbolKind::Material];
const LINE: &[SymbolKind] = &[SymbolKind::Line];
const PLANE: &[SymbolKind] = &[SymbolKind::Plane];
const NAMED: &[SymbolKind] = &[SymbolKind::Object, SymbolKind::Light];

impl SymbolIndex {
    /// Builds the index of a parsed file.
    pub fn new(file: &SourceFile) -> Self {
        let mut index = SymbolIndex::default();
        let mut counts = [0usize; 4];
        for section in &file.sections {
            let kind = match section.name.text.as_str() {
                "Points" => Some(SymbolKind::Point),
                "BRDFs" => Some(SymbolKind::Material),
                "Objects" => Some(SymbolKind::Object),
                "Lights" => Some(SymbolKind::Light),
                _ => None,
            };
            let is_transformations = section.name.text == "Transformations";
            // Good and broken statements in source order, so numbers match.
            let mut good = section.statements.iter().peekable();
            let mut broken = section.broken.iter().peekable();
            loop {
                let take_good = match (good.peek(), broken.peek()) {
                    (Some(g), Some(b)) => g.span.start() < b.span.start(),
                    (Some(_), None) => true,
                    (None, Some(_)) => false,
                    (None, None) => break,
                };
                if take_good {
                    let Some(s) = good.next() else { break };
                    let kind = if is_transformations {
                        declared_by_transformation(s)
                    } else {
                        kind
                    };
                    if let Some(kind) = kind {
                        index.declare(kind, declared_name(kind, s), s.span, &mut counts);
                    }
                    index.statement_uses(s);
                } else {
                    let Some(b) = broken.next() else { break };
                    if let Some(kind @ (SymbolKind::Point | SymbolKind::Material)) = kind {
                        let name = b
                            .name
                            .clone()
                            .filter(|_| b.labelled || kind == SymbolKind::Point);
                        index.declare(kind, name, b.span, &mut counts);
                    }
                    for r in &b.references {
                        let kinds = match r.sigil {
                            RefSigil::Percent => POINT,
                            RefSigil::Hash => MATERIAL,
                            RefSigil::At => NAMED,
                        };
                        index.add_use(r, kinds);
                    }
                }
            }
        }
        let resolved: Vec<Option<usize>> = index
            .uses
            .iter()
            .map(|u| index.resolve(&u.reference, u.kinds))
            .collect();
        for (u, d) in index.uses.iter_mut().zip(resolved) {
            u.definition = d;
        }
        index
    }

    fn declare(
        &mut self,
        kind: SymbolKind,
        name: Option<Ident>,
        span: Span,
        counts: &mut [usize; 4],
    ) {
        let number = match kind {
            SymbolKind::Point => Some(0),
            SymbolKind::Material => Some(1),
            SymbolKind::Line => Some(2),
            SymbolKind::Plane => Some(3),
            SymbolKind::Object | SymbolKind::Light => None,
        }
        .map(|slot| {
            counts[slot] += 1;
            counts[slot]
        });
        if number.is_none() && name.is_none() {
            return;
        }
        self.definitions.push(Definition {
            kind,
            number,
            name,
            span,
        });
    }

    fn add_use(&mut self, reference: &Reference, kinds: &'static [SymbolKind]) {
        self.uses.push(Use {
            reference: reference.clone(),
            kinds,
            definition: None,
        });
    }

    fn statement_uses(&mut self, s: &Statement) {
        for clause in &s.clauses {
            match clause {
                Clause::Assign { value, .. } | Clause::Value(value) => self.value_uses(value),
                Clause::Apply {
                    target, name, arg, ..
                } => {
                    if let Some(t) = target {
                        let kinds = if t.sigil == RefSigil::At {
                            NAMED
                        } else {
                            POINT
                        };
                        self.add_use(t, kinds);
                    }
                    let Some(arg) = arg else { continue };
                    // The first argument of a move is a line or a plane.
                    let first_kinds = match name.text.as_str() {
                        "Rotate" | "Translate" if target.is_some() => Some(LINE),
                        "Reflect" if target.is_some() => Some(PLANE),
                        _ => None,
                    };
                    match (first_kinds, arg) {
                        (Some(kinds), Value::Tuple { items, .. }) => {
                            for (i, item) in items.iter().enumerate() {
                                match item {
                                    Value::Reference(r)
                                        if i == 0 && r.sigil == RefSigil::Percent =>
                                    {
                                        self.add_use(r, kinds)
                                    }
                                    v => self.value_uses(v),
                                }
                            }
                        }
                        (Some(kinds), Value::Reference(r)) if r.sigil == RefSigil::Percent => {
                            self.add_use(r, kinds)
                        }
                        (_, v) => self.value_uses(v),
                    }
                }
            }
        }
    }

    fn value_uses(&mut self, value: &Value) {
        match value {
            Value::Reference(r) => {
                let kinds = match r.sigil {
                    RefSigil::Percent => POINT,
                    RefSigil::Hash => MATERIAL,
                    RefSigil::At => NAMED,
                };
                self.add_use(r, kinds);
            }
            Value::Tuple { items, .. } => {
                for v in items {
                    self.value_uses(v);
                }
            }
            Value::Number { .. } | Value::Ident(_) | Value::Str { .. } | Value::Symbol { .. } => {}
        }
    }

    /// The declaration a reference of one of `kinds` names, if any.
    pub fn resolve(&self, reference: &Reference, kinds: &[SymbolKind]) -> Option<usize> {
        self.definitions.iter().position(|d| {
            kinds.contains(&d.kind)
                && match &reference.target {
                    RefTarget::Index(k) => d.number.is_some_and(|n| n as u64 == *k),
                    RefTarget::Name(name) => d.name.as_ref().is_some_and(|i| i.text == name),
                }
        })
    }

    /// What is at byte `offset` (a declaration's name or a reference; the
    /// offset just after one counts, as a cursor at its end).
    pub fn at(&self, offset: usize) -> Option<Hit> {
        let covers = |s: Span| s.start() <= offset && offset <= s.end();
        if let Some(i) = self.uses.iter().position(|u| covers(u.reference.span)) {
            return Some(Hit::Use(i));
        }
        self.definitions
            .iter()
            .position(|d| d.name.as_ref().is_some_and(|n| covers(n.span)))
            .map(Hit::Declaration)
    }

    /// The declaration a hit is about.
    pub fn definition_of(&self, hit: Hit) -> Option<usize> {
        match hit {
            Hit::Declaration(d) => Some(d),
            Hit::Use(u) => self.uses[u].definition,
        }
    }

    /// The declaration named or referenced at `offset`.
    pub fn definition_at(&self, offset: usize) -> Option<usize> {
        self.at(offset).and_then(|h| self.definition_of(h))
    }

    /// The references to declaration `d`, in source order.
    pub fn uses_of(&self, d: usize) -> impl Iterator<Item = &Use> {
        self.uses.iter().filter(move |u| u.definition == Some(d))
    }
}

/// `hline` and `hplane` statements declare lines and planes.
fn declared_by_transformation(s: &Statement) -> Option<SymbolKind> {
    match s.clauses.first() {
        Some(Clause::Apply {
            target: None, name, ..
        }) => match name.text.as_str() {
            "hline" => Some(SymbolKind::Line),
            "hplane" => Some(SymbolKind::Plane),
            _ => None,
        },
        _ => None,
    }
}

/// The name a statement gives what it declares: its label, or for a point
/// also `name = (x, y, z)`.
fn declared_name(kind: SymbolKind, s: &Statement) -> Option<Ident> {
    if let Some(label) = &s.label {
        return Some(label.clone());
    }
    match (kind, &s.clauses[..]) {
        (SymbolKind::Point, [Clause::Assign { key, .. }, ..]) => Some(key.clone()),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SRC: &str = "Points { eye = (0,0,0.2); (0.1,0,0); c: (0,0.1,0); }\n\
        BRDFs { glass: diffuse = (1,1,1); diffuse = (1,0,0); }\n\
        Objects { ball: Sphere %2, 0.1, #glass; Cube 0.1, #2, at = %c; }\n\
        Transformations { axis: hline (%eye, %2); hplane (%1, %2, %3); %2->Rotate(%axis, 0.5); @ball->Reflect(%1); }";

    fn index() -> SymbolIndex {
        SymbolIndex::new(&crate::parse(SRC).file)
    }

    fn text(s: Span) -> &'static str {
        &SRC[s.start()..s.end()]
    }

    #[test]
    fn declarations_are_numbered_per_kind() {
        let ix = index();
        let labels: Vec<_> = ix.definitions.iter().map(|d| (d.kind, d.label())).collect();
        use SymbolKind::*;
        assert_eq!(
            labels,
            vec![
                (Point, "%eye".into()),
                (Point, "%2".into()),
                (Point, "%c".into()),
                (Material, "#glass".into()),
                (Material, "#2".into()),
                (Object, "@ball".into()),
                (Line, "%axis".into()),
                (Plane, "%1".into()),
            ]
        );
    }

    #[test]
    fn references_resolve_by_context() {
        let ix = index();
        let target = |written: &str, nth: usize| {
            let u = ix
                .uses
                .iter()
                .filter(|u| text(u.reference.span) == written)
                .nth(nth)
                .unwrap();
            ix.definitions[u.definition.unwrap()].label()
        };
        assert_eq!(target("%2", 0), "%2");
        assert_eq!(target("#glass", 0), "#glass");
        assert_eq!(target("%axis", 0), "%axis");
        // `Reflect(%1)`: plane 1, not point 1.
        let reflect = ix.uses.last().unwrap();
        assert_eq!(
            ix.definitions[reflect.definition.unwrap()].kind,
            SymbolKind::Plane
        );
        assert_eq!(target("@ball", 0), "@ball");
    }

    #[test]
    fn hits_and_uses() {
        let ix = index();
        let eye_decl = SRC.find("eye").unwrap();
        let hit = ix.at(eye_decl + 1).unwrap();
        let d = ix.definition_of(hit).unwrap();
        let uses: Vec<_> = ix.uses_of(d).map(|u| text(u.reference.span)).collect();
        assert_eq!(uses, vec!["%eye", "%1"]);
        assert_eq!(ix.at(SRC.find("Sphere").unwrap()), None);
    }

    #[test]
    fn broken_statements_keep_their_numbers() {
        let src = "Points { (0,0,0); (0,0 0); p: (0.1,0,0); } Objects { Sphere %p, 0.1, #1; }";
        let ix = SymbolIndex::new(&crate::parse(src).file);
        let p = ix.definitions.iter().find(|d| d.label() == "%p").unwrap();
        assert_eq!(p.number, Some(3));
    }
}
