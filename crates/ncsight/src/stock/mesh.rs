//! The cut stock as a closed triangle mesh (for `simulate --stl`): triangles with their outward
//! normals, in programme coordinates (mm), handed one by one to the caller (nothing is held).
//!
//! Lathe: the part revolved about Z (x = r cos theta, y = r sin theta), its outside, its bore and
//! the two end faces; where no material is left the outside meets the bore (zero thickness),
//! so the mesh stays closed. Mill: the cut top surface, the four sides and the bottom. The grid
//! is sampled at most [`MAX_ACROSS`] by [`MAX_ALONG`] (coarser for a fine grid: the mill takes the
//! deepest cell of each sample, so no cut is lost; the lathe the surface at each sampled angle).

use super::lathe::LatheStock;
use super::mill::MillStock;
use crate::motion::Vec3;

/// The most samples around (lathe) or across (mill).
pub const MAX_ACROSS: usize = 180;
/// The most samples along Z (lathe) or along X and Y (mill).
pub const MAX_ALONG: usize = 800;

/// One triangle: its outward normal and corners, counter-clockwise seen from outside.
pub type Triangle = (Vec3, [Vec3; 3]);

fn normal(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    let (u, v) = (b - a, c - a);
    let n = Vec3::new(u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x);
    let l = (n.x * n.x + n.y * n.y + n.z * n.z).sqrt();
    if l > 0.0 {
        Vec3::new(n.x / l, n.y / l, n.z / l)
    } else {
        Vec3::default()
    }
}

/// A quad a-b-c-d (counter-clockwise from outside) as two triangles.
fn quad(a: Vec3, b: Vec3, c: Vec3, d: Vec3, each: &mut dyn FnMut(Triangle)) {
    each((normal(a, b, c), [a, b, c]));
    each((normal(a, c, d), [a, c, d]));
}

/// Every `step`-th index of `0..n`, and the last.
fn samples(n: usize, max: usize) -> Vec<usize> {
    let step = n.div_ceil(max).max(1);
    let mut v: Vec<usize> = (0..n).step_by(step).collect();
    if v.last() != Some(&(n - 1)) {
        v.push(n - 1);
    }
    v
}

/// The lathe part's triangles; returns how many there were.
pub fn lathe(stock: &LatheStock, each: &mut dyn FnMut(Triangle)) -> u32 {
    let g = stock.grid;
    let thetas = samples(g.ntheta, MAX_ACROSS);
    let zs = samples(g.nz, MAX_ALONG);
    let mut n = 0u32;
    let mut count = |t: Triangle| {
        n += 1;
        each(t)
    };
    // The radii at (theta sample, z cell): the bore, and the outside no smaller than the bore.
    let radii = |j: usize, i: usize| {
        let (inner, outer) = stock.material(j, i);
        let inner = inner.max(0.0) as f64;
        (inner, (outer as f64).max(inner))
    };
    let point = |r: f64, j: usize, z: f64| {
        let a = (j as f64 * g.dtheta_deg()).to_radians();
        Vec3::new(r * a.cos(), r * a.sin(), z)
    };
    for (k, &j) in thetas.iter().enumerate() {
        let j2 = thetas[(k + 1) % thetas.len()];
        let jn = if k + 1 == thetas.len() { g.ntheta } else { j2 };
        for w in zs.windows(2) {
            let (i, i2) = (w[0], w[1]);
            let (z, z2) = (g.z(i), g.z(i2));
            let (in_a, out_a) = radii(j, i);
            let (in_b, out_b) = radii(j2, i);
            let (in_c, out_c) = radii(j2, i2);
            let (in_d, out_d) = radii(j, i2);
            // The outside, facing away from the axis; the bore, facing it.
            quad(point(out_a, j, z), point(out_b, jn, z), point(out_c, jn, z2), point(out_d, j, z2), &mut count);
            quad(point(in_d, j, z2), point(in_c, jn, z2), point(in_b, jn, z), point(in_a, j, z), &mut count);
        }
        // The end faces: the chuck's end (cell 0, facing -Z) and the face (the last cell, +Z).
        let (chuck, face) = (zs[0], *zs.last().expect("a grid has cells"));
        let (zc, zf) = (g.z(chuck), g.z(face));
        let (in_a, out_a) = radii(j, chuck);
        let (in_b, out_b) = radii(j2, chuck);
        quad(point(in_a, j, zc), point(in_b, jn, zc), point(out_b, jn, zc), point(out_a, j, zc), &mut count);
        let (in_a, out_a) = radii(j, face);
        let (in_b, out_b) = radii(j2, face);
        quad(point(out_a, j, zf), point(out_b, jn, zf), point(in_b, jn, zf), point(in_a, j, zf), &mut count);
    }
    n
}

