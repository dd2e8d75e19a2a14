//! `ncsight expand`: the programme as it runs on its controller, written again as plain moves
//! for a controller that lacks its cycles (issue 21): LinuxCNC (G0 G1 G2 G3 G4 and G33 for
//! threads) or grbl 1.1 (G0 G1 G2 G3 G4 only). Every cycle, subprogramme and macro has already
//! been run by the engine; what is written is its motion, in mm, absolute, with a comment giving
//! the source line of each block.

use super::{push_num, Format};
use ncsight::motion::{ArcDir, LongAxis, Op, Plane, StopReason};
use ncsight::{Diagnostic, Event, Profile, Rule, Vec3};
use std::io::{self, Write};

/// The controller the expanded programme is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    LinuxCnc,
    Grbl,
}

impl Target {
    pub fn by_name(name: &str) -> Option<Target> {
        match name {
            "linuxcnc" => Some(Target::LinuxCnc),
            "grbl" => Some(Target::Grbl),
            _ => None,
        }
    }

    pub fn title(self) -> &'static str {
        match self {
            Target::LinuxCnc => "LinuxCNC",
            Target::Grbl => "grbl 1.1",
        }
    }
}

/// A record the target cannot do: the expansion stops there with this alarm (NCS-E76), carried
/// out of [`Format::event`] inside an `io::Error` of kind `Unsupported`.
#[derive(Debug)]
pub struct Refused(pub Diagnostic);

impl Refused {
    /// The refusal an error of [`Format::event`] carries, if it is one.
    pub fn of(e: &io::Error) -> Option<&Diagnostic> {
        e.get_ref().and_then(|inner| inner.downcast_ref::<Refused>()).map(|r| &r.0)
    }
}

impl std::fmt::Display for Refused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0.message)
    }
}

impl std::error::Error for Refused {}

/// Decimals written: 0.0001 mm, finer than any of the controllers' least increment.
const DECIMALS: usize = 4;

/// A file's base name, safe inside a comment.
fn file_label(path: &str) -> String {
    comment_text(path.rsplit(['/', '\\']).next().unwrap_or(path))
}

/// Text safe inside a comment: brackets for parentheses (a `(` nests, a `)` ends the comment on
/// both targets), spaces for control characters.
fn comment_text(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '(' => '[',
            ')' => ']',
            c if c.is_control() => ' ',
            c => c,
        })
        .collect()
}

fn same(a: &Vec3, b: &Vec3) -> bool {
    (a.x - b.x).abs() + (a.y - b.y).abs() + (a.z - b.z).abs() < 1e-6
}

pub struct Expand {
    target: Target,
    lathe: bool,
    axes: [bool; 3],
    style: ncsight::alarm::AlarmStyle,
    source: String,
    machine: &'static str,
    started: bool,
    feed: Option<f64>,
    /// The plane in force on the target (the header's, then the last arc's).
    plane: Plane,
    /// The source line (file, line) of the last record written.
    at: Option<(Option<String>, u32)>,
    /// Warnings about what the target cannot express exactly (NCS-W29), once each.
    notes: Vec<Diagnostic>,
    warned_start_angle: bool,
    /// Where the last thread record ended, while the next record may continue it.
    thread_end: Option<Vec3>,
    /// The spindle as last written: rpm, signed (0: stopped).
    spindle_rpm: f64,
    /// Where the last move written ended: a record that starts elsewhere follows a coordinate
    /// shift (G50/G92), written as G92.
    last: Option<Vec3>,
    /// A thread pass held back until the next record shows whether it is a tapping stroke's
    /// way in (then the way back makes one G33.1), with the spindle and dwell records between.
    held: Option<(ncsight::Record, Vec<ncsight::Record>)>,
    /// M02/M30 written.
    ended: bool,
    warned_css: bool,
    warned_tap_dwell: bool,
    text: String,
}

impl Expand {
    /// `source`: the file name written in the header.
    pub fn new(profile: &'static Profile, target: Target, source: &str) -> Expand {
        Expand {
            target,
            lathe: profile.is_lathe(),
            style: profile.alarm_style,
            axes: ['X', 'Y', 'Z'].map(|a| profile.axes.contains(a)),
            source: source.to_string(),
            machine: profile.name,
            started: false,
            feed: None,
            plane: if profile.is_lathe() { Plane::ZX } else { Plane::XY },
            at: None,
            notes: Vec::new(),
            warned_start_angle: false,
            thread_end: None,
            spindle_rpm: 0.0,
            last: None,
            held: None,
            ended: false,
            warned_css: false,
            warned_tap_dwell: false,
            text: String::with_capacity(256),
        }
    }

