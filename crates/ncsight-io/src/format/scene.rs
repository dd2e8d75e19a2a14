//! The scene: what the page draws and plays, one run of a programme packed for a browser. The
//! page's engine (the core in WebAssembly) builds it, and the page reads it into typed arrays
//! without parsing a number of text per motion, so a million moves load in a few seconds.
//!
//! Layout (little-endian):
//!
//! ```text
//! "NCS1"  u32 J  J bytes of JSON (the header)  zero bytes up to a multiple of 8
//! t_s      f64 x n   seconds from programme start at the end of each motion
//! points   f32 x 6n  from X Y Z, to X Y Z (work coordinates; a lathe's X is a radius)
//! arcs     f32 x 4n  arc centre X Y Z and signed sweep in radians (+ counter-clockwise); 0 for others
//! rate     f32 x n   feed mm/min (feed, arc), lead mm (thread), 0 (rapid)
//! line     u32 x n   source line (0: a line of another file)
//! tool     u16 x n   the tool number in force
//! kind     u8  x n   bits 0-2 rapid 0, feed 1, arc 2, thread 3, thread arc 4; bits 3-4 plane
//!                    (XY 0, ZX 1, YZ 2); bit 5 pull-out; bit 6 block end (single block may stop)
//!          zero bytes up to a multiple of 4
//! hole_at  f32 x 3h  X Y Z of each hole's bottom
//! hole_seg u32 x h   the motion that reaches it
//! hole_kind u8 x h   index into the header's `hole_kinds`
//! ```
//!
//! The header holds `n` (`segments`), `h` (`holes`), `cut` (the run was cut at
//! [`MAX_SCENE_RECORDS`]) and what is not per motion: the profile,
//! the diagnostics (at most [`MAX_DIAGNOSTICS`], `diagnostics_total` says how many there were),
//! the other records (spindle, tool, stop, dwell, rotary turn, end) with their line and time, and
//! the threads' spindle angle, speed and pass.

use super::jsonl::json_str;
use super::num;
use crate::job::{Job, JobError};
use ncsight::motion::{ArcDir, Op, Plane};
use ncsight::{Event, Mode, Severity};
use std::fmt::Write as _;

/// Diagnostics the header lists; a programme with more says how many in all.
pub const MAX_DIAGNOSTICS: usize = 10_000;

/// Records (motions and the others) a scene holds at most: about 120 MB in the page's engine.
/// A legal programme may make far more (`G81 ... K9999` on a thousand lines: 40 million holes);
/// the scene then ends there, its header says `"cut":true`, and the page says that it shows the
/// programme up to that point (the command line runs all of it).
pub const MAX_SCENE_RECORDS: usize = 2_000_000;

#[derive(Default)]
struct Columns {
    t_s: Vec<f64>,
    points: Vec<f32>,
    arcs: Vec<f32>,
    rate: Vec<f32>,
    line: Vec<u32>,
    tool: Vec<u16>,
    kind: Vec<u8>,
    hole_at: Vec<f32>,
    hole_seg: Vec<u32>,
    hole_kind: Vec<u8>,
}

/// Run `text` as `job` says (a run, through the operator machine) and pack what the page needs;
/// a programme the text calls but lacks is looked for in `library` (file name, text), by the
/// programme numbers each holds.
pub fn scene(job: &Job, text: &[u8], library: Vec<(String, &[u8])>) -> Result<Vec<u8>, JobError> {
    scene_of_at_most(job, text, library, MAX_SCENE_RECORDS)
}

