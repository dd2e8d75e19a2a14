//! G12.1/G13.1 polar coordinate interpolation and G07.1 cylindrical interpolation on a lathe
//! with a C axis (FANUC 0i-T manual; GSK980TDi help text G12.1/13.1 and G7.1). In G12.1 the
//! programme is written in the Cartesian plane of X (a diameter, as X always is) and the
//! hypothetical axis C (a length, in radius); in G07.1 in the plane of Z and C (degrees) on the
//! cylinder unrolled. The machine makes either with X, Z and the C axis's turn.
//!
//! ncsight keeps the hypothetical C as the Y of the plane XY while the mode is in force, so that
//! arcs (I, J), radius compensation and the checks work in that plane unchanged; the records
//! are turned into the machine's X and C at the last stage (`push`).

use super::{Step, Words};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::polar::{angle_near, pieces, unrolled};
use crate::geom;
use crate::modal::{Hypothetical, PolarInterp};
use crate::motion::{Op, Plane, Vec3};
use crate::profile::GFn;
use crate::read::Word;
use crate::source::Span;

/// How far a recorded piece may leave the programmed path, mm (the least input increment).
const PIECE_TOLERANCE_MM: f64 = 0.001;
/// The C axis's index among the rotary axes A, B, C.
const C: usize = 2;

/// The functions a block may use in the mode (FANUC 0i-T manual: G01, G02, G03, G04, G40-G42,
/// G65-G67, G98, G99; and G13.1 to end it). The GSK help text gives no list: the same
/// (inferred), with its G15/G16 (Cartesian or polar programming in the plane).
pub(super) fn allowed(f: GFn) -> bool {
    matches!(
        f,
        GFn::Linear
            | GFn::ArcCw
            | GFn::ArcCcw
            | GFn::Dwell
            | GFn::RadiusComp(_)
            | GFn::MacroCall
            | GFn::ModalMacroCall
            | GFn::ModalMacroCancel
            | GFn::FeedPerMinute
            | GFn::FeedPerRevolution
            | GFn::PolarInterpolation(false)
            | GFn::PolarCoordinates(_)
            | GFn::CylindricalInterpolation
    )
}

/// A block's words in the mode: C (and H, its incremental address) are the plane's second
/// axis, kept as Y (V): a length in G12.1, degrees turned into the unrolled length in G07.1.
/// A Y word of the machine itself is not simulated in the mode. The block of G07.1 itself (the
/// cancel, `G07.1 C0`) keeps its C.
pub(super) fn plane_words(step: &mut Step, all: &[Word]) -> Result<Vec<Word>, Diagnostic> {
    let Some(mode) = step.st.modes.polar_interp else { return Ok(all.to_vec()) };
    let functions: Vec<GFn> = super::codes_of(step.profile, all).map(|g| g.function).collect();
    if functions.contains(&GFn::CylindricalInterpolation) {
        return Ok(all.to_vec());
    }
    // Help text G12.1, "limits": an axis off the plane moves in G01, and is ignored in an arc.
    let motion = functions.iter().rev().find(|f| matches!(f, GFn::Rapid | GFn::Linear | GFn::ArcCw | GFn::ArcCcw)).copied();
    let arc = match motion {
        Some(f) => matches!(f, GFn::ArcCw | GFn::ArcCcw),
        None => matches!(step.st.modes.motion, crate::modal::Motion::ArcCw | crate::modal::Motion::ArcCcw),
    };
    let unit = if step.st.modes.inch { 25.4 } else { 1.0 };
    let mut out = Vec::with_capacity(all.len());
    for w in all {
        let letter = match w.letter {
            b'Z' | b'W' if arc && mode.kind == Hypothetical::Polar => {
                let msg = format!("{}: an axis off the polar interpolation plane is ignored in an arc (help text G12.1, limits)", w.text());
                step.warn(Rule::TextIgnored, w.span, msg);
                continue;
            }
            // Help text G12.1 notes 2 and 5: no tool change and no change of the tool offset.
            b'T' => {
                return Err(step.alarm(
                    Rule::ImproperAddress,
                    w.span,
                    format!("{}: no tool change or offset change in polar coordinate or cylindrical interpolation (help text G12.1 notes 2 and 5)", w.text()),
                ));
            }
            b'C' => b'Y',
            b'H' => b'V',
            b'Y' | b'V' => {
                return Err(step.alarm(
                    Rule::NotSupported,
                    w.span,
                    format!("{}: a Y axis move in polar coordinate or cylindrical interpolation is not simulated", w.text()),
                ));
            }
            // FANUC 0i-T manual, cylindrical interpolation: an arc's radius is R; I, J, K are
            // not used.
            b'I' | b'J' | b'K' if matches!(mode.kind, Hypothetical::Cylinder { .. }) => {
                return Err(step.alarm(
                    Rule::ArcDataMissing,
                    w.span,
                    format!("{}: an arc in cylindrical interpolation (G07.1) takes R, not I, J or K", w.text()),
                ));
            }
            l => l,
        };
        let w = match (letter, mode.kind) {
            (b'Y' | b'V', Hypothetical::Cylinder { radius_mm, sign }) => {
                let arc_mm = sign * step.degrees(w).to_radians() * radius_mm;
                Word { letter, value: arc_mm / unit, decimal: true, expr: false, ..w.clone() }
            }
            _ => Word { letter, ..w.clone() },
        };
        out.push(w);
    }
    Ok(out)
}

