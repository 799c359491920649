//! # hrender — the hyperbolic ray tracer
//!
//! Traces a compiled [`Scene`](hscene_ir::Scene) over the chosen pixel
//! net with an [`Integrator`] (today Whitted recursion with Phong shading
//! and hyperbolic attenuation), in parallel, and writes the result as PNG,
//! TIFF or OpenEXR. Every intersection is
//! hgeom's exact one; a hierarchy of bounding h-spheres decides which exact
//! tests a ray needs. Anti-aliasing (deterministic, seeded jitter) and an
//! exposure correction are render options. `docs/rendering.md` describes
//! the whole pipeline and the tests that pin it down.
//!
//! Invariants: the renderer never sees source text (only the IR); it never
//! prints or touches a terminal (progress goes through a callback); every
//! numeric failure (a non-finite ray, hit or colour, or a tangent vector the
//! hyperboloid can no longer resolve) is counted in [`RenderStats`], never
//! hidden, and no pixel is ever NaN or infinite.

mod absorption;
mod accel;
mod aov;
mod bsdf;
mod denoise;
mod display;
mod error;
mod exposure;
mod exr_layers;
mod fallible;
mod ffmpeg;
mod fog;
mod horizon_bucket;
mod horizon_fill;
mod icc;
mod image;
mod image_texture;
mod integrator;
mod light_sampling;
mod light_select;
mod light_tree;
mod material;
mod nets;
mod noise;
mod output;
mod output_check;
mod prepare;
mod prepared_object;
mod ray_budget;
mod render_loop;
mod sampling;
mod scene;
mod space_domain;
mod space_fill;
mod space_prepare;
mod space_walk;
mod spherical_triangle;
mod tangent;
mod texture;
mod trace_stats;
mod unfinished;
mod video;

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};

use hgeom::{Isometry, Ray};
use hscene_ir::view::{CanonicalFrame, FovError};
use hscene_ir::{Camera, Net, Resolution, Rgb, Scene, Window};
use rayon::prelude::*;
use render_loop::render_picture;

pub use aov::{Aov, AovLayers, render_aovs, render_guides};
pub use denoise::{
    DenoiseError, Denoiser, Guides, OIDN_ENV, OIDN_INSTALL, denoiser, denoiser_available,
};
pub use display::{DisplayTransform, Encoding, Levels8, ToneMap, srgb_decode, srgb_encode};
pub use error::RenderError;
pub use exposure::{
    AUTO_KEY, DARK_LEVEL, Darkness, Exposure, MAX_EXPOSURE, auto_exposure, bright_level, darkness,
    exposure_for_level, is_almost_black, is_black, luminance, suggested_exposure,
};
pub use exr_layers::write_exr_with_layers;
pub use fallible::allocation_is_fallible;
pub use hscene_ir::IntegratorKind;
pub use image::Image;
pub use integrator::{Integrator, MAX_PATH_LENGTH, PathTracer, Whitted};
pub use nets::{PixelNet, Sample, pixel_footprint};
pub use noise::{ADAPTIVE_BATCH, Adaptive, PixelNoise};
pub use output::{
    FileStamp, ImageFormat, PngLevel, SampleDepth, check_depth, output_target, replace_file,
    write_atomically, write_bytes, write_files_together, write_image, write_image_with,
};
pub use output_check::{MAX_FILE_NAME_BYTES, Overwrite, check_output, check_output_file};
pub use ray_budget::{MAX_SECONDARY_RAYS, RayBudget};
pub use sampling::{SampleStream, Sampler};
pub use scene::{Nearest, PreparedLight, PreparedObject, PreparedScene, T_MIN};
pub use space_domain::PreparedSpace;
pub use space_walk::Traced;
pub use trace_stats::TraceStats;
pub use unfinished::{remove_unfinished_outputs, try_remove_unfinished_outputs};
pub use video::{VideoFormat, VideoWriter, check_video, ffmpeg_available, played_fps};

/// Most samples per pixel a render accepts.
pub use hscene_ir::limits::MAX_SAMPLES;

/// Most worker threads a render starts: far above any core count a render
/// can use, far below what exhausts the system's thread limit.
pub const MAX_THREADS: usize = 1024;

