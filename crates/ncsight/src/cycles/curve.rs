//! The curves a GSK980TDi cuts besides the circle (help text G05/G05.1, G6.2/G6.3, G7.2/G7.3),
//! in plane-local coordinates `(a, b)`: the plane's first and second axes (G18: Z, X as radii).
//! A three-point arc is a circle; an ellipse and a parabola are laid out as chords, none further
//! than `tol_mm` from the curve (the controller interpolates the curve itself; ncsight's chords
//! are its record of it).
//!
//! Angles: the help text measures Q (the ellipse's long axis, the parabola's axis) from the
//! plane's first axis (+Z in G18) turning clockwise on the rear tool post and counter-clockwise
//! on the front one, which is the sense G02 turns in both (the GSK980TDc manual: clockwise seen
//! from +Y). Here that is the `Cw` sense of the plane.

use crate::motion::ArcDir;

/// A point in the plane: (first axis, second axis).
pub type Pt = (f64, f64);

/// At most this many chords per curve; a longer curve gets longer chords
/// (docs/commands/g05_g6_g7.md).
pub const MAX_CHORDS: usize = 20_000;

/// Why the words do not make the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CurveError {
    /// The three points of G05 lie on one line (help text G05 note 2), or two coincide.
    Collinear,
    /// No ellipse of these half axes joins the two points within 180 degrees (help text
    /// G6.2 note 5: the points further apart than the long axis): the chord in the ellipse's
    /// own scale, and the long axis.
    EllipseTooSmall(f64, f64),
    /// The chord from start to end is parallel to the parabola's axis (help text G7.2 note 4).
    ParallelToAxis,
}

/// The centre of the circle through `s`, `m` and `e`, and the way it turns from `s` through `m`
/// to `e`.
pub fn three_point_arc(s: Pt, m: Pt, e: Pt) -> Result<(Pt, ArcDir), CurveError> {
    let (bx, by) = (m.0 - s.0, m.1 - s.1);
    let (cx, cy) = (e.0 - s.0, e.1 - s.1);
    let cross = bx * cy - by * cx;
    let scale = (bx * bx + by * by).max(cx * cx + cy * cy);
    // Collinear within 1e-9 of the points' spread (and any two points the same).
    if scale < 1e-18 || cross.abs() <= 1e-9 * scale {
        return Err(CurveError::Collinear);
    }
    let (b2, c2) = (bx * bx + by * by, cx * cx + cy * cy);
    let d = 2.0 * cross;
    let ux = (cy * b2 - by * c2) / d;
    let uy = (bx * c2 - cx * b2) / d;
    let dir = if cross > 0.0 { ArcDir::Ccw } else { ArcDir::Cw };
    Ok(((s.0 + ux, s.1 + uy), dir))
}

/// The unit vector at `angle_rad` from the plane's first axis, turning the `Cw` way.
fn axis_dir(angle_rad: f64) -> Pt {
    (angle_rad.cos(), -angle_rad.sin())
}

/// Coordinates of `p` in the frame with origin `o`, first axis `d` and second axis `d` turned
/// 90 degrees counter-clockwise (same handedness as the plane).
fn to_frame(p: Pt, o: Pt, d: Pt) -> Pt {
    let (x, y) = (p.0 - o.0, p.1 - o.1);
    (x * d.0 + y * d.1, -x * d.1 + y * d.0)
}

fn from_frame(q: Pt, o: Pt, d: Pt) -> Pt {
    (o.0 + q.0 * d.0 - q.1 * d.1, o.1 + q.0 * d.1 + q.1 * d.0)
}

/// The chords of the ellipse arc from `s` to `e`: half axes `long_mm` (along the axis at
/// `tilt_rad`, see the module doc) and `short_mm`, turning `dir`, at most 180 degrees (help text
/// G6.2 note 7). The points after `s`, the last one `e` exactly.
pub fn ellipse(s: Pt, e: Pt, long_mm: f64, short_mm: f64, tilt_rad: f64, dir: ArcDir, tol_mm: f64) -> Result<Vec<Pt>, CurveError> {
    let d = axis_dir(tilt_rad);
    // In the ellipse's frame, stretched along its second axis, the ellipse is a circle of
    // radius `long_mm` (the stretch keeps the way it turns).
    let k = long_mm / short_mm;
    let sl = to_frame(s, (0.0, 0.0), d);
    let el = to_frame(e, (0.0, 0.0), d);
    let (s2, e2) = ((sl.0, sl.1 * k), (el.0, el.1 * k));
    let (dx, dy) = (e2.0 - s2.0, e2.1 - s2.1);
    let chord = (dx * dx + dy * dy).sqrt();
    let half = chord / 2.0;
    if chord < 1e-12 {
        return Ok(Vec::new());
    }
    if half > long_mm * (1.0 + 1e-9) {
        return Err(CurveError::EllipseTooSmall(chord, 2.0 * long_mm));
    }
    let h = (long_mm * long_mm - half * half).max(0.0).sqrt();
    // The centre of the minor arc: left of the chord for Ccw, right for Cw.
    let side = if dir == ArcDir::Ccw { 1.0 } else { -1.0 };
    let c = (s2.0 + dx / 2.0 - side * h * dy / chord, s2.1 + dy / 2.0 + side * h * dx / chord);
    let a0 = (s2.1 - c.1).atan2(s2.0 - c.0);
    let a1 = (e2.1 - c.1).atan2(e2.0 - c.0);
    let sweep = match dir {
        ArcDir::Ccw => (a1 - a0).rem_euclid(std::f64::consts::TAU),
        ArcDir::Cw => -(a0 - a1).rem_euclid(std::f64::consts::TAU),
    };
    // The ellipse is the circle scaled by at most 1 (long_mm >= short_mm) or k: a chord's
    // deviation is at most the larger half axis times (1 - cos(step / 2)).
    let big = long_mm.max(short_mm);
    let step = 2.0 * (1.0 - (tol_mm / big).min(1.0)).acos();
    let n = ((sweep.abs() / step.max(1e-9)).ceil() as usize).clamp(1, MAX_CHORDS);
    let mut pts = Vec::with_capacity(n);
    for i in 1..n {
        let t = a0 + sweep * i as f64 / n as f64;
        let q = (c.0 + long_mm * t.cos(), (c.1 + long_mm * t.sin()) / k);
        pts.push(from_frame(q, (0.0, 0.0), d));
    }
    pts.push(e);
    Ok(pts)
}

