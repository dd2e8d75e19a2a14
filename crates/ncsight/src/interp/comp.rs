//! The look-ahead stage of tool radius compensation (G40/G41/G42; MACRO.md 10.3,
//! docs/compensation.md). In compensation a move in the plane is held back until the next one
//! shows the corner between them (`crate::comp` does the geometry); the records that come
//! between (a move along the normal axis, a dwell, an M code) wait behind it, so the stream
//! stays in time order. The held records live in the interpreter's queue (restored when a block
//! alarms); the scalar state in `Modal::comp`.
//!
//! Positions in records are the point the controller positions: the nose centre plus the tip
//! vector (the imaginary tool nose on a lathe, tips 1-8), the centre itself on a mill.

use super::frame;
use super::Step;
use crate::alarm::{Diagnostic, Rule};
use crate::comp::{self, CompError, Seg, P2};
use crate::motion::{ArcDir, Op, Record, Vec3};
use crate::read;
use crate::source::Span;

/// The alarm rule of a compensation error.
pub(super) fn rule_of(e: CompError) -> Rule {
    match e {
        CompError::NoIntersection => Rule::CompNoSolution,
        CompError::Interference | CompError::ArcTooSmall => Rule::CompInterference,
    }
}

fn alarm_of(step: &Step, e: CompError, span: Span) -> Diagnostic {
    match e {
        CompError::NoIntersection => step.alarm(Rule::CompNoSolution, span, "radius compensation: the offset paths of this inner corner do not meet (the tool does not fit)"),
        CompError::Interference => step.alarm(
            Rule::CompInterference,
            span,
            "radius compensation: the compensated move would run against the programmed one (the tool is larger than this step: it would cut into the part)",
        ),
        CompError::ArcTooSmall => step.alarm(Rule::CompInterference, span, "radius compensation: the arc's radius is smaller than the tool's on its inner side"),
    }
}

/// Note the first compensation error of the block (the block then alarms).
fn fail(step: &mut Step, e: CompError, span: Span) {
    if step.out.comp_error.is_none() {
        let d = alarm_of(step, e, span);
        step.out.comp_error = Some(d);
    }
}

/// G40/G41/G42 of a block (`side` 0, +1, -1), with the block's D (mills). On a lathe the radius
/// and tip are those of the T offset in force.
pub(super) fn command(step: &mut Step, side: i8, d: Option<u32>, span: Span, arc_move: bool) -> Result<(), Diagnostic> {
    let c = step.st.comp;
    if side == 0 {
        if c.side != 0 && arc_move {
            // FANUC 034; GSK980TDi help text, G40-G42 note 2.
            return Err(step.alarm(Rule::CompStartupArc, span, "G40: compensation is cancelled in a G00 or G01 block only, not in an arc"));
        }
        // G40 with compensation off leaves a chamfer's held move for the block's move.
        if c.side != 0 {
            break_off(step);
        }
        step.st.comp.side = 0;
        step.st.comp.started = false;
        return Ok(());
    }
    // Compensation starting after a chamfer's move: that move is made first, with no corner.
    if c.side == 0 && !step.queue.is_empty() {
        break_off(step);
    }
    let lathe = step.profile.is_lathe();
    let number = if lathe { step.st.frame.offset_number } else { d.unwrap_or(c.d) };
    let e = frame::entry(step, number, span);
    let radius = e.radius_mm + e.wear_radius_mm;
    if radius < 0.0 {
        return Err(step.alarm(Rule::ValueOutOfRange, span, format!("offset {number}: the radius with its wear is negative ({radius:.3} mm)")));
    }
    // In polar coordinate interpolation the tip direction is 0 (GSK980TDi help text, G12.1 note 6).
    let tip = if lathe && step.st.polar_interp.is_none() {
        let (dx, dz) = comp::tip_direction(e.tip);
        Vec3::new(radius * dx, 0.0, radius * dz)
    } else {
        Vec3::default()
    };
    if c.side != 0 && (c.side != side || c.radius_mm != radius || c.tip != tip) {
        // A new side or radius: the path so far ends perpendicular; the next move starts anew.
        break_off(step);
    }
    if c.side != side && radius == 0.0 {
        let whose = if lathe { format!("the T offset in force ({number})") } else { format!("D{number}") };
        let msg = format!("G4{}: the radius of {whose} is 0 (no setup, or radius_mm 0 in its [[offset]]): the programmed path is the tool's", if side > 0 { 1 } else { 2 });
        step.warn(Rule::CompRadiusZero, span, msg);
    }
    let st = &mut step.st.comp;
    if st.side != side {
        // A new start: the next move is the start-up (type A).
        st.started = false;
    }
    st.side = side;
    st.radius_mm = radius;
    st.tip = tip;
    if let Some(d) = d {
        st.d = d;
    }
    Ok(())
}

