//! The viewer without a window: a recorded flight through the scene with
//! the window's own pipeline (a move, its coarse frame, its first full
//! pass), then the still view converged, timed. For scripts, tests and the
//! benchmark.
//!
//! A flight path is text, one move per line (a `#` starts a comment):
//! `forward D`, `back D`, `right D`, `left D`, `up D`, `down D` (hyperbolic
//! distances) and `yaw A`, `pitch A`, `roll A` (degrees; positive yaw
//! turns right, positive pitch looks down).

use std::time::{Duration, Instant};

use hscene_ir::Scene;

use crate::pose::{Axis, Move, Pose};
use crate::progressive::{Frame, Progressive, ViewOptions};

/// The most moves a flight has (`--frames`, or the lines of a path file):
/// each renders a coarse frame and a full pass, so this bounds the time.
pub const MAX_FLIGHT_MOVES: u32 = 10_000;

/// The largest path file read: 1 MiB (10,000 moves take about 150 KB).
pub const MAX_FLIGHT_FILE_BYTES: u64 = 1 << 20;

/// The longest part of a line quoted in an error.
const MAX_QUOTED_CHARS: usize = 40;

/// A sequence of moves: read from a path, or the default flight, made one
/// move at a time as it is flown (nothing is held per move).
#[derive(Clone, Debug, PartialEq)]
pub enum FlightPath {
    /// Moves read from a path file.
    Moves(Vec<Move>),
    /// `n` moves of the default flight: forward and turning gently.
    Default(u32),
}

/// Why a path file gives no flight.
#[derive(Debug, thiserror::Error)]
pub enum FlightError {
    /// A directory, device, FIFO or socket (never opened: a FIFO would
    /// block, a device never end).
    #[error("not a regular file")]
    NotAFile,
    /// Larger than [`MAX_FLIGHT_FILE_BYTES`].
    #[error("the file has {0} bytes, more than the {MAX_FLIGHT_FILE_BYTES} a path may have")]
    TooLarge(u64),
    /// More than [`MAX_FLIGHT_MOVES`] moves.
    #[error("line {0}: more than {MAX_FLIGHT_MOVES} moves")]
    TooManyMoves(usize),
    /// Not UTF-8.
    #[error("the file is not UTF-8 text")]
    NotText,
    /// A line that is no move.
    #[error("line {line}: `{text}` is not a move (e.g. `forward 0.05`, `yaw 2`)")]
    NotAMove {
        /// 1-based.
        line: usize,
        /// The line, cut short.
        text: String,
    },
    /// A distance or angle out of range.
    #[error("line {line}: {value} is out of range (at most 10 for a step, 360 degrees for a turn)")]
    OutOfRange {
        /// 1-based.
        line: usize,
        /// The value, written shortly.
        value: String,
    },
    /// Reading failed.
    #[error("{0}")]
    Io(#[from] std::io::Error),
}

/// A number in a message: short whatever its size (`1e300`, not 301
/// digits).
fn short_number(v: f64) -> String {
    if v != 0.0 && !(1e-4..1e6).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

fn quoted(line: &str) -> String {
    if line.chars().count() > MAX_QUOTED_CHARS {
        let cut: String = line.chars().take(MAX_QUOTED_CHARS).collect();
        format!("{cut}…")
    } else {
        line.to_string()
    }
}

impl FlightPath {
    /// Reads a path file: a regular file (checked before it is opened) of
    /// at most [`MAX_FLIGHT_FILE_BYTES`], parsed as [`FlightPath::parse`].
    pub fn read(path: &std::path::Path) -> Result<FlightPath, FlightError> {
        use hscene_ir::bounded_read::{BoundedReadError, read_regular_file};
        let bytes = read_regular_file(path, MAX_FLIGHT_FILE_BYTES).map_err(|e| match e {
            BoundedReadError::NotAFile => FlightError::NotAFile,
            BoundedReadError::TooLarge(n) => FlightError::TooLarge(n),
            BoundedReadError::Io(e) => FlightError::from(e),
        })?;
        let text = String::from_utf8(bytes).map_err(|_| FlightError::NotText)?;
        FlightPath::parse(&text)
    }

    /// Parses the text form (module docs; a leading byte-order mark is
    /// skipped); the error names the line.
    pub fn parse(text: &str) -> Result<FlightPath, FlightError> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut moves = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            if line.is_empty() {
                continue;
            }
            if moves.len() >= MAX_FLIGHT_MOVES as usize {
                return Err(FlightError::TooManyMoves(n + 1));
            }
            moves.push(parse_move(n + 1, line)?);
        }
        Ok(FlightPath::Moves(moves))
    }

    /// `frames` moves of the default flight (at most [`MAX_FLIGHT_MOVES`]).
    pub fn default_flight(frames: u32) -> FlightPath {
        FlightPath::Default(frames.min(MAX_FLIGHT_MOVES))
    }

    /// The moves in order.
    pub fn moves(&self) -> Box<dyn Iterator<Item = Move> + '_> {
        match self {
            FlightPath::Moves(m) => Box::new(m.iter().copied()),
            FlightPath::Default(n) => Box::new((0..*n).map(|k| {
                if k % 2 == 0 {
                    Move::Step(Axis::Forward, 0.02)
                } else {
                    Move::Turn(Axis::Up, 0.5f64.to_radians())
                }
            })),
        }
    }
}

