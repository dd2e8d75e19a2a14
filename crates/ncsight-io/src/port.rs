//! `ncsight port`: a programme written for one controller rewritten for another, and verified by
//! running both (docs/commands/port.md).
//!
//! The port keeps the programme as written wherever the target runs it the same: every line is
//! kept (its comments, N numbers, cycles and calls), its lengths written with a decimal point as
//! the source controller reads them (FANUC's `X100` is 0.1 mm where its parameter 3401 says so;
//! a GSK reads 100 mm). Then both are run and their records compared in order: positions within
//! the least increment, feeds, leads and the spindle angle of every thread pass, dwells, the
//! spindle, tools, stops and the end. At the first record that differs, the source line it comes
//! from is rewritten as the moves it makes on the source controller (G00, G01, G02/G03, G32,
//! G04 and the M, S and T codes, in the target's words), with a comment saying why, and the runs
//! are compared again; a line already rewritten that still differs is listed as a difference,
//! with its size. The result is exact (the same motion), approximate (the differences listed),
//! or impossible (the source alarms).

use crate::job::{Job, JobError};
use ncsight::motion::{ArcDir, Op, Plane};
use ncsight::{Event, Mode, Record, Status, Vec3};

/// Rewrites tried at most before the rest is listed as differences.
pub const MAX_REWRITES: usize = 400;

/// Tolerances of the comparison.
const POSITION_MM: f64 = 0.0011;
const ANGLE_DEG: f64 = 0.5;

/// One difference between the two runs: the source line, what differs, by how much.
#[derive(Debug, Clone, PartialEq)]
pub struct Difference {
    pub line: u32,
    pub what: String,
    pub size: f64,
}