/// The tip vector the stage adds: none in a contour worked out for roughing (its path is the
/// programmed one).
fn tip_of(step: &Step) -> Vec3 {
    if step.contour {
        Vec3::default()
    } else {
        step.st.comp.tip
    }
}

/// The side and radius the stage offsets by: none in a contour worked out for roughing.
fn side_radius(step: &Step) -> (f64, f64) {
    if step.contour {
        (0.0, 0.0)
    } else {
        (step.st.comp.side as f64, step.st.comp.radius_mm)
    }
}

/// `op` (a move) with its in-plane coordinates at centre `c` (its normal-axis ones kept), as the
/// controller positions it.
fn at_point(step: &Step, op: Op, c: P2) -> Op {
    let plane = step.st.plane;
    let tip = tip_of(step);
    let place = |p: Vec3| comp::with_local(&p, c, plane) + tip;
    match op {
        Op::Rapid { from, to } => Op::Rapid { from: place(from), to: place(to) },
        Op::Feed { from, to, feed_mm_min } => Op::Feed { from: place(from), to: place(to), feed_mm_min },
        other => other,
    }
}

/// A record the stage takes: a move in the plane is held (the one held before is made, with
/// the corner between); anything else waits behind a held move, or goes out now.
pub(super) fn take(step: &mut Step, span: Span, n: Option<u32>, op: Op) {
    let plane = step.st.plane;
    match Seg::of(&op, plane) {
        Some(seg) if !seg.is_point() => plane_move(step, span, n, op, seg),
        _ => {
            if !step.queue.is_empty() {
                step.queue.push(Record::of_block(span, n, op));
                return;
            }
            let op = match (step.st.comp.actual, op.start_point()) {
                (Some(c), Some(_)) => {
                    let op = at_point(step, op, comp::local(&c, plane));
                    // The tool is now at the move's end (a move along the normal axis).
                    step.st.comp.actual = op.end_point().map(|e| e - tip_of(step));
                    op
                }
                _ => op,
            };
            step.push_record(span, n, op);
        }
    }
}

