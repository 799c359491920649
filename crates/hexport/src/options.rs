//! What an export is asked for: the print's size, the thinnest part a
//! printer can make, how closely triangles follow the exact surfaces, and
//! what to do with parts thinner than that.

use crate::error::ExportError;

/// A length in millimetres, positive and finite.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Millimetres(f64);

impl Millimetres {
    /// `mm` millimetres, if positive and finite.
    pub fn new(mm: f64) -> Option<Millimetres> {
        (mm > 0.0 && mm.is_finite()).then_some(Millimetres(mm))
    }

    /// The value in millimetres.
    pub fn get(self) -> f64 {
        self.0
    }

    /// Parses `100mm`, `10cm`, `0.1m`, `4in` or a bare number (millimetres).
    ///
    /// Errors: [`ExportError::BadLength`] for anything else, and for a
    /// length that is not positive and finite.
    pub fn parse(text: &str) -> Result<Millimetres, ExportError> {
        let t = text.trim();
        let bad = || ExportError::BadLength(text.to_string());
        let (number, scale) = [("mm", 1.0), ("cm", 10.0), ("in", 25.4), ("m", 1000.0)]
            .iter()
            .find_map(|(unit, scale)| t.strip_suffix(unit).map(|n| (n, *scale)))
            .unwrap_or((t, 1.0));
        let value: f64 = number.trim().parse().map_err(|_| bad())?;
        Millimetres::new(value * scale).ok_or_else(bad)
    }
}

/// What happens to a tube (an edge, a rod, a cylinder) where its exact
/// Euclidean thickness in the ball falls below the minimum feature.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThinParts {
    /// Tubes end where they get thinner than the minimum; balls and plates
    /// thinner anywhere are left out (`docs/export.md`, "The cut rule").
    Cut,
    /// Tubes keep their full length and are thickened to the minimum
    /// where they are thinner (the style of Segerman and Nelson's printed
    /// honeycombs); balls and plates as for [`ThinParts::Cut`].
    Thicken,
}

/// The most triangles an export writes unless told otherwise.
pub const DEFAULT_MAX_TRIANGLES: usize = 20_000_000;

/// The most triangles any export may write (about 1 GiB of binary STL).
pub const MAX_TRIANGLES: usize = 20_000_000;

/// The options of one export.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExportOptions {
    /// The diameter of the ball in the file.
    pub size: Millimetres,
    /// The thinnest part that is kept.
    pub min_feature: Millimetres,
    /// How far a triangle may lie from the exact surface.
    pub tolerance: Millimetres,
    /// Tubes thinner than the minimum: cut or thickened.
    pub thin: ThinParts,
    /// The hyperbolic half-thickness of polygons and honeycomb faces,
    /// which are surfaces of no thickness in a render.
    pub face_half_thickness: f64,
    /// The most triangles to write.
    pub max_triangles: usize,
}

impl Default for ExportOptions {
    /// A 100 mm ball, features down to 0.8 mm, within 0.05 mm, cut, faces
    /// 0.1 thick (hyperbolic).
    fn default() -> ExportOptions {
        ExportOptions {
            size: Millimetres(100.0),
            min_feature: Millimetres(0.8),
            tolerance: Millimetres(0.05),
            thin: ThinParts::Cut,
            face_half_thickness: 0.05,
            max_triangles: DEFAULT_MAX_TRIANGLES,
        }
    }
}

impl ExportOptions {
    /// Millimetres per unit of the ball's coordinates (its radius).
    pub fn scale(&self) -> f64 {
        self.size.get() / 2.0
    }

    /// The minimum feature in ball units.
    pub fn min_feature_ball(&self) -> f64 {
        self.min_feature.get() / self.scale()
    }

    /// The tolerance in ball units.
    pub fn tolerance_ball(&self) -> f64 {
        self.tolerance.get() / self.scale()
    }

    /// Checks the options against one another and the limits.
    ///
    /// Errors: [`ExportError::BadOptions`] when the tolerance is not below
    /// the minimum feature, the minimum feature not below the size, the
    /// face thickness not positive and finite, or the triangle budget
    /// above [`MAX_TRIANGLES`] or zero.
    pub fn validate(&self) -> Result<(), ExportError> {
        let bad = |why: &str| Err(ExportError::BadOptions(why.to_string()));
        if self.tolerance >= self.min_feature {
            return bad("the tolerance must be smaller than the minimum feature");
        }
        if self.min_feature >= self.size {
            return bad("the minimum feature must be smaller than the size");
        }
        if self.tolerance.get() < self.size.get() * 1e-7 {
            return bad("the tolerance must be at least 1e-7 of the size (f32 coordinates)");
        }
        if !(self.face_half_thickness > 0.0 && self.face_half_thickness <= 5.0) {
            return bad("the face thickness must be positive and at most 10");
        }
        if self.max_triangles == 0 || self.max_triangles > MAX_TRIANGLES {
            return bad(&format!(
                "the triangle budget must be between 1 and {MAX_TRIANGLES}"
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_read_their_units() {
        let mm = |t| Millimetres::parse(t).map(Millimetres::get).ok();
        assert_eq!(mm("100mm"), Some(100.0));
        assert_eq!(mm("10cm"), Some(100.0));
        assert_eq!(mm("0.1m"), Some(100.0));
        assert_eq!(mm("4in"), Some(101.6));
        assert_eq!(mm(" 2.5 "), Some(2.5));
        for bad in ["", "mm", "-1mm", "0", "1e400mm", "nan", "3 furlongs"] {
            assert_eq!(mm(bad), None, "{bad}");
        }
    }

    #[test]
    fn options_are_checked_against_one_another() {
        assert!(ExportOptions::default().validate().is_ok());
        let coarse = ExportOptions {
            tolerance: Millimetres(1.0),
            ..ExportOptions::default()
        };
        assert!(coarse.validate().is_err());
        let huge = ExportOptions {
            max_triangles: MAX_TRIANGLES + 1,
            ..ExportOptions::default()
        };
        assert!(huge.validate().is_err());
    }
}
