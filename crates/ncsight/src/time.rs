//! The time model (issue 5): how long each record takes, from the profile's parameters and the
//! operator's overrides.
//!
//! - Motion starts and ends at rest within each block (exact stop) and accelerates linearly:
//!   a move of length L at speed v with time constant T (from rest to v) takes `L / v + T`, or
//!   `2 sqrt(L T / v)` when it is too short to reach v (a triangle).
//! - Rapid: every axis at its own rapid rate and time constant at once (TDi help G00: "each axis
//!   at its own rapid rate, the path is not necessarily straight"); the slowest axis decides.
//! - Feed and arc: the path at the feed (per revolution already multiplied out), times the feed
//!   override, clamped to the cutting feed limit; dry run replaces the feed by the dry-run rate.
//! - Thread: the long axis at lead x rpm, no override (seed 001 G32.1 note 13: dry run at
//!   parameter 1410). A run of touching thread records accelerates once, at its start.
//! - Dwell: its seconds. Spindle, tool, stop and end records take no time (the manuals give no
//!   spindle acceleration or orientation times).

use crate::geom;
use crate::motion::{Op, Record};
use crate::profile::{ParamKey, Params};

/// What the operator set that changes the time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overrides {
    /// Feed override, percent (threads and tapping ignore it).
    pub feed_pct: f64,
    /// Rapid override, percent.
    pub rapid_pct: f64,
    pub dry_run: bool,
}

impl Default for Overrides {
    fn default() -> Overrides {
        Overrides { feed_pct: 100.0, rapid_pct: 100.0, dry_run: false }
    }
}

/// Rates and time constants of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeModel {
    rapid_mm_min: [f64; 3],
    rapid_accel_s: f64,
    feed_accel_s: f64,
    feed_max_mm_min: f64,
    dry_run_mm_min: f64,
    /// Rapid rate of a rotary axis, degrees per minute (after the rapid override).
    rotary_rapid_deg_min: f64,
    /// Seconds a change of tool takes.
    tool_change_s: f64,
    ov: Overrides,
}

/// Time for `length` at `speed_mm_min` from rest to rest with time constant `accel_s`.
pub fn trapezoid_s(length: f64, speed_mm_min: f64, accel_s: f64) -> f64 {
    if length <= 0.0 {
        return 0.0;
    }
    let v = speed_mm_min / 60.0;
    if v <= 0.0 {
        return f64::INFINITY;
    }
    if accel_s <= 0.0 || length >= v * accel_s {
        length / v + accel_s
    } else {
        2.0 * (length * accel_s / v).sqrt()
    }
}

/// Distance covered `t` seconds into a move of `length` at `speed_mm_min` with time constant
/// `accel_s` (the same profile as [`trapezoid_s`]), and the speed then (mm/s).
pub fn trapezoid_at(length: f64, speed_mm_min: f64, accel_s: f64, t: f64) -> (f64, f64) {
    let v = speed_mm_min / 60.0;
    let total = trapezoid_s(length, speed_mm_min, accel_s);
    if t <= 0.0 || length <= 0.0 {
        return (0.0, 0.0);
    }
    if t >= total {
        return (length, 0.0);
    }
    if accel_s <= 0.0 {
        return (v * t, v);
    }
    let a = v / accel_s;
    // Peak speed: v, or lower for a triangle.
    let peak = if length >= v * accel_s { v } else { (a * length).sqrt() };
    let t_acc = peak / a;
    let t_flat = total - 2.0 * t_acc;
    if t < t_acc {
        (a * t * t / 2.0, a * t)
    } else if t < t_acc + t_flat {
        (peak * t_acc / 2.0 + peak * (t - t_acc), peak)
    } else {
        let left = total - t;
        (length - a * left * left / 2.0, a * left)
    }
}

