//! The error every request handler returns: a leaf, so that the handlers
//! and the document store need nothing from the server loop.

use lsp_server::ErrorCode;

/// A request that cannot be answered.
pub struct RequestError {
    pub code: ErrorCode,
    pub message: String,
}

impl RequestError {
    /// The request is well formed but asks for something impossible.
    pub fn failed(message: impl Into<String>) -> Self {
        RequestError {
            code: ErrorCode::RequestFailed,
            message: message.into(),
        }
    }
}
