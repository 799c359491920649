//! Writing images: PNG, TIFF and OpenEXR, always atomically.
//!
//! Integer samples pass through the [`DisplayTransform`] (tone curve, sRGB
//! or linear encoding) and carry the matching colour tag; float samples
//! (float TIFF, OpenEXR) keep the linear, unclamped radiance.
//!
//! The encoder writes to a temporary file in the destination's directory,
//! which is flushed and then renamed over the destination. A failure at any
//! point leaves no partial file and does not touch an existing one.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use tiff::encoder::{TiffEncoder, colortype};

use crate::display::{DisplayTransform, Encoding};
use crate::error::RenderError;
use crate::icc;
use crate::image::Image;

/// Sample format of the written file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SampleDepth {
    /// 8-bit integer, clamped (PNG or TIFF).
    #[default]
    Eight,
    /// 16-bit integer, clamped (PNG or TIFF).
    Sixteen,
    /// 32-bit float, unclamped high dynamic range (TIFF or OpenEXR).
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
    /// `.exr` (OpenEXR, always 32-bit float)
    Exr,
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
            "exr" => Ok(ImageFormat::Exr),
            _ => Err(RenderError::UnsupportedFormat(path.display().to_string())),
        }
    }

    /// The sample depth a format gets when none is asked for: 8-bit for
    /// PNG and TIFF, float for OpenEXR (its only depth here).
    pub fn default_depth(self) -> SampleDepth {
        match self {
            ImageFormat::Png | ImageFormat::Tiff => SampleDepth::Eight,
            ImageFormat::Exr => SampleDepth::Float32,
        }
    }
}

/// How hard a PNG's image data is deflated: the zlib level, from 0
/// (stored) to 9 (smallest, slowest).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PngLevel(u8);

impl PngLevel {
    /// Level 3, the default: a rendered picture's file is about a seventh
    /// larger than at zlib's own default of 6, and deflating it takes about
    /// half the time, which for a fast render is a twentieth of the whole
    /// (docs/rendering.md, "PNG compression").
    pub const DEFAULT: PngLevel = PngLevel(3);
    /// The highest level.
    pub const MAX: u8 = 9;

    /// The level `level`, if it is one (`0..=9`).
    pub fn new(level: u8) -> Option<PngLevel> {
        (level <= Self::MAX).then_some(PngLevel(level))
    }

    /// The zlib level.
    pub fn get(self) -> u8 {
        self.0
    }
}

impl Default for PngLevel {
    fn default() -> PngLevel {
        PngLevel::DEFAULT
    }
}

/// Write the image to `path` in the format its extension names, integer
/// samples sRGB-encoded and clipped (the default [`DisplayTransform`]),
/// a PNG at the default [`PngLevel`].
pub fn write_image(image: &Image, path: &Path, depth: SampleDepth) -> Result<(), RenderError> {
    write_image_with(
        image,
        path,
        depth,
        DisplayTransform::default(),
        PngLevel::DEFAULT,
    )
}

