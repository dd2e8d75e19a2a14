//! The lathe stock as a solid of revolution with a bore: for every angle theta (the C axis's
//! positive direction, 0 at the one-revolution signal) and every z, the material lies between
//! an inner radius (the bore, 0 where the part is solid to the axis) and an outer radius. A slice
//! whose outer radius meets its inner one has been parted off or cut through.
//!
//! A thread record cuts each theta column where the tool passes it: the tool is at column theta
//! when the spindle angle is theta, i.e. once per revolution, one lead apart, at the position
//! the record's start angle and lead give (this is why `spindle_deg` must be right). Other
//! cutting moves with the spindle turning sweep every column. A tool that works outside (a
//! turning, grooving or external threading tool) lowers the outer radius to what it leaves; one
//! that works inside (a boring bar, an internal threading tool) raises the inner radius; a drill
//! on the spindle axis raises the inner radius to its own, its point's cone at the bottom.

use super::{Bar, Tool};
use crate::motion::{LongAxis, Op, Record, Vec3};
use rayon::prelude::*;

/// Grid spacing and extent.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// z of the first cell (the far end of the stock).
    pub z0_mm: f64,
    pub dz_mm: f64,
    pub nz: usize,
    pub ntheta: usize,
}

impl Grid {
    pub fn dtheta_deg(&self) -> f64 {
        360.0 / self.ntheta as f64
    }

    pub fn z(&self, i: usize) -> f64 {
        self.z0_mm + i as f64 * self.dz_mm
    }

    /// The cell of z (clamped), and whether z lies on the grid at all.
    fn cell(&self, z: f64) -> isize {
        ((z - self.z0_mm) / self.dz_mm).round() as isize
    }
}

/// Something the simulation found in the programme.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// `crash`, `chuck`, `phase`, `deviation`, `not_simulated`.
    pub kind: &'static str,
    pub line: u32,
    pub message: String,
    /// Where and when: the tool's position (X a diameter on a lathe), the spindle angle where
    /// it matters (a thread), and the time from programme start.
    pub at: Option<Place>,
    /// The tool's number (T), where one tool made it.
    pub tool: Option<u32>,
}

/// Where a finding happened.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Place {
    /// X as the controller shows it (a diameter on a lathe), Y, Z, mm.
    pub x_mm: f64,
    pub y_mm: f64,
    pub z_mm: f64,
    pub spindle_deg: Option<f64>,
    pub t_s: f64,
}

impl Finding {
    /// A finding of a record, placed at `p` (programme coordinates, X a radius on a lathe).
    pub fn at(kind: &'static str, rec: &Record, p: Vec3, diameter: bool, spindle_deg: Option<f64>, message: String) -> Finding {
        let x_mm = if diameter { 2.0 * p.x } else { p.x };
        Finding { kind, line: rec.span.line, message, at: Some(Place { x_mm, y_mm: p.y, z_mm: p.z, spindle_deg, t_s: rec.t_s }), tool: None }
    }

    /// Whether the finding is a problem with the programme (crash, chuck, phase, deviation), as
    /// opposed to a note on what was not simulated.
    pub fn is_problem(&self) -> bool {
        self.kind != "not_simulated"
    }
}

/// The stock being cut.
pub struct LatheStock {
    pub grid: Grid,
    pub bar: Bar,
    /// The surface the thread measurement reads: the bore (an internal thread) or the outside.
    pub internal: bool,
    /// The material's outer radius, one row of `nz` cells per theta.
    pub outer: Vec<f32>,
    /// The bore's radius (0 where the part is solid to the axis), one row of `nz` cells per theta.
    pub inner: Vec<f32>,
    pub findings: Vec<Finding>,
    /// Cells the tool visited (for the benchmark's figure).
    pub updates: u64,
    /// Where the last thread record ended, if the record just applied was one.
    last_thread_end: Option<Vec3>,
    /// Where the spindle was when that thread ended (degrees in its direction of turning), its
    /// speed (signed rpm) and the time: a rapid straight after it sweeps only the angles the
    /// spindle turns through while it runs.
    last_thread_turn: Option<(f64, f64, f64)>,
    /// Where the last rapid that crashed ended, if the record just applied was one: the rapid
    /// after it starts in the material the crash reported, and is not a crash of its own.
    last_crash_end: Option<Vec3>,
    /// For each z cell, the smallest bore and the largest outside at any angle (the rapids' crash
    /// check and the profile read them).
    least_inner: Vec<f32>,
    most_outer: Vec<f32>,
    /// Cells cut since their extremes were last worked out.
    stale: Vec<bool>,
    /// Tools (T numbers) assumed without a setup, whose side is not known: each of their moves
    /// cuts from the side of the material it is nearer to (a bar that feeds 1 mm from a bore's
    /// wall and 11 mm below the outside is boring).
    pub either_side: Vec<u32>,
    /// The tool and spindle direction of the last `spindle` finding (one until either changes).
    spindle_flagged: Option<(u32, i32)>,
    /// Boring bars already found in a bore too small for them.
    bore_flagged: Vec<u32>,
}

