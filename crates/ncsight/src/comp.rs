//! Tool radius compensation's geometry (G41/G42; docs/reference/macro.md 10.3, docs/compensation.md), written
//! once in plane-local coordinates: the offset of a line or an arc, and what happens where two
//! compensated moves meet. Pure functions; the interpreter's stage (`interp/comp.rs`) holds a
//! move back until the next one shows the corner.
//!
//! The corner rules are FANUC's cutter compensation C as its manuals draw them: an inner corner
//! goes to the intersection of the two offset paths; an outer corner whose angle on the work is
//! 90 degrees or more goes to the intersection of the offset lines extended along the moves'
//! tangents; a sharper outer corner goes out by the radius along each move, with a straight move
//! between.

use crate::motion::{ArcDir, Op, Plane, Vec3};

/// A point or vector in the plane: (first axis, second axis) of [`Plane::axes`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct P2 {
    pub a: f64,
    pub b: f64,
}

impl P2 {
    pub const fn new(a: f64, b: f64) -> P2 {
        P2 { a, b }
    }
    pub fn plus(self, o: P2) -> P2 {
        P2::new(self.a + o.a, self.b + o.b)
    }
    pub fn minus(self, o: P2) -> P2 {
        P2::new(self.a - o.a, self.b - o.b)
    }
    pub fn scale(self, k: f64) -> P2 {
        P2::new(self.a * k, self.b * k)
    }
    pub fn dot(self, o: P2) -> f64 {
        self.a * o.a + self.b * o.b
    }
    pub fn cross(self, o: P2) -> f64 {
        self.a * o.b - self.b * o.a
    }
    pub fn len(self) -> f64 {
        self.dot(self).sqrt()
    }
    pub fn unit(self) -> P2 {
        let l = self.len();
        if l < 1e-12 {
            P2::default()
        } else {
            self.scale(1.0 / l)
        }
    }
    /// The left normal (90 degrees counter-clockwise).
    pub fn left(self) -> P2 {
        P2::new(-self.b, self.a)
    }
    pub fn dist(self, o: P2) -> f64 {
        self.minus(o).len()
    }
}

/// The plane-local point of `p`.
pub fn local(p: &Vec3, plane: Plane) -> P2 {
    let (a, b, _) = plane.axes();
    P2::new(p.axis(a), p.axis(b))
}

/// `p` with its in-plane coordinates replaced by `q` (the normal axis kept).
pub fn with_local(p: &Vec3, q: P2, plane: Plane) -> Vec3 {
    let (a, b, _) = plane.axes();
    let mut r = *p;
    r.set_axis(a, q.a);
    r.set_axis(b, q.b);
    r
}

/// The direction of imaginary tool nose `tip` from the nose centre, as (X, Z) signs, seen with
/// +X up and +Z to the right (docs/reference/macro.md 10.3: 1-4 the corners, 5-8 the sides [inferred], 0 and 9
/// the centre).
pub fn tip_direction(tip: u8) -> (f64, f64) {
    match tip {
        1 => (1.0, 1.0),
        2 => (1.0, -1.0),
        3 => (-1.0, -1.0),
        4 => (-1.0, 1.0),
        5 => (0.0, 1.0),
        6 => (1.0, 0.0),
        7 => (0.0, -1.0),
        8 => (-1.0, 0.0),
        _ => (0.0, 0.0),
    }
}

/// A programmed move in the plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Seg {
    Line { from: P2, to: P2 },
    Arc { from: P2, to: P2, center: P2, ccw: bool },
}

impl Seg {
    /// The move of a motion op in `plane` (`None` for anything else).
    pub fn of(op: &Op, plane: Plane) -> Option<Seg> {
        match op {
            Op::Rapid { from, to } | Op::Feed { from, to, .. } => Some(Seg::Line { from: local(from, plane), to: local(to, plane) }),
            Op::Arc { from, to, center, dir, .. } => {
                Some(Seg::Arc { from: local(from, plane), to: local(to, plane), center: local(center, plane), ccw: *dir == ArcDir::Ccw })
            }
            _ => None,
        }
    }

