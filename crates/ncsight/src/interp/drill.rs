//! Drilling canned cycles on the FANUC 0-M (seed 003): the hole data that stays modal, K
//! repeats, G98/G99, and the mapping of the plane-local steps of `cycles::drill` onto X, Y, Z.

use super::words::Words;
use super::{Marks, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::drill::{self, DrillKind, Hole};
use crate::modal::SpindleDir;
use crate::motion::{Op, StopReason, Vec3};
use crate::profile::ParamKey;

/// Most repeats K (seed 003: "K 的最大取值为9999").
pub const MAX_REPEATS: f64 = 9999.0;

/// Most pecks one G73/G83 block may make (a limit of ncsight's, so that a broken Q cannot make a
/// programme of endless motion).
pub const MAX_PECKS: f64 = 30_000.0;

fn letter(axis: usize) -> u8 {
    [b'X', b'Y', b'Z'][axis]
}

/// Take the hole words (R, Q, P, the drilling-axis word) into the modal data.
fn take_hole_words(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let (_, _, n) = step.st.modes.plane.axes();
    let inc = step.st.modes.incremental;
    if let Some(w) = words.take(letter(n)) {
        let v = step.length(w)?;
        step.st.drill.bottom = Some((v, inc));
    }
    if let Some(w) = words.take(b'R') {
        let v = step.length(w)?;
        step.st.drill.r = Some((v, inc));
    }
    if let Some(w) = words.take(b'Q') {
        // Peck depth or shift; "Q is always positive" (seed 003 8.1.3, 8.1.7).
        let v = step.length(w)?.abs();
        step.st.drill.q = Some(v);
    }
    take_dwell(step, words)
}

/// The repeat count K (1 without K).
fn repeats(step: &mut Step, words: &mut Words) -> Result<u32, Diagnostic> {
    match words.take(b'K') {
        Some(w) => {
            if w.decimal || w.value < 0.0 || w.value > MAX_REPEATS {
                return Err(step.alarm(
                    Rule::ValueOutOfRange,
                    w.span,
                    format!("{}: the repeat count K is a whole number 0 to 9999 (FANUC 0-M manual, canned cycles)", w.text()),
                ));
            }
            Ok(w.value as u32)
        }
        None => Ok(1),
    }
}

/// The dwell P at the bottom, a whole number of ms (seed 003; GSK help text G83/87). A P that
/// M98 or M99 took in this block is the programme or sequence number, not the dwell: the hole
/// data P keeps its value (FANUC: `M98 P_` calls programme P; a cycle's first hole, then `M98 P_`
/// for the others, is everyday practice).
fn take_dwell(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    if !words.has_unused(b'P') {
        return Ok(());
    }
    if let Some(w) = words.take(b'P') {
        if w.decimal {
            return Err(step.alarm(Rule::IllegalDecimalPoint, w.span, format!("{}: the dwell P is a whole number of ms", w.text())));
        }
        if w.value < 0.0 {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the dwell P cannot be negative", w.text())));
        }
        step.st.drill.dwell_s = Some(w.value / 1000.0);
    }
    Ok(())
}

/// The record of one step of a hole, the tool at `here`, a point mapped by `global`; None for a
/// move that goes nowhere.
fn step_op(s: drill::Step, here: Vec3, global: impl Fn(drill::Local, &Vec3) -> Vec3, position_mode: bool, spindle_p: u32) -> Option<Op> {
    let op = match s {
        drill::Step::Rapid(l) => Op::Rapid { from: here, to: global(l, &here) },
        drill::Step::Feed(l, f) => Op::Feed { from: here, to: global(l, &here), feed_mm_min: f },
        drill::Step::Dwell(s) => Op::Dwell { seconds: s },
        drill::Step::Spindle(rpm) => Op::Spindle { rpm, surface_m_min: None, position_mode, oriented: false, p: spindle_p },
        drill::Step::Orient => Op::Spindle { rpm: 0.0, surface_m_min: None, position_mode, oriented: true, p: spindle_p },
        drill::Step::ManualRetract => Op::Stop { reason: StopReason::ManualRetract },
    };
    match op {
        Op::Rapid { from, to } | Op::Feed { from, to, .. } if from == to => None,
        op => Some(op),
    }
}

/// Where a hole leaves the tool (its last move's end, mapped by `global` from `from`), if it
/// moves.
fn hole_end(hole: &Hole, from: Vec3, global: impl Fn(drill::Local, &Vec3) -> Vec3) -> Option<Vec3> {
    drill::end_of(hole).map(|l| global(l, &from))
}

/// Emit the steps of one hole, mapped by `global`; single block stops after the hole. A tapping
/// hole drilled along the axis `tap_along`: feed hold and the feed override do not act from the
/// R level to the hole's end; the positioning to the hole (a rapid that keeps that axis) still
/// stops (seed 003 8.1.2, 8.1.8; the FANUC 0-T G84/G88 inferred the same).
fn emit_hole(step: &mut Step, hole: &Hole, tap_along: Option<usize>, global: impl Fn(drill::Local, &Vec3) -> Vec3) {
    let (position_mode, spindle_p) = (step.st.modes.spindle_position_mode, step.spindle_p());
    let first = step.out.records.len();
    if step.out.discard_records {
        // Nothing is kept: only where the hole leaves the tool matters.
        if let Some(end) = hole_end(hole, step.st.place.pos, &global) {
            step.st.place.pos = end;
        }
        return;
    }
    let tapping = Marks::TAPPING;
    let mut first_op = true;
    drill::expand_each(hole, &mut |s| {
        if let Some(op) = step_op(s, step.st.place.pos, &global, position_mode, spindle_p) {
            let positioning = first_op && tap_along.is_some_and(|along| matches!(op, Op::Rapid { from, to } if from.axis(along) == to.axis(along)));
            first_op = false;
            match tap_along {
                Some(_) if !positioning => step.marked(tapping, |step| step.emit(op)),
                _ => step.emit(op),
            }
        }
    });
    if let Some(last) = step.records_since(first).last_mut() {
        last.block_end = true;
    }
}

/// How many records a drilling block may make before its holes are made one at a time as they
/// are handed on ([`DeferredHoles`]) rather than held: far above a real programme's holes (the
/// goldens never reach it), so they keep the ordinary path.
const DEFER_RECORDS: f64 = 50_000.0;

/// The most records a deferred drilling block may make: a count at plan time, not a memory
/// bound, far above a real programme (a hundred million: about half a minute of the run; a
/// million pecks are three million), so a block that would run for days is said at once.
const MAX_DEFERRED_RECORDS: f64 = 100_000_000.0;

/// A drilling block's holes, laid out but not expanded: the driver makes their records one at a
/// time as it hands them on, so a block of any number of pecks (G83 with Q0.001 over a metre:
/// a million) holds a constant memory. Only where nothing between the cycle and the record
/// reshapes its moves (no cutter compensation, corner, coordinate transform or polar
/// interpolation, no soft limit or G22 area, not tapping).
#[derive(Debug, Clone)]
pub struct DeferredHoles {
    holes: Vec<Hole>,
    span: crate::source::Span,
    n: Option<u32>,
    to_machine: Vec3,
    plane: crate::motion::Plane,
    position_mode: bool,
    spindle_p: u32,
}

impl DeferredHoles {
    /// Every record of the holes, in order, each hole's last one ending the block for single
    /// block (as [`emit_hole`] marks it).
    pub fn each_record(&self, sink: &mut dyn FnMut(crate::motion::Record)) {
        for hole in &self.holes {
            let mut here = self.plane.from_local(hole.from);
            let mut held: Option<crate::motion::Record> = None;
            drill::expand_each(hole, &mut |s| {
                let Some(op) = step_op(s, here, |l, _| self.plane.from_local(l), self.position_mode, self.spindle_p) else { return };
                if let Some(to) = op.end_point() {
                    here = to;
                }
                let mut r = crate::motion::Record::of_block(self.span, self.n, op);
                r.to_machine = self.to_machine;
                if let Some(done) = held.replace(r) {
                    sink(done);
                }
            });
            if let Some(mut last) = held {
                last.block_end = true;
                sink(last);
            }
        }
    }
}

/// Whether a drilling block's records may be made as they are handed on ([`DeferredHoles`]):
/// as for any cycle's (`Step::may_defer_cuts`), with compensation off altogether and no soft
/// limit or G22 area (the holes are not walked dry), and no tapping cycle.
fn may_defer(step: &Step, kind: DrillKind) -> bool {
    step.may_defer_cuts()
        && step.st.comp.side == 0
        && !step.tables.limited
        && step.st.stroke2.is_none()
        && !step.st.modes.tapping_mode
        && !matches!(kind, DrillKind::G74 | DrillKind::G84)
}

/// GSK980TDi G83 (end face: hole at X, drilled along Z) and G87 (side: hole at Z, drilled along
/// X) (help text G83/87). The tool rapids to the hole position and drills from where it stands
/// on the drilling axis; the bottom, Q, R, P and J stay until G80 or a group 01 code, so a later
/// block with only a bottom drills again. A block without X, Z, U or W only stores its data.
fn from_start_block(step: &mut Step, words: &mut Words, kind: DrillKind) -> Result<(), Diagnostic> {
    let code = kind.code();
    let (place, along) = lathe_axes(step, kind)?;
    // G85/G89 take no Q, R or J (they bore in one feed).
    let pecks = !kind.bores_from_start();
    let word = if pecks { words.take(b'Q') } else { None };
    if let Some(w) = word {
        // Q in least input increments, a radius value.
        let q = super::compound::increments(step, w, code)?;
        if q < 0.0 {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the peck Q of {code} cannot be negative", w.text())));
        }
        step.st.drill.q = Some(q);
    }
    let word = if pecks { words.take(b'R') } else { None };
    if let Some(w) = word {
        let r = step.length(w)?;
        if r < 0.0 {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the retract R of {code} cannot be negative", w.text())));
        }
        step.st.drill.r = Some((r, false));
    }
    take_dwell(step, words)?;
    let word = if pecks { words.take(b'J') } else { None };
    if let Some(w) = word {
        if w.decimal || (w.value != 0.0 && w.value != 1.0) {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: J of {code} is 0 (high-speed peck) or 1 (deep hole)", w.text())));
        }
        step.st.drill.deep = w.value == 1.0;
    }
    let repeats = repeats(step, words)?;
    let place_at = lathe_position(step, words, place)?;
    let bottom_at = lathe_position(step, words, along)?;
    if let Some(b) = bottom_at {
        step.st.drill.bottom = Some((b, false));
    }
    if (place_at.is_none() && bottom_at.is_none()) || repeats == 0 {
        return Ok(());
    }
    let target = place_at.unwrap_or(step.st.place.pos.axis(place));
    let start = step.st.place.pos.axis(along);
    let axis_name = axis_name(along);
    let (bottom, _) = bottom_in_force(step, code, along)?;
    if bottom == start {
        return Err(step.alarm(
            Rule::DrillLevels,
            step.span,
            format!("{code}: the hole bottom {axis_name} is where the tool starts: there is nothing to drill"),
        ));
    }
    let d = step.st.drill;
    let q = d.q.unwrap_or(0.0);
    let retract = d.r.map_or(0.0, |r| r.0);
    let one_feed = q <= 0.0 || (!d.deep && retract <= 0.0);
    if !one_feed && ((bottom - start).abs() / q).ceil() * f64::from(repeats) > MAX_PECKS {
        return Err(step.alarm(Rule::MotionLimit, step.span, format!("{code}: more than {MAX_PECKS} pecks in one block (Q too small for the depth, times K)")));
    }
    let rpm = step.rpm_here();
    let global = lathe_global(place, along);
    for _ in 0..repeats {
        let from_g = step.st.place.pos;
        let at = [target, from_g.y];
        let feed = step.cutting_feed(code, &|u| global([at[0], at[1], start + (bottom - start) * u], &from_g))?;
        let hole = Hole {
            kind,
            from: [from_g.axis(place), from_g.y, from_g.axis(along)],
            at,
            initial: start,
            r: start,
            bottom,
            return_initial: true,
            q,
            dwell_s: d.dwell_s.unwrap_or(0.0),
            d: retract,
            deep: d.deep,
            shift_dir: [0.0; 2],
            feed,
            rpm,
        };
        emit_hole(step, &hole, None, global);
    }
    Ok(())
}

/// The `Vec3` axes of a lathe cycle, (hole position, drilling axis): G83 places the hole on X
/// and drills along Z, G87 the other way round; only in the G18 plane (GSK help text G83/87
/// note 2; a FANUC lathe has no other).
fn lathe_axes(step: &Step, kind: DrillKind) -> Result<(usize, usize), Diagnostic> {
    if step.st.modes.plane != crate::motion::Plane::ZX {
        return Err(step.alarm(Rule::PlaneMismatch, step.span, format!("{} drills only in the G18 plane (GSK980TDi help, G83/87 note 2)", kind.code())));
    }
    Ok(if kind.along_x() { (2, 0) } else { (0, 2) })
}

/// A lathe cycle's plane-local point on the machine: the hole position on `place`, the drilling
/// level on `along`, Y kept.
fn lathe_global(place: usize, along: usize) -> impl Fn(drill::Local, &Vec3) -> Vec3 + Copy {
    move |l, keep| {
        let mut v = *keep;
        v.set_axis(place, l[0]);
        v.y = l[1];
        v.set_axis(along, l[2]);
        v
    }
}

/// A lathe axis word, absolute (`abs_l`) or incremental (`inc_l`), in mm along the axis (X as a
/// radius): the value and whether it is incremental; both at once is an alarm.
fn lathe_word(step: &mut Step, words: &mut Words, axis: usize) -> Result<Option<(f64, bool)>, Diagnostic> {
    let (abs_l, inc_l) = if axis == 0 { (b'X', b'U') } else { (b'Z', b'W') };
    let scale = if axis == 0 && step.profile.diameter_x { 0.5 } else { 1.0 };
    match (words.take(abs_l), words.take(inc_l)) {
        (Some(a), Some(i)) => Err(step.alarm(Rule::DuplicateWord, i.span, format!("{} and {} both give the {} axis", a.text(), i.text(), abs_l as char))),
        (Some(w), None) => Ok(Some((step.length(w)? * scale, false))),
        (None, Some(w)) => Ok(Some((step.length(w)? * scale, true))),
        (None, None) => Ok(None),
    }
}

/// A lathe axis word as a position on that axis: absolute, or from where the tool stands.
fn lathe_position(step: &mut Step, words: &mut Words, axis: usize) -> Result<Option<f64>, Diagnostic> {
    let word = lathe_word(step, words, axis)?;
    Ok(word.map(|(v, inc)| if inc { step.st.place.pos.axis(axis) + v } else { v }))
}

/// How a lathe cycle's drilling axis is named in its messages.
fn axis_name(along: usize) -> &'static str {
    if along == 2 {
        "Z (W)"
    } else {
        "X (U)"
    }
}

