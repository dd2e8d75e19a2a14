//! Thread commands: reading their words by each manual's rules, then calling the shared
//! expansions of `cycles::thread`. The pull-out rules of each command are written here as data
//! for the one pull-out function; nothing of the geometry is copied.

use super::words::Words;
use super::{axis_target, resolve_arc, ArcOutcome, HoldOn, Marks, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::thread::arc::{self as arc_thread, ArcThreadError};
use crate::cycles::thread::cycle::{expand_cycle, Cycle};
use crate::cycles::thread::{expand, phase_after, wrap_deg, Pass, PassError, PullOut, PullOutMode};
use crate::modal::{PassMemory, PendingBody, PendingThread, SpindleDir};
use crate::motion::{ArcDir, Hold, LongAxis, Op, ThreadHold, ThreadHoldStyle, Vec3};
use crate::profile::{CycleRules, HoldRule, IntegerLengths, JkWords, ParamKey, PullOutRule, QPoint, ThreadCmd, MAX_RPM};
use crate::read::Word;

/// Largest lead of a straight thread (seed 001 F table: 0.001-500 mm; TDc p143: 0 < F <= 500).
pub const MAX_LEAD_MM: f64 = 500.0;
/// Largest lead of an arc thread (seed 002 F table: 0.001-9999 mm).
pub const MAX_ARC_LEAD_MM: f64 = 9999.0;

/// The command's code as this profile names it (G33 is the FANUC 0-M's G32), else as the
/// lathes do.
pub(super) fn name(profile: &crate::profile::Profile, cmd: ThreadCmd) -> &'static str {
    let code = profile.name_of(crate::profile::GFn::Thread(cmd));
    if code == "?" {
        default_name(cmd)
    } else {
        code
    }
}

fn default_name(cmd: ThreadCmd) -> &'static str {
    match cmd {
        ThreadCmd::Lead => "G32",
        ThreadCmd::Rigid => "G32.1",
        ThreadCmd::Cycle(rules) => rules.code,
        ThreadCmd::Tap => "G33",
        ThreadCmd::VariableLead => "G34",
        ThreadCmd::Arc(ArcDir::Cw) => "G32.2",
        ThreadCmd::Arc(ArcDir::Ccw) => "G32.3",
    }
}

/// Whether the command is a rigid (servo spindle, S-signed) one.
pub(super) fn is_rigid(cmd: ThreadCmd) -> bool {
    match cmd {
        ThreadCmd::Rigid => true,
        ThreadCmd::Cycle(rules) => rules.rigid,
        _ => false,
    }
}

/// Whether a block of `cmd` may continue a run held in `pending` (same family, seed 001 G32.1
/// note 1; TDi help G32 note 2). Cycles never continue a run.
pub(super) fn continues(cmd: ThreadCmd, pending: &PendingThread) -> bool {
    !pending.ends_run
        && match cmd {
            ThreadCmd::Lead | ThreadCmd::Arc(_) | ThreadCmd::VariableLead => !pending.rigid,
            ThreadCmd::Rigid => pending.rigid,
            ThreadCmd::Cycle(_) | ThreadCmd::Tap => false,
        }
}

