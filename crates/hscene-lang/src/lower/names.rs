//! Declarations: one table per kind of thing a scene declares (points,
//! materials, h-lines, h-planes, named objects and lights), each holding
//! its entries in declaration order (so `%3` is the third), the names that
//! refer to them, where each was declared and whether anything used it.

use std::collections::HashMap;
use std::ops::{Index, IndexMut};

use crate::diagnostic::{Code, Diagnostic, Span};
use crate::syntax::{Ident, RefTarget};

use super::Lowerer;
use super::text::quote;

/// The name `@camera` refers to; objects and lights may not take it.
pub(super) const CAMERA: &str = "camera";

/// One declaration.
pub(super) struct Entry<T> {
    pub(super) value: T,
    /// The declaring statement (for a named object or light: its name).
    pub(super) span: Span,
    /// Whether a reference resolved to it (or a failed statement probably
    /// meant it), for the lints on unused declarations.
    pub(super) used: bool,
}

/// The declarations of one kind, numbered from 1 in declaration order.
pub(super) struct Table<T> {
    entries: Vec<Entry<T>>,
    /// Each name bound to the entry that declared it first.
    names: HashMap<String, usize>,
}

impl<T> Default for Table<T> {
    fn default() -> Self {
        Table {
            entries: Vec::new(),
            names: HashMap::new(),
        }
    }
}

impl<T> Table<T> {
    pub(super) fn len(&self) -> usize {
        self.entries.len()
    }

    /// Room for `additional` more entries, reserved exactly: a section's
    /// statement count is known before it is lowered, and growth by
    /// doubling left up to half of a large table unused.
    pub(super) fn reserve(&mut self, additional: usize) {
        self.entries.reserve_exact(additional);
    }

    /// Adds an entry; returns its index.
    pub(super) fn push(&mut self, value: T, span: Span, used: bool) -> usize {
        self.entries.push(Entry { value, span, used });
        self.entries.len() - 1
    }

    /// Binds `name` to entry `index` unless it is bound already (the first
    /// declaration keeps it); returns whether it was free.
    pub(super) fn bind(&mut self, name: &str, index: usize) -> bool {
        if self.names.contains_key(name) {
            return false;
        }
        self.names.insert(name.to_string(), index);
        true
    }

    /// [`Table::bind`], with the error for a name already declared.
    pub(super) fn declare(&mut self, name: &Ident, index: usize) -> Result<(), Diagnostic> {
        if self.bind(&name.text, index) {
            return Ok(());
        }
        Err(Diagnostic::new(
            Code::DuplicateName,
            name.span,
            format!("{} is already declared", quote(&name.text)),
        )
        .with_help("give each point, material, line and plane a distinct name"))
    }

    /// Adds the entry a statement declares (unused so far), bound to `name`
    /// if it has one; the error if that name is taken (the entry is added
    /// all the same, so that the numbers after it stay right).
    pub(super) fn push_declared(
        &mut self,
        value: T,
        span: Span,
        name: Option<&Ident>,
    ) -> Result<(), Diagnostic> {
        let index = self.push(value, span, false);
        match name {
            Some(name) => self.declare(name, index),
            None => Ok(()),
        }
    }

    /// The entry a reference names (`%3`, `%apex`), if any.
    pub(super) fn find(&self, target: &RefTarget) -> Option<usize> {
        match target {
            RefTarget::Index(n) => usize::try_from(*n)
                .ok()
                .filter(|&n| n >= 1 && n <= self.entries.len())
                .map(|n| n - 1),
            RefTarget::Name(name) => self.by_name(name),
        }
    }

    /// The entry bound to `name`, if any.
    pub(super) fn by_name(&self, name: &str) -> Option<usize> {
        self.names.get(name).copied()
    }

    /// Every bound name (in no particular order), for suggestions.
    pub(super) fn names(&self) -> impl ExactSizeIterator<Item = &str> {
        self.names.keys().map(String::as_str)
    }

    /// The number of bound names.
    pub(super) fn name_count(&self) -> usize {
        self.names.len()
    }

    pub(super) fn get(&self, index: usize) -> Option<&T> {
        self.entries.get(index).map(|e| &e.value)
    }

    pub(super) fn mark_used(&mut self, index: usize) {
        if let Some(e) = self.entries.get_mut(index) {
            e.used = true;
        }
    }

    pub(super) fn entries(&self) -> &[Entry<T>] {
        &self.entries
    }

    pub(super) fn into_values(self) -> impl Iterator<Item = T> {
        self.entries.into_iter().map(|e| e.value)
    }
}

impl<T> Index<usize> for Table<T> {
    type Output = T;

    fn index(&self, index: usize) -> &T {
        &self.entries[index].value
    }
}

impl<T> IndexMut<usize> for Table<T> {
    fn index_mut(&mut self, index: usize) -> &mut T {
        &mut self.entries[index].value
    }
}

/// What an `@name` transformation target names.
#[derive(Clone, Debug)]
pub(super) enum TargetSlot {
    /// The IR objects one object statement produced (none if it failed).
    Objects(Vec<usize>),
    /// A light (`None` if it failed).
    Light(Option<usize>),
}

impl Lowerer<'_> {
    /// Declares the name of an object or light (the `@name` namespace).
    pub(super) fn declare_target(&mut self, name: &Ident, slot: TargetSlot) {
        if name.text == CAMERA {
            self.report(
                Diagnostic::new(
                    Code::ReservedName,
                    name.span,
                    "`camera` is reserved: `@camera` is the camera",
                )
                .with_help("give this object or light another name"),
            );
        } else if let Some(first) = self.targets.by_name(&name.text) {
            // Lights are lowered before objects: blame whichever declaration
            // comes later in the file.
            let first = self.targets.entries()[first].span;
            let later = if first.start() > name.span.start() {
                first
            } else {
                name.span
            };
            self.report(
                Diagnostic::new(
                    Code::DuplicateName,
                    later,
                    format!("{} is already declared", quote(&name.text)),
                )
                .with_help("objects and lights share one set of names (`@name`); give each a distinct name"),
            );
        } else {
            let index = self.targets.push(slot, name.span, false);
            self.targets.bind(&name.text, index);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ident(text: &str) -> Ident {
        Ident {
            text: text.into(),
            span: Span::default(),
        }
    }

    #[test]
    fn numbers_and_names() {
        let mut t: Table<char> = Table::default();
        let a = t.push('a', Span::default(), false);
        assert!(t.declare(&ident("first"), a).is_ok());
        let b = t.push('b', Span::default(), false);
        assert_eq!(
            t.declare(&ident("first"), b).map_err(|d| d.code),
            Err(Code::DuplicateName)
        );
        assert_eq!(t.find(&RefTarget::Index(2)), Some(1));
        assert_eq!(t.find(&RefTarget::Index(0)), None);
        assert_eq!(t.find(&RefTarget::Index(3)), None);
        assert_eq!(t.find(&RefTarget::Name("first".into())), Some(0));
        t.mark_used(1);
        assert!(!t.entries()[0].used && t.entries()[1].used);
        assert_eq!(t[1], 'b');
    }
}