/// Refuse a depth the format cannot store.
pub fn check_depth(format: ImageFormat, depth: SampleDepth) -> Result<(), RenderError> {
    let refused = match format {
        ImageFormat::Png => depth == SampleDepth::Float32,
        ImageFormat::Tiff => false,
        ImageFormat::Exr => depth != SampleDepth::Float32,
    };
    if refused {
        let name = match format {
            ImageFormat::Png => "PNG",
            ImageFormat::Tiff => "TIFF",
            ImageFormat::Exr => "OpenEXR",
        };
        return Err(RenderError::UnsupportedDepth {
            format: name,
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

/// The file a path names once symbolic links are followed (up to 40, as
/// the kernel does): writing an output through a link replaces the file
/// the link names and keeps the link. A dangling link names the file it
/// would create.
pub fn output_target(path: &Path) -> PathBuf {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => match std::fs::read_link(&p) {
                Ok(t) if t.is_absolute() => p = t,
                Ok(t) => p = output_dir(&p).join(t),
                Err(_) => return p,
            },
            _ => return p,
        }
    }
    p
}

/// Write the image to `path` in the format its extension names; integer
/// samples go through `display`; a PNG is deflated at `png`.
///
/// Errors name `path`, never the temporary file. While the temporary file
/// exists it is listed for [`remove_unfinished_outputs`], which a signal
/// handler calls before the process exits.
pub fn write_image_with(
    image: &Image,
    path: &Path,
    depth: SampleDepth,
    display: DisplayTransform,
    png: PngLevel,
) -> Result<(), RenderError> {
    let format = ImageFormat::from_path(path)?;
    check_depth(format, depth)?;
    write_atomically(path, |out| match format {
        ImageFormat::Png => encode_png(image, depth, display, png, out, path),
        ImageFormat::Tiff => encode_tiff(image, depth, display, out, path),
        ImageFormat::Exr => encode_exr(image, out, path),
    })
}

/// Writes `bytes` to `path` as [`write_atomically`] does.
pub fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), RenderError> {
    write_atomically(path, |out| {
        out.write_all(bytes).map_err(|source| RenderError::Io {
            path: path.to_path_buf(),
            source,
        })
    })
}

/// Writes `path` through `write`, atomically: into a temporary file in the
/// same directory, synced, then renamed over `path`, so a reader sees the
/// old file or the whole new one and a failed write leaves the old file.
/// A symbolic link is followed: the file it names is replaced and the link
/// stays. A replaced file keeps its permissions and (where this process
/// may give it) its owner and group.
///
/// Errors name `path`, never the temporary file. While the temporary file
/// exists it is listed for [`remove_unfinished_outputs`], which a signal
/// handler calls before the process exits.
pub fn write_atomically(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<&File>) -> Result<(), RenderError>,
) -> Result<(), RenderError> {
    replace_file(path, None, write)
}

/// Writes several files as one: each into its temporary file, all
/// flushed and synced, and only then each renamed over its output, so a
/// failure while writing any (a full disk, `ulimit -f`) leaves every one
/// of them as it was (an OBJ and its MTL).
pub fn write_files_together(files: &[(&Path, &[u8])]) -> Result<(), RenderError> {
    let mut started = Vec::with_capacity(files.len());
    for (path, bytes) in files {
        let io = |source| RenderError::Io {
            path: path.to_path_buf(),
            source,
        };
        let output = StartedOutput::new(path)?;
        {
            let mut out = BufWriter::new(output.tmp.as_file());
            out.write_all(bytes).map_err(io)?;
            out.flush().map_err(io)?;
        }
        output.tmp.as_file().sync_all().map_err(io)?;
        started.push(output);
    }
    for output in started {
        output.finish(None)?;
    }
    Ok(())
}

/// What a file looked like when it was read: replacing it is refused if it
/// changed since (`hscene fmt`, while an editor saves the same file).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FileStamp {
    len: u64,
    modified: Option<std::time::SystemTime>,
    #[cfg(unix)]
    inode: (u64, u64),
}

impl FileStamp {
    /// The stamp of the file `path` names (links followed).
    pub fn of(path: &Path) -> std::io::Result<FileStamp> {
        let meta = std::fs::metadata(path)?;
        Ok(FileStamp {
            len: meta.len(),
            modified: meta.modified().ok(),
            #[cfg(unix)]
            inode: {
                use std::os::unix::fs::MetadataExt;
                (meta.dev(), meta.ino())
            },
        })
    }
}

/// [`write_atomically`], refused with [`RenderError::ChangedMeanwhile`]
/// when `unchanged_since` is given and the file no longer matches it at
/// the moment before the rename.
pub fn replace_file(
    path: &Path,
    unchanged_since: Option<&FileStamp>,
    write: impl FnOnce(&mut BufWriter<&File>) -> Result<(), RenderError>,
) -> Result<(), RenderError> {
    let io = |source| RenderError::Io {
        path: path.to_path_buf(),
        source,
    };
    let started = StartedOutput::new(path)?;
    {
        let mut out = BufWriter::new(started.tmp.as_file());
        write(&mut out)?;
        out.flush().map_err(io)?;
    }
    started.finish(unchanged_since)
}