    pub fn from(&self) -> P2 {
        match *self {
            Seg::Line { from, .. } | Seg::Arc { from, .. } => from,
        }
    }

    pub fn to(&self) -> P2 {
        match *self {
            Seg::Line { to, .. } | Seg::Arc { to, .. } => to,
        }
    }

    /// The unit direction of travel where the move starts (`at_end` false) or ends.
    pub fn tangent(&self, at_end: bool) -> P2 {
        match *self {
            Seg::Line { from, to } => to.minus(from).unit(),
            Seg::Arc { from, to, center, ccw } => {
                let radial = (if at_end { to } else { from }).minus(center).unit();
                if ccw {
                    radial.left()
                } else {
                    radial.left().scale(-1.0)
                }
            }
        }
    }

    /// A move that has no length in the plane (a move along the normal axis only).
    pub fn is_point(&self) -> bool {
        matches!(self, Seg::Line { from, to } if from.dist(*to) < 1e-9)
    }
}

/// Why a compensated path cannot be made (FANUC 0 P/S alarm numbers in `interp/comp.rs`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CompError {
    /// The offset paths of an inner corner do not meet (033 NO SOLUTION AT CRC).
    NoIntersection,
    /// The compensated move runs against the programmed one (041 INTERFERENCE IN CRC).
    Interference,
    /// An arc smaller than the radius on its inner side (038 / 041).
    ArcTooSmall,
}

/// What a corner asks for between two moves (GSK980TDi help text, chamfer function: L, D;
/// FANUC 0-T ,C ,R).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CornerCut {
    /// A chamfer whose ends lie this far from the corner (a chord on an arc).
    FromCorner(f64),
    /// A chamfer this long (its ends equally far from the corner).
    Length(f64),
    /// An arc of this radius tangent to both moves.
    Round(f64),
}

/// Where a corner cut leaves the first move and joins the second, and for a round its centre
/// and whether it turns counter-clockwise.
pub type CornerPoints = (P2, P2, Option<(P2, bool)>);

/// The angle swept from `s` to `e` about `center` in the arc's direction, 0..2 pi.
fn arc_sweep(center: P2, ccw: bool, s: P2, e: P2) -> f64 {
    let (a0, a1) = ((s.b - center.b).atan2(s.a - center.a), (e.b - center.b).atan2(e.a - center.a));
    let d = if ccw { a1 - a0 } else { a0 - a1 };
    d.rem_euclid(std::f64::consts::TAU)
}

/// The point of `seg` a chord `t` from its end (`back`) or its start; `None` past the move.
fn along(seg: &Seg, t: f64, back: bool) -> Option<P2> {
    match *seg {
        Seg::Line { from, to } => {
            let u = to.minus(from).unit();
            (t <= from.dist(to) + 1e-9).then(|| if back { to.minus(u.scale(t)) } else { from.plus(u.scale(t)) })
        }
        Seg::Arc { from, to, center, ccw } => {
            let r = from.dist(center);
            if t > 2.0 * r {
                return None;
            }
            let delta = 2.0 * (t / (2.0 * r)).asin();
            if delta > arc_sweep(center, ccw, from, to) + 1e-12 {
                return None;
            }
            // Forward on a counter-clockwise arc turns positively.
            let (p, turn) = if back { (to, if ccw { -delta } else { delta }) } else { (from, if ccw { delta } else { -delta }) };
            let v = p.minus(center);
            let (sin, cos) = turn.sin_cos();
            Some(center.plus(P2::new(v.a * cos - v.b * sin, v.a * sin + v.b * cos)))
        }
    }
}