/// The hole bottom in force (as stored: the value and whether it counts from the R level), or
/// the alarm that none was given since the cycle began.
fn bottom_in_force(step: &Step, code: &str, along: usize) -> Result<(f64, bool), Diagnostic> {
    step.st.drill.bottom.ok_or_else(|| step.alarm(Rule::MissingWord, step.span, format!("{code} needs the hole bottom {}", axis_name(along))))
}

/// FANUC 0-T G83 (face: the hole at X, drilled along Z) and G87 (side: the hole at Z, drilled
/// along X): rapid to the hole position, rapid to the R level (R, signed, is the distance from
/// the initial level), feed to the bottom Z (X; W, U from the R level), pecking by Q (the
/// high-speed or the standard cycle, by the profile's bit), dwell P, rapid back to the initial
/// level; K repeats (a FANUC lathe manual's format, quoted in docs/commands/g83_g87_lathe.md).
/// G84/G88 tap (the spindle reversed at the bottom) and G85/G89 bore (feed out to R) the same
/// way. The data stays until G80 or a group 01 code.
fn lathe_from_r_block(step: &mut Step, words: &mut Words, kind: DrillKind) -> Result<(), Diagnostic> {
    let code = kind.code();
    let (place, along) = lathe_axes(step, kind)?;
    if step.st.drill.kind != Some(kind) {
        // A new cycle (or the other one: its bottom lies on the other axis).
        *step.st.drill = Default::default();
        step.st.drill.initial = step.st.place.pos.axis(along);
        step.st.drill.kind = Some(kind);
    }
    let drilling = matches!(kind, DrillKind::FaceFromR | DrillKind::SideFromR);
    if let Some(w) = words.peek(b'Q') {
        if !drilling {
            // Peck tapping (FANUC 0i-T 5104#6 PCT) is not simulated; boring has no Q.
            if matches!(kind, DrillKind::FaceTapR | DrillKind::SideTapR) {
                return Err(step.alarm(
                    Rule::NotSupported,
                    w.span,
                    format!("{}: peck tapping (FANUC 5104 bit 6) is not simulated; {code} without Q taps in one feed", w.text()),
                ));
            }
            return Err(step.alarm(Rule::WordNotTaken, w.span, format!("{}: {code} (boring) has no peck depth Q", w.text())));
        }
    }
    if let Some(w) = words.take(b'Q') {
        // The depth of each peck along the drilling axis (a radius value along X, as R): always
        // incremental and positive (the FANUC 0-M rule, seed 003 8.1.7; inferred for the lathe).
        let v = step.length(w)?.abs();
        step.st.drill.q = Some(v);
    }
    let drills = [b'X', b'Z', b'U', b'W', b'R'].iter().any(|l| words.has(*l));
    if let Some(w) = words.take(b'R') {
        let r = step.length(w)?;
        step.st.drill.r = Some((r, true));
    }
    take_dwell(step, words)?;
    let repeats = repeats(step, words)?;
    if let Some(b) = lathe_word(step, words, along)? {
        step.st.drill.bottom = Some(b);
    }
    let target = lathe_position(step, words, place)?.unwrap_or(step.st.place.pos.axis(place));
    if !drills || repeats == 0 {
        return Ok(());
    }
    let d = step.st.drill;
    let (r_level, bottom) = lathe_levels(step, code, along)?;
    let q = if drilling { d.q.unwrap_or(0.0) } else { 0.0 };
    if q > 0.0 {
        let pecks = ((bottom - r_level).abs() / q).ceil() * repeats as f64;
        if pecks > MAX_PECKS {
            return Err(step.alarm(
                Rule::MotionLimit,
                step.span,
                format!("{code}: {pecks:.0} pecks in one block (Q too small for the depth, times K); at most {MAX_PECKS}"),
            ));
        }
    }
    let rules = step.profile.drill;
    let full_return = rules.lathe_peck_full_return.is_some_and(|k| step.params.get(k) != 0.0);
    let um = |key: Option<ParamKey>| key.map_or(0.0, |k| step.params.get(k) * 0.001);
    let d_mm = if full_return { um(rules.g83_clearance_um) } else { um(rules.g73_retract_um) };
    let tapping = matches!(kind, DrillKind::FaceTapR | DrillKind::SideTapR);
    let rpm = step.rpm_here();
    let global = lathe_global(place, along);
    for _ in 0..repeats {
        let from_g = step.st.place.pos;
        let at = [target, from_g.y];
        let feed = step.cutting_feed(code, &|u| global([at[0], at[1], r_level + (bottom - r_level) * u], &from_g))?;
        let hole = Hole {
            kind,
            from: [from_g.axis(place), from_g.y, from_g.axis(along)],
            at,
            initial: d.initial,
            r: r_level,
            bottom,
            // G-code systems B and C have G98/G99 (the initial level at power on); A has none.
            return_initial: step.st.modes.return_initial,
            q,
            dwell_s: d.dwell_s.unwrap_or(0.0),
            d: d_mm,
            deep: full_return,
            shift_dir: [0.0; 2],
            feed,
            rpm,
        };
        emit_hole(step, &hole, tapping.then_some(along), global);
    }
    Ok(())
}

