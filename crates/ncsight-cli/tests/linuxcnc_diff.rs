//! Differential test against LinuxCNC's interpreter: every programme in tests/linuxcnc/cases is
//! in the G-code subset both read alike (G00-G03 in G17/G18/G19, G90/G91, decimal points
//! everywhere). Its `.expected` trace is what `rs274 -g` printed (tests/linuxcnc/refresh
//! regenerates and, in CI, re-verifies them); ncsight's `--format canon` must give the same
//! motion calls with the same numbers (4 decimals, so within 0.0002).
//!
//! Drilling cases come in two spellings: `drill_*.ngc` for rs274 (L repeats, P in seconds) and
//! `drill_*.nc` for ncsight (FANUC: K repeats, P in ms). LinuxCNC's fixed peck clearance of
//! 0.254 mm is matched by parameters 531 and 532. Moves of zero length (rs274 prints some, ncsight
//! leaves them out) are dropped on both sides.

mod common;

#[test]
fn canon_matches_rs274_traces() {
    let dir = common::root().join("tests/linuxcnc/cases");
    let mut cases: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    cases.retain(|p| p.extension().is_some_and(|e| e == "ngc"));
    cases.sort();
    assert!(cases.len() >= 300, "expected the committed LinuxCNC cases in {}", dir.display());
    assert!(cases.iter().filter(|c| c.with_extension("nc").exists()).count() >= 200, "drilling cases missing");
    let mut compared = 0;
    for ngc in &cases {
        let expected = std::fs::read_to_string(ngc.with_extension("expected")).unwrap();
        let fanuc = ngc.with_extension("nc");
        let input = if fanuc.exists() { fanuc } else { ngc.clone() };
        let (code, out, err) =
            common::ncsight(&["run", input.to_str().unwrap(), "--machine", "fanuc0m", "--format", "canon", "--param", "531=254", "--param", "532=254"]);
        assert_eq!(code, 0, "{}: {err}", ngc.display());
        let ours = common::motion_calls(&out);
        let theirs = common::motion_calls(&expected);
        assert_eq!(ours.len(), theirs.len(), "{}: {} calls vs rs274's {}\n{out}", ngc.display(), ours.len(), theirs.len());
        compared += common::same_calls(&ngc.display().to_string(), &ours, &theirs);
    }
    assert!(compared > 5000, "only {compared} calls compared");
}
