//! The window: winit for events, softbuffer for pixels (pure Rust on X11,
//! Wayland, macOS and Windows). Each turn of the event loop applies the
//! moves that arrived, then renders one stage (a coarse frame after a move,
//! else the next full-resolution pass) and shows it; when the view has
//! converged the loop sleeps, waking every quarter second to look for
//! changes to the scene file.

use std::num::NonZeroU32;
use std::path::PathBuf;
use std::rc::Rc;
use std::time::{Duration, Instant};

use hscene_ir::Scene;
use thiserror::Error;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{ElementState, MouseButton, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{ModifiersState, PhysicalKey};
use winit::window::{Window, WindowId};

use crate::SceneSource;
use crate::keys::{Action, action_for_key};
use crate::pose::{Axis, Move, Pose, camera_lines};
use crate::progressive::{Frame, Progressive, ViewOptions};

/// How often a still view looks for a changed scene file.
const WATCH_INTERVAL: Duration = Duration::from_millis(250);

/// Radians of turn per pixel of mouse drag.
const DRAG_TURN: f64 = 0.004;

/// Frames per second an animation plays at.
const ANIMATION_FPS: f64 = 10.0;

/// Why the window could not run.
#[derive(Debug, Error)]
pub enum ViewError {
    /// No display, or the windowing system refused.
    #[error("cannot open a window: {0} (is there a display? `--headless` needs none)")]
    Display(String),
    /// The scene could not be loaded at the start.
    #[error("{0}")]
    Scene(String),
}

impl ViewError {
    /// A windowing error in words, without the source file and line
    /// winit puts in front of an OS error's message ("os error at
    /// /root/.cargo/registry/.../winit-0.30/src/...rs:42: neither
    /// WAYLAND_DISPLAY nor ... is set"): that path says nothing to the user.
    fn display(message: &str) -> ViewError {
        let words = message
            .strip_prefix("os error at ")
            .and_then(|rest| rest.split_once(": ").map(|(_, words)| words))
            .unwrap_or(message);
        ViewError::Display(words.to_string())
    }
}

struct Live {
    window: Rc<Window>,
    surface: softbuffer::Surface<Rc<Window>, Rc<Window>>,
}

struct App<'s> {
    source: &'s mut dyn SceneSource,
    /// The scene as compiled (all frames); `scene` is the one shown.
    base: Scene,
    scene: Scene,
    pose: Pose,
    flown: bool,
    view: Progressive,
    step: f64,
    save_dir: PathBuf,
    live: Option<Live>,
    pending: Vec<Move>,
    modifiers: ModifiersState,
    dragging: Option<(f64, f64)>,
    cursor: (f64, f64),
    last_frame: Option<Frame>,
    presented: Vec<Instant>,
    last_watch: Instant,
    error: Option<String>,
    frame_index: u32,
    playing: bool,
    last_tick: Instant,
    failure: Option<ViewError>,
    /// A render failed: nothing more is tried until something changes.
    stalled: bool,
}

