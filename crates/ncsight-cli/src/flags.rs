//! The command line's arguments (clap): the commands, the machine and operator options.

use crate::*;

#[derive(Parser, Debug)]
#[command(name = "ncsight", version, about = "See what a CNC programme will do on a GSK, FANUC or YASNAC controller before the machine does it")]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(clap::Args, Debug)]
pub(crate) struct MachineArgs {
    /// Controller profile: gsk980tdi, gsk988t, fanuc0m, fanuc0t, yasnac-lx3, fanuc0i-tf, fanuc0i-mf (default: the one a first line `(ncsight: NAME)` of the programme names, else gsk980tdi).
    #[arg(long, short = 'm')]
    pub(crate) machine: Option<String>,
    /// Override a parameter by the manual's number: N=V or N.B=V for a bit (e.g. 19=10, 18.6=1).
    #[arg(long = "param", value_name = "N=V")]
    pub(crate) params: Vec<String>,
    /// Block delete switch on: blocks starting with '/' are skipped.
    #[arg(long)]
    pub(crate) block_delete: bool,
    /// Optional stop switch on: M01 stops.
    #[arg(long)]
    pub(crate) optional_stop: bool,
    /// The thread repair position recorded on the machine: X (diameter), Z and the spindle's C
    /// angle in degrees, for G92 P1 / G92.1 P1 (GSK980TDi).
    #[arg(long, value_name = "X,Z,C", allow_hyphen_values = true)]
    pub(crate) repair_position: Option<String>,
    /// How lines that are not UTF-8 are shown (default: GB18030/GBK, as GSK controls and Chinese
    /// editors save them, else Windows-1252): gbk, gb18030, big5, shift_jis, latin1, ...
    #[arg(long, value_name = "NAME")]
    pub(crate) encoding: Option<String>,
    /// The main programme, when it is not the first programme in the file (O1234 or 1234).
    #[arg(long, value_name = "O1234")]
    pub(crate) main: Option<String>,
    /// A directory where a called programme the file lacks is looked for (repeatable): a file
    /// named after its number (O1234, o1234.nc, ...), else a file that holds it.
    #[arg(long = "subprogram-dir", value_name = "DIR")]
    pub(crate) subprogram_dirs: Vec<std::path::PathBuf>,
    /// A called programme that no file holds is skipped with a warning (builder macros live
    /// in the machine), instead of the controller's alarm.
    #[arg(long)]
    pub(crate) skip_missing_subprograms: bool,
    /// The runaway guard: blocks executed again after jumps back (subprogramme repeats), at
    /// most, before the run stops with NCS-E63.
    #[arg(long, value_name = "N")]
    pub(crate) max_blocks: Option<u64>,
    /// A common macro variable as set at the machine before the run, or an input signal of the
    /// machine (#1000-#1015, #1032) (repeatable): 500=1.5, 1002=1.
    #[arg(long = "var", value_name = "N=V", allow_hyphen_values = true)]
    pub(crate) vars: Vec<String>,
    /// Run the programme as a macro called with these arguments, as a G65 block writes them
    /// after P: "A1. B2. I3." (#1, #2, #4 of the programme's own level).
    #[arg(long = "call-args", value_name = "ARGS", allow_hyphen_values = true)]
    pub(crate) call_args: Option<String>,
    /// The machine setup (TOML): axes, travel limits, reference points, work offsets (G54-G59),
    /// the tool and offset tables, the stock (docs/setup.md).
    #[arg(long, value_name = "FILE.toml")]
    pub(crate) setup: Option<String>,
    /// The setup file's text, read once (a named pipe gives its data once).
    #[arg(skip)]
    pub(crate) setup_text: std::sync::OnceLock<Result<String, String>>,
}

impl MachineArgs {
    /// The run these arguments describe (the machine resolved by [`setup`]).
    pub(crate) fn job(&self, machine: &str) -> Result<ncsight_io::Job, Failure> {
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
    pub(crate) fn setup_text(&self) -> Result<Option<&str>, Failure> {
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
    pub(crate) fn prepare(&self, program: &mut Program) -> Result<feed::Library, Failure> {
        let machine = program.profile().name;
        Ok(self.job(machine)?.prepare(program)?)
    }

    /// Every file a run of `file` with these arguments may read: the programme, the setup, and
    /// each file of the subprogramme folders. No output may be one of them.
    pub(crate) fn read_files(&self, file: &str) -> Vec<String> {
        let mut files = vec![file.to_string()];
        files.extend(self.setup.iter().cloned());
        for d in &self.subprogram_dirs {
            if let Ok(entries) = std::fs::read_dir(d) {
                files.extend(entries.filter_map(|e| e.ok()).map(|e| e.path().to_string_lossy().into_owned()));
            }
        }
        files
    }

    pub(crate) fn decoding(&self) -> Result<diag::Decoding, Failure> {
        match &self.encoding {
            None => Ok(diag::Decoding::default()),
            Some(label) => diag::Decoding::by_label(label)
                .ok_or_else(|| usage(format!("--encoding {label}: unknown encoding (try gbk, gb18030, big5, shift_jis, latin1)"))),
        }
    }
}

/// Numbers separated by commas, as many as expected.
pub(crate) fn numbers(text: &str, what: &str, n: usize) -> Result<Vec<f64>, Failure> {
    let v: Result<Vec<f64>, _> = text.split(',').map(|p| p.trim().parse::<f64>()).collect();
    match v {
        Ok(v) if v.len() == n && v.iter().all(|x| x.is_finite()) => Ok(v),
        _ => Err(usage(format!("{what} {text}: expected {n} numbers separated by commas"))),
    }
}

/// A recorded point given as X (diameter), Z, C.
pub(crate) fn recorded(text: &str, what: &str) -> Result<ncsight::repair::Recorded, Failure> {
    let v = numbers(text, what, 3)?;
    Ok(ncsight::repair::Recorded { point: ncsight::Vec3::new(v[0] / 2.0, 0.0, v[1]), c_deg: v[2].rem_euclid(360.0) })
}

/// The operator's buttons and switches during `run`.
#[derive(clap::Args, Debug)]
pub(crate) struct OperatorArgs {
    /// Single-block mode: a `stop` record after each block (whole cycles, holes, thread runs).
    #[arg(long)]
    pub(crate) single_block: bool,
    /// Press FEED HOLD at this time (seconds from programme start); CYCLE START follows when the
    /// machine has stopped. May be given several times.
    #[arg(long, value_name = "SECONDS")]
    pub(crate) feed_hold_at: Vec<f64>,
    /// Press RESET at this time (seconds from programme start).
    #[arg(long, value_name = "SECONDS")]
    pub(crate) reset_at: Option<f64>,
    /// Dry run: feeds and threads at the dry-run rate.
    #[arg(long)]
    pub(crate) dry_run: bool,
    /// Feed override, percent (1-200); threads and tapping ignore it.
    #[arg(long, value_name = "PCT", default_value_t = 100.0)]
    pub(crate) feed_override: f64,
    /// Rapid override, percent (1-100).
    #[arg(long, value_name = "PCT", default_value_t = 100.0)]
    pub(crate) rapid_override: f64,
}

impl OperatorArgs {
    pub(crate) fn options(&self) -> Result<ncsight::Options, Failure> {
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
pub(crate) enum Command {
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