/// A run of the part's profile (see [`LatheStock::profile`]), mm; X as diameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileRow {
    pub z_from_mm: f64,
    pub z_to_mm: f64,
    pub outer_diameter_mm: f64,
    pub inner_diameter_mm: f64,
}

impl ProfileRow {
    pub fn length_mm(&self) -> f64 {
        (self.z_from_mm - self.z_to_mm).abs()
    }
}

/// A tool's profile on both sides of its tip (see [`LatheStock::profile_table`]).
struct Tables {
    /// Toward -Z: cells below the tip's.
    chuck: Vec<f32>,
    /// Toward +Z: cells above the tip's.
    face: Vec<f32>,
}

/// Whether a tool works inside a bore (raising the inner radius) rather than outside.
pub fn cuts_inside(tool: &Tool) -> bool {
    tool.internal || tool.kind == super::ToolKind::Boring
}

/// An arc record (`Arc` or `ThreadArc`) as points from its start to its end, in `pieces(its
/// length)` equal steps.
fn arc_samples(op: &Op, pieces: impl Fn(f64) -> usize) -> Vec<Vec3> {
    let (Op::Arc { from, to, plane, dir, .. } | Op::ThreadArc { from, to, plane, dir, .. }) = *op else {
        return Vec::new();
    };
    let Some(g) = crate::geom::arc_geom_of(op) else {
        return vec![from, to];
    };
    let n = pieces(crate::geom::arc_length(&from, &to, plane, &g)).max(1);
    (0..=n).map(|k| crate::geom::arc_point(&from, &to, plane, dir, &g, k as f64 / n as f64)).collect()
}

/// How much a rapid may touch the stock before it counts as a crash, mm.
const CRASH_MM: f64 = 0.01;

impl LatheStock {
    pub fn new(bar: Bar, internal: bool, dz_mm: f64, ntheta: usize) -> LatheStock {
        let nz = ((bar.length_mm / dz_mm).ceil() as usize).max(1) + 1;
        let grid = Grid { z0_mm: bar.front_z_mm - (nz - 1) as f64 * dz_mm, dz_mm, nz, ntheta: ntheta.max(4) };
        let cells = nz * grid.ntheta;
        LatheStock {
            grid,
            bar,
            internal,
            outer: vec![(bar.diameter_mm / 2.0) as f32; cells],
            inner: vec![(bar.bore_mm / 2.0) as f32; cells],
            findings: Vec::new(),
            updates: 0,
            last_thread_end: None,
            last_thread_turn: None,
            last_crash_end: None,
            least_inner: vec![(bar.bore_mm / 2.0) as f32; nz],
            most_outer: vec![(bar.diameter_mm / 2.0) as f32; nz],
            stale: vec![false; nz],
            either_side: Vec::new(),
            spindle_flagged: None,
            bore_flagged: Vec::new(),
        }
    }

    /// Cells `lo..=hi` were cut: their extremes are worked out again when next read.
    fn cut_cells(&mut self, lo: usize, hi: usize) {
        let hi = hi.min(self.grid.nz - 1);
        if lo <= hi {
            self.stale[lo..=hi].fill(true);
        }
    }

    /// The smallest bore and the largest outside of cell `i` at any angle.
    fn extremes(&mut self, i: usize) -> (f32, f32) {
        if self.stale[i] {
            let nz = self.grid.nz;
            let (mut least, mut most) = (f32::MAX, f32::MIN);
            for j in 0..self.grid.ntheta {
                least = least.min(self.inner[j * nz + i]);
                most = most.max(self.outer[j * nz + i]);
            }
            (self.least_inner[i], self.most_outer[i]) = (least, most);
            self.stale[i] = false;
        }
        (self.least_inner[i], self.most_outer[i])
    }

    /// The surface the thread measurement reads (see [`LatheStock::internal`]).
    pub fn measured(&self) -> &[f32] {
        if self.internal {
            &self.inner
        } else {
            &self.outer
        }
    }

    /// Row `j` (the column at theta = j x dtheta) of the measured surface.
    pub fn row(&self, j: usize) -> &[f32] {
        &self.measured()[j * self.grid.nz..(j + 1) * self.grid.nz]
    }