/// The R level and the hole bottom of a FANUC 0-T lathe cycle along `along`: R from the initial
/// level, the bottom absolute or from the R level; the alarms for a hole of no depth and for an
/// R level beyond the bottom.
fn lathe_levels(step: &Step, code: &str, along: usize) -> Result<(f64, f64), Diagnostic> {
    let d = step.st.drill;
    let axis_name = axis_name(along);
    let (b, b_inc) = bottom_in_force(step, code, along)?;
    let r_level = d.initial + d.r.map_or(0.0, |r| r.0);
    let bottom = if b_inc { r_level + b } else { b };
    if (bottom - r_level).abs() < 1e-9 {
        return Err(step.alarm(Rule::DrillLevels, step.span, format!("{code}: the hole bottom {axis_name} is at the R level: there is nothing to drill")));
    }
    if (bottom - d.initial) * (bottom - r_level) <= 1e-12 {
        // The hole is drilled from the R level toward the bottom, the initial level on the R
        // level's side. An R level beyond the initial level (R away from the part) is taken as
        // the FANUC 0-M takes it: a rapid out to R first (the 0i-T's R is a signed distance
        // from the initial level, parameter 5102#6 RAB 0; no alarm is documented: inferred).
        return Err(step.alarm(
            Rule::DrillLevels,
            step.span,
            format!(
                "{code}: R {r_level:.3} and bottom {bottom:.3}: the R level must lie on the initial level's side of the hole bottom (initial level {:.3})",
                d.initial
            ),
        ));
    }
    Ok((r_level, bottom))
}

