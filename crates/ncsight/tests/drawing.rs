//! Property tests of the lines a drawing dimensions by their angle (docs/commands/drawing.md):
//! for any start, angle and coordinate the functions accept, the end lies on the line and has
//! the coordinate given; two lines that meet, meet on both; what they refuse is within the
//! 1-degree tolerance of the notes.

use ncsight::comp::{corner_cut, direction, end_by_angle, meet, CornerCut, Seg, DRAWING_TOLERANCE_DEG, P2};
use proptest::prelude::*;

/// How far `p` is from the line through `s` along `u` (a unit vector).
fn off_line(p: P2, s: P2, u: P2) -> f64 {
    p.minus(s).cross(u).abs()
}

/// The angle between two lines, 0..=90 degrees.
fn between(a_deg: f64, b_deg: f64) -> f64 {
    let d = (a_deg - b_deg).rem_euclid(180.0);
    d.min(180.0 - d)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, .. ProptestConfig::default() })]

    #[test]
    fn the_end_has_the_coordinate_and_lies_on_the_line(s in (-500.0..500.0f64, -500.0..500.0f64), angle in -720.0..720.0f64, c in -500.0..500.0f64, first in any::<bool>()) {
        let s = P2::new(s.0, s.1);
        let (a, b) = if first { (Some(c), None) } else { (None, Some(c)) };
        // The axis the coordinate is not on: the line must cross it by more than the tolerance.
        let axis_deg = if first { 90.0 } else { 0.0 };
        match end_by_angle(s, angle, a, b) {
            Ok(e) => {
                prop_assert!(between(angle, axis_deg) >= DRAWING_TOLERANCE_DEG - 1e-9);
                let got = if first { e.a } else { e.b };
                prop_assert!((got - c).abs() < 1e-6);
                prop_assert!(off_line(e, s, direction(angle)) < 1e-6 * (1.0 + e.dist(s)));
            }
            Err(_) => prop_assert!(between(angle, axis_deg) < DRAWING_TOLERANCE_DEG + 1e-9),
        }
    }

    #[test]
    fn two_lines_meet_on_both(s in (-500.0..500.0f64, -500.0..500.0f64), e in (-500.0..500.0f64, -500.0..500.0f64), a1 in -360.0..360.0f64, a2 in -360.0..360.0f64) {
        let (s, e) = (P2::new(s.0, s.1), P2::new(e.0, e.1));
        match meet(s, a1, e, a2) {
            Ok(p) => {
                prop_assert!(between(a1, a2) >= DRAWING_TOLERANCE_DEG - 1e-9);
                let scale = 1.0 + p.dist(s) + p.dist(e);
                prop_assert!(off_line(p, s, direction(a1)) < 1e-7 * scale, "{p:?}");
                prop_assert!(off_line(p, e, direction(a2)) < 1e-7 * scale, "{p:?}");
            }
            Err(_) => prop_assert!(between(a1, a2) < DRAWING_TOLERANCE_DEG + 1e-9),
        }
    }
}

/// A move from `s`: a line to `e`, or an arc to `e` about a centre `k` times the half chord
/// off the chord's middle (either side), turning either way.
fn seg(s: P2, e: P2, arc: Option<(f64, bool)>) -> Seg {
    match arc {
        None => Seg::Line { from: s, to: e },
        Some((k, ccw)) => {
            let mid = s.plus(e).scale(0.5);
            let half = e.minus(s).scale(0.5);
            Seg::Arc { from: s, to: e, center: mid.plus(half.left().scale(k)), ccw }
        }
    }
}

/// `p` lies on the move (on its line within its length, or on its arc within its sweep).
fn on(m: &Seg, p: P2) -> bool {
    match *m {
        Seg::Line { from, to } => {
            let u = to.minus(from).unit();
            let k = p.minus(from).dot(u);
            off_line(p, from, u) < 1e-6 && k > -1e-6 && k < from.dist(to) + 1e-6
        }
        Seg::Arc { from, to, center, ccw } => {
            let ang = |q: P2| (q.b - center.b).atan2(q.a - center.a);
            let sweep = |a: f64, b: f64| if ccw { (b - a).rem_euclid(std::f64::consts::TAU) } else { (a - b).rem_euclid(std::f64::consts::TAU) };
            let (whole, at) = (sweep(ang(from), ang(to)), sweep(ang(from), ang(p)));
            (p.dist(center) - from.dist(center)).abs() < 1e-6 * (1.0 + from.dist(center)) && (at <= whole + 1e-6 || at > std::f64::consts::TAU - 1e-6)
        }
    }
}

