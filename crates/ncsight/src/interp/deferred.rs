//! A block's moves too many to hold (a G71 of a hundred thousand levels, a G74 of a micrometre
//! peck): laid out when the block runs, checked as the ordinary path checks them, and made one
//! record at a time as the driver hands them on, so that a block of any number of moves holds a
//! constant memory. The controller never refuses such a block; neither does ncsight.

use std::ops::ControlFlow;
use std::sync::Arc;

use super::{CutFeed, Deferred, Step};
use crate::alarm::{Diagnostic, Rule};
use crate::cycles::Expansion;
use crate::motion::{Op, Record, Vec3};
use crate::source::Span;

/// How many moves a cycle block may make before they are made one at a time as they are handed
/// on rather than held: far above a real programme's (the goldens never reach it), so they keep
/// the ordinary path.
const DEFER_MOVES: usize = 50_000;

/// The most moves a deferred block may make (see [`crate::cycles::MOST_MOVES`]).
pub(super) const MAX_DEFERRED_MOVES: usize = crate::cycles::MOST_MOVES;

/// A cycle's moves, laid out but not made: the driver makes their records one at a time as it
/// hands them on.
#[derive(Debug, Clone)]
pub struct DeferredCuts {
    moves: Arc<dyn Expansion>,
    /// The feed of its cutting moves (none: it makes none).
    feed: Option<CutFeed>,
    span: Span,
    n: Option<u32>,
    to_machine: Vec3,
    /// Its last record ends the block for single block (not when the block makes records after
    /// it: a trailing M code's).
    ends_block: bool,
}

impl DeferredCuts {
    /// The block makes records after these: the last of those ends it.
    pub(super) fn followed(&mut self) {
        self.ends_block = false;
    }

    /// Every record of the cycle, in order, the last one ending the block for single block.
    pub fn each_record(&self, sink: &mut dyn FnMut(Record)) {
        let mut held: Option<Record> = None;
        let one_interpolation = self.moves.one_interpolation();
        let mut first_feed = true;
        self.moves.each_op(&mut |op| {
            let op = match &self.feed {
                Some(f) => f.apply(op).0,
                None => op,
            };
            let mut r = Record::of_block(self.span, self.n, op);
            r.to_machine = self.to_machine;
            if matches!(r.op, Op::Feed { .. }) {
                if one_interpolation && !first_feed {
                    r.accel_s = Some(0.0);
                }
                first_feed = false;
            }
            if let Some(done) = held.replace(r) {
                sink(done);
            }
            ControlFlow::Continue(())
        });
        if let Some(mut last) = held {
            last.block_end |= self.ends_block;
            sink(last);
        }
    }
}

impl Step<'_> {
    /// Whether a cycle's moves may be made as they are handed on: the consumer takes each record
    /// as it comes, and nothing between the cycle and the record reshapes a move (a transform
    /// carried, a corner held, radius compensation acting or a compensated tool position, polar
    /// interpolation: those keep the ordinary path and its cap). Soft limits and a G22 area are
    /// checked by a dry pass over the moves before any is made.
    pub(super) fn may_defer_cuts(&self) -> bool {
        self.out.may_defer
            && self.carry.is_none()
            && !super::corner::active(self)
            && self.queue.is_empty()
            && self.corners.is_empty()
            && (self.bypass_comp || self.st.comp.side == 0)
            && self.st.comp.actual.is_none()
            && self.st.modes.polar_interp.is_none()
    }

    /// Whether a cycle of `count` moves is deferred (true) or made now (false); past what either
    /// path allows, the alarm `too_many` says of the most.
    pub(super) fn defers(&self, count: usize, too_many: &dyn Fn(usize) -> String) -> Result<bool, Diagnostic> {
        if count > DEFER_MOVES && self.may_defer_cuts() {
            if count > MAX_DEFERRED_MOVES {
                return Err(self.alarm(Rule::MotionLimit, self.span, too_many(MAX_DEFERRED_MOVES)));
            }
            return Ok(true);
        }
        if count > super::MAX_MOTIONS_PER_BLOCK {
            return Err(self.alarm(Rule::MotionLimit, self.span, too_many(super::MAX_MOTIONS_PER_BLOCK)));
        }
        Ok(false)
    }

    /// Defer a cycle's moves (at most [`MAX_DEFERRED_MOVES`]; the caller says its own alarm
    /// past that): their feed found from the first cutting move (its alarm, or its warnings, are
    /// the block's, as on the ordinary path), a soft limit or G22 area checked by walking them
    /// once with nothing kept, the tool left where the last move ends.
    pub(super) fn defer_cuts(&mut self, what: &'static str, moves: Arc<dyn Expansion>) -> Result<(), Diagnostic> {
        // The first cutting move, and where the last move leaves the tool (the cycle's own end, a
        // groove's relief included): one walk, nothing kept.
        let (mut first, mut end) = (None, None);
        moves.each_op(&mut |op| {
            if first.is_none() && matches!(op, Op::Feed { .. } | Op::Arc { .. }) {
                first = Some(op);
            }
            end = op.end_point().or(end);
            ControlFlow::Continue(())
        });
        let feed = match first {
            Some(Op::Feed { from, to, .. } | Op::Arc { from, to, .. }) => Some(self.feed_rule(what, &|u| super::lerp(&from, &to, u))?),
            _ => None,
        };
        if let Some((asked, max)) = feed.and_then(|f| f.clamped()) {
            self.warn_clamped(asked, max);
        }
        let to_machine = self.tables.to_machine(&self.st.frame);
        if self.tables.limited || self.st.stroke2.is_some() {
            self.dry_pass(moves.as_ref(), &to_machine)?;
        }
        if let Some(end) = end {
            // The tool offset's movement is made with the cycle's first move.
            self.st.place.pos = end;
            self.st.frame.unmoved = Vec3::default();
        }
        let cuts = DeferredCuts { moves, feed, span: self.span, n: self.n, to_machine, ends_block: true };
        self.out.deferred = Some(Box::new((self.out.records.len(), Deferred::Cuts(cuts))));
        Ok(())
    }

    /// The moves walked once, nothing kept: the first the machine refuses (beyond a soft limit,
    /// into G22's area) is the block's alarm, before anything is made.
    fn dry_pass(&mut self, moves: &dyn Expansion, to_machine: &Vec3) -> Result<(), Diagnostic> {
        let span = self.span;
        moves.each_op(&mut |op| {
            self.travel_checks(span, &op, to_machine);
            if self.out.overtravel.is_some() || self.out.stroke_hit.is_some() {
                return ControlFlow::Break(());
            }
            ControlFlow::Continue(())
        });
        self.travel_alarm()
    }

    /// A cycle's moves made now, each through the stages with its feed ([`Step::emit_cut`]).
    pub(super) fn emit_each(&mut self, what: &'static str, moves: &dyn Expansion) -> Result<(), Diagnostic> {
        let mut result = Ok(());
        moves.each_op(&mut |op| match self.emit_cut(what, op) {
            Ok(()) => ControlFlow::Continue(()),
            Err(d) => {
                result = Err(d);
                ControlFlow::Break(())
            }
        });
        result
    }
}
