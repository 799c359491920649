//! Linear RGB: the one colour type of scenes and of the light a renderer
//! carries.

use std::ops::{Add, AddAssign, Mul};

/// A linear RGB triple: a reflectance, an intensity or a radiance.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Rgb {
    /// Red.
    pub r: f64,
    /// Green.
    pub g: f64,
    /// Blue.
    pub b: f64,
}

impl Rgb {
    /// Black.
    pub const BLACK: Rgb = Rgb::new(0.0, 0.0, 0.0);

    /// A colour from its components.
    pub const fn new(r: f64, g: f64, b: f64) -> Rgb {
        Rgb { r, g, b }
    }

    /// The three channels in order.
    pub const fn channels(self) -> [f64; 3] {
        [self.r, self.g, self.b]
    }

    /// True if every channel is finite.
    pub fn is_finite(self) -> bool {
        self.r.is_finite() && self.g.is_finite() && self.b.is_finite()
    }

    /// True if every channel is zero.
    pub fn is_black(self) -> bool {
        self.r == 0.0 && self.g == 0.0 && self.b == 0.0
    }

    /// Channel-wise product (a reflectance tinting an intensity).
    pub fn tint(self, other: Rgb) -> Rgb {
        Rgb::new(self.r * other.r, self.g * other.g, self.b * other.b)
    }
}

impl Add for Rgb {
    type Output = Rgb;
    fn add(self, o: Rgb) -> Rgb {
        Rgb::new(self.r + o.r, self.g + o.g, self.b + o.b)
    }
}

impl AddAssign for Rgb {
    fn add_assign(&mut self, o: Rgb) {
        *self = *self + o;
    }
}

impl Mul<f64> for Rgb {
    type Output = Rgb;
    fn mul(self, k: f64) -> Rgb {
        Rgb::new(self.r * k, self.g * k, self.b * k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_channel_wise() {
        let a = Rgb::new(1.0, 2.0, 3.0);
        let b = Rgb::new(0.5, 0.25, 2.0);
        assert_eq!(a + b, Rgb::new(1.5, 2.25, 5.0));
        assert_eq!(a.tint(b), Rgb::new(0.5, 0.5, 6.0));
        assert_eq!(a * 2.0, Rgb::new(2.0, 4.0, 6.0));
        let mut c = a;
        c += b;
        assert_eq!(c, a + b);
        assert_eq!(a.channels(), [1.0, 2.0, 3.0]);
        assert!(Rgb::BLACK.is_black() && !a.is_black());
        assert!(a.is_finite() && !Rgb::new(f64::NAN, 0.0, 0.0).is_finite());
    }
}
