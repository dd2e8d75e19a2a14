//! Running a programme's records through the stock, and measuring the thread that results from
//! the cut surface, not from the programme: diameters, depth, pitch, lead, starts, flank angles,
//! full-depth and run-out lengths, deviation from a named thread, and the findings (phase error
//! between passes, a rapid into the stock, the tool past the stock's end).

use rayon::prelude::*;
use super::lathe::{Finding, LatheStock};
use super::standard::Expected;
use super::{Bar, Setup, Tool};
use crate::motion::{Op, Record};

/// How the simulation is set up.
#[derive(Debug, Clone, Default)]
pub struct SimOptions {
    /// Grid spacing along z, mm (default: from the thread: lead / 300, at most 0.01 mm).
    pub dz_mm: Option<f64>,
    /// Grid spacing around, degrees (default 0.5).
    pub dtheta_deg: Option<f64>,
    pub expect: Option<Expected>,
    /// `--expect bore=D` and `od=D`: the diameter of the longest bore, of the longest outside.
    pub expect_bore_mm: Option<f64>,
    pub expect_od_mm: Option<f64>,
    /// Cut only the records that have ended by this time, s (the page's stock as the programme
    /// plays); the stock and the tools are still those of the whole programme.
    pub until_s: Option<f64>,
}

/// What was measured.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Measurement {
    pub stock_diameter_mm: f64,
    pub major_diameter_mm: Option<f64>,
    pub minor_diameter_mm: Option<f64>,
    pub depth_mm: Option<f64>,
    pub pitch_mm: Option<f64>,
    pub lead_mm: Option<f64>,
    /// `right` when the groove moves toward -Z as the part turns in its positive (M03) direction,
    /// `left` otherwise (docs/commands/simulate.md).
    pub hand: Option<&'static str>,
    pub starts: Option<u32>,
    pub start_spacing_deg: Option<f64>,
    /// Flank angles on the two sides of a groove (from the radial direction), degrees.
    pub flank_angles_deg: Option<(f64, f64)>,
    pub full_depth_length_mm: Option<f64>,
    pub runout_length_mm: Option<f64>,
    pub findings: Vec<Finding>,
    /// The tools the setup does not describe, as assumed from what they do (T number, tool).
    pub assumed_tools: Vec<(u32, Tool)>,
    pub dz_mm: f64,
    pub dtheta_deg: f64,
    pub cell_updates: u64,
    /// The stock when it was guessed from the programme (no `--stock`, no setup stock).
    pub stock_guessed: Option<Bar>,
    /// The part's profile from the face toward the chuck.
    pub profile: Vec<super::lathe::ProfileRow>,
}

/// A simulation: the stock after the programme and its measurement.
pub struct Simulation {
    pub stock: LatheStock,
    pub measurement: Measurement,
}

