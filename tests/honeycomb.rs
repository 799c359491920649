//! End-to-end tests of `Honeycomb {p,q,r}` through the binary: every one of
//! the 15 renders and draws something, other geometries are located
//! errors, `depth = N` of `{4,3,5}` draws what `Tessellation435 N` draws,
//! and a symmetry of the honeycomb applied to the camera leaves the
//! picture unchanged.
//!
//! The comparisons are pixel by pixel with a tolerance: the two renders of
//! each pair take different arithmetic paths (explicit rods against the
//! walk's pieces of rods; a camera at a moved place), so they agree to
//! rounding everywhere except on the few pixels whose centre grazes an
//! edge's silhouette, where a difference of 1e-12 in the hit decides
//! between rod and background. "Agree" is: at least 99 % of the pixels
//! within 6/255 in every channel.

use std::path::Path;

use assert_cmd::Command;
use hgeom::Schlafli;

fn hscene() -> Command {
    Command::cargo_bin("hscene").expect("binary is built by cargo test")
}

/// The 8-bit RGB pixels of a rendered PNG.
fn pixels(path: &Path) -> Vec<[u8; 3]> {
    let img = image::open(path)
        .expect("a PNG the renderer wrote")
        .to_rgb8();
    img.pixels().map(|p| p.0).collect()
}

/// Renders `source` at `size` squared; returns the pixels and stderr.
fn render(dir: &Path, name: &str, source: &str, size: u32) -> (Vec<[u8; 3]>, String) {
    let scene = dir.join(format!("{name}.hsc"));
    std::fs::write(&scene, source).expect("temporary directory is writable");
    let out = dir.join(format!("{name}.png"));
    let assert = hscene()
        .arg("render")
        .arg(&scene)
        .args(["--resolution", &format!("{size}x{size}")])
        .arg("-o")
        .arg(&out)
        .assert()
        .success();
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    (pixels(&out), stderr)
}

/// The share of pixels of `a` and `b` within `tol` in every channel.
fn agreement(a: &[[u8; 3]], b: &[[u8; 3]], tol: u8) -> f64 {
    assert_eq!(a.len(), b.len());
    let close = a
        .iter()
        .zip(b)
        .filter(|(p, q)| (0..3).all(|c| p[c].abs_diff(q[c]) <= tol))
        .count();
    close as f64 / a.len() as f64
}

const AGREE: f64 = 0.99;
const TOLERANCE: u8 = 6;

const MATERIALS: &str = "BRDFs {
    edge: ambient = (0.4, 0.3, 0.2), diffuse = (0.9, 0.75, 0.45), specular = (1, 1, 1), shininess = 40;
    glass: ambient = (0.05, 0.1, 0.2), diffuse = (0.1, 0.2, 0.3), trans = 0.7;
}
";

#[test]
fn each_of_the_fifteen_renders_and_draws_something() {
    let dir = tempfile::tempdir().expect("temporary directory");
    for (p, q, r) in Schlafli::ALL {
        let symbol = Schlafli::new(p, q, r).expect("one of the 15");
        // Inside the base cell: near the origin (its centre), or for cells
        // inscribed in horospheres on the cell's side of the face at the
        // origin.
        let eye = if symbol.has_ideal_cells() {
            "(-0.2, 0.02, 0.03)"
        } else {
            "(0.02, 0.03, 0.01)"
        };
        let source = format!(
            "Globals {{ from = {eye}; to = (0.1, 0.14, 0.4); fov = 100; background = (0, 0, 0); \
             ambient = (0.5, 0.5, 0.5); recursion_depth = 3; }}\n\
             {MATERIALS}Lights {{ {eye}, (3, 3, 3), (2, 2, 2); }}\n\
             Objects {{ Honeycomb {{{p},{q},{r}}}, #edge, edges = 0.03, faces = #glass; }}\n"
        );
        let (img, stderr) = render(dir.path(), &format!("h{p}{q}{r}"), &source, 48);
        assert!(!stderr.contains("numeric failure"), "{symbol}: {stderr}");
        let lit = img.iter().filter(|px| px.iter().any(|&c| c > 8)).count();
        assert!(
            lit * 2 > img.len(),
            "{symbol}: only {lit} of {} pixels show the honeycomb",
            img.len()
        );
        // Edges alone: the near ones, lit, stand out from the far field,
        // which takes the edges' ambient colour (every far ray meets an
        // edge; docs/honeycombs.md): neither all one colour nor no field.
        let source = source.replace(", faces = #glass", "");
        let (img, _) = render(dir.path(), &format!("e{p}{q}{r}"), &source, 48);
        let mut counts = std::collections::HashMap::new();
        for px in &img {
            *counts.entry(*px).or_insert(0usize) += 1;
        }
        let field = counts
            .iter()
            .max_by_key(|(_, n)| **n)
            .map(|(px, _)| *px)
            .expect("a picture has pixels");
        let apart = img
            .iter()
            .filter(|px| (0..3).any(|c| px[c].abs_diff(field[c]) > 8))
            .count();
        assert!(
            apart > img.len() / 20 && apart < img.len(),
            "{symbol} edges: {apart} of {} pixels stand out from {field:?}",
            img.len()
        );
    }
}

