//! The lathe part's axial section, as a drawing shows it: the plane through the spindle axis at
//! angle 0 (above the axis) and 180 degrees (below it), each half the outlines of the material
//! between the bore and the outside, from the chuck's end to the face. A thread's flanks show
//! as they are cut at those angles; a part cut through (parted off) is two outlines.

use super::lathe::LatheStock;

/// A closed outline: (z, y) points in mm, y the radius above the axis (negative below).
pub type Outline = Vec<(f64, f64)>;

/// The outlines of the section (see the module), upper half first.
pub fn outlines(stock: &LatheStock) -> Vec<Outline> {
    let g = stock.grid;
    let mut out = Vec::new();
    for (j, sign) in [(0usize, 1.0f64), (g.ntheta / 2, -1.0)] {
        let mut i = 0;
        while i < g.nz {
            if !solid(stock, j, i) {
                i += 1;
                continue;
            }
            let start = i;
            while i < g.nz && solid(stock, j, i) {
                i += 1;
            }
            out.push(outline(stock, j, start, i - 1, sign));
        }
    }
    out
}

fn solid(stock: &LatheStock, j: usize, i: usize) -> bool {
    let (inner, outer) = stock.material(j, i);
    outer > inner + 1e-4
}

/// How far a point may lie off the line of its neighbours and still be dropped, mm.
const STRAIGHT_MM: f64 = 0.0005;

/// The outline of cells `a..=b` of angle `j`: along the bore from the chuck's side to the face,
/// up the face, back along the outside, down the chuck's side. Each cell's radius is a point at
/// its z; the ends stand half a step beyond the end cells; a point on the straight line of its
/// neighbours (a bore, a taper, a drill's cone) is no corner and is dropped.
fn outline(stock: &LatheStock, j: usize, a: usize, b: usize, sign: f64) -> Outline {
    let g = stock.grid;
    let half = g.dz_mm / 2.0;
    let mut pts: Outline = Vec::new();
    let mut push = |z: f64, r: f32| {
        let p = (z, sign * r as f64);
        let n = pts.len();
        if n >= 2 && off_line(pts[n - 2], pts[n - 1], p) <= STRAIGHT_MM {
            pts[n - 1] = p;
        } else {
            pts.push(p);
        }
    };
    let radius = |i: usize, outside: bool| if outside { stock.material(j, i).1 } else { stock.material(j, i).0 };
    push(g.z(a) - half, radius(a, false));
    (a..=b).for_each(|i| push(g.z(i), radius(i, false)));
    push(g.z(b) + half, radius(b, false));
    push(g.z(b) + half, radius(b, true));
    (a..=b).rev().for_each(|i| push(g.z(i), radius(i, true)));
    push(g.z(a) - half, radius(a, true));
    pts
}

/// How far `q` lies off the straight line from `p` to `r` (its distance from `p` when they meet).
fn off_line(p: (f64, f64), q: (f64, f64), r: (f64, f64)) -> f64 {
    let (dx, dy) = (r.0 - p.0, r.1 - p.1);
    let len = dx.hypot(dy);
    if len < 1e-12 {
        return (q.0 - p.0).hypot(q.1 - p.1);
    }
    ((q.0 - p.0) * dy - (q.1 - p.1) * dx).abs() / len
}
