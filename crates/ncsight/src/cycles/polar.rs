//! Polar coordinate interpolation (G12.1/G13.1): a path programmed in the Cartesian plane of the
//! linear axis X and the hypothetical axis C (here `(x, c)`, lengths) is made by the linear
//! axis's radius and the rotary axis's angle. The controller interpolates the path exactly;
//! ncsight records it as pieces, each a radius change with a turn, short enough that the
//! straight-in-(r, angle) piece stays within `tol_mm` of the path.

/// At most this many pieces per move; a longer move gets longer pieces.
pub const MAX_PIECES: usize = 20_000;

/// One piece of a move in the machine's terms: the radius and the angle at its end (degrees,
/// unwrapped: no jump of 360), the third axis there, and the path length it covers, mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    pub radius_mm: f64,
    pub angle_deg: f64,
    pub z: f64,
    pub path_mm: f64,
}

/// The angle of `(x, c)` in degrees, unwrapped to lie within 180 of `near_deg`.
pub fn angle_near(x: f64, c: f64, near_deg: f64) -> f64 {
    let a = c.atan2(x).to_degrees();
    a + 360.0 * ((near_deg - a) / 360.0).round()
}

/// The pieces of a move whose point at fraction `u` (0..1) is `at(u)` = (x, c, z), `length_mm`
/// long along the path, from the machine angle `start_deg`. Pieces follow the path at most
/// `tol_mm` off it, both as chords of the path (`curvature` the path's largest curvature, 1/mm,
/// 0 for a line) and as the polar straight line between its ends (the angle step at most
/// sqrt(8 tol / r)).
pub fn pieces(at: &dyn Fn(f64) -> (f64, f64, f64), length_mm: f64, curvature: f64, start_deg: f64, tol_mm: f64) -> Vec<Piece> {
    // The turn and the largest radius along the path, from a fine sampling.
    const PROBE: usize = 64;
    let (mut turn, mut r_max, mut last) = (0.0f64, 0.0f64, start_deg);
    for i in 0..=PROBE {
        let (x, c, _) = at(i as f64 / PROBE as f64);
        let a = angle_near(x, c, last);
        turn += (a - last).abs();
        last = a;
        r_max = r_max.max(x.hypot(c));
    }
    let angle_step = if r_max > 0.0 { (8.0 * tol_mm / r_max).sqrt().to_degrees() } else { 360.0 };
    let by_angle = ((turn / angle_step).ceil() as usize).min(MAX_PIECES);
    let n = by_angle.max(chords(length_mm, curvature, tol_mm));
    let mut out = Vec::with_capacity(n);
    let mut angle = start_deg;
    for i in 1..=n {
        let (x, c, z) = at(i as f64 / n as f64);
        angle = angle_near(x, c, angle);
        out.push(Piece { radius_mm: x.hypot(c), angle_deg: angle, z, path_mm: length_mm / n as f64 });
    }
    out
}

/// How many chords of a path `length_mm` long, of largest curvature `curvature` (1/mm), keep
/// within `tol_mm` of it: 1 for a line, at most [`MAX_PIECES`].
fn chords(length_mm: f64, curvature: f64, tol_mm: f64) -> usize {
    let n = if curvature > 0.0 { (length_mm / (8.0 * tol_mm / curvature).sqrt()).ceil() } else { 1.0 };
    if n.is_finite() { (n as usize).clamp(1, MAX_PIECES) } else { MAX_PIECES }
}

/// Cylindrical interpolation (G07.1): the pieces of a move on the cylinder of `radius_mm`
/// unrolled, `at(u)` = (x, y, z) with y `sign` times the arc length of C. The machine's C is
/// linear in y, so a line of the unrolled plane is one piece and an arc is chords of it.
pub fn unrolled(at: &dyn Fn(f64) -> (f64, f64, f64), length_mm: f64, curvature: f64, radius_mm: f64, sign: f64, tol_mm: f64) -> Vec<Piece> {
    let n = chords(length_mm, curvature, tol_mm);
    (1..=n)
        .map(|i| {
            let (x, y, z) = at(i as f64 / n as f64);
            let angle_deg = if radius_mm > 0.0 { (sign * y / radius_mm).to_degrees() } else { 0.0 };
            Piece { radius_mm: x, angle_deg, z, path_mm: length_mm / n as f64 }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_across_the_face() {
        // A line at x = 10 from c = -10 to c = 10: the radius goes 14.14 -> 10 -> 14.14, the
        // angle -45 -> 45 degrees; every piece end lies on the line.
        let at = |u: f64| (10.0, -10.0 + 20.0 * u, 0.0);
        let p = pieces(&at, 20.0, 0.0, -45.0, 0.001);
        assert!(p.len() > 50, "{}", p.len());
        let last = p.last().unwrap();
        assert!((last.angle_deg - 45.0).abs() < 1e-9 && (last.radius_mm - 200f64.sqrt()).abs() < 1e-9);
        for q in &p {
            let (x, c) = (q.radius_mm * q.angle_deg.to_radians().cos(), q.radius_mm * q.angle_deg.to_radians().sin());
            assert!((x - 10.0).abs() < 1e-9, "{q:?}");
            assert!(c >= -10.0 - 1e-9 && c <= 10.0 + 1e-9);
        }
        assert!((p.iter().map(|q| q.path_mm).sum::<f64>() - 20.0).abs() < 1e-9);
    }

    #[test]
    fn unrolled_line_is_one_piece() {
        // Radius 20: 10 mm along the unrolled C is 28.648 degrees; Z moves with it.
        let at = |u: f64| (20.0, 10.0 * u, -5.0 * u);
        let p = unrolled(&at, 125f64.sqrt(), 0.0, 20.0, 1.0, 0.001);
        assert_eq!(p.len(), 1);
        assert!((p[0].angle_deg - 28.64788975654116).abs() < 1e-9 && p[0].z == -5.0 && p[0].radius_mm == 20.0);
        let q = unrolled(&at, 125f64.sqrt(), 0.0, 20.0, -1.0, 0.001);
        assert!((q[0].angle_deg + 28.64788975654116).abs() < 1e-9);
    }

    #[test]
    fn angles_unwrap() {
        assert_eq!(angle_near(-1.0, 0.0, 170.0), 180.0);
        assert!((angle_near(-1.0, -0.001, 179.0) - 180.0).abs() < 0.1);
        assert!((angle_near(1.0, 0.0, 350.0) - 360.0).abs() < 1e-9);
    }
}
