//! G71 (stock removal in turning) and G72 (stock removal in facing), type I, of the system-A
//! lathes: GSK980TDi help text G71 / G72 steps 1-8. One roughing written along a "level axis"
//! (the axis the depth of cut Δd is taken on: X for G71, Z for G72) and a "cut axis" (Z for
//! G71, X for G72):
//! 1. rapid from the start A to A' (A moved by the finishing allowances Δu, Δw);
//! 2. move Δd along the level axis (at the speed of the ns block: rapid for G00, feed for G01),
//!    toward the contour's start B';
//! 3. feed along the cut axis up to the contour (moved by the allowances);
//! 4. feed back e at 45 degrees (both axes);
//! 5. rapid along the cut axis back to A's cut-axis level;
//! 6. while a further Δd + e stays short of B', move it and go to 3; else move to B';
//! 7. feed along the moved contour from B' to C';
//! 8. rapid from C' to A.
//!
//! Type II (the ns block names both axes) lets the contour go back and forth along the level
//! axis, with up to 10 pockets (help text type II, 2); only figures show its path, so ncsight's
//! path is an assumption (docs/commands/g70_g71_g72.md): at each level every stretch of the cut
//! axis where the contour lies deeper than the level is cut, the first from A's side as in type
//! I, each pocket entered over the ridge before it; then steps 6-8 as in type I.

pub use crate::codes::RoughKind;

use super::Expansion;
use crate::geom;
use crate::motion::{Op, Vec3};

/// One roughing block, resolved. The contour is the finishing path from A (the ns block's move
/// first) as the interpreter produced it, not yet moved by the allowances.
#[derive(Debug, Clone, PartialEq)]
pub struct Roughing<'a> {
    pub kind: RoughKind,
    pub start: Vec3,
    pub contour: &'a [Op],
    /// The finishing allowances as a move: (Δu/2, 0, Δw).
    pub allowance: Vec3,
    /// Δd, the depth of each cut (positive).
    pub depth_mm: f64,
    /// e, the back-off (not negative).
    pub back_off_mm: f64,
    /// The ns block moves at rapid (G00) rather than at the feed (G01).
    pub ns_rapid: bool,
    /// Type II: pockets along the level axis allowed.
    pub type_two: bool,
    /// How far the contour may go back along an axis before it counts as a change of direction
    /// (a rounded corner's arc may rise a fraction of a micrometre past its end point): one
    /// least input increment in the units in force (docs/commands/g70_g71_g72.md).
    pub tolerance_mm: f64,
}

/// The directions (+1 or -1) in which a run of values moves, one entry per change: a turn
/// counts only once the values have come back more than `tol` from the furthest point reached.
pub fn direction_runs(values: impl Iterator<Item = f64>, tol: f64) -> Vec<f64> {
    let mut runs = Vec::new();
    let mut extreme: Option<f64> = None;
    for v in values {
        let Some(x) = extreme else {
            extreme = Some(v);
            continue;
        };
        match runs.last().copied() {
            None => {
                if (v - x).abs() > tol {
                    runs.push((v - x).signum());
                    extreme = Some(v);
                }
            }
            Some(dir) => {
                if (v - x) * dir > 0.0 {
                    extreme = Some(v);
                } else if (x - v) * dir > tol {
                    runs.push(-dir);
                    extreme = Some(v);
                }
            }
        }
    }
    runs
}

/// Most pockets a type II contour may have (help text G71/G72 type II, 2).
pub const MAX_POCKETS: usize = 10;

/// What a roughing does that its programmer should hear of (the control does it as well).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RoughNote {
    /// Step 8's straight rapid from C' back to A passes through the part: the contour ends
    /// deeper than something it passed.
    EndRapidThroughPart,
    /// Type II with pockets and an allowance along the cut axis: the whole contour moves, so one
    /// wall of each pocket is left thinner than the allowance, or cut into.
    AllowanceMovesPocketWalls,
    /// The contour rises outside the start point A' along the depth axis: the levels begin at A',
    /// so the roughing runs into it.
    ContourBeyondStart,
}

/// The moves of a roughing, and what to tell about them.
#[derive(Debug, Clone, PartialEq)]
pub struct Rough {
    pub ops: Vec<Op>,
    pub notes: Vec<RoughNote>,
}

/// Why a contour cannot be roughed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum RoughError {
    /// The contour is not monotonic along the given axis (index) (help text note 3).
    NotMonotonic(usize),
    /// More passes than the limit.
    TooMany,
    /// A type II contour with more than [`MAX_POCKETS`] pockets.
    TooManyPockets,
    /// The contour has a move that is not a straight line or an arc.
    NotAPath,
}

fn shift(v: &Vec3, by: &Vec3) -> Vec3 {
    Vec3::new(v.x + by.x, v.y + by.y, v.z + by.z)
}

/// A moved copy of a contour move; rapids become feeds (step 7 cuts along the whole contour).
fn moved(op: &Op, by: &Vec3) -> Result<Op, RoughError> {
    Ok(match *op {
        Op::Rapid { from, to } => Op::Feed { from: shift(&from, by), to: shift(&to, by), feed_mm_min: 0.0 },
        Op::Feed { from, to, feed_mm_min } => Op::Feed { from: shift(&from, by), to: shift(&to, by), feed_mm_min },
        Op::Arc { from, to, center, plane, dir, feed_mm_min } => {
            Op::Arc { from: shift(&from, by), to: shift(&to, by), center: shift(&center, by), plane, dir, feed_mm_min }
        }
        _ => return Err(RoughError::NotAPath),
    })
}

