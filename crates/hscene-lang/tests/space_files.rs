//! Space files that are not manifolds, or not what they claim: each
//! refused (or warned about) with a message that names the face, says what
//! was measured and never repeats the file's text (issue 49, class 9), and
//! no misleading diagnostic after a refusal. And the `"volume"` check
//! (HSC1014).

use hscene_lang::{Compiled, Options, compile_with};

const MATERIALS: &str = "BRDFs { gold: diffuse = (0.8, 0.6, 0.2); }\n";

/// The scene `globals` (and materials) compiled beside the space file
/// `text`, written as `space.json`.
fn compile_beside(json: &str, globals: &str) -> Compiled {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("space.json"), json).unwrap();
    let src = format!("Globals {{ space = \"space.json\"; {globals} }}\n{MATERIALS}");
    compile_with(
        &src,
        &Options {
            base_dir: Some(dir.path().to_path_buf()),
            ..Default::default()
        },
    )
}

/// The HSC0506 message, which must be there.
fn refusal(c: &Compiled) -> String {
    c.diagnostics
        .iter()
        .find(|d| d.code.as_str() == "HSC0506")
        .map(|d| d.message.clone())
        .unwrap_or_else(|| panic!("no HSC0506: {:#?}", c.diagnostics))
}

/// The Weeks manifold's pairings (time first), from scenes/manifolds.
fn weeks() -> Vec<[[f64; 4]; 4]> {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/manifolds/weeks.json"),
    )
    .unwrap();
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    serde_json::from_value(doc["pairings"].clone()).unwrap()
}

fn file(pairings: &[[[f64; 4]; 4]]) -> String {
    serde_json::json!({ "pairings": pairings }).to_string()
}

/// A boost along x by `d`, time first.
fn boost(d: f64) -> [[f64; 4]; 4] {
    let (c, s) = (d.cosh(), d.sinh());
    [
        [c, s, 0.0, 0.0],
        [s, c, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

#[test]
fn huge_entries_are_refused_for_their_size_with_the_face() {
    // 1e200 entries once passed the Lorentz test as inf <= inf.
    let mut p = weeks();
    p[2] = p[2].map(|row| row.map(|x| x * 1e200));
    let m = refusal(&compile_beside(&file(&p), ""));
    assert!(m.contains("face 3") && m.contains("more than"), "{m}");
    assert!(!m.contains("fixes the origin"), "{m}");
}

#[test]
fn scaled_or_far_pairings_are_not_said_to_fix_the_origin() {
    let mut scaled = weeks();
    scaled[4] = scaled[4].map(|row| row.map(|x| x * 1e300));
    let mut far = weeks();
    far[5] = boost(40.0);
    for (p, face) in [(scaled, "face 5"), (far, "face 6")] {
        let m = refusal(&compile_beside(&file(&p), ""));
        assert!(m.contains(face), "{m}");
        assert!(!m.contains("fixes the origin"), "{m}");
    }
}

#[test]
fn a_redundant_face_is_named_as_redundant() {
    // A pairing and its inverse whose bisectors lie beyond the domain: the
    // translation by 3 along x, where the Weeks domain (inradius < 1)
    // has long ended.
    let mut p = weeks();
    p.push(boost(3.0));
    p.push(boost(-3.0));
    let m = refusal(&compile_beside(&file(&p), ""));
    assert!(m.contains("face 19") && m.contains("redundant"), "{m}");
    assert!(!m.contains("open to the absolute"), "{m}");
}

#[test]
fn a_tiny_domain_is_not_called_open_to_the_absolute() {
    // The eight translations by 1e-9 along the axes and diagonals' pairs:
    // a domain far smaller than the vertices can be told apart.
    let tiny: f64 = 1e-9;
    let mut p = Vec::new();
    for axis in 0..3 {
        for sign in [1.0, -1.0] {
            let mut m = [[0.0; 4]; 4];
            for (i, row) in m.iter_mut().enumerate() {
                row[i] = 1.0;
            }
            let (c, s) = (tiny.cosh(), sign * tiny.sinh());
            m[0][0] = c;
            m[axis + 1][axis + 1] = c;
            m[0][axis + 1] = s;
            m[axis + 1][0] = s;
            p.push(m);
        }
    }
    let m = refusal(&compile_beside(&file(&p), ""));
    assert!(!m.contains("open to the absolute"), "{m}");
    assert!(m.contains("face 1"), "{m}");
}

#[test]
fn space_file_errors_do_not_quote_the_file() {
    for text in [
        r#"{"pairings": [], "password": "hunter2"}"#,
        r#"{"pairings": [[["hunter2", 0, 0, 0]]]}"#,
        r#"{"pairings": [], "time": "hunter2"}"#,
        "{\"pairings\": hunter2",
    ] {
        let m = refusal(&compile_beside(text, ""));
        assert!(!m.contains("hunter2"), "{m}");
    }
}

#[test]
fn after_a_refused_space_file_domain_is_not_said_to_have_no_effect() {
    let mut p = weeks();
    p.remove(0);
    let c = compile_beside(&file(&p), "domain = 0.03, #gold; light_reach = 2;");
    refusal(&c);
    assert!(
        !c.diagnostics.iter().any(|d| d.code.as_str() == "HSC1007"),
        "{:#?}",
        c.diagnostics
    );
}

#[test]
fn after_refused_frames_no_lint_says_one_frame() {
    let src = format!(
        "Globals {{ frames = 100001; }}\n{MATERIALS}Objects {{ Sphere (0, 0, 0), 0.1, #gold, Translate((1, 0, 0), 0.1), animate; }}"
    );
    let c = hscene_lang::compile(&src);
    assert!(c.has_errors());
    assert!(
        !c.diagnostics
            .iter()
            .any(|d| d.code.as_str() == "HSC1008" || d.message.contains("one frame")),
        "{:#?}",
        c.diagnostics
    );
}

#[test]
fn a_volume_that_is_not_the_domains_is_warned_about() {
    let p = weeks();
    let right = serde_json::json!({ "pairings": p, "volume": 0.9427073627769277 }).to_string();
    let c = compile_beside(&right, "");
    assert!(!c.has_errors(), "{:#?}", c.diagnostics);
    assert!(!c.diagnostics.iter().any(|d| d.code.as_str() == "HSC1014"));
    let wrong = serde_json::json!({ "pairings": p, "volume": "0.9427083" }).to_string();
    let c = compile_beside(&wrong, "");
    let d = c
        .diagnostics
        .iter()
        .find(|d| d.code.as_str() == "HSC1014")
        .expect("HSC1014");
    assert!(d.message.contains("0.9427083"), "{}", d.message);
    assert!(c.scene.is_some());
}
