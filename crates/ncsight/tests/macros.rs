//! Custom macro B: variables, vacancy, expressions, IF/WHILE/GOTO, G65 and the system
//! variables, each expected value worked out by hand in its comment (docs/reference/macro.md sections 3-9).

use ncsight::motion::Op;
use ncsight::profile::{self, Params};
use ncsight::{events, Event, Mode, Program, Switches};

fn run_mode(machine: &str, mode: Mode, text: &str) -> Vec<Event> {
    let program = Program::new(Params::defaults(profile::by_name(machine).unwrap()), Switches::default(), mode);
    events(program, text.as_bytes()).collect()
}

/// The end points of the moves, and the codes of the diagnostics, in order.
fn trace(machine: &str, text: &str) -> Vec<String> {
    run_mode(machine, Mode::Run, text)
        .iter()
        .filter_map(|e| match e {
            Event::Record(r) => match &r.op {
                Op::Rapid { to, .. } | Op::Feed { to, .. } => Some(format!("{}:{},{},{}", r.span.line, to.x, to.y, to.z)),
                _ => None,
            },
            Event::Diagnostic(d) => Some(d.code.to_string()),
        })
        .collect()
}

fn t(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

/// (The first move of these programmes, to X0 Y0 Z0 from there, has no length: no record.)
/// A value from a variable has a decimal point: `#1=100; X#1` is 100 mm on FANUC, where `X100`
/// is 0.1 mm (docs/reference/macro.md section 4.4). A vacant bare variable makes its word disappear: `Y#5`
/// is not written, Y stays. Arithmetic on vacant gives 0: `Z[#5+2]` is Z2.
#[test]
fn values_from_variables_and_vacant_words() {
    let text = "G21 G90 G00 X0. Y7. Z0.\n#1 = 100\nG00 X#1 Y#5 Z[#5+2]\nG00 X100\nM30\n";
    // X100 without a point is 0.1 mm, with warning NCS-W02.
    assert_eq!(trace("fanuc0m", text), t(&["1:0,7,0", "3:100,7,2", "NCS-W02", "4:0.1,7,2"]));
    // -#1 with #1 vacant disappears too (inferred); X-#1 with #1 = 4 is X-4.
    assert_eq!(trace("fanuc0m", "G90 G00 X1. Y1. Z1.\nX-#1 Y2.\n#1=4\nX-#1\nM30\n"), t(&["1:1,1,1", "2:1,2,1", "4:-4,2,1"]));
    // A value is rounded to the least increment: 500.123678 -> X500.124.
    assert_eq!(trace("fanuc0m", "G90 G00 X0 Y0 Z0\n#1=500.123678\nX#1\nM30\n"), t(&["3:500.124,0,0"]));
}

/// FIX toward zero, FUP away from zero, ROUND half away from zero, on negative values too
/// (docs/reference/macro.md section 5): FIX[-1.7] = -1, FUP[-1.2] = -2, ROUND[-2.5] = -3, ROUND[2.4] = 2.
#[test]
fn rounding_functions_on_negative_values() {
    let text = "G90 G00 X0 Y0 Z0\n#1 = FIX[-1.7]\n#2 = FUP[-1.2]\n#3 = ROUND[-2.5]\n#4 = ROUND[2.4]\nG00 X#1 Y#2 Z#3\nX#4\nM30\n";
    assert_eq!(trace("fanuc0m", text), t(&["6:-1,-2,-3", "7:2,-2,-3"]));
    // Every function once: SIN[30] = 0.5, COS[60] = 0.5, TAN[45] = 1, ASIN[1] = 90,
    // ACOS[0] = 90, ATAN[1]/[1] = 45, SQRT[16] = 4, ABS[-3] = 3, LN[1] = 0, EXP[0] = 1,
    // BCD[12] = 18 (0x12), BIN[18] = 12; the sum is 0.5+0.5+1+90+90+45+4+3+0+1+18+12 = 265.
    let text = "G90 G00 X0 Y0 Z0\n#1 = SIN[30]+COS[60]+TAN[45]+ASIN[1]+ACOS[0]+ATAN[1]/[1]+SQRT[16]+ABS[-3]+LN[1]+EXP[0]+BCD[12]+BIN[18]\nX#1\nM30\n";
    assert_eq!(trace("fanuc0m", text), t(&["3:265,0,0"]));
}

/// WHILE nests (DO1 holding DO2): the inner body runs 2 x 3 = 6 times, X counting 1..6.
#[test]
fn while_loops_nest() {
    let text = "G90 G00 X0 Y0 Z0\n#1 = 0\n#3 = 0\nWHILE [#1 LT 2] DO1\n#2 = 0\nWHILE [#2 LT 3] DO2\n#3 = #3 + 1\nG00 X#3\n#2 = #2 + 1\nEND2\n#1 = #1 + 1\nEND1\nG00 Y9.\nM30\n";
    let moves = trace("fanuc0m", text);
    assert_eq!(moves, t(&["8:1,0,0", "8:2,0,0", "8:3,0,0", "8:4,0,0", "8:5,0,0", "8:6,0,0", "13:6,9,0"]));
    // A WHILE whose condition does not hold at once: its body is passed over.
    assert_eq!(trace("fanuc0m", "G90 G00 X0 Y0 Z0\nWHILE [1 EQ 2] DO1\nG00 X5.\nEND1\nG00 Y1.\nM30\n"), t(&["5:0,1,0"]));
}

/// GOTO with a computed target, forward and back; IF THEN; IF GOTO.
#[test]
fn computed_goto_and_if() {
    // #1 = 2: GOTO [#1*10] goes to N20 (X2 is passed over); N20 counts #2 up to 3 through
    // IF [..] GOTO 20 backwards, moving Y 1, 2, 3; then IF [..] THEN sets #3 = 7 -> Z7.
    let text =
        "G90 G00 X0 Y0 Z0\n#1 = 2\n#2 = 0\nGOTO [#1*10]\nN10 G00 X2.\nN20 #2 = #2 + 1\nG00 Y#2\nIF [#2 LT 3] GOTO 20\nIF [#2 EQ 3] THEN #3 = 7\nG00 Z#3\nM30\n";
    assert_eq!(trace("fanuc0m", text), t(&["7:0,1,0", "7:0,2,0", "7:0,3,0", "10:0,3,7"]));
}

/// G65 gives the macro a new level of locals set from its arguments; M98 shares the caller's
/// (F16i manual; docs/reference/macro.md section 2). After G65 returns, the caller's #1 is as it was.
#[test]
fn g65_has_its_own_locals_and_m98_shares_them() {
    // Main: #1 = 5. G65 P100 A7. -> in O0100 #1 = 7 -> X7, and it sets #1 = 99 (its own).
    // Back in main, X#1 is X5. M98 P200: O0200 sees #1 = 5 -> Y5, sets #1 = 6 -> main X6.
    let text = "O0001\nG90 G00 X0 Y0 Z0\n#1 = 5\nG65 P100 A7.\nG00 X#1\nM98 P200\nG00 X#1\nM30\nO0100\nG00 X#1\n#1 = 99\nM99\nO0200\nG00 Y#1\n#1 = 6\nM99\n";
    assert_eq!(trace("fanuc0m", text), t(&["10:7,0,0", "5:5,0,0", "14:5,5,0", "7:6,5,0"]));
}

/// Arguments: specification I (A B C D ... Z) and II (repeated I J K: #4-#6, #7-#9, ...), the
/// later wins when both name one variable; a value without a point is in least input
/// increments on FANUC (X10 -> #24 = 0.010), in millimetres on the GSK980TDi.
#[test]
fn g65_arguments() {
    // I1. J2. K3. I4. J5. K6.: #4=1 #5=2 #6=3 #7=4 #8=5 #9=6. D9. names #7 after: #7 = 9.
    let text = "O0001\nG90 G00 X0 Y0 Z0\nG65 P100 I1. J2. K3. I4. J5. K6. D9. X10\nM30\nO0100\nG00 X[#4+#5+#6] Y[#7+#8+#9] Z[#24*1000]\nM99\n";
    // X = 1+2+3 = 6; Y = 9+5+6 = 20; Z = 0.010 * 1000 = 10.
    assert_eq!(trace("fanuc0m", text), t(&["6:6,20,10"]));
    // GSK980TDi: P comes right after G65; X10 is 10 mm, so #24 = 10 and W-#24 goes back 10.
    let gsk = "O0001\nG00 X20. Z0.\nG65 P100 X10 Z4.\nM30\nO0100\nG00 U#24 W#26\nM99\n";
    let e = run_mode("gsk980tdi", Mode::Run, gsk);
    let moves: Vec<(f64, f64)> = e
        .iter()
        .filter_map(|e| match e {
            Event::Record(r) => match &r.op {
                Op::Rapid { to, .. } => Some((to.x * 2.0, to.z)),
                _ => None,
            },
            _ => None,
        })
        .collect();
    assert_eq!(moves, vec![(20.0, 0.0), (30.0, 4.0)]);
    // L repeats the call: O0100 adds 1 to X three times.
    let text = "O0001\nG90 G00 X0 Y0 Z0\nG65 P100 L3 A1.\nM30\nO0100\n#100 = #100 + #1\nG00 X#100\nM99\n";
    assert_eq!(trace("fanuc0m", text), t(&["7:1,0,0", "7:2,0,0", "7:3,0,0"]));
}

/// Four G65 calls nest; the fifth is alarm 077, counted apart from M98's four.
#[test]
fn g65_nesting() {
    let mut text = String::from("O9000\nG65 P1 A1.\nM30\n");
    for k in 1..=5 {
        text.push_str(&format!("O{k:04}\nG65 P{} A1.\nM99\n", k + 1));
    }
    text.push_str("O0006\nM99\n");
    let e = trace("fanuc0m", &text);
    assert_eq!(e.last().map(String::as_str), Some("PS0077"), "{e:?}");
}

/// #5001-#5003 after a move, and #5041 inside a canned cycle's programme: the position the
/// tool is at (no offsets without a setup). After G81 at X10 Y10 with G98 from Z30, the tool is
/// back at the initial level Z30.
#[test]
fn position_variables() {
    let text = "G21 G17 G90 G00 X12.5 Y-3. Z30.\n#1 = #5001\n#2 = #5002\n#3 = #5003\nG00 X[#1+#2] Y#3\nG98 G81 X10. Y10. Z-5. R2. F100.\nG80\n#4 = #5041\n#5 = #5043\nG00 X[#4*2] Y#5\nM30\n";
    let e = trace("fanuc0m", text);
    // X = 12.5 - 3 = 9.5, Y = 30; after the hole: #4 = 10, #5 = 30 -> X20 Y30.
    assert_eq!(e.first().map(String::as_str), Some("1:12.5,-3,30"));
    assert_eq!(e[1], "5:9.5,30,30");
    assert_eq!(e.last().map(String::as_str), Some("10:20,30,30"), "{e:?}");
    // A lathe reads X as a diameter.
    let lathe = "G00 X40. Z2.\n#1 = #5001\nG00 X[#1-10]\nM30\n";
    let e = run_mode("gsk980tdi", Mode::Run, lathe);
    let x: Vec<f64> = e
        .iter()
        .filter_map(|e| match e {
            Event::Record(r) => match &r.op {
                Op::Rapid { to, .. } => Some(to.x * 2.0),
                _ => None,
            },
            _ => None,
        })
        .collect();
    assert_eq!(x, vec![40.0, 30.0]);
}

/// #3000 stops with the user's alarm 3000 + n and the comment's text; #3001 counts the run's
/// milliseconds (10 mm at the rapid rate takes about 0.1 s, so it is between 50 and 500).
#[test]
fn user_alarm_and_clock() {
    let e = run_mode("fanuc0m", Mode::Run, "#3000 = 7 (SPINDLE NOT READY)\nM30\n");
    let Some(Event::Diagnostic(d)) = e.last() else { panic!() };
    assert_eq!(d.code, "PS3000");
    assert!(d.message.contains("3007") && d.message.contains("SPINDLE NOT READY"), "{}", d.message);
    let text = "G90 G00 X0 Y0 Z0\nG00 X10.\n#1 = #3001\nG00 Y#1\nM30\n";
    let y: Vec<f64> = run_mode("fanuc0m", Mode::Run, text)
        .iter()
        .filter_map(|e| match e {
            Event::Record(r) => r.op.end_point().map(|p| p.y),
            _ => None,
        })
        .collect();
    assert!(y.last().is_some_and(|y| *y > 50.0 && *y < 500.0), "{y:?}");
}

/// #4001-#4120: the modal codes as the profile names them, F, S, T.
#[test]
fn modal_information() {
    let text = "G90 G17 G00 X0 Y0 Z0\nG01 X1. F250. S1200 M03\n#1 = #4001\n#2 = #4003\n#3 = #4109\nG00 X#1 Y#2 Z[#3/100]\nM30\n";
    // G01 -> 1, G90 -> 90, F250 -> Z2.5.
    assert_eq!(trace("fanuc0m", text).last().map(String::as_str), Some("6:1,90,2.5"));
}

/// A programme with macros and the same moves written out give the same records.
#[test]
fn macros_give_what_their_expansion_gives() {
    for (n, step) in [(3, 2.5), (5, 1.25), (1, 10.0)] {
        let text =
            format!("G21 G90 G00 X0 Y0 Z5.\n#1 = 0\nWHILE [#1 LT {n}] DO1\nG01 X[#1*{step}] Y[SIN[#1*30]*10] F300.\nG00 Z[5-#1]\n#1 = #1 + 1\nEND1\nM30\n");
        let mut flat = String::from("G21 G90 G00 X0 Y0 Z5.\n");
        for i in 0..n {
            let y = ((i as f64 * 30.0).to_radians().sin() * 10.0 * 1000.0).round() / 1000.0;
            flat.push_str(&format!("G01 X{:.3} Y{y:.3} F300.\nG00 Z{:.3}\n", i as f64 * step, 5.0 - i as f64));
        }
        flat.push_str("M30\n");
        let records = |text: &str| -> Vec<String> {
            run_mode("fanuc0m", Mode::Run, text)
                .into_iter()
                .map(|e| match e {
                    Event::Record(r) => format!("{:?} {:.6}", r.op, r.t_s),
                    Event::Diagnostic(d) => panic!("{d:?}"),
                })
                .collect()
        };
        assert_eq!(records(&text), records(&flat), "n = {n}");
    }
}

/// A check goes on past a macro alarm and reports each once, even in a loop.
#[test]
fn a_check_reports_a_loop_alarm_once() {
    let text = "#1 = 0\nWHILE [#1 LT 5] DO1\n#2 = 1 / 0\n#1 = #1 + 1\nEND1\nM30\n";
    let e = run_mode("fanuc0m", Mode::Check, text);
    let alarms: Vec<&str> = e
        .iter()
        .filter_map(|e| match e {
            Event::Diagnostic(d) if d.is_alarm() => Some(d.code),
            _ => None,
        })
        .collect();
    assert_eq!(alarms, vec!["PS0112"]);
}

/// G66 declares a modal call and calls nothing itself; each later block with a move calls the
/// macro after its move (its own moves do not call it again); G67 ends it. Here O9200 drills:
/// Z down to #26 and back up, after the rapids to X10 and X20 but not after G67's X30.
#[test]
fn g66_calls_after_each_move() {
    let text = "O0001\nG90 G00 X0 Y0 Z5.\nG66 P9200 Z-2.\nG00 X10.\nX20.\nG67\nX30.\nM30\nO9200\nG01 Z#26 F100.\nG00 Z5.\nM99\n";
    assert_eq!(trace("fanuc0m", text), t(&["2:0,0,5", "4:10,0,5", "10:10,0,-2", "11:10,0,5", "5:20,0,5", "10:20,0,-2", "11:20,0,5", "7:30,0,5"]));
    // GSK: a G65 cancels G66 (GSK980TDi help text, G66): after it, W-1 calls nothing.
    let gsk = "O0001\nG00 X10. Z5.\nG66 P9200 A1.\nG00 W-1\nG65 P9300\nG00 W-1\nM30\nO9200\nG00 U#1\nM99\nO9300\nM99\n";
    let e = run_mode("gsk980tdi", Mode::Run, gsk);
    let lines: Vec<u32> = e
        .iter()
        .filter_map(|e| match e {
            Event::Record(r) if matches!(r.op, Op::Rapid { .. }) => Some(r.span.line),
            _ => None,
        })
        .collect();
    assert_eq!(lines, vec![2, 4, 9, 6]);
}

/// Found by review: a G65 argument from a variable passes as it is (D#1 with #1 = 2.5 is #7 =
/// 2.5, not rounded nor scaled); H and F without a point are not scaled (H5 is #11 = 5);
/// ROUND in an address rounds to the least increment (X[ROUND[#1]+ROUND[#2]] = X3.581);
/// a GOTO out of a WHILE does not leave the loop in the way of an outer END.
#[test]
fn review_fixes() {
    let text = "O0001\nG90 G00 X0 Y0 Z0\n#1 = 2.5\nG65 P100 D#1 H5 F150\nM30\nO0100\nG00 X#7 Y#11 Z#9\nM99\n";
    assert_eq!(trace("fanuc0m", text).last().map(String::as_str), Some("7:2.5,5,150"));
    let text = "G90 G00 X0 Y0 Z0\n#1 = 1.2345\n#2 = 2.3456\nG00 X[ROUND[#1]+ROUND[#2]]\n#3 = ROUND[#1]+ROUND[#2]\nY#3\nM30\n";
    assert_eq!(trace("fanuc0m", text), t(&["4:3.581,0,0", "6:3.581,3,0"]));
    let text = "G90 G00 X0 Y0 Z0\n#1 = 0\nWHILE [#1 LT 3] DO1\n#1 = #1 + 1\nWHILE [1 EQ 1] DO2\nGOTO 10\nEND2\nN10 G00 X#1\nEND1\nM30\n";
    assert_eq!(trace("fanuc0m", text), t(&["8:1,0,0", "8:2,0,0", "8:3,0,0"]));
}

/// Found by review: a G65 block with block delete on is passed over; on the GSK980TDi `G65 P H`
/// is macro B with H an argument (#11), only `G65 H..` is macro A.
#[test]
fn review_fixes_block_delete_and_macro_a() {
    let program = |switches: Switches| {
        let p = Program::new(Params::defaults(profile::by_name("fanuc0m").unwrap()), switches, Mode::Run);
        events(p, b"O0001\nG90 G00 X0 Y0 Z0\n/G65 P100 A1.\nM30\nO0100\nG00 X#1\nM99\n".as_slice())
            .filter(|e| matches!(e, Event::Record(r) if matches!(r.op, Op::Rapid { .. })))
            .count()
    };
    assert_eq!(program(Switches { block_delete: true, ..Switches::default() }), 0);
    assert_eq!(program(Switches::default()), 1);
    let gsk = "O0001\nG00 X0 Z0\nG65 P100 H3.\nM30\nO0100\nG00 W#11\nM99\n";
    let e = run_mode("gsk980tdi", Mode::Run, gsk);
    assert!(e.iter().all(|e| !matches!(e, Event::Diagnostic(d) if d.is_alarm())), "{e:?}");
}

/// The GSK980TDi's macro A, `G65 Hm P#i Q#j R#k` (GSK980TDi manual, G65 H list), by hand:
/// #100 = 5; #101 = 5 + 3 = 8; #102 = 8 x 2 = 16; #103 = 10 SIN[30] = 5; #104 = ATAN[1/1] = 45;
/// #102 = 16 x 3 / 4 = 12; U#102 moves X by 12 (diameter), W#103 Z by 5; H81 jumps to N50
/// because #100 = 5 (W99 passed over); H99 P7 is the user's alarm 507.
#[test]
fn gsk_macro_a() {
    let text = "G00 X20. Z0.\nG65 H01 P#100 Q5\nG65 H02 P#101 Q#100 R3\nG65 H04 P#102 Q#101 R2\nG65 H31 P#103 Q10 R30\nG65 H34 P#104 Q1 R1\nG65 H26 P#102 Q3 R4\nG00 U#102 W#103\nG65 H81 P50 Q#100 R5\nG00 W99\nN50 G00 W#104\nG65 H99 P7 (DOOR OPEN)\nM30\n";
    let e = run_mode("gsk980tdi", Mode::Run, text);
    let moves: Vec<(f64, f64)> = e
        .iter()
        .filter_map(|e| match e {
            Event::Record(r) => match &r.op {
                Op::Rapid { to, .. } => Some((to.x * 2.0, (to.z * 1000.0).round() / 1000.0)),
                _ => None,
            },
            _ => None,
        })
        .collect();
    assert_eq!(moves, vec![(20.0, 0.0), (32.0, 5.0), (32.0, 50.0)]);
    let Some(Event::Diagnostic(d)) = e.last() else { panic!() };
    assert!(d.code == "NCS-E75" && d.message.contains("507") && d.message.contains("DOOR OPEN"), "{d:?}");
    // P without # where a variable is meant.
    let e = run_mode("gsk980tdi", Mode::Run, "G65 H01 P100 Q10\nM30\n");
    assert!(matches!(e.last(), Some(Event::Diagnostic(d)) if d.code == "NCS-E66"), "{e:?}");
}

/// `IF [..] #i = ..` without THEN: taken as THEN on the FANUC profiles with warning NCS-W28
/// (once, though the block runs three times), alarm 114 elsewhere.
#[test]
fn if_without_then() {
    let text = "#1 = 0\nN5 #1 = #1 + 1\nIF [#1 GT 0] #2 = #1 * 10\nIF [#1 LT 3] GOTO 5\nG90 G00 X#2 Y0 Z0\nM30\n";
    assert_eq!(trace("fanuc0m", text), t(&["NCS-W28", "5:30,0,0"]));
    let e = run_mode("gsk980tdi", Mode::Run, "#1 = 1\nIF [#1 GT 0] #2 = 5\nM30\n");
    assert!(matches!(e.last(), Some(Event::Diagnostic(d)) if d.code == "NCS-E66"), "{e:?}");
}

/// Calls a machine builder sets up by parameter (FANUC 6050-6089): with 6050 = 100, G100 X5.
/// calls O9010 with X as #24; with 6071 = 88, M88 calls O9001 as M98 (after the block's move);
/// inside O9010 a G100 is an ordinary code (here an alarm: G100 is no G code). GSK980TDi: M9123
/// calls O9123. With no such parameter set, M88 is a machine-specific M code (NCS-W05).
#[test]
fn builder_calls_by_parameter() {
    let params = |pairs: &[(&str, f64)]| {
        let mut p = Params::defaults(profile::by_name("fanuc0m").unwrap());
        for (k, v) in pairs {
            p.set_text(&format!("{k}={v}")).unwrap();
        }
        p
    };
    let text = "O0001\nG90 G00 X0 Y0 Z0\nG100 X5.\nG00 Y1. M88\nM30\nO9010\nG00 X#24\nM99\nO9001\nG00 Z2.\nM99\n";
    let run = |p: Params| -> Vec<String> {
        events(Program::new(p, Switches::default(), Mode::Run), text.as_bytes())
            .filter_map(|e| match e {
                Event::Record(r) => match r.op {
                    Op::Rapid { to, .. } => Some(format!("{}:{},{},{}@{}", r.span.line, to.x, to.y, to.z, r.call_depth)),
                    _ => None,
                },
                Event::Diagnostic(d) => Some(d.code.to_string()),
            })
            .collect()
    };
    assert_eq!(run(params(&[("6050", 100.0), ("6071", 88.0)])), t(&["7:5,0,0@1", "4:5,1,0@0", "10:5,1,2@1"]));
    let plain = run(params(&[]));
    assert_eq!(plain.first().map(String::as_str), Some("PS0010"), "{plain:?}");
    let gsk = "O0001\nG00 X10. Z0.\nM9123\nM30\nO9123\nG00 W-2.\nM99\n";
    let e = run_mode("gsk980tdi", Mode::Run, gsk);
    let z: Vec<f64> = e
        .iter()
        .filter_map(|e| match e {
            Event::Record(r) => match &r.op {
                Op::Rapid { to, .. } => Some(to.z),
                _ => None,
            },
            _ => None,
        })
        .collect();
    assert_eq!(z, vec![0.0, -2.0]);
}

/// #4005 (feed mode), #4010 (return level on a mill), #3901 (parts, settable), #5004 (no fourth
/// axis: vacant, so Y#5004 disappears).
#[test]
fn more_system_variables() {
    let text = "G90 G95 G99 G00 X0 Y0 Z0\n#1 = #4005\n#2 = #4010\n#3901 = #3901 + 1\nG00 X#1 Y#2 Z#3901\nY#5004\nM30\n";
    assert_eq!(trace("fanuc0m", text), t(&["5:95,99,1"]));
}

/// Single block and macro statements (docs/reference/macro.md section 6): a FANUC stops only after NC blocks
/// unless 6000#5 SBM is 1; then also after `#3 = 5.` (line 3) and the IF (line 4). The GSK980TDi
/// has no such parameter (not found in its help text): NC blocks only.
#[test]
fn single_block_stops_at_macro_statements_with_sbm() {
    use ncsight::motion::StopReason;
    let text = "G21 G90 G00 X0. Y0. Z0.\nG00 X1.\n#3 = 5.\nIF [#3 GT 2] THEN #4 = 1.\nG00 X#3\nM30\n";
    let lathe = "G00 X0. Z0.\nG00 X1.\n#3 = 5.\nIF [#3 GT 2] THEN #4 = 1.\nG00 X#3\nM30\n";
    let stops = |machine: &str, sbm: Option<f64>| -> Vec<u32> {
        let text = if machine == "fanuc0m" { text } else { lathe };
        let mut params = Params::defaults(profile::by_name(machine).unwrap());
        if let Some(v) = sbm {
            params.set(profile::ParamKey::Number(6000, Some(5)), v).unwrap();
        }
        let operator = ncsight::Options { single_block: true, ..ncsight::Options::default() };
        ncsight::run_text_with(params, Switches::default(), Mode::Run, operator, text.as_bytes())
            .iter()
            .filter_map(|e| match e {
                Event::Record(r) if r.op == (Op::Stop { reason: StopReason::SingleBlock }) => Some(r.span.line),
                _ => None,
            })
            .collect()
    };
    assert_eq!(stops("fanuc0m", None), [2, 5, 6]);
    assert_eq!(stops("fanuc0m", Some(0.0)), [2, 5, 6]);
    assert_eq!(stops("fanuc0m", Some(1.0)), [2, 3, 4, 5, 6]);
    assert_eq!(stops("fanuc0t", Some(1.0)), [2, 3, 4, 5, 6]);
    assert_eq!(stops("gsk980tdi", None), [2, 5, 6]);
    // Without single block, SBM changes nothing.
    let params = {
        let mut p = Params::defaults(profile::by_name("fanuc0m").unwrap());
        p.set(profile::ParamKey::Number(6000, Some(5)), 1.0).unwrap();
        p
    };
    let events = ncsight::run_text(params, Switches::default(), Mode::Run, text.as_bytes());
    assert!(!events.iter().any(|e| matches!(e, Event::Record(r) if matches!(r.op, Op::Stop { .. }))));
}

/// #4001-#4022 read the code in force in FANUC group n (#4000 + n), numbered as the mill's
/// and the lathe's G-code lists number them; #4102-#4113 the last B D E H M words.
/// Mill (fanuc0m), line 2 sets G41 D7 G43 H3 G55 G61 M08: line 3 reads group 07 (G41), 08
/// (G43), 14 (G55); line 4 group 15 (G61), D 7, H 3; line 5 M 8, group 12 (G67: no G66),
/// group 10 (G98 at power on). Inside G99 G81, #4009 is 81 and #4010 99; after G80 G40 G49,
/// #4009 is 80, #4007 40, #4008 49 and group 01 is G00 (0). Group 13 reads G97, then G96.
#[test]
fn modal_information_by_group_number() {
    let text = "G21 G17 G90 G00 X0. Y0. Z0.\nG41 D7 G43 H3 G55 G61 M08 X1.\nG00 X#4007 Y#4008 Z#4014\nG00 X#4015 Y#4107 Z#4111\nG00 X#4113 Y#4012 Z#4010\nG99 G81 X1. Y1. Z-5. R2. F100.\n#1 = #4009\n#2 = #4010\nG80 G40 G49\nG00 X#1 Y#2 Z#4009\nG00 X#4007 Y#4008 Z#4001\nM30\n";
    let moves: Vec<String> = trace("fanuc0m", text)
        .into_iter()
        .filter(|s| s.starts_with("3:") || s.starts_with("4:") || s.starts_with("5:") || s.starts_with("10:") || s.starts_with("11:"))
        .collect();
    assert_eq!(moves, t(&["3:41,43,55", "4:61,7,3", "5:8,67,98", "10:81,99,80", "11:40,49,0"]));
    // Group 13 (G96/G97): G97 at power on, G96 once given.
    let e = trace("fanuc0m", "G00 X0 Y0 Z0\nG00 X#4013\nG96 S100 M03\nG00 X#4013\nM30\n");
    assert_eq!(e, t(&["2:97,0,0", "4:96,0,0"]));
    // Group 04 (G22/G23): G23 at power on, G22 once given.
    let e = trace("fanuc0m", "G00 X0 Y0 Z0\nG00 X#4004\nG22 X100. Y100. Z100. I50. J50. K50.\nG00 X#4004\nM30\n");
    assert_eq!(e, t(&["2:23,0,0", "4:22,0,0"]));
    // Lathes number the groups as the FANUC 0-T's list (system A): 01 motion (G92 in force:
    // 92, X92. a diameter), 02 G96/G97 (97), 16 the plane (G18), 05 the feed mode (G99 per
    // revolution at power on on the FANUC 0-T, G98 per minute on the GSK980TDi), M 8; group 03
    // does not exist in system A (alarm 115).
    let lathe =
        "G00 X50. Z5. S500 M03\nG92 X48. Z-20. F2.\n#1 = #4001\nG00 X#1 Z#4002\nG00 X#4016 Z#4005\nG01 X30. F0.2 M08\nG00 X#4001 Z#4113\n#2 = #4003\nM30\n";
    let lathe_moves = |m: &str| -> Vec<String> {
        trace(m, lathe).into_iter().filter(|s| s.starts_with("4:") || s.starts_with("5:") || s.starts_with("7:") || !s.contains(':')).collect()
    };
    assert_eq!(lathe_moves("fanuc0t"), t(&["4:46,0,97", "5:9,0,99", "7:0.5,0,8", "PS0115"]));
    // (F0.2 per minute on the GSK980TDi draws its slow-feed warning.)
    let gsk: Vec<String> = lathe_moves("gsk980tdi").into_iter().filter(|s| s.contains(':')).collect();
    assert_eq!(gsk, t(&["4:46,0,97", "5:9,0,98", "7:0.5,0,8"]));
}

/// Interface signals: an input (#1000-#1015, #1032) is what the machine's switches give, which
/// ncsight cannot know: alarm 115 unless the user gives it (`--var 1002=1`, here
/// `set_variable`); a programme cannot write one (116). Outputs #1100-#1115 start off and read
/// back what was written; #1132 is the 16 at once (#1100 the lowest bit): #1101 = 1 and #1103
/// = 1 make #1132 = 2 + 8 = 10; writing #1132 = 5 sets #1100 and #1102.
#[test]
fn interface_signals() {
    let run_vars = |vars: &[(i64, f64)], text: &str| -> Vec<String> {
        let mut program = Program::new(Params::defaults(profile::by_name("fanuc0m").unwrap()), Switches::default(), Mode::Run);
        for (n, v) in vars {
            program.set_variable(*n, *v).unwrap();
        }
        events_of(program, text)
    };
    let read = "G21 G90 G00 X0 Y0 Z0\nG00 X#1002 Y#1032 Z1.\nM30\n";
    assert_eq!(run_vars(&[], read), t(&["2:PS0115"]));
    // #1032 from the 16 bits when each was given: only #1002 = 1 -> 4.
    let all: Vec<(i64, f64)> = (1000..=1015).map(|n| (n, if n == 1002 { 1.0 } else { 0.0 })).collect();
    assert_eq!(run_vars(&all, read), t(&["2:1,4,1"]));
    assert_eq!(run_vars(&[(1002, 1.0), (1032, 7.0)], read), t(&["2:1,7,1"]));
    assert_eq!(run_vars(&[], "G00 X0 Y0 Z0\n#1002 = 1\nM30\n"), t(&["2:PS0116"]));
    let outputs = "G21 G90 G00 X0 Y0 Z0\nG00 X#1101 Y#1132 Z1.\n#1101 = 1\n#1103 = 1\nG00 X#1101 Y#1132\n#1132 = 5\nG00 X#1100 Y#1101 Z#1102\nM30\n";
    assert_eq!(run_vars(&[], outputs), t(&["2:0,0,1", "5:1,10,1", "7:1,0,1"]));
    assert_eq!(run_vars(&[], "G00 X0 Y0 Z0\n#1100 = 2\nM30\n"), t(&["2:PS0115"]));
    // The operator's values are checked: a signal is 0 or 1.
    let mut program = Program::new(Params::defaults(profile::by_name("fanuc0m").unwrap()), Switches::default(), Mode::Run);
    assert!(program.set_variable(1002, 2.0).is_err());
    assert!(program.set_variable(1100, 1.0).is_err());
}

/// On a lathe the controlled axes are X and Z: #5001 is X (a diameter), #5002 Z, #5003 vacant
/// (no third axis); #5021/#5022 and #5041/#5042 likewise. After `G00 X40. Z-3.`: X[#5001/2] is
/// X20, Z[#5002*2] is Z-6; `U#5003` with #5003 vacant disappears; #5122 (handle interruption
/// of Z) is 0.
#[test]
fn lathe_positions_are_x_then_z() {
    let text = "G00 X40. Z-3.\n#1 = #5001\n#2 = #5022\nG00 X[#1/2] Z[#2*2] U#5003\nG00 X[#5041*2] Z[#5042+#5122-1]\nM30\n";
    // Line 5: #5041 is the diameter 20, so X40 (radius 20); Z -6 + 0 - 1.
    let moves: Vec<String> = trace("fanuc0t", text);
    assert_eq!(moves, t(&["1:20,0,-3", "4:10,0,-6", "5:20,0,-7"]));
}

mod expansion {
    //! The property behind every macro construct: a programme written with variables, loops,
    //! G65 calls and M98 repeats gives the same records (operations and times) as the same
    //! moves written out as numbers. Values are whole micrometres, so the 0.001 mm rounding of
    //! a variable's value in an address gives back the literal exactly.
    use super::*;
    use proptest::prelude::*;

    /// Each record as the outputs show it (six decimals: an incremental move adds in binary
    /// floating point, so 0.521 - 3.490 is -2.9690000000000003, which every output writes as
    /// -2.969), each diagnostic by its code.
    fn records(machine: &str, text: &str) -> Vec<String> {
        run_mode(machine, Mode::Run, text)
            .into_iter()
            .map(|e| match e {
                Event::Record(r) => {
                    let to = r.op.end_point().map(|p| format!("{:.6} {:.6} {:.6}", p.x, p.y, p.z)).unwrap_or_default();
                    let feed = match r.op {
                        Op::Feed { feed_mm_min, .. } => format!(" F{feed_mm_min:.6}"),
                        _ => String::new(),
                    };
                    format!("{} {to}{feed} t={:.6}", r.op.kind(), r.t_s)
                }
                Event::Diagnostic(d) => format!("{} {}", d.code, d.message),
            })
            .collect()
    }

    fn mm(um: i64) -> String {
        format!("{:.3}", um as f64 / 1000.0)
    }

    /// One pattern repeated `n` times: moves to base + i * step (X, Y) and a feed at depth z.
    #[derive(Debug, Clone)]
    struct Pattern {
        n: i64,
        base_um: (i64, i64),
        step_um: (i64, i64),
        z_um: i64,
        feed: i64,
    }

    fn pattern() -> impl Strategy<Value = Pattern> {
        (1i64..6, (-50_000i64..50_000, -50_000i64..50_000), (-20_000i64..20_000, -20_000i64..20_000), -30_000i64..-1, 50i64..2000)
            .prop_map(|(n, base_um, step_um, z_um, feed)| Pattern { n, base_um, step_um, z_um, feed })
    }

    /// The moves written out.
    fn flat(p: &Pattern) -> String {
        let mut s = String::new();
        for i in 0..p.n {
            let (x, y) = (p.base_um.0 + i * p.step_um.0, p.base_um.1 + i * p.step_um.1);
            s.push_str(&format!("G00 X{} Y{} Z5.\nG01 Z{} F{}.\nG00 Z5.\n", mm(x), mm(y), mm(p.z_um), p.feed));
        }
        s
    }

    /// The moves of a WHILE loop over #1, the values computed from #2-#6.
    fn with_while(p: &Pattern) -> String {
        format!(
            "#2 = {}\n#3 = {}\n#4 = {}\n#5 = {}\n#6 = {}\n#1 = 0\nWHILE [#1 LT {}] DO1\nG00 X[#2 + #1 * #4] Y[#3 + #1 * #5] Z5.\nG01 Z#6 F{}.\nG00 Z5.\n#1 = #1 + 1\nEND1\n",
            mm(p.base_um.0),
            mm(p.base_um.1),
            mm(p.step_um.0),
            mm(p.step_um.1),
            mm(p.z_um),
            p.n,
            p.feed
        )
    }

    /// A G65 call whose arguments (A B I J K, then C the count) a macro after M30 reads as
    /// locals #1 #2 #4 #5 #6 #3, with an IF GOTO loop.
    fn with_g65(p: &Pattern) -> (String, String) {
        let call = format!("G65 P9100 A{} B{} I{} J{} K{} C{}.\n", mm(p.base_um.0), mm(p.base_um.1), mm(p.step_um.0), mm(p.step_um.1), mm(p.z_um), p.n);
        let body = format!(
            "O9100\n#10 = 0\nN10 G00 X[#1 + #10 * #4] Y[#2 + #10 * #5] Z5.\nG01 Z#6 F{}.\nG00 Z5.\n#10 = #10 + 1\nIF [#10 LT #3] GOTO10\nM99\n",
            p.feed
        );
        (call, body)
    }

    /// M98 repeating an incremental step n times, from the base point.
    fn with_m98(p: &Pattern) -> (String, String) {
        let call = format!("G00 X{} Y{} Z5.\nG01 Z{} F{}.\nG00 Z5.\nM98 P{:04}0200\n", mm(p.base_um.0), mm(p.base_um.1), mm(p.z_um), p.feed, p.n - 1);
        let body = format!("O0200\nG91 G00 X{} Y{}\nG90 G01 Z{} F{}.\nG00 Z5.\nM99\n", mm(p.step_um.0), mm(p.step_um.1), mm(p.z_um), p.feed);
        (call, body)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 120, .. ProptestConfig::default() })]

        #[test]
        fn macros_and_calls_give_what_their_expansion_gives(p in pattern()) {
            let head = "G21 G17 G90 G00 X0. Y0. Z5.\n";
            let expected = records("fanuc0m", &format!("{head}{}M30\n", flat(&p)));
            prop_assert!(expected.iter().all(|r| !r.starts_with("NCS-E") && !r.starts_with("PS")), "{expected:?}");
            prop_assert_eq!(&records("fanuc0m", &format!("{head}{}M30\n", with_while(&p))), &expected);
            let (call, body) = with_g65(&p);
            prop_assert_eq!(&records("fanuc0m", &format!("{head}{call}M30\n{body}")), &expected);
            // M98 P<count><number> with a count of 0 calls once: the first point is written
            // out, so n = 1 needs no call at all.
            if p.n > 1 {
                let (call, body) = with_m98(&p);
                prop_assert_eq!(&records("fanuc0m", &format!("{head}{call}M30\n{body}")), &expected);
            }
        }
    }
}

