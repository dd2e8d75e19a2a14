//! Thread repair (seed 001 section 1; GSK980TDi help "螺纹修复"): re-cutting a damaged thread in
//! its own groove after the part was clamped again at an unknown angle.
//!
//! The operator puts the tool tip into the old groove and records the point M: its X, Z and the
//! spindle's C angle. A thread pass that starts at the one-revolution signal plus Q reaches the
//! long-axis coordinate of M after `d / lead` revolutions, d being the long-axis distance from
//! the pass's start to M (seed 001 1.2.3 "处理流程"). To be in the groove there the spindle must
//! be at C, so
//!
//! `Q = C' - 360 x d / lead  (mod 360)`,
//!
//! where C' is C measured in the direction the spindle turns (C itself when S > 0, `360 - C`
//! when S < 0: the C axis counts positive one way, the thread's angle follows the rotation).

use crate::cycles::thread::wrap_deg;
use crate::motion::{LongAxis, Vec3};

/// A recorded repair position: the point (mm, X a radius) and the spindle's C angle (degrees,
/// positive direction of the C axis, 0 at the one-revolution signal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Recorded {
    pub point: Vec3,
    pub c_deg: f64,
}

/// Why no repair programme can be made.
#[derive(Debug, Clone, PartialEq)]
pub enum RepairError {
    /// Seed 001 1.3 note 3 / help note 5: the recorded point's long-axis coordinate is not between
    /// the start and the end point.
    OutsideSpan { long_axis: LongAxis, recorded: f64, from: f64, to: f64 },
    /// Start and end coincide along the long axis.
    NoThread,
    /// A lead of 0 or less, or a spindle speed of 0.
    BadInput(&'static str),
}

impl std::fmt::Display for RepairError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RepairError::OutsideSpan { long_axis, recorded, from, to } => {
                let (scale, name) = if *long_axis == LongAxis::X { (2.0, "X") } else { (1.0, "Z") };
                write!(
                    f,
                    "the recorded point's {name}{} is not between the start {name}{} and the end {name}{} (GSK988T manual, thread repair 1.3 note 3)",
                    recorded * scale,
                    from * scale,
                    to * scale
                )
            }
            RepairError::NoThread => write!(f, "the start and the end point are the same along the long axis"),
            RepairError::BadInput(what) => write!(f, "{what}"),
        }
    }
}

/// The start angle Q (degrees, 0..360) that makes a thread from `start` to `end` with `lead_mm`
/// pass the recorded point in its groove. `rpm` gives the direction.
pub fn start_angle_deg(start: Vec3, end: Vec3, lead_mm: f64, rpm: f64, recorded: &Recorded) -> Result<f64, RepairError> {
    if !(lead_mm > 0.0) {
        return Err(RepairError::BadInput("the lead must be more than 0"));
    }
    if rpm == 0.0 {
        return Err(RepairError::BadInput("the spindle speed must not be 0"));
    }
    let long_axis = LongAxis::of(&start, &end);
    let i = long_axis.index();
    let (a, b, m) = (start.axis(i), end.axis(i), recorded.point.axis(i));
    if (b - a).abs() < 1e-12 {
        return Err(RepairError::NoThread);
    }
    if m < a.min(b) - 1e-9 || m > a.max(b) + 1e-9 {
        return Err(RepairError::OutsideSpan { long_axis, recorded: m, from: a, to: b });
    }
    let along_rotation = if rpm > 0.0 { recorded.c_deg } else { 360.0 - recorded.c_deg };
    Ok(wrap_deg(along_rotation - 360.0 * (m - a).abs() / lead_mm))
}

/// The two blocks the MDI thread-repair screen generates (seed 001 1.2.3):
/// `G0 X_ Z_` / `G32.1 X_ Z_ F_ Q_ S_ J_ K_`, X as a diameter, Q a whole number of 0.001 degree.
#[derive(Debug, Clone, PartialEq)]
pub struct RepairJob {
    pub start: Vec3,
    pub end: Vec3,
    pub lead_mm: f64,
    pub rpm: f64,
    pub j_mm: Option<f64>,
    pub k_mm: Option<f64>,
    pub recorded: Recorded,
}

impl RepairJob {
    /// Q in 0.001 degree, rounded (the control's resolution, seed 001 Q rule 2).
    pub fn q_counts(&self) -> Result<u32, RepairError> {
        let deg = start_angle_deg(self.start, self.end, self.lead_mm, self.rpm, &self.recorded)?;
        Ok(((deg * 1000.0).round() as u32) % 360_000)
    }

