//! Solid checker textures: fixed in the object's local space (cells of the
//! local Fermi coordinates, odd cells in the texture's colours), so they
//! move with the object.

use hgeom::glam::{DMat3, DVec3};
use hgeom::{HPlane, Isometry, from_fermi_coordinates};
use hrender::Image;
use hscene_ir::{Material, Net, Rgb, Scene, Shape};
use hscene_test_support::SplitMix64;
use hscene_test_support::scenes::*;

/// A light grey material without highlights, so hue tells the cells apart.
fn pale() -> Material {
    Material {
        specular: Rgb::BLACK,
        ..matte(0.8, 0.8, 0.8)
    }
}

const RED: Rgb = Rgb::new(0.8, 0.1, 0.1);

/// A checkered sphere (its frame: a rotation about its centre, then the
/// move to the centre) in front of a checkered h-plane (frame: the
/// identity, so its cells are cut by world Fermi coordinates), lit by two
/// point lights.
fn checker_scene(size: u32) -> Scene {
    let centre = at(DVec3::new(0.1, 0.05, 1.0), 0.9);
    let frame =
        Isometry::transvection_from_origin(centre).compose(&Isometry::orthogonal_unchecked(
            DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 0.5).normalize(), 0.7),
        ));
    let plane = HPlane::orthogonal_at(&at(DVec3::Z, 1.6), &at(DVec3::Z, 1.7)).expect("plane");
    let mut s = scene(
        settings(Net::Euclidean, size, 0.12),
        default_camera(0.1),
        vec![checkered(pale(), 0.1, RED), checkered(pale(), 0.25, RED)],
        vec![
            light(p(0.0, 0.3, 0.1), 8.0),
            light(at(DVec3::new(-1.0, 0.2, 0.3), 0.6), 6.0),
        ],
        vec![
            obj_in(sphere(centre, 0.3), 0, frame),
            obj(Shape::Plane(Box::new(plane)), 1),
        ],
    );
    s.settings.recursion_depth = 2;
    s
}

/// Counts of red (texture) and grey (material) pixels.
fn red_and_grey(img: &Image) -> (usize, usize) {
    let red = img.pixels().iter().filter(|c| c[0] > 2.0 * c[1]).count();
    let grey = img
        .pixels()
        .iter()
        .filter(|c| c[0] > 0.01 && (c[0] - c[1]).abs() < 1e-4 && (c[1] - c[2]).abs() < 1e-4)
        .count();
    (red, grey)
}

/// Both colours of the checker appear, each on a good share of the image
/// (the sphere and the plane are cut into cells).
#[test]
fn the_checker_shows_both_colours() {
    let img = draw(&checker_scene(96));
    let (red, grey) = red_and_grey(&img);
    let n = img.pixels().len();
    assert!(
        red > n / 10 && grey > n / 10,
        "red {red}, grey {grey} of {n}"
    );
    // Without the texture, nothing is red.
    let mut plain = checker_scene(96);
    for m in &mut plain.materials {
        m.texture = None;
    }
    assert_eq!(red_and_grey(&draw(&plain)).0, 0);
}

/// The texture moves with its object: moving the eye, the target, the up
/// point, every object (shape and placement) and every light by one isometry
/// leaves the image unchanged, for five random isometries with translation
/// parts of length 2.5 to 5 (at most 0.1 % of pixels off by more than
/// 1/255). Moving the shapes but not their placements changes it: the pattern
/// is fixed in the local space, not in the world.
#[test]
fn the_texture_moves_with_its_object() {
    let base = checker_scene(96);
    let before = draw(&base);
    let mut rng = SplitMix64::new(77);
    for case in 0..5 {
        let iso = random_isometry(&mut rng, 5.0, false);
        let moved_scene = moved(&base, &iso);
        let share = agreement(&draw(&moved_scene), &before, 1.0 / 255.0);
        assert!(share >= 0.999, "isometry {case}: {share}");

        let mut placements_left = moved_scene.clone();
        for (o, old) in placements_left.objects.iter_mut().zip(&base.objects) {
            o.placement = old.placement;
        }
        let share = agreement(&draw(&placements_left), &before, 1.0 / 255.0);
        assert!(share < 0.9, "isometry {case}: placements ignored, {share}");
    }
}

