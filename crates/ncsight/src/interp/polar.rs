//! G12.1/G13.1 polar coordinate interpolation on a lathe with a C axis (FANUC 0i-T manual;
//! GSK980TDi help text G12.1/13.1). Between them the programme is written in the Cartesian
//! plane of X (a diameter, as X always is) and the hypothetical axis C (a length, in radius),
//! and the machine makes it with X and the C axis's turn.
//!
//! ncsight keeps the hypothetical C as the Y of the plane XY while the mode is in force, so that
//! arcs (I, J), radius compensation and the checks work in that plane unchanged; the records
//! are turned into the machine's X and C at the last stage (`push`).

use super::{Step, Words};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::polar::{angle_near, pieces};
use crate::geom;
use crate::modal::PolarInterp;
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
    )
}

/// A block's words in the mode: C (and H, its incremental address) are the plane's second
/// axis, kept as Y (V). A Y word of the machine itself is not simulated in the mode.
pub(super) fn plane_words(step: &Step, all: &[Word]) -> Result<Vec<Word>, Diagnostic> {
    let mut out = Vec::with_capacity(all.len());
    for w in all {
        let letter = match w.letter {
            b'C' => b'Y',
            b'H' => b'V',
            b'Y' | b'V' => {
                return Err(step.alarm(Rule::NotSupported, w.span, format!("{}: a Y axis move in polar coordinate interpolation (G12.1) is not simulated", w.text())));
            }
            l => l,
        };
        out.push(Word { letter, ..w.clone() });
    }
    Ok(out)
}

/// G12.1 (`on`) or G13.1, alone in their block (GSK980TDi help text, G12.1 note 1).
pub(super) fn switch(step: &mut Step, words: &Words, on: bool, span: Span) -> Result<(), Diagnostic> {
    let code = if on { "G12.1" } else { "G13.1" };
    if let Some(w) = words.first_unused() {
        return Err(step.alarm(Rule::WordNotTaken, w.span, format!("{}: {code} stands alone in its block (help text G12.1 note 1)", w.text())));
    }
    // Help text note 3; FANUC likewise: radius compensation is started and ended inside.
    if step.st.comp.side != 0 {
        return Err(step.alarm(Rule::CompPlaneChange, span, format!("{code} in radius compensation: cancel it (G40) first")));
    }
    if on {
        if step.st.polar_interp.is_some() {
            return Ok(());
        }
        if !step.tables.rotary[C] {
            return Err(step.alarm(Rule::ImproperAddress, span, "G12.1 needs the C axis: declare it in the setup ([machine] axes = [\"X\", \"Z\", \"C\"])"));
        }
        // Note 4: the interpolation starts with the C axis at 0 degrees.
        let c_deg = step.st.rotary_deg[C];
        if (c_deg / 360.0).fract().abs() > 1e-9 {
            return Err(step.alarm(Rule::ImproperGCode, span, format!("G12.1 with C at {} degrees: polar coordinate interpolation starts at C0 (help text G12.1 note 4)", crate::alarm::shown(c_deg, 3))));
        }
        step.st.polar_interp = Some(PolarInterp { plane_before: step.st.plane, y_before: step.st.pos.y });
        step.st.plane = Plane::XY;
        step.st.pos.y = 0.0;
    } else if let Some(p) = step.st.polar_interp.take() {
        let (x, c) = (step.st.pos.x, step.st.pos.y);
        step.st.rotary_deg[C] = angle_near(x, c, step.st.rotary_deg[C]);
        step.st.pos.x = x.hypot(c);
        step.st.pos.y = p.y_before;
        step.st.plane = p.plane_before;
    }
    Ok(())
}

/// Record a move of the plane as the machine makes it: pieces of a radius change (X, Z) with
/// the C turn made together with it, the time of each the path's length at F. The first piece
/// accelerates; the others go on at speed (the move is one interpolation).
pub(super) fn push(step: &mut Step, span: Span, n: Option<u32>, op: Op, y_machine: f64) {
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
    let start_deg = step.st.rotary_deg[C];
    let mut r0 = from.x.hypot(from.y);
    let (mut a0, mut z0) = (start_deg, from.z);
    for (k, piece) in pieces(&at, length, curvature, start_deg, PIECE_TOLERANCE_MM).into_iter().enumerate() {
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
            step.push_machine(span, n, Op::Rotary { axis: b'C', from_deg: a0, to_deg: piece.angle_deg, rate_deg_min: rate, rapid: false, with_move: moved }, accel);
        }
        (r0, a0, z0) = (piece.radius_mm, piece.angle_deg, piece.z);
    }
    step.st.rotary_deg[C] = a0;
}
