//! Pixel layers (arbitrary output variables): what each pixel's primary
//! ray meets, for inspecting a picture mathematically (`--aov
//! depth,normal,id,cell`, written as extra OpenEXR channels).
//!
//! One ray per pixel, through the pixel's centre, from the eye (the pinhole
//! ray also with a lens), whatever the integrator: the layers are facts
//! about the scene along that ray, not estimates, so they are not filtered.
//!
//! - `depth` (channel `Z`): the hyperbolic distance from the eye to the
//!   first surface, `inf` where the ray meets nothing.
//! - `normal` (`N.X`, `N.Y`, `N.Z`): the shading normal there, turned to
//!   face the eye, as a unit direction in the ball coordinates of the
//!   scene (not the camera's frame); 0 where nothing is met.
//! - `id` (`id`): the object's number, 1 for the first object of the file
//!   in `Objects` order (as `check --emit ir` lists them), 0 for none.
//! - `cell` (`cell.rank`, `cell.class`): for a regular honeycomb coloured
//!   by rank, the rank of the cell the part belongs to (its layer from the
//!   base cell with `depth`, else its shell; the part's least, as the
//!   colours use) and its colour class (the rank modulo the number of
//!   classes); coloured by parity, rank `NaN` and the parity; a uniform
//!   honeycomb, rank `NaN` and the kind. `NaN` for everything else,
//!   including a honeycomb's far average beyond its horizon.
//! - `word` (`word.length`, `word.1` ... `word.8`): in a quotient space,
//!   the faces the ray left the domain by before the surface it shows, in
//!   order (numbered from 1 in the domain's order: a space file's order),
//!   so the tile shown is `g_{f_k} ∘ ... ∘ g_{f_1}` of the domain's
//!   contents: its length, and its first eight letters (0 past the end);
//!   0 everywhere in H³.
//! - `albedo` (`albedo.R`, `albedo.G`, `albedo.B`): the surface's
//!   reflectance there (its texture's where it has one), all its lobes
//!   together (diffuse, glossy, mirror, transmission, scaled as the path
//!   integrator scales them), at most 1; an emitter that reflects nothing
//!   shows its emission scaled to a largest channel of 1; 0 where nothing
//!   is met. With `normal`, the denoiser's guide (`denoise.rs`).
//! - `noisy` (`noisy.R`, `noisy.G`, `noisy.B`): the picture before
//!   denoising (the picture itself when nothing is denoised); filled in by
//!   the caller that has the picture ([`AovLayers::add_picture`]), not
//!   here.
//!
//! Every layer is of the first surface that is not fully transparent (a
//! material that lets all light through unbent and shines none: a `trans
//! = 1` face, a honeycomb's invisible walls): the ray goes on through
//! those, as the picture's light does. In a space, `id` follows the
//! object list of `check --emit ir` (an object's images share its
//! number); the domain's rods are numbered one more than the last object.

use hgeom::glam::DVec3;
use hgeom::ray::ball_direction;
use hgeom::{CellColouring, HoneycombPart, Ray, decode_honeycomb_part, lorentz};
use hscene_ir::Scene;

use crate::error::RenderError;
use crate::nets::Sample;
use crate::scene::{Nearest, T_MIN};
use rayon::prelude::*;

use crate::{Region, RenderOptions, picture};

/// A pixel layer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Aov {
    /// Hyperbolic distance along the primary ray.
    Depth,
    /// Shading normal in the scene's ball coordinates.
    Normal,
    /// The object's number.
    Id,
    /// A honeycomb cell's rank and colour class.
    Cell,
    /// In a quotient space, the group element that takes the tile a pixel
    /// shows onto the domain, as a word in the face pairings: its length
    /// and its first [`WORD_LETTERS`] letters.
    Word,
    /// The first hit's reflectance (a denoiser's guide).
    Albedo,
    /// The picture before denoising.
    Noisy,
}

/// The letters of the `word` layer kept as channels (`word.1` ...): the
/// faces crossed first; `word.length` says how many there were in all.
pub const WORD_LETTERS: usize = 8;

/// The most fully transparent surfaces a layer's ray passes through before
/// it gives up (and shows nothing).
pub const MAX_CLEAR_SURFACES: u32 = 256;

