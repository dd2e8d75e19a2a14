//! The lathe's turning, facing, peck and roughing cycles, rule by rule (GSK980TDi help text
//! G70-G75, G90, G94).

use ncsight::motion::Op;
use ncsight::{Diagnostic, Record};

mod common;

fn run(text: &str) -> (Vec<Record>, Vec<Diagnostic>) {
    common::run_plain("gsk980tdi", &[], text)
}

fn alarm(d: &[Diagnostic]) -> Option<&'static str> {
    d.iter().find(|d| d.is_alarm()).map(|d| d.code)
}

fn feeds_on_line(r: &[Record], line: u32) -> Vec<(f64, f64)> {
    r.iter().filter(|r| r.span.line == line).filter_map(|r| if let Op::Feed { to, .. } = r.op { Some((2.0 * to.x, to.z)) } else { None }).collect()
}

const START: &str = "G97 S500 M03\nG99 G0 X50 Z2\n";

#[test]
fn g90_x_z_and_r_stay_when_the_code_is_named_again() {
    // Line 4 names G90 again with X only: Z-30 and R-1 come from line 3.
    let (r, d) = run(&format!("{START}G90 X46 Z-30 R-1 F0.2\nG90 X42\nM30\n"));
    assert_eq!(alarm(&d), None);
    let f = feeds_on_line(&r, 4);
    assert_eq!(f[0], (42.0, -30.0));
    // The cut start is at X 42 + 2 x -1 = 40.
    let start = r.iter().find(|r| r.span.line == 4).unwrap().op.end_point().unwrap();
    assert!((2.0 * start.x - 40.0).abs() < 1e-9);
}

#[test]
fn switching_between_g90_and_g94_or_a_one_shot_code_forgets_the_end_point() {
    // G94 after G90: G90's X46 is not G94's end X; X stays where the tool is (X50).
    let (r, d) = run(&format!("{START}G90 X46 Z-30 F0.2\nG94 Z-2\nM30\n"));
    assert_eq!(alarm(&d), None);
    assert!(feeds_on_line(&r, 4).iter().all(|f| (f.0 - 50.0).abs() < 1e-9));
    // G28 in between: the repeat block's Z is not Z-30 any more.
    let (r, _) = run(&format!("{START}G90 X46 Z-30 F0.2\nG28 U0\nG90 X42 Z-10\nX40\nM30\n"));
    assert_eq!(feeds_on_line(&r, 6)[0], (40.0, -10.0));
}

#[test]
fn a_taper_with_no_step_is_too_large() {
    let (_, d) = run(&format!("{START}G90 U0 Z-30 R1 F0.2\nM30\n"));
    assert_eq!(alarm(&d), Some("NCS-E45"));
}

#[test]
fn g75_counts_its_pecks_without_drift() {
    // 100 mm deep (radius) in pecks of 0.1 mm: exactly 1000 feeds, the last at the bottom.
    let (r, d) = run("G97 S500 M03\nG99 G0 X300 Z0\nG75 X100 Z0 P100 F0.05\nM30\n");
    assert_eq!(alarm(&d), None);
    let f = feeds_on_line(&r, 3);
    assert_eq!(f.len(), 1000);
    assert!((f.last().unwrap().0 - 100.0).abs() < 1e-9);
}

#[test]
fn g74_and_g75_share_one_back_off() {
    // G74 R0.5 sets e for G75 too: each G75 peck is followed by a 0.5 mm rapid back in X.
    let (r, d) = run("G97 S500 M03\nG99 G0 X42 Z-10\nG74 R0.5\nG75 X36 Z-10 P2000 F0.05\nM30\n");
    assert_eq!(alarm(&d), None);
    let backs: Vec<f64> =
        r.iter().filter(|r| r.span.line == 4).filter_map(|r| if let Op::Rapid { from, to } = r.op { Some(to.x - from.x) } else { None }).collect();
    assert!((backs[0] - 0.5).abs() < 1e-9, "{backs:?}");
}

#[test]
fn a_contour_never_closed_is_an_alarm_not_a_silent_skip() {
    let (_, d) = run(&format!("{START}G71 U2 R1\nG71 P10 Q99 F0.3\nN10 G0 X20\nG1 Z-10\nM30\n"));
    assert_eq!(alarm(&d), Some("NCS-E53"));
    let (_, d) = run(&format!("{START}G71 U2 R1\nG71 P10 Q99 F0.3\nN10 G0 X20\nG1 Z-10\n"));
    assert_eq!(alarm(&d), Some("NCS-E53"));
}

