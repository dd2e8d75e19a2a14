//! A programme run: lines in, events out, one line at a time, so that nothing holds the
//! programme or its motion in memory. The caller owns all I/O.
//!
//! Two modes, as the interface specifies:
//! - `Mode::Run` stops at the first alarm, exactly as the controller does (the alarm is the last
//!   event), and stops reading at the programme end.
//! - `Mode::Check` reports every problem: a block that alarms is left out (the modal state stays as
//!   it was) and reading goes on; blocks after the programme end are still read for their syntax,
//!   up to the `%` that closes the record (after it nothing is read unless a call finds a
//!   programme there).

mod calls;
mod macros;

use crate::alarm::{Diagnostic, Rule};
use crate::dialect::Foreign;
use crate::interp::{Flow, Interpreter, Outcome, Switches};
use crate::machine::{Machine, Options};
use crate::motion::{Op, Record};
use crate::profile::Params;
use crate::read::{Block, Line, Reader, Word};
use crate::read::{Stmt, Then};
use crate::source::Span;
use calls::{Calls, Frame, Loop, Search, Target};
pub use calls::{Place, Request};

/// Blocks executed again after a jump back (a subprogramme's second run, a loop) before a run
/// is taken for one that never ends, unless the caller sets another limit.
pub const MAX_REPEATED_BLOCKS: u64 = 5_000_000;

/// How a run treats programmes that call programmes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CallOptions {
    /// The main programme's O number, when it is not the first programme of the text.
    pub main: Option<u32>,
    /// A called programme that no file holds is skipped with a warning instead of the
    /// controller's alarm (builder macros live in the machine, not the file).
    pub skip_missing: bool,
    /// The runaway guard: blocks executed again after jumps back, at most.
    pub max_repeated_blocks: u64,
}

impl Default for CallOptions {
    fn default() -> CallOptions {
        CallOptions { main: None, skip_missing: false, max_repeated_blocks: MAX_REPEATED_BLOCKS }
    }
}

/// How many "length without a decimal point" warnings (NCS-W02) are shown one by one; the rest
/// are summed up in one warning at the end.
pub const INCREMENT_WARNINGS_SHOWN: u32 = 3;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    Run,
    Check,
}

pub use crate::event::Event;

/// How the run ended (so far).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Still reading.
    Running,
    /// M02/M30 (or M99 in a main programme) was executed.
    Ended,
    /// Stopped on an alarm (run mode).
    Alarm,
}

pub struct Program {
    core: Core,
    machine: Machine,
    /// The block a batch's packed blocks are set into, one after the other.
    block: Block,
}

/// Everything but the operator machine: reading and interpreting, with buffers reused from line
/// to line so that the steady state allocates nothing.
struct Core {
    /// The programme runs as a macro called with arguments (`--call-args`): its M99 is the
    /// return to that call, the end of the run.
    run_as_called: bool,
    reader: LineReader,
    interp: Interpreter,
    mode: Mode,
    line_no: u32,
    status: Status,
    eof: bool,
    warned_after_end: bool,
    alarms: usize,
    /// Span of the last block read (for the end-of-input warning).
    last_span: Span,
    /// NCS-W02 warnings passed on so far; past [`INCREMENT_WARNINGS_SHOWN`] they are counted
    /// and summed up at the end.
    increment_warnings: u32,
    read: ReadLine,
    outcome: Outcome,
    /// The file of the line being interpreted, the byte offsets where it and the next line
    /// begin, and the place on it of the next block.
    file: u16,
    line_offset: u64,
    next_offset: u64,
    block_index: u16,
    /// Blocks of the line before this one are passed over (a jump into the middle of a line);
    /// `skip_next` is for the first line after a jump.
    skip_to: u16,
    skip_next: u16,
    /// The line is read again (after a jump back).
    again: bool,
    /// A search reads the line again.
    searched_again: bool,
    /// No jump or search yet: lines run in order from the start, up to `linear_end`.
    linear: bool,
    linear_end: u64,
    reported: Reported,
    /// The sequence number of the block being executed (for its records).
    block_n: Option<u32>,
    /// A block has been executed (before the main programme's first O, if any).
    executed_any: bool,
    calls: Calls,
    call_options: CallOptions,
    /// Custom macro B: the variables, the block a macro block's words are evaluated into, the
    /// machine time (for #3001/#3002) and the last sequence number read (#4114).
    vars: macros::Variables,
    evaluated: Block,
    clock_s: f64,
    last_n: Option<u32>,
    /// G66 in force: the macro called after each block with a move.
    modal_call: Option<ModalCall>,
    /// Codes that call the machine's macros, by parameter: (letter, code, programme, as G65).
    builder_codes: Vec<(u8, u32, u32, bool)>,
    /// Some G or M code calls a macro of the machine's (parameters, or the profile's M9000
    /// range): every block's G and M words are looked at.
    builders: bool,
    /// Single block is on and the parameters make it stop after macro statements too.
    statement_stops: bool,
    /// The last alarm told (its place and code), so one met twice in a row is told once.
    last_alarm: Option<(Span, &'static str)>,
    /// The next call is made by such a code.
    builder_call: bool,
    /// The first lines of the main file are the tape leader (before the opening `%`): not read.
    leader_lines: u32,
}

/// A G66 modal call: the macro, its count and arguments, the call depth it was given at.
#[derive(Debug, Clone, Copy)]
struct ModalCall {
    number: u32,
    count: u32,
    locals: macros::Locals,
    depth: usize,
    span: Span,
}

/// One line read, not yet interpreted: the reader's blocks and the look for another control's
/// language.
#[derive(Debug, Default)]
struct ReadLine {
    line_no: u32,
    line: Line,
    foreign: Option<Foreign>,
    /// The line's length in bytes (for the span of a foreign-language answer).
    len: usize,
}

/// Reads lines for a [`Program`]; cheap to clone and to send to a thread. Reading needs nothing
/// of the modal state, so a caller may read lines on one thread into a [`ReadBatch`] while the
/// programme interprets earlier ones on another (the command line does).
#[derive(Debug, Clone)]
pub struct LineReader {
    reader: Reader,
}

impl LineReader {
    /// The programme numbers (O blocks) on one line, in order: what a driver looks for in
    /// its other files when a called programme is not in the text.
    pub fn program_numbers(&self, raw: &[u8], out: &mut Vec<u32>) {
        // Only lines with an O or ':' can hold one.
        if !raw.iter().any(|b| matches!(b, b'O' | b'o' | b':')) {
            return;
        }
        let mut line = Line::default();
        self.reader.read_line_into(1, raw, &mut line);
        out.extend(line.blocks.iter().filter_map(|b| b.as_ref().ok().and_then(|b| b.program)));
    }

    /// Read line `line_no` (1-based, with or without its line break) into `out`, reusing its
    /// allocations.
    fn read(&self, line_no: u32, raw: &[u8], out: &mut ReadLine) {
        out.line_no = line_no;
        out.len = raw.len();
        // Another control's programme gets one answer, not a cascade of alarms (issue 10). Its
        // signs come early or carry `$ @ = <`; only such lines are looked at.
        out.foreign = None;
        let marks = crate::read::ByteMarks::of(raw);
        if line_no <= 100 || marks.has(crate::read::ByteMarks::FOREIGN) {
            out.foreign = crate::dialect::sniff(raw);
        }
        if out.foreign.is_none() {
            self.reader.read_marked_line_into(line_no, raw, marks, &mut out.line);
        }
    }
}

/// Looks at the first lines of a file for a tape leader. In the tape format the text before
/// the first `%` (the tape start) is the leader and is not read (FANUC 0i operator's manual,
/// programme configuration; assumed for the GSK and YASNAC profiles as well). A file whose
/// first lines are programme blocks has no leader: a `%` after them closes the record
/// (docs/reference/macro.md section 1). So lines before the first `%` are the leader only when none of them
/// reads as a block or starts as one (`G0 X1,5` is a programme with a mistake, not a title), and
/// at least one is text that is not a comment (a title, a CAM banner) or a punched tape's
/// blank leader (NUL or DEL bytes, also before the `%` on its line).
/// The scan is bounded: past [`LEADER_SCAN_BYTES`] without a `%` there is no leader.
#[derive(Debug, Clone)]
pub struct LeaderScan {
    reader: LineReader,
    lines: u32,
    text: bool,
    bytes: usize,
    decided: Option<u32>,
}

/// How far into a file a tape leader is looked for.
pub const LEADER_SCAN_BYTES: usize = 1 << 16;

impl LeaderScan {
    /// The next line (with or without its break). Whether the answer is known: no more lines
    /// are needed.
    pub fn push(&mut self, raw: &[u8]) -> bool {
        if self.decided.is_some() {
            return true;
        }
        self.bytes += raw.len();
        // Blanks, and the NUL and DEL bytes of a punched tape's blank leader.
        let blank = |b: &u8| matches!(b, b' ' | b'\t' | b'\r' | b'\n' | 0 | 0x7f);
        let t = raw.iter().position(|b| !blank(b)).unwrap_or(raw.len());
        let body = &raw[t..];
        if body.first() == Some(&b'%') {
            // Tape bytes before the `%` on its own line make that line part of the leader.
            let tape_bytes = raw[..t].iter().any(|b| matches!(b, 0 | 0x7f));
            self.decided = Some(if self.text || tape_bytes { self.lines + u32::from(tape_bytes) } else { 0 });
            return true;
        }
        self.lines += 1;
        if body.is_empty() {
            self.text |= raw.iter().any(|b| matches!(b, 0 | 0x7f));
            return self.bytes >= LEADER_SCAN_BYTES && self.decide_none();
        }
        // A line that starts as a block does (an address with a number, `/`, `:`) is a
        // programme, even one with a mistake in it (`G0 X1,5`): no leader.
        let code_like = match body {
            [b'/' | b':', ..] => true,
            [l, n, ..] if l.is_ascii_alphabetic() => matches!(n, b'0'..=b'9' | b'-' | b'+' | b'.' | b'#' | b'[' | b' '),
            _ => false,
        };
        if code_like {
            return self.decide_none();
        }
        if crate::dialect::sniff(raw).is_some() {
            return self.decide_none();
        }
        let mut line = Line::default();
        self.reader.reader.read_line_into(self.lines, raw, &mut line);
        let block = line.blocks.iter().any(|b| b.as_ref().is_ok_and(|b| !b.is_empty()));
        if block || line.tape_mark || line.end_of_file {
            return self.decide_none();
        }
        // Comments only are harmless either way; unreadable text makes this a leader.
        self.text |= line.blocks.iter().any(|b| b.is_err());
        self.bytes >= LEADER_SCAN_BYTES && self.decide_none()
    }

    fn decide_none(&mut self) -> bool {
        self.decided = Some(0);
        true
    }

    /// The number of leader lines (0: none); at the end of the text or of the scan.
    pub fn lines(&self) -> u32 {
        self.decided.unwrap_or(0)
    }
}

/// Lines read ahead, packed: the blocks of all lines in one array and their words in another,
/// so that a batch handed to another thread is a few buffers read front to back (issue 9: the
/// interpreting thread then streams them instead of chasing one small allocation per block).
/// The buffers are kept by [`ReadBatch::clear`] for the next batch.
#[derive(Debug, Default)]
pub struct ReadBatch {
    lines: Vec<PackedLine>,
    blocks: Vec<PackedBlock>,
    words: Vec<Word>,
    /// The rare parts: the reader's alarms and line warnings, and comment texts.
    diagnostics: Vec<Diagnostic>,
    comments: Vec<Vec<String>>,
    /// Macro blocks (custom macro B), rare.
    macros: Vec<Box<crate::read::MacroBlock>>,
    /// The reader's line buffers.
    scratch: ReadLine,
}

#[derive(Debug, Clone, Copy)]
struct PackedLine {
    line_no: u32,
    len: usize,
    /// The line's length in the text, its break included (more than `len` when the driver
    /// kept only the start of an over-long line).
    bytes: u64,
    foreign: Option<Foreign>,
    /// Index ranges into the batch's blocks and diagnostics (the line's warnings).
    blocks: (u32, u32),
    warnings: (u32, u32),
    end_of_file: bool,
    /// The line is a `%` tape mark.
    tape_mark: bool,
}

#[derive(Debug, Clone, Copy)]
struct PackedBlock {
    /// The block could not be read: this diagnostic (an index) is its alarm.
    error: Option<u32>,
    span: Span,
    block_delete: bool,
    sequence: Option<u32>,
    program: Option<u32>,
    words: (u32, u32),
    comments: Option<u32>,
    macro_block: Option<u32>,
}

/// The next index of a batch buffer (a batch holds far fewer than 2^32 of anything).
fn index<T>(v: &[T]) -> u32 {
    u32::try_from(v.len()).expect("a batch holds fewer than 2^32 items")
}

impl ReadBatch {
    /// Lines held.
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
    }

    /// Empty it for the next batch, keeping the buffers.
    pub fn clear(&mut self) {
        self.lines.clear();
        self.blocks.clear();
        self.words.clear();
        self.diagnostics.clear();
        self.comments.clear();
        self.macros.clear();
    }

