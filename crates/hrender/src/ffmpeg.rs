//! MP4 and WebM through `ffmpeg`: a trial encode of the picture's size
//! before anything is rendered, the encoder fed raw frames on its standard
//! input, and the file it wrote verified before it may replace an output.
//!
//! ffmpeg can exit 0 after a failed write (past `ulimit -f`, on a full
//! disk it reports "Error writing trailer" and a truncated file), so its
//! exit status alone proves nothing: the file is accepted only when ffmpeg
//! printed no error, the file is not empty and `ffprobe` counts in it every
//! frame that was sent.

use std::io::Read;
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::thread::JoinHandle;

use crate::error::RenderError;

/// The most of ffmpeg's error output kept for a message: its first lines
/// say why; a stream of repeated errors must not grow memory.
const MAX_STDERR_BYTES: usize = 4096;

/// The most of ffmpeg's reason quoted in an error message.
const MAX_REASON_CHARS: usize = 400;

/// MP4 (H.264) or WebM (VP9).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Codec {
    H264,
    Vp9,
}

impl Codec {
    fn args(self) -> [&'static str; 8] {
        match self {
            Codec::H264 => [
                "-c:v", "libx264", "-preset", "medium", "-crf", "18", "-f", "mp4",
            ],
            Codec::Vp9 => [
                "-c:v",
                "libvpx-vp9",
                "-b:v",
                "0",
                "-crf",
                "30",
                "-f",
                "webm",
            ],
        }
    }
}

/// The common arguments: quiet but for errors, yuv420p (what every player
/// reads), odd sizes padded by a pixel.
fn base_command() -> Command {
    let mut cmd = Command::new("ffmpeg");
    cmd.args(["-nostdin", "-hide_banner", "-loglevel", "error", "-y"]);
    cmd
}

const PIXELS_OUT: [&str; 4] = [
    "-pix_fmt",
    "yuv420p",
    "-vf",
    "pad=ceil(iw/2)*2:ceil(ih/2)*2",
];

fn failed(path: &Path, reason: &str) -> RenderError {
    RenderError::Ffmpeg {
        path: path.to_path_buf(),
        reason: short_reason(reason),
    }
}

/// [`failed`] for an error about the temporary file, which names the
/// output asked for instead (messages never name a temporary file).
fn failed_writing(path: &Path, tmp: &Path, reason: &str) -> RenderError {
    let shown = path.display().to_string();
    failed(path, &reason.replace(&tmp.display().to_string(), &shown))
}

/// ffmpeg's reason on one line, cut to a readable length.
fn short_reason(text: &str) -> String {
    let joined = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ");
    if joined.is_empty() {
        return "no reason given".into();
    }
    if joined.chars().count() > MAX_REASON_CHARS {
        let cut: String = joined.chars().take(MAX_REASON_CHARS).collect();
        return format!("{cut}…");
    }
    joined
}

/// Encodes one black frame of the picture's size to nothing, so that a
/// size or rate the codec refuses (libx264's "invalid width") is reported
/// with ffmpeg's own words before any frame is rendered.
pub(crate) fn trial_encode(
    path: &Path,
    codec: Codec,
    width: u32,
    height: u32,
    fps: f64,
) -> Result<(), RenderError> {
    let source = format!("color=c=black:s={width}x{height}:r={fps}");
    // The fastest settings: only whether the encoder opens matters.
    let fast: &[&str] = match codec {
        Codec::H264 => &["-c:v", "libx264", "-preset", "ultrafast"],
        Codec::Vp9 => &[
            "-c:v",
            "libvpx-vp9",
            "-deadline",
            "realtime",
            "-cpu-used",
            "8",
        ],
    };
    let mut cmd = base_command();
    cmd.args(["-f", "lavfi", "-i", &source, "-frames:v", "1"])
        .args(fast)
        .args(PIXELS_OUT)
        .args(["-f", "null", "-"])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    #[cfg(unix)]
    std::os::unix::process::CommandExt::process_group(&mut cmd, 0);
    // Listed like the encoder, so that a signal meanwhile stops it too.
    let (mut child, mut listed) = crate::unfinished::spawn_listed(&mut cmd)
        .map_err(|_| RenderError::NoFfmpeg(path.to_path_buf()))?;
    let stderr = child.stderr.take().map(read_bounded).unwrap_or_default();
    listed.done();
    let ok = child.wait().is_ok_and(|s| s.success());
    if !ok {
        return Err(failed(path, &String::from_utf8_lossy(&stderr)));
    }
    Ok(())
}

/// Reads a pipe to its end, keeping its first [`MAX_STDERR_BYTES`].
fn read_bounded(mut pipe: impl Read) -> Vec<u8> {
    let mut kept = Vec::new();
    let mut buf = [0u8; 4096];
    while let Ok(n) = pipe.read(&mut buf) {
        if n == 0 {
            break;
        }
        let room = MAX_STDERR_BYTES.saturating_sub(kept.len());
        kept.extend_from_slice(&buf[..n.min(room)]);
    }
    kept
}

/// A running encoder: its input pipe and its error output, drained on a
/// thread of its own (a full pipe would stall ffmpeg, and with it us).
pub(crate) struct Encoder {
    child: Child,
    stdin: Option<ChildStdin>,
    stderr: Option<JoinHandle<Vec<u8>>>,
    listed: crate::unfinished::ListedChild,
    tmp: std::path::PathBuf,
}

