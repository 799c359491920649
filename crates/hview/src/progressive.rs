//! The progressive pipeline: after a move, a coarse frame at a fraction of
//! the resolution (one sample per pixel, shown enlarged), then the full
//! resolution one sample at a time. Pass `k` is sample `k` of the same
//! `N`-sample sampler `hscene render --samples N` uses
//! (`RenderOptions::sample_range`), and the passes are averaged, so after
//! `N` passes the still picture is that render's (to float rounding of the
//! average: within one 8-bit level).

use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use hrender::{DisplayTransform, Exposure, Levels8, PreparedPicture, RenderError, RenderOptions};
use hscene_ir::{IntegratorKind, Net, Resolution, Scene};

/// How the viewer renders.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewOptions {
    /// The window's picture size.
    pub resolution: Resolution,
    /// A pixel net instead of the scene's.
    pub net: Option<Net>,
    /// An integrator instead of the scene's.
    pub integrator: Option<IntegratorKind>,
    /// The samples per pixel a still view converges to.
    pub samples: u32,
    /// The coarse frame has `1/coarse` of the resolution each way.
    pub coarse: u32,
    /// Exposure in stops.
    pub exposure: f64,
    /// Worker threads (`None`: all cores).
    pub threads: Option<usize>,
    /// Denoise the converged picture (where the library is installed).
    pub denoise: bool,
}

/// A picture to show: 0RGB pixels, row-major, at the view's resolution.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// `0x00RRGGBB` per pixel.
    pub pixels: Vec<u32>,
    /// Samples per pixel so far (0 for a coarse frame).
    pub samples: u32,
}

impl Frame {
    /// The pixel at column `x`, row `y` as `[r, g, b]`.
    pub fn rgb(&self, x: u32, y: u32) -> [u8; 3] {
        let p = self.pixels[(y * self.width + x) as usize];
        [(p >> 16) as u8, (p >> 8) as u8, p as u8]
    }
}

/// Where a view is in its refinement.
#[derive(Clone, Debug)]
pub struct Progressive {
    options: ViewOptions,
    /// The sum of the passes so far (linear radiance).
    sum: Vec<[f64; 3]>,
    passes: u32,
    coarse_shown: bool,
    /// One worker pool for the view's whole life (made on the first
    /// render): a pool per pass cost its threads' start every pass.
    pool: Option<Arc<rayon::ThreadPool>>,
    /// The full-resolution picture's set-up, kept across the passes of
    /// one view (dropped by [`Progressive::restart`]).
    prepared: Option<Arc<PreparedPicture>>,
    /// The display transform's levels as a table (made once).
    levels: Arc<Levels8>,
    /// The converged picture, denoised when asked, shown from then on.
    still: Option<Frame>,
}

impl Progressive {
    /// A view that starts with a coarse frame.
    pub fn new(options: ViewOptions) -> Progressive {
        Progressive {
            options,
            sum: Vec::new(),
            passes: 0,
            coarse_shown: false,
            pool: None,
            prepared: None,
            levels: Arc::new(Levels8::new(DisplayTransform::default())),
            still: None,
        }
    }

    /// The options.
    pub fn options(&self) -> &ViewOptions {
        &self.options
    }

    /// Starts over (the camera moved or the scene changed).
    pub fn restart(&mut self) {
        self.sum.clear();
        self.passes = 0;
        self.coarse_shown = false;
        self.prepared = None;
        self.still = None;
    }

    /// The worker pool, made on first use.
    fn pool(&mut self) -> Result<Arc<rayon::ThreadPool>, RenderError> {
        if let Some(pool) = &self.pool {
            return Ok(pool.clone());
        }
        let mut builder = rayon::ThreadPoolBuilder::new();
        if let Some(n) = self.options.threads {
            builder = builder.num_threads(n);
        }
        let pool = Arc::new(
            builder
                .build()
                .map_err(|e| RenderError::Threads(e.to_string()))?,
        );
        self.pool = Some(pool.clone());
        Ok(pool)
    }

    /// Linear pixels as 0RGB words, in parallel, through the level table.
    fn display(&self, pool: &rayon::ThreadPool, pixels: &[[f32; 3]]) -> Vec<u32> {
        pool.install(|| pack(&self.levels.to_rgb8_parallel(pixels)))
    }

    /// Samples per pixel so far.
    pub fn samples(&self) -> u32 {
        self.passes
    }

    /// True if the next stage is the coarse frame (a move's first look).
    pub fn next_is_coarse(&self) -> bool {
        !self.coarse_shown && self.options.coarse > 1
    }

    /// True once every pass is in: nothing more to render until a change.
    pub fn is_converged(&self) -> bool {
        self.passes >= self.options.samples
    }

    fn render_options(&self, resolution: Resolution, pass: u32) -> RenderOptions {
        RenderOptions {
            net: self.options.net,
            resolution: Some(resolution),
            threads: self.options.threads,
            samples: Some(self.options.samples),
            seed: 0,
            adaptive: None,
            exposure: Exposure::Stops(self.options.exposure),
            integrator: self.options.integrator,
            sample_range: Some(pass..pass + 1),
        }
    }

    /// Renders the next stage of `scene` (its camera is the view's) and
    /// returns the picture to show: the coarse frame first, then the
    /// average of the passes so far. After convergence it returns the
    /// converged picture again without rendering.
    pub fn step(&mut self, scene: &Scene) -> Result<Frame, RenderError> {
        self.step_cancellable(scene, &AtomicBool::new(false))
    }