/// G12.1 or G13.1, alone in their block (GSK980TDi help text, G12.1 note 1); `G07.1 C<radius>`
/// or `G07.1 C0` (FANUC 0i-T manual; GSK980TDi help text G7.1, type I).
pub(super) fn switch(step: &mut Step, words: &mut Words, f: GFn, span: Span) -> Result<(), Diagnostic> {
    let (code, on) = match f {
        GFn::PolarInterpolation(on) => (if on { "G12.1" } else { "G13.1" }, on),
        _ => ("G07.1", true),
    };
    let radius_mm = switch_words(step, words, f, code, span)?;
    let on = on && radius_mm.is_none_or(|r| r != 0.0);
    // Help text note 3; FANUC likewise: radius compensation is started and ended inside.
    if step.st.comp.side != 0 {
        return Err(step.alarm(Rule::CompPlaneChange, span, format!("{code} in radius compensation: cancel it (G40) first")));
    }
    if on {
        start_mode(step, f, code, span, radius_mm)
    } else if let Some(p) = step.st.modes.polar_interp {
        end_mode(step, f, code, span, p)
    } else {
        Ok(())
    }
}

/// The words of a switching block: G07.1's C, the cylinder's radius (None for G12.1, G13.1);
/// the alarms for anything else in the block.
fn switch_words(step: &mut Step, words: &mut Words, f: GFn, code: &str, span: Span) -> Result<Option<f64>, Diagnostic> {
    // G07.1's C: the cylinder's radius, 0 to end the mode.
    let radius_mm = match f {
        GFn::CylindricalInterpolation => match words.take(b'C') {
            Some(w) => Some(step.length(w)?),
            None => return Err(step.alarm(Rule::MissingWord, span, "G07.1 needs C: the cylinder's radius (G07.1 C0 ends the mode)")),
        },
        _ => None,
    };
    // GSK980TDi help text G7.1: type II, the roughing cycle, adds J, L, R, K.
    if radius_mm.is_some() {
        if let Some(w) = [b'J', b'L', b'R', b'K'].into_iter().find_map(|l| words.peek(l)) {
            return Err(step.alarm(
                Rule::NotSupported,
                w.span,
                format!("{}: G07.1 type II (the cylindrical interpolation roughing cycle) is not simulated by ncsight yet", w.text()),
            ));
        }
    }
    if let Some(w) = words.first_unused() {
        return Err(step.alarm(Rule::WordNotTaken, w.span, format!("{}: {code} stands alone in its block (help text G12.1 note 1)", w.text())));
    }
    Ok(radius_mm)
}

