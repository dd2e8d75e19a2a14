//! The lathe stock as a cylindrical height field: for every angle theta (the C axis's positive
//! direction, 0 at the one-revolution signal) and every z, the radius of the surface.
//!
//! A thread record cuts each theta column where the tool passes it: the tool is at column theta
//! when the spindle angle is theta, i.e. once per revolution, one lead apart, at the position
//! the record's start angle and lead give (this is why `spindle_deg` must be right). Other
//! cutting moves with the spindle turning sweep every column. External stock keeps the smallest
//! radius the tool leaves; a bore (internal thread) keeps the largest.

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
}

/// The stock being cut.
pub struct LatheStock {
    pub grid: Grid,
    pub bar: Bar,
    /// Works on the bore (internal thread) instead of the outside.
    pub internal: bool,
    /// Surface radius, one row of `nz` cells per theta.
    pub r: Vec<f32>,
    pub findings: Vec<Finding>,
    /// Cells the tool visited (for the benchmark's figure).
    pub updates: u64,
}

/// How much a rapid may touch the stock before it counts as a crash, mm.
const CRASH_MM: f64 = 0.01;

impl LatheStock {
    pub fn new(bar: Bar, internal: bool, dz_mm: f64, ntheta: usize) -> LatheStock {
        let nz = ((bar.length_mm / dz_mm).ceil() as usize).max(1) + 1;
        let grid = Grid { z0_mm: bar.front_z_mm - (nz - 1) as f64 * dz_mm, dz_mm, nz, ntheta: ntheta.max(4) };
        let start = if internal { bar.bore_mm / 2.0 } else { bar.diameter_mm / 2.0 };
        LatheStock { grid, bar, internal, r: vec![start as f32; nz * grid.ntheta], findings: Vec::new(), updates: 0 }
    }

    pub fn row(&self, j: usize) -> &[f32] {
        &self.r[j * self.grid.nz..(j + 1) * self.grid.nz]
    }

    /// The tool's cut surface radius at axial offsets 0, dz, 2dz, ... out to where it leaves
    /// the stock (a table, so the hot loop only looks it up).
    fn profile_table(&self, tool: &Tool, tip_r: f64) -> Vec<f32> {
        // Beyond the radial distance to the untouched surface the tool cuts nothing.
        let limit = if self.internal { tip_r - self.bar.bore_mm / 2.0 } else { self.bar.diameter_mm / 2.0 - tip_r };
        let mut t = Vec::new();
        let mut k = 0usize;
        loop {
            let p = tool.profile(k as f64 * self.grid.dz_mm);
            t.push(p as f32);
            if p > limit.max(0.0) || k > self.grid.nz {
                break;
            }
            k += 1;
        }
        t
    }

