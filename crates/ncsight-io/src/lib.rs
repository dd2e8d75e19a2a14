//! Between the core and its front ends (the command line, the Python package): programme text
//! fed to a [`ncsight::Program`] from files, memory or streams (`feed`), the events written as
//! text, JSONL or canonical calls (`format`), and a run described as its caller asks for it
//! (`Job`). Nothing here knows which front end calls it.

pub mod feed;
pub mod format;
mod job;
pub mod port;

pub use job::{
    check_operator, clip_lines, machine_from_first_line, machine_names, read_first_line, read_setup_file, Job, JobError, JsonlWriter, FIRST_LINE_SCAN_BYTES,
    MAX_SETUP_BYTES,
};