    fn header(&self, s: &mut String) {
        s.push_str(&format!("(expanded by ncsight from {} as it runs on {}, for {})\n", file_label(&self.source), self.machine, self.target.title()));
        s.push_str("(every cycle, subprogramme and macro already run: plain moves in mm, absolute; X as a radius on a lathe)\n");
        let plane = if self.lathe { "G18" } else { "G17" };
        match self.target {
            // G8: radius mode, so X is what the records hold (LinuxCNC's lathe default, written
            // out so a G7 configuration does not halve it).
            Target::LinuxCnc if self.lathe => s.push_str(&format!("G21 G90 G94 {plane} G8 G40 G49 G80\n")),
            _ => s.push_str(&format!("G21 G90 G94 {plane} G40 G49 G80\n")),
        }
    }

    fn coord(s: &mut String, letter: char, v: f64) {
        s.push(' ');
        s.push(letter);
        push_num(s, v, DECIMALS);
    }

    /// The end point: the profile's axes, and any other that is not at zero.
    fn point(&self, s: &mut String, p: &Vec3) {
        for (i, letter) in ['X', 'Y', 'Z'].into_iter().enumerate() {
            if self.axes[i] || p.axis(i).abs() > 1e-9 {
                Self::coord(s, letter, p.axis(i));
            }
        }
    }

    /// A feed that would be written as F0 (below 0.00005 mm/min, nothing at the target's four
    /// decimals) is refused before its line is begun: both targets refuse G1 F0, and a rounded
    /// feed would move at another speed than the programme's.
    fn writable_feed(&self, f: f64, span: ncsight::source::Span) -> io::Result<()> {
        if f.abs() < 0.5 * 10f64.powi(-(DECIMALS as i32)) {
            return Err(self.refuse(span, &format!("a feed of {f:e} mm/min is F0 at the target's {DECIMALS} decimals")));
        }
        Ok(())
    }

    fn feed(&mut self, s: &mut String, f: f64) {
        if self.feed != Some(f) {
            self.feed = Some(f);
            s.push_str(" F");
            push_num(s, f, DECIMALS);
        }
    }

    fn plane(&mut self, s: &mut String, plane: Plane) {
        if self.plane != plane {
            self.plane = plane;
            s.push_str(match plane {
                Plane::XY => "G17 ",
                Plane::ZX => "G18 ",
                Plane::YZ => "G19 ",
            });
        }
    }

    fn arc(&mut self, s: &mut String, from: &Vec3, to: &Vec3, center: &Vec3, plane: Plane, dir: ArcDir) {
        self.plane(s, plane);
        s.push_str(if dir == ArcDir::Cw { "G2" } else { "G3" });
        self.point(s, to);
        // The centre from the start, in the plane's two axes (I J K: X Y Z).
        let (a, b, _) = plane.axes();
        for i in [a, b] {
            Self::coord(s, ['I', 'J', 'K'][i], center.axis(i) - from.axis(i));
        }
    }

    /// `S<rpm> M3`/`M4`, or `M5` for 0.
    fn spindle(&mut self, s: &mut String, rpm: f64) {
        self.spindle_rpm = rpm;
        if rpm == 0.0 {
            s.push_str("M5");
        } else {
            s.push('S');
            push_num(s, rpm.abs(), 1);
            s.push_str(if rpm > 0.0 { " M3" } else { " M4" });
        }
    }

    fn refuse(&self, span: ncsight::source::Span, why: &str) -> io::Error {
        let d = Diagnostic::new(Rule::NotExpandable, self.style, span, format!("{why}: the expansion for {} stops here", self.target.title()));
        io::Error::new(io::ErrorKind::Unsupported, Refused(d))
    }

    fn note(&mut self, span: ncsight::source::Span, msg: String) {
        self.notes.push(Diagnostic::new(Rule::ExpandApproximate, self.style, span, msg));
    }

    /// A thread pass as `G33` (LinuxCNC; grbl has refused it before): the spindle started first
    /// when the pass turns it itself (a rigid thread), K along the path.
    fn thread(&mut self, r: &ncsight::Record, s: &mut String, code: &str) {
        let Op::Thread { from, to, lead_mm, long_axis, spindle_deg, rpm } = r.op else { return };
        // LinuxCNC's K is the distance along the path per revolution (the EMC2 manual, G33:
        // "the distance moved in XYZ for each revolution"); the FANUC and GSK lead is along the
        // thread's long axis: on a taper K is longer (inferred).
        let long = match long_axis {
            LongAxis::X => (to.x - from.x).abs(),
            LongAxis::Y => (to.y - from.y).abs(),
            LongAxis::Z => (to.z - from.z).abs(),
        };
        let path = ((to.x - from.x).powi(2) + (to.y - from.y).powi(2) + (to.z - from.z).powi(2)).sqrt();
        let k = if long > 1e-9 { lead_mm * path / long } else { lead_mm };
        // Only where a synchronised run begins: a pass's pull-out continues the thread from where
        // it ended (LinuxCNC joins consecutive G33 moves).
        let begins = self.thread_end.map_or(true, |p| !same(&p, &from));
        self.thread_end = Some(to);
        let deg = spindle_deg.rem_euclid(360.0);
        if code == "G33" && begins && deg > 0.01 && deg < 359.99 && !self.warned_start_angle {
            self.warned_start_angle = true;
            self.note(r.span, format!("this thread starts {deg:.1} degrees after the spindle's index pulse (a multi-start or shifted thread); LinuxCNC's G33 always starts at the pulse, so such passes are written as if they started there"));
        }
        // A rigid thread (G32.1 in the spindle's position mode) turns the spindle itself:
        // LinuxCNC's G33 needs it turning at that speed first.
        if rpm != 0.0 && (self.spindle_rpm == 0.0 || self.spindle_rpm.signum() != rpm.signum()) {
            self.spindle(s, rpm);
            s.push('\n');
        }
        s.push_str(code);
        self.point(s, &to);
        Self::coord(s, 'K', k);
        s.push('\n');
        self.last = Some(to);
    }

