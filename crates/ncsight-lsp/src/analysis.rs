//! The engine run for a document: `check`'s diagnostics (cancelled when a newer text comes), and
//! for hover the modal state, position and time before and after a block.

use crate::config::RunConfig;
use crate::text::{Encoding, Lines};
use lsp_types::{Diagnostic as LspDiagnostic, DiagnosticSeverity, NumberOrString};
use ncsight::{Event, Mode, Severity};
use ncsight_io::feed::{self, Input};
use ncsight_io::Job;
use std::sync::Arc;

/// The job of a configuration (machine, parameters, setup, subprogramme folders).
pub fn job_of(cfg: &RunConfig) -> Result<Job, String> {
    let mut job =
        Job { params: cfg.params.clone(), subprogram_dirs: cfg.subprogram_dirs.iter().filter(|d| d.is_dir()).cloned().collect(), ..Job::on(&cfg.machine) };
    if let Some(setup) = &cfg.setup {
        job.read_setup(&setup.to_string_lossy()).map_err(|e| e.to_string())?;
    }
    job.profile().map_err(|e| e.to_string())?;
    Ok(job)
}

/// Why a check did not finish.
pub enum Stopped {
    /// A newer text came: nothing to publish.
    Cancelled,
    /// The configuration is wrong (an unknown machine, a bad setup): said on the first line.
    Usage(String),
}

/// Every diagnostic `ncsight check` gives for `text`, as the client shows them. `cancelled` is
/// asked every few hundred events; when it says yes the check stops.
pub fn check(cfg: &RunConfig, text: &Arc<Vec<u8>>, enc: Encoding, cancelled: &dyn Fn() -> bool) -> Result<Vec<LspDiagnostic>, Stopped> {
    let job = job_of(cfg).map_err(Stopped::Usage)?;
    let (mut program, mut library) = job.program(Mode::Check).map_err(|e| Stopped::Usage(e.to_string()))?;
    let source = String::from_utf8_lossy(text);
    let lines = Lines::new(&source);
    let mut out = Vec::new();
    let mut seen = 0u32;
    let result = feed::drive(Input::Memory(text.clone()), &mut library, &mut program, &mut |e, _, file| {
        seen = seen.wrapping_add(1);
        if seen % 256 == 0 && cancelled() {
            return Err(std::io::Error::other("cancelled"));
        }
        if let Event::Diagnostic(d) = e {
            if out.len() < MAX_DIAGNOSTICS {
                out.push(to_lsp(d, file, &lines, enc));
            }
        }
        Ok(())
    });
    match result {
        Err(_) if cancelled() => Err(Stopped::Cancelled),
        Err(e) => Err(Stopped::Usage(e.to_string())),
        Ok(()) => Ok(out),
    }
}

/// Diagnostics a document shows at most (a programme with more says so in the last).
pub const MAX_DIAGNOSTICS: usize = 10_000;

/// One of the engine's diagnostics as the client shows it: at its word (or, raised in a
/// subprogramme of another file, at the call in this document), its code as `check --format
/// jsonl` gives it, the controller's title and what it means.
pub fn to_lsp(d: &ncsight::Diagnostic, file: Option<&str>, lines: &Lines, enc: Encoding) -> LspDiagnostic {
    let (line, from, to, place) = match (d.span.file, d.calls.first()) {
        (0, _) => (d.span.line, d.span.col, d.span.col + u32::from(d.span.len.max(1)), String::new()),
        (_, Some(call)) => {
            (call.line, call.col, call.col + u32::from(call.len.max(1)), format!(" (in {} line {}, called here)", file.unwrap_or("another file"), d.span.line))
        }
        (_, None) => (1, 1, 2, format!(" (in {} line {})", file.unwrap_or("another file"), d.span.line)),
    };
    let n = line.saturating_sub(1) as usize;
    let mut message = format!("{}{place}", d.message);
    if let Some(h) = &d.hint {
        message.push_str(&format!("\nhint: {h}"));
    }
    message.push_str(&format!("\n{}", d.rule.title()));
    if let Some(meaning) = crate::explain::meaning_en(d.rule.project_code()) {
        message.push_str(&format!(": {meaning}"));
    }
    LspDiagnostic {
        range: lines.range(n, from.saturating_sub(1) as usize, to.saturating_sub(1) as usize, enc),
        severity: Some(if d.severity() == Severity::Alarm { DiagnosticSeverity::ERROR } else { DiagnosticSeverity::WARNING }),
        code: Some(NumberOrString::String(d.code.to_string())),
        source: Some("ncsight".into()),
        message,
        ..LspDiagnostic::default()
    }
}

