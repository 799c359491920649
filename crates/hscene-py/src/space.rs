//! `hscene.Space`: a manifold `H³/Γ` from the face pairings of a
//! Dirichlet domain (hgeom's `QuotientSpace::from_pairings`), given as
//! matrices or straight from a SnapPy manifold, to place a scene in
//! (`Scene.from_str(text, space=...)`).
//!
//! SnapPy's numbers go through the text form of a space file
//! (`hscene_lang::space_file::parse_data`), the path `space =
//! "file.json"` takes: a ManifoldHP's entries are decimal strings of 60
//! digits, and that parser rounds each correctly to the nearest f64;
//! `float()` of them would round twice.

use std::sync::Arc;

use hgeom::QuotientSpace;
use hgeom::glam::DMat4;
use hscene_lang::space_file::{self, VOLUME_TOLERANCE};
use numpy::IntoPyArray;
use numpy::ndarray::Array3;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::arrays;
use crate::diagnostics::SceneWarning;
use crate::geom::Point;

/// Most attempts at SnapPy's Dirichlet domain: its construction fails for
/// some triangulations, and another (randomized) one usually works.
const DIRICHLET_ATTEMPTS: usize = 6;

/// A closed or cusped hyperbolic manifold, as a Dirichlet domain about
/// the origin and its face pairings.
#[pyclass(module = "hscene", frozen)]
pub struct Space {
    pairings: Arc<[DMat4]>,
    space: QuotientSpace,
    /// The volume the caller gave (SnapPy's `M.volume()`), if any.
    given_volume: Option<f64>,
}

impl Space {
    /// The pairings, time last, for `Options::space`.
    pub fn pairings(&self) -> Arc<[DMat4]> {
        Arc::clone(&self.pairings)
    }

    /// Checks `pairings` as a gluing; a volume that disagrees with the
    /// domain's is warned about, as a space file's is (HSC1014's rule).
    fn build(py: Python<'_>, pairings: Vec<DMat4>, volume: Option<f64>) -> PyResult<Space> {
        let space = py
            .detach(|| QuotientSpace::from_pairings(&pairings))
            .map_err(|e| PyValueError::new_err(format!("the pairings glue no manifold: {e}")))?;
        if let (Some(given), Some(own)) = (volume, space.volume()) {
            let error = (own - given).abs() / given.abs().max(f64::MIN_POSITIVE);
            if !(error <= VOLUME_TOLERANCE) {
                let message = std::ffi::CString::new(format!(
                    "the volume given is {given}, but the domain's is {own} ({error:.1e} relative): \
                     the pairings are not those of that manifold, or not accurate enough"
                ))
                .unwrap_or_default();
                PyErr::warn(py, &py.get_type::<SceneWarning>(), &message, 1)?;
            }
        }
        Ok(Space {
            pairings: pairings.into(),
            space,
            given_volume: volume,
        })
    }
}

/// One SnapPy number as the text a space file holds: its own decimal
/// string when it has more digits than an f64 (ManifoldHP), else the
/// shortest string of its float (Manifold's numbers print fewer digits
/// than they hold).
fn snappy_entry(x: &Bound<'_, PyAny>) -> PyResult<String> {
    let text: String = x.str()?.extract()?;
    let text: String = text.chars().filter(|c| *c != ' ').collect();
    let digits = text.chars().filter(char::is_ascii_digit).count();
    let decimal = !text.is_empty()
        && text
            .chars()
            .all(|c| c.is_ascii_digit() || "+-.eE".contains(c));
    if decimal && digits > 17 {
        return Ok(text);
    }
    let value: f64 = x
        .call_method0("__float__")
        .and_then(|f| f.extract())
        .map_err(|_| PyValueError::new_err(format!("a pairing entry is not a number: {text}")))?;
    if !value.is_finite() {
        return Err(PyValueError::new_err(format!(
            "a pairing entry is not finite: {text}"
        )));
    }
    // Rust's shortest round-trip form: read back, the same f64.
    Ok(format!("{value:e}"))
}

#[pymethods]
impl Space {
    /// The space whose Dirichlet domain has these face pairings: a
    /// sequence (or F × 4 × 4 array) of Lorentz matrices by rows, time
    /// coordinate `time` ("first": SnapPy's order, or "last": hgeom's).
    #[staticmethod]
    #[pyo3(signature = (matrices, *, time="first", volume=None))]
    fn from_pairings(
        py: Python<'_>,
        matrices: &Bound<'_, PyAny>,
        time: &str,
        volume: Option<f64>,
    ) -> PyResult<Space> {
        let time_first = arrays::time_first(time)?;
        let (shape, data) = arrays::floats(matrices, "the pairings")?;
        if shape.len() != 3 || shape[1] != 4 || shape[2] != 4 {
            return Err(PyValueError::new_err(format!(
                "the pairings must be F x 4 x 4 matrices, not an array of shape {shape:?}"
            )));
        }
        let pairings = data
            .chunks_exact(16)
            .enumerate()
            .map(|(k, m)| arrays::mat4_from_rows(m, &format!("pairing {}", k + 1), time_first))
            .collect::<PyResult<Vec<_>>>()?;
        Space::build(py, pairings, volume)
    }

