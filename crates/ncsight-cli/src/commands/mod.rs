//! One file per command (the arguments are in `flags.rs`, what several commands share in
//! `lib.rs`).

mod check;
mod cut;
mod lists;
mod page;
mod port;
mod repair;
mod run;

pub(crate) use check::*;
pub(crate) use cut::*;
pub(crate) use lists::*;
pub(crate) use page::*;
pub(crate) use port::*;
pub(crate) use repair::*;
pub(crate) use run::*;
