//! Defects found by outside checks in the third round (issue 32): each test failed before its fix.

use ncsight::motion::Op;

mod common;

/// G34 pulls out as G32 does (GSK980TDi help text, G34: "X(U), Z(W), J, K mean the same as in
/// G32"). From X30 Z5, `G34 Z-20 F2 R0.1 J1 K2`: 25 mm of thread; the revolutions, at 2.05,
/// 2.15, ... (F + R(n + 1/2)), run to Z-18 (nine make 22.05 mm, the tenth's 0.95 mm of 2.95
/// reach 23 mm), then the pull-out goes from X30 Z-18 to X32 Z-20 (J1 is a radius: X + 2) at the
/// tenth revolution's lead, with no warning.
#[test]
fn g34_pulls_out_as_g32() {
    let (records, diags) = common::run_plain("gsk980tdi", &[], "G97 S300 M03\nG0 X30. Z5.\nG34 Z-20. F2. R0.1 J1. K2.\nM30\n");
    assert!(diags.is_empty(), "{diags:?}");
    let threads: Vec<(f64, f64, f64)> = records.iter().filter_map(|r| if let Op::Thread { to, lead_mm, .. } = r.op { Some((to.x * 2.0, to.z, lead_mm)) } else { None }).collect();
    assert_eq!(threads.len(), 11, "{threads:?}");
    let (x, z, lead) = threads[9];
    assert!((x - 30.0).abs() < 1e-9 && (z + 18.0).abs() < 1e-9 && (lead - 2.95).abs() < 1e-9, "{:?}", threads[9]);
    let (x, z, lead) = threads[10];
    assert!((x - 32.0).abs() < 1e-9 && (z + 20.0).abs() < 1e-9 && (lead - 2.95).abs() < 1e-9, "{:?}", threads[10]);
    // Without J the thread ends at its end point as before.
    let (records, _) = common::run_plain("gsk980tdi", &[], "G97 S300 M03\nG0 X30. Z5.\nG34 Z-20. F2. R0.1\nM30\n");
    let last = records.iter().filter_map(|r| if let Op::Thread { to, .. } = r.op { Some(to) } else { None }).last().unwrap();
    assert!((last.x - 15.0).abs() < 1e-9 && (last.z + 20.0).abs() < 1e-9);
}
