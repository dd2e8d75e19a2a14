//! Bad input never panics, every diagnostic points inside the input, and a block that alarms
//! leaves the modal state as it was.

use ncsight::interp::{Interpreter, Switches};
use ncsight::profile::{self, Params};
use ncsight::read::Reader;
use ncsight::{run_text, Event, Mode};
use proptest::prelude::*;

fn every_profile() -> impl Strategy<Value = &'static ncsight::Profile> {
    prop::sample::select(profile::all().to_vec())
}

/// Lines made of G-code-ish pieces, so the interpreter is reached, not only the reader.
fn gcode_line() -> impl Strategy<Value = String> {
    let word = (
        prop::sample::select(b"GXYZUWIJKRFSTMPQLNODE".to_vec()),
        prop::sample::select(vec![
            "0", "1", "2", "3", "4", "-1.5", "10.", "92", "32.1", "99", "0.0", "1e3", "[1/0]", "[2*3]", ".", "-", "70", "71", "72", "73", "74", "75", "76",
            "78", "90", "94", "500", "010260",
        ]),
    )
        .prop_map(|(l, v)| format!("{}{}", l as char, v));
    prop::collection::vec(word, 0..8).prop_map(|ws| ws.join(" "))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, .. ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(p in every_profile(), lines in prop::collection::vec(prop::collection::vec(any::<u8>(), 0..80), 0..20)) {
        let text: Vec<u8> = lines.join(&b'\n');
        for mode in [Mode::Run, Mode::Check] {
            let events = run_text(Params::defaults(p), Switches::default(), mode, &text);
            let n_lines = text.split(|&b| b == b'\n').count() as u32;
            for e in events {
                if let Event::Diagnostic(d) = &e {
                    prop_assert!(d.span.line >= 1 && d.span.line <= n_lines.max(1), "{:?}", d);
                    prop_assert!(d.span.col >= 1);
                    prop_assert!(!d.message.is_empty());
                }
                if let Event::Record(r) = &e {
                    prop_assert!(r.t_s.is_finite());
                }
            }
        }
    }

    #[test]
    fn gcode_like_lines_never_panic_and_stay_finite(p in every_profile(), lines in prop::collection::vec(gcode_line(), 1..30)) {
        let text = lines.join("\n");
        let events = run_text(Params::defaults(p), Switches::default(), Mode::Check, text.as_bytes());
        for e in events {
            match e {
                Event::Record(r) => {
                    prop_assert!(r.t_s.is_finite() && r.t_s >= 0.0);
                    if let Some(q) = r.op.end_point() {
                        prop_assert!(q.x.is_finite() && q.y.is_finite() && q.z.is_finite());
                    }
                }
                Event::Diagnostic(d) => {
                    let line = lines[(d.span.line - 1) as usize].as_bytes();
                    prop_assert!((d.span.col as usize) <= line.len() + 1, "{:?} on {:?}", d, lines[(d.span.line - 1) as usize]);
                }
            }
        }
    }

    /// Block atomicity: executing a block that alarms changes nothing.
    #[test]
    fn a_block_that_alarms_changes_no_state(p in every_profile(), prefix in prop::collection::vec(gcode_line(), 0..10), bad in gcode_line()) {
        let reader = Reader::new(p.alarm_style);
        let mut interp = Interpreter::new(Params::defaults(p), Switches::default());
        for (i, l) in prefix.iter().enumerate() {
            for b in reader.read_line(i as u32 + 1, l.as_bytes()).blocks.into_iter().flatten() {
                let _ = interp.execute(&b);
            }
        }
        let before = interp.state().clone();
        for b in reader.read_line(999, bad.as_bytes()).blocks.into_iter().flatten() {
            if interp.execute(&b).is_err() {
                prop_assert_eq!(interp.state(), &before);
            }
            break;
        }
    }
}

#[test]
fn a_100_kb_line_is_one_alarm() {
    let mut text = b"G0 X1\n".to_vec();
    text.extend(std::iter::repeat(b'X').take(100_000));
    text.extend(b"\nM30\n");
    let events = run_text(Params::defaults(profile::by_name("fanuc0m").unwrap()), Switches::default(), Mode::Check, &text);
    let alarms: Vec<_> = events.iter().filter_map(|e| if let Event::Diagnostic(d) = e { d.is_alarm().then_some(d) } else { None }).collect();
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    assert_eq!(alarms[0].span.line, 2);
    assert!(alarms[0].message.contains("100000 bytes"));
}

