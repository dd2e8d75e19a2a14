//! Thread cutting, shared by every thread command (G32, G32.1, G92, G92.1, the YASNAC G92, and
//! the arc threads G32.2/G32.3).
//!
//! A thread pass is spindle-synchronised motion: the long axis moves one lead per spindle
//! revolution. Motion starts when the spindle passes its one-revolution signal plus the start
//! angle Q (docs/reference/behaviour.md, "Multi-start threads and the spindle angle"), so the
//! spindle angle anywhere along a pass is `Q + 360 x (long-axis distance so far) / lead`.
//!
//! The pull-out (退尾) geometry is one function, [`pull_out`]; what differs per command (which of
//! J and K are taken from where, signs, clamps) is decided by the caller and passed in as data.

pub mod arc;
pub mod compound;
pub mod cycle;
pub mod variable_lead;

use crate::motion::{Op, Vec3};

pub use crate::motion::LongAxis;

/// How the pull-out moves (seed 000 note 8, seed 001 G32.1 note 5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PullOutMode {
    /// GSK No.107 = 0: one straight synchronised segment, slope J/K.
    Ratio,
    /// GSK No.107 = v > 0: the short axis moves at v mm/min while the long axis keeps threading;
    /// what is left of J when the long axis arrives is finished at rapid.
    ShortAxisSpeed(f64),
}

/// A resolved pull-out: K along the long axis before the end point, J along the short axis,
/// both positive, and the direction of J (+1 or -1 along the short axis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PullOut {
    pub long_mm: f64,
    pub short_mm: f64,
    pub short_sign: f64,
    pub mode: PullOutMode,
    /// Perpendicular pull-out after the end point (K omitted on G32.1 / G92.1: seed 001 G32.1
    /// note 3/5, G92.1 note 3/4), at this feed in mm/min (parameter 1466).
    pub after_end_feed: Option<f64>,
}

/// One pass of spindle-synchronised motion and what follows it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pass {
    pub from: Vec3,
    pub to: Vec3,
    /// Long-axis travel per spindle revolution, mm.
    pub lead_mm: f64,
    /// Spindle speed, signed (negative: the spindle's negative direction).
    pub rpm: f64,
    /// Spindle angle when the pass starts, degrees from the one-revolution signal.
    pub start_deg: f64,
    pub pull_out: Option<PullOut>,
}

/// Why a pass cannot be made.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PassError {
    /// The pull-out is longer along the long axis than the thread (seed 001 G32.1 note 9,
    /// G92.1 note 10): (pull-out, thread length).
    PullOutTooLong(f64, f64),
}

/// Normalise an angle to [0, 360).
pub fn wrap_deg(a: f64) -> f64 {
    let r = a.rem_euclid(360.0);
    if r >= 360.0 - 1e-9 {
        0.0
    } else {
        r
    }
}

/// Spindle angle after `long_mm` of long-axis travel from `start_deg`.
pub fn phase_after(start_deg: f64, long_mm: f64, lead_mm: f64) -> f64 {
    wrap_deg(start_deg + 360.0 * long_mm / lead_mm)
}

/// The synchronised operation between two points, with the phase at its start.
pub fn thread_op(from: Vec3, to: Vec3, lead_mm: f64, long_axis: LongAxis, spindle_deg: f64, rpm: f64) -> Op {
    Op::Thread { from, to, lead_mm, long_axis, spindle_deg: wrap_deg(spindle_deg), rpm }
}

/// Expand a pass into operations: the thread up to the pull-out, the pull-out, and (for the
/// No.107 speed mode) the rapid that finishes J. The long axis is the thread's throughout.
/// Returns the operations and the spindle angle at the end of the last synchronised one.
pub fn expand(pass: &Pass) -> Result<(Vec<Op>, f64), PassError> {
    let long_axis = LongAxis::of(&pass.from, &pass.to);
    let (l, s) = long_axis.indices();
    let length = (pass.to.axis(l) - pass.from.axis(l)).abs();
    let lead = pass.lead_mm;
    let mut ops = Vec::with_capacity(3);
    let Some(po) = pass.pull_out.filter(|p| p.short_mm > 0.0) else {
        ops.push(thread_op(pass.from, pass.to, lead, long_axis, pass.start_deg, pass.rpm));
        return Ok((ops, phase_after(pass.start_deg, length, lead)));
    };
    if po.long_mm > length + 1e-9 {
        return Err(PassError::PullOutTooLong(po.long_mm, length));
    }
    if po.long_mm <= 0.0 && po.after_end_feed.is_none() {
        // No length along the long axis (GSK G92 note 3 with K0): nothing is synchronised; the
        // short axis goes out at rapid at the end point (assumption, docs).
        ops.push(thread_op(pass.from, pass.to, lead, long_axis, pass.start_deg, pass.rpm));
        let mut out = pass.to;
        out.set_axis(s, out.axis(s) + po.short_sign * po.short_mm);
        ops.push(Op::Rapid { from: pass.to, to: out });
        return Ok((ops, phase_after(pass.start_deg, length, lead)));
    }
    if let Some(feed) = po.after_end_feed {
        // Thread to the end point, then straight out along the short axis at the 1466 speed.
        ops.push(thread_op(pass.from, pass.to, lead, long_axis, pass.start_deg, pass.rpm));
        let mut out = pass.to;
        out.set_axis(s, out.axis(s) + po.short_sign * po.short_mm);
        ops.push(Op::Feed { from: pass.to, to: out, feed_mm_min: feed });
        return Ok((ops, phase_after(pass.start_deg, length, lead)));
    }
    // The body stops K before the end point along the long axis, on the line from..to.
    let body_frac = if length > 0.0 { (length - po.long_mm) / length } else { 0.0 };
    let body_end = lerp(&pass.from, &pass.to, body_frac);
    if length - po.long_mm > 1e-12 {
        ops.push(thread_op(pass.from, body_end, lead, long_axis, pass.start_deg, pass.rpm));
    }
    let phase_at = |long: f64| phase_after(pass.start_deg, long, lead);
    let mut out = pass.to;
    out.set_axis(s, pass.to.axis(s) + po.short_sign * po.short_mm);
    let mut end_deg = phase_at(length);
    match po.mode {
        PullOutMode::Ratio => {
            ops.push(thread_op(body_end, out, lead, long_axis, phase_at(length - po.long_mm), pass.rpm));
        }
        PullOutMode::ShortAxisSpeed(v) => {
            // Long axis at lead x rpm, short axis at v: which one arrives first decides.
            let vl = lead * pass.rpm.abs();
            let short_in_k = if vl > 0.0 { v * po.long_mm / vl } else { f64::INFINITY };
            let dir_long = (pass.to.axis(l) - pass.from.axis(l)).signum();
            if short_in_k >= po.short_mm {
                // J is covered first: then the long axis finishes K alone.
                let long_done = po.short_mm * vl / v;
                let mut mid = body_end;
                mid.set_axis(l, body_end.axis(l) + dir_long * long_done);
                mid.set_axis(s, out.axis(s));
                ops.push(thread_op(body_end, mid, lead, long_axis, phase_at(length - po.long_mm), pass.rpm));
                if po.long_mm - long_done > 1e-12 {
                    ops.push(thread_op(mid, out, lead, long_axis, phase_at(length - po.long_mm + long_done), pass.rpm));
                }
            } else {
                // The long axis arrives first; the rest of J at rapid.
                let mut at_end = pass.to;
                at_end.set_axis(s, pass.to.axis(s) + po.short_sign * short_in_k);
                ops.push(thread_op(body_end, at_end, lead, long_axis, phase_at(length - po.long_mm), pass.rpm));
                ops.push(Op::Rapid { from: at_end, to: out });
            }
            end_deg = phase_at(length);
        }
    }
    Ok((ops, end_deg))
}

