//! `hscene lsp`: a Language Server over stdio (lsp-server + lsp-types).
//!
//! Every answer comes from the compiler's own results (`hscene_lang`:
//! parse, compile, symbol index, formatter); this module only translates
//! between them and the protocol. One concept per file: the server loop
//! here, the wire (`transport.rs`), the document store, position conversion
//! and one file per request.

mod completion;
mod diagnostics;
mod documents;
mod formatting;
mod hover;
mod navigation;
mod outline;
mod position;
mod request_error;
mod transport;

use std::io::{BufRead, Write};
use std::process::ExitCode;

use lsp_server::{ErrorCode, Message, Notification, Request, Response};
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
use transport::{Incoming, Transport, WireError};

/// Runs the server until the client says `exit` or closes stdin. Exit
/// status 0 after `shutdown` then `exit` or at the end of input, 1 for
/// `exit` without `shutdown` (as the protocol asks), 2 when the stream
/// breaks (malformed headers, a client that stopped reading).
pub fn run() -> ExitCode {
    let mut transport = Transport::new(std::io::stdin().lock(), std::io::stdout().lock());
    match serve(&mut transport) {
        Ok(code) => code,
        Err(e) => {
            if let WireError::Framing(reason) = &e {
                // Said on the wire too, in case the client logs it.
                let _ = transport.write_value(&transport::error_response(
                    None,
                    transport::PARSE_ERROR,
                    &format!("{reason}; the server stops"),
                ));
            }
            diagln!("hscene lsp: {e}");
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

/// Where the conversation is: requests before `initialize` and after
/// `shutdown` are refused, as the protocol asks.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Phase {
    Uninitialised,
    Running,
    ShutDown,
}

fn serve<R: BufRead, W: Write>(t: &mut Transport<R, W>) -> Result<ExitCode, WireError> {
    let mut phase = Phase::Uninitialised;
    let mut docs = Documents::default();
    while let Some(incoming) = t.read()? {
        let message = match incoming {
            Incoming::Invalid(error) => {
                t.write_value(&error)?;
                continue;
            }
            Incoming::Message(message) => message,
        };
        match message {
            Message::Request(req) => {
                let response = match (phase, req.method.as_str()) {
                    (Phase::Uninitialised, "initialize") => {
                        phase = Phase::Running;
                        Response::new_ok(req.id, initialize_result())
                    }
                    (Phase::Uninitialised, _) => Response::new_err(
                        req.id,
                        ErrorCode::ServerNotInitialized as i32,
                        "the server is not initialised: send `initialize` first".into(),
                    ),
                    (Phase::Running, "shutdown") => {
                        phase = Phase::ShutDown;
                        Response::new_ok(req.id, serde_json::Value::Null)
                    }
                    (Phase::Running, "initialize") => Response::new_err(
                        req.id,
                        ErrorCode::InvalidRequest as i32,
                        "`initialize` was already received".into(),
                    ),
                    (Phase::Running, _) => guarded_request(&docs, req),
                    (Phase::ShutDown, _) => Response::new_err(
                        req.id,
                        ErrorCode::InvalidRequest as i32,
                        "the server is shutting down: only `exit` is accepted".into(),
                    ),
                };
                t.write(Message::Response(response))?;
            }
            Message::Notification(note) if note.method == "exit" => {
                return Ok(if phase == Phase::ShutDown {
                    ExitCode::SUCCESS
                } else {
                    ExitCode::FAILURE
                });
            }
            Message::Notification(note) => {
                if phase != Phase::Running {
                    continue;
                }
                let applied = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    handle_notification(&mut docs, note)
                }));
                match applied {
                    Ok(Some(uri)) => publish(t, &docs, &uri)?,
                    Ok(None) => {}
                    Err(_) => {
                        diagln!("hscene lsp: a notification failed (a bug); the server goes on")
                    }
                }
            }
            Message::Response(_) => {}
        }
    }
    Ok(ExitCode::SUCCESS)
}

fn initialize_result() -> serde_json::Value {
    let init = InitializeResult {
        capabilities: capabilities(),
        server_info: Some(ServerInfo {
            name: "hscene".into(),
            version: Some(env!("CARGO_PKG_VERSION").into()),
        }),
    };
    serde_json::to_value(init).unwrap_or(serde_json::Value::Null)
}

/// Answers a request; a bug that panics while answering becomes an
/// `InternalError` answer instead of the end of the server.
fn guarded_request(docs: &Documents, req: Request) -> Response {
    let id = req.id.clone();
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| handle_request(docs, req)))
        .unwrap_or_else(|_| {
            Response::new_err(
                id,
                ErrorCode::InternalError as i32,
                "the server failed on this request (a bug); it goes on".into(),
            )
        })
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

fn publish<R: BufRead, W: Write>(
    t: &mut Transport<R, W>,
    docs: &Documents,
    uri: &lsp_types::Uri,
) -> Result<(), WireError> {
    let Some(doc) = docs.get(uri) else {
        return Ok(());
    };
    let params = PublishDiagnosticsParams {
        uri: uri.clone(),
        diagnostics: diagnostics::to_lsp(uri, doc),
        version: Some(doc.version),
    };
    t.write(Message::Notification(Notification::new(
        PublishDiagnostics::METHOD.into(),
        params,
    )))
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
