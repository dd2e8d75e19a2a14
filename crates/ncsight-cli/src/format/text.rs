//! `--format text`: one aligned line per record for a person reading a terminal.

use super::{num, Format};
use ncsight::motion::{ArcDir, Op};
use ncsight::{Event, Profile, Vec3};
use std::io::{self, Write};

pub struct Text {
    profile: &'static Profile,
}

impl Text {
    pub fn new(profile: &'static Profile) -> Text {
        Text { profile }
    }

    fn point(&self, p: &Vec3, prefix: &str) -> String {
        let mut parts = Vec::new();
        for (axis, name) in [(0usize, 'X'), (1, 'Y'), (2, 'Z')] {
            if !self.profile.axes.contains(name) {
                continue;
            }
            let v = if axis == 0 && self.profile.diameter_x { p.x * 2.0 } else { p.axis(axis) };
            parts.push(format!("{prefix}{name}{}", num(v, 4)));
        }
        parts.join(" ")
    }
}

impl Format for Text {
    fn carries_diagnostics(&self) -> bool {
        false
    }

    fn event(&mut self, e: &Event, w: &mut dyn Write) -> io::Result<()> {
        let Event::Record(r) = e else { return Ok(()) };
        let what = match &r.op {
            Op::Rapid { to, .. } => self.point(to, ""),
            Op::Feed { to, feed_mm_min, .. } => format!("{}  F{} mm/min", self.point(to, ""), num(*feed_mm_min, 3)),
            Op::Arc { to, center, dir, feed_mm_min, .. } => format!(
                "{}  {} centre {}  F{} mm/min",
                self.point(to, ""),
                if *dir == ArcDir::Cw { "cw" } else { "ccw" },
                self.point(center, ""),
                num(*feed_mm_min, 3)
            ),
            Op::Thread { to, lead_mm, long_axis, spindle_deg, rpm, .. } => format!(
                "{}  lead {} along {}  from {} deg  {} rpm",
                self.point(to, ""),
                num(*lead_mm, 4),
                long_axis.as_str(),
                num(*spindle_deg, 3),
                num(*rpm, 1)
            ),
            Op::ThreadArc { to, center, dir, lead_mm, long_axis, spindle_deg, rpm, .. } => format!(
                "{}  {} centre {}  lead {} along {}  from {} deg  {} rpm",
                self.point(to, ""),
                if *dir == ArcDir::Cw { "cw" } else { "ccw" },
                self.point(center, ""),
                num(*lead_mm, 4),
                long_axis.as_str(),
                num(*spindle_deg, 3),
                num(*rpm, 1)
            ),
            Op::Dwell { seconds } => format!("{} s", num(*seconds, 3)),
            Op::Spindle { rpm, surface_m_min, position_mode, oriented } => {
                let mut s = format!("{} rpm", num(*rpm, 1));
                if *oriented {
                    s.push_str(" oriented stop");
                }
                if let Some(v) = surface_m_min {
                    s.push_str(&format!(" (G96 {} m/min)", num(*v, 1)));
                }
                if *position_mode {
                    s.push_str(" position mode");
                }
                s
            }
            Op::Tool { number, offset } => match offset {
                Some(o) => format!("T{number:02}{o:02}"),
                None => format!("T{number}"),
            },
            Op::Stop { reason } => reason.as_str().to_string(),
            Op::End { code } => format!("M{code:02}"),
        };
        writeln!(w, "{:>6}  {:<8} {:<60} t={}", r.span.line, r.op.kind(), what, num(r.t_s, 3))
    }
}