/// Overrides of the scene's own settings, and execution options. The
/// default overrides nothing: the scene as it is, on every core, seed 0,
/// no exposure correction, the scene's integrator.
#[derive(Clone, Debug, Default)]
pub struct RenderOptions {
    /// Use this pixel net instead of the scene's `net_type`.
    pub net: Option<Net>,
    /// Use this resolution instead of the scene's.
    pub resolution: Option<Resolution>,
    /// Worker threads; `None` uses all cores.
    pub threads: Option<usize>,
    /// Samples per pixel, `1..=MAX_SAMPLES`, instead of the scene's
    /// `samples` setting; averaged with a box filter. One sample looks
    /// through the pixel centre; more are jittered (stratified when the
    /// count is a perfect square).
    pub samples: Option<u32>,
    /// Seed of the sample jitter: the same seed gives the same image.
    pub seed: u64,
    /// Adaptive sampling: each pixel takes samples until its estimated
    /// noise is low enough (instead of a fixed count; `samples` is then
    /// ignored).
    pub adaptive: Option<Adaptive>,
    /// How radiance is scaled before it is stored.
    pub exposure: Exposure,
    /// How light is computed, instead of the scene's `integrator`.
    pub integrator: Option<IntegratorKind>,
    /// Only these samples (by index) of each pixel's samples, averaged: a
    /// progressive viewer renders `0..1`, `1..2`, ... of `samples` and
    /// averages the passes, which gives the image of all of them at once.
    /// `None`: all. Ignored with adaptive sampling.
    pub sample_range: Option<std::ops::Range<u32>>,
}

impl RenderOptions {
    /// Check the ranges the renderer relies on.
    pub fn validate(&self) -> Result<(), RenderError> {
        if let Some(samples) = self.samples
            && !(1..=MAX_SAMPLES).contains(&samples)
        {
            return Err(RenderError::InvalidOption(format!(
                "samples must be from 1 to {MAX_SAMPLES}, not {samples}"
            )));
        }
        if let Some(ev) = self.exposure.given_stops()
            && !(ev.is_finite() && ev.abs() <= MAX_EXPOSURE)
        {
            return Err(RenderError::InvalidOption(format!(
                "exposure must be a number of stops from -{MAX_EXPOSURE} to {MAX_EXPOSURE}, not {}",
                hgeom::Compact(ev)
            )));
        }
        if let Some(a) = self.adaptive {
            a.validate()?;
        }
        if let Some(r) = &self.sample_range
            && (r.is_empty() || r.end > self.samples.unwrap_or(MAX_SAMPLES))
        {
            return Err(RenderError::InvalidOption(format!(
                "the sample range {}..{} must be non-empty and within the samples",
                r.start, r.end
            )));
        }
        if let Some(threads) = self.threads
            && !(1..=MAX_THREADS).contains(&threads)
        {
            return Err(RenderError::InvalidOption(format!(
                "threads must be from 1 to {MAX_THREADS}, not {threads}"
            )));
        }
        Ok(())
    }
}

/// What happened during a render.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RenderStats {
    /// Rays traced, all kinds.
    pub rays: u64,
    /// Pixels with a numeric failure in at least one of their rays or
    /// shading results; the failing contribution shows the background.
    pub numeric_failures: u64,
    /// Primary rays (pixel samples or interpolation nodes) whose ray tree
    /// was cut at [`MAX_SECONDARY_RAYS`].
    pub cut_trees: u64,
    /// Pixel samples taken, all pixels together.
    pub samples: u64,
    /// The mean, over the pixels that see any light, of each pixel's
    /// relative standard error (the standard deviation of its mean
    /// luminance over that mean, from its own samples): the noise left in
    /// the image. `None` with one sample per pixel (no spread to measure)
    /// or no lit pixel.
    pub noise: Option<f64>,
}

/// A finished render.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The image.
    pub image: Image,
    /// Counters.
    pub stats: RenderStats,
    /// The stops applied by an automatic exposure ([`Exposure::Auto`] or
    /// [`Exposure::AutoKept`]); `None` for fixed stops.
    pub auto_exposure: Option<f64>,
}

