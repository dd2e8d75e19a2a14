//! Tapping with the spindle: the tap goes in synchronised with the spindle at the lead, stops at
//! the bottom, and comes out along the same groove with the spindle reversed. One stroke serves
//! G33 (GSK980TDi help text G33: M05, wait, reverse at the bottom) and the lathe rigid tapping
//! G84/G88 (help text G84/88: a dwell P at the bottom); what happens at the bottom is the
//! caller's.

use super::thread::{phase_after, thread_op, wrap_deg};
use crate::motion::{LongAxis, Op, Vec3};

/// One stroke from `start` to `bottom` and back: the tap in at `rpm` from `start_deg`, the
/// `at_bottom` operations, the tap out at `-rpm`, its start angle the one that keeps it in the
/// groove the way in cut.
pub fn stroke(start: Vec3, bottom: Vec3, lead_mm: f64, start_deg: f64, rpm: f64, at_bottom: &[Op]) -> Vec<Op> {
    let long = LongAxis::of(&start, &bottom);
    let i = long.index();
    let depth = (bottom.axis(i) - start.axis(i)).abs();
    let back_deg = wrap_deg(360.0 - phase_after(start_deg, depth, lead_mm));
    let mut ops = Vec::with_capacity(at_bottom.len() + 2);
    ops.push(thread_op(start, bottom, lead_mm, long, start_deg, rpm));
    ops.extend_from_slice(at_bottom);
    ops.push(thread_op(bottom, start, lead_mm, long, back_deg, -rpm));
    ops
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The way out starts at the angle the spindle stands at, counted the reversed way: after
    /// 10 mm at lead 1.5 (6 2/3 turns, 240 degrees past 0) the way out starts at 120 degrees.
    #[test]
    fn the_way_out_is_in_the_same_groove() {
        let (a, b) = (Vec3::new(0.0, 0.0, 5.0), Vec3::new(0.0, 0.0, -5.0));
        let ops = stroke(a, b, 1.5, 0.0, 500.0, &[Op::Dwell { seconds: 0.5 }]);
        assert_eq!(ops.len(), 3);
        let Op::Thread { spindle_deg, rpm, from, to, .. } = ops[2] else { panic!("{ops:?}") };
        assert!((spindle_deg - 120.0).abs() < 1e-9 && rpm == -500.0 && from == b && to == a, "{ops:?}");
    }
}
