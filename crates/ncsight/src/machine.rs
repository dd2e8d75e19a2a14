//! The operator machine: it runs the canonical stream in time (the time model of `time.rs`)
//! and carries out what the operator does: single block, FEED HOLD then CYCLE START, RESET,
//! dry run and the overrides. It consumes the same records as every other consumer and changes
//! the path only where the controller itself would (a hold splits a move, a thread hold pulls
//! out and returns); it is not a second interpreter.
//!
//! What each record does under FEED HOLD is decided by the interpreter from the manuals and
//! carried on the record ([`Hold`]); this file only executes it:
//! - `Hold::Stop`: decelerate to a stop where the tool is (its time constant), stop, then CYCLE
//!   START finishes the move.
//! - `Hold::AfterRecord`: stop when the record ends (G04, TDi help G04 note 5).
//! - `Hold::AfterRun`: stop when the synchronised run or tapping cycle ends (seed 001 G32.1
//!   note 6, G92.1 note 7; seed 003 on G74/G84).
//! - `Hold::ThreadCycle`: the G92 thread hold (seed 000 note 1, seed 004): pull out (thread up)
//!   at once and return to the start point A, or finish the thread first, per NO.0018 bit 6 or
//!   #6019 D7; CYCLE START then cuts the interrupted cycle again from its start, in the same
//!   groove (the records are the same, so is the spindle angle).

use crate::alarm::{AlarmStyle, Diagnostic, Rule};
use crate::cycles::thread::{phase_after, wrap_deg};
use crate::event::Event;
use crate::geom;
use crate::geom::arc_geom_of;
use crate::motion::{Hold, Op, Record, StopReason, ThreadHold, ThreadHoldStyle, Vec3};
use crate::profile::Params;
use crate::time::{Overrides, TimeModel};

/// What the operator does during the run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Options {
    /// Single-block mode: a stop after each block (each whole cycle, each hole, each run of
    /// continuous threads).
    pub single_block: bool,
    /// Times (s from programme start) at which FEED HOLD is pressed; CYCLE START follows as soon
    /// as the machine has stopped.
    pub feed_hold_at: Vec<f64>,
    /// Time at which RESET is pressed.
    pub reset_at: Option<f64>,
    pub overrides: Overrides,
}

/// The operator machine.
pub struct Machine {
    model: TimeModel,
    single_block: bool,
    holds: Vec<f64>,
    reset_at: Option<f64>,
    style: AlarmStyle,
    t: f64,
    /// A hold was pressed and waits for the end of a run (`Hold::AfterRun`).
    deferred: bool,
    /// Records of the four-step cycle being cut, for the restart after a thread hold.
    cycle_buf: Vec<Record>,
    cycle_id: Option<u32>,
    /// Where the last record ended and whether it was a thread (for a run's acceleration).
    last_thread_end: Option<Vec3>,
    /// How long the last record run took (a rotary turn made with it takes only the rest).
    last_duration_s: f64,
    /// The tool in the spindle or turret (a change to another costs `tool_change_s`).
    tool: Option<u32>,
    reset: bool,
    last_span: crate::source::Span,
    /// Records a thread hold makes the machine cut again, in order: a queue, not recursion, so
    /// any number of presses runs in constant stack.
    again: std::collections::VecDeque<Record>,
}

impl Machine {
    pub fn new(params: &Params, opts: Options) -> Machine {
        let mut holds = opts.feed_hold_at.clone();
        holds.sort_by(f64::total_cmp);
        Machine {
            model: TimeModel::new(params, opts.overrides),
            single_block: opts.single_block,
            holds,
            reset_at: opts.reset_at,
            style: params.profile().alarm_style,
            t: 0.0,
            deferred: false,
            cycle_buf: Vec::new(),
            cycle_id: None,
            last_thread_end: None,
            last_duration_s: 0.0,
            tool: None,
            reset: false,
            last_span: Default::default(),
            again: std::collections::VecDeque::new(),
        }
    }

    /// Seconds from programme start so far.
    pub fn time_s(&self) -> f64 {
        self.t
    }

