//! G76 compound thread cutting (GSK980TDi help text G76; FANUC 0-T): the depth schedule and the
//! passes. Each pass is the four-step cycle of `cycle.rs`, its cut start moved along the flank.
//!
//! Depth schedule (help text steps 1-10): roughing pass n cuts to `dd x sqrt(n)`, but at least
//! `dmin` deeper than the pass before, until the depth reaches `k - d` (the last roughing pass is
//! at exactly `k - d`); then `m` finishing passes at the full depth k, the first removing the
//! finishing allowance d.

use crate::motion::Vec3;

/// How the roughing depths grow.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Schedule {
    /// Pass n at `dd x sqrt(n)`: the same area of chip each pass (G76; G78 P m = 1).
    Decreasing,
    /// Pass n at `dd x n`: the same depth each pass (G78 P m = 0, "equal-distance infeed").
    Equal,
}

/// A flank of the thread groove: the one on its -Z side or on its +Z side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flank {
    MinusZ,
    PlusZ,
}

/// Where each pass enters the thread groove.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Infeed {
    /// Straight in, no Z shift (G78 P r = 0, "middle").
    Radial,
    /// Along one flank of the groove: every pass's edge on that flank lies on the finished
    /// flank (G76; G78 P r = 1 left = the -Z flank, 2 right = the +Z flank).
    Along(Flank),
    /// The -Z flank, then the +Z flank, pass by pass (G78 P r = 3).
    Alternate,
}

/// The Z shift (mm) of the tool tip, relative to the finished groove's centre, of pass `index`
/// (0-based) at `depth` (radius, mm) of a thread `height_mm` deep, tool angle `angle_deg`. A pass
/// that follows the -Z flank sits `(height - depth) x tan(a/2)` towards -Z, so its -Z edge is
/// on the finished flank; the passes at full depth sit on the centre.
pub fn infeed_shift_mm(infeed: Infeed, index: usize, depth: f64, height_mm: f64, angle_deg: f64) -> f64 {
    let off = (height_mm - depth).max(0.0) * (angle_deg / 2.0).to_radians().tan();
    let flank = match infeed {
        Infeed::Radial => return 0.0,
        Infeed::Along(f) => f,
        Infeed::Alternate if index.is_multiple_of(2) => Flank::MinusZ,
        Infeed::Alternate => Flank::PlusZ,
    };
    match flank {
        Flank::MinusZ => -off,
        Flank::PlusZ => off,
    }
}

/// The depth (radius, mm) of every pass of G76, roughing then finishing.
pub fn depths(k: f64, first: f64, dmin: f64, allowance: f64, finishing: u32) -> Result<Vec<f64>, &'static str> {
    pass_depths(Schedule::Decreasing, k, first, dmin, allowance, finishing)
}

/// The depth (radius, mm) of every pass, roughing then finishing: k the thread height, `first`
/// the first depth dd, `dmin` the least cut, `allowance` the finishing allowance d, `finishing`
/// the number of passes at k.
///
/// Errors when the data cannot make a thread (the text says which word).
pub fn pass_depths(schedule: Schedule, k: f64, first: f64, dmin: f64, allowance: f64, finishing: u32) -> Result<Vec<f64>, &'static str> {
    if !(k > 0.0) {
        return Err("the thread height P(k) must be more than 0");
    }
    if !(first > 0.0) {
        return Err("the first depth Q(dd) must be more than 0");
    }
    if allowance < 0.0 || allowance >= k {
        return Err("the finishing allowance R(d) must be 0 or more and less than the thread height");
    }
    let rough_to = k - allowance;
    let mut out = Vec::new();
    let mut prev = 0.0f64;
    let mut n = 1u32;
    loop {
        let mut d = match schedule {
            Schedule::Decreasing => first * (n as f64).sqrt(),
            Schedule::Equal => first * n as f64,
        };
        if d - prev < dmin {
            d = prev + dmin;
        }
        if d >= rough_to - 1e-9 {
            out.push(rough_to);
            break;
        }
        out.push(d);
        prev = d;
        n += 1;
        if n > 10_000 {
            return Err("the depth schedule needs more than 10000 passes (Q too small)");
        }
    }
    out.extend(std::iter::repeat(k).take(finishing as usize));
    Ok(out)
}

