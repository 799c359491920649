//! hscene in Python: the `hscene._hscene` extension module behind the
//! `hscene` package (`python/hscene`). Scenes compile through
//! `hscene_lang` and render through `hrender` exactly as `hscene render`
//! does; `hscene.geom` is hgeom's exact geometry. The Python API and how
//! to install it: `docs/python.md`.
//!
//! Python input is untrusted: every shape, NaN and point outside the ball
//! is refused with a `ValueError` before it reaches code that assumes
//! otherwise, and nothing here panics on input.

use pyo3::prelude::*;

mod arrays;
mod diagnostics;
mod geom;
mod picture;
mod render;
mod scene;
mod space;

/// The extension module: every class and function, re-exported by the
/// `hscene` and `hscene.geom` Python modules.
#[pymodule]
fn _hscene(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    diagnostics::register(m)?;
    scene::register(m)?;
    picture::register(m)?;
    geom::register(m)?;
    space::register(m)?;
    Ok(())
}