    /// Every number that goes into the blocks is one the control takes (seed 001's ranges for
    /// F, J, K; 8 digits of 0.001 mm for X and Z): NaN, infinity or a 300-digit number never
    /// reaches a block meant to be typed into a controller.
    fn check_ranges(&self) -> Result<(), RepairError> {
        const MAX: f64 = 99_999.999;
        let coords = [2.0 * self.start.x, self.start.z, 2.0 * self.end.x, self.end.z];
        if !coords.iter().all(|v| v.is_finite() && v.abs() <= MAX) {
            return Err(RepairError::BadInput("X and Z must be finite and at most 99999.999 mm"));
        }
        if !(self.lead_mm.is_finite() && self.lead_mm >= 0.001 && self.lead_mm <= 500.0) {
            return Err(RepairError::BadInput("the lead F must be 0.001 to 500 mm (GSK988T manual, G32.1, range of F)"));
        }
        if !(self.rpm.is_finite() && self.rpm.abs() >= 1.0 && self.rpm.abs() <= crate::profile::MAX_RPM) {
            return Err(RepairError::BadInput("the spindle speed S must be 1 to 10000 rpm either way"));
        }
        if self.j_mm.is_some_and(|j| !(j.is_finite() && j.abs() <= MAX)) {
            return Err(RepairError::BadInput("J must be finite, -99999.999 to 99999.999 mm (GSK988T manual, G32.1, range of J)"));
        }
        if self.k_mm.is_some_and(|k| !(k.is_finite() && (0.0..=MAX).contains(&k))) {
            return Err(RepairError::BadInput("K must be finite, 0 to 99999.999 mm (GSK988T manual, G32.1, range of K)"));
        }
        if !self.recorded.c_deg.is_finite() || !self.recorded.point.x.is_finite() || !self.recorded.point.z.is_finite() {
            return Err(RepairError::BadInput("the recorded point must be finite"));
        }
        Ok(())
    }

    /// The programme text, two lines.
    pub fn programme(&self) -> Result<String, RepairError> {
        self.check_ranges()?;
        let q = self.q_counts()?;
        let n = |v: f64| {
            let s = format!("{v:.4}");
            let s = s.trim_end_matches('0');
            if s == "-0." {
                "0.".to_string()
            } else {
                s.to_string()
            }
        };
        let mut second = format!("G32.1 X{} Z{} F{} Q{q} S{}", n(2.0 * self.end.x), n(self.end.z), n(self.lead_mm), self.rpm.round() as i64);
        if let Some(j) = self.j_mm {
            second.push_str(&format!(" J{}", n(j)));
        }
        if let Some(k) = self.k_mm {
            second.push_str(&format!(" K{}", n(k)));
        }
        Ok(format!("G0 X{} Z{}\n{second}\n", n(2.0 * self.start.x), n(self.start.z)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_formula() {
        // Start Z3, end Z-72, lead 2: the tool in the groove at Z-7 when C was 90 degrees.
        // 10 mm is 5 revolutions, so the pass must start at 90 degrees too.
        let rec = Recorded { point: Vec3::new(15.0, 0.0, -7.0), c_deg: 90.0 };
        let q = start_angle_deg(Vec3::new(15.0, 0.0, 3.0), Vec3::new(25.0, 0.0, -72.0), 2.0, 500.0, &rec).unwrap();
        assert!((q - 90.0).abs() < 1e-9);
        // 11 mm is 5.5 revolutions: half a turn earlier.
        let rec = Recorded { point: Vec3::new(15.0, 0.0, -8.0), c_deg: 90.0 };
        let q = start_angle_deg(Vec3::new(15.0, 0.0, 3.0), Vec3::new(25.0, 0.0, -72.0), 2.0, 500.0, &rec).unwrap();
        assert!((q - 270.0).abs() < 1e-9);
        // Turning negative, C counts the other way.
        let q = start_angle_deg(Vec3::new(15.0, 0.0, 3.0), Vec3::new(25.0, 0.0, -72.0), 2.0, -500.0, &rec).unwrap();
        assert!((q - 90.0).abs() < 1e-9);
        // Outside the span: no programme.
        let rec = Recorded { point: Vec3::new(15.0, 0.0, 8.0), c_deg: 0.0 };
        assert!(matches!(start_angle_deg(Vec3::new(15.0, 0.0, 3.0), Vec3::new(25.0, 0.0, -72.0), 2.0, 500.0, &rec), Err(RepairError::OutsideSpan { .. })));
    }

    #[test]
    fn the_two_blocks() {
        let job = RepairJob {
            start: Vec3::new(15.07, 0.0, 3.0),
            end: Vec3::new(25.785, 0.0, -72.0),
            lead_mm: 2.0,
            rpm: 500.0,
            j_mm: Some(1.0),
            k_mm: None,
            recorded: Recorded { point: Vec3::new(20.0, 0.0, -30.5), c_deg: 12.345 },
        };
        let p = job.programme().unwrap();
        // 33.5 mm = 16.75 revolutions: Q = 12.345 - 270 = 102.345 degrees.
        assert_eq!(p, "G0 X30.14 Z3.\nG32.1 X51.57 Z-72. F2. Q102345 S500 J1.\n");
    }
}
