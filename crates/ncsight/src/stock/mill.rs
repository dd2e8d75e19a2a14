//! Mill stock: a top-view height field (dexels standing on a grid over the block), the top of
//! the material at every (x, y). Every move of the tool sweeps its end along the path, sampled
//! at half a cell: a flat, ball or bull-nose mill's end, a drill's cone; lines, arcs and
//! helices in any plane (the tool's axis is Z). A cell is cut where the tool's end passes over
//! its centre, so a wall stands within one cell of where it should (the error bound). A rapid
//! whose tool end goes into material is a crash; a cut with the spindle stopped is a `spindle`
//! finding. The holes, the floors and the volume removed are measured from the cut surface.

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

/// The least area of a floor, mm² (a 3 mm slot 3.3 mm long).
pub const FLOOR_MM2: f64 = 10.0;

/// How deep a move may touch the material without it counting (a rounding of the grid), mm.
const CUT_MM: f64 = 0.01;

/// A flat end at height `z` over a run of cells: how far the highest cell stands above it, and
/// with `cut` each cell lowered to it. One pass in lanes of eight, which the compiler turns into
/// vector instructions (the tops, not the order of a reduction, decide the result).
fn lower_to(row: &mut [f32], z: f32, cut: bool) -> f32 {
    const LANES: usize = 8;
    let mut acc = [0.0f32; LANES];
    let mut chunks = row.chunks_exact_mut(LANES);
    for c in &mut chunks {
        for k in 0..LANES {
            let d = c[k] - z;
            acc[k] = if d > acc[k] { d } else { acc[k] };
            if cut {
                c[k] = if z < c[k] { z } else { c[k] };
            }
        }
    }
    let mut deepest = acc.iter().fold(0.0f32, |a, b| a.max(*b));
    for t in chunks.into_remainder() {
        deepest = deepest.max(*t - z);
        if cut && z < *t {
            *t = z;
        }
    }
    deepest
}

/// The highest of some tops (a run of a row), in lanes of eight the compiler vectorises.
fn highest(v: &[f32]) -> f32 {
    const LANES: usize = 8;
    let mut acc = [f32::MIN; LANES];
    let mut chunks = v.chunks_exact(LANES);
    for c in &mut chunks {
        for k in 0..LANES {
            acc[k] = if c[k] > acc[k] { c[k] } else { acc[k] };
        }
    }
    chunks.remainder().iter().chain(&acc).fold(f32::MIN, |m, x| if *x > m { *x } else { m })
}

/// The points within `r` of the segment from `a` to `b` (in X and Y): the union of the two end
/// discs and the band along the segment, convex, so a row crosses it in one interval
/// ([`Capsule::row`]). What does not change from row to row is worked out once.
pub struct Capsule {
    a: Vec3,
    b: Vec3,
    r: f64,
    dx: f64,
    dy: f64,
    len2: f64,
    /// r x the segment's length, 1 / dy and 1 / dx (0 where that is 0).
    r_len: f64,
    inv_dy: f64,
    inv_dx: f64,
}

impl Capsule {
    pub fn new(a: &Vec3, b: &Vec3, r: f64) -> Capsule {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let len2 = dx * dx + dy * dy;
        let inv = |v: f64| if v.abs() < 1e-12 { 0.0 } else { 1.0 / v };
        Capsule { a: *a, b: *b, r, dx, dy, len2, r_len: r * len2.sqrt(), inv_dy: inv(dy), inv_dx: inv(dx) }
    }