/// The contour as fine points (arcs as chords of at most `chord_mm`), for finding where a level
/// meets it.
fn polyline(contour: &[Op], chord_mm: f64) -> Vec<Vec3> {
    let mut pts = Vec::new();
    for op in contour {
        match op {
            Op::Feed { from, to, .. } | Op::Rapid { from, to } => {
                if pts.is_empty() {
                    pts.push(*from);
                }
                pts.push(*to);
            }
            Op::Arc { from, to, plane, dir, .. } => {
                if pts.is_empty() {
                    pts.push(*from);
                }
                if let Some(g) = crate::geom::arc_geom_of(op) {
                    let n = ((geom::arc_length(from, to, *plane, &g) / chord_mm).ceil() as usize).clamp(8, 20_000);
                    for k in 1..=n {
                        pts.push(geom::arc_point(from, to, *plane, *dir, &g, k as f64 / n as f64));
                    }
                } else {
                    pts.push(*to);
                }
            }
            _ => {}
        }
    }
    pts
}

/// The moves of one roughing block (feeds carry 0: the interpreter sets each from F), at most
/// `limit` passes and moves.
pub fn expand(r: &Roughing, limit: usize) -> Result<Rough, RoughError> {
    let plan = lay_out(r, limit)?;
    let ops = super::held(&plan, limit).ok_or(RoughError::TooMany)?;
    Ok(Rough { ops, notes: plan.notes })
}

/// A roughing laid out: what its moves are made from, made one at a time by
/// [`RoughPlan::each_op`], so that a type I roughing of any number of levels holds no more
/// than its contour (a G71 with a Δd of a micrometre: a hundred thousand levels).
#[derive(Debug, Clone, PartialEq)]
pub struct RoughPlan {
    /// A, where the cycle starts and ends.
    start: Vec3,
    /// A' and B': A and the contour's start moved by the allowances.
    a1: Vec3,
    b1: Vec3,
    /// The level axis and the cut axis.
    axes: (usize, usize),
    /// The contour after the ns move, moved by the allowances.
    path: Vec<Op>,
    /// `path` as fine points from B'.
    pts: Vec<Vec3>,
    dir_l: f64,
    /// Which way the contour runs along the level axis (from B' back toward A's level).
    rise: f64,
    dir_c: f64,
    depth_mm: f64,
    back_off_mm: f64,
    ns_rapid: bool,
    /// Type I: the levels strictly between A' and B'.
    levels: usize,
    /// Type II: the moves of steps 2-6, made when laid out (at most the limit).
    type_two: Option<Vec<Op>>,
    pub notes: Vec<RoughNote>,
}

/// Lay out one roughing block: its contour checked (help text note 3), its levels counted, what
/// its moves tell found. Type II's levels are made here (at most `limit` moves); type I's are
/// made as they are handed on.
pub fn lay_out(r: &Roughing, limit: usize) -> Result<RoughPlan, RoughError> {
    let (l, c) = r.kind.axes();
    let b = match r.contour.first() {
        Some(first) => first.end_point().ok_or(RoughError::NotAPath)?,
        None => r.start,
    };
    let a1 = shift(&r.start, &r.allowance);
    let b1 = shift(&b, &r.allowance);
    let path: Vec<Op> = r.contour.iter().skip(1).map(|op| moved(op, &r.allowance)).collect::<Result<_, _>>()?;
    let pts: Vec<Vec3> = {
        let mut p = vec![b1];
        p.extend(polyline(&path, 0.01).into_iter().skip(1));
        p
    };
    // Help text note 3: both axes monotonic along the contour (type I); type II only the cut
    // axis.
    let monotonic: &[usize] = if r.type_two { &[c] } else { &[l, c] };
    for &axis in monotonic {
        if direction_runs(pts.iter().map(|p| p.axis(axis)), r.tolerance_mm).len() > 1 {
            return Err(RoughError::NotMonotonic(axis));
        }
    }
    let end = *pts.last().unwrap_or(&b1);
    let dir_l = (b1.axis(l) - a1.axis(l)).signum();
    let mut plan = RoughPlan {
        start: r.start,
        a1,
        b1,
        axes: (l, c),
        path,
        pts: Vec::new(),
        dir_l,
        rise: (end.axis(l) - b1.axis(l)).signum(),
        dir_c: (end.axis(c) - b1.axis(c)).signum(),
        depth_mm: r.depth_mm,
        back_off_mm: r.back_off_mm,
        ns_rapid: r.ns_rapid,
        levels: 0,
        type_two: None,
        notes: Vec::new(),
    };
    if r.contour.is_empty() {
        return Ok(plan);
    }
    if r.type_two {
        // 2-6 of type II: the levels strictly between A' and the deepest point of the contour.
        let (mut ops, mut pos) = (Vec::new(), a1);
        levels_type_two(r, a1, &pts, limit, &mut ops, &mut pos, &mut plan.notes)?;
        plan.type_two = Some(ops);
    } else {
        // 2-6: the levels strictly between A' and B'.
        let total = (b1.axis(l) - a1.axis(l)).abs();
        plan.levels = level_count(total, r.depth_mm, dir_l)?;
    }
    // 8: back to A, a straight rapid (the help text's step 8), whatever lies in between.
    let last = plan.path.iter().rev().find_map(Op::end_point).unwrap_or(b1);
    let inward = (b1.axis(l) - a1.axis(l)).signum();
    let through = (0..=64).any(|k| {
        let u = f64::from(k) / 64.0;
        let (lv, cv) = (last.axis(l) + u * (r.start.axis(l) - last.axis(l)), last.axis(c) + u * (r.start.axis(c) - last.axis(c)));
        contour_level_at(&pts, l, c, cv).is_some_and(|at| (lv - at) * inward > 1e-6)
    });
    if through {
        plan.notes.push(RoughNote::EndRapidThroughPart);
    }
    plan.pts = pts;
    Ok(plan)
}

