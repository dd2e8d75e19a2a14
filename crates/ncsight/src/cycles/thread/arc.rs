//! Arc threads G32.2 / G32.3 (seed 002): a thread whose path is an arc. The arc must lie
//! wholly inside one of the four sectors that the diagonals through its centre cut the plane
//! into, so that one axis is the long axis all along (seed 002, function note 1): in the sectors
//! around the first axis's direction the second axis is long, and the other way round.

use crate::geom::ArcGeom;
use crate::motion::{ArcDir, LongAxis, Plane, Vec3};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

/// Why an arc cannot be threaded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ArcThreadError {
    /// The arc crosses a sector boundary at this angle (degrees, from the plane's first axis).
    CrossesSector(f64),
}

/// The long axis of an arc thread, or why there is none.
pub fn long_axis(from: &Vec3, plane: Plane, dir: ArcDir, g: &ArcGeom) -> Result<LongAxis, ArcThreadError> {
    let (a, b, _) = plane.axes();
    let start = (from.axis(b) - g.center.axis(b)).atan2(from.axis(a) - g.center.axis(a));
    let sign = if dir == ArcDir::Ccw { 1.0 } else { -1.0 };
    // Boundaries at 45 + 90 k degrees; one strictly inside the swept angle breaks the rule.
    let tol = 1e-9;
    for k in -8..8 {
        let boundary = FRAC_PI_4 + k as f64 * FRAC_PI_2;
        let along = (boundary - start) * sign;
        if along > tol && along < g.sweep_rad - tol {
            return Err(ArcThreadError::CrossesSector(boundary.to_degrees().rem_euclid(360.0)));
        }
    }
    let mid = start + sign * g.sweep_rad / 2.0;
    // Near the first axis's direction the motion is along the second axis.
    let long = if mid.cos().abs() >= mid.sin().abs() { b } else { a };
    Ok(LongAxis::from_index(long))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::arc_from_radius;

    #[test]
    fn seed_002_example_has_z_long() {
        // G1 X10 Z-15; G32.3 W-10 F2 R10: radius 5 -> 5, Z-15 -> Z-25, centre below.
        let from = Vec3::new(5.0, 0.0, -15.0);
        let to = Vec3::new(5.0, 0.0, -25.0);
        let g = arc_from_radius(from, to, Plane::ZX, ArcDir::Ccw, 10.0, 0.01).unwrap();
        assert!((g.center.z + 20.0).abs() < 1e-9 && (g.center.x - (5.0 - 75f64.sqrt())).abs() < 1e-9);
        assert_eq!(long_axis(&from, Plane::ZX, ArcDir::Ccw, &g), Ok(LongAxis::Z));
    }

    #[test]
    fn crossing_a_diagonal_is_refused() {
        // A quarter circle from the +Z direction to the +X direction crosses 45 degrees.
        let from = Vec3::new(0.0, 0.0, 10.0);
        let to = Vec3::new(10.0, 0.0, 0.0);
        let g = arc_from_radius(from, to, Plane::ZX, ArcDir::Ccw, 10.0, 0.01).unwrap();
        assert_eq!(long_axis(&from, Plane::ZX, ArcDir::Ccw, &g), Err(ArcThreadError::CrossesSector(45.0)));
    }
}
