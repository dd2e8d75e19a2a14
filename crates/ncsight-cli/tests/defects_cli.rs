//! Defects found by outside checks (issue 15) at the command line: each test failed before its fix.

mod common;

use std::io::Write;

fn tmp(name: &str, bytes: &[u8]) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("ncsight-defects-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

/// GBK comments (GSK controls, Chinese Windows editors) show as written, not as `????`.
#[test]
fn gbk_comments_show_as_written() {
    let p = tmp("gbk.nc", b"G0 X150 Z50 T0101 (\xC2\xDD\xCE\xC6\xB5\xB6)\nG1 X10 Q5 F0.1 (\xC2\xDD\xCE\xC6\xB5\xB6)\nM30\n");
    let (code, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "gsk980tdi"]);
    assert_eq!(code, 1);
    assert!(out.contains("(螺纹刀)"), "{out}");
    assert!(!out.contains('?'), "{out}");
}

/// One rendering per diagnostic by default (the message once), one line each with --format short.
#[test]
fn each_diagnostic_is_printed_once() {
    let p = tmp("once.nc", b"G0 X10.\nG1 X20. Q5 F100.\nM30\n");
    let (_, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "fanuc0m"]);
    assert_eq!(out.matches("does not take address Q").count(), 1, "{out}");
    assert!(out.lines().count() <= 5, "{out}");
    let (_, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "fanuc0m", "--format", "short"]);
    assert_eq!(out.lines().count(), 2, "{out}");
}

/// `check --format jsonl` as docs/reference/interface.md specifies: file, line, col, severity, code, message, hint.
#[test]
fn check_jsonl_fields() {
    let p = tmp("jsonl.nc", b"GO X10.\nG0 X10\nM30\n");
    let (code, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "fanuc0m", "--format", "jsonl"]);
    assert_eq!(code, 1);
    let lines: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 2, "{out}");
    let a = &lines[0];
    assert_eq!(a["file"], p.to_str().unwrap());
    assert_eq!((a["line"].as_u64(), a["col"].as_u64(), a["severity"].as_str()), (Some(1), Some(1), Some("alarm")));
    assert!(a["code"].is_string() && a["message"].is_string() && a["hint"].is_string(), "{a}");
    assert_eq!(lines[1]["severity"], "warning");
    assert!(lines[1].get("hint").is_none());
}

/// `check a.nc missing.nc dir b.nc` reports each unreadable one by its path and checks the rest.
#[test]
fn check_goes_on_past_unreadable_files() {
    let a = tmp("a.nc", b"G0 X10.\nM30\n");
    let b = tmp("b.nc", b"G0 X10.\nG1 X20. Q5 F100.\nM30\n");
    let dir = a.parent().unwrap().to_str().unwrap().to_string();
    let (code, out, err) = common::ncsight(&["check", a.to_str().unwrap(), "/nonexistent/x.nc", &dir, b.to_str().unwrap(), "--machine", "fanuc0m"]);
    assert_eq!(code, 2, "an unreadable file: the check is incomplete");
    assert!(err.contains("/nonexistent/x.nc") && err.contains(&format!("cannot read {dir}: it is a directory")), "{err}");
    assert!(out.contains("a.nc: 0 alarm(s)") && out.contains("b.nc: 1 alarm(s)"), "{out}");
}

