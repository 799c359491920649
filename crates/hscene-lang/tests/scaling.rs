//! Pathological inputs: deep nesting, comment openers, long lines, many
//! statements and a megabyte of garbage. Each must come back with
//! diagnostics — no panic, no stack overflow — and with the diagnostics that
//! say what is wrong. Nothing here measures time (see `benches/check.rs`);
//! a super-linear parser shows up as a test that never ends.

use hscene_lang::{Code, Compiled, LineIndex, compile};

const N: usize = 100_000;

/// Compiles `src` and checks what every result must satisfy: spans inside
/// the source and on character boundaries, diagnostics in source order, a
/// scene exactly when there is no error, and line/column lookup of every span.
#[track_caller]
fn compile_checked(src: &str) -> Compiled {
    let c = compile(src);
    let index = LineIndex::new(src);
    let mut prev = (0, 0);
    for d in &c.diagnostics {
        assert!(
            d.span.start() <= d.span.end() && d.span.end() <= src.len(),
            "{d:?}"
        );
        assert!(
            src.is_char_boundary(d.span.start()) && src.is_char_boundary(d.span.end()),
            "{d:?}"
        );
        assert!(
            (d.span.start(), d.span.end()) >= prev,
            "diagnostics out of order"
        );
        prev = (d.span.start(), d.span.end());
        let (l1, c1) = index.line_col(d.span.start());
        let (l2, c2) = index.line_col(d.span.end());
        assert!(l1 >= 1 && c1 >= 1 && (l2, c2) >= (l1, c1));
        assert!(!d.message.is_empty());
    }
    assert_eq!(c.scene.is_some(), !c.has_errors());
    c
}

fn count(c: &Compiled, code: Code) -> usize {
    c.diagnostics.iter().filter(|d| d.code == code).count()
}

/// A deterministic pseudo-random generator (xorshift64*), so the garbage is
/// the same on every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

// ----- nesting ------------------------------------------------------------

#[test]
fn hundred_thousand_parentheses_in_a_statement() {
    let src = format!("Points {{ {}0,0,0{}; }}", "(".repeat(N), ")".repeat(N));
    let c = compile_checked(&src);
    assert_eq!(count(&c, Code::NestingTooDeep), 1, "{:?}", c.diagnostics);
    // The guard points at the first `(` that is too deep: the 65th.
    let d = &c.diagnostics[0];
    assert_eq!(d.code, Code::NestingTooDeep);
    let start = "Points { ".len() + 64;
    assert_eq!((d.span.start(), d.span.end()), (start, start + 1));
}

#[test]
fn hundred_thousand_unclosed_parentheses() {
    let src = format!("Points {{ {}", "(".repeat(N));
    let c = compile_checked(&src);
    assert_eq!(count(&c, Code::NestingTooDeep), 1);
    // The section is not closed either.
    assert!(count(&c, Code::Syntax) >= 1);
}

#[test]
fn hundred_thousand_parentheses_outside_sections() {
    for src in ["(".repeat(N), ")".repeat(N), "()".repeat(N)] {
        let c = compile_checked(&src);
        // One "expected a section" for the whole run of junk.
        assert_eq!(c.diagnostics.len(), 1, "{:?}", c.diagnostics);
        assert_eq!(c.diagnostics[0].code, Code::Syntax);
        assert_eq!(c.diagnostics[0].span.len(), src.len());
    }
}

#[test]
fn many_statements_at_the_nesting_limit() {
    // 64 levels is allowed: pest must not backtrack exponentially on it,
    // whether the statement is well formed, cut off, or broken at the bottom.
    let deep = |inner: &str| format!("{}{inner}{}", "(".repeat(64), ")".repeat(64));
    let mut src = String::from("Points {\n");
    for _ in 0..200 {
        src.push_str(&deep("0,0,0"));
        src.push_str(";\n");
        src.push_str(&"(".repeat(64));
        src.push_str("0,0,0;\n");
        src.push_str(&deep("0,0,,0"));
        src.push_str(";\n");
        src.push_str(&deep("0 0 0"));
        src.push_str(";\n");
    }
    src.push_str("}\n");
    let c = compile_checked(&src);
    assert_eq!(count(&c, Code::NestingTooDeep), 0);
    // Three syntax errors per round; the nested tuples that parse are
    // reported as not being points.
    assert_eq!(count(&c, Code::Syntax), 600, "{:?}", &c.diagnostics[..4]);
    assert!(count(&c, Code::WrongArity) + count(&c, Code::WrongType) >= 200);
}

