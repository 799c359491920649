//! `hscene export`: compile the scene, mesh it (hexport), write the files
//! atomically (hrender's writer, so an interrupted export leaves nothing
//! behind and an earlier file untouched).

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use hexport::{ExportOptions, Format, Millimetres, ThinParts};

use crate::cli::{ColorChoice, ExportArgs, Format as ReportFormat};
use crate::exit::{EXIT_SCENE_ERRORS, EXIT_USAGE_OR_IO};
use crate::report;

fn fail(message: impl std::fmt::Display) -> ExitCode {
    diagln!("error: {message}");
    ExitCode::from(EXIT_USAGE_OR_IO)
}

fn options(args: &ExportArgs) -> Result<ExportOptions, hexport::ExportError> {
    let options = ExportOptions {
        size: Millimetres::parse(&args.size)?,
        min_feature: Millimetres::parse(&args.min_feature)?,
        tolerance: Millimetres::parse(&args.tolerance)?,
        thin: if args.thicken {
            ThinParts::Thicken
        } else {
            ThinParts::Cut
        },
        face_half_thickness: args.face_thickness / 2.0,
        max_triangles: args.max_triangles,
    };
    options.validate()?;
    Ok(options)
}

/// The files written for `output` in `format`, beside it.
fn output_paths(output: &Path, format: Format) -> Vec<PathBuf> {
    let mut paths = vec![output.to_path_buf()];
    if format == Format::Obj {
        paths.insert(0, output.with_extension("mtl"));
    }
    paths
}

pub fn run(args: &ExportArgs, color: ColorChoice) -> ExitCode {
    let options = match options(args) {
        Ok(o) => o,
        Err(e) => return fail(e),
    };
    let format = match Format::from_path(&args.output) {
        Ok(f) => f,
        Err(e) => return fail(e),
    };
    let overwrite = if args.force {
        hrender::Overwrite::Force
    } else {
        hrender::Overwrite::Writable
    };
    if let Err(e) = format.check_name(&args.output) {
        return fail(e);
    }
    let paths = output_paths(&args.output, format);
    for path in &paths {
        if let Err(e) = hrender::check_output_file(path, &[&args.scene], overwrite) {
            return fail(e);
        }
    }
    let source = match crate::input::read_scene_reported(&args.scene, ReportFormat::Short) {
        Ok(s) => s,
        Err(message) => {
            diag!("{message}");
            return ExitCode::from(EXIT_USAGE_OR_IO);
        }
    };
    let compiled = hscene_lang::compile_with(
        &source,
        &crate::input::compile_options(&args.scene, args.frame),
    );
    let stderr_tty = std::io::stderr().is_terminal();
    // A print has no camera: lints about the picture alone are left out.
    let shown: Vec<hscene_lang::Diagnostic> = compiled
        .diagnostics
        .iter()
        .filter(|d| d.is_error() || !d.code.is_about_the_picture())
        .cloned()
        .collect();
    if !shown.is_empty() {
        diag!(
            "{}",
            report::format_diagnostics(
                &args.scene,
                &source,
                &shown,
                compiled.omitted,
                ReportFormat::Human,
                color.enabled(stderr_tty)
            )
        );
    }
    let Some(scene) = compiled.scene else {
        return ExitCode::from(EXIT_SCENE_ERRORS);
    };
    // Now that the files the scene names are known, none may be an output.
    let mut inputs: Vec<&Path> = vec![&args.scene];
    inputs.extend(compiled.inputs.iter().map(PathBuf::as_path));
    for path in &paths {
        if let Err(e) = hrender::check_output_file(path, &inputs, overwrite) {
            return fail(e);
        }
    }
    if args.frame >= scene.settings.frames {
        return fail(format!(
            "--frame {} is past the scene's last frame ({})",
            args.frame,
            scene.settings.frames.saturating_sub(1)
        ));
    }
    let start = Instant::now();
    let bar = stderr_tty.then(|| {
        let bar = indicatif::ProgressBar::new(0);
        bar.set_style(
            indicatif::ProgressStyle::with_template("meshing {bar:40} {pos}/{len} parts {elapsed}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let progress = |done: usize, total: usize| {
        if let Some(bar) = &bar {
            bar.set_length(total as u64);
            bar.set_position(done as u64);
        }
    };
    let model = hexport::export_scene(&scene, &options, &progress);
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let model = match model {
        Ok(m) => m,
        Err(e) => return fail(e),
    };
    let files = match format.encode(&model, &args.output) {
        Ok(f) => f,
        Err(e) => return fail(e),
    };
    // An OBJ and its MTL are written together: both or neither.
    let together: Vec<(&Path, &[u8])> = files
        .iter()
        .zip(&paths)
        .map(|(file, path)| (path.as_path(), file.bytes.as_slice()))
        .collect();
    if let Err(e) = hrender::write_files_together(&together) {
        return fail(e);
    }
    let bytes: usize = files.iter().map(|f| f.bytes.len()).sum();
    diagln!(
        "wrote {}: {} shells, {} triangles, {}, {}, {} bytes, {:.2} s",
        args.output.display(),
        model.shells.len(),
        model.triangle_count(),
        volume_summary(&model),
        left_out_summary(model.parts_cut, &options),
        bytes,
        start.elapsed().as_secs_f64()
    );
    // Within the meshing tolerance, bodies whose surfaces meet may have
    // boxes a little apart.
    for label in model.floating_bodies(options.tolerance.get()) {
        diagln!(
            "warning: {label} touches no other object: printed with the rest it is a loose part; move it to touch another, or print it on its own"
        );
    }
    ExitCode::SUCCESS
}

/// The printed volume, said for what it is: the closed shells' sum (an
/// overlap counts twice); an open surface (a mesh file's with a boundary)
/// encloses nothing and is counted apart rather than given a volume.
fn volume_summary(model: &hexport::Model) -> String {
    let open = model.shells.iter().filter(|s| !s.closed).count();
    let closed: f64 = model
        .shells
        .iter()
        .filter(|s| s.closed)
        .map(hexport::Shell::signed_volume)
        .sum();
    match open {
        0 => format!("volume {closed:.1} mm³ (sum of shells)"),
        n => format!(
            "volume {closed:.1} mm³ (sum of the closed shells; {n} open surface(s) enclose none)"
        ),
    }
}

/// What the cut rule left out (docs/export.md, "The cut rule"): parts
/// thinner than the minimum; with `--thicken` nothing is left out for
/// being thin, only thickened tubes too short to print as rods and the
/// ends of tubes that run out to the boundary.
fn left_out_summary(parts: usize, options: &hexport::ExportOptions) -> String {
    let min = options.min_feature.get();
    match options.thin {
        hexport::ThinParts::Cut => format!("{parts} part(s) thinner than {min} mm left out"),
        hexport::ThinParts::Thicken => format!(
            "{parts} part(s) left out (tubes shorter than {} mm once thickened to {min} mm)",
            hexport::THICKENED_MIN_LENGTH * min
        ),
    }
}
