//! Replays the fuzzing corpus (`fuzz/corpus/compile/`) through `compile`, with
//! the same checks as the fuzz target, so that CI exercises every input the
//! fuzzer found interesting without a fuzzing toolchain. See `fuzz/README.md`.

use std::path::Path;

use hscene_lang::{LineIndex, compile};

/// The checks of `fuzz/fuzz_targets/compile.rs`.
fn check(name: &str, data: &[u8]) {
    let src = String::from_utf8_lossy(data);
    let compiled = compile(&src);
    let index = LineIndex::new(&src);
    let mut prev = (0, 0);
    for d in &compiled.diagnostics {
        assert!(
            d.span.start() <= d.span.end() && d.span.end() <= src.len(),
            "{name}: {d:?}"
        );
        assert!(
            src.is_char_boundary(d.span.start()) && src.is_char_boundary(d.span.end()),
            "{name}: {d:?}"
        );
        assert!(
            (d.span.start(), d.span.end()) >= prev,
            "{name}: out of order"
        );
        prev = (d.span.start(), d.span.end());
        let start = index.line_col(d.span.start());
        let end = index.line_col(d.span.end());
        assert!(
            start.0 >= 1 && start.1 >= 1 && end >= start,
            "{name}: {d:?}"
        );
        assert!(end.0 <= index.line_count(), "{name}: {d:?}");
        assert_eq!(d.severity, d.code.severity(), "{name}: {d:?}");
        assert!(!d.message.is_empty(), "{name}: {d:?}");
    }
    assert_eq!(
        compiled.scene.is_some(),
        !compiled.has_errors(),
        "{name}: scene present iff no error"
    );
}

#[test]
fn fuzz_corpus_replays_without_panics() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus/compile");
    let mut files = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_file() {
            let data = std::fs::read(&path).unwrap();
            check(&path.display().to_string(), &data);
            files += 1;
        }
    }
    assert!(
        files >= 50,
        "only {files} corpus files in {}",
        dir.display()
    );
}

#[test]
fn scenes_and_broken_scenes_replay_too() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in [root.join("../../scenes"), root.join("tests/broken")] {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "hsc") {
                let data = std::fs::read(&path).unwrap();
                check(&path.display().to_string(), &data);
                // Every prefix, too: a file cut off anywhere must still work.
                for cut in (0..data.len()).step_by(7) {
                    check(&path.display().to_string(), &data[..cut]);
                }
            }
        }
    }
}

/// Replays `fuzz/corpus/mesh/` with the checks of
/// `fuzz/fuzz_targets/mesh.rs`: the first byte picks the format, the second
/// the layout size, the rest is the file.
#[test]
fn mesh_fuzz_corpus_replays_without_panics() {
    use hscene_lang::mesh_file::{MeshFormat, parse};
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus/mesh");
    let mut files = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let data = std::fs::read(&path).unwrap();
        files += 1;
        let [kind, size, file @ ..] = &data[..] else {
            continue;
        };
        let format = if kind % 2 == 0 {
            MeshFormat::Obj
        } else {
            MeshFormat::Ply
        };
        match parse(format, file) {
            Err(e) => {
                let message = e.to_string();
                assert!(!message.contains('\n'), "{}: {message:?}", path.display());
            }
            Ok(mesh) => {
                let n = mesh.positions.len();
                assert!(mesh.triangles.iter().flatten().all(|&i| (i as usize) < n));
                if let Some(points) = mesh.layout(0.07 * f64::from(*size).max(1.0)) {
                    assert!(points.iter().all(|p| p.coords().length() < 1.0));
                }
            }
        }
    }
    assert!(files >= 5, "only {files} corpus files in {}", dir.display());
}