#[test]
fn deep_nesting_inside_object_arguments() {
    let src = format!(
        "BRDFs {{ diffuse = (1,1,1); }} Points {{ (0,0,0.3); }}\nObjects {{ Sphere %1, {}0.1{}, #1; Polygon {}%1{}, #1; }}",
        "(".repeat(N),
        ")".repeat(N),
        "(".repeat(N / 2),
        ")".repeat(N / 2),
    );
    let c = compile_checked(&src);
    assert_eq!(count(&c, Code::NestingTooDeep), 2, "{:?}", c.diagnostics);
}

#[test]
fn hundred_thousand_braces() {
    for src in [
        "{".repeat(N),
        "}".repeat(N),
        "{}".repeat(N),
        "Points {".repeat(N),
        "Points { ".to_string() + &"{".repeat(N),
        "Points { (0,0,0".to_string() + &"{".repeat(N) + &"}".repeat(N),
        "a{b{".repeat(N / 2),
    ] {
        let c = compile_checked(&src);
        assert!(c.has_errors(), "{}", &src[..20]);
    }
    // Every unclosed section is reported, each once.
    let c = compile_checked(&"Points {".repeat(1000));
    assert_eq!(count(&c, Code::Syntax), 1000);
}

// ----- comments -----------------------------------------------------------

#[test]
fn hundred_thousand_comment_openers() {
    let src = format!("Points {{ (0,0,0.3); }}\n{}", "/* ".repeat(N));
    let c = compile_checked(&src);
    // The first `/*` swallows the rest of the file: one diagnostic.
    assert_eq!(count(&c, Code::UnterminatedComment), 1);
    // No unused-point warning: the comment may hide its uses.
    assert_eq!(c.diagnostics.len(), 1, "{:?}", c.diagnostics);
    // `/*/*/*...`: `/*/*/` is a closed comment, then `*/*/*...` is junk and
    // the last `/*` (or `/`) is left over.
    let src = format!("Points {{ (0,0,0.3); }}\n{}", "/*".repeat(N));
    let c = compile_checked(&src);
    assert!(c.has_errors());
    assert!(c.diagnostics.len() <= 3, "{:?}", c.diagnostics);
}

#[test]
fn hundred_thousand_comment_openers_inside_a_section() {
    let src = format!("Points {{ (0,0,0.3); {}", "/*".repeat(N));
    let c = compile_checked(&src);
    assert_eq!(count(&c, Code::UnterminatedComment), 1);
    // The unclosed section is a consequence of the comment and not reported.
    assert_eq!(count(&c, Code::Syntax), 0, "{:?}", c.diagnostics);
}

#[test]
fn hundred_thousand_closed_comments() {
    let valid =
        "BRDFs { diffuse = (1,1,1); } Points { (0,0,0.3); } Objects { Sphere %1, 0.1, #1; }";
    for filler in ["/**/", "/* */\n", "// x\n", "/*/**/", "/*//*/"] {
        let src = format!("{}{valid}{}", filler.repeat(N), filler.repeat(N));
        let c = compile_checked(&src);
        assert!(c.diagnostics.is_empty(), "{filler:?}: {:?}", c.diagnostics);
    }
    // Comments between every token of a statement.
    let stmt = "Sphere /**/ %1 /**/ , /**/ 0.1 /**/ , /**/ #1 /**/ ;\n".repeat(N / 10);
    let src =
        format!("BRDFs {{ diffuse = (1,1,1); }} Points {{ (0,0,0.3); }} Objects {{ {stmt} }}");
    let c = compile_checked(&src);
    assert!(c.diagnostics.is_empty(), "{:?}", &c.diagnostics[..1]);
    assert_eq!(c.scene.unwrap().objects.len(), N / 10);
}

#[test]
fn comment_star_runs() {
    // `*` runs that almost close a comment, and `/` runs that almost open one.
    let src = format!(
        "/*{}/ Points {{ (0,0,0.3); }} {}",
        "*".repeat(N),
        "/".repeat(N)
    );
    let c = compile_checked(&src);
    // The comment ends at the last `*` + `/`; the `/`s make a line comment.
    assert!(
        c.diagnostics.iter().all(|d| !d.is_error()),
        "{:?}",
        c.diagnostics
    );
}