    /// The inner and outer radius at cell `i` of row `j`.
    pub fn material(&self, j: usize, i: usize) -> (f32, f32) {
        let k = j * self.grid.nz + i;
        (self.inner[k], self.outer[k])
    }

    /// The tool's cut surface radius at axial offsets 0, dz, 2dz, ... out to where it leaves
    /// the stock (a table, so the hot loop only looks it up), on each side of its tip: toward
    /// the chuck (-Z) and toward the face (+Z).
    fn profile_table(&self, tool: &Tool, tip_r: f64, inside: bool) -> Tables {
        // Beyond the radial distance to the untouched surface (the axis, inside) the tool cuts
        // nothing.
        let limit = if inside { tip_r } else { self.bar.diameter_mm / 2.0 - tip_r };
        let side = |chuck_side: bool| {
            let mut t = Vec::new();
            let mut k = 0usize;
            loop {
                let p = tool.profile_toward(k as f64 * self.grid.dz_mm, chuck_side);
                t.push(p as f32);
                if p > limit.max(0.0) || k > self.grid.nz {
                    break;
                }
                k += 1;
            }
            t
        };
        Tables { chuck: side(true), face: side(false) }
    }

    /// Stamp the tool with its tip at (z, radius) on one row; returns how deep it cut the most.
    #[inline]
    fn stamp(row: &mut [f32], grid: &Grid, t: &Tables, internal: bool, z: f64, tip_r: f64) -> (f32, u64) {
        let c = grid.cell(z);
        let lo = (c - (t.chuck.len() as isize - 1)).max(0);
        let hi = (c + (t.face.len() as isize - 1)).min(grid.nz as isize - 1);
        let mut deepest = 0.0f32;
        let mut n = 0u64;
        let tip = tip_r as f32;
        for i in lo..=hi {
            let e = if i < c { t.chuck[(c - i) as usize] } else { t.face[(i - c) as usize] };
            let cell = &mut row[i as usize];
            if internal {
                let cut = tip - e;
                if cut > *cell {
                    deepest = deepest.max(cut - *cell);
                    *cell = cut;
                    n += 1;
                }
            } else {
                let cut = tip + e;
                if cut < *cell {
                    deepest = deepest.max(*cell - cut);
                    *cell = cut;
                    n += 1;
                }
            }
        }
        (deepest, n)
    }

    /// Stamp the tool on one row, the hot loop of thread cutting: the cells on both sides of the
    /// tip take the smaller (bore: larger) of themselves and the tool's edge, a branch-free loop
    /// over contiguous cells that the compiler vectorises. Returns the cells visited.
    #[inline]
    fn stamp_fast(row: &mut [f32], grid: &Grid, t: &Tables, internal: bool, z: f64, tip_r: f64) -> u64 {
        let c = grid.cell(z);
        let (reach_face, reach_chuck) = (t.face.len() as isize - 1, t.chuck.len() as isize - 1);
        let n = grid.nz as isize;
        if c + reach_face < 0 || c - reach_chuck >= n {
            return 0;
        }
        let tip = tip_r as f32;
        // Toward the face (including the tip): face[0..]; toward the chuck: chuck[1..] going away.
        let r_lo = c.max(0);
        let r_hi = (c + reach_face).min(n - 1);
        let l_lo = (c - reach_chuck).max(0);
        let l_hi = (c - 1).min(n - 1);
        let mut visited = 0u64;
        if r_lo <= r_hi {
            let cells = &mut row[r_lo as usize..=r_hi as usize];
            let e = &t.face[(r_lo - c) as usize..];
            if internal {
                cells.iter_mut().zip(e).for_each(|(v, e)| *v = v.max(tip - e));
            } else {
                cells.iter_mut().zip(e).for_each(|(v, e)| *v = v.min(tip + e));
            }
            visited += cells.len() as u64;
        }
        if l_lo <= l_hi {
            let cells = &mut row[l_lo as usize..=l_hi as usize];
            let e = &t.chuck[(c - l_hi) as usize..];
            if internal {
                cells.iter_mut().rev().zip(e).for_each(|(v, e)| *v = v.max(tip - e));
            } else {
                cells.iter_mut().rev().zip(e).for_each(|(v, e)| *v = v.min(tip + e));
            }
            visited += cells.len() as u64;
        }
        visited
    }

