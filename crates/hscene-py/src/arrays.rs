//! Checked conversions from Python values to hgeom's vectors and
//! matrices: wrong shapes, NaN and infinities are `ValueError`s.

use hgeom::glam::{DMat4, DVec3, DVec4};
use numpy::PyReadonlyArrayDyn;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// The numbers of `value` (a sequence or numpy array of numbers) as f64,
/// with the shape numpy sees; anything numpy cannot make a float array of
/// is a `ValueError`.
pub fn floats(value: &Bound<'_, PyAny>, what: &str) -> PyResult<(Vec<usize>, Vec<f64>)> {
    let py = value.py();
    let np = py.import("numpy")?;
    // C order, so the numbers are one slice: copied at memory speed (an
    // element-wise walk of a dynamic-rank view cost more than the
    // distances computed from it).
    let array = np
        .call_method1("ascontiguousarray", (value, "float64"))
        .map_err(|e| PyValueError::new_err(format!("{what}: not an array of numbers ({e})")))?;
    let array: PyReadonlyArrayDyn<'_, f64> = array.extract()?;
    let view = array.as_array();
    let shape = view.shape().to_vec();
    let data: Vec<f64> = match view.as_slice() {
        Some(slice) => slice.to_vec(),
        None => view.iter().copied().collect(),
    };
    Ok((shape, data))
}

/// Exactly `N` finite numbers.
pub fn finite<const N: usize>(value: &Bound<'_, PyAny>, what: &str) -> PyResult<[f64; N]> {
    let (shape, data) = floats(value, what)?;
    if shape != [N] {
        return Err(PyValueError::new_err(format!(
            "{what} must have {N} numbers, not an array of shape {shape:?}"
        )));
    }
    if let Some(x) = data.iter().find(|x| !x.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "{what} must be finite, not {x}"
        )));
    }
    let mut out = [0.0; N];
    out.copy_from_slice(&data);
    Ok(out)
}

/// Three finite numbers.
pub fn vec3(value: &Bound<'_, PyAny>, what: &str) -> PyResult<DVec3> {
    finite::<3>(value, what).map(DVec3::from_array)
}

/// Four finite numbers.
pub fn vec4(value: &Bound<'_, PyAny>, what: &str) -> PyResult<DVec4> {
    finite::<4>(value, what).map(DVec4::from_array)
}

/// A finite 4 × 4 matrix given by rows; `time_first`: its first row and
/// column are time (SnapPy's order), moved last (hgeom's).
pub fn mat4(value: &Bound<'_, PyAny>, what: &str, time_first: bool) -> PyResult<DMat4> {
    let (shape, data) = floats(value, what)?;
    if shape != [4, 4] {
        return Err(PyValueError::new_err(format!(
            "{what} must be a 4 x 4 matrix, not an array of shape {shape:?}"
        )));
    }
    mat4_from_rows(&data, what, time_first)
}

/// [`mat4`] from its 16 numbers by rows.
pub fn mat4_from_rows(data: &[f64], what: &str, time_first: bool) -> PyResult<DMat4> {
    if let Some(x) = data.iter().find(|x| !x.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "{what} must be finite, not {x}"
        )));
    }
    let at = |r: usize, c: usize| {
        if time_first {
            data[4 * ((r + 1) % 4) + (c + 1) % 4]
        } else {
            data[4 * r + c]
        }
    };
    Ok(DMat4::from_cols_array_2d(&std::array::from_fn(|c| {
        std::array::from_fn(|r| at(r, c))
    })))
}

/// `m` by rows, its time coordinate first when `time_first`.
pub fn mat4_rows(m: &DMat4, time_first: bool) -> [[f64; 4]; 4] {
    let cols = m.to_cols_array_2d();
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            if time_first {
                cols[(c + 3) % 4][(r + 3) % 4]
            } else {
                cols[c][r]
            }
        })
    })
}

/// Whether `time` names the first or the last coordinate.
pub fn time_first(time: &str) -> PyResult<bool> {
    match time {
        "first" => Ok(true),
        "last" => Ok(false),
        other => Err(PyValueError::new_err(format!(
            "time is \"first\" or \"last\", not {other:?}"
        ))),
    }
}