/// How many levels Δd apart lie strictly short of `total` (the largest k with k Δd < total,
/// worked out, not counted one by one: a Δd of a picometre is said at once), at most a quarter of
/// [`super::MOST_MOVES`] (four moves a level).
fn level_count(total: f64, depth_mm: f64, dir_l: f64) -> Result<usize, RoughError> {
    if dir_l == 0.0 || depth_mm <= 0.0 || total <= 1e-9 {
        return Ok(0);
    }
    let guess = ((total - 1e-9) / depth_mm).ceil() - 1.0;
    if !(guess < (super::MOST_MOVES / 4) as f64) {
        return Err(RoughError::TooMany);
    }
    // The guess within one of the count; the test is the one the levels are cut by.
    let mut k = guess.max(0.0) as usize;
    while ((k + 1) as f64) * depth_mm < total - 1e-9 {
        k += 1;
    }
    while k > 0 && (k as f64) * depth_mm >= total - 1e-9 {
        k -= 1;
    }
    Ok(k)
}

/// A move to `to` (a feed or a rapid) handed on unless the tool is there already.
struct Mover<'s> {
    pos: Vec3,
    sink: &'s mut dyn FnMut(Op) -> std::ops::ControlFlow<()>,
}

impl Mover<'_> {
    fn go(&mut self, to: Vec3, feed: bool) -> std::ops::ControlFlow<()> {
        if to == self.pos {
            return std::ops::ControlFlow::Continue(());
        }
        let op = if feed { Op::Feed { from: self.pos, to, feed_mm_min: 0.0 } } else { Op::Rapid { from: self.pos, to } };
        self.pos = to;
        (self.sink)(op)
    }

    fn pass(&mut self, op: &Op) -> std::ops::ControlFlow<()> {
        self.pos = op.end_point().unwrap_or(self.pos);
        (self.sink)(*op)
    }
}

impl Expansion for RoughPlan {
    /// How many moves the roughing makes at most (a count, nothing made).
    fn move_count(&self) -> usize {
        let levels = match &self.type_two {
            Some(ops) => ops.len(),
            None => 4 * self.levels,
        };
        if self.pts.is_empty() {
            return 0;
        }
        levels + self.path.len() + 3
    }

    /// Hand on the moves in order, one at a time (the sink may stop them).
    fn each_op(&self, sink: &mut dyn FnMut(Op) -> std::ops::ControlFlow<()>) {
        // A roughing without a contour makes no move.
        if self.pts.is_empty() {
            return;
        }
        let mut m = Mover { pos: self.start, sink };
        // 1: A to A'.
        if m.go(self.a1, false).is_break() {
            return;
        }
        match &self.type_two {
            Some(ops) => {
                for op in ops {
                    if m.pass(op).is_break() {
                        return;
                    }
                }
            }
            None => {
                for k in 1..=self.levels {
                    if self.level(k, &mut m).is_break() {
                        return;
                    }
                }
            }
        }
        // 6-7: to B', along the contour to C'.
        if m.go(self.b1, !self.ns_rapid).is_break() {
            return;
        }
        for op in &self.path {
            if m.pass(op).is_break() {
                return;
            }
        }
        // 8: back to A.
        let _ = m.go(self.start, false);
    }
}

impl RoughPlan {
    /// Type I's level `k` (steps 2-5): to the level, cut to the contour, back off e at 45
    /// degrees, rapid back to A's cut-axis position.
    fn level(&self, k: usize, m: &mut Mover) -> std::ops::ControlFlow<()> {
        let (l, c) = self.axes;
        let (a1, pts) = (self.a1, &self.pts);
        let level = a1.axis(l) + self.dir_l * k as f64 * self.depth_mm;
        // Where the level meets the contour, walking from B': the contour is monotonic along
        // the level axis (checked when laid out), so a binary search finds the first point at
        // or past the level.
        let i = pts.partition_point(|p| (p.axis(l) - level) * self.rise < 0.0);
        let hit = if i == 0 {
            pts[0].axis(c)
        } else if i >= pts.len() {
            pts[pts.len() - 1].axis(c)
        } else {
            let (w0, w1) = (pts[i - 1], pts[i]);
            let (p, q) = (w0.axis(l), w1.axis(l));
            let u = if (q - p).abs() > 1e-12 { (level - p) / (q - p) } else { 1.0 };
            w0.axis(c) + u * (w1.axis(c) - w0.axis(c))
        };
        let at = |lv: f64, cv: f64| place(a1, (l, c), lv, cv);
        let e = self.back_off_mm;
        m.go(at(level, a1.axis(c)), !self.ns_rapid)?;
        m.go(at(level, hit), true)?;
        m.go(at(level - self.dir_l * e, hit - self.dir_c * e), true)?;
        m.go(at(level - self.dir_l * e, a1.axis(c)), false)
    }
}

/// The contour's position along the level axis `l` at `cv` on the cut axis `c` (the contour is
/// monotonic along `c`), if `cv` lies within its extent.
fn contour_level_at(pts: &[Vec3], l: usize, c: usize, cv: f64) -> Option<f64> {
    pts.windows(2).find_map(|w| {
        let (p, q) = (w[0].axis(c), w[1].axis(c));
        let (lo, hi) = if p < q { (p, q) } else { (q, p) };
        if cv < lo || cv > hi {
            return None;
        }
        let u = if (q - p).abs() > 1e-12 { (cv - p) / (q - p) } else { 0.0 };
        Some(w[0].axis(l) + u * (w[1].axis(l) - w[0].axis(l)))
    })
}

/// Append a move to `to` (a feed or a rapid) unless the tool is there already (type II's
/// levels, laid out whole).
fn go(to: Vec3, feed: bool, ops: &mut Vec<Op>, pos: &mut Vec3) {
    if to != *pos {
        ops.push(if feed { Op::Feed { from: *pos, to, feed_mm_min: 0.0 } } else { Op::Rapid { from: *pos, to } });
        *pos = to;
    }
}