    /// Read line `line_no` (1-based, with or without its line break) and append it.
    pub fn push(&mut self, reader: &LineReader, line_no: u32, raw: &[u8]) {
        reader.read(line_no, raw, &mut self.scratch);
        let r = &self.scratch;
        let first_block = index(&self.blocks);
        let first_warning = index(&self.diagnostics);
        self.diagnostics.extend(r.line.warnings.iter().cloned());
        let warnings = (first_warning, index(&self.diagnostics));
        for item in &r.line.blocks {
            let packed = match item {
                Err(d) => {
                    self.diagnostics.push(d.clone());
                    PackedBlock {
                        error: Some(index(&self.diagnostics) - 1),
                        span: d.span,
                        block_delete: false,
                        sequence: None,
                        program: None,
                        words: (0, 0),
                        comments: None,
                        macro_block: None,
                    }
                }
                Ok(b) => {
                    let first_word = index(&self.words);
                    self.words.extend_from_slice(&b.words);
                    let comments = (!b.comments.is_empty()).then(|| {
                        self.comments.push(b.comments.clone());
                        index(&self.comments) - 1
                    });
                    let macro_block = b.macro_block.as_ref().map(|m| {
                        self.macros.push(m.clone());
                        index(&self.macros) - 1
                    });
                    PackedBlock {
                        error: None,
                        span: b.span,
                        block_delete: b.block_delete,
                        sequence: b.sequence,
                        program: b.program,
                        words: (first_word, index(&self.words)),
                        comments,
                        macro_block,
                    }
                }
            };
            self.blocks.push(packed);
        }
        self.lines.push(PackedLine {
            line_no,
            len: r.len,
            bytes: raw.len() as u64,
            foreign: r.foreign,
            blocks: (first_block, index(&self.blocks)),
            warnings,
            end_of_file: r.line.end_of_file,
            tape_mark: r.line.tape_mark,
        });
    }

    /// The last line pushed is `bytes` long in the text, its break included: the driver kept
    /// only its start (an over-long line).
    pub fn set_last_line_bytes(&mut self, bytes: u64) {
        if let Some(l) = self.lines.last_mut() {
            l.bytes = bytes;
        }
    }

    /// Block `pb` of this batch into `b`, reusing its allocations.
    fn fill(&self, pb: &PackedBlock, b: &mut Block) {
        b.span = pb.span;
        b.block_delete = pb.block_delete;
        b.sequence = pb.sequence;
        b.program = pb.program;
        b.words.clear();
        // Word by word: blocks hold a few words, too few for a copy call to pay.
        for w in &self.words[pb.words.0 as usize..pb.words.1 as usize] {
            b.words.push(*w);
        }
        match pb.comments {
            Some(c) => b.comments.clone_from(&self.comments[c as usize]),
            None => b.comments.clear(),
        }
        b.macro_block = pb.macro_block.map(|k| self.macros[k as usize].clone());
    }
}

impl Program {
    pub fn new(params: Params, switches: Switches, mode: Mode) -> Program {
        Program::with_operator(params, switches, mode, Options::default())
    }

    /// A run with the operator's actions (single block, feed hold, reset, dry run, overrides).
    pub fn with_operator(params: Params, switches: Switches, mode: Mode, operator: Options) -> Program {
        let style = params.profile().alarm_style;
        let builder_codes = Program::builder_codes(&params);
        let builders = !builder_codes.is_empty() || params.profile().calls.builder.m9000;
        // FANUC 6000#5 SBM: single block stops after macro statements too (docs/reference/macro.md section 6).
        let statement_stops = operator.single_block && params.profile().macros.single_block_param.is_some_and(|k| params.get(k) == 1.0);
        Program {
            machine: Machine::new(&params, operator),
            block: Block::default(),
            core: Core {
                run_as_called: false,
                reader: LineReader { reader: Reader::new(style) },
                interp: Interpreter::new(params, switches),
                mode,
                line_no: 0,
                status: Status::Running,
                eof: false,
                warned_after_end: false,
                alarms: 0,
                last_span: Span::new(1, 1, 1),
                increment_warnings: 0,
                read: ReadLine::default(),
                outcome: Outcome::streaming(),
                file: 0,
                line_offset: 0,
                next_offset: 0,
                block_index: 0,
                skip_to: 0,
                skip_next: 0,
                again: false,
                searched_again: false,
                linear: true,
                linear_end: 0,
                reported: Reported::default(),
                block_n: None,
                executed_any: false,
                calls: Calls::default(),
                call_options: CallOptions::default(),
                vars: macros::Variables::default(),
                evaluated: Block::default(),
                clock_s: 0.0,
                last_n: None,
                modal_call: None,
                builder_codes,
                builders,
                builder_call: false,
                leader_lines: 0,
                statement_stops,
                last_alarm: None,
            },
        }
    }

    /// The codes the parameters make calls of the machine's macros (FANUC 6050-6089; GSK980TDi
    /// No.86-95), read once: parameters do not change during a run.
    fn builder_codes(params: &Params) -> Vec<(u8, u32, u32, bool)> {
        let b = params.profile().calls.builder;
        let mut out = Vec::new();
        for (letter, rule, as_macro) in [(b'G', b.g_macro, true), (b'M', b.m_subprogram, false), (b'M', b.m_macro, true)] {
            if let Some((first, program, n)) = rule {
                for i in 0..n {
                    let code = params.get(crate::profile::ParamKey::Number(first + i, None));
                    if code > 0.0 {
                        out.push((letter, code as u32, program + i, as_macro));
                    }
                }
            }
        }
        out
    }

    /// Check mode that passes on only the diagnostics: records are neither timed nor passed on
    /// (the same diagnostics as [`Mode::Check`], without the time model's work).
    pub fn diagnostics_only(params: Params, switches: Switches) -> Program {
        let mut p = Program::new(params, switches, Mode::Check);
        p.core.outcome.discard_records = true;
        p
    }

    pub fn interpreter(&self) -> &Interpreter {
        &self.core.interp
    }

    /// The machine's offsets, reference points and limits from a setup; given before the first
    /// line (the tool starts at the setup's reference point).
    pub fn set_setup(&mut self, setup: &crate::setup::Setup) {
        self.core.interp.set_setup(setup);
        // The machine builder's M-code macro calls the setup declares (`[machine] m_macro`),
        // as the parameters 6080-6089 make them: G65 with the block's words as arguments.
        if let Some(m) = &setup.machine {
            let c = &mut self.core;
            for (code, program) in m.m_macros() {
                c.builder_codes.retain(|(l, k, _, _)| !(*l == b'M' && *k == code));
                c.builder_codes.push((b'M', code, program, true));
                c.builders = true;
            }
        }
    }

    /// How programmes that call programmes are run; given before the first line. With a main
    /// programme named, the run begins by looking for it.
    pub fn set_call_options(&mut self, options: CallOptions) {
        let c = &mut self.core;
        c.call_options = options;
        if let Some(number) = options.main {
            let start = Place::start_of(0);
            c.leave_linear();
            c.calls.search = Some(Search {
                target: Target::Program(number),
                from: start,
                scope: start,
                wrapped: true,
                once: true,
                asked_by: Span::new(1, 1, 1),
                resume: None,
            });
        }
    }

    /// Set a common variable before the run, as the operator set it at the machine (#500-#999
    /// keep their values through power off; #100-#199 too until a reset), an input signal of
    /// the machine (#1000-#1015, #1032), or a local variable #1-#33 of the programme's own level:
    /// a macro body run on its own as if it had been called with that argument.
    pub fn set_variable(&mut self, number: i64, value: f64) -> Result<(), String> {
        if value.is_finite() && macros::is_input(number) {
            return self.core.vars.set_input(number, value);
        }
        if !value.is_finite() || !((1..=33).contains(&number) || (100..=999).contains(&number)) {
            return Err(format!("#{number}={value}: only locals #1-#33 (the programme run as a macro called with them), common variables #100-#199 and #500-#999 and the input signals #1000-#1015 and #1032 can be given, with a finite value"));
        }
        self.core.vars.write(number, Some(value), 0.0).map_err(|(_, msg)| msg)
    }

    /// Run the programme as a macro called with these arguments (`A1. B2. I3.`, as a G65 block
    /// writes them after P): each sets its local variable of the programme's level, by argument
    /// specification I (and II's repeated I J K), a value without a point read as G65 reads it.
    pub fn set_call_arguments(&mut self, text: &str) -> Result<(), String> {
        let style = self.core.interp.profile().alarm_style;
        let line = crate::read::Reader::new(style).read_line(1, text.as_bytes());
        let mut words = Vec::new();
        for b in line.blocks {
            let b = b.map_err(|d| d.message)?;
            if b.sequence.is_some() || b.program.is_some() || b.macro_block.is_some() {
                return Err("only argument words (letters and numbers) can be given".into());
            }
            words.extend(b.words);
        }
        let mut seen = [0usize; 3];
        for w in &words {
            let slot = self.core.argument_slot(w, &mut seen, "--call-args").map_err(|d| d.message)?;
            let value = self.core.argument_value(w);
            self.core.vars.write(slot as i64, Some(value), 0.0).map_err(|(_, msg)| msg)?;
        }
        self.core.run_as_called = true;
        Ok(())
    }

    /// Where the run must read next, when it is not the next line: after a line, or at the end
    /// of a text ([`Program::end_of_text`]). The driver feeds the lines from there on.
    pub fn take_request(&mut self) -> Option<Request> {
        self.core.calls.request.take()
    }

    /// The answer to [`Request::Find`]: the file called `name` holds the programme. Its
    /// number for spans and places is returned; the run asks to read it from its start.
    pub fn open_file(&mut self, name: impl Into<String>) -> u16 {
        let c = &mut self.core;
        if c.calls.files.is_empty() {
            c.calls.files.push(String::new());
        }
        let file = u16::try_from(c.calls.files.len()).unwrap_or(u16::MAX);
        c.calls.files.push(name.into());
        let start = Place::start_of(file);
        if let Some(s) = &mut c.calls.search {
            *s = Search { from: start, scope: start, wrapped: true, once: true, ..*s };
        }
        c.seek(start);
        file
    }

    /// The answer to [`Request::Find`]: no file holds the programme.
    pub fn no_file(&mut self, sink: &mut dyn FnMut(Event)) {
        self.no_file_passing_over(&[], sink);
    }

    /// [`Program::no_file`], naming the entries the driver passed over because they could not
    /// be read as programme files (a folder or a named pipe called `O1234.nc`, a file it may not
    /// read), each with why.
    pub fn no_file_passing_over(&mut self, passed_over: &[String], sink: &mut dyn FnMut(Event)) {
        let Program { core, machine, .. } = self;
        let (chain, file) = (core.calls.chain(), core.file);
        core.not_found(passed_over, &mut |e| stamped(e, &chain, file, machine, sink));
    }

    /// The name a driver gave file `file` ([`Program::open_file`]); "" for the first file.
    pub fn file_name(&self, file: u16) -> &str {
        self.core.calls.files.get(file as usize).map(String::as_str).unwrap_or("")
    }

    /// The text being fed has ended. The run may go on elsewhere (a search going back to the
    /// top, a called programme in another file): then the request is returned and the driver
    /// feeds from there. Otherwise the run is finished ([`Program::finish`]).
    pub fn end_of_text(&mut self, sink: &mut dyn FnMut(Event)) -> Option<Request> {
        let stopped = self.core.status == Status::Alarm || self.machine.is_reset();
        if !stopped {
            let Program { core, machine, .. } = self;
            let (chain, file, depth) = (core.calls.chain(), core.file, core.calls.depth());
            let sink = &mut |e| stamped(e, &chain, file, machine, sink);
            if core.calls.search.is_some() {
                core.search_ends(sink);
            } else if depth > 0 && core.status == Status::Running {
                let span = core.last_span;
                core.text_ends(span, sink);
            }
            if let Some(r) = core.calls.request.take() {
                return Some(r);
            }
        }
        self.finish(sink);
        None
    }

    pub fn status(&self) -> Status {
        self.core.status
    }

    /// The calls (M98, G65, ...) that led to the block running now, outermost first: what a
    /// consumer that groups records by the main programme's lines attributes a subprogramme's
    /// records to.
    pub fn call_chain(&self) -> Vec<Span> {
        self.core.calls.chain()
    }

    /// Alarms reported so far.
    pub fn alarm_count(&self) -> usize {
        self.core.alarms
    }

    /// Whether more lines can change anything.
    pub fn wants_more(&self) -> bool {
        let c = &self.core;
        !c.eof && !self.machine.is_reset() && (c.mode == Mode::Check || c.status == Status::Running)
    }

    /// Seconds from programme start so far (the cycle time once the input has ended).
    pub fn time_s(&self) -> f64 {
        self.machine.time_s()
    }