/// A port and how it stands.
#[derive(Debug, Clone)]
pub struct Port {
    pub text: String,
    /// Source lines written as plain moves, and why.
    pub rewritten: Vec<(u32, String)>,
    pub differences: Vec<Difference>,
    /// The target's parameters the kept cycles read (their values as the port assumed them:
    /// TO's power-on values): key, value, meaning. Named in the header comment too.
    pub parameters: Vec<(String, f64, &'static str)>,
}

impl Port {
    pub fn exact(&self) -> bool {
        self.differences.is_empty()
    }
}

/// Why a port could not be made.
#[derive(Debug)]
pub enum PortError {
    Usage(String),
    /// The programme alarms on the source controller: the first alarm's line and text.
    SourceAlarm(u32, String),
}

impl From<JobError> for PortError {
    fn from(e: JobError) -> PortError {
        PortError::Usage(e.to_string())
    }
}

/// A run's records with the source line each comes from (0: another file's).
struct Run {
    records: Vec<(u32, Record)>,
    /// The first alarm (line, code and message), if the run stopped on one.
    alarm: Option<(u32, String)>,
    /// After each record: its line, the feed mode (per revolution), the F in force, inch.
    per_rev_after: Vec<(u32, bool, Option<f64>, bool)>,
}

impl Run {
    /// The records both runs should agree on, with their lines.
    fn compared(&self) -> Vec<&(u32, Record)> {
        self.records.iter().filter(|(_, r)| compared(r)).collect()
    }
}

/// Run `text` as `job` says; a called programme the text lacks is looked for in `library`
/// (the files of the job's subprogramme folders, read once per port).
fn run(job: &Job, text: &[u8], library: &[(String, Vec<u8>)]) -> Result<Run, PortError> {
    let (program, _) = job.program(Mode::Run)?;
    let mut events = ncsight::events_with_library(program, text, library.iter().map(|(n, b)| (n.clone(), b.as_slice())).collect());
    let mut out = Run { records: Vec::new(), alarm: None, per_rev_after: Vec::new() };
    while let Some(e) = events.next() {
        match e {
            Event::Record(r) => {
                // A subprogramme's records belong to the line that called it (outermost): a
                // call written as its moves makes them all.
                let line = match (r.call_depth, events.program().call_chain().first()) {
                    (d, Some(call)) if d > 0 && call.file == 0 => call.line,
                    _ if r.span.file == 0 => r.span.line,
                    _ => 0,
                };
                let st = events.program().interpreter().state();
                out.per_rev_after.push((line, st.modes.per_rev, st.modes.feed, st.modes.inch));
                out.records.push((line, r));
            }
            Event::Diagnostic(d) if d.is_alarm() && out.alarm.is_none() => out.alarm = Some((d.span.line, format!("{} {}", d.code, d.message))),
            Event::Diagnostic(_) => {}
        }
    }
    if events.program().status() == Status::Alarm && out.alarm.is_none() {
        out.alarm = Some((0, "the run stopped on an alarm".into()));
    }
    Ok(out)
}

/// Port `text` from `from` to `to`.
pub fn port(from: &Job, to: &Job, text: &[u8]) -> Result<Port, PortError> {
    let source_text = String::from_utf8_lossy(text).into_owned();
    let lines: Vec<&str> = source_text.split('\n').map(|l| l.trim_end_matches('\r')).collect();
    // The subprogramme folders, read once for all the runs (the target's are the source's, as
    // the front ends set them, unless the target's job names its own).
    let from_library = crate::feed::library_files(&from.subprogram_dirs);
    let to_library = if to.subprogram_dirs == from.subprogram_dirs { from_library.clone() } else { crate::feed::library_files(&to.subprogram_dirs) };
    let source = run(from, text, &from_library)?;
    if let Some((line, msg)) = source.alarm {
        return Err(PortError::SourceAlarm(line, msg));
    }
    let from_params = from.parameters()?;
    let to_profile = to.profile()?;
    let mut kept: Vec<(u32, String)> = lines.iter().enumerate().map(|(k, l)| (k as u32 + 1, normalise_line(l, &from_params))).collect();
    name_the_target(&mut kept, from.profile()?.name, to_profile.name);
    // The feed mode at power on differs (the GSK980TDi starts in G98, the FANUC 0-T in G99): the
    // source's is set first, so that an F before any G98/G99 means what it meant.
    let from_profile = from.profile()?;
    if from_profile.power_on_per_rev != to_profile.power_on_per_rev && from_profile.is_lathe() && to_profile.is_lathe() {
        // After the programme's O line where it has one (a block before it would be a
        // programme of its own), else after the note that says where the programme came from.
        // The programme's first block (comment lines are none): an O line, or the first block of
        // a main programme without a number.
        let first = kept.iter().position(|(n, l)| *n > 0 && !outside_comments(l).trim().chars().all(|c| c == '%' || c == ';' || c.is_whitespace()));
        let o_line = first.filter(|&i| crate::port::starts_with_o_number(&kept[i].1));
        let note = kept.iter().position(|(n, l)| *n == 0 && l.starts_with("(PORTED FROM"));
        let at = o_line.or(note).map_or(0, |i| i + 1);
        kept.insert(
            at,
            (0, format!("{} (FEED MODE AT POWER ON ON {})", if from_profile.power_on_per_rev { "G99" } else { "G98" }, from_profile.name.to_ascii_uppercase())),
        );
    }
    let mut rewritten: Vec<(u32, String)> = Vec::new();
    for _ in 0..MAX_REWRITES {
        let (candidate, line_map) = assemble(&kept, &rewritten, &source, to_profile.name);
        let target = run(to, candidate.as_bytes(), &to_library)?;
        let done = |l: u32| rewritten.iter().any(|(r, _)| *r == l);
        if let Some((line, why)) = first_difference(&source, &target, &line_map) {
            if line > 0 && !done(line) {
                rewritten.push((line, why));
                continue;
            }
            // The target still alarms at a line already written as its moves: a mode the lines
            // before it set (M29 before a rigid tap) is what it refuses: the nearest of the three
            // lines before it still as written goes too.
            if line > 0 && why.starts_with("the target alarms") {
                if let Some(prev) = (line.saturating_sub(3)..line).rev().find(|&l| l > 0 && !done(l)) {
                    rewritten.push((prev, format!("the line after it alarms on the target as its moves: {why}")));
                    continue;
                }
            }
        }
        // The first difference is at a line already written as its moves (or at none): the
        // next line that differs and is still as written is tried, else the port is as close as
        // it gets.
        let differences = all_differences(&source, &target, &line_map);
        match differences.iter().find(|d| d.line > 0 && !rewritten.iter().any(|(l, _)| *l == d.line)) {
            Some(d) => rewritten.push((d.line, d.what.clone())),
            None => return finish(to, candidate, rewritten, differences),
        }
    }
    let (candidate, line_map) = assemble(&kept, &rewritten, &source, to_profile.name);
    let target = run(to, candidate.as_bytes(), &to_library)?;
    let differences = all_differences(&source, &target, &line_map);
    finish(to, candidate, rewritten, differences)
}

/// The port as written: the parameters of the target that the kept lines' G codes read, named
/// in comments after the note that says where the programme came from (comments: the motion
/// verified is the same).
fn finish(to: &Job, text: String, rewritten: Vec<(u32, String)>, differences: Vec<Difference>) -> Result<Port, PortError> {
    let params = to.parameters()?;
    let codes = codes_in(&text);
    let mut parameters = Vec::new();
    for d in params.profile().all_params() {
        let mentions = codes.iter().any(|c| d.meaning.split(|ch: char| !ch.is_ascii_alphanumeric() && ch != '.').any(|w| w == c));
        if mentions {
            parameters.push((d.key.to_string(), params.get(d.key), d.meaning));
        }
    }
    let mut lines: Vec<String> = text.split('\n').map(str::to_string).collect();
    let at = lines.iter().position(|l| l.starts_with("(PORTED FROM")).map_or(0, |i| i + 1);
    // Short comments (a controller reads a long comment's tail as words).
    let mut notes = Vec::new();
    let mut note = String::from("(TARGET PARAMETERS:");
    for (k, v, _) in &parameters {
        let item = format!(" {k}={}", with_point(*v).trim_end_matches('.'));
        if note.len() + item.len() > 56 {
            notes.push(format!("{note})"));
            note = String::from("(TARGET PARAMETERS:");
        }
        note.push_str(&item);
    }
    if !parameters.is_empty() {
        notes.push(format!("{note})"));
    }
    for (i, n) in notes.into_iter().enumerate() {
        lines.insert(at + i, n);
    }
    Ok(Port { text: lines.join("\n"), rewritten, differences, parameters })
}

/// The G codes of a text's blocks (comments left out), as the parameters' meanings name them
/// (`G76`, `G92`, `G71`): written without leading zeros beyond two digits (`G0` is `G00`).
fn codes_in(text: &str) -> Vec<String> {
    let mut codes: Vec<String> = Vec::new();
    for line in text.lines() {
        let mut depth = 0;
        let b = line.as_bytes();
        for (i, &c) in b.iter().enumerate() {
            match c {
                b'(' => depth += 1,
                b')' => depth = (depth - 1).max(0),
                b'G' | b'g' if depth == 0 => {
                    let digits: String = line[i + 1..].chars().take_while(|c| c.is_ascii_digit() || *c == '.').collect();
                    if let Ok(n) = digits.trim_end_matches('.').parse::<f64>() {
                        let code = if n.fract() == 0.0 {
                            format!("G{:02}", n as u32)
                        } else {
                            format!("G{:02}.{}", n.trunc() as u32, ((n.fract() * 10.0).round()) as u32)
                        };
                        if !codes.contains(&code) {
                            codes.push(code);
                        }
                    }
                }
                _ => {}
            }
        }
    }
    codes
}

/// The programme names its controller on its first line, as `run`, `check`, the page and the
/// editor read it (`(ncsight: gsk988t)`): the source's own such comment is replaced, else a line
/// is put first (after a `%` tape start). A second comment says where it came from. Comments are
/// kept short: the controllers read a long comment's tail as words.
fn name_the_target(lines: &mut Vec<(u32, String)>, from: &str, to: &str) {
    let first = lines.iter().position(|(_, l)| !l.trim().chars().all(|c| c == '%' || c.is_whitespace())).unwrap_or(lines.len());
    let named = first < lines.len() && crate::machine_from_first_line(lines[first].1.as_bytes()).is_some();
    let note = (0, format!("(PORTED FROM {} BY NCSIGHT PORT)", from.to_ascii_uppercase()));
    if named {
        let l = &lines[first].1;
        // The comment that names it: the '(' before the word ncsight (spaces may stand between).
        let lower = l.to_ascii_lowercase();
        let a = lower.find("ncsight").and_then(|w| lower[..w].rfind('(')).unwrap_or(0);
        let b = l[a..].find(')').map_or(l.len(), |e| a + e + 1);
        lines[first].1 = format!("{}(ncsight: {to}){}", &l[..a], &l[b..]);
        lines.insert(first + 1, note);
    } else if first < lines.len() && lines[first].1.trim_start().starts_with(['O', 'o', ':']) {
        // A programme number first: the comment goes on its line (lines before it would be a
        // programme of their own).
        lines[first].1.push_str(&format!(" (ncsight: {to})"));
        lines.insert(first + 1, note);
    } else {
        lines.insert(first, note);
        lines.insert(first, (0, format!("(ncsight: {to})")));
    }
}

/// A line without its `( )` comments.
fn outside_comments(line: &str) -> String {
    let mut depth = 0;
    line.chars()
        .filter(|&c| {
            match c {
                '(' => depth += 1,
                ')' if depth > 0 => {
                    depth -= 1;
                    return false;
                }
                _ => {}
            }
            depth == 0
        })
        .collect()
}

/// A line that starts with a programme number (`O1234`).
fn starts_with_o_number(line: &str) -> bool {
    let t = line.trim_start();
    t.starts_with(['O', 'o']) && t[1..].starts_with(|c: char| c.is_ascii_digit())
}

/// Positions written with a decimal point, as the source controller reads them.
fn normalise_line(line: &str, params: &ncsight::profile::Params) -> String {
    let least_increment = params.integer_lengths() == ncsight::profile::IntegerLengths::LeastIncrement;
    let mut out = String::with_capacity(line.len() + 8);
    let b = line.as_bytes();
    let mut i = 0;
    let mut in_comment = false;
    while i < b.len() {
        let c = b[i];
        if in_comment || c == b'(' {
            in_comment = c != b')';
            // Copy one character (a multi-byte one whole).
            let ch = line[i..].chars().next().unwrap_or(' ');
            out.push(ch);
            i += ch.len_utf8();
            continue;
        }
        // Lengths, and the rotary axes' angles (read by the same rule: 0.001 degree where lengths
        // are in least increments).
        let is_length = matches!(c.to_ascii_uppercase(), b'X' | b'Z' | b'U' | b'W' | b'Y' | b'V' | b'A' | b'B' | b'C')
            && (i == 0 || !b[i - 1].is_ascii_alphabetic())
            && i + 1 < b.len()
            && (b[i + 1] == b'-' || b[i + 1] == b'+' || b[i + 1].is_ascii_digit());
        if !is_length {
            // Copy one character (a multi-byte one whole).
            let ch = line[i..].chars().next().unwrap_or(' ');
            out.push(ch);
            i += ch.len_utf8();
            continue;
        }
        let start = i + 1;
        let mut j = start;
        while j < b.len() && (b[j].is_ascii_digit() || matches!(b[j], b'.' | b'-' | b'+')) {
            j += 1;
        }
        let number = &line[start..j];
        out.push(c as char);
        match (number.contains('.'), number.parse::<f64>()) {
            (false, Ok(v)) => out.push_str(&with_point(if least_increment { v * 0.001 } else { v })),
            _ => out.push_str(number),
        }
        i = j;
    }
    out
}

/// A value in mm with a decimal point (`100.`, `0.1`, `-2.5`).
fn with_point(v: f64) -> String {
    let s = format!("{v:.4}");
    let s = s.trim_end_matches('0');
    if s == "-0." {
        "0.".into()
    } else {
        s.to_string()
    }
}

/// The candidate text: kept lines as they are, rewritten lines as their moves. Each candidate
/// line's source line.
fn assemble(kept: &[(u32, String)], rewritten: &[(u32, String)], source: &Run, machine: &str) -> (String, Vec<u32>) {
    let mut text = String::new();
    let mut map = Vec::new();
    for &(n, ref line) in kept {
        let lines = if n > 0 && rewritten.iter().any(|(l, _)| *l == n) { plain_moves(n, line, source, machine) } else { vec![line.clone()] };
        for out in lines {
            text.push_str(&out);
            text.push('\n');
            map.push(n);
        }
    }
    // The text's own last line end: none added past it.
    if text.ends_with("\n\n") && !kept.last().is_some_and(|(_, l)| !l.is_empty()) {
        text.pop();
        map.pop();
    }
    (text, map)
}

/// A source line written as the moves it makes on the source controller, in the target's words;
/// then the feed mode, F and motion mode the source has after it, for the lines that follow.
fn plain_moves(n: u32, line: &str, source: &Run, machine: &str) -> Vec<String> {
    let dialect = Dialect { lathe: ncsight::profile::by_name(machine).map_or(true, |p| p.is_lathe()) };
    let comment = line.find('(').map(|a| line[a..].to_string()).unwrap_or_default();
    // Why is in the port's report; the comment stays short (a controller reads a long comment's
    // tail as words).
    let mut out = vec![format!("(PORT: LINE {n} AS ITS MOVES)")];
    // The moves are written in mm: under G20 the block is set to G21 and back after.
    let inch = source.per_rev_after.iter().find(|(l, ..)| *l == n).is_some_and(|r| r.3);
    if inch {
        out.push("G21".into());
    }
    let mut last_motion = None;
    let mut in_thread = false;
    for (_, r) in source.records.iter().filter(|(l, _)| *l == n) {
        if let Some(mut w) = dialect.words_of(&r.op) {
            // A thread run that starts away from the one-revolution signal (a second start, a
            // shifted pass): the GSK controllers' G32 takes the start angle as Q in 0.001 degree
            // (GSK980TDi help text, G32); the others have no such word, and the difference stays.
            if let (Op::Thread { spindle_deg, .. }, false, true) = (r.op, in_thread, machine.starts_with("gsk")) {
                if spindle_deg.abs() > 1e-3 {
                    w.push_str(&format!(" Q{}", (spindle_deg * 1000.0).round() as i64));
                }
            }
            out.push(w);
        }
        in_thread = r.op.is_thread();
        last_motion = match r.op {
            Op::Rapid { .. } => Some("G00"),
            Op::Feed { .. } => Some("G01"),
            Op::Arc { dir: ArcDir::Cw, .. } => Some("G02"),
            Op::Arc { dir: ArcDir::Ccw, .. } => Some("G03"),
            _ => last_motion,
        };
    }
    // What the lines after it take from the modal state: the feed mode and F, the motion mode.
    if let Some(&(_, per_rev, feed, inch_after)) = source.per_rev_after.iter().rev().find(|(l, ..)| *l == n) {
        let mode = if per_rev { dialect.per_rev() } else { dialect.per_minute() };
        // F in force is in mm (per minute or revolution); under G20 it is given back in inch.
        let f = feed.map(|f| format!(" F{}", with_point(if inch_after { f / 25.4 } else { f }))).unwrap_or_default();
        let units = if inch_after { "G20 " } else { "" };
        out.push(format!("{units}{}{mode}{f}", last_motion.map(|m| format!("{m} ")).unwrap_or_default()));
    }
    if !comment.is_empty() {
        out.push(comment);
    }
    out
}

/// How the target writes what a record is: a lathe (X a diameter, G98/G99, T with its offset) or
/// a machining centre (X Y Z, G94/G95, T and M06).
#[derive(Clone, Copy)]
struct Dialect {
    lathe: bool,
}

impl Dialect {
    fn per_minute(self) -> &'static str {
        if self.lathe {
            "G98"
        } else {
            "G94"
        }
    }

