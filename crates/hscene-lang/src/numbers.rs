//! Number problems that deserve their own words: the non-numbers some
//! languages accept (`NaN`, `inf`), which are names here, and decimal
//! literals too small for f64, which would otherwise turn silently into 0.

use crate::diagnostic::{Code, Diagnostic, Span};

/// Whether a name is a spelling of not-a-number or infinity.
pub(crate) fn is_non_finite_word(text: &str) -> bool {
    ["nan", "inf", "infinity"]
        .iter()
        .any(|w| text.eq_ignore_ascii_case(w))
}

/// The diagnostic for `NaN`, `inf` or `infinity` where a number belongs.
pub(crate) fn non_finite(span: Span, text: &str) -> Diagnostic {
    Diagnostic::new(
        Code::InvalidNumber,
        span,
        format!("`{text}` is not a number here: every value must be a finite number"),
    )
    .with_label("not a finite number")
    .with_help("write the value as digits, e.g. `0.5` or `1e3`")
}

/// Whether a literal with nonzero digits parsed to 0: it lies below the
/// smallest f64 (about 4.9e-324).
pub(crate) fn underflows(text: &str, value: f64) -> bool {
    let mantissa = text.split(['e', 'E']).next().unwrap_or("");
    value == 0.0 && mantissa.bytes().any(|b| (b'1'..=b'9').contains(&b))
}

/// The diagnostic for a literal too small for f64.
pub(crate) fn underflow(span: Span, snippet: &str) -> Diagnostic {
    Diagnostic::new(
        Code::InvalidNumber,
        span,
        format!("number {snippet} is too small for a 64-bit float: it would become 0"),
    )
    .with_label("below the smallest f64")
    .with_help(
        "nonzero numbers must be at least about 4.9e-324 in magnitude; write 0 if zero is meant",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_and_underflow() {
        assert!(is_non_finite_word("NaN") && is_non_finite_word("INF"));
        assert!(!is_non_finite_word("nano"));
        assert!(underflows("1e-400", 0.0) && underflows("-0.5E-999", 0.0));
        assert!(!underflows("0.000e-5", 0.0) && !underflows("1e-300", 1e-300));
    }
}