#[test]
fn the_ns_block_must_step_along_the_depth_axis() {
    // G72 steps its depth along Z: an ns block that only moves X is the wrong contour (note 2).
    let (_, d) = run(&format!("{START}G72 W2 R1\nG72 P10 Q20 F0.3\nN10 G0 X20\nN20 G1 Z-10\nM30\n"));
    assert_eq!(alarm(&d), Some("NCS-E55"));
    // A contour with nothing after its ns block.
    let (_, d) = run(&format!("{START}G71 U2 R1\nG71 P10 Q10 F0.3\nN10 G0 X20\nM30\n"));
    assert_eq!(alarm(&d), Some("NCS-E55"));
}

#[test]
fn m00_in_a_contour_is_ignored_in_roughing_and_g70_ends_its_block() {
    let (r, d) = run(&format!("{START}G71 U2 R1\nG71 P10 Q20 F0.3\nN10 G0 X20\nG1 Z-10 M00\nN20 X50\nG70 P10 Q20\nM30\n"));
    assert_eq!(alarm(&d), None, "{d:?}");
    // G70's last record (the rapid back to its start) carries the single-block stop.
    let last_g70 = r.iter().rev().find(|r| r.span.line == 8).expect("G70 returns to its start");
    assert!(last_g70.block_end);
    assert!(matches!(last_g70.op, Op::Rapid { .. }));
}

/// G83/G87 are group 01 codes on the GSK lathe: a thread or a G90 cycle before them does not come
/// back after G80 (the mode is then G00), and a G87 after a G83 does not take G83's bottom.
#[test]
fn lathe_drilling_ends_the_motion_mode_and_its_data() {
    let (r, d) = run(&format!("{START}G00 X0 Z2\nG32 Z-10 F1.5\nG83 X0 Z-15 F0.1\nG80\nZ-20\nM30\n"));
    assert_eq!(alarm(&d), None, "{d:?}");
    // Line 5 drills (a feed, no thread); line 7 is a rapid.
    assert!(r.iter().any(|r| r.span.line == 5 && matches!(r.op, Op::Feed { .. })));
    assert!(r.iter().filter(|r| r.span.line == 7).all(|r| matches!(r.op, Op::Rapid { .. })), "{r:?}");
    let (r, d) = run(&format!("{START}G90 X30 Z-10 F0.2\nG83 X0 Z-5 F0.1\nG80\nX20\nM30\n"));
    assert_eq!(alarm(&d), None);
    assert_eq!(r.iter().filter(|r| r.span.line == 6).count(), 1, "{r:?}");
    let (_, d) = run(&format!("{START}G00 X20 Z2\nG83 Z-5 F0.1\nG87 Z-8\nM30\n"));
    assert_eq!(alarm(&d), Some("NCS-E36"));
}

/// Pecks land on start + k Q exactly: 2 mm in Q0.2 mm pecks is 10 feeds, not 10 and a sliver.
#[test]
fn lathe_pecks_do_not_drift() {
    let (r, d) = run(&format!("{START}G00 X0 Z0\nG83 Z-2. Q200 R0.1 F0.1\nM30\n"));
    assert_eq!(alarm(&d), None);
    assert_eq!(feeds_on_line(&r, 4).len(), 10);
}

/// FANUC 3401#0 (DPI) set: a length without a decimal point is millimetres, as in the ICNC
/// course programmes of the corpus (`G03 X26 Z-13 R3`); unset, it is 0.001 mm (warned).
#[test]
fn calculator_type_input_on_fanuc() {
    let text = "G99 G97 S500 M03\nG00 X20 Z1\nG01 Z-10 F0.2\nG03 X26 Z-13 R3\nM30\n";
    let (r, d) = common::run_plain("fanuc0t", &["3401.0=1"], text);
    assert_eq!(alarm(&d), None, "{d:?}");
    assert!(d.iter().all(|d| d.rule != ncsight::Rule::IntegerLength));
    let end = r.iter().rev().find_map(|r| r.op.end_point()).unwrap();
    assert!((2.0 * end.x - 26.0).abs() < 1e-9 && (end.z + 13.0).abs() < 1e-9);
    let (r, d) = common::run_plain("fanuc0t", &[], text);
    assert!(d.iter().any(|d| d.rule == ncsight::Rule::IntegerLength));
    let end = r.iter().rev().find_map(|r| r.op.end_point()).unwrap();
    assert!((2.0 * end.x - 0.026).abs() < 1e-12);
}