/// Where pass `depth_mm` of a compound cycle cuts: from the cycle's start `a` toward its end
/// point `c` (the root at full depth `height_mm`), shifted `shift_mm` along Z by the infeed, on
/// the cone of `taper_mm` (radius, cut start minus cut end). Deeper passes lie toward the root:
/// at smaller X for an external thread (the start outside the root), larger for an internal one.
pub fn pass_line(a: Vec3, c: Vec3, taper_mm: f64, height_mm: f64, depth_mm: f64, shift_mm: f64) -> (Vec3, Vec3) {
    let outward = if a.x > c.x { 1.0 } else { -1.0 };
    let end_x = c.x + outward * (height_mm - depth_mm);
    let start_z = a.z + shift_mm;
    // On a taper the shifted start stays on the pass's cone.
    let cut_start = Vec3::new(end_x + taper_mm * (c.z - start_z) / (c.z - a.z), a.y, start_z);
    (cut_start, Vec3::new(end_x, a.y, c.z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tac_example() {
        // TAC p139: G76 P020560 Q150 R0.1 / G76 X60.64 Z-62 P3680 Q1800 F6: k 3.68, dd 1.8,
        // dmin 0.15, d 0.1, m 2. Passes: 1.8, 1.8 sqrt 2 = 2.546, 1.8 sqrt 3 = 3.118, then 3.58
        // (k - d; 1.8 sqrt 4 = 3.6 is past it), and 2 finishing passes at 3.68.
        let d = depths(3.68, 1.8, 0.15, 0.1, 2).unwrap();
        let expect = [1.8, 1.8 * 2f64.sqrt(), 1.8 * 3f64.sqrt(), 3.58, 3.68, 3.68];
        assert_eq!(d.len(), expect.len());
        for (a, b) in d.iter().zip(expect) {
            assert!((a - b).abs() < 1e-9, "{d:?}");
        }
    }

    #[test]
    fn dmin_keeps_the_passes_apart() {
        // dd = 0.2, k = 1.0, dmin = 0.15: 0.2, 0.283 -> 0.35, 0.346 -> 0.5, ... never closer than 0.15.
        let d = depths(1.0, 0.2, 0.15, 0.0, 1).unwrap();
        for w in d.windows(2).take(d.len() - 3) {
            assert!(w[1] - w[0] >= 0.15 - 1e-12, "{d:?}");
        }
        assert_eq!(*d.last().unwrap(), 1.0);
    }

    #[test]
    fn equal_depths() {
        // G78 P m = 0: k 1.0, dd 0.3, d 0.1: 0.3, 0.6, 0.9 (= k - d), then 2 passes at 1.0.
        let d = pass_depths(Schedule::Equal, 1.0, 0.3, 0.0, 0.1, 2).unwrap();
        let expect = [0.3, 0.6, 0.9, 1.0, 1.0];
        assert_eq!(d.len(), expect.len(), "{d:?}");
        for (a, b) in d.iter().zip(expect) {
            assert!((a - b).abs() < 1e-9, "{d:?}");
        }
    }

    #[test]
    fn infeed_shifts() {
        // Height 1.5, pass at depth 0.5: 1.0 x tan 30 off the centre; at full depth on it.
        let t = 30f64.to_radians().tan();
        assert_eq!(infeed_shift_mm(Infeed::Radial, 3, 0.5, 1.5, 60.0), 0.0);
        assert!((infeed_shift_mm(Infeed::Along(Flank::PlusZ), 0, 0.5, 1.5, 60.0) - t).abs() < 1e-12);
        assert!((infeed_shift_mm(Infeed::Along(Flank::MinusZ), 0, 0.5, 1.5, 60.0) + t).abs() < 1e-12);
        assert!((infeed_shift_mm(Infeed::Alternate, 0, 0.5, 1.5, 60.0) + t).abs() < 1e-12);
        assert!((infeed_shift_mm(Infeed::Alternate, 1, 0.5, 1.5, 60.0) - t).abs() < 1e-12);
        assert_eq!(infeed_shift_mm(Infeed::Alternate, 1, 1.5, 1.5, 60.0), 0.0);
        // The edge on the followed flank stays on the finished flank: tip z - (depth - y) t at
        // height y is the same line for every depth.
        for d in [0.3, 0.9, 1.5] {
            let s = infeed_shift_mm(Infeed::Along(Flank::MinusZ), 0, d, 1.5, 60.0);
            let at_surface = s - d * t;
            assert!((at_surface + 1.5 * t).abs() < 1e-12);
        }
    }

    #[test]
    fn bad_data() {
        assert!(depths(0.0, 0.1, 0.0, 0.0, 1).is_err());
        assert!(depths(1.0, 0.0, 0.0, 0.0, 1).is_err());
        assert!(depths(1.0, 0.1, 0.0, 1.0, 1).is_err());
        // dd larger than the height: one roughing pass at k - d.
        assert_eq!(depths(1.0, 2.0, 0.0, 0.1, 1).unwrap(), vec![0.9, 1.0]);
    }
}