    fn per_rev(self) -> &'static str {
        if self.lathe {
            "G99"
        } else {
            "G95"
        }
    }

    fn point(self, p: &Vec3) -> String {
        if self.lathe {
            format!("X{} Z{}", with_point(2.0 * p.x), with_point(p.z))
        } else {
            format!("X{} Y{} Z{}", with_point(p.x), with_point(p.y), with_point(p.z))
        }
    }

    /// An arc's plane code and its centre words (from the start point).
    fn arc_centre(self, plane: Plane, from: &Vec3, centre: &Vec3) -> String {
        let d = |a: f64, b: f64| with_point(b - a);
        match plane {
            Plane::XY => format!("G17 I{} J{}", d(from.x, centre.x), d(from.y, centre.y)),
            Plane::ZX if self.lathe => format!("I{} K{}", d(from.x, centre.x), d(from.z, centre.z)),
            Plane::ZX => format!("G18 I{} K{}", d(from.x, centre.x), d(from.z, centre.z)),
            Plane::YZ => format!("G19 J{} K{}", d(from.y, centre.y), d(from.z, centre.z)),
        }
    }

    /// A record in the target's words; None where it has none (a thread on a machining centre,
    /// an arc thread): the difference is then listed.
    fn words_of(self, op: &Op) -> Option<String> {
        let minute = self.per_minute();
        Some(match *op {
            Op::Rapid { to, .. } => format!("G00 {}", self.point(&to)),
            Op::Feed { to, feed_mm_min, .. } => format!("{minute} G01 {} F{}", self.point(&to), with_point(feed_mm_min)),
            Op::Arc { from, to, center, plane, dir, feed_mm_min } => {
                let g = if dir == ArcDir::Cw { "G02" } else { "G03" };
                format!("{minute} {g} {} {} F{}", self.point(&to), self.arc_centre(plane, &from, &center), with_point(feed_mm_min))
            }
            Op::Thread { to, lead_mm, .. } if self.lathe => format!("G32 {} F{}", self.point(&to), with_point(lead_mm)),
            Op::Dwell { seconds } => format!("G04 X{}", with_point(seconds)),
            Op::Spindle { rpm, .. } if rpm == 0.0 => "M05".into(),
            Op::Spindle { rpm, .. } => {
                format!("{}S{} {}", if self.lathe { "G97 " } else { "" }, with_point(rpm.abs()).trim_end_matches('.'), if rpm > 0.0 { "M03" } else { "M04" })
            }
            Op::Tool { number, offset } if self.lathe => format!("T{number:02}{:02}", offset.unwrap_or(0)),
            Op::Tool { number, .. } => format!("T{number} M06"),
            Op::Rotary { axis, to_deg, rapid: true, .. } => format!("G00 {}{}", axis as char, with_point(to_deg)),
            Op::Rotary { axis, to_deg, rate_deg_min, .. } => format!("{minute} G01 {}{} F{}", axis as char, with_point(to_deg), with_point(rate_deg_min)),
            Op::Stop { reason: ncsight::motion::StopReason::ProgramStop } => "M00".into(),
            Op::Stop { reason: ncsight::motion::StopReason::OptionalStop } => "M01".into(),
            Op::End { code } => format!("M{code:02}"),
            _ => return None,
        })
    }
}