fn plane_move(step: &mut Step, span: Span, n: Option<u32>, op: Op, seg: Seg) {
    if step.st.comp.side == 0 || step.contour {
        return corner_move(step, span, n, op, seg);
    }
    let plane = step.st.plane;
    let (side, r) = (step.st.comp.side as f64, step.st.comp.radius_mm);
    step.out.comp_plane_move = true;
    step.st.comp.idle_blocks = 0;
    let start3 = op.start_point().unwrap_or_default();
    if step.queue.is_empty() {
        // Start-up (type A), or a new start after the path was broken off.
        let centre = step.st.comp.actual.take().unwrap_or(start3 - step.st.comp.tip);
        if matches!(op, Op::Arc { .. }) {
            if !step.st.comp.started {
                let d = step.alarm(Rule::CompStartupArc, span, "G41/G42: compensation starts in a G00 or G01 block, not in an arc");
                if step.out.comp_error.is_none() {
                    step.out.comp_error = Some(d);
                }
                return;
            }
            // After a break: a straight move to the arc's offset start, then the arc.
            let s = seg.from().plus(comp::vector(&seg, false, side, r));
            let s3 = comp::with_local(&start3, s, plane);
            let link = Op::Feed { from: centre + step.st.comp.tip, to: s3 + step.st.comp.tip, feed_mm_min: feed_of(&op) };
            step.push_record(span, n, link);
            step.st.comp.held_start = s3;
            step.st.comp.held_startup = false;
        } else {
            step.st.comp.held_start = centre;
            step.st.comp.held_startup = true;
        }
        step.st.comp.started = true;
        step.queue.push(Record::of_block(span, n, op));
        return;
    }
    let held = step.queue[0].clone();
    let Some(hseg) = Seg::of(&held.op, plane) else {
        unreachable!("the queue's first record is a move in the plane")
    };
    // G39 between the held move and this one: an outer corner is an arc about the corner point,
    // from the held move's end perpendicular to this move's start perpendicular (FANUC 0i-M
    // manual, corner circular interpolation). An inner corner is as without it.
    // A rapid after G39 has no feed for the arc: the corner is made as without G39 (FANUC's
    // G39 is for cutting moves; inferred).
    if std::mem::take(&mut step.st.comp.round_corner) && !step.st.comp.held_startup && r > 0.0 && !matches!(op, Op::Rapid { .. }) {
        let p = hseg.to();
        let turn = hseg.tangent(true).cross(seg.tangent(false));
        if turn * side < -1e-12 {
            let (e, s) = (p.plus(comp::vector(&hseg, true, side, r)), p.plus(comp::vector(&seg, false, side, r)));
            if let Err(err) = make_held(step, e, None) {
                return fail(step, err, held.span);
            }
            let tip = step.st.comp.tip;
            let (a, b, c) = (comp::with_local(&start3, e, plane), comp::with_local(&start3, s, plane), comp::with_local(&start3, p, plane));
            let dir = if turn > 0.0 { ArcDir::Ccw } else { ArcDir::Cw };
            step.push_record(span, n, Op::Arc { from: a + tip, to: b + tip, center: c + tip, plane, dir, feed_mm_min: feed_of(&op) });
            note_span(step, span);
            step.st.comp.held_start = b;
            step.st.comp.held_startup = false;
            step.queue.push(Record::of_block(span, n, op));
            return;
        }
    }
    let corner = if step.st.comp.held_startup {
        // Type A: the start-up ends perpendicular to the next move at its start.
        let e = seg.from().plus(comp::vector(&seg, false, side, r));
        comp::Corner { first_end: e, between: Vec::new(), second_start: e }
    } else {
        match comp::corner(&hseg, &seg, side, r) {
            Ok(c) => c,
            Err(e) => return fail(step, e, span),
        }
    };
    if let Err(e) = make_held(step, corner.first_end, None) {
        return fail(step, e, held.span);
    }
    // The moves around an outer corner, at the next move's rate.
    let mut at = corner.first_end;
    for p in corner.between.iter().copied().chain(std::iter::once(corner.second_start)) {
        if p.dist(at) > 1e-9 {
            let (a, b) = (comp::with_local(&start3, at, plane), comp::with_local(&start3, p, plane));
            let link = match op {
                Op::Rapid { .. } => Op::Rapid { from: a + step.st.comp.tip, to: b + step.st.comp.tip },
                _ => Op::Feed { from: a + step.st.comp.tip, to: b + step.st.comp.tip, feed_mm_min: feed_of(&op) },
            };
            step.push_record(span, n, link);
            note_span(step, span);
        }
        at = p;
    }
    step.st.comp.held_start = comp::with_local(&start3, corner.second_start, plane);
    step.st.comp.held_startup = false;
    step.queue.push(Record::of_block(span, n, op));
}

