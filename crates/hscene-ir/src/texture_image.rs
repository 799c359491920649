//! An image for texturing (`texture = "file.png"`) or the sky
//! (`sky = "file.exr"`): linear RGB texels with their mipmaps, looked up
//! with bilinear filtering between the two levels that bracket the ray's
//! footprint (trilinear filtering).
//!
//! Texel `(i, j)` of a level covers `[i, i+1] × [j, j+1]` of its pixels,
//! row 0 at the top; `(u, v)` in `[0, 1]²` spans the image, `v = 0` at the
//! top. Lookups wrap in `u` and clamp in `v` (a longitude goes round, a
//! latitude stops at the poles; a disc's image never reaches its edges).

/// The most texels a texture image may have (4096 × 4096): with its
/// mipmaps at 12 bytes a texel (f32 RGB) it takes 268 MB.
pub const MAX_TEXTURE_PIXELS: u64 = 1 << 24;

/// A texture image and its mipmaps, linear RGB.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureImage {
    /// Level 0 is the image; each next one halves both sides (rounding
    /// up) by averaging 2 × 2 texels, down to 1 × 1.
    levels: Vec<Level>,
}

#[derive(Clone, Debug, PartialEq)]
struct Level {
    width: usize,
    height: usize,
    texels: Vec<[f32; 3]>,
}

impl Level {
    fn at(&self, i: i64, j: i64) -> [f32; 3] {
        let w = self.width as i64;
        let i = i.rem_euclid(w) as usize;
        let j = j.clamp(0, self.height as i64 - 1) as usize;
        self.texels[j * self.width + i]
    }

    /// Bilinear between the four texel centres around `(u, v)`.
    fn bilinear(&self, u: f64, v: f64) -> [f64; 3] {
        let x = u * self.width as f64 - 0.5;
        let y = v * self.height as f64 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let (i, j) = (x0 as i64, y0 as i64);
        let mut out = [0.0; 3];
        for (di, dj, w) in [
            (0, 0, (1.0 - fx) * (1.0 - fy)),
            (1, 0, fx * (1.0 - fy)),
            (0, 1, (1.0 - fx) * fy),
            (1, 1, fx * fy),
        ] {
            let t = self.at(i + di, j + dj);
            for c in 0..3 {
                out[c] += w * f64::from(t[c]);
            }
        }
        out
    }

    fn halved(&self) -> Level {
        let (w, h) = (self.width.div_ceil(2), self.height.div_ceil(2));
        let mut texels = Vec::with_capacity(w * h);
        for j in 0..h {
            for i in 0..w {
                let mut sum = [0.0f32; 3];
                let mut n = 0.0f32;
                for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    let (x, y) = (2 * i + di, 2 * j + dj);
                    if x < self.width && y < self.height {
                        let t = self.texels[y * self.width + x];
                        for c in 0..3 {
                            sum[c] += t[c];
                        }
                        n += 1.0;
                    }
                }
                texels.push(sum.map(|s| s / n));
            }
        }
        Level {
            width: w,
            height: h,
            texels,
        }
    }
}

/// Why texels cannot make a texture image.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TextureImageError {
    /// A side is 0, or the texels are not `width × height`.
    #[error("an image of {width} × {height} pixels with {texels} texels")]
    Shape {
        /// Columns.
        width: usize,
        /// Rows.
        height: usize,
        /// Texels given.
        texels: usize,
    },
    /// More than [`MAX_TEXTURE_PIXELS`].
    #[error("{width} × {height} pixels is more than the {MAX_TEXTURE_PIXELS} a texture may have")]
    TooLarge {
        /// Columns.
        width: usize,
        /// Rows.
        height: usize,
    },
}

impl TextureImage {
    /// The image of `width × height` linear texels, row by row from the
    /// top, with its mipmaps. Non-finite or negative texels are read as 0.
    pub fn new(
        width: usize,
        height: usize,
        texels: Vec<[f32; 3]>,
    ) -> Result<TextureImage, TextureImageError> {
        if width == 0 || height == 0 || texels.len() != width.saturating_mul(height) {
            return Err(TextureImageError::Shape {
                width,
                height,
                texels: texels.len(),
            });
        }
        if (width as u64).saturating_mul(height as u64) > MAX_TEXTURE_PIXELS {
            return Err(TextureImageError::TooLarge { width, height });
        }
        let texels = texels
            .into_iter()
            .map(|t| t.map(|c| if c.is_finite() && c > 0.0 { c } else { 0.0 }))
            .collect();
        let mut levels = vec![Level {
            width,
            height,
            texels,
        }];
        while let Some(last) = levels.last().filter(|l| l.width > 1 || l.height > 1) {
            let next = last.halved();
            levels.push(next);
        }
        Ok(TextureImage { levels })
    }