/// GSK980TDi G84 (end face: the hole at X, tapped along Z) and G88 (side: the hole at Z, tapped
/// along X), rigid tapping after `M29 S_` (help text G84/88): rapid to the hole position (the
/// tapping start point, at the level the tool stands on), tap to the bottom with the spindle
/// (lead F; F > 0 right-hand, F < 0 left-hand; or I threads per inch), dwell P, tap back out with
/// the spindle reversed to the start point; K repeats. FEED HOLD and single block wait for the
/// end of the tapping (note 4). The bottom, P and the hand stay until G80 or a group 01 code.
fn rigid_tap_block(step: &mut Step, words: &mut Words, kind: DrillKind) -> Result<(), Diagnostic> {
    let code = kind.code();
    let (place, along) = lathe_axes(step, kind)?;
    step.st.drill.kind = Some(kind);
    if !step.st.drill.rigid_tap {
        return Err(step.alarm(Rule::RigidTapOrder, step.span, format!("{code} needs M29 S_ before it (help text G84/88: rigid tapping is specified by M29)")));
    }
    let lead = match words.take(b'F') {
        Some(w) => {
            // The hand from F's sign, the lead its size; it stays as the F in force.
            let lead = step.lead_word(w);
            if lead == 0.0 || lead.abs() > super::thread::MAX_LEAD_MM + 1e-9 {
                return Err(step.alarm(
                    Rule::ValueOutOfRange,
                    w.span,
                    format!("{}: the lead of {code} must be other than 0 and at most {} mm", w.text(), super::thread::MAX_LEAD_MM),
                ));
            }
            step.st.drill.tap_left = lead < 0.0;
            step.st.modes.feed = Some(lead.abs());
            step.st.thread.lead_mm = None;
            lead.abs()
        }
        // I threads per inch, or the lead in force.
        None => step.read_lead(words, code, true, false, super::thread::MAX_LEAD_MM)?,
    };
    take_dwell(step, words)?;
    let repeats = repeats(step, words)?;
    let bottom_given = lathe_position(step, words, along)?;
    if let Some(b) = bottom_given {
        step.st.drill.bottom = Some((b, false));
    }
    let target = lathe_position(step, words, place)?;
    // A block without a position or a bottom only stores its data (F, P).
    if (target.is_none() && bottom_given.is_none()) || repeats == 0 {
        return Ok(());
    }
    let axis_name = axis_name(along);
    let (bottom, _) = bottom_in_force(step, code, along)?;
    let rpm = step.follow_rpm(code)?.abs();
    let rpm_in = if step.st.drill.tap_left { -rpm } else { rpm };
    step.st.drill.tap_waiting = false;
    let dwell_s = step.st.drill.dwell_s.unwrap_or(0.0);
    for _ in 0..repeats {
        let mut start = step.st.place.pos;
        if let Some(t) = target {
            start.set_axis(place, t);
        }
        if start != step.st.place.pos {
            step.emit(Op::Rapid { from: step.st.place.pos, to: start });
        }
        let mut end = start;
        end.set_axis(along, bottom);
        if end == start {
            return Err(step.alarm(
                Rule::DrillLevels,
                step.span,
                format!("{code}: the hole bottom {axis_name} is where the tool starts: there is nothing to tap"),
            ));
        }
        let tapping = step.out.records.len();
        let dwell = [Op::Dwell { seconds: dwell_s }];
        let at_bottom: &[Op] = if dwell_s > 0.0 { &dwell } else { &[] };
        // Note 4: FEED HOLD and single block wait for the end of the tapping and its way out;
        // single block stops after each hole, K times for K repeats (docs/commands/operator.md).
        let marks = Marks::TAPPING;
        step.marked(marks, |step| {
            for op in crate::cycles::tap::stroke(start, end, lead, 0.0, rpm_in, at_bottom) {
                step.emit(op);
            }
        });
        if let Some(last) = step.records_since(tapping).last_mut() {
            last.block_end = true;
        }
    }
    Ok(())
}

