//! Lines given as the drawing gives them (docs/commands/drawing.md): a G01 (or G00) block with
//! an angle and one coordinate ends where its line reaches that coordinate; a block with the
//! angle alone ends where its line meets the next block's, which gives its end point and its
//! angle (GSK980TDi help text, angle programming, Q; FANUC 0-T direct drawing dimension
//! programming, `,A`). The corners between such lines (L/D, `,C`/`,R`) are the look-ahead
//! stage's (interp/comp.rs).
//!
//! A line given by its angle alone is held in that stage's queue with its direction and no end
//! yet; what comes between (at most one block without a move: note 7) waits behind it, and the
//! next block's line sets its end.

use super::{corner, Given, Step, Words};
use crate::alarm::{shown, Diagnostic, Rule};
use crate::comp::{self as geometry, DrawingError};
use crate::modal::{AngleLine, Motion};
use crate::motion::{Op, Plane, Vec3};
use crate::profile::DrawingRules;
use crate::read::Word;

/// How far the held line of an angle alone reaches before its end is known. Never made: the
/// next block's line sets its end, or the block alarms.
const UNKNOWN_REACH_MM: f64 = 1.0e4;

/// The angle word of a G01 block (or G00, where the profile has the forms there), degrees.
pub(super) fn angle<'w>(step: &mut Step, words: &mut Words<'w>, rules: DrawingRules) -> Option<(f64, &'w Word)> {
    let rapid = step.st.modes.motion == Motion::Rapid;
    if !(step.st.modes.motion == Motion::Linear || rapid && rules.angle_in_rapid) {
        return None;
    }
    let plain = super::corner::plain_letters(step, rules);
    let w = words.take(rules.angle).or_else(|| if plain { words.take(b'A') } else { None })?;
    let deg = if rules.angle_thousandths { step.thousandths_deg(w, "the line's angle") } else { step.degrees(w) };
    Some((deg, w))
}

/// What the block's line does: go to `target` (an end worked out from the angle, or as
/// written), or wait for the next block (`None`: its angle alone).
pub(super) fn line(
    step: &mut Step,
    rules: DrawingRules,
    angle: Option<(f64, &Word)>,
    target: Vec3,
    how: [Option<Given>; 3],
) -> Result<Option<Vec3>, Diagnostic> {
    let plane = step.st.modes.plane;
    let (ia, ib, _) = plane.axes();
    if let Some(held) = step.st.comp.angle_line {
        return close(step, held, angle, target, how).map(Some);
    }
    let given = how.map(|g| g.is_some());
    let Some((deg, w)) = angle else {
        return Ok(Some(target));
    };
    if !rules.any_plane && plane != Plane::ZX {
        // FANUC alarm 212: direct drawing dimensions in the ZX plane only.
        return Err(step.alarm(Rule::IllegalPlane, w.span, format!("{}: a line given by its angle is programmed in the ZX plane (G18) only", w.text())));
    }
    let start = step.st.place.pos + step.st.frame.unmoved;
    let from = geometry::local(&start, plane);
    let names = plane_names(plane);
    match (given[ia], given[ib]) {
        (true, true) => {
            // Note 1: with both coordinates the block is an ordinary line; the angle is not used.
            step.warn(
                Rule::TextIgnored,
                w.span,
                format!(
                    "{}: the block gives both {} and {}: an ordinary line, the angle is not used (GSK980TDi help text, angle programming note 1)",
                    w.text(),
                    names.0,
                    names.1
                ),
            );
            Ok(Some(target))
        }
        (false, false) => {
            open(step, deg, w, target)?;
            Ok(None)
        }
        (a_given, _) => {
            let to = geometry::local(&target, plane);
            let (a, b) = if a_given { (Some(to.a), None) } else { (None, Some(to.b)) };
            match geometry::end_by_angle(from, deg, a, b) {
                Ok(end) => Ok(Some(geometry::with_local(&target, end, plane))),
                Err(_) => {
                    let (other, along) = if a_given { (names.1, names.0) } else { (names.0, names.1) };
                    let msg = format!(
                        "{}: a line within {} degree of the {other} axis does not reach the {along} given (GSK980TDi help text, angle programming notes 3-4; FANUC alarm 057)",
                        w.text(),
                        shown(geometry::DRAWING_TOLERANCE_DEG, 1)
                    );
                    Err(step.alarm(Rule::DrawingNoSolution, w.span, msg))
                }
            }
        }
    }
}

/// The addresses of the plane's first and second axes, as a message names them.
fn plane_names(plane: Plane) -> (&'static str, &'static str) {
    let name = |axis: usize| ["X", "Y", "Z"][axis];
    let (a, b, _) = plane.axes();
    (name(a), name(b))
}

/// A line given by its angle alone: held, pointing along its angle, until the next block. An
/// axis off the plane in its block (`target`) moves with it.
fn open(step: &mut Step, deg: f64, w: &Word, target: Vec3) -> Result<(), Diagnostic> {
    let why = if step.bypass_comp && !step.contour {
        Some("in a block that radius compensation does not act in (a T word, a cycle)")
    } else if step.carry.is_some() || step.st.modes.polar_interp.is_some() {
        Some("under a coordinate transform or G12.1/G07.1")
    } else {
        None
    };
    if let Some(why) = why {
        return Err(step.alarm(Rule::NotSupported, w.span, format!("{}: a line given by its angle alone {why} is not simulated by ncsight yet", w.text())));
    }
    let plane = step.st.modes.plane;
    let from = step.st.place.pos;
    // The line starts where the controller shows the tool (a tool offset's movement not made
    // yet is made with it, as with any move).
    let start = geometry::local(&target, plane);
    let reach = geometry::with_local(&target, start.plus(geometry::direction(deg).scale(UNKNOWN_REACH_MM)), plane);
    step.st.frame.unmoved = Vec3::default();
    let op = match step.st.modes.motion {
        Motion::Rapid => Op::Rapid { from, to: reach },
        // Under G96 the feed per minute is the start point's (the end is not known yet).
        _ => Op::Feed { from, to: reach, feed_mm_min: step.cutting_feed(super::What::Code(crate::profile::GFn::Linear), &|_| from)? },
    };
    corner::take(step, step.span, step.n, op);
    step.st.comp.angle_line = Some(AngleLine { angle_deg: deg, from: target, span: step.span, between: 0 });
    Ok(())
}

