//! The operator machine and the time model, rule by rule; each test names the note it follows.

use ncsight::motion::{Op, StopReason, Vec3};
use ncsight::time::Overrides;
use ncsight::{Options, Record, Switches};

mod common;

fn run(machine: &str, params: &[&str], opts: Options, text: &str) -> Vec<Record> {
    let (records, diags) = common::run_with(machine, params, Switches::default(), opts, text);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    records
}

fn hold_at(t: f64) -> Options {
    Options { feed_hold_at: vec![t], ..Options::default() }
}

fn stops(r: &[Record]) -> Vec<(usize, StopReason)> {
    r.iter().enumerate().filter_map(|(i, r)| if let Op::Stop { reason } = r.op { Some((i, reason)) } else { None }).collect()
}

fn dia_z(p: Vec3) -> (f64, f64) {
    ((p.x * 2e4).round() / 1e4, (p.z * 1e4).round() / 1e4)
}

const O0012: &str = "M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nX57.7\nM30\n";

/// The time the first thread of O0012 is halfway.
fn mid_thread(r: &[Record]) -> f64 {
    let i = r.iter().position(|r| r.op.kind() == "thread").unwrap();
    (r[i - 1].t_s + r[i].t_s) / 2.0
}

#[test]
fn seed_000_note_1_bit_6_is_0_pull_out_at_once_and_return() {
    let plain = run("gsk980tdi", &[], Options::default(), O0012);
    let h = mid_thread(&plain);
    let r = run("gsk980tdi", &[], hold_at(h), O0012);
    let s = stops(&r);
    assert_eq!(s.len(), 1);
    let i = s[0].0;
    // Before the stop: the cut thread, the pull-out from where the tool was (J3 K1 toward X65),
    // the short axis back to X65, then the long axis back to Z5.
    assert_eq!(r[i - 1].op.end_point().map(dia_z), Some((65.0, 5.0)));
    assert_eq!(r[i - 2].op.end_point().map(dia_z).unwrap().0, 65.0);
    let Op::Thread { from, to, .. } = r[i - 3].op else { panic!("{:?}", r[i - 3].op) };
    assert!((2.0 * (to.x - from.x) - 6.0).abs() < 1e-9 && ((from.z - to.z) - 1.0).abs() < 1e-9);
    // After CYCLE START the interrupted cycle runs again from its start, in the same groove.
    let again: Vec<_> = r[i + 1..].iter().take(5).map(|r| r.op.clone()).collect();
    let first: Vec<_> = plain.iter().skip(2).take(5).map(|r| r.op.clone()).collect();
    assert_eq!(again, first);
}

#[test]
fn seed_000_note_1_bit_6_is_1_finish_the_thread_then_stop() {
    let plain = run("gsk980tdi", &[], Options::default(), O0012);
    let h = mid_thread(&plain);
    let r = run("gsk980tdi", &["18.6=1"], hold_at(h), O0012);
    let s = stops(&r);
    assert_eq!(s.len(), 1);
    let i = s[0].0;
    // Stopped at the end of the pull-out (X64.7 Z-28), before step 3.
    assert_eq!(r[i - 1].op.end_point().map(dia_z), Some((64.7, -28.0)));
    assert_eq!(r[i + 1].op.end_point().map(dia_z), Some((65.0, -28.0)));
    assert_eq!(r.iter().filter(|r| r.op.kind() == "thread").count(), 4);
}

const N50: &str = "G97 S300 M03\nG00 X80. Z80.8\nG92 X70. W-50.8 I-1.5 F2.\nM30\n";

#[test]
fn seed_004_thread_cutting_hold_d7_0_returns_to_a() {
    let plain = run("yasnac-lx3", &[], Options::default(), N50);
    let h = mid_thread(&plain);
    let r = run("yasnac-lx3", &[], hold_at(h), N50);
    let i = stops(&r)[0].0;
    assert_eq!(r[i - 1].op.end_point().map(dia_z), Some((80.0, 80.8)));
    // Restart from the beginning: the whole cycle again.
    assert_eq!(r.iter().filter(|r| r.op.kind() == "thread").count(), 1 + 1 + 1);
}

