//! `ncsight lsp`: a Language Server Protocol server on standard input and output, over the same
//! engine as `ncsight check` (docs/editors.md). A thin layer: the engine knows nothing of it.
//!
//! Built on `lsp-server` (rust-analyzer's scaffold): the engine is synchronous, so a plain
//! message loop and one checking thread serve, with no async runtime. Checks are debounced and a
//! newer text cancels an older check; hover, definitions and the outline are answered at once.

mod analysis;
mod config;
mod explain;
mod hover;
mod navigate;
mod server;
pub mod text;

pub use config::{for_document, RunConfig, CONFIG_FILE};

use lsp_server::{Connection, Message};
use lsp_types::{
    HoverProviderCapability, InitializeParams, OneOf, PositionEncodingKind, ServerCapabilities, ServerInfo, TextDocumentSyncCapability, TextDocumentSyncKind,
    TextDocumentSyncOptions, TextDocumentSyncSaveOptions,
};
use text::Encoding;

/// Serve one client on standard input and output until it says exit.
pub fn run_stdio() -> Result<(), String> {
    let (connection, io_threads) = Connection::stdio();
    serve(&connection)?;
    drop(connection);
    io_threads.join().map_err(|e| format!("the client's stream: {e}"))
}

/// Serve one client on `connection` (its initialize, then every message until shutdown).
pub fn serve(connection: &Connection) -> Result<(), String> {
    let (id, params) = connection.initialize_start().map_err(|e| e.to_string())?;
    let init: InitializeParams = serde_json::from_value(params).map_err(|e| format!("initialize: {e}"))?;
    // UTF-8 columns when the client can count them (LSP 3.17), else UTF-16 as the protocol says.
    let utf8 = init.capabilities.general.as_ref().and_then(|g| g.position_encodings.as_ref()).is_some_and(|e| e.contains(&PositionEncodingKind::UTF8));
    let enc = if utf8 { Encoding::Utf8 } else { Encoding::Utf16 };
    let setting = init.initialization_options.as_ref().and_then(server::machine_setting);
    let result = lsp_types::InitializeResult {
        capabilities: capabilities(enc),
        server_info: Some(ServerInfo { name: "ncsight".into(), version: Some(env!("CARGO_PKG_VERSION").into()) }),
    };
    connection.initialize_finish(id, serde_json::to_value(result).map_err(|e| e.to_string())?).map_err(|e| e.to_string())?;
    let (mut server, worker) = server::Server::new(connection.sender.clone(), enc, setting);
    for message in &connection.receiver {
        match message {
            Message::Request(r) => {
                if connection.handle_shutdown(&r).map_err(|e| e.to_string())? {
                    break;
                }
                server.on_request(r);
            }
            Message::Notification(n) => server.on_notification(n),
            Message::Response(_) => {}
        }
    }
    drop(server);
    worker.join().map_err(|_| "the checking thread failed".to_string())
}

fn capabilities(enc: Encoding) -> ServerCapabilities {
    ServerCapabilities {
        position_encoding: Some(if enc == Encoding::Utf8 { PositionEncodingKind::UTF8 } else { PositionEncodingKind::UTF16 }),
        text_document_sync: Some(TextDocumentSyncCapability::Options(TextDocumentSyncOptions {
            open_close: Some(true),
            change: Some(TextDocumentSyncKind::INCREMENTAL),
            save: Some(TextDocumentSyncSaveOptions::Supported(true)),
            ..TextDocumentSyncOptions::default()
        })),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        inlay_hint_provider: Some(OneOf::Left(true)),
        ..ServerCapabilities::default()
    }
}
