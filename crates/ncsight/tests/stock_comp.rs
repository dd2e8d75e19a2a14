//! The stock simulation cuts with the tool's real shape along the compensated path (issue 18):
//! a part roughed with G71 and finished with G70 under G42, with a 0.8 mm nose radius and
//! imaginary tool nose 3, has the programmed diameters on its straight portions. Without the
//! compensation (the same tool, G42 taken out) the finishing pass leaves them off.

use ncsight::profile::{self, Params};
use ncsight::setup::Setup;
use ncsight::stock::measure::{simulate, SimOptions};
use ncsight::{Event, Mode, Program, Record, Switches};

const SETUP: &str = "
[[offset]]
number = 1
radius_mm = 0.8
tip = 3

[[tool]]
number = 1
kind = \"turning\"
nose_radius_mm = 0.8
included_angle_deg = 80
tip = 3

[stock]
diameter_mm = 32.0
length_mm = 60.0
";

/// The part: X20 face to Z0, a chamfer to X24, X24 to Z-30, a face to X28, X28 to Z-40; the
/// compensation starts in the contour's first block and ends moving out in X (GSK980TDi help
/// text, G40-G42 note 6: G71 cancels it, the finishing shape's first block starts it again).
fn programme(comp: bool) -> String {
    let (on, off) = if comp { ("G42 ", "G40 ") } else { ("", "") };
    format!(
        "T0101\nG99 G97 S800 M03\nG0 X32. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 {on}G0 X20.\nG1 Z0. F0.1\nX24. Z-2.\nZ-30.\nX28.\nZ-40.\nN20 {off}X34.\nG70 P10 Q20\nG0 X100. Z100.\nM30\n"
    )
}

fn records(text: &str, setup: &Setup) -> Vec<Record> {
    records_on("gsk980tdi", text, setup)
}

fn records_on(machine: &str, text: &str, setup: &Setup) -> Vec<Record> {
    let mut program = Program::new(Params::defaults(profile::by_name(machine).unwrap()), Switches::default(), Mode::Run);
    program.set_setup(setup);
    let mut out = Vec::new();
    for e in ncsight::events(program, text.as_bytes()) {
        match e {
            Event::Record(r) => out.push(r),
            Event::Diagnostic(d) => assert!(!d.is_alarm(), "{d:?}"),
        }
    }
    out
}

/// The turned diameter at z (every angle alike on a turned part: the largest is taken).
fn diameter_at(sim: &ncsight::stock::measure::Simulation, z: f64) -> f64 {
    let g = sim.stock.grid;
    let i = ((z - g.z0_mm) / g.dz_mm).round() as usize;
    2.0 * (0..g.ntheta).map(|j| sim.stock.row(j)[i] as f64).fold(f64::MIN, f64::max)
}

#[test]
fn a_part_finished_under_g42_has_its_programmed_diameters() {
    let setup = Setup::from_toml(SETUP).unwrap();
    let sim =
        simulate(&records(&programme(true), &setup), &setup, &SimOptions { dz_mm: Some(0.01), dtheta_deg: Some(2.0), expect: None, ..SimOptions::default() })
            .unwrap();
    for (z, want) in [(-5.0, 24.0), (-15.0, 24.0), (-27.0, 24.0), (-33.0, 28.0), (-38.0, 28.0)] {
        let d = diameter_at(&sim, z);
        assert!((d - want).abs() <= 0.01, "Z{z}: {d:.4} mm turned, {want} programmed");
    }
    // The face at Z-30 is where the programme puts it: the last cell turned to more than X26
    // lies at Z-30 within a cell or two.
    let g = sim.stock.grid;
    let face = (0..g.nz).map(|i| g.z(i)).filter(|z| (-31.0..-29.0).contains(z) && diameter_at(&sim, *z) > 26.0).fold(f64::MIN, f64::max);
    assert!((face + 30.0).abs() <= 0.02, "the face at Z{face:.3}");

    // Without compensation the nose radius leaves material on the chamfer and the face corner,
    // and with the tip vector the straight portions are still right: the check above is not
    // empty.
    let plain =
        simulate(&records(&programme(false), &setup), &setup, &SimOptions { dz_mm: Some(0.01), dtheta_deg: Some(2.0), expect: None, ..SimOptions::default() })
            .unwrap();
    let chamfer_mid = |s: &ncsight::stock::measure::Simulation| diameter_at(s, -1.0);
    assert!((chamfer_mid(&sim) - 22.0).abs() <= 0.02, "chamfer at Z-1: {:.4}", chamfer_mid(&sim));
    assert!(chamfer_mid(&plain) - 22.0 > 0.2, "uncompensated, the nose leaves the chamfer high: {:.4}", chamfer_mid(&plain));
}

/// FANUC: G42 before G71, G40 after G70: the roughing runs along the compensated shape too
/// (docs/reference/macro.md 10.3, inferred), and the finished part has its programmed diameters.
#[test]
fn fanuc_roughs_and_finishes_along_the_compensated_shape() {
    let setup = Setup::from_toml(SETUP).unwrap();
    let text = "T0101\nG99 G97 S800 M03\nG0 X32. Z2.\nG42\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X20.\nG1 Z0. F0.1\nX24. Z-2.\nZ-30.\nX28.\nZ-40.\nN20 X34.\nG70 P10 Q20\nG40 G0 X100. Z100.\nM30\n";
    let recs = records_on("fanuc0t", text, &setup);
    // The roughing's last pass along the contour leaves the allowance on the compensated shape:
    // X24.4 on the X24 portion, the tip on it as on the finishing pass.
    assert!(
        recs.iter().any(|r| r.span.line == 6 && matches!(r.op, ncsight::Op::Feed { to, .. } if (to.x * 2.0 - 24.4).abs() < 1e-9 && (to.z + 29.9).abs() < 1e-9)),
        "no roughing pass along X24.4 to Z-29.9"
    );
    let sim = simulate(&recs, &setup, &SimOptions { dz_mm: Some(0.01), dtheta_deg: Some(2.0), expect: None, ..SimOptions::default() }).unwrap();
    for (z, want) in [(-5.0, 24.0), (-15.0, 24.0), (-27.0, 24.0), (-33.0, 28.0), (-38.0, 28.0), (-1.0, 22.0)] {
        let d = diameter_at(&sim, z);
        assert!((d - want).abs() <= 0.02, "Z{z}: {d:.4} mm turned, {want} programmed");
    }
}
