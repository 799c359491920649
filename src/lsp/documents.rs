//! The open documents and what the compiler made of each.

use std::collections::HashMap;
use std::path::PathBuf;

use hscene_lang::symbols::SymbolIndex;
use lsp_types::Uri;

use super::request_error::RequestError;

/// One open document, analysed when it was opened or changed.
pub struct Document {
    pub text: String,
    pub version: i32,
    /// The compiler's result: diagnostics, and the IR when error-free.
    pub compiled: hscene_lang::Compiled,
    /// Declarations and references.
    pub symbols: SymbolIndex,
}

#[derive(Default)]
pub struct Documents {
    docs: HashMap<String, Document>,
}

impl Documents {
    /// Stores (or replaces) a document and analyses it.
    pub fn open(&mut self, uri: Uri, text: String, version: i32) {
        let options = hscene_lang::Options {
            base_dir: file_path(&uri).and_then(|p| p.parent().map(PathBuf::from)),
            frame: 0,
        };
        let compiled = hscene_lang::compile_with(&text, &options);
        let symbols = SymbolIndex::new(&hscene_lang::parse(&text).file);
        self.docs.insert(
            uri.as_str().to_owned(),
            Document {
                text,
                version,
                compiled,
                symbols,
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
        Ok((doc, super::position::offset(&doc.text, p.position)))
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