#[test]
fn seed_004_thread_cutting_hold_d7_1_stops_at_b() {
    let plain = run("yasnac-lx3", &[], Options::default(), N50);
    let h = mid_thread(&plain);
    let r = run("yasnac-lx3", &["6019.7=1"], hold_at(h), N50);
    let i = stops(&r)[0].0;
    // Stopped where threading up ended: a thread record just before, not at A.
    assert_eq!(r[i - 1].op.kind(), "thread");
    assert_ne!(r[i - 1].op.end_point().map(dia_z), Some((80.0, 80.8)));
    // CYCLE START: back to A, then the cycle from the beginning.
    assert_eq!(r[i + 2].op.end_point().map(dia_z), Some((80.0, 80.8)));
    assert_eq!(r[i + 4].op.kind(), "thread");
}

const O0009_RUN: &str = "M14\nG00 X30 Z3\nG32.1 W-20 F2 S500\nG32.1 W-20 J1 K1\nG00 X55\nM15\nM30\n";

fn run_diags(machine: &str, opts: Options, text: &str) -> (Vec<Record>, Vec<ncsight::Diagnostic>) {
    common::run_with(machine, &[], Switches::default(), opts, text)
}

/// GSK988T manual, G32.1 note 6: FEED HOLD during a G32.1 thread does nothing (the screen keeps
/// showing RUN); the press is not remembered, so the run goes on past the thread; the operator
/// must press again once no thread is being cut. A warning says the press was ignored.
#[test]
fn seed_001_g32_1_note_6_a_hold_during_the_thread_is_ignored() {
    let plain = run("gsk988t", &[], Options::default(), O0009_RUN);
    let h = mid_thread(&plain);
    let (r, d) = run_diags("gsk988t", hold_at(h), O0009_RUN);
    assert!(stops(&r).is_empty(), "no stop anywhere: {:?}", stops(&r));
    assert_eq!(r.len(), plain.len());
    let w: Vec<_> = d.iter().filter(|d| d.code == "NCS-W23").collect();
    assert_eq!(w.len(), 1, "{d:?}");
    assert!(w[0].message.contains("ignored"), "{}", w[0].message);
    // Pressed again during the G00 X55 that follows: that press stops the axes.
    let j = plain.iter().position(|r| r.op.end_point().map(dia_z).is_some_and(|p| p.0 == 55.0)).unwrap();
    let h2 = (plain[j - 1].t_s + plain[j].t_s) / 2.0;
    let (r, _) = run_diags("gsk988t", Options { feed_hold_at: vec![h, h2], ..Options::default() }, O0009_RUN);
    let s = stops(&r);
    assert_eq!(s.len(), 1);
    let last_thread = r.iter().rposition(|r| r.op.is_thread()).unwrap();
    assert!(s[0].0 > last_thread && r[s[0].0 - 1].op.kind() == "rapid", "the second press stops the G00: {s:?}");
}

/// GSK988T manual, G92.1 note 7: a press during the thread is ignored (the cycle goes on to its
/// end without stopping); during the cycle's rapids it stops the axes at once.
#[test]
fn seed_001_g92_1_note_7_hold_ignored_in_the_thread_but_at_once_in_a_rapid() {
    let prog = "G0 X65 Z5\nM14\nG92.1 X58.7 Z-28 F3 S300 J3 K1\nM15\nM30\n";
    let plain = run("gsk988t", &[], Options::default(), prog);
    let (r, d) = run_diags("gsk988t", hold_at(mid_thread(&plain)), prog);
    assert!(stops(&r).is_empty(), "{:?}", stops(&r));
    assert!(d.iter().any(|d| d.code == "NCS-W23"));
    // During the step 4 rapid the hold stops the axes where they are.
    let j = plain.iter().rposition(|r| matches!(r.op, Op::Rapid { .. })).unwrap();
    let h = (plain[j - 1].t_s + plain[j].t_s) / 2.0;
    let r = run("gsk988t", &[], hold_at(h), prog);
    let i = stops(&r)[0].0;
    let p = r[i - 1].op.end_point().unwrap();
    assert!(p.z > -28.0 && p.z < 5.0, "{p:?}");
    assert_eq!(r[i + 1].op.end_point().map(dia_z), Some((65.0, 5.0)));
}

