//! Involute interpolation (FANUC G02.2/G03.2; the FANUC Series 16/18-MC and 30i-MA operator's
//! manuals, "Involute interpolation"), in plane-local coordinates `(a, b)`: the plane's first and
//! second axes, turning as `crate::cycles::curve` turns. The controller interpolates the curve;
//! ncsight lays it out as chords, none further than `tol_mm` from it, made one at a time
//! (`Expansion`), so that a curve of a hundred turns holds no more memory than one of a tenth.
//!
//! The involute of a base circle (centre `c`, radius `r`) is the end of a taut string unwound
//! from it. Where the string has left the circle at the angle `θ` (its tangent point
//! `c + r (cos θ, sin θ)`), it is `r φ` long, `φ` the roll angle; the string lies along the
//! circle's tangent there, one way or the other (`side`):
//!
//! `p = c + r (cos θ, sin θ) + side · r φ (sin θ, -cos θ)`,  `θ = θ0 + side · φ`,
//!
//! `θ0` the angle where the involute starts on the circle. A point `d` from the centre has
//! `φ = sqrt(d² - r²) / r` whatever its angle: the way it turns and whether it leaves or nears
//! the circle say which of the two involutes through the start point the block follows.
//! Unwinding (`φ` growing) on `side` +1 turns counter-clockwise, on -1 clockwise; winding up
//! turns the other way.

use std::ops::ControlFlow;

use super::curve::Pt;
use super::Expansion;
use crate::motion::{ArcDir, Op, Plane, Vec3};

/// A point may be at most this many turns of the string from where its involute starts (the
/// 16/18-MC manual: "within 100 turns"; beyond, PS0242).
pub const MAX_TURNS: f64 = 100.0;

/// Why the words do not make the involute.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InvoluteError {
    /// The start (`false`) or end (`true`) point lies inside the base circle: its distance
    /// from the centre, mm.
    InsideBaseCircle { end: bool, distance_mm: f64 },
    /// The start or end point is more turns than [`MAX_TURNS`] from where the involute starts.
    TooManyTurns { end: bool, turns: f64 },
    /// The end point is not on the involute through the start point that turns this way: how
    /// far from it, mm, along the normal.
    OffTheInvolute { distance_mm: f64 },
}

/// The circle an involute is unwound from: its centre (plane-local) and radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BaseCircle {
    pub centre: Pt,
    pub radius_mm: f64,
}

/// An involute block laid out: the chords from `from` to `to`.
#[derive(Debug, Clone)]
pub struct Involute {
    from: Vec3,
    to: Vec3,
    plane: Plane,
    centre: Pt,
    radius_mm: f64,
    side: f64,
    /// The roll angles of the start and end points, and the angle where the start point's
    /// involute starts on the circle.
    roll_from: f64,
    roll_to: f64,
    base_from: f64,
    /// How far the end point's involute starts from the start point's (within the tolerance):
    /// the chords move from the one to the other as they go.
    base_shift: f64,
    chords: usize,
}

/// The roll angle of a point `distance_mm` from the centre.
fn roll_of(distance_mm: f64, radius_mm: f64) -> f64 {
    (distance_mm * distance_mm - radius_mm * radius_mm).max(0.0).sqrt() / radius_mm
}

/// Where the involute through `p` (at `roll`, on `side`) starts on the circle.
fn base_angle(p: Pt, centre: Pt, roll: f64, side: f64) -> f64 {
    let polar = (p.1 - centre.1).atan2(p.0 - centre.0);
    polar + side * roll.atan() - side * roll
}