/// A writer whose reader goes away after a few bytes (`| head -1`).
struct Closing(usize);
impl Write for Closing {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if self.0 == 0 {
            return Err(std::io::ErrorKind::BrokenPipe.into());
        }
        let n = buf.len().min(self.0);
        self.0 -= n;
        Ok(n)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// `check big.nc | head -1` still exits 1 when the programme has alarms. (`run | head -1` stops at
/// the first failed write instead, exit 0: outside_checks_cli.rs, a_cut_output_pipe_stops_run_and_expand.)
#[test]
fn output_cut_short_keeps_the_status() {
    let mut text = String::from("G0 X10.\n");
    for _ in 0..2000 {
        text.push_str("G0 X10\n");
    }
    text.push_str("G1 X20. Q5 F100.\nM30\n");
    let p = tmp("big.nc", text.as_bytes());
    for args in [vec!["check", p.to_str().unwrap(), "--machine", "fanuc0m"]] {
        let mut full = vec!["ncsight".to_string()];
        full.extend(args.iter().map(|s| s.to_string()));
        let mut err = Vec::new();
        let code = ncsight_cli::main_with(full.into_iter().map(Into::into), &mut Closing(40), &mut err);
        assert_eq!(code, 1, "{args:?}");
    }
}

/// A full-width `；` typed with a Chinese input method is named, with its ASCII twin; a NUL byte
/// is never printed raw; the DOS end-of-file mark is seen on a line that alarms.
#[test]
fn characters_are_named() {
    let p = tmp("fw.nc", "G0 X10；\nM30\n".as_bytes());
    let (_, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "gsk980tdi"]);
    assert!(out.contains("character '；' (full width)") && out.contains("ASCII ';'"), "{out}");
    let p = tmp("nul.nc", b"G0 X10 \x00\nM30\n");
    let (_, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "gsk980tdi"]);
    assert!(!out.contains('\0') && out.contains("byte 0x00"), "{out:?}");
    let p = tmp("eof.nc", b"G0 X10.\nG1 X20. Q5 F100.\x1a\nG0 X#1\n");
    let (_, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "fanuc0m", "--format", "short"]);
    assert!(out.contains("NCS-W06"), "{out}");
    assert!(!out.contains(":3:"), "line 3 lies after the end-of-file mark: {out}");
}

/// Thirty identical NCS-W02 warnings: the first few, then one summary with the hint.
#[test]
fn many_increment_warnings_are_summed_up() {
    let mut text = String::new();
    for k in 1..=30 {
        text.push_str(&format!("G0 X{k}0\n"));
    }
    text.push_str("M30\n");
    let p = tmp("w02.nc", text.as_bytes());
    let (_, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "fanuc0m"]);
    assert_eq!(out.matches("warning[NCS-W02]").count(), 4, "{out}");
    assert!(out.contains("27 more lengths") && out.contains("--param 3401.0=1"), "{out}");
}

/// The GSK988T is a lathe: no `Y0` in its records.
#[test]
fn gsk988t_records_have_no_y() {
    let p = common::root().join("examples/gsk988t_o0009.nc");
    let (_, out, _) = common::ncsight(&["run", p.to_str().unwrap(), "--machine", "gsk988t", "--format", "jsonl"]);
    assert!(!out.contains("\"y\""), "{out}");
    let (_, out, _) = common::ncsight(&["run", p.to_str().unwrap(), "--machine", "gsk988t"]);
    assert!(!out.contains(" Y0"), "{out}");
}

