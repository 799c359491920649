//! Speed against error for every hgeom operation.
//!
//! ```text
//! cargo run --release -p hgeom --example accuracy [-- --json] [-- --cases N] [-- --seed S]
//! ```
//!
//! For each operation: the number of cases tried, the largest and median
//! error against a 320-bit reference (astro-float) with its unit, and the
//! mean time per f64 call. With `--json` the same rows are printed as a JSON
//! array of objects with the keys `operation`, `cases`, `max_error`,
//! `median_error`, `unit` and `ns_per_op`.

use std::process::ExitCode;

use hscene_test_support::accuracy as cases;

struct Args {
    json: bool,
    cases: usize,
    seed: u64,
}

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        json: false,
        cases: 500,
        seed: 7,
    };
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        match a.as_str() {
            "--json" => args.json = true,
            "--cases" => {
                let v = it.next().ok_or("--cases needs a number")?;
                args.cases = v.parse().map_err(|_| format!("bad --cases `{v}`"))?;
            }
            "--seed" => {
                let v = it.next().ok_or("--seed needs a number")?;
                args.seed = v.parse().map_err(|_| format!("bad --seed `{v}`"))?;
            }
            "-h" | "--help" => {
                return Err("usage: accuracy [--json] [--cases N] [--seed S]".into());
            }
            other => return Err(format!("unknown argument `{other}`")),
        }
    }
    Ok(args)
}

/// JSON string literal (the operation names are plain ASCII, but escape
/// properly anyway).
fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    let families = cases::all(args.seed, args.cases);
    if args.json {
        let rows: Vec<String> = families
            .iter()
            .map(|f| {
                format!(
                    "{{\"operation\": {}, \"cases\": {}, \"max_error\": {:e}, \"median_error\": {:e}, \"unit\": {}, \"ns_per_op\": {:.1}}}",
                    json_string(f.operation),
                    f.errors.len(),
                    f.max(),
                    f.median(),
                    json_string(f.unit),
                    f.ns_per_op
                )
            })
            .collect();
        println!("[\n  {}\n]", rows.join(",\n  "));
    } else {
        println!(
            "{:<62} {:>6} {:>10} {:>10}  {:<20} {:>9}",
            "operation", "cases", "max", "median", "unit", "ns/op"
        );
        for f in &families {
            println!(
                "{:<62} {:>6} {:>10.2e} {:>10.2e}  {:<20} {:>9.1}",
                f.operation,
                f.errors.len(),
                f.max(),
                f.median(),
                f.unit,
                f.ns_per_op
            );
        }
    }
    ExitCode::SUCCESS
}
