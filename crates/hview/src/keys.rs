//! What each key does in the window (the README lists them).

use winit::keyboard::KeyCode;

use crate::pose::{Axis, Move};

/// Radians per turning key press.
pub const TURN: f64 = 0.05;

/// What a key asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Fly: a move in the camera's frame.
    Fly(Move),
    /// Back to the scene's own camera.
    Reset,
    /// Print the camera as `from`/`to`/`up` lines for the scene.
    PrintCamera,
    /// Render the current view at full quality to a file.
    Save,
    /// Pause or play an animation.
    TogglePlay,
    /// Close the window.
    Quit,
}

/// The action of a key, `step` being the distance one press flies
/// (`fast`: five times as far).
pub fn action_for_key(key: KeyCode, step: f64, fast: bool) -> Option<Action> {
    let d = if fast { 5.0 * step } else { step };
    let t = if fast { 5.0 * TURN } else { TURN };
    Some(match key {
        KeyCode::KeyW => Action::Fly(Move::Step(Axis::Forward, d)),
        KeyCode::KeyS => Action::Fly(Move::Step(Axis::Forward, -d)),
        KeyCode::KeyD => Action::Fly(Move::Step(Axis::Right, d)),
        KeyCode::KeyA => Action::Fly(Move::Step(Axis::Right, -d)),
        KeyCode::KeyR => Action::Fly(Move::Step(Axis::Up, d)),
        KeyCode::KeyF => Action::Fly(Move::Step(Axis::Up, -d)),
        // Turning left is a turn about up; looking up, about right.
        KeyCode::ArrowLeft => Action::Fly(Move::Turn(Axis::Up, -t)),
        KeyCode::ArrowRight => Action::Fly(Move::Turn(Axis::Up, t)),
        KeyCode::ArrowUp => Action::Fly(Move::Turn(Axis::Right, -t)),
        KeyCode::ArrowDown => Action::Fly(Move::Turn(Axis::Right, t)),
        KeyCode::KeyQ => Action::Fly(Move::Turn(Axis::Forward, t)),
        KeyCode::KeyE => Action::Fly(Move::Turn(Axis::Forward, -t)),
        KeyCode::Home | KeyCode::Digit0 => Action::Reset,
        KeyCode::KeyC => Action::PrintCamera,
        KeyCode::KeyP => Action::Save,
        KeyCode::Space => Action::TogglePlay,
        KeyCode::Escape => Action::Quit,
        _ => return None,
    })
}