    /// The controller profile the programme runs on.
    pub fn profile(&self) -> &'static crate::profile::Profile {
        self.core.interp.profile()
    }

    /// Feed the next line (with or without its line break).
    pub fn feed_line(&mut self, raw: &[u8], sink: &mut dyn FnMut(Event)) {
        self.feed_line_of(raw, raw.len() as u64, sink);
    }

    /// Feed the next line, `bytes` long in the text with its break, of which the caller kept
    /// `raw` (the start of an over-long line): byte offsets stay true for jumps.
    pub fn feed_line_of(&mut self, raw: &[u8], bytes: u64, sink: &mut dyn FnMut(Event)) {
        if !self.wants_more() {
            self.core.line_no = self.core.line_no.wrapping_add(1);
            self.core.next_offset += bytes;
            return;
        }
        let mut read = std::mem::take(&mut self.core.read);
        self.core.reader.read(self.core.line_no.wrapping_add(1), raw, &mut read);
        self.feed_read(&mut read, bytes, sink);
        self.core.read = read;
    }

    /// The tape leader of the main file, decided from its first lines (see [`LeaderScan`]):
    /// that many lines from the top are not read. Given before the first line is fed.
    pub fn set_tape_leader(&mut self, lines: u32) {
        self.core.leader_lines = lines;
    }

    /// Whether a drilling block too big to hold may make its records as they are handed on
    /// (true for a consumer that takes each event as it comes, as `feed_line`'s sink does; the
    /// pull iterator [`events`] turns it off, since it queues a line's events, and such a block
    /// then keeps the cap of NCS-E40).
    pub fn set_deferred_blocks(&mut self, allowed: bool) {
        self.core.outcome.may_defer = allowed;
    }

    /// A scan of the first lines of the main file for a tape leader.
    pub fn leader_scan(&self) -> LeaderScan {
        LeaderScan { reader: self.core.reader.clone(), lines: 0, text: false, bytes: 0, decided: None }
    }

    /// A reader for the lines of this programme (see [`ReadBatch`]).
    pub fn line_reader(&self) -> LineReader {
        self.core.reader.clone()
    }

    /// Feed line `i` of a batch read ahead by [`ReadBatch::push`]. Lines must come in order,
    /// each once, across batches.
    pub fn feed_from(&mut self, batch: &ReadBatch, i: usize, sink: &mut dyn FnMut(Event)) {
        let l = batch.lines[i];
        debug_assert_eq!(l.line_no, self.core.line_no.wrapping_add(1), "lines fed out of order");
        self.core.line_no = l.line_no;
        self.core.clock_s = self.machine.time_s();
        self.core.start_line(l.bytes);
        if !self.wants_more() {
            return;
        }
        let Program { core, machine, block } = self;
        if core.calls.depth() > 0 || core.file > 0 {
            let (chain, file) = (core.calls.chain(), core.file);
            core.interpret_packed(batch, &l, block, &mut |e| stamped(e, &chain, file, machine, sink));
        } else if core.records() {
            core.interpret_packed(batch, &l, block, &mut |e| machine.push(e, sink));
        } else {
            core.interpret_packed(batch, &l, block, sink);
        }
    }

    fn feed_read(&mut self, read: &mut ReadLine, bytes: u64, sink: &mut dyn FnMut(Event)) {
        debug_assert_eq!(read.line_no, self.core.line_no.wrapping_add(1), "lines fed out of order");
        self.core.line_no = read.line_no;
        self.core.clock_s = self.machine.time_s();
        self.core.start_line(bytes);
        if !self.wants_more() {
            return;
        }
        let Program { core, machine, .. } = self;
        if core.calls.depth() > 0 || core.file > 0 {
            let (chain, file) = (core.calls.chain(), core.file);
            core.interpret_read(read, &mut |e| stamped(e, &chain, file, machine, sink));
        } else if core.records() {
            core.interpret_read(read, &mut |e| machine.push(e, sink));
        } else {
            core.interpret_read(read, sink);
        }
    }

    /// The input has ended. Without M02/M30 the controller would wait at the last block; say so.
    pub fn finish(&mut self, sink: &mut dyn FnMut(Event)) {
        let c = &mut self.core;
        let mut events = Vec::new();
        if c.status != Status::Alarm && !self.machine.is_reset() {
            c.flush_pending(&mut |e| events.push(e));
        }
        // A G71/G72 whose contour never closed: its blocks were read but nothing ran them.
        let stopped = c.status == Status::Alarm || self.machine.is_reset();
        if let Some(d) = c.interp.unfinished_contour().filter(|_| !stopped) {
            c.alarms += 1;
            if c.mode == Mode::Run {
                c.status = Status::Alarm;
            }
            events.push(Event::Diagnostic(d));
        }
        if let Some(d) = c.increment_summary() {
            events.push(Event::Diagnostic(d));
        }
        if c.status == Status::Running && !self.machine.is_reset() {
            let d = Diagnostic::new(
                Rule::NoProgramEnd,
                c.interp.profile().alarm_style,
                c.last_span,
                "the programme has no end (M02 or M30): the controller stops after the last block",
            );
            events.push(Event::Diagnostic(d));
        }
        if !c.records() {
            events.into_iter().for_each(sink);
            return;
        }
        for e in events {
            self.machine.push(e, sink);
        }
        self.machine.finish(sink);
    }
}

impl Core {
    /// The NCS-W02 warnings not shown one by one, in one warning; when most lengths written
    /// without a decimal point would be under 1 mm, a hint that the programme was probably
    /// written for calculator-type input.
    fn increment_summary(&self) -> Option<Diagnostic> {
        let hidden = self.increment_warnings.checked_sub(INCREMENT_WARNINGS_SHOWN).filter(|n| *n > 0)?;
        let profile = self.interp.profile();
        let (all, small) = (self.outcome.increment_words, self.outcome.increment_words_small);
        let d = Diagnostic::new(
            Rule::IntegerLength,
            profile.alarm_style,
            self.last_span,
            format!(
                "{hidden} more lengths without a decimal point were read in least input increments ({all} in all, {small} of them under 1 mm or 0.1 inch); only the first {INCREMENT_WARNINGS_SHOWN} were shown"
            ),
        );
        Some(match profile.calculator_input {
            Some(key) if small * 2 > all => d.with_hint(format!(
                "whole numbers this small look like millimetres: if the programme was written for a control set for calculator-type input, run it with --param {key}=1"
            )),
            _ => d,
        })
    }

    /// Records are passed on (through the machine); not in a diagnostics-only check, whose
    /// interpreter keeps none.
    fn records(&self) -> bool {
        !self.outcome.discard_records
    }

    /// Interpret one line read; the events are untimed.
    fn interpret_read(&mut self, read: &mut ReadLine, sink: &mut dyn FnMut(Event)) {
        let line = &mut read.line;
        if self.begin_line(read.foreign, read.len, &line.warnings, line.end_of_file, line.tape_mark, sink) {
            for item in &line.blocks {
                if !self.interpret_item(item.as_ref(), sink) {
                    return;
                }
            }
        }
    }

    /// The start of a line: another control's language ends the run; the line's warnings; a DOS
    /// end-of-file mark. Whether the line's blocks are to be interpreted.
    fn begin_line(
        &mut self,
        foreign: Option<Foreign>,
        len: usize,
        warnings: &[Diagnostic],
        end_of_file: bool,
        tape_mark: bool,
        sink: &mut dyn FnMut(Event),
    ) -> bool {
        if self.file == 0 && self.line_no <= self.leader_lines {
            if self.line_no == 1 && !self.again {
                let span = Span::new(1, 1, len.clamp(1, 80) as u32);
                let lines = if self.leader_lines == 1 {
                    "line 1, before the first '%', is".to_string()
                } else {
                    format!("lines 1-{}, before the first '%', are", self.leader_lines)
                };
                sink(Event::Diagnostic(Diagnostic::new(
                    Rule::TextIgnored,
                    self.interp.profile().alarm_style,
                    span,
                    format!("{lines} the tape leader: not read (the programme starts after the '%')"),
                )));
            }
            return false;
        }
        if let Some(f) = foreign {
            let profile = self.interp.profile();
            let d = Diagnostic::new(
                Rule::ForeignDialect,
                profile.alarm_style,
                Span::new(self.line_no, 1, len.clamp(1, 80) as u32),
                format!(
                    "this looks like {}, not a programme for {} ({}): its words mean other things there, so ncsight stops here",
                    f.name(),
                    profile.name,
                    profile.title
                ),
            )
            .with_hint("run it on the profile of the control it was written for");
            self.alarm(d, sink);
            // Both modes stop: reading on would only repeat the same answer.
            self.status = Status::Alarm;
            self.eof = true;
            return false;
        }
        // A line's own warnings once: not again after a jump back, not while a search passes.
        if !warnings.is_empty() && !self.again && self.calls.search.is_none() {
            for w in warnings {
                sink(Event::Diagnostic(w.clone()));
            }
        }
        if end_of_file {
            self.eof = true;
        }
        // A `%` after the first block closes the record: the text after it is not read
        // (docs/reference/macro.md section 1, inferred). The one before is the record's start. A search for a
        // programme or a sequence number reads on past it (the controller's memory holds every
        // programme of the file; inferred).
        if tape_mark && self.executed_any && self.calls.search.is_none() {
            let span = Span { file: self.file, ..Span::new(self.line_no, 1, 1) };
            if self.calls.depth() > 0 && self.status == Status::Running {
                self.text_ends(span, sink);
            } else {
                self.eof = true;
            }
            return false;
        }
        true
    }

    /// A line of a batch, its blocks set one by one into a block kept for reuse.
    fn interpret_packed(&mut self, batch: &ReadBatch, l: &PackedLine, block: &mut Block, sink: &mut dyn FnMut(Event)) {
        let warnings = &batch.diagnostics[l.warnings.0 as usize..l.warnings.1 as usize];
        let plain = l.foreign.is_none() && warnings.is_empty() && !l.end_of_file && !l.tape_mark && self.line_no > self.leader_lines;
        if !plain && !self.begin_line(l.foreign, l.len, warnings, l.end_of_file, l.tape_mark, sink) {
            return;
        }
        for pb in &batch.blocks[l.blocks.0 as usize..l.blocks.1 as usize] {
            let go_on = match pb.error {
                Some(k) => self.interpret_item(Err(&batch.diagnostics[k as usize]), sink),
                None => {
                    batch.fill(pb, block);
                    self.interpret_item(Ok(block), sink)
                }
            };
            if !go_on {
                break;
            }
        }
    }

    /// One block of a line, or the alarm the reader made of it. Whether the rest of the line is
    /// to be interpreted (a run stops at its first alarm, at the programme end and at a jump).
    fn interpret_item(&mut self, item: Result<&Block, &Diagnostic>, sink: &mut dyn FnMut(Event)) -> bool {
        let k = self.block_index;
        self.block_index = self.block_index.saturating_add(1);
        if k < self.skip_to {
            return true;
        }
        let place = Place { file: self.file, offset: self.line_offset, line: self.line_no, block: k };
        if self.calls.search.is_some() {
            if self.searched_again && !self.guard(item.map_or_else(|d| d.span, |b| b.span), sink) {
                return false;
            }
            match self.search_step(item.ok(), place, sink) {
                Searched::Passed => return true,
                Searched::Stop => return false,
                Searched::Found => {}
            }
        }
        let block = match item {
            Ok(b) => b,
            Err(d) => {
                self.flush_pending(sink);
                self.alarm(d.clone(), sink);
                return self.mode != Mode::Run;
            }
        };
        if block.is_empty() {
            return true;
        }
        self.last_span = block.span;
        if let Some(n) = block.program {
            self.calls.note_program(n, place);
        }
        if self.status == Status::Ended {
            // Subprogrammes after M30 (O blocks) are the shop files' habit: no warning for them.
            if !self.warned_after_end && block.program.is_some() {
                self.warned_after_end = true;
            }
            if !self.warned_after_end {
                self.warned_after_end = true;
                let d = Diagnostic::new(
                    Rule::AfterEnd,
                    self.interp.profile().alarm_style,
                    block.span,
                    "this block comes after the programme end (M02/M30) and is not executed; later blocks are only read",
                );
                sink(Event::Diagnostic(d));
            }
            return true;
        }
        if let Some(n) = block.program {
            match self.calls.running() {
                // The first programme of the text is the main one.
                None if self.calls.depth() == 0 && !self.executed_any => self.calls.main = Some((Some(n), place)),
                // The running programme's own O block.
                Some((_, start)) if start == place => {}
                // Another programme begins: the running one's text has ended.
                _ => return self.text_ends(block.span, sink),
            }
            if block.words.is_empty() {
                return true;
            }
        }
        if !self.executed_any {
            self.executed_any = true;
            if self.calls.main.is_none() {
                self.calls.main = Some((None, Place::start_of(self.file)));
            }
        }
        if self.again && !self.guard(block.span, sink) {
            return false;
        }
        if block.sequence.is_some() {
            self.last_n = block.sequence;
        }
        let go_on = match block.macro_block.as_deref() {
            Some(m) => self.macro_item(m, block, place, sink),
            None => self.execute(block, place, sink),
        };
        // A G70 running the programme's blocks ends after N nf, whatever that block is (a macro
        // statement, a block skipped by block delete; an NC block ended it already).
        match self.calls.frames.last().and_then(|f| f.finishing) {
            Some(req) if block.sequence == Some(req.nf) => self.end_finishing(req, block, sink),
            _ => go_on,
        }
    }

