//! Scenes in quotient spaces (`space = NAME`): the domain's edges are the
//! honeycomb's, a mirrored cell is the honeycomb with its contents
//! reflected by hand, the Seifert-Weber gluing closes the geodesic along a
//! face's normal, and both integrators render the spaces without numeric
//! failures.

use hgeom::glam::DVec3;
use hgeom::{HPlane, Isometry, Point, QuotientSpace, Ray, Schlafli, SpaceKind};
use hrender::{Nearest, PreparedScene, RenderOptions, Rendered};
use hscene_ir::{Scene, move_object};

/// Ambient-only materials and no lights: every hit is drawn in its
/// material's ambient colour exactly, so two pictures of the same geometry
/// agree pixel for pixel.
const FLAT: &str = "BRDFs { gold: ambient = (0.8, 0.6, 0.2), diffuse = (0, 0, 0); \
                    red: ambient = (0.9, 0.1, 0.1), diffuse = (0, 0, 0); }";

fn compile(globals: &str, objects: &str) -> Scene {
    compile_from(
        "from = (0.03, 0.02, 0.01); to = (0.2, 0.1, 0.3);",
        globals,
        objects,
    )
}

/// A horosphere-inscribed cell lies on the `x < 0` side of its face
/// through the origin: the eye is put inside, looking along it.
const IN_HOROSPHERE_CELL: &str = "from = (-0.1, 0.02, 0.01); to = (-0.25, 0.1, 0.3);";

fn compile_from(camera: &str, globals: &str, objects: &str) -> Scene {
    let source = format!(
        "Globals {{ resolution = (64, 64); {camera} \
         fov = 90; background = (0, 0, 0); ambient = (1, 1, 1); {globals} }}\n{FLAT}\n\
         Objects {{ {objects} }}"
    );
    let out = hscene_lang::compile(&source);
    out.scene.unwrap_or_else(|| panic!("{:?}", out.diagnostics))
}

fn render(scene: &Scene) -> Rendered {
    let options = RenderOptions {
        samples: Some(1),
        ..RenderOptions::default()
    };
    hrender::render(scene, &options, &|_| {}).expect("the scene renders")
}

fn pixels(r: &Rendered) -> Vec<[f32; 3]> {
    let image = &r.image;
    (0..image.height())
        .flat_map(|y| (0..image.width()).map(move |x| image.get(x, y)))
        .collect()
}

fn is_black(p: &[f32; 3]) -> bool {
    p.iter().all(|c| *c == 0.0)
}

/// From inside, `domain = w, #M` with no objects draws what
/// `Honeycomb {p,q,r}, #M, edges = w` draws: every pixel that both draw
/// is the same, and where one draws an edge the other does too (each
/// fills beyond its horizon with its own average appearance).
#[test]
fn the_domain_draws_the_honeycombs_edges() {
    for (space, symbol, camera) in [
        ("seifert_weber", "{5,3,5}", None),
        ("figure_eight", "{3,3,6}", None),
        ("whitehead", "{3,4,4}", None),
        ("{4,3,5}", "{4,3,5}", None),
        ("{4,4,3}", "{4,4,3}", Some(IN_HOROSPHERE_CELL)),
        ("{6,3,6}", "{6,3,6}", Some(IN_HOROSPHERE_CELL)),
    ] {
        let camera = camera.unwrap_or("from = (0.03, 0.02, 0.01); to = (0.2, 0.1, 0.3);");
        let inside = render(&compile_from(
            camera,
            &format!("space = {space}; domain = 0.03, #gold;"),
            "",
        ));
        let honeycomb = render(&compile_from(
            camera,
            "",
            &format!("Honeycomb {symbol}, #gold, edges = 0.03;"),
        ));
        assert_eq!(inside.stats.numeric_failures, 0, "{space}");
        let (a, b) = (pixels(&inside), pixels(&honeycomb));
        let edge = [0.8f32, 0.6, 0.2];
        let close = |p: &[f32; 3]| p.iter().zip(edge).all(|(x, y)| (x - y).abs() < 1e-6);
        let both = a
            .iter()
            .zip(&b)
            .filter(|(x, y)| close(x) && close(y))
            .count();
        let only_space = a
            .iter()
            .zip(&b)
            .filter(|(x, y)| close(x) && is_black(y))
            .count();
        let only_honeycomb = a
            .iter()
            .zip(&b)
            .filter(|(x, y)| is_black(x) && close(y))
            .count();
        println!(
            "{space}: {both} edge pixels in both, {only_space} only in the space, {only_honeycomb} only in the honeycomb"
        );
        assert!(both > 500, "{space}: {both}");
        assert!(only_space + only_honeycomb <= a.len() / 200, "{space}");
    }
}

