//! Drilling canned cycles (seed 003, FANUC 0-M), rule by rule.

use ncsight::motion::{Op, StopReason};
use ncsight::{Diagnostic, Record};

mod common;

fn run(params: &[&str], text: &str) -> (Vec<Record>, Vec<Diagnostic>) {
    let (records, diags) = common::run_plain("fanuc0m", params, text);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    (records, diags)
}

/// Bottoms reached: (x, y) of each feed that ends at the given level.
fn holes(records: &[Record], bottom: f64) -> Vec<(f64, f64)> {
    records
        .iter()
        .filter_map(|r| match r.op {
            Op::Feed { to, .. } if (to.z - bottom).abs() < 1e-9 => Some((to.x, to.y)),
            _ => None,
        })
        .collect()
}

const START: &str = "G21 G17 G90 G0 X0. Y0. Z50.\nS1000 M3\n";

#[test]
fn k_repeats_under_g91_are_equally_spaced_and_k0_stores_only() {
    // Seed 003: "G91 G81 X Y Z R F K5": the first hole at X Y from the tool, then equally spaced.
    let (r, _) = run(&[], &format!("{START}G91 G99 G81 X10. Y5. Z-10. R-48. F100. K5\nM30\n"));
    assert_eq!(holes(&r, -8.0), vec![(10.0, 5.0), (20.0, 10.0), (30.0, 15.0), (40.0, 20.0), (50.0, 25.0)]);
    // K0: the data is stored, nothing moves, not even the positioning (docs/reference/parameters.md); the
    // next block drills with the data.
    let (r, _) = run(&[], &format!("{START}G81 X10. Y10. Z-5. R2. F100. K0\nX20.\nM30\n"));
    assert_eq!(holes(&r, -5.0), vec![(20.0, 0.0)]);
    assert!(!r.iter().any(|r| matches!(r.op, Op::Rapid { to, .. } if to.x == 10.0)));
}

#[test]
fn g98_returns_to_the_initial_level_g99_to_r() {
    let (r, _) = run(&[], &format!("{START}G99 G81 X10. Y10. Z-5. R2. F100.\nX20.\nG98 X30.\nM30\n"));
    let tops: Vec<f64> = r
        .iter()
        .filter_map(|r| match r.op {
            Op::Rapid { from, to } if to.z > from.z => Some(to.z),
            _ => None,
        })
        .collect();
    // The first is the approach G0 Z50.
    assert_eq!(tops, vec![50.0, 2.0, 2.0, 50.0]);
}

#[test]
fn incremental_r_is_from_the_initial_level_and_z_from_r() {
    // docs/reference/behaviour.md: under G91, R from the initial level, Z from the R point.
    let (r, _) = run(&[], &format!("{START}G91 G81 X0. Y0. R-40. Z-15. F100.\nM30\n"));
    assert_eq!(holes(&r, -5.0).len(), 1);
}

#[test]
fn g80_and_group_01_clear_the_hole_data_but_not_f() {
    let (r, _) = run(&[], &format!("{START}G81 X10. Y10. Z-5. R2. F100.\nG80\nG85 X20. Y20. Z-6. R1.\nG01 X30.\nM30\n"));
    // The G85 hole feeds at the F kept through G80; G01 cancels G85 and feeds at F100 too.
    let feeds: Vec<f64> = r.iter().filter_map(|r| if let Op::Feed { feed_mm_min, .. } = r.op { Some(feed_mm_min) } else { None }).collect();
    assert!(feeds.iter().all(|f| *f == 100.0));
    let last = r.iter().rev().find(|r| matches!(r.op, Op::Feed { .. })).unwrap();
    assert!(matches!(last.op, Op::Feed { to, .. } if to.x == 30.0 && to.z == 50.0));
}

#[test]
fn tapping_with_the_wrong_spindle_direction_is_a_warning() {
    let (_, d) = run(&[], &format!("{START}G84 X10. Y10. Z-5. R2. F1000.\nG80\nG74 X20. Z-5. R2.\nM30\n"));
    let w: Vec<_> = d.iter().filter(|d| d.code == "NCS-W18").collect();
    assert_eq!(w.len(), 1, "G74 under M03 warns, G84 under M03 does not: {d:?}");
}

#[test]
fn g87_under_g99_returns_to_the_initial_level_with_a_warning() {
    let (r, d) = run(&[], &format!("{START}G99 G87 X10. Y10. R-20. Z-5. Q2. F100.\nM30\n"));
    assert!(d.iter().any(|d| d.code == "NCS-W19"));
    let last_rapid = r.iter().rev().find_map(|r| if let Op::Rapid { to, .. } = r.op { Some(to) } else { None }).unwrap();
    assert_eq!(last_rapid.z, 50.0);
}

