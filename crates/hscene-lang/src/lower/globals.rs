//! The `Globals` section: render settings, the camera's points and the
//! view keys, each `key = value`.

use super::Lowerer;
use super::camera::CameraKey;
use super::lens_globals::LensKey;
use super::space_globals::SpaceKey;
use super::table::{self, Row, SeenKeys, unknown_word, words};
use super::view_globals::ViewKey;
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::{IntegratorKind, Net, Resolution, Rgb, Settings, Sky, Window};
use crate::syntax::{Clause, Ident, Section, Value};

/// Largest accepted image side, to keep allocations sane.
const MAX_RESOLUTION: u64 = 32_768;

pub use hscene_ir::limits::{MAX_FRAMES, MAX_PIXELS, MAX_SAMPLES};

/// What a global key sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Global {
    RecursionDepth,
    Resolution,
    WindowSize,
    NetType,
    Samples,
    Frames,
    Background,
    Sky,
    Ambient,
    Integrator,
    Denoise,
    Camera(CameraKey),
    View(ViewKey),
    Lens(LensKey),
    Space(SpaceKey),
}

/// One key of `Globals`.
struct GlobalKey {
    name: &'static str,
    sets: Global,
    /// Another spelling of a key listed before it: accepted, suggested and
    /// completed, but not listed in the help.
    alias: bool,
}

impl Row for GlobalKey {
    fn word(&self) -> &'static str {
        self.name
    }
}

const fn key(name: &'static str, sets: Global) -> GlobalKey {
    GlobalKey {
        name,
        sets,
        alias: false,
    }
}

/// Every key of `Globals`, in the order the help lists them.
const KEYS: &[GlobalKey] = &[
    key("recursion_depth", Global::RecursionDepth),
    key("resolution", Global::Resolution),
    key("window_size", Global::WindowSize),
    key("fov", Global::View(ViewKey::Fov)),
    key("net_type", Global::NetType),
    key("samples", Global::Samples),
    key("frames", Global::Frames),
    key("from", Global::Camera(CameraKey::Eye)),
    GlobalKey {
        name: "eye",
        sets: Global::Camera(CameraKey::Eye),
        alias: true,
    },
    key("to", Global::Camera(CameraKey::Target)),
    key("up", Global::Camera(CameraKey::Up)),
    key("background", Global::Background),
    key("sky", Global::Sky),
    key("ambient", Global::Ambient),
    key("integrator", Global::Integrator),
    key("denoise", Global::Denoise),
    key("fog_color", Global::View(ViewKey::FogColor)),
    key("fog_distance", Global::View(ViewKey::FogDistance)),
    key("aperture", Global::Lens(LensKey::Aperture)),
    key("focus", Global::Lens(LensKey::Focus)),
    key("space", Global::Space(SpaceKey::Space)),
    key("domain", Global::Space(SpaceKey::Domain)),
    key("light_reach", Global::Space(SpaceKey::LightReach)),
];

/// Every global key, aliases included, in the order of [`KEYS`].
pub(crate) const GLOBAL_KEYS: [&str; KEYS.len()] = words!(KEYS, name);

/// Whether `name` is the key of the frame count (read before lowering).
pub(super) fn is_frames_key(name: &str) -> bool {
    KEYS.iter()
        .any(|k| k.name == name && k.sets == Global::Frames)
}

fn keys_help() -> String {
    let names: Vec<&str> = KEYS.iter().filter(|k| !k.alias).map(|k| k.name).collect();
    format!("globals are {}", names.join(", "))
}

/// The default image size.
const DEFAULT_RESOLUTION: Resolution = match Resolution::new(512, 512) {
    Some(r) => r,
    None => panic!("the default resolution is not empty"),
};

