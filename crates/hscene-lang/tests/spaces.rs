//! `space = NAME`: the spaces it accepts, `domain` and `light_reach`, and
//! the checks of a scene in a space, each at the place it is about.

use hgeom::SpaceKind;
use hscene_lang::{Severity, compile};

const MATERIALS: &str = "BRDFs { gold: diffuse = (0.8, 0.6, 0.2); }\n";

/// The diagnostics of `globals` and `rest`, as (code, severity, the text
/// they point at).
fn diagnostics(globals: &str, rest: &str) -> Vec<(String, Severity, String)> {
    let src = format!("Globals {{ {globals} }}\n{MATERIALS}{rest}");
    compile(&src)
        .diagnostics
        .iter()
        .map(|d| {
            (
                d.code.as_str().to_string(),
                d.severity,
                src[d.span.start()..d.span.end()].to_string(),
            )
        })
        .collect()
}

#[test]
fn every_named_space_and_finite_cell_is_accepted() {
    for (text, kind) in [
        ("seifert_weber", "seifert_weber"),
        ("figure_eight", "figure_eight"),
        ("whitehead", "whitehead"),
        ("{4,3,5}", "{4,3,5}"),
        ("{3,3,6}", "{3,3,6}"),
        ("{3,4,4}", "{3,4,4}"),
    ] {
        let src = format!("Globals {{ space = {text}; domain = 0.03, #gold; }}\n{MATERIALS}");
        let c = compile(&src);
        assert!(!c.has_errors(), "{text}: {:#?}", c.diagnostics);
        let space = c.scene.unwrap().settings.space.unwrap();
        assert_eq!(space.kind.to_string(), kind);
        assert_eq!(space.domain.map(|d| d.width), Some(0.03));
        assert_eq!(space.light_reach, hscene_lang::ir::DEFAULT_LIGHT_REACH);
        assert!(matches!(
            space.kind,
            SpaceKind::SeifertWeber
                | SpaceKind::FigureEight
                | SpaceKind::Whitehead
                | SpaceKind::Mirrors(_)
        ));
    }
}

#[test]
fn an_unknown_space_is_refused_with_the_known_ones() {
    let src = format!("Globals {{ space = poincare_sphere; }}\n{MATERIALS}");
    let c = compile(&src);
    let d = c
        .diagnostics
        .iter()
        .find(|d| d.severity == Severity::Error)
        .expect("an error");
    assert_eq!(&src[d.span.start()..d.span.end()], "poincare_sphere");
    assert!(d.message.contains("unknown space"), "{}", d.message);
    let help = d.help.clone().unwrap_or_default();
    for name in hgeom::SPACE_NAMES {
        assert!(help.contains(name), "{help}");
    }
}

#[test]
fn every_regular_honeycomb_gives_a_mirrored_cell_and_other_symbols_are_refused() {
    for (p, q, r) in hgeom::Schlafli::ALL {
        let src =
            format!("Globals {{ space = {{{p},{q},{r}}}; from = (-0.1, 0, 0); }}\n{MATERIALS}");
        let c = compile(&src);
        assert!(!c.has_errors(), "{{{p},{q},{r}}}: {:#?}", c.diagnostics);
    }
    let found = diagnostics("space = {4,3,4};", "");
    assert!(
        found
            .iter()
            .any(|(code, sev, at)| code == "HSC0313" && *sev == Severity::Error && at == "{4,3,4}"),
        "{found:?}"
    );
}

#[test]
fn unbounded_objects_and_area_lights_cannot_be_placed_in_a_space() {
    let found = diagnostics(
        "space = seifert_weber;",
        "Lights { (0, 0, 0.1), (1, 1, 1), (0, 0, 0), radius = 0.05; }\n\
         Objects { Plane (0.2, 0, 0), (0.2, 0.1, 0), (0.2, 0, 0.1), #gold; Sphere (0.1, 0, 0), 0.05, #gold; }",
    );
    let errors: Vec<_> = found
        .iter()
        .filter(|(code, sev, _)| code == "HSC0314" && *sev == Severity::Error)
        .collect();
    assert_eq!(errors.len(), 2, "{found:?}");
    assert!(
        errors.iter().any(|(_, _, at)| at.starts_with("Plane")),
        "{found:?}"
    );
    assert!(
        errors
            .iter()
            .any(|(_, _, at)| at.starts_with("(0, 0, 0.1)")),
        "{found:?}"
    );
}

