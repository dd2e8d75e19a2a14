//! Plane-local geometry shared by every consumer: arcs from R or centre offsets, arc length.

use crate::motion::{ArcDir, Op, Plane, Vec3};
use std::f64::consts::TAU;

/// An arc resolved in its plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcGeom {
    pub center: Vec3,
    pub radius: f64,
    /// Swept angle, radians, always positive (direction in `dir`).
    pub sweep_rad: f64,
}

/// Why an arc cannot be made.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ArcError {
    /// |R| is shorter than half the chord by more than the tolerance: (R, half chord).
    RadiusTooSmall(f64, f64),
    /// Start and end radii differ by more than the tolerance: (start radius, end radius).
    RadiusMismatch(f64, f64),
    /// R with start = end: a zero-degree arc (TDi help G02/03 note 3).
    ZeroArcWithR,
}

fn plane_coords(p: &Vec3, plane: Plane) -> (f64, f64) {
    let (a, b, _) = plane.axes();
    (p.axis(a), p.axis(b))
}

fn angle_of(c: (f64, f64), p: (f64, f64)) -> f64 {
    (p.1 - c.1).atan2(p.0 - c.0)
}

fn sweep(start: f64, end: f64, dir: ArcDir, full_if_equal: bool) -> f64 {
    let mut d = match dir {
        ArcDir::Ccw => end - start,
        ArcDir::Cw => start - end,
    };
    d = d.rem_euclid(TAU);
    if d < 1e-12 && full_if_equal {
        d = TAU;
    }
    d
}

/// Arc from radius `r` (negative: more than 180 degrees, as FANUC and GSK say).
pub fn arc_from_radius(from: Vec3, to: Vec3, plane: Plane, dir: ArcDir, r: f64, tol_mm: f64) -> Result<ArcGeom, ArcError> {
    let (a, b, n) = plane.axes();
    let s = plane_coords(&from, plane);
    let e = plane_coords(&to, plane);
    let (dx, dy) = (e.0 - s.0, e.1 - s.1);
    let chord = (dx * dx + dy * dy).sqrt();
    if chord < 1e-9 {
        return Err(ArcError::ZeroArcWithR);
    }
    let half = chord / 2.0;
    let rad = r.abs();
    if rad < half - tol_mm {
        return Err(ArcError::RadiusTooSmall(rad, half));
    }
    let h = (rad * rad - half * half).max(0.0).sqrt();
    // Unit normal to the left of the chord direction.
    let (lx, ly) = (-dy / chord, dx / chord);
    // Minor arc: centre to the left for CCW, to the right for CW; R < 0 flips it.
    let mut side = if dir == ArcDir::Ccw { 1.0 } else { -1.0 };
    if r < 0.0 {
        side = -side;
    }
    let c = (s.0 + dx / 2.0 + side * h * lx, s.1 + dy / 2.0 + side * h * ly);
    let mut center = Vec3::default();
    center.set_axis(a, c.0);
    center.set_axis(b, c.1);
    center.set_axis(n, from.axis(n));
    let radius = rad.max(half);
    let sw = sweep(angle_of(c, s), angle_of(c, e), dir, false);
    Ok(ArcGeom { center, radius, sweep_rad: sw })
}

/// Arc from the centre (already absolute). Start = end in the plane is a full circle.
pub fn arc_from_center(from: Vec3, to: Vec3, plane: Plane, dir: ArcDir, center: Vec3, tol_mm: f64) -> Result<ArcGeom, ArcError> {
    let s = plane_coords(&from, plane);
    let e = plane_coords(&to, plane);
    let c = plane_coords(&center, plane);
    let rs = ((s.0 - c.0).powi(2) + (s.1 - c.1).powi(2)).sqrt();
    let re = ((e.0 - c.0).powi(2) + (e.1 - c.1).powi(2)).sqrt();
    if (rs - re).abs() > tol_mm {
        return Err(ArcError::RadiusMismatch(rs, re));
    }
    let same = (s.0 - e.0).abs() < 1e-9 && (s.1 - e.1).abs() < 1e-9;
    let sw = sweep(angle_of(c, s), angle_of(c, e), dir, same);
    Ok(ArcGeom { center, radius: rs, sweep_rad: sw })
}

/// Length of a (helical) arc: in-plane arc length combined with the travel along the normal.
pub fn arc_length(from: &Vec3, to: &Vec3, plane: Plane, g: &ArcGeom) -> f64 {
    let (_, _, n) = plane.axes();
    let planar = g.radius * g.sweep_rad;
    let normal = to.axis(n) - from.axis(n);
    (planar * planar + normal * normal).sqrt()
}