/// An output being written: its temporary file beside the file `path`
/// names (links followed), listed for removal by a signal handler.
pub(crate) struct StartedOutput<'l> {
    path: PathBuf,
    target: PathBuf,
    pub(crate) tmp: tempfile::NamedTempFile,
    listed: crate::unfinished::Registered<'l>,
}

impl StartedOutput<'static> {
    pub(crate) fn new(path: &Path) -> Result<Self, RenderError> {
        let target = output_target(path);
        let (tmp, listed) = crate::unfinished::LIVE
            .create(|| {
                tempfile::Builder::new()
                    .prefix(".hscene-")
                    .suffix(".part")
                    .tempfile_in(output_dir(&target))
            })
            // tempfile names its file in the message; only the kind is kept.
            .map_err(|e| RenderError::Io {
                path: path.to_path_buf(),
                source: e.kind().into(),
            })?;
        Ok(StartedOutput {
            path: path.to_path_buf(),
            target,
            tmp,
            listed,
        })
    }
}

impl StartedOutput<'_> {
    /// Syncs the temporary file and renames it over the target.
    /// Temporary files are created private (0600); an output replacing an
    /// existing one keeps that file's permissions and owner, a new one gets
    /// the usual 0644, so the result reads like any file the user wrote.
    pub(crate) fn finish(self, unchanged_since: Option<&FileStamp>) -> Result<(), RenderError> {
        let path = self.path;
        let io = |source| RenderError::Io {
            path: path.clone(),
            source,
        };
        let tmp = self.tmp;
        tmp.as_file().sync_all().map_err(io)?;
        let existing = std::fs::metadata(&self.target).ok();
        let permissions = match &existing {
            Some(m) => Some(m.permissions()),
            None => default_permissions(),
        };
        if let Some(p) = permissions {
            tmp.as_file().set_permissions(p).map_err(io)?;
        }
        if let Some(m) = &existing {
            keep_owner(tmp.as_file(), m);
        }
        let target = self.target;
        self.listed.finish(|| {
            if let Some(stamp) = unchanged_since
                && FileStamp::of(&target).ok().as_ref() != Some(stamp)
            {
                return Err(RenderError::ChangedMeanwhile(path.clone()));
            }
            tmp.persist(&target).map(drop).map_err(|e| io(e.error))
        })
    }
}

/// Gives the new file the old one's owner and group where allowed (root
/// may give any; a user may give a group of theirs); where not, the checks
/// before writing (`output_check.rs`) have asked for `--force`.
#[cfg(unix)]
fn keep_owner(file: &File, old: &std::fs::Metadata) {
    use std::os::unix::fs::MetadataExt;
    let Ok(new) = file.metadata() else {
        return;
    };
    if (new.uid(), new.gid()) != (old.uid(), old.gid()) {
        let _ = std::os::unix::fs::fchown(file, Some(old.uid()), Some(old.gid()));
    }
}

#[cfg(not(unix))]
fn keep_owner(_: &File, _: &std::fs::Metadata) {}

#[cfg(unix)]
fn default_permissions() -> Option<std::fs::Permissions> {
    use std::os::unix::fs::PermissionsExt;
    Some(std::fs::Permissions::from_mode(0o644))
}

#[cfg(not(unix))]
fn default_permissions() -> Option<std::fs::Permissions> {
    None
}

