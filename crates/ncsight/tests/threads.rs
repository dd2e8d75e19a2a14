//! Thread commands, rule by rule: each test names the manual note it follows.

use ncsight::motion::{LongAxis, Op, Vec3};
use ncsight::{Diagnostic, Record};

mod common;

struct Run {
    records: Vec<Record>,
    diags: Vec<Diagnostic>,
}

fn run(machine: &str, params: &[&str], text: &str) -> Run {
    let (records, diags) = common::run_plain(machine, params, text);
    Run { records, diags }
}

impl Run {
    fn alarm(&self) -> Option<&Diagnostic> {
        self.diags.iter().find(|d| d.is_alarm())
    }

    fn ok(self) -> Self {
        assert!(self.alarm().is_none(), "unexpected alarm {:?}", self.alarm());
        self
    }

    fn warned(&self, code: &str) -> bool {
        self.diags.iter().any(|d| d.code == code)
    }

    /// End points in the display convention (X as a diameter), rounded to 1e-6.
    fn ends(&self) -> Vec<(&'static str, f64, f64)> {
        self.records.iter().filter_map(|r| r.op.end_point().map(|p| (r.op.kind(), round(2.0 * p.x), round(p.z)))).collect()
    }

    fn threads(&self) -> Vec<(Vec3, Vec3, f64, f64, f64, LongAxis)> {
        self.records
            .iter()
            .filter_map(|r| match r.op {
                Op::Thread { from, to, lead_mm, spindle_deg, rpm, long_axis } => Some((from, to, lead_mm, spindle_deg, rpm, long_axis)),
                _ => None,
            })
            .collect()
    }
}

fn round(v: f64) -> f64 {
    (v * 1e6).round() / 1e6
}

const G92_START: &str = "M3 S300\nG0 X65 Z5\n";

fn g92(block: &str, params: &[&str]) -> Run {
    run("gsk980tdi", params, &format!("{G92_START}{block}\nM30\n"))
}

/// The cycle's pull-out segment end and the point where it starts.
fn pull_out_of(r: &Run) -> ((f64, f64), (f64, f64)) {
    let e = r.ends();
    let threads: Vec<_> = e.iter().enumerate().filter(|(_, x)| x.0 == "thread").map(|(i, _)| i).collect();
    let a = e[threads[0]];
    let b = e[*threads.last().unwrap()];
    ((a.1, a.2), (b.1, b.2))
}

#[test]
fn seed_000_note_2_j_and_k_omitted_use_no_19() {
    // No.19 = 10 -> 1 lead = 3 mm on both axes (45 degrees).
    let r = g92("G92 X58.7 Z-28 F3", &[]).ok();
    assert_eq!(pull_out_of(&r), ((58.7, -25.0), (64.7, -28.0)));
    let r = g92("G92 X58.7 Z-28 F3", &["19=5"]).ok();
    assert_eq!(pull_out_of(&r), ((58.7, -26.5), (61.7, -28.0)));
}

/// A G76 first block's P(r) rewrites the pull-out parameter for the rest of the run, and G92
/// reads the same one: GSK980TDi No.19 (TAC p135: its run-out width serves G92 and G76), FANUC
/// 5130 on fanuc0t and gsk988t (inferred). `P020560`: r = 05, half a lead = 1.5 mm at F3.
#[test]
fn a_g76_first_block_rewrites_the_g92_pull_out() {
    let r = g92("G76 P020560 Q150 R0.1\nG92 X58.7 Z-28 F3", &[]).ok();
    assert_eq!(pull_out_of(&r), ((58.7, -26.5), (61.7, -28.0)));
    for machine in ["fanuc0t", "gsk988t"] {
        let r = run(machine, &[], "M3 S300\nG0 X65. Z5.\nG76 P020560 Q150 R100\nG92 X58.7 Z-28. F3.\nM30\n").ok();
        assert_eq!(pull_out_of(&r), ((58.7, -26.5), (61.7, -28.0)), "{machine}");
    }
}

#[test]
fn seed_000_note_3_j_omitted() {
    // Long axis by K, short axis by No.19 (here 0.5 lead = 1.5 mm).
    let r = g92("G92 X58.7 Z-28 F3 K2", &["19=5"]).ok();
    assert_eq!(pull_out_of(&r), ((58.7, -26.0), (61.7, -28.0)));
}

#[test]
fn seed_000_notes_4_and_6_k_omitted_or_zero_is_j() {
    for block in ["G92 X58.7 Z-28 F3 J2", "G92 X58.7 Z-28 F3 J2 K0"] {
        let r = g92(block, &[]).ok();
        assert_eq!(pull_out_of(&r), ((58.7, -26.0), (62.7, -28.0)), "{block}");
    }
}

#[test]
fn seed_000_notes_5_and_7_j_zero_is_no_pull_out() {
    for block in ["G92 X58.7 Z-28 F3 J0", "G92 X58.7 Z-28 F3 J0 K0", "G92 X58.7 Z-28 F3 J0 K2"] {
        let r = g92(block, &[]).ok();
        assert_eq!(r.threads().len(), 1, "{block}");
        assert_eq!(r.ends()[2], ("thread", 58.7, -28.0));
        assert_eq!(r.ends()[3], ("rapid", 65.0, -28.0));
    }
}

