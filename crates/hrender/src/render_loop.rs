//! The render loop: one job shared by every row, its rows traced in
//! parallel straight into the image, and the counters they add up.

use super::*;

/// One render: everything a row of pixels needs, shared by all rows.
struct RenderJob<'a> {
    net: Net,
    pixel_net: PixelNet,
    window: Window,
    width: u32,
    height: u32,
    sampler: Sampler,
    adaptive: Option<Adaptive>,
    /// The samples of each pixel to take: `first_sample..end_sample` of
    /// the sampler's (`RenderOptions::sample_range`).
    first_sample: u32,
    end_sample: u32,
    scale: f64,
    integrator: Box<dyn Integrator + 'a>,
    background: Rgb,
    /// Depth of field: each sample starts on the lens (`hscene_ir::Lens`).
    lens: Option<hscene_ir::Lens>,
    /// Set to stop the render: looked at before each pixel, since one row
    /// of a heavy picture can take seconds.
    cancel: &'a AtomicBool,
}

impl RenderJob<'_> {
    /// The colour of one net sample, and whether it had a numeric failure;
    /// area lights draw their sample points from `stream`.
    fn shade(
        &self,
        sample: Sample,
        stream: &mut SampleStream,
        stats: &mut TraceStats,
    ) -> (Rgb, bool) {
        match sample {
            Sample::Ray(dir) => {
                let before = stats.failures;
                // With a lens, the sample's first two numbers pick its lens
                // point; the integrator draws the rest.
                let ray = match &self.lens {
                    Some(lens) => lens.ray(dir, stream.next_unit(), stream.next_unit()),
                    None => Ray::from_origin_unchecked(dir),
                };
                let c = self.integrator.radiance(&ray, stream, stats);
                (c, stats.failures > before)
            }
            Sample::Outside => (self.background, false),
        }
    }

    /// Columns `columns` of row `j` into `out` (one pixel per column):
    /// every pixel's samples, box-filtered and exposed (with adaptive
    /// sampling, as many as its noise needs, in batches).
    fn row(
        &self,
        j: u32,
        columns: std::ops::Range<u32>,
        out: &mut [[f32; 3]],
        stats: &mut TraceStats,
    ) -> RowStats {
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let mut nodes = NodeCache::default();
        let mut row = RowStats::default();
        for (i, pixel) in columns.zip(out) {
            if self.cancel.load(Ordering::Relaxed) {
                break;
            }
            let mut sum = Rgb::default();
            let mut failed = false;
            let mut noise = PixelNoise::default();
            let (first, end) = (self.first_sample, self.end_sample.min(self.sampler.count()));
            let mut k = first;
            while k < end {
                let (ox, oy) = self.sampler.offset(i, j, k);
                let sx = (f64::from(i) + ox) / w - 0.5;
                let sy = 0.5 - (f64::from(j) + oy) / h;
                let (c, f) = match self.net {
                    Net::EquidistantInterpolated => self.interpolated(sx, sy, &mut nodes, stats),
                    _ => {
                        let mut stream = self.sampler.stream(i, j, k);
                        self.shade(self.pixel_net.sample(sx, sy), &mut stream, stats)
                    }
                };
                sum += c;
                failed |= f;
                // One sample has no spread to measure: nothing to count.
                if self.sampler.count() > 1 {
                    noise.add(c);
                }
                k += 1;
                if let Some(a) = &self.adaptive
                    && a.is_done(&noise)
                {
                    break;
                }
            }
            let c = sum * (self.scale / f64::from(k - first));
            // A finite radiance beyond f32's range (a light of colour 1e18
            // delivering that at distance 30) is brighter than any display:
            // it saturates at f32's largest value instead of overflowing
            // to infinity and failing. Only NaN or infinity fail.
            let px = c.channels().map(|v| {
                if v.is_finite() {
                    v.clamp(-f64::from(f32::MAX), f64::from(f32::MAX)) as f32
                } else {
                    f32::NAN
                }
            });
            let px = if px.iter().all(|v| v.is_finite()) {
                px
            } else {
                failed = true;
                [0.0; 3]
            };
            row.failed_pixels += u64::from(failed);
            row.samples += u64::from(k - first);
            if let Some(e) = noise.relative_error() {
                row.noise_sum += e;
                row.noisy_pixels += 1;
            }
            *pixel = px;
        }
        row
    }

    /// Net 4: the screen shows the great disk as net 2 does, and each
    /// sample is interpolated bilinearly, in the equidistant coordinates
    /// `(a, b)`, from the four surrounding net-3 nodes. Nodes sit on a
    /// lattice of spacing equal to the hyperbolic pixel pitch at the disk's
    /// centre, so the two nets agree up to interpolation error. Nodes are
    /// traced once per row (`nodes` caches them) and only when their weight
    /// is not zero.
    fn interpolated(
        &self,
        sx: f64,
        sy: f64,
        nodes: &mut NodeCache,
        stats: &mut TraceStats,
    ) -> (Rgb, bool) {
        let (u, v) = (self.window.width * sx, self.window.height * sy);
        let r2 = u * u + v * v;
        if !(r2 < 1.0) {
            return (self.background, false);
        }
        // Disk point -> hyperboloid of the disk: x_i = 2 q_i / (1 - |q|^2).
        let g = 1.0 - r2;
        let (a, b) = ((2.0 * u / g).asinh(), (2.0 * v / g).asinh());
        // Pixel pitch on the disk is w/width; at the centre that is 2 w/width
        // in hyperbolic length.
        let (da, db) = (
            2.0 * self.window.width / f64::from(self.width),
            2.0 * self.window.height / f64::from(self.height),
        );
        let (fa, fb) = (a / da - 0.5, b / db - 0.5);
        let (ia, ib) = (fa.floor(), fb.floor());
        let (ta, tb) = (fa - ia, fb - ib);
        let mut sum = Rgb::default();
        let mut failed = false;
        for (di, dk, weight) in [
            (0.0, 0.0, (1.0 - ta) * (1.0 - tb)),
            (1.0, 0.0, ta * (1.0 - tb)),
            (0.0, 1.0, (1.0 - ta) * tb),
            (1.0, 1.0, ta * tb),
        ] {
            if weight == 0.0 {
                continue;
            }
            let (ni, nk) = (ia + di, ib + dk);
            // Node indices are bounded by |a|/da, and |a| < 40 in f64.
            let key = (ni as i64, nk as i64);
            let (c, f) = match nodes.0.get(&key) {
                Some(hit) => *hit,
                None => {
                    let sample = self
                        .pixel_net
                        .equidistant_node((ni + 0.5) * da, (nk + 0.5) * db);
                    // A node's light samples depend on the node, not on
                    // the pixel that first needs it.
                    let mut stream = self.sampler.node_stream(key.0, key.1);
                    let shaded = self.shade(sample, &mut stream, stats);
                    nodes.0.insert(key, shaded);
                    shaded
                }
            };
            sum += c * weight;
            failed |= f;
        }
        (sum, failed)
    }
}

