//! Semantic analysis: resolve references, validate, apply transformations,
//! and lower the syntax tree to the [`ir`](crate::ir).
//!
//! Sections are processed in dependency order whatever their order in the
//! file: `Points` and `BRDFs` first, then `Transformations` (which move
//! points, in statement order), then `Lights`, `Objects` and `Globals`, which
//! see the final positions. Every problem found is reported; lowering goes on
//! past errors so one run reports as much as it can.

mod budget;
mod figures;
mod light_strength;
mod mesh_object;
mod moves;
pub(crate) mod objects;
mod ranges;
mod seen_from;
mod suggest;
mod view_globals;
mod view_lint;

use std::collections::HashMap;
use std::path::Path;

use hgeom::glam::DVec3;
use hgeom::{HPlane, IdealPoint, Isometry, Point, Segment, Vertex};

use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{
    Camera, Light, Material, MaterialId, Net, Object, Pattern, PointPosition, PointRecord,
    Resolution, Rgb, Scene, Settings, Texture, Window,
};
use crate::syntax::{
    BrokenStatement, Clause, Ident, RefSigil, RefTarget, Reference, Section, SourceFile, Value,
};
use seen_from::SeenFrom;

/// What an `@name` transformation target names.
#[derive(Clone, Debug)]
enum TargetSlot {
    /// The IR objects one object statement produced (none if it failed).
    Objects(Vec<usize>),
    /// A light (`None` if it failed).
    Light(Option<usize>),
}

/// Section names, in processing order.
pub(crate) const SECTIONS: [&str; 6] = [
    "Points",
    "BRDFs",
    "Transformations",
    "Lights",
    "Objects",
    "Globals",
];

/// How close to the absolute a typed point may come before its decimal
/// rounding alone moves it by more than about 1e-6 in hyperbolic distance.
const NEAR_ABSOLUTE_GAP: f64 = 1e-10;

/// How far from the unit sphere a typed point may be and still count as ideal.
const IDEAL_TOLERANCE: f64 = 1e-12;

/// Largest accepted image side, to keep allocations sane.
const MAX_RESOLUTION: u64 = 32_768;

/// Most anti-aliasing samples per pixel a scene may ask for.
pub const MAX_SAMPLES: u32 = 4096;

/// Most animation frames a scene may declare.
pub const MAX_FRAMES: u32 = 100_000;

/// Largest hyperbolic radius of an area light (a sphere of radius 20 is
/// already e^20 times larger than its distance to anything inside).
const MAX_LIGHT_RADIUS: f64 = 20.0;

/// Most shadow rays per shading point for an area light.
const MAX_LIGHT_SAMPLES: u32 = 4096;

/// Shadow rays per shading point when an area light gives no `samples`.
const DEFAULT_LIGHT_SAMPLES: u32 = 16;

/// Largest accepted pixel count (about 1.6 GB of HDR samples).
pub const MAX_PIXELS: u64 = 1 << 27;

/// Default settings: the thesis's Appendix A values, at a smaller resolution.
fn default_settings() -> Settings {
    Settings {
        recursion_depth: 1,
        resolution: Resolution {
            width: 512,
            height: 512,
        },
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
    }
}

/// The default view target: the thesis's `to = (0,0,0.1)`.
const DEFAULT_TARGET: DVec3 = DVec3::new(0.0, 0.0, 0.1);

struct PointEntry {
    name: Option<String>,
    span: Span,
    position: Option<PointPosition>,
    used: bool,
}

struct MaterialEntry {
    material: Material,
    span: Span,
    used: bool,
}

struct Lowerer<'d> {
    diags: &'d mut Vec<Diagnostic>,
    points: Vec<PointEntry>,
    point_names: HashMap<String, usize>,
    materials: Vec<MaterialEntry>,
    material_names: HashMap<String, usize>,
    lines: Vec<Option<Segment>>,
    line_names: HashMap<String, usize>,
    planes: Vec<Option<HPlane>>,
    plane_names: HashMap<String, usize>,
    lights: Vec<(Light, Span)>,
    objects: Vec<(Object, Span)>,
    /// Names of objects and lights, the targets of `@name->...`, with the
    /// span of the declaring name.
    targets: HashMap<String, (TargetSlot, Span)>,
    /// Every object and light name in the file, collected before lowering,
    /// so that hints in earlier-processed sections can mention them.
    target_labels: std::collections::HashSet<String>,
    /// `@` transformations, applied once objects and lights exist.
    moves: Vec<moves::PendingMove>,
    settings: Settings,
    camera_parts: CameraParts,
    view: view_globals::ViewParts,
    /// A point reference failed (undefined, or something else where a point
    /// was needed, or text was skipped): the point meant may look unused.
    point_ref_failed: bool,
    /// The same for materials.
    material_ref_failed: bool,
    /// Where mesh file names are resolved from; `None`: the current
    /// directory.
    base_dir: Option<&'d Path>,
    /// The frame being lowered, and its time in `0..=1` (the fraction of
    /// every animated transformation applied).
    frame: u32,
    time: f64,
    /// The `animate` clauses seen.
    animations: Vec<Span>,
    /// Primitives so far, and whether the cap was reported (`budget.rs`).
    primitives: u64,
    primitive_cap_reported: bool,
    light_cap_reported: bool,
}

#[derive(Default)]
struct CameraParts {
    eye: Option<(Point, Span)>,
    target: Option<(Point, Span)>,
    up: Option<(Point, Span)>,
    /// A camera key was given but did not resolve (already reported), so
    /// camera checks would only cascade.
    failed: bool,
}

/// Lower a parsed file. Returns the scene only if no error was reported
/// (by the parser or here).
///
/// `source` is the text `file` was parsed from; it is used only to turn
/// offsets into line and column numbers in messages.
pub(crate) fn lower(
    file: &SourceFile,
    source: &str,
    options: &crate::Options,
    diags: &mut Vec<Diagnostic>,
) -> Option<Scene> {
    let frames = declared_frames(file);
    let frame = options.frame.min(frames - 1);
    let mut lw = Lowerer {
        base_dir: options.base_dir.as_deref(),
        frame,
        time: if frames > 1 {
            f64::from(frame) / f64::from(frames - 1)
        } else {
            0.0
        },
        animations: Vec::new(),
        diags,
        points: Vec::new(),
        point_names: HashMap::new(),
        materials: Vec::new(),
        material_names: HashMap::new(),
        lines: Vec::new(),
        line_names: HashMap::new(),
        planes: Vec::new(),
        plane_names: HashMap::new(),
        lights: Vec::new(),
        objects: Vec::new(),
        targets: HashMap::new(),
        target_labels: file
            .sections
            .iter()
            .filter(|s| matches!(s.name.text.as_str(), "Objects" | "Lights"))
            .flat_map(|s| &s.statements)
            .filter_map(|st| st.label.as_ref().map(|l| l.text.clone()))
            .collect(),
        moves: Vec::new(),
        settings: default_settings(),
        camera_parts: CameraParts::default(),
        view: view_globals::ViewParts::default(),
        point_ref_failed: file.incomplete,
        primitives: 0,
        primitive_cap_reported: false,
        light_cap_reported: false,
        material_ref_failed: file.incomplete,
    };
    lw.check_section_names(file, source);
    for name in SECTIONS {
        // A misspelt section is lowered as the one it was meant to be, so its
        // declarations do not go missing and cascade into undefined references.
        let meant = |s: &&Section| {
            s.name.text == name
                || (!SECTIONS.contains(&s.name.text.as_str())
                    && section_meant(&s.name.text) == Some(name))
        };
        for section in file.sections.iter().filter(meant) {
            if section.name.text != name {
                // Already an error; don't add lints about what it declares.
                lw.point_ref_failed = true;
                lw.material_ref_failed = true;
            }
            match name {
                "Points" => lw.points_section(section),
                "BRDFs" => lw.brdfs_section(section),
                "Transformations" => lw.transformations_section(section),
                "Lights" => lw.lights_section(section),
                "Objects" => lw.objects_section(section),
                _ => lw.globals_section(section),
            }
        }
    }
    let mut camera = lw.camera();
    lw.apply_moves(&mut camera);
    lw.settle_view(camera.as_ref());
    if let Some(camera) = &camera {
        lw.lint_scene(camera);
        lw.lint_outside_view(camera);
    }
    lw.mark_failed_references(file);
    lw.lint_unused();
    if lw.settings.frames == 1
        && let Some(&at) = lw.animations.first()
    {
        lw.report(
            Diagnostic::new(
                Code::StillAnimation,
                at,
                "this scene has one frame, so the animated transformations stay at their start",
            )
            .with_help("set `frames = 48;` (say) in `Globals` to render the animation, or remove `, animate` to apply the transformation in full"),
        );
    }
    if lw.diags.iter().any(Diagnostic::is_error) {
        return None;
    }
    Some(Scene {
        settings: lw.settings,
        camera: camera?,
        materials: lw.materials.into_iter().map(|m| m.material).collect(),
        lights: lw.lights.into_iter().map(|(l, _)| l).collect(),
        objects: lw.objects.into_iter().map(|(o, _)| o).collect(),
        points: lw
            .points
            .into_iter()
            .enumerate()
            .filter_map(|(i, p)| {
                Some(PointRecord {
                    number: i + 1,
                    name: p.name,
                    position: p.position?,
                })
            })
            .collect(),
        frame: lw.frame,
    })
}