/// The tools a setup lacks, from what each does (docs/commands/simulate.md):
/// - one that cuts a thread is a sharp 60-degree threading insert (internal when it leaves its
///   passes toward the axis);
/// - one that only feeds along Z on the spindle axis is a drill with a 118-degree point, as wide
///   as the narrowest place a later tool that works inside reaches within its hole (10 mm when
///   none does);
/// - any other turns, an 80-degree insert with a 0.4 mm nose radius: a boring bar when it leaves
///   its cuts toward the axis (its rapids straight after a cut go mostly along X, down): it
///   works inside; else a turning tool, each of whose moves cuts the nearer side of the material.
fn assume_tools(records: &[Record], setup: &Setup) -> Vec<(u32, Tool)> {
    #[derive(Clone, Copy, Default)]
    struct Use {
        threads: bool,
        on_axis_feeds: bool,
        other_cuts: bool,
        /// Rapids straight after a cut, mostly along X: toward the axis, away from it.
        leaves_down: u32,
        leaves_up: u32,
        /// The drilled range along Z (a drill's feeds): deepest, highest.
        drilled: Option<(f64, f64)>,
    }
    let mut uses: Vec<(u32, Use)> = Vec::new();
    let mut current = 0u32;
    let idx = |n: u32, uses: &mut Vec<(u32, Use)>| match uses.iter().position(|(m, _)| *m == n) {
        Some(i) => i,
        None => {
            uses.push((n, Use::default()));
            uses.len() - 1
        }
    };
    let mut after_cut = false;
    for r in records {
        let i = idx(current, &mut uses);
        let u = &mut uses[i].1;
        match r.op {
            Op::Tool { number, .. } => current = number,
            Op::Thread { .. } | Op::ThreadArc { .. } => u.threads = true,
            Op::Feed { from, to, .. } if from.x.abs() < 1e-3 && to.x.abs() < 1e-3 && from.z != to.z => {
                u.on_axis_feeds = true;
                let (lo, hi) = u.drilled.unwrap_or((f64::MAX, f64::MIN));
                u.drilled = Some((lo.min(from.z).min(to.z), hi.max(from.z).max(to.z)));
            }
            Op::Feed { .. } | Op::Arc { .. } => u.other_cuts = true,
            Op::Rapid { from, to } if after_cut && (to.x - from.x).abs() > (to.z - from.z).abs() => {
                if to.x < from.x { u.leaves_down += 1 } else { u.leaves_up += 1 }
            }
            _ => {}
        }
        after_cut = matches!(r.op, Op::Feed { .. } | Op::Arc { .. } | Op::Thread { .. } | Op::ThreadArc { .. });
    }
    let is_drill = |u: &Use| u.on_axis_feeds && !u.other_cuts && !u.threads;
    let inside = |u: &Use| !is_drill(u) && u.leaves_down > u.leaves_up;
    // A drill is as wide as the narrowest place that a later tool working inside reaches within
    // its hole (below its top).
    let drill_diameter = |k: usize, drilled: (f64, f64)| -> f64 {
        let mut tool = 0u32;
        let mut seen_drill = false;
        let mut narrowest = f64::MAX;
        for r in records {
            if let Op::Tool { number, .. } = r.op {
                tool = number;
            }
            seen_drill |= tool == uses[k].0;
            let later_inside = seen_drill && tool != uses[k].0 && uses.iter().any(|(n, u)| *n == tool && (inside(u) || u.threads));
            if let (true, Some(p)) = (later_inside, r.op.end_point()) {
                if p.z < drilled.1 && p.z > drilled.0 && p.x > 1e-3 {
                    narrowest = narrowest.min(2.0 * p.x);
                }
            }
        }
        if narrowest < f64::MAX { narrowest } else { 10.0 }
    };
    (0..uses.len())
        .filter(|&k| {
            let (n, u) = &uses[k];
            !setup.tools.iter().any(|t| t.number == *n) && (u.threads || u.on_axis_feeds || u.other_cuts)
        })
        .map(|k| {
            let (n, u) = uses[k];
            let tool = if u.threads {
                Tool { number: n, internal: u.leaves_down > u.leaves_up, ..Tool::default_thread() }
            } else if is_drill(&u) {
                let d = drill_diameter(k, u.drilled.expect("a drill has drilled"));
                Tool { number: n, kind: super::ToolKind::Drill, diameter_mm: d, ..Tool::default_thread() }
            } else {
                let kind = if inside(&u) { super::ToolKind::Boring } else { super::ToolKind::Turning };
                Tool { number: n, kind, included_angle_deg: 80.0, tip_radius_mm: 0.4, ..Tool::default_thread() }
            };
            (n, tool)
        })
        .collect()
}

/// How far behind the deepest cut a guessed stock ends (where the chuck is assumed): a part
/// needs some length to be held by, and a parting tool's width goes past its programmed point.
pub const GUESS_HOLD_MM: f64 = 5.0;

/// The stock a programme implies when none is given (docs/commands/simulate.md, an assumption:
/// give `--stock` to be sure), from the extents of its cutting moves (feeds, arcs, threads):
/// - the diameter is the largest one the tool cuts along (for each cutting move the smaller of
///   its two diameters, so a move coming in from outside, a facing cut or a retract, does not
///   count beyond where it cuts), or the largest diameter of any cut when none runs along one;
/// - the face is at Z0 where the cuts reach it (otherwise at the nearest cut), and the bar runs
///   to the deepest cut plus [`GUESS_HOLD_MM`], where the chuck is assumed;
/// - with an external thread, at least the thread's deepest pass plus twice the ISO external
///   thread height 0.61343 x lead (a programme that only threads: the blank's diameter);
/// - a programme that only cuts an internal thread: the bore is its deepest pass less twice that
///   height, the outside twice that height and 5 mm beyond it (a programme that also turns or
///   bores makes its own bore: solid stock).
fn infer_bar(records: &[Record], internal: bool) -> Option<Bar> {
    let (mut along, mut widest) = (0.0f64, 0.0f64);
    // Whether anything but threads cuts (then the programme makes its own bore).
    let mut other_cuts = false;
    let (mut zmin, mut zmax) = (f64::MAX, f64::MIN);
    let (mut lead, mut thread_max_x, mut thread_min_x) = (0.0f64, f64::MIN, f64::MAX);
    for r in records {
        let (from, to) = match r.op {
            Op::Feed { from, to, .. } | Op::Arc { from, to, .. } => {
                other_cuts = true;
                (from, to)
            }
            Op::Thread { from, to, lead_mm, .. } | Op::ThreadArc { from, to, lead_mm, .. } => {
                lead = lead.max(lead_mm);
                thread_max_x = thread_max_x.max(from.x).max(to.x);
                thread_min_x = thread_min_x.min(from.x).min(to.x);
                (from, to)
            }
            _ => continue,
        };
        along = along.max(from.x.min(to.x));
        widest = widest.max(from.x).max(to.x);
        zmin = zmin.min(from.z).min(to.z);
        zmax = zmax.max(from.z).max(to.z);
    }
    if zmin > zmax {
        return None;
    }
    let mut radius = if along > 0.0 { along } else { widest };
    let mut bore = 0.0;
    let height = 0.61343 * lead;
    if internal && lead > 0.0 && !other_cuts {
        // A programme that only threads inside: the bore it was written for, and a wall of twice
        // the thread's height and 5 mm around it.
        radius = radius.max(thread_max_x + 2.0 * height + 5.0);
        bore = 2.0 * (thread_max_x - height);
    } else if lead > 0.0 && !internal {
        radius = radius.max(thread_min_x + height);
    }
    if radius <= 0.0 {
        return None;
    }
    let front = zmax.min(0.0).max(zmin);
    Some(Bar { diameter_mm: 2.0 * radius, length_mm: (front - zmin) + GUESS_HOLD_MM, bore_mm: bore.max(0.0), front_z_mm: front })
}

