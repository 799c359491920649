//! `hscene explain CODE`: a diagnostic code's documentation, taken from
//! `docs/diagnostics.md` at build time so the command and the docs cannot
//! drift apart.

use std::process::ExitCode;

use hscene_lang::Code;

const DIAGNOSTICS_MD: &str = include_str!("../docs/diagnostics.md");

/// One row of a code table in docs/diagnostics.md.
#[derive(Debug, PartialEq)]
pub struct Entry<'a> {
    pub severity: &'a str,
    pub name: &'a str,
    pub meaning: &'a str,
    pub example: &'a str,
    pub fix: &'a str,
    /// The heading of the section the row is in, e.g. `Geometry`.
    pub section: &'a str,
}

/// Splits a Markdown table row into cells; a `|` inside backquotes is text.
fn cells(row: &str) -> Vec<&str> {
    let row = row.trim().trim_start_matches('|').trim_end_matches('|');
    let mut out = Vec::new();
    let mut start = 0;
    let mut in_code = false;
    for (i, c) in row.char_indices() {
        match c {
            '`' => in_code = !in_code,
            '|' if !in_code => {
                out.push(row[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(row[start..].trim());
    out
}

/// The documentation of `code` (e.g. `HSC0305`), if the docs have a row for it.
pub fn lookup(code: &str) -> Option<Entry<'static>> {
    let mut section = "";
    for line in DIAGNOSTICS_MD.lines() {
        if let Some(h) = line.strip_prefix("## ") {
            section = h.trim();
        }
        let c = cells(line);
        if line.starts_with('|') && c.len() == 6 && c[0] == code {
            return Some(Entry {
                severity: c[1],
                name: c[2].trim_matches('`'),
                meaning: c[3],
                example: c[4],
                fix: c[5],
                section,
            });
        }
    }
    None
}

/// Accepts `HSC0305`, `hsc0305`, `0305` and `305`: the digits are padded
/// to the four of every code.
fn normalise(code: &str) -> String {
    let code = code.trim().to_ascii_uppercase();
    let digits = code.strip_prefix("HSC").unwrap_or(&code);
    if !digits.is_empty() && digits.len() < 4 && digits.bytes().all(|b| b.is_ascii_digit()) {
        format!("HSC{digits:0>4}")
    } else {
        format!("HSC{digits}")
    }
}

pub fn run(code: &str) -> ExitCode {
    let code = normalise(code);
    let known = Code::ALL.iter().any(|c| c.as_str() == code);
    match lookup(&code) {
        Some(e) if known => {
            let text = format!(
                "{code} ({}): {}, {}\n\n{}\n\nExample: {}\n\nFix: {}\n",
                e.severity,
                e.name,
                e.section.to_lowercase(),
                e.meaning,
                e.example,
                e.fix
            );
            crate::exit::print_bytes(text.as_bytes())
        }
        _ => {
            diagln!(
                "error: no diagnostic code `{code}`; the codes are listed in docs/diagnostics.md"
            );
            ExitCode::from(crate::exit::EXIT_USAGE_OR_IO)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_code_is_documented() {
        for code in Code::ALL {
            let e = lookup(code.as_str()).unwrap_or_else(|| panic!("{code} undocumented"));
            assert_eq!(e.severity, code.severity().as_str(), "{code}");
            assert!(!e.meaning.is_empty() && !e.fix.is_empty(), "{code}");
        }
    }

    #[test]
    fn rows_split_outside_backquotes() {
        assert_eq!(cells("| a | `x|y` | c |"), vec!["a", "`x|y`", "c"]);
        assert_eq!(normalise("0305"), "HSC0305");
        // The trap a new user meets: the code without its zero or prefix.
        for short in ["313", "0313", "hsc0313", "HSC313", " hsc313 "] {
            assert_eq!(normalise(short), "HSC0313", "{short}");
        }
        assert_eq!(normalise("1005"), "HSC1005");
        assert_eq!(lookup("HSC9999"), None);
        assert_eq!(lookup("HSC0305").unwrap().name, "NonPlanarPolygon");
    }
}
