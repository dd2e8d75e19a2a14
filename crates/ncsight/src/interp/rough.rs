//! G71 / G72 roughing (type I) and G70 finishing on the system-A lathes (GSK980TDi help text
//! G70, G71, G72). The first block (`G71 U(Δd) R(e)`, `G72 W(Δd) R(e)`) sets the depth of cut
//! and the back-off; the second (`G71 P(ns) Q(nf) U(Δu) W(Δw) F S T`) names the contour
//! blocks, which follow it. The interpreter collects them (they are not executed then: after
//! the cycle the programme goes on after nf, help text step 8), works out the contour on a copy
//! of the modal state, and roughs it. G70 P(ns) Q(nf) runs those blocks for real (their F, S
//! and T count there) and returns to its start point.

use super::call::Flow;
use super::deferred::MAX_DEFERRED_MOVES;
use super::words::Words;
use super::{run_block, Interpreter, Outcome, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::rough::{lay_out, lay_out_pattern, RoughError, RoughKind, RoughNote, Roughing, MAX_POCKETS};
use crate::cycles::Expansion;
use crate::modal::Motion;
use crate::motion::{Op, Vec3};
use crate::read::{Block, Word};
use crate::source::Span;

/// What a second G71/G72 block asks the interpreter to do with the blocks that follow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoughRequest {
    pub kind: RoughKind,
    pub span: Span,
    pub n: Option<u32>,
    pub ns: u32,
    pub nf: u32,
    /// (Δu/2, 0, Δw): the finishing allowances as a move.
    pub allowance: Vec3,
    pub depth_mm: f64,
    pub back_off_mm: f64,
    /// G73: relief (Δi, 0, Δk) and the number of passes.
    pub pattern: Option<(Vec3, u32)>,
    pub start: Vec3,
}

/// G70: run the stored contour ns..nf, then back to `start`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FinishRequest {
    pub span: Span,
    pub n: Option<u32>,
    pub ns: u32,
    pub nf: u32,
    pub start: Vec3,
}

fn sequence_number(step: &Step, w: &Word, code: &str, what: &str) -> Result<u32, Diagnostic> {
    if w.decimal || w.value < 0.0 || w.value > 99_999.0 {
        return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: {code} {what} is a sequence number (N), 0 to 99999", w.text())));
    }
    Ok(w.value as u32)
}

fn p_and_q(step: &mut Step, words: &mut Words, code: &str) -> Result<(u32, u32), Diagnostic> {
    let (Some(p), Some(q)) = (words.take(b'P'), words.take(b'Q')) else {
        return Err(step.alarm(Rule::MissingWord, step.span, format!("{code} needs P(ns) and Q(nf), the first and last blocks of the contour")));
    };
    Ok((sequence_number(step, p, code, "P(ns)")?, sequence_number(step, q, code, "Q(nf)")?))
}

/// G71 or G72, either block.
/// The first G73 block: U(Δi) W(Δk) R(d).
fn pattern_first(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let mut data = step.st.memory.pattern_data.unwrap_or((0.0, 0.0, 1));
    if let Some(w) = words.take(b'U') {
        data.0 = step.length(w)?;
    }
    if let Some(w) = words.take(b'W') {
        data.1 = step.length(w)?;
    }
    if let Some(w) = words.take(b'R') {
        // d is a count of passes, whatever the decimal-point rule for lengths.
        if w.value.fract() != 0.0 || !(1.0..=9999.0).contains(&w.value) {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the number of G73 passes R(d) is a whole number 1 to 9999", w.text())));
        }
        data.2 = w.value as u32;
    }
    step.st.memory.pattern_data = Some(data);
    Ok(())
}

