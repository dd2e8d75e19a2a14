//! G34, variable lead (GSK980TDi help text G34): the lead grows by R each revolution, F + R at
//! the end of the first; the thread is laid out one revolution a record, each at the mean lead
//! of its revolution. A whole revolution brings the spindle back to its angle: every record
//! starts at the block's start angle.

use super::thread_op;
use crate::motion::{LongAxis, Op, Vec3};

/// Why a G34 cannot be laid out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum VariableLeadError {
    /// After this many revolutions the lead would leave (0, max] (help text note 1).
    LeadLeavesRange(u32),
    /// More revolutions than the limit.
    TooMany,
}

/// The records of a G34 thread from `from` to `to`: lead `lead_mm` (F), change `change_mm` per
/// revolution (R), the spindle at `rpm` from `start_deg`; at most `limit` revolutions, each lead
/// at most `max_lead_mm`.
pub fn expand(from: Vec3, to: Vec3, lead_mm: f64, change_mm: f64, start_deg: f64, rpm: f64, max_lead_mm: f64, limit: usize) -> Result<Vec<Op>, VariableLeadError> {
    let long = LongAxis::of(&from, &to);
    let i = long.index();
    let length = (to.axis(i) - from.axis(i)).abs();
    let mut ops = Vec::new();
    let (mut done, mut n, mut at) = (0.0, 0u32, from);
    while done < length - 1e-12 {
        // Lead during revolution n: F + R (n + 1/2); it must stay in (0, max] (help note 1).
        let rev_lead = lead_mm + change_mm * (n as f64 + 0.5);
        let end_lead = lead_mm + change_mm * (n as f64 + 1.0);
        if !(rev_lead > 0.0 && end_lead <= max_lead_mm + 1e-9 && end_lead > 0.0) {
            return Err(VariableLeadError::LeadLeavesRange(n));
        }
        let travel = rev_lead.min(length - done);
        done += travel;
        let u = done / length;
        let next = Vec3::new(from.x + (to.x - from.x) * u, from.y + (to.y - from.y) * u, from.z + (to.z - from.z) * u);
        ops.push(thread_op(at, next, rev_lead, long, start_deg, rpm));
        at = next;
        n += 1;
        if n as usize > limit {
            return Err(VariableLeadError::TooMany);
        }
    }
    Ok(ops)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// F2 R0.5 over 10 mm: revolutions of 2.25, 2.75, 3.25, then the 1.75 mm left.
    #[test]
    fn each_revolution_at_its_mean_lead() {
        let ops = expand(Vec3::new(10.0, 0.0, 0.0), Vec3::new(10.0, 0.0, -10.0), 2.0, 0.5, 90.0, 300.0, 500.0, 1000).unwrap();
        let leads: Vec<f64> = ops.iter().map(|o| if let Op::Thread { lead_mm, .. } = o { *lead_mm } else { 0.0 }).collect();
        assert_eq!(leads, vec![2.25, 2.75, 3.25, 3.75]);
        let Op::Thread { to, spindle_deg, .. } = ops[3] else { panic!() };
        assert!((to.z + 10.0).abs() < 1e-12 && spindle_deg == 90.0);
        assert_eq!(expand(Vec3::default(), Vec3::new(0.0, 0.0, -10.0), 2.0, -1.0, 0.0, 300.0, 500.0, 1000), Err(VariableLeadError::LeadLeavesRange(1)));
    }
}
