//! `--format text`: one aligned line per record for a person reading a terminal.

use super::{push_num, Format};
use ncsight::motion::{ArcDir, Op};
use ncsight::{Event, Profile, Vec3};
use std::fmt::Write as _;
use std::io::{self, Write};

pub struct Text {
    profile: &'static Profile,
    /// What the record does, then the whole line: reused.
    what: String,
    line: String,
    axes: super::ShownAxes,
    /// The time of the last record: the cycle time when the programme ends.
    last_t_s: f64,
}

fn dir_name(dir: ArcDir) -> &'static str {
    if dir == ArcDir::Cw {
        "cw"
    } else {
        "ccw"
    }
}

impl Text {
    pub fn new(profile: &'static Profile) -> Text {
        Text { profile, what: String::with_capacity(128), line: String::with_capacity(160), axes: super::ShownAxes::new(profile), last_t_s: 0.0 }
    }

    fn point(&self, s: &mut String, p: &Vec3) {
        let mut first = true;
        for (axis, name) in ['X', 'Y', 'Z'].into_iter().enumerate() {
            if !self.axes.show(axis, p) {
                continue;
            }
            if !first {
                s.push(' ');
            }
            first = false;
            let v = if axis == 0 && self.profile.diameter_x { p.x * 2.0 } else { p.axis(axis) };
            s.push(name);
            push_num(s, v, 4);
        }
    }

    fn thread(&self, s: &mut String, lead_mm: f64, long_axis: &str, spindle_deg: f64, rpm: f64) {
        s.push_str("  lead ");
        push_num(s, lead_mm, 4);
        let _ = write!(s, " along {long_axis}  from ");
        push_num(s, spindle_deg, 3);
        s.push_str(" deg  ");
        push_num(s, rpm, 1);
        s.push_str(" rpm");
    }

    /// What a record does, without its line, kind and time.
    fn what(&self, op: &Op, s: &mut String) {
        match op {
            Op::Rapid { to, .. } => self.point(s, to),
            Op::Feed { to, feed_mm_min, .. } => {
                self.point(s, to);
                s.push_str("  F");
                push_num(s, *feed_mm_min, 3);
                s.push_str(" mm/min");
            }
            Op::Arc { to, center, dir, feed_mm_min, .. } => {
                self.point(s, to);
                let _ = write!(s, "  {} centre ", dir_name(*dir));
                self.point(s, center);
                s.push_str("  F");
                push_num(s, *feed_mm_min, 3);
                s.push_str(" mm/min");
            }
            Op::Thread { to, lead_mm, long_axis, spindle_deg, rpm, .. } => {
                self.point(s, to);
                self.thread(s, *lead_mm, long_axis.as_str(), *spindle_deg, *rpm);
            }
            Op::ThreadArc { to, center, dir, lead_mm, long_axis, spindle_deg, rpm, .. } => {
                self.point(s, to);
                let _ = write!(s, "  {} centre ", dir_name(*dir));
                self.point(s, center);
                self.thread(s, *lead_mm, long_axis.as_str(), *spindle_deg, *rpm);
            }
            Op::Dwell { seconds } => {
                push_num(s, *seconds, 3);
                s.push_str(" s");
            }
            Op::Rotary { axis, to_deg, rate_deg_min, rapid, with_move, linear, .. } => {
                s.push(*axis as char);
                push_num(s, *to_deg, 3);
                if !*rapid {
                    s.push_str("  F");
                    push_num(s, *rate_deg_min, 3);
                    s.push_str(if *linear { " mm/min" } else { " deg/min" });
                }
                if *with_move {
                    s.push_str("  (with the move above)");
                }
            }
            Op::Spindle { rpm, surface_m_min, position_mode, oriented, p } => {
                push_num(s, *rpm, 1);
                s.push_str(" rpm");
                if *p != 0 {
                    let _ = write!(s, " (spindle P{p})");
                }
                if *oriented {
                    s.push_str(" oriented stop");
                }
                if let Some(v) = surface_m_min {
                    s.push_str(" (G96 ");
                    push_num(s, *v, 1);
                    s.push_str(" m/min)");
                }
                if *position_mode {
                    s.push_str(" position mode");
                }
            }
            Op::Tool { number, offset } => {
                let _ = match offset {
                    Some(o) => write!(s, "T{number:02}{o:02}"),
                    None => write!(s, "T{number}"),
                };
            }
            Op::Stop { reason } => s.push_str(reason.as_str()),
            Op::End { code } => {
                let _ = write!(s, "M{code:02}");
            }
        }
    }
}

impl Format for Text {
    fn carries_diagnostics(&self) -> bool {
        false
    }

    fn event(&mut self, e: &Event, file: Option<&str>, w: &mut dyn Write) -> io::Result<()> {
        let Event::Record(r) = e else { return Ok(()) };
        let (mut what, mut line) = (std::mem::take(&mut self.what), std::mem::take(&mut self.line));
        what.clear();
        line.clear();
        self.what(&r.op, &mut what);
        match file {
            Some(f) => {
                let _ = write!(line, "{f}:{}  {:<8} {:<60} t=", r.span.line, r.op.kind(), what);
            }
            None => {
                let _ = write!(line, "{:>6}  {:<8} {:<60} t=", r.span.line, r.op.kind(), what);
            }
        }
        push_num(&mut line, r.t_s, 3);
        line.push('\n');
        self.last_t_s = r.t_s;
        let written = w.write_all(line.as_bytes());
        (self.what, self.line) = (what, line);
        written
    }

    /// The last line says the time in h:mm:ss: the cycle time, or the time to where it stopped.
    fn finish(&mut self, why: Option<&str>, w: &mut dyn Write) -> io::Result<()> {
        let what = if why.is_some() { "time to the stop" } else { "cycle time" };
        let mut line = format!("{what} {} (", hms(self.last_t_s));
        push_num(&mut line, self.last_t_s, 3);
        line.push_str(" s)\n");
        w.write_all(line.as_bytes())
    }
}

/// Seconds as h:mm:ss, rounded to the second (as a controller's run-time display shows it).
pub fn hms(t_s: f64) -> String {
    let whole = t_s.max(0.0).round() as u64;
    format!("{}:{:02}:{:02}", whole / 3600, whole / 60 % 60, whole % 60)
}

#[cfg(test)]
mod tests {
    #[test]
    fn hms_rounds_to_the_second() {
        assert_eq!(super::hms(12.088), "0:00:12");
        assert_eq!(super::hms(3599.6), "1:00:00");
        assert_eq!(super::hms(7384.4), "2:03:04");
        assert_eq!(super::hms(0.0), "0:00:00");
    }
}
