//! Animations as one file: GIF and APNG written here, frame by frame, and
//! MP4 and WebM through `ffmpeg` (raw RGB frames streamed to its standard
//! input as they are rendered, so no more than one frame is held). Every
//! kind is written like an image: into a temporary file beside the output,
//! listed for the signal cleanup, renamed over the output when the last
//! frame is in; a failed or interrupted animation leaves the earlier file.
//!
//! Frames are the 8-bit display values ([`DisplayTransform::to_rgb8`]).
//! GIF has 256 colours a frame (NeuQuant, per frame) and a delay in
//! hundredths of a second; APNG keeps every colour; MP4 is H.264 in
//! `yuv420p` (what every player reads; odd sizes are padded by a pixel),
//! WebM VP9.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use crate::display::DisplayTransform;
use crate::error::RenderError;
use crate::ffmpeg::{self, Codec, Encoder};
use crate::image::Image;
use crate::output::StartedOutput;

/// An animation format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VideoFormat {
    /// Animated GIF (looping).
    Gif,
    /// Animated PNG (looping).
    Apng,
    /// H.264 in MP4, through ffmpeg.
    Mp4,
    /// VP9 in WebM, through ffmpeg.
    Webm,
}

impl VideoFormat {
    /// The format an output's extension names, if it is a video one.
    pub fn from_path(path: &Path) -> Option<VideoFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        Some(match ext.as_str() {
            "gif" => VideoFormat::Gif,
            "apng" => VideoFormat::Apng,
            "mp4" => VideoFormat::Mp4,
            "webm" => VideoFormat::Webm,
            _ => return None,
        })
    }

    /// True for the formats written through ffmpeg.
    pub fn needs_ffmpeg(self) -> bool {
        matches!(self, VideoFormat::Mp4 | VideoFormat::Webm)
    }
}

/// True if `ffmpeg` and `ffprobe` (which verifies what ffmpeg wrote) run.
pub fn ffmpeg_available() -> bool {
    ffmpeg::available()
}

/// Checks what can be known before rendering: the format needs nothing
/// missing (ffmpeg for MP4 and WebM).
pub fn check_video(path: &Path) -> Result<VideoFormat, RenderError> {
    let format = VideoFormat::from_path(path)
        .ok_or_else(|| RenderError::UnsupportedFormat(path.display().to_string()))?;
    if format.needs_ffmpeg() && !ffmpeg_available() {
        return Err(RenderError::NoFfmpeg(path.to_path_buf()));
    }
    Ok(format)
}

enum Sink {
    Gif(gif::Encoder<BufWriter<File>>),
    Apng(png::Writer<BufWriter<File>>),
    Ffmpeg(Encoder),
}

/// An animation being written (module docs).
pub struct VideoWriter {
    path: PathBuf,
    // Dropped before `started`: an encoder is stopped before its
    // temporary file is removed, so it cannot create the file again.
    sink: Sink,
    started: StartedOutput<'static>,
    width: u32,
    height: u32,
    frames: u32,
    fps: f64,
    display: DisplayTransform,
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> RenderError + '_ {
    move |source| RenderError::Io {
        path: path.to_path_buf(),
        source,
    }
}

fn encode(path: &Path) -> impl Fn(String) -> RenderError + '_ {
    move |message| RenderError::Encode {
        path: path.to_path_buf(),
        message,
    }
}

