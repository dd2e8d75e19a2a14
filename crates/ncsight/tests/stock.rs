//! The stock simulation (issue 7): the cut surface follows the spindle angle of every record.

use ncsight::motion::Vec3;
use ncsight::repair::{Recorded, RepairJob};
use ncsight::stock::measure::{simulate, SimOptions};
use ncsight::stock::{Bar, Setup};
use ncsight::Record;

mod common;

fn records(machine: &str, params: &[&str], text: &str) -> Vec<Record> {
    let (records, diags) = common::run_plain(machine, params, text);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    records
}

fn bar(d: f64, l: f64) -> Setup {
    Setup { stock: Some(Bar { diameter_mm: d, length_mm: l, bore_mm: 0.0, front_z_mm: 0.0 }), ..Setup::default() }
}

fn opts(dz: f64, dtheta: f64) -> SimOptions {
    SimOptions { dz_mm: Some(dz), dtheta_deg: Some(dtheta), expect: None, ..SimOptions::default() }
}

#[test]
fn one_pass_is_the_tool_v_shifted_by_lead_x_theta() {
    // One G32 pass, lead 2, 1 mm deep (radius 19 in a 40 mm bar), sharp 60-degree tool.
    let recs = records("gsk980tdi", &[], "M3 S100\nG0 X38 Z5\nG32 Z-30 F2\nG0 X50\nM30\n");
    let sim = simulate(&recs, &bar(40.0, 40.0), &opts(0.01, 1.0)).unwrap();
    let g = sim.stock.grid;
    let half = 30f64.to_radians().tan();
    for j in [0usize, 45, 90, 200, 359] {
        let row = sim.stock.row(j);
        // The groove centre at this angle: 5 - lead x theta / 360 - k lead.
        let theta = j as f64 * g.dtheta_deg();
        for i in 0..g.nz {
            let z = g.z(i);
            if !(-25.0..=-5.0).contains(&z) {
                continue;
            }
            let c0 = 5.0 - 2.0 * theta / 360.0;
            let u = ((z - c0).rem_euclid(2.0)).min(2.0 - (z - c0).rem_euclid(2.0));
            let want = (19.0 + u / half).min(20.0);
            assert!((row[i] as f64 - want).abs() < 0.02, "theta {theta} z {z}: {} vs {want}", row[i]);
        }
    }
}

#[test]
fn two_starts_are_two_grooves_180_degrees_apart() {
    let recs = records("gsk980tdi", &[], "M3 S100\nG0 X42 Z5\nG92 X38 Z-30 F4 L2 J0\nM30\n");
    let sim = simulate(&recs, &bar(40.0, 40.0), &opts(0.01, 1.0)).unwrap();
    let m = &sim.measurement;
    assert_eq!(m.starts, Some(2));
    assert!((m.lead_mm.unwrap() - 4.0).abs() < 0.02, "{m:?}");
    assert!((m.pitch_mm.unwrap() - 2.0).abs() < 0.02);
    assert_eq!(m.start_spacing_deg, Some(180.0));
}

#[test]
fn a_pass_with_a_wrong_q_is_a_phase_error() {
    // Two passes with a pull-out (out of the stock before the retract); the second at Q30000.
    let recs = records("gsk980tdi", &[], "M3 S100\nG0 X42 Z5\nX38\nG32 Z-30 F2 J1.5 K1\nG0 X42\nZ5\nX37.8\nG32 Z-30 Q30000\nG0 X42\nM30\n");
    let sim = simulate(&recs, &bar(40.0, 40.0), &opts(0.01, 1.0)).unwrap();
    let f: Vec<_> = sim.measurement.findings.iter().filter(|f| f.kind == "phase").collect();
    assert_eq!(f.len(), 1, "{:?}", sim.measurement.findings);
    assert_eq!(f[0].line, 8);
    assert!(f[0].message.starts_with("this pass is 30.000 degrees"), "{}", f[0].message);
    // The same passes with the same Q: no finding.
    let recs = records("gsk980tdi", &[], "M3 S100\nG0 X42 Z5\nX38\nG32 Z-30 F2 J1.5 K1\nG0 X42\nZ5\nX37.8\nG32 Z-30\nG0 X42\nM30\n");
    let sim = simulate(&recs, &bar(40.0, 40.0), &opts(0.01, 1.0)).unwrap();
    assert!(sim.measurement.findings.is_empty(), "{:?}", sim.measurement.findings);
}

