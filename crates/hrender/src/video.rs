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
use std::process::{Child, ChildStdin, Command, Stdio};

use crate::display::DisplayTransform;
use crate::error::RenderError;
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

/// True if `ffmpeg` runs.
pub fn ffmpeg_available() -> bool {
    Command::new("ffmpeg")
        .arg("-version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
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
    Ffmpeg(Child, Option<ChildStdin>),
}

/// An animation being written (module docs).
pub struct VideoWriter {
    path: PathBuf,
    started: StartedOutput<'static>,
    sink: Sink,
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
                let (codec, container) = if format == VideoFormat::Mp4 {
                    (
                        ["-c:v", "libx264", "-preset", "medium", "-crf", "18"],
                        "mp4",
                    )
                } else {
                    (["-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "30"], "webm")
                };
                let mut child = Command::new("ffmpeg")
                    .args(["-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo"])
                    .args(["-pix_fmt", "rgb24", "-s", &format!("{width}x{height}")])
                    .args(["-framerate", &format!("{fps}"), "-i", "-"])
                    .args(codec)
                    .args([
                        "-pix_fmt",
                        "yuv420p",
                        "-vf",
                        "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                    ])
                    .args(["-f", container])
                    .arg(started.tmp.path())
                    .stdin(Stdio::piped())
                    .stdout(Stdio::null())
                    .stderr(Stdio::piped())
                    .spawn()
                    .map_err(|_| RenderError::NoFfmpeg(path.to_path_buf()))?;
                let stdin = child.stdin.take();
                Sink::Ffmpeg(child, stdin)
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
                frame.delay = gif_delay(self.fps);
                e.write_frame(&frame)
                    .map_err(|e| encode(&path)(e.to_string()))?;
            }
            Sink::Apng(w) => w
                .write_image_data(&rgb)
                .map_err(|e| encode(&path)(e.to_string()))?,
            Sink::Ffmpeg(_, stdin) => {
                let pipe = stdin
                    .as_mut()
                    .ok_or_else(|| encode(&path)("ffmpeg's input is closed".into()))?;
                pipe.write_all(&rgb)
                    .map_err(|e| encode(&path)(format!("ffmpeg stopped reading frames: {e}")))?;
            }
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
            Sink::Ffmpeg(child, stdin) => {
                drop(stdin);
                let out = child.wait_with_output().map_err(io(&path))?;
                if !out.status.success() {
                    let message = String::from_utf8_lossy(&out.stderr).trim().to_string();
                    return Err(encode(&path)(format!("ffmpeg failed: {message}")));
                }
            }
        }
        started.finish(None)
    }
}

/// APNG's frame delay as a fraction of a second: `1/fps` for whole rates,
/// else hundredths.
fn frame_delay(fps: f64) -> (u16, u16) {
    if fps.fract() == 0.0 && (1.0..=65535.0).contains(&fps) {
        (1, fps as u16)
    } else {
        ((100.0 / fps).round().clamp(1.0, 65535.0) as u16, 100)
    }
}

/// GIF's frame delay in hundredths of a second (at least 2: browsers
/// play shorter delays at 10 frames a second).
fn gif_delay(fps: f64) -> u16 {
    (100.0 / fps).round().clamp(2.0, 65535.0) as u16
}
