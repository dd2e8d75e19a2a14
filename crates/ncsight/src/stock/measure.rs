//! Running a programme's records through the stock, and measuring the thread that results from
//! the cut surface, not from the programme: diameters, depth, pitch, lead, starts, flank angles,
//! full-depth and run-out lengths, deviation from a named thread, and the findings (phase error
//! between passes, a rapid into the stock, the tool past the stock's end).

use super::lathe::{Finding, LatheStock};
use super::standard::Expected;
use super::survey::{LatheSurvey, MillSurvey};
use super::{Bar, Setup, Tool};
use crate::motion::{Op, Record};
use rayon::prelude::*;

pub use super::survey::GUESS_HOLD_MM;

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

/// A drilling and milling simulation on a machining centre.
pub struct MillSimulation {
    pub stock: super::mill::MillStock,
    pub holes: Vec<super::mill::Hole>,
    pub findings: Vec<Finding>,
    /// The tools the setup does not describe, as assumed from what they do.
    pub assumed_tools: Vec<(u32, Tool)>,
    /// The block when it was guessed from the cuts (no `[block]`, no `--stock`).
    pub block_guessed: Option<super::mill::Block>,
}

/// Run a machining centre's records through a block: a survey, then the cut (see
/// [`MillCut`]). Records that end after `until_s` are not cut.
pub fn simulate_mill(records: &[Record], setup: &Setup, cell_mm: Option<f64>, until_s: Option<f64>) -> Result<MillSimulation, String> {
    let mut survey = MillSurvey::default();
    records.iter().for_each(|r| survey.add(r));
    let mut cut = MillCut::new(&survey, setup, cell_mm, until_s)?;
    records.iter().for_each(|r| cut.add(r));
    Ok(cut.finish())
}

/// The cut of a machining centre's block, record by record, after a [`MillSurvey`] of the same
/// records. Without a block in the setup: the cuts' extent and the widest cutting tool's radius
/// around it (what the tools swept, no more: material beyond is not known to be there, and a
/// guess must not make crashes), its top at Z0, 5 mm below the deepest cut.
pub struct MillCut {
    stock: super::mill::MillStock,
    turret: Turret,
}

/// What a cut follows record by record, on a lathe or a machining centre: the tool in the
/// turret or spindle (the setup's, or the one the survey assumed), the spindle's speed, the
/// records not cut (up to and including the first rapid: where the tool is before it is the
/// machine's business, not the programme's), the time cutting stops at, and the last
/// programme stop.
struct Turret {
    setup: Setup,
    assumed: Vec<(u32, Tool)>,
    /// A machining centre's: a tool the setup lacks and the survey did not assume is the
    /// default drill, not the default threading insert.
    mill: bool,
    tool: Tool,
    rpm: f64,
    /// Records up to and including this one are not cut (the first rapid), and how many came.
    skip: usize,
    seen: usize,
    until_s: Option<f64>,
    stops: StopNote,
}

impl Turret {
    fn new(setup: &Setup, assumed: Vec<(u32, Tool)>, mill: bool, first_rapid: Option<usize>, until_s: Option<f64>) -> Turret {
        let mut t = Turret {
            setup: setup.clone(),
            assumed,
            mill,
            tool: Tool::default_thread(),
            rpm: 0.0,
            skip: first_rapid.unwrap_or(0),
            seen: 0,
            until_s,
            stops: StopNote::default(),
        };
        t.tool = t.tool_for(0, None);
        t
    }

