//! Programme coordinate transforms of the machining centre: polar coordinate command (G15/G16),
//! programmable mirror image (G50.1/G51.1), scaling (G50/G51) and coordinate system rotation
//! (G68/G69). A block under a transform is worked out in programmed coordinates, as written;
//! each record it makes is then carried into the work coordinates the tool moves in, in the
//! order mirror image, scaling, rotation (the FANUC data flow; docs/commands/g68_g51_g16.md),
//! each stage's centre given in programmed coordinates and carried by the stages before it.
//! Polar coordinates come first of all: they only say how a block's two plane words are read.

use super::words::Words;
use super::Step;
use crate::alarm::{Diagnostic, Rule};
use crate::modal::{Rotation, Scaling, Transforms};
use crate::motion::{ArcDir, Op, Plane, Vec3};
use crate::read::Word;

/// Some transform moves the records (polar coordinates only change how words are read).
pub(super) fn moves_records(t: &Transforms) -> bool {
    t.mirror_axes != 0 || t.scaling.is_some() || t.rotation.is_some()
}

fn mirror(t: &Transforms, p: Vec3) -> Vec3 {
    let mut q = p;
    for a in 0..3 {
        if t.mirror_axes & (1 << a) != 0 {
            q.set_axis(a, 2.0 * t.mirror_at.axis(a) - p.axis(a));
        }
    }
    q
}

fn scale(s: &Scaling, centre: Vec3, p: Vec3, inverse: bool) -> Vec3 {
    let mut q = p;
    for a in 0..3 {
        let f = if inverse { 1.0 / s.factor[a] } else { s.factor[a] };
        q.set_axis(a, centre.axis(a) + f * (p.axis(a) - centre.axis(a)));
    }
    q
}

fn rotate(r: &Rotation, centre: Vec3, p: Vec3, inverse: bool) -> Vec3 {
    let (a, b, _) = r.plane.axes();
    let angle = if inverse { -r.angle_deg } else { r.angle_deg }.to_radians();
    let (sin, cos) = angle.sin_cos();
    let (da, db) = (p.axis(a) - centre.axis(a), p.axis(b) - centre.axis(b));
    let mut q = p;
    q.set_axis(a, centre.axis(a) + da * cos - db * sin);
    q.set_axis(b, centre.axis(b) + da * sin + db * cos);
    q
}

/// The scaling centre and the rotation centre as the earlier stages carry them.
fn centres(t: &Transforms) -> (Vec3, Vec3) {
    let scale_centre = t.scaling.map_or(Vec3::default(), |s| mirror(t, s.centre));
    let rotation_centre = t.rotation.map_or(Vec3::default(), |r| {
        let c = mirror(t, r.centre);
        t.scaling.map_or(c, |s| scale(&s, scale_centre, c, false))
    });
    (scale_centre, rotation_centre)
}

/// Where a programmed point is in work coordinates.
pub(super) fn apply(t: &Transforms, p: Vec3) -> Vec3 {
    let (sc, rc) = centres(t);
    let mut q = mirror(t, p);
    if let Some(s) = &t.scaling {
        q = scale(s, sc, q, false);
    }
    if let Some(r) = &t.rotation {
        q = rotate(r, rc, q, false);
    }
    q
}

/// The programmed point of a point in work coordinates (the inverse of [`apply`]).
pub(super) fn programmed(t: &Transforms, p: Vec3) -> Vec3 {
    let (sc, rc) = centres(t);
    let mut q = p;
    if let Some(r) = &t.rotation {
        q = rotate(r, rc, q, true);
    }
    if let Some(s) = &t.scaling {
        q = scale(s, sc, q, true);
    }
    mirror(t, q)
}

/// Whether the transforms turn an arc in `plane` the other way round (an odd number of
/// mirrorings among the plane's two axes, a negative scale counting as one).
fn reverses(t: &Transforms, plane: Plane) -> bool {
    let (a, b, _) = plane.axes();
    let flips =
        [a, b].iter().filter(|&&i| t.mirror_axes & (1 << i) != 0).count() + [a, b].iter().filter(|&&i| t.scaling.is_some_and(|s| s.factor[i] < 0.0)).count();
    flips % 2 == 1
}

/// Why an arc in `plane` cannot be carried (an ellipse, or a circle tilted out of its plane),
/// if it cannot.
pub(super) fn arc_refused(t: &Transforms, plane: Plane) -> Option<&'static str> {
    let (a, b, _) = plane.axes();
    if t.scaling.is_some_and(|s| (s.factor[a].abs() - s.factor[b].abs()).abs() > 1e-12) {
        return Some("scaling with other magnifications on the two axes of the arc's plane would make an ellipse");
    }
    if t.rotation.is_some_and(|r| r.plane != plane) {
        return Some("the rotation is in another plane than the arc's");
    }
    None
}