    /// Apply one record with the tool in the turret and the spindle at `rpm` (signed: negative
    /// is M04; 0 stopped); what it finds names the tool.
    pub fn apply(&mut self, rec: &Record, tool: &Tool, rpm: f64) {
        let before = self.findings.len();
        let stuck = self.spindle_check(rec, tool, rpm);
        self.apply_tool(rec, tool, rpm != 0.0);
        if stuck {
            // The part does not turn, so the move cuts no round; the tool is left in the
            // material, and the rapid out of it is part of this finding, not a crash of its own.
            self.last_crash_end = rec.op.end_point();
        }
        self.bore_check(rec, tool);
        for f in &mut self.findings[before..] {
            f.tool = Some(tool.number);
        }
    }

    fn apply_tool(&mut self, rec: &Record, tool: &Tool, spindle_turning: bool) {
        let after_thread = self.last_thread_end.take();
        let thread_turn = self.last_thread_turn.take();
        let after_crash = self.last_crash_end.take();
        if tool.kind.on_spindle_axis() {
            self.apply_axial(rec, tool, spindle_turning);
            return;
        }
        let inside = match (rec.op.start_point(), rec.op.end_point()) {
            (Some(a), Some(b)) if tool.kind != super::ToolKind::Thread && self.either_side.contains(&tool.number) => self.nearer_inside(&[a, b]),
            _ => cuts_inside(tool),
        };
        match rec.op {
            Op::Thread { from, to, lead_mm, long_axis, spindle_deg, rpm } => {
                if long_axis != LongAxis::Z {
                    self.not_simulated(
                        rec,
                        from,
                        Some(spindle_deg),
                        "a thread with X as its long axis (a face or steep taper thread) is not cut in the stock simulation",
                    );
                    return;
                }
                self.chuck_check(rec, &from, &to);
                self.cut_thread(from, to, lead_mm, spindle_deg, rpm, tool, inside);
                self.last_thread_end = Some(to);
                let end_deg = crate::cycles::thread::phase_after(spindle_deg, (to.z - from.z).abs(), lead_mm);
                self.last_thread_turn = Some((end_deg, rpm, rec.t_s));
            }
            Op::ThreadArc { from, to, long_axis, lead_mm, spindle_deg, rpm, plane, .. } => {
                if plane != crate::motion::Plane::ZX {
                    // G17/G19: the arc leaves the XZ plane the lathe stock is a section of.
                    self.not_simulated(rec, from, Some(spindle_deg), "an arc thread outside the ZX plane (G17 or G19) is not cut in the stock simulation");
                    return;
                }
                if long_axis != LongAxis::Z {
                    self.not_simulated(
                        rec,
                        from,
                        Some(spindle_deg),
                        "an arc thread with X as its long axis (a face arc thread) is not cut in the stock simulation",
                    );
                    return;
                }
                self.chuck_check(rec, &from, &to);
                // Sampled finely along the arc; each piece is cut as a thread of the same lead,
                // its start angle where the spindle is when the tool gets there.
                let pts = arc_samples(&rec.op, |len| ((len / lead_mm.max(1e-6) * 8.0).ceil() as usize).clamp(8, 20_000));
                let mut deg = spindle_deg;
                for w in pts.windows(2) {
                    let (a, b) = (w[0], w[1]);
                    if b.z != a.z {
                        self.cut_thread(a, b, lead_mm, deg, rpm, tool, inside);
                    }
                    deg = crate::cycles::thread::phase_after(deg, (b.z - a.z).abs(), lead_mm);
                }
                self.last_thread_end = Some(to);
            }
            Op::Feed { from, to, .. } if spindle_turning => {
                self.chuck_check(rec, &from, &to);
                self.sweep(&[from, to], tool, inside);
            }
            Op::Arc { from, to, .. } if spindle_turning => {
                self.chuck_check(rec, &from, &to);
                let half_cell = self.grid.dz_mm / 2.0;
                let pts = arc_samples(&rec.op, |len| ((len / half_cell).ceil() as usize).clamp(2, 100_000));
                self.sweep(&pts, tool, inside);
            }
            Op::Rapid { from, to } => self.rapid(rec, from, to, tool, inside, after_thread, thread_turn, after_crash),
            _ => {}
        }
    }