    /// RESET was carried out: nothing more runs.
    pub fn is_reset(&self) -> bool {
        self.reset
    }

    /// Take the next event of the interpreter.
    pub fn push(&mut self, e: Event, out: &mut dyn FnMut(Event)) {
        if self.reset {
            return;
        }
        match e {
            Event::Diagnostic(d) => out(Event::Diagnostic(d)),
            Event::Record(r) => {
                self.last_span = r.span;
                if r.cycle != self.cycle_id {
                    self.cycle_buf.clear();
                    self.cycle_id = r.cycle;
                }
                if r.cycle.is_some() {
                    self.cycle_buf.push(r.clone());
                }
                self.run(r, out);
            }
        }
    }

    /// The input has ended: say so about buttons that were never reached.
    pub fn finish(&mut self, out: &mut dyn FnMut(Event)) {
        if self.reset {
            return;
        }
        let late: Vec<String> = self.holds.iter().map(|h| format!("FEED HOLD at {h} s")).chain(self.reset_at.map(|r| format!("RESET at {r} s"))).collect();
        if !late.is_empty() {
            let msg = format!("{}: the programme had ended at {:.3} s", late.join(", "), self.t);
            out(Event::Diagnostic(Diagnostic::new(Rule::NotReached, self.style, self.last_span, msg)));
        }
    }

    fn stop(&mut self, span: crate::source::Span, reason: StopReason, out: &mut dyn FnMut(Event)) {
        let mut r = Record::new(span, Op::Stop { reason });
        r.t_s = self.t;
        out(Event::Record(r));
    }

    fn emit(&mut self, mut r: Record, dur: f64, out: &mut dyn FnMut(Event)) {
        self.t += dur;
        r.t_s = self.t;
        self.last_thread_end = if r.op.is_thread() { r.op.end_point() } else { None };
        out(Event::Record(r));
    }

    /// Run a record, and the records a thread hold makes it cut again (a queue, not recursion:
    /// any number of presses runs in constant stack).
    fn run(&mut self, r: Record, out: &mut dyn FnMut(Event)) {
        self.run_one(r, out);
        while let Some(r) = self.again.pop_front() {
            self.run_one(r, out);
        }
    }

    /// Run one record in time: a deferred hold before it, its duration, then RESET or FEED HOLD
    /// if pressed while it runs, else the record whole.
    fn run_one(&mut self, r: Record, out: &mut dyn FnMut(Event)) {
        if self.reset {
            return;
        }
        // A deferred hold ends where the run ends: before a record that is not part of it.
        if self.deferred && matches!(r.hold, Hold::Stop | Hold::AfterRecord) {
            self.deferred = false;
            self.stop(r.span, StopReason::FeedHold, out);
        }
        let run_start = r.op.is_thread() && self.last_thread_end != r.op.start_point();
        let mut dur = self.model.duration_after_s(&r, run_start, self.last_duration_s);
        if let Op::Tool { number, .. } = r.op {
            if self.tool.replace(number) != Some(number) {
                dur += self.model.tool_change_s();
            }
        }
        // The time the block's simultaneous motion has taken so far (a rotary turn made with
        // the records before it adds only what they do not cover).
        self.last_duration_s = if matches!(r.op, Op::Rotary { with_move: true, .. }) { self.last_duration_s + dur } else { dur };
        let start = self.t;
        let end = start + dur;
        if let Some(tr) = self.reset_at.filter(|tr| *tr < end || (*tr <= start)) {
            self.reset_at = None;
            self.reset = true;
            self.reset_during(r, start, dur, tr, out);
            return;
        }
        let hold_now = self.holds.first().copied().filter(|h| *h < end || *h <= start);
        let Some(h) = hold_now else {
            return self.finish_record(r, dur, out);
        };
        self.holds.remove(0);
        self.feed_hold_during(r, h, start, dur, out);
    }

