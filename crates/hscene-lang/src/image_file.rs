//! Reading texture and sky images: PNG and JPEG (8 or 16 bits a channel,
//! decoded from sRGB to linear light) and OpenEXR (linear floats, the
//! first RGB part). The size is checked from the header before any texel
//! is decoded: at most [`MAX_TEXTURE_PIXELS`] texels and
//! [`MAX_IMAGE_FILE_BYTES`] bytes of file; a device, FIFO or directory is
//! refused before it is opened for reading.

use std::path::Path;

use hscene_ir::bounded_read::{BoundedReadError, read_regular_file};
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

/// The most one block of an OpenEXR file (a tile or a group of scan lines,
/// every channel of it) may take decompressed: 64 MiB, 40 times a 4096-wide
/// block of 32 lines of R, G, B and A in 32-bit floats. The decoder holds
/// one block at a time besides the texels kept, so a file of many channels
/// costs one block of them, not all of them.
pub const MAX_EXR_BLOCK_BYTES: usize = 64 << 20;

/// OpenEXR: of the first part with `R`, `G` and `B` channels (or else a
/// luminance `Y`, read as grey), those channels alone, linear; the others
/// (alpha, depth, layers of AOVs) are never decoded. The part's size and
/// block size are checked from the header before any block is read.
fn decode_exr(bytes: &[u8]) -> Result<TextureImage, ImageFileError> {
    use exr::prelude::{ReadChannels, ReadLayers, ReadSpecificChannel};
    let decode = |e: exr::error::Error| ImageFileError::Decode(e.to_string());
    let meta = exr::meta::MetaData::read_from_buffered(std::io::Cursor::new(bytes), false)
        .map_err(decode)?;
    let has = |h: &exr::meta::header::Header, name: &str| {
        h.channels.list.iter().any(|c| c.name.to_string() == name)
    };
    let rgb = |h: &exr::meta::header::Header| ["R", "G", "B"].iter().all(|n| has(h, n));
    let (header, grey) = match meta.headers.iter().find(|h| rgb(h)) {
        Some(h) => (h, false),
        None => match meta.headers.iter().find(|h| has(h, "Y")) {
            Some(h) => (h, true),
            None => {
                return Err(ImageFileError::Decode(
                    "an OpenEXR image needs R, G and B channels (or Y)".into(),
                ));
            }
        },
    };
    let size = header.layer_size;
    check_pixels(size.width() as u64, size.height() as u64)?;
    if header.deep || header.max_block_byte_size() > MAX_EXR_BLOCK_BYTES {
        return Err(ImageFileError::Decode(format!(
            "an OpenEXR block of {} bytes (its {} channels) is more than the {MAX_EXR_BLOCK_BYTES} a texture's may have",
            header.max_block_byte_size(),
            header.channels.list.len()
        )));
    }
    let texels = if grey {
        exr_reader()
            .required("Y")
            .collect_pixels(create_texels, |t, at, (y,): (f32,)| {
                set_texel(t, at, [y, y, y]);
            })
            .first_valid_layer()
            .all_attributes()
            .non_parallel()
            .from_buffered(std::io::Cursor::new(bytes))
            .map(|image| image.layer_data.channel_data.pixels.1)
    } else {
        exr_reader()
            .required("R")
            .required("G")
            .required("B")
            .collect_pixels(create_texels, |t, at, (r, g, b): (f32, f32, f32)| {
                set_texel(t, at, [r, g, b]);
            })
            .first_valid_layer()
            .all_attributes()
            .non_parallel()
            .from_buffered(std::io::Cursor::new(bytes))
            .map(|image| image.layer_data.channel_data.pixels.1)
    }
    .map_err(decode)?;
    Ok(TextureImage::new(size.width(), size.height(), texels)?)
}

/// The reader of the channels named next, from the largest level of a
/// flat (not deep) image.
fn exr_reader() -> exr::image::read::specific_channels::ReadZeroChannels {
    exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .specific_channels()
}

/// The texels of an OpenEXR part, with its width for [`set_texel`].
fn create_texels<D>(size: exr::math::Vec2<usize>, _: &D) -> (usize, Vec<[f32; 3]>) {
    (size.width(), vec![[0.0; 3]; size.area()])
}

fn set_texel(texels: &mut (usize, Vec<[f32; 3]>), at: exr::math::Vec2<usize>, rgb: [f32; 3]) {
    let (width, list) = texels;
    if let Some(t) = list.get_mut(at.y() * *width + at.x()) {
        *t = rgb;
    }
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

    /// Writes an OpenEXR of `width` x `height` whose channels are `names`,
    /// channel `i` holding `i` everywhere.
    fn write_exr(path: &Path, width: usize, height: usize, names: &[&str]) {
        use exr::prelude::*;
        let channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = names
            .iter()
            .enumerate()
            .map(|(i, n)| AnyChannel::new(*n, FlatSamples::F32(vec![i as f32; width * height])))
            .collect();
        let layer = Layer::new(
            (width, height),
            LayerAttributes::named("t"),
            Encoding::SMALL_LOSSLESS,
            AnyChannels::sort(channels),
        );
        Image::from_layer(layer).write().to_file(path).unwrap();
    }

    /// Of an OpenEXR with many channels only R, G and B are read (or Y as
    /// grey); one without them is refused.
    #[test]
    fn an_exr_gives_its_colour_channels_only() {
        let dir = tempfile::tempdir().unwrap();
        let many: Vec<String> = (0..32).map(|i| format!("aov{i:02}")).collect();
        let mut names: Vec<&str> = many.iter().map(String::as_str).collect();
        names.extend(["A", "B", "G", "R"]);
        let path = dir.path().join("many.exr");
        write_exr(&path, 64, 32, &names);
        let t = load(&path).unwrap();
        assert_eq!((t.width(), t.height()), (64, 32));
        // Each channel holds its place in `names`: B 33, G 34, R 35.
        assert_eq!(t.sample(0.5, 0.5, 1.0), [35.0, 34.0, 33.0]);
        let grey = dir.path().join("grey.exr");
        write_exr(&grey, 8, 8, &["Z", "Y"]);
        assert_eq!(load(&grey).unwrap().sample(0.5, 0.5, 1.0), [1.0; 3]);
        let none = dir.path().join("none.exr");
        write_exr(&none, 8, 8, &["Z"]);
        assert!(matches!(load(&none), Err(ImageFileError::Decode(_))));
    }

    /// A block (scan lines of every channel) larger than the bound is
    /// refused from the header, before any block is decompressed.
    #[test]
    fn an_exr_block_too_large_is_refused_from_the_header() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("wide.exr");
        // 16 lines of 65,536 texels of 20 floats: 84 MB a block.
        let names: Vec<String> = (0..17).map(|i| format!("x{i:02}")).collect();
        let mut names: Vec<&str> = names.iter().map(String::as_str).collect();
        names.extend(["R", "G", "B"]);
        write_exr(&path, 65_536, 1, &names);
        let err = load(&path).unwrap_err().to_string();
        assert!(err.contains("block"), "{err}");
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
