//! The round trip of `ncsight expand` (docs/commands/expand.md), used by the golden programmes'
//! test (expand_cli.rs) and the corpus test (corpus.rs): for LinuxCNC the expansion is read back by
//! LinuxCNC's own interpreter (`rs274 -g`) and must move as `ncsight run --format canon` says the
//! original moves; for grbl every line must hold only what grbl 1.1 accepts, and a thread must
//! alarm.
#![allow(dead_code)]

use super::common;
use std::path::{Path, PathBuf};

/// A programme to expand: its name, file and `ncsight` arguments.
pub type Programme = (String, PathBuf, Vec<String>);

/// What `ncsight run --format canon` prints for the programme.
pub fn canon_of(input: &Path, args: &[String]) -> String {
    let mut run_args: Vec<&str> = vec!["run", input.to_str().unwrap(), "--format", "canon"];
    run_args.extend(args.iter().map(String::as_str));
    common::ncsight(&run_args).1
}

pub fn expand(input: &Path, args: &[String], to: &str) -> (i32, String, String) {
    let mut argv: Vec<&str> = vec!["expand", input.to_str().unwrap(), "--to", to];
    argv.extend(args.iter().map(String::as_str));
    common::ncsight(&argv)
}

/// Whether the run of a programme makes a spindle-synchronised record.
pub fn threads(canon: &str) -> bool {
    canon.contains("START_SPEED_FEED_SYNC")
}

/// rs274 on the path, or why the round trip cannot run. In CI it must (`.ci/run` installs
/// LinuxCNC); elsewhere the comparison is left to CI and said so.
pub fn rs274() -> Option<&'static str> {
    let found = std::process::Command::new("rs274").arg("-h").output().is_ok();
    if !found {
        assert!(std::env::var_os("CI").is_none(), "rs274 (Debian package linuxcnc-uspace) is missing in CI");
        eprintln!("expand_cli: rs274 is not installed here: the LinuxCNC round trip runs in CI only");
        return None;
    }
    Some("rs274")
}

/// An expansion read by `rs274 -g` (with a tool table, if given): its canonical calls without
/// rs274's count and N column, and what it said on standard error. rs274 must accept it.
pub fn read_back(rs274: &str, tools: Option<&Path>, ngc: &Path) -> (String, String) {
    let mut cmd = std::process::Command::new(rs274);
    if let Some(t) = tools {
        cmd.arg("-t").arg(t);
    }
    let out = cmd.arg("-g").arg(ngc).output().unwrap();
    let calls: String =
        String::from_utf8_lossy(&out.stdout).lines().map(|l| l.trim_start().split_once("N..... ").map_or(l, |(_, r)| r)).collect::<Vec<_>>().join("\n");
    let stderr = String::from_utf8_lossy(&out.stderr).trim().to_string();
    assert!(out.status.success(), "{}: rs274 refused the expansion: {stderr}\n{calls}", ngc.display());
    (calls, stderr)
}