/// A block while a drilling cycle is in force. `entering`: the block names a cycle code.
pub(super) fn block(step: &mut Step, words: &mut Words, kind: DrillKind, entering: bool) -> Result<(), Diagnostic> {
    if kind.rigid_tap() {
        return rigid_tap_block(step, words, kind);
    }
    if kind.from_start() {
        step.st.drill.kind = Some(kind);
        return from_start_block(step, words, kind);
    }
    if kind.on_lathe() {
        return lathe_from_r_block(step, words, kind);
    }
    let plane = step.st.modes.plane;
    let (a, b, n) = plane.axes();
    if entering && step.st.drill.kind.is_none() {
        // The initial level is where the tool stands when the cycle mode is entered (docs/reference/behaviour.md).
        step.st.drill.initial = step.st.place.pos.axis(n);
    }
    // Read before it is written: a hole block of the cycle in force changes no drilling data.
    if step.st.drill.kind != Some(kind) {
        step.st.drill.kind = Some(kind);
    }
    let drills = words.has(letter(a)) || words.has(letter(b)) || words.has(letter(n)) || words.has(b'R');
    take_hole_words(step, words)?;
    let repeats = repeats(step, words)?;
    let (delta_a, delta_b, target_a, target_b) = hole_position(step, words, a, b)?;
    if !drills || repeats == 0 {
        // K0: the data is stored, nothing moves (seed 003; docs/reference/parameters.md: no positioning).
        return Ok(());
    }
    let (r, bottom) = hole_levels(step, kind)?;
    if kind == DrillKind::G87 && !step.st.modes.return_initial {
        step.warn(Rule::ReturnLevel, step.span, "G87 returns to the initial level even under G99 (the R level is below the part)");
    }
    let rpm = step.rpm_here();
    tapping_warnings(step, kind, rpm);
    let defer = defers_holes(step, kind, r, bottom, repeats)?;
    let d = step.st.drill;
    // The hole as every repeat makes it; `from`, `at` and `feed` are each hole's own.
    let template = Hole {
        kind,
        from: [0.0; 3],
        at: [0.0; 2],
        initial: d.initial,
        r,
        bottom,
        return_initial: step.st.modes.return_initial,
        q: d.q.unwrap_or(0.0),
        dwell_s: d.dwell_s.unwrap_or(0.0),
        d: peck_retract_mm(step, kind),
        deep: false,
        shift_dir: shift_direction(step, kind),
        feed: 0.0,
        rpm,
    };
    make_holes(step, &template, repeats, (delta_a, delta_b), (target_a, target_b), defer)
}

