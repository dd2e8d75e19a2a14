//! `ncsight report`: one self-contained HTML page (styles, script and data inline, no network
//! request of any kind) that shows a person what the programme does: the backplot, a player over
//! time, the source with its alarms, the thread form from the stock simulation, the time
//! breakdown and the parameters.
//!
//! Programme text is untrusted: it goes into the page only as JSON inside a
//! `<script type="application/json">` element, with `<` written `\u003c`, and the page's script
//! puts it into the document with `textContent`, never as markup.

use crate::format::jsonl::json_str;
use crate::format::num;
use ncsight::motion::{Op, Record};
use ncsight::profile::Params;
use ncsight::stock::measure::Simulation;
use ncsight::{Diagnostic, Severity};
use std::fmt::Write as _;
use std::io::{self, Write};

/// Most points drawn; beyond it the drawing is thinned (the tables keep everything).
const MAX_DRAWN_POINTS: usize = 60_000;

/// What the page shows.
pub struct Report<'a> {
    pub file_name: &'a str,
    pub source: &'a [u8],
    pub params: &'a Params,
    pub records: &'a [Record],
    pub diagnostics: &'a [Diagnostic],
    pub sim: Option<&'a Simulation>,
    /// How lines that are not UTF-8 are decoded.
    pub decoding: crate::diag::Decoding,
    /// Why the thread could not be simulated, when it could not.
    pub sim_error: Option<&'a str>,
    /// The operator's options and switches, described.
    pub settings: Vec<String>,
}

fn esc_html(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// JSON safe inside a script element: no `<` at all.
fn script_safe(json: &str) -> String {
    json.replace('<', "\\u003c").replace('>', "\\u003e").replace('&', "\\u0026")
}

fn kind_code(op: &Op) -> &'static str {
    match op {
        Op::Rapid { .. } => "r",
        Op::Feed { .. } => "f",
        Op::Arc { .. } => "a",
        Op::Thread { .. } => "t",
        Op::ThreadArc { .. } => "ta",
        _ => "",
    }
}

