//! `hscene.Picture`: a finished render (linear pixels, the layers asked
//! for, the counters) that shows itself in Jupyter and saves itself
//! through hrender's writer.

use std::path::PathBuf;

use hrender::{AovLayers, DisplayTransform, Image, PngLevel, RenderStats, SampleDepth};
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict};

use crate::render::render_error;

/// A rendered picture.
#[pyclass(module = "hscene", frozen)]
pub struct Picture {
    pub image: Image,
    pub layers: Option<AovLayers>,
    pub stats: RenderStats,
    pub auto_exposure: Option<f64>,
}

/// The linear pixels as a `height × width × 3` float32 array.
pub fn linear_array<'py>(py: Python<'py>, image: &Image) -> PyResult<Bound<'py, PyArray3<f32>>> {
    let (w, h) = (image.width() as usize, image.height() as usize);
    Array3::from_shape_vec((h, w, 3), image.to_rgb32f())
        .map(|a| a.into_pyarray(py))
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The picture as `hscene render` writes it to an 8-bit PNG (the default
/// tone curve, sRGB), `height × width × 3` uint8.
pub fn display_array<'py>(py: Python<'py>, image: &Image) -> PyResult<Bound<'py, PyArray3<u8>>> {
    let (w, h) = (image.width() as usize, image.height() as usize);
    let bytes = DisplayTransform::default().to_rgb8(image.pixels());
    Array3::from_shape_vec((h, w, 3), bytes)
        .map(|a| a.into_pyarray(py))
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// Each layer as an array: one channel `height × width`, more
/// `height × width × channels` (`normal`: x, y, z; `cell`: rank, class;
/// `word`: length, then the letters).
pub fn layers_dict<'py>(py: Python<'py>, layers: &AovLayers) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    let (w, h) = (layers.width as usize, layers.height as usize);
    for (name, aov) in hrender::Aov::ALL {
        let channels = aov.channels();
        let Some(first) = layers.channel(channels[0]) else {
            continue;
        };
        if channels.len() == 1 {
            let a = Array2::from_shape_vec((h, w), first.to_vec())
                .map_err(|e| PyValueError::new_err(e.to_string()))?;
            dict.set_item(name, a.into_pyarray(py))?;
            continue;
        }
        let n = channels.len();
        let mut data = vec![0.0f32; w * h * n];
        for (k, channel) in channels.iter().enumerate() {
            if let Some(values) = layers.channel(channel) {
                for (i, v) in values.iter().enumerate() {
                    data[i * n + k] = *v;
                }
            }
        }
        let a = Array3::from_shape_vec((h, w, n), data)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        dict.set_item(name, a.into_pyarray(py))?;
    }
    Ok(dict)
}

/// The sample depth named by `depth=` (8, 16, 32 or None: the format's own).
pub fn sample_depth(depth: Option<u32>, path: &std::path::Path) -> PyResult<SampleDepth> {
    match depth {
        None => hrender::ImageFormat::from_path(path)
            .map(|f| f.default_depth())
            .map_err(render_error),
        Some(8) => Ok(SampleDepth::Eight),
        Some(16) => Ok(SampleDepth::Sixteen),
        Some(32) => Ok(SampleDepth::Float32),
        Some(d) => Err(PyValueError::new_err(format!(
            "depth is 8, 16 or 32 bits, not {d}"
        ))),
    }
}

/// Writes `image` (with `layers` as OpenEXR channels, which only .exr
/// holds) to `path` atomically, as `hscene render` does.
pub fn write(
    py: Python<'_>,
    image: &Image,
    layers: Option<&AovLayers>,
    path: PathBuf,
    depth: Option<u32>,
    png_level: u8,
) -> PyResult<()> {
    let depth = sample_depth(depth, &path)?;
    let png = PngLevel::new(png_level)
        .ok_or_else(|| PyValueError::new_err(format!("png_level is 0 to 9, not {png_level}")))?;
    py.detach(|| match layers {
        Some(layers) => {
            if !matches!(
                hrender::ImageFormat::from_path(&path),
                Ok(hrender::ImageFormat::Exr)
            ) {
                return Err(hrender::RenderError::InvalidOption(
                    "pixel layers (aov) are written as channels of an OpenEXR file: give an .exr path".into(),
                ));
            }
            hrender::write_exr_with_layers(image, layers, &path)
        }
        None => hrender::write_image_with(image, &path, depth, DisplayTransform::default(), png),
    })
    .map_err(render_error)
}

/// The picture as PNG bytes, for Jupyter: written through hrender's
/// encoder to a temporary file (the one encoder `hscene render` uses).
pub fn png_bytes<'py>(py: Python<'py>, image: &Image) -> PyResult<Bound<'py, PyBytes>> {
    let dir =
        tempfile::tempdir().map_err(|e| pyo3::exceptions::PyOSError::new_err(e.to_string()))?;
    let path = dir.path().join("picture.png");
    write(py, image, None, path.clone(), Some(8), 1)?;
    let bytes =
        std::fs::read(&path).map_err(|e| pyo3::exceptions::PyOSError::new_err(e.to_string()))?;
    Ok(PyBytes::new(py, &bytes))
}

#[pymethods]
impl Picture {
    /// Linear radiance, `height × width × 3` float32.
    #[getter]
    fn linear<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<f32>>> {
        linear_array(py, &self.image)
    }

    /// The sRGB-encoded 8-bit picture, `height × width × 3` uint8.
    #[getter]
    fn display<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<u8>>> {
        display_array(py, &self.image)
    }

    /// The pixel layers asked for (`aov=`), by name; empty if none.
    #[getter]
    fn aov<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        match &self.layers {
            Some(layers) => layers_dict(py, layers),
            None => Ok(PyDict::new(py)),
        }
    }

    /// Width in pixels.
    #[getter]
    fn width(&self) -> u32 {
        self.image.width()
    }

    /// Height in pixels.
    #[getter]
    fn height(&self) -> u32 {
        self.image.height()
    }

    /// The render's counters: rays, samples, numeric_failures, cut_trees,
    /// noise (or None), auto_exposure (or None).
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("rays", self.stats.rays)?;
        d.set_item("samples", self.stats.samples)?;
        d.set_item("numeric_failures", self.stats.numeric_failures)?;
        d.set_item("cut_trees", self.stats.cut_trees)?;
        d.set_item("noise", self.stats.noise)?;
        d.set_item("auto_exposure", self.auto_exposure)?;
        Ok(d)
    }

    /// Writes the picture to `path` (.png, .tif, .tiff, .exr) as `hscene
    /// render` does, atomically; `depth` 8, 16 or 32 bits (default: the
    /// format's own).
    #[pyo3(signature = (path, depth=None, png_level=3))]
    fn save(
        &self,
        py: Python<'_>,
        path: PathBuf,
        depth: Option<u32>,
        png_level: u8,
    ) -> PyResult<()> {
        write(
            py,
            &self.image,
            self.layers.as_ref(),
            path,
            depth,
            png_level,
        )
    }

    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        png_bytes(py, &self.image)
    }

    fn __repr__(&self) -> String {
        format!(
            "<hscene.Picture {}x{}, {} rays>",
            self.image.width(),
            self.image.height(),
            self.stats.rays
        )
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Picture>()
}
