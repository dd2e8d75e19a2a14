//! A run as its caller describes it (the command line's options, the Python package's
//! arguments): the controller, parameter overrides, switches, where called programmes are, the
//! variables set at the machine. One place turns that into a [`Program`], so every front end
//! refuses the same mistakes with the same words.

use crate::feed::{self, FileName, Input, Library};
use crate::format::{self, Format};
use ncsight::machine::Options;
use ncsight::profile::{self, Params, Profile};
use ncsight::{CallOptions, Event, Mode, Program, Status, Switches};
use std::io;
use std::path::PathBuf;

/// What a run needs besides its text.
#[derive(Debug, Clone, Default)]
pub struct Job {
    /// The profile's name (`gsk980tdi`, `fanuc0m`, ...).
    pub machine: String,
    /// Parameter overrides as the manual numbers them: `N=V`, or `N.B=V` for a bit.
    pub params: Vec<String>,
    pub switches: Switches,
    /// The operator's actions (single block, feed hold, overrides); a run only.
    pub operator: Options,
    /// The main programme when it is not the first in the text (`O1234` or `1234`).
    pub main: Option<String>,
    /// Where a called programme the text lacks is looked for.
    pub subprogram_dirs: Vec<PathBuf>,
    /// A called programme nobody holds is a warning, not the controller's alarm.
    pub skip_missing_subprograms: bool,
    /// The runaway guard's limit (blocks executed again after jumps back).
    pub max_blocks: Option<u64>,
    /// Variables set at the machine before the run: `N=V` (#100-#199, #500-#999, the input
    /// signals #1000-#1015 and #1032).
    pub vars: Vec<String>,
    /// The programme run as a macro called with these arguments (`A1. B2.`, as after G65 P_).
    pub call_args: Option<String>,
    /// The machine setup (`--setup FILE.toml`): offsets, reference points, limits, tools.
    pub setup: Option<ncsight::setup::Setup>,
    /// The folder of the setup file, which its relative paths start from.
    pub setup_dir: Option<PathBuf>,
}

/// Why a job cannot run: a mistake in how it was asked for (unknown machine, bad parameter,
/// unreadable file), or an error writing its output.
#[derive(Debug)]
pub enum JobError {
    Usage(String),
    Io(io::Error),
}

impl std::fmt::Display for JobError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            JobError::Usage(m) => f.write_str(m),
            JobError::Io(e) => write!(f, "{e}"),
        }
    }
}

impl From<io::Error> for JobError {
    fn from(e: io::Error) -> JobError {
        JobError::Io(e)
    }
}

fn usage(m: impl Into<String>) -> JobError {
    JobError::Usage(m.into())
}

/// Whether the operator's settings are ones a panel can give: overrides of 1-200 % (feed) and
/// 1-100 % (rapid), button times of 0 s or more. `name` gives the caller's name of a setting
/// (`feed_override`, `rapid_override`) for the message: `--feed-override` on the command line.
pub fn check_operator(o: &Options, name: fn(&str) -> String) -> Result<(), String> {
    let f = o.overrides.feed_pct;
    if !(f > 0.0 && f <= 200.0) {
        return Err(format!("{} {f}: give 1 to 200 percent", name("feed_override")));
    }
    let r = o.overrides.rapid_pct;
    if !(r > 0.0 && r <= 100.0) {
        return Err(format!("{} {r}: give 1 to 100 percent", name("rapid_override")));
    }
    for t in o.feed_hold_at.iter().chain(o.reset_at.iter()) {
        if !(t.is_finite() && *t >= 0.0) {
            return Err(format!("{t}: a button time is a number of seconds, 0 or more"));
        }
    }
    Ok(())
}