/// One line of a path file (trimmed, not empty).
fn parse_move(line_no: usize, line: &str) -> Result<Move, FlightError> {
    let bad = || FlightError::NotAMove {
        line: line_no,
        text: quoted(line),
    };
    let mut words = line.split_whitespace();
    let (Some(word), Some(value), None) = (words.next(), words.next(), words.next()) else {
        return Err(bad());
    };
    let v: f64 = value.parse().map_err(|_| bad())?;
    if !(v.is_finite() && v.abs() <= 10.0
        || matches!(word, "yaw" | "pitch" | "roll") && v.abs() <= 360.0)
    {
        return Err(FlightError::OutOfRange {
            line: line_no,
            value: short_number(v),
        });
    }
    let r = v.to_radians();
    Ok(match word {
        "forward" => Move::Step(Axis::Forward, v),
        "back" => Move::Step(Axis::Forward, -v),
        "right" => Move::Step(Axis::Right, v),
        "left" => Move::Step(Axis::Right, -v),
        "up" => Move::Step(Axis::Up, v),
        "down" => Move::Step(Axis::Up, -v),
        "yaw" => Move::Turn(Axis::Up, r),
        "pitch" => Move::Turn(Axis::Right, r),
        "roll" => Move::Turn(Axis::Forward, r),
        _ => return Err(bad()),
    })
}

/// What a headless flight measured.
#[derive(Clone, Debug)]
pub struct HeadlessReport {
    /// Moves flown.
    pub moves: usize,
    /// Summed over the moves: the time from a move to its coarse frame.
    pub to_coarse: Duration,
    /// The longest time from a move to its coarse frame.
    pub worst_coarse: Duration,
    /// Summed over the moves: the time of the first full-resolution pass.
    pub full_pass: Duration,
    /// The time to converge the last view once still, from its first
    /// full pass to its last.
    pub converge: Duration,
    /// The converged picture of the last view.
    pub last: Frame,
    /// The camera it ended at.
    pub pose: Pose,
    /// Moves refused because the eye would leave f64's range.
    pub refused: usize,
}

/// Flies `path` from the scene's camera, then lets the last view converge.
pub fn run_headless(
    scene: &Scene,
    options: ViewOptions,
    path: &FlightPath,
) -> Result<HeadlessReport, String> {
    let mut scene = scene.clone();
    let mut pose = Pose::of(&scene.camera).ok_or("the scene's camera is degenerate")?;
    let mut view = Progressive::new(options);
    let (mut to_coarse, mut full_pass, mut worst_coarse) =
        (Duration::ZERO, Duration::ZERO, Duration::ZERO);
    let (mut moves, mut refused) = (0, 0);
    let err = |e: hrender::RenderError| e.to_string();
    let space = scene.settings.space.as_ref().and_then(|s| s.build().ok());
    for m in path.moves() {
        let start = Instant::now();
        moves += 1;
        match pose.moved(m) {
            Some(p) => pose = space.as_ref().map_or(p, |q| p.folded(q)),
            None => refused += 1,
        }
        scene.camera = pose.camera().ok_or("the camera left f64's range")?;
        view.restart();
        view.step(&scene).map_err(err)?;
        let coarse = start.elapsed();
        to_coarse += coarse;
        worst_coarse = worst_coarse.max(coarse);
        let start = Instant::now();
        view.step(&scene).map_err(err)?;
        full_pass += start.elapsed();
    }
    if moves == 0 {
        view.step(&scene).map_err(err)?;
    }
    let start = Instant::now();
    let mut last = view.step(&scene).map_err(err)?;
    while !view.is_converged() {
        last = view.step(&scene).map_err(err)?;
    }
    Ok(HeadlessReport {
        moves,
        to_coarse,
        worst_coarse,
        full_pass,
        converge: start.elapsed(),
        last,
        pose,
        refused,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_skip_a_byte_order_mark_and_are_bounded() {
        let p = FlightPath::parse("\u{feff}forward 0.1\n# turn\nyaw 2\n").unwrap();
        assert_eq!(p.moves().count(), 2);
        let many = "yaw 1\n".repeat(MAX_FLIGHT_MOVES as usize + 1);
        let err = FlightPath::parse(&many).unwrap_err().to_string();
        assert!(err.contains("more than 10000 moves"), "{err}");
        assert_eq!(FlightPath::default_flight(u32::MAX).moves().count(), 10_000);
    }

    #[test]
    fn huge_numbers_and_long_lines_are_quoted_shortly() {
        let err = FlightPath::parse(&format!("forward 1{}\n", "0".repeat(300)))
            .unwrap_err()
            .to_string();
        assert!(err.contains("1e300"), "{err}");
        assert!(err.len() < 120, "{err}");
        let err = FlightPath::parse(&"x".repeat(100_000))
            .unwrap_err()
            .to_string();
        assert!(err.len() < 160, "{err}");
    }
}