    /// Where the row `y = cy` crosses the capsule: the interval of x, if any (the hull of the
    /// three pieces' crossings).
    pub fn row(&self, cy: f64) -> Option<(f64, f64)> {
        let (a, r) = (&self.a, self.r);
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for p in [&self.a, &self.b] {
            let h = r * r - (cy - p.y) * (cy - p.y);
            if h >= 0.0 {
                let w = h.sqrt();
                lo = lo.min(p.x - w);
                hi = hi.max(p.x + w);
            }
        }
        if self.len2 > 0.0 {
            let ey = cy - a.y;
            // Within r of the segment's line: |dx ey - dy (x - ax)| <= r len.
            let (mut band_lo, mut band_hi) = if self.inv_dy == 0.0 {
                if (self.dx * ey).abs() <= self.r_len {
                    (f64::NEG_INFINITY, f64::INFINITY)
                } else {
                    (1.0, -1.0)
                }
            } else {
                let (p, q) = (a.x + (self.dx * ey - self.r_len) * self.inv_dy, a.x + (self.dx * ey + self.r_len) * self.inv_dy);
                (p.min(q), p.max(q))
            };
            // Projecting within the segment: 0 <= (x - ax) dx + ey dy <= len2.
            if self.inv_dx == 0.0 {
                if !(0.0..=self.len2).contains(&(ey * self.dy)) {
                    band_hi = band_lo - 1.0;
                }
            } else {
                let (p, q) = (a.x - ey * self.dy * self.inv_dx, a.x + (self.len2 - ey * self.dy) * self.inv_dx);
                band_lo = band_lo.max(p.min(q));
                band_hi = band_hi.min(p.max(q));
            }
            if band_lo <= band_hi {
                lo = lo.min(band_lo);
                hi = hi.max(band_hi);
            }
        }
        (lo <= hi).then_some((lo, hi))
    }
}

/// The largest whole number at most `v`, as an isize (the library's floor is a call on x86-64
/// without SSE 4.1; this is two instructions).
#[inline]
fn floor_i(v: f64) -> isize {
    let t = v as isize;
    if (t as f64) > v {
        t - 1
    } else {
        t
    }
}

/// The first cell whose centre is at or past `lo` (cells of `1 / inv_cell` from `origin`).
#[inline]
fn first_cell(lo: f64, origin: f64, inv_cell: f64) -> isize {
    -floor_i(-((lo - origin) * inv_cell - 0.5))
}

/// The last cell whose centre is at or before `hi`.
#[inline]
fn last_cell(hi: f64, origin: f64, inv_cell: f64) -> isize {
    floor_i((hi - origin) * inv_cell - 0.5)
}

/// A move's rows may be cut by two threads when it has this many rows a thread...
const MIN_ROWS_A_THREAD: usize = 16;
/// ...and about this many cells in all (below, the threads' hand-over costs more than it saves).
const MIN_CELLS_TO_SPLIT: f64 = 100_000.0;

/// One straight move at one height over the grid (see [`MillStock::level_segment`]), cut over a
/// band of whole rows.
struct Move<'t> {
    capsule: Capsule,
    a: Vec3,
    b: Vec3,
    tool: &'t Tool,
    cut: bool,
    flat: bool,
    cell: f64,
    inv_cell: f64,
    x0: f64,
    y0: f64,
    nx: usize,
    ntx: usize,
}