    /// The space of a SnapPy manifold (`snappy.Manifold`, `ManifoldHP`, or
    /// anything with `dirichlet_domain()` and `volume()`): its Dirichlet
    /// domain's pairings at the precision the manifold computes them.
    #[staticmethod]
    fn from_snappy(py: Python<'_>, manifold: &Bound<'_, PyAny>) -> PyResult<Space> {
        let mut m = manifold.clone();
        let mut domain = None;
        let mut last_error = None;
        for attempt in 0..DIRICHLET_ATTEMPTS {
            if attempt > 0 {
                // Another triangulation of the same manifold, leaving the
                // caller's untouched.
                m = manifold.call_method0("copy")?;
                m.call_method0("randomize")?;
            }
            match m.call_method0("dirichlet_domain") {
                Ok(d) => {
                    domain = Some(d);
                    break;
                }
                Err(e) => last_error = Some(e),
            }
        }
        let Some(domain) = domain else {
            return Err(last_error
                .unwrap_or_else(|| PyValueError::new_err("SnapPy built no Dirichlet domain")));
        };
        let mut text = String::from("{\"pairings\": [");
        for (k, g) in domain
            .call_method0("pairing_matrices")?
            .try_iter()?
            .enumerate()
        {
            if k > 0 {
                text.push(',');
            }
            text.push('[');
            for (r, row) in g?.try_iter()?.enumerate() {
                if r > 0 {
                    text.push(',');
                }
                text.push('[');
                for (c, x) in row?.try_iter()?.enumerate() {
                    if c > 0 {
                        text.push(',');
                    }
                    // Only digits, signs, points and exponents: safe
                    // between quotes.
                    text.push_str(&format!("\"{}\"", snappy_entry(&x?)?));
                }
                text.push(']');
            }
            text.push(']');
        }
        text.push(']');
        if let Ok(v) = m.call_method0("volume") {
            text.push_str(&format!(", \"volume\": \"{}\"", snappy_entry(&v)?));
        }
        text.push('}');
        let data = space_file::parse_data(&text)
            .map_err(|e| PyValueError::new_err(format!("SnapPy's pairings: {e}")))?;
        Space::build(py, data.pairings, data.volume)
    }

    /// Faces of the domain (pairings).
    #[getter]
    fn faces(&self) -> usize {
        self.pairings.len()
    }

    /// The domain's volume (None if not computed).
    #[getter]
    fn volume(&self) -> Option<f64> {
        self.space.volume()
    }

    /// The volume the manifold gave, where it gave one (SnapPy's).
    #[getter]
    fn given_volume(&self) -> Option<f64> {
        self.given_volume
    }

    /// The pairings as an F × 4 × 4 array, time coordinate `time`.
    #[pyo3(signature = (time="last"))]
    fn pairing_matrices<'py>(
        &self,
        py: Python<'py>,
        time: &str,
    ) -> PyResult<Bound<'py, numpy::PyArray3<f64>>> {
        let time_first = arrays::time_first(time)?;
        let data: Vec<f64> = self
            .pairings
            .iter()
            .flat_map(|m| arrays::mat4_rows(m, time_first).into_iter().flatten())
            .collect();
        Array3::from_shape_vec((self.pairings.len(), 4, 4), data)
            .map(|a| a.into_pyarray(py))
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// Whether `point` lies in the domain.
    fn contains(&self, point: &Point) -> bool {
        self.space.contains(point.inner().to_hyperboloid(), 1e-12)
    }

    /// `point` moved into the domain by the pairings (the point of the
    /// manifold it is).
    fn fold(&self, point: &Point) -> PyResult<Point> {
        let p = point.inner();
        let g = self
            .space
            .fold(&p)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(Point::from_inner(g.apply(&p)))
    }

    fn __repr__(&self) -> String {
        match self.space.volume() {
            Some(v) => format!(
                "<hscene.Space {} faces, volume {v:.6}>",
                self.pairings.len()
            ),
            None => format!("<hscene.Space {} faces>", self.pairings.len()),
        }
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Space>()
}
