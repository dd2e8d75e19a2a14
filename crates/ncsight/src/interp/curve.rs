//! G05/G05.1 three-point arcs, G6.2/G6.3 ellipses and G7.2/G7.3 parabolas (GSK980TDi help
//! text): read the words, lay the curve out with `cycles::curve`, emit it as an arc or as chords.

use super::words::Words;
use super::{axis_target, Step, What, ARC_TOLERANCE_MM};
use crate::alarm::{shown, Diagnostic, Rule};
use crate::cycles::curve::{self, CurveError, Pt};
use crate::geom;
use crate::motion::{Op, Vec3};
use crate::profile::{Curve, GFn};

/// How far a chord may depart from the curve, mm (the least input increment;
/// docs/commands/g05_g6_g7.md).
pub const CHORD_TOLERANCE_MM: f64 = 0.001;

fn local(p: &Vec3, a: usize, b: usize) -> Pt {
    (p.axis(a), p.axis(b))
}

/// One block of a curve mode. Without an end point other than the start the block does nothing
/// (help text G6.2 note 6), its curve words read all the same.
pub(super) fn block(step: &mut Step, words: &mut Words, kind: Curve) -> Result<(), Diagnostic> {
    let code = step.profile.name_of(GFn::Curve(kind));
    let plane = step.st.modes.plane;
    let (a, b, _) = plane.axes();
    let from = step.st.place.pos;
    let (to, given) = axis_target(step, words)?;
    match kind {
        Curve::ThreePoint { mid_absolute } => three_point(step, words, code, mid_absolute, from, to),
        Curve::Ellipse(dir) => {
            // A and B are not modal: each block gives them (note 1); 0 or left out is an alarm.
            let mut half = [0.0; 2];
            for (i, l) in [b'A', b'B'].into_iter().enumerate() {
                let w = words.take(l);
                let v = match w {
                    Some(w) => step.length(w)?,
                    None => 0.0,
                };
                if v <= 0.0 {
                    let span = w.map_or(step.span, |w| w.span);
                    let what = if i == 0 { "A, the long half axis" } else { "B, the short half axis" };
                    return Err(step.alarm(Rule::MissingWord, span, format!("{code}: {what}, must be given and greater than 0 (help text G6.2 note 1)")));
                }
                half[i] = v;
            }
            let tilt = tilt(step, words, code);
            if to == from {
                return Ok(());
            }
            if (half[0] - half[1]).abs() < 1e-12 {
                // Note 1: A = B is the arc G02/G03 of that radius.
                let g = geom::arc_from_radius(from, to, plane, dir, half[0], ARC_TOLERANCE_MM).map_err(|_| {
                    step.alarm(
                        Rule::CurveData,
                        step.span,
                        format!("{code}: with A = B = {} it is an arc of that radius, and the end point is more than its diameter away", shown(half[0], 4)),
                    )
                })?;
                let feed = step.cutting_feed(What::Code(GFn::Curve(kind)), &|u| geom::arc_point(&from, &to, plane, dir, &g, u))?;
                step.emit(Op::Arc { from, to, center: g.center, plane, dir, feed_mm_min: feed });
                return Ok(());
            }
            let pts = curve::ellipse(local(&from, a, b), local(&to, a, b), half[0], half[1], tilt, dir, CHORD_TOLERANCE_MM)
                .map_err(|e| curve_alarm(step, code, e))?;
            chords(step, code, from, to, &pts)
        }
        Curve::Parabola(dir) => {
            // P: the parabola's Y² = 2PX, in least input increments, its sign ignored (notes 1-2).
            let p = match words.take(b'P') {
                Some(w) if w.value != 0.0 && w.value.is_finite() => {
                    // Least input increment: 0.001 mm, or 0.0001 inch under G20.
                    let (unit, increment) = if step.st.modes.inch { (25.4, 0.0001) } else { (1.0, 0.001) };
                    let v = if w.decimal { w.value } else { w.value * increment } * unit;
                    if !w.decimal && w.value.abs() < 100.0 {
                        let msg = format!("{}: P is in least input increments without a decimal point: {} mm (P2000 is 2 mm)", w.text(), shown(v.abs(), 4));
                        step.warn(Rule::IntegerLength, w.span, msg);
                    }
                    v.abs()
                }
                w => {
                    let span = w.map_or(step.span, |w| w.span);
                    return Err(step.alarm(
                        Rule::MissingWord,
                        span,
                        format!("{code}: P, the parabola's Y² = 2PX, must be given and not 0 (help text G7.2 note 1)"),
                    ));
                }
            };
            let tilt = tilt(step, words, code);
            if to == from {
                return Ok(());
            }
            let pts = curve::parabola(local(&from, a, b), local(&to, a, b), p, tilt, dir, CHORD_TOLERANCE_MM).map_err(|e| curve_alarm(step, code, e))?;
            chords(step, code, from, to, &pts)
        }
        Curve::Involute(dir) => super::involute::block(step, words, code, dir, (from, to), given),
    }
}

/// Q: the curve's axis from the plane's first axis, in 0.001 degree (with a decimal point too:
/// Q180. is 0.18 degree, the GSK980TDc manual says), turning as G02 does (cycles/curve.rs).
fn tilt(step: &mut Step, words: &mut Words, code: &str) -> f64 {
    let Some(w) = words.take(b'Q') else { return 0.0 };
    step.thousandths_deg(w, &format!("{code}'s Q")).to_radians()
}