/// The profile whose name is nearest `name` (a letter or two off, or one begins the other:
/// `gsk980td`, `fanuc0i-t`), if one is near enough.
pub fn nearest_machine(name: &str) -> Option<String> {
    let name = name.to_ascii_lowercase();
    let distance = |a: &str, b: &str| {
        // Levenshtein distance, one row at a time.
        let b: Vec<char> = b.chars().collect();
        let mut row: Vec<usize> = (0..=b.len()).collect();
        for (i, ca) in a.chars().enumerate() {
            let mut prev = row[0];
            row[0] = i + 1;
            for j in 0..b.len() {
                let cost = usize::from(ca != b[j]);
                let next = (row[j + 1] + 1).min(row[j] + 1).min(prev + cost);
                prev = row[j + 1];
                row[j + 1] = next;
            }
        }
        row[b.len()]
    };
    let scored: Vec<(&str, usize)> = profile::all()
        .into_iter()
        .map(|p| (p.name, if p.name.starts_with(&name) || name.starts_with(p.name) { 0 } else { distance(&name, p.name) }))
        .filter(|(_, d)| *d <= 2)
        .collect();
    let best = scored.iter().map(|(_, d)| *d).min()?;
    Some(scored.iter().filter(|(_, d)| *d == best).map(|(n, _)| *n).collect::<Vec<_>>().join(" or "))
}

/// How far [`read_first_line`] reads for the line that may name the machine: blank and `%`
/// lines before it, and the line itself, up to this many bytes in all.
pub const FIRST_LINE_SCAN_BYTES: usize = 64 * 1024;

/// Whether a line is one that is passed over looking for the first line: only `%` (the tape
/// start) and white space, or nothing.
fn passed_over(line: &[u8]) -> bool {
    line.iter().all(|&b| b == b'%' || b.is_ascii_whitespace())
}

/// The controller a programme names in its first line, as `(ncsight: MACHINE)`: the name as
/// written (trimmed), whether or not a profile has it ([`Job::profile`] says). The first line is
/// the first that is not blank or only `%` (the tape start), after a UTF-8 byte-order mark; the
/// comment may be the whole line or follow other words on it; `ncsight` in any case, spaces
/// allowed around the colon. `None` when that line holds no such comment (or the text ends
/// first). No I/O: the command line, the Python package and the page give it the text's start.
pub fn machine_from_first_line(text: &[u8]) -> Option<String> {
    let text = text.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(text);
    let line = text.split(|&b| b == b'\n').find(|l| !passed_over(l))?;
    let mut rest = line;
    while let Some(open) = rest.iter().position(|&b| b == b'(') {
        let after = &rest[open + 1..];
        let close = after.iter().position(|&b| b == b')')?;
        if let Some(name) = named_machine(&after[..close]) {
            return Some(name);
        }
        rest = &after[close + 1..];
    }
    None
}

/// `ncsight: NAME` (a comment's text between its parentheses): NAME.
fn named_machine(comment: &[u8]) -> Option<String> {
    let c = comment.trim_ascii();
    let (word, rest) = c.split_at_checked(7)?;
    if !word.eq_ignore_ascii_case(b"ncsight") {
        return None;
    }
    let name = rest.trim_ascii_start().strip_prefix(b":")?.trim_ascii();
    (!name.is_empty()).then(|| String::from_utf8_lossy(name).into_owned())
}

/// The start of a text up to and with its first line (as [`machine_from_first_line`] finds
/// it), at most [`FIRST_LINE_SCAN_BYTES`]: what a caller reading a stream gives that function.
/// What is read is in the result; a stream's caller reads the rest after it.
pub fn read_first_line(r: &mut dyn io::BufRead) -> io::Result<Vec<u8>> {
    use std::io::{BufRead, Read};
    let mut head = Vec::new();
    loop {
        let start = head.len();
        let room = FIRST_LINE_SCAN_BYTES.saturating_sub(start) as u64;
        let n = (&mut *r).take(room).read_until(b'\n', &mut head)?;
        let line = &head[start..];
        let line = if start == 0 { line.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(line) } else { line };
        if n == 0 || !passed_over(line) || head.len() >= FIRST_LINE_SCAN_BYTES {
            return Ok(head);
        }
    }
}