impl Encoder {
    /// Starts ffmpeg writing `tmp`. It runs in a process group of its own,
    /// so a Ctrl-C at the terminal reaches hscene alone, which stops it
    /// (module `unfinished`) before removing the file.
    pub(crate) fn start(
        path: &Path,
        tmp: &Path,
        codec: Codec,
        width: u32,
        height: u32,
        fps: f64,
    ) -> Result<Encoder, RenderError> {
        let mut cmd = base_command();
        cmd.args(["-f", "rawvideo", "-pix_fmt", "rgb24"])
            .args(["-s", &format!("{width}x{height}")])
            .args(["-framerate", &format!("{fps}"), "-i", "-"]);
        let args = codec.args();
        cmd.args(&args[..6])
            .args(PIXELS_OUT)
            .args(&args[6..])
            .arg(tmp)
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::piped());
        #[cfg(unix)]
        std::os::unix::process::CommandExt::process_group(&mut cmd, 0);
        let (child, listed) = crate::unfinished::spawn_listed(&mut cmd)
            .map_err(|_| RenderError::NoFfmpeg(path.to_path_buf()))?;
        let mut child = child;
        let stdin = child.stdin.take();
        let stderr = child
            .stderr
            .take()
            .map(|pipe| std::thread::spawn(move || read_bounded(pipe)));
        Ok(Encoder {
            child,
            stdin,
            stderr,
            listed,
            tmp: tmp.to_path_buf(),
        })
    }

    /// Sends one frame. When ffmpeg has stopped reading, the error is its
    /// own reason, not the pipe's.
    pub(crate) fn send(&mut self, path: &Path, rgb: &[u8]) -> Result<(), RenderError> {
        use std::io::Write;
        let Some(pipe) = self.stdin.as_mut() else {
            return Err(failed(path, "its input is closed"));
        };
        if pipe.write_all(rgb).is_ok() {
            return Ok(());
        }
        self.stdin = None;
        let (_, stderr) = self.wait();
        Err(failed_writing(path, &self.tmp, &stderr))
    }

    /// Closes the input and waits for ffmpeg; returns its success and its
    /// error output.
    fn wait(&mut self) -> (bool, String) {
        self.stdin = None;
        self.listed.done();
        let ok = self.child.wait().is_ok_and(|s| s.success());
        let stderr = self
            .stderr
            .take()
            .and_then(|t| t.join().ok())
            .unwrap_or_default();
        (ok, String::from_utf8_lossy(&stderr).into_owned())
    }

    /// Ends the stream and verifies the file ffmpeg wrote to `tmp` holds
    /// all `frames` frames (module docs).
    pub(crate) fn finish(mut self, path: &Path, frames: u32) -> Result<(), RenderError> {
        let (ok, stderr) = self.wait();
        let tmp = self.tmp.clone();
        let tmp = tmp.as_path();
        if !ok || !stderr.trim().is_empty() {
            return Err(failed_writing(path, tmp, &stderr));
        }
        let size = std::fs::metadata(tmp).map(|m| m.len()).unwrap_or(0);
        if size == 0 {
            return Err(failed(path, "it wrote an empty file"));
        }
        let counted = count_frames(path, tmp)?;
        if counted != u64::from(frames) {
            return Err(RenderError::VideoIncomplete {
                path: path.to_path_buf(),
                frames,
                counted,
            });
        }
        Ok(())
    }
}

impl Drop for Encoder {
    /// An encoder dropped unfinished (an error elsewhere) is stopped and
    /// waited for, so that it cannot write its file after it was removed.
    fn drop(&mut self) {
        if self.stderr.is_some() {
            let _ = self.child.kill();
            let _ = self.wait();
        }
    }
}

/// The frames `ffprobe` finds in the file: its packets, counted without
/// decoding (one per frame for H.264 and VP9), so a long video is checked
/// in a fraction of its encoding time. A file ffprobe cannot read counts 0.
fn count_frames(path: &Path, file: &Path) -> Result<u64, RenderError> {
    let out = Command::new("ffprobe")
        .args(["-v", "error", "-count_packets", "-select_streams", "v:0"])
        .args(["-show_entries", "stream=nb_read_packets", "-of", "csv=p=0"])
        .arg(file)
        .stdin(Stdio::null())
        .stderr(Stdio::null())
        .output()
        .map_err(|_| RenderError::NoFfmpeg(path.to_path_buf()))?;
    Ok(String::from_utf8_lossy(&out.stdout)
        .trim()
        .trim_end_matches(',')
        .parse()
        .unwrap_or(0))
}

/// True if `ffmpeg` and `ffprobe` both run.
pub(crate) fn available() -> bool {
    ["ffmpeg", "ffprobe"].iter().all(|tool| {
        Command::new(tool)
            .arg("-version")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reasons_are_one_bounded_line() {
        assert_eq!(short_reason("\n  a\n\nb  \n"), "a; b");
        assert_eq!(short_reason(""), "no reason given");
        let long = "x".repeat(10_000);
        assert_eq!(short_reason(&long).chars().count(), MAX_REASON_CHARS + 1);
    }
}
