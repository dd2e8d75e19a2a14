//! Defects found by outside checks (issue 15): each test failed before its fix.

use ncsight::motion::Op;

mod common;

use common::first_alarm;

fn spindle_rpms(machine: &str, text: &str) -> Vec<f64> {
    let (r, d) = common::run_plain(machine, &[], text);
    assert!(d.iter().all(|d| !d.is_alarm()), "{d:?}");
    r.iter().filter_map(|r| if let Op::Spindle { rpm, .. } = r.op { Some(rpm) } else { None }).collect()
}

/// G96 under G20: S is feet per minute (FANUC 0-T and GSK980TDi manuals, G96).
#[test]
fn g96_under_g20_is_feet_per_minute() {
    for machine in ["fanuc0t", "gsk980tdi"] {
        // 500 ft/min at a 2.0 inch diameter: 500 x 12 / (pi x 2.0) = 954.93 rpm.
        let rpm = spindle_rpms(machine, "G20 G0 X2.0 Z0.1\nG96 S500 M03\nG01 Z-1.0 F0.01\nM30\n");
        let last = *rpm.last().unwrap();
        assert!((last - 500.0 * 12.0 / (std::f64::consts::PI * 2.0)).abs() < 0.01, "{machine}: {rpm:?}");
        // 150 m/min at 50 mm: 954.93 rpm.
        let rpm = spindle_rpms(machine, "G21 G0 X50. Z2.\nG96 S150 M03\nG01 Z-10. F0.1\nM30\n");
        assert!((rpm.last().unwrap() - 150_000.0 / (std::f64::consts::PI * 50.0)).abs() < 0.01, "{machine}: {rpm:?}");
    }
}

/// FANUC alarm 0044: G27-G30 while a drilling cycle is in force (no extra hole drilled); after
/// G80, or with G80 in the same block, G28 runs.
#[test]
fn fanuc_0044_reference_return_in_a_canned_cycle() {
    let head = "G21 G17 G90 G0 X0. Y0. Z50.\nS500 M3\nG99 G81 X10. Y10. Z-10. R2. F100.\n";
    let a = first_alarm("fanuc0m", &format!("{head}G91 G28 Z0.\nM30\n")).unwrap();
    assert_eq!((a.code, a.span.line), ("PS0044", 4));
    assert!(first_alarm("fanuc0m", &format!("{head}G80\nG91 G28 Z0.\nM30\n")).is_none());
    assert!(first_alarm("fanuc0m", &format!("{head}G80 G91 G28 Z0.\nM30\n")).is_none());
    assert!(first_alarm("fanuc0m", &format!("{head}G00 G91 G28 Z0.\nM30\n")).is_none(), "a group 01 code cancels the cycle");
    // G30 in a cycle is 0044 too; outside one it runs, as does G27 (not simulated yet) give
    // 0044 in a cycle.
    assert_eq!(first_alarm("fanuc0m", &format!("{head}G30 Z0.\nM30\n")).unwrap().code, "PS0044");
    assert!(first_alarm("fanuc0m", "G30 Z0.\nM30\n").is_none());
    assert_eq!(first_alarm("fanuc0m", &format!("{head}G27 Z0.\nM30\n")).unwrap().code, "PS0044");
    assert_eq!(first_alarm("fanuc0m", &format!("{head}G29 Z0.\nM30\n")).unwrap().code, "PS0044");
}

/// A code the controller has but ncsight does not simulate is "not simulated yet" (NCS-E38),
/// never "no such G code"; a code the controller lacks is IMPROPER G-CODE.
#[test]
fn codes_of_the_manual_are_not_simulated_yet_not_unknown() {
    for (machine, block) in [("yasnac-lx3", "G76 X10. Z-10.")] {
        let a = first_alarm(machine, &format!("{block}\nM30\n")).unwrap_or_else(|| panic!("{machine} {block}: no alarm"));
        assert_eq!(a.code, "NCS-E38", "{machine} {block}: {a:?}");
        assert!(a.message.contains("not simulated"), "{}", a.message);
    }
    assert_eq!(first_alarm("fanuc0m", "G71 X10.\nM30\n").unwrap().code, "PS0010");
}