/// GSK980TDi help text, G92.1 note 3 (and G32 note 3): the thread is finished, then the run
/// pauses: the press is remembered.
#[test]
fn tdi_help_g92_1_note_3_hold_stops_after_the_thread() {
    let prog = "G0 X65 Z5\nM14\nG92.1 X58.7 Z-28 F3 S300\nM15\nM30\n";
    let plain = run("gsk980tdi", &[], Options::default(), prog);
    let (r, d) = run_diags("gsk980tdi", hold_at(mid_thread(&plain)), prog);
    let s = stops(&r);
    assert_eq!(s.len(), 1);
    assert_eq!(r[s[0].0 - 1].op.kind(), "thread");
    assert!(!d.iter().any(|d| d.code == "NCS-W23"));
}

/// Thousands of presses run in constant stack (the thread hold's restart is a queue).
#[test]
fn thousands_of_presses_do_not_overflow_the_stack() {
    let plain = run("gsk980tdi", &[], Options::default(), O0012);
    let end = plain.last().unwrap().t_s;
    let presses: Vec<f64> = (0..8000).map(|i| end * i as f64 / 8000.0).collect();
    let opts = Options { feed_hold_at: presses, ..Options::default() };
    let (r, _) = std::thread::Builder::new().stack_size(256 * 1024).spawn(move || run_diags("gsk980tdi", opts, O0012)).unwrap().join().unwrap();
    assert!(r.last().is_some_and(|r| matches!(r.op, Op::End { .. })));
}

#[test]
fn seed_003_tapping_ignores_hold_and_override() {
    let prog = "G21 G17 G90 G0 X0. Y0. Z50.\nS500 M3\nG84 X10. Y10. Z-10. R2. F625.\nG80\nM30\n";
    let plain = run("fanuc0m", &[], Options::default(), prog);
    let feed = plain.iter().position(|r| matches!(r.op, Op::Feed { .. })).unwrap();
    let h = (plain[feed - 1].t_s + plain[feed].t_s) / 2.0;
    let r = run("fanuc0m", &[], hold_at(h), prog);
    let i = stops(&r)[0].0;
    // The stop comes after the whole tapping cycle (back at the initial level).
    assert_eq!(r[i - 1].op.end_point().unwrap().z, 50.0);
    // Feed override: no effect on the tapping feeds.
    let slow = run("fanuc0m", &[], Options { overrides: Overrides { feed_pct: 50.0, ..Overrides::default() }, ..Options::default() }, prog);
    assert_eq!(slow.last().unwrap().t_s, plain.last().unwrap().t_s);
}

#[test]
fn tdi_help_g04_note_5_hold_does_not_stop_a_dwell() {
    let prog = "G04 X2.\nG0 X10\nM30\n";
    let r = run("gsk980tdi", &[], hold_at(1.0), prog);
    let s = stops(&r);
    assert_eq!(s[0].0, 1);
    assert!((r[1].t_s - 2.0).abs() < 1e-9);
}

#[test]
fn a_hold_in_a_feed_decelerates_and_cycle_start_finishes_the_move() {
    let prog = "G98 G1 W-100 F600\nM30\n"; // 100 mm at 10 mm/s: 10 s + 0.05 s
    let r = run("gsk980tdi", &[], hold_at(5.0), prog);
    let i = stops(&r)[0].0;
    // At 5 s the tool is at 0.25 mm (accelerating for 0.05 s) + 4.95 s x 10 mm/s = 49.75 mm;
    // decelerating over 0.05 s covers 0.25 mm more: it stops at 50 mm, at 5.05 s.
    let p = r[i - 1].op.end_point().unwrap();
    assert!((p.z + 50.0).abs() < 1e-6, "{p:?}");
    assert!((r[i - 1].t_s - 5.05).abs() < 1e-9);
    assert_eq!(r[i + 1].op.end_point().unwrap().z, -100.0);
}

#[test]
fn single_block_stops_after_whole_cycles_runs_and_holes() {
    let sb = Options { single_block: true, ..Options::default() };
    // Seed 000 note 9: G92 stops only at the end of its cycle (with L2: after both starts).
    let r = run("gsk980tdi", &[], sb.clone(), "M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28 F6 L2 J0\nM30\n");
    let after_g92: Vec<_> = stops(&r).into_iter().filter(|(i, _)| r[*i].span.line == 3).collect();
    assert_eq!(after_g92.len(), 1);
    assert_eq!(r[after_g92[0].0 - 1].op.end_point().map(dia_z), Some((65.0, 5.0)));
    // Seed 001 G32.1 note 7: a run of continuous threads stops after its last block.
    let r = run("gsk988t", &[], sb.clone(), O0009_RUN);
    let lines: Vec<u32> = stops(&r).iter().map(|(i, _)| r[*i].span.line).collect();
    assert!(!lines.contains(&3) && lines.contains(&4), "{lines:?}");
    // docs/reference/behaviour.md: drilling cycles stop after each hole.
    let r = run("fanuc0m", &[], sb, "G21 G0 X0. Y0. Z50.\nS500 M3\nG91 G81 X10. Z-10. R-40. F500. K3\nG90 G80\nM30\n");
    assert_eq!(stops(&r).iter().filter(|(i, _)| r[*i].span.line == 3).count(), 3);
}

