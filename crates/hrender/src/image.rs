//! The rendered image: linear, unclamped RGB.

/// A linear RGB image with unclamped (high-dynamic-range) `f32` samples,
/// stored row-major from the top-left corner.
///
/// Invariant: `pixels.len() == width * height` and every sample is finite.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    width: u32,
    height: u32,
    pixels: Vec<[f32; 3]>,
}

impl Image {
    /// An image from its pixels. Panics if the size does not match (a
    /// programming error, never input-dependent).
    pub fn from_pixels(width: u32, height: u32, pixels: Vec<[f32; 3]>) -> Image {
        assert_eq!(
            pixels.len(),
            width as usize * height as usize,
            "pixel count must match the size"
        );
        Image {
            width,
            height,
            pixels,
        }
    }

    /// Columns.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Rows.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// All pixels, row-major.
    pub fn pixels(&self) -> &[[f32; 3]] {
        &self.pixels
    }

    /// The pixel at column `x`, row `y` (row 0 is the top).
    pub fn get(&self, x: u32, y: u32) -> [f32; 3] {
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// Every sample multiplied by `2^ev`, for an exposure chosen after the
    /// render ([`crate::auto_exposure`] keeps the result finite). A sample
    /// the product would take past f32 becomes the largest finite f32.
    pub fn expose(&mut self, ev: f64) {
        let k = ev.exp2();
        for c in self.pixels.iter_mut().flatten() {
            let v = (f64::from(*c) * k) as f32;
            *c = if v.is_finite() {
                v
            } else {
                f32::MAX.copysign(v)
            };
        }
    }

    /// The unclamped samples, interleaved.
    pub fn to_rgb32f(&self) -> Vec<f32> {
        self.pixels.iter().flatten().copied().collect()
    }
}