fn kind() -> impl Strategy<Value = Option<(f64, bool)>> {
    prop_oneof![Just(None), (-3.0..3.0f64, any::<bool>()).prop_map(Some)]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 800, .. ProptestConfig::default() })]

    /// Whatever two moves and corner: a chamfer's ends lie on the moves, as far from the
    /// corner or as far apart as asked; a corner arc's ends lie on the moves, its centre its
    /// radius from both ends, and it leaves and joins each move along it (tangent).
    #[test]
    fn corners_lie_on_their_moves(s in (-50.0..50.0f64, -50.0..50.0f64), p in (-50.0..50.0f64, -50.0..50.0f64), e in (-50.0..50.0f64, -50.0..50.0f64), k1 in kind(), k2 in kind(), size in 0.01..20.0f64, which in 0..3u8) {
        let (s, p, e) = (P2::new(s.0, s.1), P2::new(p.0, p.1), P2::new(e.0, e.1));
        prop_assume!(s.dist(p) > 0.1 && p.dist(e) > 0.1);
        let (first, second) = (seg(s, p, k1), seg(p, e, k2));
        let cut = [CornerCut::FromCorner(size), CornerCut::Length(size), CornerCut::Round(size)][which as usize];
        if let Ok(Some((a, b, arc))) = corner_cut(&first, &second, cut) {
            prop_assert!(on(&first, a), "{a:?} not on {first:?}");
            prop_assert!(on(&second, b), "{b:?} not on {second:?}");
            match (cut, arc) {
                (CornerCut::FromCorner(t), None) => {
                    prop_assert!((a.dist(p) - t).abs() < 1e-6 && (b.dist(p) - t).abs() < 1e-6);
                }
                (CornerCut::Length(l), None) => {
                    prop_assert!((a.dist(b) - l).abs() < 1e-6 * (1.0 + l), "{} vs {l}", a.dist(b));
                    prop_assert!((a.dist(p) - b.dist(p)).abs() < 1e-6);
                }
                (CornerCut::Round(d), Some((c, _))) => {
                    prop_assert!((c.dist(a) - d).abs() < 1e-6 * (1.0 + d) && (c.dist(b) - d).abs() < 1e-6 * (1.0 + d), "{c:?} {a:?} {b:?}");
                }
                other => prop_assert!(false, "{other:?}"),
            }
        }
    }
}

/// An arc that curls back toward the line before it: the chamfer of length 1 is the one
/// nearest the corner (chords 0.7564), though longer chords close up again.
#[test]
fn a_chamfer_takes_the_shortest_chords() {
    // The line Z2 to Z-10 at radius 10, then a clockwise half circle back to Z-4 about Z-7.
    let line = Seg::Line { from: P2::new(2.0, 10.0), to: P2::new(-10.0, 10.0) };
    let arc = Seg::Arc { from: P2::new(-10.0, 10.0), to: P2::new(-4.0, 10.0), center: P2::new(-7.0, 10.0), ccw: false };
    let (a, b, _) = corner_cut(&line, &arc, CornerCut::Length(1.0)).unwrap().unwrap();
    assert!((a.a + 9.2436).abs() < 1e-4 && (a.b - 10.0).abs() < 1e-9, "{a:?}");
    assert!((b.a + 9.9046).abs() < 1e-4 && (b.b - 10.75035).abs() < 1e-4, "{b:?}");
}

/// A corner arc that touches an arc at its very start takes the whole arc: its tangent point
/// is that start, not a point a turn short of it.
#[test]
fn a_corner_arc_may_take_a_whole_arc() {
    let arc = Seg::Arc { from: P2::new(-10.0, 15.0), to: P2::new(-20.0, 25.0), center: P2::new(-20.0, 15.0), ccw: true };
    let line = Seg::Line { from: P2::new(-20.0, 25.0), to: P2::new(-20.0, 5.0) };
    let (a, b, arc_of) = corner_cut(&arc, &line, CornerCut::Round(5.0)).unwrap().unwrap();
    assert!(a.dist(P2::new(-10.0, 15.0)) < 1e-9, "{a:?}");
    assert!(b.dist(P2::new(-20.0, 15.0)) < 1e-9, "{b:?}");
    assert!(arc_of.unwrap().0.dist(P2::new(-15.0, 15.0)) < 1e-9);
}
