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
use crate::motion::Record;
use crate::profile::Params;
use crate::read::{Line, Reader};
use crate::source::Span;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    Run,
    Check,
}

/// What the run produced, in programme order.
#[derive(Debug, Clone, PartialEq)]
pub enum Event {
    Record(Record),
    Diagnostic(Diagnostic),
}

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
}

/// Everything but the operator machine: reading and interpreting, with buffers reused from line
/// to line so that the steady state allocates nothing.
struct Core {
    reader: Reader,
    interp: Interpreter,
    mode: Mode,
    /// Records are passed on (through the machine); off for a diagnostics-only check.
    records: bool,
    line_no: u32,
    status: Status,
    eof: bool,
    warned_after_end: bool,
    alarms: usize,
    /// Span of the last block read (for the end-of-input warning).
    last_span: Span,
    read: ReadLine,
    outcome: Outcome,
}

/// One line read ahead of its interpretation: the reader's blocks and the look for another
/// control's language. Reading needs nothing of the modal state, so a caller may read lines on
/// another thread while the programme interprets earlier ones (the command line does).
#[derive(Debug, Default)]
pub struct ReadLine {
    line_no: u32,
    line: Line,
    foreign: Option<Foreign>,
    /// The line's length in bytes (for the span of a foreign-language answer).
    len: usize,
}

/// Reads lines into [`ReadLine`]s for a [`Program`]; cheap to clone and to send to a thread.
#[derive(Debug, Clone)]
pub struct LineReader {
    reader: Reader,
}

impl LineReader {
    /// Read line `line_no` (1-based, with or without its line break) into `out`, reusing its
    /// allocations.
    pub fn read(&self, line_no: u32, raw: &[u8], out: &mut ReadLine) {
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

impl Program {
    pub fn new(params: Params, switches: Switches, mode: Mode) -> Program {
        Program::with_operator(params, switches, mode, Options::default())
    }

    /// A run with the operator's actions (single block, feed hold, reset, dry run, overrides).
    pub fn with_operator(params: Params, switches: Switches, mode: Mode, operator: Options) -> Program {
        let style = params.profile().alarm_style;
        Program {
            machine: Machine::new(&params, operator),
            core: Core {
                reader: Reader::new(style),
                interp: Interpreter::new(params, switches),
                mode,
                records: true,
                line_no: 0,
                status: Status::Running,
                eof: false,
                warned_after_end: false,
                alarms: 0,
                last_span: Span::new(1, 1, 1),
                read: ReadLine::default(),
                outcome: Outcome::default(),
            },
        }
    }

    /// Check mode that passes on only the diagnostics: records are neither timed nor passed on
    /// (the same diagnostics as [`Mode::Check`], without the time model's work).
    pub fn diagnostics_only(params: Params, switches: Switches) -> Program {
        let mut p = Program::new(params, switches, Mode::Check);
        p.core.records = false;
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
            self.core.line_no += 1;
            return;
        }
        let mut read = std::mem::take(&mut self.core.read);
        self.line_reader().read(self.core.line_no + 1, raw, &mut read);
        self.feed_read(&mut read, sink);
        self.core.read = read;
    }

    /// A reader for the lines of this programme (see [`ReadLine`]).
    pub fn line_reader(&self) -> LineReader {
        LineReader { reader: self.core.reader.clone() }
    }

    /// Feed the next line, read ahead by [`LineReader::read`]; lines must come in order, each
    /// once. The [`ReadLine`] may be reused for a later line.
    pub fn feed_read(&mut self, read: &mut ReadLine, sink: &mut dyn FnMut(Event)) {
        debug_assert_eq!(read.line_no, self.core.line_no + 1, "lines fed out of order");
        self.core.line_no = read.line_no;
        if !self.wants_more() {
            return;
        }
        let Program { core, machine } = self;
        if core.records {
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
        if c.status == Status::Running && !self.machine.is_reset() {
            let d = Diagnostic::new(
                Rule::NoProgramEnd,
                c.interp.profile().alarm_style,
                c.last_span,
                "the programme has no end (M02 or M30): the controller stops after the last block",
            );
            events.push(Event::Diagnostic(d));
        }
        if !c.records {
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
    /// Interpret one line read ahead; the events are untimed.
    fn interpret_read(&mut self, read: &mut ReadLine, sink: &mut dyn FnMut(Event)) {
        if let Some(f) = read.foreign {
            let profile = self.interp.profile();
            let d = Diagnostic::new(
                Rule::ForeignDialect,
                profile.alarm_style,
                Span::new(self.line_no, 1, read.len.clamp(1, 80) as u32),
                format!("this looks like {}, not a programme for {} ({}): its words mean other things there, so ncsight stops here", f.name(), profile.name, profile.title),
            )
            .with_hint("run it on the profile of the control it was written for");
            self.alarm(d, sink);
            // Both modes stop: reading on would only repeat the same answer.
            self.status = Status::Alarm;
            self.eof = true;
            return;
        }
        self.interpret_blocks(&mut read.line, sink);
    }

    fn interpret_blocks(&mut self, line: &mut Line, sink: &mut dyn FnMut(Event)) {
        for w in line.warnings.drain(..) {
            sink(Event::Diagnostic(w));
        }
        if line.end_of_file {
            self.eof = true;
        }
        for item in &line.blocks {
            let block = match item {
                Ok(b) => b,
                Err(d) => {
                    self.flush_pending(sink);
                    self.alarm(d.clone(), sink);
                    if self.mode == Mode::Run {
                        return;
                    }
                    continue;
                }
            };
            if block.is_empty() {
                continue;
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
                continue;
            }
            match self.interp.execute_into(block, &mut self.outcome) {
                Ok(()) => {
                    self.pass_on(sink);
                    if self.interp.state().ended {
                        self.status = Status::Ended;
                        if self.mode == Mode::Run {
                            return;
                        }
                    }
                }
                Err(d) => {
                    // The thread being cut when the next block alarms is finished first.
                    self.flush_pending(sink);
                    self.alarm(d, sink);
                    if self.mode == Mode::Run {
                        return;
                    }
                    // A programme end inside an unfinished contour still ends the programme.
                    if self.interp.state().ended {
                        self.status = Status::Ended;
                    }
                }
            }
        }
    }

    /// The warnings and (if wanted) the records of the outcome buffer, in that order.
    fn pass_on(&mut self, sink: &mut dyn FnMut(Event)) {
        for w in self.outcome.warnings.drain(..) {
            sink(Event::Diagnostic(w));
        }
        if self.records {
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
    let mut program = Program::with_operator(params, switches, mode, operator);
    let mut events = Vec::new();
    for line in text.split_inclusive(|&b| b == b'\n') {
        program.feed_line(line, &mut |e| events.push(e));
        if !program.wants_more() {
            break;
        }
    }
    program.finish(&mut |e| events.push(e));
    events
}
