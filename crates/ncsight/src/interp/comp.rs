//! The look-ahead stage of tool radius compensation (G40/G41/G42; docs/reference/macro.md 10.3,
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
        CompError::NoIntersection => {
            step.alarm(Rule::CompNoSolution, span, "radius compensation: the offset paths of this inner corner do not meet (the tool does not fit)")
        }
        CompError::Interference => step.alarm(
            Rule::CompInterference,
            span,
            "radius compensation: the compensated move would run against the programmed one (the tool is larger than this step: it would cut into the part)",
        ),
        CompError::ArcTooSmall => {
            step.alarm(Rule::CompInterference, span, "radius compensation: the arc's radius is smaller than the tool's on its inner side")
        }
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
        // The corner stage's held move is made first, in the mode it was programmed in (a
        // corner across G40 is not made: FANUC alarm 039 forbids one there).
        if c.side != 0 {
            super::corner::break_off(step);
            break_off(step);
        }
        step.st.comp.side = 0;
        step.st.comp.started = false;
        step.st.comp.resume = false;
        return Ok(());
    }
    // Compensation starting after a chamfer's move: that move is made first, with no corner.
    if c.side != side {
        super::corner::break_off(step);
    }
    let lathe = step.profile.is_lathe();
    let number = if lathe { step.st.frame.offset_number } else { d.unwrap_or(c.d) };
    let e = frame::entry(step, number, span);
    let radius = e.radius_mm + e.wear_radius_mm;
    if radius < 0.0 {
        return Err(step.alarm(Rule::ValueOutOfRange, span, format!("offset {number}: the radius with its wear is negative ({radius:.3} mm)")));
    }
    // In polar coordinate interpolation the tip direction is 0 (GSK980TDi help text, G12.1 note 6).
    let tip = if lathe && step.st.modes.polar_interp.is_none() {
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
        let msg = format!(
            "G4{}: the radius of {whose} is 0 (no setup, or radius_mm 0 in its [[offset]]): the programmed path is the tool's",
            if side > 0 { 1 } else { 2 }
        );
        step.warn(Rule::CompRadiusZero, span, msg);
    }
    let st = &mut step.st.comp;
    if st.side != side {
        // A new start: the next move is the start-up (type A).
        st.started = false;
        st.resume = false;
    }
    st.side = side;
    st.radius_mm = radius;
    st.tip = tip;
    if let Some(d) = d {
        st.d = d;
    }
    Ok(())
}

/// `op` (a move) with its in-plane coordinates at centre `c` (its normal-axis ones kept), as the
/// controller positions it.
fn at_point(step: &Step, op: Op, c: P2) -> Op {
    let plane = step.st.modes.plane;
    let tip = step.st.comp.tip;
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
    let plane = step.st.modes.plane;
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
                    step.st.comp.actual = op.end_point().map(|e| e - step.st.comp.tip);
                    op
                }
                _ => op,
            };
            step.push_record(span, n, op);
        }
    }
}

fn plane_move(step: &mut Step, span: Span, n: Option<u32>, op: Op, seg: Seg) {
    let plane = step.st.modes.plane;
    let (side, r) = (step.st.comp.side as f64, step.st.comp.radius_mm);
    step.out.comp_plane_move = true;
    step.st.comp.idle_blocks = 0;
    let start3 = op.start_point().unwrap_or_default();
    if step.queue.is_empty() {
        return start_up(step, span, n, op, seg, start3);
    }
    let held = step.queue[0].clone();
    let Some(hseg) = Seg::of(&held.op, plane) else { unreachable!("the queue's first record is a move in the plane") };
    if outer_corner_arc(step, span, n, op, &held, &hseg, &seg) {
        return;
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
    let slow = inside_corner_override(step, op, &held, &hseg, &seg);
    if let Err(e) = make_held(step, corner.first_end, slow.map_or(0.0, |s| s.0)) {
        return fail(step, e, held.span);
    }
    step.st.comp.slow_start_mm = slow.map_or(0.0, |s| s.1);
    outer_corner_moves(step, span, n, op, &corner, start3);
    step.st.comp.held_start = comp::with_local(&start3, corner.second_start, plane);
    step.st.comp.held_startup = false;
    step.queue.push(Record::of_block(span, n, op));
}

/// The first move in the plane with nothing held (`start3` its start): the start-up, held; an
/// arc after a break in the path is reached by a straight move to its offset start.
fn start_up(step: &mut Step, span: Span, n: Option<u32>, op: Op, seg: Seg, start3: Vec3) {
    let plane = step.st.modes.plane;
    let (side, r) = (step.st.comp.side as f64, step.st.comp.radius_mm);
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
        // After G39 with a direction the path goes on: the next corner is an ordinary one.
        step.st.comp.held_startup = !std::mem::take(&mut step.st.comp.resume);
    }
    step.st.comp.started = true;
    step.queue.push(Record::of_block(span, n, op));
}