/// [`scene`], cut after `max_records` records.
fn scene_of_at_most(job: &Job, text: &[u8], library: Vec<(String, &[u8])>, max_records: usize) -> Result<Vec<u8>, JobError> {
    let profile = job.profile()?;
    let (program, _) = job.program(Mode::Run)?;
    let mut events = ncsight::events_with_library(program, text, library);
    let mut c = Columns::default();
    let mut head = String::with_capacity(4096);
    let (mut diags, mut others, mut threads) = (Vec::new(), Vec::new(), Vec::new());
    let (mut diagnostics_total, mut alarms_total) = (0usize, 0usize);
    let mut hole_kinds: Vec<&'static str> = Vec::new();
    let mut tool = 0u16;
    let mut pass = 0u32;
    let mut prev_thread_end = None;
    // A hole is marked once, at its first feed, then moved to the deepest point its feeds reach
    // (a peck hole's bottom, not its first peck); the hole ends with its block end.
    let mut in_hole = false;
    let (mut hole_start, mut hole_reach) = (ncsight::Vec3::default(), 0.0f64);
    let mut cut = false;
    let mut t_before = 0.0;
    let mut total_s = 0.0f64;
    while let Some(e) = events.next() {
        if c.kind.len() + others.len() >= max_records {
            cut = true;
            break;
        }
        let r = match e {
            Event::Diagnostic(d) => {
                diagnostics_total += 1;
                alarms_total += usize::from(d.severity() == Severity::Alarm);
                if diags.len() < MAX_DIAGNOSTICS {
                    diags.push(diagnostic_json(&d, Some(c.kind.len())));
                }
                continue;
            }
            Event::Record(r) => r,
        };
        // A line of a subprogramme in another file: 0 (the page holds only the main text).
        let line = if r.span.file == 0 { r.span.line } else { 0 };
        total_s = total_s.max(r.t_s);
        let took_s = (r.t_s - std::mem::replace(&mut t_before, r.t_s)).max(0.0);
        let (from, to) = match (r.op.start_point(), r.op.end_point()) {
            (Some(a), Some(b)) => (a, b),
            _ => {
                let what = match &r.op {
                    Op::Tool { number, offset } => {
                        tool = (*number).min(u16::MAX as u32) as u16;
                        format!("\"tool\",\"tool\":{number}{}", offset.map(|o| format!(",\"offset\":{o}")).unwrap_or_default())
                    }
                    Op::Spindle { rpm, oriented, p, .. } => format!("\"spindle\",\"rpm\":{},\"oriented\":{oriented},\"p\":{p}", num(*rpm, 1)),
                    Op::Stop { reason } => format!("\"stop\",\"reason\":\"{}\"", reason.as_str()),
                    Op::Dwell { seconds } => format!("\"dwell\",\"s\":{}", num(*seconds, 3)),
                    // A linear extra axis (a sub-spindle's B) is timed as a turn, its value in mm.
                    Op::Rotary { axis, to_deg, linear, .. } => format!(
                        "\"rotary\",\"axis\":\"{}\",\"{}\":{},\"s\":{}",
                        *axis as char,
                        if *linear { "mm" } else { "deg" },
                        num(*to_deg, 3),
                        num(took_s, 4)
                    ),
                    Op::End { code } => format!("\"end\",\"code\":{code}"),
                    _ => format!("\"{}\"", r.op.kind()),
                };
                // A block end here (a tapping hole's spindle reversal, a dwell) is a single-block stop too.
                others.push(format!(
                    "{{\"k\":{what},\"l\":{line},\"t\":{},\"seg\":{}{}}}",
                    num(r.t_s, 4),
                    c.kind.len(),
                    if r.block_end { ",\"be\":1" } else { "" }
                ));
                prev_thread_end = None;
                // A hole may end on its spindle's restart (G76, G86, G87) or a dwell.
                if r.block_end {
                    in_hole = false;
                }
                continue;
            }
        };
        let i = c.kind.len() as u32;
        let (mut kind, plane, arc) = match &r.op {
            Op::Rapid { .. } => (0u8, None, None),
            Op::Feed { .. } => (1, None, None),
            Op::Arc { plane, dir, center, .. } => (2, Some(*plane), Some((*center, *dir))),
            Op::Thread { .. } => (3, None, None),
            Op::ThreadArc { plane, dir, center, .. } => (4, Some(*plane), Some((*center, *dir))),
            _ => unreachable!("only motions have end points"),
        };
        kind |= match plane {
            Some(Plane::ZX) => 1 << 3,
            Some(Plane::YZ) => 2 << 3,
            _ => 0,
        };
        match (arc, ncsight::geom::arc_geom_of(&r.op)) {
            (Some((centre, dir)), Some(g)) => {
                let sweep = if dir == ArcDir::Ccw { g.sweep_rad } else { -g.sweep_rad };
                c.arcs.extend_from_slice(&[centre.x as f32, centre.y as f32, centre.z as f32, sweep as f32]);
            }
            _ => c.arcs.extend_from_slice(&[0.0; 4]),
        }
        match r.op {
            Op::Thread { lead_mm, spindle_deg, rpm, long_axis, .. } | Op::ThreadArc { lead_mm, spindle_deg, rpm, long_axis, .. } => {
                let continues = prev_thread_end == Some(from);
                if !continues {
                    pass += 1;
                }
                // A pull-out goes on from a thread and moves the short axis.
                let (_, short) = long_axis.indices();
                if continues && (to.axis(short) - from.axis(short)).abs() > 1e-9 {
                    kind |= 1 << 5;
                }
                threads.push(format!("[{i},{},{},{pass}]", num(spindle_deg, 3), num(rpm, 1)));
                c.rate.push(lead_mm as f32);
                prev_thread_end = Some(to);
            }
            Op::Feed { feed_mm_min, .. } | Op::Arc { feed_mm_min, .. } => {
                c.rate.push(feed_mm_min as f32);
                prev_thread_end = None;
            }
            _ => {
                c.rate.push(0.0);
                prev_thread_end = None;
            }
        }
        if r.block_end {
            kind |= 1 << 6;
        }
        // The drilling cycle in force marks its holes (the interpreter's state after the block).
        let drilling = events.program().interpreter().state().drill.kind;
        if let (Some(_), true, 1) = (drilling, in_hole, kind & 7) {
            let reach = hole_start.dist(&to);
            if reach > hole_reach {
                hole_reach = reach;
                let at = c.hole_at.len() - 3;
                c.hole_at[at..].copy_from_slice(&[to.x as f32, to.y as f32, to.z as f32]);
                *c.hole_seg.last_mut().expect("a hole is open") = i;
            }
        } else if let (Some(k), false, 1) = (drilling, in_hole, kind & 7) {
            in_hole = true;
            (hole_start, hole_reach) = (from, from.dist(&to));
            let code = k.code();
            let idx = hole_kinds.iter().position(|x| *x == code).unwrap_or_else(|| {
                hole_kinds.push(code);
                hole_kinds.len() - 1
            });
            c.hole_at.extend_from_slice(&[to.x as f32, to.y as f32, to.z as f32]);
            c.hole_seg.push(i);
            c.hole_kind.push(idx.min(255) as u8);
        }
        if r.block_end || drilling.is_none() {
            in_hole = false;
        }
        c.t_s.push(r.t_s);
        c.points.extend_from_slice(&[from.x as f32, from.y as f32, from.z as f32, to.x as f32, to.y as f32, to.z as f32]);
        c.line.push(line);
        c.tool.push(tool);
        c.kind.push(kind);
    }
    let status = match events.program().status() {
        ncsight::Status::Alarm => "alarm",
        ncsight::Status::Ended => "ended",
        // The text ran out without an end of programme (or RESET was pressed).
        ncsight::Status::Running => "stopped",
    };
    let _ = write!(
        head,
        "{{\"machine\":{},\"title\":{},\"lathe\":{},\"status\":\"{status}\",\"cut\":{cut},\"total_s\":{},\"segments\":{},\"holes\":{},\"hole_kinds\":[{}],\"diagnostics_total\":{diagnostics_total},\"alarms_total\":{alarms_total},\"diagnostics\":[{}],\"events\":[{}],\"threads\":[{}],\"passes\":{pass},\"params\":[{}]}}",
        json_str(profile.name),
        json_str(profile.title),
        profile.is_lathe(),
        num(total_s, 4),
        c.kind.len(),
        c.hole_seg.len(),
        hole_kinds.iter().map(|k| json_str(k)).collect::<Vec<_>>().join(","),
        diags.join(","),
        others.join(","),
        threads.join(","),
        params_json(&job.parameters()?)
    );
    Ok(pack(&head, &c))
}

