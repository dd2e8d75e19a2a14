//! `--format canon`: the canonical-call text LinuxCNC's `rs274` prints, so that a programme in
//! the G-code both understand can be diffed against `rs274 -g`. Positions in mm with X as a
//! radius, four decimals. A thread record is wrapped as rs274 wraps a G33 move:
//! `START_SPEED_FEED_SYNC(lead,0)`, the move, `STOP_SPEED_FEED_SYNCH()`.

use super::{fixed, Format};
use ncsight::motion::{ArcDir, Op, Plane};
use ncsight::{Event, Profile, Vec3};
use std::io::{self, Write};

pub struct Canon {
    feed: Option<f64>,
    plane: Option<Plane>,
    rpm: Option<f64>,
}

impl Canon {
    pub fn new(_profile: &'static Profile) -> Canon {
        Canon { feed: None, plane: None, rpm: None }
    }

    fn set_feed(&mut self, f: f64, w: &mut dyn Write) -> io::Result<()> {
        if self.feed != Some(f) {
            self.feed = Some(f);
            writeln!(w, "SET_FEED_RATE({})", fixed(f, 4))?;
        }
        Ok(())
    }

    fn arc(&mut self, to: &Vec3, center: &Vec3, plane: Plane, dir: ArcDir, w: &mut dyn Write) -> io::Result<()> {
        if self.plane != Some(plane) {
            self.plane = Some(plane);
            let name = match plane {
                Plane::XY => "CANON_PLANE_XY",
                Plane::ZX => "CANON_PLANE_XZ",
                Plane::YZ => "CANON_PLANE_YZ",
            };
            writeln!(w, "SELECT_PLANE({name})")?;
        }
        let (a, b, n) = plane.axes();
        let rot = if dir == ArcDir::Cw { -1 } else { 1 };
        writeln!(
            w,
            "ARC_FEED({}, {}, {}, {}, {rot}, {}, 0.0000, 0.0000, 0.0000)",
            fixed(to.axis(a), 4),
            fixed(to.axis(b), 4),
            fixed(center.axis(a), 4),
            fixed(center.axis(b), 4),
            fixed(to.axis(n), 4)
        )
    }
}

fn xyz(p: &Vec3) -> String {
    format!("{}, {}, {}, 0.0000, 0.0000, 0.0000", fixed(p.x, 4), fixed(p.y, 4), fixed(p.z, 4))
}

impl Format for Canon {
    fn carries_diagnostics(&self) -> bool {
        false
    }

    fn event(&mut self, e: &Event, w: &mut dyn Write) -> io::Result<()> {
        let Event::Record(r) = e else { return Ok(()) };
        match &r.op {
            Op::Rapid { to, .. } => writeln!(w, "STRAIGHT_TRAVERSE({})", xyz(to)),
            Op::Feed { to, feed_mm_min, .. } => {
                self.set_feed(*feed_mm_min, w)?;
                writeln!(w, "STRAIGHT_FEED({})", xyz(to))
            }
            Op::Arc { to, center, plane, dir, feed_mm_min, .. } => {
                self.set_feed(*feed_mm_min, w)?;
                self.arc(to, center, *plane, *dir, w)
            }
            Op::Thread { to, lead_mm, .. } => {
                writeln!(w, "START_SPEED_FEED_SYNC({lead_mm:.6},0)")?;
                writeln!(w, "STRAIGHT_FEED({})", xyz(to))?;
                writeln!(w, "STOP_SPEED_FEED_SYNCH()")
            }
            Op::ThreadArc { to, center, plane, dir, lead_mm, .. } => {
                writeln!(w, "START_SPEED_FEED_SYNC({lead_mm:.6},0)")?;
                self.arc(to, center, *plane, *dir, w)?;
                writeln!(w, "STOP_SPEED_FEED_SYNCH()")
            }
            Op::Dwell { seconds } => writeln!(w, "DWELL({})", fixed(*seconds, 4)),
            Op::Spindle { oriented: true, .. } => {
                self.rpm = None;
                writeln!(w, "ORIENT_SPINDLE(0, 0.0000, 0)")
            }
            Op::Spindle { rpm, .. } => {
                if *rpm == 0.0 {
                    self.rpm = None;
                    return writeln!(w, "STOP_SPINDLE_TURNING(0)");
                }
                if self.rpm != Some(rpm.abs()) {
                    self.rpm = Some(rpm.abs());
                    writeln!(w, "SET_SPINDLE_SPEED(0, {})", fixed(rpm.abs(), 4))?;
                }
                if *rpm > 0.0 {
                    writeln!(w, "START_SPINDLE_CLOCKWISE(0)")
                } else {
                    writeln!(w, "START_SPINDLE_COUNTERCLOCKWISE(0)")
                }
            }
            Op::Tool { number, .. } => writeln!(w, "SELECT_TOOL({number})\nCHANGE_TOOL({number})"),
            Op::Stop { .. } => writeln!(w, "PROGRAM_STOP()"),
            Op::End { .. } => writeln!(w, "PROGRAM_END()"),
        }
    }
}