/// A usage mistake (an unknown machine, a bad `ncsight.toml` or setup) on the first line.
pub fn usage_diagnostic(message: &str) -> LspDiagnostic {
    LspDiagnostic {
        range: lsp_types::Range::default(),
        severity: Some(DiagnosticSeverity::ERROR),
        code: Some(NumberOrString::String("usage".into())),
        source: Some("ncsight".into()),
        message: message.to_string(),
        ..LspDiagnostic::default()
    }
}

/// Blocks run again after jumps back (a loop) that hover and the time hints follow at most: they
/// answer on the message loop, so a programme that loops stops them early (the state shown is
/// then as far as that; `check`'s diagnostics keep the command line's limit).
pub const EDITOR_MAX_BLOCKS: u64 = 20_000;

/// What the machine is like before and after a block, for hover.
#[derive(Debug, Clone, Default)]
pub struct BlockState {
    pub before: Option<ncsight::modal::Modal>,
    pub after_pos: Option<ncsight::Vec3>,
    /// Seconds from the start to the block's start, and the block's own.
    pub t_before_s: f64,
    pub t_block_s: f64,
    pub lathe: bool,
}

/// Run the programme up to line `line` (1-based) and through it: the modal state before it, the
/// time so far and the block's. Read as the text goes, to that line (a jump back from later in
/// the programme is not followed: the hover says "as read to this line").
pub fn state_at(cfg: &RunConfig, text: &[u8], line: u32) -> Result<BlockState, String> {
    let mut job = job_of(cfg)?;
    job.max_blocks = Some(EDITOR_MAX_BLOCKS);
    let lathe = job.profile().map_err(|e| e.to_string())?.is_lathe();
    let cut = |n: u32| -> &[u8] {
        let mut at = 0;
        for _ in 1..n {
            match text[at..].iter().position(|&b| b == b'\n') {
                Some(i) => at += i + 1,
                None => return text,
            }
        }
        &text[..at]
    };
    let run = |upto: &[u8]| -> Result<(ncsight::modal::Modal, f64), String> {
        let (program, _) = job.program(Mode::Run).map_err(|e| e.to_string())?;
        let mut events = ncsight::events(program, upto);
        let mut t = 0.0f64;
        for e in events.by_ref() {
            if let Event::Record(r) = e {
                t = t.max(r.t_s);
            }
        }
        Ok((*events.program().interpreter().state(), t))
    };
    let (before, t0) = run(cut(line))?;
    let (after, t1) = run(cut(line + 1))?;
    Ok(BlockState { before: Some(before), after_pos: Some(after.place.pos), t_before_s: t0, t_block_s: (t1 - t0).max(0.0), lathe })
}

/// The time each line of the text takes when the programme runs (seconds, by the line of the
/// records; a subprogramme's lines in another file are not this text's), for the time hints.
pub fn time_by_line(cfg: &RunConfig, text: &Arc<Vec<u8>>, line_count: usize) -> Result<Vec<f32>, String> {
    let mut job = job_of(cfg)?;
    job.max_blocks = Some(EDITOR_MAX_BLOCKS);
    let (mut program, mut library) = job.program(Mode::Run).map_err(|e| e.to_string())?;
    let mut times = vec![0f32; line_count];
    let mut t_before = 0.0f64;
    let _ = feed::drive(Input::Memory(text.clone()), &mut library, &mut program, &mut |e, _, _| {
        if let Event::Record(r) = e {
            let took = (r.t_s - t_before).max(0.0);
            t_before = t_before.max(r.t_s);
            let line = (r.span.file == 0).then_some(r.span.line);
            if let Some(slot) = line.and_then(|l| times.get_mut(l.saturating_sub(1) as usize)) {
                *slot += took as f32;
            }
        }
        Ok(())
    });
    Ok(times)
}
