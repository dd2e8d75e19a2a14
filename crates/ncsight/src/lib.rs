//! ncsight core: reads a CNC programme and executes it as a named controller would, producing
//! the canonical motion stream. No I/O: callers feed text and consume events.
//!
//! text -> [`read`] (blocks with spans) -> [`interp`] (profile + modal state, atomic per block)
//! -> [`motion`] records with time from [`time`] -> consumers (formatters in the CLI crate).

pub mod alarm;
pub mod codes;
pub mod comp;
pub mod cycles;
pub mod dialect;
pub mod event;
pub mod explain;
pub mod geom;
pub mod interp;
pub mod machine;
pub mod modal;
pub mod motion;
pub mod profile;
pub mod program;
pub mod read;
pub mod repair;
pub mod setup;
pub mod source;
pub mod stock;
pub mod time;

pub use alarm::{Diagnostic, Rule, Severity};
pub use interp::{Interpreter, Switches};
pub use machine::{Machine, Options};
pub use motion::{Op, Record, Vec3};
pub use profile::{Params, Profile};
pub use program::{
    events, events_with_library, run_text, run_text_with, CallOptions, Event, LeaderScan, LineReader, Mode, Place, Program, ReadBatch, Request, Status,
    LEADER_SCAN_BYTES,
};
