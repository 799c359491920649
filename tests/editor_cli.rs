//! The editor and terminal conventions of the binary: `fmt`, `check -`,
//! `--deny-warnings`, `--color`/NO_COLOR, `explain`, `completions`, `man`.

use std::fs;

use assert_cmd::Command;
use predicates::prelude::*;

fn hscene() -> Command {
    let mut cmd = Command::cargo_bin("hscene").expect("binary is built by cargo test");
    cmd.env_remove("NO_COLOR");
    cmd
}

const UGLY: &str = "Points{(0,0,0.2) ; // eye\n(0.1,0,0);}\nGlobals{from=%1;to=(0,0,0);}\n\
                    BRDFs{diffuse=(1,0,0);}Objects{Sphere %2,0.05,#1;}";

const WARNS: &str = "Points { (0,0,0.2); (0.1,0,0); (0,0.1,0); } Globals { from = %1; to = (0,0,0); } \
                     BRDFs { diffuse = (1,0,0); } Objects { Sphere %2, 0.05, #1; }";

#[test]
fn fmt_stdin_to_stdout_and_check() {
    let out = hscene()
        .args(["fmt", "-"])
        .write_stdin(UGLY)
        .assert()
        .success();
    let formatted = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    assert_eq!(formatted, hscene_lang::format(UGLY).unwrap());
    assert!(
        formatted.contains("    (0, 0, 0.2); // eye\n"),
        "{formatted}"
    );
    // `--check` on stdin: status only.
    hscene()
        .args(["fmt", "--check", "-"])
        .write_stdin(UGLY)
        .assert()
        .code(1)
        .stdout("");
    hscene()
        .args(["fmt", "--check", "-"])
        .write_stdin(formatted)
        .assert()
        .success();
}

#[test]
fn fmt_files_in_place() {
    let dir = tempfile::tempdir().unwrap();
    let ugly = dir.path().join("ugly.hsc");
    let fine = dir.path().join("fine.hsc");
    fs::write(&ugly, UGLY).unwrap();
    fs::write(&fine, hscene_lang::format(UGLY).unwrap()).unwrap();
    hscene()
        .args(["fmt", "--check"])
        .arg(&ugly)
        .arg(&fine)
        .assert()
        .code(1)
        .stdout(
            predicate::str::contains("would reformat").and(predicate::str::contains("ugly.hsc")),
        )
        .stdout(predicate::str::contains("fine.hsc").not());
    assert_eq!(
        fs::read_to_string(&ugly).unwrap(),
        UGLY,
        "--check changed the file"
    );
    hscene().arg("fmt").arg(&ugly).arg(&fine).assert().success();
    assert_eq!(
        fs::read_to_string(&ugly).unwrap(),
        fs::read_to_string(&fine).unwrap()
    );
    // Nothing but the two scenes is left in the directory.
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
}

#[test]
fn fmt_refuses_syntax_errors_and_keeps_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.hsc");
    let text = "Objects { Sphere %3, 0.05 #1; }\n";
    fs::write(&bad, text).unwrap();
    hscene()
        .arg("fmt")
        .arg(&bad)
        .assert()
        .code(1)
        .stderr(predicate::str::contains("HSC0001").and(predicate::str::contains("not formatted")));
    assert_eq!(fs::read_to_string(&bad).unwrap(), text);
    hscene()
        .args(["fmt", "-", "--stdin-filename", "mine.hsc"])
        .write_stdin(text)
        .assert()
        .code(1)
        .stdout("")
        .stderr(predicate::str::contains("mine.hsc:1:"));
}

#[test]
fn check_reads_stdin_with_a_file_name_for_messages_and_meshes() {
    hscene()
        .args(["check", "--format", "short", "-"])
        .write_stdin("Pionts { }")
        .assert()
        .code(1)
        .stdout(predicate::str::starts_with("<stdin>:1:1: error:"));
    hscene()
        .args([
            "check",
            "--format",
            "short",
            "--stdin-filename",
            "scenes/x.hsc",
            "-",
        ])
        .write_stdin("Pionts { }")
        .assert()
        .code(1)
        .stdout(predicate::str::starts_with("scenes/x.hsc:1:1: error:"));
    // Relative mesh names resolve from the --stdin-filename's directory.
    let scene = fs::read_to_string("scenes/thesis/fig28-bunny.hsc").unwrap();
    hscene()
        .args([
            "check",
            "--stdin-filename",
            "scenes/thesis/fig28-bunny.hsc",
            "-",
        ])
        .write_stdin(scene.clone())
        .assert()
        .success();
    hscene()
        .args(["check", "--format", "short", "-"])
        .write_stdin(scene)
        .assert()
        .code(1)
        .stdout(predicate::str::contains("HSC0501"));
}

#[test]
fn deny_warnings_fails_on_warnings() {
    hscene()
        .args(["check", "--format", "short", "-"])
        .write_stdin(WARNS)
        .assert()
        .success()
        .stdout(predicate::str::contains("HSC1001"));
    hscene()
        .args(["check", "--deny-warnings", "--format", "short", "-"])
        .write_stdin(WARNS)
        .assert()
        .code(1);
}

#[test]
fn color_choice_and_no_color() {
    let human = |color: &str, no_color: Option<&str>| {
        let mut cmd = hscene();
        cmd.args(["--color", color, "check", "--format", "human", "-"])
            .write_stdin(WARNS);
        if let Some(v) = no_color {
            cmd.env("NO_COLOR", v);
        }
        let out = cmd.assert().success();
        String::from_utf8(out.get_output().stdout.clone()).unwrap()
    };
    assert!(human("always", None).contains('\u{1b}'));
    assert!(!human("never", None).contains('\u{1b}'));
    // Not a terminal: auto means no colour, whatever NO_COLOR says.
    assert!(!human("auto", None).contains('\u{1b}'));
    // NO_COLOR does not override an explicit `always`.
    assert!(human("always", Some("1")).contains('\u{1b}'));
}

#[test]
fn explain_prints_the_documented_text() {
    let docs = fs::read_to_string("docs/diagnostics.md").unwrap();
    let row = docs.lines().find(|l| l.starts_with("| HSC0305 |")).unwrap();
    let meaning = row.split(" | ").nth(3).unwrap();
    hscene()
        .args(["explain", "HSC0305"])
        .assert()
        .success()
        .stdout(predicate::str::starts_with(
            "HSC0305 (error): NonPlanarPolygon",
        ))
        .stdout(predicate::str::contains(meaning));
    hscene().args(["explain", "hsc1001"]).assert().success();
    hscene()
        .args(["explain", "HSC9999"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("no diagnostic code"));
}

#[test]
fn completions_and_man_page_come_from_the_cli_definition() {
    hscene()
        .args(["completions", "bash"])
        .assert()
        .success()
        .stdout(
            predicate::str::contains("_hscene()").and(predicate::str::contains("--stdin-filename")),
        );
    hscene()
        .args(["completions", "zsh"])
        .assert()
        .success()
        .stdout(predicate::str::contains("#compdef hscene"));
    hscene()
        .arg("man")
        .assert()
        .success()
        .stdout(predicate::str::contains(".TH hscene").and(predicate::str::contains("explain")));
}
