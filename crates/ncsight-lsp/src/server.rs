//! The message loop: documents as the client edits them, checks on a worker thread (debounced,
//! a newer text cancelling an older check), and the answers to hover, definition, references
//! and the outline.

use crate::analysis::{self, Stopped};
use crate::config::{self, RunConfig};
use crate::navigate::{self, Target};
use crate::text::{self, Encoding, Lines};
use crossbeam_channel::Sender;
use lsp_server::{Message, Notification, Request, RequestId, Response};
use lsp_types::notification::{self as note, Notification as _};
use lsp_types::request::{self as req, Request as _};
use lsp_types::{GotoDefinitionResponse, Hover, HoverContents, Location, MarkupContent, MarkupKind, PublishDiagnosticsParams, Url};
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::{mpsc, Arc, Mutex};
use std::time::Duration;

/// How long after the last edit a check starts (an edit within it starts the wait again).
pub const DEBOUNCE: Duration = Duration::from_millis(150);

struct Doc {
    text: String,
    version: i32,
    /// Seconds each line takes, for the time hints, worked out once per version.
    times: Option<(i32, Arc<Vec<f32>>)>,
}

struct CheckJob {
    uri: Url,
    version: i32,
    text: Arc<Vec<u8>>,
    cfg: RunConfig,
    generation: u64,
    /// An edit waits [`DEBOUNCE`]; an opened document is checked at once.
    wait: bool,
}

type Latest = Arc<Mutex<HashMap<Url, u64>>>;

pub struct Server {
    docs: HashMap<Url, Doc>,
    enc: Encoding,
    /// The client's `ncsight.machine`.
    setting: Option<String>,
    checks: mpsc::Sender<CheckJob>,
    /// The newest check asked for each document: an older one still running stops.
    latest: Latest,
    generation: u64,
    out: Sender<Message>,
}

impl Server {
    /// The server and its checking thread (which ends when the server is dropped).
    pub fn new(out: Sender<Message>, enc: Encoding, setting: Option<String>) -> (Server, std::thread::JoinHandle<()>) {
        let (checks, jobs) = mpsc::channel();
        let latest: Latest = Arc::default();
        let (worker_latest, worker_out) = (latest.clone(), out.clone());
        let worker = std::thread::Builder::new()
            .name("ncsight-check".into())
            .spawn(move || check_worker(jobs, worker_latest, worker_out, enc))
            .expect("the checking thread starts");
        (Server { docs: HashMap::new(), enc, setting, checks, latest, generation: 0, out }, worker)
    }

    fn path_of(uri: &Url) -> Option<PathBuf> {
        (uri.scheme() == "file").then(|| uri.to_file_path().ok()).flatten()
    }

    fn config_of(&self, uri: &Url, text: &str) -> RunConfig {
        config::for_document(Self::path_of(uri).as_deref(), text.as_bytes(), self.setting.as_deref())
    }

    /// Ask for a check of the document's current text.
    fn schedule(&mut self, uri: &Url, wait: bool) {
        let Some(doc) = self.docs.get(uri) else { return };
        self.generation += 1;
        self.latest.lock().unwrap_or_else(|e| e.into_inner()).insert(uri.clone(), self.generation);
        let cfg = self.config_of(uri, &doc.text);
        let job = CheckJob { uri: uri.clone(), version: doc.version, text: Arc::new(doc.text.clone().into_bytes()), cfg, generation: self.generation, wait };
        let _ = self.checks.send(job);
    }

    pub fn on_notification(&mut self, n: Notification) {
        match n.method.as_str() {
            note::DidOpenTextDocument::METHOD => {
                let Ok(p) = serde_json::from_value::<lsp_types::DidOpenTextDocumentParams>(n.params) else { return };
                let uri = p.text_document.uri;
                self.docs.insert(uri.clone(), Doc { text: p.text_document.text, version: p.text_document.version, times: None });
                self.schedule(&uri, false);
            }
            note::DidChangeTextDocument::METHOD => {
                let Ok(p) = serde_json::from_value::<lsp_types::DidChangeTextDocumentParams>(n.params) else { return };
                let uri = p.text_document.uri;
                let Some(doc) = self.docs.get_mut(&uri) else { return };
                for c in p.content_changes {
                    text::apply_change(&mut doc.text, c.range, &c.text, self.enc);
                }
                doc.version = p.text_document.version;
                self.schedule(&uri, true);
            }
            note::DidSaveTextDocument::METHOD => {
                // The folder's files may have changed with it (a subprogramme saved).
                let uris: Vec<Url> = self.docs.keys().cloned().collect();
                uris.iter().for_each(|u| self.schedule(u, true));
            }
            note::DidCloseTextDocument::METHOD => {
                let Ok(p) = serde_json::from_value::<lsp_types::DidCloseTextDocumentParams>(n.params) else { return };
                self.docs.remove(&p.text_document.uri);
                self.latest.lock().unwrap_or_else(|e| e.into_inner()).remove(&p.text_document.uri);
                publish(&self.out, p.text_document.uri, Vec::new(), None);
            }
            note::DidChangeConfiguration::METHOD => {
                if let Ok(p) = serde_json::from_value::<lsp_types::DidChangeConfigurationParams>(n.params) {
                    self.setting = machine_setting(&p.settings).or(self.setting.take());
                }
                let uris: Vec<Url> = self.docs.keys().cloned().collect();
                uris.iter().for_each(|u| self.schedule(u, false));
            }
            _ => {}
        }
    }

