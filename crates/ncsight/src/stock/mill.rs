//! Mill stock for the drilling cycles (issue 7): a top-view height field, the top of the material
//! at every (x, y) of a grid over the block. A feed along Z with the spindle turning removes
//! what the drill sweeps: a cylinder of its diameter ending in the cone of its point angle.
//! Only moves along Z are cut (the drilling cycles' feeds); a rapid that goes into material is a
//! crash; the holes are measured from the cut surface.

use super::lathe::Finding;
use super::Tool;
use crate::motion::{Op, Record, Vec3};

pub use crate::setup::Block;

/// A hole found in the cut surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hole {
    pub x: f64,
    pub y: f64,
    /// From the top of the block down to the deepest point.
    pub depth_mm: f64,
    /// Across the cut at the top.
    pub diameter_mm: f64,
}

pub struct MillStock {
    pub block: Block,
    pub cell_mm: f64,
    pub nx: usize,
    pub ny: usize,
    /// Top of the material per cell, row by row along x.
    pub top: Vec<f32>,
    pub findings: Vec<Finding>,
    /// Where the drill tips went (the grid blurs a cone's point by a cell).
    tips: Vec<Vec3>,
}

impl MillStock {
    pub fn new(block: Block, cell_mm: f64) -> MillStock {
        let nx = (((block.max_mm[0] - block.min_mm[0]) / cell_mm).ceil() as usize).max(1);
        let ny = (((block.max_mm[1] - block.min_mm[1]) / cell_mm).ceil() as usize).max(1);
        MillStock { block, cell_mm, nx, ny, top: vec![block.max_mm[2] as f32; nx * ny], findings: Vec::new(), tips: Vec::new() }
    }

    fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        (self.block.min_mm[0] + (i as f64 + 0.5) * self.cell_mm, self.block.min_mm[1] + (j as f64 + 0.5) * self.cell_mm)
    }

    /// Cut a drill with its tip at `p`; returns how deep it went into material.
    fn plunge(&mut self, p: &Vec3, tool: &Tool) -> f64 {
        let r = (tool.diameter_mm / 2.0).max(self.cell_mm / 2.0);
        let cot = 1.0 / (tool.point_angle_deg.clamp(1.0, 179.0) / 2.0).to_radians().tan();
        let (i0, i1) = (((p.x - r - self.block.min_mm[0]) / self.cell_mm).floor().max(0.0) as usize, ((p.x + r - self.block.min_mm[0]) / self.cell_mm).ceil().max(0.0) as usize);
        let (j0, j1) = (((p.y - r - self.block.min_mm[1]) / self.cell_mm).floor().max(0.0) as usize, ((p.y + r - self.block.min_mm[1]) / self.cell_mm).ceil().max(0.0) as usize);
        let mut deepest = 0.0f64;
        for j in j0..j1.min(self.ny) {
            for i in i0..i1.min(self.nx) {
                let (cx, cy) = self.centre(i, j);
                let d = ((cx - p.x).powi(2) + (cy - p.y).powi(2)).sqrt();
                if d > r {
                    continue;
                }
                let z = (p.z + d * cot) as f32;
                let cell = &mut self.top[j * self.nx + i];
                if z < *cell {
                    deepest = deepest.max((*cell - z) as f64);
                    *cell = z;
                }
            }
        }
        deepest
    }

    /// Apply one record (G17 drilling along Z).
    pub fn apply(&mut self, rec: &Record, tool: &Tool, turning: bool) {
        match rec.op {
            Op::Feed { from, to, .. } if (from.x - to.x).abs() < 1e-9 && (from.y - to.y).abs() < 1e-9 && to.z < from.z => {
                if !turning {
                    self.findings.push(Finding::at("crash", rec, from, false, None, "a feed into the stock with the spindle stopped".into()));
                }
                self.plunge(&to, tool);
                self.tips.push(to);
            }
            Op::Rapid { from, to } => {
                // Sample the rapid: anywhere below the material's top is a crash.
                let n = ((from.dist(&to) / self.cell_mm).ceil() as usize).clamp(1, 200_000);
                let mut worst = 0.0f64;
                let mut worst_at = from;
                for k in 0..=n {
                    let u = k as f64 / n as f64;
                    let p = Vec3::new(from.x + (to.x - from.x) * u, from.y + (to.y - from.y) * u, from.z + (to.z - from.z) * u);
                    let i = ((p.x - self.block.min_mm[0]) / self.cell_mm).floor();
                    let j = ((p.y - self.block.min_mm[1]) / self.cell_mm).floor();
                    if i >= 0.0 && j >= 0.0 && (i as usize) < self.nx && (j as usize) < self.ny {
                        let top = self.top[j as usize * self.nx + i as usize] as f64;
                        if top - p.z > worst {
                            worst = top - p.z;
                            worst_at = p;
                        }
                    }
                }
                // The grid sees a drilled cone a cell wide: up to a cell's size is not a crash.
                if worst > 0.01 + self.cell_mm {
                    self.findings.push(Finding::at("crash", rec, worst_at, false, None, format!("a rapid move goes {worst:.3} mm into the stock")));
                }
            }
            _ => {}
        }
    }

    /// The holes: connected cells cut below the top, each with its deepest point and width.
    pub fn holes(&self) -> Vec<Hole> {
        let top = self.block.max_mm[2] as f32;
        let mut seen = vec![false; self.top.len()];
        let mut out = Vec::new();
        for start in 0..self.top.len() {
            if seen[start] || self.top[start] >= top - 1e-4 {
                continue;
            }
            let mut stack = vec![start];
            seen[start] = true;
            let (mut n, mut sx, mut sy, mut deep) = (0usize, 0.0, 0.0, 0.0f64);
            let (mut xmin, mut xmax) = (f64::MAX, f64::MIN);
            while let Some(k) = stack.pop() {
                let (i, j) = (k % self.nx, k / self.nx);
                let (cx, cy) = self.centre(i, j);
                n += 1;
                sx += cx;
                sy += cy;
                xmin = xmin.min(cx);
                xmax = xmax.max(cx);
                deep = deep.max((top - self.top[k]) as f64);
                let nb = [(i > 0).then(|| k - 1), (i + 1 < self.nx).then(|| k + 1), (j > 0).then(|| k - self.nx), (j + 1 < self.ny).then(|| k + self.nx)];
                for m in nb.into_iter().flatten() {
                    if !seen[m] && self.top[m] < top - 1e-4 {
                        seen[m] = true;
                        stack.push(m);
                    }
                }
            }
            let (mut x, mut y) = (sx / n as f64, sy / n as f64);
            let width = xmax - xmin + self.cell_mm;
            // The deepest drill tip inside the hole gives its exact depth and centre.
            let tip = self
                .tips
                .iter()
                .filter(|t| (t.x - x).abs() <= width / 2.0 && (t.y - y).abs() <= width / 2.0)
                .min_by(|a, b| a.z.total_cmp(&b.z));
            if let Some(t) = tip {
                deep = deep.max(top as f64 - t.z);
                (x, y) = (t.x, t.y);
            }
            out.push(Hole { x, y, depth_mm: deep, diameter_mm: width });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::Span;

    #[test]
    fn a_drill_makes_a_hole_of_its_size() {
        let mut s = MillStock::new(Block { min_mm: [0.0, 0.0, -20.0], max_mm: [40.0, 40.0, 0.0] }, 0.1);
        let drill = Tool { kind: super::super::ToolKind::Drill, diameter_mm: 6.0, point_angle_deg: 118.0, ..Tool::default_thread() };
        let rec = Record::new(Span::default(), Op::Feed { from: Vec3::new(10.0, 10.0, 2.0), to: Vec3::new(10.0, 10.0, -8.0), feed_mm_min: 100.0 });
        s.apply(&rec, &drill, true);
        let h = s.holes();
        assert_eq!(h.len(), 1);
        assert!((h[0].x - 10.0).abs() < 0.06 && (h[0].y - 10.0).abs() < 0.06);
        assert!((h[0].depth_mm - 8.0).abs() < 0.02);
        assert!((h[0].diameter_mm - 6.0).abs() < 0.15, "{:?}", h[0]);
        // A rapid down into the material is a crash.
        let rapid = Record::new(Span::new(9, 1, 1), Op::Rapid { from: Vec3::new(30.0, 30.0, 5.0), to: Vec3::new(30.0, 30.0, -2.0) });
        s.apply(&rapid, &drill, true);
        assert_eq!(s.findings[0].kind, "crash");
    }
}