    /// Whether `r` goes on with the pass held back: a spindle or dwell record at the bottom, or
    /// the way back out of a tapping stroke (the reverse of the way in, the spindle reversed).
    fn continues_held(&self, r: &ncsight::Record) -> bool {
        let Some((held, _)) = &self.held else { return false };
        match (&held.op, &r.op) {
            (_, Op::Spindle { oriented: false, .. } | Op::Dwell { .. }) => true,
            (Op::Thread { from: f1, to: t1, rpm: r1, .. }, Op::Thread { from: f2, to: t2, rpm: r2, .. }) => {
                same(t1, f2) && same(t2, f1) && r1.signum() == -r2.signum() && *r1 != 0.0
            }
            _ => false,
        }
    }

    /// Write the held pass as it is, and what came after it.
    fn flush_held(&mut self, s: &mut String) -> io::Result<()> {
        let Some((pass, after)) = self.held.take() else { return Ok(()) };
        self.thread(&pass, s, "G33");
        for r in &after {
            self.record(r, s)?;
        }
        Ok(())
    }

    /// The G-code of one record, each line ending in a line break.
    fn record(&mut self, r: &ncsight::Record, s: &mut String) -> io::Result<()> {
        if !matches!(r.op, Op::Thread { .. }) {
            self.thread_end = None;
        }
        // A move that starts where the last did not end follows a coordinate shift (G50/G92,
        // G52): the same shift, as G92, keeps the target's coordinates the programme's.
        if let (Some(from), Some(last), None) = (r.op.start_point(), self.last, &self.held) {
            if !same(&from, &last) {
                s.push_str("G92");
                self.point(s, &from);
                s.push_str(" (the programme's coordinates were shifted here)\n");
            }
        }
        match &r.op {
            Op::Rapid { to, .. } => {
                s.push_str("G0");
                self.point(s, to);
            }
            Op::Feed { to, feed_mm_min, .. } => {
                self.writable_feed(*feed_mm_min, r.span)?;
                s.push_str("G1");
                self.point(s, to);
                self.feed(s, *feed_mm_min);
            }
            Op::Arc { from, to, center, plane, dir, feed_mm_min } => {
                self.writable_feed(*feed_mm_min, r.span)?;
                self.arc(s, from, to, center, *plane, *dir);
                self.feed(s, *feed_mm_min);
            }
            Op::Thread { .. } => {
                if self.target == Target::Grbl {
                    return Err(self.refuse(r.span, "a thread needs motion synchronised with the spindle, which grbl does not have"));
                }
                match self.held.take() {
                    // The way back of a tapping stroke: LinuxCNC's G33.1 makes the whole stroke,
                    // reversing the spindle at the bottom and restoring it at the top.
                    Some((pass, after)) => {
                        if after.iter().any(|a| matches!(a.op, Op::Dwell { .. })) && !self.warned_tap_dwell {
                            self.warned_tap_dwell = true;
                            self.note(pass.span, "the dwell at the bottom of this tapping stroke is left out: LinuxCNC's G33.1 reverses at once".to_string());
                        }
                        let Op::Thread { rpm, .. } = pass.op else { unreachable!("held passes are threads") };
                        self.thread(&pass, s, "G33.1");
                        self.spindle_rpm = rpm;
                        self.last = pass.op.start_point();
                    }
                    None => self.held = Some((r.clone(), Vec::new())),
                }
                return Ok(());
            }
            Op::ThreadArc { .. } => {
                let why = match self.target {
                    Target::Grbl => "a thread needs motion synchronised with the spindle, which grbl does not have",
                    Target::LinuxCnc => "an arc thread (G32.2/G32.3) needs a spindle-synchronised arc, and LinuxCNC's G33 is straight only",
                };
                return Err(self.refuse(r.span, why));
            }
            Op::Rotary { axis, .. } => {
                return Err(self.refuse(
                    r.span,
                    &format!(
                        "a move of the axis {}: expand writes the X, Y and Z moves only (a block that moved both would come out as two moves)",
                        *axis as char
                    ),
                ));
            }
            Op::Dwell { .. } | Op::Spindle { oriented: false, .. } if self.held.is_some() => {
                if let Some((_, after)) = self.held.as_mut() {
                    after.push(r.clone());
                }
                return Ok(());
            }
            Op::Dwell { seconds } => {
                s.push_str("G4 P");
                push_num(s, *seconds, DECIMALS);
            }
            Op::Spindle { oriented: true, .. } => {
                self.spindle_rpm = 0.0;
                match self.target {
                    Target::LinuxCnc => s.push_str("M19 R0"),
                    Target::Grbl => s.push_str("M5 (the spindle is oriented here: grbl has no M19)"),
                }
            }
            Op::Spindle { rpm, surface_m_min, .. } => {
                if surface_m_min.is_some() && !self.warned_css {
                    self.warned_css = true;
                    // The speed as the S word below writes it (S0.2 stays S0.2).
                    let mut shown = String::new();
                    push_num(&mut shown, rpm.abs(), 1);
                    self.note(r.span, format!("constant surface speed (G96) is written as the spindle speed of this moment, S{shown}: on the target it stays there while X changes (the feeds per minute are as ncsight computed them)"));
                }
                self.spindle(s, *rpm);
            }
            Op::Tool { number, offset } => match self.target {
                // G43: the target's own tool table gives the tool's offsets (H: the offset the
                // T word named).
                Target::LinuxCnc => match offset {
                    Some(h) if *h != 0 => s.push_str(&format!("T{number} M6 G43 H{h}")),
                    _ => s.push_str(&format!("T{number} M6 G43")),
                },
                Target::Grbl => s.push_str(&format!("M0 (change to tool {number}, then cycle start: grbl has no tool changer)")),
            },
            Op::Stop { reason } => match (reason, self.target) {
                (StopReason::ProgramStop, _) => s.push_str("M0"),
                (StopReason::OptionalStop, Target::LinuxCnc) => s.push_str("M1"),
                // grbl reads M1 and does nothing: the stop the operator asked for stays a stop.
                (StopReason::OptionalStop, Target::Grbl) => s.push_str("M0 (optional stop)"),
                (StopReason::ManualRetract, _) => s.push_str("M0 (retract the tool by hand, as after G88)"),
                // The operator's own buttons are not part of the programme.
                (StopReason::FeedHold | StopReason::SingleBlock | StopReason::Reset, _) => return Ok(()),
            },
            Op::End { .. } => {
                self.ended = true;
                s.push_str("M30");
            }
        }
        if let Some(p) = r.op.end_point() {
            self.last = Some(p);
        }
        s.push('\n');
        Ok(())
    }
}