/// Type II tells what the control would also do: a straight rapid back to A through a ridge the
/// contour passed (step 8), a W allowance that shifts the pocket walls, a contour that rises
/// beyond the start point.
#[test]
fn type_two_warns_what_runs_into_the_part() {
    let warned = |contour: &str, allowance: &str| {
        let text = format!("G99 M03 S500\nG00 X50 Z2\nG71 U2 R0.5\nG71 P10 Q20 {allowance} F0.2\n{contour}\nM30\n");
        let (_, d) = run(&text);
        assert_eq!(alarm(&d), None, "{d:?}");
        d.iter().filter(|d| d.rule == ncsight::Rule::RoughingCollision).map(|d| d.message.clone()).collect::<Vec<_>>()
    };
    let w = warned("N10 G00 X20 Z2\nG01 X40 Z-10\nZ-15\nN20 X30 Z-20", "U0 W0");
    assert!(w.len() == 1 && w[0].contains("step 8"), "{w:?}");
    let w = warned("N10 G00 X20 Z2\nG01 X40 Z-10\nX30\nZ-15\nN20 X50 Z-20", "U0.4 W0.3");
    assert!(w.len() == 1 && w[0].contains("allowance W"), "{w:?}");
    let w = warned("N10 G00 X20 Z2\nG01 X60 Z-10\nX30 Z-15\nN20 X70 Z-20", "U0 W0");
    assert!(w.iter().any(|m| m.contains("beyond the start point")), "{w:?}");
    // The plain pocket of the golden trace: nothing to tell.
    assert!(warned("N10 G00 X20 Z2\nG01 X40 Z-10\nX30 Z-15\nN20 X50 Z-20", "U0 W0").is_empty());
}

/// FANUC 0-T G83: R between the initial level and the bottom, as on the 0-M; a drilling code in a
/// contour is PS0066 even when its block would alarm by itself.
#[test]
fn fanuc_lathe_drilling_levels_and_contours() {
    let (_, d) = common::run_plain("fanuc0t", &[], "G99 M03 S1000\nG00 X0 Z5.\nG83 Z4. R-3. F0.1\nM30\n");
    assert_eq!(alarm(&d), Some("NCS-E46"));
    let (r, d) = common::run_plain("fanuc0t", &[], "G99 M03 S1000\nG00 X0 Z5.\nG83 Z-10. R-3. F0.1\nM30\n");
    assert_eq!(alarm(&d), None);
    assert_eq!(feeds_on_line(&r, 3), vec![(0.0, -10.0)]);
    let text = "G99 M03 S1000\nG00 X40. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0.2 W0.1 F0.2\nN10 G00 X20.\nG83 Z-10. R-3. Q1000\nN20 G01 Z-20.\nM30\n";
    let (_, d) = common::run_plain("fanuc0t", &[], text);
    assert_eq!(alarm(&d), Some("PS0066"));
}