/// Every programme expanded for LinuxCNC and read back by rs274 (when installed): (programmes
/// compared, calls compared).
pub fn linuxcnc_round_trip(programmes: &[Programme]) -> (usize, usize) {
    let rs274 = rs274();
    let tmp = std::env::temp_dir().join(format!("ncsight-expand-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    // rs274 changes only to tools its table holds (`T12 M6`): tools 1-200 in their own pockets.
    let tools = tmp.join("tools.tbl");
    std::fs::write(&tools, (1..=200).map(|n| format!("T{n} P{n} ;\n")).collect::<String>()).unwrap();
    let (mut compared, mut files) = (0, 0);
    for (name, input, args) in programmes {
        let canon = canon_of(input, args);
        let (code, text, err) = expand(input, args, "linuxcnc");
        if canon.contains("ARC_FEED") && threads(&canon) && err.contains("NCS-E76") {
            // An arc thread (GSK988T G32.2/G32.3): LinuxCNC cannot do it; the alarm says so.
            assert_eq!(code, 1, "{name}");
            assert!(err.contains("straight only"), "{name}: {err}");
            continue;
        }
        if canon.contains("COMMENT(\"rotary") && err.contains("NCS-E76") {
            // A C, A or B axis turned (or a sub-spindle's B moved): expand writes X, Y, Z only.
            assert_eq!(code, 1, "{name}");
            assert!(err.contains("a move of the axis"), "{name}: {err}");
            continue;
        }
        assert!(!err.contains("NCS-E76"), "{name}: {err}");
        assert!(text.starts_with("(expanded by ncsight from"), "{name}: {text}");
        assert!(
            text.lines().filter(|l| !l.starts_with('(')).all(|l| !l.contains("G76") && !l.contains("G81") && !l.contains("G71")),
            "{name}: a cycle left in\n{text}"
        );
        let Some(rs274) = rs274 else { continue };
        let ngc = tmp.join(format!("{name}.ngc"));
        std::fs::write(&ngc, &text).unwrap();
        let (theirs_text, stderr) = read_back(rs274, Some(&tools), &ngc);
        let what = format!("{name} (rs274 said: {stderr})");
        let (mut ours, mut theirs) = (common::motion_calls(&canon), common::motion_calls(&rigid_taps_as_feeds(&theirs_text)));
        if text.contains("G33.1") {
            // LinuxCNC's G33.1 reverses at the bottom at once: a dwell there is left out (NCS-W29).
            ours.retain(|(n, _)| n != "DWELL");
            theirs.retain(|(n, _)| n != "DWELL");
        }
        compared += common::same_calls(&what, &ours, &theirs);
        files += 1;
    }
    let _ = std::fs::remove_dir_all(&tmp);
    (files, compared)
}

/// rs274's `RIGID_TAP(x, y, z)` (a G33.1 stroke) as the two feeds it makes: to the bottom and
/// back to where it began, as ncsight's canonical text writes a tapping stroke.
pub fn rigid_taps_as_feeds(text: &str) -> String {
    let mut out = String::new();
    let mut at = String::from("0.0000, 0.0000, 0.0000");
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("RIGID_TAP(") {
            let nums: Vec<&str> = rest.trim_end_matches(')').split(',').map(str::trim).collect();
            out.push_str(&format!("STRAIGHT_FEED({}, {}, {}, 0.0000, 0.0000, 0.0000)\n", nums[0], nums[1], nums[2]));
            out.push_str(&format!("STRAIGHT_FEED({at}, 0.0000, 0.0000, 0.0000)\n"));
            continue;
        }
        if line.starts_with("STRAIGHT_") || line.starts_with("ARC_FEED(") {
            let args: Vec<&str> = line.split_once('(').map_or("", |(_, r)| r).trim_end_matches(')').split(',').map(str::trim).collect();
            if line.starts_with("STRAIGHT_") && args.len() >= 3 {
                at = format!("{}, {}, {}", args[0], args[1], args[2]);
            }
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// grbl 1.1's G and M codes and words (its documentation's list of supported commands).
pub const GRBL_G: &[&str] = &[
    "0", "1", "2", "3", "4", "10", "17", "18", "19", "20", "21", "28", "28.1", "30", "30.1", "38.2", "38.3", "38.4", "38.5", "40", "43.1", "49", "53", "54",
    "55", "56", "57", "58", "59", "61", "80", "90", "91", "91.1", "92", "92.1", "93", "94",
];
pub const GRBL_M: &[&str] = &["0", "1", "2", "3", "4", "5", "7", "8", "9", "30", "56"];
pub const GRBL_WORDS: &str = "FIJKLNPRSTXYZGM";

/// The words of a line without its comments: (letter, number text).
pub fn words(line: &str) -> Vec<(char, String)> {
    let mut code = String::new();
    let mut depth = 0;
    for c in line.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ';' if depth == 0 => break,
            _ if depth == 0 => code.push(c),
            _ => {}
        }
    }
    let mut out: Vec<(char, String)> = Vec::new();
    for c in code.chars().filter(|c| !c.is_whitespace()) {
        if c.is_ascii_alphabetic() {
            out.push((c.to_ascii_uppercase(), String::new()));
        } else {
            out.last_mut().unwrap_or_else(|| panic!("a number without a letter in {line:?}")).1.push(c);
        }
    }
    out
}

/// Every programme expanded for grbl holds only grbl's words, and a thread alarms: (threaded
/// programmes refused, lines checked).
pub fn grbl_check(programmes: &[Programme]) -> (usize, usize) {
    let (mut lines, mut refused) = (0, 0);
    for (name, input, args) in programmes {
        let canon = canon_of(input, args);
        let (code, text, err) = expand(input, args, "grbl");
        if threads(&canon) {
            assert_eq!(code, 1, "{name}: a thread must stop the grbl expansion");
            assert!(err.contains("NCS-E76") && err.contains("grbl does not have"), "{name}: {err}");
            refused += 1;
        }
        for line in text.lines() {
            for (letter, number) in words(line) {
                assert!(GRBL_WORDS.contains(letter), "{name}: {letter}{number} in {line:?}");
                let n = number.parse::<f64>().unwrap_or_else(|_| panic!("{name}: {letter}{number} in {line:?}"));
                if letter == 'G' {
                    let code = if n.fract() == 0.0 { format!("{}", n as i64) } else { format!("{n}") };
                    assert!(GRBL_G.contains(&code.as_str()), "{name}: G{number} is not a grbl code: {line:?}");
                }
                if letter == 'M' {
                    assert!(GRBL_M.contains(&format!("{}", n as i64).as_str()), "{name}: M{number} is not a grbl code: {line:?}");
                }
            }
            lines += 1;
        }
    }
    (refused, lines)
}