/// A block whose records the stage made in this block (for the single-block marks).
fn note_span(step: &mut Step, span: Span) {
    if !step.out.comp_spans.contains(&span) {
        step.out.comp_spans.push(span);
    }
}

fn feed_of(op: &Op) -> f64 {
    match op {
        Op::Feed { feed_mm_min, .. } | Op::Arc { feed_mm_min, .. } => *feed_mm_min,
        _ => 0.0,
    }
}

/// Make the held move, compensated from its start to `end` (nose centre in the plane), then
/// `then` (a chamfer of the held move's block, and where it ends in the plane), then the
/// records that waited behind it, where the tool is by then. The queue is left empty. Returns
/// where the nose centre ends (the waiting moves along the normal axis included).
fn make_held(step: &mut Step, end: P2, then: Option<(Op, P2)>) -> Result<Vec3, CompError> {
    let plane = step.st.plane;
    let (side, r) = side_radius(step);
    let queue = std::mem::take(step.queue);
    let Some((held, rest)) = queue.split_first() else {
        return Ok(step.st.comp.held_start);
    };
    let hseg = Seg::of(&held.op, plane).expect("the queue's first record is a move in the plane");
    let start = step.st.comp.held_start;
    let end3 = comp::with_local(&held.op.end_point().unwrap_or_default(), end, plane);
    let result = comp::offset(&hseg, comp::local(&start, plane), end, side, r);
    let tip = tip_of(step);
    let made = match held.op {
        Op::Rapid { .. } => Op::Rapid { from: start + tip, to: end3 + tip },
        Op::Feed { feed_mm_min, .. } => Op::Feed { from: start + tip, to: end3 + tip, feed_mm_min },
        Op::Arc { center, plane, dir, feed_mm_min, .. } => Op::Arc { from: start + tip, to: end3 + tip, center: center + tip, plane, dir, feed_mm_min },
        other => other,
    };
    if let Err(e) = result {
        *step.queue = queue;
        return Err(e);
    }
    step.push_record(held.span, held.n, made);
    note_span(step, held.span);
    let (mut last, mut at) = (end3, end);
    if let Some((link, link_end)) = then {
        last = link.end_point().map_or(last, |e| e - tip);
        at = link_end;
        step.push_record(held.span, held.n, link);
    }
    for rec in rest {
        note_span(step, rec.span);
        let op = at_point(step, rec.op, at);
        if let Some(e) = op.end_point() {
            last = e - tip;
        }
        step.push_record(rec.span, rec.n, op);
    }
    let mut reuse = queue;
    reuse.clear();
    *step.queue = reuse;
    Ok(last)
}

/// The path is broken off: the held move ends perpendicular to itself at its end (cancel, a
/// block compensation does not act in, the look-ahead run out), and the tool stays there until
/// the next move.
pub(super) fn break_off(step: &mut Step) {
    // A line of an angle alone has no end yet: this block was to give it.
    if step.st.comp.angle_line.is_some() {
        return super::drawing::refuse(step);
    }
    // A G39 before the break has no corner left to round.
    step.st.comp.round_corner = false;
    if let Some(c) = step.st.comp.held_corner.take() {
        if step.profile.frame.drawing.is_some_and(|d| d.corner_needs_g01) {
            let d = step.alarm(Rule::CornerNoMove, step.span, format!("the block after {} makes no G01 move: the corner has no second move to join (FANUC alarm 051)", c.word()));
            step.out.comp_error.get_or_insert(d);
        } else {
            step.warn(Rule::TextIgnored, c.span, format!("{}: no G01 move follows it: no corner is made", c.word()));
        }
    }
    if step.queue.is_empty() {
        return;
    }
    let plane = step.st.plane;
    let held = step.queue[0].clone();
    let hseg = Seg::of(&held.op, plane).expect("the queue's first record is a move in the plane");
    let (side, r) = side_radius(step);
    let end = hseg.to().plus(comp::vector(&hseg, true, side, r));
    match make_held(step, end, None) {
        Ok(last) => step.st.comp.actual = Some(last),
        Err(e) => {
            // The held move cannot be made: what waited behind it still happens, where it was
            // written.
            let rest: Vec<Record> = step.queue.drain(1..).collect();
            step.queue.clear();
            for rec in rest {
                step.push_record(rec.span, rec.n, rec.op);
            }
            return fail(step, e, held.span);
        }
    }
    step.st.comp.idle_blocks = 0;
}