/// G84 rigid tapping (help text G84/88): in with the spindle, out with it reversed, the way out
/// starting at the angle the way in ended on; FEED HOLD and single block wait for the end (note
/// 4), the feed override does not apply.
#[test]
fn rigid_tapping_goes_in_and_out_with_the_spindle() {
    let (r, d) = run("G97 M03 S500\nG00 X0 Z3\nM29 S300\nG84 Z-20 P200 F1.5\nM30\n");
    assert_eq!(alarm(&d), None, "{d:?}");
    let taps: Vec<&Record> = r.iter().filter(|r| r.span.line == 4).collect();
    let threads: Vec<(f64, f64, f64)> =
        taps.iter().filter_map(|r| if let Op::Thread { to, spindle_deg, rpm, .. } = r.op { Some((to.z, spindle_deg, rpm)) } else { None }).collect();
    // 23 mm at 1.5 mm a turn = 15 1/3 turns: the way in ends at 120 degrees, the way out
    // (turning back) starts at 240.
    assert_eq!(threads.len(), 2);
    assert_eq!((threads[0].0, threads[0].2), (-20.0, 300.0));
    assert!((threads[1].1 - 240.0).abs() < 1e-6 && threads[1].2 == -300.0 && threads[1].0 == 3.0, "{threads:?}");
    assert!(taps.iter().all(|r| r.hold == ncsight::motion::Hold::AfterRun && r.override_free));
    assert!(taps.last().unwrap().block_end);
    // K2: single block stops after each hole; G04 between M29 and G84 is not a move; G84 to G88
    // keeps the hand and the dwell (note 1 asks only for the bottom again).
    let (r, d) = run("G97 M03 S500\nG00 X40 Z3\nM29 S300\nG04 X1.0\nG84 X0 Z-20 F-1.5 P300 K2\nG88 Z-10 X20\nM30\n");
    assert_eq!(alarm(&d), None, "{d:?}");
    assert_eq!(r.iter().filter(|r| r.span.line == 5 && r.block_end).count(), 2);
    let g88: Vec<f64> = r.iter().filter(|r| r.span.line == 6).filter_map(|r| if let Op::Thread { rpm, .. } = r.op { Some(rpm) } else { None }).collect();
    assert_eq!(g88, vec![-300.0, 300.0]);
    assert!(r.iter().any(|r| r.span.line == 6 && matches!(r.op, Op::Dwell { .. })));
    // M29 while G83 is in force, then a move: NCS-E57.
    let (_, d) = run("G97 M03 S500\nG00 X0 Z3\nG83 Z-5 F0.1\nM29 S300\nX10\nG84 Z-20 F1.5\nM30\n");
    assert_eq!(alarm(&d), Some("NCS-E57"));
}

/// A roughing of some 15,000 levels (Δd 0.004 mm over 60 mm, about 60,000 moves) under G96 with
/// feed per revolution, so each cut's feed follows its diameter, and a contour with an arc: made
/// as it is handed on when the consumer takes each record as it comes (issue 34), record for
/// record, block end and time what the ordinary path (the pull iterator, which holds a block's
/// records whole) makes.
#[test]
fn a_deferred_roughing_makes_the_records_the_ordinary_path_makes() {
    let text = "G50 S3000\nG96 S180 M03\nG99 G0 X122 Z2\nG71 U0.004 R0.002\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G0 X0\nG1 Z0\nG3 X40 Z-20 R20\nG1 Z-40\nN20 X122\nG0 X150 Z50\nM30\n";
    let (deferred, d1) = common::run_pushed("gsk980tdi", None, text);
    let (ordinary, d2) = run(text);
    assert_eq!((alarm(&d1), alarm(&d2)), (None, None), "{d1:?} {d2:?}");
    assert!(deferred.len() > 50_000, "{} records", deferred.len());
    common::same_records(&deferred, &ordinary);
    // The cuts' feeds differ with the diameter (G96): the deepest level's is the slowest.
    let feeds: Vec<f64> = deferred.iter().filter_map(|r| if let Op::Feed { feed_mm_min, .. } = r.op { Some(feed_mm_min) } else { None }).collect();
    assert!(feeds.iter().any(|f| (f - feeds[0]).abs() > 1.0), "{:?}", &feeds[..4]);
}

/// G71 with Δd 0.001 mm over 101 mm: 101,000 levels, some 400,000 moves, which a GSK980TDi runs
/// and ncsight used to refuse (NCS-E40). Pushed, it runs to its end; the pull iterator, which
/// would hold them, still stops at the cap.
#[test]
fn a_roughing_past_the_cap_runs_pushed_and_alarms_pulled() {
    let text = "G97 S500 M03\nG99 G0 X202 Z2\nG71 U0.001 R0.0005\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X0\nG1 Z-10\nN20 X202\nG0 X250 Z50\nM30\n";
    let (records, diags) = common::run_pushed("gsk980tdi", None, text);
    assert_eq!(alarm(&diags), None, "{diags:?}");
    let cuts = records.iter().filter(|r| r.span.line == 4 && matches!(r.op, Op::Feed { to, .. } if (to.z + 9.9).abs() < 1e-9)).count();
    assert!(cuts > 100_000, "{cuts} cuts to the contour's face");
    assert_eq!(records.iter().filter(|r| r.block_end && r.span.line == 4).count(), 1);
    // The programme goes on after the cycle: its last move is the rapid to X250 Z50.
    assert!(records.iter().any(|r| r.span.line == 8 && matches!(r.op, Op::Rapid { to, .. } if to.z == 50.0)));
    let (_, pulled) = run(text);
    assert_eq!(alarm(&pulled), Some("NCS-E40"));
}

