//! G02.2/G03.2 involute interpolation on the FANUC 0i-MF (FANUC 16/18-MC and 30i-MA manuals):
//! a curve of tens of turns made as it is handed on, record for record what the ordinary path
//! makes, and one past the cap that the push interface runs and the pull iterator refuses.

use ncsight::motion::Op;
use ncsight::{Diagnostic, Record};

mod common;

fn run(text: &str) -> (Vec<Record>, Vec<Diagnostic>) {
    common::run_plain("fanuc0i-mf", &[], text)
}

fn alarm(d: &[Diagnostic]) -> Option<&'static str> {
    d.iter().find(|d| d.is_alarm()).map(|d| d.code)
}

/// The point at `roll` of the involute of the circle R10 about the origin that starts at X10 Y0
/// (unwinding counter-clockwise), to 4 decimals as a programme writes it.
fn end_at(roll: f64) -> String {
    let (s, c) = roll.sin_cos();
    format!("X{:.4} Y{:.4}", 10.0 * (c + roll * s), 10.0 * (s - roll * c))
}

fn programme(roll: f64) -> String {
    format!("G21 G90 G17 G00 X10. Y0. Z5.\nG01 F800.\nG03.2 {} I-10. J0. R10.\nG00 Z50.\nM30\n", end_at(roll))
}

/// 190 rad of roll (some 30 turns): 190^1.5 / (1.5 sqrt(8 x 0.001 / 10)) = 61,730 chords, past
/// the 50,000 a block makes now. Pushed, they are made as they are handed on; pulled (the
/// iterator holds a block whole), the same records, the same times: the first chord accelerates
/// and the others, one interpolation, carry a time constant of 0 on both paths.
#[test]
fn a_deferred_involute_makes_the_records_the_ordinary_path_makes() {
    let text = programme(190.0);
    let (deferred, d1) = common::run_pushed("fanuc0i-mf", None, &text);
    let (ordinary, d2) = run(&text);
    assert_eq!((alarm(&d1), alarm(&d2)), (None, None), "{d1:?} {d2:?}");
    let chords = deferred.iter().filter(|r| r.span.line == 3 && matches!(r.op, Op::Feed { .. })).count();
    assert_eq!(chords, 61_730);
    common::same_records(&deferred, &ordinary);
    let later: Vec<Option<f64>> = ordinary.iter().filter(|r| r.span.line == 3).skip(1).map(|r| r.accel_s).collect();
    assert!(later.iter().all(|a| *a == Some(0.0)));
}

/// Under G95 with G96 the chords' feed would follow each one's place if made as they are handed
/// on, and the curve has one feed: such a block is held, and past 100,000 chords refused.
#[test]
fn an_involute_at_a_feed_per_revolution_under_g96_is_held() {
    let roll = 190.0;
    let text = format!("G21 G90 G17 G00 X10. Y0. Z5.\nS1000 M03\nG95 G96 S100\nG01 F0.1\nG03.2 {} I-10. J0. R10.\nM30\n", end_at(roll));
    let (pushed, d1) = common::run_pushed("fanuc0i-mf", None, &text);
    let (pulled, d2) = run(&text);
    assert_eq!((alarm(&d1), alarm(&d2)), (None, None), "{d1:?} {d2:?}");
    common::same_records(&pushed, &pulled);
    let feeds: Vec<f64> =
        pushed.iter().filter(|r| r.span.line == 5).filter_map(|r| if let Op::Feed { feed_mm_min, .. } = r.op { Some(feed_mm_min) } else { None }).collect();
    assert!(feeds.len() > 50_000 && feeds.iter().all(|f| *f == feeds[0]), "one feed for the curve");
}

/// 90 turns (316,955 chords) is past the 100,000 records a held block keeps: the push interface
/// runs it to its end, the pull iterator stops at the cap (NCS-E40).
#[test]
fn an_involute_past_the_cap_runs_pushed_and_alarms_pulled() {
    let text = programme(90.0 * std::f64::consts::TAU);
    let (records, diags) = common::run_pushed("fanuc0i-mf", None, &text);
    assert_eq!(alarm(&diags), None, "{diags:?}");
    assert_eq!(records.iter().filter(|r| r.span.line == 3).count(), 316_955);
    assert!(records.iter().any(|r| r.span.line == 4));
    let (_, pulled) = run(&text);
    assert_eq!(alarm(&pulled), Some("NCS-E40"));
}

/// What the manuals refuse, each with its number: no R, no end point, no centre, a helical Z, an
/// end point on the other involute, a start inside the base circle, G16 polar coordinates, 101
/// turns, a tool offset's movement still to be made.
#[test]
fn what_the_manuals_refuse() {
    let start = "G21 G90 G17 G00 X10. Y0. Z5.\nG01 F300.\n";
    let cases = [
        ("G03.2 X11.173 Y0.4063 I-10. J0.\n", "PS0241"),
        ("G03.2 I-10. J0. R10.\n", "PS0241"),
        ("G03.2 X11.173 Y0.4063 R10.\n", "PS0241"),
        ("G03.2 X11.173 Y0.4063 Z4. I-10. J0. R10.\n", "PS0241"),
        ("G02.2 X11.173 Y0.4063 I-10. J0. R10.\n", "PS0242"),
        ("G03.2 X11.173 Y0.4063 I-5. J0. R10.\n", "PS0242"),
        ("G16 G03.2 X11.173 Y0.4063 I-10. J0. R10.\n", "PS0242"),
    ];
    for (block, code) in cases {
        let d = common::first_alarm("fanuc0i-mf", &format!("{start}{block}M30\n"));
        assert_eq!(d.as_ref().map(|d| d.code), Some(code), "{block}: {d:?}");
    }
    let far = format!("{start}G03.2 {} I-10. J0. R10.\nM30\n", end_at(101.0 * std::f64::consts::TAU));
    let d = common::first_alarm("fanuc0i-mf", &far).unwrap();
    assert!(d.message.contains("turns"), "{}", d.message);
    // A tool length offset's movement not made yet would go with the curve: refused too, at
    // the block, where on the ordinary path it would have made the chords helical.
    let pending = "G21 G90 G17 G00 X10. Y0. Z5.\nG10 L10 P1 R5.\nG01 F300.\nG43 H1 G03.2 X11.173 Y0.4063 I-10. J0. R10.\nM30\n";
    let d = common::first_alarm("fanuc0i-mf", pending).unwrap();
    assert_eq!((d.code, d.span.line), ("PS0241", 4), "{d:?}");
    assert!(d.message.contains("tool offset"), "{}", d.message);
    // A word at fault is pointed at: R0.
    let d = common::first_alarm("fanuc0i-mf", &format!("{start}G03.2 X11.173 Y0.4063 I-10. J0. R0\nM30\n")).unwrap();
    assert_eq!((d.code, d.span.col), ("PS0241", 33), "{d:?}");
    // The right one runs.
    assert!(common::first_alarm("fanuc0i-mf", &format!("{start}G03.2 X11.173 Y0.4063 I-10. J0. R10.\nM30\n")).is_none());
}