impl Step<'_> {
    /// A lead word (F, E) in mm: GSK reads it in mm without a point; FANUC/YASNAC in least
    /// input increments (docs/reference/behaviour.md "Numbers and words").
    pub(super) fn lead_word(&mut self, w: &Word) -> f64 {
        let mut v = w.value;
        if !w.decimal && self.params.integer_lengths() == IntegerLengths::LeastIncrement {
            v *= if self.st.modes.inch { 0.0001 } else { 0.001 };
        }
        if self.st.modes.inch {
            v * 25.4
        } else {
            v
        }
    }

    /// Read F (and I threads per inch, E) into the lead in force; return the lead to use.
    /// The lead, and the hand where a negative F gives a left-hand thread (GSK980TDi G92.1 and
    /// G32.1: "F > 0 right hand, F < 0 left hand": the spindle turns the other way): -1.0 then.
    pub(super) fn read_hand_lead(
        &mut self,
        words: &mut Words,
        gname: &str,
        negative_f_left_hand: bool,
        inch_i: bool,
        e_word: bool,
    ) -> Result<(f64, f64), Diagnostic> {
        if negative_f_left_hand {
            if let Some(w) = words.peek(b'F').filter(|w| w.value < 0.0) {
                let mut positive = *w;
                positive.value = -w.value;
                words.take(b'F');
                let lead = self.lead_word(&positive);
                if lead > MAX_LEAD_MM {
                    return Err(self.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the lead of {gname} must be at most {MAX_LEAD_MM} mm", w.text())));
                }
                self.st.modes.feed = Some(lead);
                self.st.thread.lead_mm = None;
                self.st.thread.left_hand = true;
                return Ok((lead, -1.0));
            }
            // A lead written now is right-hand; one taken from memory keeps its hand.
            let written = words.has(b'F') || (inch_i && words.has(b'I'));
            let lead = self.read_lead(words, gname, inch_i, e_word, MAX_LEAD_MM)?;
            if written {
                self.st.thread.left_hand = false;
            }
            return Ok((lead, if self.st.thread.left_hand { -1.0 } else { 1.0 }));
        }
        Ok((self.read_lead(words, gname, inch_i, e_word, MAX_LEAD_MM)?, 1.0))
    }

    pub(super) fn read_lead(&mut self, words: &mut Words, gname: &str, inch_i: bool, e_word: bool, max_mm: f64) -> Result<f64, Diagnostic> {
        let f = words.take(b'F');
        let i = if inch_i { words.take(b'I') } else { None };
        let e = if e_word { words.take(b'E') } else { None };
        let given: Vec<Word> = [f, i, e].into_iter().flatten().copied().collect();
        if given.len() > 1 {
            return Err(self.alarm(Rule::DuplicateWord, given[1].span, format!("{} and {}: both give the lead of {gname}", given[0].text(), given[1].text())));
        }
        if let Some(w) = f.or(e) {
            let lead = self.lead_word(w);
            if !(lead > 0.0 && lead <= max_mm + 1e-9) {
                return Err(self.alarm(
                    Rule::ValueOutOfRange,
                    w.span,
                    format!("{}: the lead of {gname} must be more than 0 and at most {max_mm} mm", w.text()),
                ));
            }
            // One F register, as on the controller: the lead stays as the F of later blocks.
            self.st.modes.feed = Some(lead);
            self.st.thread.lead_mm = None;
        }
        if let Some(w) = i {
            // Threads per inch, 0.06-25400 (TDi p150).
            if !(0.06..=25400.0).contains(&w.value) {
                return Err(self.alarm(Rule::ValueOutOfRange, w.span, format!("{}: threads per inch must be 0.06 to 25400", w.text())));
            }
            self.st.thread.lead_mm = Some(25.4 / w.value);
        }
        // The lead in force: I threads per inch if the last lead word was I, else the F register.
        match self.st.thread.lead_mm.or(self.st.modes.feed).filter(|l| *l > 0.0) {
            Some(l) if l <= max_mm + 1e-9 => Ok(l),
            Some(l) => Err(self.alarm(
                Rule::ValueOutOfRange,
                self.span,
                format!("{gname}: the F in force ({} mm) is not a lead of at most {max_mm} mm", crate::alarm::shown(l, 4)),
            )),
            None => Err(self.alarm(
                Rule::MissingWord,
                self.span,
                format!("{gname} needs the lead: F{} was never given", if inch_i { " (or I threads per inch)" } else { "" }),
            )),
        }
    }

    /// Q, the start angle in 0.001 degree (seed 001 G32.1 Q rules; docs/reference/behaviour.md).
    pub(super) fn read_q(&mut self, words: &mut Words, unit_deg: f64, point_ok: bool) -> Result<Option<(f64, Word)>, Diagnostic> {
        let Some(w) = words.take(b'Q') else { return Ok(None) };
        if w.value < 0.0 {
            return Err(self.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the start angle cannot be negative", w.text())));
        }
        if w.decimal && !w.expr && !point_ok {
            match self.profile.thread.q_point {
                QPoint::Alarm => {
                    // Seed 001 G32.1: Q "cannot have a decimal point".
                    return Err(self.alarm(
                        Rule::IllegalDecimalPoint,
                        w.span,
                        format!("{}: Q is a whole number of 0.001 degree on {} (Q180000 is 180 degrees)", w.text(), self.profile.name),
                    ));
                }
                QPoint::Ignored => {
                    let msg = format!("{}: the decimal point of Q is ignored, Q stays in 0.001 degree ({} degrees)", w.text(), w.value * unit_deg);
                    self.warn(Rule::DecimalIgnored, w.span, msg);
                }
            }
        }
        // Above 360 degrees counts as 360 (= 0): seed 001 Q rule 2, seed 002.
        let deg = (w.value * unit_deg).min(360.0);
        Ok(Some((wrap_deg(deg), *w)))
    }

    /// J and K into the values in force. Returns whether J or K was written in this block.
    pub(super) fn read_jk(&mut self, words: &mut Words, gname: &str, j_may_be_negative: bool, k_may_be_negative: bool) -> Result<(bool, bool), Diagnostic> {
        let j = words.take(b'J');
        let k = words.take(b'K');
        if let Some(w) = j {
            let v = self.length(w)?;
            if v < 0.0 && !j_may_be_negative {
                return Err(self.alarm(Rule::ValueOutOfRange, w.span, format!("{}: J of {gname} cannot be negative", w.text())));
            }
            self.st.thread.j = Some(v);
        }
        if let Some(w) = k {
            let v = self.length(w)?;
            if v < 0.0 && !k_may_be_negative {
                return Err(self.alarm(Rule::ValueOutOfRange, w.span, format!("{}: K of {gname} has no sign (0 or more)", w.text())));
            }
            self.st.thread.k = Some(v);
        }
        Ok((j.is_some(), k.is_some()))
    }

    /// Spindle speed of an encoder-following thread: the spindle must turn.
    pub(super) fn follow_rpm(&mut self, gname: &str) -> Result<f64, Diagnostic> {
        if self.st.modes.css {
            // Issue 3: warn about G96 during threading.
            let msg = format!(
                "{gname} under G96: the speed is taken at the thread's start diameter; the controller changes it along the cut and the lead suffers (program G97)"
            );
            self.warn(Rule::ThreadWithCss, self.span, msg);
        }
        let rpm = self.rpm_here();
        if rpm == 0.0 {
            return Err(self.alarm(
                Rule::SpindleStopped,
                self.span,
                format!("{gname} with the spindle stopped or at S0: the thread waits for ever for the one-revolution signal"),
            ));
        }
        Ok(rpm)
    }

    /// Spindle speed of a rigid thread: S in the block or the last rigid S, signed; position
    /// mode required (seed 001 G32.1 notes 12 and 14, G92.1 note 12).
    fn rigid_rpm(&mut self, words: &mut Words, gname: &str) -> Result<f64, Diagnostic> {
        if !self.st.modes.spindle_position_mode {
            return Err(self.alarm(
                Rule::SpindleMode,
                self.span,
                format!("{gname} needs the spindle in position mode: program M14 first (GSK988T manual; GSK980TDi help text, G32.1 note 1)"),
            ));
        }
        if let Some(w) = words.take(b'S') {
            if w.value == 0.0 {
                return Err(self.alarm(Rule::ValueOutOfRange, w.span, format!("{}: {gname} needs a spindle speed other than 0", w.text())));
            }
            if w.value.abs() > MAX_RPM {
                return Err(self.alarm(Rule::ValueOutOfRange, w.span, format!("{}: above {MAX_RPM} rpm", w.text())));
            }
            self.st.thread.rigid_rpm = Some(w.value);
        }
        if let Some(r) = self.st.thread.rigid_rpm {
            return Ok(r);
        }
        if self.st.modes.s_word > 0.0 {
            let sign = if self.st.modes.spindle == SpindleDir::Negative { -1.0 } else { 1.0 };
            return Ok(sign * self.st.modes.s_word.min(MAX_RPM));
        }
        Err(self.alarm(
            Rule::MissingWord,
            self.span,
            format!("{gname} needs a spindle speed S (GSK988T manual, G32.1 note 12: no speed commanded is an alarm)"),
        ))
    }

    pub(super) fn feed_warning(&mut self, gname: &str, lead: f64, rpm: f64) {
        let feed = lead * rpm.abs();
        let max = self.params.feed_max_mm_min();
        if feed > max {
            let msg = format!(
                "{gname}: lead {lead} mm x {} rpm = {feed:.0} mm/min is above the cutting feed limit {max} mm/min: the axis cannot follow the spindle",
                rpm.abs()
            );
            self.warn(Rule::ThreadFeedHigh, self.span, msg);
        }
    }

    /// Compare a pass with the earlier passes of the same thread (same lead and start).
    fn remember_pass(&mut self, gname: &str, lead: f64, long_start: f64, depth: f64, rpm: f64, start_deg: f64) {
        let same = self.st.thread.memory.filter(|m| (m.lead_mm - lead).abs() < 1e-9 && (m.long_start - long_start).abs() < 1e-6);
        let Some(m) = same else {
            self.st.thread.memory = Some(PassMemory { lead_mm: lead, long_start, rpm, start_deg, depth, last_infeed: None });
            return;
        };
        if (m.rpm - rpm).abs() > 1e-9 {
            let msg = format!(
                "{gname}: this pass turns at {} rpm, the first at {} rpm: the passes may not line up",
                crate::alarm::shown(rpm, 1),
                crate::alarm::shown(m.rpm, 1)
            );
            self.warn(Rule::PassMismatch, self.span, msg);
        }
        if (m.start_deg - start_deg).abs() > 1e-9 {
            let msg = format!("{gname}: this pass starts at {start_deg} degrees, the first at {} degrees: it cuts a different groove", m.start_deg);
            self.warn(Rule::PassMismatch, self.span, msg);
        }
        let infeed = (depth - m.depth).abs();
        if let Some(prev) = m.last_infeed {
            if infeed > prev + 1e-9 {
                let msg = format!("{gname}: infeed {:.3} mm (diameter {:.3}) is larger than the previous one, {:.3} mm", infeed, 2.0 * infeed, prev);
                self.warn(Rule::InfeedGrows, self.span, msg);
            }
        }
        self.st.thread.memory = Some(PassMemory { depth, last_infeed: if infeed > 1e-12 { Some(infeed) } else { m.last_infeed }, ..m });
    }

    /// The pull-out speed mode of the profile (GSK No.107: 0 = ratio, else a speed).
    fn pull_out_mode(&self) -> PullOutMode {
        match self.profile.thread.pull_out_speed {
            Some(key) if self.params.get(key) > 0.0 => PullOutMode::ShortAxisSpeed(self.params.get(key)),
            _ => PullOutMode::Ratio,
        }
    }

    /// The time constant of the perpendicular pull-out after the end point (GSK988T 1628, seed
    /// 001 G32.1 note 5), seconds; `None` where the profile has none (the feed's own applies).
    fn pull_out_accel_s(&self) -> Option<f64> {
        self.profile.thread.pull_out_accel.map(|k| self.params.get(k) / 1000.0)
    }

    fn after_end_feed(&self) -> f64 {
        self.profile.thread.after_end_feed.map(|k| self.params.get(k)).filter(|v| *v > 0.0).unwrap_or(self.params.feed_max_mm_min())
    }

    pub(super) fn pass_error(&self, gname: &str, e: PassError) -> Diagnostic {
        match e {
            PassError::PullOutTooLong(k, len) => self.alarm(
                Rule::PullOutTooLong,
                self.span,
                format!("{gname}: the pull-out ({k:.3} mm along the long axis) is longer than the thread ({len:.3} mm)"),
            ),
        }
    }
}

/// Execute one block of a thread command. `run_deg` is the spindle angle where a continuous
/// run goes on (None: a new run, which waits for the one-revolution signal plus Q).
pub(super) fn block(step: &mut Step, words: &mut Words, cmd: ThreadCmd, explicit: bool, run_deg: Option<f64>) -> Result<(), Diagnostic> {
    match cmd {
        ThreadCmd::Lead | ThreadCmd::Rigid => straight(step, words, cmd, run_deg),
        ThreadCmd::Cycle(rules) => cycle(step, words, rules, explicit),
        ThreadCmd::Arc(dir) => arc(step, words, dir, run_deg),
        ThreadCmd::Tap => super::compound::tap(step, words),
        ThreadCmd::VariableLead => super::compound::variable_lead(step, words, run_deg),
    }
}

/// G32 (TDi help) and G32.1 (seed 001 section 2).
fn straight(step: &mut Step, words: &mut Words, cmd: ThreadCmd, run_deg: Option<f64>) -> Result<(), Diagnostic> {
    let rigid = cmd == ThreadCmd::Rigid;
    let gname = name(step.profile, cmd);
    let rules = step.profile.thread.g32_1;
    let (lead, hand) = if rigid {
        step.read_hand_lead(words, gname, rules.negative_f_left_hand, rules.lead_i, false)?
    } else {
        (step.read_lead(words, gname, step.profile.thread.g32_pull_out, step.profile.thread.g32_lead_e, MAX_LEAD_MM)?, 1.0)
    };
    // G32.1: J signed, K unsigned (seed 001 notes); G32: J signed, K as written taken positive.
    // The GSK980TDi's G32.1 takes J and K as its G32 does (inferred). FANUC's G32 has no J/K.
    let g32_style_k = !rigid || !rules.k_zero_after_end;
    let (j_given, k_given) = if rigid || step.profile.thread.g32_pull_out { step.read_jk(words, gname, true, g32_style_k)? } else { (false, false) };
    // The start angle: Q, or on the GSK980TDi's G32.1 C, the spindle's position in degrees.
    let q = if rigid && rules.start_c {
        match words.take(b'C') {
            Some(w) => {
                if words.has_unused(b'Q') {
                    let q = words.take(b'Q').expect("present");
                    return Err(step.alarm(Rule::WordNotTaken, q.span, format!("{}: {gname} gives its start angle with C on {}", q.text(), step.profile.name)));
                }
                let deg = step.degrees(w).rem_euclid(360.0);
                Some((if deg >= 360.0 { 0.0 } else { deg }, *w))
            }
            None => None,
        }
    } else {
        step.read_q(words, 0.001, false)?
    };
    let rpm = if rigid { hand * step.rigid_rpm(words, gname)? } else { step.follow_rpm(gname)? };
    let (target, _) = axis_target(step, words)?;
    let from = step.st.place.pos;
    if target == from {
        return Ok(());
    }
    let long_axis = LongAxis::of(&from, &target);
    let (l, _) = long_axis.indices();
    let length = (target.axis(l) - from.axis(l)).abs();
    step.feed_warning(gname, lead, rpm);
    let start_deg = match (run_deg, q) {
        (Some(d), Some((_, w))) => {
            // Only the first block's Q counts in a continuous run (TDi help G32 note 5; seed 002).
            step.warn(Rule::TextIgnored, w.span, format!("{}: ignored, the block continues a thread run", w.text()));
            d
        }
        (Some(d), None) => d,
        (None, q) => q.map(|(d, _)| d).unwrap_or(0.0),
    };
    let pull_out = if rigid && rules.k_zero_after_end { rigid_pull_out(step) } else { g32_pull_out(step) };
    if let Some(po) = pull_out {
        if po.long_mm > length + 1e-9 {
            // Seed 001 G32.1 note 9.
            return Err(step.pass_error(gname, PassError::PullOutTooLong(po.long_mm, length)));
        }
    }
    if run_deg.is_none() {
        let (_, s) = long_axis.indices();
        step.remember_pass(gname, lead, from.axis(l), target.axis(s), rpm, start_deg);
    }
    let pass = Pass { from, to: target, lead_mm: lead, rpm, start_deg, pull_out };
    // G32.1: a block that writes J or K (other than J0 K0) ends the run (seed 001 G32.1 note 1).
    // G32: J/K are modal and the run's pull-out uses the values in force at its end (TDi help
    // G32 note 1), so writing them does not end a run.
    // The GSK980TDi's G32.1 takes J/K as its G32 (inferred): they do not end the run there.
    let ends_run =
        rigid && rules.k_zero_after_end && (j_given || k_given) && (step.st.thread.j.unwrap_or(0.0) != 0.0 || step.st.thread.k.unwrap_or(0.0) != 0.0);
    let end_deg = phase_after(start_deg, length, lead);
    step.st.place.pos = target;
    step.st.thread.pending = Some(PendingThread { span: step.span, n: step.n, body: PendingBody::Straight(pass), ends_run, rigid, end_deg });
    Ok(())
}

/// The sign of J: which way the short axis goes out.
fn short_sign(j: f64) -> f64 {
    if j < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// G32.1's pull-out on the GSK988T from the J and K in force. No J in force, or J0: none (seed
/// 001 notes 2 and 4). K omitted or 0: no long-axis pull-out; out along the short axis after the
/// end point at parameter 1466's speed (seed 001 G32.1 notes 3 and 5).
fn rigid_pull_out(step: &Step) -> Option<PullOut> {
    let j = step.st.thread.j.filter(|j| *j != 0.0)?;
    let k = step.st.thread.k.map(f64::abs).unwrap_or(0.0);
    let after_end_feed = if k == 0.0 { Some(step.after_end_feed()) } else { None };
    Some(PullOut { long_mm: k, short_mm: j.abs(), short_sign: short_sign(j), mode: PullOutMode::Ratio, after_end_feed })
}

/// G32's pull-out from the J and K in force, as G34 takes it too (TDi help G34: "X(U), Z(W),
/// J, K mean the same as in G32"). No J in force, or J0: none (TDi p151); K omitted or 0 with J:
/// K = J (TDi p151).
pub(super) fn g32_pull_out(step: &Step) -> Option<PullOut> {
    let j = step.st.thread.j.filter(|j| *j != 0.0)?;
    let k = step.st.thread.k.map(f64::abs).unwrap_or(0.0);
    let long = if k == 0.0 { j.abs() } else { k };
    Some(PullOut { long_mm: long, short_mm: j.abs(), short_sign: short_sign(j), mode: step.pull_out_mode(), after_end_feed: None })
}

/// G32.2 / G32.3 (seed 002).
fn arc(step: &mut Step, words: &mut Words, dir: ArcDir, run_deg: Option<f64>) -> Result<(), Diagnostic> {
    let gname = name(step.profile, ThreadCmd::Arc(dir));
    // I is taken by the centre, so F is the only lead word: F[25.4/n] for inch (seed 002).
    let lead = step.read_lead(words, gname, false, false, MAX_ARC_LEAD_MM)?;
    let unit = step.profile.thread.arc_q_unit_deg;
    let q = step.read_q(words, unit, unit >= 1.0)?;
    let rpm = step.follow_rpm(gname)?;
    if let Some(r) = words.peek(b'R') {
        if r.value < 0.0 {
            return Err(step.alarm(
                Rule::ValueOutOfRange,
                r.span,
                format!("{}: the radius of an arc thread cannot be negative (GSK988T manual, G32.2/G32.3: no arcs over 180 degrees)", r.text()),
            ));
        }
    }
    let (to, _) = axis_target(step, words)?;
    let from = step.st.place.pos;
    let plane = step.st.modes.plane;
    let g = match resolve_arc(step, words, from, to, dir, gname)? {
        ArcOutcome::Arc(g) => g,
        ArcOutcome::Zero | ArcOutcome::Straight => return Ok(()),
    };
    let long_axis = match arc_thread::long_axis(&from, plane, dir, &g) {
        Ok(a) => a,
        Err(ArcThreadError::CrossesSector(deg)) => {
            return Err(step.alarm(
                Rule::ArcThreadSector,
                step.span,
                format!(
                    "{gname}: the arc crosses the {deg:.0}-degree diagonal through its centre, so its long axis would change (GSK988T manual, G32.2/G32.3 note 1: the arc must stay in one sector)"
                ),
            ))
        }
    };
    step.feed_warning(gname, lead, rpm);
    let start_deg = run_deg.unwrap_or_else(|| q.map(|(d, _)| d).unwrap_or(0.0));
    if let (Some(_), Some((_, w))) = (run_deg, q) {
        step.warn(Rule::TextIgnored, w.span, format!("{}: ignored, the block continues a thread run", w.text()));
    }
    let i = long_axis.index();
    let long_travel = (to.axis(i) - from.axis(i)).abs();
    let op = Op::ThreadArc { from, to, center: g.center, plane, dir, lead_mm: lead, long_axis, spindle_deg: wrap_deg(start_deg), rpm };
    step.st.place.pos = to;
    step.st.thread.pending = Some(PendingThread {
        span: step.span,
        n: step.n,
        body: PendingBody::Arc(op),
        ends_run: false,
        rigid: false,
        end_deg: phase_after(start_deg, long_travel, lead),
    });
    Ok(())
}

/// G92 (seed 000; seed 004 for the YASNAC) and G92.1 (seed 001 section 3).
fn cycle(step: &mut Step, words: &mut Words, rules: &'static CycleRules, explicit: bool) -> Result<(), Diagnostic> {
    let gname = rules.code;
    let (lead, hand) = step.read_hand_lead(words, gname, rules.negative_f_left_hand, rules.lead_i, rules.lead_e)?;
    read_repair_word(step, words, rules);
    read_starts(step, words, rules)?;
    let flank_mm = read_pull_out_and_flank(step, words, rules)?;
    if rules.ts_before {
        if let Some(w) = [b'T', b'S'].iter().find_map(|l| words.peek(*l)) {
            // Seed 004 (5) a: T, S and M for G92 come in the blocks before the cycle.
            let msg = format!("{}: the LX3 manual asks for T, S and M of a G92 cycle in the blocks before it", w.text());
            step.warn(Rule::CycleWords, w.span, msg);
        }
    }
    let q = if rules.q_start { step.read_q(words, 0.001, false)? } else { None };
    // Help note 6 (G92.1): the interpolation type needs the servo spindle in position mode.
    let rpm = if rules.rigid { hand * step.rigid_rpm(words, gname)? } else { step.follow_rpm(gname)? };
    let a = step.st.place.pos;
    let c = cycle_end_point(step, words, rules, explicit)?;
    let taper = step.st.thread.taper_mm;
    let cut_start = Vec3::new(c.x + taper, a.y, a.z + flank_mm);
    let long_axis = LongAxis::of(&cut_start, &c);
    let (l, s) = long_axis.indices();
    let retract = (a.axis(s) - c.axis(s)).abs();
    let toward_start = {
        let d = a.axis(s) - c.axis(s);
        if d != 0.0 {
            d.signum()
        } else if c.axis(s) < 0.0 {
            -1.0
        } else {
            1.0
        }
    };
    let pull_out = cycle_pull_out(step, rules, lead, toward_start, retract);
    step.feed_warning(gname, lead, rpm);
    let first_deg = cycle_start_deg(step, gname, q, cut_start, c, lead, rpm)?;
    step.remember_pass(gname, lead, cut_start.axis(l), c.axis(s), rpm, first_deg);
    let spec = Cycle { start: a, cut_start, cut_end: c, lead_mm: lead, rpm, starts: step.st.thread.starts, first_deg, pull_out };
    let ops = expand_cycle(&spec).map_err(|e| step.pass_error(gname, e))?;
    let hold = cycle_hold(step, rules, a, lead, retract, pull_out);
    emit_cycle(step, ops, hold);
    step.st.thread.cycle_end = Some(c);
    Ok(())
}

/// The thread repair word P of G92.1: P1 repairs the thread when repair is enabled (help notes
/// 1 and 2).
fn read_repair_word(step: &mut Step, words: &mut Words, rules: &'static CycleRules) {
    let repair_word = if rules.repair_p { words.take(b'P') } else { None };
    if let Some(w) = repair_word {
        let enabled = step.profile.thread.repair_enable.is_some_and(|k| step.params.get(k) != 0.0);
        let wants = !w.decimal && w.value == 1.0;
        if wants && !enabled {
            // Help note 1: with repair disabled, P1 is ignored.
            let key = step.profile.thread.repair_enable.map(|k| k.spoken()).unwrap_or_default();
            let msg = format!("{}: ignored, thread repair is off (parameter {key} = 0)", w.text());
            step.warn(Rule::TextIgnored, w.span, msg);
        }
        // Help note 2: P other than 1 does no repair.
        step.st.thread.repair = wants && enabled;
    }
}

/// The number of starts L of a multi-start thread, where the cycle takes one.
fn read_starts(step: &mut Step, words: &mut Words, rules: &'static CycleRules) -> Result<(), Diagnostic> {
    // L: number of starts, 1-99, modal (seed 000; seed 001 G92.1).
    if rules.starts_l {
        if let Some(w) = words.take(b'L') {
            if w.decimal || !(1.0..=99.0).contains(&w.value) {
                return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the number of starts L is a whole number 1 to 99", w.text())));
            }
            step.st.thread.starts = w.value as u32;
        }
    }
    Ok(())
}

/// The pull-out words J and K into the thread data, by the cycle's rules; or K as the flank
/// infeed: the shift of this pass's start along Z, mm (0 without it).
fn read_pull_out_and_flank(step: &mut Step, words: &mut Words, rules: &'static CycleRules) -> Result<f64, Diagnostic> {
    let gname = rules.code;
    let mut flank_mm = 0.0;
    match rules.jk {
        // Seed 000 note 10: negative J, K count as positive.
        JkWords::SignIgnored => step.read_jk(words, gname, true, true).map(|_| ())?,
        // Seed 001 G92.1: J "cannot be less than zero"; K in G32.1's range (0 or more).
        JkWords::NonNegative => step.read_jk(words, gname, false, false).map(|_| ())?,
        JkWords::None => {}
    }
    if rules.flank_k {
        // Seed 004 (4): K, with its sign, shifts this pass's start along Z (flank infeed).
        if let Some(w) = words.take(b'K') {
            flank_mm = step.length(w)?;
        }
    }
    Ok(flank_mm)
}

/// The cycle's end point (what the block omits from the last cycle's end, X else from where the
/// tool stands) with the taper it sets or keeps; the alarms for a face thread and for a taper
/// too large for the pass.
fn cycle_end_point(step: &mut Step, words: &mut Words, rules: &'static CycleRules, explicit: bool) -> Result<Vec3, Diagnostic> {
    let gname = rules.code;
    // Taper: R on GSK and FANUC, I on the YASNAC; radius, cut start minus cut end.
    let taper_word = words.take(rules.taper);
    let a = step.st.place.pos;
    let given_z = words.has(b'Z') || words.has(b'W');
    let given_x = words.has(b'X') || words.has(b'U');
    let (mut c, _) = axis_target(step, words)?;
    let remembered = if explicit { None } else { step.st.thread.cycle_end };
    if !given_z {
        match remembered {
            Some(m) => c.z = m.z,
            None => return Err(step.alarm(Rule::MissingWord, step.span, format!("{gname} needs the end point's Z (or W)"))),
        }
    }
    if !given_x {
        c.x = remembered.map(|m| m.x).unwrap_or(a.x);
    }
    match taper_word {
        Some(w) => step.st.thread.taper_mm = step.length(w)?,
        None if explicit => step.st.thread.taper_mm = 0.0,
        None => {} // continuation blocks keep the taper (assumption, docs/threads.md)
    }
    let taper = step.st.thread.taper_mm;
    if (c.z - a.z).abs() < 1e-9 {
        // Seed 000: G92 cannot cut a face thread.
        return Err(step.alarm(
            Rule::FaceThread,
            step.span,
            format!("{gname}: the end point has the start point's Z, a face thread, which {gname} cannot cut (GSK980TDi manual, G92)"),
        ));
    }
    if rules.taper_limit {
        check_taper_limit(step, gname, c.x - a.x, taper, taper_word)?;
    }
    Ok(c)
}

/// The alarm for a taper `taper` larger than the pass allows against the end point's X
/// distance `u_radius` from the start (a radius).
fn check_taper_limit(step: &Step, gname: &str, u_radius: f64, taper: f64, taper_word: Option<&Word>) -> Result<(), Diagnostic> {
    // Seed 000 / seed 001: when R and U differ in sign, |R| <= |U/2|.
    if taper != 0.0 && u_radius != 0.0 && taper.signum() != u_radius.signum() && taper.abs() > u_radius.abs() + 1e-9 {
        let span = taper_word.map(|w| w.span).unwrap_or(step.span);
        return Err(step.alarm(
            Rule::TaperTooLarge,
            span,
            format!("{gname}: R{taper} and U{} differ in sign, so |R| may be at most |U/2| = {:.3} mm", 2.0 * u_radius, u_radius.abs()),
        ));
    }
    Ok(())
}

/// The cycle's pull-out at the end of the thread, by the command's rules, at most the retract
/// distance across.
fn cycle_pull_out(step: &Step, rules: &'static CycleRules, lead: f64, toward_start: f64, retract: f64) -> Option<PullOut> {
    let pull_out = match rules.pull_out {
        // Seed 000 notes 2-7 and 10: J/K, No.19 for what is omitted.
        PullOutRule::JkTenths(tenths) => {
            let tenths = pull_out_tenths(step, tenths);
            jk_pull_out(step, step.st.thread.j, step.st.thread.k, tenths, lead, toward_start)
        }
        // Seed 001 G92.1 notes 1-6.
        PullOutRule::JkChamfer { amount, angle } => jk_chamfer_pull_out(step, lead, toward_start, amount, angle),
        // FANUC 0-T: the chamfer of its parameters (no J/K words).
        PullOutRule::Chamfer { amount, angle } => chamfer_pull_out(step, lead, toward_start, amount, Some(angle)),
        // Seed 004 describes no thread chamfer for the LX3 G92; the GSK980TDi G92.1 stops feed
        // axes and spindle together at the end point (help text, step 2).
        PullOutRule::None => None,
    };
    // Seed 001 G92.1 note 11, applied to G92 too (docs/reference/behaviour.md): J at most the retract distance.
    pull_out.map(|mut p| {
        if p.short_mm > retract {
            p.short_mm = retract;
        }
        p
    })
}

/// The spindle angle the first start begins at: Q (0 without it), or under thread repair the
/// angle that puts the pass through the recorded groove.
fn cycle_start_deg(step: &Step, gname: &str, q: Option<(f64, Word)>, cut_start: Vec3, c: Vec3, lead: f64, rpm: f64) -> Result<f64, Diagnostic> {
    let mut first_deg = q.map(|(d, _)| d).unwrap_or(0.0);
    if step.st.thread.repair {
        // Thread repair: the start angle that puts the pass through the recorded groove.
        let Some(rec) = step.repair else {
            return Err(step.alarm(
                Rule::RepairNoPosition,
                step.span,
                format!("{gname} P1: no thread repair position was recorded (help note 3; give --repair-position X,Z,C)"),
            ));
        };
        first_deg = match crate::repair::start_angle_deg(cut_start, c, lead, rpm, &rec) {
            Ok(d) => d,
            Err(e) => return Err(step.alarm(Rule::RepairOutside, step.span, format!("{gname} P1: {e} (help note 5)"))),
        };
    }
    Ok(first_deg)
}

/// What a feed hold does during the cycle, by the command's rules: pull out or finish the
/// thread, thread up, nothing, or stop after the run.
fn cycle_hold(step: &Step, rules: &'static CycleRules, a: Vec3, lead: f64, retract: f64, pull_out: Option<PullOut>) -> Hold {
    // The thread hold of the cycle (seed 000 note 1; seed 004; seed 001 G92.1 note 7).
    match rules.hold {
        HoldRule::PullOutOrFinish(bit) => {
            let finish = step.params.get(bit) != 0.0;
            let (long, short) = pull_out.map(|p| (p.long_mm, p.short_mm)).unwrap_or((0.0, 0.0));
            let style = if finish { ThreadHoldStyle::FinishThenStop } else { ThreadHoldStyle::PullOutAndReturn };
            Hold::ThreadCycle(ThreadHold { style, start: a, pull_long_mm: long, pull_short_mm: short })
        }
        HoldRule::ThreadUp(bit) => {
            // "Threading up": the LX3 excerpt gives no amount; one lead at 45 degrees, within the
            // retract distance (docs/commands/operator.md).
            let stop_at_b = step.params.get(bit) != 0.0;
            let style = if stop_at_b { ThreadHoldStyle::ThreadUpAndStop } else { ThreadHoldStyle::ThreadUpAndReturn };
            let up = lead.min(retract);
            Hold::ThreadCycle(ThreadHold { style, start: a, pull_long_mm: up, pull_short_mm: up })
        }
        // FANUC 0-T without the thread-cutting retract option: the thread finishes first
        // (assumption, docs/commands/operator.md).
        // GSK988T G92.1 note 7: a press during the thread does nothing (the cycle's rapids stop).
        HoldRule::Ignored => Hold::Ignored,
        // GSK980TDi help text, G92.1 note 3: the thread is finished, then the run pauses.
        HoldRule::AfterRun => Hold::AfterRun,
    }
}

/// Emit the cycle's moves, start by start (each start counts as a cycle), the hold on the
/// thread and on the pull-out after its end point.
fn emit_cycle(step: &mut Step, ops: Vec<(u32, Op)>, hold: Hold) {
    let mut last_start = None;
    for (k, op) in ops {
        if last_start != Some(k) {
            last_start = Some(k);
            step.st.thread.cycles += 1;
        }
        // The op's record: its cycle; the hold on the thread, and on the perpendicular pull-out
        // after the end point with its time constant (G92.1 note 3).
        let marks = Marks {
            cycle: Some(step.st.thread.cycles),
            hold: Some((hold, if op.is_thread() { HoldOn::Every } else { HoldOn::Feeds })),
            feed_accel_s: Some(step.pull_out_accel_s()),
            once: true,
            ..Marks::default()
        };
        step.marked(marks, |step| step.emit(op));
    }
}

/// Seed 000's J/K rules with `tenths` (No.19, or G76's r) for what is omitted.
pub(super) fn jk_pull_out(step: &Step, j: Option<f64>, k: Option<f64>, tenths: f64, lead: f64, sign: f64) -> Option<PullOut> {
    let (j, k) = (j.map(f64::abs), k.map(f64::abs));
    let no19 = tenths * 0.1 * lead;
    let (long, short) = match (j, k) {
        (None, None) => (no19, no19),             // note 2
        (None, Some(k)) => (k, no19),             // note 3
        (Some(j), _) if j == 0.0 => return None,  // notes 5 and 7
        (Some(j), None) => (j, j),                // note 4
        (Some(j), Some(k)) if k == 0.0 => (j, j), // note 6
        (Some(j), Some(k)) => (k, j),
    };
    if short <= 0.0 {
        return None;
    }
    Some(PullOut { long_mm: long, short_mm: short, short_sign: sign, mode: step.pull_out_mode(), after_end_feed: None })
}

/// A chamfer of `amount` x 0.1 x lead along the long axis at the angle parameter (0 or none:
/// 45 degrees): G92.1 note 1 (5130/5131), FANUC G92 and G76, GSK G76 by P(r).
pub(super) fn chamfer_pull_out(step: &Step, lead: f64, sign: f64, amount: ParamKey, angle: Option<ParamKey>) -> Option<PullOut> {
    chamfer_of(pull_out_tenths(step, amount), angle.map(|a| step.params.get(a)).unwrap_or(0.0), lead, sign)
}

/// The pull-out amount parameter `key` (0.1 x lead) as the run has it: a G76 first block's P
/// rewrote it for the rest of the run where G76 reads the same parameter (GSK980TDi No.19 for
/// G92 and G76; FANUC 5130).
fn pull_out_tenths(step: &Step, key: ParamKey) -> f64 {
    match (step.profile.thread.g76, step.st.thread.g76) {
        (Some(keys), Some(data)) if keys.pull_out == key => data.pull_out_tenths,
        _ => step.params.get(key),
    }
}

/// See [`chamfer_pull_out`]; the values given.
pub(super) fn chamfer_of(tenths: f64, angle_deg: f64, lead: f64, sign: f64) -> Option<PullOut> {
    let long = tenths * 0.1 * lead;
    let short = if angle_deg == 0.0 { long } else { long * angle_deg.to_radians().tan() };
    (short > 0.0).then_some(PullOut { long_mm: long, short_mm: short, short_sign: sign, mode: PullOutMode::Ratio, after_end_feed: None })
}

/// Seed 001 G92.1 notes 1-6 (GSK988T): J/K, the chamfer parameters for what is omitted.
fn jk_chamfer_pull_out(step: &Step, lead: f64, sign: f64, amount: ParamKey, angle: ParamKey) -> Option<PullOut> {
    let (j, k) = (step.st.thread.j, step.st.thread.k);
    let chamfer = pull_out_tenths(step, amount) * 0.1 * lead;
    let after_end = |j: f64| PullOut { long_mm: 0.0, short_mm: j, short_sign: sign, mode: PullOutMode::Ratio, after_end_feed: Some(step.after_end_feed()) };
    let (long, short) = match (j, k) {
        (None, None) => return chamfer_pull_out(step, lead, sign, amount, Some(angle)), // note 1
        (None, Some(k)) => (k, chamfer),                                                // note 2
        (Some(j), _) if j == 0.0 => return None,                                        // notes 5 and 6
        (Some(j), None) => return Some(after_end(j)),                                   // note 3
        (Some(j), Some(k)) if k == 0.0 => return Some(after_end(j)),                    // note 4
        (Some(j), Some(k)) => (k, j),
    };
    if short <= 0.0 {
        return None;
    }
    Some(PullOut { long_mm: long, short_mm: short, short_sign: sign, mode: PullOutMode::Ratio, after_end_feed: None })
}

/// Emit a held-back run end: with its pull-out if the run ends here.
pub(super) fn flush(step: &mut Step, p: PendingThread, run_ends: bool) {
    // Single block stops after the last block of a run only (seed 001 G32.1 note 7; TDi help G32
    // note 4). The perpendicular pull-out after a G32.1 end is part of the thread for the hold.
    // FEED HOLD: G32 (TDi help G32 note 3) stops when the run is cut; G32.1 ignores the press
    // (GSK988T manual, G32.1 note 6: the screen keeps showing RUN; TDi help G32.1 note 4).
    let hold = if p.rigid { Hold::Ignored } else { Hold::AfterRun };
    let marks = Marks { hold: Some((hold, HoldOn::Every)), feed_accel_s: Some(step.pull_out_accel_s()), ..Marks::default() };
    let first = step.out.records.len();
    step.marked(marks, |step| match p.body {
        PendingBody::Straight(mut pass) => {
            if !run_ends {
                pass.pull_out = None;
            }
            // The pull-out length was checked when the block was read.
            if let Ok((ops, _)) = expand(&pass) {
                for op in ops {
                    step.emit_at(p.span, p.n, op);
                }
            }
        }
        PendingBody::Arc(op) => step.emit_at(p.span, p.n, op),
    });
    if let Some(last) = step.records_since(first).last_mut() {
        last.block_end = run_ends;
    }
}