/// G39's corner arc between the held move (`held`, its segment `hseg`) and this one (`seg`), at
/// an outer corner: the held move is made, then the arc, and this move is held. Whether the
/// corner is dealt with (made, or failed); false: it is made as without G39.
fn outer_corner_arc(step: &mut Step, span: Span, n: Option<u32>, op: Op, held: &Record, hseg: &Seg, seg: &Seg) -> bool {
    let plane = step.st.modes.plane;
    let start3 = op.start_point().unwrap_or_default();
    let (side, r) = (step.st.comp.side as f64, step.st.comp.radius_mm);
    // G39 between the held move and this one: an outer corner is an arc about the corner point,
    // from the held move's end perpendicular to this move's start perpendicular (FANUC 0i-M
    // manual, corner circular interpolation). An inner corner is as without it.
    // A rapid after G39 has no feed for the arc: the corner is made as without G39 (FANUC's
    // G39 is for cutting moves; inferred).
    if std::mem::take(&mut step.st.comp.round_corner) && !step.st.comp.held_startup && r > 0.0 && !matches!(op, Op::Rapid { .. }) {
        let p = hseg.to();
        let turn = hseg.tangent(true).cross(seg.tangent(false));
        if turn * side > 1e-12 {
            step.warn(
                Rule::CornerArcOvercut,
                span,
                "G39 at an inner corner: the FANUC manuals say the cutter overcuts here; ncsight makes the corner as without G39",
            );
        }
        if turn * side < -1e-12 {
            let (e, s) = (p.plus(comp::vector(hseg, true, side, r)), p.plus(comp::vector(seg, false, side, r)));
            if let Err(err) = make_held(step, e, 0.0) {
                fail(step, err, held.span);
                return true;
            }
            let tip = step.st.comp.tip;
            let (a, b, c) = (comp::with_local(&start3, e, plane), comp::with_local(&start3, s, plane), comp::with_local(&start3, p, plane));
            let dir = if turn > 0.0 { ArcDir::Ccw } else { ArcDir::Cw };
            step.push_record(span, n, Op::Arc { from: a + tip, to: b + tip, center: c + tip, plane, dir, feed_mm_min: feed_of(&op) });
            note_span(step, span);
            step.st.comp.held_start = b;
            step.st.comp.held_startup = false;
            step.queue.push(Record::of_block(span, n, op));
            return true;
        }
    }
    false
}

/// G62's slowdown about the corner between the held move and this one, where it acts: the
/// override before the corner and after it.
fn inside_corner_override(step: &Step, op: Op, held: &Record, hseg: &Seg, seg: &Seg) -> Option<(f64, f64)> {
    let (side, r) = (step.st.comp.side as f64, step.st.comp.radius_mm);
    // G62: an inner corner no wider than the parameter's angle slows the feed about it (FANUC
    // 16i manual, inside-corner override: not after a start-up, not for rapids).
    match step.profile.frame.corner_override {
        Some(keys)
            if step.st.comp.corner_override
                && !step.st.comp.held_startup
                && r > 0.0
                && !matches!(op, Op::Rapid { .. })
                && !matches!(held.op, Op::Rapid { .. }) =>
        {
            let (d1, d2) = (hseg.tangent(true), seg.tangent(false));
            let inner = d1.cross(d2) * side > 1e-12;
            let work_angle_deg = 180.0 - d1.dot(d2).clamp(-1.0, 1.0).acos().to_degrees();
            (inner && (2.0..=step.params.get(keys.angle)).contains(&work_angle_deg)).then(|| (step.params.get(keys.before), step.params.get(keys.after)))
        }
        _ => None,
    }
}