/// The events are pulled by the consumer: taking the first few of a long programme reads only
/// the lines they come from.
#[test]
fn events_are_pulled_line_by_line() {
    let mut text = String::from("G21 G17 G90 G0 X0. Y0. Z10.\n");
    for i in 0..100_000 {
        text.push_str(&format!("G1 X{}. F500.\n", i % 100));
    }
    text.push_str("M30\n");
    let params = Params::defaults(profile::by_name("fanuc0m").unwrap());
    let program = ncsight::Program::new(params, Switches::default(), Mode::Run);
    let mut events = ncsight::program::events(program, text.as_bytes());
    let first: Vec<Event> = events.by_ref().take(3).collect();
    assert_eq!(first.len(), 3);
    // Three moves: about a second of machine time, not the whole programme's.
    assert!(events.program().time_s() < 10.0, "{}", events.program().time_s());
    assert_eq!(events.program().status(), ncsight::Status::Running);
    let rest = events.count();
    assert!(rest > 99_000);
}

/// Block atomicity without a copy of the whole state: a block that changes the modes (G91,
/// G20), the frame (G54 to G55) and the drilling memory before it alarms (G01 with no F ever
/// given) leaves every part as it was, and the next block runs from there.
#[test]
fn a_block_that_changed_parts_before_its_alarm_is_rolled_back() {
    let p = profile::by_name("fanuc0m").unwrap();
    let reader = Reader::new(p.alarm_style);
    let mut interp = Interpreter::new(Params::defaults(p), Switches::default());
    for (i, l) in ["G21 G17 G90 G54 G00 X1. Y2. Z10.", "G81 X5. Y5. Z-2. R1. F100.", "G80"].iter().enumerate() {
        for b in reader.read_line(i as u32 + 1, l.as_bytes()).blocks.into_iter().flatten() {
            interp.execute(&b).unwrap();
        }
    }
    let mut fresh = Interpreter::new(Params::defaults(p), Switches::default());
    for (i, l) in ["G21 G17 G90 G54 G00 X1. Y2. Z10.", "G81 X5. Y5. Z-2. R1. F100.", "G80"].iter().enumerate() {
        for b in reader.read_line(i as u32 + 1, l.as_bytes()).blocks.into_iter().flatten() {
            fresh.execute(&b).unwrap();
        }
    }
    let before = *interp.state();
    let bad = reader.read_line(4, b"G91 G20 G55 G83 X1. Y1. Z-1. R1. Q0. F100.").blocks.into_iter().flatten().next().unwrap();
    assert!(interp.execute(&bad).is_err(), "Q0 in G83 alarms");
    assert_eq!(interp.state(), &before);
    assert!(!interp.state().modes.incremental && !interp.state().modes.inch && interp.state().frame.work == 1);
    // The next block runs as it would had the bad block never been read.
    let next = reader.read_line(5, b"G01 X3. Y4.").blocks.into_iter().flatten().next().unwrap();
    let (a, b) = (interp.execute(&next).unwrap(), fresh.execute(&next).unwrap());
    assert_eq!(a.records, b.records);
    assert_eq!(interp.state(), fresh.state());
}

/// G70 runs its contour's blocks inside its own block: an alarm in a finishing pass (here a
/// soft limit the roughing, 0.4 mm outside the contour, never reached) puts back everything the
/// G70 block changed, the passes before it included, and the next block runs as if G70 had
/// never been read.
#[test]
fn a_g70_whose_finishing_pass_alarms_changes_no_state() {
    let p = profile::by_name("gsk980tdi").unwrap();
    let setup =
        ncsight::setup::Setup::from_toml("[machine.reference]\nx_mm = 200.0\nz_mm = 100.0\n[machine.limits]\nx_mm = [40.2, 260.0]\nz_mm = [-400.0, 120.0]\n")
            .unwrap();
    let reader = Reader::new(p.alarm_style);
    let lines = ["G99 G00 X100. Z2. T0101 S500 M03", "G71 U1. R0.5", "G71 P10 Q20 U0.4 W0.1 F0.2", "N10 G01 X60. Z2.", "X40. Z-10.", "N20 X100."];
    let start = || {
        let mut interp = Interpreter::new(Params::defaults(p), Switches::default());
        interp.set_setup(&setup);
        for (i, l) in lines.iter().enumerate() {
            for b in reader.read_line(i as u32 + 1, l.as_bytes()).blocks.into_iter().flatten() {
                interp.execute(&b).unwrap();
            }
        }
        interp
    };
    let (mut interp, mut fresh) = (start(), start());
    let before = *interp.state();
    let g70 = reader.read_line(7, b"G70 P10 Q20").blocks.into_iter().flatten().next().unwrap();
    let alarm = interp.execute(&g70).unwrap_err();
    assert_eq!(alarm.span.line, 5, "the finishing pass to X40 alarms: {alarm:?}");
    assert_eq!(interp.state(), &before);
    let next = reader.read_line(8, b"G00 X150. Z10.").blocks.into_iter().flatten().next().unwrap();
    let (a, b) = (interp.execute(&next).unwrap(), fresh.execute(&next).unwrap());
    assert_eq!(a.records, b.records);
    assert_eq!(interp.state(), fresh.state());
}