    /// A macro block: a statement, or words whose values come from the variables. Whether the
    /// rest of the line is interpreted. (Out of line: most blocks are plain NC blocks.)
    #[inline(never)]
    fn macro_item(&mut self, m: &crate::read::MacroBlock, block: &Block, place: Place, sink: &mut dyn FnMut(Event)) -> bool {
        if block.block_delete && self.interp.switches().block_delete {
            return true;
        }
        let words = match &m.stmt {
            Stmt::Words(words) => words,
            stmt => return self.statement(&m.arena, stmt, block, place, sink),
        };
        let constant = |w: &crate::read::MacroWord| match m.arena.nodes.get(w.node as usize) {
            Some(crate::read::expr::Node::Num(v)) => Some(*v),
            _ => None,
        };
        // GSK980TDi macro A: G65 Hm P#i Q#j R#k.
        if self.interp.profile().macros.macro_a && words.len() >= 2 && words[0].letter == b'G' && constant(&words[0]) == Some(65.0) && words[1].letter == b'H' {
            let next = Place { block: place.block.saturating_add(1), ..place };
            return match self.macro_a(&m.arena, words, block, next) {
                Ok(go_on) => go_on,
                Err(d) => self.fail(d, sink),
            };
        }
        // The words' values from the variables: an NC block to run.
        let mut evaluated = std::mem::take(&mut self.evaluated);
        evaluated.span = block.span;
        evaluated.block_delete = block.block_delete;
        evaluated.sequence = block.sequence;
        evaluated.program = None;
        evaluated.words.clear();
        evaluated.comments.clone_from(&block.comments);
        let inch = self.interp.state().modes.inch;
        // A G65/G66 block's words are arguments: values pass as they are.
        let arguments = words
            .iter()
            .any(|w| w.letter == b'G' && matches!(m.arena.nodes.get(w.node as usize), Some(crate::read::expr::Node::Num(v)) if *v == 65.0 || *v == 66.0));
        let mut failed = None;
        if let Err(d) = self.check_brackets(&m.arena, block.span) {
            failed = Some(d);
        }
        for w in words {
            if failed.is_some() {
                break;
            }
            let mut reading = self.reading();
            match macros::evaluate_word(&m.arena, w, &mut reading, inch, arguments) {
                Ok(Some(word)) => evaluated.words.push(word),
                Ok(None) => {}
                Err(e) => failed = Some(macros::expr_alarm(self.interp.profile().alarm_style, w.span, &e)),
            }
        }
        let go_on = match failed {
            Some(d) => self.fail(d, sink),
            None => self.execute(&evaluated, place, sink),
        };
        self.evaluated = evaluated;
        return go_on;
    }