/// Review fixes: a statement's single-block stop comes after the thread run held back before
/// it (time order); #1032 given gives its bits, and a bit that disagrees is refused; #4015 on
/// a lathe whose G61/G64 are not simulated is alarm 115, not the power-on 64.
#[test]
fn statement_stops_inputs_and_unsimulated_groups() {
    use ncsight::motion::StopReason;
    let mut params = Params::defaults(profile::by_name("fanuc0t").unwrap());
    params.set(profile::ParamKey::Number(6000, Some(5)), 1.0).unwrap();
    let operator = ncsight::Options { single_block: true, ..ncsight::Options::default() };
    let text = "G00 X40. Z5. S500 M03\nG32 W-10. F1.5\n#1 = 1\nG00 X50.\nM30\n";
    let events = ncsight::run_text_with(params, Switches::default(), Mode::Run, operator, text.as_bytes());
    let times: Vec<f64> = events
        .iter()
        .filter_map(|e| match e {
            Event::Record(r) => Some(r.t_s),
            _ => None,
        })
        .collect();
    assert!(times.windows(2).all(|w| w[0] <= w[1] + 1e-9), "{times:?}");
    let line3 = events
        .iter()
        .position(|e| matches!(e, Event::Record(r) if r.span.line == 3 && r.op == (Op::Stop { reason: StopReason::SingleBlock })))
        .expect("a stop at the statement");
    let last_thread = events.iter().rposition(|e| matches!(e, Event::Record(r) if r.span.line == 2)).unwrap();
    assert!(last_thread < line3);

    let mut program = Program::new(Params::defaults(profile::by_name("fanuc0m").unwrap()), Switches::default(), Mode::Run);
    program.set_variable(1032, 5.0).unwrap();
    let moves: Vec<String> = events_of(program, "G21 G90 G00 X0 Y0 Z0\nG00 X#1000 Y#1001 Z#1002\nM30\n");
    assert_eq!(moves, t(&["2:1,0,1"]));
    let mut program = Program::new(Params::defaults(profile::by_name("fanuc0m").unwrap()), Switches::default(), Mode::Run);
    program.set_variable(1000, 0.0).unwrap();
    assert!(program.set_variable(1032, 1.0).is_err());

    // (The GSK980TDi numbers alarm 115 its own way.)
    assert_eq!(trace("gsk980tdi", "G00 X10 Z0\n#1 = #4017\nM30\n"), [String::from("1:5,0,0"), gsk_115()]);
}

/// The GSK980TDi's code for alarm 115 (its own style).
fn gsk_115() -> String {
    ncsight::Rule::IllegalVariable.code(profile::by_name("gsk980tdi").unwrap().alarm_style).to_string()
}

/// The rapids of a run as "line:x,y,z", each diagnostic as "line:code".
fn events_of(program: Program, text: &str) -> Vec<String> {
    events(program, text.as_bytes())
        .filter_map(|e| match e {
            Event::Record(r) => match r.op {
                Op::Rapid { to, .. } => Some(format!("{}:{},{},{}", r.span.line, to.x, to.y, to.z)),
                _ => None,
            },
            Event::Diagnostic(d) => Some(format!("{}:{}", d.span.line, d.code)),
        })
        .collect()
}