impl Report<'_> {
    /// Display coordinates of a point: lathe (z, x as a diameter), mill (x, y, z).
    fn pt(&self, lathe: bool, p: &ncsight::Vec3) -> String {
        if lathe {
            format!("[{},{}]", num(p.z, 4), num(2.0 * p.x, 4))
        } else {
            format!("[{},{},{}]", num(p.x, 4), num(p.y, 4), num(p.z, 4))
        }
    }

    fn data(&self) -> String {
        let profile = self.params.profile();
        let lathe = profile.is_lathe();
        let mut s = String::with_capacity(1 << 16);
        // Each line as written: UTF-8, or GB18030 / the --encoding where it is not (GSK comments).
        let source = self.source.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(self.source);
        let lines: Vec<String> = source
            .split(|&b| b == b'\n')
            .map(|l| json_str(&self.decoding.decode(l.strip_suffix(b"\r").unwrap_or(l))))
            .collect();
        let lines = if source.ends_with(b"\n") { &lines[..lines.len() - 1] } else { &lines[..] };
        let _ = write!(
            s,
            "{{\"file\":{},\"machine\":{},\"title\":{},\"lathe\":{lathe},\"lines\":[{}],",
            json_str(self.file_name),
            json_str(profile.name),
            json_str(profile.title),
            lines.join(",")
        );
        // Segments: kind, line, t0, t1, points; threads add angle, lead, rpm, pass, pull-out.
        let total_points: usize = self.records.iter().filter(|r| kind_code(&r.op) != "").count() * 2;
        let thin = total_points > MAX_DRAWN_POINTS;
        s.push_str("\"segs\":[");
        let mut t0 = 0.0;
        let mut pass = 0u32;
        let mut prev_thread_end = None;
        let mut first = true;
        for r in self.records {
            let k = kind_code(&r.op);
            if k.is_empty() {
                t0 = r.t_s;
                prev_thread_end = None;
                continue;
            }
            let (from, to) = (r.op.start_point().unwrap(), r.op.end_point().unwrap());
            let mut pts = vec![self.pt(lathe, &from)];
            if let (Op::Arc { plane, dir, .. } | Op::ThreadArc { plane, dir, .. }, Some(g)) = (&r.op, ncsight::geom::arc_geom_of(&r.op)) {
                let n = if thin { 4 } else { (g.sweep_rad.to_degrees() / 5.0).ceil().clamp(4.0, 72.0) as usize };
                for i in 1..n {
                    pts.push(self.pt(lathe, &ncsight::geom::arc_point(&from, &to, *plane, *dir, &g, i as f64 / n as f64)));
                }
            }
            pts.push(self.pt(lathe, &to));
            if !first {
                s.push(',');
            }
            first = false;
            let _ = write!(s, "{{\"k\":\"{k}\",\"l\":{},\"t0\":{},\"t1\":{},\"p\":[{}]", source_line(r.span), num(t0, 4), num(r.t_s, 4), pts.join(","));
            if let Op::Thread { lead_mm, spindle_deg, rpm, long_axis, .. } | Op::ThreadArc { lead_mm, spindle_deg, rpm, long_axis, .. } = r.op {
                let continues = prev_thread_end == Some(from);
                if !continues {
                    pass += 1;
                }
                // A pull-out: a record that goes on a run and moves the short axis.
                let (_, short) = long_axis.indices();
                let pull = continues && (to.axis(short) - from.axis(short)).abs() > 1e-9;
                let _ = write!(
                    s,
                    ",\"deg\":{},\"lead\":{},\"rpm\":{},\"la\":\"{}\",\"pass\":{pass},\"pull\":{pull}",
                    num(spindle_deg, 3),
                    num(lead_mm, 4),
                    num(rpm, 1),
                    long_axis.as_str()
                );
                prev_thread_end = Some(to);
            } else {
                prev_thread_end = None;
            }
            if let Op::Feed { feed_mm_min, .. } | Op::Arc { feed_mm_min, .. } = r.op {
                let _ = write!(s, ",\"f\":{}", num(feed_mm_min, 2));
            }
            if r.block_end {
                s.push_str(",\"be\":1");
            }
            s.push('}');
            t0 = r.t_s;
        }
        s.push_str("],");
        let _ = write!(s, "\"passes\":{pass},\"thin\":{thin},");
        // Other records: spindle, stops, tools, dwells, ends.
        s.push_str("\"events\":[");
        let mut before_s = 0.0;
        let evs: Vec<String> = self
            .records
            .iter()
            .filter_map(|r| {
                let took_s = r.t_s - std::mem::replace(&mut before_s, r.t_s);
                let what = match &r.op {
                    // A rotary axis's turn: the time it adds (the plot shows X, Y, Z only).
                    Op::Rotary { axis, to_deg, .. } => format!("\"rotary\",\"axis\":\"{}\",\"deg\":{},\"s\":{}", *axis as char, num(*to_deg, 3), num(took_s.max(0.0), 4)),
                    Op::Spindle { rpm, oriented, .. } => format!("\"spindle\",\"rpm\":{}{}", num(*rpm, 1), if *oriented { ",\"oriented\":true" } else { "" }),
                    Op::Stop { reason } => format!("\"stop\",\"reason\":\"{}\"", reason.as_str()),
                    Op::Tool { number, .. } => format!("\"tool\",\"tool\":{number}"),
                    Op::Dwell { seconds } => format!("\"dwell\",\"s\":{}", num(*seconds, 3)),
                    Op::End { code } => format!("\"end\",\"code\":{code}"),
                    _ => return None,
                };
                Some(format!("{{\"k\":{what},\"l\":{},\"t\":{}}}", source_line(r.span), num(r.t_s, 4)))
            })
            .collect();
        s.push_str(&evs.join(","));
        s.push_str("],\"diags\":[");
        let ds: Vec<String> = self
            .diagnostics
            .iter()
            .map(|d| {
                let sev = if d.severity() == Severity::Alarm { "alarm" } else { "warning" };
                format!(
                    "{{\"l\":{},\"c\":{},\"code\":{},\"sev\":\"{sev}\",\"msg\":{}{}}}",
                    if d.span.file == 0 { d.span.line } else { d.calls.first().map_or(0, |c| c.line) },
                    d.span.col,
                    json_str(d.code),
                    json_str(&with_calls(d)),
                    d.hint.as_ref().map(|h| format!(",\"hint\":{}", json_str(h))).unwrap_or_default()
                )
            })
            .collect();
        s.push_str(&ds.join(","));
        s.push_str("],\"params\":[");
        let ps: Vec<String> = profile
            .all_params()
            .map(|d| {
                format!(
                    "[{},{},{},{},{}]",
                    json_str(&d.key.to_string()),
                    num(self.params.get(d.key), 4),
                    json_str(d.unit),
                    json_str(d.meaning),
                    json_str(d.source)
                )
            })
            .collect();
        s.push_str(&ps.join(","));
        let settings: Vec<String> = self.settings.iter().map(|x| json_str(x)).collect();
        let _ = write!(s, "],\"settings\":[{}],", settings.join(","));
        match self.sim {
            Some(sim) => {
                let m = crate::simulate::json(&sim.measurement);
                let _ = write!(s, "\"sim\":{},", m.trim_end());
                // The axial section at angle 0, thinned to 2000 points.
                let g = sim.stock.grid;
                let row = sim.stock.row(0);
                let step = g.nz.div_ceil(2000).max(1);
                let sec: Vec<String> = (0..g.nz).step_by(step).map(|i| format!("[{},{}]", num(g.z(i), 4), num(2.0 * row[i] as f64, 4))).collect();
                let _ = write!(s, "\"section\":[{}],", sec.join(","));
                let mut png = Vec::new();
                if crate::simulate::image(sim, &mut png).is_ok() {
                    let _ = write!(s, "\"unrolled\":\"data:image/png;base64,{}\",", base64(&png));
                }
            }
            None => {
                s.push_str("\"sim\":null,");
                if let Some(e) = self.sim_error {
                    let _ = write!(s, "\"sim_error\":{},", json_str(e));
                }
            }
        }
        let total = self.records.last().map(|r| r.t_s).unwrap_or(0.0);
        let _ = write!(s, "\"total\":{}}}", num(total, 4));
        s
    }

    pub fn write(&self, w: &mut dyn Write) -> io::Result<()> {
        let data = script_safe(&self.data());
        let title = esc_html(&format!("ncsight report: {}", self.file_name));
        write!(
            w,
            "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n\
             <meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n\
             <title>{title}</title>\n<style>{}</style></head>\n<body>\n{}\n\
             <script type=\"application/json\" id=\"ncsight-data\">{data}</script>\n<script>{}</script>\n</body></html>\n",
            include_str!("report/style.css"),
            include_str!("report/body.html"),
            include_str!("report/app.js")
        )
    }
}