#[test]
fn seed_000_note_10_negative_j_k_count_as_positive() {
    let a = g92("G92 X58.7 Z-28 F3 J-3 K-1", &[]).ok();
    let b = g92("G92 X58.7 Z-28 F3 J3 K1", &[]).ok();
    assert_eq!(a.ends(), b.ends());
}

#[test]
fn seed_000_note_8_no_107_short_axis_speed() {
    // No.107 = 600 mm/min, long axis 3 x 300 = 900 mm/min: in K1 the short axis covers 2/3 mm
    // of J3 (radius); the rest at rapid.
    let r = g92("G92 X58.7 Z-28 F3 J3 K1", &["107=600"]).ok();
    let e = r.ends();
    assert_eq!(e[2], ("thread", 58.7, -27.0));
    assert_eq!(e[3], ("thread", round(58.7 + 2.0 * 600.0 / 900.0), -28.0));
    assert_eq!(e[4], ("rapid", 64.7, -28.0));
}

#[test]
fn pull_out_direction_is_toward_the_start_point() {
    // Internal thread: the start X20 is inside the cut X30, so J pulls toward smaller X.
    let r = run("gsk980tdi", &[], "M3 S300\nG0 X20 Z5\nG92 X30 Z-20 F2 J1 K1\nM30\n").ok();
    assert_eq!(pull_out_of(&r), ((30.0, -19.0), (28.0, -20.0)));
}

#[test]
fn seed_001_note_11_j_is_clamped_to_the_retract_distance() {
    // From X60 the retract to the start is 0.65 mm of radius: J3 becomes 0.65.
    let r = run("gsk980tdi", &[], "M3 S300\nG0 X60 Z5\nG92 X58.7 Z-28 F3 J3 K1\nM30\n").ok();
    assert_eq!(pull_out_of(&r).1, (60.0, -28.0));
}

#[test]
fn g92_continuation_blocks_keep_z_taper_and_pull_out() {
    let r = g92("G92 X58.7 Z-28 R-1 F3 J3 K1\nX57.7", &[]).ok();
    let e = r.ends();
    // Pass 2 starts at X57.7 + 2 x (-1) = 55.7 and ends at Z-28 with the same pull-out.
    assert_eq!(e[6], ("rapid", 55.7, 5.0));
    assert_eq!(e[8], ("thread", 63.7, -28.0));
}

#[test]
fn g92_taper_long_axis_and_sign_rule() {
    // R/U sign rule (seed 000): U = -6.3 from X65 to X58.7, so R may be positive only up to 3.15.
    let r = g92("G92 X58.7 Z-28 R4 F3", &[]);
    assert_eq!(r.alarm().unwrap().code, "NCS-E45");
    assert!(g92("G92 X58.7 Z-28 R3 F3", &[]).alarm().is_none());
    // A steep taper: 4 mm of Z against 10 mm of radius, X is the long axis (seed 000).
    let r = run("gsk980tdi", &[], "M3 S300\nG0 X100 Z5\nG92 X80 Z1 R10 F2 J0\nM30\n").ok();
    assert_eq!(r.threads()[0].5, LongAxis::X);
}

#[test]
fn g92_face_thread_is_an_alarm() {
    let r = g92("G92 X40 W0 F3", &[]);
    assert_eq!(r.alarm().unwrap().code, "NCS-E44");
}

#[test]
fn g92_inch_threads_per_inch() {
    let r = g92("G92 X58.7 Z-28 I10 J0", &[]).ok();
    assert!((r.threads()[0].2 - 2.54).abs() < 1e-12);
}

#[test]
fn g92_l_starts_are_full_cycles_360_over_l_apart() {
    let r = g92("G92 X58.7 Z-28 F6 L3 J0", &[]).ok();
    let starts: Vec<f64> = r.threads().iter().map(|t| t.3).collect();
    assert_eq!(starts, vec![0.0, 120.0, 240.0]);
    // Each start is a full four-step cycle: 3 x (rapid, thread, rapid, rapid) after the approach.
    assert_eq!(r.ends().iter().filter(|e| e.0 == "rapid" && e.1 == 65.0 && e.2 == 5.0).count(), 1 + 3);
    // L is modal (seed 000): the continuation block cuts three starts too.
    let r = g92("G92 X58.7 Z-28 F6 L3 J0\nX58", &[]).ok();
    assert_eq!(r.threads().len(), 6);
    assert!(g92("G92 X58.7 Z-28 F6 L100", &[]).alarm().is_some());
}

#[test]
fn g92_repeated_passes_start_at_the_same_phase() {
    let r = run("gsk980tdi", &[], &format!("{G92_START}G92 X58.7 Z-28 F3 J3 K1\nX57.7\nX57\nX56.9\nM30\n")).ok();
    let firsts: Vec<f64> = r.threads().iter().step_by(2).map(|t| t.3).collect();
    assert_eq!(firsts, vec![0.0; 4]);
}

#[test]
fn thread_warnings() {
    // A later pass with another speed, and an infeed larger than the one before.
    let r = run("gsk980tdi", &[], &format!("{G92_START}G92 X58.7 Z-28 F3 J0\nX58\nX57\nS400\nX56.9\nM30\n")).ok();
    assert!(r.warned("NCS-W17"), "{:?}", r.diags);
    assert!(r.warned("NCS-W16"));
    // G96 in force.
    let r = run("gsk980tdi", &[], "G50 S2000\nG96 S100 M3\nG0 X65 Z5\nG92 X58.7 Z-28 F3\nM30\n").ok();
    assert!(r.warned("NCS-W14"));
    // Lead x rpm above No.027.
    let r = run("gsk980tdi", &[], "M3 S3000\nG0 X65 Z5\nG92 X58.7 Z-28 F3\nM30\n").ok();
    assert!(r.warned("NCS-W15"));
}

