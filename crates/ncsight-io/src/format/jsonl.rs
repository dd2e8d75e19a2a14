//! `--format jsonl`: one JSON object per line, field for field as docs/reference/interface.md
//! says. Lathe X is shown as a diameter; axes the machine lacks are left out.

use super::{push_num, Format};
use ncsight::motion::{ArcDir, Op};
use ncsight::{Event, Profile, Severity, Vec3};
use std::fmt::Write as _;
use std::io::{self, Write};

pub struct Jsonl {
    axes: super::ShownAxes,
    /// Motion records carry `machine_x/_y/_z` (a setup gave the machine's frame).
    machine_positions: bool,
    x_scale: f64,
    /// The line being written, reused.
    text: String,
}

impl Jsonl {
    pub fn new(profile: &'static Profile, machine_positions: bool) -> Jsonl {
        Jsonl { axes: super::ShownAxes::new(profile), machine_positions, x_scale: if profile.diameter_x { 2.0 } else { 1.0 }, text: String::with_capacity(256) }
    }

    fn point(&self, s: &mut String, p: &Vec3, prefix: &str) {
        for (axis, name) in ["x", "y", "z"].into_iter().enumerate() {
            if !self.axes.show(axis, p) {
                continue;
            }
            let v = if axis == 0 { p.x * self.x_scale } else { p.axis(axis) };
            field(s, prefix, name);
            push_num(s, v, 4);
        }
    }
}

/// `,"<prefix><name>":` before a value.
fn field(s: &mut String, prefix: &str, name: &str) {
    s.push_str(",\"");
    s.push_str(prefix);
    s.push_str(name);
    s.push_str("\":");
}

/// A field with a number of at most `decimals` decimals.
fn num_field(s: &mut String, name: &str, v: f64, decimals: usize) {
    field(s, "", name);
    push_num(s, v, decimals);
}

/// Append a JSON string literal.
/// A JSON string literal.
pub fn json_str(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    push_json_str(&mut out, s);
    out
}

