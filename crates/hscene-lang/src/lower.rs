//! Semantic analysis: resolve references, validate, apply transformations,
//! and lower the syntax tree to the [`ir`](crate::ir).
//!
//! Sections are processed in dependency order whatever their order in the
//! file: `Points` and `BRDFs` first, then `Transformations` (which move
//! points, in statement order), then `Lights`, `Objects` and `Globals`, which
//! see the final positions. Every problem found is reported; lowering goes on
//! past errors so one run reports as much as it can.
//!
//! This file holds the state of one lowering and the order of its steps;
//! each section, the camera, the lints and the moves of named things have
//! a file of their own, as methods on [`Lowerer`].

mod budget;
mod camera;
mod globals;
mod image_textures;
mod lens_globals;
mod light_strength;
mod lights;
mod lints;
mod materials;
mod moves;
mod names;
mod objects;
mod placement;
mod points;
mod ranges;
mod resolve;
mod seen_from;
mod space_globals;
mod suggest;
mod table;
mod text;
mod transformations;
mod up_lint;
mod values;
mod view_globals;
mod view_lint;

use std::collections::HashMap;
use std::path::Path;

use hgeom::{HPlane, Segment};

use crate::diagnostic::{Code, Diagnostic, Span};
use crate::diagnostic_list::DiagnosticList;
use crate::ir::{Animation, Light, Material, Object, PointRecord, Scene, Settings, frame_time};
use crate::line_index::LineIndex;
use crate::syntax::{Clause, Section, SourceFile, Value};

pub(crate) use globals::GLOBAL_KEYS;
pub use globals::{MAX_FRAMES, MAX_PIXELS, MAX_SAMPLES};
pub(crate) use lights::LIGHT_OPTIONS;
pub(crate) use materials::MATERIAL_FIELDS;
pub(crate) use objects::keywords::OBJECT_KEYWORDS;
pub(crate) use objects::options::OPTION_NAMES;
pub(crate) use transformations::TRANSFORMATIONS;

/// Section names, in processing order.
pub(crate) const SECTIONS: [&str; 6] = [
    "Points",
    "BRDFs",
    "Transformations",
    "Lights",
    "Objects",
    "Globals",
];

/// The state of one lowering.
struct Lowerer<'d> {
    diags: &'d mut DiagnosticList,
    points: names::Table<points::DeclaredPoint>,
    materials: names::Table<Material>,
    lines: names::Table<Option<Segment>>,
    planes: names::Table<Option<HPlane>>,
    lights: Vec<(Light, Span)>,
    objects: Vec<(Object, Span)>,
    /// Names of objects and lights, the targets of `@name->...`, each with
    /// the span of the declaring name.
    targets: names::Table<names::TargetSlot>,
    /// Every object and light name in the file, collected before lowering,
    /// so that hints in earlier-processed sections can mention them.
    target_labels: std::collections::HashSet<String>,
    /// `@` transformations, applied once objects and lights exist.
    moves: Vec<moves::PendingMove>,
    settings: Settings,
    camera_parts: camera::CameraParts,
    view: view_globals::ViewParts,
    lens: lens_globals::LensParts,
    /// The space keys (`space_globals.rs`).
    space: space_globals::SpaceParts,
    /// The meshes and images read, by path: a file named twice is read once.
    files: &'d crate::file_cache::FileCache,
    /// Every file named and read (meshes, images, space files), in order:
    /// what an output must never overwrite.
    inputs: Vec<std::path::PathBuf>,
    /// A point reference failed (undefined, or something else where a point
    /// was needed, or text was skipped): the point meant may look unused.
    point_ref_failed: bool,
    /// `frames = N` was refused: the scene's frame count is unknown, so
    /// no lint may say it has one frame.
    frames_refused: bool,
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
    /// What moves from frame to frame (`apply_moves` fills the tracks).
    animation: Animation,
    /// Primitives so far, and whether the cap was reported (`budget.rs`).
    primitives: u64,
    primitive_cap_reported: bool,
    light_cap_reported: bool,
    /// Where `integrator = NAME` was given, if it was.
    integrator_span: Option<Span>,
}

