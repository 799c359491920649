//! The diagnostics of one compile, kept up to a cap and counted past it.
//!
//! A file of the allowed size can hold millions of errors (16 MiB of `;`
//! is sixteen million "expected a statement"); kept whole they cost
//! hundreds of bytes each, gigabytes in all, for a report that shows the
//! first hundred. The first [`MAX_KEPT_DIAGNOSTICS`] are kept; the rest
//! are counted by severity, so reports still say how many there were and
//! whether any was an error.

use crate::diagnostic::{Diagnostic, Severity};

/// Diagnostics kept per compile (parse and lowering together).
pub const MAX_KEPT_DIAGNOSTICS: usize = 10_000;

/// How many diagnostics were counted but not kept, by severity.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Omitted {
    /// Errors not kept.
    pub errors: usize,
    /// Warnings not kept.
    pub warnings: usize,
}

impl Omitted {
    /// All of them.
    pub fn total(self) -> usize {
        self.errors + self.warnings
    }
}

/// A list of diagnostics that keeps the first [`MAX_KEPT_DIAGNOSTICS`].
#[derive(Clone, Debug, Default)]
pub(crate) struct DiagnosticList {
    kept: Vec<Diagnostic>,
    omitted: Omitted,
}

impl DiagnosticList {
    pub(crate) fn from_parts(kept: Vec<Diagnostic>, omitted: Omitted) -> Self {
        DiagnosticList { kept, omitted }
    }

    pub(crate) fn push(&mut self, d: Diagnostic) {
        if self.kept.len() < MAX_KEPT_DIAGNOSTICS {
            self.kept.push(d);
        } else if d.severity == Severity::Error {
            self.omitted.errors += 1;
        } else {
            self.omitted.warnings += 1;
        }
    }

    pub(crate) fn extend(&mut self, ds: impl IntoIterator<Item = Diagnostic>) {
        for d in ds {
            self.push(d);
        }
    }

    /// Whether the cap is reached: what is found from now on is counted.
    pub(crate) fn is_full(&self) -> bool {
        self.kept.len() >= MAX_KEPT_DIAGNOSTICS
    }

    /// The kept diagnostics, in the order found.
    pub(crate) fn iter(&self) -> std::slice::Iter<'_, Diagnostic> {
        self.kept.iter()
    }

    /// Whether any diagnostic, kept or not, is an error.
    pub(crate) fn has_errors(&self) -> bool {
        self.omitted.errors > 0 || self.kept.iter().any(Diagnostic::is_error)
    }

    pub(crate) fn into_parts(self) -> (Vec<Diagnostic>, Omitted) {
        (self.kept, self.omitted)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::{Code, Span};

    #[test]
    fn past_the_cap_diagnostics_are_counted_not_kept() {
        let mut list = DiagnosticList::default();
        for i in 0..MAX_KEPT_DIAGNOSTICS + 5 {
            list.push(Diagnostic::new(
                Code::UnusedPoint,
                Span::new(i, i + 1),
                "unused",
            ));
        }
        assert!(!list.has_errors());
        list.push(Diagnostic::new(Code::Syntax, Span::new(0, 1), "bad"));
        assert!(list.has_errors(), "an error past the cap still counts");
        let (kept, omitted) = list.into_parts();
        assert_eq!(kept.len(), MAX_KEPT_DIAGNOSTICS);
        assert_eq!(
            omitted,
            Omitted {
                errors: 1,
                warnings: 5
            }
        );
    }
}