pub(super) fn block(step: &mut Step, words: &mut Words, kind: RoughKind) -> Result<(), Diagnostic> {
    let code = kind.code();
    if kind == RoughKind::Pattern && !(words.has(b'P') || words.has(b'Q')) {
        return pattern_first(step, words);
    }
    let slot = usize::from(kind == RoughKind::Facing);
    if !(words.has(b'P') || words.has(b'Q')) {
        // First block: Δd (U for G71, W for G72) and e.
        let depth_letter = if kind == RoughKind::Turning { b'U' } else { b'W' };
        let mut data = step.st.memory.rough_data[slot].unwrap_or((0.0, 0.0));
        if let Some(w) = words.take(depth_letter) {
            let d = step.length(w)?;
            if d <= 0.0 {
                return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the depth of cut Δd of {code} must be more than 0", w.text())));
            }
            data.0 = d;
        }
        if let Some(w) = words.take(b'R') {
            data.1 = step.length(w)?.abs();
        }
        step.st.memory.rough_data[slot] = Some(data);
        return Ok(());
    }
    let (ns, nf) = p_and_q(step, words, code)?;
    // G73 takes its relief and passes from its first block; G71/G72 their depth of cut and
    // back-off (G73 has neither: 0).
    let (depth_mm, back_off_mm, pattern) = if kind == RoughKind::Pattern {
        let Some((di, dk, d)) = step.st.memory.pattern_data else {
            return Err(step.alarm(Rule::MissingWord, step.span, format!("G73 P{ns} Q{nf} needs its first block G73 U(Δi) W(Δk) R(d) before it")));
        };
        (0.0, 0.0, Some((Vec3::new(di, 0.0, dk), d)))
    } else {
        let Some((depth_mm, back_off_mm)) = step.st.memory.rough_data[slot].filter(|d| d.0 > 0.0) else {
            let letter = if kind == RoughKind::Turning { 'U' } else { 'W' };
            return Err(step.alarm(
                Rule::MissingWord,
                step.span,
                format!("{code} P{ns} Q{nf} needs the depth of cut first: a block {code} {letter}(Δd) R(e) before it"),
            ));
        };
        (depth_mm, back_off_mm, None)
    };
    let mut allowance = Vec3::default();
    if let Some(w) = words.take(b'U') {
        // Δu is on the diameter, as X is programmed.
        allowance.x = step.length(w)? / 2.0;
    }
    if let Some(w) = words.take(b'W') {
        allowance.z = step.length(w)?;
    }
    for l in [b'K', b'J'] {
        if let Some(w) = words.take(l) {
            let msg = format!("{}: the type II options of {code} (K monotony check, J extra contour pass) are not simulated", w.text());
            step.warn(Rule::NotSimulated, w.span, msg);
        }
    }
    step.out.rough_request =
        Some(Box::new(RoughRequest { kind, span: step.span, n: step.n, ns, nf, allowance, depth_mm, back_off_mm, pattern, start: step.st.place.pos }));
    Ok(())
}

/// G70 P(ns) Q(nf).
pub(super) fn finishing(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let (ns, nf) = p_and_q(step, words, "G70")?;
    step.out.finish_request = Some(FinishRequest { span: step.span, n: step.n, ns, nf, start: step.st.place.pos });
    Ok(())
}

/// At most this many blocks in one contour (help text G71 note 5).
const MAX_CONTOUR_BLOCKS: usize = 100;

/// Whether a block ends the programme (M02, M30, M99): a contour cannot run past it.
fn ends_programme(block: &Block) -> bool {
    block.words.iter().any(|w| w.letter == b'M' && !w.decimal && matches!(w.value as i64, 2 | 30 | 99))
}

impl Interpreter {
    pub(super) fn contour_alarm(&self, rule: Rule, span: Span, msg: String) -> Diagnostic {
        Diagnostic::new(rule, self.profile.alarm_style, span, msg)
    }

