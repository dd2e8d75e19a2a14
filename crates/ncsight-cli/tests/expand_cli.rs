//! `ncsight expand` (docs/commands/expand.md): the programme as plain moves for LinuxCNC or
//! grbl. For LinuxCNC the expansion is read back by LinuxCNC's own interpreter (`rs274 -g`)
//! and must move as `ncsight run --format canon` says the original moves; for grbl every line
//! must hold only what grbl 1.1 accepts, and a thread must alarm.

mod common;

use std::path::{Path, PathBuf};

/// Golden programmes, and the corpus programmes that run to their end, with their arguments.
fn programmes() -> Vec<(String, PathBuf, Vec<String>)> {
    let mut out = Vec::new();
    let dir = common::root().join("tests/golden");
    let mut cases: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    cases.sort();
    for case in cases {
        let args = std::fs::read_to_string(case.join("args")).unwrap_or_default();
        out.push((case.file_name().unwrap().to_string_lossy().into_owned(), case.join("input.nc"), args.split_whitespace().map(String::from).collect()));
    }
    for name in ["doosan-lynx300__O0201.nc", "doosan-lynx300__O3380.nc"] {
        out.push((name.to_string(), common::shared().join("corpus").join(name), vec!["--machine".into(), "fanuc0t".into()]));
    }
    assert!(out.len() >= 25);
    out
}

fn expand(input: &Path, args: &[String], to: &str) -> (i32, String, String) {
    let mut argv: Vec<&str> = vec!["expand", input.to_str().unwrap(), "--to", to];
    argv.extend(args.iter().map(String::as_str));
    common::ncsight(&argv)
}

/// Whether the run of a programme makes a spindle-synchronised record.
fn threads(canon: &str) -> bool {
    canon.contains("START_SPEED_FEED_SYNC")
}

/// rs274 on the path, or why the round trip cannot run. In CI it must (`.ci/run` installs
/// LinuxCNC); elsewhere the comparison is left to CI and said so.
fn rs274() -> Option<&'static str> {
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
fn read_back(rs274: &str, tools: Option<&Path>, ngc: &Path) -> (String, String) {
    let mut cmd = std::process::Command::new(rs274);
    if let Some(t) = tools {
        cmd.arg("-t").arg(t);
    }
    let out = cmd.arg("-g").arg(ngc).output().unwrap();
    let calls: String = String::from_utf8_lossy(&out.stdout).lines().map(|l| l.trim_start().split_once("N..... ").map_or(l, |(_, r)| r)).collect::<Vec<_>>().join("\n");
    let stderr = String::from_utf8_lossy(&out.stderr).trim().to_string();
    assert!(out.status.success(), "{}: rs274 refused the expansion: {stderr}\n{calls}", ngc.display());
    (calls, stderr)
}

