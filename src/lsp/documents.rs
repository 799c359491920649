//! The open documents and what the compiler made of each.

use std::collections::HashMap;
use std::path::PathBuf;

use hscene_lang::symbols::SymbolIndex;
use hscene_lang::{FileCache, LineIndex};
use lsp_types::Uri;

use super::request_error::RequestError;
use crate::input::MAX_SCENE_BYTES;

/// One open document, analysed when it was opened or changed.
pub struct Document {
    pub text: String,
    /// Lines and columns of `text`, for every position conversion.
    pub lines: LineIndex,
    pub version: i32,
    /// The compiler's result: diagnostics, and the IR when error-free.
    /// Empty for a document over [`MAX_SCENE_BYTES`].
    pub compiled: hscene_lang::Compiled,
    /// Declarations and references.
    pub symbols: SymbolIndex,
    /// The meshes and images it names, read once and again only when
    /// they change on disk.
    files: FileCache,
}

impl Document {
    /// Whether the text is over the limit and was not analysed.
    pub fn too_large(&self) -> bool {
        self.text.len() as u64 > MAX_SCENE_BYTES
    }
}

#[derive(Default)]
pub struct Documents {
    docs: HashMap<String, Document>,
}

impl Documents {
    /// Stores (or replaces) a document and analyses it, unless it is
    /// larger than a scene file may be (then it is held unanalysed, and
    /// [`Document::too_large`] says so).
    pub fn open(&mut self, uri: Uri, text: String, version: i32) {
        let files = self
            .docs
            .remove(uri.as_str())
            .map(|d| d.files)
            .unwrap_or_default();
        let (compiled, symbols) = if text.len() as u64 > MAX_SCENE_BYTES {
            let empty = hscene_lang::parse("");
            (
                hscene_lang::Compiled {
                    scene: None,
                    diagnostics: Vec::new(),
                    omitted: hscene_lang::Omitted::default(),
                    inputs: Vec::new(),
                },
                SymbolIndex::new(&empty.file),
            )
        } else {
            let options = hscene_lang::Options {
                base_dir: file_path(&uri).and_then(|p| p.parent().map(PathBuf::from)),
                frame: 0,
                files: files.clone(),
                space: None,
            };
            // Analysed as `check` reads the same file (a lone CR is a line
            // end there; the offsets are the same).
            let analysed = hscene_lang::source::lone_crs_as_lf(&text);
            (
                hscene_lang::compile_with(&analysed, &options),
                SymbolIndex::new(&hscene_lang::parse(&analysed).file),
            )
        };
        let lines = LineIndex::new(&text);
        self.docs.insert(
            uri.as_str().to_owned(),
            Document {
                text,
                lines,
                version,
                compiled,
                symbols,
                files,
            },
        );
    }

    pub fn close(&mut self, uri: &Uri) {
        self.docs.remove(uri.as_str());
    }

    pub fn get(&self, uri: &Uri) -> Option<&Document> {
        self.docs.get(uri.as_str())
    }

    /// The document of a request, or the error to answer with.
    pub fn require(&self, uri: &Uri) -> Result<&Document, RequestError> {
        self.get(uri)
            .ok_or_else(|| RequestError::failed(format!("{} is not open", uri.as_str())))
    }

    /// The document and byte offset a position request is about.
    pub fn at(
        &self,
        p: &lsp_types::TextDocumentPositionParams,
    ) -> Result<(&Document, usize), RequestError> {
        let doc = self.require(&p.text_document.uri)?;
        Ok((doc, super::position::offset(&doc.lines, p.position)))
    }
}

/// The local path of a `file:` URI (percent-escapes decoded), so relative
/// mesh file names resolve as they would for `hscene check`.
pub fn file_path(uri: &Uri) -> Option<PathBuf> {
    let rest = uri.as_str().strip_prefix("file://")?;
    let mut bytes = Vec::with_capacity(rest.len());
    let raw = rest.as_bytes();
    let mut i = 0;
    while i < raw.len() {
        if raw[i] == b'%'
            && let Some(hex) = rest.get(i + 1..i + 3)
            && let Ok(b) = u8::from_str_radix(hex, 16)
        {
            bytes.push(b);
            i += 3;
            continue;
        }
        bytes.push(raw[i]);
        i += 1;
    }
    String::from_utf8(bytes).ok().map(PathBuf::from)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::str::FromStr;

    #[test]
    fn file_uris_become_paths() {
        let uri = Uri::from_str("file:///tmp/my%20scenes/a.hsc").unwrap();
        assert_eq!(file_path(&uri), Some(PathBuf::from("/tmp/my scenes/a.hsc")));
        let other = Uri::from_str("untitled:Untitled-1").unwrap();
        assert_eq!(file_path(&other), None);
    }
}
