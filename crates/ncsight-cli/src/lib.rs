//! The `ncsight` command line over the core library: argument parsing, file I/O, output
//! formats and diagnostics. `main.rs` only calls [`main_with`].

pub mod diag;
pub use ncsight_io::{feed, format};
mod output;
pub mod report;
pub mod simulate;

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

#[derive(Parser, Debug)]
#[command(name = "ncsight", version, about = "See what a CNC programme will do on a GSK, FANUC or YASNAC controller before the machine does it")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(clap::Args, Debug)]
struct MachineArgs {
    /// Controller profile: gsk980tdi, gsk988t, fanuc0m, fanuc0t, yasnac-lx3, fanuc0i-tf, fanuc0i-mf (default: the one a first line `(ncsight: NAME)` of the programme names, else gsk980tdi).
    #[arg(long, short = 'm')]
    machine: Option<String>,
    /// Override a parameter by the manual's number: N=V or N.B=V for a bit (e.g. 19=10, 18.6=1).
    #[arg(long = "param", value_name = "N=V")]
    params: Vec<String>,
    /// Block delete switch on: blocks starting with '/' are skipped.
    #[arg(long)]
    block_delete: bool,
    /// Optional stop switch on: M01 stops.
    #[arg(long)]
    optional_stop: bool,
    /// The thread repair position recorded on the machine: X (diameter), Z and the spindle's C
    /// angle in degrees, for G92 P1 / G92.1 P1 (GSK980TDi).
    #[arg(long, value_name = "X,Z,C", allow_hyphen_values = true)]
    repair_position: Option<String>,
    /// How lines that are not UTF-8 are shown (default: GB18030/GBK, as GSK controls and Chinese
    /// editors save them, else Windows-1252): gbk, gb18030, big5, shift_jis, latin1, ...
    #[arg(long, value_name = "NAME")]
    encoding: Option<String>,
    /// The main programme, when it is not the first programme in the file (O1234 or 1234).
    #[arg(long, value_name = "O1234")]
    main: Option<String>,
    /// A directory where a called programme the file lacks is looked for (repeatable): a file
    /// named after its number (O1234, o1234.nc, ...), else a file that holds it.
    #[arg(long = "subprogram-dir", value_name = "DIR")]
    subprogram_dirs: Vec<std::path::PathBuf>,
    /// A called programme that no file holds is skipped with a warning (builder macros live
    /// in the machine), instead of the controller's alarm.
    #[arg(long)]
    skip_missing_subprograms: bool,
    /// The runaway guard: blocks executed again after jumps back (subprogramme repeats), at
    /// most, before the run stops with NCS-E63.
    #[arg(long, value_name = "N")]
    max_blocks: Option<u64>,
    /// A common macro variable as set at the machine before the run, or an input signal of the
    /// machine (#1000-#1015, #1032) (repeatable): 500=1.5, 1002=1.
    #[arg(long = "var", value_name = "N=V", allow_hyphen_values = true)]
    vars: Vec<String>,
    /// Run the programme as a macro called with these arguments, as a G65 block writes them
    /// after P: "A1. B2. I3." (#1, #2, #4 of the programme's own level).
    #[arg(long = "call-args", value_name = "ARGS", allow_hyphen_values = true)]
    call_args: Option<String>,
    /// The machine setup (TOML): axes, travel limits, reference points, work offsets (G54-G59),
    /// the tool and offset tables, the stock (docs/setup.md).
    #[arg(long, value_name = "FILE.toml")]
    setup: Option<String>,
    /// The setup file's text, read once (a named pipe gives its data once).
    #[arg(skip)]
    setup_text: std::sync::OnceLock<Result<String, String>>,
}

impl MachineArgs {
    /// The run these arguments describe (the machine resolved by [`setup`]).
    fn job(&self, machine: &str) -> Result<ncsight_io::Job, Failure> {
        let mut job = ncsight_io::Job {
            machine: machine.to_string(),
            params: self.params.clone(),
            switches: Switches { block_delete: self.block_delete, optional_stop: self.optional_stop, repair_position: None },
            operator: ncsight::Options::default(),
            main: self.main.clone(),
            subprogram_dirs: self.subprogram_dirs.clone(),
            skip_missing_subprograms: self.skip_missing_subprograms,
            max_blocks: self.max_blocks,
            vars: self.vars.clone(),
            call_args: self.call_args.clone(),
            setup: None,
            setup_dir: None,
        };
        if let Some(path) = &self.setup {
            let text = self.setup_text()?.expect("a setup is given");
            job.set_setup_text(text, path)?;
        }
        Ok(job)
    }

    /// The text of `--setup`, read once and at most ncsight_io's bound, however many times it
    /// is asked for.
    fn setup_text(&self) -> Result<Option<&str>, Failure> {
        let Some(path) = &self.setup else { return Ok(None) };
        let read = self.setup_text.get_or_init(|| {
            ncsight_io::read_setup_file(path).map_err(|e| match e {
                ncsight_io::JobError::Usage(m) => m,
                ncsight_io::JobError::Io(e) => format!("cannot read {path}: {e}"),
            })
        });
        match read {
            Ok(text) => Ok(Some(text.as_str())),
            Err(m) => Err(usage(m.clone())),
        }
    }

    /// The run's calls and variables as the arguments give them, set on `program`.
    fn prepare(&self, program: &mut Program) -> Result<feed::Library, Failure> {
        let machine = program.profile().name;
        Ok(self.job(machine)?.prepare(program)?)
    }

    /// Every file a run of `file` with these arguments may read: the programme, the setup, and
    /// each file of the subprogramme folders. No output may be one of them.
    fn read_files(&self, file: &str) -> Vec<String> {
        let mut files = vec![file.to_string()];
        files.extend(self.setup.iter().cloned());
        for d in &self.subprogram_dirs {
            if let Ok(entries) = std::fs::read_dir(d) {
                files.extend(entries.filter_map(|e| e.ok()).map(|e| e.path().to_string_lossy().into_owned()));
            }
        }
        files
    }

    fn decoding(&self) -> Result<diag::Decoding, Failure> {
        match &self.encoding {
            None => Ok(diag::Decoding::default()),
            Some(label) => diag::Decoding::by_label(label)
                .ok_or_else(|| usage(format!("--encoding {label}: unknown encoding (try gbk, gb18030, big5, shift_jis, latin1)"))),
        }
    }
}

/// Numbers separated by commas, as many as expected.
fn numbers(text: &str, what: &str, n: usize) -> Result<Vec<f64>, Failure> {
    let v: Result<Vec<f64>, _> = text.split(',').map(|p| p.trim().parse::<f64>()).collect();
    match v {
        Ok(v) if v.len() == n && v.iter().all(|x| x.is_finite()) => Ok(v),
        _ => Err(usage(format!("{what} {text}: expected {n} numbers separated by commas"))),
    }
}