/// The longest chord from an end of `seg` that stays on it.
fn max_chord(seg: &Seg) -> f64 {
    match *seg {
        Seg::Line { from, to } => from.dist(to),
        Seg::Arc { from, to, center, ccw } => {
            let (r, sweep) = (from.dist(center), arc_sweep(center, ccw, from, to));
            if sweep >= std::f64::consts::PI {
                2.0 * r
            } else {
                2.0 * r * (sweep / 2.0).sin()
            }
        }
    }
}

/// The point of `seg`'s line or circle nearest `c` (the foot of the perpendicular; on an arc's
/// circle, along the ray from its centre), and whether it lies on the move.
fn foot(seg: &Seg, c: P2) -> (P2, bool) {
    match *seg {
        Seg::Line { from, to } => {
            let u = to.minus(from).unit();
            let k = c.minus(from).dot(u);
            (from.plus(u.scale(k)), k >= -1e-9 && k <= from.dist(to) + 1e-9)
        }
        Seg::Arc { from, to, center, ccw } => {
            let q = center.plus(c.minus(center).unit().scale(from.dist(center)));
            let whole = arc_sweep(center, ccw, from, to);
            let at = arc_sweep(center, ccw, from, q);
            // A point within the tolerance of an end is that end (not a turn short of a circle).
            if at >= std::f64::consts::TAU - 1e-9 {
                (from, true)
            } else if at > whole {
                (to, at <= whole + 1e-9)
            } else {
                (q, true)
            }
        }
    }
}

/// A chamfer or corner arc between `first` (from where it starts now to the corner) and
/// `second` (from the corner), each a line or an arc: where it leaves the first and joins the
/// second. `Ok(None)` when the moves go on in one direction (case 1: no corner); `Err` when it
/// needs more of a move than the move has (case 2), with how far from the corner it reaches.
pub fn corner_cut(first: &Seg, second: &Seg, cut: CornerCut) -> Result<Option<CornerPoints>, f64> {
    let p = first.to();
    let (u1, u2) = (first.tangent(true), second.tangent(false));
    let (sin, cos) = (u1.cross(u2), u1.dot(u2));
    if sin.abs() < TANGENT_RAD && cos > 0.0 {
        return Ok(None);
    }
    let lines = matches!((first, second), (Seg::Line { .. }, Seg::Line { .. }));
    let ccw = sin > 0.0;
    let points = match cut {
        CornerCut::Round(d) if lines => {
            // Tangent to both: D tan(half the turn) from the corner.
            let t = d * sin.abs() / (1.0 + cos);
            let a = p.minus(u1.scale(t));
            let n = if ccw { u1.left() } else { u1.left().scale(-1.0) };
            (along(first, t, true).ok_or(t)?, along(second, t, false).ok_or(t)?, Some((a.plus(n.scale(d)), ccw)))
        }
        CornerCut::Round(d) => {
            // The centre lies D inside both moves: where their offsets toward the turn meet.
            let side = if ccw { 1.0 } else { -1.0 };
            let centre = corner(first, second, side, d).map(|c| c.first_end).map_err(|_| f64::INFINITY)?;
            let ((a, a_on), (b, b_on)) = (foot(first, centre), foot(second, centre));
            if !(a_on && b_on) {
                return Err(a.dist(p).max(b.dist(p)));
            }
            (a, b, Some((centre, ccw)))
        }
        CornerCut::FromCorner(t) => (along(first, t, true).ok_or(t)?, along(second, t, false).ok_or(t)?, None),
        CornerCut::Length(l) if lines => {
            let t = l / u1.plus(u2).len();
            if !t.is_finite() {
                return Err(t);
            }
            (along(first, t, true).ok_or(t)?, along(second, t, false).ok_or(t)?, None)
        }
        CornerCut::Length(l) => {
            // Equal chords from the corner whose ends lie `l` apart: the shortest such chord.
            // The gap need not grow all the way (an arc may curl back toward the other move):
            // stepped out from the corner to the first chord whose gap reaches `l`, then halved.
            let gap = |t: f64| match (along(first, t, true), along(second, t, false)) {
                (Some(a), Some(b)) => a.dist(b),
                _ => f64::NEG_INFINITY,
            };
            let longest = max_chord(first).min(max_chord(second)) * (1.0 - 1e-12);
            const STEPS: usize = 256;
            let Some(k) = (1..=STEPS).find(|k| gap(longest * *k as f64 / STEPS as f64) >= l) else {
                return Err(longest);
            };
            let (mut lo, mut hi) = (longest * (k - 1) as f64 / STEPS as f64, longest * k as f64 / STEPS as f64);
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if gap(mid) < l {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let t = 0.5 * (lo + hi);
            (along(first, t, true).ok_or(t)?, along(second, t, false).ok_or(t)?, None)
        }
    };
    Ok(Some(points))
}

/// Two moves whose directions differ by less than this (radians) meet without a corner.
pub const TANGENT_RAD: f64 = 1e-4;

/// Lines as a drawing dimensions them (GSK980TDi help text, angle programming; FANUC 0-T direct
/// drawing dimension programming): an angle from the plane's first axis toward its second
/// (counter-clockwise: from +Z toward +X in G18), in degrees.
pub fn direction(angle_deg: f64) -> P2 {
    let r = angle_deg.to_radians();
    P2::new(r.cos(), r.sin())
}

/// How far from parallel a line must be to meet the coordinate or the line it is given with:
/// 1 degree (GSK980TDi help text, angle programming notes 2-5).
pub const DRAWING_TOLERANCE_DEG: f64 = 1.0;

/// Why a line given by its angle has no end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DrawingError {
    /// The line runs within the tolerance of parallel to the other axis (a line along Z never
    /// reaches the X given).
    AlongAxis,
    /// The two lines are within the tolerance of parallel.
    Parallel,
}

