//! `run` and `expand`: the programme's records written as they are made.

use crate::*;

/// A writer whose reader went away (`ncsight check big.nc | head -1`): the rest is dropped
/// silently and the run goes on, so that the exit status still says what was found.
pub(crate) struct Tolerant<W: Write> {
    pub(crate) inner: W,
    pub(crate) gone: bool,
}

impl<W: Write> Tolerant<W> {
    pub(crate) fn new(inner: W) -> Tolerant<W> {
        Tolerant { inner, gone: false }
    }
}

impl<W: Write> Write for Tolerant<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.gone {
            return Ok(buf.len());
        }
        match self.inner.write(buf) {
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                self.gone = true;
                Ok(buf.len())
            }
            r => r,
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        if self.gone {
            return Ok(());
        }
        match self.inner.flush() {
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                self.gone = true;
                Ok(())
            }
            r => r,
        }
    }
}

/// Output buffer: large writes, few system calls.
pub(crate) const OUTPUT_BUFFER_BYTES: usize = 256 * 1024;

pub(crate) fn run(
    file: &str,
    m: &MachineArgs,
    operator: &OperatorArgs,
    format: &str,
    output: Option<&str>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    let head = Head::of(file)?;
    let (params, switches) = setup(m, head.named(shown(file)), err)?;
    let operator = operator.options()?;
    let mut fmt =
        format::by_name(format, params.profile(), m.setup.is_some()).ok_or_else(|| usage(format!("unknown format '{format}': choose text, jsonl or canon")))?;
    let program = Program::with_operator(params, switches, Mode::Run, operator);
    run_into(file, head, m, program, fmt.as_mut(), output, out, err)
}

/// `ncsight expand`: the run written as plain moves for `to` (docs/commands/expand.md).
pub(crate) fn expand(file: &str, m: &MachineArgs, to: &str, output: Option<&str>, out: &mut dyn Write, err: &mut dyn Write) -> Result<i32, Failure> {
    let target = format::expand::Target::by_name(to).ok_or_else(|| usage(format!("--to {to}: choose linuxcnc or grbl")))?;
    let head = Head::of(file)?;
    let (params, switches) = setup(m, head.named(shown(file)), err)?;
    let mut fmt = format::expand::Expand::new(params.profile(), target, shown(file));
    let program = Program::new(params, switches, Mode::Run);
    run_into(file, head, m, program, &mut fmt, output, out, err)
}

/// Run `program` on `file` (its `head` read) and write its events through `fmt` to `output` (or
/// `out`); alarms, and diagnostics the format does not carry, go to `err`. A record the format
/// refuses ([`format::expand::Refused`]) is an alarm there, and the run stops.
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_into(
    file: &str,
    mut head: Head,
    m: &MachineArgs,
    mut program: Program,
    fmt: &mut dyn format::Format,
    output: Option<&str>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    let decoding = m.decoding()?;
    // Refused before the programme is run; created only when there is something to write.
    let mut file_out = output.map(|path| output::LazyFile::new(path, &m.read_files(file), OUTPUT_BUFFER_BYTES)).transpose().map_err(usage)?;
    let input = head.input(file)?;
    let mut stdout_buf;
    let writer: &mut dyn Write = match file_out.as_mut() {
        Some(f) => f,
        None => {
            // The output is what `run` and `expand` are for: when its reader goes away
            // (`ncsight run big.nc | head`), the first failed write stops the run (exit 0, as
            // any cut pipe: docs/commands/run.md).
            stdout_buf = io::BufWriter::with_capacity(OUTPUT_BUFFER_BYTES, out);
            &mut stdout_buf
        }
    };
    let mut library = m.prepare(&mut program)?;
    let carries = fmt.carries_diagnostics();
    let shown = if file == "-" { "<stdin>" } else { file };
    let mut err = Tolerant::new(err);
    let mut refused = false;
    let result = drive(file, input, &mut library, &mut program, &mut |e, text, name| {
        let mut show = |d: &ncsight::Diagnostic| err.write_all(diag::render(name.unwrap_or(shown), text, d, diag::Style::Full, &decoding).as_bytes());
        if let Event::Diagnostic(d) = e {
            if !carries || d.severity() == Severity::Alarm {
                show(d)?;
            }
            if !carries {
                return Ok(());
            }
        }
        let written = fmt.event(e, name, writer);
        if let Some(d) = written.as_ref().err().and_then(format::expand::Refused::of) {
            refused = true;
            show(d)?;
        }
        for d in fmt.take_notes() {
            show(&d)?;
        }
        written
    });
    let why = if refused {
        Some("the target cannot do the block above: the expansion stops here")
    } else if program.status() == Status::Alarm {
        Some("the programme stops here with an alarm on its controller")
    } else {
        None
    };
    if result.is_ok() || refused {
        fmt.finish(why, writer)?;
    }
    writer.flush()?;
    match result {
        Err(Failure::Io(_)) if refused => Ok(EXIT_ALARM),
        r => r.map(|()| if program.status() == Status::Alarm { EXIT_ALARM } else { EXIT_OK }),
    }
}