#[test]
fn other_geometries_are_located_errors() {
    let dir = tempfile::tempdir().expect("temporary directory");
    for (symbol, geometry) in [
        ("{4,3,4}", "is Euclidean"),
        ("{3,3,5}", "is spherical"),
        ("{7,3,3}", "hyperideal"),
    ] {
        let scene = dir.path().join("bad.hsc");
        std::fs::write(
            &scene,
            format!("{MATERIALS}Objects {{ Honeycomb {symbol}, #edge; }}\n"),
        )
        .expect("temporary directory is writable");
        let out = hscene()
            .args(["check", "--format", "short"])
            .arg(&scene)
            .assert()
            .code(1)
            .get_output()
            .stdout
            .clone();
        let text = String::from_utf8_lossy(&out);
        // Line 5 (after the four lines of MATERIALS), column 21: the `{`.
        assert!(text.contains(":5:21: error"), "{text}");
        assert!(text.contains(geometry), "{text}");
        assert!(text.contains("[HSC0313]"), "{text}");
    }
}

#[test]
fn depth_draws_what_tessellation435_draws() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let scene = |object: &str| {
        format!(
            "Globals {{ from = (0.05, -0.04, 0.02); to = (0.2, 0.1, 0.5); fov = 110; \
             background = (0, 0, 0); ambient = (0.4, 0.4, 0.4); recursion_depth = 0; }}\n\
             {MATERIALS}Lights {{ (0, 0, 0), (4, 4, 4), (3, 3, 3); }}\n\
             Objects {{ {object} }}\n"
        )
    };
    for depth in [1, 2] {
        let (walk, _) = render(
            dir.path(),
            &format!("walk{depth}"),
            &scene(&format!(
                "Honeycomb {{4,3,5}}, #edge, edges = 0.03, depth = {depth};"
            )),
            96,
        );
        let (cells, _) = render(
            dir.path(),
            &format!("cells{depth}"),
            &scene(&format!(
                "Tessellation435 {depth}, #edge, wireframe = 0.03;"
            )),
            96,
        );
        let share = agreement(&walk, &cells, TOLERANCE);
        eprintln!("depth {depth}: {share} of the pixels agree with Tessellation435");
        assert!(share >= AGREE, "depth {depth}: {share} of the pixels agree");
        let lit = walk.iter().filter(|px| px.iter().any(|&c| c > 8)).count();
        assert!(
            lit > walk.len() / 20,
            "depth {depth}: only {lit} pixels lit"
        );
    }
}

/// The rotation by 72° about an edge of the base cube of `{4,3,5}` is a
/// symmetry of the honeycomb (five cubes around every edge): the camera
/// and its light moved by it see the same picture, from inside another
/// cell. The edge runs between the vertices on the rays `(1,1,1)` and
/// `(1,1,-1)`, at ball radius `tanh(R/2)` with `cosh R = φ²/√2`.
#[test]
fn a_symmetry_applied_to_the_camera_leaves_the_picture_unchanged() {
    symmetry_leaves_the_picture_unchanged("");
}

/// The same rotation is in the group `[4,3,5]`, so it is a symmetry of
/// every uniform honeycomb of the group too: the truncated and the
/// runcinated `{4,3,5}` look the same from the moved camera.
#[test]
fn a_symmetry_of_the_group_leaves_uniform_pictures_unchanged() {
    symmetry_leaves_the_picture_unchanged(", rings = (0, 1)");
    symmetry_leaves_the_picture_unchanged(", rings = (0, 3)");
}

