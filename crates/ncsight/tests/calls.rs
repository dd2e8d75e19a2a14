//! Subprogrammes: M98 and M99 on the profiles, the search for a called programme, the call
//! stack's limits, and what records and diagnostics carry. Each expected trace is worked out
//! by hand in its comment.

use ncsight::motion::Op;
use ncsight::profile::{self, Params};
use ncsight::{events_with_library, CallOptions, Event, Mode, Program, Switches};

fn run_with(machine: &str, mode: Mode, options: CallOptions, text: &str, library: &[(&str, &str)]) -> Vec<Event> {
    let mut program = Program::new(Params::defaults(profile::by_name(machine).unwrap()), Switches::default(), mode);
    program.set_call_options(options);
    let library = library.iter().map(|(n, t)| (n.to_string(), t.as_bytes())).collect();
    events_with_library(program, text.as_bytes(), library).collect()
}

fn run(machine: &str, text: &str) -> Vec<Event> {
    run_with(machine, Mode::Run, CallOptions::default(), text, &[])
}

/// Each move as "line:kind:x,y,z@depth", other records as "line:kind@depth", each diagnostic
/// as "line:code".
fn trace(events: &[Event]) -> Vec<String> {
    events
        .iter()
        .map(|e| match e {
            Event::Record(r) => match &r.op {
                Op::Rapid { to, .. } | Op::Feed { to, .. } => format!("{}:{}:{},{},{}@{}", r.span.line, r.op.kind(), to.x, to.y, to.z, r.call_depth),
                op => format!("{}:{}@{}", r.span.line, op.kind(), r.call_depth),
            },
            Event::Diagnostic(d) => format!("{}:{}", d.span.line, d.code),
        })
        .collect()
}