    /// The variables as a block reads them.
    fn reading(&self) -> macros::Reading<'_> {
        macros::Reading {
            vars: &self.vars,
            modal: self.interp.state(),
            to_machine: self.interp.tables().to_machine(&self.interp.state().frame),
            profile: self.interp.profile(),
            clock_s: self.clock_s,
            program: self.calls.running().and_then(|(n, _)| n),
            last_n: self.last_n,
            modal_call: self.modal_call.is_some(),
            axes: &self.interp.tables().axis_order,
            tables: self.interp.tables(),
        }
    }

    /// Write macro variable `number`: a table entry's (`#2001`, `#5221`: the interpreter's
    /// tables), else the variables'.
    fn write_variable(&mut self, number: i64, value: crate::read::expr::Value) -> Result<(), (Rule, String)> {
        if let Some(v) = value {
            if let Some(result) = self.interp.write_table_variable(number, v) {
                return result.map_err(|e| (Rule::IllegalVariable, format!("#{number} = {e}")));
            }
        }
        self.vars.write(number, value, self.clock_s)
    }

    /// Brackets nested deeper than the profile allows: FANUC alarm 118 (five levels, function
    /// brackets included: FANUC Series 16/18 operator's manual for lathe, custom macro).
    fn check_brackets(&self, arena: &crate::read::expr::Arena, span: Span) -> Result<(), Diagnostic> {
        let profile = self.interp.profile();
        let max = profile.macros.max_brackets;
        if arena.depth > max {
            return Err(Diagnostic::new(
                Rule::BracketNesting,
                profile.alarm_style,
                span,
                format!("brackets nested {} deep: {} allows {max}", arena.depth, profile.name),
            ));
        }
        Ok(())
    }

    /// An alarm of the block being run; whether the rest of the line is interpreted.
    fn fail(&mut self, d: Diagnostic, sink: &mut dyn FnMut(Event)) -> bool {
        self.flush_pending(sink);
        self.alarm(d, sink);
        self.mode != Mode::Run
    }

    /// Evaluate a tree of the block at `span`, its failure the controller's alarm.
    fn value(&self, arena: &crate::read::expr::Arena, root: u32, span: Span) -> Result<crate::read::expr::Value, Diagnostic> {
        let mut reading = self.reading();
        crate::read::expr::eval(arena, root, &mut reading).map_err(|e| macros::expr_alarm(self.interp.profile().alarm_style, span, &e))
    }

    /// A macro statement: an assignment, IF, WHILE, END, GOTO. Whether the rest of the line is
    /// interpreted.
    fn statement(&mut self, arena: &crate::read::expr::Arena, stmt: &Stmt, block: &Block, place: Place, sink: &mut dyn FnMut(Event)) -> bool {
        if let Err(d) = self.check_brackets(arena, block.span) {
            return self.fail(d, sink);
        }
        let next = Place { block: place.block.saturating_add(1), ..place };
        let mut sink_warning = None;
        let result = match stmt {
            Stmt::Words(_) => unreachable!("words are run as an NC block"),
            Stmt::Assign { var, value } => self.assign(arena, *var, *value, block),
            Stmt::If { cond, then } => self.if_statement(arena, *cond, then, block, next, &mut sink_warning),
            Stmt::While { cond, label } => self.while_statement(arena, *cond, *label, block, place, next),
            Stmt::End { label } => self.end_statement(*label, block),
            Stmt::Goto { target } => self.goto(arena, *target, block.span, next),
        };
        if let Some(w) = sink_warning {
            sink(Event::Diagnostic(w));
        }
        match result {
            Ok(go_on) => {
                if self.statement_stops && self.records() {
                    // The machine stops here: a thread run held back ends first, as at M00.
                    self.interp.flush_thread_into(&mut self.outcome);
                    self.outcome.warnings.clear();
                    self.pass_on(sink);
                    let stop = crate::motion::Op::Stop { reason: crate::motion::StopReason::SingleBlock };
                    sink(Event::Record(crate::motion::Record::of_block(block.span, block.sequence, stop)));
                }
                go_on
            }
            Err(d) => self.fail(d, sink),
        }
    }

    /// `IF [cond] GOTO n` or `IF [cond] THEN #i = ..` (a FANUC 0i's `IF [..] #i = ..` noted in
    /// `warning`).
    fn if_statement(
        &mut self,
        arena: &crate::read::expr::Arena,
        cond: u32,
        then: &Then,
        block: &Block,
        next: Place,
        warning: &mut Option<Diagnostic>,
    ) -> Result<bool, Diagnostic> {
        let profile = self.interp.profile();
        if let Then::Assign { written: false, .. } = then {
            // IF [..] #i = .. without THEN: a FANUC 0i takes it (a real programme
            // relies on it), the others are not known to (docs/reference/macro.md section 6).
            if !profile.macros.if_without_then {
                return Err(Diagnostic::new(
                    Rule::MacroFormat,
                    profile.alarm_style,
                    block.span,
                    "IF [..] #i = ..: THEN is missing (IF [..] THEN #i = ..)".to_string(),
                ));
            }
            if self.reported.first(&Diagnostic::new(Rule::ThenOmitted, profile.alarm_style, block.span, String::new())) {
                *warning = Some(Diagnostic::new(
                    Rule::ThenOmitted,
                    profile.alarm_style,
                    block.span,
                    "IF [..] #i = .. without THEN: read as IF [..] THEN #i = .., as a FANUC 0i takes it".to_string(),
                ));
            }
        }
        if !macros::holds(self.value(arena, cond, block.span)?) {
            return Ok(true);
        }
        match then {
            Then::Goto(t) => self.goto(arena, *t, block.span, next),
            Then::Assign { var, value, .. } => self.assign(arena, *var, *value, block),
        }
    }

    /// `WHILE [cond] DO m`: into the loop (its END looked for ahead), or past its END.
    fn while_statement(
        &mut self,
        arena: &crate::read::expr::Arena,
        cond: u32,
        label: u32,
        block: &Block,
        place: Place,
        next: Place,
    ) -> Result<bool, Diagnostic> {
        let profile = self.interp.profile();
        // DO m: m is 1, 2 or 3 (GSK980TDi help text, WHILE; FANUC alarm 126).
        if !(1..=3).contains(&label) {
            return Err(Diagnostic::new(Rule::LoopNumber, profile.alarm_style, block.span, format!("DO{label}: the loop number is 1, 2 or 3")));
        }
        let depth = self.calls.depth();
        // This WHILE's loop, if it is running: loops above it were left by a GOTO.
        let own = self.calls.loops.iter().rposition(|l| l.place == place && l.depth == depth);
        if let Some(k) = own {
            self.calls.loops.truncate(k + 1);
        }
        let top_here = own.is_some();
        if macros::holds(self.value(arena, cond, block.span)?) {
            if !top_here {
                if self.calls.loops.iter().filter(|l| l.depth == depth).count() >= 3 {
                    return Err(Diagnostic::new(Rule::LoopNumber, profile.alarm_style, block.span, "WHILE loops nest at most three deep".to_string()));
                }
                self.calls.loops.push(Loop { label, place, depth });
                // Its END must follow in the programme: looked for now, not when the
                // body has run to the programme's end (FANUC alarm 124).
                let scope = self.calls.running().map_or(Place::start_of(self.file), |(_, s)| s);
                self.leave_linear();
                self.calls.search = Some(Search {
                    target: Target::LoopEndAhead(label),
                    from: next,
                    scope,
                    wrapped: true,
                    once: true,
                    asked_by: block.span,
                    resume: Some(next),
                });
            }
            return Ok(true);
        }
        if top_here {
            self.calls.loops.pop();
        }
        // Past the matching END m.
        let scope = self.calls.running().map_or(Place::start_of(self.file), |(_, s)| s);
        self.leave_linear();
        self.calls.search = Some(Search { target: Target::LoopEnd(label), from: next, scope, wrapped: true, once: true, asked_by: block.span, resume: None });
        Ok(true)
    }

    /// `END m`: back to its WHILE.
    fn end_statement(&mut self, label: u32, block: &Block) -> Result<bool, Diagnostic> {
        let profile = self.interp.profile();
        let depth = self.calls.depth();
        // The nearest running loop of this number; loops above it were left by a GOTO.
        match self.calls.loops.iter().rposition(|l| l.label == label && l.depth == depth) {
            Some(k) => {
                self.calls.loops.truncate(k + 1);
                let back = self.calls.loops[k].place;
                self.seek(back);
                Ok(false)
            }
            _ => Err(Diagnostic::new(Rule::MissingEnd, profile.alarm_style, block.span, format!("END {label}: no WHILE [..] DO {label} is running"))),
        }
    }

    /// `#i = value`; `#3000 = n` is the user's alarm.
    fn assign(&mut self, arena: &crate::read::expr::Arena, var: u32, value: u32, block: &Block) -> Result<bool, Diagnostic> {
        let profile = self.interp.profile();
        let number =
            crate::read::expr::variable_number(self.value(arena, var, block.span)?).map_err(|e| macros::expr_alarm(profile.alarm_style, block.span, &e))?;
        let v = self.value(arena, value, block.span)?;
        if number == 3000 {
            // The user's alarm: 3000 + n with the comment's text (FANUC 0i; docs/reference/macro.md section 8).
            let n = v.unwrap_or(0.0).round() as i64;
            let text = block.comments.first().map(|c| format!(" ({})", c.trim())).unwrap_or_default();
            return Err(Diagnostic::new(Rule::UserAlarm, profile.alarm_style, block.span, format!("user alarm {}{text}: #3000 = {n}", 3000 + n)));
        }
        self.write_variable(number, v).map_err(|(rule, msg)| Diagnostic::new(rule, profile.alarm_style, block.span, msg))?;
        Ok(true)
    }

    /// The GSK980TDi's macro A, `G65 Hm P#i Q#j R#k` (GSK980TDi manual, G65 H list): #i is set
    /// from #j and #k (variables or constants) by operation m; H80-H86 jump to N(P), H99 is the
    /// user's alarm 500+P. Where the table's entries were lost (H27, H82-H86, H24/H25 names)
    /// FANUC macro A's are used (inferred).
    fn macro_a(&mut self, arena: &crate::read::expr::Arena, words: &[crate::read::MacroWord], block: &Block, next: Place) -> Result<bool, Diagnostic> {
        use crate::read::expr::Node;
        let profile = self.interp.profile();
        let style = profile.alarm_style;
        let find = |l: u8| words.iter().find(|w| w.letter == l);
        let h_word = find(b'H').expect("an H word");
        let h = self.value(arena, h_word.node, h_word.span)?.unwrap_or(-1.0);
        if let Some(w) = words.iter().find(|w| !matches!(w.letter, b'G' | b'H' | b'P' | b'Q' | b'R')) {
            return Err(Diagnostic::new(Rule::MacroFormat, style, w.span, format!("{}: G65 H (macro A) takes H, P, Q and R only", w.letter as char)));
        }
        let operand = |this: &Self, l: u8| -> Result<f64, Diagnostic> {
            match find(l) {
                Some(w) => Ok(this.value(arena, w.node, w.span)?.unwrap_or(0.0)),
                None => Ok(0.0),
            }
        };
        let (j, k) = (operand(self, b'Q')?, operand(self, b'R')?);
        let Some(p) = find(b'P') else {
            return Err(Diagnostic::new(Rule::AddressPMissing, style, h_word.span, "G65 H: P is missing (the result #i, or the sequence number)".to_string()));
        };
        let h = h.round() as i64;
        // The jumps and the alarm take P as a number.
        if matches!(h, 80..=86 | 99) {
            let n = self.value(arena, p.node, p.span)?.unwrap_or(0.0);
            let jump = match h {
                80 => true,
                81 => j == k,
                82 => j != k,
                83 => j > k,
                84 => j < k,
                85 => j >= k,
                86 => j <= k,
                _ => {
                    let text = block.comments.first().map(|c| format!(" ({})", c.trim())).unwrap_or_default();
                    return Err(Diagnostic::new(Rule::UserAlarm, style, block.span, format!("user alarm {}{text}: G65 H99 P{n}", 500 + n.round() as i64)));
                }
            };
            if !jump {
                return Ok(true);
            }
            let mut t = crate::read::expr::Arena::default();
            t.nodes.push(Node::Num(n));
            return self.goto(&t, 0, block.span, next);
        }
        // P#i: the variable the result goes to.
        let Some(Node::Var(number)) = arena.nodes.get(p.node as usize).copied() else {
            return Err(Diagnostic::new(Rule::MacroFormat, style, p.span, "G65 H: P names the result variable, written P#i".to_string()));
        };
        let i = crate::read::expr::variable_number(self.value(arena, number, p.span)?).map_err(|e| macros::expr_alarm(style, p.span, &e))?;
        let old = crate::read::expr::Variables::read(&mut self.reading(), i).map_err(|e| macros::expr_alarm(style, p.span, &e))?.unwrap_or(0.0);
        let v = macro_a_operation(h, j, k, old, style, block.span, h_word.span)?;
        if !v.is_finite() {
            return Err(Diagnostic::new(Rule::MacroOverflow, style, block.span, "G65 H: the value is not a finite number".to_string()));
        }
        self.write_variable(i, Some(v)).map_err(|(rule, msg)| Diagnostic::new(rule, style, p.span, msg))?;
        Ok(true)
    }

    /// GOTO n: to block N`n` of the running programme, looked for forward, then from its top.
    fn goto(&mut self, arena: &crate::read::expr::Arena, target: u32, span: Span, next: Place) -> Result<bool, Diagnostic> {
        let profile = self.interp.profile();
        let v = self.value(arena, target, span)?;
        let n = v.map(f64::round).unwrap_or(-1.0);
        // FANUC 0 alarm 128: the target is 1 to 9999 (99999 where N has five digits).
        if !(1.0..=99_999.0).contains(&n) {
            return Err(Diagnostic::new(
                Rule::MacroSequence,
                profile.alarm_style,
                span,
                format!("GOTO {}: the sequence number is 1 to 99999", v.map_or("vacant".into(), |v| v.to_string())),
            ));
        }
        let n = n as u32;
        let scope = self.calls.running().map_or(Place::start_of(self.file), |(_, s)| s);
        match self.calls.sequence(scope, n) {
            Some(p) => {
                self.seek(p);
                Ok(false)
            }
            None => {
                self.leave_linear();
                self.calls.search =
                    Some(Search { target: Target::Goto(n), from: next, scope, wrapped: false, once: false, asked_by: span, resume: Some(next) });
                Ok(true)
            }
        }
    }

    /// Run an NC block (read, or evaluated from a macro block).
    #[inline(always)]
    fn execute(&mut self, block: &Block, place: Place, sink: &mut dyn FnMut(Event)) -> bool {
        if block.block_delete && self.interp.switches().block_delete {
            return true;
        }
        // One look at the words: most blocks hold no G65-G67 and no code that calls a macro.
        let builders = self.builders;
        let mut special = self.modal_call.is_some();
        for w in &block.words {
            special |= match w.letter {
                b'G' => builders || (65.0..=67.0).contains(&w.value),
                b'M' => builders,
                _ => false,
            };
        }
        if !special {
            return self.execute_nc(block, place, sink);
        }
        self.execute_calling(block, place, sink)
    }

    /// A block that may call a macro: G65-G67, a code the parameters make a call, a move under
    /// G66.
    #[inline(never)]
    fn execute_calling(&mut self, block: &Block, place: Place, sink: &mut dyn FnMut(Event)) -> bool {
        // A code the parameters make a call of the machine's macro (not inside such a macro:
        // there the code is an ordinary one).
        if self.builders && !self.calls.frames.iter().any(|f| f.builder) {
            if let Some((k, number, as_macro)) = self.builder_call_word(block) {
                return self.call_builder_macro(block, place, k, number, as_macro, sink);
            }
        }
        // G65, G66, G67: run here, not by the interpreter.
        if let Some((k, f)) = self.macro_call_word(block) {
            return self.execute_macro_code(block, place, k, f, sink);
        }
        self.execute_under_g66(block, place, sink)
    }

    /// The word of the block that is a code the parameters make a call of the machine's macro:
    /// its index, the programme it calls, and whether it calls as G65 (else as M98).
    fn builder_call_word(&self, block: &Block) -> Option<(usize, u32, bool)> {
        let profile = self.interp.profile();
        block.words.iter().enumerate().find_map(|(k, w)| {
            if !matches!(w.letter, b'G' | b'M') || w.value.fract() != 0.0 || w.value < 0.0 {
                return None;
            }
            let code = w.value as u32;
            if w.letter == b'M' && profile.calls.builder.m9000 && (9000..=9999).contains(&code) {
                // GSK980TDi help text, M9000-9999: M9123 calls O9123.
                return Some((k, code, false));
            }
            self.builder_codes.iter().find(|(l, c, _, _)| *l == w.letter && *c == code).map(|(_, _, program, as_macro)| (k, *program, *as_macro))
        })
    }

    /// Call the machine's macro O`number` that the block's word `k` calls: as G65 with the
    /// block's other words as arguments, or as M98 after them.
    fn call_builder_macro(&mut self, block: &Block, place: Place, k: usize, number: u32, as_macro: bool, sink: &mut dyn FnMut(Event)) -> bool {
        let profile = self.interp.profile();
        let next = Place { block: place.block.saturating_add(1), ..place };
        let mut span = block.span;
        span.file = self.file;
        let result = if as_macro {
            // As G65 P<programme> with the block's other words as arguments.
            let mut call = block.clone();
            let at = call.words[k].span;
            let trigger = call.words[k].text();
            call.words.remove(k);
            // G65 has no P argument: a P in the block is said to be ignored (no manual
            // says what the machine does with it; inferred).
            if let Some(pw) = call.words.iter().find(|w| w.letter == b'P') {
                let d = Diagnostic::new(
                    Rule::TextIgnored,
                    profile.alarm_style,
                    pw.span,
                    format!("{}: the macro call by {trigger} takes no P argument (G65 has none): ignored", pw.text()),
                );
                sink(Event::Diagnostic(d));
            }
            call.words.retain(|w| w.letter != b'P');
            call.words.insert(0, Word { letter: b'G', value: 65.0, decimal: false, expr: false, span: at });
            call.words.insert(1, Word { letter: b'P', value: f64::from(number), decimal: false, expr: false, span: at });
            self.macro_arguments(&call, 0).and_then(|(number, count, locals)| {
                self.builder_call = true;
                self.call(number, count, span, next, Some(locals))
            })
        } else {
            // As M98: the block's other words first, then the call.
            let mut rest = block.clone();
            rest.words.remove(k);
            if !rest.words.is_empty() && !self.execute_nc(&rest, place, sink) {
                return false;
            }
            self.builder_call = true;
            self.call(number, 1, span, next, None)
        };
        result.unwrap_or_else(|d| self.fail(d, sink))
    }

    /// The block's G65, G66 or G67 (as the profile names them): its word's index and what it does.
    fn macro_call_word(&self, block: &Block) -> Option<(usize, crate::profile::GFn)> {
        use crate::profile::GFn;
        let profile = self.interp.profile();
        block.words.iter().enumerate().find_map(|(k, w)| {
            let code = (w.letter == b'G' && w.value.fract() == 0.0 && (65.0..=67.0).contains(&w.value)).then_some(w.value as u32)?;
            let f = profile.g_code(code, None)?.function;
            matches!(f, GFn::MacroCall | GFn::ModalMacroCall | GFn::ModalMacroCancel).then_some((k, f))
        })
    }

    /// Run the block's G65 (a call, or macro A's `G65 H..`), G66 (a modal call declared) or
    /// G67 (the modal call ended), its word `k`.
    fn execute_macro_code(&mut self, block: &Block, place: Place, k: usize, f: crate::profile::GFn, sink: &mut dyn FnMut(Event)) -> bool {
        use crate::profile::GFn;
        let profile = self.interp.profile();
        match f {
            GFn::MacroCall if profile.macros.macro_a && block.words.get(k + 1).is_some_and(|w| w.letter == b'H') => {
                // Macro A with constants only (`G65 H80 P50`, `G65 H99 P7`): as trees of numbers.
                let mut arena = crate::read::expr::Arena::default();
                let words: Vec<crate::read::MacroWord> = block.words[k..]
                    .iter()
                    .map(|w| {
                        arena.nodes.push(crate::read::expr::Node::Num(w.value));
                        crate::read::MacroWord {
                            letter: w.letter,
                            node: (arena.nodes.len() - 1) as u32,
                            decimal: w.decimal,
                            constant: !w.decimal,
                            span: w.span,
                        }
                    })
                    .collect();
                let next = Place { block: place.block.saturating_add(1), ..place };
                self.macro_a(&arena, &words, block, next).unwrap_or_else(|d| self.fail(d, sink))
            }
            GFn::MacroCall => {
                if profile.macros.g65_cancels_g66 {
                    self.modal_call = None;
                }
                let next = Place { block: place.block.saturating_add(1), ..place };
                let result = self.macro_arguments(block, k).and_then(|(number, count, locals)| {
                    let mut span = block.span;
                    span.file = self.file;
                    self.call(number, count, span, next, Some(locals))
                });
                result.unwrap_or_else(|d| self.fail(d, sink))
            }
            GFn::ModalMacroCall => {
                // G66 declares the call; the blocks with a move that follow make it (GSK980TDi help
                // text, G66; FANUC Series 16i).
                match self.macro_arguments(block, k) {
                    Ok((number, count, locals)) => {
                        let mut span = block.span;
                        span.file = self.file;
                        self.modal_call = Some(ModalCall { number, count, locals, depth: self.calls.depth(), span });
                        true
                    }
                    Err(d) => self.fail(d, sink),
                }
            }
            _ => {
                // G67: the modal call ends; the block's other words run as a block of their own.
                self.modal_call = None;
                if block.words.len() == 1 {
                    return true;
                }
                let mut rest = block.clone();
                rest.words.remove(k);
                self.execute(&rest, place, sink)
            }
        }
    }

    /// Run an NC block, then, under G66, the modal macro call its move makes.
    fn execute_under_g66(&mut self, block: &Block, place: Place, sink: &mut dyn FnMut(Event)) -> bool {
        // A move of any axis calls it: the setup's rotary axes (and H, the lathe's incremental C) too.
        let added = self.interp.tables().added_addresses;
        let modal_call = self.modal_call.filter(|m| {
            m.depth == self.calls.depth()
                && block.words.iter().any(|w| {
                    matches!(w.letter, b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W') || (matches!(w.letter, b'A' | b'B' | b'C' | b'H') && added.contains(w.letter))
                })
        });
        let go_on = self.execute_nc(block, place, sink);
        match modal_call {
            // After a block with a move, the G66 macro is called (its moves do not call it again:
            // it runs a level deeper).
            Some(m) if go_on && self.calls.request.is_none() && self.calls.search.is_none() && self.status == Status::Running => {
                let next = Place { block: place.block.saturating_add(1), ..place };
                self.call(m.number, m.count, m.span, next, Some(m.locals)).unwrap_or_else(|d| self.fail(d, sink))
            }
            _ => go_on,
        }
    }

    /// An NC block through the interpreter, then its M98/M99.
    #[inline(always)]
    fn execute_nc(&mut self, block: &Block, place: Place, sink: &mut dyn FnMut(Event)) -> bool {
        self.block_n = block.sequence;
        match self.interp.execute_into(block, &mut self.outcome) {
            Ok(()) => {
                let flow = self.outcome.flow.take();
                // A GSK parameter line read a parameter into a macro variable.
                if let Some((number, value)) = self.outcome.var_write.take() {
                    let style = self.interp.profile().alarm_style;
                    if let Err((rule, msg)) = self.write_variable(i64::from(number), Some(value)) {
                        self.alarm(Diagnostic::new(rule, style, block.span, msg), sink);
                        if self.mode == Mode::Run {
                            return false;
                        }
                    }
                }
                self.pass_on(sink);
                // A programme end inside a G70's blocks ends the G70 (PS0063) before the run;
                // its N nf ends it in interpret_item, whatever the block is.
                if let Some(req) = self.calls.frames.last().and_then(|f| f.finishing).filter(|_| self.interp.state().modes.ended) {
                    return self.end_finishing(req, block, sink);
                }
                if self.interp.state().modes.ended {
                    self.status = Status::Ended;
                    if self.mode == Mode::Run {
                        return false;
                    }
                }
                if let Some(flow) = flow {
                    return self.jump(flow, place, sink);
                }
            }
            Err(d) => {
                // The thread being cut when the next block alarms is finished first.
                self.flush_pending(sink);
                let finishing = self.leave_finishing();
                self.alarm(d, sink);
                if self.mode == Mode::Run {
                    return false;
                }
                // A check goes on after the G70 whose blocks alarmed.
                if let Some(f) = finishing {
                    self.seek(f.back);
                    return false;
                }
                // A programme end inside an unfinished contour still ends the programme.
                if self.interp.state().modes.ended {
                    self.status = Status::Ended;
                }
            }
        }
        true
    }

    /// The G70 running the programme's blocks has run N nf (or met the programme's end first:
    /// alarm PS0063): back to its start point, then on after the G70 block.
    fn end_finishing(&mut self, req: crate::interp::FinishRequest, block: &Block, sink: &mut dyn FnMut(Event)) -> bool {
        let Some(frame) = self.leave_finishing() else { return true };
        let result = if block.sequence == Some(req.nf) {
            self.interp.finish_return(req, &mut self.outcome)
        } else {
            let style = self.interp.profile().alarm_style;
            Err(Diagnostic::new(Rule::ContourNotFound, style, req.span, format!("G70 Q{}: the programme ends before block N{}", req.nf, req.nf)))
        };
        match result {
            Ok(()) => self.pass_on(sink),
            Err(d) => {
                self.alarm(d, sink);
                if self.interp.state().modes.ended {
                    self.status = Status::Ended;
                }
                if self.mode == Mode::Run || self.interp.state().modes.ended {
                    return false;
                }
            }
        }
        self.seek(frame.back);
        false
    }

    /// A G70 running the programme's blocks ends (its last block, an alarm): its frame goes.
    fn leave_finishing(&mut self) -> Option<Frame> {
        if self.calls.frames.last().is_none_or(|f| f.finishing.is_none()) {
            return None;
        }
        self.interp.set_finishing(false);
        let f = self.calls.frames.pop()?;
        self.left(&f);
        Some(f)
    }

    /// A new line of `bytes` bytes (its break included) begins where the last one ended.
    fn start_line(&mut self, bytes: u64) {
        self.line_offset = self.next_offset;
        self.next_offset += bytes;
        self.block_index = 0;
        self.skip_to = std::mem::take(&mut self.skip_next);
        if self.linear {
            // Nothing has jumped yet: every line is new, and what ran is [0, here).
            self.linear_end = self.next_offset;
            return;
        }
        self.again = self.calls.was_read(self.file, self.line_offset);
        self.searched_again = self.calls.seen(self.file, self.line_offset, self.next_offset) && self.calls.search.is_some();
        // A line read by a search is not executed: it counts as read when run.
        if self.calls.search.is_none() {
            self.calls.mark_read(self.file, self.line_offset, self.next_offset);
        }
    }

    /// The first jump or search: from now on the executed stretches are kept one by one (until
    /// then they are the text from its start, read in order).
    fn leave_linear(&mut self) {
        if self.linear {
            self.linear = false;
            if self.linear_end > 0 {
                self.calls.mark_read(0, 0, self.linear_end);
                self.calls.seen(0, 0, self.linear_end);
            }
        }
    }

    /// The runaway guard (docs/reference/macro.md section 6: a loop may never end on the machine): blocks
    /// executed again, and blocks a search reads again, past the limit stop the run. Whether
    /// the run goes on.
    fn guard(&mut self, span: Span, sink: &mut dyn FnMut(Event)) -> bool {
        self.calls.repeated_blocks += 1;
        let max = self.call_options.max_repeated_blocks;
        if self.calls.repeated_blocks <= max {
            return true;
        }
        let d = Diagnostic::new(
            Rule::Runaway,
            self.interp.profile().alarm_style,
            span,
            format!("more than {max} blocks were executed or searched again after jumps back: the programme probably never ends, so ncsight stops here"),
        )
        .with_hint("a programme that really runs this long can be run with a higher --max-blocks");
        self.calls.search = None;
        self.flush_pending(sink);
        self.alarm(d, sink);
        self.status = Status::Alarm;
        self.eof = true;
        false
    }

    /// Ask the driver to go on from `to`.
    fn seek(&mut self, to: Place) {
        self.leave_linear();
        // A text that ended (a DOS end-of-file mark) is read again from the place.
        if self.status != Status::Alarm {
            self.eof = false;
        }
        self.calls.request = Some(crate::program::Request::Seek(to));
        self.file = to.file;
        self.next_offset = to.offset;
        self.line_no = to.line.wrapping_sub(1);
        self.skip_next = to.block;
    }

    /// Call programme O`number` `count` times, back to `back`; `locals` for a G65 call (a new
    /// level of local variables). Whether the rest of the line is interpreted.
    fn call(&mut self, number: u32, count: u32, span: Span, back: Place, locals: Option<macros::Locals>) -> Result<bool, Diagnostic> {
        let profile = self.interp.profile();
        let macro_call = locals.is_some();
        let builder = std::mem::take(&mut self.builder_call);
        let max = profile.calls.max_depth;
        // M98 and G65 nest separately, four levels each (FANUC Series 16i operator's manual,
        // custom macro; GSK980TDi help text, G65).
        let depth = self.calls.nesting(macro_call);
        if depth >= max as usize {
            // FANUC 0 alarm 077 (FANUC 0i-TB/MB operator's manual 12.3: four levels).
            let what = if macro_call { "macro call (G65)" } else { "subprogramme call" };
            return Err(Diagnostic::new(
                Rule::CallNesting,
                profile.alarm_style,
                span,
                format!("O{number:04} would be the {}th nested {what}: {} allows {max} levels", max + 1, profile.name),
            ));
        }
        if let Some(l) = locals {
            self.vars.levels.push(l);
        }
        let start = self.calls.program(self.file, number);
        self.calls.frames.push(Frame { number, start, entry: None, finishing: None, back, remaining: count.max(1) - 1, call: span, macro_call, builder });
        match start {
            Some(p) => {
                self.seek(p);
                Ok(false)
            }
            None => {
                // Not read yet: the blocks that follow are read (not executed) until it is found,
                // then the file from its top, then the driver's other files.
                let scope = Place::start_of(self.file);
                self.leave_linear();
                self.calls.search =
                    Some(Search { target: Target::Program(number), from: back, scope, wrapped: false, once: false, asked_by: span, resume: Some(back) });
                Ok(true)
            }
        }
    }

    /// `M98 Q<n> [L<count>]` (FANUC 0i-F): the running programme's blocks from N`n` to its M99,
    /// `count` times, then on after the calling block. A level of subprogramme nesting as M98 P.
    fn call_sequence(&mut self, n: u32, count: u32, span: Span, back: Place, finishing: Option<crate::interp::FinishRequest>) -> Result<bool, Diagnostic> {
        let profile = self.interp.profile();
        let max = profile.calls.max_depth;
        // A G70 is no call: it is not counted (nor counts, calls::Calls::nesting).
        if self.calls.nesting(false) >= max as usize && finishing.is_none() {
            let msg = format!("M98 Q{n} would be the {}th nested subprogramme call: {} allows {max} levels", max + 1, profile.name);
            return Err(Diagnostic::new(Rule::CallNesting, profile.alarm_style, span, msg));
        }
        // The frame keeps the calling programme's start, so GOTO and M99 P look there.
        let (number, scope) = self.calls.running().map_or((0, Place::start_of(self.file)), |(n, s)| (n.unwrap_or(0), s));
        let entry = self.calls.sequence(scope, n);
        self.calls.frames.push(Frame {
            number,
            start: Some(scope),
            entry,
            finishing,
            back,
            remaining: count.max(1) - 1,
            call: span,
            macro_call: false,
            builder: false,
        });
        if finishing.is_some() {
            self.interp.set_finishing(true);
        }
        match entry {
            Some(p) => {
                self.seek(p);
                Ok(false)
            }
            None => {
                self.leave_linear();
                self.calls.search =
                    Some(Search { target: Target::CallSequence(n), from: back, scope, wrapped: false, once: false, asked_by: span, resume: Some(back) });
                Ok(true)
            }
        }
    }

    /// A call's answer: whether the rest of the line is interpreted, or its alarm (after which a
    /// check goes on and a run stops).
    fn go_on_or_alarm(&mut self, called: Result<bool, Diagnostic>, sink: &mut dyn FnMut(Event)) -> bool {
        called.unwrap_or_else(|d| {
            self.alarm(d, sink);
            self.mode != Mode::Run
        })
    }

    /// A call has ended (its M99, a failed search): its local level and its loops go.
    fn left(&mut self, frame: &Frame) {
        if frame.macro_call && self.vars.levels.len() > 1 {
            self.vars.levels.pop();
        }
        let depth = self.calls.depth();
        self.calls.loops.retain(|l| l.depth <= depth);
    }

    /// The local variable (1-33) an argument word of `code` sets: argument specification I,
    /// and II's repeated I J K counted in `seen` (the later wins: FANUC Series 16i).
    fn argument_slot(&self, w: &Word, seen: &mut [usize; 3], code: &str) -> Result<usize, Diagnostic> {
        let style = self.interp.profile().alarm_style;
        let slot = match w.letter {
            // FANUC 0 alarm 129: G is not an argument.
            b'G' => return Err(Diagnostic::new(Rule::ArgumentAddress, style, w.span, format!("{}: G cannot be a {code} argument", w.text()))),
            b'I' | b'J' | b'K' => {
                let k = (w.letter - b'I') as usize;
                seen[k] += 1;
                4 + k + 3 * (seen[k] - 1)
            }
            // Specification I: A#1 B#2 C#3 D#7 E#8 F#9 H#11 M#13 Q#17 R#18 S#19 T#20 U#21
            // V#22 W#23 X#24 Y#25 Z#26 (GSK980TDi help text, G65; FANUC Series 16i).
            b'A' => 1,
            b'B' => 2,
            b'C' => 3,
            b'D' => 7,
            b'E' => 8,
            b'F' => 9,
            b'H' => 11,
            b'M' => 13,
            l @ b'Q'..=b'Z' => 17 + (l - b'Q') as usize,
            _ => {
                return Err(Diagnostic::new(
                    Rule::ArgumentAddress,
                    style,
                    w.span,
                    format!("{}: {} is not a {code} argument", w.text(), crate::read::address_name(w.letter)),
                ))
            }
        };
        if slot > 33 {
            return Err(Diagnostic::new(Rule::ArgumentAddress, style, w.span, format!("{}: more than ten I J K sets", w.text())));
        }
        Ok(slot)
    }

    /// An argument's value: one written without a point is in least input increments where
    /// the profile reads lengths so (FANUC Series 16i: G65 P9 X10 gives #24 = 0.010); the
    /// whole-number addresses M S T H D and the feed F pass as written (inferred).
    fn argument_value(&self, w: &Word) -> f64 {
        let lii = self.interp.params().integer_lengths() == crate::profile::IntegerLengths::LeastIncrement;
        let increment = if self.interp.state().modes.inch { 1e-4 } else { 1e-3 };
        if !w.decimal && lii && !matches!(w.letter, b'M' | b'S' | b'T' | b'H' | b'D' | b'F') {
            w.value * increment
        } else {
            w.value
        }
    }

    /// The programme, count and locals of `G65 P_ L_ <arguments>` (or G66): a new level of
    /// local variables set from the arguments (FANUC Series 16i operator's manual, custom macro;
    /// GSK980TDi help text, G65).
    fn macro_arguments(&self, block: &Block, g65: usize) -> Result<(u32, u32, macros::Locals), Diagnostic> {
        let profile = self.interp.profile();
        let style = profile.alarm_style;
        let at = block.words[g65].span;
        let code = block.words[g65].text();
        if profile.macros.macro_a && block.words.get(g65 + 1).is_some_and(|w| w.letter == b'H') {
            return Err(Diagnostic::new(Rule::MacroFormat, style, at, format!("{code} H (macro A): write G65 Hm P#i Q#j R#k, the result variable with #")));
        }
        // GSK: G65 is followed directly by P (GSK980TDi help text, G65).
        if profile.macros.p_first && block.words.get(g65 + 1).is_some_and(|w| w.letter != b'P') {
            let w = block.words[g65 + 1];
            return Err(Diagnostic::new(
                Rule::MacroFormat,
                style,
                w.span,
                format!("{}: on {} the programme number P comes right after {code}", w.text(), profile.name),
            ));
        }
        let mut number = None;
        let mut count = 1u32;
        let mut locals: macros::Locals = [None; 33];
        let mut seen = [0usize; 3];
        for (k, w) in block.words.iter().enumerate() {
            if k == g65 {
                continue;
            }
            match w.letter {
                b'P' => {
                    let eight = profile.calls.eight_digit.is_some_and(|k| self.interp.params().get(k) != 0.0);
                    let max = if eight { crate::interp::MAX_PROGRAM_NUMBER_8 } else { crate::interp::MAX_PROGRAM_NUMBER };
                    if w.value < 0.0 || w.value.fract() != 0.0 || w.value > f64::from(max) {
                        return Err(Diagnostic::new(Rule::ValueOutOfRange, style, w.span, format!("{}: the macro's programme number is 1 to {max}", w.text())));
                    }
                    number = Some(w.value as u32);
                }
                b'L' => {
                    if w.value < 1.0 || w.value.fract() != 0.0 || w.value > 9999.0 {
                        return Err(Diagnostic::new(Rule::ValueOutOfRange, style, w.span, format!("{}: the repeat count L is 1 to 9999", w.text())));
                    }
                    count = w.value as u32;
                }
                _ => locals[self.argument_slot(w, &mut seen, &code)? - 1] = Some(self.argument_value(w)),
            }
        }
        let Some(number) = number else {
            return Err(Diagnostic::new(Rule::AddressPMissing, style, at, format!("{code}: the macro to call is not given (P)")));
        };
        Ok((number, count, locals))
    }

    /// M98 or M99 after the block's records. Whether the rest of the line is interpreted.
    fn jump(&mut self, flow: Flow, place: Place, sink: &mut dyn FnMut(Event)) -> bool {
        let profile = self.interp.profile();
        let next = Place { block: place.block.saturating_add(1), ..place };
        match flow {
            Flow::Call { count, span, sequence: Some(n), .. } => {
                let called = self.call_sequence(n, count, Span { file: self.file, ..span }, next, None);
                self.go_on_or_alarm(called, sink)
            }
            // G70 whose blocks no roughing collected (FANUC: read from the programme): its
            // blocks N ns to N nf run as a call by sequence number that ends after N nf.
            Flow::Finish(req) => {
                let called = self.call_sequence(req.ns, 1, Span { file: self.file, ..req.span }, next, Some(req));
                self.go_on_or_alarm(called, sink)
            }
            Flow::Call { number, count, span, sequence: None } => {
                let called = self.call(number, count, Span { file: self.file, ..span }, next, None);
                self.go_on_or_alarm(called, sink)
            }
            Flow::Return { sequence, span } => {
                let Some(frame) = self.calls.frames.last_mut() else {
                    // M99 in the main programme (GSK980TDi help text, M99: it runs again); in a
                    // programme run as if called, the return.
                    if !self.run_as_called {
                        let d = Diagnostic::new(
                            Rule::ProgramLoops,
                            profile.alarm_style,
                            span,
                            "M99 in the main programme: the controller starts it again from the top; the simulation ends here",
                        );
                        sink(Event::Diagnostic(d));
                    }
                    // A move still held (radius compensation) is made before the end.
                    self.flush_pending(sink);
                    let mut end = Record::new(span, Op::End { code: 99 });
                    end.n = self.block_n;
                    end.block_end = true;
                    if self.records() {
                        sink(Event::Record(end));
                    }
                    self.status = Status::Ended;
                    return self.mode != Mode::Run;
                };
                if sequence.is_none() && frame.remaining > 0 {
                    frame.remaining -= 1;
                    let start = frame.entry.or(frame.start).unwrap_or(place);
                    self.seek(start);
                    return false;
                }
                let frame = self.calls.frames.pop().expect("a frame was just seen");
                self.left(&frame);
                match sequence {
                    None => self.seek(frame.back),
                    Some(n) => {
                        // M99 P: to block N of the caller (GSK980TDi help text, M99), looked for
                        // from the calling block on, then from the caller's start.
                        let scope = self.calls.running().map(|(_, s)| s).unwrap_or(Place::start_of(frame.back.file));
                        match self.calls.sequence(scope, n) {
                            Some(p) => self.seek(p),
                            None => {
                                self.leave_linear();
                                self.calls.search = Some(Search {
                                    target: Target::Sequence(n),
                                    from: frame.back,
                                    scope,
                                    wrapped: false,
                                    once: false,
                                    asked_by: span,
                                    resume: Some(frame.back),
                                });
                                self.seek(frame.back);
                            }
                        }
                    }
                }
                false
            }
        }
    }

    /// A block read while a jump looks for its target.
    fn search_step(&mut self, block: Option<&Block>, place: Place, sink: &mut dyn FnMut(Event)) -> Searched {
        let s = self.calls.search.expect("searching");
        if s.wrapped && !s.once && place.file == s.from.file && (place.offset, place.block) >= (s.from.offset, s.from.block) {
            // Round once: it is not in this file.
            self.search_ends(sink);
            return Searched::Stop;
        }
        let Some(b) = block else { return Searched::Passed };
        if let Some(n) = b.program {
            self.calls.note_program(n, place);
        }
        match s.target {
            Target::Program(n) if b.program == Some(n) => {
                self.calls.search = None;
                match self.calls.frames.last_mut() {
                    Some(f) if f.start.is_none() => f.start = Some(place),
                    // The main programme the caller named.
                    _ => self.calls.main = Some((Some(n), place)),
                }
                Searched::Found
            }
            Target::Sequence(_) | Target::Goto(_) | Target::CallSequence(_) | Target::LoopEnd(_) | Target::LoopEndAhead(_)
                if b.program.is_some() && place != s.scope =>
            {
                // The programme's text ends at the next programme's O.
                self.search_ends(sink);
                Searched::Stop
            }
            Target::Sequence(n) | Target::Goto(n) if b.sequence == Some(n) => {
                self.calls.search = None;
                self.calls.note_sequence(s.scope, n, place);
                Searched::Found
            }
            Target::CallSequence(n) if b.sequence == Some(n) => {
                self.calls.search = None;
                self.calls.note_sequence(s.scope, n, place);
                if let Some(f) = self.calls.frames.last_mut() {
                    f.entry = Some(place);
                }
                Searched::Found
            }
            // The END of a loop not run: the search ends past it.
            Target::LoopEnd(label) if b.macro_block.as_ref().is_some_and(|m| m.stmt == Stmt::End { label }) => {
                self.calls.search = None;
                Searched::Passed
            }
            // The END of a loop about to run is there: back to its body.
            Target::LoopEndAhead(label) if b.macro_block.as_ref().is_some_and(|m| m.stmt == Stmt::End { label }) => {
                self.calls.search = None;
                if let Some(body) = s.resume {
                    self.seek(body);
                }
                Searched::Stop
            }
            _ => Searched::Passed,
        }
    }

    /// A search has read to the end of its scope: back to the scope's start once, then (for a
    /// programme) the driver's other files, then it fails.
    fn search_ends(&mut self, sink: &mut dyn FnMut(Event)) {
        let Some(s) = self.calls.search.as_mut() else { return };
        if !s.wrapped && !s.once {
            s.wrapped = true;
            let scope = s.scope;
            self.seek(scope);
            return;
        }
        match s.target {
            Target::Program(number) if !s.once => self.calls.request = Some(Request::Find { number }),
            _ => self.not_found(&[], sink),
        }
    }

    /// The target is nowhere: the controller's alarm (FANUC 0 alarm 078), or with
    /// `skip_missing` a warning and the call does nothing.
    fn not_found(&mut self, passed_over: &[String], sink: &mut dyn FnMut(Event)) {
        let Some(s) = self.calls.search.take() else { return };
        let profile = self.interp.profile();
        let calling = matches!(s.target, Target::Program(_)) && self.calls.frames.last().is_some_and(|f| f.start.is_none());
        let finishing = self.calls.frames.last().is_some_and(|f| f.finishing.is_some());
        let (message, hint) = match s.target {
            // A machine builder's macro (the setup's m_macro, parameters 6050-6089): its
            // resident programme lives in the machine.
            Target::Program(n) if calling && self.calls.frames.last().is_some_and(|f| f.builder) => (
                format!("O{n:04}: the machine's own programme this code calls (the setup's [machine] m_macro, or parameters 6050-6089) is in no file read"),
                "give the folder of the machine's resident programmes with the setup's [machine] library (or --subprogram-dir), or run with --skip-missing-subprograms",
            ),
            Target::Program(n) if calling => (
                format!("O{n:04}: the called programme is in no file read (the programme's own file, the subprogramme directories)"),
                "give the directory that holds it with --subprogram-dir, or run with --skip-missing-subprograms",
            ),
            Target::Program(n) => (format!("O{n:04}: the main programme named is not in the file"), "name a programme the file holds with --main"),
            Target::Sequence(n) => (format!("N{n}: M99 P returns to a block with this sequence number, and the calling programme has none"), "the N of M99 P must be in the calling programme"),
            Target::Goto(n) => (format!("GOTO {n}: the programme has no block N{n}"), "the N of GOTO must be in the same programme"),
            Target::CallSequence(n) if finishing => {
                (format!("G70 P{n}: the programme has no block N{n}"), "G70 P(ns) Q(nf) runs the programme's blocks N ns to N nf")
            }
            Target::CallSequence(n) => (format!("M98 Q{n}: the programme has no block N{n}"), "M98 Q calls a sequence number of the same programme"),
            Target::LoopEnd(m) | Target::LoopEndAhead(m) => (format!("WHILE [..] DO{m}: no END{m} follows in the programme"), "each WHILE [..] DOm ends with ENDm"),
        };
        let message =
            if passed_over.is_empty() { message } else { format!("{message}; passed over, not readable as a programme file: {}", passed_over.join(", ")) };
        if calling && self.call_options.skip_missing {
            let d = Diagnostic::new(Rule::CallSkipped, profile.alarm_style, s.asked_by, format!("{message}: the call is skipped (--skip-missing-subprograms)"));
            sink(Event::Diagnostic(d));
            if let Some(f) = self.calls.frames.pop() {
                self.left(&f);
            }
            if let Some(p) = s.resume {
                self.seek(p);
            }
            return;
        }
        // FANUC 0: 078 for a programme or M99's N, 128 for GOTO's, 124 for a missing END.
        let rule = match s.target {
            Target::Goto(_) => Rule::MacroSequence,
            Target::CallSequence(_) if finishing => Rule::ContourNotFound,
            Target::LoopEnd(_) | Target::LoopEndAhead(_) => Rule::MissingEnd,
            _ => Rule::NumberNotFound,
        };
        let d = Diagnostic::new(rule, profile.alarm_style, s.asked_by, message).with_hint(hint);
        self.flush_pending(sink);
        // A call by sequence number that found none is no call: its frame goes first.
        let sequence_call = matches!(s.target, Target::CallSequence(_));
        if sequence_call && self.leave_finishing().is_none() {
            if let Some(f) = self.calls.frames.pop() {
                self.left(&f);
            }
        }
        self.alarm(d, sink);
        if calling {
            if let Some(f) = self.calls.frames.pop() {
                self.left(&f);
            }
        }
        match s.resume {
            // A check goes on after the block that asked.
            Some(p) if self.mode == Mode::Check => self.seek(p),
            _ => {
                self.status = Status::Alarm;
                self.eof = true;
            }
        }
    }

    /// The running programme's text ends (another programme's O, the end of the text) at
    /// `span`. Whether the rest of the line is interpreted.
    fn text_ends(&mut self, span: Span, sink: &mut dyn FnMut(Event)) -> bool {
        let profile = self.interp.profile();
        self.flush_pending(sink);
        // A G70 running the programme's blocks met the programme's end before N nf: PS0063,
        // then on after the G70 (a check) or the stop.
        if let Some(frame) = self.leave_finishing() {
            let nf = frame.finishing.map_or(0, |r| r.nf);
            let d = Diagnostic::new(Rule::ContourNotFound, profile.alarm_style, frame.call, format!("G70 Q{nf}: the programme ends before block N{nf}"));
            self.alarm(d, sink);
            if self.mode == Mode::Run {
                self.eof = true;
                return false;
            }
            self.seek(frame.back);
            return false;
        }
        let popped = self.calls.frames.pop();
        if let Some(f) = &popped {
            self.left(f);
        }
        match popped {
            None => {
                let d = Diagnostic::new(
                    Rule::NoProgramEnd,
                    profile.alarm_style,
                    span,
                    "the main programme has no end (M02 or M30) before the next programme begins: the controller stops after its last block",
                );
                sink(Event::Diagnostic(d));
                self.status = Status::Ended;
                self.mode != Mode::Run
            }
            Some(frame) => {
                // No manual says what a controller does here (docs/reference/macro.md section 1, inferred): an
                // alarm; a check goes on as if M99 had been there.
                let d = Diagnostic::new(
                    Rule::NoReturn,
                    profile.alarm_style,
                    span,
                    format!("O{:04} ends here without M99: a subprogramme returns with M99", frame.number),
                );
                self.alarm(d, sink);
                if self.mode == Mode::Check {
                    self.seek(frame.back);
                }
                false
            }
        }
    }

    /// The warnings and (if wanted) the records of the outcome buffer, in that order.
    fn pass_on(&mut self, sink: &mut dyn FnMut(Event)) {
        if !self.outcome.warnings.is_empty() {
            for w in self.outcome.warnings.drain(..) {
                // Once per place: a block run again does not repeat its warnings.
                if !self.reported.first(&w) && self.again {
                    continue;
                }
                if w.rule == Rule::IntegerLength {
                    self.increment_warnings += 1;
                    if self.increment_warnings > INCREMENT_WARNINGS_SHOWN {
                        continue;
                    }
                }
                sink(Event::Diagnostic(w));
            }
        }
        let deferred = self.outcome.deferred.take();
        if self.records() && (!self.outcome.records.is_empty() || deferred.is_some()) {
            // A drilling block's deferred holes come where the block laid them out, made one
            // record at a time as they go (a block of any number of pecks holds no more).
            let at = deferred.as_deref().map_or(self.outcome.records.len(), |(at, _)| (*at).min(self.outcome.records.len()));
            let mut rest = self.outcome.records.split_off(at);
            for r in self.outcome.records.drain(..) {
                sink(Event::Record(r));
            }
            if let Some((_, holes)) = deferred.as_deref() {
                holes.each_record(&mut |r| sink(Event::Record(r)));
            }
            for r in rest.drain(..) {
                sink(Event::Record(r));
            }
        }
    }

    fn flush_pending(&mut self, sink: &mut dyn FnMut(Event)) {
        self.interp.flush_pending_into(&mut self.outcome);
        // A flush reports its records, and after them the alarm of a move they make that the
        // machine refuses (beyond a soft limit, a compensated path with no solution).
        let alarms: Vec<Diagnostic> = self.outcome.warnings.drain(..).filter(|d| d.is_alarm()).collect();
        self.pass_on(sink);
        for d in alarms {
            self.alarm(d, sink);
        }
    }

    fn alarm(&mut self, d: Diagnostic, sink: &mut dyn FnMut(Event)) {
        // A check gives an alarm of a block run again once (a run stops at its first anyway).
        if !self.reported.first(&d) && self.again && self.mode == Mode::Check {
            return;
        }
        // The same alarm twice in a row (a held move's, met again when the run stops) once.
        let key = (d.span, d.code);
        if self.last_alarm == Some(key) {
            return;
        }
        self.last_alarm = Some(key);
        self.alarms += 1;
        if self.mode == Mode::Run {
            self.status = Status::Alarm;
        }
        sink(Event::Diagnostic(d));
    }
}

