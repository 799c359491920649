//! `hscene lsp`: a Language Server over stdio (lsp-server + lsp-types).
//!
//! Every answer comes from the compiler's own results (`hscene_lang`:
//! parse, compile, symbol index, formatter); this module only translates
//! between them and the protocol. One concept per file: the server loop
//! here, the document store, position conversion and one file per request.

mod completion;
mod diagnostics;
mod documents;
mod formatting;
mod hover;
mod navigation;
mod outline;
mod position;
mod request_error;

use std::process::ExitCode;

use lsp_server::{Connection, ErrorCode, Message, Notification, Request, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, Notification as _,
    PublishDiagnostics,
};
use lsp_types::request::{
    Completion, DocumentSymbolRequest, Formatting, GotoDefinition, HoverRequest, References,
    Rename, Request as _,
};
use lsp_types::{
    CompletionOptions, HoverProviderCapability, InitializeResult, OneOf, PositionEncodingKind,
    PublishDiagnosticsParams, ServerCapabilities, ServerInfo, TextDocumentSyncCapability,
    TextDocumentSyncKind,
};

use documents::Documents;
use request_error::RequestError;

/// Runs the server until the client says `exit` (or closes stdin).
pub fn run() -> ExitCode {
    let (connection, io_threads) = Connection::stdio();
    let code = match serve(&connection) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("hscene lsp: {e}");
            ExitCode::from(crate::exit::EXIT_USAGE_OR_IO)
        }
    };
    drop(connection);
    match io_threads.join() {
        Ok(()) => code,
        Err(e) => {
            eprintln!("hscene lsp: {e}");
            ExitCode::from(crate::exit::EXIT_USAGE_OR_IO)
        }
    }
}

fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        // Positions are UTF-16 code units, the protocol's default.
        position_encoding: Some(PositionEncodingKind::UTF16),
        text_document_sync: Some(TextDocumentSyncCapability::Kind(TextDocumentSyncKind::FULL)),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        rename_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec!["%".into(), "#".into(), "@".into()]),
            ..CompletionOptions::default()
        }),
        document_symbol_provider: Some(OneOf::Left(true)),
        document_formatting_provider: Some(OneOf::Left(true)),
        ..ServerCapabilities::default()
    }
}

fn serve(connection: &Connection) -> Result<(), Box<dyn std::error::Error>> {
    let init = InitializeResult {
        capabilities: capabilities(),
        server_info: Some(ServerInfo {
            name: "hscene".into(),
            version: Some(env!("CARGO_PKG_VERSION").into()),
        }),
    };
    let (id, _params) = connection.initialize_start()?;
    connection.initialize_finish(id, serde_json::to_value(init)?)?;
    let mut docs = Documents::default();
    for message in &connection.receiver {
        match message {
            Message::Request(req) => {
                if connection.handle_shutdown(&req)? {
                    return Ok(());
                }
                let response = handle_request(&docs, req);
                connection.sender.send(Message::Response(response))?;
            }
            Message::Notification(note) => {
                if let Some(uri) = handle_notification(&mut docs, note) {
                    publish(connection, &docs, &uri)?;
                }
            }
            Message::Response(_) => {}
        }
    }
    Ok(())
}

/// Applies a document notification; returns the document whose diagnostics
/// must be sent again.
fn handle_notification(docs: &mut Documents, note: Notification) -> Option<lsp_types::Uri> {
    match note.method.as_str() {
        DidOpenTextDocument::METHOD => {
            let p: lsp_types::DidOpenTextDocumentParams =
                note.extract(DidOpenTextDocument::METHOD).ok()?;
            let uri = p.text_document.uri.clone();
            docs.open(
                p.text_document.uri,
                p.text_document.text,
                p.text_document.version,
            );
            Some(uri)
        }
        DidChangeTextDocument::METHOD => {
            let p: lsp_types::DidChangeTextDocumentParams =
                note.extract(DidChangeTextDocument::METHOD).ok()?;
            // Full synchronisation: the last change holds the whole text.
            let text = p.content_changes.into_iter().last()?.text;
            let uri = p.text_document.uri.clone();
            docs.open(p.text_document.uri, text, p.text_document.version);
            Some(uri)
        }
        DidCloseTextDocument::METHOD => {
            let p: lsp_types::DidCloseTextDocumentParams =
                note.extract(DidCloseTextDocument::METHOD).ok()?;
            docs.close(&p.text_document.uri);
            None
        }
        _ => None,
    }
}

fn publish(
    connection: &Connection,
    docs: &Documents,
    uri: &lsp_types::Uri,
) -> Result<(), Box<dyn std::error::Error>> {
    let Some(doc) = docs.get(uri) else {
        return Ok(());
    };
    let params = PublishDiagnosticsParams {
        uri: uri.clone(),
        diagnostics: diagnostics::to_lsp(uri, doc),
        version: Some(doc.version),
    };
    connection
        .sender
        .send(Message::Notification(Notification::new(
            PublishDiagnostics::METHOD.into(),
            params,
        )))?;
    Ok(())
}

/// Answers one request; unknown methods get `MethodNotFound`.
fn handle_request(docs: &Documents, req: Request) -> Response {
    let id = req.id.clone();
    let result = match req.method.as_str() {
        HoverRequest::METHOD => answer(req, |p| hover::hover(docs, p)),
        GotoDefinition::METHOD => answer(req, |p| navigation::definition(docs, p)),
        References::METHOD => answer(req, |p| navigation::references(docs, p)),
        Rename::METHOD => answer(req, |p| navigation::rename(docs, p)),
        Completion::METHOD => answer(req, |p| completion::complete(docs, p)),
        DocumentSymbolRequest::METHOD => answer(req, |p| outline::document_symbols(docs, p)),
        Formatting::METHOD => answer(req, |p| formatting::format(docs, p)),
        _ => Err(RequestError {
            code: ErrorCode::MethodNotFound,
            message: format!("unsupported request `{}`", req.method),
        }),
    };
    match result {
        Ok(value) => Response::new_ok(id, value),
        Err(e) => Response::new_err(id, e.code as i32, e.message),
    }
}

fn answer<P, R>(
    req: Request,
    handler: impl FnOnce(P) -> Result<R, RequestError>,
) -> Result<serde_json::Value, RequestError>
where
    P: serde::de::DeserializeOwned,
    R: serde::Serialize,
{
    let method = req.method.clone();
    let (_, params) = req.extract::<P>(&method).map_err(|e| RequestError {
        code: ErrorCode::InvalidParams,
        message: format!("{e:?}"),
    })?;
    let result = handler(params)?;
    serde_json::to_value(result).map_err(|e| RequestError {
        code: ErrorCode::InternalError,
        message: e.to_string(),
    })
}