/// The moves from the held move's offset end around the corner to this move's offset start
/// (`start3` its start), as rapids or feeds as this move is.
fn outer_corner_moves(step: &mut Step, span: Span, n: Option<u32>, op: Op, corner: &comp::Corner, start3: Vec3) {
    let plane = step.st.modes.plane;
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
}

/// `op` cut in pieces: its first `start_mm` and last `end_mm` (along its path) at `factor` times
/// its feed, the rest as it is (G62).
fn slowed(op: Op, start_mm: f64, end_mm: f64, factor: f64) -> Vec<Op> {
    let (from, to) = match (op.start_point(), op.end_point()) {
        (Some(a), Some(b)) => (a, b),
        _ => return vec![op],
    };
    let geometry = crate::geom::arc_geom_of(&op);
    let length = match (&op, &geometry) {
        (Op::Feed { .. }, _) => from.dist(&to),
        (Op::Arc { plane, .. }, Some(g)) => crate::geom::arc_length(&from, &to, *plane, g),
        _ => return vec![op],
    };
    if length < 1e-9 {
        return vec![op];
    }
    let mut a = (start_mm / length).min(1.0);
    let mut b = (1.0 - end_mm / length).max(a);
    // Break points within a micrometre of another are one (no piece shorter than that: an
    // arc from a point to itself would be a whole circle).
    let snap = |u: f64| {
        if u * length < 1e-6 {
            0.0
        } else if (1.0 - u) * length < 1e-6 {
            1.0
        } else {
            u
        }
    };
    a = snap(a);
    b = snap(b).max(a);
    if (b - a) * length < 1e-6 {
        b = a;
    }
    let point = |u: f64| match (&op, &geometry) {
        (Op::Arc { plane, dir, .. }, Some(g)) => crate::geom::arc_point(&from, &to, *plane, *dir, g, u),
        _ => super::lerp(&from, &to, u),
    };
    let piece = |u0: f64, u1: f64, slow: bool| {
        let (p, q) = (if u0 <= 0.0 { from } else { point(u0) }, if u1 >= 1.0 { to } else { point(u1) });
        match op {
            Op::Feed { feed_mm_min, .. } => Op::Feed { from: p, to: q, feed_mm_min: if slow { feed_mm_min * factor } else { feed_mm_min } },
            Op::Arc { center, plane, dir, feed_mm_min, .. } => {
                Op::Arc { from: p, to: q, center, plane, dir, feed_mm_min: if slow { feed_mm_min * factor } else { feed_mm_min } }
            }
            other => other,
        }
    };
    [(0.0, a, true), (a, b, false), (b, 1.0, true)].into_iter().filter(|(u0, u1, _)| u1 > u0).map(|(u0, u1, slow)| piece(u0, u1, slow)).collect()
}

/// A block whose records the stage made in this block (for the single-block marks).
fn note_span(step: &mut Step, span: Span) {
    if !step.out.comp_spans.contains(&span) {
        step.out.comp_spans.push(span);
    }
}

pub(super) fn feed_of(op: &Op) -> f64 {
    match op {
        Op::Feed { feed_mm_min, .. } | Op::Arc { feed_mm_min, .. } => *feed_mm_min,
        _ => 0.0,
    }
}