/// The profiles' names, for messages.
pub fn machine_names() -> String {
    profile::all().iter().map(|p| p.name).collect::<Vec<_>>().join(", ")
}

impl Job {
    /// A job on `machine` with everything else as it is at power on.
    pub fn on(machine: &str) -> Job {
        Job { machine: machine.to_string(), ..Job::default() }
    }

    pub fn profile(&self) -> Result<&'static Profile, JobError> {
        profile::by_name(&self.machine).ok_or_else(|| {
            let near = nearest_machine(&self.machine).map(|n| format!("did you mean {n}? ")).unwrap_or_default();
            usage(format!("unknown machine '{}': {near}choose one of {}", self.machine, machine_names()))
        })
    }

    /// The profile's parameters with the overrides applied.
    pub fn parameters(&self) -> Result<Params, JobError> {
        let profile = self.profile()?;
        let mut params = Params::defaults(profile);
        // The setup's machine facts that are settings, before `--param` (which wins).
        if let Some(s) = self.setup.as_ref().and_then(|s| s.machine.as_ref()).and_then(|m| m.tool_change_s) {
            params.set(ncsight::profile::ParamKey::Setting("tool_change_s"), s).map_err(|e| usage(format!("[machine] tool_change_s: {e}")))?;
        }
        for p in &self.params {
            params.set_text(p).map_err(|e| usage(format!("{} ({})", e, profile.name)))?;
        }
        Ok(params)
    }

    /// How programmes that call programmes run, and where called ones are looked for.
    pub fn calls(&self) -> Result<(CallOptions, Library), JobError> {
        let main = match &self.main {
            None => None,
            Some(t) => {
                let digits = t.strip_prefix(['O', 'o']).unwrap_or(t);
                match digits.parse::<u32>() {
                    Ok(n) if !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) && n <= 99_999_999 => Some(n),
                    _ => return Err(usage(format!("--main {t}: expected a programme number such as O1234"))),
                }
            }
        };
        for d in &self.subprogram_dirs {
            if !d.is_dir() {
                return Err(usage(format!("--subprogram-dir {}: not a directory", d.display())));
            }
        }
        let options = CallOptions {
            main,
            skip_missing: self.skip_missing_subprograms,
            max_repeated_blocks: self.max_blocks.unwrap_or(ncsight::program::MAX_REPEATED_BLOCKS),
        };
        let mut dirs = self.subprogram_dirs.clone();
        dirs.extend(self.library_dirs()?);
        Ok((options, Library::new(dirs)))
    }

    /// The setup's `[machine] library` folders (the machine's resident programmes), relative
    /// to the setup file's folder.
    fn library_dirs(&self) -> Result<Vec<PathBuf>, JobError> {
        let Some(m) = self.setup.as_ref().and_then(|s| s.machine.as_ref()) else { return Ok(Vec::new()) };
        let mut dirs = Vec::new();
        for d in &m.library {
            let path = PathBuf::from(d);
            let path = match &self.setup_dir {
                Some(base) if path.is_relative() => base.join(path),
                _ => path,
            };
            if !path.is_dir() {
                return Err(usage(format!("the setup's [machine] library {d:?}: {} is not a directory", path.display())));
            }
            dirs.push(path);
        }
        Ok(dirs)
    }

    /// Read the setup file at `path` (TOML) into the job.
    pub fn read_setup(&mut self, path: &str) -> Result<(), JobError> {
        let text = read_setup_file(path)?;
        self.set_setup_text(&text, path)
    }

    /// The setup from its TOML text; `name` says where it came from in a message.
    pub fn set_setup_text(&mut self, text: &str, name: &str) -> Result<(), JobError> {
        if text.len() as u64 > MAX_SETUP_BYTES {
            return Err(too_large(name, text.len() as u64));
        }
        self.setup = Some(ncsight::setup::Setup::from_toml(text).map_err(|e| usage(format!("{name}: {}", clip_lines(&e.to_string()))))?);
        // A setup read from a file: its library folders are relative to that file's folder.
        let file = std::path::Path::new(name);
        self.setup_dir = file.is_file().then(|| file.parent().map(PathBuf::from).unwrap_or_default());
        Ok(())
    }

    /// The operator's actions and switches from `key=value` lines, as the page keeps them:
    /// `single_block`, `dry_run`, `block_delete`, `optional_stop` (1 or 0), `feed_hold_at`
    /// (seconds, comma-separated), `reset_at` (seconds), `feed_override` and `rapid_override`
    /// (percent); and `main`, `var` (`N=V`, repeatable), `skip_missing_subprograms`, `max_blocks`
    /// as the command line's options of those names. The same limits as the command line's.
    pub fn set_operator_text(&mut self, text: &str) -> Result<(), JobError> {
        for line in text.lines().map(str::trim).filter(|l| !l.is_empty()) {
            let (key, value) = line.split_once('=').map(|(k, v)| (k.trim(), v.trim())).ok_or_else(|| usage(format!("{line}: expected key=value")))?;
            let number = |v: &str| v.parse::<f64>().map_err(|_| usage(format!("{key}={v}: expected a number")));
            let flag = |v: &str| match v {
                "1" | "true" => Ok(true),
                "0" | "false" => Ok(false),
                _ => Err(usage(format!("{key}={v}: expected 1 or 0"))),
            };
            match key {
                "single_block" => self.operator.single_block = flag(value)?,
                "dry_run" => self.operator.overrides.dry_run = flag(value)?,
                "block_delete" => self.switches.block_delete = flag(value)?,
                "optional_stop" => self.switches.optional_stop = flag(value)?,
                "feed_hold_at" => {
                    self.operator.feed_hold_at = value.split(',').map(str::trim).filter(|v| !v.is_empty()).map(number).collect::<Result<_, _>>()?
                }
                "reset_at" => self.operator.reset_at = if value.is_empty() { None } else { Some(number(value)?) },
                "feed_override" => self.operator.overrides.feed_pct = number(value)?,
                "rapid_override" => self.operator.overrides.rapid_pct = number(value)?,
                // What the command line's --main, --var, --skip-missing-subprograms and
                // --max-blocks give (checked where the run starts).
                "main" => self.main = Some(value.to_string()),
                "var" => self.vars.push(value.to_string()),
                "call_args" => self.call_args = Some(value.to_string()),
                "skip_missing_subprograms" => self.skip_missing_subprograms = flag(value)?,
                "max_blocks" => self.max_blocks = Some(value.parse().map_err(|_| usage(format!("{key}={value}: expected a whole number")))?),
                _ => return Err(usage(format!("{key}: not an operator setting (single_block, feed_hold_at, reset_at, feed_override, rapid_override, dry_run, block_delete, optional_stop, main, var, call_args, skip_missing_subprograms, max_blocks)"))),
            }
        }
        check_operator(&self.operator, |key| key.to_string()).map_err(usage)
    }

    /// The run's setup, calls and variables set on `program`; the library of called programmes.
    pub fn prepare(&self, program: &mut Program) -> Result<Library, JobError> {
        if let Some(setup) = &self.setup {
            program.set_setup(setup);
        }
        let (options, library) = self.calls()?;
        program.set_call_options(options);
        for v in &self.vars {
            let parsed = v.split_once('=').and_then(|(n, x)| Some((n.trim().trim_start_matches('#').parse::<i64>().ok()?, x.trim().parse::<f64>().ok()?)));
            let Some((n, x)) = parsed else {
                return Err(usage(format!("--var {v}: expected N=V, e.g. 500=1.5")));
            };
            program.set_variable(n, x).map_err(|e| usage(format!("--var {v}: {e}")))?;
        }
        if let Some(args) = &self.call_args {
            program.set_call_arguments(args).map_err(|e| usage(format!("--call-args {args}: {e}")))?;
        }
        Ok(library)
    }

    /// The programme for a run (records through the operator machine) or a check
    /// (diagnostics only), with its library.
    pub fn program(&self, mode: Mode) -> Result<(Program, Library), JobError> {
        let params = self.parameters()?;
        let mut program = match mode {
            Mode::Run => Program::with_operator(params, self.switches, Mode::Run, self.operator.clone()),
            Mode::Check => Program::diagnostics_only(params, self.switches),
        };
        let library = self.prepare(&mut program)?;
        Ok((program, library))
    }

    /// Run `input` and write it as JSONL lines: a run gives its records and diagnostics as
    /// `run --format jsonl` writes them; a check its diagnostics as `check --format jsonl`,
    /// each naming the file `name` (or the subprogramme file it comes from). Returns how the
    /// programme ended.
    pub fn jsonl(&self, input: Input, mode: Mode, name: &str, on_line: &mut dyn FnMut(&str) -> io::Result<()>) -> Result<Status, JobError> {
        let (mut program, mut library) = self.program(mode)?;
        let mut writer = self.jsonl_writer(mode, name)?;
        let mut line = Vec::with_capacity(256);
        let mut on_event = |e: &Event, _: &[u8], file: FileName| -> io::Result<()> {
            line.clear();
            writer.write(e, file, &mut line)?;
            // One object per line; the formatter ends each with a line break.
            for l in line.split(|b| *b == b'\n').filter(|l| !l.is_empty()) {
                on_line(std::str::from_utf8(l).map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e))?)?;
            }
            Ok(())
        };
        feed::drive(input, &mut library, &mut program, &mut on_event).map_err(|e| {
            if feed::is_read_failure(&e) {
                usage(format!("cannot read {name}: {e}"))
            } else {
                JobError::Io(e)
            }
        })?;
        Ok(program.status())
    }

    /// What [`Job::jsonl`] writes for each event, for a caller that drives the programme itself
    /// (the WebAssembly engine, which has no threads to read a file on).
    pub fn jsonl_writer<'n>(&self, mode: Mode, name: &'n str) -> Result<JsonlWriter<'n>, JobError> {
        Ok(JsonlWriter { mode, name, jsonl: format::Jsonl::new(self.profile()?, self.setup.is_some()) })
    }
}