/// A record carried from programmed into work coordinates.
pub(super) fn carry(t: &Transforms, op: Op) -> Op {
    match op {
        Op::Rapid { from, to } => Op::Rapid { from: apply(t, from), to: apply(t, to) },
        Op::Feed { from, to, feed_mm_min } => Op::Feed { from: apply(t, from), to: apply(t, to), feed_mm_min },
        Op::Arc { from, to, center, plane, dir, feed_mm_min } => {
            let dir = if reverses(t, plane) {
                match dir {
                    ArcDir::Cw => ArcDir::Ccw,
                    ArcDir::Ccw => ArcDir::Cw,
                }
            } else {
                dir
            };
            Op::Arc { from: apply(t, from), to: apply(t, to), center: apply(t, center), plane, dir, feed_mm_min }
        }
        other => other,
    }
}

/// The centre words of G68 and G51 (absolute, programmed coordinates): the axes given, the
/// current programmed position for those not given (FANUC).
fn centre_words(step: &mut Step, words: &mut Words, axes: &[usize]) -> Result<Vec3, Diagnostic> {
    let mut c = step.st.place.pos;
    for &a in axes {
        if let Some(w) = words.take(b"XYZ"[a]) {
            c.set_axis(a, step.length(w)?);
        }
    }
    Ok(c)
}

/// G68 (on) / G69 (off): `G68 a_ b_ R_` rotates the plane's coordinates about the point
/// (a, b) by R degrees, counter-clockwise positive; R omitted is the profile's angle parameter;
/// in G91, with the profile's bit for it set, R adds to the angle in force.
pub(super) fn rotation(step: &mut Step, words: &mut Words, on: bool, span: crate::source::Span) -> Result<(), Diagnostic> {
    if !on {
        step.st.transform.rotation = None;
        return Ok(());
    }
    let keys = step.profile.frame.transform_keys;
    let plane = step.st.modes.plane;
    let (a, b, _) = plane.axes();
    let centre = centre_words(step, words, &[a, b])?;
    let before = step.st.transform.rotation.map_or(0.0, |r| r.angle_deg);
    let angle_deg = match words.take(b'R') {
        Some(w) => {
            let v = step.degrees(w);
            let incremental = step.st.modes.incremental && keys.rotation_incremental.is_some_and(|k| step.params.get(k) != 0.0);
            if incremental {
                before + v
            } else {
                v
            }
        }
        None => match keys.rotation_angle {
            Some(k) => step.params.get(k) * 0.001,
            None => return Err(step.alarm(Rule::MissingWord, span, "G68 needs the angle R")),
        },
    };
    if !angle_deg.is_finite() || angle_deg.abs() > 360.0 {
        return Err(step.alarm(Rule::ValueOutOfRange, span, format!("G68: the angle {angle_deg} is outside -360 to 360 degrees")));
    }
    step.st.transform.rotation = Some(Rotation { plane, centre, angle_deg });
    Ok(())
}

/// G51.1 (on) / G50.1 (off): the axes written are mirrored about the positions written
/// (programmed coordinates), or the mirror image of the axes written ends.
pub(super) fn mirror_image(step: &mut Step, words: &mut Words, on: bool, span: crate::source::Span) -> Result<(), Diagnostic> {
    let mut any = false;
    for a in 0..3 {
        if let Some(w) = words.take(b"XYZ"[a]) {
            any = true;
            if on {
                let at = step.length(w)?;
                step.st.transform.mirror_at.set_axis(a, at);
                step.st.transform.mirror_axes |= 1 << a;
            } else {
                step.st.transform.mirror_axes &= !(1 << a);
            }
        }
    }
    if !any {
        let code = if on { "G51.1" } else { "G50.1" };
        return Err(step.alarm(Rule::MissingWord, span, format!("{code} names the axes of the mirror image (X, Y, Z)")));
    }
    Ok(())
}

/// G68 (on) / G69 (off) on a lathe: X mirrored about the spindle's centre line, X = 0 (YASNAC
/// LX3 manual 2.8.24, program mirror image: X, U and I inverted, G02 and G03 exchanged, the
/// tool nose's side with them; the FANUC 0-T's mirror image for double turrets likewise). The
/// block makes no move. In tool nose radius compensation it is an alarm (2.8.24 (3) c).
pub(super) fn turret_mirror(step: &mut Step, on: bool, span: crate::source::Span) -> Result<(), Diagnostic> {
    if step.st.comp.side != 0 {
        let code = if on { "G68" } else { "G69" };
        return Err(step.alarm(
            Rule::ImproperGCode,
            span,
            format!("{code} in tool nose radius compensation: cancel it (G40) first (YASNAC LX3 manual 2.8.24)"),
        ));
    }
    if on {
        step.st.transform.mirror_at.x = 0.0;
        step.st.transform.mirror_axes |= 1;
    } else {
        step.st.transform.mirror_axes &= !1;
    }
    Ok(())
}

