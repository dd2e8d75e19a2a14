//! G34, variable lead (GSK980TDi help text G34): the lead grows by R each revolution, F + R at
//! the end of the first; the thread is laid out one revolution a record, each at the mean lead
//! of its revolution. A whole revolution brings the spindle back to its angle: every record
//! starts at the block's start angle. J and K give a pull-out as G32's (help text G34: "X(U),
//! Z(W), J, K mean the same as in G32"): the revolutions stop K before the end along the long
//! axis and the pull-out goes on at the lead of the revolution it starts in (an assumption: the
//! help text does not say how the lead changes during the pull-out).

use super::{phase_after, thread_op, Pass, PassError, PullOut};
use crate::motion::{LongAxis, Op, Vec3};

/// Why a G34 cannot be laid out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum VariableLeadError {
    /// After this many revolutions the lead would leave (0, max] (help text note 1).
    LeadLeavesRange(u32),
    /// More revolutions than the limit.
    TooMany,
    /// The pull-out is longer than the thread.
    Pass(PassError),
}

/// The records of a G34 thread from `from` to `to`: lead `lead_mm` (F), change `change_mm` per
/// revolution (R), the spindle at `rpm` from `start_deg`, with its pull-out; at most `limit`
/// revolutions, each lead at most `max_lead_mm`.
#[allow(clippy::too_many_arguments)]
pub fn expand(
    from: Vec3,
    to: Vec3,
    lead_mm: f64,
    change_mm: f64,
    start_deg: f64,
    rpm: f64,
    pull_out: Option<PullOut>,
    max_lead_mm: f64,
    limit: usize,
) -> Result<Vec<Op>, VariableLeadError> {
    let long = LongAxis::of(&from, &to);
    let i = long.index();
    let length = (to.axis(i) - from.axis(i)).abs();
    let pull_out = pull_out.filter(|p| p.short_mm > 0.0);
    let pull_long = pull_out.map_or(0.0, |p| p.long_mm);
    if pull_long > length + 1e-9 {
        return Err(VariableLeadError::Pass(PassError::PullOutTooLong(pull_long, length)));
    }
    // The revolutions end where the pull-out begins (at the end point without one).
    let body = length - pull_long;
    let mut ops = Vec::new();
    let (mut done, mut n, mut at, mut deg) = (0.0, 0u32, from, start_deg);
    let mut rev_lead = lead_mm + change_mm * 0.5;
    while done < body - 1e-12 {
        // Lead during revolution n: F + R (n + 1/2); it must stay in (0, max] (help note 1).
        rev_lead = lead_mm + change_mm * (n as f64 + 0.5);
        let end_lead = lead_mm + change_mm * (n as f64 + 1.0);
        if !(rev_lead > 0.0 && end_lead <= max_lead_mm + 1e-9 && end_lead > 0.0) {
            return Err(VariableLeadError::LeadLeavesRange(n));
        }
        let travel = rev_lead.min(body - done);
        done += travel;
        let next = super::lerp(&from, &to, done / length);
        ops.push(thread_op(at, next, rev_lead, long, start_deg, rpm));
        deg = phase_after(start_deg, travel, rev_lead);
        at = next;
        n += 1;
        if n as usize > limit {
            return Err(VariableLeadError::TooMany);
        }
    }
    if let Some(po) = pull_out {
        // The pull-out as G32 makes it, from where the revolutions stopped.
        let pass = Pass { from: at, to, lead_mm: rev_lead, rpm, start_deg: deg, pull_out: Some(po) };
        let (more, _) = super::expand(&pass).map_err(VariableLeadError::Pass)?;
        ops.extend(more);
    }
    Ok(ops)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// F2 R0.5 over 10 mm: revolutions of 2.25, 2.75, 3.25, then the 1.75 mm left.
    #[test]
    fn each_revolution_at_its_mean_lead() {
        let ops = expand(Vec3::new(10.0, 0.0, 0.0), Vec3::new(10.0, 0.0, -10.0), 2.0, 0.5, 90.0, 300.0, None, 500.0, 1000).unwrap();
        let leads: Vec<f64> = ops.iter().map(|o| if let Op::Thread { lead_mm, .. } = o { *lead_mm } else { 0.0 }).collect();
        assert_eq!(leads, vec![2.25, 2.75, 3.25, 3.75]);
        let Op::Thread { to, spindle_deg, .. } = ops[3] else { panic!() };
        assert!((to.z + 10.0).abs() < 1e-12 && spindle_deg == 90.0);
        assert_eq!(expand(Vec3::default(), Vec3::new(0.0, 0.0, -10.0), 2.0, -1.0, 0.0, 300.0, None, 500.0, 1000), Err(VariableLeadError::LeadLeavesRange(1)));
    }

    /// The case (radius 15 = X30), F2 R0.1 J1 K2 from Z5 to Z-20: 25 mm of thread, the
    /// revolutions over the first 23 mm (2.05, 2.15, ... 2.95: ten revolutions make 25 mm, so
    /// nine make 2.05+...+2.85 = 22.05 mm and the tenth's 0.95 mm of its 2.95 stop at Z-18), then
    /// the pull-out from X30 Z-18 to X32 Z-20 at 2.95, starting 0.95/2.95 of a turn past 0 deg.
    #[test]
    fn pull_out_as_g32() {
        use super::super::PullOutMode;
        let po = PullOut { long_mm: 2.0, short_mm: 1.0, short_sign: 1.0, mode: PullOutMode::Ratio, after_end_feed: None };
        let ops = expand(Vec3::new(15.0, 0.0, 5.0), Vec3::new(15.0, 0.0, -20.0), 2.0, 0.1, 0.0, 300.0, Some(po), 500.0, 1000).unwrap();
        assert_eq!(ops.len(), 11);
        let Op::Thread { from, to, lead_mm, spindle_deg, .. } = ops[10] else { panic!() };
        assert!((from.z + 18.0).abs() < 1e-9 && from.x == 15.0, "{from:?}");
        assert!((to.z + 20.0).abs() < 1e-9 && (to.x - 16.0).abs() < 1e-12, "{to:?}");
        assert!((lead_mm - 2.95).abs() < 1e-12);
        assert!((spindle_deg - 360.0 * 0.95 / 2.95).abs() < 1e-6, "{spindle_deg}");
        let Op::Thread { to, lead_mm, .. } = ops[9] else { panic!() };
        assert!((to.z + 18.0).abs() < 1e-9 && (lead_mm - 2.95).abs() < 1e-12);
        let long = PullOut { long_mm: 30.0, ..po };
        assert_eq!(
            expand(Vec3::new(15.0, 0.0, 5.0), Vec3::new(15.0, 0.0, -20.0), 2.0, 0.1, 0.0, 300.0, Some(long), 500.0, 1000),
            Err(VariableLeadError::Pass(PassError::PullOutTooLong(30.0, 25.0)))
        );
    }
}
