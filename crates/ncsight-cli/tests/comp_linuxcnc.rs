//! Mill cutter compensation (G41/G42 in G17 with D) against LinuxCNC's `rs274`, on generated
//! contours where both controllers define the same path (docs/compensation.md): every corner is
//! on the inner side (both go to the intersection of the offset paths) or tangent (lines into
//! arcs), and the entry and exit moves run along the first and last edges, so FANUC's type A
//! start-up and cancel and LinuxCNC's entry and exit moves agree. Outer corners differ (FANUC
//! extends the offsets, LinuxCNC rounds the corner with an arc): the goldens
//! `fanuc0m_cutter_comp` hold ncsight's by hand.
//!
//! rs274 runs live on each generated programme. In CI it must be there (`.ci/run` installs
//! LinuxCNC); elsewhere the comparison is left to CI and said so.

mod common;

use std::fmt::Write as _;

/// A small deterministic generator (no dependency for a test's shapes).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

/// A number as both read it: always with a decimal point (FANUC reads `X5` as 0.005 mm).
fn n(v: f64) -> String {
    format!("{v:.4}")
}

/// A programme around `points` (closed), inside, with compensation on `side` ("G41" for a
/// counter-clockwise contour, "G42" for a clockwise one), radius `r`. `arc` > 0 rounds every
/// corner with a tangent arc of that radius.
fn contour(points: &[(f64, f64)], side: &str, arc: f64) -> String {
    let k = points.len();
    let ccw = side == "G41";
    let mut s = String::from("G21 G17 G90 G40 G94\n");
    // The corners' tangent points when rounded.
    let dir = |i: usize| {
        let (a, b) = (points[i], points[(i + 1) % k]);
        let l = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        ((b.0 - a.0) / l, (b.1 - a.1) / l)
    };
    // Each edge runs from (edge start) to (edge end), trimmed by the corner arcs.
    let trim = |i: usize, at_end: bool| -> (f64, f64) {
        let (d_in, d_out) = (dir((i + k - 1) % k), dir(i));
        let turn = (d_in.0 * d_out.1 - d_in.1 * d_out.0).atan2(d_in.0 * d_out.0 + d_in.1 * d_out.1).abs();
        let t = arc * (turn / 2.0).tan();
        let p = points[i];
        if at_end {
            (p.0 - d_in.0 * t, p.1 - d_in.1 * t)
        } else {
            (p.0 + d_out.0 * t, p.1 + d_out.1 * t)
        }
    };
    let start = trim(0, false);
    let d0 = dir(0);
    let entry = (start.0 - d0.0 * 10.0, start.1 - d0.1 * 10.0);
    let _ = writeln!(s, "G00 X{} Y{} Z5.", n(entry.0), n(entry.1));
    let _ = writeln!(s, "G01 Z-2. F300.");
    let _ = writeln!(s, "{side} D1 G01 X{} Y{}", n(start.0), n(start.1));
    for i in 0..k {
        let j = (i + 1) % k;
        let end = trim(j, true);
        let _ = writeln!(s, "G01 X{} Y{}", n(end.0), n(end.1));
        if arc > 0.0 {
            let next = trim(j, false);
            let _ = writeln!(s, "{} X{} Y{} R{}", if ccw { "G03" } else { "G02" }, n(next.0), n(next.1), n(arc));
        }
    }
    // Out along the first edge again, then cancelled along it.
    let exit = (start.0 + d0.0 * 10.0, start.1 + d0.1 * 10.0);
    let _ = writeln!(s, "G40 G01 X{} Y{}", n(exit.0), n(exit.1));
    let _ = writeln!(s, "G00 Z5.\nM30");
    s
}

/// A convex polygon of `k` vertices around (cx, cy), counter-clockwise.
fn convex(rng: &mut Lcg, k: usize) -> Vec<(f64, f64)> {
    let (cx, cy, rad) = (rng.range(-50.0, 50.0), rng.range(-50.0, 50.0), rng.range(25.0, 60.0));
    let phase = rng.range(0.0, std::f64::consts::TAU);
    (0..k)
        .map(|i| {
            let a = phase + std::f64::consts::TAU * (i as f64 + rng.range(-0.2, 0.2)) / k as f64;
            let r = rad * rng.range(0.85, 1.0);
            (cx + r * a.cos(), cy + r * a.sin())
        })
        .collect()
}

#[test]
fn cutter_compensation_matches_linuxcnc_where_both_define_the_path() {
    let found = std::process::Command::new("rs274").arg("-h").output().is_ok();
    if !found {
        assert!(std::env::var_os("CI").is_none(), "rs274 (Debian package linuxcnc-uspace) is missing in CI");
        eprintln!("comp_linuxcnc: rs274 is not installed here: the comparison runs in CI only");
        return;
    }
    let tmp = std::env::temp_dir().join(format!("ncsight-comp-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let mut rng = Lcg(18);
    let mut compared = 0;
    for case in 0..40 {
        let r = rng.range(0.5, 4.0);
        let k = 3 + case % 6;
        let mut points = convex(&mut rng, k);
        let side = if case % 2 == 0 { "G41" } else { "G42" };
        if side == "G42" {
            points.reverse();
        }
        let arc = if case % 3 == 0 { r + rng.range(1.0, 5.0) } else { 0.0 };
        let text = contour(&points, side, arc);
        let ngc = tmp.join(format!("c{case}.ngc"));
        std::fs::write(&ngc, &text).unwrap();
        // rs274's tool table is in inches: the diameter 2r in inches.
        let tools = tmp.join(format!("c{case}.tbl"));
        std::fs::write(&tools, format!("T1 P1 D{:.8} ;\n", 2.0 * r / 25.4)).unwrap();
        let setup = tmp.join(format!("c{case}.toml"));
        std::fs::write(&setup, format!("[[offset]]\nnumber = 1\nradius_mm = {r}\n")).unwrap();
        let out = std::process::Command::new("rs274").arg("-t").arg(&tools).arg("-g").arg(&ngc).output().unwrap();
        let theirs_text =
            String::from_utf8_lossy(&out.stdout).lines().map(|l| l.trim_start().split_once("N..... ").map_or(l, |(_, r)| r)).collect::<Vec<_>>().join("\n");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success() && theirs_text.contains("PROGRAM_END()"), "case {case}: rs274 refused it: {stderr}\n{theirs_text}\n{text}");
        let (code, ours_text, err) =
            common::ncsight(&["run", ngc.to_str().unwrap(), "--machine", "fanuc0m", "--setup", setup.to_str().unwrap(), "--format", "canon"]);
        assert_eq!(code, 0, "case {case}: {err}\n{text}");
        let what = format!("case {case} ({side}, r {r:.3}, {k} corners, arcs {arc:.3})\n{text}");
        compared += common::same_calls(&what, &common::motion_calls(&ours_text), &common::motion_calls(&theirs_text));
    }
    assert!(compared > 300, "only {compared} calls compared");
    std::fs::remove_dir_all(&tmp).ok();
}