/// `-o` naming the input file is refused (exit 2) and the programme is left as it was, whatever
/// the spelling of the path; likewise `report -o` and `simulate --image`.
#[test]
fn output_is_never_the_input() {
    let src = std::fs::read(common::root().join("examples/gsk980tdi_o0012.nc")).unwrap();
    let p = tmp("o12.nc", &src);
    let dir = p.parent().unwrap().to_str().unwrap().to_string();
    let other_spelling = format!("{dir}/./o12.nc");
    for args in [
        vec!["run", p.to_str().unwrap(), "--machine", "gsk980tdi", "-o", &other_spelling],
        vec!["report", p.to_str().unwrap(), "--machine", "gsk980tdi", "-o", p.to_str().unwrap()],
        vec!["simulate", p.to_str().unwrap(), "--machine", "gsk980tdi", "--stock", "60x80", "--image", p.to_str().unwrap()],
    ] {
        let (code, _, err) = common::ncsight(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains("a file this run reads: refusing to overwrite it"), "{err}");
        assert_eq!(std::fs::read(&p).unwrap(), src, "{args:?} changed the programme");
    }
    // A run that fails before it has anything to write leaves an existing output as it was.
    let out = tmp("keep.txt", b"keep me");
    let (code, _, _) = common::ncsight(&["run", "/nonexistent/x.nc", "--machine", "gsk980tdi", "-o", out.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert_eq!(std::fs::read(&out).unwrap(), b"keep me");
}

/// Every number that goes into the repair blocks is range-checked: no `JNaN`, `Kinf` or a
/// 300-digit J in blocks meant to be typed into a controller.
#[test]
fn repair_refuses_numbers_the_control_cannot_take() {
    let base = [
        "repair",
        "--machine",
        "gsk988t",
        "--param",
        "8135.7=1",
        "--start",
        "60,5",
        "--end",
        "60,-30",
        "--lead",
        "2",
        "--rpm",
        "500",
        "--measured",
        "58,-10,90",
    ];
    for extra in [["--j", "nan"], ["--k", "inf"], ["--j", "1e300"], ["--k", "-1"]] {
        let args: Vec<&str> = base.iter().copied().chain(extra).collect();
        let (code, out, err) = common::ncsight(&args);
        assert_eq!(code, 2, "{extra:?}: {out}{err}");
        assert!(out.is_empty(), "{out}");
    }
    let (code, out, _) = common::ncsight(&base);
    assert_eq!(code, 0);
    assert!(out.starts_with("G0 X60. Z5."), "{out}");
}

/// Parameters: an overflowing value is "not finite", a fraction of a whole-number parameter is
/// refused; `--expect pitch=0` is refused; a line of more than 64 kB says "at least".
#[test]
fn usage_errors_name_the_rule() {
    let prog = common::root().join("examples/gsk980tdi_o0012.nc");
    let prog = prog.to_str().unwrap();
    let (code, _, err) = common::ncsight(&["run", prog, "--machine", "gsk980tdi", "--param", "19=1e309"]);
    assert!(code == 2 && err.contains("not a finite number"), "{err}");
    let (code, _, err) = common::ncsight(&["run", prog, "--machine", "gsk980tdi", "--param", "19=0.5"]);
    assert!(code == 2 && err.contains("whole number"), "{err}");
    let (code, _, err) = common::ncsight(&["simulate", prog, "--machine", "gsk980tdi", "--expect", "major=60,minor=56,pitch=0"]);
    assert!(code == 2 && err.contains("pitch"), "{err}");
    let mut long = b"G0 X1".to_vec();
    long.extend(std::iter::repeat_n(b' ', 200_000));
    long.extend(b"\nM30\n");
    let p = tmp("long.nc", &long);
    let (_, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "gsk980tdi", "--format", "short"]);
    assert!(out.contains("at least 65536 bytes"), "{out}");
}

/// `report`'s page holds the programme, not its motions: 60,000 holes from six blocks make a page
/// of the engine's size; `simulate` refuses work past its documented limit at once instead of
/// running for hours.
#[test]
fn report_and_simulate_are_bounded() {
    let mut text = String::from("G21 G17 G90 G0 X0. Y0. Z10.\nS500 M3\n");
    for _ in 0..6 {
        text.push_str("G91 G81 X1. Y0. Z-5. R-8. F100. K9999\n");
    }
    text.push_str("G80\nM30\n");
    let p = tmp("k.nc", text.as_bytes());
    let html = p.with_extension("html");
    let (code, _, err) = common::ncsight(&["report", p.to_str().unwrap(), "--machine", "fanuc0m", "-o", html.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(page.contains("K9999"));
    assert!(page.len() < 3_000_000, "{} bytes", page.len());
    let g76 = tmp("g76long.nc", b"G97 S300 M03\nG0 X70 Z5\nG76 P010060 Q1 R0.01\nG76 X60 Z-2500 P5000 Q1 F6\nM30\n");
    let t = std::time::Instant::now();
    let (code, _, err) = common::ncsight(&["simulate", g76.to_str().unwrap(), "--machine", "gsk980tdi", "--stock", "70x2600"]);
    assert_eq!(code, 2);
    assert!(err.contains("G cell updates"), "{err}");
    assert!(t.elapsed().as_secs() < 30);
}

/// A G71/G70 part with a 2 mm chamfer before a G76 M24x2 thread measures the thread, not the
/// chamfer; without a setup the turning tool is a turning insert and the drill at X0 a drill
/// (no false crash), and the output says which tools were assumed.
#[test]
fn the_stock_simulation_measures_the_thread_only() {
    let prog = "O0024\nT0101\nG99 G97 S800 M03\nG0 X32. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X20.\nG1 Z0. F0.1\nX24. Z-2.\nZ-30.\nX28.\nN20 Z-40.\nG70 P10 Q20\nG0 X100. Z100.\nT0202\nG0 X0. Z5.\nG1 Z-10. F0.1\nG0 Z5.\nG0 X100. Z100.\nT0303\nG97 S500 M03\nG0 X30. Z5.\nG76 P021060 Q50 R0.05\nG76 X21.55 Z-26. P1227 Q400 F2.\nG0 X100. Z100.\nM30\n";
    let p = tmp("m24.nc", prog.as_bytes());
    let (code, out, err) =
        common::ncsight(&["simulate", p.to_str().unwrap(), "--machine", "gsk980tdi", "--stock", "32x60", "--expect", "M24x2", "--format", "json"]);
    assert_eq!(code, 0, "{err}{out}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!((v["minor_diameter_mm"].as_f64().unwrap() - 21.55).abs() <= 0.02, "{out}");
    assert!((v["pitch_mm"].as_f64().unwrap() - 2.0).abs() <= 0.01, "{out}");
    assert_eq!(v["findings"].as_array().unwrap().len(), 0, "{out}");
    let tools = v["assumed_tools"].to_string();
    assert!(tools.contains("T1: turning") && tools.contains("T2: drill") && tools.contains("T3: threading"), "{tools}");
}

/// Findings carry X, Z, the spindle angle where relevant, and the time; a crash after a thread
/// that ends inside the stock says so; findings have their own exit status (3).
#[test]
fn findings_are_placed_and_change_the_exit_status() {
    // G76 without a pull-out (r = 00) ends inside the bar: the rapid out of it cuts the stock.
    let prog = "G97 S500 M03\nG0 X30. Z5.\nG76 P020060 Q50 R0.05\nG76 X21.55 Z-26. P1227 Q400 F2.\nG0 X100. Z100.\nM30\n";
    let p = tmp("crash.nc", prog.as_bytes());
    let (code, out, _) = common::ncsight(&["simulate", p.to_str().unwrap(), "--machine", "gsk980tdi", "--stock", "24x60", "--format", "json"]);
    assert_eq!(code, 3, "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let f = &v["findings"][0];
    assert_eq!(f["kind"], "crash");
    assert!(f["x"].is_number() && f["z"].is_number() && f["t"].is_number(), "{f}");
    assert!(f["message"].as_str().unwrap().contains("ends inside the stock"), "{f}");
}

/// `simulate --image` on a machining centre refuses clearly instead of writing nothing.
#[test]
fn simulate_image_on_a_mill_refuses() {
    let p = tmp("mill.nc", b"G21 G17 G90 G0 X0. Y0. Z50.\nS500 M3\nG81 X10. Y10. Z-10. R2. F100.\nG80\nM30\n");
    let png = p.with_extension("png");
    let (code, _, err) = common::ncsight(&["simulate", p.to_str().unwrap(), "--machine", "fanuc0m", "--image", png.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("machining centre"), "{err}");
}

/// Arc threads (G32.2/G32.3 in G18) are cut; a face thread is a `not_simulated` finding shown
/// first, never silence.
#[test]
fn arc_threads_are_cut_and_face_threads_are_said() {
    let ex = common::root().join("examples/gsk988t_arc_thread.nc");
    let (_, out, err) = common::ncsight(&["simulate", ex.to_str().unwrap(), "--machine", "gsk988t", "--stock", "40x60", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}{err}"));
    assert!(v["depth_mm"].as_f64().is_some_and(|d| d > 0.1), "the arc thread cuts a groove: {out}");
    // Without a stock, the stock is inferred from the arc thread too.
    let (_, _, err) = common::ncsight(&["simulate", ex.to_str().unwrap(), "--machine", "gsk988t"]);
    assert!(!err.contains("no stock"), "{err}");
    let face = tmp("face.nc", b"G97 S300 M03\nG0 X60. Z1.\nG32 X20. F2.\nG0 Z5.\nM30\n");
    let (_, out, _) = common::ncsight(&["simulate", face.to_str().unwrap(), "--machine", "gsk980tdi", "--stock", "60x40"]);
    assert!(out.starts_with("finding not_simulated"), "{out}");
}

/// Every example runs to the end on its machine (the name before the first `_`), without alarm.
#[test]
fn every_example_runs() {
    let dir = common::root().join("examples");
    let mut n = 0;
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_str().unwrap().to_string();
        let machine = match name.split('_').next().unwrap() {
            "yasnac" => "yasnac-lx3",
            m => m,
        };
        let (code, _, err) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", machine]);
        assert_eq!(code, 0, "{name}: {err}");
        n += 1;
    }
    assert!(n >= 8, "{n} examples");
}

/// Less noise, clearer answers (issue 36): a near-miss machine name is suggested; a machining
/// centre's programme on a lathe profile is said to be one; subprogrammes after M30 are no
/// "blocks after the programme end".
#[test]
fn near_misses_and_the_other_kind_of_machine_are_named() {
    let dir = std::env::temp_dir().join(format!("ncsight-noise-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let lathe = dir.join("lathe.nc");
    std::fs::write(&lathe, "O0001\nG98 G00 X20. Z2.\nM98 P0002\nM30\nO0002\nG00 X30.\nM99\n").unwrap();
    let (code, _, err) = common::ncsight(&["check", lathe.to_str().unwrap(), "--machine", "gsk980td"]);
    assert_eq!(code, 2);
    assert!(err.contains("did you mean gsk980tdi?"), "{err}");
    let (_, _, err) = common::ncsight(&["check", lathe.to_str().unwrap(), "--machine", "fanuc0i"]);
    assert!(err.contains("did you mean fanuc0i-tf or fanuc0i-mf?"), "{err}");
    let (code, out, _) = common::ncsight(&["check", lathe.to_str().unwrap(), "--machine", "gsk980tdi"]);
    assert_eq!(code, 0, "{out}");
    assert!(!out.contains("NCS-W09"), "{out}");
    let mill = dir.join("mill.nc");
    std::fs::write(&mill, "G21 G17 G90\nG00 X10. Y10. Z5.\nG81 Z-5. R2. F100.\nG80\nM30\n").unwrap();
    let (code, out, _) = common::ncsight(&["check", mill.to_str().unwrap(), "--machine", "gsk980tdi"]);
    assert_eq!(code, 1);
    assert!(out.contains("a machining centre programme? choose one of fanuc0m, fanuc0i-mf"), "{out}");
    assert!(out.contains("G81 is a code of the machining centre profiles (fanuc0m, fanuc0i-mf)"), "{out}");
    let _ = std::fs::remove_dir_all(dir);
}

/// G70 with a range no roughing collected, on a profile whose G70 needs the collected contour
/// (the GSK980TDi): the message names the range the G71 did collect (issue 36: the real cause).
#[test]
fn a_g70_range_names_what_the_roughing_collected() {
    let p = tmp(
        "g70_range.nc",
        b"O0001\nG99 G00 X52. Z2. S800 M03\nG71 U1. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X30.\nG01 Z-20. F0.1\nN20 X50.\nN30 Z-30.\nG70 P10 Q30\nM30\n",
    );
    let (code, out, _) = common::ncsight(&["check", p.to_str().unwrap(), "--machine", "gsk980tdi"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("collected the blocks N10 to N20, not N10 to N30") && out.contains("write G70 P10 Q20"), "{out}");
}
