//! The `Lights` section: point lights and spherical area lights.

use super::Lowerer;
use super::light_strength;
use super::names::TargetSlot;
use super::table::{self, SeenKeys, unknown_word, words};
use super::text::and_list;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::Light;
use crate::syntax::{Clause, Ident, Section, Statement, Value};

/// Largest hyperbolic radius of an area light (a sphere of radius 20 is
/// already e^20 times larger than its distance to anything inside).
const MAX_LIGHT_RADIUS: f64 = 20.0;

/// Most shadow rays per shading point for an area light.
const MAX_LIGHT_SAMPLES: u32 = 4096;

/// Largest `near` distance (as `irradiance_at`'s bound).
const MAX_LIGHT_NEAR: f64 = 30.0;

/// Shadow rays per shading point when an area light gives no `samples`.
const DEFAULT_LIGHT_SAMPLES: u32 = 16;

/// A light option.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LightKey {
    Radius,
    Samples,
    Near,
    /// Handled by `light_strength.rs`.
    IrradianceAt,
}

/// Every light option with what it means, in the order the help lists them.
const OPTIONS: &[(&str, LightKey, &str)] = &[
    (
        "radius",
        LightKey::Radius,
        "hyperbolic, 0 for a point light",
    ),
    (
        "samples",
        LightKey::Samples,
        "shadow rays per shading point",
    ),
    (
        "near",
        LightKey::Near,
        "nearer than this the fall-off stops growing",
    ),
    (
        light_strength::KEY,
        LightKey::IrradianceAt,
        "the colours are the irradiance at this distance",
    ),
];

/// The names of the light options, in the order of [`OPTIONS`].
pub(crate) const LIGHT_OPTIONS: [&str; OPTIONS.len()] = words!(OPTIONS, 0);

fn option(name: &str) -> Option<LightKey> {
    table::find(OPTIONS, name).map(|(_, k, _)| *k)
}

fn options_help() -> String {
    let described: Vec<String> = OPTIONS
        .iter()
        .map(|(name, _, meaning)| format!("`{name}` ({meaning})"))
        .collect();
    format!("the options of a light are {}", and_list(&described))
}