#[test]
fn g32_continuous_run_keeps_the_phase_and_pulls_out_once() {
    // TDi help G32 notes 1, 2 and 5: the second block continues without waiting, its Q is
    // ignored, and the modal J/K make the pull-out at the end of the run only.
    let r = run("gsk980tdi", &[], "M3 S300\nG0 X40 Z2\nG32 Z-10 F2 Q90000\nG32 X44 Z-20 Q45000\nG32 Z-30 J2 K2\nG0 X60\nM30\n");
    let r = r.ok();
    let t = r.threads();
    assert_eq!(t.len(), 4, "{:?}", r.ends());
    assert!((t[0].3 - 90.0).abs() < 1e-9);
    // 12 mm of Z at lead 2 is 6 revolutions: the second block starts at 90 degrees again.
    assert!((t[1].3 - 90.0).abs() < 1e-9);
    assert!(r.warned("NCS-W04"));
    // Third block: 10 mm, 5 revolutions; it ends with the pull-out 2 mm before Z-30.
    assert!((t[2].3 - 90.0).abs() < 1e-9);
    assert_eq!((round(2.0 * t[2].1.x), round(t[2].1.z)), (44.0, -28.0));
    assert_eq!((round(2.0 * t[3].1.x), round(t[3].1.z)), (48.0, -30.0));
    // The time runs on without a gap: every record follows the one before.
    let times: Vec<f64> = r.records.iter().map(|r| r.t_s).collect();
    assert!(times.windows(2).all(|w| w[1] >= w[0]));
}

#[test]
fn g32_help_text_j_k_rules() {
    // J omitted: no pull-out (TDi p151); K omitted: K = J; J signed.
    let r = run("gsk980tdi", &[], "M3 S300\nG0 X40 Z2\nG32 Z-20 F2 K3\nG0 X50\nM30\n").ok();
    assert_eq!(r.threads().len(), 1);
    let r = run("gsk980tdi", &[], "M3 S300\nG0 X40 Z2\nG32 Z-20 F2 J-1\nG0 X50\nM30\n").ok();
    let t = r.threads();
    assert_eq!((round(2.0 * t[0].1.x), round(t[0].1.z)), (40.0, -19.0));
    assert_eq!((round(2.0 * t[1].1.x), round(t[1].1.z)), (38.0, -20.0));
}

#[test]
fn g32_needs_a_turning_spindle_and_a_lead() {
    let r = run("gsk980tdi", &[], "G0 X40 Z2\nG32 Z-20 F2\nM30\n");
    assert_eq!(r.alarm().unwrap().code, "NCS-E39");
    let r = run("gsk980tdi", &[], "M3 S100\nG0 X40 Z2\nG32 Z-20\nM30\n");
    assert_eq!(r.alarm().unwrap().code, "NCS-E36");
}

#[test]
fn g32_q_units() {
    // Q in 0.001 degree; on the GSK980TDi a decimal point is ignored with a warning (TDi p150).
    let r = run("gsk980tdi", &[], "M3 S300\nG0 X40 Z2\nG32 Z-20 F2 Q180.0\nM30\n").ok();
    assert!((r.threads()[0].3 - 0.18).abs() < 1e-12);
    assert!(r.warned("NCS-W07"));
}

const O0009_START: &str = "M14\nG00 X30.14 Z3\n";

fn g321(block: &str) -> Run {
    run("gsk988t", &[], &format!("{O0009_START}{block}\nG00 X55\nM15\nM30\n"))
}

#[test]
fn seed_001_g32_1_q_rules() {
    // Rule 2: ISB 0.001 degree, Q180000 = 180 degrees, Q180 = 0.18 degrees, above 360000 = 360 = 0.
    for (q, deg) in [("Q180000", 180.0), ("Q180", 0.18), ("Q400000", 0.0), ("", 0.0)] {
        let r = g321(&format!("G32.1 X51.57 W-75 F2.0 S500 {q}")).ok();
        assert!((r.threads()[0].3 - deg).abs() < 1e-12, "{q}");
    }
    // "Cannot have a decimal point".
    assert_eq!(g321("G32.1 X51.57 W-75 F2.0 S500 Q180.").alarm().unwrap().code, "NCS-E07");
}

#[test]
fn seed_001_g32_1_spindle_rules() {
    // Note 14: position mode required.
    let r = run("gsk988t", &[], "G00 X30 Z3\nG32.1 W-10 F2 S500\nM30\n");
    assert_eq!(r.alarm().unwrap().code, "NCS-E41");
    // Note 12: a spindle speed is required.
    let r = run("gsk988t", &[], "M14\nG00 X30 Z3\nG32.1 W-10 F2\nM30\n");
    assert_eq!(r.alarm().unwrap().code, "NCS-E36");
    // S < 0: the negative direction.
    let r = g321("G32.1 X51.57 W-75 F2.0 S-500").ok();
    assert_eq!(r.threads()[0].4, -500.0);
}