    /// A block after a second G71/G72 block: part of the contour, not executed now.
    pub(super) fn collect_contour(&mut self, block: &Block, out: &mut Outcome) -> Result<(), Diagnostic> {
        let (req, blocks) = self.collecting.as_mut().expect("collecting");
        let req = *req;
        let code = req.kind.code();
        if blocks.is_empty() && block.sequence != Some(req.ns) {
            self.collecting = None;
            return Err(self.contour_alarm(
                Rule::ContourNotFound,
                block.span,
                format!("{code} P{}: ncsight needs the contour right after the cycle block, starting with N{}; this block is not N{}", req.ns, req.ns, req.ns),
            ));
        }
        if ends_programme(block) {
            self.collecting = None;
            // The end still ends the programme (check mode reads on after the alarm).
            self.state.modes.ended = true;
            return Err(self.contour_alarm(Rule::ContourNotFound, block.span, format!("{code} Q{}: the programme ends before block N{}", req.nf, req.nf)));
        }
        if blocks.len() >= MAX_CONTOUR_BLOCKS {
            self.collecting = None;
            return Err(self.contour_alarm(
                Rule::ContourNotFound,
                block.span,
                format!("{code} Q{}: no block N{} within {MAX_CONTOUR_BLOCKS} blocks of the contour's start (help text note 5)", req.nf, req.nf),
            ));
        }
        blocks.push(block.clone());
        if block.sequence == Some(req.nf) {
            let (req, blocks) = self.collecting.take().expect("collecting");
            // Kept for G70 even when the roughing alarms (check mode reads on).
            self.contours.retain(|c| (c.ns, c.nf) != (req.ns, req.nf));
            self.contours.push(Contour { ns: req.ns, nf: req.nf, blocks, failed: false, warned: Vec::new() });
            let blocks = &self.contours.last().expect("just pushed").blocks.clone();
            let result = self.rough_contour(req, blocks, out);
            if result.is_ok() {
                // The contour blocks' warnings were said with the roughing (not when it alarms:
                // then only its hint names one, and G70 says them).
                let warned: Vec<Diagnostic> = out.warnings.iter().filter(|w| blocks.iter().any(|b| b.span == w.span)).cloned().collect();
                if let Some(c) = self.contours.last_mut() {
                    c.warned = warned;
                }
            }
            if let Err(d) = result {
                // An alarm in one of the contour's own blocks: a G70 reading them again would
                // only report it a second time (check mode reads on).
                if blocks.iter().any(|b| b.span.line == d.span.line) {
                    if let Some(c) = self.contours.last_mut() {
                        c.failed = true;
                    }
                }
                return Err(d);
            }
        }
        Ok(())
    }

    /// The input ended while a contour was being collected.
    pub fn unfinished_contour(&mut self) -> Option<Diagnostic> {
        let (req, blocks) = self.collecting.take()?;
        let span = blocks.last().map(|b| b.span).unwrap_or(req.span);
        Some(self.contour_alarm(Rule::ContourNotFound, span, format!("{} Q{}: the input ends before block N{}", req.kind.code(), req.nf, req.nf)))
    }

