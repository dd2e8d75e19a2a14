//! Golden traces: tests/golden/<case>/ holds `input.nc`, `args` (the machine and parameters,
//! one line) and `expected.jsonl`, the trace `ncsight run --format jsonl` must print. Each case
//! says in its comments what the manual says and how the trace was checked by hand.
//! NCSIGHT_BLESS=1 rewrites the expected files (review the diff before committing).
//!
//! tests/bad/*.nc: programmes whose first line is `(expect CODE line L col C on MACHINE)` (a
//! same-name `.toml` is their setup, a `.args` more arguments);
//! `run` must stop with that alarm at that place, and `check` must report it and exit 1.

mod common;

#[test]
fn golden_traces() {
    let dir = common::root().join("tests/golden");
    let mut cases: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    cases.sort();
    assert!(!cases.is_empty());
    for case in cases {
        let input = case.join("input.nc");
        let args = std::fs::read_to_string(case.join("args")).unwrap_or_default();
        let mut argv = vec!["run", input.to_str().unwrap(), "--format", "jsonl"];
        argv.extend(args.split_whitespace());
        // A case with a machine setup keeps it beside its programme.
        let setup = case.join("setup.toml");
        let setup = setup.to_str().unwrap();
        if case.join("setup.toml").is_file() {
            argv.extend(["--setup", setup]);
        }
        let (code, out, err) = common::ncsight(&argv);
        let expected_code = if out.lines().last().is_some_and(|l| l.contains("\"kind\":\"alarm\"")) { 1 } else { 0 };
        assert_eq!(code, expected_code, "{}: {err}", case.display());
        common::expect_file(&case.join("expected.jsonl"), &out);
    }
}

#[test]
fn bad_programmes_raise_their_alarm() {
    let dir = common::root().join("tests/bad");
    let mut files: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).filter(|p| p.extension().is_some_and(|x| x == "nc")).collect();
    files.sort();
    assert!(files.len() >= 10);
    for f in files {
        let text = std::fs::read(&f).unwrap();
        let first = String::from_utf8_lossy(text.split(|&b| b == b'\n').next().unwrap()).into_owned();
        let spec: Vec<&str> = first.trim().trim_start_matches('(').trim_end_matches(')').split_whitespace().collect();
        assert!(
            spec.len() == 8 && spec[0] == "expect" && spec[2] == "line" && spec[4] == "col" && spec[6] == "on",
            "{}: first line must be (expect CODE line L col C on MACHINE)",
            f.display()
        );
        let (code, line, col, machine) = (spec[1], spec[3], spec[5], spec[7]);
        let path = f.to_str().unwrap();
        let setup_file = f.with_extension("toml");
        let mut setup_arg: Vec<&str> = if setup_file.is_file() { vec!["--setup", setup_file.to_str().unwrap()] } else { vec![] };
        // More arguments (a setting the programme's machine has) in `<name>.args`.
        let extra = std::fs::read_to_string(f.with_extension("args")).unwrap_or_default();
        setup_arg.extend(extra.split_whitespace());
        let with_setup = |args: &[&str]| -> Vec<String> { args.iter().chain(setup_arg.iter()).map(|s| s.to_string()).collect() };
        let run_args = with_setup(&["run", path, "--machine", machine, "--format", "jsonl"]);
        let (status, out, err) = common::ncsight(&run_args.iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(status, 1, "{}: run must stop on an alarm\n{out}{err}", f.display());
        let last = out.lines().last().unwrap_or_default();
        let v: serde_json::Value = serde_json::from_str(last).unwrap();
        assert_eq!(v["kind"], "alarm", "{}", f.display());
        assert_eq!(v["code"], code, "{}: {last}", f.display());
        assert_eq!(v["line"].to_string(), line, "{}: {last}", f.display());
        assert_eq!(v["col"].to_string(), col, "{}: {last}", f.display());
        assert!(!v["message"].as_str().unwrap().is_empty());
        let check_args = with_setup(&["check", path, "--machine", machine]);
        let (status, out, _) = common::ncsight(&check_args.iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(status, 1, "{}", f.display());
        assert!(out.contains(&format!(":{line}:{col}: alarm[{code}]")), "{}: check output\n{out}", f.display());
    }
}

/// `--format jsonl` follows docs/reference/interface.md field for field on every golden trace.
#[test]
fn jsonl_follows_the_interface() {
    let dir = common::root().join("tests/golden");
    let mut seen_kinds = std::collections::BTreeSet::new();
    for case in std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()) {
        let text = std::fs::read_to_string(case.join("expected.jsonl")).unwrap();
        let args = std::fs::read_to_string(case.join("args")).unwrap_or_default();
        let lathe = !args.contains("fanuc0m");
        // A lathe whose setup adds a Y axis shows Y from the first record that moves it on.
        let setup = std::fs::read_to_string(case.join("setup.toml")).unwrap_or_default();
        let lathe_y = lathe && setup.lines().any(|l| l.trim_start().starts_with("axes") && l.contains("\"Y\""));
        let mut y_seen = false;
        let mut last_t = 0.0;
        for l in text.lines() {
            let v: serde_json::Value = serde_json::from_str(l).unwrap_or_else(|e| panic!("{}: {e}: {l}", case.display()));
            assert!(v["line"].as_u64().is_some_and(|n| n >= 1), "{l}");
            let kind = v["kind"].as_str().unwrap_or_else(|| panic!("no kind: {l}"));
            seen_kinds.insert(kind.to_string());
            match kind {
                "rapid" | "feed" | "arc" | "thread" | "thread_arc" => {
                    assert!(v["x"].is_number() && v["z"].is_number(), "{l}");
                    // A lathe has no Y: none is shown unless a programme moves one.
                    if lathe_y {
                        assert!(v["y"].is_number() || !y_seen, "{l}");
                        y_seen |= v["y"].is_number();
                    } else {
                        assert_eq!(v["y"].is_number(), !lathe, "{l}");
                    }
                    let t = v["t"].as_f64().unwrap();
                    assert!(t >= last_t, "time goes backwards: {l}");
                    last_t = t;
                    if kind == "arc" || kind == "thread_arc" {
                        assert!(v["cx"].is_number() && v["cz"].is_number(), "{l}");
                        assert!(v["dir"] == "cw" || v["dir"] == "ccw", "{l}");
                    }
                    if kind == "thread" || kind == "thread_arc" {
                        assert!(v["lead"].is_number() && v["rpm"].is_number(), "{l}");
                        assert!(v["long_axis"] == "x" || v["long_axis"] == "z", "{l}");
                        let a = v["spindle_deg"].as_f64().unwrap();
                        assert!((0.0..360.0).contains(&a), "{l}");
                    }
                }
                "rotary" => {
                    let axis = v["axis"].as_str().unwrap_or_else(|| panic!("no axis: {l}"));
                    assert!(["a", "b", "c"].contains(&axis) && v[axis].is_number(), "{l}");
                    let t = v["t"].as_f64().unwrap();
                    assert!(t >= last_t, "time goes backwards: {l}");
                    last_t = t;
                }
                "alarm" | "warning" => {
                    assert!(v["code"].is_string() && v["message"].is_string(), "{l}");
                    assert!(v["col"].as_u64().is_some_and(|c| c >= 1), "{l}");
                }
                _ => assert!(v["t"].is_number(), "{l}"),
            }
        }
    }
    for k in ["rapid", "feed", "arc", "dwell", "spindle", "end"] {
        assert!(seen_kinds.contains(k), "no golden trace shows a {k} record");
    }
}
