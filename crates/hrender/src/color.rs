//! Linear RGB arithmetic for shading.

use std::ops::{Add, AddAssign, Mul};

use hscene_lang::ir::Rgb;

/// A linear RGB radiance value.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Color(pub [f64; 3]);

impl Color {
    /// True if every channel is finite.
    pub fn is_finite(&self) -> bool {
        self.0.iter().all(|c| c.is_finite())
    }

    /// Channel-wise product.
    pub fn tint(self, other: Color) -> Color {
        Color([
            self.0[0] * other.0[0],
            self.0[1] * other.0[1],
            self.0[2] * other.0[2],
        ])
    }
}

impl From<Rgb> for Color {
    fn from(c: Rgb) -> Self {
        Color([c.r, c.g, c.b])
    }
}

impl Add for Color {
    type Output = Color;
    fn add(self, o: Color) -> Color {
        Color([self.0[0] + o.0[0], self.0[1] + o.0[1], self.0[2] + o.0[2]])
    }
}

impl AddAssign for Color {
    fn add_assign(&mut self, o: Color) {
        *self = *self + o;
    }
}

impl Mul<f64> for Color {
    type Output = Color;
    fn mul(self, k: f64) -> Color {
        Color([self.0[0] * k, self.0[1] * k, self.0[2] * k])
    }
}