#[test]
fn o0012_measures_minor_56_9_and_pitch_3() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/gsk980tdi_o0012.nc")).unwrap();
    let recs = records("gsk980tdi", &[], &text);
    let sim = simulate(&recs, &bar(60.0, 80.0), &opts(0.01, 0.5)).unwrap();
    let m = &sim.measurement;
    assert!((m.minor_diameter_mm.unwrap() - 56.9).abs() <= 0.02, "{m:?}");
    assert!((m.pitch_mm.unwrap() - 3.0).abs() <= 0.02, "{m:?}");
    assert!((m.lead_mm.unwrap() - 3.0).abs() <= 0.02, "{m:?}");
    let (a, b) = m.flank_angles_deg.unwrap();
    assert!((a - 30.0).abs() < 0.5 && (b - 30.0).abs() < 0.5);
    assert!(m.findings.is_empty(), "{:?}", m.findings);
}

#[test]
fn a_rapid_into_the_stock_and_the_chuck_side_are_found() {
    let recs = records("gsk980tdi", &[], "M3 S100\nG0 X50 Z5\nG0 X30 Z-10\nG98 G1 Z-60 F100\nG0 X50\nM30\n");
    let sim = simulate(&recs, &bar(40.0, 40.0), &opts(0.02, 5.0)).unwrap();
    let kinds: Vec<&str> = sim.measurement.findings.iter().map(|f| f.kind).collect();
    assert!(kinds.contains(&"crash") && kinds.contains(&"chuck"), "{kinds:?}");
}

/// Issue 7: cut a thread, clamp the part again at a random angle, record a point in the groove,
/// run the repair programme: it removes nothing more (within the grid).
#[test]
fn repair_round_trip_removes_no_extra_material() {
    for (k, turn) in [37.0f64, 123.5, 250.25, 301.0].into_iter().enumerate() {
        let rpm = if k % 2 == 0 { 500.0 } else { -500.0 };
        let prog = format!("M14\nG0 X40 Z3\nG32.1 Z-30 F2 S{rpm}\nG0 X45\nZ3\nX39\nG32.1 Z-30\nG0 X45\nM15\nM30\n");
        let recs = records("gsk988t", &[], &prog);
        let (dz, dt) = (0.01, 0.25);
        let mut sim = simulate(&recs, &bar(42.0, 40.0), &opts(dz, dt)).unwrap();
        let g = sim.stock.grid;
        // Clamp again turned by `turn` degrees: the rows move round.
        let shift = (turn / dt).round() as usize % g.ntheta;
        let mut turned = vec![0f32; sim.stock.outer.len()];
        for j in 0..g.ntheta {
            let to = (j + shift) % g.ntheta;
            turned[to * g.nz..(to + 1) * g.nz].copy_from_slice(sim.stock.row(j));
        }
        sim.stock.outer = turned;
        // Put the tool in the groove at Z-12: the angle where the surface there is deepest.
        let i = ((-12.0 - g.z0_mm) / g.dz_mm).round() as usize;
        let (jm, _) = (0..g.ntheta).map(|j| (j, sim.stock.row(j)[i])).fold((0, f32::MAX), |a, b| if b.1 < a.1 { b } else { a });
        let recorded = Recorded { point: Vec3::new(19.5, 0.0, -12.0), c_deg: jm as f64 * dt };
        let job = RepairJob { start: Vec3::new(19.5, 0.0, 3.0), end: Vec3::new(19.5, 0.0, -30.0), lead_mm: 2.0, rpm, j_mm: None, k_mm: None, recorded };
        let repair = records("gsk988t", &["8135.7=1"], &format!("M14\n{}G0 X45\nM15\nM30\n", job.programme().unwrap()));
        let before = sim.stock.outer.clone();
        let tool = Setup::default().tool(0);
        let first_thread = repair.iter().position(|r| r.op.is_thread()).unwrap();
        for r in &repair[first_thread..] {
            sim.stock.apply(r, &tool, 1000.0);
        }
        let removed = before.iter().zip(&sim.stock.outer).map(|(a, b)| (a - b).abs()).fold(0f32, f32::max);
        // The recorded angle is good to half a grid step around: that far along the thread, the
        // flank moves by lead x step / 360 / tan 30.
        let allowed = 2.0 * (2.0 * dt / 360.0 / 30f64.to_radians().tan() + dz) as f32;
        assert!(removed <= allowed, "turn {turn}: the repair removed {removed} mm (allowed {allowed})");
    }
}