/// `base` with the level axis `l` at `lv` and the cut axis `c` at `cv`.
fn place(base: Vec3, (l, c): (usize, usize), lv: f64, cv: f64) -> Vec3 {
    let mut v = base;
    v.set_axis(l, lv);
    v.set_axis(c, cv);
    v
}

/// A type II contour's pockets: each turn from going deeper to coming out again (help text
/// type II, 2), at most [`MAX_POCKETS`]; with pockets, an allowance along the cut axis is told.
fn count_pockets(r: &Roughing, pts: &[Vec3], dir_l: f64, notes: &mut Vec<RoughNote>) -> Result<(), RoughError> {
    let (l, c) = r.kind.axes();
    let runs = direction_runs(pts.iter().map(|p| p.axis(l) * dir_l), r.tolerance_mm);
    let pockets = runs.windows(2).filter(|w| w[0] > 0.0 && w[1] < 0.0).count();
    if pockets > MAX_POCKETS {
        return Err(RoughError::TooManyPockets);
    }
    if pockets > 0 && r.allowance.axis(c) != 0.0 {
        notes.push(RoughNote::AllowanceMovesPocketWalls);
    }
    Ok(())
}

/// Steps 2-6 of type II. At each level (Δd apart from A', strictly short of the contour's
/// deepest point) the stretches of the cut axis where the contour lies deeper than the level are
/// cut in order from A's side: the first, if it starts on A's side, as in type I (move to the
/// level at A's cut-axis position, cut); each later one (a pocket) by rising to a travel level
/// over the ridge before it, rapid along the cut axis to the pocket's edge, rapid down to the
/// level before this one and feed down to the level, cut. Every cut ends with the 45-degree
/// back-off e; after the level the tool rises to the travel level over what lies between it and
/// A's cut-axis position and rapids back there. A travel level is e outside the last level cut
/// over the highest point passed, so that it clears the steps the levels leave.
fn levels_type_two(
    r: &Roughing,
    a1: Vec3,
    pts: &[Vec3],
    limit: usize,
    ops: &mut Vec<Op>,
    pos: &mut Vec3,
    notes: &mut Vec<RoughNote>,
) -> Result<(), RoughError> {
    let axes = r.kind.axes();
    let (l, c) = axes;
    let (Some(first), Some(last)) = (pts.first(), pts.last()) else { return Ok(()) };
    let dir_c = (last.axis(c) - first.axis(c)).signum();
    // The contour lies on this side of A' along the level axis; its deepest point there.
    let dir_l = (first.axis(l) - a1.axis(l)).signum();
    let deepest = pts.iter().map(|p| p.axis(l)).fold(a1.axis(l), |m, v| if (v - m) * dir_l > 0.0 { v } else { m });
    if dir_l == 0.0 || r.depth_mm <= 0.0 {
        return Ok(());
    }
    // Outward, away from the part: the way the tool backs off.
    let out = -dir_l;
    let e = r.back_off_mm;
    count_pockets(r, pts, dir_l, notes)?;
    let at = |lv: f64, cv: f64| place(a1, axes, lv, cv);
    // How far along the cut axis the levels reach (for the check after them).
    let mut reach = a1.axis(c);
    let outer = |a: f64, b: f64| Outermost::outer_of(out, a, b);
    // The travel level over the contour between two cut-axis positions (nothing stands before
    // the contour's start).
    let outermost = Outermost::new(pts, l, c, dir_c, out);
    let travel = |from_c: f64, to_c: f64, level: f64| {
        let (lo, hi) = if from_c < to_c { (from_c, to_c) } else { (to_c, from_c) };
        let inside = outermost.between(lo, hi);
        let ends = [lo, hi].into_iter().filter_map(|cv| contour_level_at(pts, l, c, cv));
        match inside.into_iter().chain(ends).reduce(outer) {
            None => level + out * e,
            Some(top) => {
                // The last level cut over the top lies strictly outside it (the test of
                // `deeper_stretches`): a level exactly at a flat leaves its slab standing.
                let mut whole = ((top - a1.axis(l)) * dir_l / r.depth_mm).floor().max(0.0);
                while whole > 0.0 && (top - (a1.axis(l) + dir_l * whole * r.depth_mm)) * dir_l <= 0.0 {
                    whole -= 1.0;
                }
                outer(a1.axis(l) + dir_l * whole * r.depth_mm, level) + out * e
            }
        }
    };
    let total = (deepest - a1.axis(l)).abs();
    let mut count = 0usize;
    while ((count + 1) as f64) * r.depth_mm < total - 1e-9 {
        count += 1;
        if count > limit {
            return Err(RoughError::TooMany);
        }
    }
    let level_of = |k: usize| a1.axis(l) + dir_l * k as f64 * r.depth_mm;
    let all = all_stretches(pts, l, c, &level_of, count, dir_l, a1.axis(c));
    for (k, stretches) in (1..=count).zip(&all) {
        if ops.len() > limit {
            return Err(RoughError::TooMany);
        }
        let level = level_of(k);
        for (i, &(from_c, to_c)) in stretches.iter().enumerate() {
            if i == 0 && from_c == a1.axis(c) {
                go(at(level, from_c), !r.ns_rapid, ops, pos);
            } else {
                let top = outer(travel(pos.axis(c), from_c, level), pos.axis(l));
                go(at(top, pos.axis(c)), false, ops, pos);
                go(at(top, from_c), false, ops, pos);
                // Down at rapid through what the earlier levels cleared, to the level before.
                let above = level + out * r.depth_mm;
                go(at(if (above - top) * out < 0.0 { above } else { top }, from_c), false, ops, pos);
                go(at(level, from_c), true, ops, pos);
            }
            go(at(level, to_c), true, ops, pos);
            if (to_c - reach) * dir_c > 0.0 {
                reach = to_c;
            }
            // The back-off, at 45 degrees but no wider than the stretch (a narrow pocket).
            let back = e.min((to_c - from_c).abs());
            go(at(level + out * e, to_c - dir_c * back), true, ops, pos);
        }
        let top = outer(travel(pos.axis(c), a1.axis(c), level), pos.axis(l));
        go(at(top, pos.axis(c)), false, ops, pos);
        go(at(top, a1.axis(c)), false, ops, pos);
    }
    // A point of the contour outside A' where the levels pass: they begin at A' and run into it.
    let (lo, hi) = if a1.axis(c) < reach { (a1.axis(c), reach) } else { (reach, a1.axis(c)) };
    if pts.iter().any(|p| p.axis(c) >= lo && p.axis(c) <= hi && (p.axis(l) - a1.axis(l)) * dir_l < -1e-9) {
        notes.push(RoughNote::ContourBeyondStart);
    }
    Ok(())
}