/// Make the held move, compensated from its start to `end` (nose centre in the plane), then
/// the records that waited behind it, where the tool is by then. The queue is left empty.
/// Returns where the nose centre ends (the waiting moves along the normal axis included).
/// `slow_end_mm`: the last this much of it runs at G62's inner-corner override (and its first
/// `slow_start_mm`, when an inner corner came before it).
fn make_held(step: &mut Step, end: P2, slow_end_mm: f64) -> Result<Vec3, CompError> {
    let plane = step.st.modes.plane;
    let (side, r) = (step.st.comp.side as f64, step.st.comp.radius_mm);
    let queue = std::mem::take(step.queue);
    let Some((held, rest)) = queue.split_first() else {
        return Ok(step.st.comp.held_start);
    };
    let hseg = Seg::of(&held.op, plane).expect("the queue's first record is a move in the plane");
    let start = step.st.comp.held_start;
    let end3 = comp::with_local(&held.op.end_point().unwrap_or_default(), end, plane);
    let result = comp::offset(&hseg, comp::local(&start, plane), end, side, r);
    let tip = step.st.comp.tip;
    let made = match held.op {
        Op::Rapid { .. } => Op::Rapid { from: start + tip, to: end3 + tip },
        Op::Feed { feed_mm_min, .. } => Op::Feed { from: start + tip, to: end3 + tip, feed_mm_min },
        Op::Arc { from, center, plane, dir, feed_mm_min, .. } => {
            // Inside an arc the cutter centre runs on a smaller circle: the control slows it so
            // that the programmed path keeps F, down to parameter 1710 per cent at the least (the
            // FANUC 0i-M and 16i manuals, internal circular cutting feedrate change: in cutter
            // compensation whether G62 is on or not).
            let (programmed, centre_path) =
                (comp::local(&from, plane).dist(comp::local(&center, plane)), comp::local(&start, plane).dist(comp::local(&center, plane)));
            let feed_mm_min = match step.profile.frame.corner_override {
                Some(keys) if centre_path < programmed - 1e-9 && programmed > 0.0 => {
                    feed_mm_min * (centre_path / programmed).max(step.params.get(keys.arc_min_percent) / 100.0)
                }
                _ => feed_mm_min,
            };
            Op::Arc { from: start + tip, to: end3 + tip, center: center + tip, plane, dir, feed_mm_min }
        }
        other => other,
    };
    if let Err(e) = result {
        *step.queue = queue;
        return Err(e);
    }
    let slow_start_mm = std::mem::take(&mut step.st.comp.slow_start_mm);
    if slow_start_mm > 0.0 || slow_end_mm > 0.0 {
        let percent = step.profile.frame.corner_override.map_or(100.0, |k| step.params.get(k.percent));
        for (k, piece) in slowed(made, slow_start_mm, slow_end_mm, percent / 100.0).into_iter().enumerate() {
            // The pieces run on without stopping: only the first accelerates.
            if k == 0 || step.st.modes.polar_interp.is_some() {
                step.push_record(held.span, held.n, piece);
            } else {
                step.push_machine(held.span, held.n, piece, Some(0.0));
            }
        }
    } else {
        step.push_record(held.span, held.n, made);
    }
    note_span(step, held.span);
    let mut last = end3;
    for rec in rest {
        note_span(step, rec.span);
        let op = at_point(step, rec.op, end);
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
    // A G39 before the break has no corner left to round.
    step.st.comp.round_corner = false;
    step.st.comp.resume = false;
    if step.queue.is_empty() {
        return;
    }
    let plane = step.st.modes.plane;
    let held = step.queue[0].clone();
    let hseg = Seg::of(&held.op, plane).expect("the queue's first record is a move in the plane");
    let (side, r) = (step.st.comp.side as f64, step.st.comp.radius_mm);
    let end = hseg.to().plus(comp::vector(&hseg, true, side, r));
    match make_held(step, end, 0.0) {
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

/// G39 (FANUC 0i-M manual, corner circular interpolation): the corner between the move held
/// and the next one is an arc of the cutter's radius about the corner point. Outside
/// compensation there is no corner to round: a warning. With a direction (`G39 I_ J_`, from the
/// corner; or `G39 X_ Y_`, a point toward which, absolute or incremental: the FANUC 16-MC
/// manual) the arc is made at once, to the new offset vector at right angles to that direction
/// on the compensated side, clockwise with G41 and counter-clockwise with G42; the path goes on
/// from there.
pub(super) fn corner_arc(step: &mut Step, words: &mut super::Words, span: Span) -> Result<(), Diagnostic> {
    let plane = step.st.modes.plane;
    let (ia, ib, _) = plane.axes();
    let centre_letters = [b'I', b'J', b'K'];
    let (la, lb) = (centre_letters[ia], centre_letters[ib]);
    let corner = step.st.place.pos;
    let direction = if words.has(la) || words.has(lb) {
        let a = words.take(la).map(|w| step.length(w)).transpose()?.unwrap_or(0.0);
        let b = words.take(lb).map(|w| step.length(w)).transpose()?.unwrap_or(0.0);
        Some(P2::new(a, b))
    } else {
        let (target, given) = super::axis_target(step, words)?;
        let (_, _, normal) = plane.axes();
        if given[normal].is_some() {
            let w = words.peek([b'X', b'Y', b'Z'][normal]).or(words.peek([b'U', b'V', b'W'][normal]));
            let span = w.map_or(span, |w| w.span);
            return Err(step.alarm(Rule::WordNotTaken, span, "G39: its direction is a point in the plane; an axis off the plane moves nothing here"));
        }
        given.iter().any(Option::is_some).then(|| comp::local(&target, plane).minus(comp::local(&corner, plane)))
    };
    if let Some(w) = centre_letters.iter().filter(|l| **l != la && **l != lb).find_map(|l| words.take(*l)) {
        return Err(step.alarm(Rule::WordNotTaken, w.span, format!("{}: G39's direction is given in the plane's I, J or K", w.text())));
    }
    if step.st.comp.side == 0 {
        step.warn(Rule::TextIgnored, span, "G39 outside cutter compensation (G41/G42): no corner to round");
        return Ok(());
    }
    if let Some(d) = direction {
        return directed_corner_arc(step, span, d, corner);
    }
    step.st.comp.round_corner = true;
    // G39 stands between the two moves it joins: it is not a block without a move for the
    // look-ahead (or the path would end perpendicular before the corner it rounds).
    step.out.comp_plane_move = true;
    Ok(())
}

/// G39 with a direction `d` from the corner (the held move's programmed end `corner`).
fn directed_corner_arc(step: &mut Step, span: Span, d: P2, corner: Vec3) -> Result<(), Diagnostic> {
    let plane = step.st.modes.plane;
    let (side, r) = (step.st.comp.side as f64, step.st.comp.radius_mm);
    if d.len() < 1e-9 {
        return Err(step.alarm(Rule::ValueOutOfRange, span, "G39: the direction given is of length 0"));
    }
    if step.queue.is_empty() && step.st.comp.actual.is_none() {
        // No offset vector yet (G41/G42 without a move, or the path started anew): an arc in
        // the start-up is FANUC alarm 034.
        return Err(step.alarm(
            Rule::CompStartupArc,
            span,
            "G39 with a direction: no compensated move comes before it to turn from (an arc may not start compensation)",
        ));
    }
    let feed = step.cutting_feed(super::What::from("G39"), &|_| corner)?;
    // The held move ends at right angles to itself at the corner (its old vector).
    break_off(step);
    if step.out.comp_error.is_some() {
        return Ok(());
    }
    let tip = step.st.comp.tip;
    let from = step.st.comp.actual.unwrap_or(corner - tip);
    let p = comp::local(&corner, plane);
    // The arc keeps the radius the tool is at (after a D change the old one, until a move).
    let at_radius = comp::local(&from, plane).dist(p);
    let new_vector = d.unit().left().scale(side * if at_radius > 1e-9 { at_radius } else { r });
    let to = comp::with_local(&from, p.plus(new_vector), plane);
    // The path turning toward the cutter (an inner corner): the arc loops round through the
    // part (the FANUC 15i manual: G39 overcuts at an inner corner).
    let old_vector = comp::local(&from, plane).minus(p);
    let came_along = old_vector.left().scale(-side);
    if came_along.cross(d) * side > 1e-9 * old_vector.len().max(1.0) {
        step.warn(Rule::CornerArcOvercut, span, "G39 at an inner corner: the arc loops round through the part (the FANUC manuals: G39 overcuts there)");
    }
    if from.dist(&to) > 1e-9 {
        // G41 turns clockwise, G42 counter-clockwise (FANUC 16-MC manual).
        let dir = if side > 0.0 { ArcDir::Cw } else { ArcDir::Ccw };
        step.push_record(
            span,
            step.n,
            Op::Arc { from: from + tip, to: to + tip, center: comp::with_local(&from, p, plane) + tip, plane, dir, feed_mm_min: feed },
        );
    }
    step.st.comp.actual = Some(to);
    step.st.comp.resume = true;
    step.out.comp_plane_move = true;
    Ok(())
}

/// After a block in compensation: count it if it had no move in the plane; past the look-ahead
/// the held move ends perpendicular; the controller's limit of such blocks is an alarm (GSK980TDi
/// help text, G40-G42 note 1). The programme's end cancels compensation (note 3).
pub(super) fn end_of_block(step: &mut Step) -> Result<(), Diagnostic> {
    if step.st.modes.ended {
        break_off(step);
        step.st.comp.side = 0;
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
        Op::Rapid { to, .. } | Op::Feed { to, .. } | Op::Arc { to, .. } => op.with_ends(from, to),
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
