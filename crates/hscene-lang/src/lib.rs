//! # hscene-lang — the hscene scene language
//!
//! Parses scene files (the thesis's format and its extensions), validates
//! them, applies their transformations and lowers them to a typed IR made of
//! `hgeom` values. Every problem comes back as a [`Diagnostic`] with a span,
//! a stable code, a message and usually a hint.
//!
//! Invariants: parsing never fails — it returns a tree and a list of
//! diagnostics; the IR carries no source text or spans.
//!
//! ```
//! let compiled = hscene_lang::compile("Points { (0,0,0.2); } BRDFs { diffuse = (1,0,0); } Objects { Sphere %1, 0.1, #1; }");
//! assert!(compiled.diagnostics.iter().all(|d| !d.is_error()));
//! let scene = compiled.scene.unwrap();
//! assert_eq!(scene.objects.len(), 1);
//! ```

pub mod diagnostic;
mod diagnostic_list;
mod file_cache;
pub mod format;
pub mod image_file;
mod indexed_source;
mod line_index;
mod lower;
pub mod mesh_file;
mod numbers;
mod options;
mod parser;
pub mod report;
pub mod source;
pub mod space_file;
pub mod symbols;
pub mod syntax;
pub mod tokens;
pub mod vocabulary;

/// The IR this language compiles to: the `hscene-ir` crate, re-exported so
/// that a user of the language needs no second dependency.
pub use hscene_ir as ir;
/// The view geometry of the IR (`hscene_ir::view`).
pub use hscene_ir::view;

pub use diagnostic::{Code, Diagnostic, Severity, Span};
pub use diagnostic_list::{MAX_KEPT_DIAGNOSTICS, Omitted};
pub use file_cache::FileCache;
pub use format::{FormatError, format};
pub use indexed_source::IndexedSource;
pub use line_index::LineIndex;
pub use lower::{MAX_FRAMES, MAX_PIXELS, MAX_SAMPLES};
pub use options::Options;
pub use parser::{Parsed, parse};

/// The result of compiling a scene: the IR if there were no errors, and every
/// diagnostic (errors and warnings) sorted by position.
#[derive(Clone, Debug)]
pub struct Compiled {
    /// The lowered scene; `None` if any error was reported.
    pub scene: Option<ir::Scene>,
    /// The diagnostics, in source order: the first
    /// [`MAX_KEPT_DIAGNOSTICS`] found.
    pub diagnostics: Vec<Diagnostic>,
    /// How many more were found and not kept.
    pub omitted: Omitted,
    /// The files the scene names and the compiler read (meshes, images,
    /// space files), each once, as resolved from the base directory: an
    /// output must be none of them.
    pub inputs: Vec<std::path::PathBuf>,
}

impl Compiled {
    /// True if any diagnostic, kept or not, is an error.
    pub fn has_errors(&self) -> bool {
        self.omitted.errors > 0 || self.diagnostics.iter().any(Diagnostic::is_error)
    }
}

/// Parse, validate and lower a scene: frame 0, mesh files relative to the
/// current directory.
pub fn compile(source: &str) -> Compiled {
    compile_with(source, &Options::default())
}

/// Parse, validate and lower a scene with explicit [`Options`].
pub fn compile_with(source: &str, options: &Options) -> Compiled {
    options.files.start_compile();
    let parsed = parse(source);
    let mut list = diagnostic_list::DiagnosticList::from_parts(parsed.diagnostics, parsed.omitted);
    let mut inputs = Vec::new();
    let scene = lower::lower(parsed.file, source, options, &mut list, &mut inputs);
    let (mut diagnostics, omitted) = list.into_parts();
    diagnostics.sort_by_key(|d| (d.span.start(), d.span.end()));
    let mut seen = std::collections::HashSet::new();
    inputs.retain(|p| seen.insert(p.clone()));
    Compiled {
        scene,
        diagnostics,
        omitted,
        inputs,
    }
}