fn curve_alarm(step: &Step, code: &str, e: CurveError) -> Diagnostic {
    let msg = match e {
        CurveError::Collinear => format!("{code}: the start, middle and end points lie on one line (help text G05 note 2)"),
        CurveError::EllipseTooSmall(chord, long) => format!(
            "{code}: no ellipse of these half axes joins the two points within 180 degrees (their distance, measured in the ellipse's scale, is {} mm, its long axis {} mm; help text G6.2 notes 5 and 7)",
            shown(chord, 4),
            shown(long, 4)
        ),
        CurveError::ParallelToAxis => format!("{code}: the line from the start to the end point is parallel to the parabola's axis (help text G7.2 note 4)"),
    };
    step.alarm(Rule::CurveData, step.span, msg)
}

/// G05 (I/K the middle point from the start, as radii) or G05.1 (I/K its coordinates): the arc
/// through the three points, the way they turn.
fn three_point(step: &mut Step, words: &mut Words, code: &'static str, mid_absolute: bool, from: Vec3, to: Vec3) -> Result<(), Diagnostic> {
    let plane = step.st.modes.plane;
    let (a, b, _) = plane.axes();
    let letter = |axis: usize| [b'I', b'J', b'K'][axis];
    let (wa, wb) = (words.take(letter(a)), words.take(letter(b)));
    if wa.is_none() && wb.is_none() {
        return Err(step.alarm(
            Rule::ArcDataMissing,
            step.span,
            format!("{code} needs the middle point: {} and {} (help text G05 note 3: both left out is an alarm)", letter(a) as char, letter(b) as char),
        ));
    }
    let mut mid = [0.0; 2];
    for (i, (w, axis)) in [(wa, a), (wb, b)].into_iter().enumerate() {
        // Note 3: a word left out is 0.
        let v = match w {
            Some(w) => step.length(w)?,
            None => 0.0,
        };
        mid[i] = if mid_absolute {
            // G05.1: the coordinate as that axis's words give it (X a diameter where X is one;
            // inferred).
            let scale = if axis == 0 && step.profile.diameter_x { 0.5 } else { 1.0 };
            v * scale
        } else {
            from.axis(axis) + v
        };
    }
    let s = local(&from, a, b);
    let e = local(&to, a, b);
    if (s.0 - e.0).abs() < 1e-12 && (s.1 - e.1).abs() < 1e-12 {
        return Err(step.alarm(
            Rule::CurveData,
            step.span,
            format!("{code}: the end point is the start point; a three-point arc cannot be a full circle (help text G05 note 5)"),
        ));
    }
    let (c, dir) = curve::three_point_arc(s, (mid[0], mid[1]), e).map_err(|e| curve_alarm(step, code, e))?;
    let mut center = from;
    center.set_axis(a, c.0);
    center.set_axis(b, c.1);
    let g = geom::arc_from_center(from, to, plane, dir, center, f64::INFINITY).expect("a centre always makes an arc");
    let feed = step.cutting_feed(code, &|u| geom::arc_point(&from, &to, plane, dir, &g, u))?;
    step.emit(Op::Arc { from, to, center, plane, dir, feed_mm_min: feed });
    Ok(())
}

/// Emit the chords from `from` through `pts` (the last is `to`). The axis normal to the plane
/// moves with them in proportion. The controller interpolates one curve: the time model
/// accelerates once, at the first chord (the others carry a time constant of 0).
pub(super) fn chords(step: &mut Step, code: &'static str, from: Vec3, to: Vec3, pts: &[Pt]) -> Result<(), Diagnostic> {
    let plane = step.st.modes.plane;
    let (a, b, n) = plane.axes();
    let count = pts.len();
    let corners: Vec<Vec3> = std::iter::once(from)
        .chain(pts.iter().enumerate().map(|(i, p)| {
            let mut q = to;
            if i + 1 < count {
                q.set_axis(a, p.0);
                q.set_axis(b, p.1);
                q.set_axis(n, from.axis(n) + (to.axis(n) - from.axis(n)) * (i + 1) as f64 / count as f64);
            }
            q
        }))
        .collect();
    // One feed for the curve (F per revolution at the speed of its points under G96): one
    // interpolation, one warning if it is clamped.
    let along = |u: f64| {
        let k = ((u * count as f64).floor() as usize).min(count - 1);
        let f = u * count as f64 - k as f64;
        let (p, q) = (corners[k], corners[k + 1]);
        Vec3::new(p.x + (q.x - p.x) * f, p.y + (q.y - p.y) * f, p.z + (q.z - p.z) * f)
    };
    let feed = step.cutting_feed(code, &along)?;
    let first = step.out.records.len();
    for w in corners.windows(2) {
        step.emit(Op::Feed { from: w[0], to: w[1], feed_mm_min: feed });
    }
    // Marked after they are made, not as (`Marks`): in radius compensation the stage lets a
    // chord's record go one chord later, so which record is the curve's first is known only here.
    let span = step.span;
    let mut later = false;
    for r in step.records_since(first).iter_mut().filter(|r| r.span == span && matches!(r.op, Op::Feed { .. })) {
        if later {
            r.accel_s = Some(0.0);
        }
        later = true;
    }
    Ok(())
}