    /// The tool of a T number: the setup's, or the one assumed. A turning or boring tool whose
    /// [[tool]] gives no imaginary nose takes the one of its offset (T0101 -> [[offset]] 1),
    /// and that offset's radius if it gives none (a machining centre's tool change names no
    /// offset).
    fn tool_for(&self, number: u32, offset: Option<u32>) -> Tool {
        let given = || if self.mill { self.setup.mill_tool(number) } else { self.setup.tool(number) };
        let mut t = self.assumed.iter().find(|(n, _)| *n == number).map(|(_, t)| *t).unwrap_or_else(given);
        if t.tip.is_none() && matches!(t.kind, super::ToolKind::Turning | super::ToolKind::Boring) {
            if let Some(o) = offset.and_then(|n| self.setup.offset(n)).filter(|o| o.tip != 0 || o.radius_mm > 0.0) {
                t.tip = Some(o.tip);
                if t.tip_radius_mm <= 0.0 {
                    t.tip_radius_mm = o.radius_mm + o.wear_radius_mm;
                }
            }
        }
        t
    }

    /// Take one record in: the tool, the spindle and the last stop follow it. None when it ends
    /// after the time cutting stops at; else whether it is cut.
    fn take(&mut self, r: &Record) -> Option<bool> {
        let k = self.seen;
        self.seen += 1;
        if self.until_s.is_some_and(|t| r.t_s > t) {
            return None;
        }
        match r.op {
            Op::Tool { number, offset } => self.tool = self.tool_for(number, offset),
            Op::Spindle { rpm, .. } => self.rpm = rpm,
            _ => {}
        }
        self.stops.see(r);
        Some(k > self.skip)
    }
}

/// The last programme stop (M00, M01) before a finding: a part turned over or re-clamped there
/// (a second operation) is not known to the stock, so a crash after it says so.
#[derive(Default)]
struct StopNote {
    line: Option<u32>,
}

impl StopNote {
    fn see(&mut self, r: &Record) {
        if let Op::Stop { reason: crate::motion::StopReason::ProgramStop | crate::motion::StopReason::OptionalStop } = r.op {
            self.line = Some(r.span.line);
        }
    }

    /// Findings made after a stop: a crash, holder or chuck finding says so.
    fn mark(&self, findings: &mut [Finding]) {
        let Some(line) = self.line else { return };
        for f in findings.iter_mut().filter(|f| matches!(f.kind, "crash" | "holder" | "chuck")) {
            f.message.push_str(&format!(" (after the programme stop at line {line}: if the part was turned over or clamped again there, the simulation does not know it: it goes on with the stock as cut)"));
        }
    }
}

impl MillCut {
    pub fn new(survey: &MillSurvey, setup: &Setup, cell_mm: Option<f64>, until_s: Option<f64>) -> Result<MillCut, String> {
        let top = setup.block.map_or(0.0, |b| b.max_mm[2]);
        let turret = Turret::new(setup, survey.assumed_tools(setup, top), true, survey.first_rapid, until_s);
        let block = match setup.block {
            Some(b) => b,
            None if survey.cuts() => {
                let (lo, hi) = (survey.cut_min, survey.cut_max);
                let m = survey.cutting_tools().map(|n| turret.tool_for(n, None).diameter_mm / 2.0).fold(0.0, f64::max);
                super::mill::Block { min_mm: [lo[0] - m, lo[1] - m, lo[2].min(0.0) - 5.0], max_mm: [hi[0] + m, hi[1] + m, 0.0] }
            }
            None => return Err("no block: give one in the setup ([block] min_mm, max_mm) or --stock XxYxZ; the programme cuts nothing to infer it from".into()),
        };
        let cell = cell_mm.unwrap_or(0.1);
        let cells = ((block.max_mm[0] - block.min_mm[0]) / cell) * ((block.max_mm[1] - block.min_mm[1]) / cell);
        if !(cell > 0.0) || cells > 100e6 {
            return Err(format!("a grid of {cells:.0} cells: coarsen --resolution"));
        }
        Ok(MillCut { stock: super::mill::MillStock::new(block, cell), turret })
    }

    /// Cut one record (a tool change or a spindle record cuts nothing).
    pub fn add(&mut self, r: &Record) {
        if self.turret.take(r) != Some(true) {
            return;
        }
        let t = &self.turret;
        let before = self.stock.findings.len();
        self.stock.apply(r, &t.tool, t.rpm);
        t.stops.mark(&mut self.stock.findings[before..]);
    }