impl Aov {
    /// Every layer, by the names `--aov` takes.
    pub const ALL: [(&'static str, Aov); 7] = [
        ("depth", Aov::Depth),
        ("normal", Aov::Normal),
        ("id", Aov::Id),
        ("cell", Aov::Cell),
        ("word", Aov::Word),
        ("albedo", Aov::Albedo),
        ("noisy", Aov::Noisy),
    ];

    /// The layers of a comma-separated list (`depth,normal`), each once.
    pub fn parse_list(list: &str) -> Result<Vec<Aov>, String> {
        let mut out = Vec::new();
        for word in list.split(',').map(str::trim) {
            let Some((_, aov)) = Aov::ALL.iter().find(|(name, _)| *name == word) else {
                let names: Vec<&str> = Aov::ALL.iter().map(|(n, _)| *n).collect();
                return Err(format!(
                    "unknown pixel layer `{word}`: the layers are {}",
                    names.join(", ")
                ));
            };
            if !out.contains(aov) {
                out.push(*aov);
            }
        }
        Ok(out)
    }

    /// The OpenEXR channels it writes.
    pub fn channels(self) -> &'static [&'static str] {
        match self {
            Aov::Depth => &["Z"],
            Aov::Normal => &["N.X", "N.Y", "N.Z"],
            Aov::Id => &["id"],
            Aov::Cell => &["cell.rank", "cell.class"],
            Aov::Word => &[
                "word.length",
                "word.1",
                "word.2",
                "word.3",
                "word.4",
                "word.5",
                "word.6",
                "word.7",
                "word.8",
            ],
            Aov::Albedo => &["albedo.R", "albedo.G", "albedo.B"],
            Aov::Noisy => &["noisy.R", "noisy.G", "noisy.B"],
        }
    }
}

/// The layers of a picture: named channels of `width × height` samples,
/// row by row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct AovLayers {
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Each channel's name and samples.
    pub channels: Vec<(&'static str, Vec<f32>)>,
}

impl AovLayers {
    /// The samples of channel `name`, if it was rendered.
    pub fn channel(&self, name: &str) -> Option<&[f32]> {
        self.channels
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| v.as_slice())
    }

    /// The `noisy` layer's channels filled from `picture` (same size),
    /// where the layers include it.
    pub fn add_picture(&mut self, picture: &crate::Image) {
        for (k, name) in Aov::Noisy.channels().iter().enumerate() {
            if let Some((_, c)) = self.channels.iter_mut().find(|(n, _)| n == name) {
                for (v, px) in c.iter_mut().zip(picture.pixels()) {
                    *v = px[k];
                }
            }
        }
    }

    /// The three channels `names` as pixels.
    fn triples(&self, names: &[&str]) -> Option<Vec<[f32; 3]>> {
        let [r, g, b] = [
            self.channel(names[0])?,
            self.channel(names[1])?,
            self.channel(names[2])?,
        ];
        Some(
            r.iter()
                .zip(g)
                .zip(b)
                .map(|((r, g), b)| [*r, *g, *b])
                .collect(),
        )
    }
}

/// Sub-positions per pixel side the denoiser's guides average: its input
/// is anti-aliased, so guides through the pixel centre alone would give
/// it staircase edges its picture does not have.
const GUIDE_GRID: u32 = 3;

/// The denoiser's guides for the picture `render_region` would make of
/// `scene` with `options` and `region`: albedo and normal, each the mean
/// over a grid of [`GUIDE_GRID`]² positions in the pixel.
pub fn render_guides(
    scene: &Scene,
    options: &RenderOptions,
    region: Option<Region>,
) -> Result<crate::denoise::Guides, RenderError> {
    let layers = render_layers(
        scene,
        options,
        region,
        &[Aov::Albedo, Aov::Normal],
        GUIDE_GRID,
    )?;
    let albedo = layers.triples(Aov::Albedo.channels());
    let normal = layers.triples(Aov::Normal.channels());
    match (albedo, normal) {
        (Some(albedo), Some(normal)) => Ok(crate::denoise::Guides { albedo, normal }),
        _ => Err(RenderError::InvalidScene(
            "the guide layers were not rendered".to_string(),
        )),
    }
}

/// The layers `which` of the picture `render_region` would make of `scene`
/// with `options` and `region`.
pub fn render_aovs(
    scene: &Scene,
    options: &RenderOptions,
    region: Option<Region>,
    which: &[Aov],
) -> Result<AovLayers, RenderError> {
    render_layers(scene, options, region, which, 1)
}