/// The frame count a file declares (`frames = N` in `Globals`), read before
/// lowering because the transformations need it; 1 if absent or invalid
/// (the invalid value is reported when `Globals` is lowered).
fn declared_frames(file: &SourceFile) -> u32 {
    file.sections
        .iter()
        .filter(|s| s.name.text == "Globals")
        .flat_map(|s| &s.statements)
        .flat_map(|st| &st.clauses)
        .filter_map(|c| match c {
            Clause::Assign {
                key,
                value: Value::Number { value, .. },
                ..
            } if key.text == "frames" => Some(*value),
            _ => None,
        })
        .rfind(|x| x.fract() == 0.0 && (1.0..=f64::from(MAX_FRAMES)).contains(x))
        .map_or(1, |x| x as u32)
}

/// The checker fields of one material statement, as given.
#[derive(Default)]
struct CheckerFields {
    scale: Option<f64>,
    diffuse: Option<Rgb>,
    ambient: Option<Rgb>,
}

/// `c` with every channel multiplied by `k`.
fn scaled(c: Rgb, k: f64) -> Rgb {
    Rgb::new(c.r * k, c.g * k, c.b * k)
}

/// The translation along `line` by `fraction` of its length: the whole
/// translation (first point to second) at 1, the identity at 0.
fn partial_translation(line: &Segment, fraction: f64) -> Result<Isometry, hgeom::GeomError> {
    if fraction == 1.0 {
        return Isometry::translation(line);
    }
    if fraction == 0.0 {
        return Ok(Isometry::IDENTITY);
    }
    let (a, b) = (line.start(), line.end());
    let geodesic = hgeom::HLine::through(&Vertex::Interior(a), &Vertex::Interior(b))?;
    let from = geodesic.foot_parameter(&a);
    let to = geodesic.foot_parameter(&b);
    let end = geodesic.point_at(from + fraction * (to - from))?;
    Isometry::translation(&Segment::new(a, end)?)
}

/// A material with every field at its default.
fn default_material(name: Option<String>) -> Material {
    Material {
        name,
        ambient: Rgb::BLACK,
        diffuse: Rgb::BLACK,
        specular: Rgb::BLACK,
        reflection: 0.0,
        transmission: 0.0,
        shininess: 1.0,
        refraction: 1.0,
        texture: None,
    }
}

/// Calls `f` on every reference in `value`.
fn each_reference<'a>(value: &'a Value, f: &mut impl FnMut(&'a Reference)) {
    match value {
        Value::Reference(r) => f(r),
        Value::Tuple { items, .. } => items.iter().for_each(|v| each_reference(v, f)),
        Value::Number { .. } | Value::Ident(_) | Value::Str { .. } => {}
    }
}

/// "1 value" / "3 values".
fn count(n: usize, what: &str) -> String {
    if n == 1 {
        format!("1 {what}")
    } else {
        format!("{n} {what}s")
    }
}