/// Standard base64 (RFC 4648) for the inline image.
fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for c in bytes.chunks(3) {
        let n = (c[0] as u32) << 16 | (*c.get(1).unwrap_or(&0) as u32) << 8 | *c.get(2).unwrap_or(&0) as u32;
        out.push(A[(n >> 18) as usize & 63] as char);
        out.push(A[(n >> 12) as usize & 63] as char);
        out.push(if c.len() > 1 { A[(n >> 6) as usize & 63] as char } else { '=' });
        out.push(if c.len() > 2 { A[n as usize & 63] as char } else { '=' });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_and_escaping() {
        assert_eq!(base64(b"Man"), "TWFu");
        assert_eq!(base64(b"Ma"), "TWE=");
        assert_eq!(base64(b"M"), "TQ==");
        assert_eq!(script_safe("\"</script><img>\""), "\"\\u003c/script\\u003e\\u003cimg\\u003e\"");
        assert_eq!(esc_html("<a href=\"x\">&"), "&lt;a href=&quot;x&quot;&gt;&amp;");
    }
}

/// The line of the page's source a record or a diagnostic belongs to; 0 (none) for one from a
/// subprogramme in another file (`--subprogram-dir`), whose text the page does not hold.
fn source_line(span: ncsight::source::Span) -> u32 {
    if span.file == 0 { span.line } else { 0 }
}

/// A diagnostic's message with the calls that led to it, when raised in a subprogramme (the page
/// lists it under the line of the outermost call when it lies in another file).
fn with_calls(d: &ncsight::Diagnostic) -> String {
    if d.calls.is_empty() {
        return d.message.clone();
    }
    let chain: Vec<String> = d.calls.iter().rev().map(|c| format!("line {}", c.line)).collect();
    let place = if d.span.file == 0 { String::new() } else { format!(" (line {} of another file)", d.span.line) };
    format!("{}{place} - in a subprogramme called at {}", d.message, chain.join(", called at "))
}
