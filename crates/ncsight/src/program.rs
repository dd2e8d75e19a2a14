//! A programme run: lines in, events out, one line at a time, so that nothing holds the
//! programme or its motion in memory. The caller owns all I/O.
//!
//! Two modes, as the interface specifies:
//! - `Mode::Run` stops at the first alarm, exactly as the controller does (the alarm is the last
//!   event), and stops reading at the programme end.
//! - `Mode::Check` reports every problem: a block that alarms is left out (the modal state stays as
//!   it was) and reading goes on; blocks after the programme end are still read for their syntax.

use crate::alarm::{Diagnostic, Rule};
use crate::interp::{Interpreter, Switches};
use crate::machine::{Machine, Options};
use crate::motion::Record;
use crate::profile::Params;
use crate::read::Reader;
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
    reader: Reader,
    interp: Interpreter,
    machine: Machine,
    mode: Mode,
    line_no: u32,
    status: Status,
    eof: bool,
    warned_after_end: bool,
    alarms: usize,
    /// Span of the last block read (for the end-of-input warning).
    last_span: Span,
    /// Events of the line being read, reused.
    buffer: Vec<Event>,
}

impl Program {
    pub fn new(params: Params, switches: Switches, mode: Mode) -> Program {
        Program::with_operator(params, switches, mode, Options::default())
    }

    /// A run with the operator's actions (single block, feed hold, reset, dry run, overrides).
    pub fn with_operator(params: Params, switches: Switches, mode: Mode, operator: Options) -> Program {
        let style = params.profile().alarm_style;
        Program {
            reader: Reader::new(style),
            machine: Machine::new(&params, operator),
            interp: Interpreter::new(params, switches),
            mode,
            line_no: 0,
            status: Status::Running,
            eof: false,
            warned_after_end: false,
            alarms: 0,
            last_span: Span::new(1, 1, 1),
            buffer: Vec::new(),
        }
    }

    pub fn interpreter(&self) -> &Interpreter {
        &self.interp
    }

    pub fn status(&self) -> Status {
        self.status
    }

    /// Alarms reported so far.
    pub fn alarm_count(&self) -> usize {
        self.alarms
    }

    /// Whether more lines can change anything.
    pub fn wants_more(&self) -> bool {
        !self.eof && !self.machine.is_reset() && (self.mode == Mode::Check || self.status == Status::Running)
    }

    /// Seconds from programme start so far (the cycle time once the input has ended).
    pub fn time_s(&self) -> f64 {
        self.machine.time_s()
    }

    /// Feed the next line (with or without its line break).
    pub fn feed_line(&mut self, raw: &[u8], sink: &mut dyn FnMut(Event)) {
        self.line_no += 1;
        if !self.wants_more() {
            return;
        }
        let mut events = std::mem::take(&mut self.buffer);
        self.interpret_line(raw, &mut |e| events.push(e));
        for e in events.drain(..) {
            self.machine.push(e, sink);
        }
        self.buffer = events;
    }

    /// Read and interpret one line; the events are untimed.
    fn interpret_line(&mut self, raw: &[u8], sink: &mut dyn FnMut(Event)) {
        let line = self.reader.read_line(self.line_no, raw);
        for w in line.warnings {
            sink(Event::Diagnostic(w));
        }
        if line.end_of_file {
            self.eof = true;
        }
        for item in line.blocks {
            let block = match item {
                Ok(b) => b,
                Err(d) => {
                    self.flush_pending(sink);
                    self.alarm(d, sink);
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
            match self.interp.execute(&block) {
                Ok(out) => {
                    for w in out.warnings {
                        sink(Event::Diagnostic(w));
                    }
                    for r in out.records {
                        sink(Event::Record(r));
                    }
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
                }
            }
        }
    }

    fn flush_pending(&mut self, sink: &mut dyn FnMut(Event)) {
        for r in self.interp.flush_pending().records {
            sink(Event::Record(r));
        }
    }

    fn alarm(&mut self, d: Diagnostic, sink: &mut dyn FnMut(Event)) {
        self.alarms += 1;
        if self.mode == Mode::Run {
            self.status = Status::Alarm;
        }
        sink(Event::Diagnostic(d));
    }

    /// The input has ended. Without M02/M30 the controller would wait at the last block; say so.
    pub fn finish(&mut self, sink: &mut dyn FnMut(Event)) {
        let mut events = Vec::new();
        if self.status != Status::Alarm && !self.machine.is_reset() {
            self.flush_pending(&mut |e| events.push(e));
        }
        if self.status == Status::Running && !self.machine.is_reset() {
            let d = Diagnostic::new(
                Rule::NoProgramEnd,
                self.interp.profile().alarm_style,
                self.last_span,
                "the programme has no end (M02 or M30): the controller stops after the last block",
            );
            events.push(Event::Diagnostic(d));
        }
        for e in events {
            self.machine.push(e, sink);
        }
        self.machine.finish(sink);
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
