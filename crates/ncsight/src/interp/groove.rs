//! G74 / G75 blocks on the system-A lathes (GSK980TDi help text G74, G75): the first block
//! (`G74 R(e)`) sets the back-off, the second (`G74 X(U) Z(W) P(Δi) Q(Δk) R(Δd) F`) cuts.

use super::compound::increments;
use super::deferred::MAX_DEFERRED_MOVES;
use super::words::Words;
use super::{axis_target, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::groove::{lay_out, PeckCycle, PeckError, PeckKind};
use crate::cycles::Expansion;

pub(super) fn block(step: &mut Step, words: &mut Words, kind: PeckKind) -> Result<(), Diagnostic> {
    let code = kind.code();
    let has_axis = [b'X', b'Z', b'U', b'W'].iter().any(|l| words.has(*l));
    if !has_axis {
        // First block: R(e), the back-off after each peck; it stays for later blocks.
        if let Some(w) = words.take(b'R') {
            let e = step.length(w)?;
            if e < 0.0 {
                return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the back-off e of {code} cannot be negative", w.text())));
            }
            step.st.memory.peck_back_off_mm = Some(e);
        }
        return Ok(());
    }
    // As the help text writes the steps: G74 moves X by Δi/2 and Δd/2 (steps 4 and 6), G75
    // moves X by Δi (step 1); Z amounts as given.
    let halved = if kind == PeckKind::Face { 0.5 } else { 1.0 };
    let (peck_letter, step_letter) = if kind == PeckKind::Face { (b'Q', b'P') } else { (b'P', b'Q') };
    let amount = |step: &mut Step, words: &mut Words, letter: u8, scale: f64| -> Result<f64, Diagnostic> {
        match words.take(letter) {
            Some(w) => Ok(increments(step, w, code)?.abs() * scale),
            None => Ok(0.0),
        }
    };
    let peck_mm = amount(step, words, peck_letter, 1.0)?;
    let step_mm = amount(step, words, step_letter, halved)?;
    let relief_mm = match words.take(b'R') {
        Some(w) => step.length(w)?.abs() * halved,
        None => 0.0,
    };
    let back_off_mm = step.st.memory.peck_back_off_mm.or_else(|| step.profile.peck_back_off.map(|k| step.params.get(k))).unwrap_or(0.0);
    let start = step.st.place.pos;
    let (end, _) = axis_target(step, words)?;
    let cycle = PeckCycle { kind, start, end, back_off_mm, peck_mm, step_mm, relief_mm };
    let plan = lay_out(&cycle, MAX_DEFERRED_MOVES).map_err(|e| {
        let (peck_name, step_name) = if kind == PeckKind::Face { ("Q(Δk)", "P(Δi)") } else { ("P(Δi)", "Q(Δk)") };
        let (rule, msg) = match e {
            PeckError::NoPeck => (Rule::MissingWord, format!("{code}: the end point is deeper than the start but the peck {peck_name} is missing or 0")),
            PeckError::NoStep => (Rule::MissingWord, format!("{code}: the end point lies across from the start but the step {step_name} is missing or 0")),
            PeckError::TooMany => (Rule::MotionLimit, format!("{code}: more than {MAX_DEFERRED_MOVES} moves in one block (the peck or step is too small)")),
        };
        step.alarm(rule, step.span, msg)
    })?;
    // Past what a block holds its moves are made as they are handed on (interp/deferred.rs).
    if step.defers(plan.move_count(), &|most| format!("{code}: more than {most} moves in one block (the peck or step is too small)"))? {
        return step.defer_cuts(code, std::sync::Arc::new(plan));
    }
    step.emit_each(code, &plan)
}