#[test]
fn reset_decelerates_and_ends_the_run() {
    // Seed 000 note 11: reset during a thread decelerates to a stop.
    let plain = run("gsk980tdi", &[], Options::default(), O0012);
    let h = mid_thread(&plain);
    let r = run("gsk980tdi", &[], Options { reset_at: Some(h), ..Options::default() }, O0012);
    let last = r.last().unwrap();
    assert!(matches!(last.op, Op::Stop { reason: StopReason::Reset }));
    // Decelerating from full speed takes the time constant, 0.05 s.
    assert!((r[r.len() - 2].t_s - (h + 0.05)).abs() < 1e-9);
    assert_eq!(r.iter().filter(|r| r.op.kind() == "thread").count(), 1);
}

#[test]
fn seed_001_note_13_dry_run_threads_at_1410_whatever_the_override() {
    let ov = Overrides { dry_run: true, feed_pct: 20.0, ..Overrides::default() };
    let r = run("gsk988t", &["1410=3000"], Options { overrides: ov, ..Options::default() }, "M14\nG00 X30 Z3\nG32.1 W-75 F2 S500\nM15\nM30\n");
    let i = r.iter().position(|r| r.op.kind() == "thread").unwrap();
    // 75 mm at 3000 mm/min = 1.5 s, plus the run's 0.05 s.
    assert!((r[i].t_s - r[i - 1].t_s - 1.55).abs() < 1e-9);
}

#[test]
fn overrides_scale_feeds_and_rapids_but_not_threads() {
    let prog = "M3 S300\nG0 X65 Z5\nG98 G1 W-10 F600\nG92 X58.7 Z-28 F3 J0\nM30\n";
    let base = run("gsk980tdi", &[], Options::default(), prog);
    let ov = Options { overrides: Overrides { feed_pct: 50.0, rapid_pct: 50.0, dry_run: false }, ..Options::default() };
    let slow = run("gsk980tdi", &[], ov, prog);
    let dur = |r: &[Record], kind: &str| {
        let i = r.iter().position(|x| x.op.kind() == kind).unwrap();
        r[i].t_s - r[i - 1].t_s
    };
    assert!((dur(&slow, "feed") - (2.0 + 0.05)).abs() < 1e-9); // 10 mm at 300 mm/min
    assert!((dur(&base, "feed") - (1.0 + 0.05)).abs() < 1e-9);
    assert!((dur(&slow, "thread") - dur(&base, "thread")).abs() < 1e-9);
}