#[test]
fn seed_001_g32_1_pull_out_notes() {
    // Note 2: J omitted: none. Note 4: J = 0: none.
    assert_eq!(g321("G32.1 W-20 F2 S500 K2").ok().threads().len(), 1);
    assert_eq!(g321("G32.1 W-20 F2 S500 J0 K2").ok().threads().len(), 1);
    // Notes 3 and 5: K omitted: thread to the end, then J straight out at parameter 1466's speed.
    let r = g321("G32.1 W-20 F2 S500 J2").ok();
    let after = r.records.iter().find_map(|r| if let Op::Feed { to, feed_mm_min, .. } = r.op { Some((to, feed_mm_min)) } else { None });
    let (to, feed) = after.expect("a perpendicular pull-out feed");
    assert_eq!((round(2.0 * to.x), round(to.z)), (34.14, -17.0));
    assert_eq!(feed, 3000.0);
    let r = run("gsk988t", &["1466=1200"], &format!("{O0009_START}G32.1 W-20 F2 S500 J2 K0\nM30\n")).ok();
    assert!(r.records.iter().any(|r| matches!(r.op, Op::Feed { feed_mm_min, .. } if feed_mm_min == 1200.0)));
    // J signed: J-1 K1 pulls toward smaller X during the last 1 mm.
    let r = g321("G32.1 W-20 F2 S500 J-1 K1").ok();
    let t = r.threads();
    assert_eq!((round(2.0 * t[1].1.x), round(t[1].1.z)), (28.14, -17.0));
    // K has no sign; note 9: a pull-out longer than the thread.
    assert_eq!(g321("G32.1 W-20 F2 S500 J1 K-1").alarm().unwrap().code, "NCS-E33");
    assert_eq!(g321("G32.1 W-20 F2 S500 J1 K25").alarm().unwrap().code, "NCS-E42");
}

#[test]
fn seed_001_g32_1_note_1_j_k_only_on_the_last_block() {
    // Without J/K the first block runs on into the second; the second's J/K make the pull-out.
    let r = g321("G32.1 W-10 F2 S500\nG32.1 W-10 J1 K1").ok();
    let t = r.threads();
    assert_eq!(t.len(), 3);
    assert!((t[1].3 - 0.0).abs() < 1e-9); // 10 mm at lead 2: 5 revolutions
                                          // A first block with J/K is not continuous: it pulls out, and the next block starts anew
                                          // at its own Q (J/K stay modal, so it pulls out too).
    let r = g321("G32.1 W-10 F2 S500 J1 K1\nG32.1 W-10 Q90000").ok();
    let t = r.threads();
    assert_eq!(t.len(), 4);
    assert!((t[2].3 - 90.0).abs() < 1e-9);
    // J0 K0 in a first block keeps the run going.
    let r = g321("G32.1 W-10 F2 S500 J0 K0\nG32.1 W-10 J1 K1").ok();
    assert_eq!(r.threads().len(), 3);
}

#[test]
fn seed_001_g32_1_note_10_basic_and_parallel_axis() {
    let r = g321("G32.1 X40 U2 W-10 F2 S500");
    assert_eq!(r.alarm().unwrap().code, "NCS-E34");
}

fn g921(block: &str, params: &[&str]) -> Run {
    run("gsk988t", params, &format!("G0 X65 Z5\nM14\n{block}\nM15\nM30\n"))
}

#[test]
fn seed_001_g92_1_note_1_parameters_5130_5131() {
    // J, K omitted: long = 5130 x 0.1 x F (10 -> 3 mm); 5131 = 0: 45 degrees.
    let r = g921("G92.1 X58.7 Z-28 F3 S300", &[]).ok();
    assert_eq!(pull_out_of(&r), ((58.7, -25.0), (64.7, -28.0)));
    // 5131 = 30: short = 3 x tan 30 = 1.732 (radius).
    let r = g921("G92.1 X58.7 Z-28 F3 S300", &["5131=30"]).ok();
    let (_, (x, _)) = pull_out_of(&r);
    assert!((x - (58.7 + 2.0 * 3.0 * 30f64.to_radians().tan())).abs() < 1e-6);
}

#[test]
fn seed_001_g92_1_notes_2_to_6() {
    // Note 2: J omitted: long by K, short by 5130 (5 -> 1.5 mm).
    let r = g921("G92.1 X58.7 Z-28 F3 S300 K2", &["5130=5"]).ok();
    assert_eq!(pull_out_of(&r), ((58.7, -26.0), (61.7, -28.0)));
    // Notes 3 and 4: K omitted or 0: J straight out after the end point.
    for b in ["G92.1 X58.7 Z-28 F3 S300 J1", "G92.1 X58.7 Z-28 F3 S300 J1 K0"] {
        let r = g921(b, &[]).ok();
        assert_eq!(r.threads().len(), 1, "{b}");
        assert!(r.records.iter().any(|r| matches!(r.op, Op::Feed { .. })), "{b}");
    }
    // Notes 5 and 6: J = 0: none.
    assert_eq!(g921("G92.1 X58.7 Z-28 F3 S300 J0 K2", &[]).ok().threads().len(), 1);
    // J cannot be negative.
    assert_eq!(g921("G92.1 X58.7 Z-28 F3 S300 J-1 K1", &[]).alarm().unwrap().code, "NCS-E33");
    // Note 10: pull-out longer than the thread.
    assert_eq!(g921("G92.1 X58.7 Z-28 F3 S300 J1 K40", &[]).alarm().unwrap().code, "NCS-E42");
    // Note 12: position mode.
    let r = run("gsk988t", &[], "G0 X65 Z5\nG92.1 X58.7 Z-28 F3 S300\nM30\n");
    assert_eq!(r.alarm().unwrap().code, "NCS-E41");
}

