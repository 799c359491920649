//! Criterion benchmark of the scene-language front end: `hscene_lang::compile`
//! (parse, validate, apply transformations, lower, lint) on the thesis's
//! Appendix A scene and on a generated, valid scene of about 1 MB, and the
//! parser alone (`hscene_lang::parse`) on the same two inputs.
//!
//! Throughput is reported in decimal MB/s of source text.
//!
//! `cargo bench --bench check -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_main};

const APPENDIX: &str = include_str!("../scenes/thesis-appendix-a.hsc");

/// Appends one formatted line to a `String`, which cannot fail (writing
/// to a `String` is infallible), so no `Result` is left to unwrap.
macro_rules! push_line {
    ($s:ident, $($arg:tt)*) => {{
        $s.push_str(&format!($($arg)*));
        $s.push('\n');
    }};
}

/// A valid scene of at least `target` bytes: named and anonymous points, two
/// materials, a few lights, spheres, Platonic solids and a polygon, and a
/// rotation and a translation for every point.
fn generated_scene(target: usize) -> String {
    let mut s = String::with_capacity(target + 4096);
    s.push_str(
        "// Generated benchmark scene.\n\
         Globals {\n    recursion_depth = 2;\n    resolution = (640, 480);\n    \
         window_size = (0.15, 0.1125);\n    net_type = 0;\n    from = (0, 0, 0);\n    \
         to = %target;\n    up = (0, 0.1, 0);\n    background = (0.02, 0.02, 0.05);\n    \
         ambient = (0.1, 0.1, 0.1);\n}\n\n\
         BRDFs {\n    matte: ambient = (0.4, 0.8, 0.4), diffuse = (0.4, 0.8, 0.4), \
         specular = (0.7, 0.7, 0.7), alpha = 0.6, trans = 0.3, shininess = 50, refraction = 1;\n    \
         glass: ambient = (0.1, 0.1, 0.1), diffuse = (0.2, 0.2, 0.2), specular = (1, 1, 1), \
         alpha = 0.1, trans = 0.8, shininess = 80, refraction = 1.15;\n}\n\n",
    );
    // Each point costs about 40 + 30 + 60 bytes (declaration, sphere,
    // transformations); 200 points per light.
    let n = target / 130;
    let lights = (n / 200).max(1);
    s.push_str("Points {\n    target = (0, 0, 0.3);\n    a = (0, 0, 0);\n    b = (0, 0, 0.1);\n    c = (0, 0.1, 0);\n");
    for i in 0..n {
        let t = i as f64 * 0.618_033_988_749_895;
        let (x, y) = (0.2 * t.sin(), 0.2 * t.cos());
        let z = 0.3 + 0.2 * ((i % 97) as f64 / 97.0);
        push_line!(s, "    p{i} = ({x:.6}, {y:.6}, {z:.6});");
    }
    for i in 0..lights {
        let t = i as f64 * 0.7;
        push_line!(
            s,
            "    ({:.4}, {:.4}, -0.05);",
            0.3 * t.sin(),
            0.3 * t.cos()
        );
    }
    s.push_str("    (0.05, 0, 0.3); (0.05, 0.05, 0.3); (0, 0.05, 0.3);\n}\n\nLights {\n");
    for i in 0..lights {
        push_line!(
            s,
            "    %{}, (0.35, 0.35, 0.35), (0.7, 0.7, 0.7);",
            n + 5 + i
        );
    }
    s.push_str("}\n\nObjects {\n    Dodecahedron 0.045, #glass;\n    Icosahedron 0.03, #matte;\n");
    push_line!(
        s,
        "    Polygon (%target, %{}, %{}, %{}), #matte;",
        n + lights + 5,
        n + lights + 6,
        n + lights + 7
    );
    for i in 0..n {
        let m = if i % 3 == 0 { "glass" } else { "matte" };
        push_line!(s, "    Sphere %p{i}, 0.004, #{m};");
    }
    s.push_str("}\n\nTransformations {\n    hline (%a, %b);\n    axis: hline (%a, %c);\n");
    for i in 0..n {
        push_line!(s, "    %p{i}->Rotate(%1, -0.0{});", i % 10);
        push_line!(s, "    %p{i}->Translate(%axis);");
    }
    s.push_str("}\n");
    s
}

fn check(c: &mut Criterion) {
    let big = generated_scene(1_000_000);
    for (name, src) in [("appendix-a", APPENDIX), ("generated", big.as_str())] {
        let compiled = hscene_lang::compile(src);
        assert!(
            !compiled.has_errors(),
            "{name}: {:?}",
            &compiled.diagnostics[..compiled.diagnostics.len().min(3)]
        );
    }
    eprintln!(
        "generated scene: {} bytes, {} lines",
        big.len(),
        big.lines().count()
    );

    let inputs = [
        ("thesis-appendix-a", APPENDIX),
        ("generated-1MB", big.as_str()),
    ];
    per_byte(c, "compile", &inputs, hscene_lang::compile);
    // The parser alone (scanner and pest), to separate it from lowering.
    per_byte(c, "parse", &inputs, hscene_lang::parse);
}

/// The benchmark group `group`: `run` on each named input, in bytes per
/// second.
fn per_byte<T>(c: &mut Criterion, group: &str, inputs: &[(&str, &str)], run: impl Fn(&str) -> T) {
    let mut group = c.benchmark_group(group);
    for &(name, src) in inputs {
        group.throughput(Throughput::BytesDecimal(src.len() as u64));
        group.bench_function(name, |b| b.iter(|| run(black_box(src))));
    }
    group.finish();
}

// `criterion_group!` declares an undocumented `pub fn`; in a private module
// it is no public item for `missing_docs` to flag.
mod group {
    criterion::criterion_group!(benches, super::check);
}
criterion_main!(group::benches);