/// The picture of `Honeycomb {4,3,5}` with `options` from a camera and
/// light turned about an edge of the base cube by multiples of 72°, and by
/// 36° (not a symmetry).
fn symmetry_leaves_the_picture_unchanged(options: &str) {
    let dir = tempfile::tempdir().expect("temporary directory");
    let phi_sq = (3.0 + 5f64.sqrt()) / 2.0;
    let circumradius = (phi_sq / std::f64::consts::SQRT_2).acosh();
    let k = (0.5 * circumradius).tanh() / 3f64.sqrt();
    let base = |moves: &str| {
        format!(
            "Globals {{ from = %eye; to = %target; up = %up; fov = 100; background = (0, 0, 0); \
             ambient = (0.4, 0.4, 0.4); recursion_depth = 2; }}\n\
             {MATERIALS}Points {{ eye = (0.05, -0.1, 0.08); target = (0.3, 0.2, 0.6); \
             up = (0.05, 0.2, 0.08); a = ({k}, {k}, {k}); b = ({k}, {k}, {m}); }}\n\
             Lights {{ lamp: %eye, (4, 4, 4), (3, 3, 3); }}\n\
             Objects {{ Honeycomb {{4,3,5}}, #edge, edges = 0.03, faces = #glass, vertices = 0.06{options}; }}\n\
             Transformations {{ edge: hline (%a, %b); {moves} }}\n",
            m = -k
        )
    };
    let (still, _) = render(dir.path(), "still", &base(""), 64);
    let turn = 2.0 * std::f64::consts::PI / 5.0;
    for (name, turns) in [("once", 1.0), ("twice", 2.0), ("back", -1.0)] {
        let moves = format!(
            "@camera->Rotate(%edge, {a}); @lamp->Rotate(%edge, {a});",
            a = turns * turn
        );
        let (moved, _) = render(dir.path(), name, &base(&moves), 64);
        let share = agreement(&still, &moved, TOLERANCE);
        eprintln!("{options}: rotation {name}: {share} of the pixels agree");
        assert!(
            share >= AGREE,
            "{options} {name}: {share} of the pixels agree"
        );
    }
    // A rotation that is not a symmetry does change the picture.
    let moves = format!(
        "@camera->Rotate(%edge, {a}); @lamp->Rotate(%edge, {a});",
        a = 0.5 * turn
    );
    let (other, _) = render(dir.path(), "half", &base(&moves), 64);
    let share = agreement(&still, &other, TOLERANCE);
    eprintln!("{options}: half a turn: {share} of the pixels agree");
    assert!(share < 0.9, "{options}: {share}");
}

/// `rings = (0)` is the regular honeycomb, the same picture to the bit;
/// other rings draw another honeycomb of the same group.
#[test]
fn node_zero_ringed_is_the_regular_picture_and_other_rings_are_not() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let scene = |options: &str| {
        format!(
            "Globals {{ from = (0.02, 0.03, 0.01); to = (0.06, 0.09, 0.4); fov = 100; \
             background = (0, 0, 0); ambient = (0.4, 0.4, 0.4); recursion_depth = 3; }}\n\
             {MATERIALS}Lights {{ (0.1, 0.2, -0.1), (4, 4, 4), (3, 3, 3); }}\n\
             Objects {{ Honeycomb {{5,3,4}}, #edge, edges = 0.03, faces = #glass{options}; }}\n"
        )
    };
    let (plain, _) = render(dir.path(), "plain", &scene(""), 64);
    let (zero, _) = render(dir.path(), "zero", &scene(", rings = (0)"), 64);
    assert!(plain == zero);
    let (truncated, _) = render(dir.path(), "truncated", &scene(", rings = (0, 1)"), 64);
    let lit = truncated
        .iter()
        .filter(|px| px.iter().any(|&c| c > 8))
        .count();
    assert!(lit > truncated.len() / 10, "{lit} pixels lit");
    assert!(agreement(&plain, &truncated, TOLERANCE) < 0.9);
}

/// Shadow rays walk the honeycomb and lose light at every face they cross:
/// a ball in the base cell lit from the next cell is brighter behind clear
/// faces than behind opaque ones, and brightest with no faces at all.
#[test]
fn shadow_rays_cross_faces_by_their_transmission() {
    let dir = tempfile::tempdir().expect("temporary directory");
    // The {4,3,5} cube's face `x = +h` is at ball x = 0.26; the light is
    // beyond it, the ball and the eye inside, the light off the picture.
    let scene = |faces: &str| {
        format!(
            "Globals {{ from = (0, 0, -0.2); to = (0, 0, 0); fov = 40; background = (0, 0, 0); \
             ambient = (0, 0, 0); recursion_depth = 0; }}\n\
             BRDFs {{ ball: diffuse = (1, 1, 1); edge: diffuse = (0.5, 0.5, 0.5); \
             clear: diffuse = (0, 0, 0), trans = 0.9; dark: diffuse = (0, 0, 0), trans = 0; }}\n\
             Lights {{ (0.45, 0, 0), (20, 20, 20), (0, 0, 0); }}\n\
             Objects {{ Sphere (0, 0, 0), 0.1, #ball; Honeycomb {{4,3,5}}, #edge, edges = 0.01{faces}; }}\n"
        )
    };
    let brightness = |name: &str, faces: &str| -> f64 {
        let (img, _) = render(dir.path(), name, &scene(faces), 32);
        // The middle of the picture: the lit ball.
        let mut sum = 0.0;
        for y in 12..20 {
            for x in 12..20 {
                sum += f64::from(img[y * 32 + x][0]);
            }
        }
        sum
    };
    let open = brightness("open", "");
    let clear = brightness("clear", ", faces = #clear");
    let dark = brightness("dark", ", faces = #dark");
    eprintln!("ball brightness: no faces {open}, clear faces {clear}, opaque faces {dark}");
    assert!(open > clear && clear > dark, "{open} {clear} {dark}");
    assert!(
        dark < 0.05 * open,
        "opaque faces cast a shadow: {dark} of {open}"
    );
}