/// Start polar coordinate interpolation (`radius_mm` None) or cylindrical interpolation on a
/// cylinder of that radius: the hypothetical C becomes the plane's Y, at the C axis's turn.
fn start_mode(step: &mut Step, f: GFn, code: &str, span: Span, radius_mm: Option<f64>) -> Result<(), Diagnostic> {
    if let Some(m) = step.st.modes.polar_interp {
        let same = matches!((m.kind, f), (Hypothetical::Polar, GFn::PolarInterpolation(_)) | (Hypothetical::Cylinder { .. }, GFn::CylindricalInterpolation));
        if same && radius_mm.is_none() {
            return Ok(());
        }
        return Err(step.alarm(Rule::ImproperGCode, span, format!("{code} while polar coordinate or cylindrical interpolation is in force: end it first")));
    }
    if !step.tables.rotary[C] {
        return Err(step.alarm(
            Rule::ImproperAddress,
            span,
            format!("{code} needs the C axis: declare it in the setup ([machine] axes = [\"X\", \"Z\", \"C\"])"),
        ));
    }
    let c_deg = step.st.place.rotary_deg[C];
    let kind = hypothetical_axis(step, span, radius_mm, c_deg)?;
    let mode = PolarInterp { kind, plane_before: step.st.modes.plane, y_before: step.st.place.pos.y };
    step.st.modes.polar_interp = Some(mode);
    let c_plane = match kind {
        Hypothetical::Polar => 0.0,
        Hypothetical::Cylinder { radius_mm, sign } => sign * c_deg.to_radians() * radius_mm,
    };
    step.st.place.pos.y = c_plane;
    // Where compensation last left the tool (a G40 without a move), in the plane too.
    if let Some(a) = step.st.comp.actual.as_mut() {
        a.y = c_plane;
    }
    step.st.modes.plane = match kind {
        Hypothetical::Polar => Plane::XY,
        Hypothetical::Cylinder { .. } => Plane::YZ,
    };
    Ok(())
}

/// The hypothetical axis the mode starts with (the C axis at `c_deg`): polar (`radius_mm`
/// None), or the unrolled cylinder with the sign that keeps C turning the plane's way; the
/// alarms for what the mode cannot start from.
fn hypothetical_axis(step: &Step, span: Span, radius_mm: Option<f64>, c_deg: f64) -> Result<Hypothetical, Diagnostic> {
    Ok(match radius_mm {
        None => {
            if step.st.modes.per_rev && step.profile.frame.polar_refuses_per_rev {
                return Err(step.alarm(
                    Rule::ImproperGCode,
                    span,
                    "G12.1 under feed per revolution (G99): polar coordinate interpolation is in G98 (help text G12.1 note 3)",
                ));
            }
            // Note 4: polar coordinate interpolation starts with the C axis at 0 degrees.
            if (c_deg / 360.0).fract().abs() > 1e-9 {
                return Err(step.alarm(
                    Rule::ImproperGCode,
                    span,
                    format!("G12.1 with C at {} degrees: polar coordinate interpolation starts at C0 (help text G12.1 note 4)", crate::alarm::shown(c_deg, 3)),
                ));
            }
            Hypothetical::Polar
        }
        Some(r) => {
            if r < 0.0 {
                return Err(step.alarm(Rule::ValueOutOfRange, span, "G07.1 C: the cylinder's radius cannot be negative"));
            }
            // The unrolled plane: Z and C as the programme's plane has them. In G19 (C
            // parallel to Y) C comes first; in G18 (C in X's place) Z does, so C is kept as
            // -Y to turn the same way in the plane YZ.
            let sign = match step.st.modes.plane {
                Plane::YZ => 1.0,
                Plane::ZX => -1.0,
                Plane::XY => {
                    return Err(step.alarm(
                        Rule::PlaneMismatch,
                        span,
                        "G07.1 in the XY plane (G17): cylindrical interpolation is in the plane of Z and C (G18 or G19)",
                    ))
                }
            };
            Hypothetical::Cylinder { radius_mm: r, sign }
        }
    })
}