impl App<'_> {
    fn title(&self) -> String {
        let now = Instant::now();
        let fps = self
            .presented
            .iter()
            .filter(|t| now.duration_since(**t) < Duration::from_secs(1))
            .count();
        let mut t = format!(
            "hscene view — {} — {fps} fps — {}/{} spp",
            self.source.name(),
            self.view.samples(),
            self.view.options().samples
        );
        if self.base.settings.frames > 1 {
            t += &format!(" — frame {}", self.frame_index);
        }
        if self.error.is_some() {
            t += " — error: see the terminal";
        }
        t
    }

    fn reset(&mut self) {
        if let Some(p) = Pose::of(&self.scene.camera) {
            self.pose = p;
        }
        self.flown = false;
        self.stalled = false;
        self.view.restart();
    }

    fn apply_moves(&mut self) {
        if self.pending.is_empty() {
            return;
        }
        // In a quotient space the eye is folded back into the domain after
        // each move (`Pose::folded`), so flying never leaves f64's range.
        let space = self
            .scene
            .settings
            .space
            .as_ref()
            .and_then(|s| s.build().ok());
        for m in std::mem::take(&mut self.pending) {
            match self.pose.moved(m) {
                Some(p) => self.pose = space.as_ref().map_or(p, |q| p.folded(q)),
                None => diagln!("hscene view: that move would take the eye past what f64 holds"),
            }
        }
        self.flown = true;
        self.stalled = false;
        self.view.restart();
    }

    fn show_frame(&mut self, k: u32) {
        match self.base.frame(k) {
            Ok(s) => {
                let camera = self.scene.camera;
                self.scene = s;
                if self.flown {
                    self.scene.camera = camera;
                } else if let Some(p) = Pose::of(&self.scene.camera) {
                    self.pose = p;
                }
                self.frame_index = k;
                self.stalled = false;
                self.view.restart();
            }
            Err(e) => diagln!("hscene view: frame {k}: {e}"),
        }
    }

    fn reload(&mut self) {
        match self.source.load() {
            Ok(scene) => {
                self.error = None;
                self.base = scene;
                let k = self
                    .frame_index
                    .min(self.base.settings.frames.saturating_sub(1));
                self.show_frame(k);
                if !self.flown {
                    self.reset();
                }
                diagln!("hscene view: reloaded {}", self.source.name());
            }
            Err(message) => {
                diag!("{message}");
                self.error = Some(message);
            }
        }
        // The picture may not change (an error keeps the last good scene):
        // the title says what happened now.
        let title = self.title();
        if let Some(live) = &self.live {
            live.window.set_title(&title);
        }
    }

    fn save(&mut self) {
        let name = self.source.name();
        let stem = std::path::Path::new(&name)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "view".into());
        let path = (1..10_000)
            .map(|k| self.save_dir.join(format!("{stem}-view-{k:03}.png")))
            .find(|p| !p.exists());
        let Some(path) = path else {
            diagln!("hscene view: no free file name to save to");
            return;
        };
        let o = self.view.options();
        let options = hrender::RenderOptions {
            net: o.net,
            resolution: Some(o.resolution),
            threads: o.threads,
            samples: Some(o.samples),
            exposure: hrender::Exposure::Stops(o.exposure),
            integrator: o.integrator,
            ..hrender::RenderOptions::default()
        };
        let saved = hrender::render(&self.scene, &options, &|_| {})
            .and_then(|r| hrender::write_image(&r.image, &path, hrender::SampleDepth::Eight));
        match saved {
            Ok(()) => diagln!("hscene view: saved {}", path.display()),
            Err(e) => diagln!("hscene view: cannot save: {e}"),
        }
    }

    fn present(&mut self) {
        let (Some(live), Some(frame)) = (&mut self.live, &self.last_frame) else {
            return;
        };
        let size = live.window.inner_size();
        let (Some(w), Some(h)) = (NonZeroU32::new(size.width), NonZeroU32::new(size.height)) else {
            return;
        };
        if live.surface.resize(w, h).is_err() {
            return;
        }
        let Ok(mut buffer) = live.surface.buffer_mut() else {
            return;
        };
        let (w, h) = (w.get(), h.get());
        // The picture at the top left, 1:1; any margin black.
        for y in 0..h {
            for x in 0..w {
                buffer[(y * w + x) as usize] = if x < frame.width && y < frame.height {
                    frame.pixels[(y * frame.width + x) as usize]
                } else {
                    0
                };
            }
        }
        let _ = buffer.present();
        self.presented.push(Instant::now());
        let cutoff = Instant::now() - Duration::from_secs(2);
        self.presented.retain(|t| *t > cutoff);
        let title = self.title();
        if let Some(live) = &self.live {
            live.window.set_title(&title);
        }
    }

    fn act(&mut self, action: Action, event_loop: &ActiveEventLoop) {
        // Moves that arrived before this key are part of the view it means.
        if !matches!(action, Action::Fly(_)) {
            self.apply_moves();
        }
        match action {
            Action::Fly(m) => self.pending.push(m),
            Action::Reset => self.reset(),
            Action::PrintCamera => match self.pose.camera() {
                Some(c) => {
                    use std::io::Write as _;
                    // A closed or full stdout loses the print, not the view.
                    let _ = writeln!(std::io::stdout().lock(), "{}", camera_lines(&c));
                }
                None => diagln!("hscene view: the camera is past what f64 holds"),
            },
            Action::Save => self.save(),
            Action::TogglePlay => self.playing = !self.playing,
            Action::Quit => event_loop.exit(),
        }
    }
}

