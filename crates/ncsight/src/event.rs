//! What a run produces, in programme order: the canonical stream's records and the diagnostics,
//! one type that every stage after the interpreter passes on (the operator machine, the
//! programme driver, the consumers).

use crate::alarm::Diagnostic;
use crate::motion::Record;

/// A record of the canonical stream, or a diagnostic.
#[derive(Debug, Clone, PartialEq)]
pub enum Event {
    Record(Record),
    Diagnostic(Diagnostic),
}