/// Default settings: the thesis's Appendix A values, at a smaller resolution.
pub(super) fn default_settings() -> Settings {
    Settings {
        recursion_depth: 1,
        resolution: DEFAULT_RESOLUTION,
        window: Window {
            width: 0.15,
            height: 0.15,
        },
        net: Net::Euclidean,
        background: Rgb::BLACK,
        ambient: Rgb::new(0.1, 0.1, 0.1),
        samples: 1,
        frames: 1,
        fov: None,
        fog: None,
        integrator: IntegratorKind::Whitted,
        sky: None,
        lens: None,
        space: None,
        denoise: false,
    }
}

impl Lowerer<'_> {
    pub(super) fn globals_section(&mut self, section: &Section) {
        let mut seen = SeenKeys::default();
        for st in &section.statements {
            let mut clauses = st.clauses.iter().peekable();
            while let Some(clause) = clauses.next() {
                // `domain = w, #M`: the material is the clause after it.
                if let Clause::Assign { key, value, span } = clause
                    && table::find(KEYS, &key.text).map(|k| k.sets)
                        == Some(Global::Space(SpaceKey::Domain))
                {
                    if let Some(twice) = seen.again(key) {
                        self.report(twice);
                    }
                    let material =
                        clauses
                            .next_if(|c| matches!(c, Clause::Value(_)))
                            .and_then(|c| match c {
                                Clause::Value(v) => Some(v),
                                _ => None,
                            });
                    self.domain_global(value, material, *span);
                    continue;
                }
                let Clause::Assign { key, value, .. } = clause else {
                    self.report(
                        Diagnostic::new(Code::WrongType, clause.span(), "expected `key = value`")
                            .with_help(keys_help()),
                    );
                    continue;
                };
                if let Some(twice) = seen.again(key) {
                    self.report(twice);
                }
                self.global(key, value);
            }
        }
    }

    fn global(&mut self, key: &Ident, value: &Value) {
        let Some(global) = table::find(KEYS, &key.text) else {
            self.report(unknown_word(
                Code::UnknownKey,
                key,
                "global",
                &GLOBAL_KEYS,
                &keys_help(),
            ));
            return;
        };
        match global.sets {
            Global::RecursionDepth => {
                if let Some(n) = self.integer(value, 0, 64, "recursion_depth") {
                    self.settings.recursion_depth = n as u32;
                }
            }
            Global::Resolution => self.resolution(value),
            Global::WindowSize => {
                self.view.window_span = Some(value.span());
                if let Some(v) = self.tuple_of_numbers(value, 2, "window_size = (width, height)") {
                    if v.iter().all(|x| *x > 0.0) {
                        self.settings.window = Window {
                            width: v[0],
                            height: v[1],
                        };
                    } else {
                        self.error(
                            Code::InvalidValue,
                            value.span(),
                            "the window size must be positive",
                        );
                    }
                }
            }
            Global::NetType => {
                if let Some(x) = self.number(value) {
                    match (x.fract() == 0.0 && x >= 0.0).then(|| Net::from_index(x as u64)).flatten() {
                        Some(net) => self.settings.net = net,
                        None => self.report(
                            Diagnostic::new(Code::UnknownNetType, value.span(), format!("unknown net type {x}"))
                                .with_help("net_type is 0 (Euclidean), 1 (hyperparallel h-lines), 2 (great disk), 3 (h-equidistants) or 4 (h-equidistants, interpolated)"),
                        ),
                    }
                }
            }
            Global::Samples => {
                if let Some(n) = self.integer(value, 1, u64::from(MAX_SAMPLES), "samples") {
                    self.settings.samples = n as u32;
                }
            }
            Global::Frames => match self.integer(value, 1, u64::from(MAX_FRAMES), "frames") {
                Some(n) => self.settings.frames = n as u32,
                None => self.frames_refused = true,
            },
            Global::Background => {
                self.settings.background = self.rgb(value).unwrap_or(self.settings.background)
            }
            Global::Sky => self.sky(value),
            Global::Ambient => {
                self.settings.ambient = self.rgb(value).unwrap_or(self.settings.ambient)
            }
            Global::Integrator => self.integrator(value),
            Global::Denoise => self.denoise(value),
            Global::View(key) => self.view_global(key, value),
            Global::Lens(key) => self.lens_global(key, value),
            Global::Space(key) => self.space_global(key, value),
            Global::Camera(key) => self.camera_global(key, value),
        }
    }

    /// `sky = ((r, g, b), (r, g, b))`: the zenith's colour, then the
    /// horizon's.
    fn sky(&mut self, value: &Value) {
        if let Value::Str { .. } = value {
            if let Some((_, image)) = self.image_file(value, "the sky") {
                self.settings.sky = Some(Sky::Image(image));
            }
            return;
        }
        let Value::Tuple { items, .. } = value else {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    value.span(),
                    format!("expected two colours, found {}", value.describe()),
                )
                .with_help("write `sky = ((0.3, 0.5, 0.9), (0.9, 0.9, 1.0));`: the zenith's colour, then the horizon's"),
            );
            return;
        };
        if items.len() != 2 {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    value.span(),
                    format!(
                        "`sky` takes two colours (zenith, horizon), found {}",
                        items.len()
                    ),
                )
                .with_help("write `sky = ((0.3, 0.5, 0.9), (0.9, 0.9, 1.0));`"),
            );
            return;
        }
        if let (Some(zenith), Some(horizon)) = (self.rgb(&items[0]), self.rgb(&items[1])) {
            self.settings.sky = Some(Sky::Gradient { zenith, horizon });
        }
    }

    /// `integrator = whitted|path`.
    fn integrator(&mut self, value: &Value) {
        let help = || format!("integrators are {}", IntegratorKind::names());
        let Value::Ident(name) = value else {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    value.span(),
                    format!("expected an integrator's name, found {}", value.describe()),
                )
                .with_help(help()),
            );
            return;
        };
        match IntegratorKind::from_name(&name.text) {
            Some(kind) => {
                self.settings.integrator = kind;
                self.integrator_span = Some(value.span());
            }
            None => self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    value.span(),
                    format!("unknown integrator `{}`", name.text),
                )
                .with_help(help()),
            ),
        }
    }

    /// `denoise = true|false`.
    fn denoise(&mut self, value: &Value) {
        let found = match value {
            Value::Ident(name) => match name.text.as_str() {
                "true" => Some(true),
                "false" => Some(false),
                _ => None,
            },
            _ => None,
        };
        match found {
            Some(on) => self.settings.denoise = on,
            None => self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    value.span(),
                    match value {
                        Value::Ident(name) => {
                            format!("`denoise` is `true` or `false`, not `{}`", name.text)
                        }
                        _ => format!("`denoise` is `true` or `false`, not {}", value.describe()),
                    },
                )
                .with_help(
                    "write `denoise = true;` to denoise the picture with Intel Open Image Denoise (path-traced pictures gain most)",
                ),
            ),
        }
    }

    /// `resolution = (width, height)`.
    fn resolution(&mut self, value: &Value) {
        let Some(v) = self.tuple_of_numbers(value, 2, "resolution = (width, height)") else {
            return;
        };
        if v.contains(&0.0) {
            self.report(
                Diagnostic::new(
                    Code::ZeroResolution,
                    value.span(),
                    "the resolution must be at least 1x1 pixel",
                )
                .with_help("for example `resolution = (800, 600);`"),
            );
        } else if let (Some(w), Some(h)) = (
            self.integer_value(v[0], 1, MAX_RESOLUTION, value.span(), "width"),
            self.integer_value(v[1], 1, MAX_RESOLUTION, value.span(), "height"),
        ) {
            if w * h > MAX_PIXELS {
                self.error(
                    Code::InvalidValue,
                    value.span(),
                    format!("{w}x{h} is more than {MAX_PIXELS} pixels"),
                );
                return;
            }
            // Both sides are from 1 to MAX_RESOLUTION, so this is `Some`.
            if let Some(resolution) = Resolution::new(w as u32, h as u32) {
                self.settings.resolution = resolution;
            }
        }
    }
}