/// Custom macro statements are read as statements, never as a misleading alarm about their
/// first letter ("address I has no value", "letter O where a zero was meant"): each gives what
/// it means (a condition that does not hold passes, a GOTO to nowhere is FANUC alarm 128).
#[test]
fn macro_statements_are_read_as_statements() {
    for (block, expected) in [
        ("IF [#1 GT 10] GOTO 20", None),
        ("WHILE [#2 LT 5] DO 1\n#2 = #2 + 1\nEND 1", None),
        ("END 1", Some("PS0124")),
        ("GOTO 4", Some("PS0128")),
        ("/GOTO4", Some("PS0128")),
        // #100 is vacant: EQ tells vacant from 0, so the condition does not hold.
        ("N10 IF[#100EQ0]GOTO99", None),
        ("N10 #100 = 0\nIF[#100EQ0]GOTO99", Some("PS0128")),
        ("#100 = 5", None),
        ("G0 X#1", None),
        ("DO1", Some("NCS-E38")),
    ] {
        let a = first_alarm("fanuc0m", &format!("{block}\nM30\n"));
        assert_eq!(a.as_ref().map(|a| a.code), expected, "{block}: {a:?}");
        assert!(a.as_ref().and_then(|a| a.hint.as_deref()).is_none_or(|h| !h.contains("letter O")), "{block}: {a:?}");
    }
    // Inside a block two letters side by side are a typing mistake, not a macro statement.
    let a = first_alarm("fanuc0m", "G41 DO1 X10.\nM30\n").unwrap();
    assert!(a.hint.as_deref().is_some_and(|h| h.contains("letter O")), "{a:?}");
}

/// The G71 monotonic check has a tolerance of one least input increment: a rounded corner
/// `G03 X.875 Z-.036 R.036` whose arc rises 0.0007 mm past its end point is not a pocket; a
/// real step back of 0.01 mm still is PS0064.
#[test]
fn g71_contour_check_has_a_tolerance() {
    let prog = |start: &str, back: &str| {
        format!(
            "G20 G99 G97 S1000 M03\nG0 X1.0 Z0.1\nG71 U0.02 R0.01\nG71 P10 Q20 U0.01 W0.005 F0.008\nN10 G0 X{start}\nG1 Z0 F0.004\nG03 X.875 Z-.036 R.036\nG1 Z-.5\n{back}N20 G1 X1.0\nG70 P10 Q20\nG0 X2. Z1.\nM30\n"
        )
    };
    // Start X.823: the arc's centre lies between its ends, its highest point 0.0007 mm above X.875.
    assert!(first_alarm("fanuc0t", &prog(".823", "")).is_none());
    let a = first_alarm("fanuc0t", &prog(".823", "G1 X.8742 Z-.6\nG1 Z-.7\n")).unwrap();
    assert_eq!(a.code, "PS0064");
}

/// A G73 (or G71) contour whose first block is a G00 to where the tool already stands: the
/// help text asks only for a G00 or G01 code in that block (note 1), so it runs; a first block
/// with no G00/G01 move words at all, or a G71 first block without X, still alarms.
#[test]
fn a_contour_may_start_with_a_move_of_no_length() {
    let g73 = "G99 G97 S800 M03\nG0 X42. Z2.\nG73 U3. W0. R3\nG73 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X42. Z2.\nG1 X20. Z0.\nZ-20.\nN20 X42. Z-25.\nG70 P10 Q20\nG0 X100. Z100.\nM30\n";
    for machine in ["gsk980tdi", "fanuc0t"] {
        let (r, d) = common::run_plain(machine, &[], g73);
        assert!(d.iter().all(|d| !d.is_alarm()), "{machine}: {d:?}");
        assert!(r.iter().filter(|r| matches!(r.op, Op::Feed { .. })).count() > 6);
    }
    let g71 = "G99 G97 S800 M03\nG0 X42. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 Z2.\nG1 X20. Z0.\nZ-20.\nN20 X42. Z-25.\nM30\n";
    assert_eq!(first_alarm("gsk980tdi", g71).unwrap().code, "NCS-E55");
}

/// Messages show computed numbers rounded to the display increment, never a raw float such as
/// `F0.11683999999999999 mm/rev` (F0.0046 inch per revolution is 0.11684 mm).
#[test]
fn messages_round_computed_numbers() {
    let a = first_alarm("fanuc0t", "G20 G99 G0 X1.0 Z0.1\nM05\nG01 Z-1.0 F0.0046\nM30\n").unwrap();
    assert!(a.message.contains("F0.1168 mm/rev"), "{}", a.message);
    assert_eq!(ncsight::alarm::shown(-0.00001, 3), "0");
    assert_eq!(ncsight::alarm::shown(954.929658, 1), "954.9");
    assert_eq!(ncsight::alarm::shown(2.0, 4), "2");
}

