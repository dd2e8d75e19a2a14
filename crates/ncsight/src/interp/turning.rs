//! G90 / G94 blocks (GSK980TDi help text G90, G94): read the end point and taper, keep them for
//! the blocks that repeat the cycle, and emit the box of `cycles::turning`.

use super::words::Words;
use super::{axis_target, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::turning::{box_cycle, BoxKind};
use crate::modal::BoxMemory;

/// One G90 or G94 block, naming the code or repeating the cycle in force.
pub(super) fn block(step: &mut Step, words: &mut Words, kind: BoxKind) -> Result<(), Diagnostic> {
    let name = kind.code();
    let taper_word = words.take(step.profile.box_taper);
    let a = step.st.place.pos;
    let given_x = words.has(b'X') || words.has(b'U');
    let given_z = words.has(b'Z') || words.has(b'W');
    let (mut c, _) = axis_target(step, words)?;
    // X, Z and R are modal in the cycle: what a block leaves out comes from the last cycle block,
    // whether or not it names G90/G94 again.
    let memory = step.st.memory.box_cycle;
    if let Some(m) = memory.end {
        if !given_x {
            c.x = m.x;
        }
        if !given_z {
            c.z = m.z;
        }
    }
    let taper_mm = match taper_word {
        Some(w) => step.length(w)?,
        None => memory.taper_mm,
    };
    // The taper may not carry the cut start past the start point: with R and U (G90) or R and
    // W (G94) of opposite signs, |R| is at most the step (FANUC 0-T and GSK figures: the four
    // taper cases).
    let step_axis = kind.step_axis();
    let travel = c.axis(step_axis) - a.axis(step_axis);
    if taper_mm != 0.0 && (travel == 0.0 || taper_mm.signum() != travel.signum()) && taper_mm.abs() > travel.abs() + 1e-9 {
        let span = taper_word.map(|w| w.span).unwrap_or(step.span);
        let (letter, shown) = if kind == BoxKind::Turning { ("U/2", travel.abs()) } else { ("W", travel.abs()) };
        return Err(step.alarm(
            Rule::TaperTooLarge,
            span,
            format!(
                "{name}: {} and the step to the end point differ in sign, so its size may be at most |{letter}| = {shown:.3} mm",
                step.profile.box_taper as char
            ),
        ));
    }
    step.st.memory.box_cycle = BoxMemory { end: Some(c), taper_mm };
    if c == a && taper_mm == 0.0 {
        return Ok(());
    }
    // Steps 2 and 3 are cutting feeds at the F in force.
    let mut ops = box_cycle(kind, a, c, taper_mm);
    let comp = step.st.comp;
    if comp.side != 0 && comp.radius_mm > 0.0 && step.profile.frame.box_by_tip {
        match by_tip(&ops, comp.radius_mm, comp.tip) {
            Ok(Some(done)) => ops = done,
            Ok(None) => {
                let msg = format!(
                    "{name}: the imaginary tool nose of the offset in force gives the cycle no side (tip 0, 9 or along the cut): the programmed cycle runs"
                );
                step.warn(Rule::NotSimulated, step.span, msg);
            }
            Err(e) => {
                return Err(step.alarm(
                    super::comp::rule_of(e),
                    step.span,
                    format!("{name}: the cycle cannot be compensated by the nose radius {:.3} mm (the tool does not fit it)", comp.radius_mm),
                ));
            }
        }
    }
    for op in ops {
        step.emit_cut(name, op)?;
    }
    Ok(())
}

/// FANUC G90/G94 in nose radius compensation: the box's moves in, along and out are
/// compensated on the side the imaginary tool nose puts the nose centre, whatever G41/G42 say
/// (docs/reference/macro.md 10.3 [inferred]); the rapid back to the start goes from where the tool is. A
/// straight cycle then cuts where it is written (on its lines the nose's imaginary point stays
/// on the programmed line); a taper is offset as a compensated taper is.
fn by_tip(ops: &[crate::motion::Op], r: f64, tip: crate::motion::Vec3) -> Result<Option<Vec<crate::motion::Op>>, crate::comp::CompError> {
    use crate::comp::{self, Seg};
    use crate::motion::{Op, Plane};
    let plane = Plane::ZX;
    let Some(cut) = ops.get(1).and_then(|op| Seg::of(op, plane)).filter(|_| ops.len() == 4) else {
        return Ok(None);
    };
    // The nose centre lies against the tip's direction: left or right of the cut's travel.
    let to_centre = comp::local(&(crate::motion::Vec3::default() - tip), plane);
    let side = comp::P2::cross(cut.tangent(false), to_centre);
    if side.abs() < 1e-12 {
        return Ok(None);
    }
    let side = side.signum();
    let mut out = comp::path(&ops[..3], plane, side, r, tip)?;
    let back = match (out.last().and_then(Op::end_point), ops[3]) {
        (Some(from), Op::Rapid { to, .. }) => Op::Rapid { from, to },
        (_, other) => other,
    };
    out.push(back);
    Ok(Some(out))
}