#[test]
fn seed_001_g92_1_q_and_l() {
    let r = g921("G92.1 X58.7 Z-28 F6 S300 L2 Q30000 J0", &[]).ok();
    let starts: Vec<f64> = r.threads().iter().map(|t| t.3).collect();
    assert_eq!(starts, vec![30.0, 210.0]);
}

#[test]
fn seed_002_arc_thread_rules() {
    let base = "G98 F100\nG1 X10 Z-15\nM03 S200\n";
    // R negative: alarm. Crossing a sector: alarm.
    let r = run("gsk988t", &[], &format!("{base}G32.3 W-10 F2 R-10\nM30\n"));
    assert_eq!(r.alarm().unwrap().code, "NCS-E33");
    let r = run("gsk988t", &[], &format!("{base}G32.2 X30 Z-25 F2 R10\nM30\n"));
    assert_eq!(r.alarm().unwrap().code, "NCS-E43", "{:?}", r.diags);
    // R wins over I/K (note 4), with a warning.
    let r = run("gsk988t", &[], &format!("{base}G32.3 W-10 F2 R10 I3 K3\nM30\n")).ok();
    assert!(r.records.iter().any(|r| r.op.kind() == "thread_arc"));
    assert!(r.warned("NCS-W04"));
    // Q in degrees on the GSK988T (seed 002 table), in 0.001 degree on the GSK980TDi (help text).
    let r = run("gsk988t", &[], &format!("{base}G32.3 W-10 F2 R10 Q90.5\nM30\n")).ok();
    let deg = r.records.iter().find_map(|r| if let Op::ThreadArc { spindle_deg, .. } = r.op { Some(spindle_deg) } else { None });
    assert_eq!(deg, Some(90.5));
    let r = run("gsk980tdi", &[], &format!("{base}G32.3 W-10 F2 R10 Q90500\nM30\n")).ok();
    let deg = r.records.iter().find_map(|r| if let Op::ThreadArc { spindle_deg, .. } = r.op { Some(spindle_deg) } else { None });
    assert!((deg.unwrap() - 90.5).abs() < 1e-9);
    // F[25.4/n] for inch threads (seed 002, I is taken by the centre).
    let r = run("gsk988t", &[], &format!("{base}G32.3 W-10 F[25.4/10] R10\nM30\n")).ok();
    assert!(r.records.iter().any(|r| matches!(r.op, Op::ThreadArc { lead_mm, .. } if (lead_mm - 2.54).abs() < 1e-12)));
}

#[test]
fn seed_002_arc_threads_in_g17_and_g19() {
    // G17: an arc in XY around Y's direction has X long... here the arc sits near +X of its
    // centre, so Y is the long axis.
    let r = run("gsk988t", &[], "G98 F100\nG17\nG1 X20 Y-5 Z0\nM3 S100\nG32.3 X20 Y5 F1 R10\nM30\n").ok();
    let la = r.records.iter().find_map(|r| if let Op::ThreadArc { long_axis, .. } = r.op { Some(long_axis) } else { None });
    assert_eq!(la, Some(LongAxis::Y));
    let r = run("gsk988t", &[], "G98 F100\nG19\nG1 Y10 Z-5\nM3 S100\nG32.3 Y10 Z5 F1 J-10 K5\nM30\n").ok();
    let la = r.records.iter().find_map(|r| if let Op::ThreadArc { long_axis, .. } = r.op { Some(long_axis) } else { None });
    assert_eq!(la, Some(LongAxis::Z));
}

#[test]
fn seed_004_yasnac_k_flank_infeed_and_e_lead() {
    let base = "G97 S300 M03\nG00 X80. Z80.8\n";
    // K shifts the cut's start along Z by K for that pass; the end point stays (docs/reference/behaviour.md).
    let r = run("yasnac-lx3", &[], &format!("{base}G92 X70. W-50.8 K-0.3 F2.\nM30\n")).ok();
    let e = r.ends();
    assert_eq!(e[1], ("rapid", 70.0, 80.5));
    assert_eq!(e[2], ("thread", 70.0, 30.0));
    // E is a lead like F.
    let r = run("yasnac-lx3", &[], &format!("{base}G92 X70. W-50.8 E1.814286\nM30\n")).ok();
    assert!((r.threads()[0].2 - 1.814286).abs() < 1e-12);
    // T, S and M blocks without motion do not run the cycle again (seed 004 (5) a).
    let r = run("yasnac-lx3", &[], &format!("{base}G92 X70. W-50.8 F2.\nS310\nX69.\nM30\n")).ok();
    assert_eq!(r.threads().len(), 2);
}