impl TimeModel {
    /// Where a motion record is (fraction of its path) `t` seconds after it started, and how
    /// far it goes on (fraction) and how long it takes (s) if it decelerates from there.
    pub fn stop_from(&self, r: &Record, length: f64, t: f64) -> (f64, f64, f64) {
        let (speed, accel) = match &r.op {
            Op::Rapid { from, to } => {
                // The slowest axis sets the pace; the others follow in proportion.
                let (axis, _) = (0..3)
                    .map(|a| (a, trapezoid_s((to.axis(a) - from.axis(a)).abs(), self.rapid_mm_min[a], self.rapid_accel_s)))
                    .fold((0, -1.0), |best, x| if x.1 > best.1 { x } else { best });
                let l = (to.axis(axis) - from.axis(axis)).abs();
                let (d, v) = trapezoid_at(l, self.rapid_mm_min[axis], self.rapid_accel_s, t);
                if l <= 0.0 {
                    return (1.0, 0.0, 0.0);
                }
                let a = self.rapid_mm_min[axis] / 60.0 / self.rapid_accel_s.max(1e-9);
                let stop_d = v * v / (2.0 * a);
                return ((d / l).min(1.0), (stop_d / l).min(1.0), v / a);
            }
            _ => (self.path_speed(r), self.accel_s(r)),
        };
        if length <= 0.0 {
            return (1.0, 0.0, 0.0);
        }
        let (d, v) = trapezoid_at(length, speed, accel, t);
        let a = speed / 60.0 / accel.max(1e-9);
        let stop_d = if accel > 0.0 { v * v / (2.0 * a) } else { 0.0 };
        ((d / length).min(1.0), (stop_d / length).min(1.0), if accel > 0.0 { v / a } else { 0.0 })
    }

    pub fn new(params: &Params, ov: Overrides) -> TimeModel {
        let setting = |name| params.get(ParamKey::Setting(name)) / 1000.0;
        TimeModel {
            rapid_mm_min: [0, 1, 2].map(|a| params.rapid_mm_min(a) * ov.rapid_pct / 100.0),
            rapid_accel_s: setting("rapid_accel_ms"),
            feed_accel_s: setting("feed_accel_ms"),
            feed_max_mm_min: params.feed_max_mm_min(),
            rotary_rapid_deg_min: params.get(ParamKey::Setting("rotary_rapid_deg_min")) * ov.rapid_pct / 100.0,
            dry_run_mm_min: params.get(params.profile().time.dry_run),
            tool_change_s: params.get(ParamKey::Setting("tool_change_s")),
            ov,
        }
    }

    /// Seconds a change of tool takes (the setup's `[machine] tool_change_s`).
    pub fn tool_change_s(&self) -> f64 {
        self.tool_change_s
    }

    pub fn feed_accel_s(&self) -> f64 {
        self.feed_accel_s
    }

    /// Path speed of a feed or arc record, mm/min.
    pub fn feed_speed(&self, r: &Record, programmed: f64) -> f64 {
        if self.ov.dry_run {
            return self.dry_run_mm_min;
        }
        if r.override_free {
            return programmed;
        }
        (programmed * self.ov.feed_pct / 100.0).min(self.feed_max_mm_min)
    }

    /// Long-axis speed of a thread record, mm/min.
    pub fn thread_speed(&self, lead_mm: f64, rpm: f64) -> f64 {
        if self.ov.dry_run {
            self.dry_run_mm_min
        } else {
            lead_mm * rpm.abs()
        }
    }

    /// The speed along the path while the record runs (for the distance a hold needs to stop).
    pub fn path_speed(&self, r: &Record) -> f64 {
        match &r.op {
            Op::Feed { feed_mm_min, .. } | Op::Arc { feed_mm_min, .. } => self.feed_speed(r, *feed_mm_min),
            Op::Thread { lead_mm, rpm, .. } | Op::ThreadArc { lead_mm, rpm, .. } => self.thread_speed(*lead_mm, *rpm),
            Op::Rapid { .. } => self.rapid_mm_min.iter().cloned().fold(f64::INFINITY, f64::min),
            _ => 0.0,
        }
    }

    /// The time constant that applies to a record.
    pub fn accel_s(&self, r: &Record) -> f64 {
        if matches!(r.op, Op::Rapid { .. }) {
            self.rapid_accel_s
        } else {
            r.accel_s.unwrap_or(self.feed_accel_s)
        }
    }

