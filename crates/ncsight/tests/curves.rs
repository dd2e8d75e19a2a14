//! Property tests of the curves the GSK980TDi cuts (G05, G06.2/G06.3, G07.2/G07.3), of the FANUC
//! involute (G02.2/G03.2) and of
//! the pieces that record polar coordinate interpolation (G12.1): for any data the functions
//! accept, every point they give lies on the curve, the last is the end point, and the count
//! stays bounded; whatever they are given, they do not panic.

use ncsight::cycles::curve::{ellipse, parabola, three_point_arc, MAX_CHORDS};
use ncsight::cycles::involute::{BaseCircle, Involute};
use ncsight::cycles::polar::{pieces, MAX_PIECES};
use ncsight::cycles::Expansion;
use ncsight::motion::ArcDir;
use ncsight::motion::{Op, Plane, Vec3};
use proptest::prelude::*;

fn dir() -> impl Strategy<Value = ArcDir> {
    prop_oneof![Just(ArcDir::Cw), Just(ArcDir::Ccw)]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, .. ProptestConfig::default() })]


    /// An involute between two of its own points, either way round, unwinding or winding up:
    /// laid out, every chord end lies on it, the last is the end point, the count is what it
    /// says.
    #[test]
    fn involute_chords_lie_on_the_curve(
        rolls in (0.0..20.0f64, 0.0..20.0f64), side in prop_oneof![Just(1.0f64), Just(-1.0f64)],
        base_deg in -180.0..180.0f64, radius in 0.5..50.0f64, centre in (-100.0..100.0f64, -100.0..100.0f64),
    ) {
        let (a, b) = rolls;
        prop_assume!((a - b).abs() > 1e-3);
        let base = base_deg.to_radians();
        let at = |roll: f64| {
            let t = base + side * roll;
            Vec3::new(centre.0 + radius * (t.cos() + side * roll * t.sin()), centre.1 + radius * (t.sin() - side * roll * t.cos()), 0.0)
        };
        // Unwinding on side +1 and winding up on -1 turn counter-clockwise.
        let dir = if (side > 0.0) == (b > a) { ArcDir::Ccw } else { ArcDir::Cw };
        let inv = Involute::new(at(a), at(b), Plane::XY, BaseCircle { centre, radius_mm: radius }, dir, 0.01, 0.001).unwrap();
        let mut ends = Vec::new();
        inv.each_op(&mut |op| {
            if let Op::Feed { to, .. } = op {
                ends.push(to);
            }
            std::ops::ControlFlow::Continue(())
        });
        prop_assert_eq!(ends.len(), inv.move_count());
        prop_assert_eq!(*ends.last().unwrap(), at(b));
        for p in &ends {
            let d = (p.x - centre.0).hypot(p.y - centre.1);
            let roll = (d * d - radius * radius).max(0.0).sqrt() / radius;
            let q = at(roll);
            prop_assert!((q.x - p.x).hypot(q.y - p.y) <= 1e-6 * d.max(1.0), "{:?} off the involute ({:?})", p, q);
        }
    }

    /// Whatever it is given, the involute does not panic, and a lay-out it accepts ends at the
    /// end point.
    #[test]
    fn involute_never_panics(s in (-1e3..1e3f64, -1e3..1e3f64), e in (-1e3..1e3f64, -1e3..1e3f64), c in (-1e3..1e3f64, -1e3..1e3f64), radius in 1e-6..1e3f64, dir in dir()) {
        let (from, to) = (Vec3::new(s.0, s.1, 0.0), Vec3::new(e.0, e.1, 0.0));
        if let Ok(inv) = Involute::new(from, to, Plane::XY, BaseCircle { centre: c, radius_mm: radius }, dir, 0.01, 0.001) {
            if inv.move_count() > 0 && inv.move_count() < 100_000 {
                let mut last = from;
                inv.each_op(&mut |op| {
                    if let Op::Feed { to, .. } = op {
                        last = to;
                    }
                    std::ops::ControlFlow::Continue(())
                });
                prop_assert_eq!(last, to);
            }
        }
    }

    /// The centre of a three-point arc is as far from all three points.
    #[test]
    fn three_point_centre_is_equidistant(s in (-100.0..100.0f64, -100.0..100.0f64), m in (-100.0..100.0f64, -100.0..100.0f64), e in (-100.0..100.0f64, -100.0..100.0f64)) {
        if let Ok((c, _)) = three_point_arc(s, m, e) {
            let d = |p: (f64, f64)| (p.0 - c.0).hypot(p.1 - c.1);
            let r = d(s);
            prop_assert!((d(m) - r).abs() <= 1e-6 * r.max(1.0), "{s:?} {m:?} {e:?} {c:?}");
            prop_assert!((d(e) - r).abs() <= 1e-6 * r.max(1.0));
        }
    }

    /// An ellipse through a point on it: every chord end lies on the same ellipse (centre,
    /// half axes, tilt), the last one is the end, and there are at most MAX_CHORDS.
    #[test]
    fn ellipse_points_lie_on_the_ellipse(a in 0.5..50.0f64, b in 0.5..50.0f64, tilt in 0.0..6.28f64, t0 in 0.0..6.28f64, sweep in 0.05..3.1f64, d in dir(), cx in -50.0..50.0f64, cy in -50.0..50.0f64) {
        // Points of the ellipse at angles t0 and t0 +- sweep (the way d turns), in the frame
        // whose first axis is at `tilt` turned the Cw way.
        let (ux, uy) = (tilt.cos(), -tilt.sin());
        let (vx, vy) = (-uy, ux);
        let at = |t: f64| (cx + a * t.cos() * ux + b * t.sin() * vx, cy + a * t.cos() * uy + b * t.sin() * vy);
        let t1 = if d == ArcDir::Ccw { t0 + sweep } else { t0 - sweep };
        let (s, e) = (at(t0), at(t1));
        let pts = ellipse(s, e, a, b, tilt, d, 0.001).unwrap();
        prop_assert!(!pts.is_empty() && pts.len() <= MAX_CHORDS);
        prop_assert_eq!(*pts.last().unwrap(), e);
        for p in &pts {
            let (x, y) = (p.0 - cx, p.1 - cy);
            let (u, v) = (x * ux + y * uy, x * vx + y * vy);
            prop_assert!((u * u / (a * a) + v * v / (b * b) - 1.0).abs() < 1e-6, "{p:?}");
        }
    }

    /// Whatever the numbers, the curves give a result or an error, in bounded size.
    #[test]
    fn curves_never_panic(s in (-1e6..1e6f64, -1e6..1e6f64), e in (-1e6..1e6f64, -1e6..1e6f64), a in 1e-6..1e6f64, b in 1e-6..1e6f64, p in 1e-6..1e6f64, tilt in -10.0..10.0f64, d in dir()) {
        if let Ok(pts) = ellipse(s, e, a, b, tilt, d, 0.001) {
            prop_assert!(pts.len() <= MAX_CHORDS);
        }
        if let Ok(pts) = parabola(s, e, p, tilt, d, 0.001) {
            prop_assert!(pts.len() <= MAX_CHORDS);
            prop_assert!(pts.iter().all(|q| q.0.is_finite() && q.1.is_finite()));
        }
    }

    /// Polar pieces of a straight line: each end lies on the line, the path lengths add up, and
    /// there are at most MAX_PIECES.
    #[test]
    fn polar_pieces_follow_the_line(x0 in -30.0..30.0f64, c0 in -30.0..30.0f64, x1 in -30.0..30.0f64, c1 in -30.0..30.0f64) {
        let len = (x1 - x0).hypot(c1 - c0);
        prop_assume!(len > 1e-3 && x0.hypot(c0) > 1e-3);
        let at = |u: f64| (x0 + (x1 - x0) * u, c0 + (c1 - c0) * u, 0.0);
        let start = c0.atan2(x0).to_degrees();
        let ps = pieces(&at, len, 0.0, start, 0.001);
        prop_assert!(!ps.is_empty() && ps.len() <= MAX_PIECES);
        prop_assert!((ps.iter().map(|q| q.path_mm).sum::<f64>() - len).abs() < 1e-6);
        for q in &ps {
            let (x, c) = (q.radius_mm * q.angle_deg.to_radians().cos(), q.radius_mm * q.angle_deg.to_radians().sin());
            // Distance from the line through (x0, c0) along the move.
            let dist = ((x - x0) * (c1 - c0) - (c - c0) * (x1 - x0)).abs() / len;
            prop_assert!(dist < 1e-6, "{q:?}");
        }
    }
}