/// A drilling simulation on a machining centre.
pub struct MillSimulation {
    pub stock: super::mill::MillStock,
    pub holes: Vec<super::mill::Hole>,
    pub findings: Vec<Finding>,
    /// The tools the setup does not describe, as assumed from what they do.
    pub assumed_tools: Vec<(u32, Tool)>,
}

/// Run a machining centre's records through a block (G17 drilling). Without a block in the
/// setup: the holes' extent plus 10 mm around, its top at Z0, 5 mm below the deepest hole.
/// Records that end after `until_s` are not cut.
pub fn simulate_mill(records: &[Record], setup: &Setup, cell_mm: Option<f64>, until_s: Option<f64>) -> Result<MillSimulation, String> {
    // What the cutting moves reach: their end points.
    let cuts: Vec<crate::motion::Vec3> = records.iter().filter(|r| matches!(r.op, Op::Feed { .. } | Op::Arc { .. })).filter_map(|r| r.op.end_point()).collect();
    let block = match setup.block {
        Some(b) => b,
        None if !cuts.is_empty() => {
            let f = |k: usize, min: bool| cuts.iter().map(|p| p.axis(k)).fold(if min { f64::MAX } else { f64::MIN }, if min { f64::min } else { f64::max });
            super::mill::Block { min_mm: [f(0, true) - 10.0, f(1, true) - 10.0, f(2, true).min(0.0) - 5.0], max_mm: [f(0, false) + 10.0, f(1, false) + 10.0, 0.0] }
        }
        None => return Err("no block: give one in the setup ([block] min_mm, max_mm); the programme cuts nothing to infer it from".into()),
    };
    let cell = cell_mm.unwrap_or(0.1);
    let cells = ((block.max_mm[0] - block.min_mm[0]) / cell) * ((block.max_mm[1] - block.min_mm[1]) / cell);
    if !(cell > 0.0) || cells > 100e6 {
        return Err(format!("a grid of {cells:.0} cells: coarsen --resolution"));
    }
    let assumed = assume_mill_tools(records, setup, block.max_mm[2]);
    let tool_for = |n: u32| assumed.iter().find(|(m, _)| *m == n).map(|(_, t)| *t).unwrap_or_else(|| setup.mill_tool(n));
    let mut stock = super::mill::MillStock::new(block, cell);
    let mut tool = tool_for(0);
    let mut rpm = 0.0;
    let first_rapid = records.iter().position(|r| matches!(r.op, Op::Rapid { .. })).unwrap_or(0);
    let until = until_s.map_or(records.len(), |t| records.partition_point(|r| r.t_s <= t));
    for (k, r) in records[..until].iter().enumerate() {
        match r.op {
            Op::Tool { number, .. } => tool = tool_for(number),
            Op::Spindle { rpm: s, .. } => rpm = s,
            _ if k > first_rapid => stock.apply(r, &tool, rpm),
            _ => {}
        }
    }
    let holes = stock.holes();
    let findings = std::mem::take(&mut stock.findings);
    Ok(MillSimulation { stock, holes, findings, assumed_tools: assumed })
}

