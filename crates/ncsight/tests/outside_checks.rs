//! Defects found by outside checks in the third round (issue 32): each test failed before its fix.

use ncsight::motion::Op;

mod common;

use common::first_alarm;

/// G34 pulls out as G32 does (GSK980TDi help text, G34: "X(U), Z(W), J, K mean the same as in
/// G32"). From X30 Z5, `G34 Z-20 F2 R0.1 J1 K2`: 25 mm of thread; the revolutions, at 2.05,
/// 2.15, ... (F + R(n + 1/2)), run to Z-18 (nine make 22.05 mm, the tenth's 0.95 mm of 2.95
/// reach 23 mm), then the pull-out goes from X30 Z-18 to X32 Z-20 (J1 is a radius: X + 2) at the
/// tenth revolution's lead, with no warning.
#[test]
fn g34_pulls_out_as_g32() {
    let (records, diags) = common::run_plain("gsk980tdi", &[], "G97 S300 M03\nG0 X30. Z5.\nG34 Z-20. F2. R0.1 J1. K2.\nM30\n");
    assert!(diags.is_empty(), "{diags:?}");
    let threads: Vec<(f64, f64, f64)> =
        records.iter().filter_map(|r| if let Op::Thread { to, lead_mm, .. } = r.op { Some((to.x * 2.0, to.z, lead_mm)) } else { None }).collect();
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

/// A subprogramme call inside a G71 contour is refused by the roughing itself (GSK980TDi help
/// text, G71 note 4: "no subprogramme call codes (such as M98/M99) between ns and nf"), with no
/// G70 after it, before anything is roughed.
#[test]
fn a_call_in_a_roughing_contour_alarms_in_the_roughing() {
    let text = "O0001\nG0 X40. Z2.\nG71 U1. R0.5\nG71 P10 Q30 U0.5 W0.1 F0.2\nN10 G0 X20.\nG1 Z-10.\nM98 P1000\nN30 X40.\nM30\nO1000\nM99\n";
    let (records, diags) = common::run_plain("gsk980tdi", &[], text);
    let a = diags.iter().find(|d| d.is_alarm()).expect("an alarm");
    assert_eq!((a.code, a.span.line), ("NCS-E55", 7), "{a:?}");
    assert!(a.message.contains("G71 note 4"), "{}", a.message);
    assert!(!records.iter().any(|r| matches!(r.op, Op::Feed { .. })), "nothing is roughed");
    // G72 and G73 likewise.
    for head in ["G72 W1. R0.5\nG72 P10 Q30 U0.5 W0.1 F0.2", "G73 U2. W0. R2\nG73 P10 Q30 U0.5 W0.1 F0.2"] {
        let t = text.replace("G71 U1. R0.5\nG71 P10 Q30 U0.5 W0.1 F0.2", head);
        assert_eq!(first_alarm("gsk980tdi", &t).map(|a| (a.code, a.span.line)), Some(("NCS-E55", 7)), "{head}");
    }
}

/// P in an M98 block is the programme to call, never the drilling cycle's dwell: on a FANUC the
/// hole data P keeps its value (FANUC 0-M: M98 P is the programme number; the everyday practice
/// of "a cycle's first hole, then M98 P with the others", M. Lynch, "Merging Subprograms with
/// Canned Cycles", Modern Machine Shop). The called programme's holes dwell P500 = 0.5 s.
#[test]
fn m98_p_in_a_drilling_cycle_calls_and_keeps_the_dwell() {
    let text = "G21 G17 G90 G0 X0. Y0. Z50.\nS500 M3\nG99 G82 X10. Y10. Z-10. R2. P500 F100.\nM98 P2100\nG80\nM30\nO2100\nX20. Y20.\nX30.\nM99\n";
    let (records, diags) = common::run_plain("fanuc0m", &[], text);
    assert!(!diags.iter().any(|d| d.is_alarm()), "{diags:?}");
    let dwells: Vec<f64> = records.iter().filter_map(|r| if let Op::Dwell { seconds } = r.op { Some(seconds) } else { None }).collect();
    assert_eq!(dwells, vec![0.5, 0.5, 0.5], "three holes, each 0.5 s");
    // The M98 block itself drills no hole: the holes are at X10 Y10, X20 Y20 and X30 Y20.
    let bottoms: Vec<(f64, f64)> = records.iter().filter_map(|r| if let Op::Feed { to, .. } = r.op { Some((to.x, to.y)) } else { None }).collect();
    assert_eq!(bottoms, vec![(10.0, 10.0), (20.0, 20.0), (30.0, 20.0)]);
}

/// Setup shapes a machine cannot have are refused, naming the value: an axis twice (and so more
/// than six), a limit of three numbers, a block corner of NaN or infinity or four numbers.
#[test]
fn setup_shapes_are_checked_and_named() {
    use ncsight::setup::Setup;
    let refused = |toml: &str| Setup::from_toml(toml).expect_err(toml).to_string();
    assert!(refused("[machine]\naxes = [\"X\", \"X\"]\n").contains("\"X\" is named twice"));
    let many = format!("[machine]\naxes = [{}]\n", vec!["\"A\""; 300].join(", "));
    assert!(refused(&many).contains("\"A\" is named twice"));
    assert!(refused("[machine]\nlimits = { x_mm = [1.0, 2.0, 3.0] }\n").contains("give exactly 2 numbers, not 3"));
    assert!(refused("[block]\nmin_mm = [nan, 0.0, 0.0]\nmax_mm = [1.0, 1.0, 1.0]\n").contains("x from NaN to 1 mm"));
    assert!(refused("[block]\nmin_mm = [0.0, 0.0, 0.0]\nmax_mm = [inf, 1.0, 1.0]\n").contains("x from 0 to inf mm"));
    assert!(refused("[block]\nmin_mm = [0.0, 0.0, 0.0, 1.0]\nmax_mm = [1.0, 1.0, 1.0]\n").contains("give exactly 3 numbers, not 4"));
    assert!(refused("[machine]\nlimits = { z_mm = [5.0, -5.0] }\n").contains("z_mm = [5, -5]"));
    // What a machine can have still reads.
    let s = Setup::from_toml(
        "[machine]\naxes = [\"X\", \"Y\", \"Z\", \"C\"]\nlimits = { x_mm = [-1.0, 300.0] }\n[block]\nmin_mm = [0.0, 0.0, -20.0]\nmax_mm = [100.0, 50.0, 0.0]\n",
    )
    .unwrap();
    assert_eq!(s.block.unwrap().max_mm, [100.0, 50.0, 0.0]);
}

/// A WHILE whose END is missing is FANUC alarm 124 at the WHILE, found before its body runs
/// (the controller's search for END), not a run through the body to M30 without alarm. With
/// its END the loop runs as before, its body three times.
#[test]
fn a_while_without_end_alarms_before_its_body_runs() {
    for cond in ["1 EQ 1", "#1 LT 3"] {
        let (records, diags) = common::run_plain("fanuc0m", &[], &format!("O0001\n#1 = 0\nWHILE [{cond}] DO 1\nG0 X1. Y1.\n#1 = #1 + 1\nM30\n"));
        let a = diags.iter().find(|d| d.is_alarm()).unwrap_or_else(|| panic!("{cond}: no alarm"));
        assert_eq!((a.code, a.span.line), ("PS0124", 3), "{cond}: {a:?}");
        assert!(!records.iter().any(|r| matches!(r.op, Op::Rapid { .. })), "{cond}: the body ran");
    }
    let (records, diags) = common::run_plain("fanuc0m", &[], "O0001\n#1 = 0\nWHILE [#1 LT 3] DO 1\nG0 X#1 Y1.\n#1 = #1 + 1\nEND 1\nM30\n");
    assert!(diags.is_empty(), "{diags:?}");
    assert_eq!(records.iter().filter(|r| matches!(r.op, Op::Rapid { .. })).count(), 3);
}

/// A warning of a contour block is said once: by the roughing cycle that reads the contour
/// first, not again (out of line order) when G70 runs the same blocks.
#[test]
fn a_contour_blocks_warning_is_said_once() {
    let text = "G99 M03 S500\nG00 X40. Z2.\nG71 U1. R0.5\nG71 P10 Q30 U0.5 W0.1 F0.2\nN10 G00 X20.\nG01 Z-10. F200.\nN30 X40.\nG70 P10 Q30\nM30\n";
    let (_, diags) = common::run_plain("gsk980tdi", &[], text);
    let said: Vec<(u32, &str)> = diags.iter().map(|d| (d.span.line, d.code)).collect();
    assert_eq!(said, [(6, "NCS-W25"), (6, "NCS-W11"), (7, "NCS-W11")], "{diags:?}");
}