/// The outermost level of the contour's points over a range of the cut axis, answered from a
/// table of powers of two (the contour is monotonic along the cut axis, so a range of the axis
/// is a range of points): each query is two lookups, not a walk over the contour.
struct Outermost<'a> {
    pts: &'a [Vec3],
    c: usize,
    dir_c: f64,
    out: f64,
    /// `table[j][i]`: the outermost level of points i .. i + 2^j.
    table: Vec<Vec<f64>>,
}

impl<'a> Outermost<'a> {
    fn new(pts: &'a [Vec3], l: usize, c: usize, dir_c: f64, out: f64) -> Outermost<'a> {
        let mut table = vec![pts.iter().map(|p| p.axis(l)).collect::<Vec<f64>>()];
        let mut width = 1;
        while 2 * width <= pts.len() {
            let prev = table.last().expect("one row at least");
            let row = (0..=pts.len() - 2 * width).map(|i| Self::outer_of(out, prev[i], prev[i + width])).collect();
            table.push(row);
            width *= 2;
        }
        Outermost { pts, c, dir_c, out, table }
    }

    /// The one of `a` and `b` further out (`out` gives the outward sign); `a` on a tie.
    fn outer_of(out: f64, a: f64, b: f64) -> f64 {
        if (a - b) * out >= 0.0 {
            a
        } else {
            b
        }
    }

    /// The outermost level of the points with cut-axis position in `lo..=hi`, if any.
    fn between(&self, lo: f64, hi: f64) -> Option<f64> {
        let (i0, i1) = if self.dir_c == 0.0 {
            // All at one cut-axis position.
            let inside = self.pts.first().is_some_and(|p| p.axis(self.c) >= lo && p.axis(self.c) <= hi);
            if inside {
                (0, self.pts.len())
            } else {
                (0, 0)
            }
        } else {
            let key = |p: &Vec3| p.axis(self.c) * self.dir_c;
            let (a, b) = if self.dir_c > 0.0 { (lo, hi) } else { (-hi, -lo) };
            (self.pts.partition_point(|p| key(p) < a), self.pts.partition_point(|p| key(p) <= b))
        };
        if i0 >= i1 {
            return None;
        }
        let j = (usize::BITS - 1 - (i1 - i0).leading_zeros()) as usize;
        let row = &self.table[j];
        Some(Self::outer_of(self.out, row[i0], row[i1 - (1 << j)]))
    }
}

/// The stretches `(from, to)` of the cut axis, in the contour's order, where the contour lies
/// deeper than each level 1 ..= `count` (the side `dir_l` points to); a stretch that begins at the
/// contour's start begins at `start_c`, A's cut-axis position (nothing stands before the contour).
/// All levels at once, in one pass over the contour: a
/// segment's ends lie on different sides only of the levels between them, so each segment is
/// looked at for those levels alone (and one more each side, where rounding could tip it).
fn all_stretches(pts: &[Vec3], l: usize, c: usize, level_of: &dyn Fn(usize) -> f64, count: usize, dir_l: f64, start_c: f64) -> Vec<Vec<(f64, f64)>> {
    let mut crossings: Vec<Vec<u32>> = vec![Vec::new(); count];
    if count > 0 && pts.len() > 1 {
        let deeper = |p: &Vec3, k: usize| (p.axis(l) - level_of(k)) * dir_l > 0.0;
        // A point's depth in levels from A' (level k lies at k).
        let a1 = level_of(0);
        let depth = |p: &Vec3| (p.axis(l) - a1) * dir_l / ((level_of(1) - a1) * dir_l);
        for (s, w) in pts.windows(2).enumerate() {
            let (t0, t1) = (depth(&w[0]), depth(&w[1]));
            let lo = (t0.min(t1).floor() - 1.0).max(1.0);
            let hi = (t0.max(t1).ceil() + 1.0).min(count as f64);
            if !(lo <= hi) {
                continue;
            }
            for k in lo as usize..=hi as usize {
                if deeper(&w[0], k) != deeper(&w[1], k) {
                    crossings[k - 1].push(s as u32);
                }
            }
        }
    }
    (1..=count)
        .zip(&crossings)
        .map(|(k, segs)| {
            let level = level_of(k);
            let cross = |p: &Vec3, q: &Vec3| {
                let (a, b) = (p.axis(l), q.axis(l));
                let u = if (b - a).abs() > 1e-12 { (level - a) / (b - a) } else { 0.0 };
                p.axis(c) + u * (q.axis(c) - p.axis(c))
            };
            let mut out = Vec::new();
            let mut open = pts.first().filter(|p| (p.axis(l) - level) * dir_l > 0.0).map(|_| start_c);
            for &s in segs {
                let (p, q) = (&pts[s as usize], &pts[s as usize + 1]);
                match open {
                    None => open = Some(cross(p, q)),
                    Some(from) => {
                        out.push((from, cross(p, q)));
                        open = None;
                    }
                }
            }
            if let (Some(from), Some(p)) = (open, pts.last()) {
                out.push((from, p.axis(c)));
            }
            out
        })
        .collect()
}

/// G73 pattern repeating (GSK980TDi help text G73): `passes` (d) passes over the whole contour,
/// the ns move included, pass k (1-based) moved by the allowance plus `relief x (d - k) / (d - 1)`
/// (the first pass Δi, Δk further out, the last on the allowance); a rapid from each pass's end
/// to the next pass's start (A1 -> B1 -> C1 -> A2 ...), and from the last back to A.
pub fn pattern(start: Vec3, contour: &[Op], allowance: Vec3, relief: Vec3, passes: u32, limit: usize) -> Result<Vec<Op>, RoughError> {
    let plan = lay_out_pattern(start, contour, allowance, relief, passes)?;
    // The moves are known before any is made: more than `limit` is refused at once.
    super::held(&plan, limit).ok_or(RoughError::TooMany)
}

/// A G73 laid out: the contour (checked: lines and arcs) and the passes, its moves made one at a
/// time by [`PatternPlan::each_op`], so that any number of passes holds the contour and no more.
#[derive(Debug, Clone, PartialEq)]
pub struct PatternPlan {
    start: Vec3,
    contour: Vec<Op>,
    allowance: Vec3,
    relief: Vec3,
    passes: u32,
}

/// Lay out a G73: the contour's moves must be lines or arcs ([`RoughError::NotAPath`]).
pub fn lay_out_pattern(start: Vec3, contour: &[Op], allowance: Vec3, relief: Vec3, passes: u32) -> Result<PatternPlan, RoughError> {
    for op in contour {
        moved(op, &allowance)?;
    }
    Ok(PatternPlan { start, contour: contour.to_vec(), allowance, relief, passes })
}

impl PatternPlan {
    /// Pass `k` (1 to the passes): the contour moved by the allowance and what is left of the
    /// relief, the ns move at its own speed.
    fn pass_op(&self, k: u32, i: usize, by: &Vec3) -> Op {
        match self.contour[i] {
            // The ns move keeps its own speed.
            Op::Rapid { from, to } if i == 0 => Op::Rapid { from: shift(&from, by), to: shift(&to, by) },
            ref op => moved(op, by).unwrap_or_else(|_| unreachable!("checked when laid out (pass {k})")),
        }
    }
}

impl Expansion for PatternPlan {
    /// How many moves the passes make at most: per pass the rapid to its start and the contour;
    /// then the way back.
    fn move_count(&self) -> usize {
        if self.contour.is_empty() || self.passes == 0 {
            return 0;
        }
        (self.passes as usize).saturating_mul(self.contour.len() + 1).saturating_add(1)
    }