/// `:0100` is a programme number in ISO code (FANUC: the colon is the O address of ISO tape).
#[test]
fn a_colon_is_the_iso_programme_number() {
    let line = ncsight::read::Reader::new(ncsight::alarm::AlarmStyle::Fanuc).read_line(1, b":0100 (ISO)");
    assert_eq!(line.blocks[0].as_ref().unwrap().program, Some(100));
    assert!(first_alarm("fanuc0m", ":0100\nG0 X10.\nM30\n").is_none());
}

/// An alarm in a contour block that G73 and G70 both read is reported once by `check`.
#[test]
fn a_contour_alarm_is_reported_once() {
    let text = "G99 G97 S800 M03\nG0 X42. Z2.\nG73 U3. W0. R3\nG73 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X20. Z2.\nG1 Z-20. K5\nN20 X42. Z-25.\nG70 P10 Q20\nG0 X100. Z100.\nM30\n";
    let params = common::params("gsk980tdi", &[]);
    let events = ncsight::run_text(params, ncsight::Switches::default(), ncsight::Mode::Check, text.as_bytes());
    let alarms: Vec<_> = events.iter().filter_map(|e| if let ncsight::Event::Diagnostic(d) = e { d.is_alarm().then_some(d) } else { None }).collect();
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    assert_eq!(alarms[0].span.line, 6);
}

/// Silent where a student needs a word: F0.2 under G98 on a lathe (a 22 mm cut in 1 h 50 min),
/// a G84 whose F/S makes a 0.01 mm pitch.
#[test]
fn implausible_values_are_warned_with_their_numbers() {
    let (_, d) = common::run_plain("gsk980tdi", &[], "G98 M3 S500\nG0 X20. Z2.\nG1 Z-20. F0.2\nZ-40.\nM30\n");
    let w: Vec<_> = d.iter().filter(|d| d.code == "NCS-W25").collect();
    assert_eq!(w.len(), 1, "once per F value: {d:?}");
    assert!(w[0].message.contains("22 mm") && w[0].message.contains("1 h 50 min") && w[0].message.contains("G99"), "{}", w[0].message);
    let (_, d) = common::run_plain("fanuc0m", &[], "G21 G17 G90 G0 X0. Y0. Z50.\nS500 M3\nG84 X10. Y10. Z-10. R2. F5.\nG80\nM30\n");
    assert!(d.iter().any(|d| d.code == "NCS-W25" && d.message.contains("0.01 mm")), "{d:?}");
    let (_, d) = common::run_plain("fanuc0m", &[], "G21 G17 G90 G0 X0. Y0. Z50.\nS500 M3\nG84 X10. Y10. Z-10. R2. F625.\nG80\nM30\n");
    assert!(!d.iter().any(|d| d.code == "NCS-W25"), "{d:?}");
}

/// Smaller ones: the coordinate range is 99999.999 mm under G21 (9999.9999 inch under G20); S
/// above the maximum warns; an F below the least increment is FEED ZERO; brackets nest at most
/// 32 deep, the word's own counted.
#[test]
fn smaller_range_checks() {
    assert_eq!(first_alarm("gsk980tdi", "G21 G0 Z100000.\nM30\n").unwrap().code, "NCS-E33");
    assert!(first_alarm("gsk980tdi", "G21 G0 Z99999.\nM30\n").is_none());
    assert_eq!(first_alarm("gsk980tdi", "G20 G0 Z10000.\nM30\n").unwrap().code, "NCS-E33");
    let (_, d) = common::run_plain("gsk980tdi", &[], "G97 S20000 M03\nM30\n");
    assert!(d.iter().any(|d| d.code == "NCS-W26"), "{d:?}");
    let (_, d) = common::run_plain("gsk980tdi", &[], "G96 S20000 M03\nM30\n");
    assert!(!d.iter().any(|d| d.code == "NCS-W26"), "G96 clamps by G50: {d:?}");
    assert_eq!(first_alarm("gsk980tdi", "G99 M3 S500\nG0 X20. Z2.\nG1 Z-20. F0.0000001\nM30\n").unwrap().code, "NCS-E11");
    let nest = |n: usize| format!("G0 X{}1{}\nM30\n", "[".repeat(n), "]".repeat(n));
    assert!(first_alarm("gsk980tdi", &nest(32)).is_none());
    assert_eq!(first_alarm("gsk980tdi", &nest(33)).unwrap().code, "NCS-E32");
}