/// Every diagnostic of a check of `text` (`ncsight check`: the run goes on after an alarm, no
/// motion is made), as JSON: `{"total":N,"alarms":A,"diagnostics":[...]}` in the header's form without
/// `seg`, at most [`MAX_DIAGNOSTICS`] of them. The page lists those a run stopped before.
pub fn check(job: &Job, text: &[u8], library: Vec<(String, &[u8])>) -> Result<String, JobError> {
    let (program, _) = job.program(Mode::Check)?;
    let (mut total, mut alarms) = (0usize, 0usize);
    let mut diags = Vec::new();
    for e in ncsight::events_with_library(program, text, library) {
        if let Event::Diagnostic(d) = e {
            total += 1;
            alarms += usize::from(d.severity() == Severity::Alarm);
            if diags.len() < MAX_DIAGNOSTICS {
                diags.push(diagnostic_json(&d, None));
            }
        }
    }
    Ok(format!("{{\"total\":{total},\"alarms\":{alarms},\"diagnostics\":[{}]}}", diags.join(",")))
}

/// A diagnostic for the header; `seg` is how many motions came before it (where it is drawn).
fn diagnostic_json(d: &ncsight::Diagnostic, seg: Option<usize>) -> String {
    let sev = if d.severity() == Severity::Alarm { "alarm" } else { "warning" };
    // A diagnostic from a subprogramme in another file is listed under the outermost call.
    let line = if d.span.file == 0 { d.span.line } else { d.calls.first().map_or(0, |c| c.line) };
    let mut message = d.message.clone();
    if !d.calls.is_empty() {
        let chain: Vec<String> = d.calls.iter().rev().map(|c| format!("line {}", c.line)).collect();
        let place = if d.span.file == 0 { String::new() } else { format!(" (line {} of another file)", d.span.line) };
        message = format!("{message}{place} - in a subprogramme called at {}", chain.join(", called at "));
    }
    // `rule`: the project code the explanations are kept under (`code` is the profile's own).
    format!(
        "{{\"l\":{line},\"c\":{}{},\"code\":{},\"rule\":{},\"sev\":\"{sev}\",\"msg\":{}{}}}",
        d.span.col,
        seg.map(|s| format!(",\"seg\":{s}")).unwrap_or_default(),
        json_str(d.code),
        json_str(d.rule.project_code()),
        json_str(&message),
        d.hint.as_ref().map(|h| format!(",\"hint\":{}", json_str(h))).unwrap_or_default()
    )
}