/// The point at fraction `f` (0..1) along an arc, for consumers that sample it.
pub fn arc_point(from: &Vec3, to: &Vec3, plane: Plane, dir: ArcDir, g: &ArcGeom, f: f64) -> Vec3 {
    let (a, b, n) = plane.axes();
    let c = plane_coords(&g.center, plane);
    let s = plane_coords(from, plane);
    let a0 = angle_of(c, s);
    let ang = match dir {
        ArcDir::Ccw => a0 + f * g.sweep_rad,
        ArcDir::Cw => a0 - f * g.sweep_rad,
    };
    let mut p = Vec3::default();
    p.set_axis(a, c.0 + g.radius * ang.cos());
    p.set_axis(b, c.1 + g.radius * ang.sin());
    p.set_axis(n, from.axis(n) + f * (to.axis(n) - from.axis(n)));
    p
}

/// The smallest and largest coordinate an arc reaches on each axis: its ends, and the quadrant
/// points of its circle that lie within its sweep.
pub fn arc_extent(from: &Vec3, to: &Vec3, plane: Plane, dir: ArcDir, g: &ArcGeom) -> (Vec3, Vec3) {
    let (a, b, _) = plane.axes();
    let mut lo = Vec3::new(from.x.min(to.x), from.y.min(to.y), from.z.min(to.z));
    let mut hi = Vec3::new(from.x.max(to.x), from.y.max(to.y), from.z.max(to.z));
    let c = plane_coords(&g.center, plane);
    let start = angle_of(c, plane_coords(from, plane));
    for k in 0..4 {
        let quadrant = k as f64 * TAU / 4.0;
        // How far along the sweep the quadrant point lies, in the arc's direction.
        let along = match dir {
            ArcDir::Ccw => (quadrant - start).rem_euclid(TAU),
            ArcDir::Cw => (start - quadrant).rem_euclid(TAU),
        };
        if along <= g.sweep_rad {
            let (axis, value) = match k {
                0 => (a, c.0 + g.radius),
                1 => (b, c.1 + g.radius),
                2 => (a, c.0 - g.radius),
                _ => (b, c.1 - g.radius),
            };
            lo.set_axis(axis, lo.axis(axis).min(value));
            hi.set_axis(axis, hi.axis(axis).max(value));
        }
    }
    (lo, hi)
}

/// The geometry of an `Op::Arc` or `Op::ThreadArc` from its stored fields.
pub fn arc_geom_of(op: &Op) -> Option<ArcGeom> {
    match op {
        Op::Arc { from, to, center, plane, dir, .. } | Op::ThreadArc { from, to, center, plane, dir, .. } => {
            arc_from_center(*from, *to, *plane, *dir, *center, f64::INFINITY).ok()
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn radius_arcs_pick_the_right_centre() {
        let s = Vec3::new(10.0, 2.0, 0.0);
        let e = Vec3::new(20.0, 2.0, 0.0);
        let g = arc_from_radius(s, e, Plane::XY, ArcDir::Cw, 5.0, 0.01).unwrap();
        assert!((g.center.x - 15.0).abs() < 1e-9 && (g.center.y - 2.0).abs() < 1e-9);
        assert!((g.sweep_rad - PI).abs() < 1e-9);
        // Quarter circle, CCW from (1,0) to (0,1) with R1: centre at the origin.
        let g = arc_from_radius(Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0), Plane::XY, ArcDir::Ccw, 1.0, 0.01).unwrap();
        assert!(g.center.x.abs() < 1e-9 && g.center.y.abs() < 1e-9);
        assert!((g.sweep_rad - PI / 2.0).abs() < 1e-9);
        // R negative: the major arc, centre at (1,1), 270 degrees.
        let g = arc_from_radius(Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0), Plane::XY, ArcDir::Ccw, -1.0, 0.01).unwrap();
        assert!((g.center.x - 1.0).abs() < 1e-9 && (g.center.y - 1.0).abs() < 1e-9);
        assert!((g.sweep_rad - 1.5 * PI).abs() < 1e-9);
    }

    #[test]
    fn centre_arcs_and_full_circles() {
        let s = Vec3::new(1.0, 0.0, 0.0);
        let g = arc_from_center(s, s, Plane::XY, ArcDir::Cw, Vec3::default(), 0.01).unwrap();
        assert!((g.sweep_rad - 2.0 * PI).abs() < 1e-9);
        assert!(matches!(arc_from_center(s, Vec3::new(0.0, 2.0, 0.0), Plane::XY, ArcDir::Cw, Vec3::default(), 0.01), Err(ArcError::RadiusMismatch(..))));
        // ZX plane: from Z=0,X=1 ... CW seen from +Y.
        let g = arc_from_center(Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 1.0), Plane::ZX, ArcDir::Ccw, Vec3::default(), 0.01).unwrap();
        // In (Z, X) coordinates the start is (0,1) at 90 deg, the end (1,0) at 0 deg: CCW is 270 deg.
        assert!((g.sweep_rad - 1.5 * PI).abs() < 1e-9);
        let mid = arc_point(&Vec3::new(1.0, 0.0, 0.0), &Vec3::new(0.0, 0.0, 1.0), Plane::ZX, ArcDir::Ccw, &g, 1.0);
        assert!((mid.z - 1.0).abs() < 1e-9 && mid.x.abs() < 1e-9);
    }
}
