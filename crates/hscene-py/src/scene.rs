//! `hscene.Scene`: a scene compiled from a file or a string, as `hscene
//! check` compiles it, rendered and saved as `hscene render` renders and
//! writes it.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use hgeom::glam::DMat4;
use hscene_ir::Scene as IrScene;
use hscene_ir::bounded_read::BoundedReadError;
use hscene_lang::{Compiled, Options};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyTuple};

use crate::diagnostics::{self, Diagnostic};
use crate::picture::{self, Picture};
use crate::render::{self, ExposureArg, Overrides};
use crate::space::Space;

/// Largest scene text read, as `hscene` reads (16 MiB).
const MAX_SCENE_BYTES: u64 = 16 << 20;

/// The width `Scene._repr_png_` renders at (the height keeps the scene's
/// aspect ratio): small enough for a notebook to show at once.
const PREVIEW_WIDTH: u32 = 256;

/// A compiled scene.
#[pyclass(module = "hscene", frozen)]
pub struct Scene {
    /// The scene at frame 0 (or the frame it was compiled for).
    scene: Arc<IrScene>,
    source: String,
    name: String,
    base_dir: Option<PathBuf>,
    space: Option<Arc<[DMat4]>>,
    diagnostics: Vec<Diagnostic>,
}

/// Compiles `source` as `hscene check` does; errors raise `SceneError`,
/// warnings go through `warnings.warn`.
fn compile(
    py: Python<'_>,
    source: &str,
    name: &str,
    base_dir: Option<PathBuf>,
    space: Option<Arc<[DMat4]>>,
    frame: u32,
) -> PyResult<(Compiled, IrScene)> {
    let options = Options {
        base_dir,
        frame,
        space,
        ..Options::default()
    };
    let mut compiled = py.detach(|| hscene_lang::compile_with(source, &options));
    if compiled.has_errors() {
        return Err(diagnostics::scene_error(py, name, source, &compiled));
    }
    diagnostics::warn(py, name, source, &compiled)?;
    match compiled.scene.take() {
        Some(scene) => Ok((compiled, scene)),
        // No errors means a scene; kept as an error rather than a panic.
        None => Err(diagnostics::scene_error(py, name, source, &compiled)),
    }
}

impl Scene {
    fn new(
        py: Python<'_>,
        source: String,
        name: String,
        base_dir: Option<PathBuf>,
        space: Option<Arc<[DMat4]>>,
        frame: u32,
    ) -> PyResult<Scene> {
        let (compiled, scene) =
            compile(py, &source, &name, base_dir.clone(), space.clone(), frame)?;
        let diagnostics = diagnostics::list(&source, &compiled);
        Ok(Scene {
            scene: Arc::new(scene),
            source,
            name,
            base_dir,
            space,
            diagnostics,
        })
    }

    /// The scene at frame `k` of its animation (`None`: as compiled), as
    /// `hscene render --frame` takes it: from the compiled animation, or
    /// compiled again where the animation moves points.
    fn at_frame(&self, py: Python<'_>, frame: Option<i64>) -> PyResult<Arc<IrScene>> {
        let Some(k) = frame else {
            return Ok(Arc::clone(&self.scene));
        };
        let frames = self.scene.settings.frames;
        let k = u32::try_from(k)
            .ok()
            .filter(|k| *k < frames)
            .ok_or_else(|| {
                PyValueError::new_err(format!(
                    "frame must be from 0 to {}, not {k}",
                    frames.saturating_sub(1)
                ))
            })?;
        if !self.scene.animation.moves_points {
            return self
                .scene
                .frame(k)
                .map(Arc::new)
                .map_err(|e| PyValueError::new_err(e.to_string()));
        }
        let (_, scene) = compile(
            py,
            &self.source,
            &self.name,
            self.base_dir.clone(),
            self.space.clone(),
            k,
        )?;
        Ok(Arc::new(scene))
    }