/// G51 (on) / G50 (off) scaling, where the machine has the option (a setting): `G51 X Y Z P`
/// the same magnification on every axis, `G51 X Y Z I J K` one per axis (negative: mirrored);
/// P, I, J, K in 0.001 without a decimal point; P omitted is the profile's magnification
/// parameter. The centre is X Y Z (programmed coordinates), the current position where omitted.
pub(super) fn scaling(step: &mut Step, words: &mut Words, on: bool, span: crate::source::Span) -> Result<(), Diagnostic> {
    let keys = step.profile.frame.transform_keys;
    if !keys.scaling_option.is_some_and(|k| step.params.get(k) != 0.0) {
        let code = if on { "G51" } else { "G50" };
        return Err(step.alarm(
            Rule::ImproperGCode,
            span,
            format!("{code}: scaling is an option this machine does not have (give --param scaling_option=1 if it has)"),
        ));
    }
    if !on {
        step.st.transform.scaling = None;
        return Ok(());
    }
    let centre = centre_words(step, words, &[0, 1, 2])?;
    let magnification = |w: &Word| if w.decimal { w.value } else { w.value * 0.001 };
    let mut factor = [keys.magnification.map_or(1.0, |k| step.params.get(k) * 0.001); 3];
    let ijk = [words.take(b'I'), words.take(b'J'), words.take(b'K')];
    if let Some(w) = words.take(b'P') {
        if ijk.iter().any(Option::is_some) {
            return Err(step.alarm(Rule::WordNotTaken, w.span, format!("{}: G51 takes P (every axis) or I, J, K (each axis), not both", w.text())));
        }
        if w.value <= 0.0 {
            return Err(step.alarm(
                Rule::ValueOutOfRange,
                w.span,
                format!("{}: G51's P is a positive magnification (a mirror image is a negative I, J or K)", w.text()),
            ));
        }
        factor = [magnification(w); 3];
    }
    for (a, w) in ijk.iter().enumerate() {
        if let Some(w) = w {
            factor[a] = magnification(w);
        }
    }
    if let Some(a) = factor.iter().position(|f| !f.is_finite() || *f == 0.0 || f.abs() > 999.999) {
        return Err(step.alarm(
            Rule::ValueOutOfRange,
            span,
            format!("G51: the magnification of {} is {}: it must be other than 0 and at most 999.999", ["X", "Y", "Z"][a], factor[a]),
        ));
    }
    step.st.transform.scaling = Some(Scaling { centre, factor });
    Ok(())
}

/// The two plane words of a block under G16 as the X, Y, Z words they stand for, in
/// programmed coordinates: the first is the radius, the second the angle (degrees,
/// counter-clockwise from the plane's first axis). The radius given in G91 puts the origin at
/// the current position; otherwise it is the programme's zero (FANUC). The angle in G91 adds to
/// the last angle. What a block leaves out is the last radius and angle. The words are written
/// back in the units and distance mode of the block (`incremental`: G91 in force or in the
/// block), with a decimal point.
pub(super) fn polar_words(step: &mut Step, all: &[Word], incremental: bool, plane: Plane) -> Result<Option<Vec<Word>>, Diagnostic> {
    let (a, b, _) = plane.axes();
    let (la, lb) = (b"XYZ"[a], b"XYZ"[b]);
    let radius_w = all.iter().rev().find(|w| w.letter == la);
    let angle_w = all.iter().rev().find(|w| w.letter == lb);
    if radius_w.is_none() && angle_w.is_none() {
        return Ok(None);
    }
    // Where the tool is in programmed coordinates (under a rotation, scaling or mirror image).
    let t = step.st.transform;
    let here = if moves_records(&t) { programmed(&t, step.st.place.pos) } else { step.st.place.pos };
    let mut origin = Vec3::default();
    let mut radius = step.st.transform.polar_radius;
    if let Some(w) = radius_w {
        radius = step.length(w)?;
        if incremental {
            origin = here;
        }
    }
    let mut angle = step.st.transform.polar_angle_deg;
    if let Some(w) = angle_w {
        let v = step.degrees(w);
        angle = if incremental { angle + v } else { v };
    }
    step.st.transform.polar_radius = radius;
    step.st.transform.polar_angle_deg = angle;
    let (sin, cos) = angle.to_radians().sin_cos();
    let point = [origin.axis(a) + radius * cos, origin.axis(b) + radius * sin];
    let unit = if step.st.modes.inch { 25.4 } else { 1.0 };
    let mut out: Vec<Word> = all.iter().filter(|w| w.letter != la && w.letter != lb).cloned().collect();
    for (k, (letter, w)) in [(la, radius_w.or(angle_w)), (lb, angle_w.or(radius_w))].into_iter().enumerate() {
        let axis = if k == 0 { a } else { b };
        let value = if incremental { point[k] - here.axis(axis) } else { point[k] };
        let w = w.expect("one of the two is given");
        // X words are diameters where X is programmed so (the polar radius is a radius).
        let scale = if letter == b'X' && step.profile.diameter_x { 2.0 } else { 1.0 };
        out.push(Word { letter, value: value / unit * scale, decimal: true, expr: false, ..w.clone() });
    }
    Ok(Some(out))
}