/// The looping fly-through of `{4,3,5}` (scenes/video): stepping the whole
/// way to the next cube's centre, twice the inradius, in 25 frames, the
/// last frame is the first (the step is a symmetry of the honeycomb), so
/// the scene's 24 frames of 23/24 of the step loop seamlessly.
#[test]
fn the_flythrough_loops() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let source = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/video/flythrough-435.hsc"),
    )
    .expect("the fly-through scene is in the repository");
    assert!(source.contains("frames = 24;") && source.contains("1.017055"));
    let whole_step = source
        .replace("frames = 24;", "frames = 25;")
        .replace("resolution = (240, 240);", "resolution = (64, 64);")
        .replace("1.017055", "1.061275");
    let scene = dir.path().join("loop.hsc");
    std::fs::write(&scene, whole_step).expect("temporary directory is writable");
    let frame = |k: u32| {
        let out = dir.path().join(format!("frame{k}.png"));
        hscene()
            .arg("render")
            .arg(&scene)
            .args(["--frame", &k.to_string(), "-o"])
            .arg(&out)
            .assert()
            .success();
        pixels(&out)
    };
    let (first, last) = (frame(0), frame(24));
    let share = agreement(&first, &last, 6);
    assert!(share >= AGREE, "first and last frames agree on {share}");
    // And the frames between differ: the camera moves.
    let middle = frame(12);
    assert!(agreement(&first, &middle, 6) < 0.9);
}

/// docs/honeycombs.md, "Measures": from the centre of a `{5,3,4}` cell
/// along its face axis `(1, √5 − 2, 0)` (normalised), one step of twice
/// the inradius (2 × 0.808461) lands on the next cell's centre turned by
/// 36° about the axis (a dodecahedron's opposite face is turned so), and
/// two steps land on a cell's centre looking the same way: the first
/// frame and the looped one agree.
#[test]
fn two_steps_loop_through_a_dodecahedron() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let axis = 5f64.sqrt() - 2.0;
    let frame = |distance: f64, k: u32| {
        let scene = dir.path().join(format!("d{distance}.hsc"));
        let source = format!(
            "Globals {{ resolution = (64, 64); frames = 2; to = (0.4, {to_y}, 0.1); fov = 100; \
             ambient = (0.5, 0.5, 0.5); background = (0, 0, 0); }}\n\
             Transformations {{ axis: hline ((0, 0, 0), (0.5, {ay}, 0)); \
             @camera->Translate(%axis, {distance}), animate; }}\n\
             BRDFs {{ edge: ambient = (0.9, 0.7, 0.35); }}\n\
             Objects {{ Honeycomb {{5,3,4}}, #edge, edges = 0.04; }}",
            to_y = 0.4 * axis,
            ay = 0.5 * axis,
        );
        std::fs::write(&scene, source).expect("temporary directory is writable");
        let out = dir.path().join(format!("d{distance}-{k}.png"));
        hscene()
            .arg("render")
            .arg(&scene)
            .args(["--frame", &k.to_string(), "-o"])
            .arg(&out)
            .assert()
            .success();
        pixels(&out)
    };
    let inradius = 0.808461;
    let start = frame(2.0 * inradius, 0);
    let one_step = frame(2.0 * inradius, 1);
    let two_steps = frame(4.0 * inradius, 1);
    let looped = agreement(&start, &two_steps, 6);
    assert!(looped >= AGREE, "two steps agree on {looped}");
    let turned = agreement(&start, &one_step, 6);
    assert!(
        turned < 0.9,
        "one step agrees on {turned}: it should be turned"
    );
}