impl Lowerer<'_> {
    pub(super) fn lights_section(&mut self, section: &Section) {
        for st in &section.statements {
            let index = self.light_statement(st);
            if let Some(label) = &st.label {
                self.declare_target(label, TargetSlot::Light(index));
            }
        }
    }

    /// Lowers one light; returns its index, or `None` after reporting why not.
    fn light_statement(&mut self, st: &Statement) -> Option<usize> {
        const USAGE: &str = "write `%P, (diffuse r, g, b), (specular r, g, b);` (or `camera` for the point: a light at the eye), optionally followed by `radius = r, samples = n` for an area light or `near = d`";
        let mut values: Vec<&Value> = Vec::new();
        let mut options: Vec<(&Ident, &Value)> = Vec::new();
        // `camera` in place of the point: the light goes where the eye goes.
        let on_camera = matches!(
            st.clauses.first(),
            Some(Clause::Apply { target: None, name, arg: None, .. }) if name.text == "camera"
        );
        for clause in st.clauses.iter().skip(usize::from(on_camera)) {
            match clause {
                Clause::Value(v) if options.is_empty() => values.push(v),
                Clause::Assign { key, .. } if values.len() < 3 && option(&key.text).is_none() => {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            clause.span(),
                            "a light's point and colours are plain values, not `key = value`",
                        )
                        .with_help(USAGE),
                    );
                    return None;
                }
                Clause::Assign { key, value, .. } => options.push((key, value)),
                bad => {
                    let message = if matches!(bad, Clause::Value(_)) {
                        "a light's options (`radius = r`, `samples = n`) must come after its point and colours"
                    } else {
                        "a light's parts are plain values and `key = value` options, not names"
                    };
                    self.report(
                        Diagnostic::new(Code::WrongType, bad.span(), message).with_help(USAGE),
                    );
                    return None;
                }
            }
        }
        let given = values.len() + usize::from(on_camera);
        if given != 3 {
            self.wrong_arity(
                st.span,
                format!("a light takes 3 values (a point and two colours), got {given}"),
                USAGE,
            );
            return None;
        }
        // A camera light's position is the eye's, set once the camera is
        // known (`Lowerer::place_camera_lights`).
        let position = if on_camera {
            Some(hgeom::Point::ORIGIN)
        } else {
            self.point_arg(values[0], "a light")
        };
        let colours = &values[values.len() - 2..];
        let diffuse = self.rgb(colours[0]);
        let specular = self.rgb(colours[1]);
        let (options, strength) = self.take_irradiance_at(options);
        let (radius, samples, near) = self.light_options(&options)?;
        if on_camera && radius > 0.0 {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    st.span,
                    "a camera light cannot be an area light: the eye would be inside its sphere",
                )
                .with_help("remove `radius` and bound the fall-off with `near = d` instead"),
            );
            return None;
        }
        let (position, (diffuse, specular)) = (position?, strength.apply(diffuse?, specular?)?);
        if !self.light_fits(st.span) {
            return None;
        }
        self.lights.push((
            Light {
                position,
                diffuse,
                specular,
                name: st.label.as_ref().map(|l| l.text.to_string()),
                radius,
                samples,
                near,
                on_camera,
            },
            st.span,
        ));
        Some(self.lights.len() - 1)
    }

    /// The area-light options `radius = r` and `samples = n`: a point light
    /// (radius 0, one sample) when neither is given, 16 samples when only
    /// the radius is; and `near = d` (0 when absent).
    fn light_options(&mut self, options: &[(&Ident, &Value)]) -> Option<(f64, u32, f64)> {
        let mut near = 0.0;
        let mut radius: Option<(f64, Span)> = None;
        let mut samples: Option<(u32, Span)> = None;
        let mut seen = SeenKeys::default();
        let mut ok = true;
        for (key, value) in options {
            if let Some(twice) = seen.again(key) {
                self.report(twice);
            }
            match option(&key.text) {
                Some(LightKey::Radius) => match self.light_length(
                    value,
                    0.0,
                    MAX_LIGHT_RADIUS,
                    "a light's radius must be from 0 to",
                    "the radius is a hyperbolic length; 0 makes a point light",
                ) {
                    Some(r) => radius = Some((r, key.span)),
                    None => ok = false,
                },
                Some(LightKey::Samples) => {
                    match self.integer(value, 1, u64::from(MAX_LIGHT_SAMPLES), "samples") {
                        Some(n) => samples = Some((n as u32, key.span)),
                        None => ok = false,
                    }
                }
                Some(LightKey::Near) => match self.light_length(
                    value,
                    f64::MIN_POSITIVE,
                    MAX_LIGHT_NEAR,
                    "a light's `near` must be above 0 and at most",
                    "`near` is a hyperbolic distance: nearer than it the light's fall-off stops growing",
                ) {
                    Some(d) => near = d,
                    None => ok = false,
                },
                // `irradiance_at` was taken out before (`light_strength.rs`).
                Some(LightKey::IrradianceAt) | None => {
                    ok = false;
                    self.report(unknown_word(
                        Code::UnknownKey,
                        key,
                        "light option",
                        &LIGHT_OPTIONS,
                        &options_help(),
                    ));
                }
            }
        }
        if !ok {
            return None;
        }
        let r = radius.map_or(0.0, |(r, _)| r);
        match samples {
            Some((_, span)) if r == 0.0 => {
                self.report(
                    Diagnostic::new(
                        Code::IneffectiveOption,
                        span,
                        "`samples` has no effect on a point light",
                    )
                    .with_help("add `radius = 0.05` (a hyperbolic radius) to make it an area light, or remove `samples`"),
                );
                Some((0.0, 1, near))
            }
            Some((n, _)) => Some((r, n, near)),
            None if r > 0.0 => Some((r, DEFAULT_LIGHT_SAMPLES, near)),
            None => Some((0.0, 1, near)),
        }
    }

    /// A light's length option in `lo..=hi`, or `None` after reporting
    /// `message` (completed with the bound and the value) and `help`.
    fn light_length(
        &mut self,
        value: &Value,
        lo: f64,
        hi: f64,
        message: &str,
        help: &'static str,
    ) -> Option<f64> {
        let x = self.number(value)?;
        if (lo..=hi).contains(&x) {
            return Some(x);
        }
        self.report(
            Diagnostic::new(
                Code::InvalidValue,
                value.span(),
                format!("{message} {hi}, got {}", hgeom::Compact(x)),
            )
            .with_help(help),
        );
        None
    }
}