/// A recorded point given as X (diameter), Z, C.
fn recorded(text: &str, what: &str) -> Result<ncsight::repair::Recorded, Failure> {
    let v = numbers(text, what, 3)?;
    Ok(ncsight::repair::Recorded { point: ncsight::Vec3::new(v[0] / 2.0, 0.0, v[1]), c_deg: v[2].rem_euclid(360.0) })
}

/// The operator's buttons and switches during `run`.
#[derive(clap::Args, Debug)]
struct OperatorArgs {
    /// Single-block mode: a `stop` record after each block (whole cycles, holes, thread runs).
    #[arg(long)]
    single_block: bool,
    /// Press FEED HOLD at this time (seconds from programme start); CYCLE START follows when the
    /// machine has stopped. May be given several times.
    #[arg(long, value_name = "SECONDS")]
    feed_hold_at: Vec<f64>,
    /// Press RESET at this time (seconds from programme start).
    #[arg(long, value_name = "SECONDS")]
    reset_at: Option<f64>,
    /// Dry run: feeds and threads at the dry-run rate.
    #[arg(long)]
    dry_run: bool,
    /// Feed override, percent (1-200); threads and tapping ignore it.
    #[arg(long, value_name = "PCT", default_value_t = 100.0)]
    feed_override: f64,
    /// Rapid override, percent (1-100).
    #[arg(long, value_name = "PCT", default_value_t = 100.0)]
    rapid_override: f64,
}