/// Issue 5: the cycle time of a seed example, by hand. O0009 (seed 001): each G32.1 pass is
/// 75 mm / (2 mm x 500 rpm) = 4.5 s, plus the 0.05 s acceleration of the run.
#[test]
fn cycle_time_of_o0009_by_hand() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/gsk988t_o0009.nc")).unwrap();
    let r = run("gsk988t", &[], Options::default(), &text);
    let threads: Vec<f64> = r.windows(2).filter(|w| w[1].op.kind() == "thread").map(|w| w[1].t_s - w[0].t_s).collect();
    assert_eq!(threads.len(), 2);
    for d in threads {
        assert!((d - 4.55).abs() < 1e-9, "{d}");
    }
    // Rapids by hand at 8000 mm/min per axis with 0.1 s: from X0 Z0 to X30.14 Z3 the X axis
    // (15.07 mm) decides: 15.07 / 133.33 + 0.1 s.
    let first = r.iter().find(|r| r.op.kind() == "rapid").unwrap();
    assert!((first.t_s - (15.07 / (8000.0 / 60.0) + 0.1)).abs() < 1e-9);
    let total = r.last().unwrap().t_s;
    // A rapid of L mm at 133.33 mm/s with 0.1 s: L / v + 0.1 when L >= 13.33 mm (the distance
    // to reach full speed and stop again), else a triangle, 2 sqrt(L x 0.1 / v).
    let v = 8000.0 / 60.0;
    let rapid = |l: f64| if l >= v * 0.1 { l / v + 0.1 } else { 2.0 * (l * 0.1 / v).sqrt() };
    let hand = rapid(15.07) // G00 X30.14 Z3 (X decides)
        + 4.55 // first pass
        + rapid(1.715) // G00 X55 from X51.57
        + rapid(75.0) // W75
        + rapid(12.93) // X29.14 from X55
        + 4.55 // second pass
        + rapid(2.215) // G00 X55 from X50.57
        + rapid(75.0); // W75
    assert!((total - hand).abs() < 1e-6, "{total} vs {hand}");
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 100, .. ProptestConfig::default() })]

        /// Issue 5: a thread hold never loses the spindle phase: after the restart every thread
        /// record of the pass is the one of the plain run (same groove).
        #[test]
        fn thread_hold_keeps_the_groove(frac in 0.0f64..1.0, bit6 in 0u8..2, lead in 1.0f64..4.0) {
            let prog = format!("M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28 F{lead:.3} J2 K1 L2\nX58\nM30\n");
            let plain = run("gsk980tdi", &[], Options::default(), &prog);
            let end = plain.last().unwrap().t_s;
            let h = frac * end;
            let held = run("gsk980tdi", &[&format!("18.6={bit6}")], hold_at(h), &prog);
            let full = |r: &[Record]| -> Vec<(f64, f64, f64, f64)> {
                r.iter().filter_map(|r| match r.op {
                    Op::Thread { from, to, spindle_deg, .. } if (from.z - 5.0).abs() < 1e-9 => Some((from.x, to.x, to.z, spindle_deg)),
                    _ => None,
                }).collect()
            };
            let a = full(&plain);
            let b = full(&held);
            // Every pass of the plain run is cut, in order, with the same start angle; a pass
            // interrupted and restarted appears once more.
            prop_assert!(b.len() == a.len() || b.len() == a.len() + 1, "{} vs {}", a.len(), b.len());
            for p in &b {
                prop_assert!(a.iter().any(|q| (q.0 - p.0).abs() < 1e-9 && (q.3 - p.3).abs() < 1e-9 ), "{:?}", p);
            }
        }
    }
}

/// GSK988T manual, G32.1 note 5: with J and no K the tool goes straight out along the short axis
/// after the end point at parameter 1466's speed, with parameter 1628's acceleration time constant.
#[test]
fn seed_001_g32_1_note_5_the_pull_out_follows_1466_and_1628() {
    let prog = "M14\nG00 X30 Z3\nG32.1 W-20 F2 S500 J1\nG00 X55\nM15\nM30\n";
    let pull_out_s = |params: &[&str]| {
        let r = run("gsk988t", params, Options::default(), prog);
        let i = r.iter().position(|r| matches!(r.op, Op::Feed { .. })).expect("the pull-out feed");
        let Op::Feed { from, to, .. } = r[i].op else { unreachable!() };
        assert!((from.dist(&to) - 1.0).abs() < 1e-9, "J1: 1 mm out");
        r[i].t_s - r[i - 1].t_s
    };
    // 1 mm at 3000 mm/min (50 mm/s): never at speed with T = 0.05 s (it would need 2.5 mm):
    // a triangle, 2 sqrt(L T / v).
    let t = pull_out_s(&["1466=3000", "1628=50"]);
    assert!((t - 2.0 * (1.0f64 * 0.05 / 50.0).sqrt()).abs() < 1e-9, "{t}");
    let t = pull_out_s(&["1466=3000", "1628=500"]);
    assert!((t - 2.0 * (1.0f64 * 0.5 / 50.0).sqrt()).abs() < 1e-9, "{t}");
    // 600 mm/min (10 mm/s), T = 0.05 s: at speed after 0.5 mm: L / v + T.
    let t = pull_out_s(&["1466=600", "1628=50"]);
    assert!((t - (0.1 + 0.05)).abs() < 1e-9, "{t}");
}