/// The tools of a machining centre the setup lacks, from what each does: one that only feeds
/// along Z is a 5 mm drill with a 118-degree point (as before); one that feeds across below the
/// block's top (`top_z`) is a 10 mm flat end mill (docs/commands/simulate.md).
fn assume_mill_tools(records: &[Record], setup: &Setup, top_z: f64) -> Vec<(u32, Tool)> {
    let mut across: Vec<(u32, bool)> = Vec::new();
    let mut current = 0u32;
    for r in records {
        let (from, to) = match r.op {
            Op::Tool { number, .. } => {
                current = number;
                continue;
            }
            Op::Feed { from, to, .. } | Op::Arc { from, to, .. } => (from, to),
            _ => continue,
        };
        let sideways = (matches!(r.op, Op::Arc { .. }) || (from.x - to.x).abs() > 1e-9 || (from.y - to.y).abs() > 1e-9) && from.z.min(to.z) < top_z;
        match across.iter_mut().find(|(n, _)| *n == current) {
            Some((_, a)) => *a |= sideways,
            None => across.push((current, sideways)),
        }
    }
    across
        .into_iter()
        .filter(|(n, _)| !setup.tools.iter().any(|t| t.number == *n))
        .map(|(n, sideways)| {
            let tool = if sideways { Tool { number: n, kind: crate::setup::ToolKind::Mill, diameter_mm: 10.0, ..Tool::default_thread() } } else { Tool { number: n, ..setup.mill_tool(n) } };
            (n, tool)
        })
        .collect()
}

/// Run the records through the stock and measure.
pub fn simulate(records: &[Record], setup: &Setup, opts: &SimOptions) -> Result<Simulation, String> {
    simulate_with(records, setup, opts, &mut |_, _| {})
}

/// The most cell updates a lathe simulation may need (about a minute on two cores): past it the
/// simulation refuses at once instead of running for hours (docs/commands/simulate.md).
pub const MAX_CELL_UPDATES: f64 = 50e9;

/// An upper bound of the cell updates the records make on a grid of `nz` x `ntheta` cells
/// `dz` apart: every cutting record touches each row over its z extent (clipped to the bar).
fn work_estimate(records: &[Record], bar_length_mm: f64, dz: f64, ntheta: usize) -> f64 {
    records
        .iter()
        .map(|r| match r.op {
            Op::Thread { from, to, .. } | Op::ThreadArc { from, to, .. } | Op::Feed { from, to, .. } | Op::Arc { from, to, .. } | Op::Rapid { from, to } => {
                let span = match r.op {
                    // An arc may bulge beyond its end points: its whole circle's extent.
                    Op::Arc { center, .. } | Op::ThreadArc { center, .. } => 2.0 * center.dist(&from),
                    _ => (to.z - from.z).abs(),
                };
                (span.min(bar_length_mm) / dz + 2.0) * ntheta as f64
            }
            _ => 0.0,
        })
        .sum()
}

/// The tool in the turret at each record, and whether the spindle turns: it follows the T
/// words; a tool the setup does not describe is the one `assumed` from what it does.
fn tools_of(records: &[Record], setup: &Setup, assumed: &[(u32, Tool)]) -> Vec<(Tool, f64)> {
    let tool_for = |number: u32| assumed.iter().find(|(n, _)| *n == number).map(|(_, t)| *t).unwrap_or_else(|| setup.tool(number));
    let mut tool_of = Vec::with_capacity(records.len());
    let mut tool = tool_for(0);
    let mut rpm = 0.0;
    // A turning or boring tool whose [[tool]] gives no imaginary nose takes the one of its
    // offset (T0101 -> [[offset]] 1), and that offset's radius if it gives none.
    let with_offset = |mut t: Tool, offset: Option<u32>| {
        if t.tip.is_none() && matches!(t.kind, crate::setup::ToolKind::Turning | crate::setup::ToolKind::Boring) {
            if let Some(o) = offset.and_then(|n| setup.offset(n)).filter(|o| o.tip != 0 || o.radius_mm > 0.0) {
                t.tip = Some(o.tip);
                if t.tip_radius_mm <= 0.0 {
                    t.tip_radius_mm = o.radius_mm + o.wear_radius_mm;
                }
            }
        }
        t
    };
    for r in records {
        match r.op {
            Op::Tool { number, offset } => tool = with_offset(tool_for(number), offset),
            Op::Spindle { rpm: r, .. } => rpm = r,
            _ => {}
        }
        tool_of.push((tool, rpm));
    }
    tool_of
}

