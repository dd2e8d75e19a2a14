//! Axes a setup adds to a profile (docs/setup.md): the rotary axes in the macro variables, in
//! G66 calls, in the other motion modes, and several of them turning in one block.

mod common;

use ncsight::motion::Op;
use ncsight::Record;

fn run(machine: &str, axes: &str, text: &str) -> (Vec<Record>, Vec<ncsight::Diagnostic>) {
    common::run_setup(machine, &format!("[machine]\naxes = {axes}\n"), text, false)
}

fn alarms(diags: &[ncsight::Diagnostic]) -> Vec<&str> {
    diags.iter().filter(|d| d.is_alarm()).map(|d| d.code).collect()
}

/// #5001-#5006 read the axes in the setup's order: the 4th axis A is #5004 (45 after G91 A45.),
/// a lathe's C after X and Z is #5003. The value lands in #100 and moves X there.
#[test]
fn position_variables_read_the_declared_axes() {
    let (r, d) = run("fanuc0m", r#"["X", "Y", "Z", "A"]"#, "G91 G00 A45.\nG90\n#100 = #5004\nG00 X#100\nM30\n");
    assert!(alarms(&d).is_empty(), "{d:?}");
    assert!(r.iter().any(|r| matches!(r.op, Op::Rapid { to, .. } if to.x == 45.0)), "{r:?}");
    let (r, d) = run("fanuc0t", r#"["X", "Z", "C"]"#, "G00 C30.\n#100 = #5003\nG00 Z#100\nM30\n");
    assert!(alarms(&d).is_empty(), "{d:?}");
    assert!(r.iter().any(|r| matches!(r.op, Op::Rapid { to, .. } if to.z == 30.0)), "{r:?}");
}

/// G66 calls its macro after a block that only turns a rotary axis (O9000 moves Z to 1, once
/// per call: after `A45.` and after `X1. A90.`).
#[test]
fn a_modal_call_follows_a_rotary_turn() {
    let text = "G66 P9000\nA45.\nX1. A90.\nG67\nM30\nO9000\nG91 G00 Z1.\nG90\nM99\n";
    let (r, d) = run("fanuc0m", r#"["X", "Y", "Z", "A"]"#, text);
    assert!(alarms(&d).is_empty(), "{d:?}");
    let z_moves = r.iter().filter(|r| matches!(r.op, Op::Rapid { from, to } if to.z != from.z)).count();
    assert_eq!(z_moves, 2, "{r:?}");
}

/// A rotary word in another motion mode is a word that mode does not take (NCS-E35), not the
/// mode's own complaint (G02 without R).
#[test]
fn a_rotary_word_in_an_arc_mode_is_not_taken() {
    let (_, d) = run("fanuc0m", r#"["X", "Y", "Z", "A"]"#, "G02 X10. Y0 R5. F100.\nA45.\nM30\n");
    assert_eq!(alarms(&d), ["NCS-E35"], "{d:?}");
}

/// Two rotary axes in one block turn together: G00 A90. B90. takes the time of one (0.5 s at
/// 10800 deg/min plus 0.1 s), G01 A0 B0 F600. the time of the 127.28 degree vector at F600
/// (12.73 s plus 0.05 s), each axis at 424.26 deg/min.
#[test]
fn rotary_axes_of_one_block_overlap_in_time() {
    let (r, d) = run("fanuc0m", r#"["X", "Y", "Z", "A", "B"]"#, "G00 A90. B90.\nG01 A0 B0 F600.\nM30\n");
    assert!(alarms(&d).is_empty(), "{d:?}");
    let t: Vec<f64> = r.iter().map(|r| (r.t_s * 1000.0).round() / 1000.0).collect();
    assert_eq!(t[..4], [0.6, 0.6, 13.378, 13.378], "{r:?}");
    assert!(matches!(r[2].op, Op::Rotary { rate_deg_min, .. } if (rate_deg_min - 424.264).abs() < 1e-3), "{:?}", r[2]);
}
