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
}

/// The letters of the `word` layer kept as channels (`word.1` ...): the
/// faces crossed first; `word.length` says how many there were in all.
pub const WORD_LETTERS: usize = 8;

/// The most fully transparent surfaces a layer's ray passes through before
/// it gives up (and shows nothing).
pub const MAX_CLEAR_SURFACES: u32 = 256;

impl Aov {
    /// Every layer, by the names `--aov` takes.
    pub const ALL: [(&'static str, Aov); 5] = [
        ("depth", Aov::Depth),
        ("normal", Aov::Normal),
        ("id", Aov::Id),
        ("cell", Aov::Cell),
        ("word", Aov::Word),
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
}

/// The layers `which` of the picture `render_region` would make of `scene`
/// with `options` and `region`.
pub fn render_aovs(
    scene: &Scene,
    options: &RenderOptions,
    region: Option<Region>,
    which: &[Aov],
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
    let to_scene = picture.camera_to_scene.to_lorentz();
    let n = (region.width as usize) * (region.height as usize);
    let names: Vec<&'static str> = which.iter().flat_map(|a| a.channels()).copied().collect();
    let mut channels: Vec<(&'static str, Vec<f32>)> =
        names.iter().map(|name| (*name, vec![0.0; n])).collect();
    let (w, h) = (f64::from(picture.width), f64::from(picture.height));
    for row in 0..region.height {
        for col in 0..region.width {
            let (i, j) = (region.x + col, region.y + row);
            let sx = (f64::from(i) + 0.5) / w - 0.5;
            let sy = 0.5 - (f64::from(j) + 0.5) / h;
            let mut word: Vec<usize> = Vec::new();
            let found = match picture.pixel_net.sample(sx, sy) {
                Sample::Ray(dir) => first_visible(
                    &picture.prepared,
                    Ray::from_origin_unchecked(dir),
                    &mut word,
                ),
                Sample::Outside => None,
            };
            let k = (row as usize) * (region.width as usize) + col as usize;
            let mut put = |name: &str, v: f64| {
                if let Some((_, c)) = channels.iter_mut().find(|(n, _)| *n == name) {
                    c[k] = v as f32;
                }
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
            let normal: DVec3 = ball_direction(to_scene * hit.point, to_scene * facing);
            put("N.X", normal.x);
            put("N.Y", normal.y);
            put("N.Z", normal.z);
            // In a space, the prepared objects are the objects' images and
            // the domain's rods: each is given its object's number.
            let number = match &picture.prepared.space {
                Some(space) => space.numbers.get(index).copied().unwrap_or(0),
                None => index + 1,
            };
            put("id", number as f64);
            let (rank, class) = cell_of(scene, number.wrapping_sub(1), hit.part);
            put("cell.rank", rank);
            put("cell.class", class);
        }
    }
    Ok(AovLayers {
        width: region.width,
        height: region.height,
        channels,
    })
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