    /// The contour's moves, worked out on a copy of the modal state (their F, S, T and M do not
    /// count during roughing: help text note 7).
    ///
    /// Returns the ns block's move, the moves after it, and the warnings the blocks gave.
    #[allow(clippy::type_complexity)]
    fn contour_moves(&self, code: &str, blocks: &[Block]) -> Result<(Op, Vec<Op>, Vec<Diagnostic>, ContourNotes), Diagnostic> {
        let mut st = self.state.clone();
        let mut scratch = Outcome::default();
        // The motion mode and position after the ns block (a G00 to where the tool stands makes
        // no record).
        let mut after_ns = None;
        let mut comp_at_ns = st.comp;
        // The corner stage's held move (a chamfer's, a line of an angle alone) across blocks.
        let (mut no_queue, mut corners) = (Vec::new(), Vec::new());
        let mut ns_corner = false;
        for (k, b) in blocks.iter().enumerate() {
            if b.block_delete && self.switches.block_delete {
                continue;
            }
            // G83/G87 note 3: no drilling cycle inside G71-G73, whatever else the block says.
            let drilling = b.words.iter().filter(|w| w.letter == b'G').find_map(|w| {
                let (major, minor) = w.code();
                self.profile.g_code(major, minor).filter(|g| matches!(g.function, crate::profile::GFn::Drill(_)))
            });
            if let Some(g) = drilling {
                return Err(self.contour_alarm(Rule::ContourCommand, b.span, format!("{code}: a contour block cannot run the drilling cycle G{}", g.major)));
            }
            // The contour is the programmed one (compensation of the finishing shape: docs/compensation.md);
            // its chamfers and corner arcs are made as in a run (docs/commands/drawing.md).
            let mut step = Step {
                profile: self.profile,
                params: &self.params,
                tables: &self.tables,
                queue: &mut no_queue,
                corners: &mut corners,
                bypass_comp: true,
                contour: true,
                repair: None,
                span: b.span,
                n: b.sequence,
                st: &mut st,
                carry: None,
                marks: super::Marks::default(),
                out: &mut scratch,
            };
            run_block(&mut step, b, self.switches)?;
            // GSK980TDi help text, G71 note 4 (G72, G73 likewise): no subprogramme call or
            // return in the contour blocks ns to nf; the roughing refuses it as G70 does.
            if let Some(Flow::Call { span, .. } | Flow::Return { span, .. }) = step.out.flow.take() {
                return Err(self.contour_alarm(
                    Rule::ContourCommand,
                    span,
                    format!("{code}: M98 and M99 may not be used in the contour blocks ns to nf (GSK980TDi manual, G71 note 4)"),
                ));
            }
            if !step.corners.is_empty() {
                super::corner::end_of_block(&mut step)?;
            }
            if let Some(d) = step.out.comp_error.take() {
                return Err(d);
            }
            // The contour's blocks share one outcome: past the limit its moves would be lost.
            if scratch.emitted > super::MAX_MOTIONS_PER_BLOCK {
                return Err(self.contour_alarm(
                    Rule::MotionLimit,
                    b.span,
                    format!("{code}: the contour makes more than {} moves", super::MAX_MOTIONS_PER_BLOCK),
                ));
            }
            if scratch.rough_request.is_some() || scratch.finish_request.is_some() {
                return Err(self.contour_alarm(Rule::ContourCommand, b.span, format!("{code}: a contour block cannot call a cycle itself")));
            }
            if let Some(kind) = st.drill.kind {
                // G83/G87 note 3: no drilling cycle inside G71-G73.
                return Err(self.contour_alarm(Rule::ContourCommand, b.span, format!("{code}: a contour block cannot run the drilling cycle {}", kind.code())));
            }
            if k == 0 {
                after_ns = Some((st.modes.motion, st.place.pos));
                comp_at_ns = st.comp;
                ns_corner = st.comp.held_corner.is_some_and(|c| c.span == b.span);
            }
        }
        // Otherwise each block's end made its move (corner::end_of_block): nothing is held.
        self.contour_end_held(code, blocks, &st)?;
        debug_assert!(corners.is_empty());
        let (ns_move, moves) = self.split_contour(code, blocks, &scratch.records, after_ns, ns_corner)?;
        let notes = ContourNotes {
            feed_warned: st.notes.feed_warned,
            increment_words: scratch.increment_words,
            increment_words_small: scratch.increment_words_small,
            comp: *comp_at_ns,
        };
        Ok((ns_move, moves, scratch.warnings, notes))
    }

    /// The last block may not leave a corner or a line without its end (FANUC alarm 069;
    /// GSK980TDi help text, angle programming note 8).
    fn contour_end_held(&self, code: &str, blocks: &[Block], st: &crate::modal::Modal) -> Result<(), Diagnostic> {
        if let Some(last) = blocks.last() {
            let (corner, line) = (st.comp.held_corner, st.comp.angle_line);
            if corner.is_some() || line.is_some() {
                let what = match corner {
                    Some(c) => c.word(),
                    None => "a line of an angle alone".to_string(),
                };
                return Err(self.contour_alarm(
                    Rule::ContourEndsInCorner,
                    last.span,
                    format!("{code}: the contour's last block leaves {what} without the move that ends it (FANUC alarm 069)"),
                ));
            }
        }
        Ok(())
    }

