//! G22/G23: stored stroke check 2. G22 sets a box in machine coordinates that the tool may not
//! enter (or, by a setting, not leave); a move that would is an alarm, and so is G22 given
//! while the tool already stands where it may not (FANUC 0i, inferred for the FANUC 0;
//! GSK980TDi help text, G22/23: X Y Z the limits on the positive side, I J K on the negative
//! side, machine coordinates, note 2 the side by a parameter). docs/commands/g22_g23.md.

use super::words::Words;
use super::{transform, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::geom;
use crate::modal::StrokeArea;
use crate::motion::{Op, Vec3};
use crate::profile::ParamKey;
use crate::source::Span;

/// G22 (on, with its area) or G23 (off).
pub(super) fn set(step: &mut Step, words: &mut Words, on: bool, span: Span) -> Result<(), Diagnostic> {
    if !on {
        *step.st.stroke2 = None;
        return Ok(());
    }
    let mut lo = Vec3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut hi = Vec3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY);
    for (axis, (upper, lower)) in [(b'X', b'I'), (b'Y', b'J'), (b'Z', b'K')].into_iter().enumerate() {
        let scale = if axis == 0 && step.profile.diameter_x { 0.5 } else { 1.0 };
        if let Some(w) = words.take(upper) {
            hi.set_axis(axis, step.length(w)? * scale);
        }
        if let Some(w) = words.take(lower) {
            lo.set_axis(axis, step.length(w)? * scale);
        }
        if lo.axis(axis) >= hi.axis(axis) {
            let (name, low) = (upper as char, lower as char);
            return Err(step.alarm(Rule::ValueOutOfRange, span, format!("G22: the {name} limits: the upper ({name}) must be above the lower ({low})")));
        }
    }
    let outside = step.profile.param(ParamKey::Setting("stroke2_outside")).is_some_and(|_| step.params.get(ParamKey::Setting("stroke2_outside")) != 0.0);
    let area = StrokeArea { lo, hi, outside };
    let t = step.st.transform;
    let here = if transform::moves_records(&t) { transform::apply(&t, step.st.place.pos) } else { step.st.place.pos };
    let at = here + step.tables.to_machine(&step.st.frame);
    if forbidden_point(&area, &at) {
        return Err(step.alarm(Rule::StrokeCheck2, span, format!("G22: the tool stands {} the area already", if outside { "outside" } else { "inside" })));
    }
    *step.st.stroke2 = Some(area);
    Ok(())
}

fn inside(area: &StrokeArea, p: &Vec3) -> bool {
    (0..3).all(|a| area.lo.axis(a) < p.axis(a) && p.axis(a) < area.hi.axis(a))
}

fn forbidden_point(area: &StrokeArea, p: &Vec3) -> bool {
    inside(area, p) != area.outside
}

/// Why the move `op` (programme coordinates; `to_machine` added gives machine coordinates) goes
/// where G22 forbids, if it does. A straight move is checked along its whole length, an arc by
/// the box that holds it (a little stricter than its path).
pub(super) fn entered(area: &StrokeArea, op: &Op, to_machine: &Vec3) -> Option<String> {
    let (start, end) = op.start_point().zip(op.end_point())?;
    let (from, to) = (start + *to_machine, end + *to_machine);
    let hit = match geom::arc_geom_of(op) {
        Some(g) => {
            let (lo, hi) = match *op {
                Op::Arc { plane, dir, .. } | Op::ThreadArc { plane, dir, .. } => geom::arc_extent(&start, &end, plane, dir, &g),
                _ => return None,
            };
            let (lo, hi) = (lo + *to_machine, hi + *to_machine);
            if area.outside {
                !(0..3).all(|a| area.lo.axis(a) <= lo.axis(a) && hi.axis(a) <= area.hi.axis(a))
            } else {
                (0..3).all(|a| lo.axis(a) < area.hi.axis(a) && hi.axis(a) > area.lo.axis(a))
            }
        }
        None if area.outside => forbidden_point(area, &from) || forbidden_point(area, &to),
        None => segment_enters(area, &from, &to),
    };
    hit.then(|| {
        if area.outside {
            "this move leaves the area G22 keeps the tool in (stored stroke check 2)".to_string()
        } else {
            "this move enters the area G22 forbids (stored stroke check 2)".to_string()
        }
    })
}

/// Whether the segment from `a` to `b` passes through the open box (slab method).
fn segment_enters(area: &StrokeArea, a: &Vec3, b: &Vec3) -> bool {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for axis in 0..3 {
        let (p, d) = (a.axis(axis), b.axis(axis) - a.axis(axis));
        let (lo, hi) = (area.lo.axis(axis), area.hi.axis(axis));
        if d == 0.0 {
            if p <= lo || p >= hi {
                return false;
            }
            continue;
        }
        let (mut ta, mut tb) = ((lo - p) / d, (hi - p) / d);
        if ta > tb {
            std::mem::swap(&mut ta, &mut tb);
        }
        t0 = t0.max(ta);
        t1 = t1.min(tb);
        if t0 >= t1 {
            return false;
        }
    }
    true
}