/// NaN and infinity in the setup file are refused, as every out-of-range value.
#[test]
fn setup_values_are_validated() {
    use ncsight::stock::Setup;
    assert!(Setup::from_toml("[stock]\ndiameter_mm = 60.0\nlength_mm = 80.0\n").is_ok());
    Setup::from_toml("[[tool]]\nnumber = 1\nkind = \"thread\"\ntip_radius_mm = 0.2\n").unwrap();
    for bad in [
        "[stock]\ndiameter_mm = nan\nlength_mm = 80.0\n",
        "[stock]\ndiameter_mm = 60.0\nlength_mm = inf\n",
        "[stock]\ndiameter_mm = 60.0\nlength_mm = 80.0\nfront_z_mm = nan\n",
        "[[tool]]\nnumber = 1\nkind = \"thread\"\ntip_radius_mm = nan\n",
        "[[tool]]\nnumber = 1\nkind = \"thread\"\nincluded_angle_deg = inf\n",
        "[[tool]]\nnumber = 1\nkind = \"thread\"\npoint_angle_deg = nan\n",
        "[[tool]]\nnumber = 1\nkind = \"thread\"\ndiameter_mm = -1.0\n",
    ] {
        assert!(Setup::from_toml(bad).is_err(), "{bad}");
    }
}

/// A G73 whose passes over the contour would make more than the per-block limit alarms at once
/// (NCS-E40), never drops moves in silence; a block-deleted ns block is no ns block.
#[test]
fn roughing_past_the_limit_alarms() {
    let mut prog = String::from("G99 G97 S800 M03\nG0 X50. Z2.\nG73 U5. W0. R9999\nG73 P10 Q30 U0.2 W0.1 F0.2\nN10 G0 X20.\n");
    for k in 1..=10 {
        prog.push_str(&format!("G1 X{}. Z-{}.\n", 20 + k, 2 * k));
    }
    prog.push_str("N30 X50.\nM30\n");
    assert_eq!(first_alarm("gsk980tdi", &prog).unwrap().code, "NCS-E40");
    let switches = ncsight::Switches { block_delete: true, ..Default::default() };
    let g73 = "G99 G97 S800 M03\nG0 X42. Z2.\nG73 U3. W0. R3\nG73 P10 Q20 U0.4 W0.1 F0.2\n/N10 G0 X42. Z2.\nG1 X20. Z0.\nZ-20.\nN20 X42. Z-25.\nM30\n";
    let (_, d) = common::run_with("gsk980tdi", &[], switches, ncsight::Options::default(), g73);
    assert!(d.iter().any(|d| d.is_alarm()), "{d:?}");
}

/// The DOS end-of-file mark (0x1A) ends the text wherever it stands: inside a comment, after a
/// tape mark, early on a line too long to read.
#[test]
fn the_end_of_file_mark_is_seen_everywhere() {
    let eof = |text: &[u8]| {
        let params = common::params("gsk980tdi", &[]);
        let events = ncsight::run_text(params, ncsight::Switches::default(), ncsight::Mode::Check, text);
        let diags: Vec<_> = events.iter().filter_map(|e| if let ncsight::Event::Diagnostic(d) = e { Some(d.clone()) } else { None }).collect();
        diags
    };
    let d = eof(b"G0 X10 (A\x1A) G0 X#1\n");
    assert!(d.iter().any(|d| d.code == "NCS-W06") && !d.iter().any(|d| d.is_alarm()), "{d:?}");
    let d = eof(b"M30 (END\x1A)\nG0 X#1\n");
    assert!(d.iter().any(|d| d.code == "NCS-W06") && !d.iter().any(|d| d.span.line == 2), "{d:?}");
    let d = eof(b"G0 X10\nM30\n%\x1A\nG0 X#1\n");
    assert!(d.iter().any(|d| d.code == "NCS-W06") && !d.iter().any(|d| d.span.line == 4), "{d:?}");
    let mut long = b"G0 X10\x1A".to_vec();
    long.extend(std::iter::repeat_n(b' ', 5000));
    long.extend(b"\nG0 X#1\n");
    let d = eof(&long);
    assert!(d.iter().any(|d| d.code == "NCS-W06") && !d.iter().any(|d| d.is_alarm()), "{d:?}");
}

/// The repair switch is named as the manual names it.
#[test]
fn repair_off_names_the_parameter_as_the_manual_does() {
    let (_, d) = common::run_plain("gsk980tdi", &[], "G97 S300 M03\nG0 X30 Z5\nG92 X28 Z-20 F1.5 P1\nM30\n");
    assert!(d.iter().any(|d| d.message.contains("parameter No.174 bit 4 = 0")), "{d:?}");
}