    /// RESET pressed at `tr` while the record runs (from `start`, for `dur`): the part of it
    /// made before the axes stop, then the stop.
    fn reset_during(&mut self, r: Record, start: f64, dur: f64, tr: f64, out: &mut dyn FnMut(Event)) {
        // RESET: the axes decelerate to a stop (seed 000 note 11; seed 001 notes 8 and 9).
        if tr > start && r.op.end_point().is_some() {
            let (first, _) = self.split(&r, start, dur, tr, true);
            if let Some((f, fdur)) = first {
                self.emit(f, fdur, out);
            }
        } else if let (true, Op::Rotary { from_deg, to_deg, .. }) = (tr > start && dur > 0.0, r.op) {
            // A turn stops where it has come to (in proportion to its time: the deceleration
            // of a rotary axis is not modelled).
            let reached = from_deg + (to_deg - from_deg) * ((tr - start) / dur);
            let mut part = r.clone();
            if let Op::Rotary { to_deg, .. } = &mut part.op {
                *to_deg = reached;
            }
            self.emit(part, tr - start, out);
        }
        self.stop(r.span, StopReason::Reset, out);
    }

    /// FEED HOLD pressed at `h` while the record runs (from `start`, for `dur`): what the
    /// record's [`Hold`] says the machine does.
    fn feed_hold_during(&mut self, r: Record, h: f64, start: f64, dur: f64, out: &mut dyn FnMut(Event)) {
        match r.hold {
            Hold::Stop => self.hold_and_stop(r, h, start, dur, out),
            Hold::AfterRecord => {
                let span = r.span;
                let block_end = r.block_end;
                self.emit(Record { block_end: false, ..r }, dur, out);
                self.stop(span, StopReason::FeedHold, out);
                if block_end && self.single_block {
                    self.stop(span, StopReason::SingleBlock, out);
                }
            }
            Hold::AfterRun => {
                self.deferred = true;
                self.finish_record(r, dur, out);
            }
            Hold::Ignored => self.ignore_holds(r, h, start + dur, dur, out),
            Hold::ThreadCycle(th) => match th.style {
                ThreadHoldStyle::FinishThenStop => {
                    // NO.0018 bit 6 = 1: the thread and its pull-out are finished first.
                    self.deferred = true;
                    self.finish_record(r, dur, out);
                }
                _ => self.thread_hold(r, th, start, dur, h.max(start), out),
            },
        }
    }

    /// `Hold::Stop`: decelerate to a stop where the tool is, stop, then CYCLE START finishes
    /// the move.
    fn hold_and_stop(&mut self, r: Record, h: f64, start: f64, dur: f64, out: &mut dyn FnMut(Event)) {
        if h <= start || r.op.end_point().is_none() {
            self.stop(r.span, StopReason::FeedHold, out);
            return self.finish_record(r, dur, out);
        }
        let span = r.span;
        let (first, rest) = self.split(&r, start, dur, h, true);
        match (first, rest) {
            (Some((f, fdur)), Some(rest)) => {
                self.emit(f, fdur, out);
                self.stop(span, StopReason::FeedHold, out);
                let rdur = self.model.duration_s(&rest, false);
                self.finish_record(rest, rdur, out);
            }
            _ => {
                // The deceleration ends past the end of the move: stop at its end.
                let block_end = r.block_end;
                self.emit(Record { block_end: false, ..r }, dur, out);
                self.stop(span, StopReason::FeedHold, out);
                if block_end && self.single_block {
                    self.stop(span, StopReason::SingleBlock, out);
                }
            }
        }
    }

    /// `Hold::Ignored`: the press at `h` and every other before the record's `end` are
    /// warned of and lost; the record runs whole.
    fn ignore_holds(&mut self, r: Record, h: f64, end: f64, dur: f64, out: &mut dyn FnMut(Event)) {
        // Every press while the thread is cut is lost: the screen keeps showing RUN
        // (GSK988T manual, G32.1 note 6).
        let mut presses = vec![h];
        while let Some(&next) = self.holds.first().filter(|t| **t < end) {
            presses.push(next);
            self.holds.remove(0);
        }
        for h in presses {
            let msg = format!(
                "FEED HOLD at {h} s was ignored: the thread is being cut (the control keeps running and does not remember the press; press it again once the thread is done)"
            );
            out(Event::Diagnostic(Diagnostic::new(Rule::HoldIgnored, self.style, r.span, msg)));
        }
        self.finish_record(r, dur, out);
    }

