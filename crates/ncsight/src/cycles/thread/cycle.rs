//! The four-step thread-cutting cycle of G92 (GSK980TDi seed 000, YASNAC LX3 seed 004) and
//! G92.1 (GSK988T seed 001):
//! 1. X rapid from the start point A to the cut start B;
//! 2. thread from B to the cut end C (with its pull-out);
//! 3. X rapid back to A's X ("opposite to step 1");
//! 4. Z rapid back to A.
//!
//! With L starts, one block cuts every start at the same depth, start k at `Q + k x 360 / L`,
//! each as a full four-step cycle, in that order (docs/reference/behaviour.md, "Multi-start threads").

use super::{expand, Pass, PassError, PullOut};
use crate::motion::{Op, Vec3};

/// One cycle block, resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct Cycle {
    /// A: where the tool stands when the block starts.
    pub start: Vec3,
    /// B: where the thread starts (A's Z, or A's Z shifted by the YASNAC K; X from the end and
    /// the taper).
    pub cut_start: Vec3,
    /// C: where the thread ends.
    pub cut_end: Vec3,
    pub lead_mm: f64,
    pub rpm: f64,
    /// Number of starts L, 1..=99.
    pub starts: u32,
    /// Start angle of the first start, degrees.
    pub first_deg: f64,
    pub pull_out: Option<PullOut>,
}

/// The operations of a cycle block, each with the start (0-based) it belongs to.
pub fn expand_cycle(c: &Cycle) -> Result<Vec<(u32, Op)>, PassError> {
    let mut ops = Vec::new();
    for k in 0..c.starts.max(1) {
        let deg = c.first_deg + k as f64 * 360.0 / c.starts.max(1) as f64;
        // 1: rapid to the cut start (X only, unless a flank infeed shifts Z too).
        if c.cut_start != c.start {
            ops.push((k, Op::Rapid { from: c.start, to: c.cut_start }));
        }
        // 2: the thread and its pull-out.
        let pass = Pass { from: c.cut_start, to: c.cut_end, lead_mm: c.lead_mm, rpm: c.rpm, start_deg: deg, pull_out: c.pull_out };
        let (thread, _) = expand(&pass)?;
        let mut at = c.cut_end;
        for op in thread {
            at = op.end_point().unwrap_or(at);
            ops.push((k, op));
        }
        // 3: X rapid back to A's X.
        let d = Vec3::new(c.start.x, at.y, at.z);
        if d != at {
            ops.push((k, Op::Rapid { from: at, to: d }));
        }
        // 4: Z rapid back to A.
        if d != c.start {
            ops.push((k, Op::Rapid { from: d, to: c.start }));
        }
    }
    Ok(ops)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cycles::thread::PullOutMode;

    #[test]
    fn seed_000_worked_example() {
        // G0 X65 Z5; G92 X58.7 Z-28 F3 J3 K1 (issue 3's worked example; radius coordinates).
        let c = Cycle {
            start: Vec3::new(32.5, 0.0, 5.0),
            cut_start: Vec3::new(29.35, 0.0, 5.0),
            cut_end: Vec3::new(29.35, 0.0, -28.0),
            lead_mm: 3.0,
            rpm: 300.0,
            starts: 1,
            first_deg: 0.0,
            pull_out: Some(PullOut { long_mm: 1.0, short_mm: 3.0, short_sign: 1.0, mode: PullOutMode::Ratio, after_end_feed: None }),
        };
        let ops = expand_cycle(&c).unwrap();
        let ends: Vec<Vec3> = ops.iter().map(|(_, o)| o.end_point().unwrap()).collect();
        let expect = [(29.35, 5.0), (29.35, -27.0), (32.35, -28.0), (32.5, -28.0), (32.5, 5.0)];
        assert_eq!(ends.len(), expect.len());
        for (e, (x, z)) in ends.iter().zip(expect) {
            assert!((e.x - x).abs() < 1e-9 && (e.z - z).abs() < 1e-9, "{e:?} vs {x} {z}");
        }
        assert!(matches!(ops[1].1, Op::Thread { .. }) && matches!(ops[2].1, Op::Thread { .. }));
    }

    #[test]
    fn starts_are_evenly_spaced() {
        let c = Cycle {
            start: Vec3::new(32.5, 0.0, 5.0),
            cut_start: Vec3::new(29.35, 0.0, 5.0),
            cut_end: Vec3::new(29.35, 0.0, -28.0),
            lead_mm: 6.0,
            rpm: 300.0,
            starts: 3,
            first_deg: 10.0,
            pull_out: None,
        };
        let ops = expand_cycle(&c).unwrap();
        let angles: Vec<f64> = ops.iter().filter_map(|(_, o)| if let Op::Thread { spindle_deg, .. } = o { Some(*spindle_deg) } else { None }).collect();
        assert_eq!(angles, vec![10.0, 130.0, 250.0]);
    }
}