    /// A rapid: a crash when its cutting point goes into the material (then it cuts its way);
    /// `after_thread` and `thread_turn`: the thread record just before it ended there, with the
    /// spindle's angle, speed and time; `after_crash`: a crash just left the tool there.
    #[allow(clippy::too_many_arguments)]
    fn rapid(
        &mut self,
        rec: &Record,
        from: Vec3,
        to: Vec3,
        tool: &Tool,
        inside: bool,
        after_thread: Option<Vec3>,
        thread_turn: Option<(f64, f64, f64)>,
        after_crash: Option<Vec3>,
    ) {
        // Where the rapid starts inside what is left of the stock, the thread's pull-out
        // before it ended there.
        let pull_out_inside = after_thread == Some(from) && self.in_material(&from);
        // A rapid crashes when its cutting point goes into the material (the flanks of
        // the insert's model are wider than a real insert's clearance: a rapid just in
        // front of the face is no crash); then it cuts what it passes.
        let dz = Vec3::new(0.0, 0.0, tool.edge_point_dz_mm());
        // Out of a thread's groove, a rapid that ends before the spindle has turned once
        // meets only the angles it turns through (the groove it leaves is at the first).
        let turned = thread_turn.filter(|_| after_thread == Some(from)).map(|(deg, rpm, t)| (deg, rpm, rpm.abs() / 60.0 * 360.0 * (rec.t_s - t).max(0.0)));
        let into = match turned {
            Some((deg, rpm, sweep)) if sweep < 360.0 => self.depth_turning(&[from + dz, to + dz], deg, sweep, rpm),
            _ => self.depth_along(&[from + dz, to + dz]),
        };
        // It cuts its way (the whole tool's profile); how deep it went is its point's depth
        // (a threading insert's flanks, modelled as going on, would say more).
        let cut = if into > CRASH_MM {
            self.sweep(&[from, to], tool, inside);
            into
        } else {
            0.0
        };
        if cut > CRASH_MM {
            self.last_crash_end = Some(to);
        }
        // A rapid from where a crash just left the tool is still in that crash's material.
        if cut > CRASH_MM && after_crash != Some(from) {
            let message = match after_thread {
                Some(_) if pull_out_inside => format!(
                    "a rapid move cuts {cut:.3} mm into the stock: the thread before it ends inside the stock at X{:.3} Z{:.3} (its pull-out, if any, does not bring the tool out)",
                    2.0 * from.x,
                    from.z
                ),
                _ => format!("a rapid move cuts {cut:.3} mm into the stock"),
            };
            let f = Finding::at("crash", rec, from, true, None, message);
            self.findings.push(f);
        }
    }

    /// A drill or tap on the spindle axis: a feed with the spindle turning drills (the bore
    /// grows to the drill's radius, its point's cone at the bottom); a rapid into material is a
    /// crash. A live tool (a mill) is not simulated on the lathe stock.
    fn apply_axial(&mut self, rec: &Record, tool: &Tool, spindle_turning: bool) {
        if tool.kind == super::ToolKind::Mill || tool.diameter_mm <= 0.0 {
            return;
        }
        let (from, to, rapid) = match rec.op {
            Op::Feed { from, to, .. } if spindle_turning => (from, to, false),
            Op::Rapid { from, to } => (from, to, true),
            _ => return,
        };
        if !rapid {
            self.chuck_check(rec, &from, &to);
        }
        let cut = self.drill(&from, &to, tool);
        if rapid && cut > CRASH_MM {
            self.findings.push(Finding::at("crash", rec, from, true, None, format!("a rapid move of the drill cuts {cut:.3} mm into the stock")));
        }
    }

    /// The drill from `from` to `to` (centred at the larger of their X: off the axis it bores a
    /// larger hole): every slice from its deepest point out to the face gets the bore of its
    /// body, the cone of its point at the deepest end. Returns the most material removed,
    /// radially.
    fn drill(&mut self, from: &Vec3, to: &Vec3, tool: &Tool) -> f64 {
        let grid = self.grid;
        let radius = tool.diameter_mm / 2.0 + from.x.abs().max(to.x.abs());
        // The point: radius grows by tan(half the point angle) per mm behind the tip.
        let tan = (tool.point_angle_deg.clamp(1.0, 179.0) / 2.0).to_radians().tan();
        // The drill's body stands behind its tip all the way out of the part: every slice from
        // the tip to the face is where the body is (long drills; a stubby one stops short).
        let tip = from.z.min(to.z);
        let top = from.z.max(to.z).max(self.bar.front_z_mm);
        let (lo, hi) = (grid.cell(tip).max(0), grid.cell(top).min(grid.nz as isize - 1));
        if lo > hi {
            return 0.0;
        }
        let (lo, hi) = (lo as usize, hi as usize);
        let deepest = self
            .inner
            .par_chunks_mut(grid.nz)
            .zip(self.outer.par_chunks(grid.nz))
            .map(|(inner, outer)| {
                let mut d = 0.0f32;
                for i in lo..=hi {
                    let need = (radius.min((grid.z(i) - tip).max(0.0) * tan)) as f32;
                    if need > inner[i] {
                        d = d.max(need.min(outer[i]) - inner[i]);
                        inner[i] = need;
                    }
                }
                d
            })
            .reduce(|| 0.0, f32::max);
        self.updates += ((hi - lo + 1) * grid.ntheta) as u64;
        self.cut_cells(lo, hi);
        deepest as f64
    }