/// [`simulate`] that reports its progress: `progress(done, total)` after each record.
pub fn simulate_with(records: &[Record], setup: &Setup, opts: &SimOptions, progress: &mut dyn FnMut(usize, usize)) -> Result<Simulation, String> {
    let assumed = assume_tools(records, setup);
    let tool_of = tools_of(records, setup, &assumed);
    let internal = records.iter().zip(&tool_of).any(|(r, (t, _))| r.op.is_thread() && t.internal);
    let (bar, guessed) = match setup.stock {
        Some(b) => (b, false),
        None => match infer_bar(records, internal) {
            Some(b) => (b, true),
            None => return Err("no stock: give --stock DIAxLEN or a setup (the programme cuts nothing to guess it from)".into()),
        },
    };
    let max_lead = records
        .iter()
        .filter_map(|r| if let Op::Thread { lead_mm, .. } | Op::ThreadArc { lead_mm, .. } = r.op { Some(lead_mm) } else { None })
        .fold(0.0, f64::max);
    let dz = opts.dz_mm.unwrap_or(if max_lead > 0.0 { (max_lead / 300.0).min(0.01) } else { 0.01 });
    let dtheta = opts.dtheta_deg.unwrap_or(0.5);
    if !(dz > 0.0 && dtheta > 0.0 && dtheta <= 90.0) {
        return Err("the grid spacing must be more than 0 (and at most 90 degrees around)".into());
    }
    let ntheta = (360.0 / dtheta).round() as usize;
    let cells = (bar.length_mm / dz) * ntheta as f64;
    if cells > 400e6 {
        return Err(format!("a grid of {cells:.0} cells is too large: coarsen --resolution"));
    }
    let work = work_estimate(records, bar.length_mm, dz, ntheta);
    if work > MAX_CELL_UPDATES {
        return Err(format!(
            "the simulation would need about {:.0} G cell updates, more than its limit of {:.0} G (about a minute): coarsen --resolution or simulate fewer passes",
            work / 1e9,
            MAX_CELL_UPDATES / 1e9
        ));
    }
    let mut stock = LatheStock::new(bar, internal, dz, ntheta);
    // A tool assumed to turn may be a boring bar whose retracts did not show it: each of its
    // moves cuts the nearer side. One assumed to bore (it leaves its cuts toward the axis) works
    // inside, as a boring bar in a tube the guessed stock does not know the bore of.
    stock.either_side = assumed.iter().filter(|(_, t)| t.kind == crate::setup::ToolKind::Turning).map(|(n, _)| *n).collect();
    // A turning tool with an imaginary tool nose (its `tip`) is positioned by that point: the
    // stock cuts with the nose, whose lowest point (highest in a bore) lies R x d(tip) and R
    // from it (docs/compensation.md). Without a tip, the record's point is the nose's.
    let nose_shift = |t: &Tool| -> Option<crate::motion::Vec3> {
        let tip = t.tip?;
        if !matches!(t.kind, crate::setup::ToolKind::Turning | crate::setup::ToolKind::Boring) || t.tip_radius_mm <= 0.0 {
            return None;
        }
        let r = t.tip_radius_mm;
        let (dx, dz) = crate::comp::tip_direction(tip);
        let side = if super::lathe::cuts_inside(t) { 1.0 } else { -1.0 };
        Some(crate::motion::Vec3::new(-r * dx + side * r, 0.0, -r * dz))
    };
    // Where the tool is before the first rapid is the machine's business, not the programme's
    // (the power-on position): motion up to the end of the first rapid is not cut.
    let first_rapid = records.iter().position(|r| matches!(r.op, Op::Rapid { .. })).unwrap_or(0);
    let total = records.len();
    let until = opts.until_s.map_or(total, |t| records.partition_point(|r| r.t_s <= t));
    for (k, (r, (t, rpm))) in records[..until].iter().zip(&tool_of).enumerate().skip(first_rapid + 1) {
        match nose_shift(t) {
            Some(d) => stock.apply(&shifted(r, d), t, *rpm),
            None => stock.apply(r, t, *rpm),
        }
        progress(k + 1, total);
    }
    let mut m = measure(&stock, records, &tool_of.iter().map(|(t, _)| *t).collect::<Vec<_>>());
    m.assumed_tools = assumed;
    if let Some(e) = &opts.expect {
        deviation(&mut m, e, dz, records.iter().rev().find(|r| r.op.is_thread()));
    }
    m.findings.splice(0..0, stock.findings.iter().cloned());
    m.profile = stock.profile();
    sizes(&mut m, opts);
    if guessed {
        m.stock_guessed = Some(bar);
        // A chuck found against a stock nobody gave may not be there: said with each finding.
        for f in m.findings.iter_mut().filter(|f| f.kind == "chuck") {
            f.message.push_str(" (against a guessed stock: give --stock DIAxLEN for the real bar and chuck)");
        }
    }
    Ok(Simulation { stock, measurement: m })
}