    /// Seconds a record takes. `run_start`: a thread record that starts a synchronised run
    /// (it carries the run's acceleration).
    pub fn duration_s(&self, r: &Record, run_start: bool) -> f64 {
        match &r.op {
            Op::Rapid { from, to } => {
                (0..3).map(|a| trapezoid_s((to.axis(a) - from.axis(a)).abs(), self.rapid_mm_min[a], self.rapid_accel_s)).fold(0.0, f64::max)
            }
            Op::Feed { from, to, feed_mm_min } => trapezoid_s(from.dist(to), self.feed_speed(r, *feed_mm_min), self.accel_s(r)),
            Op::Arc { from, to, plane, feed_mm_min, .. } => {
                let len = geom::arc_geom_of(&r.op).map(|g| geom::arc_length(from, to, *plane, &g)).unwrap_or(0.0);
                trapezoid_s(len, self.feed_speed(r, *feed_mm_min), self.feed_accel_s)
            }
            Op::Thread { from, to, lead_mm, long_axis, rpm, .. } | Op::ThreadArc { from, to, lead_mm, long_axis, rpm, .. } => {
                let i = long_axis.index();
                let long = (to.axis(i) - from.axis(i)).abs();
                let v = self.thread_speed(*lead_mm, *rpm) / 60.0;
                long / v + if run_start { self.feed_accel_s } else { 0.0 }
            }
            Op::Dwell { seconds } => *seconds,
            Op::Rotary { from_deg, to_deg, rate_deg_min, rapid, linear, .. } => {
                let turn = (to_deg - from_deg).abs();
                if *rapid {
                    // A linear extra axis (a sub-spindle's B) at the Z axis's rapid rate (assumed).
                    let rate = if *linear { self.rapid_mm_min[2] } else { self.rotary_rapid_deg_min };
                    trapezoid_s(turn, rate, self.rapid_accel_s)
                } else {
                    trapezoid_s(turn, self.feed_speed(r, *rate_deg_min), self.accel_s(r))
                }
            }
            Op::Spindle { .. } | Op::Tool { .. } | Op::Stop { .. } | Op::End { .. } => 0.0,
        }
    }

    /// Seconds a record takes after the record before it took `previous_s`: a rotary turn made
    /// with a linear move takes only what that move does not already take.
    pub fn duration_after_s(&self, r: &Record, run_start: bool, previous_s: f64) -> f64 {
        let d = self.duration_s(r, run_start);
        if matches!(r.op, Op::Rotary { with_move: true, .. }) {
            (d - previous_s).max(0.0)
        } else {
            d
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn position_in_time() {
        // 100 mm at 100 mm/s, 0.1 s: 0.5 mm in the first 0.1 s, then 100 mm/s.
        let (d, v) = trapezoid_at(100.0, 6000.0, 0.1, 0.1);
        assert!((d - 5.0).abs() < 1e-9 && (v - 100.0).abs() < 1e-9);
        let (d, _) = trapezoid_at(100.0, 6000.0, 0.1, 0.6);
        assert!((d - 55.0).abs() < 1e-9);
        let (d, v) = trapezoid_at(100.0, 6000.0, 0.1, 1.1);
        assert!((d - 100.0).abs() < 1e-9 && v == 0.0);
    }

    #[test]
    fn trapezoid_and_triangle() {
        // 100 mm at 6000 mm/min (100 mm/s) with 0.1 s: 1 s + 0.1 s.
        assert!((trapezoid_s(100.0, 6000.0, 0.1) - 1.1).abs() < 1e-12);
        // 4 mm never reaches 100 mm/s in 0.1 s (it would need 10 mm): 2 sqrt(4 x 0.1 / 100).
        assert!((trapezoid_s(4.0, 6000.0, 0.1) - 2.0 * 0.004f64.sqrt()).abs() < 1e-12);
        assert_eq!(trapezoid_s(0.0, 6000.0, 0.1), 0.0);
        assert!((trapezoid_s(100.0, 6000.0, 0.0) - 1.0).abs() < 1e-12);
    }
}