/// A chamfer or corner arc asked for in a G01/G02/G03 block (GSK980TDi help text, chamfer
/// function: L, D; FANUC 0-T direct drawing dimension programming: ,C ,R): the corner between
/// this block's move and the next. ncsight makes it between two straight moves (G01 to G01);
/// with an arc on either side it is not simulated yet.
pub(super) fn corner_words(step: &mut Step, words: &mut super::Words, rules: crate::profile::DrawingRules) -> Result<(), Diagnostic> {
    let (l, d) = (words.take(rules.chamfer), words.take(rules.round));
    let (w, round) = match (l, d) {
        (None, None) => return Ok(()),
        (Some(a), Some(b)) => {
            // FANUC alarm 053 is for two of I, K, R; here: one corner, one word (inferred).
            return Err(step.alarm(Rule::DuplicateWord, b.span, format!("{} and {}: a corner is a chamfer ({}) or an arc ({}), not both", a.text(), b.text(), read::address_name(rules.chamfer), read::address_name(rules.round))));
        }
        (Some(w), None) => (w, false),
        (None, Some(w)) => (w, true),
    };
    let size = step.length(w)?;
    if size <= 0.0 {
        return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: a chamfer or corner arc is longer than 0", w.text())));
    }
    if step.bypass_comp && !step.contour {
        return Err(step.alarm(Rule::NotSupported, w.span, format!("{}: a chamfer or corner arc in a block that radius compensation does not act in (a T word, a cycle) is not simulated by ncsight yet", w.text())));
    }
    if step.st.comp.side != 0 && !step.contour {
        return Err(step.alarm(Rule::NotSupported, w.span, format!("{}: a chamfer or corner arc in nose radius compensation is not simulated by ncsight yet", w.text())));
    }
    if step.st.motion != crate::modal::Motion::Linear {
        return Err(step.alarm(Rule::NotSupported, w.span, format!("{}: a chamfer or corner arc at the end of an arc (G02/G03) is not simulated by ncsight yet (G01 to G01 only)", w.text())));
    }
    // The stage adds no tip vector outside compensation: where the tool is stays where it is.
    // (A contour for roughing keeps its compensation's data for the finishing shape.)
    if !step.contour {
        let tip = step.st.comp.tip;
        if let Some(a) = step.st.comp.actual.as_mut() {
            *a = *a + tip;
        }
        step.st.comp.tip = Vec3::default();
    }
    let from_corner = rules.chamfer_type.is_none_or(|key| step.params.get(key) != 0.0);
    step.st.comp.corner_for_next = Some(crate::modal::CornerRequest { letter: w.letter, size_mm: size, round, from_corner, span: step.span });
    Ok(())
}