/// The records both runs should agree on: motions, dwells, spindle, tools, stops, the end.
fn compared(r: &Record) -> bool {
    !matches!(r.op, Op::Stop { reason: ncsight::motion::StopReason::SingleBlock | ncsight::motion::StopReason::FeedHold })
}

/// Why two records differ and by how much, or None when they agree. Positions are compared on
/// the machine (each record's point plus its offsets: controllers apply tool offsets each their
/// own way, the tool must go to the same place).
fn differ(ra: &Record, rb: &Record) -> Option<(String, f64)> {
    let (a, b) = (&ra.op, &rb.op);
    let (ma, mb) = (ra.to_machine, rb.to_machine);
    let pos = |p: &Vec3, q: &Vec3| Vec3::new(p.x + ma.x, p.y + ma.y, p.z + ma.z).dist(&Vec3::new(q.x + mb.x, q.y + mb.y, q.z + mb.z));
    match (a, b) {
        (Op::Rapid { to: p, .. }, Op::Rapid { to: q, .. }) => (pos(p, q) > POSITION_MM).then(|| ("rapid end point".to_string(), pos(p, q))),
        (Op::Feed { to: p, feed_mm_min: f, .. }, Op::Feed { to: q, feed_mm_min: g, .. })
        | (Op::Arc { to: p, feed_mm_min: f, .. }, Op::Arc { to: q, feed_mm_min: g, .. }) => {
            if pos(p, q) > POSITION_MM {
                Some(("end point".into(), pos(p, q)))
            } else {
                ((f - g).abs() > 1e-3 * f.abs().max(1.0)).then(|| ("feed mm/min".to_string(), (f - g).abs()))
            }
        }
        (Op::Thread { to: p, lead_mm: l, spindle_deg: s, .. }, Op::Thread { to: q, lead_mm: m, spindle_deg: t, .. }) => {
            let phase = ((s - t + 540.0).rem_euclid(360.0) - 180.0).abs();
            if pos(p, q) > POSITION_MM {
                Some(("thread end point".into(), pos(p, q)))
            } else if (l - m).abs() > 1e-6 {
                Some(("lead".into(), (l - m).abs()))
            } else {
                (phase > ANGLE_DEG).then(|| ("spindle angle at the thread's start, degrees".to_string(), phase))
            }
        }
        (Op::Dwell { seconds: s }, Op::Dwell { seconds: t }) => ((s - t).abs() > 1e-3).then(|| ("dwell seconds".to_string(), (s - t).abs())),
        (Op::Rotary { axis: x, to_deg: p, .. }, Op::Rotary { axis: y, to_deg: q, .. }) => {
            if x != y {
                Some((format!("{} turned where the source turns {}", *y as char, *x as char), 0.0))
            } else {
                ((p - q).abs() > 1e-3).then(|| (format!("{} end, degrees", *x as char), (p - q).abs()))
            }
        }
        (Op::ThreadArc { to: p, lead_mm: l, .. }, Op::ThreadArc { to: q, lead_mm: m, .. }) => {
            if pos(p, q) > POSITION_MM {
                Some(("arc thread end point".into(), pos(p, q)))
            } else {
                ((l - m).abs() > 1e-6).then(|| ("arc thread lead".to_string(), (l - m).abs()))
            }
        }
        (Op::Spindle { rpm: s, .. }, Op::Spindle { rpm: t, .. }) => ((s - t).abs() > 0.5).then(|| ("spindle rpm".to_string(), (s - t).abs())),
        (Op::Tool { number: n, .. }, Op::Tool { number: m, .. }) => (n != m).then(|| ("tool".to_string(), (*n as f64 - *m as f64).abs())),
        (x, y) if std::mem::discriminant(x) == std::mem::discriminant(y) => None,
        (x, y) => Some((format!("{} where the source makes a {}", y.kind(), x.kind()), 0.0)),
    }
}