/// PNG through the png crate, which writes the `sRGB` chunk for
/// sRGB-encoded samples; linear samples go untagged, as the thesis wrote
/// them.
fn encode_png(
    image: &Image,
    depth: SampleDepth,
    display: DisplayTransform,
    level: PngLevel,
    out: &mut BufWriter<&File>,
    path: &Path,
) -> Result<(), RenderError> {
    let err = encode_error::<png::EncodingError>(path);
    let mut enc = png::Encoder::new(out, image.width(), image.height());
    enc.set_color(png::ColorType::Rgb);
    // zlib through zlib-rs at the level asked for; the rows keep the png
    // crate's adaptive filter (the best of the five for each row).
    enc.set_deflate_compression(png::DeflateCompression::Level(level.get()));
    if display.encoding == Encoding::Srgb {
        enc.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    }
    let bytes = match depth {
        SampleDepth::Eight => {
            enc.set_depth(png::BitDepth::Eight);
            display.to_rgb8(image.pixels())
        }
        _ => {
            enc.set_depth(png::BitDepth::Sixteen);
            // PNG stores 16-bit samples big-endian.
            display
                .to_rgb16(image.pixels())
                .iter()
                .flat_map(|v| v.to_be_bytes())
                .collect()
        }
    };
    let mut writer = enc.write_header().map_err(err)?;
    writer.write_image_data(&bytes).map_err(err)?;
    writer.finish().map_err(err)
}

/// An ICC profile as a TIFF value of type UNDEFINED, as tag 34675 wants.
struct IccBytes<'a>(&'a [u8]);

impl tiff::encoder::TiffValue for IccBytes<'_> {
    const BYTE_LEN: u8 = 1;
    const FIELD_TYPE: tiff::tags::Type = tiff::tags::Type::UNDEFINED;

    fn count(&self) -> usize {
        self.0.len()
    }

    fn data(&self) -> std::borrow::Cow<'_, [u8]> {
        std::borrow::Cow::Borrowed(self.0)
    }
}

/// TIFF, `PhotometricInterpretation = RGB`: sRGB-encoded integer samples
/// embed the sRGB ICC profile, float samples a linear one with the same
/// primaries; linear integer samples go untagged.
fn encode_tiff(
    image: &Image,
    depth: SampleDepth,
    display: DisplayTransform,
    out: &mut BufWriter<&File>,
    path: &Path,
) -> Result<(), RenderError> {
    let err = encode_error::<tiff::TiffError>(path);
    let mut enc = TiffEncoder::new(out).map_err(err)?;
    let (w, h) = (image.width(), image.height());
    let profile = match (depth, display.encoding) {
        (SampleDepth::Float32, _) => Some(icc::rgb_profile(icc::Curve::Linear)),
        (_, Encoding::Srgb) => Some(icc::rgb_profile(icc::Curve::Srgb)),
        (_, Encoding::Linear) => None,
    };
    macro_rules! write {
        ($colour:ty, $data:expr) => {{
            let mut img = enc.new_image::<$colour>(w, h).map_err(err)?;
            if let Some(p) = &profile {
                img.encoder()
                    .write_tag(tiff::tags::Tag::IccProfile, IccBytes(p))
                    .map_err(err)?;
            }
            img.write_data(&$data).map_err(err)
        }};
    }
    match depth {
        SampleDepth::Eight => write!(colortype::RGB8, display.to_rgb8(image.pixels())),
        SampleDepth::Sixteen => write!(colortype::RGB16, display.to_rgb16(image.pixels())),
        // The image's pixels are interleaved f32 RGB already: written from
        // where they are, not copied (2^27 pixels are 1.6 GB).
        SampleDepth::Float32 => write!(colortype::RGB32Float, image.pixels().as_flattened()),
    }
}

/// OpenEXR: 32-bit float RGB, linear and unclamped, ZIP-compressed (lossless);
/// without a `chromaticities` attribute, which by the OpenEXR convention
/// means Rec. 709 primaries and D65 white, those of sRGB.
fn encode_exr(image: &Image, out: &mut BufWriter<&File>, path: &Path) -> Result<(), RenderError> {
    use exr::prelude::{SpecificChannels, Vec2, WritableImage};
    let (w, h) = (image.width() as usize, image.height() as usize);
    let channels = SpecificChannels::rgb(|p: Vec2<usize>| {
        let [r, g, b] = image.get(p.x() as u32, p.y() as u32);
        (r, g, b)
    });
    let exr_image = exr::image::Image::from_encoded_channels(
        (w, h),
        exr::image::Encoding::SMALL_LOSSLESS,
        channels,
    );
    exr_image
        .write()
        .to_buffered(out)
        .map_err(encode_error(path))
}

