//! The corner stage (docs/commands/chamfer.md, drawing.md): a move whose block asks for a
//! chamfer or a corner arc (GSK980TDi L, D; FANUC 0-T ,C ,R) is held until the next block's move
//! shows the corner; a line given by its angle alone is held until the next block gives its end
//! (interp/drawing.rs). The stage works on the programmed path; what it makes goes on to radius
//! compensation's look-ahead (interp/comp.rs) when that is on, else out. Records that come while
//! a move is held (a move along the normal axis, a dwell, an M code) wait behind it, so the
//! stream stays in time order. The held records live in the interpreter's corner queue
//! (restored when a block alarms); the scalar state in `Modal::comp`.

use super::{comp, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::comp::{self as geometry, Seg};
use crate::modal::{CornerRequest, RightAngle};
use crate::motion::{ArcDir, Op, Record};
use crate::read::{self, Word};
use crate::source::Span;

/// A chamfer or corner arc asked for in a G01 block (G02/G03 too where the profile allows): the
/// corner between this block's move and the next, each a line or an arc.
pub(super) fn words(step: &mut Step, words: &mut super::Words, rules: crate::profile::DrawingRules) -> Result<(), Diagnostic> {
    refuse_comma(step, words, rules)?;
    let right_angle = if rules.right_angle && step.st.modes.motion == crate::modal::Motion::Linear { right_angle_words(step, words, rules)? } else { None };
    let asked = match right_angle {
        Some(asked) => Some(asked),
        None => drawing_words(step, words, rules)?,
    };
    if asked.is_some() {
        step.st.comp.corner_for_next = asked;
    }
    Ok(())
}

/// The drawing's words are plain C, R and A (FANUC 0i-TF parameter 3405#4 CCR = 1).
pub(super) fn plain_letters(step: &Step, rules: crate::profile::DrawingRules) -> bool {
    rules.plain_letters.is_some_and(|k| step.params.get(k) != 0.0)
}

/// With the plain letters in force, a comma word is FANUC alarm PS0312.
pub(super) fn refuse_comma(step: &Step, words: &super::Words, rules: crate::profile::DrawingRules) -> Result<(), Diagnostic> {
    if !plain_letters(step, rules) {
        return Ok(());
    }
    match [rules.chamfer, rules.round, rules.angle].iter().find_map(|l| words.peek(*l)) {
        Some(w) => Err(step.alarm(
            Rule::DrawingComma,
            w.span,
            format!("{}: parameter 3405#4 (CCR) is 1, so the drawing's words are C, R and A without the comma", w.text()),
        )),
        None => Ok(()),
    }
}

/// A corner in a block that radius compensation does not act in (a T word, a cycle) is not
/// simulated; in a roughing contour it is.
fn refuse_bypassed(step: &Step, w: &Word) -> Result<(), Diagnostic> {
    if step.bypass_comp && !step.contour {
        return Err(step.alarm(
            Rule::NotSupported,
            w.span,
            format!(
                "{}: a chamfer or corner arc in a block that radius compensation does not act in (a T word, a cycle) is not simulated by ncsight yet",
                w.text()
            ),
        ));
    }
    Ok(())
}

/// L/D (GSK) or ,C/,R (FANUC): the chamfer's size or the arc's radius, measured as the profile
/// says.
fn drawing_words(step: &mut Step, words: &mut super::Words, rules: crate::profile::DrawingRules) -> Result<Option<CornerRequest>, Diagnostic> {
    // FANUC 0i-TF 3405#4 CCR = 1: C and R without the comma.
    let plain = plain_letters(step, rules);
    let l = words.take(rules.chamfer).or_else(|| if plain { words.take(b'C') } else { None });
    let d = words.take(rules.round).or_else(|| if plain { words.take(b'R') } else { None });
    let (w, round) = match (l, d) {
        (None, None) => return Ok(None),
        (Some(a), Some(b)) => {
            // FANUC alarm 053 is for two of I, K, R; here: one corner, one word (inferred).
            return Err(step.alarm(
                Rule::DuplicateWord,
                b.span,
                format!(
                    "{} and {}: a corner is a chamfer ({}) or an arc ({}), not both",
                    a.text(),
                    b.text(),
                    read::address_name(rules.chamfer),
                    read::address_name(rules.round)
                ),
            ));
        }
        (Some(w), None) => (w, false),
        (None, Some(w)) => (w, true),
    };
    let size = step.length(w)?;
    if size <= 0.0 {
        return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: a chamfer or corner arc is longer than 0", w.text())));
    }
    refuse_bypassed(step, w)?;
    let from_corner = rules.chamfer_type.is_none_or(|key| step.params.get(key) != 0.0);
    Ok(Some(CornerRequest { letter: w.letter, size_mm: size, round, from_corner, span: step.span, right_angle: None }))
}

/// FANUC's chamfering and corner R at a right angle (the FANUC 0i-T and 30i manuals: `G01 Z_ I_`,
/// `G01 X_ K_`, `G01 Z_ R_`, `G01 X_ R_`): a 45-degree chamfer whose legs are |I| or |K| (a
/// radius value), or a corner arc of radius |R|, to a next move along the other axis the way
/// the sign says. One of I, K, R, and none with `,C` or `,R` (alarm 053).
fn right_angle_words(step: &mut Step, words: &mut super::Words, rules: crate::profile::DrawingRules) -> Result<Option<CornerRequest>, Diagnostic> {
    // FANUC 0i-TF 3405#4 CCR = 1: the chamfer is C (its axis the block's), not I or K.
    let plain = plain_letters(step, rules);
    let letters: &[u8] = if plain { b"CR" } else { b"IKR" };
    let given: Vec<&Word> = letters.iter().chain([rules.chamfer, rules.round].iter()).filter_map(|l| words.peek(*l)).collect();
    let Some(&w) = given.iter().find(|w| letters.contains(&w.letter)) else {
        return Ok(None);
    };
    if given.len() > 1 {
        let names: Vec<String> = given.iter().map(|w| w.text()).collect();
        return Err(step.alarm(Rule::CornerWords, given[1].span, format!("{}: one chamfer or corner R a block (FANUC alarm 053)", names.join(" and "))));
    }
    let w = words.take(w.letter).expect("peeked above");
    let v = step.length(w)?;
    if v == 0.0 {
        return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: a chamfer or corner R is longer than 0", w.text())));
    }
    refuse_bypassed(step, w)?;
    // The block's programmed move runs along one axis, the one the word follows (alarm 054):
    // the words decide, not the move (a tool offset's movement may ride along with it).
    let (along_z, along_x) = ([b'Z', b'W'].iter().any(|l| words.has(*l)), [b'X', b'U'].iter().any(|l| words.has(*l)));
    // A plain C chamfers toward the other axis, as I does after a Z move and K after an X move.
    let letter = match w.letter {
        b'C' if along_z && !along_x => b'I',
        b'C' if along_x && !along_z => b'K',
        b'C' => b'R',
        l => l,
    };
    let next_along_second = match (letter, along_z, along_x) {
        (b'I' | b'R', true, false) => true,
        (b'K' | b'R', false, true) => false,
        _ => {
            let msg = match w.letter {
                b'I' => format!("{}: the move of its block is along Z only (Z or W), its chamfer leading to a move along X (FANUC alarm 054)", w.text()),
                b'K' => format!("{}: the move of its block is along X only (X or U), its chamfer leading to a move along Z (FANUC alarm 054)", w.text()),
                _ => format!("{}: the move of its block is along one axis, Z or X (FANUC alarm 054)", w.text()),
            };
            return Err(step.alarm(Rule::CornerTaper, step.span, msg));
        }
    };
    let right_angle = Some(RightAngle { next_along_second, sign: v.signum() });
    Ok(Some(CornerRequest { letter: w.letter, size_mm: v.abs(), round: w.letter == b'R', from_corner: true, span: step.span, right_angle }))
}

/// The next move after a right-angle chamfer or corner R: a line along the other axis (alarm
/// 052), the way the word's sign says (alarm 051).
fn right_angle_next(step: &Step, c: &CornerRequest, span: Span, seg: &Seg) -> Result<(), Diagnostic> {
    let Some(ra) = c.right_angle else { return Ok(()) };
    let next = ra.next_along_second;
    let u = seg.tangent(false);
    let (along, across) = if next { (u.b, u.a) } else { (u.a, u.b) };
    let axis = if next { "X" } else { "Z" };
    if !matches!(seg, Seg::Line { .. }) || across.abs() > 1e-9 {
        return Err(step.alarm(Rule::CornerNotLinear, span, format!("{} asks for a corner with a G01 move along {axis} only (FANUC alarm 052)", c.word())));
    }
    if along * ra.sign < 0.0 {
        let way = if ra.sign > 0.0 { "+" } else { "-" };
        return Err(step.alarm(
            Rule::CornerNoMove,
            span,
            format!("{}: its sign asks for the next move toward {way}{axis}; this one goes the other way (FANUC alarm 051)", c.word()),
        ));
    }
    Ok(())
}

/// The stage is at work: a corner is asked for, or a move is held.
pub(super) fn active(step: &Step) -> bool {
    step.st.comp.corner_for_next.is_some() || !step.corners.is_empty()
}

/// Whatever a block that radius compensation does not act in records waits behind a held move
/// (a T block's tool record and its offset's movement: nothing else of such a block comes while
/// a move is held, run_block makes the held move first).
pub(super) fn waits(step: &Step) -> bool {
    !step.corners.is_empty()
}

/// A record the stage takes: a move in the plane is held (the one held before is made, with
/// the corner between); anything else waits behind a held move, or goes on now.
pub(super) fn take(step: &mut Step, span: Span, n: Option<u32>, op: Op) {
    match Seg::of(&op, step.st.modes.plane) {
        // A T block's offset movement (the block bypasses compensation) waits as it is.
        Some(seg) if !seg.is_point() && !(step.bypass_comp && !step.contour) => plane_move(step, span, n, op, seg),
        _ if !step.corners.is_empty() => step.corners.push(Record::of_block(span, n, op)),
        _ => pass(step, span, n, op),
    }
}

/// A record the stage has made (or lets by) goes on: to compensation's look-ahead when that
/// acts in this block, else out where the tool is.
fn pass(step: &mut Step, span: Span, n: Option<u32>, op: Op) {
    if span != step.span && !step.out.comp_spans.contains(&span) {
        // Made during a later block: its block's single-block mark is placed here.
        step.out.comp_spans.push(span);
    }
    if step.st.comp.side != 0 && !step.bypass_comp {
        return comp::take(step, span, n, op);
    }
    let op = if step.st.comp.actual.is_some() { comp::from_actual(step, span, n, op) } else { op };
    step.push_record(span, n, op);
}

/// Make the held move from where it starts to `end` (in the plane), then `then` (its chamfer
/// or corner arc), then what waited behind it. The queue is left empty.
fn make_held(step: &mut Step, end: geometry::P2, then: Option<Op>) {
    let plane = step.st.modes.plane;
    let queue = std::mem::take(step.corners);
    let Some((held, rest)) = queue.split_first() else {
        return;
    };
    let from = step.st.comp.corner_start;
    let to = geometry::with_local(&held.op.end_point().unwrap_or_default(), end, plane);
    let made = held.op.with_ends(from, to);
    // A corner may take the whole move (a corner arc touching an arc at its start): nothing of
    // it is left to make (an arc from a point to itself would be a whole circle).
    let programmed_length = held.op.start_point().zip(held.op.end_point()).map_or(0.0, |(s, e)| s.dist(&e));
    let taken_whole = from.dist(&to) < 1e-9 && programmed_length > 1e-9;
    if !taken_whole {
        pass(step, held.span, held.n, made);
    }
    if let Some(link) = then {
        pass(step, held.span, held.n, link);
    }
    for rec in rest {
        pass(step, rec.span, rec.n, rec.op.clone());
    }
    let mut reuse = queue;
    reuse.clear();
    *step.corners = reuse;
}

/// A move in the plane while the stage is at work: the move held is made to the chamfer's start,
/// the chamfer (a line, or an arc tangent to both moves; GSK980TDi help text: line to line, line
/// to arc, arc to arc, arc to line), and this move waits from its end; a move held without a
/// chamfer is made whole.
fn plane_move(step: &mut Step, span: Span, n: Option<u32>, op: Op, seg: Seg) {
    if step.st.comp.angle_line.is_some() {
        return super::drawing::refuse(step);
    }
    let plane = step.st.modes.plane;
    let start3 = op.start_point().unwrap_or_default();
    let mut next_start = start3;
    if let Some(held) = step.corners.first().cloned() {
        let hseg = Seg::of(&held.op, plane).expect("the corner queue's first record is a move in the plane");
        let mut end = hseg.to();
        let mut chamfer = None;
        let mut corner = step.st.comp.held_corner.take();
        let strict = step.profile.frame.drawing.is_some_and(|d| d.corner_needs_g01);
        if let (Some(c), true) = (corner, strict && !matches!(op, Op::Feed { .. })) {
            // FANUC alarm 052: the block after a chamfer or corner R is a G01.
            let d = step.alarm(
                Rule::CornerNotLinear,
                span,
                format!(
                    "{} asks for a corner with a G01 move: this block's move is a {} (FANUC alarm 052)",
                    c.word(),
                    if matches!(op, Op::Rapid { .. }) { "G00" } else { "G02/G03" }
                ),
            );
            step.out.comp_error.get_or_insert(d);
            return;
        }
        if let (Some(c), Op::Rapid { .. }) = (corner, &op) {
            // The help text joins G01, G02 and G03 moves: a G00 next gets no corner.
            step.warn(Rule::TextIgnored, c.span, format!("{}: the next move is a G00: no corner is made", c.word()));
            corner = None;
        }
        if let Some(c) = corner {
            if let Err(d) = right_angle_next(step, &c, span, &seg) {
                step.out.comp_error.get_or_insert(d);
                return;
            }
            let cut = if c.round {
                geometry::CornerCut::Round(c.size_mm)
            } else if c.from_corner {
                geometry::CornerCut::FromCorner(c.size_mm)
            } else {
                geometry::CornerCut::Length(c.size_mm)
            };
            // The held move as it is left: from where an earlier corner ended, if one did.
            let from = geometry::local(&step.st.comp.corner_start, plane);
            let first = match hseg {
                Seg::Line { to, .. } => Seg::Line { from, to },
                Seg::Arc { to, center, ccw, .. } => Seg::Arc { from, to, center, ccw },
            };
            match geometry::corner_cut(&first, &seg, cut) {
                Ok(None) => {}
                Ok(Some((a, b, arc))) => {
                    let (a3, b3) = (geometry::with_local(&start3, a, plane), geometry::with_local(&start3, b, plane));
                    let feed_mm_min = comp::feed_of(&held.op);
                    chamfer = Some(match arc {
                        Some((centre, ccw)) => Op::Arc {
                            from: a3,
                            to: b3,
                            center: geometry::with_local(&start3, centre, plane),
                            plane,
                            dir: if ccw { ArcDir::Ccw } else { ArcDir::Cw },
                            feed_mm_min,
                        },
                        None => Op::Feed { from: a3, to: b3, feed_mm_min },
                    });
                    next_start = b3;
                    end = a;
                }
                Err(reach) => {
                    // Case 2: the chamfer cannot join the two moves.
                    let needs = if reach.is_finite() {
                        format!("reaches {} mm from the corner, more than a move has", crate::alarm::shown(reach, 4))
                    } else {
                        "cannot join these two moves".to_string()
                    };
                    let msg = format!(
                        "{}{}: the corner {needs} (GSK980TDi help text, chamfer function, case 2; FANUC alarm 055)",
                        read::address_name(c.letter),
                        crate::alarm::shown(c.size_mm, 4)
                    );
                    let d = step.alarm(Rule::CornerTooLarge, c.span, msg);
                    step.out.comp_error.get_or_insert(d);
                    return;
                }
            }
        }
        make_held(step, end, chamfer);
    }
    step.st.comp.corner_start = next_start;
    step.st.comp.held_corner = step.st.comp.corner_for_next.take();
    // The block made a move in the plane, though it waits here (compensation's look-ahead
    // counts it as one).
    step.out.comp_plane_move = true;
    step.st.comp.idle_blocks = 0;
    step.corners.push(Record::of_block(span, n, op));
}

/// The held move is made whole: no move follows it in time (a G00, a cycle, a block without a
/// move, the programme's end). A corner it asked for is not made: warning NCS-W04, or on FANUC
/// alarm 051.
pub(super) fn break_off(step: &mut Step) {
    // A line of an angle alone has no end yet: this block was to give it.
    if step.st.comp.angle_line.is_some() {
        return super::drawing::refuse(step);
    }
    if let Some(c) = step.st.comp.held_corner.take() {
        if step.profile.frame.drawing.is_some_and(|d| d.corner_needs_g01) {
            let d = step.alarm(Rule::CornerNoMove, step.span, format!("no G01 move follows {} to make the corner with: this block makes none, or first ends the path (G40/G41/G42, a plane change, a T word, a cycle) (FANUC alarm 051)", c.word()));
            step.out.comp_error.get_or_insert(d);
        } else {
            step.warn(Rule::TextIgnored, c.span, format!("{}: no G01 move follows it: no corner is made", c.word()));
        }
    }
    if let Some(held) = step.corners.first() {
        let end = Seg::of(&held.op, step.st.modes.plane).expect("the corner queue's first record is a move in the plane").to();
        make_held(step, end, None);
    }
}

/// After a block: a held move waits only for the block right after its own; a line of an angle
/// alone for one block without a move at most.
pub(super) fn end_of_block(step: &mut Step) -> Result<(), Diagnostic> {
    if let Some(held) = step.st.comp.angle_line {
        return super::drawing::end_of_block(step, held);
    }
    if step.st.modes.ended || !step.st.comp.held_corner.is_some_and(|c| c.span == step.span) {
        break_off(step);
    }
    Ok(())
}