/// A record with every point moved by `d`.
fn shifted(r: &Record, d: crate::motion::Vec3) -> Record {
    let op = match r.op {
        Op::Rapid { from, to } => Op::Rapid { from: from + d, to: to + d },
        Op::Feed { from, to, feed_mm_min } => Op::Feed { from: from + d, to: to + d, feed_mm_min },
        Op::Arc { from, to, center, plane, dir, feed_mm_min } => Op::Arc { from: from + d, to: to + d, center: center + d, plane, dir, feed_mm_min },
        other => other,
    };
    Record { op, ..r.clone() }
}

/// `--expect bore=D` / `od=D`: the diameter over the longest section of that kind (a bore: the
/// inner diameter where there is one; the outside: where there is material) within 0.02 mm.
fn sizes(m: &mut Measurement, opts: &SimOptions) {
    let longest = |inside: bool| {
        m.profile
            .iter()
            .filter(|r| r.outer_diameter_mm > 0.0 && (!inside || r.inner_diameter_mm > 0.0))
            .max_by(|a, b| a.length_mm().total_cmp(&b.length_mm()))
            .map(|r| if inside { r.inner_diameter_mm } else { r.outer_diameter_mm })
    };
    for (what, want, inside) in [("bore", opts.expect_bore_mm, true), ("outside diameter", opts.expect_od_mm, false)] {
        let Some(want) = want else { continue };
        let message = match longest(inside) {
            Some(got) if (got - want).abs() <= 0.02 => continue,
            Some(got) => format!("{what} {got:.3} mm over its longest section, {want:.3} mm expected ({:+.3} mm)", got - want),
            None => format!("no {what} to compare with {want:.3} mm"),
        };
        m.findings.push(Finding { kind: "deviation", line: 0, message, at: None, tool: None });
    }
}

fn deviation(m: &mut Measurement, e: &Expected, dz: f64, last_thread: Option<&Record>) {
    // Placed at the thread's last pass (its line, end point and time).
    let place = |kind, message: String| match last_thread {
        Some(r) => Finding::at(kind, r, r.op.end_point().unwrap_or_default(), true, None, message),
        None => Finding { kind, line: 0, message, at: None, tool: None },
    };
    let checks = [("major diameter", m.major_diameter_mm, e.major_mm, 2.0 * dz + 0.02), ("minor diameter", m.minor_diameter_mm, e.minor_mm, 2.0 * dz + 0.02), ("pitch", m.pitch_mm, e.pitch_mm, dz + 0.005)];
    for (what, got, want, tol) in checks {
        match got {
            Some(g) if (g - want).abs() > tol => m.findings.push(place("deviation", format!("{what} {g:.3} mm, {} has {want:.3} mm ({:+.3} mm)", e.name, g - want))),
            None => m.findings.push(place("deviation", format!("no {what} could be measured to compare with {}", e.name))),
            _ => {}
        }
    }
}

/// Groove bottoms along one row: the centres of the runs below `level`.
fn grooves(row: &[f32], z: impl Fn(usize) -> f64, level: f32, internal: bool) -> Vec<f64> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, &v) in row.iter().enumerate() {
        let inside = if internal { v > level } else { v < level };
        match (inside, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                out.push((z(s) + z(i - 1)) / 2.0);
                start = None;
            }
            _ => {}
        }
    }
    out
}

fn median(mut v: Vec<f64>) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    Some(v[v.len() / 2])
}

