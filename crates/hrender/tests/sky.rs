//! The sky: the radiance of the ideal point a ray runs to, fixed in the
//! scene, seen directly, from a moved eye, and in a mirror.

use hgeom::glam::DVec3;
use hgeom::{HLine, Point};
use hscene_ir::{Rgb, Scene, Sky};

use crate::one_pixel::{self, pixel};

const ZENITH: (f64, f64, f64) = (0.2, 0.4, 0.9);
const HORIZON: (f64, f64, f64) = (0.9, 0.8, 0.7);

fn compile(camera: &str, extra: &str, integrator: &str) -> Scene {
    one_pixel::compile(&format!(
        "Globals {{ resolution = (1, 1); {camera} sky = ((0.2, 0.4, 0.9), (0.9, 0.8, 0.7)); \
         recursion_depth = 4; integrator = {integrator}; }}\n{extra}"
    ))
}

fn expected(u: DVec3) -> Rgb {
    let sky = Sky::Gradient {
        zenith: Rgb::new(ZENITH.0, ZENITH.1, ZENITH.2),
        horizon: Rgb::new(HORIZON.0, HORIZON.1, HORIZON.2),
    };
    sky.radiance(u)
}

fn assert_colour(got: [f32; 3], want: Rgb, what: &str) {
    for (g, w) in got.iter().zip([want.r, want.g, want.b]) {
        assert!(
            (f64::from(*g) - w).abs() < 1e-5,
            "{what}: {got:?} against {want:?}"
        );
    }
}

#[test]
fn straight_up_is_the_zenith_and_level_is_the_horizon() {
    for integrator in ["whitted", "path"] {
        let up = compile(
            "from = (0, 0, 0); to = (0, 0.3, 0); up = (0, 0, 0.3);",
            "",
            integrator,
        );
        assert_colour(pixel(&up), expected(DVec3::Y), "up");
        let level = compile("from = (0, 0, 0); to = (0, 0, 0.3);", "", integrator);
        assert_colour(pixel(&level), expected(DVec3::Z), "level");
    }
}

/// From an eye moved 2 along x, the ray leaving straight "up" (+y at the
/// eye) ends at an ideal point well below the zenith: that point, not the
/// ray's direction, gives the colour.
#[test]
fn a_moved_eye_sees_the_sky_where_its_rays_end() {
    let eye = Point::at_distance_from_origin(DVec3::X, 2.0).unwrap();
    let line = HLine::from_point_direction(&eye, DVec3::Y).unwrap();
    let target = line.point_at(0.3).unwrap().coords();
    let (_, end) = line.ends();
    let u = end.coords();
    assert!(
        u.y < 0.8,
        "the endpoint {u:?} should be far from the zenith"
    );
    let e = eye.coords();
    let camera = format!(
        "from = ({}, {}, {}); to = ({}, {}, {}); up = ({}, {}, 0.3);",
        e.x, e.y, e.z, target.x, target.y, target.z, e.x, e.y
    );
    let scene = compile(&camera, "", "whitted");
    assert_colour(pixel(&scene), expected(u), "moved eye");
}

/// Looking down at a level mirror, the central ray comes back straight up:
/// the mirror shows the zenith.
#[test]
fn a_mirror_shows_the_sky_its_reflected_rays_reach() {
    let extra = "Points { a = (0.3, -0.2, 0); b = (-0.15, -0.2, -0.25980762113533157); c = (-0.15, -0.2, 0.25980762113533157); }\n\
                 BRDFs { mirror: alpha = 1; }\n\
                 Objects { Plane %a, %b, %c, #mirror; }\n";
    let scene = compile(
        "from = (0, 0, 0); to = (0, -0.1, 0); up = (0, 0, 0.3);",
        extra,
        "whitted",
    );
    assert_colour(pixel(&scene), expected(DVec3::Y), "mirror");
}

/// `sky = "file"`: an equirectangular image, its top half red and bottom
/// half blue: straight up is red, straight down blue, in both integrators.
#[test]
fn an_image_sky_by_the_ideal_endpoint() {
    let dir = tempfile::tempdir().unwrap();
    let img = image::RgbImage::from_fn(64, 32, |_, j| {
        image::Rgb(if j < 16 { [255, 0, 0] } else { [0, 0, 255] })
    });
    img.save(dir.path().join("sky.png")).unwrap();
    for integrator in ["whitted", "path"] {
        for (to, up, red) in [
            ("(0, 0.3, 0)", "up = (0, 0, 0.3);", true),
            ("(0, -0.3, 0)", "up = (0, 0, 0.3);", false),
        ] {
            let source = format!(
                "Globals {{ resolution = (1, 1); from = (0, 0, 0); to = {to}; {up} \
                 sky = \"sky.png\"; integrator = {integrator}; }}\n"
            );
            let options = hscene_lang::Options {
                base_dir: Some(dir.path().to_path_buf()),
                ..hscene_lang::Options::default()
            };
            let out = hscene_lang::compile_with(&source, &options);
            let scene = out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics));
            let px = pixel(&scene);
            if red {
                assert!(px[0] > 0.99 && px[2] < 0.01, "{integrator} up: {px:?}");
            } else {
                assert!(px[2] > 0.99 && px[0] < 0.01, "{integrator} down: {px:?}");
            }
        }
    }
}