/// The layers `which`, each pixel's the mean over `grid`² positions in
/// it (1: its centre); only albedo and normal are meaningful as means.
fn render_layers(
    scene: &Scene,
    options: &RenderOptions,
    region: Option<Region>,
    which: &[Aov],
    grid: u32,
) -> Result<AovLayers, RenderError> {
    options.validate()?;
    // Ranks, not classes, where a honeycomb's classes are ranks.
    let ranked;
    let scene = if which.contains(&Aov::Cell) {
        let mut s = scene.clone();
        for o in &mut s.objects {
            if let Some(ranked) = o.shape.with_walk(|w| w.with_rank_classes()) {
                o.shape = ranked;
            }
        }
        ranked = s;
        &ranked
    } else {
        scene
    };
    let picture = picture(scene, options)?;
    let region = region.unwrap_or(Region {
        x: 0,
        y: 0,
        width: picture.width,
        height: picture.height,
    });
    let n = (region.width as usize) * (region.height as usize);
    let names: Vec<&'static str> = which.iter().flat_map(|a| a.channels()).copied().collect();
    let stride = names.len();
    let row_len = region.width as usize * stride;
    // Interleaved (pixel by pixel, channel by channel) so that rows are
    // computed in parallel into disjoint slices, then split by channel.
    let mut data = vec![0.0f32; n * stride];
    let layer = LayerJob {
        scene,
        picture: &picture,
        to_scene: picture.camera_to_scene.to_lorentz(),
        names: &names,
        grid: grid.max(1),
    };
    let fill = |data: &mut [f32]| {
        data.par_chunks_mut(row_len.max(1))
            .zip(region.y..region.y + region.height)
            .for_each(|(out, j)| {
                for (col, values) in out.chunks_mut(stride.max(1)).enumerate() {
                    layer.pixel(region.x + col as u32, j, values);
                }
            });
    };
    match options.threads {
        Some(t) => rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build()
            .map_err(|e| RenderError::Threads(e.to_string()))?
            .install(|| fill(&mut data)),
        None => fill(&mut data),
    }
    let channels = names
        .iter()
        .enumerate()
        .map(|(k, name)| {
            (
                *name,
                data.iter().skip(k).step_by(stride).copied().collect(),
            )
        })
        .collect();
    Ok(AovLayers {
        width: region.width,
        height: region.height,
        channels,
    })
}

/// What every pixel of a layer render shares.
struct LayerJob<'a> {
    scene: &'a Scene,
    picture: &'a crate::Picture,
    to_scene: hgeom::glam::DMat4,
    names: &'a [&'static str],
    grid: u32,
}

impl LayerJob<'_> {
    /// Pixel `(i, j)`'s channel values into `values` (in `names` order).
    fn pixel(&self, i: u32, j: u32, values: &mut [f32]) {
        let picture = self.picture;
        let (w, h) = (f64::from(picture.width), f64::from(picture.height));
        let g = f64::from(self.grid);
        let weight = 1.0 / (g * g);
        let mut put = |name: &str, v: f64| {
            if let Some(k) = self.names.iter().position(|n| *n == name) {
                values[k] += (v * weight) as f32;
            }
        };
        for sub in 0..self.grid * self.grid {
            let (ox, oy) = (
                (f64::from(sub % self.grid) + 0.5) / g,
                (f64::from(sub / self.grid) + 0.5) / g,
            );
            let sx = (f64::from(i) + ox) / w - 0.5;
            let sy = 0.5 - (f64::from(j) + oy) / h;
            let mut word: Vec<usize> = Vec::new();
            let found = match picture.pixel_net.sample(sx, sy) {
                Sample::Ray(dir) => first_visible(
                    &picture.prepared,
                    Ray::from_origin_unchecked(dir),
                    &mut word,
                ),
                Sample::Outside => None,
            };
            put("word.length", word.len() as f64);
            for (letter, face) in word.iter().take(WORD_LETTERS).enumerate() {
                put(WORD_CHANNELS[letter], (face + 1) as f64);
            }
            let Some((ray, travelled, hit, index)) = found else {
                put("Z", f64::INFINITY);
                put("cell.rank", f64::NAN);
                put("cell.class", f64::NAN);
                continue;
            };
            put("Z", travelled + hit.t);
            let d = ray.tangent_at(hit.t);
            let facing = if lorentz::dot(d, hit.shading) > 0.0 {
                -hit.shading
            } else {
                hit.shading
            };
            let normal: DVec3 = ball_direction(self.to_scene * hit.point, self.to_scene * facing);
            put("N.X", normal.x);
            put("N.Y", normal.y);
            put("N.Z", normal.z);
            if let Some(object) = picture.prepared.objects.get(index) {
                let albedo = albedo_of(&picture.prepared, object, &hit);
                put("albedo.R", albedo.r);
                put("albedo.G", albedo.g);
                put("albedo.B", albedo.b);
            }
            // In a space, the prepared objects are the objects' images and
            // the domain's rods: each is given its object's number.
            let number = match &picture.prepared.space {
                Some(space) => space.numbers.get(index).copied().unwrap_or(0),
                None => index + 1,
            };
            put("id", number as f64);
            let (rank, class) = cell_of(self.scene, number.wrapping_sub(1), hit.part);
            put("cell.rank", rank);
            put("cell.class", class);
        }
    }
}