/// A move outside compensation while a chamfer waits (`plane_move` with side 0): the move held
/// is made to the chamfer's start, the chamfer (a line, or an arc tangent to both moves), and
/// this move waits from its end; a move held without a chamfer is made whole.
fn corner_move(step: &mut Step, span: Span, n: Option<u32>, op: Op, seg: Seg) {
    if step.st.comp.angle_line.is_some() {
        return super::drawing::refuse(step);
    }
    let plane = step.st.plane;
    let start3 = op.start_point().unwrap_or_default();
    let mut next_start = start3;
    if !step.queue.is_empty() {
        let held = step.queue[0].clone();
        let hseg = Seg::of(&held.op, plane).expect("the queue's first record is a move in the plane");
        let mut end = hseg.to();
        let mut chamfer = None;
        let mut corner = step.st.comp.held_corner.take();
        let strict = step.profile.frame.drawing.is_some_and(|d| d.corner_needs_g01);
        if let (Some(c), true) = (corner, strict && !matches!(op, Op::Feed { .. })) {
            // FANUC alarm 052: the block after a chamfer or corner R is a G01.
            let d = step.alarm(Rule::CornerNotLinear, span, format!("{} asks for a corner with a G01 move: this block's move is a {} (FANUC alarm 052)", c.word(), if matches!(op, Op::Rapid { .. }) { "G00" } else { "G02/G03" }));
            step.out.comp_error.get_or_insert(d);
            return;
        }
        if let (Some(c), Op::Rapid { .. }) = (corner, &op) {
            // The help text joins G01, G02 and G03 moves: a G00 next gets no corner.
            step.warn(Rule::TextIgnored, c.span, format!("{}: the next move is a G00: no corner is made", c.word()));
            corner = None;
        }
        if let Some(c) = corner {
            let lines = matches!((hseg, seg), (Seg::Line { .. }, Seg::Line { .. }));
            if !lines {
                let d = step.alarm(Rule::NotSupported, span, "a chamfer or corner arc next to an arc (G02/G03) is not simulated by ncsight yet (G01 to G01 only)");
                step.out.comp_error.get_or_insert(d);
                return;
            }
            let t_of = |u1: P2, u2: P2| {
                if c.round {
                    // Tangent to both: D tan(half the turn) from the corner.
                    c.size_mm * u1.cross(u2).abs() / (1.0 + u1.dot(u2))
                } else if c.from_corner {
                    c.size_mm
                } else {
                    c.size_mm / u1.plus(u2).len()
                }
            };
            if let Some((a, b, arc)) = comp::chamfer_points(&hseg, &seg, &t_of, c.round.then_some(c.size_mm)) {
                // Case 2: the chamfer cannot join the two moves (the held move starts where an
                // earlier chamfer ended, if one did).
                let t = a.dist(hseg.to());
                let held_length = comp::local(&step.st.comp.held_start, plane).dist(hseg.to());
                if !t.is_finite() || t > held_length + 1e-9 || t > seg.from().dist(seg.to()) + 1e-9 {
                    let needs = if t.is_finite() { format!("needs {} mm of each move, more than a move has", crate::alarm::shown(t, 4)) } else { "cannot join two moves that turn straight back".to_string() };
                    let msg = format!("{}{}: the corner {needs} (GSK980TDi help text, chamfer function, case 2; FANUC alarm 055)", read::address_name(c.letter), crate::alarm::shown(c.size_mm, 4));
                    let d = step.alarm(Rule::CornerTooLarge, c.span, msg);
                    step.out.comp_error.get_or_insert(d);
                    return;
                }
                // The held move, its chamfer, then what waited behind the move (an S, an M code).
                let (a3, b3) = (comp::with_local(&start3, a, plane), comp::with_local(&start3, b, plane));
                let feed = feed_of(&held.op);
                let link = match arc {
                    Some((centre, ccw)) => Op::Arc { from: a3, to: b3, center: comp::with_local(&start3, centre, plane), plane, dir: if ccw { ArcDir::Ccw } else { ArcDir::Cw }, feed_mm_min: feed },
                    None => Op::Feed { from: a3, to: b3, feed_mm_min: feed },
                };
                chamfer = Some((link, b));
                next_start = b3;
                end = a;
            }
        }
        if let Err(e) = make_held(step, end, chamfer) {
            return fail(step, e, held.span);
        }
    } else if let Some(a) = step.st.comp.actual.take() {
        next_start = a;
    }
    step.st.comp.held_start = next_start;
    step.st.comp.held_startup = false;
    step.st.comp.held_corner = step.st.comp.corner_for_next.take();
    step.out.comp_plane_move = true;
    step.queue.push(Record::of_block(span, n, op));
}