/// Append a JSON string literal.
pub fn push_json_str(out: &mut String, s: &str) {
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

fn thread_fields(s: &mut String, lead: f64, long_axis: &str, spindle_deg: f64, rpm: f64) {
    // 360 - 1e-7 would print as 360: keep the interface's [0, 360).
    let deg = if super::num(spindle_deg, 6) == "360" { 0.0 } else { spindle_deg };
    num_field(s, "lead", lead, 6);
    let _ = write!(s, ",\"long_axis\":\"{long_axis}\"");
    num_field(s, "spindle_deg", deg, 6);
    num_field(s, "rpm", rpm, 3);
}

fn dir_field(s: &mut String, dir: ArcDir) {
    s.push_str(if dir == ArcDir::Cw { ",\"dir\":\"cw\"" } else { ",\"dir\":\"ccw\"" });
}

/// The calling blocks of a diagnostic raised in a subprogramme: `"calls":[{"line":..,"col":..},..]`,
/// outermost first (the file of each is the file of the call, shown by `file` where it differs).
fn calls_field(s: &mut String, calls: &[ncsight::source::Span]) {
    if calls.is_empty() {
        return;
    }
    s.push_str(",\"calls\":[");
    for (i, c) in calls.iter().enumerate() {
        if i > 0 {
            s.push(',');
        }
        let _ = write!(s, "{{\"line\":{},\"col\":{}}}", c.line, c.col);
    }
    s.push(']');
}

/// One diagnostic as `check --format jsonl` writes it (docs/reference/interface.md, "check --format jsonl"):
/// file, line, col, severity, code, message and the hint where there is one.
pub fn diagnostic_line(file: &str, d: &ncsight::Diagnostic) -> String {
    let mut s = String::with_capacity(160);
    s.push_str("{\"file\":");
    push_json_str(&mut s, file);
    let severity = if d.severity() == Severity::Alarm { "alarm" } else { "warning" };
    let _ = write!(s, ",\"line\":{},\"col\":{},\"severity\":\"{severity}\",\"code\":", d.span.line, d.span.col);
    push_json_str(&mut s, d.code);
    s.push_str(",\"message\":");
    push_json_str(&mut s, &d.message);
    if let Some(h) = &d.hint {
        s.push_str(",\"hint\":");
        push_json_str(&mut s, h);
    }
    calls_field(&mut s, &d.calls);
    s.push_str("}\n");
    s
}

impl Jsonl {
    fn line(&self, e: &Event, file: Option<&str>, s: &mut String) {
        let file_field = |s: &mut String| {
            if let Some(f) = file {
                s.push_str(",\"file\":");
                push_json_str(s, f);
            }
        };
        match e {
            Event::Diagnostic(d) => {
                let kind = if d.severity() == Severity::Alarm { "alarm" } else { "warning" };
                let _ = write!(s, "{{\"line\":{}", d.span.line);
                file_field(s);
                let _ = write!(s, ",\"kind\":\"{kind}\",\"code\":");
                push_json_str(s, d.code);
                s.push_str(",\"message\":");
                push_json_str(s, &d.message);
                let _ = write!(s, ",\"col\":{}", d.span.col);
                if let Some(h) = &d.hint {
                    s.push_str(",\"hint\":");
                    push_json_str(s, h);
                }
                calls_field(s, &d.calls);
                s.push('}');
            }
            Event::Record(r) => {
                let _ = write!(s, "{{\"line\":{}", r.span.line);
                file_field(s);
                let _ = write!(s, ",\"kind\":\"{}\"", r.op.kind());
                match &r.op {
                    Op::Rapid { to, .. } => self.point(s, to, ""),
                    Op::Feed { to, feed_mm_min, .. } => {
                        self.point(s, to, "");
                        num_field(s, "f", *feed_mm_min, 4);
                    }
                    Op::Arc { to, center, dir, feed_mm_min, .. } => {
                        self.point(s, to, "");
                        self.point(s, center, "c");
                        dir_field(s, *dir);
                        num_field(s, "f", *feed_mm_min, 4);
                    }
                    Op::Thread { to, lead_mm, long_axis, spindle_deg, rpm, .. } => {
                        self.point(s, to, "");
                        thread_fields(s, *lead_mm, long_axis.as_str(), *spindle_deg, *rpm);
                    }
                    Op::ThreadArc { to, center, dir, lead_mm, long_axis, spindle_deg, rpm, .. } => {
                        self.point(s, to, "");
                        self.point(s, center, "c");
                        dir_field(s, *dir);
                        thread_fields(s, *lead_mm, long_axis.as_str(), *spindle_deg, *rpm);
                    }
                    Op::Dwell { seconds } => num_field(s, "seconds", *seconds, 6),
                    Op::Rotary { axis, to_deg, rate_deg_min, rapid, with_move, .. } => {
                        let _ = write!(s, ",\"axis\":\"{}\"", axis.to_ascii_lowercase() as char);
                        num_field(s, &(axis.to_ascii_lowercase() as char).to_string(), *to_deg, 4);
                        if !*rapid {
                            num_field(s, "f", *rate_deg_min, 4);
                        }
                        if *with_move {
                            s.push_str(",\"with_move\":true");
                        }
                    }
                    Op::Spindle { rpm, surface_m_min, position_mode, oriented, p } => {
                        num_field(s, "rpm", *rpm, 3);
                        if *p != 0 {
                            let _ = write!(s, ",\"spindle_p\":{p}");
                        }
                        if *oriented {
                            s.push_str(",\"oriented\":true");
                        }
                        if let Some(v) = surface_m_min {
                            num_field(s, "surface_m_min", *v, 3);
                        }
                        s.push_str(if *position_mode { ",\"mode\":\"position\"" } else { ",\"mode\":\"speed\"" });
                    }
                    Op::Tool { number, offset } => {
                        let _ = write!(s, ",\"tool\":{number}");
                        if let Some(o) = offset {
                            let _ = write!(s, ",\"offset\":{o}");
                        }
                    }
                    Op::Stop { reason } => {
                        let _ = write!(s, ",\"reason\":\"{}\"", reason.as_str());
                    }
                    Op::End { code } => {
                        let _ = write!(s, ",\"code\":\"M{code:02}\"");
                    }
                }
                if self.machine_positions {
                    if let Some(to) = r.op.end_point() {
                        self.point(s, &(to + r.to_machine), "machine_");
                    }
                }
                num_field(s, "t", r.t_s, 6);
                if let Some(n) = r.n {
                    let _ = write!(s, ",\"n\":{n}");
                }
                let _ = write!(s, ",\"call_depth\":{}", r.call_depth);
                s.push('}');
            }
        }
        s.push('\n');
    }
}

impl Format for Jsonl {
    fn carries_diagnostics(&self) -> bool {
        true
    }

    fn event(&mut self, e: &Event, file: Option<&str>, w: &mut dyn Write) -> io::Result<()> {
        let mut s = std::mem::take(&mut self.text);
        s.clear();
        self.line(e, file, &mut s);
        let written = w.write_all(s.as_bytes());
        self.text = s;
        written
    }
}
