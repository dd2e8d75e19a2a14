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