    /// How deep a path of the tool's point goes into the material as it is now: at each point
    /// the nearer of the bore and the outside, the most at any angle and along the path (0 when
    /// it stays in the air).
    fn depth_along(&mut self, path: &[Vec3]) -> f64 {
        let g = self.grid;
        // No material was ever beyond the bar or inside its first bore.
        let (bar_outer, bar_inner) = ((self.bar.diameter_mm / 2.0) as f32, (self.bar.bore_mm / 2.0) as f32);
        let mut deepest = 0.0f32;
        for w in path.windows(2) {
            let len = (w[1].z - w[0].z).abs().max((w[1].x - w[0].x).abs());
            let n = ((len / (g.dz_mm / 2.0)).ceil() as usize).clamp(1, 10_000_000);
            for k in 0..=n {
                let u = k as f64 / n as f64;
                let r = (w[0].x + (w[1].x - w[0].x) * u).abs() as f32;
                if r >= bar_outer || r <= bar_inner {
                    continue;
                }
                let c = g.cell(w[0].z + (w[1].z - w[0].z) * u);
                if c < 0 || c >= g.nz as isize {
                    continue;
                }
                let (inner, outer) = self.extremes(c as usize);
                deepest = deepest.max((r - inner).min(outer - r));
            }
        }
        deepest as f64
    }

    /// How deep a straight path of the tool's point goes into the material when the spindle
    /// turns from `start_deg` through `sweep_deg` (signed `rpm`: its direction) while the tool
    /// runs it: at each point the material of the column under the tool then (0 in the air).
    fn depth_turning(&self, path: &[Vec3; 2], start_deg: f64, sweep_deg: f64, rpm: f64) -> f64 {
        let g = self.grid;
        let [a, b] = *path;
        let len = (b.z - a.z).abs().max((b.x - a.x).abs());
        let n = ((len / (g.dz_mm / 2.0)).ceil() as usize).clamp(1, 10_000_000);
        let mut deepest = 0.0f32;
        for k in 0..=n {
            let u = k as f64 / n as f64;
            let phi = (start_deg + sweep_deg * u).rem_euclid(360.0);
            let theta = if rpm >= 0.0 { phi } else { (360.0 - phi).rem_euclid(360.0) };
            let j = (theta / g.dtheta_deg()).round() as usize % g.ntheta;
            let c = g.cell(a.z + (b.z - a.z) * u);
            if c < 0 || c >= g.nz as isize {
                continue;
            }
            let r = (a.x + (b.x - a.x) * u).abs() as f32;
            let (inner, outer) = self.material(j, c as usize);
            if r > inner && r < outer {
                deepest = deepest.max((r - inner).min(outer - r));
            }
        }
        deepest as f64
    }

    /// The part's profile from the face toward the chuck: for each run of Z cells alike, the
    /// largest outer diameter at any angle (a thread's major diameter) and the smallest bore
    /// (0 where solid to the axis); a slice with no material left has both 0.
    pub fn profile(&mut self) -> Vec<ProfileRow> {
        let g = self.grid;
        let mut rows: Vec<ProfileRow> = Vec::new();
        for i in (0..g.nz).rev() {
            let (inner, outer) = self.extremes(i);
            let (inner, outer) = (inner as f64, outer as f64);
            let (od, id) = if outer > inner + 1e-6 { (2.0 * outer, 2.0 * inner.max(0.0)) } else { (0.0, 0.0) };
            let (od, id) = ((od * 1e3).round() / 1e3, (id * 1e3).round() / 1e3);
            match rows.last_mut() {
                Some(r) if r.outer_diameter_mm == od && r.inner_diameter_mm == id => r.z_to_mm = g.z(i),
                _ => rows.push(ProfileRow { z_from_mm: g.z(i), z_to_mm: g.z(i), outer_diameter_mm: od, inner_diameter_mm: id }),
            }
        }
        rows
    }

    /// Whether a path lies nearer the bore than the outside of the material: the most it would
    /// cut from each side, compared.
    fn nearer_inside(&mut self, path: &[Vec3]) -> bool {
        let g = self.grid;
        let (mut from_inside, mut from_outside) = (f32::MIN, f32::MIN);
        for p in path {
            let c = g.cell(p.z);
            if c < 0 || c >= g.nz as isize {
                continue;
            }
            let r = p.x.abs() as f32;
            let (inner, outer) = self.extremes(c as usize);
            from_inside = from_inside.max(r - inner);
            from_outside = from_outside.max(outer - r);
        }
        from_inside < from_outside
    }