/// The reflectance of `object` at `hit` (module docs, `albedo`).
fn albedo_of(
    scene: &crate::scene::PreparedScene,
    object: &crate::scene::PreparedObject,
    hit: &hgeom::Hit,
) -> hscene_ir::Rgb {
    let Some(m) = scene.materials.get(object.material_of(hit)) else {
        return hscene_ir::Rgb::BLACK;
    };
    let (_, diffuse) = crate::material::reflectances(object, m, hit);
    let k = crate::bsdf::energy_scale(m, diffuse);
    let white = (m.reflection + m.transmission) * k;
    let smooth = (diffuse + m.specular) * k;
    let albedo = hscene_ir::Rgb::new(smooth.r + white, smooth.g + white, smooth.b + white);
    let clamp = |c: hscene_ir::Rgb| {
        let [r, g, b] = c.channels().map(|v| {
            if v.is_finite() {
                v.clamp(0.0, 1.0)
            } else {
                0.0
            }
        });
        hscene_ir::Rgb::new(r, g, b)
    };
    if albedo.is_black() && !m.emission.is_black() {
        let top = m.emission.channels().into_iter().fold(0.0, f64::max);
        if top > 0.0 && top.is_finite() {
            return clamp(m.emission * (1.0 / top));
        }
    }
    clamp(albedo)
}

/// The channels of the word's letters.
const WORD_CHANNELS: [&str; WORD_LETTERS] = [
    "word.1", "word.2", "word.3", "word.4", "word.5", "word.6", "word.7", "word.8",
];

/// The first surface along `ray` that is not fully transparent (a
/// material that lets all light through unbent and shines none: `trans =
/// 1` alone, or a honeycomb's invisible walls), as the ray it was met on,
/// the arc length before that ray's origin, the hit and the prepared
/// object's index; the faces crossed on the way pushed onto `word`.
/// `None` where nothing else is met.
fn first_visible(
    scene: &crate::scene::PreparedScene,
    mut ray: Ray,
    word: &mut Vec<usize>,
) -> Option<(Ray, f64, hgeom::Hit, usize)> {
    let mut before = 0.0;
    for _ in 0..MAX_CLEAR_SURFACES {
        let traced = scene.trace_recording(&ray, T_MIN, |face| word.push(face));
        let Nearest::Hit(hit, index) = traced.nearest else {
            return None;
        };
        let object = scene.objects.get(index)?;
        let clear = scene
            .materials
            .get(object.material_of(&hit))
            .is_some_and(|m| crate::bsdf::clear_transmission(m) >= 1.0 && m.emission.is_black());
        if !clear {
            return Some((traced.ray, before + traced.travelled, hit, index));
        }
        // On through it, from where it was met.
        before += traced.travelled + hit.t;
        ray = Ray {
            origin: traced.ray.at(hit.t),
            dir: traced.ray.tangent_at(hit.t),
        };
    }
    None
}

/// A honeycomb hit's rank and colour class (module docs), `NaN` for
/// anything else.
fn cell_of(scene: &Scene, index: usize, part: u32) -> (f64, f64) {
    let Some(h) = scene.objects.get(index).and_then(|o| o.shape.honeycomb()) else {
        return (f64::NAN, f64::NAN);
    };
    let (kind, class) = decode_honeycomb_part(part);
    if kind == HoneycombPart::Horizon {
        return (f64::NAN, f64::NAN);
    }
    let ranked = h.surface.rings().is_regular() && h.surface.colouring() == CellColouring::Rank;
    if !ranked {
        return (f64::NAN, f64::from(class));
    }
    // The palettes count round their lengths' least common multiple.
    let k = hscene_ir::palette_period(h.materials.palette.len(), h.materials.face_palette.len());
    (f64::from(class), f64::from(class) % k as f64)
}