impl Format for Expand {
    fn carries_diagnostics(&self) -> bool {
        false
    }

    fn take_notes(&mut self) -> Vec<Diagnostic> {
        std::mem::take(&mut self.notes)
    }

    fn event(&mut self, e: &Event, file: Option<&str>, w: &mut dyn Write) -> io::Result<()> {
        let Event::Record(r) = e else { return Ok(()) };
        let mut s = std::mem::take(&mut self.text);
        s.clear();
        if !self.started {
            self.started = true;
            self.header(&mut s);
        }
        let mut result = Ok(());
        if self.held.is_some() && !self.continues_held(r) {
            result = self.flush_held(&mut s);
        }
        let at = (file.map(file_label), r.span.line);
        if result.is_ok() && self.at.as_ref() != Some(&at) {
            match (&at.0, r.n) {
                (Some(f), _) => s.push_str(&format!("(line {} of {f})\n", at.1)),
                (None, Some(n)) => s.push_str(&format!("(line {} N{n})\n", at.1)),
                (None, None) => s.push_str(&format!("(line {})\n", at.1)),
            }
            self.at = Some(at);
        }
        if result.is_ok() {
            result = self.record(r, &mut s);
        }
        let written = w.write_all(s.as_bytes());
        self.text = s;
        result.and(written)
    }

    fn finish(&mut self, why: Option<&str>, w: &mut dyn Write) -> io::Result<()> {
        let mut s = String::new();
        if !self.started {
            self.started = true;
            self.header(&mut s);
        }
        if why.is_none() {
            self.flush_held(&mut s)?;
        }
        if !self.ended {
            let why = why.unwrap_or("the programme has no M02 or M30: its controller stops after its last block");
            s.push_str(&format!("({})\nM30\n", comment_text(why)));
            self.ended = true;
        }
        w.write_all(s.as_bytes())
    }
}