/// Every press during a G32.1 thread is lost, not only the first (GSK988T manual, G32.1 note 6):
/// two presses in the same thread, and the programme still runs on without a stop.
#[test]
fn seed_001_g32_1_note_6_every_press_in_the_thread_is_lost() {
    let prog = "M14\nG00 X30 Z3\nG32.1 W-40 F2 S500\nG00 X55\nM15\nM30\n";
    let plain = run("gsk988t", &[], Options::default(), prog);
    let i = plain.iter().position(|r| r.op.kind() == "thread").unwrap();
    let (a, b) = (plain[i - 1].t_s, plain[i].t_s);
    let opts = Options { feed_hold_at: vec![a + (b - a) * 0.3, a + (b - a) * 0.6], ..Options::default() };
    let (r, d) = run_diags("gsk988t", opts, prog);
    assert!(stops(&r).is_empty(), "{:?}", stops(&r));
    assert_eq!(d.iter().filter(|d| d.code == "NCS-W23").count(), 2);
}

/// Two FEED HOLDs in one G92 cycle, the second during the restarted cycle: the machine cuts the
/// cycle once more from its start and never runs what was left of the first restart (the tool
/// never jumps: every move starts where the one before ended).
#[test]
fn a_second_thread_hold_in_a_restarted_cycle_restarts_it_once() {
    let plain = run("gsk980tdi", &[], Options::default(), O0012);
    let i = plain.iter().position(|r| r.op.kind() == "thread").unwrap();
    // The first press in the pull-out (the second thread record), the second in the thread of
    // the restarted cycle.
    let pull = (plain[i].t_s + plain[i + 1].t_s) / 2.0;
    let first = run("gsk980tdi", &[], hold_at(pull), O0012);
    // The restarted cycle's thread: the next thread record that starts at the cycle's Z5.
    let k = first.iter().enumerate().skip(i + 1).find(|(_, r)| matches!(r.op, Op::Thread { from, .. } if (from.z - 5.0).abs() < 1e-9)).map(|(k, _)| k).unwrap();
    let again = (first[k - 1].t_s + first[k].t_s) / 2.0;
    let r = run("gsk980tdi", &[], Options { feed_hold_at: vec![pull, again], ..Options::default() }, O0012);
    let mut at: Option<Vec3> = None;
    for rec in &r {
        if let (Some(p), Some(s)) = (at, rec.op.start_point()) {
            assert!(p.dist(&s) < 1e-9, "a jump from {p:?} to {s:?} at {rec:?}");
        }
        if let Some(e) = rec.op.end_point() {
            at = Some(e);
        }
    }
    assert!(matches!(r.last().unwrap().op, Op::End { .. }));
}

/// FANUC 0i-M manual, tapping mode (G63): the feed override does not apply and FEED HOLD lets
/// the move end; G64 ends the mode. G01 Z-10 from Z0 at F100: 6 s + 0.05 s at any override; the
/// G01 after G64 takes twice as long at 50 %.
#[test]
fn g63_tapping_mode_ignores_the_override_and_finishes_the_move_on_hold() {
    let prog = "G00 X1. Y0 Z0\nG63 G01 Z-10. F100.\nG64 G01 Z0\nM30\n";
    let plain = run("fanuc0m", &[], Options::default(), prog);
    let slow = run("fanuc0m", &[], Options { overrides: Overrides { feed_pct: 50.0, ..Overrides::default() }, ..Options::default() }, prog);
    let dur = |r: &[Record], line_index: usize| r[line_index].t_s - r[line_index - 1].t_s;
    let tap = plain.iter().position(|r| r.op.kind() == "feed").unwrap();
    assert_eq!(tap, 1, "{plain:?}");
    assert!((dur(&plain, tap) - 6.05).abs() < 1e-9);
    assert!((dur(&slow, tap) - 6.05).abs() < 1e-9);
    assert!((dur(&slow, tap + 1) - 2.0 * 6.0 - 0.05).abs() < 1e-9);
    // FEED HOLD 2 s into the tap: the stop comes at its end, Z-10.
    let h = plain[tap - 1].t_s + 2.0;
    let r = run("fanuc0m", &[], hold_at(h), prog);
    let i = stops(&r)[0].0;
    assert_eq!(r[i - 1].op.end_point().unwrap().z, -10.0);
}