impl ApplicationHandler for App<'_> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.live.is_some() {
            return;
        }
        let o = self.view.options();
        let attributes = Window::default_attributes()
            .with_title(self.title())
            .with_inner_size(PhysicalSize::new(
                o.resolution.width(),
                o.resolution.height(),
            ))
            .with_resizable(false);
        let opened = event_loop
            .create_window(attributes)
            .map_err(|e| e.to_string())
            .and_then(|window| {
                let window = Rc::new(window);
                let context =
                    softbuffer::Context::new(window.clone()).map_err(|e| e.to_string())?;
                let surface = softbuffer::Surface::new(&context, window.clone())
                    .map_err(|e| e.to_string())?;
                Ok(Live { window, surface })
            });
        match opened {
            Ok(live) => self.live = Some(live),
            Err(e) => {
                self.failure = Some(ViewError::display(&e));
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::ModifiersChanged(m) => self.modifiers = m.state(),
            WindowEvent::KeyboardInput { event, .. } if event.state == ElementState::Pressed => {
                if let PhysicalKey::Code(code) = event.physical_key
                    && let Some(action) =
                        action_for_key(code, self.step, self.modifiers.shift_key())
                {
                    self.act(action, event_loop);
                }
            }
            WindowEvent::MouseInput {
                state,
                button: MouseButton::Left,
                ..
            } => {
                self.dragging = (state == ElementState::Pressed).then_some(self.cursor);
            }
            WindowEvent::CursorMoved { position, .. } => {
                self.cursor = (position.x, position.y);
                if let Some((x0, y0)) = self.dragging {
                    let (dx, dy) = (position.x - x0, position.y - y0);
                    if dx != 0.0 {
                        self.pending.push(Move::Turn(Axis::Up, -dx * DRAG_TURN));
                    }
                    if dy != 0.0 {
                        self.pending.push(Move::Turn(Axis::Right, -dy * DRAG_TURN));
                    }
                    self.dragging = Some(self.cursor);
                }
            }
            WindowEvent::RedrawRequested => self.present(),
            _ => {}
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        let now = Instant::now();
        if now.duration_since(self.last_watch) >= WATCH_INTERVAL {
            self.last_watch = now;
            if self.source.changed() {
                self.reload();
            }
        }
        let animated = self.base.settings.frames > 1 && self.playing;
        if animated && now.duration_since(self.last_tick).as_secs_f64() >= 1.0 / ANIMATION_FPS {
            self.last_tick = now;
            let next = (self.frame_index + 1) % self.base.settings.frames;
            self.show_frame(next);
        }
        self.apply_moves();
        if let Some(camera) = self.pose.camera() {
            self.scene.camera = camera;
        }
        // While an animation plays, one full pass a frame is enough.
        let busy =
            !(self.stalled || self.view.is_converged() || animated && self.view.samples() >= 1);
        if busy {
            match self.view.step(&self.scene) {
                Ok(frame) => {
                    self.last_frame = Some(frame);
                    self.present();
                }
                Err(e) => {
                    diagln!("hscene view: {e}");
                    self.error = Some(e.to_string());
                    self.stalled = true;
                    event_loop.set_control_flow(ControlFlow::WaitUntil(now + WATCH_INTERVAL));
                    return;
                }
            }
            event_loop.set_control_flow(ControlFlow::Poll);
        } else {
            let wake = if animated {
                Duration::from_secs_f64(1.0 / ANIMATION_FPS)
            } else {
                WATCH_INTERVAL
            };
            event_loop.set_control_flow(ControlFlow::WaitUntil(now + wake));
        }
    }
}

/// Opens the window on `source`'s scene and runs until it is closed.
/// `step` is the distance one key press flies; saved renders go to
/// `save_dir`.
pub fn run_window(
    source: &mut dyn SceneSource,
    options: ViewOptions,
    step: f64,
    save_dir: PathBuf,
) -> Result<(), ViewError> {
    let base = source.load().map_err(ViewError::Scene)?;
    let scene = base.clone();
    let pose = Pose::of(&scene.camera)
        .ok_or_else(|| ViewError::Scene("the scene's camera is degenerate".into()))?;
    let event_loop = EventLoop::new().map_err(|e| ViewError::display(&e.to_string()))?;
    let now = Instant::now();
    let mut app = App {
        source,
        base,
        scene,
        pose,
        flown: false,
        view: Progressive::new(options),
        step,
        save_dir,
        live: None,
        pending: Vec::new(),
        modifiers: ModifiersState::empty(),
        dragging: None,
        cursor: (0.0, 0.0),
        last_frame: None,
        presented: Vec::new(),
        last_watch: now,
        error: None,
        frame_index: 0,
        playing: true,
        last_tick: now,
        failure: None,
        stalled: false,
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| ViewError::display(&e.to_string()))?;
    match app.failure {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// winit's source path is dropped, the reason kept; other messages
    /// are left as they are.
    #[test]
    fn display_errors_drop_the_source_path() {
        let e = ViewError::display(
            "os error at /root/.cargo/registry/src/winit-0.30.12/src/platform_impl/linux/mod.rs:771: neither WAYLAND_DISPLAY nor WAYLAND_SOCKET nor DISPLAY is set.",
        );
        let text = e.to_string();
        assert!(!text.contains(".rs"), "{text}");
        assert!(text.contains("neither WAYLAND_DISPLAY"), "{text}");
        assert_eq!(
            ViewError::display("the display refused").to_string(),
            ViewError::Display("the display refused".into()).to_string()
        );
    }
}