    pub fn on_request(&mut self, r: Request) {
        let id = r.id.clone();
        let result = match r.method.as_str() {
            // (`&mut self` for the time hints' cache; the others only read.)
            req::HoverRequest::METHOD => self.hover(r.params).map(|h| serde_json::to_value(h).unwrap_or_default()),
            req::GotoDefinition::METHOD => self.definition(r.params).map(|d| serde_json::to_value(d).unwrap_or_default()),
            req::References::METHOD => self.references(r.params).map(|d| serde_json::to_value(d).unwrap_or_default()),
            req::DocumentSymbolRequest::METHOD => self.symbols(r.params).map(|d| serde_json::to_value(d).unwrap_or_default()),
            req::InlayHintRequest::METHOD => self.inlay_hints(r.params).map(|d| serde_json::to_value(d).unwrap_or_default()),
            _ => {
                let _ = self.out.send(Message::Response(Response::new_err(
                    id,
                    lsp_server::ErrorCode::MethodNotFound as i32,
                    format!("{} is not offered", r.method),
                )));
                return;
            }
        };
        self.respond(id, result.unwrap_or(serde_json::Value::Null));
    }

    fn respond(&self, id: RequestId, value: serde_json::Value) {
        let _ = self.out.send(Message::Response(Response::new_ok(id, value)));
    }

    /// The document and the line and byte column of a position request.
    fn at(&self, params: serde_json::Value) -> Option<(Url, usize, usize)> {
        let p: lsp_types::TextDocumentPositionParams = serde_json::from_value(params).ok()?;
        let doc = self.docs.get(&p.text_document.uri)?;
        let lines = Lines::new(&doc.text);
        let line = p.position.line as usize;
        let col = text::byte_col(lines.line(line), p.position.character, self.enc);
        Some((p.text_document.uri, line, col))
    }

    fn hover(&self, params: serde_json::Value) -> Option<Hover> {
        let (uri, n, col) = self.at(params)?;
        let doc = self.docs.get(&uri)?;
        let cfg = self.config_of(&uri, &doc.text);
        let lines = Lines::new(&doc.text);
        let state = analysis::state_at(&cfg, doc.text.as_bytes(), n as u32 + 1).ok();
        let value = crate::hover::hover(&lines, n, col, &cfg, state.as_ref())?;
        Some(Hover { contents: HoverContents::Markup(MarkupContent { kind: MarkupKind::Markdown, value }), range: None })
    }

    fn target(&self, uri: &Url, n: usize, col: usize) -> Option<(Target, RunConfig)> {
        let doc = self.docs.get(uri)?;
        let cfg = self.config_of(uri, &doc.text);
        let lathe = ncsight::profile::by_name(&cfg.machine).is_some_and(|p| p.is_lathe());
        let lines = Lines::new(&doc.text);
        let words = text::words(lines.line(n));
        let w = text::word_at(&words, col)?;
        Some((navigate::target_of(w, &words, &cfg.machine, lathe)?, cfg))
    }

    fn definition(&self, params: serde_json::Value) -> Option<GotoDefinitionResponse> {
        let (uri, n, col) = self.at(params)?;
        let (t, cfg) = self.target(&uri, n, col)?;
        let doc = self.docs.get(&uri)?;
        let lines = Lines::new(&doc.text);
        if let Some((k, a, b)) = navigate::find_in(&lines, t, n) {
            return Some(GotoDefinitionResponse::Scalar(Location { uri, range: lines.range(k, a, b, self.enc) }));
        }
        let Target::Programme(number) = t else { return None };
        let here = Self::path_of(&uri);
        let (file, k, a, b) = navigate::find_programme_file(&cfg.subprogram_dirs, number, here.as_deref())?;
        // The other file's columns: read as its own text (UTF-8, else each byte as a character).
        let other = std::fs::read(&file).ok()?;
        let other = String::from_utf8_lossy(&other);
        let range = Lines::new(&other).range(k, a, b, self.enc);
        navigate::location(&file, range).map(GotoDefinitionResponse::Scalar)
    }

    fn references(&self, params: serde_json::Value) -> Option<Vec<Location>> {
        let p: lsp_types::ReferenceParams = serde_json::from_value(params).ok()?;
        let pos = serde_json::to_value(p.text_document_position).ok()?;
        let (uri, n, col) = self.at(pos)?;
        let (t, cfg) = self.target(&uri, n, col)?;
        let doc = self.docs.get(&uri)?;
        let lines = Lines::new(&doc.text);
        let lathe = ncsight::profile::by_name(&cfg.machine).is_some_and(|p| p.is_lathe());
        let mut out: Vec<Location> = navigate::references(&lines, t, &cfg.machine, lathe)
            .into_iter()
            .map(|(k, a, b)| Location { uri: uri.clone(), range: lines.range(k, a, b, self.enc) })
            .collect();
        if p.context.include_declaration {
            if let Some((k, a, b)) = navigate::find_in(&lines, t, n) {
                out.insert(0, Location { uri: uri.clone(), range: lines.range(k, a, b, self.enc) });
            }
        }
        Some(out)
    }