/// Angle between two directions, as lines (0..=90 degrees).
fn line_angle_deg(u: P2, v: P2) -> f64 {
    u.cross(v).abs().atan2(u.dot(v).abs()).to_degrees()
}

/// The end of the line through `start` at `angle_deg` where its first-axis coordinate is `a`
/// or its second-axis one is `b` (one of the two; the line runs either way along its angle).
pub fn end_by_angle(start: P2, angle_deg: f64, a: Option<f64>, b: Option<f64>) -> Result<P2, DrawingError> {
    let u = direction(angle_deg);
    let (axis, along, to) = match (a, b) {
        (Some(a), _) => (P2::new(0.0, 1.0), u.a, a - start.a),
        (None, Some(b)) => (P2::new(1.0, 0.0), u.b, b - start.b),
        (None, None) => return Ok(start),
    };
    // Within a degree of the other axis: the coordinate given is (nearly) never reached.
    if line_angle_deg(u, axis) < DRAWING_TOLERANCE_DEG {
        return Err(DrawingError::AlongAxis);
    }
    Ok(start.plus(u.scale(to / along)))
}

/// Where the line from `start` at `first_deg` meets the line through `end` at `second_deg`.
pub fn meet(start: P2, first_deg: f64, end: P2, second_deg: f64) -> Result<P2, DrawingError> {
    let (u, v) = (direction(first_deg), direction(second_deg));
    if line_angle_deg(u, v) < DRAWING_TOLERANCE_DEG {
        return Err(DrawingError::Parallel);
    }
    line_line(start, u, end, v).ok_or(DrawingError::Parallel)
}

/// The offset vector of length `r` on `side` (+1 left: G41, -1 right: G42) of a move's start or
/// end.
pub fn vector(seg: &Seg, at_end: bool, side: f64, r: f64) -> P2 {
    seg.tangent(at_end).left().scale(side * r)
}

/// What the tool does where two compensated moves meet: where the first ends, the points that
/// straight moves go to between them (outer corners of arcs), where the second starts (a
/// straight move joins the last of these to it where they differ).
#[derive(Debug, Clone, PartialEq)]
pub struct Corner {
    pub first_end: P2,
    pub between: Vec<P2>,
    pub second_start: P2,
}