/// Diagnostics already given, by place and code: a block run again (each run of a
/// subprogramme, each turn of a loop) does not repeat them. Bounded: emptied when full.
#[derive(Debug, Default)]
struct Reported {
    seen: std::collections::HashSet<(u16, u32, u32, &'static str)>,
}

impl Reported {
    const MAX: usize = 100_000;

    /// Whether `d` is new (and note it).
    fn first(&mut self, d: &Diagnostic) -> bool {
        if self.seen.len() >= Self::MAX {
            self.seen.clear();
        }
        self.seen.insert((d.span.file, d.span.line, d.span.col, d.code))
    }
}

/// What a search made of a block.
enum Searched {
    /// Not the target: read on.
    Passed,
    /// The target: it is executed.
    Found,
    /// The search moved elsewhere or failed: the rest of the line is not read.
    Stop,
}

/// An event of a block in a called programme or another file: its file and depth set, the
/// call chain on its diagnostics; then on to the machine (records) or the sink.
fn stamped(mut e: Event, chain: &[Span], file: u16, machine: &mut Machine, sink: &mut dyn FnMut(Event)) {
    match &mut e {
        Event::Record(r) => {
            r.span.file = file;
            r.call_depth = chain.len().min(u8::MAX as usize) as u8;
        }
        Event::Diagnostic(d) => {
            d.span.file = file;
            if d.calls.is_empty() && !chain.is_empty() {
                d.calls = chain.into();
            }
        }
    }
    machine.push(e, sink);
}

/// Run a whole text (tests and small inputs): every event in order.
pub fn run_text(params: Params, switches: Switches, mode: Mode, text: &[u8]) -> Vec<Event> {
    run_text_with(params, switches, mode, Options::default(), text)
}

/// [`run_text`] with the operator's actions.
pub fn run_text_with(params: Params, switches: Switches, mode: Mode, operator: Options, text: &[u8]) -> Vec<Event> {
    events(Program::with_operator(params, switches, mode, operator), text).collect()
}

/// The events of a programme text, pulled one at a time by the consumer: a line is read only
/// when the events of the lines before it have been taken, so a consumer that stops early (or
/// reads a huge text lazily) holds one line's events at a time. Jumps go back and forth in the
/// text; a called programme the text lacks is an alarm (see [`events_with_library`]).
pub fn events(program: Program, text: &[u8]) -> Events<'_> {
    events_with_library(program, text, Vec::new())
}