    pub fn finish(mut self) -> MillSimulation {
        let holes = self.stock.holes();
        let mut findings = std::mem::take(&mut self.stock.findings);
        let block_guessed = self.turret.setup.block.is_none().then_some(self.stock.block);
        if block_guessed.is_some() {
            // The guess holds every cut's reach; between the cuts it may hold material the real
            // stock has not (round a contour's corners, say): said with each finding.
            for f in findings.iter_mut().filter(|f| matches!(f.kind, "crash" | "holder")) {
                f.message.push_str(" (against a guessed block: give --stock XxYxZ or [block] for the real one)");
            }
        }
        MillSimulation { stock: self.stock, holes, findings, assumed_tools: self.turret.assumed, block_guessed }
    }
}

/// Run the records through the stock and measure.
pub fn simulate(records: &[Record], setup: &Setup, opts: &SimOptions) -> Result<Simulation, String> {
    simulate_with(records, setup, opts, &mut |_, _| {})
}

/// The most cell updates a lathe simulation may need (about a minute on two cores): past it the
/// simulation refuses at once instead of running for hours (docs/commands/simulate.md).
pub const MAX_CELL_UPDATES: f64 = 50e9;

/// [`simulate`] that reports its progress: `progress(done, total)` after each record.
pub fn simulate_with(records: &[Record], setup: &Setup, opts: &SimOptions, progress: &mut dyn FnMut(usize, usize)) -> Result<Simulation, String> {
    let mut survey = LatheSurvey::new(setup);
    records.iter().for_each(|r| survey.add(r));
    let mut cut = LatheCut::new(&survey, setup, opts)?;
    for (k, r) in records.iter().enumerate() {
        cut.add(r);
        progress(k + 1, records.len());
    }
    Ok(cut.finish(opts))
}

/// The cut of a lathe's stock, record by record, after a [`LatheSurvey`] of the same records:
/// the tool in the turret follows the T words (a tool the setup does not describe is the one
/// the survey assumed), the spindle its S and M words; the thread's passes are followed for
/// their phase and the threaded range for the measurement.
pub struct LatheCut {
    stock: LatheStock,
    turret: Turret,
    guessed: Option<Bar>,
    phase: Phase,
    /// The threaded range along Z, and the last thread record (a deviation is placed there).
    thread_z: Option<(f64, f64)>,
    last_thread: Option<Record>,
}

impl LatheCut {
    pub fn new(survey: &LatheSurvey, setup: &Setup, opts: &SimOptions) -> Result<LatheCut, String> {
        let assumed = survey.assumed_tools(setup);
        let internal = survey.threads_inside(setup, &assumed);
        let (bar, guessed) = match setup.stock {
            Some(b) => (b, None),
            None => match survey.guessed_bar(internal) {
                Some(b) => (b, Some(b)),
                None => return Err("no stock: give --stock DIAxLEN or a setup (the programme cuts nothing to guess it from)".into()),
            },
        };
        let max_lead = survey.max_lead_mm;
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
        let work = survey.work_estimate(dz, ntheta);
        if work > MAX_CELL_UPDATES {
            return Err(format!(
                "the simulation would need about {:.0} G cell updates, more than its limit of {:.0} G (about a minute): coarsen --resolution or simulate fewer passes",
                work / 1e9,
                MAX_CELL_UPDATES / 1e9
            ));
        }
        let mut stock = LatheStock::new(bar, internal, dz, ntheta);
        // A tool assumed to turn may be a boring bar whose retracts did not show it: each of its
        // moves cuts the nearer side. One assumed to bore (it leaves its cuts toward the axis)
        // works inside, as a boring bar in a tube the guessed stock does not know the bore of.
        stock.either_side = assumed.iter().filter(|(_, t)| t.kind == super::ToolKind::Turning).map(|(n, _)| *n).collect();
        let turret = Turret::new(setup, assumed, false, survey.first_rapid, opts.until_s);
        Ok(LatheCut { stock, turret, guessed, phase: Phase::default(), thread_z: None, last_thread: None })
    }