/// The hole position in the plane from the block's positioning words on the plane's axes `a`
/// and `b`: the increment each repeat moves by under G91 (0 under G90) and the first hole's
/// position, as (delta a, delta b, target a, target b).
#[inline(always)]
fn hole_position(step: &mut Step, words: &mut Words, a: usize, b: usize) -> Result<(f64, f64, f64, f64), Diagnostic> {
    // Positioning words in the plane.
    // Kept in scalars, not arrays written element by element: this runs for every hole.
    let (mut delta_a, mut delta_b) = (0.0, 0.0);
    let (mut target_a, mut target_b) = (step.st.place.pos.axis(a), step.st.place.pos.axis(b));
    for (delta, target, axis) in [(&mut delta_a, &mut target_a, a), (&mut delta_b, &mut target_b, b)] {
        if let Some(w) = words.take(letter(axis)) {
            let v = step.length(w)?;
            if step.st.modes.incremental {
                *delta = v;
                *target += v;
            } else {
                *target = v;
            }
        }
    }
    Ok((delta_a, delta_b, target_a, target_b))
}

/// The R level and the hole bottom of the hole data in force, from the initial level (R and Z
/// each absolute or incremental): the alarms for a missing R, Z or peck depth Q, and for an R
/// level on the wrong side of the bottom.
#[inline(always)]
fn hole_levels(step: &Step, kind: DrillKind) -> Result<(f64, f64), Diagnostic> {
    let code = kind.code();
    let d = step.st.drill;
    let (Some((r_word, r_inc)), Some((z_word, z_inc))) = (d.r, d.bottom) else {
        let missing = if d.r.is_none() { "R" } else { "the hole bottom" };
        return Err(step.alarm(
            Rule::MissingWord,
            step.span,
            format!("{code} needs {missing}: Z and R must be given when a cycle starts, also after G80 or a group 01 code (FANUC 0-M manual, canned cycles)"),
        ));
    };
    if kind.needs_q() && d.q.unwrap_or(0.0) <= 0.0 {
        return Err(step.alarm(Rule::PeckMissing, step.span, format!("{code} needs the peck depth Q greater than 0")));
    }
    let initial = d.initial;
    let r = if r_inc { initial + r_word } else { r_word };
    let bottom = if z_inc { r + z_word } else { z_word };
    let wrong = if kind == DrillKind::G87 { bottom <= r } else { bottom >= r };
    if wrong {
        let what = if kind == DrillKind::G87 {
            "G87 backs up from the R level below the hole: R must be below Z"
        } else {
            "the R level must be above the hole bottom Z"
        };
        return Err(step.alarm(Rule::DrillLevels, step.span, format!("{code}: R {r:.3} and bottom {bottom:.3}: {what}")));
    }
    Ok((r, bottom))
}