/// Lower a parsed file. Returns the scene only if no error was reported
/// (by the parser or here).
///
/// The file is consumed: each section's syntax is dropped as soon as it is
/// lowered, so the tree of a large scene's materials is gone before its
/// objects are built (peak memory, docs/performance.md).
///
/// `source` is the text `file` was parsed from; it is used only to turn
/// offsets into line and column numbers in messages.
pub(crate) fn lower(
    file: SourceFile,
    source: &str,
    options: &crate::options::Options,
    diags: &mut DiagnosticList,
    inputs: &mut Vec<std::path::PathBuf>,
) -> Option<Scene> {
    let frames = declared_frames(&file);
    let frame = options.frame.min(frames - 1);
    let mut lw = Lowerer {
        base_dir: options.base_dir.as_deref(),
        frame,
        time: frame_time(frame, frames),
        animations: Vec::new(),
        animation: Animation::default(),
        diags,
        points: names::Table::default(),
        materials: names::Table::default(),
        lines: names::Table::default(),
        planes: names::Table::default(),
        lights: Vec::new(),
        objects: Vec::new(),
        targets: names::Table::default(),
        target_labels: file
            .sections
            .iter()
            .filter(|s| matches!(s.name.text.as_str(), "Objects" | "Lights"))
            .flat_map(|s| &s.statements)
            .filter_map(|st| st.label.as_ref().map(|l| l.text.to_string()))
            .collect(),
        moves: Vec::new(),
        settings: globals::default_settings(),
        camera_parts: camera::CameraParts::default(),
        view: view_globals::ViewParts::default(),
        lens: lens_globals::LensParts::default(),
        space: space_globals::SpaceParts::default(),
        files: &options.files,
        inputs: Vec::new(),
        point_ref_failed: file.incomplete,
        frames_refused: false,
        primitives: 0,
        primitive_cap_reported: false,
        light_cap_reported: false,
        integrator_span: None,
        material_ref_failed: file.incomplete,
    };
    if let Some(pairings) = &options.space {
        lw.space.give(std::sync::Arc::clone(pairings));
    }
    lw.check_section_names(&file, source);
    let mut sections: Vec<Option<Section>> = file.sections.into_iter().map(Some).collect();
    for name in SECTIONS {
        // A misspelt section is lowered as the one it was meant to be, so its
        // declarations do not go missing and cascade into undefined references.
        let meant = |s: &Section| {
            s.name.text == name
                || (!SECTIONS.contains(&s.name.text.as_str())
                    && suggest::meant(&s.name.text, &SECTIONS) == Some(name))
        };
        for slot in sections
            .iter_mut()
            .filter(|s| s.as_ref().is_some_and(meant))
        {
            let Some(section) = slot.take() else { continue };
            if section.name.text != name {
                // Already an error; don't add lints about what it declares.
                lw.point_ref_failed = true;
                lw.material_ref_failed = true;
            }
            match name {
                "Points" => lw.points_section(&section),
                "BRDFs" => lw.brdfs_section(&section),
                "Transformations" => lw.transformations_section(&section),
                "Lights" => lw.lights_section(&section),
                "Objects" => lw.objects_section(&section),
                _ => lw.globals_section(&section),
            }
            lw.mark_failed_references(&section);
        }
    }
    // Sections under no known name were not lowered; what they refer to
    // still counts as meant.
    for section in sections.into_iter().flatten() {
        lw.mark_failed_references(&section);
    }
    let mut camera = lw.camera();
    lw.apply_moves(&mut camera);
    lw.settle_view(camera.as_ref());
    lw.settle_lens(camera.as_ref());
    lw.settle_space();
    if let Some(camera) = &camera {
        lw.refuse_too_far_from_eye(camera);
        lw.lint_scene(camera);
        lw.lint_outside_view(camera);
        lw.lint_squeezed_disk(camera);
        lw.lint_up_roll(camera);
    }
    lw.lint_unused();
    lw.lint_still_animation();
    lw.lint_ambient_under_path();
    inputs.append(&mut lw.inputs);
    if lw.diags.has_errors() {
        return None;
    }
    let camera = camera?;
    for (light, _) in lw.lights.iter_mut().filter(|(l, _)| l.on_camera) {
        light.position = camera.eye;
    }
    Some(Scene {
        settings: lw.settings,
        camera,
        materials: exact(lw.materials.into_values().collect()),
        lights: lw.lights.into_iter().map(|(l, _)| l).collect(),
        objects: exact(lw.objects.into_iter().map(|(o, _)| o).collect()),
        points: lw
            .points
            .into_values()
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
        animation: lw.animation,
    })
}

/// `list` in an allocation of its own length: a list collected in place
/// from one of larger items keeps the larger allocation.
fn exact<T>(mut list: Vec<T>) -> Vec<T> {
    list.shrink_to_fit();
    list
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
            } if globals::is_frames_key(&key.text) => Some(*value),
            _ => None,
        })
        .rfind(|x| x.fract() == 0.0 && (1.0..=f64::from(MAX_FRAMES)).contains(x))
        .map_or(1, |x| x as u32)
}

impl Lowerer<'_> {
    fn report(&mut self, d: Diagnostic) {
        self.diags.push(d);
    }

    fn error(&mut self, code: Code, span: Span, message: impl Into<String>) {
        self.report(Diagnostic::new(code, span, message));
    }

    fn wrong_arity(&mut self, span: Span, message: impl Into<String>, usage: impl Into<String>) {
        self.report(Diagnostic::new(Code::WrongArity, span, message).with_help(usage));
    }

    /// Reports `d` if there is one (a declaration refused by its table).
    fn report_refused(&mut self, d: Result<(), Diagnostic>) {
        if let Err(d) = d {
            self.report(d);
        }
    }

    fn check_section_names(&mut self, file: &SourceFile, source: &str) {
        let mut seen: HashMap<&str, Span> = HashMap::new();
        let mut lines: Option<LineIndex> = None;
        for section in &file.sections {
            let name = section.name.text.as_str();
            if !SECTIONS.contains(&name) {
                let mut d = Diagnostic::new(
                    Code::UnknownSection,
                    section.name.span,
                    format!("unknown section {}", text::quote(name)),
                );
                d = match suggest::meant(name, &SECTIONS) {
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
                    .get_or_insert_with(|| LineIndex::new(source))
                    .line_col(first.start());
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
}