#[test]
fn linuxcnc_reads_the_expansion_back_as_the_original_moves() {
    let rs274 = rs274();
    let tmp = std::env::temp_dir().join(format!("ncsight-expand-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    // rs274 changes only to tools its table holds (`T12 M6`): tools 1-200 in their own pockets.
    let tools = tmp.join("tools.tbl");
    std::fs::write(&tools, (1..=200).map(|n| format!("T{n} P{n} ;\n")).collect::<String>()).unwrap();
    let (mut compared, mut files) = (0, 0);
    for (name, input, args) in programmes() {
        let mut run_args: Vec<&str> = vec!["run", input.to_str().unwrap(), "--format", "canon"];
        run_args.extend(args.iter().map(String::as_str));
        let (_, canon, _) = common::ncsight(&run_args);
        let (code, text, err) = expand(&input, &args, "linuxcnc");
        if canon.contains("ARC_FEED") && threads(&canon) && err.contains("NCS-E76") {
            // An arc thread (GSK988T G32.2/G32.3): LinuxCNC cannot do it; the alarm says so.
            assert_eq!(code, 1, "{name}");
            assert!(err.contains("straight only"), "{name}: {err}");
            continue;
        }
        assert!(!err.contains("NCS-E76"), "{name}: {err}");
        assert!(text.starts_with("(expanded by ncsight from"), "{name}: {text}");
        assert!(text.lines().filter(|l| !l.starts_with('(')).all(|l| !l.contains("G76") && !l.contains("G81") && !l.contains("G71")), "{name}: a cycle left in\n{text}");
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
    if rs274.is_some() {
        assert!(files >= 20 && compared > 500, "only {files} programmes, {compared} calls compared");
    }
}

/// rs274's `RIGID_TAP(x, y, z)` (a G33.1 stroke) as the two feeds it makes: to the bottom and
/// back to where it began, as ncsight's canonical text writes a tapping stroke.
fn rigid_taps_as_feeds(text: &str) -> String {
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
const GRBL_G: &[&str] = &[
    "0", "1", "2", "3", "4", "10", "17", "18", "19", "20", "21", "28", "28.1", "30", "30.1", "38.2", "38.3", "38.4", "38.5", "40", "43.1", "49", "53", "54", "55",
    "56", "57", "58", "59", "61", "80", "90", "91", "91.1", "92", "92.1", "93", "94",
];
const GRBL_M: &[&str] = &["0", "1", "2", "3", "4", "5", "7", "8", "9", "30", "56"];
const GRBL_WORDS: &str = "FIJKLNPRSTXYZGM";

/// The words of a line without its comments: (letter, number text).
fn words(line: &str) -> Vec<(char, String)> {
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

#[test]
fn grbl_gets_only_what_grbl_accepts_and_threads_alarm() {
    let (mut lines, mut refused) = (0, 0);
    for (name, input, args) in programmes() {
        let mut run_args: Vec<&str> = vec!["run", input.to_str().unwrap(), "--format", "canon"];
        run_args.extend(args.iter().map(String::as_str));
        let (_, canon, _) = common::ncsight(&run_args);
        let (code, text, err) = expand(&input, &args, "grbl");
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
    assert!(refused >= 10, "only {refused} threaded programmes refused");
    assert!(lines > 1000, "only {lines} lines checked");
}

#[test]
fn expand_says_what_it_cannot_do() {
    let (code, _, err) = common::ncsight(&["expand", "nowhere.nc", "--machine", "fanuc0m", "--to", "haas"]);
    assert_eq!(code, 2);
    assert!(err.contains("--to haas: choose linuxcnc or grbl"), "{err}");
    // A mill programme: rapids, a feed, an arc in G17 and a drilling cycle, written out.
    let dir = std::env::temp_dir().join(format!("ncsight-expand-small-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("o1.nc");
    std::fs::write(&f, "O1\nG21 G17 G90 G00 X0. Y0. Z10.\nS1000 M03\nN20 G01 Z-1. F200.\nG02 X10. Y0. I5. J0.\nG00 Z10.\nG98 G81 X20. Y5. Z-3. R2. F100.\nG80\nM30\n").unwrap();
    let (code, text, err) = common::ncsight(&["expand", f.to_str().unwrap(), "--machine", "fanuc0m", "--to", "grbl"]);
    assert_eq!(code, 0, "{err}");
    let body: Vec<&str> = text.lines().skip(2).collect();
    // By hand: the header, then each block's line and moves; the G81 hole as its rapid to the
    // hole, to R, the feed to the bottom, the rapid back to the initial level (G98: Z10).
    assert_eq!(
        body,
        [
            "G21 G90 G94 G17 G40 G49 G80",
            "(line 2)",
            "G0 X0 Y0 Z10",
            "(line 3)",
            "S1000 M3",
            "(line 4 N20)",
            "G1 X0 Y0 Z-1 F200",
            "(line 5)",
            "G2 X10 Y0 Z-1 I5 J0",
            "(line 6)",
            "G0 X10 Y0 Z10",
            "(line 7)",
            "G0 X20 Y5 Z10",
            "G0 X20 Y5 Z2",
            "G1 X20 Y5 Z-3 F100",
            "G0 X20 Y5 Z10",
            "(line 9)",
            "M30",
        ]
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A coordinate shift (G50 on the FANUC 0-T) in mid-programme: the moves after it are in the
/// shifted coordinates, so the expansion shifts the target the same way (`G92 X0 Z0` where the
/// tool stands), and LinuxCNC then moves as ncsight says. A programme without M30 gets one,
/// with a comment, so the target does not stop on a missing end.
#[test]
fn a_coordinate_shift_is_carried_over() {
    let dir = std::env::temp_dir().join(format!("ncsight-expand-shift-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("g50.nc");
    std::fs::write(&f, "G00 X40. Z10. S500 M03\nG50 X0 Z0\nG01 X10. Z-5. F0.2\nG00 X20.\n").unwrap();
    let (code, text, err) = common::ncsight(&["expand", f.to_str().unwrap(), "--machine", "fanuc0t", "--to", "linuxcnc"]);
    assert_eq!(code, 0, "{err}");
    let body: Vec<&str> = text.lines().skip(3).collect();
    assert_eq!(
        body,
        [
            "(line 1)",
            "S500 M3",
            "G0 X20 Z10",
            "(line 3)",
            "G92 X0 Z0 (the programme's coordinates were shifted here)",
            "G1 X5 Z-5 F100",
            "(line 4)",
            "G0 X10 Z-5",
            "(the programme has no M02 or M30: its controller stops after its last block)",
            "M30",
        ]
    );
    if let Some(rs274) = rs274() {
        let ngc = dir.join("g50.ngc");
        std::fs::write(&ngc, &text).unwrap();
        let (theirs, _) = read_back(rs274, None, &ngc);
        let (_, canon, _) = common::ncsight(&["run", f.to_str().unwrap(), "--machine", "fanuc0t", "--format", "canon"]);
        common::same_calls("g50", &common::motion_calls(&canon), &common::motion_calls(&theirs));
    }
    let _ = std::fs::remove_dir_all(&dir);
}