/// The offset circle of an arc (its radius on the compensated side, `None` when it vanishes).
fn offset_radius(seg: &Seg, side: f64, r: f64) -> Option<(P2, f64)> {
    match *seg {
        Seg::Arc { from, center, ccw, .. } => {
            // The left normal of a counter-clockwise arc points to its centre.
            let inward = if ccw { side } else { -side };
            let rr = from.dist(center) - inward * r;
            (rr > 1e-9).then_some((center, rr))
        }
        Seg::Line { .. } => None,
    }
}

/// Intersections of the line through `p` along `d` with the circle (`c`, `rr`).
fn line_circle(p: P2, d: P2, c: P2, rr: f64) -> Vec<P2> {
    let f = p.minus(c);
    let (a, b, cc) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - rr * rr);
    let disc = b * b - 4.0 * a * cc;
    if disc < -1e-12 || a < 1e-18 {
        return Vec::new();
    }
    let s = disc.max(0.0).sqrt();
    [(-b - s) / (2.0 * a), (-b + s) / (2.0 * a)].iter().map(|t| p.plus(d.scale(*t))).collect()
}

/// Intersections of two circles.
fn circle_circle(c1: P2, r1: f64, c2: P2, r2: f64) -> Vec<P2> {
    let d = c2.minus(c1);
    let dist = d.len();
    if dist < 1e-12 || dist > r1 + r2 + 1e-9 || dist < (r1 - r2).abs() - 1e-9 {
        return Vec::new();
    }
    let a = (r1 * r1 - r2 * r2 + dist * dist) / (2.0 * dist);
    let h = (r1 * r1 - a * a).max(0.0).sqrt();
    let m = c1.plus(d.scale(a / dist));
    let n = d.unit().left().scale(h);
    vec![m.plus(n), m.minus(n)]
}

/// Intersection of the lines through `p1` along `d1` and `p2` along `d2`.
fn line_line(p1: P2, d1: P2, p2: P2, d2: P2) -> Option<P2> {
    let den = d1.cross(d2);
    if den.abs() < 1e-12 {
        return None;
    }
    let t = p2.minus(p1).cross(d2) / den;
    Some(p1.plus(d1.scale(t)))
}

