//! G90 (outer/inner diameter cutting cycle) and G94 (end face cutting cycle): the single
//! turning and facing cycles of the system-A lathes (GSK980TDi help text, G90 and G94 steps 1-4).
//!
//! Both are one four-leg box written once along a "cut axis": G90 cuts along Z and steps in X,
//! G94 cuts along X and steps in Z.
//! 1. rapid from the start A along the step axis to the cut start B (the taper R moves B);
//! 2. feed from B to the end point C;
//! 3. feed back along the step axis to A's level;
//! 4. rapid along the cut axis back to A.

pub use crate::codes::BoxKind;

use crate::motion::{Op, Vec3};

/// The four legs of one box, from the start `a` to the end point `c` with taper `taper_mm`
/// (radius for G90); the cut (step 2) and the way back (step 3) are feeds that carry 0 (the
/// interpreter sets each from F). Legs of zero length are left out.
pub fn box_cycle(kind: BoxKind, a: Vec3, c: Vec3, taper_mm: f64) -> Vec<Op> {
    let s = kind.step_axis();
    let mut b = a;
    b.set_axis(s, c.axis(s) + taper_mm);
    let mut d = c;
    d.set_axis(s, a.axis(s));
    let legs = [(a, b, false), (b, c, true), (c, d, true), (d, a, false)];
    legs.into_iter()
        .filter(|(from, to, _)| from != to)
        .map(|(from, to, cut)| if cut { Op::Feed { from, to, feed_mm_min: 0.0 } } else { Op::Rapid { from, to } })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ends(ops: &[Op]) -> Vec<(f64, f64, bool)> {
        ops.iter()
            .map(|o| {
                let e = o.end_point().unwrap();
                (e.x, e.z, matches!(o, Op::Feed { .. }))
            })
            .collect()
    }

    #[test]
    fn g90_straight_and_taper() {
        // Radius coordinates: from X25 Z2 to X20 Z-30.
        let a = Vec3::new(25.0, 0.0, 2.0);
        let c = Vec3::new(20.0, 0.0, -30.0);
        assert_eq!(ends(&box_cycle(BoxKind::Turning, a, c, 0.0)), vec![(20.0, 2.0, false), (20.0, -30.0, true), (25.0, -30.0, true), (25.0, 2.0, false)]);
        // the cut starts 2 mm (radius) below the end X.
        assert_eq!(ends(&box_cycle(BoxKind::Turning, a, c, -2.0))[0], (18.0, 2.0, false));
    }

    #[test]
    fn g94_face() {
        let a = Vec3::new(25.0, 0.0, 2.0);
        let c = Vec3::new(10.0, 0.0, -1.0);
        assert_eq!(ends(&box_cycle(BoxKind::Facing, a, c, 0.0)), vec![(25.0, -1.0, false), (10.0, -1.0, true), (10.0, 2.0, true), (25.0, 2.0, false)]);
        assert_eq!(ends(&box_cycle(BoxKind::Facing, a, c, -0.5))[0], (25.0, -1.5, false));
    }
}