    /// Emit a record and what follows it: a deferred hold at the end of its run, single block.
    fn finish_record(&mut self, r: Record, dur: f64, out: &mut dyn FnMut(Event)) {
        let span = r.span;
        let block_end = r.block_end;
        self.emit(r, dur, out);
        if self.deferred && block_end {
            self.deferred = false;
            self.stop(span, StopReason::FeedHold, out);
        }
        if block_end && self.single_block {
            self.stop(span, StopReason::SingleBlock, out);
        }
    }

    /// Split a record at time `at` (inside it). With `decelerate`, the tool goes on for its
    /// stopping distance. Returns the part up to the stop (with its duration) and the rest, or
    /// `None` when the stop comes at the end of the move.
    fn split(&self, r: &Record, start: f64, dur: f64, at: f64, decelerate: bool) -> (Option<(Record, f64)>, Option<Record>) {
        let len = path_length(&r.op);
        if len <= 0.0 || dur <= 0.0 {
            return (None, None);
        }
        let (mut u, stop_u, stop_s) = self.model.stop_from(r, len, at - start);
        let mut stop_dur = at - start;
        if decelerate {
            u += stop_u;
            stop_dur += stop_s;
        }
        if u >= 1.0 - 1e-12 {
            return (None, None);
        }
        let (a, b) = split_op(&r.op, u);
        let first = Record { op: a, block_end: false, ..r.clone() };
        let rest = Record { op: b, ..r.clone() };
        (Some((first, stop_dur)), Some(rest))
    }

    /// The G92 thread hold: pull out (thread up) at once from where the tool is, return to A
    /// (or stop where the pull-out ends), then cut the cycle again from its start.
    fn thread_hold(&mut self, r: Record, th: ThreadHold, start: f64, dur: f64, at: f64, out: &mut dyn FnMut(Event)) {
        let span = r.span;
        // The moves the hold makes are in the thread's frame (its machine coordinates).
        let to_machine = r.to_machine;
        let Op::Thread { from, to, lead_mm, long_axis, spindle_deg, rpm } = r.op else {
            self.finish_record(r, dur, out);
            return;
        };
        let u = if dur > 0.0 { ((at - start) / dur).clamp(0.0, 1.0) } else { 0.0 };
        let (l, s) = long_axis.indices();
        let (first, _) = split_op(&r.op, u);
        let p = first.end_point().unwrap_or(from);
        if u > 0.0 {
            self.emit(Record { op: first, block_end: false, hold: Hold::Stop, ..r.clone() }, at - start, out);
        }
        // The pull-out (GSK: "in the pull-out manner"; YASNAC: threading up), synchronised.
        let long_dir = (to.axis(l) - from.axis(l)).signum();
        let remaining = (to.axis(l) - p.axis(l)).abs();
        let mut q = p;
        let along = th.pull_long_mm.min(remaining);
        q.set_axis(l, p.axis(l) + long_dir * along);
        let toward_a = (th.start.axis(s) - p.axis(s)).signum();
        q.set_axis(s, p.axis(s) + toward_a * th.pull_short_mm.min((th.start.axis(s) - p.axis(s)).abs()));
        if q != p {
            let travelled = (p.axis(l) - from.axis(l)).abs();
            let op = if along > 0.0 {
                Op::Thread { from: p, to: q, lead_mm, long_axis, spindle_deg: phase_after(spindle_deg, travelled, lead_mm), rpm }
            } else {
                Op::Rapid { from: p, to: q }
            };
            let mut rec = Record::new(span, op);
            rec.hold = Hold::Stop;
            rec.to_machine = to_machine;
            let d = self.model.duration_s(&rec, false);
            self.emit(rec, d, out);
        }
        let back = |me: &mut Machine, from: Vec3, out: &mut dyn FnMut(Event)| {
            // Short axis back to A's, then the long axis (seed 000 note 1; seed 004 point A).
            let mut d = from;
            d.set_axis(s, th.start.axis(s));
            for (a, b) in [(from, d), (d, th.start)] {
                if a != b {
                    let rec = Record { to_machine, ..Record::new(span, Op::Rapid { from: a, to: b }) };
                    let t = me.model.duration_s(&rec, false);
                    me.emit(rec, t, out);
                }
            }
        };
        if th.style == ThreadHoldStyle::ThreadUpAndStop {
            // #6019 D7 = 1: stop where threading up ended; CYCLE START returns to A first.
            self.stop(span, StopReason::FeedHold, out);
            back(self, q, out);
        } else {
            back(self, q, out);
            self.stop(span, StopReason::FeedHold, out);
        }
        // CYCLE START: the interrupted cycle again from its start (seed 004: "restarts the current
        // processing from the beginning"), the same records, so the same groove.
        // A hold during a restart restarts the cycle again: what was left of the earlier
        // restart is not run (it would cut the rest of the cycle twice).
        self.again.clear();
        for rec in self.cycle_buf.iter().rev() {
            self.again.push_front(rec.clone());
        }
    }
}