#[test]
fn what_lies_outside_the_domain_is_folded_in_with_a_warning() {
    // The Seifert-Weber domain's inradius is about 1 (ball radius 0.46):
    // a ball at 0.8 of the way to the absolute is outside.
    let found = diagnostics(
        "space = seifert_weber;",
        "Lights { (0, 0.85, 0), (1, 1, 1), (0, 0, 0); }\n\
         Objects { Sphere (0.8, 0, 0), 0.05, #gold; Sphere (0.1, 0, 0), 0.05, #gold; }",
    );
    let warned: Vec<_> = found
        .iter()
        .filter(|(code, sev, _)| code == "HSC1013" && *sev == Severity::Warning)
        .map(|(_, _, at)| at.as_str())
        .collect();
    assert_eq!(warned.len(), 2, "{found:?}");
    assert!(warned.iter().any(|at| at.starts_with("Sphere (0.8")));
    assert!(warned.iter().any(|at| at.starts_with("(0, 0.85, 0)")));
    // Nothing is behind the eye in a space: the gluing brings it round.
    assert!(
        !found.iter().any(|(code, _, _)| code == "HSC1005"),
        "{found:?}"
    );
}

#[test]
fn domain_and_light_reach_without_a_space_have_no_effect() {
    let found = diagnostics("domain = 0.03, #gold; light_reach = 2;", "");
    let warned: Vec<_> = found
        .iter()
        .filter(|(code, _, _)| code == "HSC1007")
        .map(|(_, _, at)| at.as_str())
        .collect();
    assert_eq!(warned, ["domain = 0.03", "2"], "{found:?}");
}

#[test]
fn domain_and_light_reach_are_checked() {
    for (globals, at) in [
        ("space = whitehead; domain = 0.03;", "domain = 0.03"),
        ("space = whitehead; domain = -1, #gold;", "-1"),
        ("space = whitehead; light_reach = 7;", "7"),
        ("space = whitehead; light_reach = 0;", "0"),
    ] {
        let found = diagnostics(globals, "");
        assert!(
            found
                .iter()
                .any(|(_, sev, text)| *sev == Severity::Error && text == at),
            "{globals}: {found:?}"
        );
    }
}

/// Compiles `globals` with files taken from `scenes/manifolds/`.
fn compile_in_manifolds(globals: &str) -> hscene_lang::Compiled {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/manifolds");
    hscene_lang::compile_with(
        &format!("Globals {{ {globals} }}\n{MATERIALS}"),
        &hscene_lang::Options {
            base_dir: Some(dir),
            frame: 0,
            ..Default::default()
        },
    )
}

#[test]
fn a_space_file_gives_the_manifold_of_its_pairings() {
    let c = compile_in_manifolds("space = \"weeks.json\"; domain = 0.02, #gold;");
    assert!(!c.has_errors(), "{:#?}", c.diagnostics);
    let space = c.scene.unwrap().settings.space.unwrap();
    assert_eq!(space.kind, SpaceKind::Pairings);
    assert_eq!(space.pairings.as_ref().map(|p| p.len()), Some(18));
    assert_eq!(space.build().unwrap().faces().len(), 18);
}

#[test]
fn a_space_file_that_glues_no_manifold_is_refused_at_its_name() {
    let dir = tempfile::tempdir().unwrap();
    let weeks: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../scenes/manifolds/weeks.json"),
        )
        .unwrap(),
    )
    .unwrap();
    let mut pairings = weeks["pairings"].as_array().unwrap().clone();
    pairings.remove(0);
    std::fs::write(
        dir.path().join("broken.json"),
        serde_json::json!({ "pairings": pairings }).to_string(),
    )
    .unwrap();
    let src = "Globals { space = \"broken.json\"; }";
    let c = hscene_lang::compile_with(
        src,
        &hscene_lang::Options {
            base_dir: Some(dir.path().to_path_buf()),
            frame: 0,
            ..Default::default()
        },
    );
    let d = c
        .diagnostics
        .iter()
        .find(|d| d.is_error())
        .expect("an error");
    assert_eq!(d.code.as_str(), "HSC0506");
    assert_eq!(&src[d.span.start()..d.span.end()], "\"broken.json\"");
    assert!(d.message.contains("glue no manifold"), "{}", d.message);
}

#[test]
fn a_space_takes_at_most_sixteen_lights() {
    let lights: String = (0..17)
        .map(|k| {
            format!(
                "({}, 0, 0.05), (0.1, 0.1, 0.1), (0, 0, 0);\n",
                0.01 * f64::from(k)
            )
        })
        .collect();
    let found = diagnostics("space = seifert_weber;", &format!("Lights {{ {lights} }}"));
    let errors: Vec<_> = found
        .iter()
        .filter(|(code, sev, _)| code == "HSC0314" && *sev == Severity::Error)
        .map(|(_, _, at)| at.as_str())
        .collect();
    assert_eq!(
        errors,
        ["(0.16, 0, 0.05), (0.1, 0.1, 0.1), (0, 0, 0);"],
        "{found:?}"
    );
}
