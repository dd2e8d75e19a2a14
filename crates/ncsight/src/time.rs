//! The first time model (issue 2, item 7): constant velocity, no acceleration yet.
//!
//! - Rapid: every axis moves at its own rapid rate at once (TDi help G00: "each axis at its own
//!   rapid rate; the path is not necessarily straight"), so the move takes as long as the slowest
//!   axis.
//! - Feed and arc: path length / feed, the feed already clamped to the profile's upper limit and
//!   multiplied by the spindle speed for feed per revolution.
//! - Dwell: its seconds. Spindle, tool, stop and end records take no time in this model.

use crate::geom;
use crate::motion::Op;
use crate::profile::Params;

/// Seconds an operation takes.
pub fn duration_s(op: &Op, params: &Params) -> f64 {
    match op {
        Op::Rapid { from, to } => (0..3)
            .map(|a| (to.axis(a) - from.axis(a)).abs() / params.rapid_mm_min(a) * 60.0)
            .fold(0.0, f64::max),
        Op::Feed { from, to, feed_mm_min } => from.dist(to) / feed_mm_min * 60.0,
        Op::Arc { from, to, center, plane, dir: _, feed_mm_min } => {
            // Recover the sweep from the stored centre; the interpreter stored a valid arc.
            let g = arc_geom_of(op).unwrap_or(geom::ArcGeom { center: *center, radius: 0.0, sweep_rad: 0.0 });
            geom::arc_length(from, to, *plane, &g) / feed_mm_min * 60.0
        }
        // Spindle-synchronised: the long axis at lead x rpm.
        Op::Thread { from, to, lead_mm, long_axis, rpm, .. } | Op::ThreadArc { from, to, lead_mm, long_axis, rpm, .. } => {
            let i = long_axis.index();
            (to.axis(i) - from.axis(i)).abs() / (lead_mm * rpm.abs()) * 60.0
        }
        Op::Dwell { seconds } => *seconds,
        Op::Spindle { .. } | Op::Tool { .. } | Op::Stop { .. } | Op::End { .. } => 0.0,
    }
}

/// The geometry of an `Op::Arc` from its stored fields.
pub fn arc_geom_of(op: &Op) -> Option<geom::ArcGeom> {
    if let Op::Arc { from, to, center, plane, dir, .. } = op {
        geom::arc_from_center(*from, *to, *plane, *dir, *center, f64::INFINITY).ok()
    } else {
        None
    }
}
