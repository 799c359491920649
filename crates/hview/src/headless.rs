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

/// A sequence of moves.
#[derive(Clone, Debug, PartialEq)]
pub struct FlightPath(pub Vec<Move>);

impl FlightPath {
    /// Parses the text form (module docs); the error names the line.
    pub fn parse(text: &str) -> Result<FlightPath, String> {
        let mut moves = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            if line.is_empty() {
                continue;
            }
            let bad = || {
                format!(
                    "line {}: `{line}` is not a move (e.g. `forward 0.05`, `yaw 2`)",
                    n + 1
                )
            };
            let mut words = line.split_whitespace();
            let (Some(word), Some(value), None) = (words.next(), words.next(), words.next()) else {
                return Err(bad());
            };
            let v: f64 = value.parse().map_err(|_| bad())?;
            if !(v.is_finite() && v.abs() <= 10.0
                || matches!(word, "yaw" | "pitch" | "roll") && v.abs() <= 360.0)
            {
                return Err(format!(
                    "line {}: {v} is out of range (at most 10 for a step, 360 degrees for a turn)",
                    n + 1
                ));
            }
            let r = v.to_radians();
            moves.push(match word {
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
            });
        }
        Ok(FlightPath(moves))
    }

    /// `frames` moves of the default flight: forward and turning gently.
    pub fn default_flight(frames: u32) -> FlightPath {
        FlightPath(
            (0..frames)
                .map(|k| {
                    if k % 2 == 0 {
                        Move::Step(Axis::Forward, 0.02)
                    } else {
                        Move::Turn(Axis::Up, 0.5f64.to_radians())
                    }
                })
                .collect(),
        )
    }
}

/// What a headless flight measured.
#[derive(Clone, Debug)]
pub struct HeadlessReport {
    /// Per move: the time from the move to its coarse frame.
    pub to_coarse: Vec<Duration>,
    /// Per move: the time of its first full-resolution pass.
    pub full_pass: Vec<Duration>,
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
    let (mut to_coarse, mut full_pass) = (Vec::new(), Vec::new());
    let mut refused = 0;
    let err = |e: hrender::RenderError| e.to_string();
    for m in &path.0 {
        let start = Instant::now();
        match pose.moved(*m) {
            Some(p) => pose = p,
            None => refused += 1,
        }
        scene.camera = pose.camera().ok_or("the camera left f64's range")?;
        view.restart();
        view.step(&scene).map_err(err)?;
        to_coarse.push(start.elapsed());
        let start = Instant::now();
        view.step(&scene).map_err(err)?;
        full_pass.push(start.elapsed());
    }
    if path.0.is_empty() {
        view.step(&scene).map_err(err)?;
    }
    let start = Instant::now();
    let mut last = view.step(&scene).map_err(err)?;
    while !view.is_converged() {
        last = view.step(&scene).map_err(err)?;
    }
    Ok(HeadlessReport {
        to_coarse,
        full_pass,
        converge: start.elapsed(),
        last,
        pose,
        refused,
    })
}