    /// The contour's records split into the ns block's one G00 or G01 move and the moves
    /// after it (help text notes 1, 2 and 7). `after_ns`: the motion mode and position after
    /// the ns block; `ns_corner`: a corner asked for in the ns block.
    fn split_contour(
        &self,
        code: &str,
        blocks: &[Block],
        records: &[crate::motion::Record],
        after_ns: Option<(Motion, Vec3)>,
        ns_corner: bool,
    ) -> Result<(Op, Vec<Op>), Diagnostic> {
        // Help text notes 1 and 2: the ns block makes one G00 or G01 move.
        let ns_span = blocks[0].span;
        // A corner asked for in the ns block (its chamfer, after its move) belongs to the contour.
        let first_ns = records.iter().position(|r| r.span == ns_span && r.op.end_point().is_some());
        let in_contour =
            |i: usize, r: &crate::motion::Record| r.span != ns_span || (ns_corner && first_ns.is_some_and(|f| i > f) && r.op.end_point().is_some());
        let ns_moves: Vec<&Op> =
            records.iter().enumerate().filter(|(i, r)| r.span == ns_span && r.op.end_point().is_some() && !in_contour(*i, r)).map(|(_, r)| &r.op).collect();
        let axis_word = blocks[0].words.iter().any(|w| b"XZUW".contains(&w.letter));
        let ns_move = match (ns_moves.as_slice(), after_ns) {
            ([op @ (Op::Rapid { .. } | Op::Feed { .. })], _) => (*op).clone(),
            // A G00 or G01 block to where the tool already stands: the help text (note 1) asks
            // only for a G00 or G01 code in the block; the FANUC manuals likewise (PS0065 is for
            // a block without one). Its move has no length (docs).
            ([], Some((Motion::Rapid, p))) if axis_word => Op::Rapid { from: p, to: p },
            ([], Some((Motion::Linear, p))) if axis_word => Op::Feed { from: p, to: p, feed_mm_min: 0.0 },
            _ => {
                return Err(self.contour_alarm(
                    Rule::ContourCommand,
                    ns_span,
                    format!("{code}: the contour's first block must make one G00 or G01 move (help text note 1)"),
                ))
            }
        };
        let mut moves = Vec::new();
        for r in records.iter().enumerate().filter(|(i, r)| in_contour(*i, r)).map(|(_, r)| r) {
            match r.op {
                Op::Rapid { .. } | Op::Feed { .. } | Op::Arc { .. } => moves.push(r.op.clone()),
                // Note 7: S, T and M in the contour do nothing during roughing.
                Op::Spindle { .. } | Op::Tool { .. } | Op::Dwell { .. } | Op::Stop { .. } => {}
                _ => {
                    return Err(self.contour_alarm(
                        Rule::ContourCommand,
                        r.span,
                        format!("{code}: the contour may hold only G00, G01, G02 and G03 moves; this block makes a {} record", r.op.kind()),
                    ))
                }
            }
        }
        if moves.is_empty() {
            return Err(self.contour_alarm(Rule::ContourCommand, ns_span, format!("{code}: the contour has no move after its first block")));
        }
        Ok((ns_move, moves))
    }

    /// The alarm of a roughing the cycle cannot lay out (`hint`: the first warning of the
    /// contour's blocks, which often says why).
    fn rough_error(&self, e: RoughError, req: &RoughRequest, type_two: bool, hint: Option<&str>) -> Diagnostic {
        let code = req.kind.code();
        match e {
            RoughError::NotMonotonic(axis) => {
                let rule = if type_two { "type II roughing needs that along the cut axis" } else { "type I roughing needs that" };
                let d = self.contour_alarm(
                    Rule::ContourNotMonotonic,
                    req.span,
                    format!(
                        "{code}: the contour N{}..N{} does not move one way only along {} ({rule}: help text note 3)",
                        req.ns,
                        req.nf,
                        if axis == 0 { "X" } else { "Z" }
                    ),
                );
                match hint {
                    Some(h) => d.with_hint(format!("the contour's blocks warned: {h}")),
                    None => d,
                }
            }
            RoughError::TooManyPockets => self.contour_alarm(
                Rule::ContourNotMonotonic,
                req.span,
                format!("{code}: the contour N{}..N{} has more than {MAX_POCKETS} pockets (help text type II, 2)", req.ns, req.nf),
            ),
            // Type II holds its levels; type I is counted against what a deferred block may make.
            RoughError::TooMany => self.contour_alarm(
                Rule::MotionLimit,
                req.span,
                format!(
                    "{code}: more than {} roughing moves in one cycle (Δd too small)",
                    if type_two { super::MAX_MOTIONS_PER_BLOCK } else { MAX_DEFERRED_MOVES }
                ),
            ),
            RoughError::NotAPath => {
                self.contour_alarm(Rule::ContourCommand, req.span, format!("{code}: the contour holds a move that is not a line or an arc"))
            }
        }
    }