impl Lowerer<'_> {
    fn report(&mut self, d: Diagnostic) {
        self.diags.push(d);
    }

    fn error(&mut self, code: Code, span: Span, message: impl Into<String>) {
        self.report(Diagnostic::new(code, span, message));
    }

    // ----- sections -------------------------------------------------------

    fn check_section_names(&mut self, file: &SourceFile, source: &str) {
        let mut seen: HashMap<&str, Span> = HashMap::new();
        let mut lines: Option<crate::diagnostic::LineIndex> = None;
        for section in &file.sections {
            let name = section.name.text.as_str();
            if !SECTIONS.contains(&name) {
                let mut d = Diagnostic::new(
                    Code::UnknownSection,
                    section.name.span,
                    format!("unknown section {}", quote(name)),
                );
                d = match section_meant(name) {
                    Some(s) if s.eq_ignore_ascii_case(name) => d.with_help(format!(
                        "section names are case-sensitive: did you mean `{s}`? (its contents are checked as `{s}`)"
                    )),
                    Some(s) => d.with_help(format!(
                        "did you mean `{s}`? (its contents are checked as `{s}`)"
                    )),
                    None => d.with_help(format!("the sections are {}", SECTIONS.join(", "))),
                };
                self.report(d);
            } else if let Some(first) = seen.get(name) {
                let (line, col) = lines
                    .get_or_insert_with(|| crate::diagnostic::LineIndex::new(source))
                    .line_col(first.start);
                self.report(
                    Diagnostic::new(
                        Code::DuplicateSection,
                        section.name.span,
                        format!("section `{name}` appears more than once; its statements are merged in order"),
                    )
                    .with_help(format!("the first `{name}` section starts at line {line}, column {col}")),
                );
            } else {
                seen.insert(name, section.name.span);
            }
        }
    }

    fn points_section(&mut self, section: &Section) {
        let mut broken = section.broken.iter().peekable();
        for st in &section.statements {
            while let Some(b) = broken.next_if(|b| b.span.start < st.span.start) {
                self.broken_point(b);
            }
            let (name, value) = match (st.label.as_ref(), st.clauses.as_slice()) {
                (label, [Clause::Value(v)]) => (label.cloned(), v),
                (None, [Clause::Assign { key, value, .. }]) => (Some(key.clone()), value),
                _ => {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            st.span,
                            "a point is written `(x, y, z);` or `name = (x, y, z);`",
                        )
                        .with_label("not a point declaration"),
                    );
                    // Keep numbering aligned with what the user counted.
                    self.points.push(PointEntry {
                        name: None,
                        span: st.span,
                        position: None,
                        used: true,
                    });
                    continue;
                }
            };
            let position = self
                .point_literal(value)
                .and_then(|(v, span)| self.classify_point(v, span));
            if let Some(name) = &name {
                self.declare_name(NameKind::Point, name);
            }
            self.points.push(PointEntry {
                name: name.map(|n| n.text),
                span: st.span,
                position,
                used: false,
            });
        }
        for b in broken {
            self.broken_point(b);
        }
    }

    /// A point statement that did not parse (already reported) still takes
    /// its number and name, so later references do not cascade into errors.
    fn broken_point(&mut self, b: &BrokenStatement) {
        let name = b.name.as_ref().map(|n| n.text.clone());
        if let Some(n) = &name {
            self.point_names
                .entry(n.clone())
                .or_insert(self.points.len());
        }
        self.points.push(PointEntry {
            name,
            span: b.span,
            position: None,
            used: true,
        });
    }

    /// A material statement that did not parse (already reported) still
    /// takes its number and name, like [`Self::broken_point`].
    fn broken_material(&mut self, b: &BrokenStatement) {
        let name = b
            .name
            .as_ref()
            .filter(|_| b.labelled)
            .map(|n| n.text.clone());
        if let Some(n) = &name {
            self.material_names
                .entry(n.clone())
                .or_insert(self.materials.len());
        }
        self.materials.push(MaterialEntry {
            material: default_material(name),
            span: b.span,
            used: true,
        });
    }

    fn brdfs_section(&mut self, section: &Section) {
        let mut broken = section.broken.iter().peekable();
        for st in &section.statements {
            while let Some(b) = broken.next_if(|b| b.span.start < st.span.start) {
                self.broken_material(b);
            }
            let mut m = default_material(st.label.as_ref().map(|l| l.text.clone()));
            let mut seen: HashMap<String, Span> = HashMap::new();
            let mut checker = CheckerFields::default();
            for clause in &st.clauses {
                let Clause::Assign { key, value, .. } = clause else {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            clause.span(),
                            "expected a `field = value` pair",
                        )
                        .with_help(MATERIAL_FIELDS_HELP),
                    );
                    continue;
                };
                if let Some(prev) = seen.insert(key.text.clone(), key.span) {
                    let _ = prev;
                    self.report(Diagnostic::new(
                        Code::DuplicateKey,
                        key.span,
                        format!("{} is set twice; the last value wins", quote(&key.text)),
                    ));
                }
                match key.text.as_str() {
                    "ambient" => m.ambient = self.rgb(value).unwrap_or(m.ambient),
                    "diffuse" => m.diffuse = self.rgb(value).unwrap_or(m.diffuse),
                    "specular" => m.specular = self.rgb(value).unwrap_or(m.specular),
                    "alpha" => m.reflection = self.unit_interval(value, "alpha").unwrap_or(0.0),
                    "trans" => m.transmission = self.unit_interval(value, "trans").unwrap_or(0.0),
                    "shininess" => {
                        if let Some(x) = self.number(value) {
                            if x >= 0.0 {
                                m.shininess = x;
                            } else {
                                self.error(
                                    Code::InvalidValue,
                                    value.span(),
                                    format!(
                                        "shininess must be non-negative, got {}",
                                        hgeom::Compact(x)
                                    ),
                                );
                            }
                        }
                    }
                    "refraction" => {
                        if let Some(x) = self.number(value) {
                            if x > 0.0 {
                                m.refraction = x;
                            } else {
                                self.error(
                                    Code::InvalidValue,
                                    value.span(),
                                    format!(
                                        "the index of refraction must be positive, got {}",
                                        hgeom::Compact(x)
                                    ),
                                );
                            }
                        }
                    }
                    "checker" => {
                        if let Some(x) = self.positive(value, "the checker cell size") {
                            checker.scale = Some(x);
                        }
                    }
                    "checker_diffuse" => checker.diffuse = self.rgb(value),
                    "checker_ambient" => checker.ambient = self.rgb(value),
                    other => self.report(
                        Diagnostic::new(
                            Code::UnknownKey,
                            key.span,
                            format!("unknown material field {}", quote(other)),
                        )
                        .with_help(did_you_mean(
                            other,
                            MATERIAL_FIELDS,
                            MATERIAL_FIELDS_HELP,
                        )),
                    ),
                }
            }
            m.texture = checker.scale.map(|scale| Texture {
                pattern: Pattern::Checker,
                scale,
                diffuse: checker.diffuse.unwrap_or(scaled(m.diffuse, 0.25)),
                ambient: checker.ambient.unwrap_or(scaled(m.ambient, 0.25)),
            });
            if m.texture.is_none()
                && let Some(key) = ["checker_diffuse", "checker_ambient"]
                    .iter()
                    .find_map(|k| seen.get(*k))
            {
                self.report(
                    Diagnostic::new(
                        Code::IneffectiveOption,
                        *key,
                        "the checker colours have no effect without `checker = size`",
                    )
                    .with_help("add `checker = 0.25` (the cell size, a hyperbolic length) or remove the checker colours"),
                );
            }
            if let Some(label) = &st.label {
                self.declare_name(NameKind::Material, label);
            }
            self.materials.push(MaterialEntry {
                material: m,
                span: st.span,
                used: false,
            });
        }
        for b in broken {
            self.broken_material(b);
        }
    }

    fn transformations_section(&mut self, section: &Section) {
        for st in &section.statements {
            let (first, animate) = match st.clauses.as_slice() {
                [first] => (Some(first), None),
                [
                    first,
                    Clause::Apply {
                        target: None,
                        name,
                        arg: None,
                        ..
                    },
                ] if name.text == "animate" => (Some(first), Some(name.span)),
                _ => (None, None),
            };
            let Some(Clause::Apply {
                target,
                name,
                arg,
                span,
            }) = first
            else {
                self.report(
                    Diagnostic::new(Code::WrongType, st.span, "expected a transformation statement")
                        .with_help("write `hline (%A, %B);`, `hplane (%A, %B, %C);`, `%P->Rotate(L, angle);`, `%P->Translate(L);` or `%P->Reflect(S);`; a rotation or translation may end in `, animate`"),
                );
                continue;
            };
            if let Some(at) = animate
                && !matches!(name.text.as_str(), "Rotate" | "Translate" | "Reflect")
            {
                self.report(
                    Diagnostic::new(
                        Code::NotAnimatable,
                        at,
                        format!("`{}` cannot be animated", name.text),
                    )
                    .with_help(
                        "only the transformations `Rotate` and `Translate` can end in `, animate`",
                    ),
                );
            }
            match (target, name.text.as_str()) {
                (None, "hline") => self.declare_line(st.label.as_ref(), name, arg.as_ref(), *span),
                (None, "hplane") => {
                    self.declare_plane(st.label.as_ref(), name, arg.as_ref(), *span)
                }
                (Some(target), "Rotate" | "Translate" | "Reflect") => match target.sigil {
                    RefSigil::At => {
                        let iso = self.transformation(name, arg.as_ref(), *span, animate);
                        self.moves.push(moves::PendingMove {
                            target: target.clone(),
                            iso,
                        });
                    }
                    RefSigil::Hash => {
                        self.report(
                            Diagnostic::new(
                                Code::WrongType,
                                target.span,
                                format!("a material (`{}`) cannot be transformed", reference_text(target)),
                            )
                            .with_help("transformations act on points (`%P`), named objects and lights (`@name`) and the camera (`@camera`)"),
                        );
                        let _ = self.transformation(name, arg.as_ref(), *span, animate);
                    }
                    RefSigil::Percent => {
                        if let Some(iso) = self.transformation(name, arg.as_ref(), *span, animate) {
                            self.move_point(target, &iso);
                        } else {
                            // Still mark the target as used so errors don't cascade into lints.
                            let _ = self.resolve_point(target);
                        }
                    }
                },
                (None, "Rotate" | "Translate" | "Reflect") => self.report(
                    Diagnostic::new(
                        Code::WrongType,
                        name.span,
                        format!("`{}` needs a point to act on", name.text),
                    )
                    .with_help(format!("write `%P->{}(...)`", name.text)),
                ),
                (_, other) => self.report(
                    Diagnostic::new(
                        Code::UnknownTransformation,
                        name.span,
                        format!("unknown transformation {}", quote(other)),
                    )
                    .with_help(did_you_mean(
                        other,
                        TRANSFORMATIONS,
                        "transformations are hline, hplane, Rotate, Translate and Reflect",
                    )),
                ),
            }
        }
    }

    fn lights_section(&mut self, section: &Section) {
        for st in &section.statements {
            let index = self.light_statement(st);
            if let Some(label) = &st.label {
                self.declare_target(label, TargetSlot::Light(index));
            }
        }
    }

    /// Lowers one light; returns its index, or `None` after reporting why not.
    fn light_statement(&mut self, st: &crate::syntax::Statement) -> Option<usize> {
        const USAGE: &str = "write `%P, (diffuse r, g, b), (specular r, g, b);`, optionally followed by `radius = r, samples = n` for an area light";
        let mut values: Vec<&Value> = Vec::new();
        let mut options: Vec<(&Ident, &Value)> = Vec::new();
        for clause in &st.clauses {
            match clause {
                Clause::Value(v) if options.is_empty() => values.push(v),
                Clause::Assign { key, .. }
                    if values.len() < 3
                        && !matches!(
                            key.text.as_str(),
                            "radius" | "samples" | light_strength::KEY
                        ) =>
                {
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
        if values.len() != 3 {
            self.wrong_arity(
                st.span,
                format!(
                    "a light takes 3 values (a point and two colours), got {}",
                    values.len()
                ),
                USAGE,
            );
            return None;
        }
        let position = self.point_arg(values[0], "a light");
        let diffuse = self.rgb(values[1]);
        let specular = self.rgb(values[2]);
        let (options, strength) = self.take_irradiance_at(options);
        let (radius, samples) = self.light_options(&options)?;
        let (position, (diffuse, specular)) = (position?, strength.apply(diffuse?, specular?)?);
        if !self.light_fits(st.span) {
            return None;
        }
        self.lights.push((
            Light {
                position,
                diffuse,
                specular,
                name: st.label.as_ref().map(|l| l.text.clone()),
                radius,
                samples,
            },
            st.span,
        ));
        Some(self.lights.len() - 1)
    }

    /// The area-light options `radius = r` and `samples = n`: a point light
    /// (radius 0, one sample) when neither is given, 16 samples when only
    /// the radius is.
    fn light_options(&mut self, options: &[(&Ident, &Value)]) -> Option<(f64, u32)> {
        let mut radius: Option<(f64, Span)> = None;
        let mut samples: Option<(u32, Span)> = None;
        let mut seen: HashMap<&str, Span> = HashMap::new();
        let mut ok = true;
        for (key, value) in options {
            if seen.insert(key.text.as_str(), key.span).is_some() {
                self.report(Diagnostic::new(
                    Code::DuplicateKey,
                    key.span,
                    format!("{} is set twice; the last value wins", quote(&key.text)),
                ));
            }
            match key.text.as_str() {
                "radius" => match self.number(value) {
                    Some(r) if (0.0..=MAX_LIGHT_RADIUS).contains(&r) => {
                        radius = Some((r, key.span))
                    }
                    Some(r) => {
                        ok = false;
                        self.report(
                            Diagnostic::new(
                                Code::InvalidValue,
                                value.span(),
                                format!(
                                    "a light's radius must be from 0 to {MAX_LIGHT_RADIUS}, got {}",
                                    hgeom::Compact(r)
                                ),
                            )
                            .with_help("the radius is a hyperbolic length; 0 makes a point light"),
                        );
                    }
                    None => ok = false,
                },
                "samples" => {
                    match self.integer(value, 1, u64::from(MAX_LIGHT_SAMPLES), "samples") {
                        Some(n) => samples = Some((n as u32, key.span)),
                        None => ok = false,
                    }
                }
                other => {
                    ok = false;
                    self.report(
                        Diagnostic::new(
                            Code::UnknownKey,
                            key.span,
                            format!("unknown light option {}", quote(other)),
                        )
                        .with_help(did_you_mean(
                            other,
                            &["radius", "samples", light_strength::KEY],
                            "the options of a light are `radius` (hyperbolic, 0 for a point light), `samples` (shadow rays per shading point) and `irradiance_at` (the colours are the irradiance at this distance)",
                        )),
                    );
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
                Some((0.0, 1))
            }
            Some((n, _)) => Some((r, n)),
            None if r > 0.0 => Some((r, DEFAULT_LIGHT_SAMPLES)),
            None => Some((0.0, 1)),
        }
    }

    fn globals_section(&mut self, section: &Section) {
        let mut seen: HashMap<String, Span> = HashMap::new();
        for st in &section.statements {
            for clause in &st.clauses {
                let Clause::Assign { key, value, .. } = clause else {
                    self.report(
                        Diagnostic::new(Code::WrongType, clause.span(), "expected `key = value`")
                            .with_help(GLOBAL_KEYS_HELP),
                    );
                    continue;
                };
                if seen.insert(key.text.clone(), key.span).is_some() {
                    self.report(Diagnostic::new(
                        Code::DuplicateKey,
                        key.span,
                        format!("{} is set twice; the last value wins", quote(&key.text)),
                    ));
                }
                self.global(key, value);
            }
        }
    }

    fn global(&mut self, key: &Ident, value: &Value) {
        match key.text.as_str() {
            "recursion_depth" => {
                if let Some(n) = self.integer(value, 0, 64, "recursion_depth") {
                    self.settings.recursion_depth = n as u32;
                }
            }
            "resolution" => {
                if let Some(v) = self.tuple_of_numbers(value, 2, "resolution = (width, height)") {
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
                        self.settings.resolution = Resolution {
                            width: w as u32,
                            height: h as u32,
                        };
                    }
                }
            }
            "window_size" => {
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
            "net_type" => {
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
            "samples" => {
                if let Some(n) = self.integer(value, 1, u64::from(MAX_SAMPLES), "samples") {
                    self.settings.samples = n as u32;
                }
            }
            "frames" => {
                if let Some(n) = self.integer(value, 1, u64::from(MAX_FRAMES), "frames") {
                    self.settings.frames = n as u32;
                }
            }
            "background" => {
                self.settings.background = self.rgb(value).unwrap_or(self.settings.background)
            }
            "ambient" => self.settings.ambient = self.rgb(value).unwrap_or(self.settings.ambient),
            k if view_globals::VIEW_KEYS.contains(&k) => self.view_global(key, value),
            "from" | "eye" | "to" | "up" => {
                let role = match key.text.as_str() {
                    "to" => "the view target",
                    "up" => "the up point",
                    _ => "the eye",
                };
                let point = self.point_arg(value, role).map(|p| (p, value.span()));
                self.camera_parts.failed |= point.is_none();
                match key.text.as_str() {
                    "to" => self.camera_parts.target = point,
                    "up" => self.camera_parts.up = point,
                    _ => self.camera_parts.eye = point,
                }
            }
            other => self.report(
                Diagnostic::new(
                    Code::UnknownKey,
                    key.span,
                    format!("unknown global {}", quote(other)),
                )
                .with_help(did_you_mean(other, GLOBAL_KEYS, GLOBAL_KEYS_HELP)),
            ),
        }
    }

    // ----- objects ----------------------------------------------------------

    fn material_arg(&mut self, value: &Value) -> Option<MaterialId> {
        match value {
            Value::Reference(r) if r.sigil == RefSigil::Hash => self.resolve_material(r),
            other => {
                self.material_ref_failed = true;
                self.report(
                    Diagnostic::new(
                        Code::WrongType,
                        other.span(),
                        format!(
                            "expected a material reference like `#1`, found {}",
                            other.describe()
                        ),
                    )
                    .with_label("expected `#N` or `#name`"),
                );
                None
            }
        }
    }

    // ----- transformations --------------------------------------------------

    fn declare_line(
        &mut self,
        label: Option<&Ident>,
        name: &Ident,
        arg: Option<&Value>,
        span: Span,
    ) {
        let segment = match arg {
            Some(Value::Tuple { items, .. }) if items.len() == 2 => {
                let a = self.point_arg(&items[0], "an h-line end");
                let b = self.point_arg(&items[1], "an h-line end");
                match (a, b) {
                    (Some(a), Some(b)) => match Segment::new(a, b) {
                        Ok(s) => Some(s),
                        Err(_) => {
                            self.report(
                                Diagnostic::new(
                                    Code::DegenerateLine,
                                    span,
                                    "the two points of this h-line coincide",
                                )
                                .with_help("an h-line needs two distinct points"),
                            );
                            None
                        }
                    },
                    _ => None,
                }
            }
            _ => {
                self.wrong_arity(
                    span,
                    format!("`{}` takes two points", name.text),
                    "write `hline (%A, %B);`",
                );
                None
            }
        };
        self.declare_label(NameKind::Line, label);
        self.lines.push(segment);
    }

    fn wrong_arity(&mut self, span: Span, message: impl Into<String>, usage: impl Into<String>) {
        self.report(Diagnostic::new(Code::WrongArity, span, message).with_help(usage));
    }

    fn declare_label(&mut self, kind: NameKind, label: Option<&Ident>) {
        if let Some(label) = label {
            self.declare_name(kind, label);
        }
    }

    fn declare_plane(
        &mut self,
        label: Option<&Ident>,
        name: &Ident,
        arg: Option<&Value>,
        span: Span,
    ) {
        let plane = match arg {
            Some(Value::Tuple { items, .. }) if items.len() == 3 => {
                let vs: Vec<Option<Vertex>> = items.iter().map(|v| self.vertex_arg(v)).collect();
                match (vs[0], vs[1], vs[2]) {
                    (Some(a), Some(b), Some(c)) => match HPlane::through(&a, &b, &c) {
                        Ok(p) => Some(p),
                        Err(_) => {
                            self.report(
                                Diagnostic::new(
                                    Code::DegeneratePlane,
                                    items[0].span().to(items[2].span()),
                                    "these three points lie on one h-line, so they do not fix an h-plane",
                                )
                                .with_help("choose three points that are not on one h-line (and all distinct)"),
                            );
                            None
                        }
                    },
                    _ => None,
                }
            }
            _ => {
                self.wrong_arity(
                    span,
                    format!("`{}` takes three points", name.text),
                    "write `hplane (%A, %B, %C);`",
                );
                None
            }
        };
        self.declare_label(NameKind::Plane, label);
        self.planes.push(plane);
    }

    /// The isometry of a `Rotate`, `Translate` or `Reflect` statement. With
    /// `animate` (the span of the `animate` clause), only the fraction of it
    /// that belongs to this frame: the angle, or the distance along the
    /// line, times the frame's time in `0..=1`.
    fn transformation(
        &mut self,
        name: &Ident,
        arg: Option<&Value>,
        span: Span,
        animate: Option<Span>,
    ) -> Option<Isometry> {
        let items: Vec<&Value> = match arg {
            Some(Value::Tuple { items, .. }) => items.iter().collect(),
            Some(v) => vec![v],
            None => Vec::new(),
        };
        let fraction = match animate {
            Some(at) => {
                self.animations.push(at);
                self.time
            }
            None => 1.0,
        };
        match (name.text.as_str(), items.as_slice()) {
            ("Rotate", [line, angle]) => {
                let line = self.resolve_line(line);
                let angle = self.number(angle);
                Some(Isometry::rotation_about_segment_unchecked(
                    &line?,
                    fraction * angle?,
                ))
            }
            ("Translate", [line]) => {
                let line = self.resolve_line(line)?;
                match partial_translation(&line, fraction) {
                    Ok(t) => Some(t),
                    Err(e) => {
                        self.error(
                            Code::NumericFailure,
                            span,
                            format!("cannot build this translation: {e}"),
                        );
                        None
                    }
                }
            }
            ("Reflect", [plane]) => {
                if let Some(at) = animate {
                    self.report(
                        Diagnostic::new(Code::NotAnimatable, at, "a reflection cannot be animated")
                            .with_help("a reflection has no halfway state; animate a rotation or translation instead, or remove `, animate`"),
                    );
                }
                Some(Isometry::reflection(&self.resolve_plane(plane)?))
            }
            (n, _) => {
                let usage = match n {
                    "Rotate" => "`%P->Rotate(L, angle);` (L: an h-line number, angle in radians)",
                    "Translate" => {
                        "`%P->Translate(L);` (along h-line L, from its first point to its second)"
                    }
                    _ => "`%P->Reflect(S);` (S: an h-plane number)",
                };
                self.wrong_arity(
                    span,
                    format!("wrong number of arguments to `{n}`"),
                    format!("write {usage}"),
                );
                None
            }
        }
    }

    fn move_point(&mut self, target: &Reference, iso: &Isometry) {
        let Some(i) = self.resolve_point(target) else {
            return;
        };
        let moved = match self.points[i].position {
            Some(PointPosition::Interior(q)) => match iso.checked_apply(&q) {
                Ok(p) => Some(PointPosition::Interior(p)),
                Err(_) => {
                    self.report(
                        Diagnostic::new(
                            Code::NumericFailure,
                            target.span,
                            format!(
                                "this moves `{}` so close to the absolute that f64 cannot represent it",
                                reference_text(target)
                            ),
                        )
                        .with_help("f64 holds ball points out to about distance 37 from the origin; move it less far"),
                    );
                    None
                }
            },
            Some(PointPosition::Ideal(q)) => Some(PointPosition::Ideal(iso.apply_ideal(&q))),
            None => None,
        };
        self.points[i].position = moved;
    }

    fn resolve_line(&mut self, value: &Value) -> Option<Segment> {
        let index = self.resolve_indexed(value, NameKind::Line)?;
        self.lines[index]
    }

    fn resolve_plane(&mut self, value: &Value) -> Option<HPlane> {
        let index = self.resolve_indexed(value, NameKind::Plane)?;
        self.planes[index]
    }

    /// Resolve `%N` / `%name` against the line or plane tables.
    fn resolve_indexed(&mut self, value: &Value, kind: NameKind) -> Option<usize> {
        let (len, what, code) = match kind {
            NameKind::Line => (self.lines.len(), "h-line", Code::UndefinedLine),
            _ => (self.planes.len(), "h-plane", Code::UndefinedLine),
        };
        let Value::Reference(
            r @ Reference {
                sigil: RefSigil::Percent,
                ..
            },
        ) = value
        else {
            self.report(Diagnostic::new(
                Code::WrongType,
                value.span(),
                format!(
                    "expected an {what} reference like `%1`, found {}",
                    value.describe()
                ),
            ));
            return None;
        };
        let names = if kind == NameKind::Line {
            &self.line_names
        } else {
            &self.plane_names
        };
        let found = match &r.target {
            RefTarget::Index(n) => (*n >= 1 && (*n as usize) <= len).then(|| *n as usize - 1),
            RefTarget::Name(name) => names.get(name).copied(),
        };
        if found.is_none() && !self.index_overflowed(r) {
            let declared = if len == 0 {
                format!("no {what}s are declared yet")
            } else {
                format!("{} declared so far", count(len, what))
            };
            self.report(
                Diagnostic::new(
                    code,
                    r.span,
                    format!("undefined {what} `{}`", reference_text(r)),
                )
                .with_help(format!(
                    "{declared}; declare one with `{}` before using it",
                    if kind == NameKind::Line {
                        "hline (%A, %B);"
                    } else {
                        "hplane (%A, %B, %C);"
                    }
                )),
            );
        }
        found
    }

    // ----- points -----------------------------------------------------------

    fn point_literal(&mut self, value: &Value) -> Option<(DVec3, Span)> {
        let v = self.tuple_of_numbers(value, 3, "a point `(x, y, z)`")?;
        Some((DVec3::new(v[0], v[1], v[2]), value.span()))
    }

    fn classify_point(&mut self, v: DVec3, span: Span) -> Option<PointPosition> {
        let norm = v.length();
        // Ideal first: a point typed on the unit sphere whose f64 norm happens
        // to round just below 1 must not become a far interior point.
        if let Ok(ideal) = IdealPoint::new(v, IDEAL_TOLERANCE) {
            return Some(PointPosition::Ideal(ideal));
        }
        if let Ok(p) = Point::from_coords(v) {
            if p.gap() < NEAR_ABSOLUTE_GAP {
                // gap = 1 - |x|^2 = (1 - |x|)(1 + |x|), about twice 1 - |x| here.
                self.report(
                    Diagnostic::new(Code::PointNearAbsolute, span, format!("this point is within {:.1e} of the absolute; decimal rounding alone moves it noticeably", 0.5 * p.gap()))
                        .with_help("positions this close to the absolute are not reproducible in f64; move it inward or place it with transformations"),
                );
            }
            return Some(PointPosition::Interior(p));
        }
        self.report(
            Diagnostic::new(Code::PointOutsideAbsolute, span, format!("point lies outside the absolute: |x| = {norm}"))
                .with_label("outside the unit ball")
                .with_help("h-points need |x| < 1 (ideal points |x| = 1); scale the coordinates into the unit ball"),
        );
        None
    }

    fn resolve_point(&mut self, r: &Reference) -> Option<usize> {
        if r.sigil != RefSigil::Percent {
            let what = match r.sigil {
                RefSigil::At => "the object reference",
                _ => "the material reference",
            };
            self.report(Diagnostic::new(
                Code::WrongType,
                r.span,
                format!(
                    "expected a point reference like `%1`, found {what} `{}`",
                    reference_text(r)
                ),
            ));
            self.point_ref_failed = true;
            return None;
        }
        let found = self.lookup_point(r);
        match found {
            Some(i) => {
                self.points[i].used = true;
                Some(i)
            }
            None if self.index_overflowed(r) => {
                self.point_ref_failed = true;
                None
            }
            None => {
                self.point_ref_failed = true;
                let help = match (&r.target, self.points.len()) {
                    (RefTarget::Index(0), _) => "points are numbered from %1".to_string(),
                    (_, 0) => {
                        "no points are declared: add them to the `Points` section".to_string()
                    }
                    (RefTarget::Index(_), n) => {
                        format!("{} declared (%1 to %{n})", count(n, "point"))
                    }
                    (RefTarget::Name(n), _) if self.target_labels.contains(n) => {
                        let n = shorten(n);
                        format!(
                            "`{n}` is an object or light, not a point: write `@{n}` to transform it"
                        )
                    }
                    (RefTarget::Name(n), _) => {
                        let names = self.point_names.keys().map(String::as_str);
                        match suggest::closest_declared(n, names) {
                            Some(s) => format!("did you mean `%{s}`?"),
                            None => "declare it in `Points` as `name = (x, y, z);`".to_string(),
                        }
                    }
                };
                self.report(
                    Diagnostic::new(
                        Code::UndefinedPoint,
                        r.span,
                        format!("undefined point `{}`", reference_text(r)),
                    )
                    .with_help(help),
                );
                None
            }
        }
    }

    /// An interior point given as a reference or a literal.
    fn point_arg(&mut self, value: &Value, role: &str) -> Option<Point> {
        let (pos, span) = match value {
            Value::Reference(r) => {
                let i = self.resolve_point(r)?;
                (self.points[i].position?, r.span)
            }
            Value::Tuple { .. } => {
                let (v, span) = self.point_literal(value)?;
                (self.classify_point(v, span)?, span)
            }
            other => {
                self.report(Diagnostic::new(
                    Code::WrongType,
                    other.span(),
                    format!("expected a point for {role}, found {}", other.describe()),
                ));
                self.point_ref_failed = true;
                return None;
            }
        };
        match pos {
            PointPosition::Interior(p) => Some(p),
            PointPosition::Ideal(_) => {
                self.report(
                    Diagnostic::new(
                        Code::IdealPointNotAllowed,
                        span,
                        format!(
                            "{role} must be inside the ball, but this point is on the absolute"
                        ),
                    )
                    .with_help(IDEAL_ALLOWED_HELP),
                );
                None
            }
        }
    }

    /// A point that may be ideal.
    fn vertex_arg(&mut self, value: &Value) -> Option<Vertex> {
        let pos = match value {
            Value::Reference(r) => {
                let i = self.resolve_point(r)?;
                self.points[i].position?
            }
            Value::Tuple { .. } => {
                let (v, span) = self.point_literal(value)?;
                self.classify_point(v, span)?
            }
            other => {
                self.report(Diagnostic::new(
                    Code::WrongType,
                    other.span(),
                    format!("expected a point, found {}", other.describe()),
                ));
                self.point_ref_failed = true;
                return None;
            }
        };
        Some(match pos {
            PointPosition::Interior(p) => Vertex::Interior(p),
            PointPosition::Ideal(p) => Vertex::Ideal(p),
        })
    }

    fn resolve_material(&mut self, r: &Reference) -> Option<MaterialId> {
        let found = self.lookup_material(r);
        match found {
            Some(i) => {
                self.materials[i].used = true;
                Some(MaterialId(i))
            }
            None if self.index_overflowed(r) => {
                self.material_ref_failed = true;
                None
            }
            None => {
                self.material_ref_failed = true;
                let names = self.material_names.keys().map(String::as_str);
                let suggestion = match &r.target {
                    RefTarget::Name(n) => suggest::closest_declared(n, names),
                    RefTarget::Index(_) => None,
                };
                let help = match (suggestion, self.materials.len()) {
                    (Some(s), _) => format!("did you mean `#{s}`?"),
                    (None, 0) => {
                        "no materials are declared: add one to the `BRDFs` section".to_string()
                    }
                    (None, n) => format!("{} declared (#1 to #{n})", count(n, "material")),
                };
                self.report(
                    Diagnostic::new(
                        Code::UndefinedMaterial,
                        r.span,
                        format!("undefined material `{}`", reference_text(r)),
                    )
                    .with_help(help),
                );
                None
            }
        }
    }

    fn declare_name(&mut self, kind: NameKind, name: &Ident) {
        let (table, index) = match kind {
            NameKind::Point => (&mut self.point_names, self.points.len()),
            NameKind::Material => (&mut self.material_names, self.materials.len()),
            NameKind::Line => (&mut self.line_names, self.lines.len()),
            NameKind::Plane => (&mut self.plane_names, self.planes.len()),
        };
        if table.contains_key(&name.text) {
            self.diags.push(
                Diagnostic::new(
                    Code::DuplicateName,
                    name.span,
                    format!("{} is already declared", quote(&name.text)),
                )
                .with_help("give each point, material, line and plane a distinct name"),
            );
        } else {
            table.insert(name.text.clone(), index);
        }
    }

    /// Declares the name of an object or light (the `@name` namespace).
    fn declare_target(&mut self, name: &Ident, slot: TargetSlot) {
        if name.text == moves::CAMERA {
            self.report(
                Diagnostic::new(
                    Code::ReservedName,
                    name.span,
                    "`camera` is reserved: `@camera` is the camera",
                )
                .with_help("give this object or light another name"),
            );
        } else if let Some((_, first)) = self.targets.get(&name.text) {
            // Lights are lowered before objects: blame whichever declaration
            // comes later in the file.
            let later = if first.start > name.span.start {
                *first
            } else {
                name.span
            };
            self.report(
                Diagnostic::new(
                    Code::DuplicateName,
                    later,
                    format!("{} is already declared", quote(&name.text)),
                )
                .with_help("objects and lights share one set of names (`@name`); give each a distinct name"),
            );
        } else {
            self.targets.insert(name.text.clone(), (slot, name.span));
        }
    }

    // ----- values -----------------------------------------------------------

    fn number(&mut self, value: &Value) -> Option<f64> {
        match value {
            // An overflowing literal was already reported by the parser.
            Value::Number { value, .. } if !value.is_finite() => None,
            Value::Number { value, .. } => Some(*value),
            Value::Ident(name) if crate::numbers::is_non_finite_word(&name.text) => {
                self.report(crate::numbers::non_finite(name.span, &name.text));
                None
            }
            other => {
                self.report(Diagnostic::new(
                    Code::WrongType,
                    other.span(),
                    format!("expected a number, found {}", other.describe()),
                ));
                None
            }
        }
    }

    fn positive(&mut self, value: &Value, what: &str) -> Option<f64> {
        let x = self.number(value)?;
        if x > 0.0 {
            Some(x)
        } else {
            self.report(
                Diagnostic::new(
                    Code::NonPositiveRadius,
                    value.span(),
                    format!("{what} must be positive, got {}", hgeom::Compact(x)),
                )
                .with_help("lengths are hyperbolic and must be greater than 0"),
            );
            None
        }
    }

    fn unit_interval(&mut self, value: &Value, what: &str) -> Option<f64> {
        let x = self.number(value)?;
        if (0.0..=1.0).contains(&x) {
            Some(x)
        } else {
            self.report(Diagnostic::new(
                Code::InvalidValue,
                value.span(),
                format!(
                    "`{what}` must be between 0 and 1, got {}",
                    hgeom::Compact(x)
                ),
            ));
            None
        }
    }

    fn integer(&mut self, value: &Value, min: u64, max: u64, what: &str) -> Option<u64> {
        let x = self.number(value)?;
        self.integer_value(x, min, max, value.span(), what)
    }

    fn integer_value(&mut self, x: f64, min: u64, max: u64, span: Span, what: &str) -> Option<u64> {
        if x.fract() == 0.0 && x >= min as f64 && x <= max as f64 {
            Some(x as u64)
        } else {
            self.report(Diagnostic::new(
                Code::InvalidValue,
                span,
                format!(
                    "{what} must be a whole number from {min} to {max}, got {}",
                    hgeom::Compact(x)
                ),
            ));
            None
        }
    }

    fn tuple_of_numbers(&mut self, value: &Value, n: usize, what: &str) -> Option<Vec<f64>> {
        let Value::Tuple { items, span } = value else {
            self.report(Diagnostic::new(
                Code::WrongType,
                value.span(),
                format!("expected {what}, found {}", value.describe()),
            ));
            return None;
        };
        if items.len() != n {
            self.report(Diagnostic::new(
                Code::WrongArity,
                *span,
                format!(
                    "expected {what} with {}, found {}",
                    count(n, "value"),
                    items.len()
                ),
            ));
            return None;
        }
        let mut out = Vec::with_capacity(n);
        for item in items {
            out.push(self.number(item)?);
        }
        Some(out)
    }

    fn rgb(&mut self, value: &Value) -> Option<Rgb> {
        let v = self.tuple_of_numbers(value, 3, "a colour `(r, g, b)`")?;
        self.colour_in_range(value, [v[0], v[1], v[2]])
    }

    // ----- camera and lints -----------------------------------------------------

    fn camera(&mut self) -> Option<Camera> {
        if self.camera_parts.failed {
            return None;
        }
        let (eye, eye_span) = self
            .camera_parts
            .eye
            .unwrap_or((Point::ORIGIN, Span::default()));
        let (target, target_span) = match self.camera_parts.target {
            Some(t) => t,
            // The default target can only meet an explicit eye.
            None => (Point::from_coords(DEFAULT_TARGET).ok()?, eye_span),
        };
        if Segment::new(eye, target).is_err() {
            self.report(
                Diagnostic::new(
                    Code::DegenerateCamera,
                    target_span,
                    "the view target coincides with the eye",
                )
                .with_help("`to` must differ from `from` (the eye defaults to the origin)"),
            );
            return None;
        }
        let up = self.camera_parts.up.map(|(p, _)| p);
        if let Some((u, span)) = self.camera_parts.up {
            let collinear = HPlane::through(&eye.into(), &target.into(), &u.into()).is_err();
            if collinear {
                self.report(Diagnostic::new(Code::DegenerateCamera, span, "the up point lies on the line of sight, so it does not fix an up direction").with_help("choose an up point off the h-line through the eye and the target"));
                return None;
            }
        }
        Some(Camera { eye, target, up })
    }

    fn lint_scene(&mut self, camera: &Camera) {
        // Decided in the eye's own frame (see `seen_from`): the plane through
        // the eye orthogonal to the view direction; objects entirely on its
        // far side can't be seen.
        let eye = SeenFrom::new(camera.eye);
        let view = eye.direction_to(&camera.target);
        let mut found = Vec::new();
        // One statement can give many objects (edges, tessellation cells),
        // all with the statement's span: lint each statement once.
        for group in self.objects.chunk_by(|a, b| a.1 == b.1) {
            let span = group[0].1;
            if group.iter().any(|(o, _)| eye.is_inside(&o.shape)) {
                found.push(
                    Diagnostic::new(
                        Code::EyeInsideObject,
                        span,
                        "the eye is inside this object, so every view ray starts inside it",
                    )
                    .with_help("move the eye (`from`) or the object if this is not intended"),
                );
            } else if view.is_some_and(|v| group.iter().all(|(o, _)| eye.is_behind(&o.shape, v))) {
                found.push(Diagnostic::new(
                    Code::ObjectBehindEye,
                    span,
                    "this object is entirely behind the eye and cannot be seen",
                ));
            }
        }
        for (light, span) in &self.lights {
            let from = SeenFrom::new(light.position);
            for (object, _) in &self.objects {
                let opaque = self
                    .materials
                    .get(object.material.0)
                    .is_some_and(|m| m.material.transmission == 0.0);
                if opaque && from.is_inside(&object.shape) {
                    found.push(Diagnostic::new(
                        Code::LightInsideOpaqueObject,
                        *span,
                        "this light is inside an opaque object, so it lights nothing outside it",
                    ));
                    break;
                }
            }
        }
        self.diags.extend(found);
    }

    /// Whether `r` is an index the parser already reported as too large
    /// (it stands for `u64::MAX`); reporting it as undefined would repeat it.
    fn index_overflowed(&self, r: &Reference) -> bool {
        r.target == RefTarget::Index(u64::MAX)
            && self
                .diags
                .iter()
                .any(|d| d.code == Code::InvalidNumber && d.span == r.span)
    }

    /// The point `r` names, if any (without reporting).
    fn lookup_point(&self, r: &Reference) -> Option<usize> {
        match &r.target {
            RefTarget::Index(n) => usize::try_from(*n)
                .ok()
                .filter(|&n| n >= 1 && n <= self.points.len())
                .map(|n| n - 1),
            RefTarget::Name(name) => self.point_names.get(name).copied(),
        }
    }

    /// The material `r` names, if any (without reporting).
    fn lookup_material(&self, r: &Reference) -> Option<usize> {
        match &r.target {
            RefTarget::Index(n) => usize::try_from(*n)
                .ok()
                .filter(|&n| n >= 1 && n <= self.materials.len())
                .map(|n| n - 1),
            RefTarget::Name(name) => self.material_names.get(name).copied(),
        }
    }

    /// Statements that did not parse or failed to lower stop early, before
    /// they resolve all their references: mark what they refer to as used,
    /// so that one error does not also make its points and materials look
    /// unused.
    fn mark_failed_references(&mut self, file: &SourceFile) {
        let mut error_starts: Vec<usize> = self
            .diags
            .iter()
            .filter(|d| d.is_error())
            .map(|d| d.span.start)
            .collect();
        if error_starts.is_empty() {
            return;
        }
        error_starts.sort_unstable();
        let has_error = |span: Span| {
            let i = error_starts.partition_point(|&s| s < span.start);
            error_starts.get(i).is_some_and(|&s| s < span.end)
        };
        let mut refs: Vec<&Reference> = Vec::new();
        for section in &file.sections {
            refs.extend(section.broken.iter().flat_map(|b| &b.references));
            for st in section.statements.iter().filter(|st| has_error(st.span)) {
                for clause in &st.clauses {
                    match clause {
                        Clause::Assign { value, .. } => {
                            each_reference(value, &mut |r| refs.push(r))
                        }
                        Clause::Apply { target, arg, .. } => {
                            refs.extend(target);
                            if let Some(v) = arg {
                                each_reference(v, &mut |r| refs.push(r));
                            }
                        }
                        Clause::Value(v) => each_reference(v, &mut |r| refs.push(r)),
                    }
                }
            }
        }
        for r in refs {
            match r.sigil {
                RefSigil::Percent => {
                    if let Some(i) = self.lookup_point(r) {
                        self.points[i].used = true;
                    }
                }
                RefSigil::Hash => {
                    if let Some(i) = self.lookup_material(r) {
                        self.materials[i].used = true;
                    }
                }
                RefSigil::At => {}
            }
        }
    }

    /// Reports unused points and materials, unless a failed reference means
    /// that one of them was probably meant (the warnings would only add
    /// noise to the error).
    fn lint_unused(&mut self) {
        let mut found = Vec::new();
        for (i, p) in self.points.iter().enumerate() {
            if !self.point_ref_failed && !p.used && p.position.is_some() {
                // The number always identifies it, even when a name is duplicated.
                let name = match &p.name {
                    Some(n) => format!("%{} ({})", i + 1, quote(n)),
                    None => format!("%{}", i + 1),
                };
                found.push(Diagnostic::new(
                    Code::UnusedPoint,
                    p.span,
                    format!("point {name} is never used"),
                ));
            }
        }
        for (i, m) in self.materials.iter().enumerate() {
            if !self.material_ref_failed && !m.used {
                let name = match &m.material.name {
                    Some(n) => format!("#{} ({})", i + 1, quote(n)),
                    None => format!("#{}", i + 1),
                };
                found.push(Diagnostic::new(
                    Code::UnusedMaterial,
                    m.span,
                    format!("material {name} is never used"),
                ));
            }
        }
        self.diags.extend(found);
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum NameKind {
    Point,
    Material,
    Line,
    Plane,
}

/// Where ideal points may stand, for the help of `IdealPointNotAllowed`.
const IDEAL_ALLOWED_HELP: &str = "ideal points are allowed only as polygon vertices, rod and cylinder ends, `Plane` and `hplane` points and horosphere centres";

pub(crate) const GLOBAL_KEYS: &[&str] = &[
    "recursion_depth",
    "resolution",
    "window_size",
    "net_type",
    "samples",
    "frames",
    "from",
    "to",
    "up",
    "background",
    "ambient",
    "fov",
    "fog_color",
    "fog_distance",
];

pub(crate) const MATERIAL_FIELDS: &[&str] = &[
    "ambient",
    "diffuse",
    "specular",
    "alpha",
    "trans",
    "shininess",
    "checker",
    "checker_diffuse",
    "checker_ambient",
    "refraction",
];

const MATERIAL_FIELDS_HELP: &str = "material fields are ambient, diffuse, specular, alpha, trans, shininess, refraction, checker, checker_diffuse, checker_ambient";

pub(crate) const TRANSFORMATIONS: &[&str] = &["hline", "hplane", "Rotate", "Translate", "Reflect"];

/// `help`, preceded by "did you mean `X`?" when `word` is a near miss of
/// one of `candidates`.
fn did_you_mean(word: &str, candidates: &[&str], help: &str) -> String {
    match objects::closest(word, candidates) {
        Some(s) => format!("did you mean `{s}`? {help}"),
        None => help.to_string(),
    }
}

/// The known section an unknown section name was probably meant to be.
fn section_meant(name: &str) -> Option<&'static str> {
    SECTIONS
        .iter()
        .find(|s| s.eq_ignore_ascii_case(name))
        .or_else(|| {
            let s = objects::closest(name, &SECTIONS)?;
            SECTIONS.iter().find(|t| **t == s)
        })
        .copied()
}

const GLOBAL_KEYS_HELP: &str = "globals are recursion_depth, resolution, window_size, fov, net_type, samples, frames, from, to, up, background, ambient, fog_color, fog_distance";

/// A reference as written, shortened like [`quote`] (without the backticks).
fn reference_text(r: &Reference) -> String {
    let sigil = r.sigil.as_char();
    match &r.target {
        RefTarget::Index(n) => format!("{sigil}{n}"),
        RefTarget::Name(s) => format!("{sigil}{}", shorten(s)),
    }
}

/// A user-written name, shortened so that a very long one does not flood
/// the message.
fn shorten(name: &str) -> String {
    const MAX: usize = 24;
    match name.char_indices().nth(MAX) {
        Some((i, _)) => format!("{}…", &name[..i]),
        None => name.to_string(),
    }
}

/// A user-written name in backticks, shortened like [`shorten`].
fn quote(name: &str) -> String {
    format!("`{}`", shorten(name))
}
