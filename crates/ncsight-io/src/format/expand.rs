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

pub struct Expand {
    target: Target,
    lathe: bool,
    axes: [bool; 3],
    style: ncsight::alarm::AlarmStyle,
    source: String,
    machine: &'static str,
    started: bool,
    feed: Option<f64>,
    plane: Option<Plane>,
    /// The source line (file, line) of the last record written.
    at: Option<(Option<String>, u32)>,
    /// Warnings about what the target cannot express exactly (NCS-W29), once each.
    notes: Vec<Diagnostic>,
    warned_start_angle: bool,
    /// Where the last thread record ended, while the next record may continue it.
    thread_end: Option<Vec3>,
    /// The spindle as last written: rpm, signed (0: stopped).
    spindle_rpm: f64,
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
            // The header's plane.
            plane: Some(if profile.is_lathe() { Plane::ZX } else { Plane::XY }),
            at: None,
            notes: Vec::new(),
            warned_start_angle: false,
            thread_end: None,
            spindle_rpm: 0.0,
            text: String::with_capacity(256),
        }
    }

    /// What the target could not express exactly, said once each.
    pub fn take_notes(&mut self) -> Vec<Diagnostic> {
        std::mem::take(&mut self.notes)
    }

    fn header(&self, s: &mut String) {
        s.push_str(&format!("(expanded by ncsight from {} as it runs on {}, for {})\n", self.source, self.machine, self.target.title()));
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

    fn feed(&mut self, s: &mut String, f: f64) {
        if self.feed != Some(f) {
            self.feed = Some(f);
            s.push_str(" F");
            push_num(s, f, DECIMALS);
        }
    }

    fn plane(&mut self, s: &mut String, plane: Plane) {
        if self.plane != Some(plane) {
            self.plane = Some(plane);
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

    /// The G-code of one record, each line ending in a line break.
    fn record(&mut self, r: &ncsight::Record, s: &mut String) -> io::Result<()> {
        if !matches!(r.op, Op::Thread { .. }) {
            self.thread_end = None;
        }
        match &r.op {
            Op::Rapid { to, .. } => {
                s.push_str("G0");
                self.point(s, to);
            }
            Op::Feed { to, feed_mm_min, .. } => {
                s.push_str("G1");
                self.point(s, to);
                self.feed(s, *feed_mm_min);
            }
            Op::Arc { from, to, center, plane, dir, feed_mm_min } => {
                self.arc(s, from, to, center, *plane, *dir);
                self.feed(s, *feed_mm_min);
            }
            Op::Thread { from, to, lead_mm, long_axis, spindle_deg, rpm } => {
                if self.target == Target::Grbl {
                    return Err(self.refuse(r.span, "a thread needs motion synchronised with the spindle, which grbl does not have"));
                }
                // LinuxCNC's K is the distance along the path per revolution (the EMC2
                // manual, G33: "the distance moved in XYZ for each revolution"); the FANUC and
                // GSK lead is along the thread's long axis: on a taper K is longer (inferred).
                let long = match long_axis {
                    LongAxis::X => (to.x - from.x).abs(),
                    LongAxis::Y => (to.y - from.y).abs(),
                    LongAxis::Z => (to.z - from.z).abs(),
                };
                let path = ((to.x - from.x).powi(2) + (to.y - from.y).powi(2) + (to.z - from.z).powi(2)).sqrt();
                let k = if long > 1e-9 { lead_mm * path / long } else { *lead_mm };
                // Only where a synchronised run begins: a pass's pull-out continues the thread
                // from where it ended (LinuxCNC joins consecutive G33 moves).
                let begins = self.thread_end.map_or(true, |p| (p.x - from.x).abs() + (p.y - from.y).abs() + (p.z - from.z).abs() > 1e-6);
                self.thread_end = Some(*to);
                let deg = spindle_deg.rem_euclid(360.0);
                if begins && deg > 0.01 && deg < 359.99 && !self.warned_start_angle {
                    self.warned_start_angle = true;
                    let msg = format!("this thread starts {deg:.1} degrees after the spindle's index pulse (a multi-start or shifted thread); LinuxCNC's G33 always starts at the pulse, so such passes are written as if they started there");
                    self.notes.push(Diagnostic::new(Rule::ExpandApproximate, self.style, r.span, msg));
                }
                // A rigid thread (G32.1 in the spindle's position mode) turns the spindle itself:
                // LinuxCNC's G33 needs it turning at that speed first.
                if *rpm != 0.0 && (self.spindle_rpm == 0.0 || self.spindle_rpm.signum() != rpm.signum()) {
                    self.spindle(s, *rpm);
                    s.push('\n');
                }
                s.push_str("G33");
                self.point(s, to);
                Self::coord(s, 'K', k);
            }
            Op::ThreadArc { .. } => {
                let why = match self.target {
                    Target::Grbl => "a thread needs motion synchronised with the spindle, which grbl does not have",
                    Target::LinuxCnc => "an arc thread (G32.2/G32.3) needs a spindle-synchronised arc, and LinuxCNC's G33 is straight only",
                };
                return Err(self.refuse(r.span, why));
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
            Op::Spindle { rpm, .. } => self.spindle(s, *rpm),
            Op::Tool { number, .. } => match self.target {
                Target::LinuxCnc => s.push_str(&format!("T{number} M6")),
                Target::Grbl => s.push_str(&format!("M0 (change to tool {number}, then cycle start: grbl has no tool changer)")),
            },
            Op::Stop { reason } => match reason {
                StopReason::ProgramStop => s.push_str("M0"),
                StopReason::OptionalStop => s.push_str("M1"),
                StopReason::ManualRetract => s.push_str("M0 (retract the tool by hand, as after G88)"),
                // The operator's own buttons are not part of the programme.
                StopReason::FeedHold | StopReason::SingleBlock | StopReason::Reset => return Ok(()),
            },
            Op::End { .. } => s.push_str("M30"),
        }
        s.push('\n');
        Ok(())
    }
}

impl Format for Expand {
    fn carries_diagnostics(&self) -> bool {
        false
    }

    fn event(&mut self, e: &Event, file: Option<&str>, w: &mut dyn Write) -> io::Result<()> {
        let Event::Record(r) = e else { return Ok(()) };
        let mut s = std::mem::take(&mut self.text);
        s.clear();
        if !self.started {
            self.started = true;
            self.header(&mut s);
        }
        let at = (file.map(str::to_string), r.span.line);
        if self.at.as_ref() != Some(&at) {
            match (&at.0, r.n) {
                (Some(f), _) => s.push_str(&format!("({f} line {})\n", at.1)),
                (None, Some(n)) => s.push_str(&format!("(line {} N{n})\n", at.1)),
                (None, None) => s.push_str(&format!("(line {})\n", at.1)),
            }
            self.at = Some(at);
        }
        let result = self.record(r, &mut s);
        let written = w.write_all(s.as_bytes());
        self.text = s;
        result.and(written)
    }
}
