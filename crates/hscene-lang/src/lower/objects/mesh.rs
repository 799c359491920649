//! Building a `Mesh` object: reading and laying out its file, and its
//! `smooth` option (see `docs/language.md`, "Mesh").

use hgeom::TriangleMesh;

use crate::diagnostic::{Code, Diagnostic};
use crate::lower::Lowerer;
use crate::lower::ranges::MAX_MESH_SIZE;
use crate::lower::text::quote;
use crate::mesh_file::{self, MeshFileError};
use crate::syntax::Value;

impl Lowerer<'_> {
    /// The crease angle of `smooth = ANGLE`, in degrees (`0..=180`).
    pub(super) fn crease_angle(&mut self, value: &Value) -> Option<f64> {
        let angle = self.number(value)?;
        if (0.0..=180.0).contains(&angle) {
            return Some(angle);
        }
        self.report(
            Diagnostic::new(
                Code::InvalidValue,
                value.span(),
                format!("a `smooth` angle must be between 0 and 180 degrees, got {}", hgeom::Compact(angle)),
            )
            .with_help("creases between faces sharper than the angle stay sharp: 30 to 60 suits most meshes, 180 smooths every edge"),
        );
        None
    }

    /// Reads and lays out a mesh file (see `mesh_file.rs`).
    pub(super) fn mesh(
        &mut self,
        file: &str,
        size: f64,
        values: &[&Value],
        smooth: Option<f64>,
    ) -> Option<TriangleMesh> {
        let (file_span, size_span) = (values[0].span(), values[1].span());
        if size > MAX_MESH_SIZE {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    size_span,
                    format!("a mesh size must be at most {MAX_MESH_SIZE}, got {}", hgeom::Compact(size)),
                )
                .with_help("the size is the distance of the mesh's farthest vertex from its centre; opposite vertices are twice that apart, and f64 holds about 37"),
            );
            return None;
        }
        let path = match self.base_dir {
            Some(dir) => dir.join(file),
            None => std::path::PathBuf::from(file),
        };
        self.inputs.push(path.clone());
        let data = match self.files.mesh(&path, mesh_file::load) {
            Ok(data) => data,
            Err(MeshFileError::Io(e)) => {
                // The folder is named because a scene copied from the docs
                // or the examples names its meshes from where it was: the
                // user must see where the name led, not only that it failed.
                let whose = match self.base_dir {
                    Some(_) => "the scene file's folder",
                    None => "the current folder",
                };
                // Made absolute: a scene named as `scene.hsc` has the
                // folder "", which says nothing.
                let looked = std::path::absolute(&path).unwrap_or_else(|_| path.clone());
                let folder = looked.parent().unwrap_or(&looked);
                self.report(
                    Diagnostic::new(
                        Code::MeshFileUnreadable,
                        file_span,
                        format!(
                            "cannot read the mesh file {} (looked in the folder `{}`): {e}",
                            quote(file),
                            folder.display()
                        ),
                    )
                    .with_help(format!("a relative file name is taken from {whose}, not from where hscene runs: in a scene copied from the docs or the examples, copy the mesh beside your scene or write its path from your scene's folder")),
                );
                return None;
            }
            Err(e) => {
                self.report(
                    Diagnostic::new(
                        Code::MeshFileInvalid,
                        file_span,
                        format!("cannot use the mesh file {}: {e}", quote(file)),
                    )
                    .with_help("meshes are read from Wavefront OBJ (`.obj`) and PLY (`.ply`, ASCII or binary) files with triangle or polygon faces"),
                );
                return None;
            }
        };
        let Some(vertices) = data.layout(size) else {
            self.report(
                Diagnostic::new(
                    Code::MeshFileInvalid,
                    file_span,
                    format!(
                        "the mesh in {} has no extent: all its vertices coincide",
                        quote(file)
                    ),
                )
                .with_help("use a file whose vertices span a surface"),
            );
            return None;
        };
        let total = data.triangles.len();
        if !self.fits(crate::ir::mesh_budget_cost(total as u64), file_span) {
            return None;
        }
        // The file's normals are laid out only when smoothing asks for them.
        // The file's data stays in the cache (`file_cache.rs`) for the next
        // statement or compile that names it.
        let given = smooth.and_then(|_| data.layout_normals(size));
        let triangles = data.triangles.clone();
        let built = TriangleMesh::new(vertices, triangles).and_then(|mesh| match smooth {
            Some(angle) => mesh.smoothed(angle, given.as_ref()),
            None => Ok(mesh),
        });
        match built {
            Ok(mesh) => {
                let dropped = mesh.dropped_triangles();
                if dropped > 0 {
                    self.report(
                        Diagnostic::new(
                            Code::DegenerateTriangles,
                            file_span,
                            format!("{dropped} of the {total} triangles of this mesh have no area and are left out"),
                        )
                        .with_help("such triangles (repeated or collinear vertices) draw nothing; clean the mesh to silence this"),
                    );
                }
                Some(mesh)
            }
            Err(e) => {
                self.geom_failure(file_span, "this mesh", &e);
                None
            }
        }
    }
}