/// The chords of the parabola `v² = 2 p u` (u along its axis at `tilt_rad`, opening one way or
/// the other) from `s` to `e`, turning `dir`. The two points and the axis direction fix it: its
/// vertex lies where both points are on it (help text G7.2). The points after `s`, the last `e`.
pub fn parabola(s: Pt, e: Pt, p_mm: f64, tilt_rad: f64, dir: ArcDir, tol_mm: f64) -> Result<Vec<Pt>, CurveError> {
    let d = axis_dir(tilt_rad);
    let (u1, v1) = to_frame(s, (0.0, 0.0), d);
    let (u2, v2) = to_frame(e, (0.0, 0.0), d);
    if (u1 - u2).abs() < 1e-12 && (v1 - v2).abs() < 1e-12 {
        return Ok(Vec::new());
    }
    let span = (v2 - v1).abs();
    if span <= 1e-9 * (u2 - u1).abs().max(1.0) {
        return Err(CurveError::ParallelToAxis);
    }
    // Opening towards +u or -u: the one that turns `dir` from s to e. Going from s to e along
    // v, u'' = 1/p; the path turns counter-clockwise where u'' and dv have opposite signs (in
    // the frame (u, v), v moving with u bending: the cross product of the tangent (u', 1) dv
    // and its change (u'', 0) dv² is -u'' dv³).
    let dv = v2 - v1;
    let ccw_when_positive = dv < 0.0;
    let p = if (dir == ArcDir::Ccw) == ccw_when_positive { p_mm } else { -p_mm };
    let v0 = (v1 + v2) / 2.0 - p * (u2 - u1) / (v2 - v1);
    let u0 = u1 - (v1 - v0) * (v1 - v0) / (2.0 * p);
    // A chord spanning h along v departs from the curve by h² / (8 |p|) along u.
    let h = (8.0 * p.abs() * tol_mm).sqrt();
    let n = ((span / h.max(1e-9)).ceil() as usize).clamp(1, MAX_CHORDS);
    let mut pts = Vec::with_capacity(n);
    for i in 1..n {
        let v = v1 + dv * i as f64 / n as f64;
        let u = u0 + (v - v0) * (v - v0) / (2.0 * p);
        pts.push(from_frame((u, v), (0.0, 0.0), d));
    }
    pts.push(e);
    Ok(pts)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Pt, b: Pt) -> bool {
        (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9
    }

    #[test]
    fn three_points() {
        // (0,0), (1,1), (2,0): centre (1,0), turning clockwise (the middle point above).
        let (c, dir) = three_point_arc((0.0, 0.0), (1.0, 1.0), (2.0, 0.0)).unwrap();
        assert!(close(c, (1.0, 0.0)) && dir == ArcDir::Cw);
        let (_, dir) = three_point_arc((0.0, 0.0), (1.0, -1.0), (2.0, 0.0)).unwrap();
        assert_eq!(dir, ArcDir::Ccw);
        assert_eq!(three_point_arc((0.0, 0.0), (1.0, 1.0), (2.0, 2.0)), Err(CurveError::Collinear));
        assert_eq!(three_point_arc((0.0, 0.0), (0.0, 0.0), (2.0, 2.0)), Err(CurveError::Collinear));
    }

    #[test]
    fn ellipse_quarter() {
        // Half axes 20 (along the first axis) and 10: from (20, 0) to (0, 10) counter-clockwise
        // about the origin is a quarter. Every chord point lies on x²/400 + y²/100 = 1.
        let pts = ellipse((20.0, 0.0), (0.0, 10.0), 20.0, 10.0, 0.0, ArcDir::Ccw, 0.001).unwrap();
        assert!(pts.len() > 10);
        for p in &pts {
            assert!((p.0 * p.0 / 400.0 + p.1 * p.1 / 100.0 - 1.0).abs() < 1e-9, "{p:?}");
            assert!(p.0 >= -1e-9 && p.1 >= -1e-9);
        }
        assert_eq!(*pts.last().unwrap(), (0.0, 10.0));
        // Clockwise the same two points: the centre on the other side, (20, 10).
        let pts = ellipse((20.0, 0.0), (0.0, 10.0), 20.0, 10.0, 0.0, ArcDir::Cw, 0.001).unwrap();
        for p in &pts {
            let (x, y) = (p.0 - 20.0, p.1 - 10.0);
            assert!((x * x / 400.0 + y * y / 100.0 - 1.0).abs() < 1e-9);
        }
        // Tilted 90 degrees the Cw way: the long axis along -second axis.
        let pts = ellipse((0.0, -20.0), (10.0, 0.0), 20.0, 10.0, std::f64::consts::FRAC_PI_2, ArcDir::Ccw, 0.001).unwrap();
        for p in &pts {
            assert!((p.0 * p.0 / 100.0 + p.1 * p.1 / 400.0 - 1.0).abs() < 1e-9, "{p:?}");
        }
        assert!(matches!(ellipse((0.0, 0.0), (50.0, 0.0), 20.0, 10.0, 0.0, ArcDir::Ccw, 0.001), Err(CurveError::EllipseTooSmall(..))));
        // Q 45 degrees turns the long axis from the first axis the Cw way (as G02 turns): along
        // (1, -1)/sqrt 2. Its ends are then at (14.142, -14.142) and the opposite point; from
        // the first end to the short axis's end (7.071, 7.071) about the origin, Ccw, every
        // point lies on the tilted ellipse. With the other sense the ends would not fit.
        let (c, s) = (std::f64::consts::FRAC_1_SQRT_2, std::f64::consts::FRAC_1_SQRT_2);
        let pts = ellipse((20.0 * c, -20.0 * s), (10.0 * s, 10.0 * c), 20.0, 10.0, std::f64::consts::FRAC_PI_4, ArcDir::Ccw, 0.001).unwrap();
        for p in &pts {
            let (u, v) = (p.0 * c - p.1 * s, p.0 * s + p.1 * c);
            assert!((u * u / 400.0 + v * v / 100.0 - 1.0).abs() < 1e-9, "{p:?}");
        }
        assert!(pts.iter().all(|p| p.0 >= -1e-9));
    }

    #[test]
    fn chords_within_tolerance() {
        // Midpoints of the chords are within 0.001 mm of the ellipse (checked by the
        // algebraic distance, good near the curve).
        let pts = ellipse((30.0, 0.0), (-30.0, 0.0), 30.0, 5.0, 0.0, ArcDir::Ccw, 0.001).unwrap();
        let mut prev = (30.0, 0.0);
        for p in &pts {
            let m = ((prev.0 + p.0) / 2.0, (prev.1 + p.1) / 2.0);
            // Radial shortfall of the midpoint in the ellipse's normalised radius, times the
            // larger half axis, bounds its distance.
            let r = (m.0 * m.0 / 900.0 + m.1 * m.1 / 25.0).sqrt();
            assert!((1.0 - r) * 30.0 <= 0.001 + 1e-9, "{m:?} {r}");
            prev = *p;
        }
    }

    #[test]
    fn parabola_through_both_points() {
        // Axis along the first axis, |p| = 2, from (0, 0) to (4, 4): v0 = 2 - p (u2 - u1) /
        // (v2 - v1) = 2 - p; counter-clockwise opens towards -u (p = -2: vertex (4, 4)).
        for dir in [ArcDir::Ccw, ArcDir::Cw] {
            let pts = parabola((0.0, 0.0), (4.0, 4.0), 2.0, 0.0, dir, 0.001).unwrap();
            assert_eq!(*pts.last().unwrap(), (4.0, 4.0));
            // Fit: u - u0 = (v - v0)² / (2p) with p = ±2 through (0,0) and (4,4).
            let p = if dir == ArcDir::Ccw { -2.0 } else { 2.0 };
            let v0 = 2.0 - p * 4.0 / 4.0;
            let u0 = -(v0 * v0) / (2.0 * p);
            for q in &pts {
                assert!((q.0 - u0 - (q.1 - v0).powi(2) / (2.0 * p)).abs() < 1e-9, "{dir:?} {q:?}");
            }
            // The turning sense: the middle of the curve against the chord.
            let m = pts[pts.len() / 2];
            // The middle to the right of the chord: from s through it to e turns counter-clockwise.
            let cross = 4.0 * m.1 - 4.0 * m.0;
            assert_eq!(cross < 0.0, dir == ArcDir::Ccw, "{dir:?} {m:?}");
        }
        assert_eq!(parabola((0.0, 0.0), (5.0, 0.0), 2.0, 0.0, ArcDir::Cw, 0.001), Err(CurveError::ParallelToAxis));
    }
}