/// The JSONL of a job's events: a run's records and diagnostics as `run --format jsonl` writes
/// them, or a check's diagnostics as `check --format jsonl` does, named after the file they come
/// from (`name` for the text the job began with).
pub struct JsonlWriter<'n> {
    mode: Mode,
    name: &'n str,
    jsonl: format::Jsonl,
}

impl JsonlWriter<'_> {
    /// The lines of one event (none for a record in a check), each ending in a line break.
    pub fn write(&mut self, e: &Event, file: FileName, out: &mut Vec<u8>) -> io::Result<()> {
        match (self.mode, e) {
            (Mode::Run, _) => self.jsonl.event(e, file, out),
            (Mode::Check, Event::Diagnostic(d)) => {
                out.extend_from_slice(format::jsonl::diagnostic_line(file.unwrap_or(self.name), d).as_bytes());
                Ok(())
            }
            (Mode::Check, Event::Record(_)) => Ok(()),
        }
    }
}

/// The most a setup file may hold. A setup is a few kB; this bound keeps `--setup /dev/zero` or a
/// runaway file from filling the memory.
pub const MAX_SETUP_BYTES: u64 = 16 << 20;

/// The longest line of a message quoted from a file: a parse error that quotes a 10 MB line
/// shows its start.
pub const MAX_MESSAGE_LINE_CHARS: usize = 200;