/// A soft limit in force: the deferred roughing's moves are walked once before any is made, and
/// the first beyond the limit stops the block as on the ordinary path (the same alarm, the same
/// block, nothing of it made).
#[test]
fn a_deferred_roughing_beyond_a_soft_limit_alarms_as_the_ordinary_path() {
    let setup = "[machine.limits]\nx_mm = [-10.0, 300.0]\nz_mm = [-15.0, 100.0]\n";
    // The contour's face at Z-20 lies beyond Z-15: the first level's cut reaches it.
    let text = "G97 S500 M03\nG99 G0 X122 Z2\nG71 U0.004 R0.002\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X0\nG1 Z-20\nN20 X122\nG0 X150 Z50\nM30\n";
    let (r1, d1) = common::run_pushed("gsk980tdi", Some(setup), text);
    let (r2, d2) = common::run_setup("gsk980tdi", setup, text, false);
    let first = |d: &[Diagnostic]| d.iter().find(|d| d.is_alarm()).map(|d| (d.code, d.span, d.message.clone()));
    assert!(first(&d1).is_some());
    assert_eq!(first(&d1), first(&d2));
    assert!(r1.iter().all(|r| r.span.line != 4), "nothing of the roughing is made");
    assert_eq!(r1.len(), r2.len());
}

/// A G74 face peck of some 25,000 pecks (Q4: 0.004 mm over 101 mm, about 50,500 moves) with a
/// back-off, and a G75 across two grooves: made as they are handed on when the consumer takes
/// each record as it comes, record for record, block end and time what the ordinary path (the
/// pull iterator) makes.
#[test]
fn a_deferred_peck_cycle_makes_the_records_the_ordinary_path_makes() {
    let text = "G97 S800 M03\nG99 G0 X0 Z1\nG74 R0.002\nG74 Z-100 Q4 F0.05\nG0 X42 Z-10\nG75 X20 Z-12 P8 Q2000 F0.05\nG0 X100 Z50\nM30\n";
    let (deferred, d1) = common::run_pushed("gsk980tdi", None, text);
    let (ordinary, d2) = run(text);
    assert_eq!((alarm(&d1), alarm(&d2)), (None, None), "{d1:?} {d2:?}");
    assert!(deferred.len() > 50_000, "{} records", deferred.len());
    common::same_records(&deferred, &ordinary);
    // One single-block stop for each cycle block, after its last move.
    assert_eq!(deferred.iter().filter(|r| r.block_end && (r.span.line == 4 || r.span.line == 6)).count(), 2);
}

/// G74 with Q1 (a micrometre) over 400 mm: 400,000 pecks, 800,000 moves, which a GSK980TDi runs
/// and ncsight used to refuse (NCS-E40). Pushed, it runs to its end; the pull iterator, which
/// would hold them, stops at the cap.
#[test]
fn a_peck_cycle_past_the_cap_runs_pushed_and_alarms_pulled() {
    let text = "G97 S800 M03\nG99 G0 X0 Z1\nG74 R0.0005\nG74 Z-400 Q1 F0.05\nG0 X100 Z50\nM30\n";
    let (records, diags) = common::run_pushed("gsk980tdi", None, text);
    assert_eq!(alarm(&diags), None, "{diags:?}");
    let pecks = records.iter().filter(|r| r.span.line == 4 && matches!(r.op, Op::Feed { .. })).count();
    assert_eq!(pecks, 401_000);
    assert!(records.iter().any(|r| r.span.line == 4 && matches!(r.op, Op::Feed { to, .. } if to.z == -400.0)));
    let (_, pulled) = run(text);
    assert_eq!(alarm(&pulled), Some("NCS-E40"));
}