    /// Hand on the moves in order (the sink may stop them).
    fn each_op(&self, sink: &mut dyn FnMut(Op) -> std::ops::ControlFlow<()>) {
        if self.move_count() == 0 {
            return;
        }
        let (start, passes, a, r) = (self.start, self.passes, self.allowance, self.relief);
        let mut pos = start;
        for k in 1..=passes {
            let f = if passes > 1 { (passes - k) as f64 / (passes - 1) as f64 } else { 0.0 };
            let by = Vec3::new(a.x + r.x * f, a.y + r.y * f, a.z + r.z * f);
            let pass_start = shift(&start, &by);
            if pass_start != pos && sink(Op::Rapid { from: pos, to: pass_start }).is_break() {
                return;
            }
            for i in 0..self.contour.len() {
                let m = self.pass_op(k, i, &by);
                pos = m.end_point().unwrap_or(pos);
                if sink(m).is_break() {
                    return;
                }
            }
        }
        if pos != start {
            let _ = sink(Op::Rapid { from: pos, to: start });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn feed(from: (f64, f64), to: (f64, f64)) -> Op {
        Op::Feed { from: Vec3::new(from.0, 0.0, from.1), to: Vec3::new(to.0, 0.0, to.1), feed_mm_min: 100.0 }
    }

    #[test]
    fn g71_step_contour() {
        // Radius coordinates. A (25, 2); contour: ns G00 to X10 (B at Z2), Z-10, X20, Z-20, X25.
        let contour = [
            Op::Rapid { from: Vec3::new(25.0, 0.0, 2.0), to: Vec3::new(10.0, 0.0, 2.0) },
            feed((10.0, 2.0), (10.0, -10.0)),
            feed((10.0, -10.0), (20.0, -10.0)),
            feed((20.0, -10.0), (20.0, -20.0)),
            feed((20.0, -20.0), (25.0, -20.0)),
        ];
        let r = Roughing {
            kind: RoughKind::Turning,
            start: Vec3::new(25.0, 0.0, 2.0),
            contour: &contour,
            allowance: Vec3::new(0.5, 0.0, 0.1),
            depth_mm: 4.0,
            back_off_mm: 1.0,
            ns_rapid: true,
            type_two: false,
            tolerance_mm: 0.001,
        };
        let ops = expand(&r, 1000).unwrap().ops;
        // A' = (25.5, 2.1); levels 21.5, 17.5, 13.5 (B' is at 10.5).
        let cuts: Vec<(f64, f64)> = ops
            .iter()
            .filter_map(|o| match o {
                Op::Feed { from, to, feed_mm_min } if *feed_mm_min == 0.0 && from.x == to.x && from.z == 2.1 => Some((to.x, to.z)),
                _ => None,
            })
            .collect();
        // Level 21.5 meets the moved contour at Z -20 + 0.1 = -19.9; 17.5 and 13.5 at -9.9.
        assert_eq!(cuts.len(), 3, "{ops:?}");
        for (got, want) in cuts.iter().zip([(21.5, -19.9), (17.5, -9.9), (13.5, -9.9)]) {
            assert!((got.0 - want.0).abs() < 1e-9 && (got.1 - want.1).abs() < 1e-9, "{cuts:?}");
        }
        // The 45-degree back-off after the first cut: to (22.5, -18.9).
        assert!(ops.iter().any(|o| matches!(o, Op::Feed { to, .. } if (to.x - 22.5).abs() < 1e-9 && (to.z + 18.9).abs() < 1e-9)));
        // Ends with the contour pass (moved) and a rapid back to A.
        assert_eq!(ops.last().unwrap(), &Op::Rapid { from: Vec3::new(25.5, 0.0, -19.9), to: Vec3::new(25.0, 0.0, 2.0) });
    }

    #[test]
    fn g73_passes_close_in_evenly() {
        let contour = [Op::Rapid { from: Vec3::new(25.0, 0.0, 2.0), to: Vec3::new(10.0, 0.0, 2.0) }, feed((10.0, 2.0), (20.0, -10.0))];
        // Three passes, relief (3, 0, 1), allowance (0.5, 0, 0): offsets 3.5/1, 2/0.5, 0.5/0.
        let ops = pattern(Vec3::new(25.0, 0.0, 2.0), &contour, Vec3::new(0.5, 0.0, 0.0), Vec3::new(3.0, 0.0, 1.0), 3, 100_000).unwrap();
        let cut_ends: Vec<(f64, f64)> = ops.iter().filter_map(|o| if let Op::Feed { to, .. } = o { Some((to.x, to.z)) } else { None }).collect();
        assert_eq!(cut_ends, vec![(23.5, -9.0), (22.0, -9.5), (20.5, -10.0)]);
        assert_eq!(*ops.last().unwrap(), Op::Rapid { from: Vec3::new(20.5, 0.0, -10.0), to: Vec3::new(25.0, 0.0, 2.0) });
    }

    #[test]
    fn a_pocket_is_not_type_one() {
        let contour = [
            Op::Rapid { from: Vec3::new(25.0, 0.0, 2.0), to: Vec3::new(10.0, 0.0, 2.0) },
            feed((10.0, 2.0), (20.0, -10.0)),
            feed((20.0, -10.0), (15.0, -15.0)),
            feed((15.0, -15.0), (25.0, -20.0)),
        ];
        let r = Roughing {
            kind: RoughKind::Turning,
            start: Vec3::new(25.0, 0.0, 2.0),
            contour: &contour,
            allowance: Vec3::default(),
            depth_mm: 2.0,
            back_off_mm: 0.5,
            ns_rapid: true,
            type_two: false,
            tolerance_mm: 0.001,
        };
        assert_eq!(expand(&r, 1000), Err(RoughError::NotMonotonic(0)));
    }

    /// Type II over one pocket, radius coordinates, no allowance. A (25, 2); contour: B (10, 2),
    /// out to (20, -10), down into the pocket to (15, -15), out to (25, -20). Δd 2, e 0.5:
    /// levels 23 ... 11 (the deepest point is B at 10).
    #[test]
    fn type_two_cuts_the_pocket_from_over_its_ridge() {
        let contour = [
            Op::Rapid { from: Vec3::new(25.0, 0.0, 2.0), to: Vec3::new(10.0, 0.0, 2.0) },
            feed((10.0, 2.0), (20.0, -10.0)),
            feed((20.0, -10.0), (15.0, -15.0)),
            feed((15.0, -15.0), (25.0, -20.0)),
        ];
        let r = Roughing {
            kind: RoughKind::Turning,
            start: Vec3::new(25.0, 0.0, 2.0),
            contour: &contour,
            allowance: Vec3::default(),
            depth_mm: 2.0,
            back_off_mm: 0.5,
            ns_rapid: true,
            type_two: true,
            tolerance_mm: 0.001,
        };
        let ops = expand(&r, 1000).unwrap().ops;
        let cuts: Vec<(f64, f64, f64)> = ops
            .iter()
            .filter_map(|o| match o {
                Op::Feed { from, to, .. } if from.x == to.x && from.z != to.z => Some((to.x, from.z, to.z)),
                _ => None,
            })
            .collect();
        let near = |a: f64, b: f64| (a - b).abs() < 1e-6;
        // Level 23 and 21: one stretch each, from A's side to where the last rise meets them
        // (z -19 and -18); the ridge top (20) is deeper than both.
        assert!(near(cuts[0].0, 23.0) && near(cuts[0].1, 2.0) && near(cuts[0].2, -19.0), "{cuts:?}");
        assert!(near(cuts[1].0, 21.0) && near(cuts[1].2, -18.0), "{cuts:?}");
        // Level 19: from A's side to the ridge (z -8.8: 10 + 10.8 x 10/12 = 19), then the pocket from -11 to -17.
        assert!(near(cuts[2].0, 19.0) && near(cuts[2].2, -8.8), "{cuts:?}");
        assert!(near(cuts[3].0, 19.0) && near(cuts[3].1, -11.0) && near(cuts[3].2, -17.0), "{cuts:?}");
        // Down to level 15 the pocket is cut again at each level; below it only A's side.
        let pocket_levels: Vec<f64> = cuts.iter().filter(|c| c.1 < -10.0).map(|c| c.0).collect();
        assert_eq!(pocket_levels.len(), 2, "{cuts:?}");
        assert!(near(pocket_levels[1], 17.0));
        // The pocket is entered over the ridge: the last level cut over the ridge top 20 is 21,
        // plus e: travel at 21.5, down at rapid to the level before (21), feed in to 19.
        assert!(
            ops.windows(3).any(|w| matches!(w, [Op::Rapid { to: a, .. }, Op::Rapid { to: b, .. }, Op::Feed { to: f, .. }]
            if near(a.x, 21.5) && near(a.z, -11.0) && near(b.x, 21.0) && near(f.x, 19.0) && near(f.z, -11.0))),
            "{ops:?}"
        );
        // No move passes through the part: every point of every move is outside the contour.
        let contour_x = |z: f64| -> f64 {
            if z >= 2.0 {
                return f64::NEG_INFINITY;
            }
            if z >= -10.0 {
                10.0 + (2.0 - z) * 10.0 / 12.0
            } else if z >= -15.0 {
                20.0 - (-10.0 - z)
            } else if z >= -20.0 {
                15.0 + (-15.0 - z) * 2.0
            } else {
                25.0
            }
        };
        for o in &ops {
            if let Op::Feed { from, to, .. } | Op::Rapid { from, to } = o {
                for k in 0..=20 {
                    let u = k as f64 / 20.0;
                    let (x, z) = (from.x + u * (to.x - from.x), from.z + u * (to.z - from.z));
                    assert!(x >= contour_x(z) - 1e-6, "{o:?} passes through the part at ({x}, {z})");
                }
            }
        }
    }

    #[test]
    fn too_many_pockets() {
        let mut contour = vec![Op::Rapid { from: Vec3::new(30.0, 0.0, 2.0), to: Vec3::new(10.0, 0.0, 2.0) }];
        let mut z = 2.0;
        for _ in 0..12 {
            contour.push(feed((10.0, z), (20.0, z - 1.0)));
            contour.push(feed((20.0, z - 1.0), (10.0, z - 2.0)));
            z -= 2.0;
        }
        contour.push(feed((10.0, z), (30.0, z - 1.0)));
        let r = Roughing {
            kind: RoughKind::Turning,
            start: Vec3::new(30.0, 0.0, 2.0),
            contour: &contour,
            allowance: Vec3::default(),
            depth_mm: 1.0,
            back_off_mm: 0.5,
            ns_rapid: true,
            type_two: true,
            tolerance_mm: 0.001,
        };
        assert_eq!(expand(&r, 1000), Err(RoughError::TooManyPockets));
    }

    /// The plain scan, level by level, that `all_stretches` must agree with.
    /// The stretches `(from, to)` of the cut axis, in the contour's order, where the contour lies
    /// deeper than `level` (the side `dir_l` points to); a stretch that begins at the contour's
    /// start begins at `start_c`, A's cut-axis position (nothing stands before the contour).
    fn deeper_stretches(pts: &[Vec3], l: usize, c: usize, level: f64, dir_l: f64, start_c: f64) -> Vec<(f64, f64)> {
        let deeper = |p: &Vec3| (p.axis(l) - level) * dir_l > 0.0;
        let cross = |p: &Vec3, q: &Vec3| {
            let (a, b) = (p.axis(l), q.axis(l));
            let u = if (b - a).abs() > 1e-12 { (level - a) / (b - a) } else { 0.0 };
            p.axis(c) + u * (q.axis(c) - p.axis(c))
        };
        let mut out = Vec::new();
        let mut open = pts.first().filter(|p| deeper(p)).map(|_| start_c);
        for w in pts.windows(2) {
            match (open, deeper(&w[0]), deeper(&w[1])) {
                (None, false, true) => open = Some(cross(&w[0], &w[1])),
                (Some(from), true, false) => {
                    out.push((from, cross(&w[0], &w[1])));
                    open = None;
                }
                _ => {}
            }
        }
        if let (Some(from), Some(p)) = (open, pts.last()) {
            out.push((from, p.axis(c)));
        }
        out
    }

    proptest::proptest! {
        /// `all_stretches` gives, bit for bit, what scanning the contour at each level gives,
        /// and `Outermost` what scanning the points in a range gives.
        #[test]
        fn one_pass_stretches_match_the_scan(
            levels in proptest::collection::vec(-30.0f64..30.0, 2..60),
            step in 0.01f64..3.0,
            dz in 0.05f64..2.0,
            start in -5.0f64..35.0,
            outward in proptest::bool::ANY,
            ranges in proptest::collection::vec((-80.0f64..10.0, -80.0f64..10.0), 1..8),
        ) {
            // Cut axis Z falling, level axis X: a zigzag contour (flats when two levels repeat).
            let pts: Vec<Vec3> = levels.iter().enumerate().map(|(i, &x)| Vec3::new((x * 4.0).round() / 4.0, 0.0, -(i as f64) * dz)).collect();
            let dir_l = if outward { 1.0 } else { -1.0 };
            let a1 = start * -dir_l;
            let level_of = |k: usize| a1 + dir_l * k as f64 * step;
            let deepest = pts.iter().map(|p| p.x).fold(a1, |m, v| if (v - m) * dir_l > 0.0 { v } else { m });
            let count = (((deepest - a1).abs() / step) as usize).min(400);
            let all = all_stretches(&pts, 0, 2, &level_of, count, dir_l, 2.0);
            for k in 1..=count {
                proptest::prop_assert_eq!(&all[k - 1], &deeper_stretches(&pts, 0, 2, level_of(k), dir_l, 2.0), "level {}", k);
            }
            let out = -dir_l;
            let table = Outermost::new(&pts, 0, 2, -1.0, out);
            for (a, b) in ranges {
                let (lo, hi) = if a < b { (a, b) } else { (b, a) };
                let scan = pts.iter().filter(|p| p.z >= lo && p.z <= hi).map(|p| p.x).reduce(|m, v| if (m - v) * out >= 0.0 { m } else { v });
                proptest::prop_assert_eq!(table.between(lo, hi), scan);
            }
        }
    }
}