impl OperatorArgs {
    fn options(&self) -> Result<ncsight::Options, Failure> {
        let options = ncsight::Options {
            single_block: self.single_block,
            feed_hold_at: self.feed_hold_at.clone(),
            reset_at: self.reset_at,
            overrides: ncsight::time::Overrides { feed_pct: self.feed_override, rapid_pct: self.rapid_override, dry_run: self.dry_run },
        };
        ncsight_io::check_operator(&options, |key| format!("--{}", key.replace('_', "-"))).map_err(usage)?;
        Ok(options)
    }
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Interpret the programme as the controller would and print every motion.
    Run {
        /// Programme file, or - for standard input.
        file: String,
        #[command(flatten)]
        machine: MachineArgs,
        /// Output format: text, jsonl or canon.
        #[arg(long, default_value = "text")]
        format: String,
        /// Write the output to this file instead of standard output.
        #[arg(short = 'o', long = "output")]
        output: Option<String>,
        #[command(flatten)]
        operator: OperatorArgs,
    },
    /// Write the programme as it runs on the machine as plain moves for a controller that lacks
    /// its cycles: LinuxCNC (G0-G3, G4, G33 threads) or grbl (G0-G3, G4).
    Expand {
        /// Programme file, or - for standard input.
        file: String,
        #[command(flatten)]
        machine: MachineArgs,
        /// The controller the moves are written for: linuxcnc or grbl.
        #[arg(long = "to", value_name = "linuxcnc|grbl")]
        to: String,
        /// Write the programme to this file instead of standard output.
        #[arg(short = 'o', long = "output")]
        output: Option<String>,
    },
    /// Rewrite the programme for another controller, keeping its structure, and verify it by
    /// running both: exit 0 the motion is the same, 4 it differs (each difference listed), 1 the
    /// programme alarms on its own controller, 2 usage.
    Port {
        /// Programme file, or - for standard input.
        file: String,
        #[command(flatten)]
        machine: MachineArgs,
        /// The controller the programme is written for: gsk980tdi, gsk988t, fanuc0t,
        /// yasnac-lx3, fanuc0i-tf (lathes); fanuc0m, fanuc0i-mf (machining centres).
        #[arg(long = "to", value_name = "MACHINE")]
        to: String,
        /// The target machine's setup (axes, offsets, limits, tools), as --setup is the source's.
        /// Without it the target has none.
        #[arg(long = "to-setup", value_name = "S.toml")]
        to_setup: Option<String>,
        /// Write the programme to this file instead of standard output.
        #[arg(short = 'o', long = "output")]
        output: Option<String>,
        /// text (the report on standard error) or json (the report on standard output, the
        /// programme in it as "text" unless -o is given).
        #[arg(long, default_value = "text")]
        format: String,
    },
    /// Report every alarm and warning with file:line:column; run nothing.
    Check {
        /// Programme files, or - for standard input.
        #[arg(required = true)]
        files: Vec<String>,
        #[command(flatten)]
        machine: MachineArgs,
        /// full (the line underlined, the hint), short (one line each) or jsonl (one JSON
        /// object per diagnostic).
        #[arg(long, default_value = "full")]
        format: String,
    },
    /// Cut the stock with the programme and measure the thread it makes.
    Simulate {
        file: String,
        #[command(flatten)]
        machine: MachineArgs,
        /// Stock: on a lathe DIAxLEN in mm (a bar, its face at Z0), e.g. 60x80; on a machining centre XxYxZ (a block, its top at Z0, its corner at the work zero), e.g. 100x80x30.
        #[arg(long)]
        stock: Option<String>,
        /// The thread it should be: M30x3.5, M30, 1/2-13UNC, or major=..,minor=..,pitch=..
        #[arg(long)]
        expect: Option<String>,
        /// Output: text or json.
        #[arg(long, default_value = "text")]
        format: String,
        /// Write the unrolled surface (z across, angle down) as a PNG.
        #[arg(long)]
        image: Option<String>,
        /// Write the cut stock as a closed binary STL mesh (mm, programme coordinates).
        #[arg(long, value_name = "OUT.stl")]
        stl: Option<String>,
        /// Write the lathe part's axial section as a drawing: SVG or DXF by the name's ending.
        #[arg(long, value_name = "OUT.svg|OUT.dxf")]
        section: Option<String>,
        /// Grid spacing DZ,DTHETA (mm, degrees).
        #[arg(long)]
        resolution: Option<String>,
    },
    /// Write one self-contained HTML page that runs the programme in the browser and shows what it
    /// does (the `app` page, opening with this programme).
    Report {
        file: String,
        #[command(flatten)]
        machine: MachineArgs,
        #[command(flatten)]
        operator: OperatorArgs,
        /// Stock as DIAxLEN for the thread-form view.
        #[arg(long)]
        stock: Option<String>,
        /// The thread it should make (M24x2, or major=,minor=,pitch=, as `simulate` takes it):
        /// drawn over the measured section, and a deviation is a finding.
        #[arg(long)]
        expect: Option<String>,
        /// The HTML file to write (standard output if omitted).
        #[arg(short = 'o', long = "output")]
        output: Option<String>,
    },
    /// Write the page empty: open it from disk, choose the controller, paste or drop a programme.
    App {
        /// The HTML file to write (standard output if omitted).
        #[arg(short = 'o', long = "output")]
        output: Option<String>,
    },
    /// Thread repair (the GSK988T manual's MDI repair screen): the two blocks that re-cut a thread in the
    /// groove of a recorded point.
    Repair {
        #[command(flatten)]
        machine: MachineArgs,
        /// Start point of the thread: X (diameter),Z.
        #[arg(long, value_name = "X,Z", allow_hyphen_values = true)]
        start: String,
        /// End point of the thread: X (diameter),Z.
        #[arg(long, value_name = "X,Z", allow_hyphen_values = true)]
        end: String,
        /// Lead in mm (or give --tpi).
        #[arg(long, value_name = "F")]
        lead: Option<f64>,
        /// Threads per inch instead of --lead.
        #[arg(long, value_name = "N")]
        tpi: Option<f64>,
        /// Spindle speed; negative turns the spindle in its negative direction.
        #[arg(long, value_name = "S", allow_hyphen_values = true)]
        rpm: f64,
        /// The recorded point: X (diameter),Z,C (degrees).
        #[arg(long, value_name = "X,Z,C", allow_hyphen_values = true)]
        measured: String,
        /// Pull-out along the short axis (radius, signed).
        #[arg(long, allow_hyphen_values = true)]
        j: Option<f64>,
        /// Pull-out length along the long axis.
        #[arg(long)]
        k: Option<f64>,
    },
    /// List the controller profiles; with a name, its parameters.
    Machines { machine: Option<String> },
    /// What an alarm or warning means, its usual causes, how to fix it, a wrong and a right
    /// example: NCS-E53 or the controller's PS0063. In English, or in Chinese with --lang zh
    /// (or a locale starting with zh).
    Explain {
        /// The code, as check gives it.
        code: Option<String>,
        /// en or zh.
        #[arg(long)]
        lang: Option<String>,
        /// List every code with its title.
        #[arg(long)]
        list: bool,
    },
    /// A Language Server Protocol server on standard input and output, for editors: the
    /// diagnostics of check as you type, hover, definitions, the outline (docs/editors.md).
    /// The controller: the first line's (ncsight: MACHINE), else ncsight.toml beside the
    /// programmes, else the editor's setting ncsight.machine, else gsk980tdi.
    Lsp {
        /// Accepted for editors that pass it (the server always speaks on standard input and output).
        #[arg(long)]
        stdio: bool,
    },
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

/// A writer whose reader went away (`ncsight check big.nc | head -1`): the rest is dropped
/// silently and the run goes on, so that the exit status still says what was found.
struct Tolerant<W: Write> {
    inner: W,
    gone: bool,
}

impl<W: Write> Tolerant<W> {
    fn new(inner: W) -> Tolerant<W> {
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
const OUTPUT_BUFFER_BYTES: usize = 256 * 1024;

fn run(
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
fn expand(file: &str, m: &MachineArgs, to: &str, output: Option<&str>, out: &mut dyn Write, err: &mut dyn Write) -> Result<i32, Failure> {
    let target = format::expand::Target::by_name(to).ok_or_else(|| usage(format!("--to {to}: choose linuxcnc or grbl")))?;
    let head = Head::of(file)?;
    let (params, switches) = setup(m, head.named(shown(file)), err)?;
    let mut fmt = format::expand::Expand::new(params.profile(), target, shown(file));
    let program = Program::new(params, switches, Mode::Run);
    run_into(file, head, m, program, &mut fmt, output, out, err)
}

/// Exit status of a port whose motion differs on the target (docs/reference/interface.md).
const EXIT_PORT_DIFFERS: i32 = 4;

/// `ncsight port`: the programme in the target's words, verified by running both.
fn port(
    file: &str,
    m: &MachineArgs,
    (to, to_setup): (&str, Option<&str>),
    output: Option<&str>,
    format: &str,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    if format != "text" && format != "json" {
        return Err(usage(format!("--format {format}: choose text or json")));
    }
    let mut head = Head::of(file)?;
    let from_name = machine_for(m, head.named(shown(file)), true, err)?;
    let from = m.job(&from_name)?;
    // The target runs as the source is asked to (switches, variables, the main programme,
    // where called programmes are), on its own machine with its own setup.
    let mut target = ncsight_io::Job {
        switches: from.switches,
        vars: from.vars.clone(),
        main: from.main.clone(),
        call_args: from.call_args.clone(),
        subprogram_dirs: from.subprogram_dirs.clone(),
        skip_missing_subprograms: from.skip_missing_subprograms,
        max_blocks: from.max_blocks,
        ..ncsight_io::Job::on(to)
    };
    let to_profile = target.profile()?;
    if from.profile()?.is_lathe() != to_profile.is_lathe() {
        let kind = if from.profile()?.is_lathe() { "lathe" } else { "machining centre" };
        return Err(usage(format!("--to {to}: a {kind} programme ports to a {kind} only")));
    }
    if let Some(path) = to_setup {
        target.read_setup(path)?;
    }
    // Standard input was read for its first line already: the rest comes through the head.
    let source = match head.input(file)? {
        feed::Input::Stream(mut r) => {
            let mut v = Vec::new();
            r.read_to_end(&mut v)?;
            v
        }
        _ => read_whole(file)?,
    };
    let decoding = m.decoding()?;
    let text = editor_text(&source, &decoding);
    let result = match ncsight_io::port::port(&from, &target, text.as_bytes()) {
        Ok(p) => p,
        Err(ncsight_io::port::PortError::Usage(e)) => return Err(usage(e)),
        Err(ncsight_io::port::PortError::SourceAlarm(line, msg)) => {
            let _ = writeln!(err, "ncsight: {}:{line}: the programme alarms on {from_name}: {msg}; nothing is written", shown(file));
            return Ok(EXIT_ALARM);
        }
    };
    // The programme names its controller on its first line (`(ncsight: TO)`, port.rs).
    let programme = result.text.clone();
    let status = if result.exact() { EXIT_OK } else { EXIT_PORT_DIFFERS };
    let bytes = as_opened(&programme, &source, &decoding);
    match output {
        Some(path) => {
            if m.read_files(file).iter().any(|f| same_file::is_same_file(f, path).unwrap_or(false)) {
                return Err(usage(format!("-o {path}: that is the programme being read; choose another file")));
            }
            std::fs::write(path, &bytes).map_err(|e| usage(format!("cannot write {path}: {e}")))?;
        }
        None if format == "text" => out.write_all(&bytes)?,
        None => {}
    }
    if format == "json" {
        let diffs: Vec<String> = result
            .differences
            .iter()
            .map(|d| format!("{{\"line\":{},\"what\":{},\"size\":{}}}", d.line, ncsight_io::format::jsonl::json_str(&d.what), d.size))
            .collect();
        let rewrites: Vec<String> =
            result.rewritten.iter().map(|(l, why)| format!("{{\"line\":{l},\"why\":{}}}", ncsight_io::format::jsonl::json_str(why))).collect();
        let mut text_field = if output.is_none() { format!(",\"text\":{}", ncsight_io::format::jsonl::json_str(&programme)) } else { String::new() };
        let params: Vec<String> = result
            .parameters
            .iter()
            .map(|(k, v, m)| {
                format!("{{\"key\":{},\"value\":{v},\"meaning\":{}}}", ncsight_io::format::jsonl::json_str(k), ncsight_io::format::jsonl::json_str(m))
            })
            .collect();
        text_field.push_str(&format!(",\"parameters\":[{}]", params.join(",")));
        writeln!(
            out,
            "{{\"from\":{},\"to\":{},\"exact\":{},\"rewritten\":[{}],\"differences\":[{}]{text_field}}}",
            ncsight_io::format::jsonl::json_str(&from_name),
            ncsight_io::format::jsonl::json_str(to_profile.name),
            result.exact(),
            rewrites.join(","),
            diffs.join(",")
        )?;
    } else {
        for (l, why) in &result.rewritten {
            let _ = writeln!(err, "ncsight: line {l} written as its moves: {why}");
        }
        for d in &result.differences {
            let _ = writeln!(err, "ncsight: difference at line {}: {} ({})", d.line, d.what, d.size);
        }
        for (k, v, m) in &result.parameters {
            let _ = writeln!(err, "ncsight: {} parameter {k} = {v} as assumed (its power-on value): {m}", to_profile.name);
        }
        let _ = writeln!(err, "ncsight: {} -> {}: {}", from_name, to_profile.name, if result.exact() { "the same motion" } else { "approximate" });
    }
    Ok(status)
}

/// A text written the way `source` was: GBK (the encoding its lines that are not UTF-8 were read
/// in) when it was not UTF-8, as GSK controllers and Chinese editors save; CR LF line ends and a
/// byte-order mark where it had them.
fn as_opened(text: &str, source: &[u8], decoding: &diag::Decoding) -> Vec<u8> {
    let crlf = source.windows(2).any(|w| w == b"\r\n");
    let text = if crlf { text.replace("\r\n", "\n").replace('\n', "\r\n") } else { text.to_string() };
    let mut out = Vec::with_capacity(text.len() + 3);
    if source.starts_with(&[0xEF, 0xBB, 0xBF]) {
        out.extend_from_slice(&[0xEF, 0xBB, 0xBF]);
    }
    match std::str::from_utf8(source) {
        Ok(_) => out.extend_from_slice(text.as_bytes()),
        Err(_) => {
            let enc = encoding_rs::Encoding::for_label(decoding.label().as_bytes()).unwrap_or(encoding_rs::GB18030);
            out.extend_from_slice(&enc.encode(&text).0);
        }
    }
    out
}

/// A programme file (or standard input) read whole.
fn read_whole(file: &str) -> Result<Vec<u8>, Failure> {
    if file == "-" {
        let mut v = Vec::new();
        io::stdin().read_to_end(&mut v)?;
        return Ok(v);
    }
    std::fs::read(file).map_err(|e| usage(format!("cannot read {file}: {e}")))
}

/// Run `program` on `file` (its `head` read) and write its events through `fmt` to `output` (or
/// `out`); alarms, and diagnostics the format does not carry, go to `err`. A record the format
/// refuses ([`format::expand::Refused`]) is an alarm there, and the run stops.
#[allow(clippy::too_many_arguments)]
fn run_into(
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

fn check(files: &[String], m: &MachineArgs, format: &str, out: &mut dyn Write, err: &mut dyn Write) -> Result<i32, Failure> {
    // With --machine, every file on it; without, each file on the machine its first line
    // names, else gsk980tdi (said once).
    let given = m.machine.as_ref().map(|_| setup(m, None, err)).transpose()?;
    let mut default_said = false;
    let mut machines: Vec<(String, (Params, Switches))> = Vec::new();
    let decoding = m.decoding()?;
    let style = match format {
        "full" => Some(diag::Style::Full),
        "short" => Some(diag::Style::Short),
        "jsonl" => None,
        _ => return Err(usage(format!("unknown format '{format}': choose full, short or jsonl"))),
    };
    let mut any_alarm = false;
    let mut unreadable = false;
    let mut w = Tolerant::new(io::BufWriter::new(Tolerant::new(out)));
    for file in files {
        let shown = shown(file);
        // A file that cannot be read, or whose first line names no machine ncsight has, is
        // reported, and the others are still checked.
        let read = Head::of(file).and_then(|mut head| {
            let machine = machine_for(m, head.named(shown), !default_said, err)?;
            default_said |= head.named.is_none();
            Ok((machine, head.input(file)?))
        });
        let (machine, input) = match read {
            Ok(r) => r,
            Err(Failure::Usage(msg)) => {
                writeln!(err, "ncsight: {msg}")?;
                unreadable = true;
                continue;
            }
            Err(e) => return Err(e),
        };
        let (params, switches) = match &given {
            Some(p) => p.clone(),
            None => match machines.iter().find(|(n, _)| *n == machine) {
                Some((_, p)) => p.clone(),
                None => {
                    let p = setup_on(m, &machine)?;
                    machines.push((machine, p.clone()));
                    p
                }
            },
        };
        let mut program = Program::diagnostics_only(params.clone(), switches);
        let mut library = m.prepare(&mut program)?;
        let (mut alarms, mut warnings) = (0usize, 0usize);
        let result = drive(file, input, &mut library, &mut program, &mut |e, text, name| {
            if let Event::Diagnostic(d) = e {
                if d.is_alarm() {
                    alarms += 1
                } else {
                    warnings += 1
                }
                let shown = name.unwrap_or(shown);
                match style {
                    Some(style) => w.write_all(diag::render(shown, text, d, style, &decoding).as_bytes())?,
                    None => w.write_all(format::jsonl::diagnostic_line(shown, d).as_bytes())?,
                }
            }
            Ok(())
        });
        match result {
            Ok(()) => {}
            Err(Failure::Usage(msg)) => {
                writeln!(err, "ncsight: {msg}")?;
                unreadable = true;
            }
            Err(e) => return Err(e),
        }
        if style.is_some() {
            writeln!(w, "{shown}: {alarms} alarm(s), {warnings} warning(s) on {}", params.profile().name)?;
        }
        any_alarm |= alarms > 0;
    }
    w.flush()?;
    // An unreadable file outranks what the others held: the check is not complete.
    Ok(if unreadable {
        EXIT_USAGE
    } else if any_alarm {
        EXIT_ALARM
    } else {
        EXIT_OK
    })
}

/// Progress of long work on a terminal: after a second, "simulating: 37 %" on standard error,
/// rewritten in place a few times a second; nothing when standard error is not a terminal.
fn progress_on(err: &mut dyn Write) -> impl FnMut(usize, usize) + '_ {
    use std::io::IsTerminal;
    let terminal = io::stderr().is_terminal();
    let start = std::time::Instant::now();
    let mut last = start;
    move |done, total| {
        if !terminal || total == 0 {
            return;
        }
        let now = std::time::Instant::now();
        if now.duration_since(start).as_secs_f64() < 1.0 || now.duration_since(last).as_secs_f64() < 0.2 {
            if done == total && now.duration_since(start).as_secs_f64() >= 1.0 {
                let _ = write!(err, "\rsimulating: 100 %\n");
            }
            return;
        }
        last = now;
        let _ = write!(err, "\rsimulating: {} %", done * 100 / total);
        if done == total {
            let _ = writeln!(err);
        }
    }
}

/// What the machine setup gives and what the run assumes without it (docs/setup.md), as the
/// report says it.
fn setup_notes(setup: Option<(&str, &ncsight::stock::Setup)>, profile: &ncsight::Profile) -> Vec<String> {
    let x = if profile.diameter_x { 2.0 } else { 1.0 };
    let r = profile.reference_point_mm;
    let assumed_reference = if profile.is_lathe() { format!("X{} Z{}", r.x * x, r.z) } else { format!("X{} Y{} Z{}", r.x, r.y, r.z) };
    let Some((path, s)) = setup else {
        return vec![format!(
            "no machine setup (--setup): work and tool offsets 0, radius compensation with radius 0, no travel limits, the reference point assumed at {assumed_reference}, the tool at programme zero at power on"
        )];
    };
    let mut out = vec![format!("machine setup {path}")];
    let m = s.machine.as_ref();
    out.push(match m.and_then(|m| m.reference) {
        Some(_) => "reference point from the setup; the tool there at power on".into(),
        None => format!("no [machine.reference]: the reference point assumed at {assumed_reference}, the tool at programme zero at power on"),
    });
    out.push(match m.and_then(|m| m.limits) {
        Some(_) => "soft travel limits from the setup".into(),
        None => "no travel limits".into(),
    });
    let works: Vec<&str> = s
        .work
        .as_ref()
        .map(|w| ["external", "G54", "G55", "G56", "G57", "G58", "G59"].into_iter().zip(w.all()).filter(|(_, p)| p.is_some()).map(|(n, _)| n).collect())
        .unwrap_or_default();
    out.push(if works.is_empty() { "work offsets 0".into() } else { format!("work offsets {} from the setup, the others 0", works.join(", ")) });
    out.push(if s.offsets.is_empty() {
        "no offset table: tool offsets and radii 0".into()
    } else {
        format!("{} tool offset(s) from the setup, the others 0", s.offsets.len())
    });
    out
}

/// The job setup from `--setup` (as the run's job read and checked it) and `--stock`.
fn job_setup(m: &MachineArgs, profile: &ncsight::profile::Profile, stock: Option<&str>) -> Result<ncsight::stock::Setup, Failure> {
    let mut job = m.job(profile.name)?.setup.unwrap_or_default();
    if let Some(s) = stock {
        job.set_stock_text(s, profile.is_lathe()).map_err(|e| usage(e.to_string()))?;
    }
    Ok(job)
}

#[allow(clippy::too_many_arguments)]
fn report(
    file: &str,
    m: &MachineArgs,
    operator: &OperatorArgs,
    stock: Option<&str>,
    expect: Option<&str>,
    output: Option<&str>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    if let Some(why) = report::engine_missing() {
        return Err(usage(why));
    }
    let mut head = Head::of(file)?;
    let (params, switches) = setup(m, head.named(shown(file)), err)?;
    let decoding = m.decoding()?;
    let file_out = output.map(|path| output::LazyFile::new(path, &m.read_files(file), 1 << 16)).transpose().map_err(usage)?;
    let opts = operator.options()?;
    let job = job_setup(m, params.profile(), stock)?;
    let sim_options = simulate::options(None, expect).map_err(usage)?;
    let source = match head.input.take() {
        Some(feed::Input::Stream(mut r)) => {
            let mut v = Vec::new();
            r.read_to_end(&mut v)?;
            v
        }
        Some(feed::Input::Memory(text)) => text.to_vec(),
        Some(feed::Input::File(_)) | None => std::fs::read(file).map_err(|e| usage(format!("cannot read {file}: {e}")))?,
    };
    let mut settings = vec![format!("profile {} ({})", params.profile().name, params.profile().title)];
    settings.extend(setup_notes(m.setup.as_deref().map(|p| (p, &job)), params.profile()));
    if m.repair_position.is_some() {
        settings.push("--repair-position is not passed to the page: its runs have no recorded repair position".into());
    }
    settings.push("assumptions: docs/guide.md and docs/commands/*.md".into());
    // The run here gives the exit status and, on a lathe that cuts a thread, the records the
    // stock simulation measures; the page runs the programme again itself.
    let mut program = Program::with_operator(params.clone(), switches, Mode::Run, opts.clone());
    let mut library = m.prepare(&mut program)?;
    let lathe = params.profile().is_lathe();
    let text = std::sync::Arc::new(source.clone());
    let mut survey = ncsight::stock::survey::LatheSurvey::new(&job);
    let mut threads = false;
    drive(file, feed::Input::Memory(text.clone()), &mut library, &mut program, &mut |e, _, _| {
        if let (Event::Record(r), true) = (e, lathe) {
            threads |= r.op.is_thread();
            survey.add(r);
        }
        Ok(())
    })?;
    // The thread section: simulated when the programme cuts a thread on a lathe (a second run,
    // cut record by record); when it cannot be, the page says why (never "cuts no thread" for a
    // thread it could not simulate).
    let (sim, sim_error) = if threads {
        match ncsight::stock::measure::LatheCut::new(&survey, &job, &sim_options) {
            Ok(mut cut) => {
                let mut again = Program::with_operator(params.clone(), switches, Mode::Run, opts.clone());
                let mut library = m.prepare(&mut again)?;
                drive(file, feed::Input::Memory(text), &mut library, &mut again, &mut |e, _, _| {
                    if let Event::Record(r) = e {
                        cut.add(r);
                    }
                    Ok(())
                })?;
                (Some(cut.finish(&sim_options)), None)
            }
            Err(e) => (None, Some(e)),
        }
    } else {
        (None, None)
    };
    let extra = page_settings(m);
    let page = report::Preload {
        file_name: if file == "-" { "<stdin>" } else { file },
        text: editor_text(&source, &decoding),
        original: &source,
        encoding: decoding.label(),
        machine: params.profile().name,
        params: &m.params,
        setup: m.setup_text()?.map(str::to_string),
        options: &opts,
        switches,
        extra_options: extra,
        stock: job.stock,
        expect: sim_options.expect.as_ref(),
        library: library_texts(&m.subprogram_dirs, &decoding),
        settings,
        sim: sim.as_ref(),
        sim_error: sim_error.as_deref(),
    };
    match file_out {
        Some(mut w) => {
            report::write(Some(&page), &mut w)?;
            w.flush()?;
        }
        None => report::write(Some(&page), out)?,
    }
    Ok(status_with_findings(program.status() == Status::Alarm, sim.as_ref().map(|s| &s.measurement.findings[..]).unwrap_or(&[])))
}

/// What the report's command line gave besides the machine, as the page's operator settings
/// pass it on (`main=`, `var=`, `call_args=`, `skip_missing_subprograms=`, `max_blocks=`).
fn page_settings(m: &MachineArgs) -> Vec<String> {
    let mut extra = Vec::new();
    extra.extend(m.main.iter().map(|v| format!("main={v}")));
    extra.extend(m.vars.iter().map(|v| format!("var={v}")));
    extra.extend(m.call_args.iter().map(|v| format!("call_args={v}")));
    if m.skip_missing_subprograms {
        extra.push("skip_missing_subprograms=1".into());
    }
    extra.extend(m.max_blocks.iter().map(|v| format!("max_blocks={v}")));
    extra
}

/// The files of the `--subprogram-dir` directories, for the page to look for called
/// programmes in (each by its file name, as the editor would show it). Files over 8 MB are left
/// out (not programme files; the page says so if one is called).
fn library_texts(dirs: &[std::path::PathBuf], decoding: &diag::Decoding) -> Vec<(String, String)> {
    feed::library_files(dirs).into_iter().map(|(name, bytes)| (name, editor_text(&bytes, decoding))).collect()
}

/// A programme file as the page's editor shows it: without a byte-order mark, each line as
/// written, UTF-8, or decoded where it is not (`--encoding`; GB18030 by default), CR LF as LF.
fn editor_text(bytes: &[u8], decoding: &diag::Decoding) -> String {
    let body = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(bytes);
    let lines: Vec<String> = body.split(|&b| b == b'\n').map(|l| decoding.decode(l.strip_suffix(b"\r").unwrap_or(l))).collect();
    lines.join("\n")
}

/// `ncsight app`: the page with no programme in it.
fn app(output: Option<&str>, out: &mut dyn Write) -> Result<i32, Failure> {
    if let Some(why) = report::engine_missing() {
        return Err(usage(why));
    }
    match output {
        Some(path) => {
            let mut w = output::LazyFile::new::<&str>(path, &[], 1 << 16).map_err(usage)?;
            report::write(None, &mut w)?;
            w.flush()?;
        }
        None => report::write(None, out)?,
    }
    Ok(0)
}

#[allow(clippy::too_many_arguments)]
fn simulate(
    file: &str,
    m: &MachineArgs,
    stock: Option<&str>,
    expect: Option<&str>,
    format: &str,
    outputs: SimOutputs,
    resolution: Option<&str>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    let image = outputs.image;
    if format != "text" && format != "json" {
        return Err(usage(format!("unknown format '{format}': choose text or json")));
    }
    let mut head = Head::of(file)?;
    let (params, switches) = setup(m, head.named(shown(file)), err)?;
    let decoding = m.decoding()?;
    let mut job = job_setup(m, params.profile(), stock)?;
    let reads = m.read_files(file);
    let image_out = image.map(|path| output::LazyFile::new(path, &reads, 1 << 16)).transpose().map_err(usage)?;
    let stl_out = outputs.stl.map(|path| output::LazyFile::new(path, &reads, 1 << 16)).transpose().map_err(usage)?;
    let dxf = match outputs.section {
        Some(p) if p.to_ascii_lowercase().ends_with(".dxf") => true,
        Some(p) if p.to_ascii_lowercase().ends_with(".svg") => false,
        Some(p) => return Err(usage(format!("--section {p}: name the drawing OUT.svg or OUT.dxf"))),
        None => false,
    };
    if outputs.section.is_some() && !params.profile().is_lathe() {
        return Err(usage(format!(
            "--section draws a turned part's axial section; {} is a machining centre (--stl writes its cut block)",
            params.profile().name
        )));
    }
    let section_out = outputs.section.map(|path| output::LazyFile::new(path, &reads, 1 << 16)).transpose().map_err(usage)?;
    if image_out.is_some() && !params.profile().is_lathe() {
        return Err(usage(format!(
            "--image draws the unrolled surface of a thread on a lathe; {} is a machining centre: the drilling simulation has no image (its holes are in the text or JSON output)",
            params.profile().name
        )));
    }
    let opts = simulate::options(resolution, expect).map_err(usage)?;
    let lathe = params.profile().is_lathe();
    // Two runs of the programme: a survey (the tools to assume, the stock to guess, the grid),
    // then the cut, each record as it comes; nothing holds the programme's records, so a
    // programme of any length is simulated. Standard input or a pipe is read once, into a
    // temporary file both runs read.
    let source = Spooled::of(file, head.input.take())?;
    let shown = if file == "-" { "<stdin>" } else { file };
    let mut lathe_survey = ncsight::stock::survey::LatheSurvey::new(&job);
    let mut mill_survey = ncsight::stock::survey::MillSurvey::default();
    // A school simulator's `[BILLET` line gives the stock where neither --stock nor the setup does.
    let mut billet_free = if lathe { job.stock.is_none() } else { job.block.is_none() };
    let alarmed = {
        let mut program = Program::new(params.clone(), switches, Mode::Run);
        let mut library = m.prepare(&mut program)?;
        drive(file, source.input()?, &mut library, &mut program, &mut |e, text, name| {
            match e {
                Event::Diagnostic(d) if d.rule == ncsight::Rule::SimulatorStock && billet_free => {
                    let given = ncsight::read::simulator::billet(text).and_then(|b| b.stock_text(lathe));
                    if let Some(stock) = given.filter(|s| job.set_stock_text(s, lathe).is_ok()) {
                        billet_free = false;
                        writeln!(err, "{}: stock {stock} mm from its [BILLET line", name.unwrap_or(shown))?;
                        lathe_survey.stock_given(&job);
                    }
                }
                Event::Record(r) if lathe => lathe_survey.add(r),
                Event::Record(r) => mill_survey.add(r),
                Event::Diagnostic(d) if d.is_alarm() => err.write_all(diag::render(name.unwrap_or(shown), text, d, diag::Style::Full, &decoding).as_bytes())?,
                Event::Diagnostic(_) => {}
            }
            Ok(())
        })?;
        program.status() == Status::Alarm
    };
    let mut program = Program::new(params, switches, Mode::Run);
    let mut library = m.prepare(&mut program)?;
    if !lathe {
        let mut cut = match ncsight::stock::measure::MillCut::new(&mill_survey, &job, opts.dz_mm, None) {
            Ok(cut) => cut,
            Err(e) => return not_simulated(alarmed || !mill_survey.cuts(), alarmed, e, err),
        };
        cut_beside(file, source.input()?, &mut library, &mut program, &mut |r| cut.add(r))?;
        let sim = cut.finish();
        let body = if format == "json" { simulate::mill_json(&sim) } else { simulate::mill_text(&sim) };
        out.write_all(body.as_bytes())?;
        if let Some(mut w) = stl_out {
            simulate::stl(&mut w, &|each| ncsight::stock::mesh::mill(&sim.stock, each))?;
            w.flush()?;
        }
        return Ok(status_with_findings(alarmed, &sim.findings));
    }
    let mut cut = match ncsight::stock::measure::LatheCut::new(&lathe_survey, &job, &opts) {
        Ok(cut) => cut,
        Err(e) => return not_simulated(alarmed || lathe_survey.guessed_bar(false).is_none(), alarmed, e, err),
    };
    let (total, mut done) = (lathe_survey.records, 0usize);
    let mut progress = progress_on(err);
    drive(file, source.input()?, &mut library, &mut program, &mut |e, _, _| {
        if let Event::Record(r) = e {
            cut.add(r);
            done += 1;
            progress(done, total);
        }
        Ok(())
    })?;
    let sim = cut.finish(&opts);
    let body = if format == "json" { simulate::json(&sim.measurement) } else { simulate::text(&sim.measurement) };
    out.write_all(body.as_bytes())?;
    if let Some(mut w) = image_out {
        simulate::image(&sim, &mut w)?;
        w.flush()?;
    }
    if let Some(mut w) = stl_out {
        simulate::stl(&mut w, &|each| ncsight::stock::mesh::lathe(&sim.stock, each))?;
        w.flush()?;
    }
    if let Some(mut w) = section_out {
        if dxf {
            simulate::section_dxf(&mut w, &sim.stock)?
        } else {
            simulate::section_svg(&mut w, &sim.stock)?
        }
        w.flush()?;
    }
    Ok(status_with_findings(alarmed, &sim.measurement.findings))
}

/// The stock could not be set up (no stock given and nothing cut to guess it from, a grid too
/// large): a usage mistake, unless there is nothing to simulate: the programme stopped on an
/// alarm, or ran and cut nothing. Then it says so and the exit status is the run's (the alarm
/// is already shown).
fn not_simulated(nothing_to_cut: bool, alarmed: bool, why: String, err: &mut dyn Write) -> Result<i32, Failure> {
    if !nothing_to_cut {
        return Err(usage(why));
    }
    writeln!(err, "ncsight: the stock was not simulated: {why}")?;
    Ok(if alarmed { EXIT_ALARM } else { 0 })
}

/// Records a batch takes from the interpreter to the cut beside it.
const CUT_BATCH: usize = 512;

/// Run the programme and hand its records to `cut` on a thread of its own, in batches, so the
/// interpreter and the cut work at once (a machining centre's cut is one thread's work).
fn cut_beside(
    file: &str,
    input: feed::Input,
    library: &mut feed::Library,
    program: &mut Program,
    cut: &mut (dyn FnMut(&ncsight::Record) + Send),
) -> Result<(), Failure> {
    let (to_cut, batches) = std::sync::mpsc::sync_channel::<Vec<ncsight::Record>>(8);
    std::thread::scope(|scope| {
        // The cut runs on the parallel pool's threads, where a move splits its rows between the
        // two at little cost (from a thread outside the pool each split waits for a wake-up).
        let cutter = scope.spawn(move || {
            let pool = rayon::ThreadPoolBuilder::new().build();
            let work = || {
                for batch in batches {
                    batch.iter().for_each(&mut *cut);
                }
            };
            match pool {
                Ok(pool) => pool.install(work),
                Err(_) => work(),
            }
        });
        let mut batch = Vec::with_capacity(CUT_BATCH);
        let ran = drive(file, input, library, program, &mut |e, _, _| {
            if let Event::Record(r) = e {
                batch.push(r.clone());
                if batch.len() == CUT_BATCH {
                    // The cut ends only when this sender is dropped: a send cannot fail first.
                    let _ = to_cut.send(std::mem::replace(&mut batch, Vec::with_capacity(CUT_BATCH)));
                }
            }
            Ok(())
        });
        if !batch.is_empty() {
            let _ = to_cut.send(batch);
        }
        drop(to_cut);
        if cutter.join().is_err() {
            return Err(Failure::Io(io::Error::other("the stock simulation's thread failed")));
        }
        ran
    })
}

/// A programme `simulate` reads twice: a file, read again; standard input or a pipe, copied once
/// into a temporary file that goes when this does.
struct Spooled {
    path: std::path::PathBuf,
    temporary: bool,
}

impl Spooled {
    /// `file`, or its `input` already opened (standard input or a pipe, its first line read).
    fn of(file: &str, input: Option<feed::Input>) -> Result<Spooled, Failure> {
        if file != "-" {
            let regular = std::fs::metadata(file).map(|m| m.is_file()).map_err(|e| usage(format!("cannot read {file}: {e}")))?;
            if regular {
                return Ok(Spooled { path: file.into(), temporary: false });
            }
        }
        static NEXT: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);
        let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let path = std::env::temp_dir().join(format!("ncsight-simulate-{}-{n}.nc", std::process::id()));
        let spooled = Spooled { path, temporary: true };
        let mut to =
            std::fs::File::create(&spooled.path).map_err(|e| usage(format!("cannot write a temporary copy of {file} at {}: {e}", spooled.path.display())))?;
        let input = match input {
            Some(input) => input,
            None => open(file)?,
        };
        let copied = match input {
            feed::Input::Stream(mut r) => io::copy(&mut r, &mut to),
            feed::Input::File(p) => std::fs::File::open(p).and_then(|mut f| io::copy(&mut f, &mut to)),
            feed::Input::Memory(t) => to.write_all(&t).map(|_| t.len() as u64),
        };
        copied.map_err(|e| usage(format!("cannot read {file}: {e}")))?;
        Ok(spooled)
    }

    fn input(&self) -> Result<feed::Input, Failure> {
        Ok(feed::Input::File(self.path.clone()))
    }
}

impl Drop for Spooled {
    fn drop(&mut self) {
        if self.temporary {
            let _ = std::fs::remove_file(&self.path);
        }
    }
}

/// The files `simulate` writes besides its report.
struct SimOutputs<'a> {
    image: Option<&'a str>,
    stl: Option<&'a str>,
    section: Option<&'a str>,
}

#[allow(clippy::too_many_arguments)]
fn repair(
    m: &MachineArgs,
    start: &str,
    end: &str,
    lead: Option<f64>,
    tpi: Option<f64>,
    rpm: f64,
    measured: &str,
    j: Option<f64>,
    k: Option<f64>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    let (params, _) = setup(m, None, err)?;
    let profile = params.profile();
    let Some(enable) =
        profile.thread.repair_enable.filter(|_| profile.g_code(32, Some(1)).is_some_and(|g| matches!(g.function, ncsight::profile::GFn::Thread(_))))
    else {
        let how = if profile.thread.repair_enable.is_some() { "repairs with G92 P1 / G92.1 P1 and `run --repair-position`" } else { "has no thread repair" };
        return Err(usage(format!("the thread-repair screen that writes G32.1 is a GSK988T function (GSK988T manual); {} {how}", profile.name)));
    };
    let s = numbers(start, "--start", 2)?;
    let e = numbers(end, "--end", 2)?;
    let lead_mm = match (lead, tpi) {
        (Some(f), None) if f > 0.0 && f <= 500.0 => f,
        (None, Some(n)) if (0.06..=25400.0).contains(&n) => 25.4 / n,
        _ => return Err(usage("give the lead as --lead F (0-500 mm) or --tpi N (0.06-25400)")),
    };
    if rpm == 0.0 || !rpm.is_finite() {
        return Err(usage("--rpm: a spindle speed other than 0 (negative: the negative direction)"));
    }
    let alarm = |err: &mut dyn Write, rule: ncsight::Rule, msg: String| -> Result<i32, Failure> {
        writeln!(err, "ncsight: alarm[{}]: {msg}", rule.code(profile.alarm_style))?;
        Ok(EXIT_ALARM)
    };
    let recorded = recorded(measured, "--measured")?;
    if params.get(enable) == 0.0 {
        return alarm(
            err,
            ncsight::Rule::RepairDisabled,
            format!("thread repair is not enabled: parameter {enable} (RPTH) is 0 (GSK988T manual, thread repair 1.4); give --param {enable}=1"),
        );
    }
    let job = ncsight::repair::RepairJob {
        start: ncsight::Vec3::new(s[0] / 2.0, 0.0, s[1]),
        end: ncsight::Vec3::new(e[0] / 2.0, 0.0, e[1]),
        lead_mm,
        rpm,
        j_mm: j,
        k_mm: k,
        recorded,
    };
    match job.programme() {
        Ok(text) => {
            out.write_all(text.as_bytes())?;
            Ok(EXIT_OK)
        }
        // A number the control would not take is the caller's mistake: a usage error.
        Err(ncsight::repair::RepairError::BadInput(why)) => Err(usage(format!("{why}; no programme is written"))),
        Err(e) => alarm(err, ncsight::Rule::RepairOutside, format!("{e}; no programme is written")),
    }
}

/// One code of `machines NAME`: the code, its status, what it does, where that comes from.
fn code_line(out: &mut dyn Write, code: &str, status: ncsight::profile::CodeStatus, meaning: &str, source: &str) -> std::io::Result<()> {
    use ncsight::profile::CodeStatus;
    let (state, why) = match status {
        CodeStatus::Simulated => ("simulated", String::new()),
        CodeStatus::Assumed(a) => ("assumed", format!(" ({a})")),
        CodeStatus::NotYet => ("not yet", String::new()),
    };
    writeln!(out, "  {code:<7} {state:<10} {meaning}{why} [{source}]")
}

/// `ncsight explain CODE [--lang en|zh]`, `ncsight explain --list`.
fn explain(code: Option<&str>, lang: Option<&str>, list: bool, out: &mut dyn Write) -> Result<i32, Failure> {
    use ncsight::explain::Lang;
    let lang = match lang {
        Some(l) if l.eq_ignore_ascii_case("zh") || l.to_ascii_lowercase().starts_with("zh") => Lang::Zh,
        Some(l) if l.eq_ignore_ascii_case("en") => Lang::En,
        Some(l) => return Err(usage(format!("--lang {l}: choose en or zh"))),
        None => {
            // The locale, as a terminal gives it.
            let zh = ["LC_ALL", "LC_MESSAGES", "LANG"]
                .iter()
                .find_map(|k| std::env::var(k).ok().filter(|v| !v.is_empty()))
                .is_some_and(|v| v.to_ascii_lowercase().starts_with("zh"));
            if zh {
                Lang::Zh
            } else {
                Lang::En
            }
        }
    };
    if list {
        for r in ncsight::Rule::ALL {
            writeln!(out, "{:<8} {:<7} {}", r.project_code(), r.fanuc_code().unwrap_or("-"), r.title())?;
        }
        return Ok(EXIT_OK);
    }
    let Some(code) = code else {
        return Err(usage("ncsight explain CODE (NCS-E53, PS0063), or --list"));
    };
    match ncsight::explain::explain(code) {
        Some((rule, e)) => {
            out.write_all(ncsight::explain::render(rule, &e, lang).as_bytes())?;
            Ok(EXIT_OK)
        }
        None => Err(usage(format!("{code}: no such code (ncsight explain --list lists them)"))),
    }
}

fn machines(name: Option<&str>, out: &mut dyn Write) -> Result<i32, Failure> {
    match name {
        None => {
            for p in profile::all() {
                writeln!(out, "{:<12} {}", p.name, p.title)?;
            }
        }
        Some(n) => {
            let p = profile::by_name(n).ok_or_else(|| usage(format!("unknown machine '{n}': choose one of {}", names())))?;
            writeln!(out, "{} - {}\n", p.name, p.title)?;
            writeln!(out, "{}\n", p.summary)?;
            // The key column as wide as the longest key (setting names are long).
            let w = p.all_params().map(|d| d.key.to_string().len()).max().unwrap_or(0).max(9);
            writeln!(out, "{:<w$} {:>10} {:<11} {:<16} meaning [source]", "parameter", "default", "unit", "range")?;
            for d in p.all_params() {
                writeln!(
                    out,
                    "{:<w$} {:>10} {:<11} {:<16} {} [{}]",
                    d.key.to_string(),
                    format::num(d.default, 4),
                    d.unit,
                    format!("{}..{}", format::num(d.min, 4), format::num(d.max, 4)),
                    d.meaning,
                    d.source
                )?;
            }
            writeln!(
                out,
                "\nG codes (status: simulated; assumed = runs with a warning that names the assumption; not yet = alarm NCS-E38, not simulated yet):"
            )?;
            for t in p.g_codes {
                for g in t.codes {
                    code_line(out, g.name, p.code_status(g), g.meaning, t.source)?;
                }
            }
            writeln!(out, "\nM codes:")?;
            for t in p.m_codes {
                for mc in t.codes {
                    code_line(out, &format!("M{:02}", mc.code), mc.function.status(), mc.meaning, t.source)?;
                }
            }
        }
    }
    Ok(EXIT_OK)
}