    /// Cut one record; a thread's passes are followed for their phase and range whether or not
    /// they are cut.
    pub fn add(&mut self, r: &Record) {
        let Some(cut) = self.turret.take(r) else { return };
        let t = &self.turret;
        self.phase.add(r, &t.tool);
        if let Op::Thread { from, to, .. } | Op::ThreadArc { from, to, .. } = r.op {
            let (lo, hi) = self.thread_z.unwrap_or((f64::MAX, f64::MIN));
            self.thread_z = Some((lo.min(from.z).min(to.z), hi.max(from.z).max(to.z)));
            self.last_thread = Some(r.clone());
        }
        if !cut {
            return;
        }
        let before = self.stock.findings.len();
        match nose_shift(&t.tool) {
            Some(d) => self.stock.apply(&shifted(r, d), &t.tool, t.rpm),
            None => self.stock.apply(r, &t.tool, t.rpm),
        }
        t.stops.mark(&mut self.stock.findings[before..]);
    }

    /// The stock after the records, and its measurement.
    pub fn finish(mut self, opts: &SimOptions) -> Simulation {
        let dz = self.stock.grid.dz_mm;
        let mut m = measure(&self.stock, self.thread_z);
        m.findings = std::mem::take(&mut self.phase.findings);
        m.assumed_tools = self.turret.assumed;
        if let Some(e) = &opts.expect {
            deviation(&mut m, e, dz, self.last_thread.as_ref());
        }
        m.findings.splice(0..0, self.stock.findings.iter().cloned());
        m.profile = self.stock.profile();
        sizes(&mut m, opts);
        if let Some(bar) = self.guessed {
            m.stock_guessed = Some(bar);
            // A chuck found against a stock nobody gave may not be there: said with each finding.
            for f in m.findings.iter_mut().filter(|f| f.kind == "chuck") {
                f.message.push_str(" (against a guessed stock: give --stock DIAxLEN for the real bar and chuck)");
            }
        }
        Simulation { stock: self.stock, measurement: m }
    }
}