fn measure(stock: &LatheStock, records: &[Record], tools: &[Tool]) -> Measurement {
    let g = stock.grid;
    let internal = stock.internal;
    let mut m = Measurement {
        stock_diameter_mm: stock.bar.diameter_mm,
        dz_mm: g.dz_mm,
        dtheta_deg: g.dtheta_deg(),
        cell_updates: stock.updates,
        stock_guessed: None,
        ..Measurement::default()
    };
    m.findings = phase_findings(records, tools);
    // The threaded region: where thread records ran.
    let (mut z_lo, mut z_hi) = (f64::MAX, f64::MIN);
    for r in records {
        if let Op::Thread { from, to, .. } | Op::ThreadArc { from, to, .. } = r.op {
            z_lo = z_lo.min(from.z.min(to.z));
            z_hi = z_hi.max(from.z.max(to.z));
        }
    }
    if z_lo > z_hi {
        return m;
    }
    let i_lo = ((z_lo - g.z0_mm) / g.dz_mm).floor().max(0.0) as usize;
    let i_hi = (((z_hi - g.z0_mm) / g.dz_mm).ceil().max(0.0) as usize).min(g.nz - 1);
    if i_lo >= i_hi {
        return m;
    }
    // One pass in memory order, rows in parallel: around each z the deepest point (the
    // envelope) and the shallowest (the crest).
    let deeper = |a: f32, b: f32| if internal { a.max(b) } else { a.min(b) };
    let shallower = |a: f32, b: f32| if internal { a.min(b) } else { a.max(b) };
    let n = i_hi - i_lo + 1;
    let empty = || (vec![if internal { f32::MIN } else { f32::MAX }; n], vec![if internal { f32::MAX } else { f32::MIN }; n]);
    let (envelope, crest) = stock
        .measured()
        .par_chunks(g.nz)
        .fold(empty, |(mut env, mut top), row| {
            for ((e, t), &v) in env.iter_mut().zip(top.iter_mut()).zip(&row[i_lo..=i_hi]) {
                *e = deeper(*e, v);
                *t = shallower(*t, v);
            }
            (env, top)
        })
        .reduce(empty, |(mut env_a, mut top_a), (env_b, top_b)| {
            env_a.iter_mut().zip(&env_b).for_each(|(a, &b)| *a = deeper(*a, b));
            top_a.iter_mut().zip(&top_b).for_each(|(a, &b)| *a = shallower(*a, b));
            (env_a, top_a)
        });
    // The thread is where the threading tool cut a full profile: the columns whose crest stands
    // at the thread's crest. A lead-in chamfer, a neck or a relief the thread passes over has a
    // lower crest and is not the thread (issue 15: a 2 mm chamfer made "minor 20 mm").
    let top = crest.iter().copied().fold(if internal { f32::MAX } else { f32::MIN }, shallower);
    let bottom = envelope.iter().copied().fold(if internal { f32::MIN } else { f32::MAX }, deeper);
    let full = (top - bottom).abs();
    let tol = (0.15 * full).max(2.0 * g.dz_mm as f32);
    let at_crest: Vec<bool> = crest.iter().map(|&c| (c - top).abs() <= tol).collect();
    // The longest run of such columns.
    let (mut best, mut run_start) = ((0usize, 0usize), None);
    for (k, &ok) in at_crest.iter().chain(std::iter::once(&false)).enumerate() {
        match (ok, run_start) {
            (true, None) => run_start = Some(k),
            (false, Some(s)) => {
                if k - s > best.1 - best.0 {
                    best = (s, k);
                }
                run_start = None;
            }
            _ => {}
        }
    }
    let (a, b) = if best.1 > best.0 + 1 { (best.0, best.1 - 1) } else { (0, n - 1) };
    let (i_lo, i_hi) = (i_lo + a, i_lo + b);
    let envelope: Vec<f32> = envelope[a..=b].to_vec();
    let crest = &crest[a..=b];
    let lo = envelope.iter().chain(crest).copied().fold(f32::MAX, f32::min);
    let hi = envelope.iter().chain(crest).copied().fold(f32::MIN, f32::max);
    // External: the crest is the largest radius, the root the smallest; a bore the other way
    // round, and its major diameter is still the largest.
    let (major_r, minor_r) = (hi, lo);
    let depth = (major_r - minor_r) as f64;
    m.major_diameter_mm = Some(2.0 * major_r as f64);
    m.minor_diameter_mm = Some(2.0 * minor_r as f64);
    m.depth_mm = Some(depth);
    if depth <= 2.0 * g.dz_mm {
        return m;
    }
    // Groove bottoms: within 10 % of the depth from the root.
    let root = if internal { major_r } else { minor_r };
    let level = if internal { root - 0.1 * depth as f32 } else { root + 0.1 * depth as f32 };
    let zf = |i: usize| g.z(i_lo + i);
    let row0: Vec<f64> = grooves(&stock.row(0)[i_lo..=i_hi], zf, level, internal);
    let pitch = median(row0.windows(2).map(|w| w[1] - w[0]).collect());
    m.pitch_mm = pitch;
    // Lead: follow one groove once around.
    if let (Some(p), Some(&c0)) = (pitch, row0.get(row0.len() / 2)) {
        let mut c = c0;
        let mut ok = true;
        // Look only a little around the groove being followed.
        let span = ((2.0 * p / g.dz_mm).ceil() as usize).max(4);
        for j in 1..=g.ntheta {
            let ci = ((c - g.z0_mm) / g.dz_mm).round().max(0.0) as usize;
            let (a, b) = (ci.saturating_sub(span).max(i_lo), (ci + span).min(i_hi));
            if a >= b {
                ok = false;
                break;
            }
            let row = grooves(&stock.row(j % g.ntheta)[a..=b], |i| g.z(a + i), level, internal);
            let next = row.iter().copied().min_by(|a, b| (a - c).abs().total_cmp(&(b - c).abs()));
            match next {
                Some(n) if (n - c).abs() < p / 2.0 => c = n,
                _ => {
                    ok = false;
                    break;
                }
            }
        }
        if ok {
            let shift = c - c0;
            let lead = shift.abs();
            if lead > g.dz_mm {
                m.lead_mm = Some(lead);
                m.hand = Some(if shift < 0.0 { "right" } else { "left" });
                let starts = (lead / p).round().max(1.0) as u32;
                m.starts = Some(starts);
                m.start_spacing_deg = Some(360.0 / starts as f64);
            }
        }
    }
    // Flank angles: a middle groove of row 0, the points between 20 % and 80 % of the depth.
    if let Some(&c) = row0.get(row0.len() / 2) {
        let row = stock.row(0);
        let ci = ((c - g.z0_mm) / g.dz_mm).round() as isize;
        let fit = |dir: isize| -> Option<f64> {
            let (mut pts, mut i) = (Vec::new(), ci);
            while i >= 0 && (i as usize) < g.nz {
                let d = (row[i as usize] - minor_r).abs() as f64 / depth;
                let d = if internal { 1.0 - d } else { d };
                if d > 0.8 {
                    break;
                }
                if d >= 0.2 {
                    pts.push((g.z(i as usize), row[i as usize] as f64));
                }
                i += dir;
            }
            if pts.len() < 3 {
                return None;
            }
            let n = pts.len() as f64;
            let (mz, mr) = (pts.iter().map(|p| p.0).sum::<f64>() / n, pts.iter().map(|p| p.1).sum::<f64>() / n);
            let (sxy, sxx) = pts.iter().fold((0.0, 0.0), |(a, b), p| (a + (p.0 - mz) * (p.1 - mr), b + (p.0 - mz).powi(2)));
            let slope = (sxy / sxx).abs(); // radial per axial
            Some((1.0 / slope).atan().to_degrees())
        };
        if let (Some(a), Some(b)) = (fit(-1), fit(1)) {
            m.flank_angles_deg = Some((a, b));
        }
    }
    // Full depth and run-out along z, from the deepest point around each z.
    let mut full = 0usize;
    let mut partial = 0usize;
    for &env in &envelope {
        let reached = ((env - if internal { minor_r } else { major_r }).abs() as f64) / depth;
        if reached >= 0.95 {
            full += 1;
        } else if reached > 0.05 {
            partial += 1;
        }
    }
    m.full_depth_length_mm = Some(full as f64 * g.dz_mm);
    m.runout_length_mm = Some(partial as f64 * g.dz_mm);
    m
}

