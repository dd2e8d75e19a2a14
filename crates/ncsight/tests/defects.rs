//! Defects found by outside checks (issue 15): each test failed before its fix.

use ncsight::motion::Op;

mod common;

fn spindle_rpms(machine: &str, text: &str) -> Vec<f64> {
    let (r, d) = common::run_plain(machine, &[], text);
    assert!(d.iter().all(|d| !d.is_alarm()), "{d:?}");
    r.iter().filter_map(|r| if let Op::Spindle { rpm, .. } = r.op { Some(rpm) } else { None }).collect()
}

/// G96 under G20: S is feet per minute (FANUC 0-T and GSK980TDi manuals, G96).
#[test]
fn g96_under_g20_is_feet_per_minute() {
    for machine in ["fanuc0t", "gsk980tdi"] {
        // 500 ft/min at a 2.0 inch diameter: 500 x 12 / (pi x 2.0) = 954.93 rpm.
        let rpm = spindle_rpms(machine, "G20 G0 X2.0 Z0.1\nG96 S500 M03\nG01 Z-1.0 F0.01\nM30\n");
        let last = *rpm.last().unwrap();
        assert!((last - 500.0 * 12.0 / (std::f64::consts::PI * 2.0)).abs() < 0.01, "{machine}: {rpm:?}");
        // 150 m/min at 50 mm: 954.93 rpm.
        let rpm = spindle_rpms(machine, "G21 G0 X50. Z2.\nG96 S150 M03\nG01 Z-10. F0.1\nM30\n");
        assert!((rpm.last().unwrap() - 150_000.0 / (std::f64::consts::PI * 50.0)).abs() < 0.01, "{machine}: {rpm:?}");
    }
}