/// The mill block's triangles; returns how many there were.
pub fn mill(stock: &MillStock, each: &mut dyn FnMut(Triangle)) -> u32 {
    let (xs, ys) = (samples(stock.nx, MAX_ALONG), samples(stock.ny, MAX_ALONG));
    let b = stock.block;
    // The deepest cell of each sample's span, so that no cut is lost when sampling.
    let height = |xi: usize, yi: usize| -> f64 {
        let (i0, i1) = (xs[xi], xs.get(xi + 1).copied().unwrap_or(stock.nx));
        let (j0, j1) = (ys[yi], ys.get(yi + 1).copied().unwrap_or(stock.ny));
        let mut z = f32::MAX;
        for j in j0..j1.max(j0 + 1) {
            for i in i0..i1.max(i0 + 1) {
                z = z.min(stock.top[j * stock.nx + i]);
            }
        }
        (z as f64).max(b.min_mm[2])
    };
    let x_at = |xi: usize| {
        if xi == 0 {
            b.min_mm[0]
        } else if xi + 1 >= xs.len() {
            b.max_mm[0]
        } else {
            b.min_mm[0] + (xs[xi] as f64 + 0.5) * stock.cell_mm
        }
    };
    let y_at = |yi: usize| {
        if yi == 0 {
            b.min_mm[1]
        } else if yi + 1 >= ys.len() {
            b.max_mm[1]
        } else {
            b.min_mm[1] + (ys[yi] as f64 + 0.5) * stock.cell_mm
        }
    };
    let mut n = 0u32;
    let mut count = |t: Triangle| {
        n += 1;
        each(t)
    };
    let top = |xi: usize, yi: usize| Vec3::new(x_at(xi), y_at(yi), height(xi, yi));
    let bottom = |xi: usize, yi: usize| Vec3::new(x_at(xi), y_at(yi), b.min_mm[2]);
    let (nx, ny) = (xs.len(), ys.len());
    for yi in 0..ny - 1 {
        for xi in 0..nx - 1 {
            quad(top(xi, yi), top(xi + 1, yi), top(xi + 1, yi + 1), top(xi, yi + 1), &mut count);
            quad(bottom(xi, yi + 1), bottom(xi + 1, yi + 1), bottom(xi + 1, yi), bottom(xi, yi), &mut count);
        }
    }
    // The four sides, from the bottom edge up to the cut top.
    for xi in 0..nx - 1 {
        quad(bottom(xi, 0), bottom(xi + 1, 0), top(xi + 1, 0), top(xi, 0), &mut count);
        quad(bottom(xi + 1, ny - 1), bottom(xi, ny - 1), top(xi, ny - 1), top(xi + 1, ny - 1), &mut count);
    }
    for yi in 0..ny - 1 {
        quad(bottom(0, yi + 1), bottom(0, yi), top(0, yi), top(0, yi + 1), &mut count);
        quad(bottom(nx - 1, yi), bottom(nx - 1, yi + 1), top(nx - 1, yi + 1), top(nx - 1, yi), &mut count);
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::{Bar, Block};

    /// Every edge of a closed mesh is shared by exactly two triangles, in opposite directions.
    fn closed(tris: &[Triangle]) -> bool {
        use std::collections::HashMap;
        let key = |p: &Vec3| ((p.x * 1e4).round() as i64, (p.y * 1e4).round() as i64, (p.z * 1e4).round() as i64);
        let mut edges: HashMap<((i64, i64, i64), (i64, i64, i64)), i32> = HashMap::new();
        for (_, t) in tris {
            for k in 0..3 {
                let (a, b) = (key(&t[k]), key(&t[(k + 1) % 3]));
                if a == b {
                    continue;
                }
                *edges.entry((a, b)).or_default() += 1;
                *edges.entry((b, a)).or_default() -= 1;
            }
        }
        edges.values().all(|v| *v == 0)
    }

    #[test]
    fn a_bar_and_a_block_are_closed() {
        let stock = LatheStock::new(Bar { diameter_mm: 40.0, length_mm: 10.0, bore_mm: 10.0, front_z_mm: 0.0 }, false, 0.5, 36);
        let mut tris = Vec::new();
        let n = lathe(&stock, &mut |t| tris.push(t));
        assert_eq!(n as usize, tris.len());
        assert!(closed(&tris));
        // The outside's normals point away from the axis.
        let (nrm, t) = tris[0];
        assert!(nrm.x * t[0].x + nrm.y * t[0].y > 0.0, "{nrm:?} {t:?}");
        let block = MillStock::new(Block { min_mm: [0.0, 0.0, -5.0], max_mm: [10.0, 8.0, 0.0] }, 0.5);
        let mut tris = Vec::new();
        mill(&block, &mut |t| tris.push(t));
        assert!(closed(&tris));
    }
}