/// Issue 3's invariant: along a run of thread records the spindle angle at the start of each
/// record is the previous start plus 360 x long-axis travel / lead.
#[test]
fn spindle_phase_carries_through_pull_outs_and_runs() {
    let programmes = [
        ("gsk980tdi", "M3 S300\nG0 X40 Z2\nG32 Z-10.3 F2 Q12345\nG32 X44 Z-20.7\nG32 Z-30 J2 K1.3\nG0 X60\nM30\n"),
        ("gsk980tdi", "M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28.37 F3.3 J3 K1.7 L3\nX57.7\nM30\n"),
        ("gsk988t", "M14\nG0 X65 Z5\nG92.1 X58.7 Z-28 F3 S300 J2 K1.1 L2 Q33000\nM15\nM30\n"),
    ];
    for (m, p) in programmes {
        let r = run(m, &["107=0"].iter().filter(|_| m == "gsk980tdi").copied().collect::<Vec<_>>(), p).ok();
        let mut prev: Option<(f64, f64, f64, Vec3)> = None;
        for rec in &r.records {
            match rec.op {
                Op::Thread { from, to, lead_mm, spindle_deg, long_axis, .. } => {
                    let i = long_axis.index();
                    if let Some((deg, travel, lead, end)) = prev {
                        if end == from {
                            let expect = (deg + 360.0 * travel / lead).rem_euclid(360.0);
                            let diff = (expect - spindle_deg).abs();
                            assert!(diff < 1e-6 || (360.0 - diff) < 1e-6, "{m}: {expect} vs {spindle_deg}");
                        }
                    }
                    prev = Some((spindle_deg, (to.axis(i) - from.axis(i)).abs(), lead_mm, to));
                }
                _ => prev = None,
            }
        }
    }
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    /// Check the phase formula between every two touching thread records.
    fn phases_are_continuous(r: &Run) -> Result<(), TestCaseError> {
        let mut prev: Option<(f64, f64, f64, Vec3)> = None;
        for rec in &r.records {
            if let Op::Thread { from, to, lead_mm, spindle_deg, long_axis, .. } = rec.op {
                prop_assert!((0.0..360.0).contains(&spindle_deg));
                let i = long_axis.index();
                if let Some((deg, travel, lead, end)) = prev {
                    if end == from {
                        let expect = (deg + 360.0 * travel / lead).rem_euclid(360.0);
                        let d = (expect - spindle_deg).abs();
                        prop_assert!(d < 1e-6 || 360.0 - d < 1e-6, "{} vs {}", expect, spindle_deg);
                    }
                }
                prev = Some((spindle_deg, (to.axis(i) - from.axis(i)).abs(), lead_mm, to));
            } else {
                prev = None;
            }
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 200, .. ProptestConfig::default() })]

        #[test]
        fn g92_passes_and_starts(
            lead in 0.5f64..6.0,
            starts in 1u32..5,
            jk in prop::option::of((0.0f64..3.0, prop::option::of(0.0f64..3.0))),
            no107 in prop::sample::select(vec![0.0, 150.0, 600.0, 3000.0]),
            depths in prop::collection::vec(0.05f64..1.0, 1..5),
        ) {
            let mut text = format!("M3 S300\nG0 X65 Z5\nG92 X60 Z-30 F{lead:.4} L{starts}");
            if let Some((j, k)) = jk {
                text.push_str(&format!(" J{j:.3}"));
                if let Some(k) = k { text.push_str(&format!(" K{k:.3}")); }
            }
            let mut x = 60.0;
            for d in &depths {
                x -= d;
                text.push_str(&format!("\nX{x:.3}"));
            }
            text.push_str("\nM30\n");
            let r = run("gsk980tdi", &[&format!("107={no107}")], &text);
            prop_assert!(r.alarm().is_none(), "{:?}\n{}", r.alarm(), text);
            phases_are_continuous(&r)?;
            // The first thread record of each cycle: start k at k x 360 / L, every pass alike.
            let firsts: Vec<f64> = r.records.windows(2)
                .filter(|w| matches!(w[0].op, Op::Rapid { .. }) && matches!(w[1].op, Op::Thread { .. }))
                .map(|w| if let Op::Thread { spindle_deg, .. } = w[1].op { spindle_deg } else { unreachable!() })
                .collect();
            prop_assert_eq!(firsts.len(), (depths.len() + 1) * starts as usize);
            for (n, deg) in firsts.iter().enumerate() {
                let k = (n % starts as usize) as f64;
                let expect = (k * 360.0 / starts as f64).rem_euclid(360.0);
                prop_assert!((deg - expect).abs() < 1e-9, "start {} at {} not {}", k, deg, expect);
            }
        }

        #[test]
        fn g32_runs_carry_the_phase(
            lead in 0.5f64..5.0,
            q in 0u32..360000,
            segs in prop::collection::vec((1.0f64..20.0, -2.0f64..2.0), 1..5),
            j in prop::option::of(-2.0f64..2.0),
        ) {
            let mut text = format!("M3 S250\nG0 X40 Z2\nG32 W-{:.3} U{:.3} F{lead:.4} Q{q}", segs[0].0, segs[0].1);
            for (dz, dx) in &segs[1..] {
                text.push_str(&format!("\nG32 W-{dz:.3} U{dx:.3}"));
            }
            if let Some(j) = j {
                text.push_str(&format!(" J{j:.3} K0.5"));
            }
            text.push_str("\nG0 X80\nM30\n");
            let r = run("gsk980tdi", &[], &text);
            if let Some(a) = r.alarm() {
                // A pull-out longer than a short last block is the only alarm allowed.
                prop_assert_eq!(a.code, "NCS-E42", "{}", text);
                return Ok(());
            }
            phases_are_continuous(&r)?;
            let first = r.threads()[0].3;
            prop_assert!((first - q as f64 * 0.001).abs() < 1e-9);
        }
    }
}