/// The canonical frame of `camera`, or the error a render reports for a
/// camera whose view and up directions are degenerate.
pub fn canonical_frame(camera: &Camera) -> Result<CanonicalFrame, RenderError> {
    CanonicalFrame::of(camera).ok_or(RenderError::DegenerateCamera)
}

/// Render a scene. `progress` is called with the number of rows finished so
/// far (from worker threads, in no particular order of rows).
pub fn render(
    scene: &Scene,
    options: &RenderOptions,
    progress: &(dyn Fn(u32) + Sync),
) -> Result<Rendered, RenderError> {
    render_region(scene, options, None, progress)
}

/// A rectangle of the image in pixels, from its top-left corner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    /// First column.
    pub x: u32,
    /// First row (row 0 is the top).
    pub y: u32,
    /// Columns, at least 1.
    pub width: u32,
    /// Rows, at least 1.
    pub height: u32,
}

/// Render only `region` of the image (`None`: all of it). Every pixel is
/// computed exactly as in the whole image (its rays, samples and jitter
/// depend on its position in the whole image only), so tiles rendered apart
/// and put side by side give the whole image bit for bit. `progress` counts
/// the region's rows.
pub fn render_region(
    scene: &Scene,
    options: &RenderOptions,
    region: Option<Region>,
    progress: &(dyn Fn(u32) + Sync),
) -> Result<Rendered, RenderError> {
    render_region_cancellable(scene, options, region, progress, &AtomicBool::new(false))
}

/// [`render_region`], stopped early when `cancel` becomes true (set from
/// another thread: the Python binding sets it on Ctrl-C, since a process
/// that embeds the renderer cannot simply exit as the CLI does). Each
/// worker looks at it before every pixel, so a render stops within about
/// one pixel's time; the result is then [`RenderError::Cancelled`], never
/// a partial image.
pub fn render_region_cancellable(
    scene: &Scene,
    options: &RenderOptions,
    region: Option<Region>,
    progress: &(dyn Fn(u32) + Sync),
    cancel: &AtomicBool,
) -> Result<Rendered, RenderError> {
    options.validate()?;
    let pool = {
        let mut b = rayon::ThreadPoolBuilder::new();
        if let Some(n) = options.threads {
            b = b.num_threads(n);
        }
        b.build().map_err(|e| RenderError::Threads(e.to_string()))?
    };
    pool.install(|| render_in_pool(scene, options, region, progress, cancel))
}

/// The scene's window, or the one its `fov` gives for this net, resolution
/// and view-plane distance.
fn view_window(
    scene: &Scene,
    net: Net,
    resolution: Resolution,
    view_distance: f64,
) -> Result<Window, RenderError> {
    let Some(fov) = scene.settings.fov else {
        return Ok(scene.settings.window);
    };
    hscene_ir::view::fov_window(fov, net, resolution, view_distance).map_err(|e| {
        RenderError::InvalidOption(match e {
            FovError::OutOfRange => format!("fov must be between 0 and 180 degrees, not {}", hgeom::Compact(fov)),
            FovError::BeyondViewPlane(max) => format!(
                "net {} cannot show fov = {fov}: the view h-plane spans less than {max:.1} degrees from the eye",
                net.index()
            ),
        })
    })
}

/// Where net 0's view plane lies for a picture whose `fov` is given: its
/// rays depend only on the window's shape over the plane's distance, so
/// the plane is brought nearer the eye (never farther than `to`) until the
/// whole window lies inside the ball and every pixel shows the angle `fov`
/// asks for. At `to`'s own distance a far `to` put the window's edges past
/// the absolute, and those pixels showed the background: a narrower view
/// than asked, without a word. The other nets' planes are fixed by `to`
/// (the language refuses a `fov` they cannot show, HSC0403).
fn view_plane_distance(scene: &Scene, net: Net, resolution: Resolution, to: f64) -> f64 {
    let Some(fov) = scene.settings.fov else {
        return to;
    };
    if net != Net::Euclidean || !(fov > 0.0 && fov < 180.0) {
        return to;
    }
    let t = (fov.to_radians() / 2.0).tan();
    let aspect = f64::from(resolution.height()) / f64::from(resolution.width());
    // The window's corner lies at `f sqrt(1 + t^2 (1 + aspect^2))`; a tenth
    // short of the absolute keeps it clear of rounding.
    let inside = 0.9 / (1.0 + t * t * (1.0 + aspect * aspect)).sqrt();
    to.min(inside)
}

