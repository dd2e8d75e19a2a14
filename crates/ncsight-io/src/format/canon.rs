//! `--format canon`: the canonical-call text LinuxCNC's `rs274` prints, so that a programme in
//! the G-code both understand can be diffed against `rs274 -g`. Positions in mm with X as a
//! radius, four decimals. A thread record is wrapped as rs274 wraps a G33 move:
//! `START_SPEED_FEED_SYNC(lead,0)`, the move, `STOP_SPEED_FEED_SYNCH()`.

use super::{push_fixed, Format};
use ncsight::motion::{ArcDir, Op, Plane};
use ncsight::{Event, Profile, Vec3};
use std::fmt::Write as _;
use std::io::{self, Write};

pub struct Canon {
    feed: Option<f64>,
    plane: Option<Plane>,
    rpm: Option<f64>,
    /// The text of the record being written, reused.
    text: String,
}

/// `v` with four decimals and the separator rs274 puts after an argument.
fn arg(s: &mut String, v: f64) {
    push_fixed(s, v, 4);
    s.push_str(", ");
}

/// A straight move's arguments: X, Y, Z and the three rotary axes at zero.
fn xyz(s: &mut String, name: &str, p: &Vec3) {
    s.push_str(name);
    s.push('(');
    arg(s, p.x);
    arg(s, p.y);
    push_fixed(s, p.z, 4);
    s.push_str(", 0.0000, 0.0000, 0.0000)\n");
}

impl Canon {
    pub fn new(_profile: &'static Profile) -> Canon {
        Canon { feed: None, plane: None, rpm: None, text: String::with_capacity(256) }
    }

    fn set_feed(&mut self, f: f64, s: &mut String) {
        if self.feed != Some(f) {
            self.feed = Some(f);
            s.push_str("SET_FEED_RATE(");
            push_fixed(s, f, 4);
            s.push_str(")\n");
        }
    }

    fn arc(&mut self, to: &Vec3, center: &Vec3, plane: Plane, dir: ArcDir, s: &mut String) {
        if self.plane != Some(plane) {
            self.plane = Some(plane);
            let name = match plane {
                Plane::XY => "CANON_PLANE_XY",
                Plane::ZX => "CANON_PLANE_XZ",
                Plane::YZ => "CANON_PLANE_YZ",
            };
            let _ = writeln!(s, "SELECT_PLANE({name})");
        }
        let (a, b, n) = plane.axes();
        s.push_str("ARC_FEED(");
        for v in [to.axis(a), to.axis(b), center.axis(a), center.axis(b)] {
            arg(s, v);
        }
        s.push_str(if dir == ArcDir::Cw { "-1, " } else { "1, " });
        push_fixed(s, to.axis(n), 4);
        s.push_str(", 0.0000, 0.0000, 0.0000)\n");
    }

    /// The calls of one record, each line ending in a line break.
    fn record(&mut self, op: &Op, s: &mut String) {
        match op {
            Op::Rapid { to, .. } => xyz(s, "STRAIGHT_TRAVERSE", to),
            Op::Feed { to, feed_mm_min, .. } => {
                self.set_feed(*feed_mm_min, s);
                xyz(s, "STRAIGHT_FEED", to);
            }
            Op::Arc { to, center, plane, dir, feed_mm_min, .. } => {
                self.set_feed(*feed_mm_min, s);
                self.arc(to, center, *plane, *dir, s);
            }
            Op::Thread { to, lead_mm, .. } => {
                let _ = writeln!(s, "START_SPEED_FEED_SYNC({lead_mm:.6},0)");
                xyz(s, "STRAIGHT_FEED", to);
                s.push_str("STOP_SPEED_FEED_SYNCH()\n");
            }
            Op::ThreadArc { to, center, plane, dir, lead_mm, .. } => {
                let _ = writeln!(s, "START_SPEED_FEED_SYNC({lead_mm:.6},0)");
                self.arc(to, center, *plane, *dir, s);
                s.push_str("STOP_SPEED_FEED_SYNCH()\n");
            }
            Op::Dwell { seconds } => {
                s.push_str("DWELL(");
                push_fixed(s, *seconds, 4);
                s.push_str(")\n");
            }
            Op::Spindle { oriented: true, .. } => {
                self.rpm = None;
                s.push_str("ORIENT_SPINDLE(0, 0.0000, 0)\n");
            }
            Op::Spindle { rpm, .. } => {
                if *rpm == 0.0 {
                    self.rpm = None;
                    s.push_str("STOP_SPINDLE_TURNING(0)\n");
                    return;
                }
                if self.rpm != Some(rpm.abs()) {
                    self.rpm = Some(rpm.abs());
                    s.push_str("SET_SPINDLE_SPEED(0, ");
                    push_fixed(s, rpm.abs(), 4);
                    s.push_str(")\n");
                }
                s.push_str(if *rpm > 0.0 { "START_SPINDLE_CLOCKWISE(0)\n" } else { "START_SPINDLE_COUNTERCLOCKWISE(0)\n" });
            }
            Op::Tool { number, .. } => {
                let _ = writeln!(s, "SELECT_TOOL({number})\nCHANGE_TOOL({number})");
            }
            // The canonical calls here carry X, Y, Z only: a rotary turn is told, not moved.
            Op::Rotary { axis, to_deg, .. } => {
                let _ = writeln!(s, "COMMENT(\"rotary {} {to_deg:.4}\")", *axis as char);
            }
            Op::Stop { .. } => s.push_str("PROGRAM_STOP()\n"),
            Op::End { .. } => s.push_str("PROGRAM_END()\n"),
        }
    }
}

impl Format for Canon {
    fn carries_diagnostics(&self) -> bool {
        false
    }

    fn event(&mut self, e: &Event, _file: Option<&str>, w: &mut dyn Write) -> io::Result<()> {
        let Event::Record(r) = e else { return Ok(()) };
        let mut s = std::mem::take(&mut self.text);
        s.clear();
        self.record(&r.op, &mut s);
        let written = w.write_all(s.as_bytes());
        self.text = s;
        written
    }
}
