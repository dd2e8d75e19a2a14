//! G76 and G78 compound thread cutting (two blocks), G33 tapping and G34 variable lead (GSK980TDi help
//! text; G76 also FANUC 0-T). The passes are the shared four-step cycle and pull-out.

use super::thread::{chamfer_of, jk_pull_out};
use super::words::Words;
use super::{axis_target, HoldOn, Marks, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::tap;
use crate::cycles::thread::compound::{infeed_shift_mm, pass_depths, pass_line, Flank, Infeed, Schedule};
use crate::cycles::thread::cycle::{expand_cycle, Cycle};
use crate::cycles::thread::variable_lead::{self, VariableLeadError};
use crate::modal::{G76Data, G78Data, SpindleDir};
use crate::motion::{Hold, Op};
use crate::profile::Compound;
use crate::read::Word;

/// Lengths the manual gives in least input increments whatever the profile's decimal-point
/// rule: G76 P(k), Q(dd), Q(dmin) (docs/reference/behaviour.md; TAC p139: `Q150` = 0.15 mm).
pub(super) fn increments(step: &Step, w: &Word, code: &str) -> Result<f64, Diagnostic> {
    if w.decimal && !w.expr {
        return Err(step.alarm(
            Rule::IllegalDecimalPoint,
            w.span,
            format!("{}: {code} gives this in least input increments, without a decimal point", w.text()),
        ));
    }
    let unit = if step.st.modes.inch { 0.0001 * 25.4 } else { 0.001 };
    Ok(w.value * unit)
}

fn cycle_alarm(step: &Step, name: &str, msg: impl Into<String>) -> Diagnostic {
    step.alarm(Rule::ThreadData, step.span, format!("{name}: {}", msg.into()))
}

/// The G76 data the parameters give (power-on values, before any first block).
fn params_data(step: &Step) -> G76Data {
    let keys = step.profile.thread.g76.expect("the profile has G76");
    let p = |k| step.params.get(k);
    G76Data {
        finishing: p(keys.finishing) as u32,
        pull_out_tenths: p(keys.pull_out),
        angle_deg: p(keys.angle),
        dmin_mm: p(keys.dmin_um) * 0.001,
        allowance_mm: p(keys.allowance) * keys.allowance_to_mm,
        j: None,
        k: None,
    }
}

/// The data in force for `kind`: what its first block set, else the parameters. G78 without a
/// first block: decreasing depths, straight infeed, one start (ncsight's choice; docs/commands/g78.md).
fn data_in_force(step: &Step, kind: Compound) -> G78Data {
    match kind {
        Compound::G76 => {
            let base = step.st.thread.g76.unwrap_or_else(|| params_data(step));
            // The flank is chosen from the cut direction in `cut`.
            G78Data { base, schedule: Schedule::Decreasing, infeed: Infeed::Along(Flank::PlusZ), starts: 1 }
        }
        // A G76 first block rewrote the parameters G78 falls back on (No.57, 19, 58-60).
        Compound::G78 => step.st.thread.g78.unwrap_or_else(|| G78Data {
            base: step.st.thread.g76.unwrap_or_else(|| params_data(step)),
            schedule: Schedule::Decreasing,
            infeed: Infeed::Radial,
            starts: 1,
        }),
    }
}

/// G76 or G78, either block. The first (`G76 P(m)(r)(a) Q(dmin) R(d) [J K]`,
/// `G78 P(m)(r)(a) Q(dmin) R(d) J K D L E`) sets the data; the second
/// (`X(U) Z(W) R(i) P(k) Q(dd) F(I)`, the same for both) cuts.
pub(super) fn compound(step: &mut Step, words: &mut Words, kind: Compound) -> Result<(), Diagnostic> {
    let name = match kind {
        Compound::G76 => "G76",
        Compound::G78 => "G78",
    };
    let has_axis = [b'X', b'Z', b'U', b'W'].iter().any(|l| words.has(*l));
    let mut data = data_in_force(step, kind);
    if has_axis {
        return cut(step, words, name, kind, data);
    }
    if let Some(w) = words.take(b'P') {
        if w.decimal || w.value < 0.0 || w.value > 999_999.0 {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: {name} P is six digits m m r r a a", w.text())));
        }
        let p = w.value as u32;
        let (m, r) = (p / 10_000, (p / 100) % 100);
        data.base.angle_deg = (p % 100) as f64;
        match kind {
            Compound::G76 => {
                // P(m)(r)(a): finishing passes, pull-out in 0.1 lead, tool angle (rewrites No.57,
                // No.19, No.58 on the GSK; 5142, 5130, 5143 on the FANUC).
                data.base.finishing = m;
                data.base.pull_out_tenths = r as f64;
            }
            Compound::G78 => {
                // G78 help text: m 0 equal-distance infeed, 1 decreasing (as G76); r 0-3 the
                // cut-in mode: middle, left, right, left and right in turn.
                data.schedule = match m {
                    0 => Schedule::Equal,
                    1 => Schedule::Decreasing,
                    _ => {
                        return Err(step.alarm(
                            Rule::ValueOutOfRange,
                            w.span,
                            format!("{}: G78 P(m) is 00 (equal depths) or 01 (decreasing depths), not {m:02}", w.text()),
                        ))
                    }
                };
                data.infeed = match r {
                    0 => Infeed::Radial,
                    1 => Infeed::Along(Flank::MinusZ),
                    2 => Infeed::Along(Flank::PlusZ),
                    3 => Infeed::Alternate,
                    _ => return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: G78 P(r), the cut-in mode, is 00 to 03, not {r:02}", w.text()))),
                };
            }
        }
    }
    if let Some(w) = words.take(b'Q') {
        data.base.dmin_mm = increments(step, w, name)?;
    }
    if let Some(w) = words.take(b'R') {
        data.base.allowance_mm = step.length(w)?;
    }
    if step.profile.thread.g32_pull_out {
        // GSK: J/K in the first block; the pull-out is then that of G32/G92 (G76 help note 2).
        if let Some(w) = words.take(b'J') {
            data.base.j = Some(step.length(w)?);
        }
        if let Some(w) = words.take(b'K') {
            data.base.k = Some(step.length(w)?);
        }
    }
    if kind == Compound::G78 {
        if let Some(w) = words.take(b'D') {
            if w.decimal || !(0.0..=99.0).contains(&w.value) {
                return Err(step.alarm(
                    Rule::ValueOutOfRange,
                    w.span,
                    format!("{}: G78 D, the number of finishing passes, is a whole number 0 to 99", w.text()),
                ));
            }
            data.base.finishing = w.value as u32;
        }
        if let Some(w) = words.take(b'L') {
            if w.decimal || !(1.0..=99.0).contains(&w.value) {
                return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the number of starts L is a whole number 1 to 99", w.text())));
            }
            data.starts = w.value as u32;
        }
        if let Some(w) = words.take(b'E') {
            let e = step.length(w)?;
            if e != 0.0 {
                // The help text names E "X screw-in distance (radius)" without saying where it acts.
                let msg = format!("{}: the G78 screw-in distance E is not simulated (the help text does not say how it moves the tool)", w.text());
                step.warn(Rule::NotSimulated, w.span, msg);
            }
        }
        step.st.thread.g78 = Some(data);
    } else {
        step.st.thread.g76 = Some(data.base);
    }
    Ok(())
}

/// The second block: every pass of the schedule, each a four-step cycle (for each start).
fn cut(step: &mut Step, words: &mut Words, name: &str, kind: Compound, data: G78Data) -> Result<(), Diagnostic> {
    let lead = step.read_lead(words, name, step.profile.thread.g32_pull_out, false, super::thread::MAX_LEAD_MM)?;
    let taper = match words.take(b'R') {
        Some(w) => step.length(w)?,
        None => 0.0,
    };
    let height = match words.take(b'P') {
        Some(w) => increments(step, w, name)?,
        None => return Err(cycle_alarm(step, name, "the thread height P(k) is missing")),
    };
    let first = match words.take(b'Q') {
        Some(w) => increments(step, w, name)?,
        None => return Err(cycle_alarm(step, name, "the first depth Q(dd) is missing")),
    };
    let rpm = step.follow_rpm(name)?;
    let a = step.st.place.pos;
    let (c, _) = axis_target(step, words)?;
    if (c.z - a.z).abs() < 1e-9 {
        return Err(cycle_alarm(step, name, "the end point has the start point's Z: it cuts no face thread"));
    }
    if (c.x - a.x).abs() < 1e-9 {
        return Err(cycle_alarm(step, name, "the start point is at the thread's root X: there is no room to retract"));
    }
    let base = data.base;
    if base.finishing == 0 {
        step.warn(Rule::AllowanceNotCut, step.span, format!("{name} with no finishing passes: the finishing allowance is never cut"));
    }
    let schedule = pass_depths(data.schedule, height, first, base.dmin_mm, base.allowance_mm, base.finishing).map_err(|e| cycle_alarm(step, name, e))?;
    // External thread when the start is outside the root: deeper passes are at smaller X.
    let outward = if a.x > c.x { 1.0 } else { -1.0 };
    let infeed = match kind {
        // G76 follows the flank on the start point's side: the passes move in along it toward
        // the finished groove, which the passes at full depth cut at the programmed position.
        Compound::G76 => Infeed::Along(if c.z < a.z { Flank::PlusZ } else { Flank::MinusZ }),
        Compound::G78 => data.infeed,
    };
    step.feed_warning(name, lead, rpm);
    for (index, depth) in schedule.into_iter().enumerate() {
        let shift = infeed_shift_mm(infeed, index, depth, height, base.angle_deg);
        let (cut_start, cut_end) = pass_line(a, c, taper, height, depth, shift);
        let retract = (a.x - cut_end.x).abs();
        let pull_out = if base.j.is_some() || base.k.is_some() {
            jk_pull_out(step, base.j, base.k, base.pull_out_tenths, lead, outward)
        } else {
            let angle = step.profile.thread.g76.and_then(|k| k.pull_out_angle).map(|k| step.params.get(k)).unwrap_or(0.0);
            chamfer_of(base.pull_out_tenths, angle, lead, outward)
        }
        .map(|mut p| {
            p.short_mm = p.short_mm.min(retract);
            p
        });
        let spec = Cycle { start: a, cut_start, cut_end, lead_mm: lead, rpm, starts: data.starts, first_deg: 0.0, pull_out };
        let ops = expand_cycle(&spec).map_err(|e| step.pass_error(name, e))?;
        let mut last_start = None;
        for (start, op) in ops {
            if last_start != Some(start) {
                step.st.thread.cycles += 1;
                last_start = Some(start);
            }
            // Each pass and start a cycle of its own; G76 help note 1: FEED HOLD waits for the
            // end of the thread.
            let marks = Marks { cycle: Some(step.st.thread.cycles), hold: Some((Hold::AfterRun, HoldOn::Threads)), ..Marks::default() };
            step.marked(marks, |step| step.emit(op));
        }
    }
    Ok(())
}

/// G33 tapping (GSK980TDi help): in to Z at the lead, M05, the spindle reversed, out to the
/// start, M05; with L starts, again for each start.
pub(super) fn tap(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let lead = step.read_lead(words, "G33", true, false, super::thread::MAX_LEAD_MM)?;
    let starts = match words.take(b'L') {
        Some(w) if !w.decimal && (1.0..=99.0).contains(&w.value) => w.value as u32,
        Some(w) => return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the number of starts L is a whole number 1 to 99", w.text()))),
        None => 1,
    };
    if words.has(b'X') || words.has(b'U') {
        let w = words.take(b'X').or_else(|| words.take(b'U')).unwrap();
        return Err(step.alarm(Rule::WordNotTaken, w.span, format!("{}: G33 taps along Z only (Z or W)", w.text())));
    }
    // Help note 1: the spindle must turn before G33, in the tap's direction.
    let rpm = step.follow_rpm("G33")?;
    let a = step.st.place.pos;
    let (bottom, _) = axis_target(step, words)?;
    if bottom == a {
        return Ok(());
    }
    let position_mode = step.st.modes.spindle_position_mode;
    // Steps 2-4: M05 at the bottom, wait for the stop, turn the other way.
    let reverse = [
        Op::Spindle { rpm: 0.0, surface_m_min: None, position_mode, oriented: false, p: step.spindle_p() },
        Op::Spindle { rpm: -rpm, surface_m_min: None, position_mode, oriented: false, p: step.spindle_p() },
    ];
    // Help note 4: single block and feed hold wait for the end of the tapping.
    let marks = Marks::TAPPING;
    step.marked(marks, |step| {
        for k in 0..starts {
            let deg = k as f64 * 360.0 / starts as f64;
            for op in tap::stroke(a, bottom, lead, deg, rpm, &reverse) {
                step.emit(op);
            }
            // Step 6: M05.
            step.emit(Op::Spindle { rpm: 0.0, surface_m_min: None, position_mode, oriented: false, p: step.spindle_p() });
        }
    });
    step.st.modes.spindle = SpindleDir::Stopped;
    Ok(())
}

/// G34 variable lead (GSK980TDi help): the lead grows (or shrinks) by R every revolution. Cut as
/// one record per revolution, each with the lead of that revolution (its mean), so the spindle
/// angle at every record start is exact.
pub(super) fn variable_lead(step: &mut Step, words: &mut Words, run_deg: Option<f64>) -> Result<(), Diagnostic> {
    let rules = step.profile.thread.g34;
    // I (threads per inch) where G32 takes it (GSK), E where G32 takes it (YASNAC LX3).
    let lead = step.read_lead(words, "G34", step.profile.thread.g32_pull_out, step.profile.thread.g32_lead_e, super::thread::MAX_LEAD_MM)?;
    let change = match words.take(rules.change) {
        Some(w) => {
            let v = step.length(w)?;
            if let Some(max) = rules.change_max_mm.filter(|m| v.abs() > *m) {
                return Err(step.alarm(rules.lead_rule, w.span, format!("{}: G34's change of lead is at most {max} mm per revolution", w.text())));
            }
            v
        }
        None => 0.0,
    };
    // J and K as G32's, modal with G32's (help text G34: "J, K mean the same as in G32").
    let pull_out = if rules.pull_out_words {
        step.read_jk(words, "G34", true, true)?;
        super::thread::g32_pull_out(step)
    } else {
        None
    };
    let q = step.read_q(words, 0.001, false)?;
    let rpm = step.follow_rpm("G34")?;
    let from = step.st.place.pos;
    let (to, _) = axis_target(step, words)?;
    if to == from {
        return Ok(());
    }
    let start_deg = run_deg.or(q.map(|(d, _)| d)).unwrap_or(0.0);
    let max = super::thread::MAX_LEAD_MM;
    let limit = super::MAX_MOTIONS_PER_BLOCK;
    let ops = variable_lead::expand(from, to, lead, change, start_deg, rpm, pull_out, max, limit).map_err(|e| match e {
        VariableLeadError::LeadLeavesRange(n) => step.alarm(
            rules.lead_rule,
            step.span,
            format!(
                "G34: after {n} revolutions the lead would leave 0 to {max} mm (F{} {}{})",
                crate::alarm::shown(lead, 4),
                rules.change as char,
                crate::alarm::shown(change, 4)
            ),
        ),
        VariableLeadError::TooMany => step.alarm(Rule::MotionLimit, step.span, format!("G34: more than {limit} revolutions in one block")),
        VariableLeadError::Pass(e) => step.pass_error("G34", e),
    })?;
    for op in ops {
        step.emit(op);
    }
    Ok(())
}