/// A picture's set-up: its net and window, size, and the scene prepared
/// for it.
struct Picture {
    net: Net,
    window: Window,
    width: u32,
    height: u32,
    pixel_net: PixelNet,
    prepared: PreparedScene,
    /// From the camera's canonical frame back to the scene's.
    camera_to_scene: Isometry,
}

/// The set-up of the picture of `scene` that `options` ask for.
fn picture(scene: &Scene, options: &RenderOptions) -> Result<Picture, RenderError> {
    let camera = canonical_frame(&scene.camera)?;
    let net = options.net.unwrap_or(scene.settings.net);
    let resolution = options.resolution.unwrap_or(scene.settings.resolution);
    let (width, height) = (resolution.width(), resolution.height());
    let plane = view_plane_distance(scene, net, resolution, camera.view_distance);
    let window = view_window(scene, net, resolution, plane)?;
    let pixel_net = PixelNet::new(net, window, plane);
    let prepared = match pixel_footprint(&pixel_net, width, height) {
        Some(footprint) => PreparedScene::for_picture(scene, &camera, &footprint)?,
        None => PreparedScene::for_camera(scene, &camera)?,
    };
    let camera_to_scene = camera
        .stages
        .iter()
        .fold(Isometry::IDENTITY, |acc, stage| stage.compose(&acc))
        .inverse();
    Ok(Picture {
        net,
        window,
        width,
        height,
        pixel_net,
        prepared,
        camera_to_scene,
    })
}

fn render_in_pool(
    scene: &Scene,
    options: &RenderOptions,
    region: Option<Region>,
    progress: &(dyn Fn(u32) + Sync),
    cancel: &AtomicBool,
) -> Result<Rendered, RenderError> {
    let picture = picture(scene, options)?;
    render_picture(scene, &picture, options, region, progress, cancel)
}

/// A picture's set-up (its net, window and the scene prepared for its
/// camera and footprint), kept by a caller that renders the same view
/// many times: a progressive viewer's passes differ only in their
/// samples, and preparing a large scene costs more than a pass.
pub struct PreparedPicture {
    picture: Picture,
}

impl std::fmt::Debug for PreparedPicture {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PreparedPicture")
            .field("width", &self.picture.width)
            .field("height", &self.picture.height)
            .finish_non_exhaustive()
    }
}

/// The set-up of the picture of `scene` that `options` ask for (their
/// net and resolution; the rest may change between renders of it).
pub fn prepare_picture(
    scene: &Scene,
    options: &RenderOptions,
) -> Result<PreparedPicture, RenderError> {
    options.validate()?;
    Ok(PreparedPicture {
        picture: picture(scene, options)?,
    })
}

/// [`render_region`] of a prepared picture, on the current rayon pool
/// (the caller's, kept for many renders; `options.threads` is not used).
/// `scene` and `options`' net and resolution must be those it was
/// prepared with (the samples, their range, the seed, the exposure and
/// the integrator may differ).
pub fn render_prepared(
    scene: &Scene,
    prepared: &PreparedPicture,
    options: &RenderOptions,
    region: Option<Region>,
    progress: &(dyn Fn(u32) + Sync),
) -> Result<Rendered, RenderError> {
    let never = AtomicBool::new(false);
    render_prepared_cancellable(scene, prepared, options, region, progress, &never)
}

/// [`render_prepared`], stopped early when `cancel` becomes true, as
/// [`render_region_cancellable`] is: a viewer renders its passes on a
/// worker and cancels the one in flight when the camera moves or the
/// window closes, so the window never waits out a pass.
pub fn render_prepared_cancellable(
    scene: &Scene,
    prepared: &PreparedPicture,
    options: &RenderOptions,
    region: Option<Region>,
    progress: &(dyn Fn(u32) + Sync),
    cancel: &AtomicBool,
) -> Result<Rendered, RenderError> {
    options.validate()?;
    render_picture(scene, &prepared.picture, options, region, progress, cancel)
}
