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
/// long along the path, from the machine angle `start_deg`. Each piece's end lies on the path;
/// its course, straight in radius and angle, stays about `tol_mm` from the path: chords of the
/// path's curve (`curvature` its largest, 1/mm, 0 for a line), each halved while its turn
/// `dθ` at its larger radius `r` departs by more than `r dθ² / 8` (near the centre the angle
/// turns fast: the pieces there are short).
pub fn pieces(at: &dyn Fn(f64) -> (f64, f64, f64), length_mm: f64, curvature: f64, start_deg: f64, tol_mm: f64) -> Vec<Piece> {
    let n = chords(length_mm, curvature, tol_mm);
    let mut out = Vec::with_capacity(n);
    let mut angle = start_deg;
    let mut from = (0.0, at(0.0));
    for i in 1..=n {
        let u = i as f64 / n as f64;
        from = split(at, from, u, &mut angle, length_mm, tol_mm, 0, &mut out);
    }
    out
}

/// The piece from `from` (its fraction and point) to fraction `u`, halved until it is close
/// enough (or 40 halvings, or [`MAX_PIECES`] pieces); returns the end.
#[allow(clippy::too_many_arguments)]
fn split(
    at: &dyn Fn(f64) -> (f64, f64, f64),
    from: (f64, (f64, f64, f64)),
    u: f64,
    angle: &mut f64,
    length_mm: f64,
    tol_mm: f64,
    depth: u32,
    out: &mut Vec<Piece>,
) -> (f64, (f64, f64, f64)) {
    let (u0, p0) = from;
    let p1 = at(u);
    let a1 = angle_near(p1.0, p1.1, *angle);
    let r = p0.0.hypot(p0.1).max(p1.0.hypot(p1.1));
    let turn = (a1 - *angle).abs().to_radians();
    if r * turn * turn / 8.0 <= tol_mm || depth >= 40 || out.len() >= MAX_PIECES {
        *angle = a1;
        out.push(Piece { radius_mm: p1.0.hypot(p1.1), angle_deg: a1, z: p1.2, path_mm: length_mm * (u - u0) });
        return (u, p1);
    }
    let mid = split(at, from, (u0 + u) / 2.0, angle, length_mm, tol_mm, depth + 1, out);
    split(at, mid, u, angle, length_mm, tol_mm, depth + 1, out)
}

/// How many chords of a path `length_mm` long, of largest curvature `curvature` (1/mm), keep
/// within `tol_mm` of it: 1 for a line, at most [`MAX_PIECES`].
fn chords(length_mm: f64, curvature: f64, tol_mm: f64) -> usize {
    let n = if curvature > 0.0 { (length_mm / (8.0 * tol_mm / curvature).sqrt()).ceil() } else { 1.0 };
    if n.is_finite() {
        (n as usize).clamp(1, MAX_PIECES)
    } else {
        MAX_PIECES
    }
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
    fn near_the_centre_the_pieces_are_short() {
        // A line 0.01 mm from the centre of a 10 mm radius: the angle turns nearly 180 degrees
        // within 0.1 mm. Every piece's turn at its radius stays within the tolerance.
        let at = |u: f64| (0.01, -10.0 + 20.0 * u, 0.0);
        let p = pieces(&at, 20.0, 0.0, angle_near(0.01, -10.0, 0.0), 0.001);
        let mut prev = (0.01f64.hypot(10.0), angle_near(0.01, -10.0, 0.0));
        for q in &p {
            let turn = (q.angle_deg - prev.1).abs().to_radians();
            assert!(prev.0.max(q.radius_mm) * turn * turn / 8.0 <= 0.001 + 1e-12, "{q:?} after {prev:?}");
            prev = (q.radius_mm, q.angle_deg);
        }
        assert!((p.last().unwrap().angle_deg - prev.1).abs() < 1e-12);
        assert!((p.iter().map(|q| q.path_mm).sum::<f64>() - 20.0).abs() < 1e-9);
    }

    #[test]
    fn angles_unwrap() {
        assert_eq!(angle_near(-1.0, 0.0, 170.0), 180.0);
        assert!((angle_near(-1.0, -0.001, 179.0) - 180.0).abs() < 0.1);
        assert!((angle_near(1.0, 0.0, 350.0) - 360.0).abs() < 1e-9);
    }
}