/// G39 (FANUC 0i-M manual, corner circular interpolation): the corner between the move held
/// and the next one is an arc of the cutter's radius about the corner point. Outside
/// compensation there is no corner to round: a warning. `G39 I_ J_` (the direction of a corner
/// not followed by a move) is not simulated.
pub(super) fn corner_arc(step: &mut Step, words: &mut super::Words, span: Span) -> Result<(), Diagnostic> {
    for l in [b'I', b'J', b'K'] {
        if let Some(w) = words.take(l) {
            return Err(step.alarm(Rule::NotSupported, w.span, format!("{}: G39 with a direction (I, J, K) is not simulated by ncsight yet", w.text())));
        }
    }
    if step.st.comp.side == 0 {
        step.warn(Rule::TextIgnored, span, "G39 outside cutter compensation (G41/G42): no corner to round");
        return Ok(());
    }
    step.st.comp.round_corner = true;
    // G39 stands between the two moves it joins: it is not a block without a move for the
    // look-ahead (or the path would end perpendicular before the corner it rounds).
    step.out.comp_plane_move = true;
    Ok(())
}

/// After a block in compensation: count it if it had no move in the plane; past the look-ahead
/// the held move ends perpendicular; the controller's limit of such blocks is an alarm (GSK980TDi
/// help text, G40-G42 note 1). The programme's end cancels compensation (note 3).
pub(super) fn end_of_block(step: &mut Step) -> Result<(), Diagnostic> {
    if step.st.ended {
        break_off(step);
        step.st.comp.side = 0;
        return Ok(());
    }
    if let Some(held) = step.st.comp.angle_line {
        return super::drawing::end_of_block(step, held);
    }
    if step.st.comp.side == 0 || step.contour {
        // A chamfer's move waits for the next block's move; anything else is made now.
        if !step.queue.is_empty() && !step.st.comp.held_corner.is_some_and(|c| c.span == step.span) {
            break_off(step);
        }
        return Ok(());
    }
    if step.queue.is_empty() || step.out.comp_plane_move {
        return Ok(());
    }
    step.st.comp.idle_blocks = step.st.comp.idle_blocks.saturating_add(1);
    let idle = step.st.comp.idle_blocks;
    if let Some(limit) = step.profile.frame.comp_idle_alarm {
        if idle >= limit {
            return Err(step.alarm(
                Rule::CompIdleBlocks,
                step.span,
                format!("{idle} blocks in a row without a move in radius compensation: {} allows fewer than {limit}", step.profile.name),
            ));
        }
    }
    if idle > step.profile.frame.comp_lookahead {
        break_off(step);
    }
    Ok(())
}

/// A move made outside compensation while the tool is off its programmed point (the move after
/// G40, or a block compensation does not act in) starts where the tool is.
pub(super) fn from_actual(step: &mut Step, span: Span, n: Option<u32>, op: Op) -> Op {
    let Some(c) = step.st.comp.actual else {
        return op;
    };
    if op.start_point().is_none() {
        return op;
    }
    step.st.comp.actual = None;
    let from = c + step.st.comp.tip;
    match op {
        // A plain move (the move after G40, a cycle's first rapid) goes from where the tool is.
        Op::Rapid { to, .. } => Op::Rapid { from, to },
        Op::Feed { to, feed_mm_min, .. } => Op::Feed { from, to, feed_mm_min },
        Op::Arc { to, center, plane, dir, feed_mm_min, .. } => Op::Arc { from, to, center, plane, dir, feed_mm_min },
        // A thread starts where it is written: the tool goes there first, at rapid.
        other => {
            if let Some(start) = other.start_point() {
                if start.dist(&from) > 1e-9 {
                    step.push_record(span, n, Op::Rapid { from, to: start });
                }
            }
            other
        }
    }
}