#[test]
fn g32_j_k_in_a_first_block_stay_modal_for_the_run_end() {
    // TDi help G32 notes 1, 2: J/K may be left out of continuous blocks; the run's pull-out uses
    // the values in force. Writing them in the first block does not end the run (unlike G32.1).
    let r = run("gsk980tdi", &[], "M3 S300\nG0 X40 Z2\nG32 Z-10 F2 J2 K1\nZ-20\nG0 X60\nM30\n").ok();
    let t = r.threads();
    assert_eq!(t.len(), 3, "{:?}", r.ends());
    assert!((t[1].3 - 0.0).abs() < 1e-9); // 12 mm = 6 revolutions: no new wait
    assert_eq!((round(2.0 * t[2].1.x), round(t[2].1.z)), (44.0, -20.0));
}

#[test]
fn g92_j_k_stay_modal_across_other_codes() {
    // Seed 000 calls J/K modal; only seed 001 note 1 (G32.1) cancels them with other codes.
    let r = g92("G92 X58.7 Z-28 F3 J2 K1\nG0 X70\nG0 X65 Z5\nG92 X58.7 Z-28", &[]).ok();
    let threads: Vec<_> = r.threads().iter().map(|t| (round(2.0 * t.1.x), round(t.1.z))).collect();
    assert_eq!(threads[3], (62.7, -28.0));
}

#[test]
fn one_f_register_for_leads_and_feeds() {
    // The lead of a thread block stays as the F of a later G01, and the other way round.
    let r = run("gsk980tdi", &[], "M3 S300\nG99 G0 X40 Z2\nG32 Z-10 F1.5\nG0 X50\nG1 Z-12\nM30\n").ok();
    let feed = r.records.iter().find_map(|r| if let Op::Feed { feed_mm_min, .. } = r.op { Some(feed_mm_min) } else { None });
    assert_eq!(feed, Some(450.0)); // 1.5 mm/rev x 300 rpm
    let r = run("gsk980tdi", &[], "M3 S300\nG99 G1 X40 Z2 F2.5\nG32 Z-10\nM30\n").ok();
    assert_eq!(r.threads()[0].2, 2.5);
}

#[test]
fn seed_000_note_3_with_k0_pulls_out_at_rapid() {
    // J omitted, K0: no length along the long axis; No.19 along the short axis, at rapid.
    let r = g92("G92 X58.7 Z-28 F3 K0", &[]).ok();
    let e = r.ends();
    assert_eq!(e[2], ("thread", 58.7, -28.0));
    assert_eq!(e[3], ("rapid", 64.7, -28.0));
}

#[test]
fn seed_004_t_s_m_in_the_cycle_block_warn() {
    let r = run("yasnac-lx3", &[], "G97 S300 M03\nG00 X80. Z80.8\nG92 X70. W-50.8 F2. S600\nM30\n").ok();
    assert!(r.warned("NCS-W21"));
}

mod g76 {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 150, .. ProptestConfig::default() })]

        /// Issue 11, for G76 and G78: depths strictly increase until the finishing depth, the
        /// last roughing pass is at k - d, exactly m (G78: D) finishing passes at k, every pass
        /// of a start begins at that start's spindle angle, and G78's equal schedule steps by dd.
        #[test]
        fn compound_depth_schedule(
            k_um in 300u32..4000, first_frac in 0.05f64..0.9, dmin_um in 0u32..200,
            d_frac in 0.0f64..0.3, m in 1u32..5, lead in 0.5f64..4.0,
            g78 in any::<bool>(), equal in any::<bool>(), infeed in 0u32..4, starts in 1u32..4,
        ) {
            let first_um = ((k_um as f64 * first_frac) as u32).max(1);
            let d_mm = ((k_um as f64 * d_frac) as u32) as f64 / 1000.0;
            let (first_block, starts) = if g78 {
                (format!("G78 P{:02}{infeed:02}60 Q{dmin_um} R{d_mm:.3} D{m} L{starts}", u32::from(!equal)), starts)
            } else {
                (format!("G76 P{m:02}0060 Q{dmin_um} R{d_mm:.3}"), 1)
            };
            let code = if g78 { "G78" } else { "G76" };
            let prog = format!(
                "G97 S300 M03\nG0 X70 Z5\n{first_block}\n{code} X60 Z-40 P{k_um} Q{first_um} F{lead:.3}\nM30\n"
            );
            let r = run("gsk980tdi", &[], &prog);
            prop_assert!(r.alarm().is_none(), "{:?}\n{}", r.alarm(), prog);
            let k = k_um as f64 / 1000.0;
            // The cut of each pass: the first thread record after a rapid to the pass start.
            let cuts: Vec<(f64, f64)> = r.records.windows(2)
                .filter(|w| matches!(w[0].op, Op::Rapid { .. }) && matches!(w[1].op, Op::Thread { .. }))
                .map(|w| match w[1].op { Op::Thread { from, spindle_deg, .. } => (k - (from.x - 30.0), spindle_deg), _ => unreachable!() })
                .collect();
            // Each depth is cut once per start, start j at j x 360 / L.
            prop_assert_eq!(cuts.len() % starts as usize, 0);
            for (i, c) in cuts.iter().enumerate() {
                let j = (i % starts as usize) as f64;
                prop_assert!((c.1 - j * 360.0 / starts as f64).abs() < 1e-9, "{:?}", cuts);
                prop_assert!((c.0 - cuts[i - i % starts as usize].0).abs() < 1e-12);
            }
            let passes: Vec<f64> = cuts.iter().step_by(starts as usize).map(|c| c.0).collect();
            // With no finishing allowance the last roughing pass is at k too.
            let at_k = passes.iter().filter(|p| (*p - k).abs() < 1e-9).count() as u32;
            prop_assert_eq!(at_k, m + u32::from(d_mm == 0.0));
            let rough = &passes[..passes.len() - m as usize];
            prop_assert!((rough.last().unwrap() - (k - d_mm)).abs() < 1e-9, "{:?} k {} d {}", rough, k, d_mm);
            for w in rough.windows(2) {
                prop_assert!(w[1] > w[0]);
            }
            if g78 && equal {
                // Equal-distance infeed: every roughing step but the last is max(dd, dmin).
                let step = (first_um.max(dmin_um)) as f64 / 1000.0;
                for w in rough.windows(2).take(rough.len().saturating_sub(2)) {
                    prop_assert!((w[1] - w[0] - step).abs() < 1e-9, "{:?} step {}", rough, step);
                }
            }
        }
    }
}