fn too_large(name: &str, at_least: u64) -> JobError {
    usage(format!(
        "{name}: a setup file holds at most {} MiB ({MAX_SETUP_BYTES} bytes); this one holds {at_least} bytes or more (a setup is a few kB)",
        MAX_SETUP_BYTES >> 20
    ))
}

/// The text of the setup file at `path`, read once (a named pipe gives its data once), at most
/// [`MAX_SETUP_BYTES`].
pub fn read_setup_file(path: &str) -> Result<String, JobError> {
    use std::io::Read;
    let f = std::fs::File::open(path).map_err(|e| usage(format!("cannot read {path}: {e}")))?;
    let mut bytes = Vec::new();
    f.take(MAX_SETUP_BYTES + 1).read_to_end(&mut bytes).map_err(|e| usage(format!("cannot read {path}: {e}")))?;
    if bytes.len() as u64 > MAX_SETUP_BYTES {
        return Err(too_large(path, bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|e| usage(format!("{path}: the setup is not UTF-8 text (byte {} is not)", e.utf8_error().valid_up_to())))
}

/// Each line of a message cut to [`MAX_MESSAGE_LINE_CHARS`] characters, with how much was left out.
pub fn clip_lines(message: &str) -> String {
    let mut out = String::with_capacity(message.len().min(4096));
    for (i, line) in message.lines().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        let chars = line.chars().count();
        if chars > MAX_MESSAGE_LINE_CHARS {
            out.extend(line.chars().take(MAX_MESSAGE_LINE_CHARS));
            out.push_str(&format!("... ({} more characters)", chars - MAX_MESSAGE_LINE_CHARS));
        } else {
            out.push_str(line);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_first_line_names_the_machine() {
        let m = |t: &str| super::machine_from_first_line(t.as_bytes());
        assert_eq!(m("(ncsight: fanuc0m)\nG81\n").as_deref(), Some("fanuc0m"));
        assert_eq!(m("O0001 (PART 12) (NCSight:FANUC0M )\r\nG0 X0\n").as_deref(), Some("FANUC0M"));
        assert_eq!(m("\u{feff}%\r\n\n  %  \n( ncsight :  yasnac-lx3 )\n").as_deref(), Some("yasnac-lx3"));
        assert_eq!(m("(ncsight: nosuch)").as_deref(), Some("nosuch"));
        assert_eq!(m("G0 X0\n(ncsight: fanuc0m)\n"), None, "only the first line");
        assert_eq!(m("(ncsight fanuc0m)\n"), None, "the colon is needed");
        assert_eq!(m("(ncsight:)\n"), None);
        assert_eq!(m("(ncsight: fanuc0m\n"), None, "an unclosed comment");
        assert_eq!(m("(ncsightx: fanuc0m)\n"), None);
        assert_eq!(m("%\n%\n"), None);
        assert_eq!(m(""), None);
    }

    #[test]
    fn the_first_line_is_read_with_what_comes_before_it() {
        let text = b"\xEF\xBB\xBF%\n\n(ncsight: fanuc0t)\nG0 X0\nM30\n";
        let mut r = std::io::Cursor::new(&text[..]);
        let head = super::read_first_line(&mut r).unwrap();
        assert_eq!(head, &text[..text.len() - b"G0 X0\nM30\n".len()]);
        assert_eq!(super::machine_from_first_line(&head).as_deref(), Some("fanuc0t"));
        let long = vec![b'%'; 3 * super::FIRST_LINE_SCAN_BYTES];
        assert_eq!(super::read_first_line(&mut &long[..]).unwrap().len(), super::FIRST_LINE_SCAN_BYTES);
    }

    #[test]
    fn long_lines_are_clipped() {
        let long = "x".repeat(1000);
        let m = super::clip_lines(&format!("first\n{long}\nlast"));
        assert_eq!(m, format!("first\n{}... (800 more characters)\nlast", "x".repeat(200)));
    }
}