/// The warnings of a tapping cycle (G74, G84): the spindle turning the other way than the tap,
/// and a pitch (F over S) no tap has.
#[inline(always)]
fn tapping_warnings(step: &mut Step, kind: DrillKind, rpm: f64) {
    let code = kind.code();
    if matches!(kind, DrillKind::G74 | DrillKind::G84) {
        let (want, name) = if kind == DrillKind::G84 { (SpindleDir::Positive, "M03") } else { (SpindleDir::Negative, "M04") };
        if step.st.modes.spindle != want {
            let msg = format!("{code} taps with the spindle turning {name}-wise; it is not (FANUC 0-M manual, canned cycles: program {name} before the cycle)");
            step.warn(Rule::TapDirection, step.span, msg);
        }
    }
    if matches!(kind, DrillKind::G74 | DrillKind::G84) {
        // The pitch the feed and speed make (seed 003: F/S is the pitch): a word for F/S slips.
        if let (Some(f), true) = (step.st.modes.feed, rpm.abs() > 0.0) {
            let pitch = if step.st.modes.per_rev { f } else { f / rpm.abs() };
            if !(0.2..=10.0).contains(&pitch) {
                let unit = if step.st.modes.inch { 25.4 } else { 1.0 };
                let msg = format!(
                    "{code}: F{} at {} rpm taps a pitch of {} mm; taps run from 0.2 to 10 mm (F = pitch x S under G94)",
                    crate::alarm::shown(f / unit, 4),
                    crate::alarm::shown(rpm.abs(), 1),
                    crate::alarm::shown(pitch, 4)
                );
                step.warn(Rule::Implausible, step.span, msg);
            }
        }
    }
}

