//! What a quotient space looks like beyond the walk's horizon.
//!
//! A ray in a space is walked across the domain's faces no farther than
//! where a honeycomb of the domain's cells would fall below a pixel (never
//! past distance 12), and for at most [`hscene_ir::MAX_SPACE_CROSSINGS`]
//! crossings. Drawing the background where the walk gave up made the far
//! field of a closed space salt-and-pepper speckle (the tiles there are
//! below a pixel, so a few samples hit or miss them at random) and showed
//! the background down every cusp, where a ray crosses ever smaller tiles
//! until its crossings run out. So a walk that gives up reports where
//! ([`crate::space_walk::Traced::gave_up`]), and the integrators draw
//! there what the rest of the way to distance 12 holds on average, as
//! they do beyond a honeycomb's horizon (`horizon_fill.rs`, whose
//! averaging this shares).
//!
//! **The average.** A space is not homogeneous as a honeycomb is: what a
//! segment meets depends on where in the space it starts. The average is
//! taken over the picture's own eye: 1,024 lines leave the eye in an even spread of directions and are walked
//! exactly as rays are (across the faces, meeting the objects' images and
//! the domain's rods, up to 1,024 crossings per piece), from distance
//! [`SAMPLE_START`] to distance 12; a line is counted from its start at
//! 3, past the tiles around the eye, where the starts fall all over the
//! space. A line that runs out of crossings (down a cusp) is open from
//! there on. The mean ambient reflectance, emission, transparency and
//! tint met within `Δ`, and the openness `O(Δ)`, make one material and
//! one openness per `Δ` in steps of [`STEP`](crate::horizon_bucket::STEP);
//! a walk that gave up at arc length `h` takes the one for `Δ = 12 - h`.

use hgeom::{DEFAULT_HORIZON, Ray};
use hscene_ir::{Material, Scene};

use crate::absorption::{absorbed, sheet_filter};
use crate::horizon_bucket::bucket_for_rest;
use crate::horizon_fill::{
    Met, SAMPLE_START, Seen, append_fills, average_appearance, depth_and_surround, seen_along,
};
use crate::material::reflectances;
use crate::scene::{Nearest, PreparedScene, T_MIN};
use crate::space_walk::Traced;

/// Gives the space of `prepared` (made from the unfolded `scene`) its
/// fills: its average appearance and openness for every remaining length
/// (module docs), the materials appended to the scene's.
pub(crate) fn fill_space(prepared: &mut PreparedScene, scene: &Scene) {
    if prepared.space.is_none() {
        return;
    }
    let (depth, surround) = depth_and_surround(scene);
    let shared: &PreparedScene = prepared;
    let walk = |from_eye: &Ray| space_line(shared, from_eye, depth);
    let beyond = average_appearance(
        walk,
        &Material::default(),
        "the space beyond its horizon",
        surround,
    );
    let fills = append_fills(&mut prepared.materials, beyond);
    if let Some(space) = &mut prepared.space {
        space.fill = fills;
    }
}

/// What the sample line along `from_eye` meets in the space from
/// [`SAMPLE_START`] to distance 12, walked as a ray is: after each part
/// it goes on along the carried ray, its horizon the rest of the 12.
fn space_line(scene: &PreparedScene, from_eye: &Ray, max_depth: u32) -> Vec<Met> {
    let (mut ray, mut t_min, mut base) = (*from_eye, SAMPLE_START, 0.0);
    // Where the line last entered a solid: its absorption acts over the
    // way inside, from there to where it leaves.
    let mut entered = 0.0;
    let next = || {
        let traced = scene.walk(&ray, t_min, DEFAULT_HORIZON - base, |_| {});
        let Nearest::Hit(hit, index) = traced.nearest else {
            return None;
        };
        let object = &scene.objects[index];
        let m = &scene.materials[object.material_of(&hit)];
        let (ambient, diffuse) = reflectances(object, m, &hit);
        let s = base + traced.travelled + hit.t - SAMPLE_START;
        let cos = hgeom::lorentz::dot(traced.ray.tangent_at(hit.t), hit.normal);
        let filter = if object.parts.is_some() {
            sheet_filter(m, cos)
        } else if cos > 0.0 {
            absorbed(m, s - entered)
        } else {
            entered = s;
            hscene_ir::Rgb::new(1.0, 1.0, 1.0)
        };
        base += traced.travelled;
        (ray, t_min) = (traced.ray, hit.t + T_MIN);
        Some(Seen {
            s,
            material: m,
            ambient,
            diffuse,
            filter,
        })
    };
    seen_along(next, max_depth)
}

impl PreparedScene {
    /// For a ray whose walk gave up in a quotient space, what it draws
    /// there: the space's average material for the rest of the way to
    /// distance 12, its openness, and the arc length where the walk gave
    /// up (for fog). `None` for a hit, and for every ray in H³.
    pub(crate) fn beyond_space(&self, traced: &Traced) -> Option<(&Material, hscene_ir::Rgb, f64)> {
        let (Nearest::Miss, Some(at)) = (&traced.nearest, traced.gave_up) else {
            return None;
        };
        let fills = &self.space.as_ref()?.fill;
        let fill = fills.get(bucket_for_rest(DEFAULT_HORIZON - at, fills.len()))?;
        Some((self.materials.get(fill.material)?, fill.open, at))
    }
}