/// The cell is that of the local Fermi coordinates, and the odd cells take
/// the texture's colours: a small sphere with an ambient-only material
/// about the point of local Fermi coordinates `(0.5, 0.5, 0.5) s` lies in
/// the even cell `(0, 0, 0)` and shows only the material's colour; about
/// the middles of the odd cells `(1, 0, 0)`, `(0, -1, 0)` and `(0, 0, 1)`
/// only the texture's; about that of `(1, -1, 0)` (even) the material's
/// again. The
/// object's frame is a rotation and a move, so the local space is not the
/// world's.
#[test]
fn the_cell_parity_of_the_local_fermi_coordinates_decides() {
    let s = 0.5;
    let frame = Isometry::transvection_from_origin(at(DVec3::Z, 1.0)).compose(
        &Isometry::orthogonal_unchecked(DMat3::from_axis_angle(
            DVec3::new(-0.3, 1.0, 0.2).normalize(),
            2.1,
        )),
    );
    let green = Rgb::new(0.2, 0.6, 0.2);
    let magenta = Rgb::new(0.9, 0.1, 0.9);
    for (cell, odd) in [
        ([0.0, 0.0, 0.0], false),
        ([1.0, 0.0, 0.0], true),
        ([0.0, -1.0, 0.0], true),
        ([0.0, 0.0, 1.0], true),
        ([1.0, -1.0, 0.0], false),
    ] {
        let local = from_fermi_coordinates((DVec3::from_array(cell) + 0.5) * s);
        // Radius 0.3 s: every point of the ball is within 0.3 s of the
        // centre, so each Fermi coordinate within 0.3 s of the middle of
        // the cell (the coordinates are 1-Lipschitz).
        let centre = frame.apply(&local);
        let mut sc = scene(
            settings(Net::Euclidean, 64, 0.25),
            default_camera(0.1),
            vec![checkered(flat(green.r, green.g, green.b), s, magenta)],
            vec![],
            vec![obj_in(sphere(centre, 0.3 * s), 0, frame)],
        );
        sc.settings.ambient = Rgb::new(1.0, 1.0, 1.0);
        let img = draw(&sc);
        let want = if odd { magenta } else { green };
        let want = [want.r as f32, want.g as f32, want.b as f32];
        let bg = sc.settings.background;
        let bg = [bg.r as f32, bg.g as f32, bg.b as f32];
        let mut seen = 0;
        for px in img.pixels() {
            if *px == bg {
                continue;
            }
            assert_eq!(*px, want, "cell {cell:?}");
            seen += 1;
        }
        assert!(
            seen > 50,
            "cell {cell:?}: the sphere is in view ({seen} px)"
        );
    }
}

/// The floor everyone writes first, an h-plane through the ball's centre
/// with a checker, lies exactly on a wall of its checker cells: each hit's
/// cell must not be decided by rounding. In the near floor, where every
/// cell is many pixels wide, no pixel differs from all four of its
/// neighbours (rounding made a salt of hundreds of them there), and the
/// floor shows both colours. (Near the horizon, where cells shrink to a
/// pixel, a checker's corners alias into single pixels by right.)
#[test]
fn a_checker_plane_through_the_centre_has_no_salt() {
    let compiled = hscene_lang::compile(
        "Globals { resolution = (96, 72); from = (0, 0.3, -0.2); to = (0, 0, 0.3); fov = 90;
                   ambient = (1, 1, 1); }
         BRDFs { floor: ambient = (0.9, 0.9, 0.9), checker = 0.25,
                 checker_ambient = (0.1, 0.1, 0.4); }
         Objects { Plane (1, 0, 0), (0, 0, 1), (-1, 0, 0), #floor; }",
    );
    let scene = compiled.scene.expect("the floor scene compiles");
    let image =
        hrender::render(&scene, &hrender::RenderOptions::default(), &|_| {}).expect("renders");
    let (w, h) = (96usize, 72usize);
    let px = image.image.pixels();
    let at = |x: usize, y: usize| px[y * w + x][0];
    let mut isolated = 0;
    let (mut pale, mut dark) = (0, 0);
    for y in 48..h - 1 {
        for x in 1..w - 1 {
            let c = at(x, y);
            pale += usize::from(c > 0.5);
            dark += usize::from(c > 0.0 && c < 0.5);
            let differs = |v: f32| (v - c).abs() > 0.05;
            if differs(at(x - 1, y))
                && differs(at(x + 1, y))
                && differs(at(x, y - 1))
                && differs(at(x, y + 1))
            {
                isolated += 1;
            }
        }
    }
    assert!(pale > 300 && dark > 300, "{pale} pale, {dark} dark");
    assert_eq!(isolated, 0, "isolated pixels");
}
