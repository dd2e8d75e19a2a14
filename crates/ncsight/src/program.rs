//! A programme run: lines in, events out, one line at a time, so that nothing holds the
//! programme or its motion in memory. The caller owns all I/O.
//!
//! Two modes, as the interface specifies:
//! - `Mode::Run` stops at the first alarm, exactly as the controller does (the alarm is the last
//!   event), and stops reading at the programme end.
//! - `Mode::Check` reports every problem: a block that alarms is left out (the modal state stays as
//!   it was) and reading goes on; blocks after the programme end are still read for their syntax.

use crate::alarm::{Diagnostic, Rule};
use crate::dialect::Foreign;
use crate::interp::{Interpreter, Outcome, Switches};
use crate::machine::{Machine, Options};
use crate::profile::Params;
use crate::read::{Block, Line, Reader, Word};
use crate::source::Span;

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
    /// Read line `line_no` (1-based, with or without its line break) into `out`, reusing its
    /// allocations.
    fn read(&self, line_no: u32, raw: &[u8], out: &mut ReadLine) {
        out.line_no = line_no;
        out.len = raw.len();
        // Another control's programme gets one answer, not a cascade of alarms (issue 10). Its
        // signs come early or carry `$ @ = <`; only such lines are looked at.
        out.foreign = None;
        if line_no <= 100 || raw.iter().any(|b| matches!(b, b'$' | b'@' | b'=' | b'<')) {
            out.foreign = crate::dialect::sniff(raw);
        }
        if out.foreign.is_none() {
            self.reader.read_line_into(line_no, raw, &mut out.line);
        }
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
    /// The reader's line buffers.
    scratch: ReadLine,
}

#[derive(Debug, Clone, Copy)]
struct PackedLine {
    line_no: u32,
    len: usize,
    foreign: Option<Foreign>,
    /// Index ranges into the batch's blocks and diagnostics (the line's warnings).
    blocks: (u32, u32),
    warnings: (u32, u32),
    end_of_file: bool,
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
                    }
                }
                Ok(b) => {
                    let first_word = index(&self.words);
                    self.words.extend_from_slice(&b.words);
                    let comments = (!b.comments.is_empty()).then(|| {
                        self.comments.push(b.comments.clone());
                        index(&self.comments) - 1
                    });
                    PackedBlock {
                        error: None,
                        span: b.span,
                        block_delete: b.block_delete,
                        sequence: b.sequence,
                        program: b.program,
                        words: (first_word, index(&self.words)),
                        comments,
                    }
                }
            };
            self.blocks.push(packed);
        }
        self.lines.push(PackedLine {
            line_no,
            len: r.len,
            foreign: r.foreign,
            blocks: (first_block, index(&self.blocks)),
            warnings,
            end_of_file: r.line.end_of_file,
        });
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
    }
}

impl Program {
    pub fn new(params: Params, switches: Switches, mode: Mode) -> Program {
        Program::with_operator(params, switches, mode, Options::default())
    }

