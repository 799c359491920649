//! Images named in a scene: a material's `texture = "file.png"` and the
//! `sky = "file.exr"`, read relative to the scene's directory
//! (`image_file.rs`), each file once per lowering.

use std::path::PathBuf;
use std::sync::Arc;

use hscene_ir::TextureImage;

use super::Lowerer;
use super::text::quote;
use crate::diagnostic::{Code, Diagnostic};
use crate::image_file::{self, ImageFileError};
use crate::syntax::Value;

impl Lowerer<'_> {
    /// The image a string value names, for `what` ("a texture", "the
    /// sky"); reported and `None` if it cannot be read.
    pub(super) fn image_file(
        &mut self,
        value: &Value,
        what: &str,
    ) -> Option<(String, Arc<TextureImage>)> {
        let Value::Str { text, span } = value else {
            self.report(
                Diagnostic::new(
                    Code::WrongType,
                    value.span(),
                    format!(
                        "{what} is an image file name in quotes, found {}",
                        value.describe()
                    ),
                )
                .with_help("write the file name in double quotes, e.g. `\"tiling.png\"`"),
            );
            return None;
        };
        let path = match self.base_dir {
            Some(dir) => dir.join(text),
            None => PathBuf::from(text),
        };
        self.inputs.push(path.clone());
        match self.files.image(&path, image_file::load) {
            Ok(image) => Some((text.clone(), image)),
            Err(ImageFileError::Io(e)) => {
                self.report(
                    Diagnostic::new(
                        Code::ImageFileUnreadable,
                        *span,
                        format!("cannot read the image file {}: {e}", quote(text)),
                    )
                    .with_help("a relative file name is taken from the scene file's directory"),
                );
                None
            }
            Err(e) => {
                self.report(
                    Diagnostic::new(
                        Code::ImageFileInvalid,
                        *span,
                        format!("cannot use the image file {}: {e}", quote(text)),
                    )
                    .with_help("images are read from PNG, JPEG (sRGB) and OpenEXR (linear) files of at most 4096 × 4096 pixels"),
                );
                None
            }
        }
    }
}