/// A G73 of 9,000 passes over a contour with an arc (about 63,000 moves) under G96: made as it is
/// handed on when the consumer takes each record as it comes, record for record, block end and
/// time what the ordinary path makes; the most passes (9,999) over a contour of 13 moves
/// (140,000 moves) run pushed and stop pulled at the cap.
#[test]
fn a_deferred_pattern_cycle_makes_the_records_the_ordinary_path_makes() {
    let text = |passes: u32| {
        format!("G50 S2500\nG96 S150 M03\nG99 G0 X62 Z2\nG73 U4 W0 R{passes}\nG73 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X20\nG1 Z-10\nG2 X40 Z-20 R10\nG1 Z-30\nN20 X62\nG0 X100 Z50\nM30\n")
    };
    let (deferred, d1) = common::run_pushed("gsk980tdi", None, &text(9000));
    let (ordinary, d2) = run(&text(9000));
    assert_eq!((alarm(&d1), alarm(&d2)), (None, None), "{d1:?} {d2:?}");
    assert!(deferred.len() > 50_000, "{} records", deferred.len());
    common::same_records(&deferred, &ordinary);
    let long = "G97 S500 M03\nG99 G0 X62 Z2\nG73 U4 W0 R9999\nG73 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X20\nG1 Z-5\nX24 Z-7\nZ-10\nG2 X40 Z-20 R10\nG1 Z-25\nX44\nZ-28\nX48 Z-30\nZ-33\nX52\nZ-36\nN20 X62\nG0 X100 Z50\nM30\n";
    let (records, diags) = common::run_pushed("gsk980tdi", None, long);
    assert_eq!(alarm(&diags), None, "{diags:?}");
    assert_eq!(records.iter().filter(|r| r.span.line == 4 && matches!(r.op, Op::Arc { .. })).count(), 9999);
    let (_, pulled) = run(long);
    assert_eq!(alarm(&pulled), Some("NCS-E40"));
}

/// A depth of cut of a picometre is said at once (the levels are worked out, not counted one by
/// one): NCS-E40, whether the records are pushed or pulled.
#[test]
fn a_picometre_step_alarms_at_once() {
    let g71 = "G97 S500 M03\nG99 G0 X102 Z2\nG71 U0.000000000001 R0.5\nG71 P10 Q20 F0.2\nN10 G0 X0\nG1 Z-10\nN20 X102\nM30\n";
    for text in [g71] {
        let start = std::time::Instant::now();
        let (_, pushed) = common::run_pushed("gsk980tdi", None, text);
        let (_, pulled) = run(text);
        assert_eq!((alarm(&pushed), alarm(&pulled)), (Some("NCS-E40"), Some("NCS-E40")), "{text}: {pushed:?}");
        assert!(start.elapsed().as_secs() < 10, "{text}: {:?}", start.elapsed());
    }
}

/// A deferred G74 of one groove with a relief Δd (no step across) ends where its last move ends,
/// the relief away from the start, as on the ordinary path; a trailing M code's record ends the
/// block for single block, not the cycle's last move, as on the ordinary path.
#[test]
fn a_deferred_peck_cycle_ends_where_its_last_move_ends() {
    let text = "G97 S800 M03\nG99 G0 X10 Z1\nG74 R0.002\nG74 Z-100.1 Q4 R1 F0.05 M00\nG1 U2 F0.1\nM30\n";
    let (deferred, d1) = common::run_pushed("gsk980tdi", None, text);
    let (ordinary, d2) = run(text);
    assert_eq!((alarm(&d1), alarm(&d2)), (None, None), "{d1:?} {d2:?}");
    assert!(deferred.len() > 50_000, "{} records", deferred.len());
    common::same_records(&deferred, &ordinary);
    assert_eq!(deferred.iter().filter(|r| r.block_end && r.span.line == 4).count(), 1);
}

/// G22's area entered by a roughing stops it on the ordinary path as on the deferred one.
#[test]
fn a_roughing_into_a_g22_area_alarms() {
    // The area X0-40 (diameters) Z-50-0 on the machine; the contour's levels cut into it.
    let text = "G97 S500 M03\nG99 G0 X102 Z2\nG22 X40 Z0 I0 K-50\nG71 U2 R0.5\nG71 P10 Q20 F0.2\nN10 G0 X20\nG1 Z-10\nN20 X102\nM30\n";
    let (_, d) = run(text);
    assert_eq!(alarm(&d), Some(common::first_alarm("gsk980tdi", "G97 S500 M03\nG0 X102 Z2\nG22 X40 Z0 I0 K-50\nG0 X20 Z-10\nM30\n").unwrap().code));
}