    /// A render with the keywords of `render`, `picture` and `save`.
    #[allow(clippy::too_many_arguments)]
    fn picture_with(
        &self,
        py: Python<'_>,
        overrides: Overrides,
        frame: Option<i64>,
        aov: Option<Vec<String>>,
    ) -> PyResult<Picture> {
        let options = overrides.options()?;
        let which = aov.as_deref().map(render::aov_list).transpose()?;
        let scene = self.at_frame(py, frame)?;
        let rendered = render::render(py, Arc::clone(&scene), options.clone())?;
        let layers = match which {
            Some(which) if !which.is_empty() => {
                Some(render::render_aovs(py, &scene, &options, &which)?)
            }
            _ => None,
        };
        Ok(Picture {
            image: rendered.image,
            layers,
            stats: rendered.stats,
            auto_exposure: rendered.auto_exposure,
        })
    }
}

/// The keyword overrides, from Python's arguments.
#[allow(clippy::too_many_arguments)]
fn overrides(
    resolution: Option<(i64, i64)>,
    samples: Option<i64>,
    integrator: Option<String>,
    net: Option<i64>,
    exposure: Option<ExposureArg>,
    seed: u64,
    threads: Option<i64>,
) -> Overrides {
    Overrides {
        resolution,
        samples,
        integrator,
        net,
        exposure,
        seed,
        threads,
    }
}

#[pymethods]
impl Scene {
    /// The scene in the file `path` (meshes, images and space files named
    /// in it are found from its folder).
    #[staticmethod]
    #[pyo3(signature = (path, *, space=None, frame=0))]
    fn from_file(
        py: Python<'_>,
        path: PathBuf,
        space: Option<PyRef<'_, Space>>,
        frame: u32,
    ) -> PyResult<Scene> {
        let bytes =
            hscene_ir::bounded_read::read_regular_file(&path, MAX_SCENE_BYTES).map_err(|e| {
                let why = match e {
                    BoundedReadError::NotAFile => "not a regular file".to_string(),
                    BoundedReadError::TooLarge(_) => {
                        format!("the file is larger than the limit of {MAX_SCENE_BYTES} bytes")
                    }
                    BoundedReadError::Io(e) => e.to_string(),
                };
                PyOSError::new_err(format!("cannot read {}: {why}", path.display()))
            })?;
        let source = hscene_lang::source::decode(bytes)
            .map_err(|e| PyValueError::new_err(format!("cannot read {}: {e}", path.display())))?;
        let base_dir = path.parent().map(Path::to_path_buf);
        let name = path.display().to_string();
        Scene::new(
            py,
            source,
            name,
            base_dir,
            space.map(|s| s.pairings()),
            frame,
        )
    }

    /// The scene in `text`; `name` is the file name its messages give,
    /// `base_dir` the folder files it names are read from (default: the
    /// current one), `space` a `Space` the scene is placed in (then the
    /// text gives no `space =`).
    #[staticmethod]
    #[pyo3(signature = (text, name="<string>", *, space=None, base_dir=None, frame=0))]
    fn from_str(
        py: Python<'_>,
        text: String,
        name: &str,
        space: Option<PyRef<'_, Space>>,
        base_dir: Option<PathBuf>,
        frame: u32,
    ) -> PyResult<Scene> {
        // The same decoding as a file's: a BOM dropped, line ends unified.
        let source = hscene_lang::source::decode(text.into_bytes())
            .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
        Scene::new(
            py,
            source,
            name.to_string(),
            base_dir,
            space.map(|s| s.pairings()),
            frame,
        )
    }

    /// The warnings of the compile (errors raise SceneError instead).
    #[getter]
    fn diagnostics(&self) -> Vec<Diagnostic> {
        self.diagnostics.clone()
    }

    /// The scene's own resolution, (width, height).
    #[getter]
    fn resolution(&self) -> (u32, u32) {
        let r = self.scene.settings.resolution;
        (r.width(), r.height())
    }

    /// Frames of its animation (1 for a still scene).
    #[getter]
    fn frames(&self) -> u32 {
        self.scene.settings.frames
    }

