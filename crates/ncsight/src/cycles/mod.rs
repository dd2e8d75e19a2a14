//! Cycle expansions: pure functions from a cycle's resolved data to canonical operations. No
//! modal state and no words here; the interpreter reads the words and calls these.

pub mod curve;
pub mod drill;
pub mod groove;
pub mod involute;
pub mod polar;
pub mod rough;
pub mod tap;
pub mod thread;
pub mod turning;

/// The most moves a cycle may lay out: a count, not a memory bound, far above a real programme (a
/// hundred million: about half a minute of the run; a block the machine would run for days), so
/// that such a block is said at once and a count never overflows.
pub const MOST_MOVES: usize = 100_000_000;

/// A cycle laid out: its moves made one at a time, as many as it has, so that a block of any
/// number of moves holds its lay-out and no more (the interpreter makes them as they are handed
/// on when they are too many to hold, `interp/deferred.rs`).
pub trait Expansion: std::fmt::Debug + Send + Sync {
    /// How many moves it makes at most (counted, nothing made).
    fn move_count(&self) -> usize;
    /// Hand on the moves in order (feeds carry 0: the interpreter sets each from F); the sink
    /// may stop them.
    fn each_op(&self, sink: &mut dyn FnMut(crate::motion::Op) -> std::ops::ControlFlow<()>);
    /// The moves are chords of one curve the controller interpolates whole: the time model
    /// accelerates once, at the first (the feeds after it carry a time constant of 0).
    fn one_interpolation(&self) -> bool {
        false
    }
}

/// A lay-out's moves held whole, or none when it counts more than `limit` (refused before any is
/// made).
pub fn held(moves: &dyn Expansion, limit: usize) -> Option<Vec<crate::motion::Op>> {
    if moves.move_count() > limit {
        return None;
    }
    let mut ops = Vec::with_capacity(moves.move_count());
    moves.each_op(&mut |op| {
        ops.push(op);
        std::ops::ControlFlow::Continue(())
    });
    Some(ops)
}

/// Moves made already (a cycle that lays itself out whole: G73's passes): handed on in order.
impl Expansion for Vec<crate::motion::Op> {
    fn move_count(&self) -> usize {
        self.len()
    }

    fn each_op(&self, sink: &mut dyn FnMut(crate::motion::Op) -> std::ops::ControlFlow<()>) {
        for op in self {
            if sink(*op).is_break() {
                return;
            }
        }
    }
}