impl VideoWriter {
    /// Starts `path` for `frames` frames of `width` x `height` at `fps`
    /// frames per second.
    pub fn create(
        path: &Path,
        width: u32,
        height: u32,
        frames: u32,
        fps: f64,
        display: DisplayTransform,
    ) -> Result<VideoWriter, RenderError> {
        let format = check_video(path)?;
        let started = StartedOutput::new(path)?;
        let file = || started.tmp.reopen().map(BufWriter::new).map_err(io(path));
        let too_big = || encode(path)(format!("{width}x{height} is too large for this format"));
        let sink = match format {
            VideoFormat::Gif => {
                let (w, h) = (
                    u16::try_from(width).map_err(|_| too_big())?,
                    u16::try_from(height).map_err(|_| too_big())?,
                );
                let mut e = gif::Encoder::new(file()?, w, h, &[])
                    .map_err(|e| encode(path)(e.to_string()))?;
                e.set_repeat(gif::Repeat::Infinite)
                    .map_err(|e| encode(path)(e.to_string()))?;
                Sink::Gif(e)
            }
            VideoFormat::Apng => {
                let mut e = png::Encoder::new(file()?, width, height);
                e.set_color(png::ColorType::Rgb);
                e.set_depth(png::BitDepth::Eight);
                e.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
                let err = |e: png::EncodingError| encode(path)(e.to_string());
                e.set_animated(frames.max(1), 0).map_err(err)?;
                let (num, den) = frame_delay(fps);
                e.set_frame_delay(num, den).map_err(err)?;
                Sink::Apng(e.write_header().map_err(err)?)
            }
            VideoFormat::Mp4 | VideoFormat::Webm => {
                let codec = if format == VideoFormat::Mp4 {
                    Codec::H264
                } else {
                    Codec::Vp9
                };
                ffmpeg::trial_encode(path, codec, width, height, fps)?;
                Sink::Ffmpeg(Encoder::start(
                    path,
                    started.tmp.path(),
                    codec,
                    width,
                    height,
                    fps,
                )?)
            }
        };
        Ok(VideoWriter {
            path: path.to_path_buf(),
            started,
            sink,
            width,
            height,
            frames: 0,
            fps,
            display,
        })
    }

    /// Appends a frame (of the size the video was created with).
    pub fn push(&mut self, image: &Image) -> Result<(), RenderError> {
        if (image.width(), image.height()) != (self.width, self.height) {
            return Err(encode(&self.path)(format!(
                "frame {} is {}x{}, not {}x{}",
                self.frames,
                image.width(),
                image.height(),
                self.width,
                self.height
            )));
        }
        let rgb = self.display.to_rgb8(image.pixels());
        let path = self.path.clone();
        match &mut self.sink {
            Sink::Gif(e) => {
                // Speed 10 of NeuQuant's 1 (best) to 30: good colours at a
                // tenth of the best's time.
                let mut frame =
                    gif::Frame::from_rgb_speed(self.width as u16, self.height as u16, &rgb, 10);
                frame.delay = gif_delay(self.fps, self.frames);
                e.write_frame(&frame)
                    .map_err(|e| encode(&path)(e.to_string()))?;
            }
            Sink::Apng(w) => w
                .write_image_data(&rgb)
                .map_err(|e| encode(&path)(e.to_string()))?,
            Sink::Ffmpeg(encoder) => encoder.send(&path, &rgb)?,
        }
        self.frames += 1;
        Ok(())
    }

    /// Finishes the file and renames it over the output.
    pub fn finish(self) -> Result<(), RenderError> {
        let VideoWriter {
            path,
            started,
            sink,
            frames,
            ..
        } = self;
        match sink {
            Sink::Gif(e) => {
                let mut w = e.into_inner().map_err(io(&path))?;
                w.flush().map_err(io(&path))?;
            }
            Sink::Apng(w) => {
                w.finish().map_err(|e| encode(&path)(e.to_string()))?;
            }
            Sink::Ffmpeg(encoder) => encoder.finish(&path, frames)?,
        }
        started.finish(None)
    }
}

/// APNG's frame delay as a fraction of a second, `num/den` with both
/// at most 65,535: `1/fps` to a thousandth of a frame a second, so 23.976
/// (24000/1001) plays at 23.976 and not at the 25 of hundredths.
fn frame_delay(fps: f64) -> (u16, u16) {
    for num in [1000u16, 100, 10, 1] {
        let den = (fps * f64::from(num)).round();
        if (1.0..=65535.0).contains(&den) {
            let (n, d) = (u32::from(num), den as u32);
            let g = gcd(n, d);
            return ((n / g) as u16, (d / g) as u16);
        }
    }
    (1, 65535)
}