/// End the interpolation `p` in force: the plane's X and C back to the machine's X and the C
/// axis's turn, the plane and Y as before it.
fn end_mode(step: &mut Step, f: GFn, code: &str, span: Span, p: PolarInterp) -> Result<(), Diagnostic> {
    let ends = matches!((p.kind, f), (Hypothetical::Polar, GFn::PolarInterpolation(false)) | (Hypothetical::Cylinder { .. }, GFn::CylindricalInterpolation));
    if !ends {
        return Err(step.alarm(Rule::ImproperGCode, span, format!("{code} does not end the interpolation in force")));
    }
    let (x, c) = (step.st.place.pos.x, step.st.place.pos.y);
    match p.kind {
        Hypothetical::Polar => {
            step.st.place.rotary_deg[C] = angle_near(x, c, step.st.place.rotary_deg[C]);
            step.st.place.pos.x = x.hypot(c);
        }
        Hypothetical::Cylinder { radius_mm, sign } => {
            step.st.place.rotary_deg[C] = if radius_mm > 0.0 { (sign * c / radius_mm).to_degrees() } else { step.st.place.rotary_deg[C] };
        }
    }
    if let Some(a) = step.st.comp.actual.as_mut() {
        if p.kind == Hypothetical::Polar {
            a.x = a.x.hypot(a.y);
        }
        a.y = p.y_before;
    }
    step.st.modes.polar_interp = None;
    step.st.place.pos.y = p.y_before;
    step.st.modes.plane = p.plane_before;
    // G16 belongs to the plane that ends here.
    step.st.transform.polar = false;
    Ok(())
}

/// Record a move of the plane as the machine makes it: pieces of a radius change (X, Z) with
/// the C turn made together with it, the time of each the path's length at F. The first piece
/// accelerates; the others go on at speed (the move is one interpolation).
pub(super) fn push(step: &mut Step, span: Span, n: Option<u32>, op: Op, mode: PolarInterp) {
    let y_machine = mode.y_before;
    let (from, to, feed) = match op {
        Op::Feed { from, to, feed_mm_min } | Op::Arc { from, to, feed_mm_min, .. } => (from, to, feed_mm_min),
        other => return step.push_machine(span, n, other, None),
    };
    let arc = geom::arc_geom_of(&op);
    let (length, curvature) = match (&op, arc) {
        (Op::Arc { plane, .. }, Some(g)) => (geom::arc_length(&from, &to, *plane, &g), 1.0 / g.radius.max(1e-9)),
        _ => (from.dist(&to), 0.0),
    };
    let at = |u: f64| -> (f64, f64, f64) {
        let p = match (&op, arc) {
            (Op::Arc { plane, dir, .. }, Some(g)) => geom::arc_point(&from, &to, *plane, *dir, &g, u),
            _ => Vec3::new(from.x + (to.x - from.x) * u, from.y + (to.y - from.y) * u, from.z + (to.z - from.z) * u),
        };
        (p.x, p.y, p.z)
    };
    let start_deg = step.st.place.rotary_deg[C];
    let (list, mut r0) = match mode.kind {
        Hypothetical::Polar => (pieces(&at, length, curvature, start_deg, PIECE_TOLERANCE_MM), from.x.hypot(from.y)),
        Hypothetical::Cylinder { radius_mm, sign } => (unrolled(&at, length, curvature, radius_mm, sign, PIECE_TOLERANCE_MM), from.x),
    };
    let (mut a0, mut z0) = (start_deg, from.z);
    for (k, piece) in list.into_iter().enumerate() {
        let accel = if k == 0 { None } else { Some(0.0) };
        let seconds = piece.path_mm / feed.max(1e-9);
        let (a, b) = (Vec3::new(r0, y_machine, z0), Vec3::new(piece.radius_mm, y_machine, piece.z));
        let linear = a.dist(&b);
        let moved = linear > 1e-12;
        if moved {
            step.push_machine(span, n, Op::Feed { from: a, to: b, feed_mm_min: linear / seconds }, accel);
        }
        let turn = (piece.angle_deg - a0).abs();
        if turn > 1e-12 {
            let rate = if seconds > 0.0 { turn / seconds } else { 0.0 };
            step.push_machine(
                span,
                n,
                Op::Rotary { axis: b'C', from_deg: a0, to_deg: piece.angle_deg, rate_deg_min: rate, rapid: false, with_move: moved, linear: false },
                accel,
            );
        }
        (r0, a0, z0) = (piece.radius_mm, piece.angle_deg, piece.z);
    }
    step.st.place.rotary_deg[C] = a0;
}
