//! `--format jsonl`: one JSON object per line, field for field as ../shared/spec/INTERFACE.md
//! says. Lathe X is shown as a diameter; axes the machine lacks are left out.

use super::{num, Format};
use ncsight::motion::{ArcDir, Op};
use ncsight::{Event, Profile, Severity, Vec3};
use std::io::{self, Write};

pub struct Jsonl {
    profile: &'static Profile,
    x_scale: f64,
}

impl Jsonl {
    pub fn new(profile: &'static Profile) -> Jsonl {
        Jsonl { profile, x_scale: if profile.diameter_x { 2.0 } else { 1.0 } }
    }

    fn point(&self, s: &mut String, p: &Vec3, prefix: &str) {
        for (axis, name) in [(0usize, "x"), (1, "y"), (2, "z")] {
            if !self.profile.axes.contains(name.to_ascii_uppercase().as_str()) {
                continue;
            }
            let v = if axis == 0 { p.x * self.x_scale } else { p.axis(axis) };
            s.push_str(&format!(",\"{prefix}{name}\":{}", num(v, 4)));
        }
    }
}

/// A JSON string literal.
pub fn json_str(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn thread_fields(s: &mut String, lead: f64, long_axis: &str, spindle_deg: f64, rpm: f64) {
    // 360 - 1e-7 would print as 360: keep the interface's [0, 360).
    let deg = if num(spindle_deg, 6) == "360" { 0.0 } else { spindle_deg };
    s.push_str(&format!(
        ",\"lead\":{},\"long_axis\":\"{long_axis}\",\"spindle_deg\":{},\"rpm\":{}",
        num(lead, 6),
        num(deg, 6),
        num(rpm, 3)
    ));
}

impl Format for Jsonl {
    fn carries_diagnostics(&self) -> bool {
        true
    }

    fn event(&mut self, e: &Event, w: &mut dyn Write) -> io::Result<()> {
        let mut s = String::with_capacity(128);
        match e {
            Event::Diagnostic(d) => {
                let kind = if d.severity() == Severity::Alarm { "alarm" } else { "warning" };
                s.push_str(&format!(
                    "{{\"line\":{},\"kind\":\"{kind}\",\"code\":{},\"message\":{},\"col\":{}",
                    d.span.line,
                    json_str(d.code),
                    json_str(&d.message),
                    d.span.col
                ));
                if let Some(h) = &d.hint {
                    s.push_str(&format!(",\"hint\":{}", json_str(h)));
                }
                s.push('}');
            }
            Event::Record(r) => {
                s.push_str(&format!("{{\"line\":{},\"kind\":\"{}\"", r.span.line, r.op.kind()));
                match &r.op {
                    Op::Rapid { to, .. } => self.point(&mut s, to, ""),
                    Op::Feed { to, feed_mm_min, .. } => {
                        self.point(&mut s, to, "");
                        s.push_str(&format!(",\"f\":{}", num(*feed_mm_min, 4)));
                    }
                    Op::Arc { to, center, dir, feed_mm_min, .. } => {
                        self.point(&mut s, to, "");
                        self.point(&mut s, center, "c");
                        let d = if *dir == ArcDir::Cw { "cw" } else { "ccw" };
                        s.push_str(&format!(",\"dir\":\"{d}\",\"f\":{}", num(*feed_mm_min, 4)));
                    }
                    Op::Thread { to, lead_mm, long_axis, spindle_deg, rpm, .. } => {
                        self.point(&mut s, to, "");
                        thread_fields(&mut s, *lead_mm, long_axis.as_str(), *spindle_deg, *rpm);
                    }
                    Op::ThreadArc { to, center, dir, lead_mm, long_axis, spindle_deg, rpm, .. } => {
                        self.point(&mut s, to, "");
                        self.point(&mut s, center, "c");
                        let d = if *dir == ArcDir::Cw { "cw" } else { "ccw" };
                        s.push_str(&format!(",\"dir\":\"{d}\""));
                        thread_fields(&mut s, *lead_mm, long_axis.as_str(), *spindle_deg, *rpm);
                    }
                    Op::Dwell { seconds } => s.push_str(&format!(",\"seconds\":{}", num(*seconds, 6))),
                    Op::Spindle { rpm, surface_m_min, position_mode, oriented } => {
                        s.push_str(&format!(",\"rpm\":{}", num(*rpm, 3)));
                        if *oriented {
                            s.push_str(",\"oriented\":true");
                        }
                        if let Some(v) = surface_m_min {
                            s.push_str(&format!(",\"surface_m_min\":{}", num(*v, 3)));
                        }
                        let mode = if *position_mode { "position" } else { "speed" };
                        s.push_str(&format!(",\"mode\":\"{mode}\""));
                    }
                    Op::Tool { number, offset } => {
                        s.push_str(&format!(",\"tool\":{number}"));
                        if let Some(o) = offset {
                            s.push_str(&format!(",\"offset\":{o}"));
                        }
                    }
                    Op::Stop { reason } => s.push_str(&format!(",\"reason\":\"{}\"", reason.as_str())),
                    Op::End { code } => s.push_str(&format!(",\"code\":\"M{code:02}\"")),
                }
                s.push_str(&format!(",\"t\":{}}}", num(r.t_s, 6)));
            }
        }
        s.push('\n');
        w.write_all(s.as_bytes())
    }
}