impl Involute {
    /// The involute from `from` to `to` in `plane` of the base circle `circle` (its radius
    /// greater than 0), turning `dir`; the end point may be off the start point's
    /// involute by `tol_mm`, and no chord departs further than `chord_tol_mm` from the curve.
    /// The axis normal to the plane keeps its place (the caller refuses a helical block).
    pub fn new(from: Vec3, to: Vec3, plane: Plane, circle: BaseCircle, dir: ArcDir, tol_mm: f64, chord_tol_mm: f64) -> Result<Involute, InvoluteError> {
        let BaseCircle { centre, radius_mm } = circle;
        let (a, b, _) = plane.axes();
        let (s, e) = ((from.axis(a), from.axis(b)), (to.axis(a), to.axis(b)));
        let mut roll = [0.0; 2];
        for (i, p) in [s, e].into_iter().enumerate() {
            let distance_mm = (p.0 - centre.0).hypot(p.1 - centre.1);
            if distance_mm < radius_mm * (1.0 - 1e-12) {
                return Err(InvoluteError::InsideBaseCircle { end: i == 1, distance_mm });
            }
            roll[i] = roll_of(distance_mm, radius_mm);
            let turns = roll[i] / std::f64::consts::TAU;
            if turns > MAX_TURNS {
                return Err(InvoluteError::TooManyTurns { end: i == 1, turns });
            }
        }
        let [roll_from, roll_to] = roll;
        let unwinding = roll_to > roll_from;
        let side = if (dir == ArcDir::Ccw) == unwinding { 1.0 } else { -1.0 };
        let base_from = base_angle(s, centre, roll_from, side);
        let base_shift = (base_angle(e, centre, roll_to, side) - base_from + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
        // The involutes of one circle are parallel curves: two that start Δθ0 apart are r Δθ0
        // apart everywhere, along their common normal.
        let off_mm = radius_mm * base_shift.abs();
        let same_point = (s.0 - e.0).hypot(s.1 - e.1) <= 1e-9;
        if off_mm > tol_mm {
            return Err(InvoluteError::OffTheInvolute { distance_mm: off_mm });
        }
        // Chords of equal sag: the curve's radius of curvature at roll φ is r φ, so a chord
        // spanning Δφ sags r φ Δφ² / 8; in w = φ^1.5 the steps that sag `chord_tol_mm` are equal.
        let step_w = 1.5 * (8.0 * chord_tol_mm / radius_mm).sqrt();
        let span_w = (roll_to.powf(1.5) - roll_from.powf(1.5)).abs();
        let chords = if same_point { 0 } else { ((span_w / step_w).ceil() as usize).max(1) };
        Ok(Involute { from, to, plane, centre, radius_mm, side, roll_from, roll_to, base_from, base_shift, chords })
    }

    /// The point at `u` (0 the start, 1 the end) along the curve (by its chords' parameter).
    pub fn point_at(&self, u: f64) -> Vec3 {
        if u >= 1.0 {
            return self.to;
        }
        let (w0, w1) = (self.roll_from.powf(1.5), self.roll_to.powf(1.5));
        let roll = (w0 + (w1 - w0) * u.max(0.0)).powf(2.0 / 3.0);
        // The start point's involute turning into the end point's as the roll goes.
        let along = if (self.roll_to - self.roll_from).abs() > 0.0 { (roll - self.roll_from) / (self.roll_to - self.roll_from) } else { 0.0 };
        let theta = self.base_from + self.base_shift * along + self.side * roll;
        let (sin, cos) = theta.sin_cos();
        let r = self.radius_mm;
        let p = (self.centre.0 + r * cos + self.side * r * roll * sin, self.centre.1 + r * sin - self.side * r * roll * cos);
        let (a, b, _) = self.plane.axes();
        let mut q = self.from;
        q.set_axis(a, p.0);
        q.set_axis(b, p.1);
        q
    }

    /// The chords' end points after the start, the last one the end point exactly, in order.
    pub fn each_point(&self, sink: &mut dyn FnMut(Vec3) -> ControlFlow<()>) {
        for i in 1..=self.chords {
            // The last is at u = 1 exactly: the end point.
            if sink(self.point_at(i as f64 / self.chords as f64)).is_break() {
                return;
            }
        }
    }
}

impl Expansion for Involute {
    fn move_count(&self) -> usize {
        self.chords
    }

    fn each_op(&self, sink: &mut dyn FnMut(Op) -> ControlFlow<()>) {
        let mut at = self.from;
        self.each_point(&mut |p| {
            let op = Op::Feed { from: at, to: p, feed_mm_min: 0.0 };
            at = p;
            sink(op)
        });
    }