/// [`events`] with other texts, by name, where a called programme the text lacks is looked for
/// (what `--subprogram-dir` gives the command line).
pub fn events_with_library<'a>(program: Program, text: &'a [u8], library: Vec<(String, &'a [u8])>) -> Events<'a> {
    let mut program = program;
    let mut scan = program.leader_scan();
    for line in text.split_inclusive(|&b| b == b'\n') {
        if scan.push(line) {
            break;
        }
    }
    program.set_tape_leader(scan.lines());
    program.set_deferred_blocks(false);
    Events { program, texts: vec![text], library, at: (0, 0), queue: std::collections::VecDeque::new(), finished: false }
}

/// See [`events`].
pub struct Events<'a> {
    program: Program,
    /// The texts being read, by file number (0: the main text).
    texts: Vec<&'a [u8]>,
    library: Vec<(String, &'a [u8])>,
    /// The text and the byte offset of the next line.
    at: (usize, usize),
    queue: std::collections::VecDeque<Event>,
    finished: bool,
}

impl Events<'_> {
    /// The programme being run (its status, its time so far).
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// Where the run asks to read next, taken from the programme.
    fn follow(&mut self, request: Request) {
        match request {
            Request::Seek(p) => self.at = (p.file as usize, p.offset as usize),
            Request::Find { number } => {
                let reader = self.program.line_reader();
                let mut numbers = Vec::new();
                let holds = |text: &[u8], numbers: &mut Vec<u32>| {
                    text.split_inclusive(|&b| b == b'\n').any(|l| {
                        numbers.clear();
                        reader.program_numbers(l, numbers);
                        numbers.contains(&number)
                    })
                };
                // A file opened before is looked in again: its search stopped at the programme it
                // was opened for, so a later one in it was not noted.
                let found = (0..self.library.len()).find(|i| holds(self.library[*i].1, &mut numbers));
                match found {
                    Some(i) => {
                        let file = self.program.open_file(self.library[i].0.clone());
                        if self.texts.len() <= file as usize {
                            self.texts.resize(file as usize + 1, &[]);
                        }
                        self.texts[file as usize] = self.library[i].1;
                    }
                    None => {
                        let Events { program, queue, .. } = self;
                        program.no_file(&mut |e| queue.push_back(e));
                    }
                }
            }
        }
    }
}