/// The corner between `first` and `second` (which starts where `first` ends), compensated by
/// `r` on `side`.
pub fn corner(first: &Seg, second: &Seg, side: f64, r: f64) -> Result<Corner, CompError> {
    let p = first.to();
    let (d1, d2) = (first.tangent(true), second.tangent(false));
    let (v1, v2) = (vector(first, true, side, r), vector(second, false, side, r));
    let turn = d1.cross(d2);
    // Tangent within 0.0001 rad (a programme's 4 decimals put a tangent arc's ends this far
    // off): no corner; the arc's side of the join is kept exact, the line's moves by at most
    // r x 0.0001.
    let tangent = turn.abs() < TANGENT_RAD && d1.dot(d2) > 0.0;
    if tangent || r == 0.0 {
        let q = if matches!(second, Seg::Arc { .. }) { p.plus(v2) } else { p.plus(v1) };
        return Ok(Corner { first_end: q, between: Vec::new(), second_start: q });
    }
    // The path turns toward the compensated side: an inner corner.
    let inner = turn * side > 0.0;
    if inner {
        let candidates = match (first, second) {
            (Seg::Line { .. }, Seg::Line { .. }) => line_line(p.plus(v1), d1, p.plus(v2), d2).into_iter().collect(),
            (Seg::Line { .. }, Seg::Arc { .. }) => match offset_radius(second, side, r) {
                Some((c, rr)) => line_circle(p.plus(v1), d1, c, rr),
                None => return Err(CompError::ArcTooSmall),
            },
            (Seg::Arc { .. }, Seg::Line { .. }) => match offset_radius(first, side, r) {
                Some((c, rr)) => line_circle(p.plus(v2), d2, c, rr),
                None => return Err(CompError::ArcTooSmall),
            },
            (Seg::Arc { .. }, Seg::Arc { .. }) => match (offset_radius(first, side, r), offset_radius(second, side, r)) {
                (Some((c1, r1)), Some((c2, r2))) => circle_circle(c1, r1, c2, r2),
                _ => return Err(CompError::ArcTooSmall),
            },
        };
        // The intersection nearest the corner (the other lies across the path).
        let target = p.plus(v1.plus(v2).scale(0.5));
        let q = candidates.into_iter().min_by(|a, b| a.dist(target).total_cmp(&b.dist(target))).ok_or(CompError::NoIntersection)?;
        return Ok(Corner { first_end: q, between: Vec::new(), second_start: q });
    }
    // Outer corner. The angle on the work side is 90 degrees or more when the moves' directions
    // differ by 90 degrees or less: the offsets extended along the tangents meet at q. Sharper:
    // out by r along the first move (a), in by r against the second (b). A line is extended to
    // its point; an arc ends (starts) perpendicular and a straight move joins it.
    let (e1, s2) = (p.plus(v1), p.plus(v2));
    let (out_pt, in_pt) = if d1.dot(d2) >= 0.0 {
        let q = line_line(e1, d1, s2, d2).unwrap_or(e1);
        (q, q)
    } else {
        (e1.plus(d1.scale(r)), s2.minus(d2.scale(r)))
    };
    let first_is_line = matches!(first, Seg::Line { .. });
    let second_is_line = matches!(second, Seg::Line { .. });
    let first_end = if first_is_line { out_pt } else { e1 };
    let second_start = if second_is_line { in_pt } else { s2 };
    let mut between = Vec::new();
    if !first_is_line {
        between.push(out_pt);
    }
    if !second_is_line && (between.last() != Some(&in_pt)) && in_pt.dist(first_end) > 1e-12 {
        between.push(in_pt);
    }
    Ok(Corner { first_end, between, second_start })
}

