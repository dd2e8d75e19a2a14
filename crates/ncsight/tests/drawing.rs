//! Property tests of the lines a drawing dimensions by their angle (docs/commands/drawing.md):
//! for any start, angle and coordinate the functions accept, the end lies on the line and has
//! the coordinate given; two lines that meet, meet on both; what they refuse is within the
//! 1-degree tolerance of the notes.

use ncsight::comp::{direction, end_by_angle, meet, P2, DRAWING_TOLERANCE_DEG};
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