    /// A run with the operator's actions (single block, feed hold, reset, dry run, overrides).
    pub fn with_operator(params: Params, switches: Switches, mode: Mode, operator: Options) -> Program {
        let style = params.profile().alarm_style;
        Program {
            machine: Machine::new(&params, operator),
            block: Block::default(),
            core: Core {
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
                outcome: Outcome::default(),
            },
        }
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

    pub fn status(&self) -> Status {
        self.core.status
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

    /// Feed the next line (with or without its line break).
    pub fn feed_line(&mut self, raw: &[u8], sink: &mut dyn FnMut(Event)) {
        if !self.wants_more() {
            self.core.line_no = self.core.line_no.wrapping_add(1);
            return;
        }
        let mut read = std::mem::take(&mut self.core.read);
        self.core.reader.read(self.core.line_no.wrapping_add(1), raw, &mut read);
        self.feed_read(&mut read, sink);
        self.core.read = read;
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
        if !self.wants_more() {
            return;
        }
        let Program { core, machine, block } = self;
        if core.records() {
            core.interpret_packed(batch, &l, block, &mut |e| machine.push(e, sink));
        } else {
            core.interpret_packed(batch, &l, block, sink);
        }
    }

    fn feed_read(&mut self, read: &mut ReadLine, sink: &mut dyn FnMut(Event)) {
        debug_assert_eq!(read.line_no, self.core.line_no.wrapping_add(1), "lines fed out of order");
        self.core.line_no = read.line_no;
        if !self.wants_more() {
            return;
        }
        let Program { core, machine, .. } = self;
        if core.records() {
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
        if self.begin_line(read.foreign, read.len, line.warnings.drain(..), line.end_of_file, sink) {
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
        warnings: impl Iterator<Item = Diagnostic>,
        end_of_file: bool,
        sink: &mut dyn FnMut(Event),
    ) -> bool {
        if let Some(f) = foreign {
            let profile = self.interp.profile();
            let d = Diagnostic::new(
                Rule::ForeignDialect,
                profile.alarm_style,
                Span::new(self.line_no, 1, len.clamp(1, 80) as u32),
                format!("this looks like {}, not a programme for {} ({}): its words mean other things there, so ncsight stops here", f.name(), profile.name, profile.title),
            )
            .with_hint("run it on the profile of the control it was written for");
            self.alarm(d, sink);
            // Both modes stop: reading on would only repeat the same answer.
            self.status = Status::Alarm;
            self.eof = true;
            return false;
        }
        for w in warnings {
            sink(Event::Diagnostic(w));
        }
        if end_of_file {
            self.eof = true;
        }
        true
    }

    /// A line of a batch, its blocks set one by one into a block kept for reuse.
    fn interpret_packed(&mut self, batch: &ReadBatch, l: &PackedLine, block: &mut Block, sink: &mut dyn FnMut(Event)) {
        let warnings = batch.diagnostics[l.warnings.0 as usize..l.warnings.1 as usize].iter().cloned();
        if !self.begin_line(l.foreign, l.len, warnings, l.end_of_file, sink) {
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
    /// to be interpreted (a run stops at its first alarm and at the programme end).
    fn interpret_item(&mut self, item: Result<&Block, &Diagnostic>, sink: &mut dyn FnMut(Event)) -> bool {
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
        if self.status == Status::Ended {
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
        match self.interp.execute_into(block, &mut self.outcome) {
            Ok(()) => {
                self.pass_on(sink);
                if self.interp.state().ended {
                    self.status = Status::Ended;
                    if self.mode == Mode::Run {
                        return false;
                    }
                }
            }
            Err(d) => {
                // The thread being cut when the next block alarms is finished first.
                self.flush_pending(sink);
                self.alarm(d, sink);
                if self.mode == Mode::Run {
                    return false;
                }
                // A programme end inside an unfinished contour still ends the programme.
                if self.interp.state().ended {
                    self.status = Status::Ended;
                }
            }
        }
        true
    }

    /// The warnings and (if wanted) the records of the outcome buffer, in that order.
    fn pass_on(&mut self, sink: &mut dyn FnMut(Event)) {
        if !self.outcome.warnings.is_empty() {
            for w in self.outcome.warnings.drain(..) {
                if w.rule == Rule::IntegerLength {
                    self.increment_warnings += 1;
                    if self.increment_warnings > INCREMENT_WARNINGS_SHOWN {
                        continue;
                    }
                }
                sink(Event::Diagnostic(w));
            }
        }
        if self.records() && !self.outcome.records.is_empty() {
            for r in self.outcome.records.drain(..) {
                sink(Event::Record(r));
            }
        }
    }

    fn flush_pending(&mut self, sink: &mut dyn FnMut(Event)) {
        self.interp.flush_pending_into(&mut self.outcome);
        self.outcome.warnings.clear(); // a flush reports its records only
        self.pass_on(sink);
    }

    fn alarm(&mut self, d: Diagnostic, sink: &mut dyn FnMut(Event)) {
        self.alarms += 1;
        if self.mode == Mode::Run {
            self.status = Status::Alarm;
        }
        sink(Event::Diagnostic(d));
    }
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
/// reads a huge text lazily) holds one line's events at a time.
pub fn events(program: Program, text: &[u8]) -> Events<'_> {
    Events { program, lines: text.split_inclusive(|&b| b == b'\n'), queue: std::collections::VecDeque::new(), finished: false }
}

/// See [`events`].
pub struct Events<'a> {
    program: Program,
    lines: std::slice::SplitInclusive<'a, u8, fn(&u8) -> bool>,
    queue: std::collections::VecDeque<Event>,
    finished: bool,
}

impl Events<'_> {
    /// The programme being run (its status, its time so far).
    pub fn program(&self) -> &Program {
        &self.program
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
            let Events { program, lines, queue, finished } = self;
            match lines.next().filter(|_| program.wants_more()) {
                Some(line) => program.feed_line(line, &mut |e| queue.push_back(e)),
                None => {
                    program.finish(&mut |e| queue.push_back(e));
                    *finished = true;
                }
            }
        }
    }
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
