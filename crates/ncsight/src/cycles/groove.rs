//! G74 (end face peck cutting: pecks along Z, steps along X) and G75 (outer/inner diameter
//! grooving: pecks along X, steps along Z) of the system-A lathes, GSK980TDi help text G74/G75
//! steps 1-7. One cycle written once along a "peck axis" and a "step axis":
//! 1. from the groove's start An, feed Δk (G74) / Δi (G75) along the peck axis;
//! 2. rapid back e;
//! 3. feed on by (peck + e) while the end stays between An and Bn, else feed to Bn;
//! 4. rapid the relief Δd along the step axis to Cn;
//! 5. rapid back along the peck axis to Dn (the start's peck level);
//! 6. if grooves remain, rapid along the step axis by (Δd + step), no further than Af, and 1;
//! 7. else rapid along the step axis back to the start A.

pub use crate::codes::PeckKind;

use super::Expansion;

use crate::motion::Vec3;

/// One cycle block, resolved (all lengths mm along the axes, positive).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeckCycle {
    pub kind: PeckKind,
    pub start: Vec3,
    pub end: Vec3,
    /// e: the back-off after each peck.
    pub back_off_mm: f64,
    /// The peck along the peck axis (Δk for G74, Δi for G75).
    pub peck_mm: f64,
    /// The step between grooves along the step axis (Δi for G74, Δk for G75).
    pub step_mm: f64,
    /// Δd: the relief at the bottom along the step axis, away from the direction of stepping.
    pub relief_mm: f64,
}

/// One move of the cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Move {
    Rapid(Vec3),
    Feed(Vec3),
}

/// Why a cycle cannot run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PeckError {
    /// The end differs from the start along the peck axis but the peck is 0.
    NoPeck,
    /// The end differs from the start along the step axis but the step is 0.
    NoStep,
    /// More moves than `limit`.
    TooMany,
}

/// The moves of one cycle block, at most `limit` of them.
pub fn expand(c: &PeckCycle, limit: usize) -> Result<Vec<Move>, PeckError> {
    let plan = lay_out(c, limit)?;
    let mut out = Vec::with_capacity(plan.move_count().min(limit));
    plan.each_move(&mut |m| {
        out.push(m);
        std::ops::ControlFlow::Continue(())
    });
    if out.len() > limit {
        return Err(PeckError::TooMany);
    }
    Ok(out)
}

/// A cycle block laid out: its pecks and grooves counted (once: a sum of many small steps would
/// drift past the end), its moves made one at a time by [`PeckPlan::each_move`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeckPlan {
    c: PeckCycle,
    pecks: usize,
    grooves: usize,
}

/// Lay out one cycle block: the peck and the step checked, the pecks per groove and the grooves
/// counted; more than `limit` pecks in all is [`PeckError::TooMany`].
pub fn lay_out(c: &PeckCycle, limit: usize) -> Result<PeckPlan, PeckError> {
    let (p, s) = c.kind.axes();
    let depth = (c.end.axis(p) - c.start.axis(p)).abs();
    let across = (c.end.axis(s) - c.start.axis(s)).abs();
    if depth > 0.0 && c.peck_mm <= 0.0 {
        return Err(PeckError::NoPeck);
    }
    if across > 0.0 && c.step_mm <= 0.0 {
        return Err(PeckError::NoStep);
    }
    let count = |total: f64, each: f64| if total > 0.0 { ((total / each) - 1e-9).ceil().max(1.0) } else { 0.0 };
    let (pecks, grooves) = (count(depth, c.peck_mm), count(across, c.step_mm) + 1.0);
    // Every move counted (a groove of no depth still makes its step and its way out), before
    // anything is made or cast: more than `limit` is refused at once.
    if grooves * (2.0 * pecks + 3.0) + 1.0 > limit.min(super::MOST_MOVES) as f64 {
        return Err(PeckError::TooMany);
    }
    Ok(PeckPlan { c: *c, pecks: pecks as usize, grooves: grooves as usize })
}

impl PeckPlan {
    /// Hand on the moves in order (the sink may stop them).
    pub fn each_move(&self, sink: &mut dyn FnMut(Move) -> std::ops::ControlFlow<()>) {
        let c = &self.c;
        let (p, s) = c.kind.axes();
        let (p0, p_end) = (c.start.axis(p), c.end.axis(p));
        let (s0, s_end) = (c.start.axis(s), c.end.axis(s));
        let (dir_p, dir_s) = ((p_end - p0).signum(), (s_end - s0).signum());
        let (depth, across) = ((p_end - p0).abs(), (s_end - s0).abs());
        let at = |pv: f64, sv: f64| {
            let mut v = c.start;
            v.set_axis(p, pv);
            v.set_axis(s, sv);
            v
        };
        for g in 0..self.grooves {
            let sv = s0 + dir_s * (g as f64 * c.step_mm).min(across);
            // Step 6: over to the next groove, no further than Af.
            if g > 0 && sink(Move::Rapid(at(p0, sv))).is_break() {
                return;
            }
            if depth <= 0.0 {
                continue;
            }
            // Steps 1-3: peck down to the groove's bottom.
            for i in 1..=self.pecks {
                let reached = (i as f64 * c.peck_mm).min(depth);
                if sink(Move::Feed(at(p0 + dir_p * reached, sv))).is_break() {
                    return;
                }
                if i < self.pecks && c.back_off_mm > 0.0 && sink(Move::Rapid(at(p0 + dir_p * (reached - c.back_off_mm).max(0.0), sv))).is_break() {
                    return;
                }
            }
            // Steps 4-5: the relief along the step axis, back toward the start's side (at every
            // groove, the first too, as the help text's steps say), out to Dn.
            let relief_s = sv - dir_s * c.relief_mm;
            if relief_s != sv && sink(Move::Rapid(at(p_end, relief_s))).is_break() {
                return;
            }
            if sink(Move::Rapid(at(p0, relief_s))).is_break() {
                return;
            }
        }
        // Step 7: back to A along the step axis.
        if across > 0.0 {
            let _ = sink(Move::Rapid(at(p0, s0)));
        }
    }
}

