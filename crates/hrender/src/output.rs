//! Writing images: PNG and TIFF, always atomically.
//!
//! The encoder writes to a temporary file in the destination's directory,
//! which is flushed and then renamed over the destination. A failure at any
//! point leaves no partial file and does not touch an existing one.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use tiff::encoder::{TiffEncoder, colortype};

use crate::error::RenderError;
use crate::image::Image;

/// Sample format of the written file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SampleDepth {
    /// 8-bit integer, clamped (PNG or TIFF).
    #[default]
    Eight,
    /// 16-bit integer, clamped (PNG or TIFF).
    Sixteen,
    /// 32-bit float, unclamped high dynamic range (TIFF only).
    Float32,
}

impl SampleDepth {
    fn describe(self) -> &'static str {
        match self {
            SampleDepth::Eight => "8-bit samples",
            SampleDepth::Sixteen => "16-bit samples",
            SampleDepth::Float32 => "32-bit float samples",
        }
    }
}

/// The container format, chosen from the file extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageFormat {
    /// `.png`
    Png,
    /// `.tif` or `.tiff`
    Tiff,
}

impl ImageFormat {
    /// The format for a path's extension (case-insensitive).
    pub fn from_path(path: &Path) -> Result<ImageFormat, RenderError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("")
            .to_ascii_lowercase();
        match ext.as_str() {
            "png" => Ok(ImageFormat::Png),
            "tif" | "tiff" => Ok(ImageFormat::Tiff),
            _ => Err(RenderError::UnsupportedFormat(path.display().to_string())),
        }
    }
}

/// Refuses a sample depth the format cannot hold.
pub(crate) fn check_depth(format: ImageFormat, depth: SampleDepth) -> Result<(), RenderError> {
    if format == ImageFormat::Png && depth == SampleDepth::Float32 {
        return Err(RenderError::UnsupportedDepth {
            format: "PNG",
            depth: depth.describe(),
        });
    }
    Ok(())
}

/// The directory an output goes into (`.` for a bare file name).
pub(crate) fn output_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// Write the image to `path` in the format its extension names.
///
/// Errors name `path`, never the temporary file. While the temporary file
/// exists it is listed for [`remove_unfinished_outputs`], which a signal
/// handler calls before the process exits.
pub fn write_image(image: &Image, path: &Path, depth: SampleDepth) -> Result<(), RenderError> {
    let format = ImageFormat::from_path(path)?;
    check_depth(format, depth)?;
    let io = |source| RenderError::Io {
        path: path.to_path_buf(),
        source,
    };
    let tmp = tempfile::Builder::new()
        .prefix(".hscene-")
        .suffix(".part")
        .tempfile_in(output_dir(path))
        // tempfile names its file in the message; only the kind is kept.
        .map_err(|e| io(e.kind().into()))?;
    let live = crate::unfinished::LIVE.register(tmp.path());
    {
        let mut out = BufWriter::new(tmp.as_file());
        match format {
            ImageFormat::Png => encode_png(image, depth, &mut out, path)?,
            ImageFormat::Tiff => encode_tiff(image, depth, &mut out, path)?,
        }
        out.flush().map_err(io)?;
    }
    tmp.as_file().sync_all().map_err(io)?;
    // Temporary files are created private (0600); an image replacing an
    // existing one keeps that file's permissions, a new one gets the usual
    // 0644, so the result reads like any file the user wrote.
    let permissions = match std::fs::metadata(path) {
        Ok(m) => Some(m.permissions()),
        Err(_) => default_permissions(),
    };
    if let Some(p) = permissions {
        tmp.as_file().set_permissions(p).map_err(io)?;
    }
    live.finish(|| tmp.persist(path).map(drop).map_err(|e| io(e.error)))
}

#[cfg(unix)]
fn default_permissions() -> Option<std::fs::Permissions> {
    use std::os::unix::fs::PermissionsExt;
    Some(std::fs::Permissions::from_mode(0o644))
}

#[cfg(not(unix))]
fn default_permissions() -> Option<std::fs::Permissions> {
    None
}