/// The cell of `{4,3,5}` with mirror walls and a ball in it equals
/// `Honeycomb {4,3,5}`'s space with the ball and its six images in the
/// cube's faces placed by hand, wherever the hand-made scene has
/// something: a ray reflected once by a wall is the ray that crosses
/// that face into the neighbouring cell.
#[test]
fn the_mirrored_cell_is_the_ball_reflected_by_hand() {
    let (drawn, reflected, differ) = mirrored_against_by_hand(
        (4, 3, 5),
        "from = (0.03, 0.02, 0.01); to = (0.2, 0.1, 0.3);",
        "Sphere (0.1, 0.05, 0.15), 0.12, #red;",
    );
    assert!(reflected > 80, "{reflected}");
    assert!(differ <= drawn / 200, "{differ} of {drawn}");
}

/// The mirrored cell of `{p,q,r}` with `ball` in it, and `Honeycomb
/// {p,q,r}`'s space with the ball and its images in the cell's faces put
/// there by hand, seen from `camera`: the pixels the hand-made picture
/// draws, those its images add, and those where the two differ.
fn mirrored_against_by_hand(
    (p, q, r): (u32, u32, u32),
    camera: &str,
    ball: &str,
) -> (usize, usize, usize) {
    let mirrored = compile_from(camera, &format!("space = {{{p},{q},{r}}};"), ball);
    let mut by_hand = compile_from(camera, "", ball);
    let cell = QuotientSpace::new(SpaceKind::Mirrors(Schlafli::new(p, q, r).unwrap())).unwrap();
    let original = by_hand.objects[0].clone();
    for n in cell.faces() {
        let mirror = Isometry::reflection(&HPlane::from_normal(*n).unwrap());
        if let Some(image) = move_object(&original, &mirror) {
            by_hand.objects.push(image);
        }
    }
    let alone = pixels(&render(&compile_from(camera, "", ball)));
    let (a, b) = (pixels(&render(&mirrored)), pixels(&render(&by_hand)));
    let drawn = b.iter().filter(|p| !is_black(p)).count();
    let reflected = drawn - alone.iter().filter(|p| !is_black(p)).count();
    let differ = a
        .iter()
        .zip(&b)
        .filter(|(x, y)| !is_black(y) && x != y)
        .count();
    println!(
        "{{{p},{q},{r}}}: {drawn} pixels drawn by hand ({reflected} by the images), {differ} differ"
    );
    (drawn, reflected, differ)
}

/// The same for a cell inscribed in a horosphere, `{6,3,4}`, whose faces
/// are infinitely many: the ball and its images in the faces near it. An
/// even number of cells round each edge (4) makes the mirrored cell an
/// orbifold, whose images agree however a ray reaches them: a line that
/// crosses two faces near an edge into the cell across the first sees
/// the same image in both pictures. (With `r` odd, such a line sees a
/// doubly reflected image in the kaleidoscope: `docs/manifolds.md`.)
#[test]
fn the_mirrored_horosphere_cell_is_the_ball_reflected_by_hand() {
    let (drawn, reflected, differ) = mirrored_against_by_hand(
        (6, 3, 4),
        IN_HOROSPHERE_CELL,
        "Sphere (-0.12, 0.05, 0.25), 0.15, #red;",
    );
    assert!(reflected > 60, "{reflected}");
    assert!(differ <= drawn / 200, "{differ} of {drawn}");
}