    /// The scene's name, as messages give it.
    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    /// Renders the scene. Returns the linear picture, `height × width × 3`
    /// float32 (`display=True`: the sRGB 8-bit one `hscene render` writes
    /// to a PNG, uint8); with `aov`, a pair (picture, dict of layers).
    #[pyo3(signature = (*, resolution=None, samples=None, integrator=None, net=None,
        exposure=None, seed=0, frame=None, display=false, aov=None, threads=None))]
    #[allow(clippy::too_many_arguments)]
    fn render<'py>(
        &self,
        py: Python<'py>,
        resolution: Option<(i64, i64)>,
        samples: Option<i64>,
        integrator: Option<String>,
        net: Option<i64>,
        exposure: Option<ExposureArg>,
        seed: u64,
        frame: Option<i64>,
        display: bool,
        aov: Option<Vec<String>>,
        threads: Option<i64>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let want_layers = aov.is_some();
        let o = overrides(
            resolution, samples, integrator, net, exposure, seed, threads,
        );
        let p = self.picture_with(py, o, frame, aov)?;
        let pixels = if display {
            picture::display_array(py, &p.image)?.into_any()
        } else {
            picture::linear_array(py, &p.image)?.into_any()
        };
        if !want_layers {
            return Ok(pixels);
        }
        let layers = match &p.layers {
            Some(l) => picture::layers_dict(py, l)?,
            None => PyDict::new(py),
        };
        Ok(PyTuple::new(py, [pixels, layers.into_any()])?.into_any())
    }

    /// Renders the scene into a `Picture` (linear and display arrays,
    /// layers, counters; shown inline by Jupyter).
    #[pyo3(signature = (*, resolution=None, samples=None, integrator=None, net=None,
        exposure=None, seed=0, frame=None, aov=None, threads=None))]
    #[allow(clippy::too_many_arguments)]
    fn picture(
        &self,
        py: Python<'_>,
        resolution: Option<(i64, i64)>,
        samples: Option<i64>,
        integrator: Option<String>,
        net: Option<i64>,
        exposure: Option<ExposureArg>,
        seed: u64,
        frame: Option<i64>,
        aov: Option<Vec<String>>,
        threads: Option<i64>,
    ) -> PyResult<Picture> {
        let o = overrides(
            resolution, samples, integrator, net, exposure, seed, threads,
        );
        self.picture_with(py, o, frame, aov)
    }

    /// Renders the scene and writes it to `path` in the format its
    /// extension names (.png, .tif, .tiff, .exr), atomically, as `hscene
    /// render` does; `aov` layers go into an .exr as extra channels.
    #[pyo3(signature = (path, *, resolution=None, samples=None, integrator=None, net=None,
        exposure=None, seed=0, frame=None, aov=None, threads=None, depth=None, png_level=3))]
    #[allow(clippy::too_many_arguments)]
    fn save(
        &self,
        py: Python<'_>,
        path: PathBuf,
        resolution: Option<(i64, i64)>,
        samples: Option<i64>,
        integrator: Option<String>,
        net: Option<i64>,
        exposure: Option<ExposureArg>,
        seed: u64,
        frame: Option<i64>,
        aov: Option<Vec<String>>,
        threads: Option<i64>,
        depth: Option<u32>,
        png_level: u8,
    ) -> PyResult<()> {
        // A bad output is refused before the render, as the CLI does.
        picture::sample_depth(depth, &path)?;
        let o = overrides(
            resolution, samples, integrator, net, exposure, seed, threads,
        );
        let p = self.picture_with(py, o, frame, aov)?;
        picture::write(py, &p.image, p.layers.as_ref(), path, depth, png_level)
    }

    /// A small picture (256 pixels wide) for Jupyter.
    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        let r = self.scene.settings.resolution;
        let width = r.width().min(PREVIEW_WIDTH);
        let height = (u64::from(r.height()) * u64::from(width) / u64::from(r.width())).max(1);
        let o = Overrides {
            resolution: Some((i64::from(width), height as i64)),
            ..Overrides::default()
        };
        let p = self.picture_with(py, o, None, None)?;
        picture::png_bytes(py, &p.image)
    }

    fn __repr__(&self) -> String {
        let r = self.scene.settings.resolution;
        format!(
            "<hscene.Scene {} {}x{}, {} object(s)>",
            self.name,
            r.width(),
            r.height(),
            self.scene.objects.len()
        )
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Scene>()
}