// ----- long lines and tokens ------------------------------------------------

#[test]
fn a_megabyte_long_tuple() {
    let items = vec!["0.125"; 150_000].join(",");
    let src = format!("Points {{ ({items}); }}");
    assert!(src.len() > 900_000);
    let c = compile_checked(&src);
    assert_eq!(count(&c, Code::WrongArity), 1, "{:?}", c.diagnostics);
}

#[test]
fn a_megabyte_long_statement_with_an_error_at_the_end() {
    let items = vec!["0.125"; 150_000].join(",");
    let src = format!("Points {{ ({items},); }}");
    let c = compile_checked(&src);
    assert_eq!(c.diagnostics.len(), 1, "{:?}", c.diagnostics);
    let d = &c.diagnostics[0];
    assert_eq!(d.code, Code::Syntax);
    assert_eq!(&src[d.span.start()..d.span.end()], ")");
    assert_eq!(
        LineIndex::new(&src).line_col(d.span.start()),
        (1, src.len() - 3)
    );
}

#[test]
fn a_megabyte_long_clause_list() {
    let clauses = vec!["shininess = 1"; 70_000].join(", ");
    let src = format!("BRDFs {{ {clauses}; }}");
    let c = compile_checked(&src);
    // Every repetition after the first is a duplicate key: the first
    // MAX_KEPT_DIAGNOSTICS kept, the rest counted (with the lints that
    // come after them, here the unused material).
    assert_eq!(
        count(&c, Code::DuplicateKey),
        hscene_lang::MAX_KEPT_DIAGNOSTICS
    );
    assert_eq!(c.omitted.errors, 0);
    assert!(c.omitted.warnings >= 70_000 - 1 - hscene_lang::MAX_KEPT_DIAGNOSTICS);
}

#[test]
fn megabyte_tokens() {
    let long = 1 << 20;
    let digits = "9".repeat(long);
    let name = "a".repeat(long);
    for (src, code) in [
        (format!("Points {{ ({digits},0,0); }}"), Code::InvalidNumber),
        (
            format!("Points {{ (1.{digits},0,0); }}"),
            Code::PointOutsideAbsolute,
        ),
        (
            format!("Points {{ (0,0,0); }} Lights {{ %{digits}, (1,1,1), (1,1,1); }}"),
            Code::InvalidNumber,
        ),
        (
            format!("Points {{ (0,0,0); }} Lights {{ %{name}, (1,1,1), (1,1,1); }}"),
            Code::UndefinedPoint,
        ),
        (format!("{name} {{ }}"), Code::UnknownSection),
        (format!("Globals {{ {name} = 1; }}"), Code::UnknownKey),
        (
            format!("Points {{ (1{},0,0); }}", "e".repeat(long)),
            Code::Syntax,
        ),
        (name.clone(), Code::Syntax),
    ] {
        let c = compile_checked(&src);
        assert!(count(&c, code) >= 1, "{code:?} not in {:?}", c.diagnostics);
        // The parser's messages quote long tokens shortened. (Those of the
        // later passes quote names in full, however long.)
        for d in c.diagnostics.iter().filter(|d| d.code.as_str() < "HSC0100") {
            assert!(d.message.len() < 400, "{}", &d.message[..400]);
        }
    }
}

#[test]
fn a_megabyte_on_one_line_without_newlines() {
    // LineIndex on one huge line; columns count characters.
    let src = format!("Points {{ {}(2,0,0); }}", "/*é*/".repeat(N));
    let c = compile_checked(&src);
    assert_eq!(c.diagnostics.len(), 1);
    let (line, col) = LineIndex::new(&src).line_col(c.diagnostics[0].span.start());
    assert_eq!((line, col), (1, "Points { ".len() + 5 * N + 1));
}

// ----- many statements ----------------------------------------------------

