//! Textures: where on a surface a material's pattern replaces its own
//! reflectances.

use hgeom::{Hit, Point, fermi_coordinates};
use hscene_ir::{Material, Pattern, Rgb, Texture};

use crate::scene::PreparedObject;

/// The ambient and diffuse reflectances of a textured material at a hit:
/// the hit taken to the object's local space, its Fermi coordinates `c`
/// ([`fermi_coordinates`]), the cell `floor(c / scale)`; cells with an odd
/// sum of indices take the texture's colours, the others the material's.
/// A hit whose local point f64 cannot represent keeps the material's own
/// colours (it is drawn, only not patterned).
pub fn texture_colours(
    object: &PreparedObject,
    m: &Material,
    t: &Texture,
    hit: &Hit,
) -> (Rgb, Rgb) {
    let own = (m.ambient, m.diffuse);
    let Some(local) = Point::from_hyperboloid(hit.point).map(|w| object.to_local.apply(&w)) else {
        return own;
    };
    if !local.is_representable() {
        return own;
    }
    match t.pattern {
        Pattern::Checker => {
            if checker_is_odd(fermi_coordinates(&local), t.scale) {
                (t.ambient, t.diffuse)
            } else {
                own
            }
        }
    }
}

/// How far below a cell wall (in cells) a point still counts as above it.
/// A surface that lies on a wall (a plane through the object's origin: the
/// floor everyone writes first) has local coordinates of a few ulps either
/// side of it; without the snap each hit's cell would be decided by
/// rounding, a salt of isolated pixels. With it every such point is in the
/// cell above the wall; only points within 1e-7 of a cell's size below a
/// wall move, far below any pixel.
const WALL_SNAP: f64 = 1e-7;

/// True when the checker cell `floor(c / scale + 1e-7)` of local Fermi
/// coordinates `c` has an odd sum of indices (see [`WALL_SNAP`]). Indices
/// are exact integers in f64 below 2^53 (beyond, every f64 is even); a
/// non-finite cell counts as even.
#[inline]
fn checker_is_odd(c: hgeom::glam::DVec3, scale: f64) -> bool {
    let cell = (c / scale + WALL_SNAP).floor();
    (cell.x + cell.y + cell.z).rem_euclid(2.0) == 1.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use hgeom::glam::DVec3;

    /// The checker uses the parity of the cell of the local Fermi
    /// coordinates: the middle of the cell at the origin is even (material
    /// colours), its neighbours along each axis odd, diagonal neighbours
    /// even again.
    #[test]
    fn checker_parity_is_that_of_the_fermi_cell() {
        let s = 0.3;
        let middle = |i: f64, j: f64, k: f64| {
            let c = fermi_coordinates(&hgeom::from_fermi_coordinates(
                (DVec3::new(i, j, k) + 0.5) * s,
            ));
            checker_is_odd(c, s)
        };
        assert!(!middle(0.0, 0.0, 0.0));
        assert!(middle(1.0, 0.0, 0.0) && middle(0.0, -1.0, 0.0) && middle(0.0, 0.0, 1.0));
        assert!(!middle(1.0, 1.0, 0.0) && !middle(-1.0, 0.0, 1.0));
        assert!(middle(1.0, 1.0, 1.0) && middle(-3.0, 2.0, 4.0));
        assert!(!checker_is_odd(DVec3::new(f64::NAN, 0.0, 0.0), s));
        assert!(!checker_is_odd(DVec3::splat(1e300), 1e-300));
    }

    /// Points on a cell wall, a few ulps either side of it as a plane's
    /// hits are, all fall in the same cell.
    #[test]
    fn points_on_a_wall_fall_in_one_cell() {
        let s = 0.25;
        let parity = |y: f64| checker_is_odd(DVec3::new(0.1, y, 0.3), s);
        let on_wall = parity(0.0);
        for y in [1e-17, -1e-17, 3e-16, -3e-16, -1e-12, 1e-12] {
            assert_eq!(parity(y), on_wall, "{y}");
        }
        // A wall away from the origin too: y = 2 cells.
        let wall = 2.0 * s;
        for y in [wall, wall * (1.0 + 1e-15), wall * (1.0 - 1e-15)] {
            assert_eq!(parity(y), parity(wall), "{y}");
        }
        // Farther from the wall than the snap, the cells differ as before.
        assert_ne!(parity(-1e-3), parity(1e-3));
    }
}
