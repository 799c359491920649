//! Reading texture and sky images: PNG and JPEG (8 or 16 bits a channel,
//! decoded from sRGB to linear light) and OpenEXR (linear floats, the
//! first RGB part). The size is checked from the header before any texel
//! is decoded: at most [`MAX_TEXTURE_PIXELS`] texels and
//! [`MAX_IMAGE_FILE_BYTES`] bytes of file; a device, FIFO or directory is
//! refused before it is opened for reading.

use std::io::BufReader;
use std::path::Path;

use crate::bounded_read::{BoundedReadError, read_regular_file};
use hscene_ir::{MAX_TEXTURE_PIXELS, TextureImage, TextureImageError, srgb_to_linear};

/// The largest image file read: 256 MiB.
pub const MAX_IMAGE_FILE_BYTES: u64 = 256 << 20;

/// Why an image file gives no texture.
#[derive(Debug, thiserror::Error)]
pub enum ImageFileError {
    /// The extension names no format read here.
    #[error("unknown image format: use .png, .jpg, .jpeg or .exr")]
    UnknownFormat,
    /// Not a regular file.
    #[error("not a regular file")]
    NotAFile,
    /// Larger than [`MAX_IMAGE_FILE_BYTES`].
    #[error("the file has {size} bytes, more than the {MAX_IMAGE_FILE_BYTES} an image may have")]
    TooLarge {
        /// Its size.
        size: u64,
    },
    /// More texels than [`MAX_TEXTURE_PIXELS`], read from the header.
    #[error("{width} × {height} pixels is more than the {MAX_TEXTURE_PIXELS} an image may have")]
    TooManyPixels {
        /// Columns.
        width: u64,
        /// Rows.
        height: u64,
    },
    /// The decoder's complaint.
    #[error("{0}")]
    Decode(String),
    /// Reading failed.
    #[error("{0}")]
    Io(#[from] std::io::Error),
}

impl From<TextureImageError> for ImageFileError {
    fn from(e: TextureImageError) -> ImageFileError {
        ImageFileError::Decode(e.to_string())
    }
}

/// The texture image in the file at `path`.
pub fn load(path: &Path) -> Result<TextureImage, ImageFileError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let exr = match ext.as_deref() {
        Some("png" | "jpg" | "jpeg") => false,
        Some("exr") => true,
        _ => return Err(ImageFileError::UnknownFormat),
    };
    let bytes = read_regular_file(path, MAX_IMAGE_FILE_BYTES).map_err(|e| match e {
        BoundedReadError::NotAFile => ImageFileError::NotAFile,
        BoundedReadError::TooLarge(size) => ImageFileError::TooLarge { size },
        BoundedReadError::Io(e) => ImageFileError::Io(e),
    })?;
    if exr {
        decode_exr(&bytes)
    } else {
        decode_srgb(&bytes)
    }
}

fn check_pixels(width: u64, height: u64) -> Result<(), ImageFileError> {
    if width.saturating_mul(height) > MAX_TEXTURE_PIXELS {
        return Err(ImageFileError::TooManyPixels { width, height });
    }
    Ok(())
}

/// PNG or JPEG, by its content: the header's size first, then the texels
/// from sRGB to linear.
fn decode_srgb(bytes: &[u8]) -> Result<TextureImage, ImageFileError> {
    let decode = |e: image::ImageError| ImageFileError::Decode(e.to_string());
    let reader = image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .map_err(ImageFileError::Io)?;
    let (w, h) = reader.into_dimensions().map_err(decode)?;
    check_pixels(u64::from(w), u64::from(h))?;
    let mut reader = image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .map_err(ImageFileError::Io)?;
    let mut limits = image::Limits::default();
    // The texels as 16-bit RGB: 6 bytes each, within the pixel bound.
    limits.max_alloc = Some(MAX_TEXTURE_PIXELS * 8 + (1 << 20));
    reader.limits(limits);
    let decoded = reader.decode().map_err(decode)?.into_rgb16();
    let table: Vec<f32> = (0..=u16::MAX)
        .map(|x| srgb_to_linear(f64::from(x) / 65535.0) as f32)
        .collect();
    let texels = decoded
        .pixels()
        .map(|p| p.0.map(|c| table[usize::from(c)]))
        .collect();
    Ok(TextureImage::new(w as usize, h as usize, texels)?)
}