/// In Seifert-Weber space, from the centre along a face's normal, the
/// geodesic leaves at the inradius ρ and comes back through the opposite
/// face: a ball of radius `a` at distance `s` behind the eye on that axis
/// is met ahead at `2ρ - s - a`.
#[test]
fn seifert_weber_shows_what_is_behind_the_eye_ahead() {
    let space = QuotientSpace::seifert_weber().unwrap();
    let n = space.faces()[0];
    let u = -n.truncate().normalize();
    let rho = (-n.w).asinh();
    let (s, a) = (0.35, 0.1);
    let c = Point::at_distance_from_origin(-u, s).unwrap().coords();
    let scene = compile(
        "space = seifert_weber;",
        &format!("Sphere ({}, {}, {}), {a}, #red;", c.x, c.y, c.z),
    );
    let prepared = PreparedScene::new(&scene, &Isometry::IDENTITY).unwrap();
    let traced = prepared.trace(&Ray::from_origin(u).unwrap(), 1e-9);
    let Nearest::Hit(hit, _) = traced.nearest else {
        panic!("the ray meets nothing");
    };
    let t = traced.travelled + hit.t;
    println!("met at {t}, expected {}", 2.0 * rho - s - a);
    assert!((t - (2.0 * rho - s - a)).abs() < 1e-12);
    // Behind the eye it is where it was put.
    let back = prepared.trace(&Ray::from_origin(-u).unwrap(), 1e-9);
    let Nearest::Hit(hit, _) = back.nearest else {
        panic!("the ray back meets nothing");
    };
    assert!(back.travelled == 0.0 && (hit.t - (s - a)).abs() < 1e-12);
    let _ = DVec3::X;
}

/// A ball centred on a face of the Seifert-Weber domain crosses it: the
/// part beyond the face is seen through the opposite face, where the
/// gluing brings it back, so looking either way along the face's normal
/// from the centre meets the ball at `ρ - a`, its near side.
#[test]
fn an_object_across_a_face_is_whole_on_both_sides() {
    let space = QuotientSpace::seifert_weber().unwrap();
    let n = space.faces()[0];
    let u = -n.truncate().normalize();
    let rho = (-n.w).asinh();
    let a = 0.3;
    let c = Point::at_distance_from_origin(u, rho).unwrap().coords();
    let scene = compile(
        "space = seifert_weber;",
        &format!("Sphere ({}, {}, {}), {a}, #red;", c.x, c.y, c.z),
    );
    let prepared = PreparedScene::new(&scene, &Isometry::IDENTITY).unwrap();
    for (dir, what) in [(u, "towards the face"), (-u, "towards the opposite face")] {
        let traced = prepared.trace(&Ray::from_origin(dir).unwrap(), 1e-9);
        let Nearest::Hit(hit, _) = traced.nearest else {
            panic!("{what}: the ray meets nothing");
        };
        let t = traced.travelled + hit.t;
        println!("{what}: met at {t}, expected {}", rho - a);
        assert_eq!(traced.travelled, 0.0, "{what}: met inside the domain");
        assert!((t - (rho - a)).abs() < 1e-12, "{what}: {t}");
    }
}

