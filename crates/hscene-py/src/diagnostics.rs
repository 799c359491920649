//! `hscene.SceneError`, `hscene.SceneWarning` and `hscene.Diagnostic`: a
//! compile's diagnostics, worded as `hscene check` words them
//! (`hscene_lang::report`, without colour).

use hscene_lang::{Compiled, LineIndex, Severity};
use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyUserWarning};
use pyo3::prelude::*;
use pyo3::types::PyList;

create_exception!(
    hscene,
    SceneError,
    PyException,
    "A scene with errors: str() is the report `hscene check` prints; .diagnostics lists them."
);
create_exception!(
    hscene,
    SceneWarning,
    PyUserWarning,
    "A warning about a scene (a lint), given through warnings.warn."
);

/// One diagnostic: where (1-based line and column, in characters) and what.
#[pyclass(module = "hscene", frozen, get_all)]
#[derive(Clone)]
pub struct Diagnostic {
    /// Stable code, as `HSC0403`.
    code: String,
    /// `error` or `warning`.
    severity: String,
    /// First line of the span, from 1.
    line: usize,
    /// Its column, in characters from 1.
    column: usize,
    /// Last line of the span.
    end_line: usize,
    /// Column after its end.
    end_column: usize,
    /// What is wrong.
    message: String,
    /// How to fix it, where known.
    help: Option<String>,
}

#[pymethods]
impl Diagnostic {
    fn __repr__(&self) -> String {
        format!(
            "Diagnostic({}, {}, line {}, column {}: {:?})",
            self.code, self.severity, self.line, self.column, self.message
        )
    }

    fn __str__(&self) -> String {
        format!(
            "{}:{}: {}: {} [{}]",
            self.line, self.column, self.severity, self.message, self.code
        )
    }
}

/// The diagnostics of `compiled` as Python objects.
pub fn list(source: &str, compiled: &Compiled) -> Vec<Diagnostic> {
    let index = LineIndex::new(source);
    compiled
        .diagnostics
        .iter()
        .map(|d| {
            let (line, column) = index.line_col(d.span.start());
            let (end_line, end_column) = index.line_col(d.span.end());
            Diagnostic {
                code: d.code.as_str().to_string(),
                severity: d.severity.as_str().to_string(),
                line,
                column,
                end_line,
                end_column,
                message: d.message.clone(),
                help: d.help.clone(),
            }
        })
        .collect()
}

/// The `SceneError` of a compile with errors: the report of `hscene
/// check` as its message, the diagnostics as `.diagnostics`.
pub fn scene_error(py: Python<'_>, name: &str, source: &str, compiled: &Compiled) -> PyErr {
    let report = hscene_lang::report::human_report(
        name,
        source,
        &compiled.diagnostics,
        compiled.omitted,
        false,
    );
    let err = SceneError::new_err(report.trim_end().to_string());
    let diagnostics = list(source, compiled);
    if let Ok(items) = PyList::new(py, diagnostics) {
        // Setting an attribute on a fresh exception cannot fail in
        // practice; if it did, the message still says everything.
        let _ = err.value(py).setattr("diagnostics", items);
    }
    err
}

/// Each warning of a compile through Python's `warnings.warn`, as one
/// `name:line:col: warning: message [CODE]` line (a filter can then pick
/// by code); an error from warnings (a filter set to "error") is raised.
pub fn warn(py: Python<'_>, name: &str, source: &str, compiled: &Compiled) -> PyResult<()> {
    let index = LineIndex::new(source);
    let category = py.get_type::<SceneWarning>();
    for d in &compiled.diagnostics {
        if d.severity != Severity::Warning {
            continue;
        }
        let line = hscene_lang::report::short_line(name, &index, d);
        let message =
            std::ffi::CString::new(line.trim_end().replace('\0', " ")).unwrap_or_default();
        PyErr::warn(py, &category, &message, 1)?;
    }
    Ok(())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("SceneError", py.get_type::<SceneError>())?;
    m.add("SceneWarning", py.get_type::<SceneWarning>())?;
    m.add_class::<Diagnostic>()?;
    Ok(())
}