/// GSK980TDi G92.1 and G32.1: a negative F is a left-hand thread, and the hand stays with the
/// lead: the passes that take the lead from memory turn the same way.
#[test]
fn a_left_hand_lead_stays_left_hand() {
    let rpms = |r: &[Record]| r.iter().filter_map(|r| if let Op::Thread { rpm, .. } = r.op { Some(rpm) } else { None }).collect::<Vec<_>>();
    let cycle = run("gsk980tdi", &[], Options::default(), "M14\nG00 X35 Z5\nG92.1 X29 Z-20 F-2 S500\nX28.5\nG92.1 X28 Z-20 F2 S500\nM15\nM30\n");
    assert_eq!(rpms(&cycle), vec![-500.0, -500.0, 500.0]);
    let run_g32_1 = run("gsk980tdi", &[], Options::default(), "M14\nG00 X29 Z5\nG32.1 W-10 F-2 S500\nW-10\nG00 X40\nM15\nM30\n");
    assert!(rpms(&run_g32_1).iter().all(|r| *r == -500.0), "{:?}", rpms(&run_g32_1));
}

/// G39 before a rapid: the rapid has no feed for the arc, so the corner is made as without G39
/// and every time stays finite.
#[test]
fn g39_before_a_rapid_makes_no_arc() {
    let setup = "[[offset]]\nnumber = 1\nradius_mm = 5.0\n";
    let (r, _) = common::run_setup("fanuc0m", setup, "G00 X-20. Y0\nG41 G01 X0 Y0 D1 F100.\nY20.\nG39\nG00 X30.\nG40 X50.\nM30\n", false);
    assert!(r.iter().all(|r| r.t_s.is_finite()));
    assert!(!r.iter().any(|r| r.op.kind() == "arc"));
    // With a feed after it, the arc is there.
    let (r, _) = common::run_setup("fanuc0m", setup, "G00 X-20. Y0\nG41 G01 X0 Y0 D1 F100.\nY20.\nG39\nX30.\nG40 X50.\nM30\n", false);
    assert_eq!(r.iter().filter(|r| r.op.kind() == "arc").count(), 1);
}

/// Single block with corners and lines of an angle alone (docs/commands/drawing.md): a block
/// whose move waits for the next block stops once, after its own move and its corner, not
/// before them; the block between a line of an angle alone and the line that ends it stops
/// after the held line is made.
#[test]
fn single_block_stops_after_held_corners_and_lines() {
    let sb = Options { single_block: true, ..Options::default() };
    let text = "G98 M03 S800 G00 X20. Z2.\nG01 Z0 F100.\nX40. ,C2.\nZ-20.\n,A90.\nS500\nX60. Z-30. ,A180.\nM30\n";
    let r = run("fanuc0t", &[], sb, text);
    let lines: Vec<u32> = stops(&r).iter().map(|(i, _)| r[*i].span.line).collect();
    assert_eq!(lines, vec![1, 2, 3, 4, 5, 6, 7, 8], "{lines:?}");
    // Each stop follows the last record of its block: line 3's chamfer, line 5's held line.
    for (i, _) in stops(&r) {
        let before = &r[i - 1];
        assert_eq!(before.span.line, r[i].span.line, "stop {:?} after a record of line {}", r[i].span, before.span.line);
    }
    let chamfer_end = stops(&r).iter().find(|(i, _)| r[*i].span.line == 3).map(|(i, _)| r[i - 1].op.end_point().map(dia_z)).unwrap();
    assert_eq!(chamfer_end, Some((40.0, -2.0)));
}

/// G39 at an inner corner overcuts on the machine (the FANUC manuals): warned, with its
/// direction (the arc loops round, 270 degrees) and without (the corner as without G39).
#[test]
fn g39_at_an_inner_corner_is_an_overcut_warning() {
    let setup = "[[offset]]\nnumber = 1\nradius_mm = 5.0\n";
    for (g39, arcs) in [("G39 I-10. J0", 1), ("G39", 0)] {
        let text = format!("G00 X-20. Y0\nG41 G01 X0 Y0 D1 F100.\nY20.\n{g39}\nX-30.\nG40 X-50.\nM30\n");
        let (r, d) = common::run_setup("fanuc0m", setup, &text, false);
        assert_eq!(d.iter().filter(|d| d.code == "NCS-W36").count(), 1, "{g39}: {d:?}");
        assert_eq!(r.iter().filter(|r| r.op.kind() == "arc").count(), arcs, "{g39}");
    }
    // An outer corner: no warning.
    let (_, d) = common::run_setup("fanuc0m", setup, "G00 X-20. Y0\nG41 G01 X0 Y0 D1 F100.\nY20.\nG39 I10. J0\nX30.\nG40 X50.\nM30\n", false);
    assert!(d.iter().all(|d| d.code != "NCS-W36"), "{d:?}");
}
