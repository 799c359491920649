//! The file formats: binary STL and 3MF (millimetres, for printers), OBJ
//! with its MTL and binary glTF (metres, with materials, for Blender and
//! other renderers). Every encoder is a pure function of the model, so an
//! export run twice writes the same bytes.

mod glb;
mod obj;
mod stl;
mod threemf;

use std::path::Path;

use crate::error::ExportError;
use crate::model::Model;

/// A format we write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Binary STL, millimetres, no colour.
    Stl,
    /// 3MF, millimetres, one object a shell, base-material colours.
    ThreeMf,
    /// Wavefront OBJ and its MTL, metres, one object a shell.
    Obj,
    /// Binary glTF 2.0, metres, one node a shell.
    Glb,
}

/// One file an export writes.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputFile {
    /// Its name, relative to the output's directory.
    pub name: String,
    /// Its bytes.
    pub bytes: Vec<u8>,
}

impl Format {
    /// The format the path's extension names.
    ///
    /// Errors: [`ExportError::UnknownFormat`].
    pub fn from_path(path: &Path) -> Result<Format, ExportError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("stl") => Ok(Format::Stl),
            Some("3mf") => Ok(Format::ThreeMf),
            Some("obj") => Ok(Format::Obj),
            Some("glb") => Ok(Format::Glb),
            _ => Err(ExportError::UnknownFormat(path.display().to_string())),
        }
    }

    /// True for formats a printer reads, which need closed shells.
    pub fn needs_closed_shells(self) -> bool {
        matches!(self, Format::Stl | Format::ThreeMf)
    }

    /// Refuses an output name the format cannot write: for OBJ, one with a
    /// control character (a line break would inject lines into the OBJ
    /// through its `mtllib` line). Checked before meshing and again when
    /// encoding.
    pub fn check_name(self, path: &Path) -> Result<(), ExportError> {
        if self == Format::Obj {
            let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
            if let Some(name) = name
                && name.chars().any(char::is_control)
            {
                return Err(ExportError::UnwritableName(name.escape_debug().to_string()));
            }
        }
        Ok(())
    }

    /// The files of `model` in this format for an output called `path`:
    /// the file itself, and for OBJ its MTL beside it (same stem).
    ///
    /// Errors: [`ExportError::OpenMesh`] for an open shell in STL or 3MF;
    /// [`ExportError::Package`] if the 3MF zip cannot be assembled.
    pub fn encode(self, model: &Model, path: &Path) -> Result<Vec<OutputFile>, ExportError> {
        self.check_name(path)?;
        if self.needs_closed_shells()
            && let Some(shell) = model.shells.iter().find(|s| !s.closed)
        {
            return Err(ExportError::OpenMesh {
                object: shell.object.clone(),
                uses: shell.boundary_defect().unwrap_or(1),
            });
        }
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| "export".to_string());
        Ok(match self {
            Format::Stl => vec![OutputFile {
                name,
                bytes: stl::encode(model),
            }],
            Format::ThreeMf => vec![OutputFile {
                name,
                bytes: threemf::encode(model)?,
            }],
            Format::Glb => vec![OutputFile {
                name,
                bytes: glb::encode(model),
            }],
            Format::Obj => {
                let stem = path
                    .file_stem()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_else(|| "export".to_string());
                let mtl = format!("{stem}.mtl");
                vec![
                    OutputFile {
                        bytes: obj::encode_mtl(model),
                        name: mtl.clone(),
                    },
                    OutputFile {
                        bytes: obj::encode(model, &mtl),
                        name,
                    },
                ]
            }
        })
    }
}

/// Millimetres to metres, for the formats read as metres.
const METRES_PER_MM: f64 = 1e-3;

/// A shell's triangle normal (unit, or zero for a degenerate triangle).
fn normal(corners: [hgeom::glam::DVec3; 3]) -> hgeom::glam::DVec3 {
    let [a, b, c] = corners;
    (b - a).cross(c - a).normalize_or_zero()
}