    /// [`Progressive::step`], stopped early when `cancel` becomes true
    /// (from another thread: the window renders on a worker): the result
    /// is then [`RenderError::Cancelled`] and the view is where it was
    /// before the step, the cancelled stage still to do.
    pub fn step_cancellable(
        &mut self,
        scene: &Scene,
        cancel: &AtomicBool,
    ) -> Result<Frame, RenderError> {
        let pool = self.pool()?;
        if self.next_is_coarse() {
            return self.coarse(&pool, scene, cancel);
        }
        if let Some(still) = &self.still {
            return Ok(still.clone());
        }
        if !self.is_converged() {
            self.pass(&pool, scene, cancel)?;
        }
        let n = f64::from(self.passes.max(1));
        let mean: Vec<[f32; 3]> = self.sum.iter().map(|s| s.map(|c| (c / n) as f32)).collect();
        let converged = self.is_converged();
        let shown = if converged && (self.options.denoise || scene.settings.denoise) {
            self.denoised(&pool, scene, &mean).unwrap_or(mean)
        } else {
            mean
        };
        let frame = Frame {
            width: self.options.resolution.width(),
            height: self.options.resolution.height(),
            pixels: self.display(&pool, &shown),
            samples: self.passes,
        };
        if converged {
            self.still = Some(frame.clone());
        }
        Ok(frame)
    }

    /// The coarse frame: one sample per pixel at `1/coarse` of the
    /// resolution, each pixel shown as a block.
    fn coarse(
        &mut self,
        pool: &rayon::ThreadPool,
        scene: &Scene,
        cancel: &AtomicBool,
    ) -> Result<Frame, RenderError> {
        let (w, h) = (
            self.options.resolution.width(),
            self.options.resolution.height(),
        );
        let c = self.options.coarse;
        let small =
            Resolution::new(w.div_ceil(c), h.div_ceil(c)).unwrap_or(self.options.resolution);
        let options = self.render_options(small, 0);
        let prepared = pool.install(|| hrender::prepare_picture(scene, &options))?;
        let image = render_on(pool, scene, &prepared, &options, cancel)?;
        // Marked shown only once rendered: a cancelled coarse frame is
        // still due.
        self.coarse_shown = true;
        let colours = self.display(pool, image.pixels());
        let sw = small.width();
        let pixels = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x / c, y / c)))
            .map(|(x, y)| colours[(y * sw + x) as usize])
            .collect();
        Ok(Frame {
            width: w,
            height: h,
            pixels,
            samples: 0,
        })
    }

    /// The next full-resolution pass, added to the sum (a cancelled pass
    /// adds nothing and is still to do).
    fn pass(
        &mut self,
        pool: &rayon::ThreadPool,
        scene: &Scene,
        cancel: &AtomicBool,
    ) -> Result<(), RenderError> {
        let options = self.render_options(self.options.resolution, self.passes);
        let prepared = match &self.prepared {
            Some(p) => p.clone(),
            None => {
                let p = Arc::new(pool.install(|| hrender::prepare_picture(scene, &options))?);
                self.prepared = Some(p.clone());
                p
            }
        };
        let image = render_on(pool, scene, &prepared, &options, cancel)?;
        if self.sum.len() != image.pixels().len() {
            self.sum = vec![[0.0; 3]; image.pixels().len()];
        }
        for (s, p) in self.sum.iter_mut().zip(image.pixels()) {
            for c in 0..3 {
                s[c] += f64::from(p[c]);
            }
        }
        self.passes += 1;
        Ok(())
    }

    /// The still picture `mean` denoised, or `None` where the library is
    /// missing or fails (the view then shows it as it is: a viewer has no
    /// reason to stop over a denoiser).
    fn denoised(
        &self,
        pool: &rayon::ThreadPool,
        scene: &Scene,
        mean: &[[f32; 3]],
    ) -> Option<Vec<[f32; 3]>> {
        let denoiser = hrender::denoiser().ok()?;
        let options = self.render_options(self.options.resolution, 0);
        let (w, h) = (
            self.options.resolution.width(),
            self.options.resolution.height(),
        );
        if mean.len() != w as usize * h as usize {
            return None;
        }
        let image = hrender::Image::from_pixels(w, h, mean.to_vec());
        let guides = pool
            .install(|| hrender::render_guides(scene, &options, None))
            .ok()?;
        let out = denoiser
            .denoise(&image, &guides, self.options.threads)
            .ok()?;
        Some(out.pixels().to_vec())
    }
}

/// Interleaved 8-bit RGB as 0RGB words.
fn pack(rgb: &[u8]) -> Vec<u32> {
    rgb.chunks_exact(3)
        .map(|p| (u32::from(p[0]) << 16) | (u32::from(p[1]) << 8) | u32::from(p[2]))
        .collect()
}

/// The whole picture of `prepared`, rendered on `pool`, stopped early when
/// `cancel` is set (then [`RenderError::Cancelled`]).
fn render_on(
    pool: &rayon::ThreadPool,
    scene: &Scene,
    prepared: &PreparedPicture,
    options: &RenderOptions,
    cancel: &AtomicBool,
) -> Result<hrender::Image, RenderError> {
    pool.install(|| {
        hrender::render_prepared_cancellable(scene, prepared, options, None, &|_| {}, cancel)
    })
    .map(|rendered| rendered.image)
}