impl Expansion for PeckPlan {
    /// How many moves the cycle makes at most: per groove the step over, a feed and a back-off
    /// per peck, the relief and the way out; then the way back (counted within the limit when
    /// laid out).
    fn move_count(&self) -> usize {
        self.grooves * (2 * self.pecks + 3) + 1
    }

    fn each_op(&self, sink: &mut dyn FnMut(crate::motion::Op) -> std::ops::ControlFlow<()>) {
        use crate::motion::Op;
        let mut from = self.c.start;
        self.each_move(&mut |m| {
            let op = match m {
                Move::Rapid(to) => Op::Rapid { from, to },
                Move::Feed(to) => Op::Feed { from, to, feed_mm_min: 0.0 },
            };
            from = op.end_point().unwrap_or(from);
            sink(op)
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(m: &[Move]) -> Vec<(char, f64, f64)> {
        m.iter()
            .map(|m| match m {
                Move::Rapid(v) => ('r', v.x, v.z),
                Move::Feed(v) => ('f', v.x, v.z),
            })
            .collect()
    }

    #[test]
    fn g74_centre_hole_pecks_and_backs_off() {
        // From X0 Z1 to Z-10, peck 4, back-off 0.5: depths 4, back to 3.5, 8, back to 7.5, 11
        // (the bottom), then out to Z1.
        let c = PeckCycle {
            kind: PeckKind::Face,
            start: Vec3::new(0.0, 0.0, 1.0),
            end: Vec3::new(0.0, 0.0, -10.0),
            back_off_mm: 0.5,
            peck_mm: 4.0,
            step_mm: 0.0,
            relief_mm: 0.0,
        };
        let got = pts(&expand(&c, 100).unwrap());
        let want = [('f', 0.0, -3.0), ('r', 0.0, -2.5), ('f', 0.0, -7.0), ('r', 0.0, -6.5), ('f', 0.0, -10.0), ('r', 0.0, 1.0)];
        assert_eq!(got.len(), want.len(), "{got:?}");
        for (g, w) in got.iter().zip(want) {
            assert!(g.0 == w.0 && (g.1 - w.1).abs() < 1e-9 && (g.2 - w.2).abs() < 1e-9, "{got:?}");
        }
    }

    #[test]
    fn g75_steps_across_and_stops_at_the_end() {
        // Grooves from Z0 to Z-5 with step 2: at Z0, -2, -4, -5; relief 0.2 toward the start.
        let c = PeckCycle {
            kind: PeckKind::Groove,
            start: Vec3::new(20.0, 0.0, 0.0),
            end: Vec3::new(18.0, 0.0, -5.0),
            back_off_mm: 0.0,
            peck_mm: 5.0,
            step_mm: 2.0,
            relief_mm: 0.2,
        };
        let m = expand(&c, 100).unwrap();
        let bottoms: Vec<f64> = m.iter().filter_map(|m| if let Move::Feed(v) = m { Some(v.z) } else { None }).collect();
        assert_eq!(bottoms, vec![0.0, -2.0, -4.0, -5.0]);
        // The relief at the second groove moves Z back 0.2 toward the start before X comes out.
        assert!(pts(&m).contains(&('r', 18.0, -1.8)));
        assert_eq!(*m.last().unwrap(), Move::Rapid(Vec3::new(20.0, 0.0, 0.0)));
    }

    #[test]
    fn missing_peck_or_step_and_the_limit() {
        let mut c = PeckCycle {
            kind: PeckKind::Face,
            start: Vec3::new(0.0, 0.0, 1.0),
            end: Vec3::new(5.0, 0.0, -10.0),
            back_off_mm: 0.0,
            peck_mm: 1.0,
            step_mm: 0.0,
            relief_mm: 0.0,
        };
        assert_eq!(expand(&c, 100), Err(PeckError::NoStep));
        c.step_mm = 1.0;
        c.peck_mm = 0.0;
        assert_eq!(expand(&c, 100), Err(PeckError::NoPeck));
        c.peck_mm = 0.001;
        assert_eq!(expand(&c, 1000), Err(PeckError::TooMany));
        // No depth: the grooves alone are counted, before anything is made or cast.
        let flat = PeckCycle {
            kind: PeckKind::Groove,
            start: Vec3::new(20.0, 0.0, 0.0),
            end: Vec3::new(20.0, 0.0, -100.0),
            back_off_mm: 0.0,
            peck_mm: 1.0,
            step_mm: 1e-9,
            relief_mm: 0.0,
        };
        assert_eq!(lay_out(&flat, crate::cycles::MOST_MOVES), Err(PeckError::TooMany));
    }
}