fn encode_png(
    image: &Image,
    depth: SampleDepth,
    out: &mut BufWriter<&File>,
    path: &Path,
) -> Result<(), RenderError> {
    use image::ImageEncoder;
    use image::codecs::png::PngEncoder;
    let enc = PngEncoder::new(out);
    let (w, h) = (image.width(), image.height());
    let result = match depth {
        SampleDepth::Eight => {
            enc.write_image(&image.to_rgb8(), w, h, image::ExtendedColorType::Rgb8)
        }
        _ => {
            // The image crate takes 16-bit samples in native byte order and
            // writes them big-endian itself, as PNG requires; converting to
            // big-endian here would swap them twice on little-endian hosts.
            let bytes: Vec<u8> = image
                .to_rgb16()
                .iter()
                .flat_map(|v| v.to_ne_bytes())
                .collect();
            enc.write_image(&bytes, w, h, image::ExtendedColorType::Rgb16)
        }
    };
    result.map_err(|e| RenderError::Encode {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

fn encode_tiff(
    image: &Image,
    depth: SampleDepth,
    out: &mut BufWriter<&File>,
    path: &Path,
) -> Result<(), RenderError> {
    let err = |e: tiff::TiffError| RenderError::Encode {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut enc = TiffEncoder::new(out).map_err(err)?;
    let (w, h) = (image.width(), image.height());
    match depth {
        SampleDepth::Eight => enc.write_image::<colortype::RGB8>(w, h, &image.to_rgb8()),
        SampleDepth::Sixteen => enc.write_image::<colortype::RGB16>(w, h, &image.to_rgb16()),
        SampleDepth::Float32 => enc.write_image::<colortype::RGB32Float>(w, h, &image.to_rgb32f()),
    }
    .map_err(err)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tiny() -> Image {
        Image::from_pixels(2, 1, vec![[0.25, 0.5, 2.0], [0.0, 1.0, 0.125]])
    }

    #[test]
    fn writes_png_and_tiff_of_every_depth() {
        let dir = tempfile::tempdir().unwrap();
        for (name, depth) in [
            ("a.png", SampleDepth::Eight),
            ("b.png", SampleDepth::Sixteen),
            ("c.tif", SampleDepth::Eight),
            ("d.tiff", SampleDepth::Sixteen),
            ("e.tif", SampleDepth::Float32),
        ] {
            let path = dir.path().join(name);
            write_image(&tiny(), &path, depth).unwrap();
            assert!(std::fs::metadata(&path).unwrap().len() > 0, "{name}");
        }
        // Only the outputs remain: no temporary files left behind.
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 5);
    }

    #[cfg(unix)]
    #[test]
    fn outputs_are_not_left_private() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("new.png");
        write_image(&tiny(), &path, SampleDepth::Eight).unwrap();
        let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode(&path), 0o644);
        // Replacing a file keeps its permissions.
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o640)).unwrap();
        write_image(&tiny(), &path, SampleDepth::Eight).unwrap();
        assert_eq!(mode(&path), 0o640);
    }

    #[test]
    fn float_tiff_keeps_unclamped_values() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("hdr.tif");
        write_image(&tiny(), &path, SampleDepth::Float32).unwrap();
        let mut dec = tiff::decoder::Decoder::new(File::open(&path).unwrap()).unwrap();
        match dec.read_image().unwrap() {
            tiff::decoder::DecodingResult::F32(v) => assert_eq!(v[2], 2.0),
            other => panic!("unexpected {:?}", std::mem::discriminant(&other)),
        }
    }

    #[test]
    fn failed_write_leaves_existing_file_untouched() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("keep.png");
        std::fs::write(&path, b"precious").unwrap();
        assert!(write_image(&tiny(), &path, SampleDepth::Float32).is_err());
        assert_eq!(std::fs::read(&path).unwrap(), b"precious");
        assert!(matches!(
            write_image(&tiny(), &dir.path().join("x.bmp"), SampleDepth::Eight),
            Err(RenderError::UnsupportedFormat(_))
        ));
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }
}