    /// Rough the collected contour (the records carry the G71/G72 block's span).
    fn rough_contour(&mut self, req: RoughRequest, blocks: &[Block], out: &mut Outcome) -> Result<(), Diagnostic> {
        let code = req.kind.code();
        let (ns_move, rest, warnings, notes) = self.contour_moves(code, blocks)?;
        // What the contour's blocks said stays said: an implausible F once, the lengths without a
        // decimal point counted for the summary.
        self.state.notes.feed_warned = notes.feed_warned;
        out.increment_words += notes.increment_words;
        out.increment_words_small += notes.increment_words_small;
        let first = &blocks[0];
        let ns_rapid = matches!(ns_move, Op::Rapid { .. });
        let mut contour: Vec<Op> = std::iter::once(ns_move.clone()).chain(rest).collect();
        // FANUC roughs along the compensated finishing shape (docs/reference/macro.md 10.3, inferred); the GSK
        // cancels compensation in G71-G73 (help text, G40-G42 note 6) and roughs the programmed
        // one.
        let c = notes.comp;
        if c.side != 0 && c.radius_mm > 0.0 && !self.profile.frame.rough_cancels_comp {
            let has_length = ns_move.start_point().zip(ns_move.end_point()).is_some_and(|(a, b)| a.dist(&b) > 1e-9);
            if has_length {
                contour = crate::comp::path(&contour, crate::motion::Plane::ZX, c.side as f64, c.radius_mm, c.tip).map_err(|e| {
                    self.contour_alarm(
                        super::comp::rule_of(e),
                        req.span,
                        format!("{code}: the finishing shape cannot be compensated by the nose radius {:.3} mm (the tool does not fit it)", c.radius_mm),
                    )
                })?;
            }
        }
        // The contour blocks' own warnings (a length without a decimal point, ...) are passed on.
        out.warnings.extend(warnings.iter().cloned());
        let hint = warnings.first().map(|w| format!("{} (line {})", w.message, w.span.line));
        if let Some((relief, passes)) = req.pattern {
            let plan = lay_out_pattern(req.start, &contour, req.allowance, relief, passes)
                .map_err(|_| self.contour_alarm(Rule::ContourCommand, req.span, format!("{code}: the contour holds a move that is not a line or an arc")))?;
            return self.run_cycle(&req, plan, out, &|most| format!("{code}: {passes} passes over the contour make more than {most} moves in one cycle"));
        }
        let has = |letters: &[u8]| first.words.iter().any(|w| letters.contains(&w.letter));
        let type_two = has(b"XU") && has(b"ZW");
        // Note 2: the ns move goes along the depth axis (X for G71, Z for G72).
        let (level_axis, _) = req.kind.axes();
        // The block names the depth axis (a move of no length included: the tool may stand there).
        if !has(if level_axis == 0 { b"XU" } else { b"ZW" }) {
            let axis = if level_axis == 0 { "X (U)" } else { "Z (W)" };
            return Err(self.contour_alarm(
                Rule::ContourCommand,
                first.span,
                format!("{code}: the contour's first block N{} must move along {axis}, the axis {code} steps its depth on (help text note 2)", req.ns),
            ));
        }
        let r = Roughing {
            kind: req.kind,
            start: req.start,
            contour: &contour,
            allowance: req.allowance,
            depth_mm: req.depth_mm,
            back_off_mm: req.back_off_mm,
            ns_rapid,
            type_two,
            tolerance_mm: if self.state.modes.inch { 0.00254 } else { 0.001 },
        };
        let rough = lay_out(&r, super::MAX_MOTIONS_PER_BLOCK).map_err(|e| self.rough_error(e, &req, type_two, hint.as_deref()))?;
        // The depth axis, and the allowance word and axis along the cut.
        let (depth_axis, cut_word, cut_axis) = if req.kind == RoughKind::Facing { ("Z", "U", "X") } else { ("X", "W", "Z") };
        for n in &rough.notes {
            let msg = match n {
                RoughNote::EndRapidThroughPart => format!("{code}: the rapid from the contour's end back to the start point (step 8) passes through the part: end the contour N{} outside what it passes", req.nf),
                RoughNote::AllowanceMovesPocketWalls => format!("{code}: with pockets, the allowance {cut_word} moves the whole contour along {cut_axis}: one wall of each pocket keeps less than {cut_word}, or is cut into (give {cut_word}0 for type II)"),
                RoughNote::ContourBeyondStart => format!("{code}: the contour N{}..N{} rises beyond the start point along {depth_axis}: the levels begin at the start point and run into it", req.ns, req.nf),
            };
            out.warnings.push(self.contour_alarm(Rule::RoughingCollision, req.span, msg));
        }
        self.run_cycle(&req, rough, out, &|most| format!("{code}: more than {most} roughing moves in one cycle (Δd too small)"))
    }

