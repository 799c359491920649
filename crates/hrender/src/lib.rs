//! # hrender — the hyperbolic ray tracer
//!
//! Traces a lowered [`Scene`](hscene_lang::ir::Scene) over the chosen pixel
//! net with Whitted recursion, Phong shading and hyperbolic attenuation, in
//! parallel, and writes the result as PNG or TIFF.
//!
//! Invariants: the renderer never sees source text (only the IR); it never
//! prints or touches a terminal (progress goes through a callback); every
//! non-finite shading result is counted in [`RenderStats`], never hidden.

mod camera;
mod color;
mod error;
mod image;
mod nets;
mod output;
mod scene;
mod tracer;

use hgeom::Ray;
use hscene_lang::ir::{Net, Resolution, Scene};
use rayon::prelude::*;

pub use camera::CanonicalCamera;
pub use error::RenderError;
pub use image::Image;
pub use nets::{PixelNet, Sample};
pub use output::{ImageFormat, SampleDepth, write_image};
pub use scene::PreparedScene;
pub use tracer::TraceStats;

/// Overrides of the scene's own settings, and execution options.
#[derive(Clone, Debug, Default)]
pub struct RenderOptions {
    /// Use this pixel net instead of the scene's `net_type`.
    pub net: Option<Net>,
    /// Use this resolution instead of the scene's.
    pub resolution: Option<Resolution>,
    /// Worker threads; `None` uses all cores.
    pub threads: Option<usize>,
}

/// What happened during a render.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderStats {
    /// Rays traced, all kinds.
    pub rays: u64,
    /// Pixels whose shading was not finite (shown as background).
    pub numeric_failures: u64,
}

/// A finished render.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The image.
    pub image: Image,
    /// Counters.
    pub stats: RenderStats,
}

/// Render a scene. `progress` is called with the number of rows finished so
/// far (from worker threads, in no particular order of rows).
pub fn render(
    scene: &Scene,
    options: &RenderOptions,
    progress: &(dyn Fn(u32) + Sync),
) -> Result<Rendered, RenderError> {
    let pool = {
        let mut b = rayon::ThreadPoolBuilder::new();
        if let Some(n) = options.threads {
            b = b.num_threads(n.max(1));
        }
        b.build().map_err(|e| RenderError::Threads(e.to_string()))?
    };
    pool.install(|| render_in_pool(scene, options, progress))
}

fn render_in_pool(
    scene: &Scene,
    options: &RenderOptions,
    progress: &(dyn Fn(u32) + Sync),
) -> Result<Rendered, RenderError> {
    let camera = CanonicalCamera::new(&scene.camera)?;
    let prepared = PreparedScene::new(scene, &camera.to_canonical)?;
    let net = options.net.unwrap_or(scene.settings.net);
    let Resolution { width, height } = options.resolution.unwrap_or(scene.settings.resolution);
    let pixel_net = PixelNet::new(net, scene.settings.window, camera.view_distance);
    let tracer = tracer::Tracer::new(&prepared);
    let background = color::Color::from(prepared.background);

    let shade = |sample: Sample, stats: &mut TraceStats| match sample {
        Sample::Ray(dir) => tracer.primary(&Ray::from_origin(dir), stats),
        Sample::Outside => background,
    };

    let done = std::sync::atomic::AtomicU32::new(0);
    let rows: Vec<(Vec<[f32; 3]>, TraceStats)> = (0..height)
        .into_par_iter()
        .map(|j| {
            let mut stats = TraceStats::default();
            let sy = 0.5 - (f64::from(j) + 0.5) / f64::from(height);
            let row = (0..width)
                .map(|i| {
                    let sx = (f64::from(i) + 0.5) / f64::from(width) - 0.5;
                    let c = match net {
                        Net::EquidistantInterpolated => interpolated(
                            &pixel_net, scene, sx, sy, width, height, &shade, &mut stats,
                        ),
                        _ => shade(pixel_net.sample(sx, sy), &mut stats),
                    };
                    c.0.map(|v| v as f32)
                })
                .collect();
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(n);
            (row, stats)
        })
        .collect();

    let mut stats = TraceStats::default();
    let mut pixels = Vec::with_capacity(width as usize * height as usize);
    for (row, s) in rows {
        pixels.extend(row);
        stats = stats.merge(s);
    }
    Ok(Rendered {
        image: Image::from_pixels(width, height, pixels),
        stats: RenderStats {
            rays: stats.rays,
            numeric_failures: stats.numeric_failures,
        },
    })
}

/// Net 4: the screen shows the great disk as net 2 does, and each pixel is
/// interpolated bilinearly, in the equidistant coordinates `(a, b)`, from the
/// four surrounding net-3 nodes. Nodes sit on a lattice of spacing equal to
/// the hyperbolic pixel pitch at the disk's centre, so the two nets agree
/// up to interpolation error.
#[allow(clippy::too_many_arguments)]
fn interpolated(
    net: &PixelNet,
    scene: &Scene,
    sx: f64,
    sy: f64,
    width: u32,
    height: u32,
    shade: &(dyn Fn(Sample, &mut TraceStats) -> color::Color + Sync),
    stats: &mut TraceStats,
) -> color::Color {
    let w = scene.settings.window;
    let (u, v) = (w.width * sx, w.height * sy);
    let r2 = u * u + v * v;
    if r2 >= 1.0 {
        return shade(Sample::Outside, stats);
    }
    // Disk point -> hyperboloid of the disk: x_i = 2 q_i / (1 - |q|^2).
    let g = 1.0 - r2;
    let (a, b) = ((2.0 * u / g).asinh(), (2.0 * v / g).asinh());
    // Pixel pitch on the disk is w/width; at the centre that is 2 w/width in
    // hyperbolic length.
    let (da, db) = (
        2.0 * w.width / f64::from(width),
        2.0 * w.height / f64::from(height),
    );
    let (fa, fb) = (a / da - 0.5, b / db - 0.5);
    let (ia, ib) = (fa.floor(), fb.floor());
    let (ta, tb) = (fa - ia, fb - ib);
    let node = |i: f64, k: f64, stats: &mut TraceStats| {
        shade(net.equidistant_node((i + 0.5) * da, (k + 0.5) * db), stats)
    };
    let c00 = node(ia, ib, stats);
    let c10 = node(ia + 1.0, ib, stats);
    let c01 = node(ia, ib + 1.0, stats);
    let c11 = node(ia + 1.0, ib + 1.0, stats);
    c00 * ((1.0 - ta) * (1.0 - tb))
        + c10 * (ta * (1.0 - tb))
        + c01 * ((1.0 - ta) * tb)
        + c11 * (ta * tb)
}
