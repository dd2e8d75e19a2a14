//! The `ncsight` command line over the core library: argument parsing, file I/O, output
//! formats and diagnostics. `main.rs` only calls [`main_with`].

pub mod diag;
pub use ncsight_io::{feed, format};
mod commands;
mod flags;
mod output;
pub mod report;
pub mod simulate;

use commands::*;
use flags::*;

use clap::{Parser, Subcommand};
use ncsight::profile::{self, Params};
use ncsight::{Event, Mode, Program, Severity, Status, Switches};
use std::io::{self, BufReader, Read, Write};

/// Exit status: ran to the end / clean.
pub const EXIT_OK: i32 = 0;
/// Exit status: stopped on an alarm (run) or an alarm was found (check).
pub const EXIT_ALARM: i32 = 1;
/// Exit status: usage or I/O error.
pub const EXIT_USAGE: i32 = 2;
/// Exit status of `simulate` and `report`: the programme ran to the end, and the stock
/// simulation found a problem (a crash, a phase error, the chuck reached, a deviation from
/// `--expect`).
pub const EXIT_FINDINGS: i32 = 3;

/// The exit status of a run whose stock simulation gave these findings.
fn status_with_findings(alarm: bool, findings: &[ncsight::stock::Finding]) -> i32 {
    if alarm {
        EXIT_ALARM
    } else if findings.iter().any(|f| f.is_problem()) {
        EXIT_FINDINGS
    } else {
        EXIT_OK
    }
}

/// Run the command line. Returns the exit status.
pub fn main_with(args: impl IntoIterator<Item = std::ffi::OsString>, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    let cli = match Cli::try_parse_from(args) {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { EXIT_USAGE } else { EXIT_OK };
            let text = e.render().to_string();
            if e.use_stderr() {
                let _ = err.write_all(text.as_bytes());
            } else {
                let _ = out.write_all(text.as_bytes());
            }
            return code;
        }
    };
    let result = match cli.command {
        Command::Run { file, machine, format, output, operator } => run(&file, &machine, &operator, &format, output.as_deref(), out, err),
        Command::Check { files, machine, format } => check(&files, &machine, &format, out, err),
        Command::Expand { file, machine, to, output } => expand(&file, &machine, &to, output.as_deref(), out, err),
        Command::Port { file, machine, to, to_setup, output, format } => {
            port(&file, &machine, (&to, to_setup.as_deref()), output.as_deref(), &format, out, err)
        }
        Command::Machines { machine } => machines(machine.as_deref(), out),
        Command::Explain { code, lang, list } => explain(code.as_deref(), lang.as_deref(), list, out),
        Command::Lsp { stdio: _ } => ncsight_lsp::run_stdio().map(|()| EXIT_OK).map_err(|e| usage(format!("lsp: {e}"))),
        Command::Simulate { file, machine, stock, expect, format, image, stl, section, resolution } => {
            let outputs = SimOutputs { image: image.as_deref(), stl: stl.as_deref(), section: section.as_deref() };
            simulate(&file, &machine, stock.as_deref(), expect.as_deref(), &format, outputs, resolution.as_deref(), out, err)
        }
        Command::Report { file, machine, operator, stock, expect, output } => {
            report(&file, &machine, &operator, stock.as_deref(), expect.as_deref(), output.as_deref(), out, err)
        }
        Command::App { output } => app(output.as_deref(), out),
        Command::Repair { machine, start, end, lead, tpi, rpm, measured, j, k } => repair(&machine, &start, &end, lead, tpi, rpm, &measured, j, k, out, err),
    };
    match result {
        Ok(code) => code,
        Err(Failure::Usage(msg)) => {
            let _ = writeln!(err, "ncsight: {msg}");
            EXIT_USAGE
        }
        Err(Failure::Io(e)) if e.kind() == io::ErrorKind::BrokenPipe => EXIT_OK,
        Err(Failure::Io(e)) => {
            let _ = writeln!(err, "ncsight: {e}");
            EXIT_USAGE
        }
    }
}

enum Failure {
    Usage(String),
    Io(io::Error),
}

impl From<io::Error> for Failure {
    fn from(e: io::Error) -> Failure {
        Failure::Io(e)
    }
}

impl From<ncsight_io::JobError> for Failure {
    fn from(e: ncsight_io::JobError) -> Failure {
        match e {
            ncsight_io::JobError::Usage(m) => Failure::Usage(m),
            ncsight_io::JobError::Io(e) => Failure::Io(e),
        }
    }
}

fn usage(msg: impl Into<String>) -> Failure {
    Failure::Usage(msg.into())
}

fn names() -> String {
    ncsight_io::machine_names()
}

/// The profile and parameters the arguments name, or the programme's first line
/// (`named`: the programme as shown and the name in its `(ncsight: NAME)`; [`machine_for`]).
fn setup(m: &MachineArgs, named: Option<(&str, &str)>, err: &mut dyn Write) -> Result<(Params, Switches), Failure> {
    let name = machine_for(m, named, true, err)?;
    setup_on(m, &name)
}