impl Iterator for Events<'_> {
    type Item = Event;

    fn next(&mut self) -> Option<Event> {
        loop {
            if let Some(e) = self.queue.pop_front() {
                return Some(e);
            }
            if self.finished {
                return None;
            }
            if let Some(r) = self.program.take_request() {
                self.follow(r);
                continue;
            }
            let (file, offset) = self.at;
            let text = self.texts.get(file).copied().unwrap_or(&[]);
            let rest = text.get(offset..).unwrap_or(&[]);
            let Events { program, queue, .. } = self;
            if rest.is_empty() || !program.wants_more() {
                match program.end_of_text(&mut |e| queue.push_back(e)) {
                    Some(r) => self.follow(r),
                    None => self.finished = true,
                }
                continue;
            }
            let len = rest.iter().position(|&b| b == b'\n').map_or(rest.len(), |k| k + 1);
            program.feed_line(&rest[..len], &mut |e| queue.push_back(e));
            self.at.1 += len;
        }
    }
}

/// Macro A's operation H`h` on #j and #k (`old`: #i before, for H26), as the GSK980TDi's G65 H
/// list gives them; `span` the block's, `h_span` the H word's.
fn macro_a_operation(h: i64, j: f64, k: f64, old: f64, style: crate::alarm::AlarmStyle, span: Span, h_span: Span) -> Result<f64, Diagnostic> {
    use crate::read::expr::{eval, Func, Node};
    let func = |f: Func, x: f64| -> Result<f64, Diagnostic> {
        let mut a = crate::read::expr::Arena::default();
        a.nodes.push(Node::Num(x));
        a.nodes.push(Node::Call(f, 0));
        Ok(eval(&a, 1, &mut crate::read::expr::NoVariables).map_err(|e| macros::expr_alarm(style, span, &e))?.unwrap_or(0.0))
    };
    let divide = |a: f64, b: f64| {
        if b == 0.0 {
            Err(Diagnostic::new(Rule::DivideByZero, style, span, "G65 H: division by zero".to_string()))
        } else {
            Ok(a / b)
        }
    };
    let whole = |v: f64| v.round() as i64;
    let v = match h {
        1 => j,
        2 => j + k,
        3 => j - k,
        4 => j * k,
        5 => divide(j, k)?,
        11 => (whole(j) | whole(k)) as f64,
        12 => (whole(j) & whole(k)) as f64,
        13 => (whole(j) ^ whole(k)) as f64,
        21 => func(Func::Sqrt, j)?,
        22 => j.abs(),
        23 => {
            if k == 0.0 {
                return Err(Diagnostic::new(Rule::DivideByZero, style, span, "G65 H23: remainder of a division by zero".to_string()));
            }
            j % k
        }
        24 => func(Func::Bin, j)?,
        25 => func(Func::Bcd, j)?,
        26 => divide(old * j, k)?,
        27 => (j * j + k * k).sqrt(),
        31 => j * func(Func::Sin, k)?,
        32 => j * func(Func::Cos, k)?,
        33 => j * func(Func::Tan, k)?,
        34 => {
            let deg = j.atan2(k).to_degrees();
            if deg < 0.0 {
                deg + 360.0
            } else {
                deg
            }
        }
        _ => {
            return Err(Diagnostic::new(
                Rule::MacroFormat,
                style,
                h_span,
                format!("H{h}: no such macro A operation (H01-H05, H11-H13, H21-H27, H31-H34, H80-H86, H99)"),
            ))
        }
    };
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile;

    /// Lines fed through a packed batch give the events that feeding them one by one gives:
    /// reader alarms, line warnings, comments, several blocks on a line, block delete, N and O
    /// numbers, an unclosed comment, text after `%`, a BOM, a DOS end-of-file mark.
    #[test]
    fn a_batch_feeds_as_lines_do() {
        let text: &[u8] = b"\xEF\xBB\xBF% tape\nO0012 (PART 12)\nN10 G00 X10. Z2. ; (tool) ; N11 G01 Z-5. F0.1\n/N12 X1\nG0 X#1\nX-4.5.Z0.\n(open comment\nG0 X1 (FURA\x80AO) Z1\nGO X0.\nN20 G4 P100\n\nM30\nG0 X5\n\x1A\nG0 X9\n";
        for machine in ["gsk980tdi", "fanuc0t", "fanuc0m"] {
            for mode in [Mode::Run, Mode::Check] {
                let params = || Params::defaults(profile::by_name(machine).unwrap());
                let expected = run_text(params(), Switches::default(), mode, text);
                let mut program = Program::new(params(), Switches::default(), mode);
                let reader = program.line_reader();
                let mut batch = ReadBatch::default();
                let lines: Vec<&[u8]> = text.split_inclusive(|&b| b == b'\n').collect();
                let mut events = Vec::new();
                // Two batches, the second reusing the first one's buffers.
                for part in lines.chunks(7) {
                    batch.clear();
                    let first = program.core.line_no;
                    for (k, l) in part.iter().enumerate() {
                        batch.push(&reader, first + 1 + k as u32, l);
                    }
                    for i in 0..batch.len() {
                        program.feed_from(&batch, i, &mut |e| events.push(e));
                    }
                }
                program.finish(&mut |e| events.push(e));
                assert_eq!(events, expected, "{machine} {mode:?}");
            }
        }
    }
}