#[test]
fn g78_infeed_modes_shift_the_pass_start_along_the_flank() {
    // k 1, dd 0.5, d 0: passes at 0.5 and 1.0, a 60: the tip sits (k - depth) x tan 30 off the
    // groove's centre toward the flank it follows (left = -Z), the full-depth pass on it.
    let t = 30f64.to_radians().tan();
    for (mode, signs) in [(0, [0.0, 0.0]), (1, [-1.0, -1.0]), (2, [1.0, 1.0]), (3, [-1.0, 1.0])] {
        let prog = format!("G97 S300 M03\nG0 X70 Z5\nG78 P00{mode:02}60 Q0 R0 D0\nG78 X60 Z-40 P1000 Q500 F2\nM30\n");
        let r = run("gsk980tdi", &[], &prog).ok();
        let starts: Vec<f64> = r.threads().iter().filter(|t| (t.0.z - 5.0).abs() < 1.0).map(|t| t.0.z).collect();
        assert_eq!(starts.len(), 2, "{starts:?}");
        for (z, (sign, depth)) in starts.iter().zip(signs.iter().zip([0.5, 1.0])) {
            assert!((z - (5.0 + sign * (1.0 - depth) * t)).abs() < 1e-9, "mode {mode}: {starts:?}");
        }
    }
    // Bad P fields, D, L: alarms naming the word; E warns that it is not simulated.
    for (block, code) in [("G78 P020060", "NCS-E33"), ("G78 P000460", "NCS-E33"), ("G78 P000060 D1.5", "NCS-E33"), ("G78 P000060 L0", "NCS-E33")] {
        let r = run("gsk980tdi", &[], &format!("G97 S300 M03\nG0 X70 Z5\n{block}\nM30\n"));
        assert_eq!(r.alarm().map(|a| a.code), Some(code), "{block}");
    }
    let r = run("gsk980tdi", &[], "G97 S300 M03\nG0 X70 Z5\nG78 P000060 E0.2\nG78 X60 Z-40 P1000 Q500 F2\nM30\n").ok();
    assert!(r.warned("NCS-W12"), "E warns");
}

#[test]
fn g76_reads_p_q_in_increments_and_alarms_on_bad_data() {
    // P(k) and Q(dd) with a decimal point: alarm (least input increments only).
    let r = run("gsk980tdi", &[], "G97 S300 M03\nG0 X70 Z5\nG76 X60 Z-40 P3.68 Q1800 F6\nM30\n");
    assert_eq!(r.alarm().unwrap().code, "NCS-E07");
    let r = run("gsk980tdi", &[], "G97 S300 M03\nG0 X70 Z5\nG76 X60 Z-40 Q1800 F6\nM30\n");
    assert_eq!(r.alarm().unwrap().code, "NCS-E51");
    // J/K in the first block: the pull-out of G32/G92 (help note 2).
    let r = run("gsk980tdi", &[], "G97 S300 M03\nG0 X70 Z5\nG76 P010060 Q100 R0.1 J1 K2\nG76 X60 Z-40 P1000 Q500 F2\nM30\n").ok();
    let t = r.threads();
    let pull = t.iter().find(|t| (t.1.z + 40.0).abs() < 1e-9).unwrap();
    assert!((pull.0.z + 38.0).abs() < 1e-9, "{pull:?}");
}

#[test]
fn g34_lead_must_stay_positive() {
    let r = run("gsk980tdi", &[], "G97 S200 M03\nG0 X40 Z5\nG34 Z-40 F2 R-0.5\nM30\n");
    assert_eq!(r.alarm().unwrap().code, "NCS-E51");
}

/// G76 with m = 0 finishing passes: its own warning (NCS-W24), not the "text ignored" one.
#[test]
fn g76_without_finishing_passes_warns_with_its_own_code() {
    let r = run("gsk980tdi", &[], "G97 S300 M03\nG0 X70 Z5\nG76 P000060 Q100 R0.1\nG76 X60 Z-40 P1000 Q500 F2\nM30\n").ok();
    assert!(r.warned("NCS-W24"));
    assert!(!r.warned("NCS-W04"));
}