/// The machine a run uses: `--machine`, else the one the programme's first line names
/// (`(ncsight: fanuc0m)`: `named` is the programme as shown and that name), else gsk980tdi. A
/// note on `err` says which, unless the machine is the given one (or the default with
/// `say_default` false); `--machine` and a first line that differ are noted. An unknown name in
/// the first line is a usage error, as an unknown `--machine` is.
fn machine_for(m: &MachineArgs, named: Option<(&str, &str)>, say_default: bool, err: &mut dyn Write) -> Result<String, Failure> {
    match (&m.machine, named) {
        (Some(given), Some((shown, name))) => {
            let differ = matches!(profile::by_name(given), Some(p) if profile::by_name(name).map(|q| q.name) != Some(p.name));
            if differ {
                let _ = writeln!(err, "ncsight: using --machine {given}, not {name} named by the first line of {shown}");
            }
            Ok(given.clone())
        }
        (Some(given), None) => Ok(given.clone()),
        (None, Some((shown, name))) => {
            let p = ncsight_io::Job::on(name).profile().map_err(|e| usage(format!("{shown}: first line (ncsight: {name}): {e}")))?;
            let _ = writeln!(err, "ncsight: using {} named by the first line of {shown}", p.name);
            Ok(p.name.to_string())
        }
        (None, None) => {
            if say_default {
                let _ = writeln!(err, "ncsight: no --machine given, using gsk980tdi (profiles: {})", names());
            }
            Ok("gsk980tdi".to_string())
        }
    }
}

/// The profile `name` and its parameters as the arguments set them.
fn setup_on(m: &MachineArgs, name: &str) -> Result<(Params, Switches), Failure> {
    let job = m.job(name)?;
    let params = job.parameters()?;
    let repair_position = m.repair_position.as_deref().map(|t| recorded(t, "--repair-position")).transpose()?;
    Ok((params, Switches { repair_position, ..job.switches }))
}

fn open(file: &str) -> Result<feed::Input, Failure> {
    if file == "-" {
        return Ok(feed::Input::Stream(Box::new(BufReader::new(io::stdin()))));
    }
    if std::fs::metadata(file).is_ok_and(|m| m.is_dir()) {
        return Err(usage(format!("cannot read {file}: it is a directory, not a programme file")));
    }
    feed::Input::open(std::path::Path::new(file)).map_err(|e| usage(format!("cannot read {file}: {e}")))
}

/// A programme's first line, read before the run for the machine it may name
/// ([`ncsight_io::machine_from_first_line`]).
struct Head {
    /// NAME of a first line `(ncsight: NAME)`, as written.
    named: Option<String>,
    /// The input of standard input or a pipe, its first line given back in front of the rest
    /// (they give their data once); `None` for a file, which the run opens again.
    input: Option<feed::Input>,
}

impl Head {
    fn of(file: &str) -> Result<Head, Failure> {
        if file != "-" {
            match std::fs::metadata(file) {
                Ok(md) if md.is_file() => {
                    // A file that cannot be read is named by the run's own opening.
                    let head = std::fs::File::open(file).and_then(|f| ncsight_io::read_first_line(&mut BufReader::new(f)));
                    return Ok(Head { named: head.ok().and_then(|h| ncsight_io::machine_from_first_line(&h)), input: None });
                }
                Ok(md) if !md.is_dir() => {}
                _ => return Ok(Head { named: None, input: None }),
            }
        }
        match open(file)? {
            feed::Input::Stream(mut r) => {
                let head = ncsight_io::read_first_line(&mut r).map_err(|e| usage(format!("cannot read {file}: {e}")))?;
                let named = ncsight_io::machine_from_first_line(&head);
                Ok(Head { named, input: Some(feed::Input::Stream(Box::new(io::Cursor::new(head).chain(r)))) })
            }
            input => Ok(Head { named: None, input: Some(input) }),
        }
    }

    /// The programme as shown and the machine its first line names, for [`setup`].
    fn named<'a>(&'a self, shown: &'a str) -> Option<(&'a str, &'a str)> {
        self.named.as_deref().map(|n| (shown, n))
    }

    /// The run's input: the stream already opened, else `file` opened now.
    fn input(&mut self, file: &str) -> Result<feed::Input, Failure> {
        match self.input.take() {
            Some(input) => Ok(input),
            None => open(file),
        }
    }
}

/// How `file` is named in messages.
fn shown(file: &str) -> &str {
    if file == "-" {
        "<stdin>"
    } else {
        file
    }
}

/// [`feed::drive`] with an error in reading the input named by its file.
fn drive(
    file: &str,
    input: feed::Input,
    library: &mut feed::Library,
    program: &mut Program,
    on_event: &mut dyn FnMut(&Event, &[u8], feed::FileName) -> io::Result<()>,
) -> Result<(), Failure> {
    feed::drive(input, library, program, on_event)
        .map_err(|e| if feed::is_read_failure(&e) { usage(format!("cannot read {file}: {e}")) } else { Failure::Io(e) })
}