    /// A roughing's moves under the cycle block's span: made now when a block can hold them, else
    /// as they are handed on (interp/deferred.rs);
    /// past what either allows, the alarm `too_many` says of the most.
    fn run_cycle(
        &mut self,
        req: &RoughRequest,
        moves: impl Expansion + 'static,
        out: &mut Outcome,
        too_many: &dyn Fn(usize) -> String,
    ) -> Result<(), Diagnostic> {
        let mut step = self.step(req.span, req.n, true, out);
        if step.defers(moves.move_count(), too_many)? {
            return step.defer_cuts(req.kind.code(), std::sync::Arc::new(moves));
        }
        self.emit_cycle(req, &moves, out)
    }

    /// Emit a roughing cycle's moves under the cycle block's span, each feed at the block's F
    /// (per revolution under G99, at the point's speed under G96).
    fn emit_cycle(&mut self, req: &RoughRequest, moves: &dyn Expansion, out: &mut Outcome) -> Result<(), Diagnostic> {
        let code = req.kind.code();
        let before = self.state;
        let mut step = self.step(req.span, req.n, true, out);
        let result = step.emit_each(code, moves).and_then(|()| {
            // The per-block limit (the cycle's moves come here, not through `execute_into`).
            if step.out.emitted > super::MAX_MOTIONS_PER_BLOCK {
                return Err(step.alarm(Rule::MotionLimit, req.span, format!("{code}: more than {} moves in one cycle", super::MAX_MOTIONS_PER_BLOCK)));
            }
            // A roughing pass beyond a soft limit, or into G22's area, stops the cycle
            // (docs/setup.md), as every other block's move does.
            step.travel_alarm()
        });
        if let Err(d) = result {
            out.clear();
            self.state = before;
            return Err(d);
        }
        if let Some(last) = out.records.last_mut() {
            last.block_end = true;
        }
        Ok(())
    }