/// Whether the block's holes are made as they are handed on ([`DeferredHoles`]) rather than
/// held; the alarm for a block of more pecks (or moves) than one block may make.
#[inline(always)]
fn defers_holes(step: &Step, kind: DrillKind, r: f64, bottom: f64, repeats: u32) -> Result<bool, Diagnostic> {
    let code = kind.code();
    let d = step.st.drill;
    // The records the block makes, about: three a peck, five a hole. Past DEFER_RECORDS they are
    // made as they are handed on where nothing reshapes them, and any number is taken (a check
    // keeps none anyway); elsewhere a cap on the motion one block may make (issue 10).
    let pecks = if kind.needs_q() { ((bottom - r).abs() / d.q.unwrap_or(1.0)).ceil() * repeats as f64 } else { 0.0 };
    let records = 3.0 * pecks + 5.0 * repeats as f64;
    // The count first: it is a comparison, the stages' state a dozen reads.
    let defer = records > DEFER_RECORDS && may_defer(step, kind);
    if defer && records > MAX_DEFERRED_RECORDS {
        return Err(step.alarm(
            Rule::MotionLimit,
            step.span,
            format!("{code}: about {records:.0} moves in one block (Q too small for the depth, times K); at most {MAX_DEFERRED_RECORDS:.0}"),
        ));
    }
    if kind.needs_q() && !defer && pecks > MAX_PECKS {
        return Err(step.alarm(
            Rule::MotionLimit,
            step.span,
            format!("{code}: {pecks:.0} pecks in one block (Q too small for the depth, times K); at most {MAX_PECKS}"),
        ));
    }
    Ok(defer)
}

/// The retract d after each peck: G73's retract, G83's clearance (the profile's parameters, mm);
/// 0 for the other cycles.
#[inline(always)]
fn peck_retract_mm(step: &Step, kind: DrillKind) -> f64 {
    let rules = step.profile.drill;
    let um = |key: Option<ParamKey>| key.map_or(0.0, |k| step.params.get(k) * 0.001);
    match kind {
        DrillKind::G73 => um(rules.g73_retract_um),
        DrillKind::G83 => um(rules.g83_clearance_um),
        _ => 0.0,
    }
}

/// The unit direction in the plane a G76/G87 shift moves the tool (the profile's shift bits);
/// none for the other cycles.
#[inline(always)]
fn shift_direction(step: &Step, kind: DrillKind) -> [f64; 2] {
    let rules = step.profile.drill;
    // The shift bits (high, low): 00 +X, 01 -X, 10 +Y, 11 -Y (docs/guide.md); X is the plane's
    // first axis and Y its second (exact in G17).
    match rules.shift_bits {
        Some((low, high)) if kind.shifts() => {
            let b4 = step.params.get(low) != 0.0;
            let b5 = step.params.get(high) != 0.0;
            let sign = if b4 { -1.0 } else { 1.0 };
            if b5 {
                [0.0, sign]
            } else {
                [sign, 0.0]
            }
        }
        // A profile without the bits shifts along +X.
        None if kind.shifts() => [1.0, 0.0],
        _ => [0.0; 2],
    }
}

/// The block's `repeats` holes, `template` at each position from `target` (moved on by `delta`
/// each repeat under G91), from where the tool stands: made now, or laid out to be made as they
/// are handed on (`defer`).
#[inline(always)]
fn make_holes(
    step: &mut Step,
    template: &Hole,
    repeats: u32,
    (delta_a, delta_b): (f64, f64),
    (mut target_a, mut target_b): (f64, f64),
    defer: bool,
) -> Result<(), Diagnostic> {
    let kind = template.kind;
    let code = kind.code();
    let (r, bottom) = (template.r, template.bottom);
    let plane = step.st.modes.plane;
    let (a, b, n) = plane.axes();
    let mut deferred = Vec::new();
    for k in 0..repeats {
        if k > 0 && step.st.modes.incremental {
            // Under G91 each repeat moves by the increment again: equally spaced holes.
            target_a += delta_a;
            target_b += delta_b;
        }
        let from_g = step.st.place.pos;
        let from = [from_g.axis(a), from_g.axis(b), from_g.axis(n)];
        let at = [target_a, target_b];
        let feed = step.cutting_feed(code, &|u| {
            let lvl = r + (bottom - r) * u;
            plane.from_local([at[0], at[1], lvl])
        })?;
        let hole = Hole { from, at, feed, ..*template };
        if defer {
            // Laid out now, made as they are handed on: the tool is where the hole leaves it.
            if let Some(end) = hole_end(&hole, step.st.place.pos, |l, _| plane.from_local(l)) {
                step.st.place.pos = end;
                step.st.frame.unmoved = Vec3::default();
            }
            deferred.push(hole);
            continue;
        }
        // Tapping: feed hold and feed override are ignored until the cycle ends (seed 003 8.1.2);
        // positioning to the hole still stops. Single block stops after each hole (docs/reference/behaviour.md).
        let tap_along = matches!(kind, DrillKind::G74 | DrillKind::G84).then_some(n);
        emit_hole(step, &hole, tap_along, |l, _| plane.from_local(l));
    }
    if !deferred.is_empty() && !step.out.discard_records {
        let holes = DeferredHoles {
            holes: deferred,
            span: step.span,
            n: step.n,
            to_machine: step.tables.to_machine(&step.st.frame),
            plane,
            position_mode: step.st.modes.spindle_position_mode,
            spindle_p: step.spindle_p(),
        };
        step.out.deferred = Some(Box::new((step.out.records.len(), super::Deferred::Holes(holes))));
    }
    Ok(())
}
