//! What holds across the golden traces (tests/golden/<case>/expected.jsonl; each case is a test
//! of its own in tests/cases.rs, with the bad programmes): the JSONL follows the interface.

mod common;

/// `--format jsonl` follows docs/reference/interface.md field for field on every golden trace.
#[test]
fn jsonl_follows_the_interface() {
    let dir = common::root().join("tests/golden");
    let mut seen_kinds = std::collections::BTreeSet::new();
    for case in std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()) {
        let text = std::fs::read_to_string(case.join("expected.jsonl")).unwrap();
        // A comment line of the input is a comment, never an alarm's place (a stray ')' in the
        // hand-checked notes would make the rest of the line code).
        let input = std::fs::read_to_string(case.join("input.nc")).unwrap_or_default();
        let lines: Vec<&str> = input.lines().collect();
        for l in text.lines().filter(|l| l.contains("\"kind\":\"alarm\"")) {
            let v: serde_json::Value = serde_json::from_str(l).unwrap();
            let n = v["line"].as_u64().unwrap_or(0) as usize;
            let at = lines.get(n.wrapping_sub(1)).copied().unwrap_or("");
            assert!(!at.trim_start().starts_with('('), "{}: an alarm on the comment line {n}: {l}", case.display());
        }
        let args = std::fs::read_to_string(case.join("args")).unwrap_or_default();
        let machine = args.split_whitespace().skip_while(|a| *a != "--machine").nth(1).unwrap_or("gsk980tdi");
        let lathe = ncsight::profile::by_name(machine).is_none_or(|p| p.is_lathe());
        // A lathe whose setup adds a Y axis shows Y from the first record that moves it on.
        let setup = std::fs::read_to_string(case.join("setup.toml")).unwrap_or_default();
        let assumed_y = ncsight::profile::by_name(machine).is_some_and(|p| p.frame.assumed_axes.contains('Y'));
        let lathe_y = lathe && (assumed_y || setup.lines().any(|l| l.trim_start().starts_with("axes") && l.contains("\"Y\"")));
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