    /// Whether a point lies in the material as it is now (at any angle): between the bore and
    /// the outside, by more than the crash tolerance.
    fn in_material(&self, p: &Vec3) -> bool {
        let c = self.grid.cell(p.z);
        if c < 0 || c >= self.grid.nz as isize {
            return false;
        }
        let r = p.x.abs() as f32;
        let tol = CRASH_MM as f32;
        (0..self.grid.ntheta).any(|j| {
            let (inner, outer) = self.material(j, c as usize);
            r > inner + tol && r < outer - tol
        })
    }

    fn not_simulated(&mut self, rec: &Record, at: Vec3, spindle_deg: Option<f64>, message: &str) {
        if !self.findings.iter().any(|f| f.kind == "not_simulated" && f.line == rec.span.line) {
            self.findings.push(Finding::at("not_simulated", rec, at, true, spindle_deg, message.into()));
        }
    }

    fn chuck_check(&mut self, rec: &Record, from: &Vec3, to: &Vec3) {
        let far = self.bar.front_z_mm - self.bar.length_mm;
        let p = if from.z < to.z { *from } else { *to };
        let line = rec.span.line;
        if p.z < far - 1e-9 && !self.findings.iter().any(|f| f.kind == "chuck" && f.line == line) {
            let msg = format!("the tool reaches Z{:.3}, past the end of the stock at Z{far:.3} (the chuck side)", p.z);
            self.findings.push(Finding::at("chuck", rec, p, true, None, msg));
        }
    }

    /// A cutting move into material with the spindle stopped, or turning the wrong way for the
    /// tool's `hand` (a right-hand tool cuts with M03): a `spindle` finding, once until the
    /// spindle or the tool changes. Checked on the material before the move cuts it. Returns
    /// whether the move goes into material with the spindle stopped.
    fn spindle_check(&mut self, rec: &Record, tool: &Tool, rpm: f64) -> bool {
        let rpm = match rec.op {
            Op::Thread { rpm, .. } | Op::ThreadArc { rpm, .. } => rpm,
            Op::Feed { .. } | Op::Arc { .. } => rpm,
            _ => return false,
        };
        let wrong_way = tool.turns_wrong_way(rpm);
        let state = (tool.number, rpm.signum() as i32);
        if !(rpm == 0.0 || wrong_way) {
            return false;
        }
        let (Some(from), Some(to)) = (rec.op.start_point(), rec.op.end_point()) else { return false };
        let dz = Vec3::new(0.0, 0.0, tool.edge_point_dz_mm());
        let depth = self.depth_along(&[from + dz, to + dz]);
        if depth <= CRASH_MM || self.spindle_flagged == Some(state) {
            return depth > CRASH_MM && rpm == 0.0;
        }
        self.spindle_flagged = Some(state);
        let message = if rpm == 0.0 {
            format!("a cutting move goes {depth:.3} mm into the material with the spindle stopped")
        } else {
            let (hand, code) = if rpm < 0.0 { ("right", "M04") } else { ("left", "M03") };
            format!("a {hand}-hand tool cuts {depth:.3} mm into the material with the spindle turning the wrong way ({code})")
        };
        self.findings.push(Finding::at("spindle", rec, from, true, None, message));
        rpm == 0.0
    }

    /// A boring bar with a `min_bore_mm` in a smaller bore: between its tip and the face, the
    /// least bore where there is material is smaller than the bar needs (a `holder` finding, once
    /// per tool).
    fn bore_check(&mut self, rec: &Record, tool: &Tool) {
        if tool.kind != super::ToolKind::Boring || tool.min_bore_mm <= 0.0 || self.bore_flagged.contains(&tool.number) {
            return;
        }
        let (Op::Rapid { to, .. } | Op::Feed { to, .. } | Op::Arc { to, .. }) = rec.op else { return };
        let g = self.grid;
        let (lo, hi) = (g.cell(to.z).max(0), g.cell(self.bar.front_z_mm).min(g.nz as isize - 1));
        let mut least = f32::MAX;
        for i in lo..=hi {
            let (inner, outer) = self.extremes(i as usize);
            if outer > inner && (to.x.abs() as f32) < outer {
                least = least.min(inner);
            }
        }
        let need = tool.min_bore_mm / 2.0;
        if lo > hi || least == f32::MAX || least as f64 >= need - CRASH_MM {
            return;
        }
        self.bore_flagged.push(tool.number);
        let message = format!("the boring bar needs a bore of {:.3} mm; it enters one of {:.3} mm", tool.min_bore_mm, 2.0 * least);
        self.findings.push(Finding::at("holder", rec, to, true, None, message));
    }