pub(crate) fn lerp(a: &Vec3, b: &Vec3, u: f64) -> Vec3 {
    Vec3::new(a.x + (b.x - a.x) * u, a.y + (b.y - a.y) * u, a.z + (b.z - a.z) * u)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pass(pull_out: Option<PullOut>) -> Pass {
        // Seed 000 O0012 first pass: X58.7 (radius 29.35) from Z5 to Z-28, lead 3.
        Pass { from: Vec3::new(29.35, 0.0, 5.0), to: Vec3::new(29.35, 0.0, -28.0), lead_mm: 3.0, rpm: 300.0, start_deg: 0.0, pull_out }
    }

    #[test]
    fn seed_000_worked_example_pull_out() {
        // J3 K1, No.107 = 0: thread to Z-27, then to X64.7 (radius 32.35) Z-28.
        let po = PullOut { long_mm: 1.0, short_mm: 3.0, short_sign: 1.0, mode: PullOutMode::Ratio, after_end_feed: None };
        let (ops, end) = expand(&pass(Some(po))).unwrap();
        assert_eq!(ops.len(), 2);
        assert_eq!(ops[0].end_point().unwrap(), Vec3::new(29.35, 0.0, -27.0));
        let e = ops[1].end_point().unwrap();
        assert!((e.x - 32.35).abs() < 1e-12 && (e.z + 28.0).abs() < 1e-12);
        // 32 mm of thread is 10 2/3 revolutions: the pull-out starts at 240 degrees.
        let Op::Thread { spindle_deg, .. } = ops[1] else { panic!() };
        assert!((spindle_deg - 240.0).abs() < 1e-9);
        assert!((end - 0.0).abs() < 1e-9); // 33 mm = 11 revolutions
    }

    #[test]
    fn short_axis_speed_mode() {
        // No.107 = 600 mm/min; long axis at 3 x 300 = 900 mm/min. In K = 1 mm (1/900 min) the
        // short axis covers 0.667 mm of J = 3: the rest at rapid.
        let po = PullOut { long_mm: 1.0, short_mm: 3.0, short_sign: 1.0, mode: PullOutMode::ShortAxisSpeed(600.0), after_end_feed: None };
        let (ops, _) = expand(&pass(Some(po))).unwrap();
        assert_eq!(ops.len(), 3);
        let p = ops[1].end_point().unwrap();
        assert!((p.x - (29.35 + 600.0 / 900.0)).abs() < 1e-9 && (p.z + 28.0).abs() < 1e-12);
        assert!(matches!(ops[2], Op::Rapid { .. }));
        // A fast short axis covers J first, then the long axis goes on alone.
        let po = PullOut { long_mm: 1.0, short_mm: 0.5, short_sign: 1.0, mode: PullOutMode::ShortAxisSpeed(1800.0), after_end_feed: None };
        let (ops, _) = expand(&pass(Some(po))).unwrap();
        assert_eq!(ops.len(), 3);
        let p = ops[1].end_point().unwrap();
        assert!((p.z - (-27.0 - 0.25)).abs() < 1e-9 && (p.x - 29.85).abs() < 1e-12);
    }

    #[test]
    fn pull_out_longer_than_the_thread_is_an_error() {
        let po = PullOut { long_mm: 40.0, short_mm: 3.0, short_sign: 1.0, mode: PullOutMode::Ratio, after_end_feed: None };
        assert_eq!(expand(&pass(Some(po))), Err(PassError::PullOutTooLong(40.0, 33.0)));
    }
}
