//! The `Objects` section. An object statement is
//!
//! ```text
//! (name:)? Keyword arg, arg, ..., #material (, option = value)* ;
//! ```
//!
//! Positional arguments come first and are checked against the keyword's
//! parameters (`keywords.rs`, `args.rs`); options follow (`options.rs`).
//! Every argument is checked even after one fails, so one statement
//! reports all of its problems. The checked statement is built
//! (`build.rs`, `figures.rs`, `mesh.rs`), then placed and counted.

mod args;
mod build;
mod built;
pub(super) mod figures;
mod honeycomb;
pub(super) mod keywords;
mod mesh;
pub(super) mod options;

use super::Lowerer;
use super::names::TargetSlot;
use super::suggest::meant;
use super::text::quote;
use crate::diagnostic::{Code, Diagnostic};
use crate::syntax::{Clause, Ident, Section, Statement, Value};
use args::Arg;
use figures::figure_estimate;
use keywords::{OBJECT_KEYWORDS, ObjectKeyword, keyword};

impl Lowerer<'_> {
    pub(super) fn objects_section(&mut self, section: &Section) {
        // Most statements give one object: reserved exactly, a large scene's
        // list is not left up to half empty by growth by doubling.
        self.objects.reserve_exact(section.statements.len());
        for st in &section.statements {
            let indices = self.object_statement(st);
            if let Some(label) = &st.label {
                self.declare_target(label, TargetSlot::Objects(indices));
            }
        }
    }

    /// Lowers one object statement; returns the indices of the IR objects it
    /// produced (none on error, two for `edges = t`, one per cell for
    /// tessellations, one for a honeycomb however many cells it has).
    fn object_statement(&mut self, st: &Statement) -> Vec<usize> {
        let Some((
            Clause::Apply {
                target: None,
                name,
                arg,
                ..
            },
            rest,
        )) = st.clauses.split_first()
        else {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    st.span,
                    "expected an object, e.g. `Sphere %1, 0.05, #1;`",
                )
                .with_help(format!("objects are {}", OBJECT_KEYWORDS.join(", "))),
            );
            return Vec::new();
        };
        let Some(row) = keyword(&name.text) else {
            self.unknown_object(name);
            return Vec::new();
        };
        // Positional values first, then `key = value` options.
        let mut positional: Vec<&Value> = arg.iter().collect();
        let mut options: Vec<(&Ident, &Value)> = Vec::new();
        for clause in rest {
            match clause {
                Clause::Value(v) if options.is_empty() => positional.push(v),
                Clause::Value(v) => {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            v.span(),
                            "positional arguments must come before the options",
                        )
                        .with_help("move the options (`key = value`) to the end of the statement"),
                    );
                    return Vec::new();
                }
                Clause::Assign { key, value, .. } => options.push((key, value)),
                Clause::Apply { .. } => {
                    self.error(
                        Code::WrongType,
                        clause.span(),
                        "object arguments must be values separated by `,`",
                    );
                    return Vec::new();
                }
            }
        }
        let signature = row.signature;
        let usage = signature.usage.replace("{name}", &name.text);
        let wanted = signature.params.len() + 1;
        if positional.len() != wanted {
            let span = if positional.len() > wanted {
                positional[wanted]
                    .span()
                    .to(positional[positional.len() - 1].span())
            } else {
                st.span
            };
            self.wrong_arity(
                span,
                format!("`{}` takes {}", name.text, signature.takes),
                usage,
            );
            return Vec::new();
        }
        let mut ok = true;
        let mut args = Vec::with_capacity(signature.params.len());
        for (param, value) in signature.params.iter().zip(&positional) {
            match self.object_arg(*param, value, &usage) {
                Some(a) => args.push(a),
                None => ok = false,
            }
        }
        let material = self.material_arg(positional[wanted - 1]);
        let opts = self.object_options(name, signature.options, &options);
        let (Some(material), Some(mut opts), true) = (material, opts, ok) else {
            return Vec::new();
        };
        if let ObjectKeyword::Figure(f) = row.builds {
            let depth = args.first().and_then(Arg::number);
            let estimate = figure_estimate(f, depth, opts.faces(), opts.edges());
            if !self.fits(estimate, st.span) {
                return Vec::new();
            }
        }
        let Some(built) = self.build(row.builds, name, &args, &positional, &mut opts, st.span)
        else {
            return Vec::new();
        };
        let placed = self.place(built, material, opts, st);
        let cost = placed
            .iter()
            .map(|&i| self.objects[i].0.shape.budget_cost())
            .sum();
        if !self.charge(cost, st.span) {
            return Vec::new();
        }
        placed
    }

    fn unknown_object(&mut self, name: &Ident) {
        let other = name.text.as_str();
        let mut d = Diagnostic::new(
            Code::UnknownObject,
            name.span,
            format!("unknown object {}", quote(other)),
        );
        d = match meant(other, &OBJECT_KEYWORDS) {
            Some(s) if s.eq_ignore_ascii_case(other) => d.with_help(format!(
                "object names are case-sensitive: did you mean `{s}`?"
            )),
            Some(s) => d.with_help(format!("did you mean `{s}`?")),
            None => d.with_help(format!("objects are {}", OBJECT_KEYWORDS.join(", "))),
        };
        self.report(d);
    }
}