    /// A thread record: every column at the places the tool passes it.
    #[allow(clippy::too_many_arguments)]
    fn cut_thread(&mut self, from: Vec3, to: Vec3, lead: f64, start_deg: f64, rpm: f64, tool: &Tool, internal: bool) {
        let grid = self.grid;
        let length = (to.z - from.z).abs();
        if length <= 0.0 || lead <= 0.0 {
            return;
        }
        let tip_min = from.x.min(to.x);
        let tip_max = from.x.max(to.x);
        let table = self.profile_table(tool, if internal { tip_max } else { tip_min }, internal);
        let dtheta = grid.dtheta_deg();
        let field = if internal { &mut self.inner } else { &mut self.outer };
        let updates: u64 = field
            .par_chunks_mut(grid.nz)
            .enumerate()
            .map(|(j, row)| {
                // The column's angle in the direction of turning.
                let theta = j as f64 * dtheta;
                let phi = if rpm >= 0.0 { theta } else { (360.0 - theta).rem_euclid(360.0) };
                let mut s = (phi - start_deg).rem_euclid(360.0) / 360.0 * lead;
                let mut n = 0u64;
                while s <= length + 1e-12 {
                    let u = s / length;
                    let z = from.z + (to.z - from.z) * u;
                    let x = from.x + (to.x - from.x) * u;
                    n += Self::stamp_fast(row, &grid, &table, internal, z, x);
                    s += lead;
                }
                n
            })
            .sum();
        self.updates += updates;
        // The cells the tool's profile reached, on either side of the thread.
        let (a, b) = (grid.cell(from.z.min(to.z)) - table.chuck.len() as isize, grid.cell(from.z.max(to.z)) + table.face.len() as isize);
        if b >= 0 && a < grid.nz as isize {
            self.cut_cells(a.max(0) as usize, b.min(grid.nz as isize - 1) as usize);
        }
    }

    /// A cut with the spindle turning along a path: the same on every column. Returns the most
    /// material it removed, radially (a cut in the air of a bore, or below what a parting cut
    /// left, removes none).
    fn sweep(&mut self, path: &[Vec3], tool: &Tool, internal: bool) -> f64 {
        let grid = self.grid;
        let mut env = vec![if internal { f32::MIN } else { f32::MAX }; grid.nz];
        let tip = path.iter().map(|p| p.x).fold(if internal { f64::MIN } else { f64::MAX }, |a, b| if internal { a.max(b) } else { a.min(b) });
        let table = self.profile_table(tool, tip, internal);
        for w in path.windows(2) {
            let len = (w[1].z - w[0].z).abs().max((w[1].x - w[0].x).abs());
            let n = ((len / (grid.dz_mm / 2.0)).ceil() as usize).clamp(1, 10_000_000);
            for k in 0..=n {
                let u = k as f64 / n as f64;
                let z = w[0].z + (w[1].z - w[0].z) * u;
                let x = w[0].x + (w[1].x - w[0].x) * u;
                Self::stamp(&mut env, &grid, &table, internal, z, x);
            }
        }
        // Only the cells the path can reach: where the tool came below the bar's surface (above
        // the axis, inside).
        let surface = if internal { 0.0 } else { (self.bar.diameter_mm / 2.0) as f32 };
        let reaches = |e: &f32| if internal { *e > surface } else { *e < surface };
        let (Some(lo), Some(hi)) = (env.iter().position(reaches), env.iter().rposition(reaches)) else {
            return 0.0;
        };
        self.cut_cells(lo, hi);
        let (cut, other) = if internal { (&mut self.inner, &self.outer) } else { (&mut self.outer, &self.inner) };
        let deepest = cut
            .par_chunks_mut(grid.nz)
            .zip(other.par_chunks(grid.nz))
            .map(|(row, other)| {
                let mut d = 0.0f32;
                for ((cell, e), o) in row[lo..=hi].iter_mut().zip(&env[lo..=hi]).zip(&other[lo..=hi]) {
                    // The material removed lies between the new surface and the old one, within
                    // what the other surface leaves.
                    if internal && *e > *cell {
                        d = d.max(e.min(*o) - *cell);
                        *cell = *e;
                    } else if !internal && *e < *cell {
                        d = d.max(*cell - e.max(*o));
                        *cell = *e;
                    }
                }
                d
            })
            .reduce(|| 0.0, f32::max);
        deepest as f64
    }
}
