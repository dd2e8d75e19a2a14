//! Programmes that call programmes, on the command line: --subprogram-dir, --main,
//! --skip-missing-subprograms, --max-blocks, what JSONL and check show of a call, and a
//! programme on standard input that jumps back.

mod common;

use std::io::Write;
use std::process::{Command, Stdio};

/// A fresh directory under the target directory for one test's files.
fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

const MAIN: &str = "O0001\nG21 G17 G90 G00 X0. Y0. Z10.\nM98 P0020200\nG00 X5.\nM30\n";

#[test]
fn a_programme_from_a_subprogram_dir() {
    let d = scratch("subdir");
    let lib = d.join("lib");
    std::fs::create_dir_all(&lib).unwrap();
    std::fs::write(d.join("main.nc"), MAIN).unwrap();
    // Found by its name (o0200.txt: any case, any extension).
    std::fs::write(lib.join("o0200.txt"), "%\nO0200 (POCKET)\nG91 G00 Y1.\nG90 M99\n%\n").unwrap();
    let main = d.join("main.nc");
    let (code, out, err) = common::ncsight(&["run", main.to_str().unwrap(), "-m", "fanuc0m", "--format", "jsonl", "--subprogram-dir", lib.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    // Rapid, two runs of Y+1 in the other file at depth 1, X5, M30.
    assert_eq!(lines.len(), 5, "{out}");
    let file = lib.join("o0200.txt");
    assert!(
        lines[1].contains(&format!("\"line\":3,\"file\":\"{}\"", file.display())) && lines[1].contains("\"y\":1,") && lines[1].contains("\"call_depth\":1"),
        "{}",
        lines[1]
    );
    assert!(lines[2].contains("\"y\":2,"), "{}", lines[2]);
    assert!(lines[3].contains("\"call_depth\":0") && !lines[3].contains("\"file\""), "{}", lines[3]);
    // Found by its content when no file is named after it.
    std::fs::rename(lib.join("o0200.txt"), lib.join("pockets.nc")).unwrap();
    let (code, out2, _) = common::ncsight(&["run", main.to_str().unwrap(), "-m", "fanuc0m", "--format", "jsonl", "--subprogram-dir", lib.to_str().unwrap()]);
    assert_eq!((code, out2.lines().count()), (0, 5), "{out2}");
    // Without the directory: FANUC 0 alarm 078 at the call.
    let (code, _, err) = common::ncsight(&["run", main.to_str().unwrap(), "-m", "fanuc0m"]);
    assert_eq!(code, 1);
    assert!(err.contains("main.nc:3:1: alarm[PS0078]: O0200"), "{err}");
    // Skipped: a warning, and the run goes on.
    let (code, out, _) = common::ncsight(&["run", main.to_str().unwrap(), "-m", "fanuc0m", "--format", "jsonl", "--skip-missing-subprograms"]);
    assert_eq!(code, 0);
    assert!(out.contains("\"code\":\"NCS-W27\""), "{out}");
}

/// An alarm inside a subprogramme: check names its file and line and the call that led there.
#[test]
fn check_shows_the_call_chain() {
    let d = scratch("chain");
    std::fs::write(d.join("main.nc"), "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0100\nM30\nO0100\nG00 Q1.\nM99\n").unwrap();
    let main = d.join("main.nc");
    let (code, out, _) = common::ncsight(&["check", main.to_str().unwrap(), "-m", "fanuc0m"]);
    assert_eq!(code, 1);
    assert!(out.contains("main.nc:6:5: alarm[NCS-E35]"), "{out}");
    assert!(out.contains("= in a subprogramme called at line 3, column 1"), "{out}");
    let (_, out, _) = common::ncsight(&["check", main.to_str().unwrap(), "-m", "fanuc0m", "--format", "jsonl"]);
    assert!(out.contains("\"calls\":[{\"line\":3,\"col\":1}]"), "{out}");
}

#[test]
fn main_and_max_blocks() {
    let d = scratch("main");
    std::fs::write(d.join("two.nc"), "O0100\nG91 G00 X1.\nG90 M99\nO0200\nG90 G00 X0. Y0. Z10.\nM98 P9990100\nM30\n").unwrap();
    let f = d.join("two.nc");
    let (code, out, err) = common::ncsight(&["run", f.to_str().unwrap(), "-m", "fanuc0m", "--main", "O0200", "--format", "jsonl"]);
    assert_eq!(code, 0, "{err}");
    // The rapid of O0200, 999 moves of O0100, the end.
    assert_eq!(out.lines().count(), 1 + 999 + 1);
    let (code, _, err) = common::ncsight(&["run", f.to_str().unwrap(), "-m", "fanuc0m", "--main", "O0200", "--max-blocks", "100"]);
    assert_eq!(code, 1);
    assert!(err.contains("NCS-E63") && err.contains("more than 100 blocks"), "{err}");
    let (code, _, err) = common::ncsight(&["run", f.to_str().unwrap(), "-m", "fanuc0m", "--main", "X12"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--main X12"), "{err}");
    let (code, _, err) = common::ncsight(&["run", f.to_str().unwrap(), "-m", "fanuc0m", "--subprogram-dir", "/no/such/dir"]);
    assert_eq!(code, 2, "{err}");
}

/// Standard input: a programme that only reads forward runs; one that jumps back through a
/// pipe gets a clear error (a file can be read again, a pipe cannot).
#[test]
fn standard_input_and_jumps() {
    let run = |text: &str| {
        let mut child = Command::new(env!("CARGO_BIN_EXE_ncsight"))
            .args(["run", "-", "-m", "fanuc0m"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        child.stdin.take().unwrap().write_all(text.as_bytes()).unwrap();
        let o = child.wait_with_output().unwrap();
        (o.status.code().unwrap(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
    };
    // O0100 is called once and comes after M30: the search reads on, the return goes back.
    let (code, _, err) = run("G90 G00 X0. Y0. Z1.\nM98 P0100\nM30\nO0100\nG00 X1.\nM99\n");
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("a pipe cannot be read again: give the programme as a file"), "{err}");
    let (code, out, err) = run("G90 G00 X0. Y0. Z1.\nG00 X2.\nM30\n");
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().count(), 4, "three records and the cycle time: {out}");
}

/// The tape leader through the file and pipe readers: the banner before the first `%` is not
/// read (one warning on line 1), the lines after it keep their numbers, and a call that jumps
/// back after M30 finds its way by byte offsets that count the leader (O0100 on line 7 moves
/// X to 1, the return comes back to line 5's X2).
#[test]
fn the_tape_leader_from_a_file_and_a_pipe() {
    let d = scratch("leader");
    let text = "SOMECAM POST V2 -- PART 77\n%\nO0001\nM98 P0100\nG00 X2.\nM30\nO0100\nG00 X1.\nM99\n%\n";
    let f = d.join("leader.nc");
    std::fs::write(&f, text).unwrap();
    let (code, out, err) = common::ncsight(&["run", f.to_str().unwrap(), "-m", "fanuc0m", "--format", "jsonl"]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].contains("\"code\":\"NCS-W04\"") && lines[0].contains("\"line\":1,"), "{out}");
    assert!(lines[1].contains("\"line\":8,") && lines[1].contains("\"x\":1,"), "{out}");
    assert!(lines[2].contains("\"line\":5,") && lines[2].contains("\"x\":2,"), "{out}");
    assert!(lines[3].contains("\"line\":6,") && lines[3].contains("\"end\""), "{out}");
    assert_eq!(lines.len(), 4, "{out}");
    // Through a pipe (a programme that only reads forward).
    let mut child = Command::new(env!("CARGO_BIN_EXE_ncsight"))
        .args(["check", "-", "-m", "fanuc0m"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(b"PART 77\n%\nG00 X1.\nM30\n").unwrap();
    let o = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr).into_owned() + &String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("<stdin>:1:1: warning[NCS-W04]: line 1, before the first '%', is the tape leader"), "{err}");
    assert!(err.contains("0 alarm(s), 1 warning(s)"), "{err}");
}

/// A macro body run on its own (issue 35): `--call-args` gives its arguments as a G65 block
/// writes them after P (A #1, B #2, I J K #4-#6, F #9; without a point in least input
/// increments as G65 reads them), `--var` its locals #1-#33; its M99 is then the return, with
/// no "M99 in the main programme" warning. Without them the division by its vacant argument is
/// alarm 112 with a hint that names both.
#[test]
fn a_macro_body_runs_with_its_arguments() {
    let d = scratch("call_args");
    let body = d.join("o9010.nc");
    std::fs::write(&body, "O9010\n#3 = #1 + #2\n#10 = 60 / #9\nG01 X#3 Y#4 F#9\nM99\n").unwrap();
    let p = body.to_str().unwrap();
    let (code, out, err) = common::ncsight(&["run", p, "-m", "fanuc0m", "--format", "jsonl", "--call-args", "A1. B2. I5 F100."]);
    assert_eq!(code, 0, "{err}");
    // #3 = 3 mm; I5 without a point is 0.005 mm (FANUC 0-M least input increment).
    assert!(out.contains(r#""kind":"feed","x":3,"y":0.005,"z":0,"f":100"#), "{out}");
    assert!(!out.contains("NCS-W08"), "{out}");
    let (code, out, err) = common::ncsight(&["run", p, "-m", "fanuc0m", "--format", "jsonl", "--var", "1=1", "--var", "2=1", "--var", "9=50"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains(r#""x":2,"y":0,"z":0,"f":50"#), "{out}");
    let (code, out, _) = common::ncsight(&["check", p, "-m", "fanuc0m"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("PS0112") && out.contains("--call-args"), "{out}");
    for bad in ["A1. P9010", "G01 A1.", "N10 A1."] {
        let (code, _, err) = common::ncsight(&["check", p, "-m", "fanuc0m", "--call-args", bad]);
        assert_eq!(code, 2, "{bad}: {err}");
        assert!(err.contains("--call-args"), "{err}");
    }
}

/// The machine builder's M-code macro calls and resident programmes from the setup (issue 35):
/// `[machine] m_macro = { 165 = "O9832" }` makes `M165 A2.` a call of O9832 with #1 = 2 (a P in
/// the block is said to be ignored: G65 has no P argument), `library = ["lib"]` (relative to
/// the setup) is where O9832 is found. Without the programme, the alarm names the setup's keys;
/// without the setup, the refused P's hint names m_macro.
#[test]
fn builder_macros_from_the_setup() {
    let d = scratch("m_macro");
    std::fs::create_dir_all(d.join("lib")).unwrap();
    std::fs::write(d.join("setup.toml"), "[machine]\nm_macro = { 165 = \"O9832\" }\nlibrary = [\"lib\"]\n").unwrap();
    std::fs::write(d.join("main.nc"), "O0001\nG98 G00 X50. Z5.\nM165 P9832 A2.\nG00 X60.\nM30\n").unwrap();
    let main = d.join("main.nc");
    let setup = d.join("setup.toml");
    let args = ["run", main.to_str().unwrap(), "-m", "fanuc0t", "--format", "jsonl", "--setup", setup.to_str().unwrap()];
    let (code, out, _) = common::ncsight(&args);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("PS0078") && out.contains("m_macro") && out.contains("[machine] library"), "{out}");
    std::fs::write(d.join("lib/O9832.nc"), "O9832\nG00 W-#1\nM99\n").unwrap();
    let (code, out, err) = common::ncsight(&args);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains(r#""kind":"rapid","x":50,"z":3"#), "{out}");
    assert!(out.contains("NCS-W04"), "{out}");
    std::fs::write(d.join("plain.nc"), "O0002\nG98 G00 X50. Z5.\nM165 P9832\nM30\n").unwrap();
    let (code, out, _) = common::ncsight(&["check", d.join("plain.nc").to_str().unwrap(), "-m", "fanuc0t"]);
    assert_eq!(code, 1);
    assert!(out.contains("[machine] m_macro = { 165"), "{out}");
    std::fs::write(d.join("bad.toml"), "[machine]\nm_macro = { 98 = \"O9832\" }\n").unwrap();
    let (code, _, err) = common::ncsight(&["check", main.to_str().unwrap(), "-m", "fanuc0t", "--setup", d.join("bad.toml").to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("machine.m_macro"), "{err}");
}
