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
    let taper_word = words.take(b'R');
    let a = step.st.pos;
    let given_x = words.has(b'X') || words.has(b'U');
    let given_z = words.has(b'Z') || words.has(b'W');
    let (mut c, _) = axis_target(step, words)?;
    // X, Z and R are modal in the cycle: what a block leaves out comes from the last cycle block,
    // whether or not it names G90/G94 again.
    let memory = step.st.box_cycle;
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
            format!("{name}: R and the step to the end point differ in sign, so |R| may be at most |{letter}| = {shown:.3} mm"),
        ));
    }
    step.st.box_cycle = BoxMemory { end: Some(c), taper_mm };
    if c == a && taper_mm == 0.0 {
        return Ok(());
    }
    // Steps 2 and 3 are cutting feeds at the F in force.
    for op in box_cycle(kind, a, c, taper_mm) {
        step.emit_cut(name, op)?;
    }
    Ok(())
}