/// The first disagreement: the source line to rewrite, and why.
fn first_difference(source: &Run, target: &Run, map: &[u32]) -> Option<(u32, String)> {
    if let Some((line, msg)) = &target.alarm {
        let src = map.get(line.saturating_sub(1) as usize).copied().unwrap_or(0);
        return Some((src, format!("the target alarms: {msg}")));
    }
    let (a, b) = (source.compared(), target.compared());
    for (k, (sa, ra)) in a.iter().map(|x| (x.0, &x.1)).enumerate() {
        let Some((lb, rb)) = b.get(k).map(|x| (x.0, &x.1)) else { return Some((sa, "the target's run ends before".into())) };
        let tb = map.get(lb.saturating_sub(1) as usize).copied().unwrap_or(0);
        if let Some((why, size)) = differ(ra, rb) {
            // The earlier of the two lines is the one to rewrite.
            let line = if tb > 0 && tb < sa { tb } else { sa };
            return Some((line, if size > 0.0 { format!("{why} differs by {}", with_point(size)) } else { why }));
        }
    }
    b.get(a.len()).map(|x| (map.get(x.0.saturating_sub(1) as usize).copied().unwrap_or(0), "the target makes more records".into()))
}

/// Every difference left, in order (at most 100).
fn all_differences(source: &Run, target: &Run, map: &[u32]) -> Vec<Difference> {
    let mut out = Vec::new();
    if let Some((line, msg)) = &target.alarm {
        out.push(Difference { line: map.get(line.saturating_sub(1) as usize).copied().unwrap_or(0), what: format!("the target alarms: {msg}"), size: 0.0 });
    }
    let (a, b) = (source.compared(), target.compared());
    for (k, x) in a.iter().enumerate() {
        match b.get(k) {
            Some(y) => {
                if let Some((what, size)) = differ(&x.1, &y.1) {
                    out.push(Difference { line: x.0, what, size });
                }
            }
            None => out.push(Difference { line: x.0, what: format!("the target's run has no {} here", x.1.op.kind()), size: 0.0 }),
        }
        if out.len() >= 100 {
            break;
        }
    }
    if b.len() > a.len() {
        out.push(Difference { line: 0, what: format!("the target makes {} records more", b.len() - a.len()), size: 0.0 });
    }
    out
}