#[test]
fn ten_thousand_objects_and_transformations() {
    let n = 10_000;
    // The window shows every sphere (no HSC1005 for those outside it).
    let mut src = String::from(
        "Globals { to = (0,0,0.5); window_size = (1.2, 1.2); }\nBRDFs { diffuse = (1,1,1); }\nPoints {\n",
    );
    for i in 0..n {
        let x = (i % 100) as f64 * 0.004 - 0.2;
        let y = (i / 100) as f64 * 0.004 - 0.2;
        src.push_str(&format!("  p{i} = ({x}, {y}, 0.5);\n"));
    }
    src.push_str("  a = (0,0,0); b = (0,0.1,0);\n}\nLights { %a, (1,1,1), (1,1,1); }\nObjects {\n");
    for i in 0..n {
        src.push_str(&format!("  Sphere %p{i}, 0.001, #1;\n"));
    }
    src.push_str("}\nTransformations {\n  hline (%a, %b);\n");
    for i in 0..n {
        src.push_str(&format!("  %p{i}->Rotate(%1, 0.001);\n"));
    }
    src.push_str("}\n");
    let c = compile_checked(&src);
    assert!(c.diagnostics.is_empty(), "{:?}", &c.diagnostics[..1]);
    let scene = c.scene.unwrap();
    assert_eq!(scene.objects.len(), n);
    assert_eq!(scene.points.len(), n + 2);
}

#[test]
fn thousands_of_broken_statements_each_reported() {
    // 9,000 diagnostics: under the cap of 10,000 kept.
    let n = 3_000;
    let body = "  Sphere %1, 0.1 #1;\n  Spere %1, 0.1, #1;\n  Sphere %99, 0.1, #1;\n".repeat(n);
    let src =
        format!("BRDFs {{ diffuse = (1,1,1); }} Points {{ (0,0,0.3); }} Objects {{\n{body}}}");
    let c = compile_checked(&src);
    assert_eq!(count(&c, Code::Syntax), n);
    assert_eq!(count(&c, Code::UnknownObject), n);
    assert_eq!(count(&c, Code::UndefinedPoint), n);
}

#[test]
fn thousands_of_sections_and_duplicate_names() {
    // 2 (n - 1) diagnostics: under the cap of 10,000 kept.
    let n = 5_000;
    let src = "Points { p = (0,0,0.1); }\n".repeat(n);
    let c = compile_checked(&src);
    assert_eq!(count(&c, Code::DuplicateSection), n - 1);
    assert_eq!(count(&c, Code::DuplicateName), n - 1);
}

// ----- garbage ------------------------------------------------------------

/// A megabyte of random text built from the language's own pieces and some
/// noise, so that it reaches deep into both parser layers.
fn garbage(seed: u64, len: usize) -> String {
    const PIECES: &[&str] = &[
        "Globals",
        "BRDFs",
        "Points",
        "Lights",
        "Objects",
        "Transformations",
        "Sphere",
        "Polygon",
        "Dodecahedron",
        "hline",
        "hplane",
        "Rotate",
        "Translate",
        "Reflect",
        "resolution",
        "net_type",
        "to",
        "from",
        "up",
        "diffuse",
        "trans",
        "{",
        "}",
        "(",
        ")",
        ";",
        ",",
        "=",
        ":",
        "->",
        "%1",
        "%2",
        "#1",
        "%eye",
        "#glass",
        "0",
        "0.5",
        "-0.7",
        "1e400",
        "(0,0,0.3)",
        "(1,0,0)",
        "/*",
        "*/",
        "//",
        "\n",
        " ",
        "\t",
        "é",
        "€",
        "😀",
        "\r\n",
        "\0",
        "%",
        "#",
        ".",
        "e",
        "+",
        "-",
    ];
    let mut rng = Rng(seed);
    let mut s = String::with_capacity(len + 16);
    while s.len() < len {
        if rng.below(8) == 0 {
            // Any char, including controls and non-ASCII.
            let c = char::from_u32(rng.below(0x3000) as u32).unwrap_or('?');
            s.push(c);
        } else {
            s.push_str(PIECES[rng.below(PIECES.len())]);
        }
    }
    s
}

#[test]
fn a_megabyte_of_garbage() {
    for seed in [1, 2, 3] {
        let src = garbage(seed, 1 << 20);
        let c = compile_checked(&src);
        assert!(c.has_errors());
    }
}

#[test]
fn a_megabyte_of_random_ascii() {
    let mut rng = Rng(42);
    let src: String = (0..1 << 20)
        .map(|_| (rng.below(95) as u8 + b' ') as char)
        .collect();
    let c = compile_checked(&src);
    assert!(c.has_errors());
}
