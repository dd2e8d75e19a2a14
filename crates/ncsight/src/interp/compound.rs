//! G76 compound thread cutting (two blocks), G33 tapping and G34 variable lead (GSK980TDi help
//! text; G76 also FANUC 0-T). The passes are the shared four-step cycle and pull-out.

use super::thread::{chamfer_of, gsk_jk_pull_out};
use super::words::Words;
use super::{axis_target, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::thread::compound::depths;
use crate::cycles::thread::cycle::{expand_cycle, Cycle};
use crate::cycles::thread::{phase_after, thread_op, wrap_deg};
use crate::modal::{G76Data, SpindleDir};
use crate::motion::{Hold, LongAxis, Op, Vec3};
use crate::read::Word;

/// Lengths the manual gives in least input increments whatever the profile's decimal-point
/// rule: G76 P(k), Q(dd), Q(dmin) (BEHAVIOUR.md; TAC p139: `Q150` = 0.15 mm).
fn increments(step: &Step, w: &Word) -> Result<f64, Diagnostic> {
    if w.decimal && !w.expr {
        return Err(step.alarm(
            Rule::IllegalDecimalPoint,
            w.span,
            format!("{}: G76 gives this in least input increments, without a decimal point", w.text()),
        ));
    }
    let unit = if step.st.inch { 0.0001 * 25.4 } else { 0.001 };
    Ok(w.value * unit)
}

fn g76_alarm(step: &Step, msg: impl Into<String>) -> Diagnostic {
    step.alarm(Rule::ThreadData, step.span, format!("G76: {}", msg.into()))
}

/// The G76 data in force: what the first block set, else the parameters.
fn g76_data(step: &Step) -> G76Data {
    if let Some(d) = step.st.thread.g76 {
        return d;
    }
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

/// G76, either block. The first (`G76 P(m)(r)(a) Q(dmin) R(d) [J K]`) sets the data; the second
/// (`G76 X(U) Z(W) R(i) P(k) Q(dd) F(I)`) cuts.
pub(super) fn g76(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let has_axis = [b'X', b'Z', b'U', b'W'].iter().any(|l| words.has(*l));
    let mut data = g76_data(step);
    if !has_axis {
        if let Some(w) = words.take(b'P') {
            if w.decimal || w.value < 0.0 || w.value > 999_999.0 {
                return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: G76 P is six digits m m r r a a", w.text())));
            }
            let p = w.value as u32;
            // P(m)(r)(a): finishing passes, pull-out in 0.1 lead, tool angle (rewrites No.57,
            // No.19, No.58 on the GSK; 5142, 5130, 5143 on the FANUC).
            data.finishing = p / 10_000;
            data.pull_out_tenths = ((p / 100) % 100) as f64;
            data.angle_deg = (p % 100) as f64;
        }
        if let Some(w) = words.take(b'Q') {
            data.dmin_mm = increments(step, &w)?;
        }
        if let Some(w) = words.take(b'R') {
            data.allowance_mm = step.length(&w)?;
        }
        if step.profile.thread.g32_pull_out {
            // GSK: J/K in the first block; the pull-out is then that of G32/G92 (help note 2).
            if let Some(w) = words.take(b'J') {
                data.j = Some(step.length(&w)?);
            }
            if let Some(w) = words.take(b'K') {
                data.k = Some(step.length(&w)?);
            }
        }
        step.st.thread.g76 = Some(data);
        return Ok(());
    }
    let lead = step.read_lead(words, "G76", step.profile.thread.g32_pull_out, false, super::thread::MAX_LEAD_MM)?;
    let taper = match words.take(b'R') {
        Some(w) => step.length(&w)?,
        None => 0.0,
    };
    let height = match words.take(b'P') {
        Some(w) => increments(step, &w)?,
        None => return Err(g76_alarm(step, "the thread height P(k) is missing")),
    };
    let first = match words.take(b'Q') {
        Some(w) => increments(step, &w)?,
        None => return Err(g76_alarm(step, "the first depth Q(dd) is missing")),
    };
    let rpm = step.follow_rpm("G76")?;
    let a = step.st.pos;
    let (c, _) = axis_target(step, words)?;
    if (c.z - a.z).abs() < 1e-9 {
        return Err(g76_alarm(step, "the end point has the start point's Z: G76 cuts no face thread"));
    }
    if (c.x - a.x).abs() < 1e-9 {
        return Err(g76_alarm(step, "the start point is at the thread's root X: there is no room to retract"));
    }
    if data.finishing == 0 {
        step.warn(Rule::TextIgnored, step.span, "G76 with m = 0 finishing passes: the finishing allowance is never cut");
    }
    let schedule = depths(height, first, data.dmin_mm, data.allowance_mm, data.finishing).map_err(|e| g76_alarm(step, e))?;
    // External thread when the start is outside the root: deeper passes are at smaller X.
    let outward = if a.x > c.x { 1.0 } else { -1.0 };
    let dir_z = (c.z - a.z).signum();
    let half_angle = (data.angle_deg / 2.0).to_radians().tan();
    step.feed_warning("G76", lead, rpm);
    for depth in schedule {
        let end_x = c.x + outward * (height - depth);
        // Flank infeed: each pass starts depth x tan(a/2) further along the cut, so the tool cuts
        // on one flank (the start of the first, shallowest pass is nearest the programmed start).
        let cut_start = Vec3::new(end_x + taper, a.y, a.z + dir_z * depth * half_angle);
        let cut_end = Vec3::new(end_x, a.y, c.z);
        let retract = (a.x - end_x).abs();
        let pull_out = if data.j.is_some() || data.k.is_some() {
            gsk_jk_pull_out(step, data.j, data.k, data.pull_out_tenths, lead, outward)
        } else {
            let angle = step.profile.thread.g76.and_then(|k| k.pull_out_angle).map(|k| step.params.get(k)).unwrap_or(0.0);
            chamfer_of(data.pull_out_tenths, angle, lead, outward)
        }
        .map(|mut p| {
            p.short_mm = p.short_mm.min(retract);
            p
        });
        let spec = Cycle { start: a, cut_start, cut_end, lead_mm: lead, rpm, starts: 1, first_deg: 0.0, pull_out };
        let ops = expand_cycle(&spec).map_err(|e| step.pass_error("G76", e))?;
        step.st.thread.cycles += 1;
        let id = step.st.thread.cycles;
        let first_rec = step.out.records.len();
        for (_, op) in ops {
            step.emit(op);
        }
        for r in step.records_since(first_rec) {
            r.cycle = Some(id);
            if r.op.is_thread() {
                // Help note 1: FEED HOLD waits for the end of the thread.
                r.hold = Hold::AfterRun;
            }
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
    let a = step.st.pos;
    let (bottom, _) = axis_target(step, words)?;
    if bottom == a {
        return Ok(());
    }
    let depth = (bottom.z - a.z).abs();
    let position_mode = step.st.spindle_position_mode;
    let first = step.out.records.len();
    for k in 0..starts {
        let deg = k as f64 * 360.0 / starts as f64;
        step.emit(thread_op(a, bottom, lead, LongAxis::Z, deg, rpm));
        // Steps 2-4: M05 at the bottom, wait for the stop, turn the other way.
        step.emit(Op::Spindle { rpm: 0.0, surface_m_min: None, position_mode, oriented: false });
        step.emit(Op::Spindle { rpm: -rpm, surface_m_min: None, position_mode, oriented: false });
        let back_deg = wrap_deg(360.0 - phase_after(deg, depth, lead));
        step.emit(thread_op(bottom, a, lead, LongAxis::Z, back_deg, -rpm));
        // Step 6: M05.
        step.emit(Op::Spindle { rpm: 0.0, surface_m_min: None, position_mode, oriented: false });
    }
    step.st.spindle = SpindleDir::Stopped;
    // Help note 4: single block and feed hold wait for the end of the tapping.
    for r in step.records_since(first) {
        r.hold = Hold::AfterRun;
        r.override_free = true;
    }
    Ok(())
}

/// G34 variable lead (GSK980TDi help): the lead grows (or shrinks) by R every revolution. Cut as
/// one record per revolution, each with the lead of that revolution (its mean), so the spindle
/// angle at every record start is exact.
pub(super) fn variable_lead(step: &mut Step, words: &mut Words, run_deg: Option<f64>) -> Result<(), Diagnostic> {
    let lead = step.read_lead(words, "G34", true, false, super::thread::MAX_LEAD_MM)?;
    let change = match words.take(b'R') {
        Some(w) => step.length(&w)?,
        None => 0.0,
    };
    for l in [b'J', b'K'] {
        if let Some(w) = words.take(l) {
            let msg = format!("{}: the pull-out of a variable-lead thread is not simulated; the thread ends at its end point", w.text());
            step.warn(Rule::NotSimulated, w.span, msg);
        }
    }
    let q = step.read_q(words, 0.001, false)?;
    let rpm = step.follow_rpm("G34")?;
    let from = step.st.pos;
    let (to, _) = axis_target(step, words)?;
    if to == from {
        return Ok(());
    }
    let long_axis = LongAxis::of(&from, &to);
    let i = long_axis.index();
    let length = (to.axis(i) - from.axis(i)).abs();
    let start_deg = run_deg.or(q.map(|(d, _)| d)).unwrap_or(0.0);
    let mut done = 0.0;
    let mut n = 0u32;
    let mut at = from;
    let max = super::thread::MAX_LEAD_MM;
    while done < length - 1e-12 {
        // Lead during revolution n: F + R (n + 1/2); it must stay in (0, max] (help note 1).
        let rev_lead = lead + change * (n as f64 + 0.5);
        if !(rev_lead > 0.0 && lead + change * (n as f64 + 1.0) <= max + 1e-9 && lead + change * (n as f64 + 1.0) > 0.0) {
            return Err(step.alarm(
                Rule::ThreadData,
                step.span,
                format!("G34: after {n} revolutions the lead would leave 0 to {max} mm (F{lead} R{change})"),
            ));
        }
        let travel = rev_lead.min(length - done);
        done += travel;
        let next = super::lerp(&from, &to, done / length);
        step.emit(thread_op(at, next, rev_lead, long_axis, start_deg, rpm));
        at = next;
        n += 1;
        if n > 1_000_000 {
            return Err(step.alarm(Rule::MotionLimit, step.span, "G34: more than a million revolutions"));
        }
    }
    Ok(())
}
