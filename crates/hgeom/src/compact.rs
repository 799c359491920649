//! Numbers in messages: `1e300`, not three hundred and one digits.

use std::fmt;

/// Displays an f64 in its shortest round-trip form, in scientific notation
/// when it is very large or very small (`|x| >= 1e9` or `|x| < 1e-6`), so a
/// message never runs to hundreds of digits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Compact(pub f64);

impl fmt::Display for Compact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        let magnitude = x.abs();
        if x.is_finite() && x != 0.0 && !(1e-6..1e9).contains(&magnitude) {
            write!(f, "{x:e}")
        } else {
            write!(f, "{x}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn large_and_small_numbers_are_short() {
        let s = |x: f64| Compact(x).to_string();
        assert_eq!(s(1e300), "1e300");
        assert_eq!(s(-2.5e-300), "-2.5e-300");
        assert_eq!(s(711.0), "711");
        assert_eq!(s(0.125), "0.125");
        assert_eq!(s(0.0), "0");
        assert_eq!(s(f64::NAN), "NaN");
        assert_eq!(s(f64::INFINITY), "inf");
        assert_eq!(s(123_456_789.0), "123456789");
    }
}