/// No seam in the light across a face: a point on a face of the domain
/// and its image on the partner face are one point of the space, and the
/// light the images of a lamp give it (each faded out near its reach,
/// `PreparedLight::fade`) is the same computed from either side.
#[test]
fn the_light_is_the_same_on_both_sides_of_a_face() {
    for space in ["seifert_weber", "figure_eight", "{5,3,4}"] {
        let scene = compile(
            &format!("space = {space};"),
            "Sphere (0.1, 0, 0), 0.05, #red;",
        );
        let mut scene = scene;
        scene.lights.push(hscene_ir::Light {
            position: Point::from_coords(hgeom::glam::DVec3::new(0.05, 0.12, -0.07)).unwrap(),
            diffuse: hscene_ir::Rgb::new(1.0, 1.0, 1.0),
            specular: hscene_ir::Rgb::BLACK,
            name: None,
            radius: 0.0,
            samples: 1,
            near: 0.0,
            on_camera: false,
        });
        let prepared = PreparedScene::new(&scene, &Isometry::IDENTITY).unwrap();
        let light_at = |x: hgeom::glam::DVec4| -> f64 {
            prepared
                .lights
                .iter()
                .map(|l| {
                    let d = hgeom::lorentz::distance(x, l.position);
                    l.fade(d) / d.sinh().powi(2)
                })
                .sum()
        };
        let q = scene.settings.space.as_ref().unwrap().build().unwrap();
        let domain = q.domain().unwrap();
        let mut worst = 0.0f64;
        let mut tested = 0;
        for face in 0..q.faces().len() {
            let n = q.faces()[face];
            // Points of the face: the foot of the centre's perpendicular,
            // and its midpoints with the face's vertices.
            let foot = {
                let x = hgeom::glam::DVec4::W + (-n.w) * n;
                x / (-hgeom::lorentz::dot(x, x)).sqrt()
            };
            let mut points = vec![foot];
            for &k in domain.face_vertices(face) {
                let v = domain.vertices()[k];
                let m = foot + v / v.w;
                points.push(m / (-hgeom::lorentz::dot(m, m)).sqrt());
            }
            let g = q.pairing(face).to_lorentz();
            // The images kept light every point within the domain's
            // radius of its centre (all of a closed domain; a cusped one
            // but for its cusps: docs/manifolds.md).
            let near = |x: hgeom::glam::DVec4| {
                hgeom::lorentz::distance(x, hgeom::glam::DVec4::W) <= q.radius()
            };
            for x in points {
                if !(near(x) && near(g * x)) {
                    continue;
                }
                tested += 1;
                let (a, b) = (light_at(x), light_at(g * x));
                worst = worst.max((a - b).abs() / a.max(b));
            }
        }
        println!(
            "{space}: {} light images; at {tested} points of the faces the light on the two sides differs by {worst:.1e}",
            prepared.lights.len()
        );
        assert!(tested >= 6, "{space}: {tested}");
        assert!(worst < 1e-9, "{space}: {worst}");
    }
}

/// Both integrators light a scene in each built-in space by the light's
/// images, with no numeric failure, and lit surfaces are brighter than
/// the ambient alone.
#[test]
fn both_integrators_light_every_space() {
    for space in [
        "seifert_weber",
        "figure_eight",
        "whitehead",
        "{5,3,4}",
        "{3,4,4}",
        "{4,4,4}",
    ] {
        for integrator in ["whitted", "path"] {
            // Inside every cell, the horosphere-inscribed ones included.
            let source = format!(
                "Globals {{ resolution = (24, 24); from = (-0.05, 0.02, 0.01); \
                 to = (-0.2, 0.1, 0.3); fov = 90; space = {space}; domain = 0.03, #white; \
                 integrator = {integrator}; samples = 4; }}\n\
                 BRDFs {{ white: diffuse = (0.8, 0.8, 0.8); }}\n\
                 Lights {{ (-0.1, -0.05, 0.1), (1, 1, 1), (0, 0, 0), irradiance_at = 0.3; }}\n\
                 Objects {{ Sphere (-0.15, 0.05, 0.15), 0.08, #white; }}"
            );
            let out = hscene_lang::compile(&source);
            let scene = out
                .scene
                .unwrap_or_else(|| panic!("{space}: {:?}", out.diagnostics));
            let r = render(&scene);
            let mean = pixels(&r).iter().map(|p| p[0] + p[1] + p[2]).sum::<f32>() / 576.0;
            println!("{space} {integrator}: mean {mean}, {} rays", r.stats.rays);
            assert_eq!(r.stats.numeric_failures, 0, "{space} {integrator}");
            assert!(mean > 0.05, "{space} {integrator}: {mean}");
        }
    }
}