    /// G70: the stored contour run for real, then back to the start.
    pub(super) fn finish_contour(&mut self, req: FinishRequest, out: &mut Outcome) -> Result<(), Diagnostic> {
        if self.replaying {
            return Err(self.contour_alarm(Rule::ContourCommand, req.span, "G70 cannot run inside the contour it is finishing".into()));
        }
        let Some(contour) = self.contours.iter().find(|c| (c.ns, c.nf) == (req.ns, req.nf)) else {
            if self.profile.calls.g70_reads_programme {
                // FANUC: G70 runs the blocks N ns to N nf of the programme, whichever roughing
                // collected them (or none): the programme driver finds and runs them.
                out.flow = Some(super::Flow::Finish(req));
                return Ok(());
            }
            // The real cause where a roughing collected a range that shares one end (issue 36).
            let near = self.contours.iter().rev().find(|c| c.ns == req.ns || c.nf == req.nf);
            let msg = match near {
                Some(c) => format!(
                    "G70 P{} Q{}: the roughing cycle before it collected the blocks N{} to N{}, not N{} to N{}: G70 finishes the contour a G71, G72 or G73 collected (write G70 P{} Q{})",
                    req.ns, req.nf, c.ns, c.nf, req.ns, req.nf, c.ns, c.nf
                ),
                None => format!("G70 P{} Q{}: no G71, G72 or G73 before it collected the blocks N{} to N{}", req.ns, req.nf, req.ns, req.nf),
            };
            return Err(self.contour_alarm(Rule::ContourNotFound, req.span, msg));
        };
        if contour.failed {
            // Its alarm was reported at the roughing cycle (check mode): G70 does nothing.
            return Ok(());
        }
        let blocks = contour.blocks.clone();
        let warned = contour.warned.clone();
        let said = |d: &Diagnostic| warned.iter().any(|w| w.code == d.code && w.span == d.span && w.message == d.message);
        self.replaying = true;
        let mut scratch = Outcome::default();
        let mut result = Ok(());
        for b in &blocks {
            if let Err(d) = self.execute_into(b, &mut scratch) {
                result = Err(d);
                break;
            }
            out.records.append(&mut scratch.records);
            // What the roughing said of these blocks is not said twice (and out of line order).
            out.warnings.extend(scratch.warnings.drain(..).filter(|d| !said(d)));
        }
        out.increment_words += scratch.increment_words;
        out.increment_words_small += scratch.increment_words_small;
        self.replaying = false;
        result?;
        self.finish_return(req, out)
    }

    /// The blocks of a G70 run from the programme's text (`on`), or no longer (the programme
    /// driver's [`super::Flow::Finish`]): inside them G70-G73, M98 and M99 alarm.
    pub fn set_finishing(&mut self, on: bool) {
        self.replaying = on;
    }

    /// The end of G70: back to the start point at rapid (the cycle's end, as G71 step 8),
    /// checked against the soft limits as every move; a contour move still held in radius
    /// compensation is made first (it ends perpendicular), and the return starts where the tool
    /// is. Its records go to `out`, the last one ending the block (single block stops after the
    /// whole G70).
    pub fn finish_return(&mut self, req: FinishRequest, out: &mut Outcome) -> Result<(), Diagnostic> {
        let from = self.state.place.pos;
        let before = self.state;
        let mut scratch = Outcome::default();
        let mut step = self.step(req.span, req.n, true, &mut scratch);
        super::corner::break_off(&mut step);
        super::comp::break_off(&mut step);
        if from != req.start || step.st.comp.actual.is_some() {
            step.emit(Op::Rapid { from, to: req.start });
        }
        if let Some(d) = scratch.comp_error.take() {
            self.state = before;
            return Err(d);
        }
        if let Some(hit) = scratch.overtravel {
            self.state = before;
            return Err(super::overtravel_alarm(self.profile, hit));
        }
        out.records.append(&mut scratch.records);
        // Single block stops after the whole G70.
        if let Some(last) = out.records.last_mut() {
            last.block_end = true;
        }
        Ok(())
    }
}

/// A contour collected by G71-G73, kept for G70.
#[derive(Clone)]
pub(super) struct Contour {
    pub ns: u32,
    pub nf: u32,
    pub blocks: Vec<Block>,
    /// One of its blocks alarmed when the roughing cycle read it.
    pub failed: bool,
    /// The warnings its blocks gave when the roughing cycle read them: G70 reading the same
    /// blocks does not say them again.
    pub warned: Vec<Diagnostic>,
}

/// What reading a contour's blocks on a copy of the modal state leaves behind for the programme.
pub(super) struct ContourNotes {
    feed_warned: Option<bool>,
    increment_words: u32,
    increment_words_small: u32,
    /// Radius compensation in force after the ns block (a G41/G42 before the cycle or in it).
    comp: crate::modal::CompState,
}