/// Length along the path of a motion record.
fn path_length(op: &Op) -> f64 {
    match op {
        Op::Rapid { from, to } | Op::Feed { from, to, .. } | Op::Thread { from, to, .. } => from.dist(to),
        Op::Arc { from, to, plane, .. } | Op::ThreadArc { from, to, plane, .. } => {
            arc_geom_of(op).map(|g| geom::arc_length(from, to, *plane, &g)).unwrap_or(0.0)
        }
        _ => 0.0,
    }
}

/// Split a motion at fraction `u` of its path.
fn split_op(op: &Op, u: f64) -> (Op, Op) {
    let lerp = |a: &Vec3, b: &Vec3| Vec3::new(a.x + (b.x - a.x) * u, a.y + (b.y - a.y) * u, a.z + (b.z - a.z) * u);
    match *op {
        Op::Rapid { from, to } => {
            let p = lerp(&from, &to);
            (Op::Rapid { from, to: p }, Op::Rapid { from: p, to })
        }
        Op::Feed { from, to, feed_mm_min } => {
            let p = lerp(&from, &to);
            (Op::Feed { from, to: p, feed_mm_min }, Op::Feed { from: p, to, feed_mm_min })
        }
        Op::Thread { from, to, lead_mm, long_axis, spindle_deg, rpm } => {
            let p = lerp(&from, &to);
            let i = long_axis.index();
            let deg = phase_after(spindle_deg, (p.axis(i) - from.axis(i)).abs(), lead_mm);
            (Op::Thread { from, to: p, lead_mm, long_axis, spindle_deg, rpm }, Op::Thread { from: p, to, lead_mm, long_axis, spindle_deg: wrap_deg(deg), rpm })
        }
        Op::Arc { from, to, center, plane, dir, feed_mm_min } => {
            let g = arc_geom_of(op).expect("a stored arc");
            let p = geom::arc_point(&from, &to, plane, dir, &g, u);
            (Op::Arc { from, to: p, center, plane, dir, feed_mm_min }, Op::Arc { from: p, to, center, plane, dir, feed_mm_min })
        }
        Op::ThreadArc { from, to, center, plane, dir, lead_mm, long_axis, spindle_deg, rpm } => {
            let g = arc_geom_of(op).expect("a stored arc");
            let p = geom::arc_point(&from, &to, plane, dir, &g, u);
            let i = long_axis.index();
            let deg = phase_after(spindle_deg, (p.axis(i) - from.axis(i)).abs(), lead_mm);
            (
                Op::ThreadArc { from, to: p, center, plane, dir, lead_mm, long_axis, spindle_deg, rpm },
                Op::ThreadArc { from: p, to, center, plane, dir, lead_mm, long_axis, spindle_deg: deg, rpm },
            )
        }
        ref other => (other.clone(), other.clone()),
    }
}