/// The block after a line of an angle alone: its absolute end point and its angle give its line;
/// the held line ends where the two meet, and this block's line starts there.
fn close(step: &mut Step, held: AngleLine, angle: Option<(f64, &Word)>, target: Vec3, how: [Option<Given>; 3]) -> Result<Vec3, Diagnostic> {
    let plane = step.st.modes.plane;
    let (ia, ib, _) = plane.axes();
    let names = plane_names(plane);
    let end_given = how[ia] == Some(Given::Absolute) && how[ib] == Some(Given::Absolute);
    let Some((deg, w)) = angle.filter(|_| end_given) else {
        let msg = format!(
            "the line before (its angle alone) ends where it meets this block's line: this block gives its end point as absolute {} and {} and its angle (GSK980TDi help text, angle programming note 6; FANUC alarm 056)",
            names.0, names.1
        );
        return Err(step.alarm(Rule::DrawingEndMissing, step.span, msg));
    };
    let start = geometry::local(&held.from, plane);
    let u = geometry::direction(held.angle_deg);
    let meet = match geometry::meet(start, held.angle_deg, geometry::local(&target, plane), deg) {
        Ok(p) => p,
        Err(DrawingError::Parallel | DrawingError::AlongAxis) => {
            let msg = format!(
                "{}: this line and the one before are within {} degree of parallel: they do not meet (GSK980TDi help text, angle programming note 5; FANUC alarm 057)",
                w.text(),
                shown(geometry::DRAWING_TOLERANCE_DEG, 1)
            );
            return Err(step.alarm(Rule::DrawingNoSolution, w.span, msg));
        }
    };
    // A line runs either way along its angle, as in form 1. A chamfer or corner arc before it
    // was made for the way its angle points: it must leave some of the line that way.
    let held_start = geometry::local(&step.st.comp.corner_start, plane);
    let placed = step.corners.first().and_then(|r| r.op.start_point()).map_or(start, |p| geometry::local(&p, plane));
    if held_start.dist(placed) > 1e-9 && meet.minus(held_start).dot(u) < -1e-9 {
        let msg =
            format!("the corner before this line (its angle alone) needs more of it than it has: it ends {} mm from the corner", shown(meet.dist(start), 4));
        return Err(step.alarm(Rule::CornerTooLarge, held.span, msg));
    }
    let end = geometry::with_local(&held.from, meet, plane);
    let first = step.corners.first_mut().expect("a line of an angle alone is held in the corner stage");
    first.op = first.op.with_ends(first.op.start_point().expect("the held line is a move"), end);
    step.st.comp.angle_line = None;
    step.st.place.pos = end;
    // This block's axes not written count from there.
    let mut target = target;
    for axis in [0, 1, 2] {
        if axis != ia && axis != ib && how[axis].is_none() {
            target.set_axis(axis, end.axis(axis));
        }
    }
    Ok(target)
}

/// After a block while a line of an angle alone waits for its end: one block without a move may
/// come between (note 7); the programme's end may not.
pub(super) fn end_of_block(step: &mut Step, mut held: AngleLine) -> Result<(), Diagnostic> {
    if step.st.modes.ended {
        return Err(step.alarm(
            Rule::DrawingEndNotFound,
            step.span,
            "the programme ends before the line of an angle alone is given its end (the next block's line; FANUC alarm 058)",
        ));
    }
    if held.span != step.span {
        held.between += 1;
        if held.between > 1 {
            let msg = "a second block without a move after a line of an angle alone: at most one (G04, M, S, T) may come before the line that ends it (GSK980TDi help text, angle programming note 7; FANUC alarm 058)";
            return Err(step.alarm(Rule::DrawingEndNotFound, step.span, msg));
        }
        step.st.comp.angle_line = Some(held);
    }
    Ok(())
}

/// A move or a break that the held line of an angle alone cannot take: the block alarms.
pub(super) fn refuse(step: &mut Step) {
    let msg = "the line before (its angle alone) ends where it meets the next line: this block gives that line (G01) with its absolute end point and its angle, and does not first end the path (G40/G41/G42, a plane change, a cycle) (GSK980TDi help text, angle programming note 6; FANUC alarm 056)";
    let d = step.alarm(Rule::DrawingEndMissing, step.span, msg);
    step.out.comp_error.get_or_insert(d);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::comp::P2;

    #[test]
    fn lines_meet_where_the_worked_example_says() {
        // X50 Z50 (radius 25), ,A30. then X0 Z150 ,A-45.: Z97.548, X104.904 (diameter).
        let p = geometry::meet(P2::new(50.0, 25.0), 30.0, P2::new(150.0, 0.0), -45.0).unwrap();
        assert!((p.a - 97.548).abs() < 5e-4 && (p.b * 2.0 - 104.904).abs() < 5e-4, "{p:?}");
    }
}