/// The error of an encoder writing `path`, in the encoder's words.
fn encode_error<E: std::fmt::Display>(path: &Path) -> impl Fn(E) -> RenderError + Copy + '_ {
    |e| RenderError::Encode {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
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
            ("f.exr", SampleDepth::Float32),
        ] {
            let path = dir.path().join(name);
            write_image(&tiny(), &path, depth).unwrap();
            assert!(std::fs::metadata(&path).unwrap().len() > 0, "{name}");
        }
        // Only the outputs remain: no temporary files left behind.
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 6);
    }

    /// Every PNG level stores the same samples (deflate is lossless), and
    /// on a picture with structure a higher level never gives a larger
    /// file: stored (0) is the largest, 9 the smallest. Levels past 9 do
    /// not exist.
    #[test]
    fn png_levels_store_the_same_samples() {
        let (w, h) = (96u32, 64u32);
        let pixels = (0..w * h)
            .map(|k| {
                let (x, y) = (f64::from(k % w), f64::from(k / w));
                let v = ((x * 0.3).sin() * (y * 0.2).cos() * 0.5 + 0.5) as f32;
                [v, v * v, (x / f64::from(w)) as f32]
            })
            .collect();
        let image = Image::from_pixels(w, h, pixels);
        let dir = tempfile::tempdir().unwrap();
        let mut decoded = Vec::new();
        let mut sizes = Vec::new();
        for level in [0, 3, 6, 9] {
            let path = dir.path().join(format!("l{level}.png"));
            let png = PngLevel::new(level).unwrap();
            write_image_with(
                &image,
                &path,
                SampleDepth::Eight,
                DisplayTransform::default(),
                png,
            )
            .unwrap();
            sizes.push(std::fs::metadata(&path).unwrap().len());
            let mut reader = png::Decoder::new(std::io::BufReader::new(File::open(&path).unwrap()))
                .read_info()
                .unwrap();
            let mut buf = vec![0; reader.output_buffer_size().unwrap()];
            let info = reader.next_frame(&mut buf).unwrap();
            buf.truncate(info.buffer_size());
            decoded.push(buf);
        }
        assert!(decoded.iter().all(|d| *d == decoded[0]));
        assert!(sizes.windows(2).all(|s| s[1] <= s[0]), "{sizes:?}");
        assert!(sizes[0] > sizes[1], "{sizes:?}");
        assert_eq!(PngLevel::default(), PngLevel::new(3).unwrap());
        assert_eq!(PngLevel::new(10), None);
    }

    /// The chunk types of a PNG file, in order.
    fn png_chunks(bytes: &[u8]) -> Vec<String> {
        let mut at = 8;
        let mut names = Vec::new();
        while at + 8 <= bytes.len() {
            let len = u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
            names.push(String::from_utf8_lossy(&bytes[at + 4..at + 8]).into_owned());
            at += 12 + len;
        }
        names
    }

    /// sRGB-encoded PNGs carry the `sRGB` chunk (before the image data);
    /// linear ones carry no colour chunk at all.
    #[test]
    fn png_is_tagged_srgb_unless_linear() {
        let dir = tempfile::tempdir().unwrap();
        for depth in [SampleDepth::Eight, SampleDepth::Sixteen] {
            let path = dir.path().join("srgb.png");
            write_image(&tiny(), &path, depth).unwrap();
            let chunks = png_chunks(&std::fs::read(&path).unwrap());
            let srgb = chunks
                .iter()
                .position(|c| c == "sRGB")
                .expect("an sRGB chunk");
            assert!(srgb < chunks.iter().position(|c| c == "IDAT").unwrap());
            let linear = DisplayTransform {
                encoding: Encoding::Linear,
                ..DisplayTransform::default()
            };
            write_image_with(&tiny(), &path, depth, linear, PngLevel::DEFAULT).unwrap();
            let chunks = png_chunks(&std::fs::read(&path).unwrap());
            for tag in ["sRGB", "gAMA", "cHRM", "iCCP"] {
                assert!(!chunks.iter().any(|c| c == tag), "{tag} in {chunks:?}");
            }
        }
    }

    /// The TIFF carries `PhotometricInterpretation = RGB` and the sRGB ICC
    /// profile (tag 34675), the float TIFF the linear one.
    #[test]
    fn tiff_embeds_the_icc_profile() {
        use tiff::tags::Tag;
        let dir = tempfile::tempdir().unwrap();
        for (depth, curve) in [
            (SampleDepth::Eight, icc::Curve::Srgb),
            (SampleDepth::Sixteen, icc::Curve::Srgb),
            (SampleDepth::Float32, icc::Curve::Linear),
        ] {
            let path = dir.path().join("t.tif");
            write_image(&tiny(), &path, depth).unwrap();
            let mut dec = tiff::decoder::Decoder::new(File::open(&path).unwrap()).unwrap();
            assert_eq!(
                dec.get_tag_u32(Tag::PhotometricInterpretation).unwrap(),
                2,
                "RGB"
            );
            let profile = dec.get_tag_u8_vec(Tag::IccProfile).unwrap();
            assert_eq!(profile, icc::rgb_profile(curve));
        }
    }

    /// The OpenEXR file reads back, with the exr crate, as the same
    /// unclamped float samples.
    #[test]
    fn exr_reads_back_exactly() {
        use exr::prelude::{ReadChannels, ReadLayers};
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("hdr.exr");
        write_image(&tiny(), &path, SampleDepth::Float32).unwrap();
        let read = exr::prelude::read()
            .no_deep_data()
            .largest_resolution_level()
            .rgb_channels(
                |size, _| vec![[0.0f32; 3]; size.width() * size.height()],
                |pixels: &mut Vec<[f32; 3]>, p, (r, g, b): (f32, f32, f32)| {
                    pixels[p.y() * 2 + p.x()] = [r, g, b];
                },
            )
            .first_valid_layer()
            .all_attributes()
            .from_file(&path)
            .unwrap();
        assert_eq!(read.layer_data.size.width(), 2);
        assert_eq!(read.layer_data.channel_data.pixels, tiny().pixels());
        // An 8-bit EXR does not exist.
        assert!(matches!(
            write_image(&tiny(), &path, SampleDepth::Eight),
            Err(RenderError::UnsupportedDepth { .. })
        ));
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

    /// `fmt` reads, formats, then replaces: a save in between (another
    /// length, another time) is kept and the replacement refused.
    #[test]
    fn a_file_changed_since_it_was_read_is_not_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("s.hsc");
        std::fs::write(&path, b"Points{}").unwrap();
        let stamp = FileStamp::of(&path).unwrap();
        std::fs::write(&path, b"Points { saved; }").unwrap();
        let result = replace_file(&path, Some(&stamp), |out| {
            out.write_all(b"Points {}\n")
                .map_err(|source| RenderError::Io {
                    path: path.clone(),
                    source,
                })
        });
        assert!(
            matches!(result, Err(RenderError::ChangedMeanwhile(_))),
            "{result:?}"
        );
        assert_eq!(std::fs::read(&path).unwrap(), b"Points { saved; }");
        assert_eq!(
            std::fs::read_dir(dir.path()).unwrap().count(),
            1,
            "no temporary file"
        );
        // Unchanged, it is replaced.
        let stamp = FileStamp::of(&path).unwrap();
        replace_file(&path, Some(&stamp), |out| {
            out.write_all(b"Points {}\n")
                .map_err(|source| RenderError::Io {
                    path: path.clone(),
                    source,
                })
        })
        .unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"Points {}\n");
    }

    /// An output named through a symbolic link replaces the file the link
    /// names; the link stays.
    #[cfg(unix)]
    #[test]
    fn a_link_is_followed_and_kept() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.png");
        std::fs::write(&real, b"old").unwrap();
        let link = dir.path().join("link.png");
        std::os::unix::fs::symlink("real.png", &link).unwrap();
        write_image(&tiny(), &link, SampleDepth::Eight).unwrap();
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_ne!(std::fs::read(&real).unwrap(), b"old");
    }
}