    /// Columns of the image.
    pub fn width(&self) -> usize {
        self.levels[0].width
    }

    /// Rows of the image.
    pub fn height(&self) -> usize {
        self.levels[0].height
    }

    /// The colour at `(u, v)` for a lookup whose footprint spans
    /// `footprint` texels of the image (level 0): trilinear between the
    /// levels of `log2(footprint)`, plain bilinear at or below 1.
    pub fn sample(&self, u: f64, v: f64, footprint: f64) -> [f64; 3] {
        if !(u.is_finite() && v.is_finite()) {
            return [0.0; 3];
        }
        let lod = if footprint > 1.0 {
            footprint.log2().min((self.levels.len() - 1) as f64)
        } else {
            0.0
        };
        let lo = lod.floor() as usize;
        let f = lod - lo as f64;
        let a = self.levels[lo].bilinear(u, v);
        if f == 0.0 || lo + 1 >= self.levels.len() {
            return a;
        }
        let b = self.levels[lo + 1].bilinear(u, v);
        [0, 1, 2].map(|c| a[c] * (1.0 - f) + b[c] * f)
    }
}

/// The sRGB transfer function undone: an encoded value in `[0, 1]` to
/// linear light (IEC 61966-2-1).
pub fn srgb_to_linear(x: f64) -> f64 {
    if x <= 0.040_45 {
        x / 12.92
    } else {
        ((x + 0.055) / 1.055).powf(2.4)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn checker(n: usize) -> TextureImage {
        let texels = (0..n * n)
            .map(|k| {
                let v = ((k / n + k % n) % 2) as f32;
                [v, v, v]
            })
            .collect();
        TextureImage::new(n, n, texels).unwrap()
    }

    /// Texel centres read back exactly; the mipmaps average, so a fine
    /// checker seen through a wide footprint is its mean, grey.
    #[test]
    fn lookups_are_exact_at_centres_and_average_when_wide() {
        let t = checker(8);
        assert_eq!(t.sample(0.5 / 8.0, 0.5 / 8.0, 1.0), [0.0; 3]);
        assert_eq!(t.sample(1.5 / 8.0, 0.5 / 8.0, 1.0), [1.0; 3]);
        let wide = t.sample(0.37, 0.61, 8.0);
        assert!(wide.iter().all(|c| (c - 0.5).abs() < 1e-6), "{wide:?}");
        assert_eq!(t.levels.len(), 4);
    }

    /// Odd sizes halve rounding up, down to one texel; `u` wraps.
    #[test]
    fn odd_sizes_and_wrapping() {
        let t = TextureImage::new(3, 1, vec![[1.0; 3], [2.0; 3], [3.0; 3]]).unwrap();
        assert_eq!(t.levels.len(), 3);
        assert_eq!(t.levels[1].texels, vec![[1.5; 3], [3.0; 3]]);
        assert_eq!(t.sample(0.5 / 3.0 + 1.0, 0.5, 1.0), [1.0; 3]);
    }

    #[test]
    fn bad_shapes_and_sizes_are_refused() {
        assert!(TextureImage::new(0, 3, vec![]).is_err());
        assert!(TextureImage::new(2, 2, vec![[0.0; 3]; 3]).is_err());
        assert!(matches!(
            TextureImage::new(1 << 13, 1 << 12, Vec::new()),
            Err(TextureImageError::Shape { .. })
        ));
    }

    #[test]
    fn srgb_decodes_to_linear() {
        assert_eq!(srgb_to_linear(0.0), 0.0);
        assert!((srgb_to_linear(1.0) - 1.0).abs() < 1e-12);
        assert!((srgb_to_linear(0.5) - 0.214_041).abs() < 1e-6);
    }
}
