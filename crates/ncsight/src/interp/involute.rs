//! G02.2/G03.2 involute interpolation (FANUC Series 16/18-MC and 30i-MA operator's manuals,
//! "Involute interpolation"; an option of the 0i-MF): the block's words read and checked, the
//! involute laid out by `cycles::involute`, its chords made now or, past what a block holds, one
//! at a time as they are handed on (`interp/deferred.rs`).
//!
//! The manuals' rules: the end point in the plane's axes, absolute or incremental; I, J, K the
//! base circle's centre seen from the start point, always incremental; R the base circle's
//! radius. No end point, no centre (I0 J0 too) or no R > 0 is PS0241; a start or end point
//! inside the base circle, or more than 100 turns from where its involute starts, is PS0242.
//! Not under G16 polar coordinates, G12.1 polar or G07.1 cylindrical interpolation, and no
//! helical move. Inferred (docs/commands/g02_2_g03_2.md): the end point may be off the start
//! point's involute by the arc tolerance, 0.01 mm, as an arc's end may be off its circle; further
//! is PS0242.

use std::sync::Arc;

use super::words::Words;
use super::{Given, Step, ARC_TOLERANCE_MM};
use crate::alarm::{shown, Diagnostic, Rule};
use crate::cycles::involute::{BaseCircle, Involute, InvoluteError, MAX_TURNS};
use crate::cycles::Expansion;
use crate::motion::{ArcDir, Vec3};

/// One block of the involute mode: `ends` the start and the end point the axis words named,
/// `given` which axes they gave.
pub(super) fn block(
    step: &mut Step,
    words: &mut Words,
    code: &'static str,
    dir: ArcDir,
    ends: (Vec3, Vec3),
    given: [Option<Given>; 3],
) -> Result<(), Diagnostic> {
    let (from, to) = ends;
    let plane = step.st.modes.plane;
    let (a, b, n) = plane.axes();
    if step.st.transform.polar || step.st.modes.polar_interp.is_some() {
        return Err(step.alarm(
            Rule::InvoluteCommand,
            step.span,
            format!("{code} cannot be used under G16 polar coordinates, G12.1 polar interpolation or G07.1 cylindrical interpolation (FANUC 16/18-MC manual, involute interpolation)"),
        ));
    }
    let letter = |axis: usize| [b'I', b'J', b'K'][axis];
    let (wa, wb, radius_word) = (words.take(letter(a)), words.take(letter(b)), words.take(b'R'));
    if given[a].is_none() && given[b].is_none() {
        return Err(format_alarm(step, step.span, format!("{code} needs its end point in the plane's axes")));
    }
    if to.axis(n) != from.axis(n) {
        // Written, or a tool offset's movement not made yet, which would go with this move.
        let normal = [b'X', b'Y', b'Z'][n];
        let msg = match words.peek(normal) {
            Some(w) => (w.span, format!("{}: {code} cannot move the axis normal to the plane: no helical involute", w.text())),
            None => (step.span, format!("{code}: a tool offset's movement along {} is not made yet and would go with the curve, a helical involute: make it in a block of its own first", normal as char)),
        };
        return Err(format_alarm(step, msg.0, msg.1));
    }
    let mut offset = [0.0; 2];
    for (i, w) in [wa, wb].into_iter().enumerate() {
        if let Some(w) = w {
            offset[i] = step.length(w)?;
        }
    }
    if offset == [0.0, 0.0] {
        let (la, lb) = (letter(a) as char, letter(b) as char);
        let span = wa.or(wb).map_or(step.span, |w| w.span);
        return Err(format_alarm(step, span, format!("{code} needs the base circle's centre from the start point: {la} and {lb}, not both left out or 0")));
    }
    let centre = (from.axis(a) + offset[0], from.axis(b) + offset[1]);
    let radius_mm = match radius_word {
        Some(w) => step.length(w)?,
        None => 0.0,
    };
    if radius_mm <= 0.0 {
        let span = radius_word.map_or(step.span, |w| w.span);
        return Err(format_alarm(step, span, format!("{code} needs R, the base circle's radius, greater than 0")));
    }
    let lay = Involute::new(from, to, plane, BaseCircle { centre, radius_mm }, dir, ARC_TOLERANCE_MM, super::curve::CHORD_TOLERANCE_MM)
        .map_err(|e| step.alarm(Rule::InvoluteCommand, step.span, refusal(code, e)))?;
    if lay.move_count() == 0 {
        return Ok(());
    }
    let too_many = |most: usize| format!("{code}: the involute makes {} chords, more than {most}", lay.move_count());
    // The curve has one feed (one interpolation). Made as they are handed on, the chords would
    // each take the feed at their own place under G95 with G96: such a block is held (inferred;
    // a machining centre cuts an involute at a feed per minute).
    let steady_feed = !(step.st.modes.per_rev && step.st.modes.css);
    if steady_feed && step.defers(lay.move_count(), &too_many)? {
        return step.defer_cuts(code, Arc::new(lay));
    }
    if lay.move_count() > super::MAX_MOTIONS_PER_BLOCK {
        return Err(step.alarm(Rule::MotionLimit, step.span, too_many(super::MAX_MOTIONS_PER_BLOCK)));
    }
    let mut points = Vec::with_capacity(lay.move_count());
    lay.each_point(&mut |p| {
        points.push((p.axis(a), p.axis(b)));
        std::ops::ControlFlow::Continue(())
    });
    super::curve::chords(step, code, from, to, &points)
}

fn format_alarm(step: &Step, span: crate::source::Span, msg: String) -> Diagnostic {
    step.alarm(Rule::InvoluteFormat, span, format!("{msg} (FANUC 16/18-MC and 30i-MA manuals, involute interpolation)"))
}

fn refusal(code: &str, e: InvoluteError) -> String {
    let which = |end: bool| if end { "end" } else { "start" };
    match e {
        InvoluteError::InsideBaseCircle { end, distance_mm } => {
            format!("{code}: the {} point is inside the base circle, {} mm from its centre (the manuals: PS0242)", which(end), shown(distance_mm, 4))
        }
        InvoluteError::TooManyTurns { end, turns } => format!(
            "{code}: the {} point is {} turns from where its involute starts, more than {MAX_TURNS} (FANUC 16/18-MC manual, involute interpolation)",
            which(end),
            shown(turns, 1)
        ),
        InvoluteError::OffTheInvolute { distance_mm } => format!(
            "{code}: the end point is {} mm off the involute through the start point that turns this way (tolerance {ARC_TOLERANCE_MM} mm, as an arc's end; inferred)",
            shown(distance_mm, 4)
        ),
    }
}