    /// Stamp the tool with its tip at (z, radius) on one row; returns how deep it cut the most.
    #[inline]
    fn stamp(row: &mut [f32], grid: &Grid, table: &[f32], internal: bool, z: f64, tip_r: f64) -> (f32, u64) {
        let c = grid.cell(z);
        let reach = table.len() as isize - 1;
        let lo = (c - reach).max(0);
        let hi = (c + reach).min(grid.nz as isize - 1);
        let mut deepest = 0.0f32;
        let mut n = 0u64;
        let tip = tip_r as f32;
        for i in lo..=hi {
            let u = (i - c).unsigned_abs();
            let cell = &mut row[i as usize];
            if internal {
                let cut = tip - table[u];
                if cut > *cell {
                    deepest = deepest.max(cut - *cell);
                    *cell = cut;
                    n += 1;
                }
            } else {
                let cut = tip + table[u];
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
    fn stamp_fast(row: &mut [f32], grid: &Grid, table: &[f32], internal: bool, z: f64, tip_r: f64) -> u64 {
        let c = grid.cell(z);
        let reach = table.len() as isize - 1;
        let n = grid.nz as isize;
        if c + reach < 0 || c - reach >= n {
            return 0;
        }
        let tip = tip_r as f32;
        // Right of the tip (including it): table[0..], left: table[1..] going away.
        let r_lo = c.max(0);
        let r_hi = (c + reach).min(n - 1);
        let l_lo = (c - reach).max(0);
        let l_hi = (c - 1).min(n - 1);
        let mut visited = 0u64;
        if r_lo <= r_hi {
            let cells = &mut row[r_lo as usize..=r_hi as usize];
            let t = &table[(r_lo - c) as usize..];
            if internal {
                cells.iter_mut().zip(t).for_each(|(v, e)| *v = v.max(tip - e));
            } else {
                cells.iter_mut().zip(t).for_each(|(v, e)| *v = v.min(tip + e));
            }
            visited += cells.len() as u64;
        }
        if l_lo <= l_hi {
            let cells = &mut row[l_lo as usize..=l_hi as usize];
            let t = &table[(c - l_hi) as usize..];
            if internal {
                cells.iter_mut().rev().zip(t).for_each(|(v, e)| *v = v.max(tip - e));
            } else {
                cells.iter_mut().rev().zip(t).for_each(|(v, e)| *v = v.min(tip + e));
            }
            visited += cells.len() as u64;
        }
        visited
    }

    /// Apply one record with the tool in the turret.
    pub fn apply(&mut self, rec: &Record, tool: &Tool, spindle_turning: bool) {
        let line = rec.span.line;
        match rec.op {
            Op::Thread { from, to, lead_mm, long_axis, spindle_deg, rpm } => {
                if long_axis != LongAxis::Z {
                    self.findings.push(Finding {
                        kind: "not_simulated",
                        line,
                        message: "a thread with X as its long axis (a face or steep taper thread) is not cut in the stock simulation".into(),
                    });
                    return;
                }
                self.chuck_check(&from, &to, line);
                self.cut_thread(from, to, lead_mm, spindle_deg, rpm, tool);
            }
            Op::Feed { from, to, .. } if spindle_turning => {
                self.chuck_check(&from, &to, line);
                self.sweep(&[from, to], tool);
            }
            Op::Arc { from, to, .. } if spindle_turning => {
                self.chuck_check(&from, &to, line);
                let g = crate::time::arc_geom_of(&rec.op).expect("a stored arc");
                let (plane, dir) = match rec.op {
                    Op::Arc { plane, dir, .. } => (plane, dir),
                    _ => unreachable!(),
                };
                let len = crate::geom::arc_length(&from, &to, plane, &g);
                let n = ((len / (self.grid.dz_mm / 2.0)).ceil() as usize).clamp(2, 100_000);
                let pts: Vec<Vec3> = (0..=n).map(|k| crate::geom::arc_point(&from, &to, plane, dir, &g, k as f64 / n as f64)).collect();
                self.sweep(&pts, tool);
            }
            Op::Rapid { from, to } => {
                let cut = self.sweep(&[from, to], tool);
                if cut > CRASH_MM {
                    self.findings.push(Finding {
                        kind: "crash",
                        line,
                        message: format!("a rapid move cuts {cut:.3} mm into the stock"),
                    });
                }
            }
            _ => {}
        }
    }

    fn chuck_check(&mut self, from: &Vec3, to: &Vec3, line: u32) {
        let far = self.bar.front_z_mm - self.bar.length_mm;
        let z = from.z.min(to.z);
        if z < far - 1e-9 && !self.findings.iter().any(|f| f.kind == "chuck" && f.line == line) {
            self.findings.push(Finding {
                kind: "chuck",
                line,
                message: format!("the tool reaches Z{z:.3}, past the end of the stock at Z{far:.3} (the chuck side)"),
            });
        }
    }

    /// A thread record: every column at the places the tool passes it.
    fn cut_thread(&mut self, from: Vec3, to: Vec3, lead: f64, start_deg: f64, rpm: f64, tool: &Tool) {
        let grid = self.grid;
        let internal = self.internal;
        let length = (to.z - from.z).abs();
        if length <= 0.0 || lead <= 0.0 {
            return;
        }
        let tip_min = from.x.min(to.x);
        let tip_max = from.x.max(to.x);
        let table = self.profile_table(tool, if internal { tip_max } else { tip_min });
        let dtheta = grid.dtheta_deg();
        let updates: u64 = self
            .r
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
    }

    /// A cut with the spindle turning along a path: the same on every column. Returns the
    /// deepest cut.
    fn sweep(&mut self, path: &[Vec3], tool: &Tool) -> f64 {
        let grid = self.grid;
        let internal = self.internal;
        let mut env = vec![if internal { f32::MIN } else { f32::MAX }; grid.nz];
        let tip = path.iter().map(|p| p.x).fold(if internal { f64::MIN } else { f64::MAX }, |a, b| if internal { a.max(b) } else { a.min(b) });
        let table = self.profile_table(tool, tip);
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
        // Only the cells the path can reach: where the tool came below the bar's surface.
        let surface = if internal { (self.bar.bore_mm / 2.0) as f32 } else { (self.bar.diameter_mm / 2.0) as f32 };
        let reaches = |e: &f32| if internal { *e > surface } else { *e < surface };
        let (Some(lo), Some(hi)) = (env.iter().position(reaches), env.iter().rposition(reaches)) else {
            return 0.0;
        };
        let deepest = self
            .r
            .par_chunks_mut(grid.nz)
            .map(|row| {
                let mut d = 0.0f32;
                for (cell, e) in row[lo..=hi].iter_mut().zip(&env[lo..=hi]) {
                    if internal && *e > *cell {
                        d = d.max(*e - *cell);
                        *cell = *e;
                    } else if !internal && *e < *cell {
                        d = d.max(*cell - *e);
                        *cell = *e;
                    }
                }
                d
            })
            .reduce(|| 0.0, f32::max);
        deepest as f64
    }
}