fn gcd(a: u32, b: u32) -> u32 {
    if b == 0 { a.max(1) } else { gcd(b, a % b) }
}

/// The fastest rate a GIF plays at: delays under 2 hundredths of a second
/// are played by browsers at 10 frames a second.
const GIF_MAX_FPS: f64 = 50.0;

/// GIF's delay after frame `k`, in hundredths of a second. Delays are
/// whole hundredths, so a rate like 24 (4.1667 each) cannot be one delay:
/// each frame ends at `k + 1` frames' time rounded to the hundredth, so
/// the delays alternate (4, 4, 5, 4, 4, 4, ...) and frame `k` starts
/// within half a hundredth of `k / fps` however long the animation runs.
/// Above 50 frames a second every delay is the least, 2.
fn gif_delay(fps: f64, k: u32) -> u16 {
    if fps > GIF_MAX_FPS {
        return 2;
    }
    let end = |k: u32| (100.0 * f64::from(k) / fps).round();
    // `fps` is at least 0.1 (the render checks it), so a delay is at most
    // 1,000; the clamp keeps a smaller rate from wrapping.
    (end(k + 1) - end(k)).clamp(2.0, 65535.0) as u16
}

/// The rate a video of `format` written at `fps` plays at: GIF's delays
/// are whole hundredths of a second, alternated to keep the rate on
/// average ([`gif_delay`]), and at least 2 (so at most 50 frames a
/// second), APNG's are exact to a thousandth of a frame a second, MP4 and
/// WebM exact. The render says so when it is not the rate asked for.
pub fn played_fps(format: VideoFormat, fps: f64) -> f64 {
    match format {
        VideoFormat::Gif => fps.min(GIF_MAX_FPS),
        VideoFormat::Apng => {
            let (num, den) = frame_delay(fps);
            f64::from(den) / f64::from(num)
        }
        VideoFormat::Mp4 | VideoFormat::Webm => fps,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn played_rates_are_what_the_formats_hold() {
        assert_eq!(played_fps(VideoFormat::Gif, 240.0), 50.0);
        assert_eq!(played_fps(VideoFormat::Gif, 25.0), 25.0);
        assert!((played_fps(VideoFormat::Apng, 23.976) - 23.976).abs() < 1e-9);
        assert_eq!(played_fps(VideoFormat::Apng, 240.0), 240.0);
        assert_eq!(played_fps(VideoFormat::Apng, 0.1), 0.1);
        assert_eq!(frame_delay(24000.0 / 1001.0), (125, 2997));
        assert_eq!(played_fps(VideoFormat::Gif, 24.0), 24.0);
        assert_eq!(played_fps(VideoFormat::Gif, 30.0), 30.0);
    }

    #[test]
    fn gif_delays_keep_every_frame_within_half_a_hundredth_of_its_time() {
        for fps in [24.0, 30.0, 23.976, 12.0, 7.0, 50.0, 0.1] {
            let mut start = 0u64;
            for k in 0..2000 {
                let want = 100.0 * f64::from(k) / fps;
                assert!(
                    (start as f64 - want).abs() <= 0.5 + 1e-9,
                    "{fps} fps, frame {k}: {start} cs, not {want}"
                );
                let d = gif_delay(fps, k);
                assert!(d >= 2, "{fps} fps: delay {d}");
                start += u64::from(d);
            }
        }
        let first: Vec<u16> = (0..6).map(|k| gif_delay(24.0, k)).collect();
        assert_eq!(first, [4, 4, 5, 4, 4, 4]);
        assert_eq!(gif_delay(240.0, 7), 2);
    }
}