    fn one_interpolation(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOL: f64 = 0.001;

    fn xy(x: f64, y: f64) -> Vec3 {
        Vec3::new(x, y, 5.0)
    }

    /// The involute of the circle of radius 10 about the origin that starts at (10, 0): at
    /// roll φ on side +1 it is (10 (cos φ + φ sin φ), 10 (sin φ - φ cos φ)).
    fn on_curve(roll: f64, side: f64) -> Vec3 {
        let t = side * roll;
        xy(10.0 * (t.cos() + side * roll * t.sin()), 10.0 * (t.sin() - side * roll * t.cos()))
    }

    fn points(inv: &Involute) -> Vec<Vec3> {
        let mut v = Vec::new();
        inv.each_point(&mut |p| {
            v.push(p);
            ControlFlow::Continue(())
        });
        v
    }

    /// Each chord point on the involute (its distance from the centre gives its roll; its
    /// angle then must be the involute's), and the curve between a chord's ends within the
    /// tolerance of the chord (sampled at 50 rolls).
    fn assert_on_involute(pts: &[Vec3], start: Vec3, side: f64) {
        let mut prev = start;
        for p in pts {
            let roll = roll_of(p.x.hypot(p.y), 10.0);
            let q = on_curve(roll, side);
            assert!((q.x - p.x).abs() < 1e-9 && (q.y - p.y).abs() < 1e-9, "{p:?} is not on the involute ({q:?})");
            let roll_prev = roll_of(prev.x.hypot(prev.y), 10.0);
            let (dx, dy) = (p.x - prev.x, p.y - prev.y);
            let len2 = dx * dx + dy * dy;
            for k in 1..50 {
                let c = on_curve(roll_prev + (roll - roll_prev) * k as f64 / 50.0, side);
                let t = (((c.x - prev.x) * dx + (c.y - prev.y) * dy) / len2).clamp(0.0, 1.0);
                let off = (c.x - prev.x - t * dx).hypot(c.y - prev.y - t * dy);
                assert!(off <= TOL * 1.01, "the chord to {p:?} is {off} mm from the curve");
            }
            prev = *p;
        }
    }

    #[test]
    fn counter_clockwise_away_from_the_circle() {
        // From the involute's own start on the circle to roll 1.5 rad: G03.2 unwinds on side +1.
        let (s, e) = (on_curve(0.0, 1.0), on_curve(1.5, 1.0));
        let inv = Involute::new(s, e, Plane::XY, BaseCircle { centre: (0.0, 0.0), radius_mm: 10.0 }, ArcDir::Ccw, 0.01, TOL).unwrap();
        let pts = points(&inv);
        assert!(pts.len() > 20 && pts.len() == inv.move_count(), "{} chords", pts.len());
        assert_eq!(*pts.last().unwrap(), e);
        assert_on_involute(&pts, s, 1.0);
        // The third axis stays where it was.
        assert!(pts.iter().all(|p| p.z == 5.0));
    }

    #[test]
    fn the_four_ways() {
        // G02.2 unwinding follows side -1; G03.2 winding up side -1; G02.2 winding up side +1.
        let cases = [(ArcDir::Cw, 0.5, 2.0, -1.0), (ArcDir::Ccw, 2.0, 0.5, -1.0), (ArcDir::Cw, 2.0, 0.5, 1.0), (ArcDir::Ccw, 0.5, 2.0, 1.0)];
        for (dir, from_roll, to_roll, side) in cases {
            let (s, e) = (on_curve(from_roll, side), on_curve(to_roll, side));
            let inv = Involute::new(s, e, Plane::XY, BaseCircle { centre: (0.0, 0.0), radius_mm: 10.0 }, dir, 0.01, TOL).unwrap();
            assert_on_involute(&points(&inv), s, side);
            // The way it turns: the angle about the centre grows counter-clockwise.
            let p = inv.point_at(0.5);
            let turned = (s.x * p.y - s.y * p.x).signum();
            assert_eq!(turned > 0.0, dir == ArcDir::Ccw, "{dir:?} from {from_roll} to {to_roll}");
        }
    }

    #[test]
    fn many_turns_are_counted_not_held() {
        // Ninety turns out: the chords are counted before any is made; one chord at a time.
        let to_roll = 90.0 * std::f64::consts::TAU;
        let (s, e) = (on_curve(0.0, 1.0), on_curve(to_roll, 1.0));
        let inv = Involute::new(s, e, Plane::XY, BaseCircle { centre: (0.0, 0.0), radius_mm: 10.0 }, ArcDir::Ccw, 0.01, TOL).unwrap();
        // Δw = φ^1.5 over 1.5 sqrt(8 tol / r): 565.487^1.5 = 13,447.25, over 0.0424264:
        // 316,954.8, so 316,955 chords.
        assert_eq!(inv.move_count(), 316_955);
        let mut n = 0;
        inv.each_op(&mut |_| {
            n += 1;
            ControlFlow::Continue(())
        });
        assert_eq!(n, inv.move_count());
    }

    #[test]
    fn what_the_manual_refuses() {
        let c = (0.0, 0.0);
        let inside = Involute::new(xy(5.0, 0.0), on_curve(1.0, 1.0), Plane::XY, BaseCircle { centre: c, radius_mm: 10.0 }, ArcDir::Ccw, 0.01, TOL);
        assert!(matches!(inside, Err(InvoluteError::InsideBaseCircle { end: false, .. })));
        let far = on_curve(101.0 * std::f64::consts::TAU, 1.0);
        assert!(matches!(
            Involute::new(on_curve(1.0, 1.0), far, Plane::XY, BaseCircle { centre: c, radius_mm: 10.0 }, ArcDir::Ccw, 0.01, TOL),
            Err(InvoluteError::TooManyTurns { end: true, .. })
        ));
        // The end point as far from the centre as the curve's but 0.1 rad further round.
        let e = on_curve(2.0, 1.0);
        let (sin, cos) = 0.1f64.sin_cos();
        let turned = xy(e.x * cos - e.y * sin, e.x * sin + e.y * cos);
        let off = Involute::new(on_curve(0.5, 1.0), turned, Plane::XY, BaseCircle { centre: c, radius_mm: 10.0 }, ArcDir::Ccw, 0.01, TOL);
        // Turned 0.1 rad about the centre, it lies on the involute that starts 0.1 rad further
        // round: 10 x 0.1 = 1 mm from the start point's, along the normal.
        assert!(matches!(off, Err(InvoluteError::OffTheInvolute { distance_mm }) if (distance_mm - 1.0).abs() < 1e-9));
    }

    #[test]
    fn an_end_point_a_little_off_is_reached() {
        // 0.005 mm off, within 0.01: the chords end exactly at the end point given.
        let e = on_curve(2.0, 1.0);
        let e_off = xy(e.x + 0.003, e.y - 0.004);
        let inv = Involute::new(on_curve(0.5, 1.0), e_off, Plane::XY, BaseCircle { centre: (0.0, 0.0), radius_mm: 10.0 }, ArcDir::Ccw, 0.01, TOL).unwrap();
        assert_eq!(*points(&inv).last().unwrap(), e_off);
    }

    #[test]
    fn in_the_zx_plane() {
        // G18: a = Z, b = X. The same curve with Z for x and X for y.
        let (s, e) = (on_curve(0.2, 1.0), on_curve(1.2, 1.0));
        let zx = |p: Vec3| Vec3::new(p.y, 7.0, p.x);
        let inv = Involute::new(zx(s), zx(e), Plane::ZX, BaseCircle { centre: (0.0, 0.0), radius_mm: 10.0 }, ArcDir::Ccw, 0.01, TOL).unwrap();
        for p in points(&inv) {
            assert_eq!(p.y, 7.0);
            let roll = roll_of(p.z.hypot(p.x), 10.0);
            let q = on_curve(roll, 1.0);
            assert!((q.x - p.z).abs() < 1e-9 && (q.y - p.x).abs() < 1e-9);
        }
    }
}