/// OpenEXR: the first layer's `R`, `G`, `B` channels (a luminance-only
/// `Y` image is grey), linear.
fn decode_exr(bytes: &[u8]) -> Result<TextureImage, ImageFileError> {
    use exr::prelude::{ReadChannels, ReadLayers};
    let decode = |e: exr::error::Error| ImageFileError::Decode(e.to_string());
    let meta = exr::meta::MetaData::read_from_buffered(std::io::Cursor::new(bytes), false)
        .map_err(decode)?;
    let header = meta
        .headers
        .first()
        .ok_or_else(|| ImageFileError::Decode("an OpenEXR file with no part".into()))?;
    let size = header.layer_size;
    check_pixels(size.width() as u64, size.height() as u64)?;
    let read = exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_buffered(BufReader::new(std::io::Cursor::new(bytes)))
        .map_err(decode)?;
    let layer = &read.layer_data;
    let (w, h) = (layer.size.width(), layer.size.height());
    let channel = |name: &str| {
        layer
            .channel_data
            .list
            .iter()
            .find(|c| c.name.to_string() == name)
    };
    let grey = channel("Y");
    let [r, g, b] = ["R", "G", "B"].map(|n| channel(n).or(grey));
    let (Some(r), Some(g), Some(b)) = (r, g, b) else {
        return Err(ImageFileError::Decode(
            "an OpenEXR image needs R, G and B channels (or Y)".into(),
        ));
    };
    let texels = (0..w * h)
        .map(|k| [r, g, b].map(|c| c.sample_data.value_by_flat_index(k).to_f32()))
        .collect();
    Ok(TextureImage::new(w, h, texels)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write_png(path: &Path, w: u32, h: u32, rgb: [u8; 3]) {
        let img = image::RgbImage::from_pixel(w, h, image::Rgb(rgb));
        img.save(path).unwrap();
    }

    #[test]
    fn a_png_is_decoded_to_linear_light() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("grey.png");
        write_png(&path, 4, 2, [128, 255, 0]);
        let t = load(&path).unwrap();
        assert_eq!((t.width(), t.height()), (4, 2));
        let [r, g, b] = t.sample(0.3, 0.4, 1.0);
        assert!((r - srgb_to_linear(128.0 / 255.0)).abs() < 1e-4, "{r}");
        assert!((g - 1.0).abs() < 1e-6 && b == 0.0);
    }

    #[test]
    fn bad_files_are_refused_before_decoding() {
        let dir = tempfile::tempdir().unwrap();
        assert!(matches!(
            load(&dir.path().join("x.gif")),
            Err(ImageFileError::UnknownFormat)
        ));
        assert!(matches!(
            load(&dir.path().join("missing.png")),
            Err(ImageFileError::Io(_))
        ));
        let not_png = dir.path().join("text.png");
        std::fs::write(&not_png, "not an image").unwrap();
        assert!(matches!(load(&not_png), Err(ImageFileError::Decode(_))));
        let sub = dir.path().join("d.png");
        std::fs::create_dir(&sub).unwrap();
        assert!(matches!(load(&sub), Err(ImageFileError::NotAFile)));
    }

    /// A header claiming more pixels than the bound is refused from the
    /// header, before the texels are decoded.
    #[test]
    fn too_many_pixels_are_refused_from_the_header() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("wide.png");
        // 8193 × 2049 > 2^24, a one-colour PNG of a few kilobytes.
        write_png(&path, 8193, 2049, [0, 0, 0]);
        assert!(matches!(
            load(&path),
            Err(ImageFileError::TooManyPixels { .. })
        ));
    }
}
