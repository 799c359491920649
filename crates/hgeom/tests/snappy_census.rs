//! Dirichlet domains from SnapPy's censuses (closed and cusped manifolds,
//! knot and link exteriors), written by `tests/snappy_census.py
//! --fixtures` from `snappy.ManifoldHP` with their entries rounded to 25
//! digits: every one is accepted, and its domain's volume is SnapPy's
//! `M.volume()` to 1e-9 relative (measured: about 1e-13).

use hgeom::QuotientSpace;
use hgeom::glam::DMat4;

/// A number of a space file: a JSON number or a decimal string.
fn number(v: &serde_json::Value) -> f64 {
    match v {
        serde_json::Value::String(s) => s.replace(' ', "").parse().unwrap(),
        other => other.as_f64().unwrap(),
    }
}

/// The pairings (time coordinate last) and the volume of a space file.
fn load(path: &std::path::Path) -> (Vec<DMat4>, f64) {
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let pairings = doc["pairings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| {
            // Row r, column c of the time-last matrix is row (r+1)%4,
            // column (c+1)%4 of the time-first one.
            let at = |r: usize, c: usize| number(&m[(r + 1) % 4][(c + 1) % 4]);
            DMat4::from_cols_array_2d(&std::array::from_fn(|c| std::array::from_fn(|r| at(r, c))))
        })
        .collect();
    (pairings, number(&doc["volume"]))
}

fn fixtures() -> Vec<std::path::PathBuf> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snappy");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

#[test]
fn snappy_census_domains_are_accepted_with_their_volumes() {
    let files = fixtures();
    assert!(files.len() >= 15, "{} fixtures", files.len());
    let mut worst = 0.0f64;
    for path in &files {
        let (pairings, expected) = load(path);
        let space = QuotientSpace::from_pairings(&pairings)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let volume = space.volume().unwrap();
        let error = (volume - expected).abs() / expected;
        let d = space.domain().unwrap();
        println!(
            "{}: {} faces, {} vertices ({} ideal), volume {volume:.15} ({error:.1e})",
            path.file_name().unwrap().to_string_lossy(),
            d.faces().len(),
            d.vertices().len(),
            d.ideal().iter().filter(|i| **i).count()
        );
        assert!(error < 1e-9, "{}: {volume} vs {expected}", path.display());
        worst = worst.max(error);
    }
    println!("worst volume error {worst:.1e}");
}
