//! M98 and M99: the words of a subprogramme call and return. The block asks for the jump
//! ([`Flow`]); the programme driver finds the programme, keeps the call stack and its limits.

use super::words::Words;
use super::Step;
use crate::alarm::{Diagnostic, Rule};
use crate::read::Word;
use crate::source::Span;

/// The largest programme number (four digits: GSK980TDi help text, M98; FANUC O1-O9999).
pub const MAX_PROGRAM_NUMBER: u32 = 9999;
/// The largest with eight-digit programme numbers (FANUC 0i-F option).
pub const MAX_PROGRAM_NUMBER_8: u32 = 99_999_999;

/// A jump a block asks the programme driver for, after its motion (the move first, then the
/// call or the return: docs/reference/macro.md section 11, inferred).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Flow {
    /// M98: run programme O`number` `count` times, then go on after the calling block; with
    /// `sequence` (`M98 Q_`, FANUC 0i-F), the running programme's blocks from N`sequence` to its
    /// M99 (`number` is then 0).
    Call { number: u32, count: u32, span: Span, sequence: Option<u32> },
    /// M99: back to the caller, to its block N`sequence` when P gives one (GSK980TDi help text,
    /// M99); in a main programme, the programme starts again.
    Return { sequence: Option<u32>, span: Span },
    /// G70 P(ns) Q(nf) whose blocks no roughing cycle collected, on a controller whose G70 reads
    /// them from the programme (FANUC): the programme runs its blocks N`ns` to N`nf` for real,
    /// then the tool goes back to the start point ([`super::Interpreter::finish_return`]).
    Finish(super::FinishRequest),
}

/// A whole number written without a decimal point, in `0..=max`.
fn whole(step: &Step, w: &Word, what: &str, max: u32) -> Result<u32, Diagnostic> {
    if w.decimal || w.expr {
        return Err(step.alarm(Rule::IllegalDecimalPoint, w.span, format!("{}: {what} is a whole number without a decimal point", w.text())));
    }
    if w.value < 0.0 || w.value > f64::from(max) {
        return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: {what} is 0 to {max}", w.text())));
    }
    Ok(w.value as u32)
}

/// `M98 P<count><number>` (the last four digits the number, those above them the count), or
/// `M98 P<number> L<count>` where the profile takes L.
pub(super) fn call(step: &Step, words: &mut Words, m: &Word) -> Result<Flow, Diagnostic> {
    let rules = step.profile.calls;
    // FANUC 0i-F: `M98 Q100 [L2]` runs the blocks from N100 of this programme to its M99.
    if let (true, None, Some(q)) = (rules.sequence_q, words.peek(b'P'), words.peek(b'Q')) {
        words.take(b'Q');
        let sequence = whole(step, q, "M98 Q (the sequence number to call)", 99_999)?;
        let count = match words.take(b'L') {
            Some(l) => whole(step, l, "the repeat count L", rules.max_count)?,
            None => 1,
        };
        return Ok(Flow::Call { number: 0, count: count.max(1), span: m.span.to(q.span), sequence: Some(sequence) });
    }
    let Some(p) = words.take(b'P') else {
        // FANUC 0 alarm 076; the GSK980TDi help text gives M98 only with P.
        let hint = if words.has(b'Q') {
            "M98 Q (a sequence number of the same programme) is the FANUC 0i-F's: choose fanuc0i-tf or fanuc0i-mf"
        } else {
            "M98 P<programme number>"
        };
        return Err(step.alarm(Rule::AddressPMissing, m.span, format!("{}: the subprogramme to call is not given (P)", m.text())).with_hint(hint));
    };
    let span = m.span.to(p.span);
    let l = words.peek(b'L');
    // Eight-digit programme numbers (the FANUC 0i-F's option, a setting here): P is the number.
    if rules.eight_digit.is_some_and(|k| step.params.get(k) != 0.0) {
        let number = whole(step, p, "the programme number P (eight digits)", MAX_PROGRAM_NUMBER_8)?;
        let count = match words.take(b'L') {
            Some(l) => whole(step, l, "the repeat count L", rules.max_count)?,
            None => 1,
        };
        return Ok(Flow::Call { number, count: count.max(1), span, sequence: None });
    }
    let (number, count) = match l {
        Some(l) if rules.l_count => {
            words.take(b'L');
            let number = whole(step, p, "the programme number P (with L)", MAX_PROGRAM_NUMBER)?;
            let count = whole(step, l, "the repeat count L", rules.max_count)?;
            (number, count)
        }
        Some(l) => {
            let name = step.profile.name;
            return Err(step
                .alarm(
                    Rule::ImproperAddress,
                    l.span,
                    format!("{}: M98 on {name} takes no L: the repeat count is written in P, before the four digits of the programme number", l.text()),
                )
                .with_hint(format!("write M98 P{}{:04} for {} calls of O{:04}", l.value, p.value, l.value, p.value)));
        }
        None => {
            let max = rules.max_count * 10_000 + MAX_PROGRAM_NUMBER;
            let value = whole(step, p, "M98 P (the repeat count, then the four digits of the programme number)", max).map_err(|d| match rules.eight_digit {
                Some(k) => d.with_hint(format!("a machine with eight-digit programme numbers reads P as the number: --param {k}=1")),
                None => d,
            })?;
            (value % 10_000, value / 10_000)
        }
    };
    // A count of 0 calls once, as no count does (docs/reference/macro.md section 2, inferred).
    Ok(Flow::Call { number, count: count.max(1), span, sequence: None })
}

/// `M99` or `M99 P<sequence number>`.
pub(super) fn ret(step: &Step, words: &mut Words, m: &Word) -> Result<Flow, Diagnostic> {
    let sequence = match words.take(b'P') {
        Some(p) => Some(whole(step, p, "M99 P (the sequence number to return to)", 99_999)?),
        None => None,
    };
    Ok(Flow::Return { sequence, span: m.span })
}