/// Phase: a later pass of a thread that does not fall in the groove its first passes cut. The
/// groove of a pass is where it would cross z = 0 in angle: `start angle - 360 z / lead`. A pass
/// may sit off by as much as its flank infeed allows (G76, YASNAC K): the difference in depth
/// times tan(half the tool angle).
fn phase_findings(records: &[Record], tools: &[Tool]) -> Vec<Finding> {
    struct Ref {
        lead: f64,
        line: u32,
        grooves: Vec<f64>,
        x: f64,
    }
    let mut refs: Vec<Ref> = Vec::new();
    let mut out = Vec::new();
    let mut prev_end = None;
    for (r, tool) in records.iter().zip(tools) {
        let (Op::Thread { from, to, lead_mm, spindle_deg, rpm, .. } | Op::ThreadArc { from, to, lead_mm, spindle_deg, rpm, .. }) = r.op else {
            prev_end = None;
            continue;
        };
        let first_of_pass = prev_end != Some(from);
        prev_end = Some(to);
        if !first_of_pass {
            continue;
        }
        let angle = if rpm >= 0.0 { spindle_deg } else { (360.0 - spindle_deg).rem_euclid(360.0) };
        let dir = if rpm >= 0.0 { 1.0 } else { -1.0 };
        let groove = (angle - dir * 360.0 * from.z / lead_mm).rem_euclid(360.0);
        match refs.iter_mut().find(|f| (f.lead - lead_mm).abs() < 1e-9) {
            None => refs.push(Ref { lead: lead_mm, line: r.span.line, grooves: vec![groove], x: from.x }),
            Some(f) if f.line == r.span.line => f.grooves.push(groove),
            Some(f) => {
                let off = f
                    .grooves
                    .iter()
                    .map(|g| {
                        let d = (groove - g).rem_euclid(360.0);
                        d.min(360.0 - d)
                    })
                    .fold(f64::MAX, f64::min);
                let axial = off / 360.0 * lead_mm;
                let half = (tool.included_angle_deg / 2.0).to_radians().tan();
                let allowed = (from.x - f.x).abs() * half + 1e-3 * lead_mm + 1e-6;
                if axial > allowed {
                    let msg = format!(
                        "this pass is {off:.3} degrees ({axial:.4} mm along the thread) off the groove cut at line {}: it cuts a new groove",
                        f.line
                    );
                    out.push(Finding::at("phase", r, from, true, Some(spindle_deg), msg));
                }
            }
        }
    }
    out
}