fn t(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

/// The subprogramme follows M30 (as in z64-cncbook stdbc.nc): it is found by reading on, run
/// three times (P0030100: count 3, O0100), and the run comes back to the block after the call.
/// Each run moves X by +1 (G91), so X goes 1, 2, 3; N50 then goes to X5.
#[test]
fn a_subprogramme_after_m30_runs_count_times_and_returns() {
    let text = "O0001\nG21 G17 G90 G00 X0. Y0. Z10.\nM98 P0030100\nN50 G00 X5.\nM30\nO0100\nG91 G01 X1. F100.\nG90 M99\n";
    let expected = t(&["2:rapid:0,0,10@0", "7:feed:1,0,10@1", "7:feed:2,0,10@1", "7:feed:3,0,10@1", "4:rapid:5,0,10@0", "5:end@0"]);
    assert_eq!(trace(&run("fanuc0m", text)), expected);
    // The FANUC 0-M's own form: P the number, L the count.
    assert_eq!(trace(&run("fanuc0m", &text.replace("P0030100", "P100 L3"))), expected);
    // A count of 0 calls once, as no count does.
    let once = t(&["2:rapid:0,0,10@0", "7:feed:1,0,10@1", "4:rapid:5,0,10@0", "5:end@0"]);
    assert_eq!(trace(&run("fanuc0m", &text.replace("P0030100", "P100"))), once);
    assert_eq!(trace(&run("fanuc0m", &text.replace("P0030100", "P100 L0"))), once);
}

/// GSK980TDi: M98 P<count 1-9999><number>, no L (help text, M98). Lengths without a point
/// are millimetres there.
#[test]
fn gsk_counts_in_p_and_refuses_l() {
    let text = "O0001\nG00 X20 Z5\nM98 P20100\nM30\nO0100\nG01 W-1 F0.1\nM99\n";
    let e = run("gsk980tdi", text);
    let moves: Vec<String> = trace(&e).into_iter().filter(|s| s.contains("feed") || s.contains("rapid")).collect();
    assert_eq!(moves, t(&["2:rapid:10,0,5@0", "6:feed:10,0,4@1", "6:feed:10,0,3@1"]));
    let e = run("gsk980tdi", &text.replace("P20100", "P100 L2"));
    let Some(Event::Diagnostic(d)) = e.last() else { panic!("{e:?}") };
    assert!(d.is_alarm() && d.span.line == 3, "{d:?}");
    // More than 9999 calls cannot be written: P is at most eight digits.
    let e = run("fanuc0m", &text.replace("P20100", "P10000100"));
    let Some(Event::Diagnostic(d)) = e.last() else { panic!() };
    assert_eq!(d.code, "NCS-E33", "{d:?}");
}

/// The second call of a programme goes straight to it (its place was noted): the records are
/// those of the first call.
#[test]
fn a_second_call_jumps_back_to_the_noted_place() {
    let text = "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0100\nG00 Y5.\nM98 P0100\nM30\nO0100\nG91 G00 X1.\nG90 M99\n";
    let e = run("fanuc0m", text);
    assert_eq!(trace(&e), t(&["2:rapid:0,0,10@0", "8:rapid:1,0,10@1", "4:rapid:1,5,10@0", "8:rapid:2,5,10@1", "6:end@0"]));
}

/// Four levels nest; the fifth call is FANUC alarm 077 (FANUC 0i-TB/MB operator's manual 12.3).
#[test]
fn the_fifth_nested_call_alarms() {
    let mut text = String::from("O0001\nM98 P0001\nM30\n");
    for k in 1..=5 {
        text.push_str(&format!("O{k:04}\n"));
        if k < 5 {
            text.push_str(&format!("M98 P{:04}\n", k + 1));
        }
        text.push_str("M99\n");
    }
    // O0001 is the main programme here, so its own number cannot be called: renumber.
    let text = text.replacen("O0001\nM98 P0001", "O9000\nM98 P0001", 1);
    let e = run("fanuc0m", &text);
    let Some(Event::Diagnostic(d)) = e.last() else { panic!("{e:?}") };
    assert_eq!((d.code, d.span.line), ("PS0077", 14), "{d:?}");
    // The alarm names its four calls, outermost first.
    assert_eq!(d.calls.iter().map(|s| s.line).collect::<Vec<_>>(), vec![2, 5, 8, 11]);
    // Lines: 2 calls O0001 (level 1), 5 O0002, 8 O0003, 11 O0004 (level 4), 14 O0005: the fifth.
    // Four levels run to the end.
    let four = text.replace("M98 P0005\n", "");
    let e = run("fanuc0m", &four);
    assert!(e.iter().all(|e| !matches!(e, Event::Diagnostic(d) if d.is_alarm())), "{:?}", trace(&e));
}

/// M99 P returns to the caller's block N20, not to the block after the call (GSK980TDi help
/// text, M99): N10's X7 is passed over.
#[test]
fn m99_p_returns_to_a_sequence_number() {
    let text = "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0100\nN10 G00 X7.\nN20 G00 Y9.\nM30\nO0100\nG00 X1.\nM99 P20\n";
    assert_eq!(trace(&run("fanuc0m", text)), t(&["2:rapid:0,0,10@0", "8:rapid:1,0,10@1", "5:rapid:1,9,10@0", "6:end@0"]));
    // A sequence number the caller lacks: FANUC 0 alarm 078 at the M99.
    let e = run("fanuc0m", &text.replace("P20", "P30"));
    let Some(Event::Diagnostic(d)) = e.last() else { panic!() };
    assert_eq!((d.code, d.span.line), ("PS0078", 9), "{d:?}");
}

/// M99 in the main programme: it would start again; the simulation ends with NCS-W08.
#[test]
fn m99_in_the_main_programme_ends_the_run() {
    let e = run("gsk980tdi", "G00 X10 Z2\nM99\nG00 X99\n");
    assert_eq!(trace(&e), t(&["1:rapid:5,0,2@0", "2:NCS-W08", "2:end@0"]));
}

/// `M99O0810`: an O word after other words starts the next programme on the same line (the
/// SK7420 punch in the corpus); both programmes are found.
#[test]
fn an_o_word_in_mid_line_starts_the_next_programme() {
    let text = "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0800\nM98 P0810\nM30\nO0800\nG00 X1.\nM99O0810\nG00 Y2.\nM99\n";
    assert_eq!(trace(&run("fanuc0m", text)), t(&["2:rapid:0,0,10@0", "7:rapid:1,0,10@1", "9:rapid:1,2,10@1", "5:end@0"]));
}

/// A subprogramme whose text ends (the next O, the end of the file) without M99: NCS-E62; a
/// check goes on after the call as if M99 had been there.
#[test]
fn a_subprogramme_without_m99_alarms() {
    let text = "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0100\nG00 Y3.\nM30\nO0100\nG00 X1.\nO0200\nM99\n";
    let e = run("fanuc0m", text);
    assert_eq!(trace(&e), t(&["2:rapid:0,0,10@0", "7:rapid:1,0,10@1", "8:NCS-E62"]));
    let e = run_with("fanuc0m", Mode::Check, CallOptions::default(), text, &[]);
    // The subprogrammes after M30 are no "blocks after the programme end" (issue 36: no NCS-W09).
    assert_eq!(trace(&e), t(&["2:rapid:0,0,10@0", "7:rapid:1,0,10@1", "8:NCS-E62", "4:rapid:1,3,10@0", "5:end@0"]));
}

/// A main programme without M30 that runs into the next programme ends there (NCS-W13); the
/// subprogramme after it is not executed.
#[test]
fn the_main_programme_ends_where_the_next_begins() {
    let e = run("fanuc0m", "O0001\nG90 G00 X1. Y0. Z0.\nO0100\nG00 X9.\nM99\n");
    assert_eq!(trace(&e), t(&["2:rapid:1,0,0@0", "3:NCS-W13"]));
}

/// `--main O0200`: the run begins at that programme; the first one is a subprogramme of it.
#[test]
fn the_main_programme_can_be_named() {
    let text = "O0100\nG00 X1.\nM99\nO0200\nG90 G00 X0. Y0. Z10.\nM98 P0100\nM30\n";
    let options = CallOptions { main: Some(200), ..CallOptions::default() };
    let e = run_with("fanuc0m", Mode::Run, options, text, &[]);
    assert_eq!(trace(&e), t(&["5:rapid:0,0,10@0", "2:rapid:1,0,10@1", "7:end@0"]));
    let options = CallOptions { main: Some(300), ..CallOptions::default() };
    let e = run_with("fanuc0m", Mode::Run, options, text, &[]);
    assert_eq!(trace(&e), t(&["1:PS0078"]));
}

/// A programme no file holds: FANUC 0 alarm 078 at the call (the forward search, then the one
/// from the top, then the library found nothing); skipped with a warning when asked; a check
/// reports it and goes on.
#[test]
fn a_missing_programme_alarms_or_is_skipped() {
    let text = "G90 G00 X0. Y0. Z10.\nM98 P9832\nG00 X4.\nM30\n";
    assert_eq!(trace(&run("fanuc0m", text)), t(&["1:rapid:0,0,10@0", "2:PS0078"]));
    let skip = CallOptions { skip_missing: true, ..CallOptions::default() };
    let e = run_with("fanuc0m", Mode::Run, skip, text, &[]);
    assert_eq!(trace(&e), t(&["1:rapid:0,0,10@0", "2:NCS-W27", "3:rapid:4,0,10@0", "4:end@0"]));
    let e = run_with("fanuc0m", Mode::Check, CallOptions::default(), text, &[]);
    assert_eq!(trace(&e), t(&["1:rapid:0,0,10@0", "2:PS0078", "3:rapid:4,0,10@0", "4:end@0"]));
}

/// A programme in another file (what --subprogram-dir gives): its records carry that file and
/// depth 1; an alarm there names the file and the call.
#[test]
fn a_programme_in_another_file() {
    let text = "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0200\nM30\n";
    let lib = [("other.nc", "%\nO0300\nM99\n%\n"), ("O0200.nc", "%\nO0200\nG91 G00 Y1.\nG90 M99\n%\n")];
    let e = run_with("fanuc0m", Mode::Run, CallOptions::default(), text, &lib);
    assert_eq!(trace(&e), t(&["2:rapid:0,0,10@0", "3:rapid:0,1,10@1", "4:end@0"]));
    let Event::Record(r) = &e[1] else { panic!() };
    assert_eq!(r.span.file, 1);
    let bad = [("O0200.nc", "O0200\nG00 Q1.\nM99\n")];
    let e = run_with("fanuc0m", Mode::Run, CallOptions::default(), text, &bad);
    let Some(Event::Diagnostic(d)) = e.last() else { panic!() };
    assert_eq!((d.span.file, d.span.line, d.calls.len(), d.calls[0].line, d.calls[0].file), (1, 2, 1, 3, 0), "{d:?}");
}

/// The runaway guard: O0001 calls O0200 999 times, which calls O0300 999 times (10^6 blocks
/// and more): the run stops with NCS-E63 once the blocks executed again pass the limit.
#[test]
fn a_runaway_programme_stops() {
    let text = "O0001\nM98 P9990200\nM30\nO0200\nM98 P9990300\nM99\nO0300\nG91 G00 X0.001\nM99\n";
    let options = CallOptions { max_repeated_blocks: 5_000, ..CallOptions::default() };
    let e = run_with("fanuc0m", Mode::Run, options, text, &[]);
    let Some(Event::Diagnostic(d)) = e.last() else { panic!() };
    assert_eq!(d.code, "NCS-E63");
    let moves = e.iter().filter(|e| matches!(e, Event::Record(_))).count();
    assert!(moves > 1_000 && moves < 5_000, "{moves}");
}

/// A line read again (each run of a subprogramme) gives its own warnings once, not once a run.
#[test]
fn line_warnings_are_given_once() {
    let text = "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0030100\nM30\nO0100\nG91 G00 X1. (open comment\nG90 M99\n";
    let e = run("fanuc0m", text);
    assert_eq!(e.iter().filter(|e| matches!(e, Event::Diagnostic(d) if d.code == "NCS-W03")).count(), 1, "{:?}", trace(&e));
}

/// A programme and the same moves written out without calls give the same records, whatever
/// the nesting and counts (positions, kinds and times).
#[test]
fn calls_give_what_their_expansion_gives() {
    let sub_c = "G91 G01 X0.5 F200.\nG00 Y-0.25\nG90\n";
    let sub_b = format!("G91 G00 Z-1.\nG90\nM98 P0020300\n");
    for (count_b, count_a) in [(1, 1), (2, 3), (3, 2)] {
        let sub_a = format!("G91 G00 X2.\nG90\nM98 P{count_b:03}0200\n");
        let text =
            format!("O0001\nG21 G17 G90 G00 X0. Y0. Z10.\nM98 P{count_a:03}0100\nG00 X0. Y0.\nM30\nO0100\n{sub_a}M99\nO0200\n{sub_b}M99\nO0300\n{sub_c}M99\n");
        let mut flat = String::from("G21 G17 G90 G00 X0. Y0. Z10.\n");
        for _ in 0..count_a {
            flat.push_str("G91 G00 X2.\nG90\n");
            for _ in 0..count_b {
                flat.push_str("G91 G00 Z-1.\nG90\n");
                for _ in 0..2 {
                    flat.push_str(sub_c);
                }
            }
        }
        flat.push_str("G00 X0. Y0.\nM30\n");
        let strip = |e: Vec<Event>| -> Vec<(String, f64)> {
            e.into_iter()
                .filter_map(|e| match e {
                    Event::Record(r) => Some((format!("{:?}", r.op), r.t_s)),
                    Event::Diagnostic(d) => panic!("{d:?}"),
                })
                .collect()
        };
        let called = strip(run("fanuc0m", &text));
        let written = strip(run("fanuc0m", &flat));
        assert_eq!(called.len(), written.len());
        for (a, b) in called.iter().zip(&written) {
            assert_eq!(a.0, b.0);
            assert!((a.1 - b.1).abs() < 1e-9);
        }
    }
}

/// Found by review: a call forward to a subprogramme after M30 does not make the rest of the
/// main programme count as run again (its line warnings still come, the runaway guard does not
/// count it); a second programme in a library file already opened is found; a backward jump in
/// a text that ends with a DOS end-of-file mark goes back.
#[test]
fn review_fixes() {
    let text = "O0001\nG90 G00 X0. Y0. Z1.\nM98 P0100\nG00 X1. (unclosed\nM30\nO0100\nM99\n";
    let e = run("fanuc0m", text);
    assert!(trace(&e).contains(&"4:NCS-W03".to_string()), "{:?}", trace(&e));
    let mut main = String::from("O0001\nG90 G00 X0. Y0. Z1.\nM98 P0100\n");
    for i in 0..50 {
        main.push_str(&format!("G00 X{i}.\n"));
    }
    main.push_str("M30\nO0100\nM99\n");
    let options = CallOptions { max_repeated_blocks: 10, ..CallOptions::default() };
    let e = run_with("fanuc0m", Mode::Run, options, &main, &[]);
    assert!(e.iter().all(|e| !matches!(e, Event::Diagnostic(d) if d.is_alarm())), "{:?}", trace(&e));
    let lib = [("subs.nc", "O0100\nG91 G00 X1.\nG90 M99\nO0200\nG91 G00 Y1.\nG90 M99\n")];
    let e = run_with("fanuc0m", Mode::Run, CallOptions::default(), "G90 G00 X0. Y0. Z1.\nM98 P0100\nM98 P0200\nM30\n", &lib);
    assert_eq!(trace(&e), t(&["1:rapid:0,0,1@0", "2:rapid:1,0,1@1", "5:rapid:1,1,1@1", "4:end@0"]));
    let e = run("fanuc0m", "G90 G00 X0. Y0. Z1.\n#1 = 0\nN10 #1 = #1 + 1\nG00 X#1\nIF [#1 LT 3] GOTO 10\nM30\n\x1A");
    assert_eq!(trace(&e).iter().filter(|s| s.contains("rapid")).count(), 4, "{:?}", trace(&e));
}

/// A loop whose body searches in vain (a check goes on past GOTO's alarm, round and round):
/// the blocks a search reads again count for the runaway guard too, so it stops (the fuzzer
/// found a 12-second case before they counted). A first forward search does not count: a long
/// main programme calling a subprogramme after M30 is not a runaway.
#[test]
fn searches_count_for_the_runaway_guard() {
    let text = "#1 = 0\nWHILE [1 EQ 1] DO1\nGOTO 99\nEND1\nM30\n";
    let options = CallOptions { max_repeated_blocks: 1_000, ..CallOptions::default() };
    let e = run_with("fanuc0m", Mode::Check, options, text, &[]);
    let codes: Vec<&str> = e
        .iter()
        .filter_map(|e| match e {
            Event::Diagnostic(d) if d.is_alarm() => Some(d.code),
            _ => None,
        })
        .collect();
    assert_eq!(codes, vec!["PS0128", "NCS-E63"]);
    let mut main = String::from("O0001\nM98 P0100\n");
    for i in 0..3_000 {
        main.push_str(&format!("G00 X{}.\n", i % 7));
    }
    main.push_str("M30\nO0100\nM99\n");
    let e = run_with("fanuc0m", Mode::Run, options, &main, &[]);
    assert!(e.iter().all(|e| !matches!(e, Event::Diagnostic(d) if d.is_alarm())), "{:?}", trace(&e).last());
}

/// `%` closes the record (docs/reference/macro.md section 1, inferred): the text after the closing `%` is not
/// read, the first `%` only opens it. Line 6 (after the closing mark on line 5) gives neither a
/// move nor the after-the-end warning; without M30 the run ends at the mark with the
/// no-programme-end warning (NCS-W.. at the last block). A subprogramme that reaches the
/// closing mark without M99 alarms as at the end of the text (NCS-E62); a programme after the
/// mark is still found by a call (the search reads on).
#[test]
fn the_closing_percent_ends_the_text() {
    let ended = run("fanuc0m", "%\nO0001\nG21 G90 G00 X1. Y0. Z0.\nM30\n%\nG00 X5.\n");
    assert_eq!(trace(&ended), t(&["3:rapid:1,0,0@0", "4:end@0"]));
    let open = run("fanuc0m", "%\nG21 G90 G00 X1. Y0. Z0.\n%\nG00 X5.\nM30\n");
    let no_end = ncsight::Rule::NoProgramEnd.code(profile::by_name("fanuc0m").unwrap().alarm_style);
    assert_eq!(trace(&open), t(&["2:rapid:1,0,0@0", &format!("2:{no_end}")]));
    let no_return = run("fanuc0m", "%\nO0001\nG21 G90 G00 X0. Y0. Z0.\nM98 P100\nM30\nO0100\nG00 X1.\n%\nG00 X9.\nM99\n");
    assert_eq!(trace(&no_return), t(&["7:rapid:1,0,0@1", "8:NCS-E62"]));
    let after = run("fanuc0m", "%\nO0001\nG21 G90 G00 X0. Y0. Z0.\nM98 P100\nM30\n%\n%\nO0100\nG00 X1.\nM99\n%\n");
    assert_eq!(trace(&after), t(&["9:rapid:1,0,0@1", "5:end@0"]));
}

/// The tape leader: text before the first `%` is not read (FANUC tape format). A CAM banner and
/// a title line before the `%` give one warning on line 1 and nothing else; the programme after
/// the `%` runs (its rapid on line 5 to X10, radius 5, M30 on line 6). A file that starts with blocks has no
/// leader: its `%` closes the record, and what follows is read only by a search (O2 here is
/// called by M98 and runs at depth 1).
#[test]
fn text_before_the_first_percent_is_the_tape_leader() {
    let text = "PART 12 REV B - SOMECAM 4.2\n(POST: FANUC)\n%\nO1000\nG00 X10. Z5.\nM30\n%\n";
    assert_eq!(trace(&run("fanuc0t", text)), t(&["1:NCS-W04", "5:rapid:5,0,5@0", "6:end@0"]));
    // The leader's words could be read if it were a programme: the same answer on every profile.
    for m in ["gsk980tdi", "gsk988t", "yasnac-lx3", "fanuc0m"] {
        let e = trace(&run(m, text));
        assert_eq!((e[0].as_str(), e.len()), ("1:NCS-W04", 3), "{m}: {e:?}");
    }
    // Blocks first: no leader.
    let record = "O1\nG00 X1. Z1.\nM98 P2\nM30\n%\nO2\nG00 X2.\nM99\n%\n";
    assert_eq!(trace(&run("fanuc0t", record)), t(&["2:rapid:0.5,0,1@0", "7:rapid:1,0,1@1", "4:end@0"]));
    // Only comments before the `%`: nothing to warn about, nothing skipped that would matter.
    let comments = "(MADE BY X)\n%\nO1000\nG00 X10. Z5.\nM30\n%\n";
    assert_eq!(trace(&run("fanuc0t", comments)), t(&["4:rapid:5,0,5@0", "5:end@0"]));
    // A programme with mistakes before a closing `%` is a programme (its lines start as blocks):
    // its alarm, not a leader.
    assert_eq!(trace(&run("fanuc0t", "G0 X1,5 Z2,0\nG1 X3,0 F0,2\n%\n"))[0].as_str(), "1:NCS-E30");
    // A punched tape's blank leader: NUL bytes, also before the `%` on its line.
    let tape = "\0\0\0\0\n\0\0%\nO1000\nG00 X10. Z5.\nM30\n%\n";
    assert_eq!(trace(&run("fanuc0t", tape)), t(&["1:NCS-W04", "4:rapid:5,0,5@0", "5:end@0"]));
    // Unreadable text and no `%` at all: the alarm at line 1, as before.
    let none = "PART 12 REV B\nG00 X10. Z5.\nM30\n";
    assert_eq!(trace(&run("fanuc0t", none))[0].as_str(), "1:PS0005");
}