/// The compensated form of `seg` from `start` to `end` (an arc keeps its centre); an error when
/// it runs against the programmed move (FANUC's interference check).
pub fn offset(seg: &Seg, start: P2, end: P2, side: f64, r: f64) -> Result<Seg, CompError> {
    match *seg {
        Seg::Line { from, to } => {
            let (prog, comp) = (to.minus(from), end.minus(start));
            if prog.len() > 1e-9 && comp.len() > 1e-9 && prog.dot(comp) < 0.0 {
                return Err(CompError::Interference);
            }
            Ok(Seg::Line { from: start, to: end })
        }
        Seg::Arc { from, to, center, ccw } => {
            if offset_radius(seg, side, r).is_none() {
                return Err(CompError::ArcTooSmall);
            }
            let sweep = |s: P2, e: P2| arc_sweep(center, ccw, s, e);
            // Corners only shorten an arc (an outer one ends it perpendicular, as programmed):
            // its start moves forward by a, its end back by b. When a + b is more than the
            // programmed sweep the two cross: the compensated arc would run backwards. (A
            // full circle keeps its sweep.)
            let prog = sweep(from, to);
            let (a, b) = (sweep(from, start), sweep(end, to));
            // A move of a few micrometres backwards reads as almost a full turn: as 0.
            let fwd = |x: f64| if x > std::f64::consts::PI * 1.5 { 0.0 } else { x };
            if prog > 1e-9 && prog < std::f64::consts::TAU - 1e-9 && fwd(a) + fwd(b) > prog + 1e-9 {
                return Err(CompError::Interference);
            }
            Ok(Seg::Arc { from: start, to: end, center, ccw })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: P2, b: P2) -> bool {
        a.dist(b) < 1e-9
    }

    #[test]
    fn inner_corner_of_two_lines_is_their_offsets_intersection() {
        // Along +a then turning left (+b), tool on the left (G41): an inner corner.
        let l1 = Seg::Line { from: P2::new(0.0, 0.0), to: P2::new(10.0, 0.0) };
        let l2 = Seg::Line { from: P2::new(10.0, 0.0), to: P2::new(10.0, 10.0) };
        let c = corner(&l1, &l2, 1.0, 1.0).unwrap();
        assert!(close(c.first_end, P2::new(9.0, 1.0)) && close(c.second_start, P2::new(9.0, 1.0)) && c.between.is_empty());
    }

    #[test]
    fn outer_right_angle_goes_to_the_extended_offsets() {
        // The same turn with the tool on the right (G42): an outer 90-degree corner.
        let l1 = Seg::Line { from: P2::new(0.0, 0.0), to: P2::new(10.0, 0.0) };
        let l2 = Seg::Line { from: P2::new(10.0, 0.0), to: P2::new(10.0, 10.0) };
        let c = corner(&l1, &l2, -1.0, 1.0).unwrap();
        assert!(close(c.first_end, P2::new(11.0, -1.0)) && close(c.second_start, P2::new(11.0, -1.0)), "{c:?}");
    }

    #[test]
    fn sharp_outer_corner_goes_out_by_the_radius_on_each_move() {
        // Along +a, then back at 135 degrees: the work-side angle is 45 degrees.
        let l1 = Seg::Line { from: P2::new(0.0, 0.0), to: P2::new(10.0, 0.0) };
        let l2 = Seg::Line { from: P2::new(10.0, 0.0), to: P2::new(0.0, 10.0) };
        let c = corner(&l1, &l2, -1.0, 1.0).unwrap();
        let s = 0.5f64.sqrt();
        assert!(close(c.first_end, P2::new(11.0, -1.0)), "{c:?}");
        // Second's right normal is (s, s); back along it by r.
        assert!(close(c.second_start, P2::new(10.0 + s + s, s - s)), "{c:?}");
        assert_eq!(c.between.len(), 0, "the stage joins first_end and second_start with one move");
    }

    #[test]
    fn arc_offset_radius_and_interference() {
        // A counter-clockwise arc of radius 5 with the tool on its left (inside): radius 4.
        let arc = Seg::Arc { from: P2::new(5.0, 0.0), to: P2::new(0.0, 5.0), center: P2::new(0.0, 0.0), ccw: true };
        assert_eq!(offset_radius(&arc, 1.0, 1.0).unwrap().1, 4.0);
        assert_eq!(offset_radius(&arc, 1.0, 6.0), None);
        assert_eq!(
            offset(&arc, P2::new(4.0, 0.0), P2::new(0.0, 4.0), 1.0, 1.0).unwrap(),
            Seg::Arc { from: P2::new(4.0, 0.0), to: P2::new(0.0, 4.0), center: P2::new(0.0, 0.0), ccw: true }
        );
        // A 270-degree arc whose shortened ends cross: its start forward to 300 degrees, its end
        // back to 200 degrees (from 90 and 0 = 360).
        let long = Seg::Arc { from: P2::new(0.0, 5.0), to: P2::new(5.0, 0.0), center: P2::new(0.0, 0.0), ccw: true };
        let at = |deg: f64| P2::new(4.0 * deg.to_radians().cos(), 4.0 * deg.to_radians().sin());
        assert_eq!(offset(&long, at(300.0), at(200.0), 1.0, 1.0), Err(CompError::Interference));
        assert!(offset(&long, at(100.0), at(350.0), 1.0, 1.0).is_ok());
        let short = Seg::Line { from: P2::new(0.0, 0.0), to: P2::new(1.0, 0.0) };
        assert_eq!(offset(&short, P2::new(2.0, 1.0), P2::new(1.5, 1.0), 1.0, 1.0), Err(CompError::Interference));
    }

    #[test]
    fn line_into_a_tangent_arc_has_no_corner() {
        let l = Seg::Line { from: P2::new(-10.0, -5.0), to: P2::new(0.0, -5.0) };
        let arc = Seg::Arc { from: P2::new(0.0, -5.0), to: P2::new(5.0, 0.0), center: P2::new(0.0, 0.0), ccw: true };
        let c = corner(&l, &arc, 1.0, 1.0).unwrap();
        assert!(close(c.first_end, P2::new(0.0, -4.0)) && close(c.second_start, P2::new(0.0, -4.0)));
    }
}

/// A whole path compensated at once (a G71-G73 contour on FANUC, which roughs along the
/// compensated finishing shape): the first move is the start-up from its start (type A: it
/// ends perpendicular to the second move), the corners as [`corner`], the last move ends
/// perpendicular (the cancel). Positions are the points the controller positions: the nose
/// centre plus `tip`. Moves of no length in the plane are left out.
pub fn path(ops: &[Op], plane: Plane, side: f64, r: f64, tip: Vec3) -> Result<Vec<Op>, CompError> {
    let segs: Vec<(usize, Seg)> = ops.iter().enumerate().filter_map(|(i, op)| Seg::of(op, plane).filter(|s| !s.is_point()).map(|s| (i, s))).collect();
    if segs.len() < 2 || r == 0.0 {
        return Ok(ops.to_vec());
    }
    let feed_of = |op: &Op| match op {
        Op::Feed { feed_mm_min, .. } | Op::Arc { feed_mm_min, .. } => Some(*feed_mm_min),
        _ => None,
    };
    let place = |base: &Vec3, p: P2| with_local(base, p, plane) + tip;
    let mut out = Vec::with_capacity(ops.len() + 4);
    // The start-up begins where the tool stands: its controlled point is the programmed start.
    let first = &ops[segs[0].0];
    let mut at = local(&(first.start_point().unwrap_or_default() - tip), plane);
    for (k, (i, seg)) in segs.iter().enumerate() {
        let op = &ops[*i];
        let (end, between, next_start) = if k == 0 {
            let e = segs[1].1.from().plus(vector(&segs[1].1, false, side, r));
            (e, Vec::new(), e)
        } else if k + 1 == segs.len() {
            let e = seg.to().plus(vector(seg, true, side, r));
            (e, Vec::new(), e)
        } else {
            let c = corner(seg, &segs[k + 1].1, side, r)?;
            (c.first_end, c.between, c.second_start)
        };
        // The start-up and the cancel leg are not checked (they are not offset moves: a short
        // last move in a cycle ends perpendicular wherever that is).
        if k > 0 && k + 1 < segs.len() {
            offset(seg, at, end, side, r)?;
        }
        let (from3, to3) = (op.start_point().unwrap_or_default(), op.end_point().unwrap_or_default());
        out.push(match *op {
            Op::Rapid { .. } => Op::Rapid { from: place(&from3, at), to: place(&to3, end) },
            Op::Feed { feed_mm_min, .. } => Op::Feed { from: place(&from3, at), to: place(&to3, end), feed_mm_min },
            Op::Arc { center, plane, dir, feed_mm_min, .. } => {
                Op::Arc { from: place(&from3, at), to: place(&to3, end), center: center + tip, plane, dir, feed_mm_min }
            }
            other => other,
        });
        let mut p = end;
        let next_feed = segs.get(k + 1).and_then(|(j, _)| feed_of(&ops[*j]));
        for q in between.into_iter().chain(std::iter::once(next_start)) {
            if q.dist(p) > 1e-9 {
                let (a, b) = (place(&to3, p), place(&to3, q));
                out.push(match next_feed {
                    Some(f) => Op::Feed { from: a, to: b, feed_mm_min: f },
                    None => Op::Rapid { from: a, to: b },
                });
            }
            p = q;
        }
        at = next_start;
    }
    Ok(out)
}