/// A turning tool with an imaginary tool nose (its `tip`) is positioned by that point: the stock
/// cuts with the nose, whose lowest point (highest in a bore) lies R x d(tip) and R from it
/// (docs/compensation.md). Without a tip, the record's point is the nose's.
fn nose_shift(t: &Tool) -> Option<crate::motion::Vec3> {
    let tip = t.tip?;
    if !matches!(t.kind, super::ToolKind::Turning | super::ToolKind::Boring) || t.tip_radius_mm <= 0.0 {
        return None;
    }
    let r = t.tip_radius_mm;
    let (dx, dz) = crate::comp::tip_direction(tip);
    let side = if super::lathe::cuts_inside(t) { 1.0 } else { -1.0 };
    Some(crate::motion::Vec3::new(-r * dx + side * r, 0.0, -r * dz))
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
    let checks = [
        ("major diameter", m.major_diameter_mm, e.major_mm, 2.0 * dz + 0.02),
        ("minor diameter", m.minor_diameter_mm, e.minor_mm, 2.0 * dz + 0.02),
        ("pitch", m.pitch_mm, e.pitch_mm, dz + 0.005),
    ];
    for (what, got, want, tol) in checks {
        match got {
            Some(g) if (g - want).abs() > tol => {
                m.findings.push(place("deviation", format!("{what} {g:.3} mm, {} has {want:.3} mm ({:+.3} mm)", e.name, g - want)))
            }
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

/// The thread cut within `thread_z` (the thread records' range along Z), measured on the
/// stock.
fn measure(stock: &LatheStock, thread_z: Option<(f64, f64)>) -> Measurement {
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
    // The threaded region: where thread records ran.
    let Some((z_lo, z_hi)) = thread_z else { return m };
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
    lead_of(&mut m, stock, &row0, pitch, (i_lo, i_hi), level);
    m.flank_angles_deg = flank_angles(stock, &row0, minor_r, depth);
    let (full, partial) = depth_lengths(&envelope, if internal { minor_r } else { major_r }, depth, g.dz_mm);
    m.full_depth_length_mm = Some(full);
    m.runout_length_mm = Some(partial);
    m
}

/// Full depth and run-out along z, mm: the cells whose deepest point around (`envelope`) is
/// within 5 % of the thread's `depth` from the `crest`, and those between 5 % and 95 % of it.
fn depth_lengths(envelope: &[f32], crest: f32, depth: f64, dz_mm: f64) -> (f64, f64) {
    let (mut full, mut partial) = (0usize, 0usize);
    for &env in envelope {
        let reached = ((env - crest).abs() as f64) / depth;
        if reached >= 0.95 {
            full += 1;
        } else if reached > 0.05 {
            partial += 1;
        }
    }
    (full as f64 * dz_mm, partial as f64 * dz_mm)
}

/// The lead and hand: one groove of row 0 (`row0`, the grooves' z) followed once around, from
/// row to row within a little of where it was (`span`: the thread's cells `i_lo..=i_hi`).
fn lead_of(m: &mut Measurement, stock: &LatheStock, row0: &[f64], pitch: Option<f64>, (i_lo, i_hi): (usize, usize), level: f32) {
    let g = stock.grid;
    let internal = stock.internal;
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
}

/// The flank angles of a middle groove of row 0, from the points between 20 % and 80 % of the
/// depth on each side.
fn flank_angles(stock: &LatheStock, row0: &[f64], minor_r: f32, depth: f64) -> Option<(f64, f64)> {
    let g = stock.grid;
    let internal = stock.internal;
    let c = *row0.get(row0.len() / 2)?;
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
    Some((fit(-1)?, fit(1)?))
}

/// The grooves a lead's thread passes may fall in (its starts): at most this many are kept.
const MAX_GROOVES: usize = 360;

/// Phase: a later pass of a thread that does not fall in the groove its first passes cut. The
/// groove of a pass is where it would cross z = 0 in angle: `start angle - 360 z / lead`. A pass
/// may sit off by as much as its flank infeed allows (G76, YASNAC K): the difference in depth
/// times tan(half the tool angle). Followed record by record.
#[derive(Default)]
struct Phase {
    /// Per lead: the line of its first pass, the grooves that line cut, its first pass's X.
    refs: Vec<PhaseRef>,
    prev_end: Option<crate::motion::Vec3>,
    findings: Vec<Finding>,
}

struct PhaseRef {
    lead: f64,
    line: u32,
    grooves: Vec<f64>,
    x: f64,
}

impl Phase {
    fn add(&mut self, r: &Record, tool: &Tool) {
        let (Op::Thread { from, to, lead_mm, spindle_deg, rpm, .. } | Op::ThreadArc { from, to, lead_mm, spindle_deg, rpm, .. }) = r.op else {
            self.prev_end = None;
            return;
        };
        let first_of_pass = self.prev_end != Some(from);
        self.prev_end = Some(to);
        if !first_of_pass {
            return;
        }
        let angle = if rpm >= 0.0 { spindle_deg } else { (360.0 - spindle_deg).rem_euclid(360.0) };
        let dir = if rpm >= 0.0 { 1.0 } else { -1.0 };
        let groove = (angle - dir * 360.0 * from.z / lead_mm).rem_euclid(360.0);
        match self.refs.iter_mut().find(|f| (f.lead - lead_mm).abs() < 1e-9) {
            None => self.refs.push(PhaseRef { lead: lead_mm, line: r.span.line, grooves: vec![groove], x: from.x }),
            Some(f) if f.line == r.span.line => {
                if f.grooves.len() < MAX_GROOVES {
                    f.grooves.push(groove);
                }
            }
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
                    let msg =
                        format!("this pass is {off:.3} degrees ({axial:.4} mm along the thread) off the groove cut at line {}: it cuts a new groove", f.line);
                    self.findings.push(Finding::at("phase", r, from, true, Some(spindle_deg), msg));
                }
            }
        }
    }
}