impl Move<'_> {
    /// The rows of `top` (and their runs' highest tops, `tiles`), the first of them row `j0` of
    /// the grid: the most the tool reaches into them. The tool's end is nowhere lower than its
    /// tip: a run whose highest top is no higher is left alone.
    fn rows(&self, top: &mut [f32], tiles: &mut [f32], j0: usize) -> f32 {
        let (nx, ntx) = (self.nx, self.ntx);
        let low = self.a.z as f32;
        let mut deepest = 0.0f32;
        for (k, (row, row_tiles)) in top.chunks_exact_mut(nx).zip(tiles.chunks_exact_mut(ntx)).enumerate() {
            let cy = self.y0 + ((j0 + k) as f64 + 0.5) * self.cell;
            let Some((xl, xh)) = self.capsule.row(cy) else { continue };
            let (i0, i1) = (first_cell(xl, self.x0, self.inv_cell).max(0) as usize, last_cell(xh, self.x0, self.inv_cell));
            if i1 < 0 || i0 >= nx {
                continue;
            }
            let i1 = (i1 as usize).min(nx - 1);
            let mut i = i0;
            while i <= i1 {
                let t = i / TILE;
                let end = ((t + 1) * TILE - 1).min(i1);
                if row_tiles[t] > low {
                    deepest = deepest.max(self.run(&mut row[i..=end], i, cy));
                    let (k0, k1) = (t * TILE, ((t + 1) * TILE).min(nx));
                    if self.cut && self.flat && i == k0 && end + 1 == k1 {
                        // A flat end over the whole run: every top is now at most its height.
                        row_tiles[t] = row_tiles[t].min(low);
                    } else if self.cut {
                        row_tiles[t] = highest(&row[k0..k1]);
                    }
                }
                i = end + 1;
            }
        }
        deepest
    }

    /// A run of cells of the row at `cy`, the first cell `i0`, all within the tool's reach: how
    /// far the highest stands above the tool's end, and with `cut` each lowered to it. A flat
    /// end is one height across them.
    fn run(&self, cells: &mut [f32], i0: usize, cy: f64) -> f32 {
        let (a, b) = (&self.a, &self.b);
        if self.flat {
            return lower_to(cells, a.z as f32, self.cut);
        }
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let len2 = dx * dx + dy * dy;
        let mut deepest = 0.0f32;
        for (k, top) in cells.iter_mut().enumerate() {
            let cx = self.x0 + ((i0 + k) as f64 + 0.5) * self.cell;
            let u = if len2 > 0.0 { (((cx - a.x) * dx + (cy - a.y) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
            let d = ((cx - a.x - u * dx).powi(2) + (cy - a.y - u * dy).powi(2)).sqrt();
            let Some(h) = self.tool.end_height(d.min(self.tool.diameter_mm / 2.0)) else { continue };
            let zc = (a.z + h) as f32;
            if zc < *top {
                deepest = deepest.max(*top - zc);
                if self.cut {
                    *top = zc;
                }
            }
        }
        deepest
    }
}

/// Cells of a row whose highest top is kept (see [`MillStock::tile_max`]).
const TILE: usize = 32;

pub struct MillStock {
    pub block: Block,
    pub cell_mm: f64,
    pub nx: usize,
    pub ny: usize,
    /// Top of the material per cell, row by row along x.
    pub top: Vec<f32>,
    /// The highest top in each run of [`TILE`] cells of a row (`ntx` runs a row): a move over a
    /// run already lower than its tool's end skips it.
    tile_max: Vec<f32>,
    ntx: usize,
    pub findings: Vec<Finding>,
    /// Where the drill tips went (the grid blurs a cone's point by a cell).
    tips: Vec<Vec3>,
}

impl MillStock {
    pub fn new(block: Block, cell_mm: f64) -> MillStock {
        let nx = (((block.max_mm[0] - block.min_mm[0]) / cell_mm).ceil() as usize).max(1);
        let ny = (((block.max_mm[1] - block.min_mm[1]) / cell_mm).ceil() as usize).max(1);
        let ntx = nx.div_ceil(TILE);
        let top = block.max_mm[2] as f32;
        MillStock { block, cell_mm, nx, ny, top: vec![top; nx * ny], tile_max: vec![top; ntx * ny], ntx, findings: Vec::new(), tips: Vec::new() }
    }

    fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        (self.block.min_mm[0] + (i as f64 + 0.5) * self.cell_mm, self.block.min_mm[1] + (j as f64 + 0.5) * self.cell_mm)
    }

    /// A straight move at one height (a point when `a` is `b`), exactly: each cell whose centre
    /// lies within the tool's radius of the segment takes the tool's end at its distance from
    /// the segment (a flat, ball or bull end and a drill's cone depend only on that distance).
    /// The most it reaches into the material; with `cut`, the material is removed. One pass over
    /// the move's cells, row by row over the span the segment's capsule covers in that row
    /// ([`Capsule::row`]); a flat end is the same height across its span, a branch-free pass
    /// the compiler vectorises.
    fn level_segment(&mut self, a: &Vec3, b: &Vec3, tool: &Tool, cut: bool) -> f64 {
        let r = (tool.diameter_mm / 2.0).max(self.cell_mm / 2.0);
        let (cell, y0, nx, ntx) = (self.cell_mm, self.block.min_mm[1], self.nx, self.ntx);
        let inv_cell = 1.0 / cell;
        let j0 = first_cell(a.y.min(b.y) - r, y0, inv_cell).max(0) as usize;
        let j1 = last_cell(a.y.max(b.y) + r, y0, inv_cell);
        if j1 < 0 || j0 >= self.ny {
            return 0.0;
        }
        let j1 = (j1 as usize).min(self.ny - 1);
        let move_ = Move {
            capsule: Capsule::new(a, b, r),
            a: *a,
            b: *b,
            tool,
            cut,
            flat: tool.kind == super::ToolKind::Mill && matches!(tool.shape, crate::setup::MillShape::Flat | crate::setup::MillShape::Face),
            cell,
            inv_cell,
            x0: self.block.min_mm[0],
            y0,
            nx,
            ntx,
        };
        let top = &mut self.top[j0 * nx..(j1 + 1) * nx];
        let tiles = &mut self.tile_max[j0 * ntx..(j1 + 1) * ntx];
        let rows = j1 + 1 - j0;
        // A move over many cells is cut by both cores, half its rows each (the rows are apart
        // in memory, so the halves never meet).
        let deepest = if rows >= 2 * MIN_ROWS_A_THREAD && (rows as f64) * 2.0 * r * inv_cell >= MIN_CELLS_TO_SPLIT {
            let half = rows / 2;
            let (top_a, top_b) = top.split_at_mut(half * nx);
            let (tiles_a, tiles_b) = tiles.split_at_mut(half * ntx);
            let (da, db) = rayon::join(|| move_.rows(top_a, tiles_a, j0), || move_.rows(top_b, tiles_b, j0 + half));
            da.max(db)
        } else {
            move_.rows(top, tiles, j0)
        };
        deepest.max(0.0) as f64
    }

    /// How deep a move reaches into the material (and with `cut`, removes it): a straight move
    /// at one height exactly, others stamped every half cell along their path.
    fn sweep(&mut self, op: &Op, tool: &Tool, cut: bool) -> (f64, Vec3) {
        if let Op::Feed { from, to, .. } | Op::Rapid { from, to } = *op {
            if (from.z - to.z).abs() < 1e-9 {
                return (self.level_segment(&from, &to, tool, cut), from);
            }
        }
        let (mut worst, mut at) = (0.0f64, op.start_point().unwrap_or_default());
        for p in self.path(op) {
            let d = self.level_segment(&p, &p, tool, cut);
            if d > worst {
                (worst, at) = (d, p);
            }
        }
        (worst, at)
    }

    /// The points of a move's path, at most half a cell apart (an arc or a helix along its
    /// curve).
    fn path(&self, op: &Op) -> Vec<Vec3> {
        let half = self.cell_mm / 2.0;
        match *op {
            Op::Arc { from, to, plane, dir, .. } => match crate::geom::arc_geom_of(op) {
                Some(g) => {
                    let n = ((crate::geom::arc_length(&from, &to, plane, &g) / half).ceil() as usize).clamp(1, 10_000_000);
                    (0..=n).map(|k| crate::geom::arc_point(&from, &to, plane, dir, &g, k as f64 / n as f64)).collect()
                }
                None => vec![from, to],
            },
            _ => match (op.start_point(), op.end_point()) {
                (Some(a), Some(b)) => {
                    let n = ((a.dist(&b) / half).ceil() as usize).clamp(1, 10_000_000);
                    (0..=n).map(|k| super::super::cycles::thread::lerp(&a, &b, k as f64 / n as f64)).collect()
                }
                _ => Vec::new(),
            },
        }
    }

    /// Apply one record with the spindle at `rpm` (signed: negative is M04; 0 stopped); what it
    /// finds names the tool.
    pub fn apply(&mut self, rec: &Record, tool: &Tool, rpm: f64) {
        let before = self.findings.len();
        self.apply_tool(rec, tool, rpm);
        for f in &mut self.findings[before..] {
            f.tool = Some(tool.number);
        }
    }

    fn apply_tool(&mut self, rec: &Record, tool: &Tool, rpm: f64) {
        if matches!(rec.op, Op::Feed { .. } | Op::Arc { .. } | Op::Rapid { .. }) {
            self.tool_checks(rec, tool);
        }
        match rec.op {
            Op::Feed { .. } | Op::Arc { .. } => {
                let (deepest, _) = self.sweep(&rec.op, tool, true);
                if deepest > CUT_MM && (rpm == 0.0 || tool.turns_wrong_way(rpm)) {
                    let at = rec.op.start_point().unwrap_or_default();
                    let message = if rpm == 0.0 {
                        format!("a cut {deepest:.3} mm deep with the spindle stopped")
                    } else {
                        format!("a cut {deepest:.3} mm deep with the spindle turning the wrong way for the tool ({})", if rpm < 0.0 { "M04" } else { "M03" })
                    };
                    self.findings.push(Finding::at("spindle", rec, at, false, None, message));
                }
                if let Op::Feed { from, to, .. } = rec.op {
                    if (from.x - to.x).abs() < 1e-9 && (from.y - to.y).abs() < 1e-9 && to.z < from.z {
                        self.tips.push(to);
                    }
                }
            }
            Op::Rapid { .. } => {
                // The tool's end along the rapid: into the material is a crash (a drilled cone's
                // point is seen a cell wide: up to a cell is not one); then it cuts its way.
                let (worst, worst_at) = self.sweep(&rec.op, tool, false);
                if worst > CUT_MM + self.cell_mm {
                    self.findings.push(Finding::at("crash", rec, worst_at, false, None, format!("a rapid move goes {worst:.3} mm into the stock")));
                    self.sweep(&rec.op, tool, true);
                }
            }
            _ => {}
        }
    }

    /// What the tool's shape forbids, checked on the material before the move cuts it:
    /// - `plunge`: a mill that does not cut at its centre fed straight down into material;
    /// - `flute`: material engaged higher up the tool than its flutes reach;
    /// - `holder`: the holder (from the stick-out up) over material it comes down to.
    fn tool_checks(&mut self, rec: &Record, tool: &Tool) {
        let (Some(from), Some(to)) = (rec.op.start_point(), rec.op.end_point()) else { return };
        let is_feed = !matches!(rec.op, Op::Rapid { .. });
        let straight_down = (from.x - to.x).abs() < 1e-9 && (from.y - to.y).abs() < 1e-9 && to.z < from.z;
        if is_feed && straight_down && tool.kind == super::ToolKind::Mill && !tool.centre_cutting {
            if let Some(top) = self.top_at(to.x, to.y).filter(|top| *top > to.z + CUT_MM) {
                let msg = format!("a mill that does not cut at its centre plunges {:.3} mm into the material", top - to.z);
                self.findings.push(Finding::at("plunge", rec, to, false, None, msg));
            }
        }
        let low = if to.z < from.z { to } else { from };
        if is_feed && tool.flute_length_mm > 0.0 {
            let highest = self.highest_within(&low, tool.diameter_mm / 2.0);
            if highest - low.z > tool.flute_length_mm + CUT_MM {
                let msg = format!("the cut reaches {:.3} mm up the tool, beyond its {:.3} mm flutes", highest - low.z, tool.flute_length_mm);
                self.findings.push(Finding::at("flute", rec, low, false, None, msg));
            }
        }
        if let (Some(h), true) = (tool.holder, tool.stick_out_mm > 0.0) {
            let face = low.z + tool.stick_out_mm;
            if face < self.block.max_mm[2] {
                let highest = self.highest_within(&low, h.diameter_mm / 2.0);
                if highest > face + CUT_MM {
                    let msg = format!(
                        "the holder (Ø{:.3} mm, {:.3} mm from the tip) comes {:.3} mm into the material",
                        h.diameter_mm,
                        tool.stick_out_mm,
                        highest - face
                    );
                    self.findings.push(Finding::at("holder", rec, low, false, None, msg));
                }
            }
        }
    }

    /// The material's top at (x, y), if it is over the block.
    fn top_at(&self, x: f64, y: f64) -> Option<f64> {
        let i = ((x - self.block.min_mm[0]) / self.cell_mm).floor();
        let j = ((y - self.block.min_mm[1]) / self.cell_mm).floor();
        (i >= 0.0 && j >= 0.0 && (i as usize) < self.nx && (j as usize) < self.ny).then(|| self.top[j as usize * self.nx + i as usize] as f64)
    }

    /// The highest top of the material within `r` of a point (-inf where there is none).
    fn highest_within(&self, p: &Vec3, r: f64) -> f64 {
        let cell = self.cell_mm;
        let (i0, i1) = (
            ((p.x - r - self.block.min_mm[0]) / cell).floor().max(0.0) as usize,
            (((p.x + r - self.block.min_mm[0]) / cell).ceil().max(0.0) as usize).min(self.nx),
        );
        let (j0, j1) = (
            ((p.y - r - self.block.min_mm[1]) / cell).floor().max(0.0) as usize,
            (((p.y + r - self.block.min_mm[1]) / cell).ceil().max(0.0) as usize).min(self.ny),
        );
        let mut highest = f64::NEG_INFINITY;
        for j in j0..j1 {
            for i in i0..i1 {
                let (cx, cy) = self.centre(i, j);
                if (cx - p.x).powi(2) + (cy - p.y).powi(2) <= r * r {
                    highest = highest.max(self.top[j * self.nx + i] as f64);
                }
            }
        }
        highest
    }

    /// The flat levels below the top: each height at which at least [`FLOOR_MM2`] of the cut
    /// surface stands (a drill's cone or a ball mill's scallops do not make one), with its area,
    /// highest first.
    pub fn floors(&self) -> Vec<(f64, f64)> {
        let top = self.block.max_mm[2] as f32;
        let mut levels: std::collections::BTreeMap<i64, usize> = std::collections::BTreeMap::new();
        for &z in self.top.iter().filter(|z| **z < top - 1e-4) {
            *levels.entry((z as f64 * 1000.0).round() as i64).or_default() += 1;
        }
        let cell_area = self.cell_mm * self.cell_mm;
        levels.into_iter().rev().map(|(z, n)| (z as f64 / 1000.0, n as f64 * cell_area)).filter(|(_, a)| *a >= FLOOR_MM2).collect()
    }

    /// The volume cut from the block, mm³.
    pub fn removed_mm3(&self) -> f64 {
        let top = self.block.max_mm[2] as f32;
        self.top.iter().map(|z| (top - z).max(0.0) as f64).sum::<f64>() * self.cell_mm * self.cell_mm
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
            let (mut xmin, mut xmax, mut ymin, mut ymax) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
            while let Some(k) = stack.pop() {
                let (i, j) = (k % self.nx, k / self.nx);
                let (cx, cy) = self.centre(i, j);
                n += 1;
                sx += cx;
                sy += cy;
                xmin = xmin.min(cx);
                xmax = xmax.max(cx);
                ymin = ymin.min(cy);
                ymax = ymax.max(cy);
                deep = deep.max((top - self.top[k]) as f64);
                let nb = [(i > 0).then(|| k - 1), (i + 1 < self.nx).then(|| k + 1), (j > 0).then(|| k - self.nx), (j + 1 < self.ny).then(|| k + self.nx)];
                for m in nb.into_iter().flatten() {
                    if !seen[m] && self.top[m] < top - 1e-4 {
                        seen[m] = true;
                        stack.push(m);
                    }
                }
            }
            let (x, y) = (sx / n as f64, sy / n as f64);
            let width = xmax - xmin + self.cell_mm;
            // A hole is round (as wide both ways, and filling its circle: a drilled or helically
            // bored hole); a pocket or a slot is a floor, not a hole.
            let across = ymax - ymin + self.cell_mm;
            let area = n as f64 * self.cell_mm * self.cell_mm;
            let round = (width - across).abs() <= 2.0 * self.cell_mm + 0.02 * width && area >= 0.8 * std::f64::consts::PI * width * width / 4.0;
            if !round {
                continue;
            }
            // The deepest drill tip inside it gives a drilled hole's exact depth (the grid sees
            // the cone's point a cell wide).
            let tip = self.tips.iter().filter(|t| (t.x - x).abs() <= width / 2.0 && (t.y - y).abs() <= width / 2.0).min_by(|a, b| a.z.total_cmp(&b.z));
            if let Some(t) = tip {
                deep = deep.max(top as f64 - t.z);
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

    /// The row spans of a segment's capsule hold exactly the cells whose centres lie within the
    /// radius of the segment (checked cell by cell by distance), for segments in every direction:
    /// level, steep, along an axis, a point; and a flat mill's cut through the spans is the
    /// same as a bull-nose mill's with no corner (the cell-by-cell path).
    #[test]
    fn capsule_rows_hold_exactly_the_cells_within_reach() {
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 33) as f64 / (1u64 << 31) as f64
        };
        let block = Block { min_mm: [0.0, 0.0, -20.0], max_mm: [30.0, 30.0, 0.0] };
        for case in 0..300 {
            let a = Vec3::new(5.0 + 20.0 * next(), 5.0 + 20.0 * next(), -1.0);
            let b = match case % 4 {
                0 => a,
                1 => Vec3::new(a.x + 8.0 * (next() - 0.5), a.y, -1.0),
                2 => Vec3::new(a.x, a.y + 8.0 * (next() - 0.5), -1.0),
                _ => Vec3::new(a.x + 8.0 * (next() - 0.5), a.y + 8.0 * (next() - 0.5), -1.0),
            };
            let r = 0.3 + 4.0 * next();
            let flat = Tool { kind: super::super::ToolKind::Mill, diameter_mm: 2.0 * r, ..Tool::default_thread() };
            let bull = Tool { shape: crate::setup::MillShape::Bull, corner_radius_mm: 0.0, ..flat };
            let (mut f, mut g) = (MillStock::new(block, 0.1), MillStock::new(block, 0.1));
            let df = f.level_segment(&a, &b, &flat, true);
            let dg = g.level_segment(&a, &b, &bull, true);
            assert_eq!(f.top, g.top, "case {case}");
            assert!((df - 1.0).abs() < 1e-6 && (dg - 1.0).abs() < 1e-6, "case {case}: {df} {dg}");
            // Cell by cell: cut exactly where the centre is within r (a hair either side of the
            // boundary is left to rounding).
            for j in 0..f.ny {
                for i in 0..f.nx {
                    let (cx, cy) = f.centre(i, j);
                    let p = Vec3::new(cx, cy, -1.0);
                    let (dx, dy) = (b.x - a.x, b.y - a.y);
                    let len2 = dx * dx + dy * dy;
                    let u = if len2 > 0.0 { (((cx - a.x) * dx + (cy - a.y) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
                    let d = ((p.x - a.x - u * dx).powi(2) + (p.y - a.y - u * dy).powi(2)).sqrt();
                    let cut = f.top[j * f.nx + i] < 0.0;
                    if (d - r).abs() > 1e-9 {
                        assert_eq!(cut, d < r, "case {case}: cell ({i}, {j}) at {d} of {r}");
                    }
                }
            }
        }
    }

    #[test]
    fn a_drill_makes_a_hole_of_its_size() {
        let mut s = MillStock::new(Block { min_mm: [0.0, 0.0, -20.0], max_mm: [40.0, 40.0, 0.0] }, 0.1);
        let drill = Tool { kind: super::super::ToolKind::Drill, diameter_mm: 6.0, point_angle_deg: 118.0, ..Tool::default_thread() };
        let rec = Record::new(Span::default(), Op::Feed { from: Vec3::new(10.0, 10.0, 2.0), to: Vec3::new(10.0, 10.0, -8.0), feed_mm_min: 100.0 });
        s.apply(&rec, &drill, 1000.0);
        let h = s.holes();
        assert_eq!(h.len(), 1);
        assert!((h[0].x - 10.0).abs() < 0.06 && (h[0].y - 10.0).abs() < 0.06);
        assert!((h[0].depth_mm - 8.0).abs() < 0.02);
        assert!((h[0].diameter_mm - 6.0).abs() < 0.15, "{:?}", h[0]);
        // A rapid down into the material is a crash.
        let rapid = Record::new(Span::new(9, 1, 1), Op::Rapid { from: Vec3::new(30.0, 30.0, 5.0), to: Vec3::new(30.0, 30.0, -2.0) });
        s.apply(&rapid, &drill, 1000.0);
        assert_eq!(s.findings[0].kind, "crash");
    }
}