    /// The time each block takes, at the end of its line (blocks of a tenth of a second or more).
    fn inlay_hints(&mut self, params: serde_json::Value) -> Option<Vec<lsp_types::InlayHint>> {
        let p: lsp_types::InlayHintParams = serde_json::from_value(params).ok()?;
        let uri = p.text_document.uri;
        let doc = self.docs.get(&uri)?;
        let times = match &doc.times {
            Some((v, t)) if *v == doc.version => t.clone(),
            _ => {
                let cfg = self.config_of(&uri, &doc.text);
                let count = Lines::new(&doc.text).count();
                let t = Arc::new(analysis::time_by_line(&cfg, &Arc::new(doc.text.clone().into_bytes()), count).ok()?);
                let version = doc.version;
                self.docs.get_mut(&uri)?.times = Some((version, t.clone()));
                t
            }
        };
        let doc = self.docs.get(&uri)?;
        let lines = Lines::new(&doc.text);
        let (from, to) = (p.range.start.line as usize, (p.range.end.line as usize).min(lines.count().saturating_sub(1)));
        let hints = (from..=to)
            .filter(|&k| times.get(k).is_some_and(|&t| t >= 0.1))
            .map(|k| lsp_types::InlayHint {
                position: lines.position(k, lines.line(k).len(), self.enc),
                label: lsp_types::InlayHintLabel::String(crate::hover::hms(f64::from(times[k]))),
                kind: None,
                text_edits: None,
                tooltip: Some(lsp_types::InlayHintTooltip::String("time of this block (h:mm:ss.s) as ncsight runs it on this controller".into())),
                padding_left: Some(true),
                padding_right: None,
                data: None,
            })
            .collect();
        Some(hints)
    }

    fn symbols(&self, params: serde_json::Value) -> Option<lsp_types::DocumentSymbolResponse> {
        let p: lsp_types::DocumentSymbolParams = serde_json::from_value(params).ok()?;
        let doc = self.docs.get(&p.text_document.uri)?;
        let cfg = self.config_of(&p.text_document.uri, &doc.text);
        let lathe = ncsight::profile::by_name(&cfg.machine).is_some_and(|p| p.is_lathe());
        Some(lsp_types::DocumentSymbolResponse::Nested(navigate::symbols(&Lines::new(&doc.text), self.enc, &cfg.machine, lathe)))
    }
}

/// `ncsight.machine` from the client's settings (`{"ncsight": {"machine": ...}}` or
/// `{"machine": ...}`).
pub fn machine_setting(v: &serde_json::Value) -> Option<String> {
    let m = v.get("ncsight").and_then(|n| n.get("machine")).or_else(|| v.get("machine"))?;
    m.as_str().map(str::to_string)
}

fn publish(out: &Sender<Message>, uri: Url, diagnostics: Vec<lsp_types::Diagnostic>, version: Option<i32>) {
    let params = PublishDiagnosticsParams { uri, diagnostics, version };
    let _ = out.send(Message::Notification(Notification::new(note::PublishDiagnostics::METHOD.to_string(), params)));
}

/// The checking thread: takes the newest job of each document once edits pause, checks it
/// (stopping when a newer one comes) and publishes what it finds.
fn check_worker(jobs: mpsc::Receiver<CheckJob>, latest: Latest, out: Sender<Message>, enc: Encoding) {
    let is_latest = |uri: &Url, g: u64| latest.lock().unwrap_or_else(|e| e.into_inner()).get(uri) == Some(&g);
    while let Ok(first) = jobs.recv() {
        let mut waiting: HashMap<Url, CheckJob> = HashMap::new();
        let mut wait = first.wait;
        waiting.insert(first.uri.clone(), first);
        // Take what else came; wait while edits keep coming.
        loop {
            let next = if wait { jobs.recv_timeout(DEBOUNCE).ok() } else { jobs.try_recv().ok() };
            match next {
                Some(j) => {
                    wait = j.wait;
                    waiting.insert(j.uri.clone(), j);
                }
                None => break,
            }
        }
        for (uri, job) in waiting {
            if !is_latest(&uri, job.generation) {
                continue;
            }
            let mut diagnostics = job.cfg.problem.as_deref().map(analysis::usage_diagnostic).into_iter().collect::<Vec<_>>();
            match analysis::check(&job.cfg, &job.text, enc, &|| !is_latest(&uri, job.generation)) {
                Ok(found) => diagnostics.extend(found),
                Err(Stopped::Cancelled) => continue,
                Err(Stopped::Usage(m)) => diagnostics.push(analysis::usage_diagnostic(&m)),
            }
            publish(&out, uri, diagnostics, Some(job.version));
        }
    }
}