/// What a row's pixels add to the render's counters.
#[derive(Clone, Copy, Debug, Default)]
struct RowStats {
    failed_pixels: u64,
    samples: u64,
    /// The sum of the relative errors of the pixels that have one.
    noise_sum: f64,
    noisy_pixels: u64,
}

impl RowStats {
    fn merge(self, o: RowStats) -> RowStats {
        RowStats {
            failed_pixels: self.failed_pixels + o.failed_pixels,
            samples: self.samples + o.samples,
            noise_sum: self.noise_sum + o.noise_sum,
            noisy_pixels: self.noisy_pixels + o.noisy_pixels,
        }
    }
}

/// Net-3 nodes already traced for the current row, by lattice index.
#[derive(Default)]
struct NodeCache(HashMap<(i64, i64), (Rgb, bool)>);

/// Renders `picture` (of `scene`) as `options` ask, on the current rayon
/// pool: the region's rows in parallel, each pixel checking `cancel`.
pub(crate) fn render_picture(
    scene: &Scene,
    picture: &Picture,
    options: &RenderOptions,
    region: Option<Region>,
    progress: &(dyn Fn(u32) + Sync),
    cancel: &AtomicBool,
) -> Result<Rendered, RenderError> {
    let Picture {
        net,
        window,
        width,
        height,
        pixel_net,
        prepared,
        ..
    } = picture;
    let (net, window, width, height) = (*net, *window, *width, *height);
    let region = region.unwrap_or(Region {
        x: 0,
        y: 0,
        width,
        height,
    });
    let fits = |start: u32, len: u32, total: u32| {
        len > 0 && start.checked_add(len).is_some_and(|end| end <= total)
    };
    if !(fits(region.x, region.width, width) && fits(region.y, region.height, height)) {
        return Err(RenderError::InvalidOption(format!(
            "the crop {}x{} at ({}, {}) is not inside the {width}x{height} image",
            region.width, region.height, region.x, region.y
        )));
    }
    let job = RenderJob {
        net,
        pixel_net: *pixel_net,
        window,
        width,
        height,
        sampler: match options.adaptive {
            Some(a) => Sampler::jittered(a.max_samples, options.seed),
            None => Sampler::new(
                options
                    .samples
                    .unwrap_or(scene.settings.samples)
                    .clamp(1, MAX_SAMPLES),
                options.seed,
            ),
        },
        adaptive: options.adaptive,
        first_sample: match (&options.sample_range, options.adaptive) {
            (Some(r), None) => r.start,
            _ => 0,
        },
        end_sample: match (&options.sample_range, options.adaptive) {
            (Some(r), None) => r.end,
            _ => u32::MAX,
        },
        scale: options.exposure.render_scale(),
        lens: scene.settings.lens,
        integrator: integrator::build(
            options.integrator.unwrap_or(scene.settings.integrator),
            prepared,
        ),
        background: prepared.background,
        cancel,
    };

    let done = std::sync::atomic::AtomicU32::new(0);
    let columns = region.x..region.x + region.width;
    // Each row is traced straight into its place in the image: no row of
    // its own to allocate, and no copy of the whole image after.
    // Allocated fallibly, before the first ray: a machine without the
    // memory refuses the render with an error instead of aborting in it.
    let count = region.width as usize * region.height as usize;
    let mut pixels: Vec<[f32; 3]> = Vec::new();
    fallible::fallibly(|| pixels.try_reserve_exact(count)).map_err(|_| {
        RenderError::OutOfMemory {
            what: "the image",
            bytes: count.saturating_mul(std::mem::size_of::<[f32; 3]>()),
        }
    })?;
    pixels.resize(count, [0.0; 3]);
    let (failed, traced) = pixels
        .par_chunks_mut(region.width as usize)
        .zip(region.y..region.y + region.height)
        .map(|(out, j)| {
            let mut stats = TraceStats::default();
            if cancel.load(Ordering::Relaxed) {
                return (RowStats::default(), stats);
            }
            let row = job.row(j, columns.clone(), out, &mut stats);
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(n);
            (row, stats)
        })
        .reduce(
            || (RowStats::default(), TraceStats::default()),
            |(fa, sa), (fb, sb)| (fa.merge(fb), sa.merge(sb)),
        );
    if cancel.load(Ordering::Relaxed) {
        return Err(RenderError::Cancelled);
    }
    let stats = RenderStats {
        rays: traced.rays,
        cut_trees: traced.cut_trees,
        numeric_failures: failed.failed_pixels,
        samples: failed.samples,
        noise: (failed.noisy_pixels > 0).then(|| failed.noise_sum / failed.noisy_pixels as f64),
    };
    let mut image = Image::from_pixels(region.width, region.height, pixels);
    let auto_exposure = options.exposure.finish(&mut image);
    Ok(Rendered {
        image,
        stats,
        auto_exposure,
    })
}