#[test]
fn g88_stops_for_the_manual_retract() {
    let (r, _) = run(&[], &format!("{START}G88 X10. Y10. Z-5. R2. P500 F100.\nM30\n"));
    assert!(r.iter().any(|r| matches!(r.op, Op::Stop { reason: StopReason::ManualRetract })));
}

#[test]
fn g76_shift_follows_parameter_2_bits_4_and_5() {
    // (bit 5, bit 4) = 10: +Y.
    let (r, _) = run(&["2.5=1"], &format!("{START}G76 X10. Y10. Z-5. R2. Q1.5 F100.\nM30\n"));
    assert!(r.iter().any(|r| matches!(r.op, Op::Rapid { to, .. } if to.x == 10.0 && to.y == 11.5 && to.z == -5.0)));
    // 11: -Y.
    let (r, _) = run(&["2.5=1", "2.4=1"], &format!("{START}G76 X10. Y10. Z-5. R2. Q1.5 F100.\nM30\n"));
    assert!(r.iter().any(|r| matches!(r.op, Op::Rapid { to, .. } if to.y == 8.5 && to.z == -5.0)));
}

#[test]
fn hole_data_in_least_increments_without_a_point() {
    // FANUC: Z-5000 R2000 Q1000 are 5 mm, 2 mm, 1 mm (warned).
    let (r, d) = run(&["531=100"], &format!("{START}G73 X10. Y10. Z-5000 R2000 Q1000 F100.\nM30\n"));
    assert_eq!(holes(&r, -5.0).len(), 1);
    assert!(d.iter().filter(|d| d.code == "NCS-W02").count() >= 3);
}

/// 2 mm in pecks of 0.2: ten feeds, the last to the bottom, no sliver of an eleventh (the control
/// counts in increments; rs274 makes 11 here by adding Q in floating point).
#[test]
fn pecks_do_not_drift() {
    for code in ["G83", "G73"] {
        let (r, _) = run(&[], &format!("{START}G98 {code} X0. Y0. Z-2. R0. Q0.2 F100.\nM30\n"));
        let feeds: Vec<f64> = r.iter().filter_map(|r| if let Op::Feed { to, .. } = r.op { Some(to.z) } else { None }).collect();
        assert_eq!(feeds.len(), 10, "{code}: {feeds:?}");
        assert_eq!(*feeds.last().unwrap(), -2.0);
    }
}

/// `text` on the FANUC 0-M through the push interface (see [`common::run_pushed`]).
fn run_pushed(text: &str) -> (Vec<Record>, Vec<Diagnostic>) {
    common::run_pushed("fanuc0m", None, text)
}

/// A drilling block too big to hold (about 60,000 records: G83 over 202 mm in 0.02 mm pecks,
/// then twice more with K2 under G91) is made as it is handed on when the consumer takes each
/// record as it comes (issue 34), record for record what the ordinary path makes: the pull
/// iterator, which holds a block's records whole, gives the same records, block ends and times.
#[test]
fn a_deferred_drilling_block_makes_the_records_the_ordinary_path_makes() {
    let text = "G21 G17 G90 G00 X0. Y0. Z10.\nS1000 M03\nF500.\nG99 G83 X10. Y10. Z-200. R2. Q0.02\nG91 X5. K2\nG90 G80\nG00 Z10.\nM30\n";
    let (deferred, d1) = run_pushed(text);
    let (ordinary, d2) = common::run_plain("fanuc0m", &[], text);
    assert!(d1.iter().chain(&d2).all(|d| !d.is_alarm()), "{d1:?} {d2:?}");
    assert!(deferred.len() > 50_000, "{} records", deferred.len());
    common::same_records(&deferred, &ordinary);
    // Three holes, each to Z-200.
    assert_eq!(deferred.iter().filter(|r| matches!(r.op, ncsight::motion::Op::Feed { to, .. } if to.z == -200.0)).count(), 3);
}

/// Past the ordinary path's cap (30,000 pecks in one block), the pushed run goes on (its holes
/// deferred) where the pull iterator, which would have to hold them, stops with NCS-E40.
#[test]
fn a_block_past_the_cap_runs_pushed_and_alarms_pulled() {
    let text = "G21 G17 G90 G00 X0. Y0. Z10.\nS1000 M03\nF500.\nG98 G83 X10. Y10. Z-100. R2. Q0.002\nG80\nM30\n";
    let (records, diags) = run_pushed(text);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    assert!(records.len() > 150_000, "{}", records.len());
    let (_, diags) = common::run_plain("fanuc0m", &[], text);
    assert!(diags.iter().any(|d| d.is_alarm() && d.code == "NCS-E40"), "{diags:?}");
}
