//! Cycle expansions: pure functions from a cycle's resolved data to canonical operations. No
//! modal state and no words here; the interpreter reads the words and calls these.

pub mod curve;
pub mod drill;
pub mod groove;
pub mod polar;
pub mod rough;
pub mod tap;
pub mod thread;
pub mod turning;

/// A cycle laid out: its moves made one at a time, as many as it has, so that a block of any
/// number of moves holds its lay-out and no more (the interpreter makes them as they are handed
/// on when they are too many to hold, `interp/deferred.rs`).
pub trait Expansion: std::fmt::Debug + Send + Sync {
    /// How many moves it makes at most (counted, nothing made).
    fn move_count(&self) -> usize;
    /// Hand on the moves in order (feeds carry 0: the interpreter sets each from F); the sink
    /// may stop them.
    fn each_op(&self, sink: &mut dyn FnMut(crate::motion::Op) -> std::ops::ControlFlow<()>);
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