/// The profile's parameters as the run had them: key, value, unit, meaning, source, and the
/// meaning in Chinese.
fn params_json(params: &ncsight::profile::Params) -> String {
    let rows: Vec<String> = params
        .profile()
        .all_params()
        .map(|d| {
            let zh = ncsight::profile::meaning_zh(d.meaning).unwrap_or(d.meaning);
            format!(
                "[{},{},{},{},{},{}]",
                json_str(&d.key.to_string()),
                num(params.get(d.key), 4),
                json_str(d.unit),
                json_str(d.meaning),
                json_str(d.source),
                json_str(zh)
            )
        })
        .collect();
    rows.join(",")
}

fn pack(head: &str, c: &Columns) -> Vec<u8> {
    let n = c.kind.len();
    let h = c.hole_seg.len();
    let mut out = Vec::with_capacity(16 + head.len() + n * 71 + h * 17);
    out.extend_from_slice(b"NCS1");
    out.extend_from_slice(&(head.len() as u32).to_le_bytes());
    out.extend_from_slice(head.as_bytes());
    let pad = |out: &mut Vec<u8>, to: usize| out.resize(out.len().div_ceil(to) * to, 0);
    pad(&mut out, 8);
    c.t_s.iter().for_each(|v| out.extend_from_slice(&v.to_le_bytes()));
    for col in [&c.points, &c.arcs, &c.rate] {
        col.iter().for_each(|v| out.extend_from_slice(&v.to_le_bytes()));
    }
    c.line.iter().for_each(|v| out.extend_from_slice(&v.to_le_bytes()));
    c.tool.iter().for_each(|v| out.extend_from_slice(&v.to_le_bytes()));
    out.extend_from_slice(&c.kind);
    pad(&mut out, 4);
    c.hole_at.iter().for_each(|v| out.extend_from_slice(&v.to_le_bytes()));
    c.hole_seg.iter().for_each(|v| out.extend_from_slice(&v.to_le_bytes()));
    out.extend_from_slice(&c.hole_kind);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn head(b: &[u8]) -> String {
        let j = u32::from_le_bytes(b[4..8].try_into().unwrap()) as usize;
        String::from_utf8(b[8..8 + j].to_vec()).unwrap()
    }

    /// An alarm inside a subprogramme: the message names the call that led there.
    #[test]
    fn the_call_chain_is_in_the_message() {
        let h = head(&scene(&Job::on("fanuc0m"), b"O0001\nG90 G00 X0. Y0. Z10.\nM98 P0100\nM30\nO0100\nG00 Q1.\nM99\n", Vec::new()).unwrap());
        assert!(h.contains("in a subprogramme called at line 3"), "{h}");
        assert!(h.contains("\"status\":\"alarm\""), "{h}");
    }

    /// A rotary axis's turn is among the other records with the time it adds (45 degrees at the
    /// rotary rapid rate, 10800 deg/min: 0.25 s plus 0.1 s to accelerate), for the time table.
    #[test]
    fn a_rotary_turn_and_its_time() {
        let mut job = Job::on("fanuc0m");
        job.set_setup_text("[machine]\naxes = [\"X\", \"Y\", \"Z\", \"A\"]\n", "s.toml").unwrap();
        let h = head(&scene(&job, b"G91 G00 A45.\nM30\n", Vec::new()).unwrap());
        assert!(h.contains(r#"{"k":"rotary","axis":"A","deg":45,"s":0.35,"l":1"#), "{h}");
    }

    /// The holes' (f32) X Y Z from a scene.
    fn holes(b: &[u8]) -> Vec<f32> {
        let h = head(b);
        let field = |name: &str| -> usize { h.split(&format!("\"{name}\":")).nth(1).unwrap().split([',', '}']).next().unwrap().parse().unwrap() };
        let (n, holes) = (field("segments"), field("holes"));
        let j = u32::from_le_bytes(b[4..8].try_into().unwrap()) as usize;
        let at = ((8 + j).div_ceil(8) * 8 + n * (8 + 24 + 16 + 4 + 4 + 2 + 1)).div_ceil(4) * 4;
        (0..3 * holes).map(|i| f32::from_le_bytes(b[at + 4 * i..at + 4 * i + 4].try_into().unwrap())).collect()
    }

    /// A peck hole is marked at its bottom (Z-30), not at the end of its first peck (Z-3): the
    /// page's side views and its scene say "each hole's bottom".
    #[test]
    fn a_peck_hole_is_marked_at_its_bottom() {
        let text = b"G21 G17 G90 G00 X0 Y0 Z10.\nG99 G83 X10. Y5. Z-30. R2. Q3. F100.\nG73 X20. Z-12. Q4.\nG80\nM30\n";
        assert_eq!(holes(&scene(&Job::on("fanuc0m"), text, Vec::new()).unwrap()), [10.0, 5.0, -30.0, 20.0, 5.0, -12.0]);
    }

    /// A scene holds at most so many records: a legal programme that makes more (40 million
    /// holes) is cut there and says so, instead of filling the page's memory.
    #[test]
    fn a_scene_is_cut_at_its_bound() {
        let text = b"G21 G17 G90 G00 X0 Y0 Z10.\nG91 G99 G81 X1. Z-3. R-8. F100. K9999\nG90 G80\nM30\n";
        let b = scene_of_at_most(&Job::on("fanuc0m"), text, Vec::new(), 1000).unwrap();
        let h = head(&b);
        assert!(h.contains("\"cut\":true") && h.contains("\"segments\":1000"), "{h}");
        let whole = scene(&Job::on("fanuc0m"), b"G21 G90 G00 X0 Y0 Z10.\nM30\n", Vec::new()).unwrap();
        assert!(head(&whole).contains("\"cut\":false"));
    }

    /// A check lists every alarm, where a run stops at the first.
    #[test]
    fn a_check_lists_every_alarm() {
        let text = b"G0 X10 Z5\nG0 X10 Q1\nG0 X20 Q1\nM30\n";
        let h = head(&scene(&Job::on("gsk980tdi"), text, Vec::new()).unwrap());
        assert!(h.contains("\"diagnostics_total\":1,\"alarms_total\":1,") && h.contains("\"l\":2,\"c\":8,\"seg\":1,"), "{h}");
        let c = check(&Job::on("gsk980tdi"), text, Vec::new()).unwrap();
        assert!(c.starts_with("{\"total\":2,\"alarms\":2,\"diagnostics\":[{\"l\":2,\"c\":8,\"code\":"), "{c}");
        assert!(c.contains("{\"l\":3,\"c\":8,"), "{c}");
    }

    /// Every hole of the FANUC 0-M cycles (seed 003) has its marker, whatever ends it: a rapid
    /// out (G81), the spindle's restart after an oriented stop (G76, G86, G87), the feed out
    /// (G85, G89), the manual retract (G88) or the tapping's reversal (G74, G84).
    #[test]
    fn a_marker_for_every_hole() {
        let text = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/golden/fanuc0m_cycles_g17/input.nc")).unwrap();
        let h = head(&scene(&Job::on("fanuc0m"), &text, Vec::new()).unwrap());
        // X10 ... X120: twelve holes, one kind each.
        assert!(
            h.contains("\"holes\":12,\"hole_kinds\":[\"G81\",\"G82\",\"G73\",\"G83\",\"G76\",\"G85\",\"G86\",\"G87\",\"G88\",\"G89\",\"G74\",\"G84\"]"),
            "{h}"
        );
    }
}
