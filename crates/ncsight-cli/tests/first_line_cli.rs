//! The machine named by a programme's first line, `(ncsight: MACHINE)` (docs/reference/
//! interface.md, "Added in the third round"; docs/commands/run.md, "The machine"): every command
//! that reads a programme honours it when no `--machine` is given.

mod common;

use common::Scratch;

use std::io::Write;

/// A drilling programme of a machining centre: G81 is NCS-E10 on the default gsk980tdi.
const DRILL: &str = "G90 G0 X0 Y0 Z10. S1000 M03\nG81 X10. Y5. Z-5. R2. F100\nG80\nM30\n";

#[test]
fn the_first_line_selects_the_machine() {
    let dir = Scratch::new("firstline-selects");
    let bare = dir.file("bare.nc", DRILL);
    let (code, out, err) = common::ncsight(&["check", &bare]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.contains("NCS-E10") && err.contains("no --machine given, using gsk980tdi"), "{out}{err}");

    let named = dir.file("named.nc", &format!("(ncsight: fanuc0m)\n{DRILL}"));
    let (code, out, err) = common::ncsight(&["check", &named]);
    assert_eq!(code, 0, "{out}{err}");
    // The comment is an ordinary comment for the controller: no warning for it.
    assert!(out.contains("0 alarm(s), 0 warning(s) on fanuc0m"), "{out}");
    assert_eq!(err.trim_end(), format!("ncsight: using fanuc0m named by the first line of {named}"));
    assert!(!err.contains("no --machine given"), "{err}");

    let (code, out, err) = common::ncsight(&["run", &named, "--format", "jsonl"]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("alarm") && out.contains("M30"), "{out}");
    assert!(err.contains("using fanuc0m named by the first line"), "{err}");

    // The comment may follow other words on its line; `ncsight` in any case, spaces around the colon.
    let words = dir.file("words.nc", &format!("O0001 (DRILL PLATE) ( NCSight :  FANUC0M )\n{DRILL}"));
    let (code, out, err) = common::ncsight(&["check", &words, "--format", "short"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("on fanuc0m"), "{out}");

    // Only the first line counts.
    let second = dir.file("second.nc", &format!("G90\n(ncsight: fanuc0m)\n{DRILL}"));
    let (code, out, _) = common::ncsight(&["check", &second]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("on gsk980tdi"), "{out}");

    // Every command that reads a programme: expand, simulate (and report when built with its page).
    let (code, out, err) = common::ncsight(&["expand", &named, "--to", "linuxcnc"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("fanuc0m") && err.contains("named by the first line"), "{out}{err}");
    let (code, out, err) = common::ncsight(&["simulate", &named, "--stock", "40x20x10"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(err.contains("using fanuc0m named by the first line"), "{err}");
    let (code, out, err) = common::ncsight(&["report", &named]);
    if !err.contains("built without the page's engine") {
        assert_eq!(code, 0, "{err}");
        assert!(out.contains(r#""machine":"fanuc0m""#), "the page opens on the machine the first line names");
    }
}

#[test]
fn machine_given_wins_with_a_note() {
    let dir = Scratch::new("firstline-wins");
    let named = dir.file("named.nc", &format!("(ncsight: fanuc0m)\n{DRILL}"));
    let (code, out, err) = common::ncsight(&["check", &named, "--machine", "gsk980tdi"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.contains("NCS-E10") && out.contains("on gsk980tdi"), "{out}");
    assert_eq!(err.trim_end(), format!("ncsight: using --machine gsk980tdi, not fanuc0m named by the first line of {named}"));
    assert!(!err.contains("alarm") && !err.contains("warning"), "a note, not a diagnostic: {err}");
    // The same machine both ways: nothing to say.
    let (code, out, err) = common::ncsight(&["run", &named, "-m", "FANUC0M"]);
    assert_eq!(code, 0, "{out}{err}");
    assert_eq!(err, "");
    // A name in the first line that no profile has does not matter when --machine is given.
    let odd = dir.file("odd.nc", &format!("(ncsight: fanucom)\n{DRILL}"));
    let (code, _, err) = common::ncsight(&["check", &odd, "-m", "fanuc0m"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("using --machine fanuc0m, not fanucom"), "{err}");
}

#[test]
fn an_unknown_name_is_a_usage_error_with_a_suggestion() {
    let dir = Scratch::new("firstline-unknown");
    let odd = dir.file("odd.nc", &format!("(ncsight: fanucom)\n{DRILL}"));
    for cmd in [&["run"][..], &["check"], &["expand", "--to", "grbl"], &["simulate", "--stock", "40x20x10"]] {
        let mut args = vec![cmd[0], odd.as_str()];
        args.extend_from_slice(&cmd[1..]);
        let (code, out, err) = common::ncsight(&args);
        assert_eq!(code, 2, "{cmd:?}: {out}{err}");
        assert!(err.contains("unknown machine 'fanucom'") && err.contains("did you mean fanuc0m?"), "{cmd:?}: {err}");
        assert!(err.contains("first line (ncsight: fanucom)"), "{cmd:?}: {err}");
    }
    // check names the file and checks the others (exit 2: the check is incomplete).
    let good = dir.file("good.nc", &format!("(ncsight: fanuc0m)\n{DRILL}"));
    let (code, out, err) = common::ncsight(&["check", &odd, &good]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(out.contains(&format!("{good}: 0 alarm(s), 0 warning(s) on fanuc0m")), "{out}");
    assert!(!out.contains(&format!("{odd}:")), "{out}");
}

#[test]
fn a_percent_line_and_a_byte_order_mark_come_before_the_first_line() {
    let dir = Scratch::new("firstline-percent");
    let tape = dir.file("tape.nc", &format!("\u{feff}%\r\n\r\n(ncsight: fanuc0m)\r\n{}%\r\n", DRILL.replace('\n', "\r\n")));
    let (code, out, err) = common::ncsight(&["check", &tape]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("0 alarm(s), 0 warning(s) on fanuc0m"), "{out}");
    let (code, _, err) = common::ncsight(&["run", &tape]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn check_takes_each_files_machine() {
    let dir = Scratch::new("firstline-each");
    let mill = dir.file("mill.nc", &format!("(ncsight: fanuc0m)\n{DRILL}"));
    let lathe = dir.file("lathe.nc", "G99 S500 M03\nG0 X40. Z2.\nG1 X38. F0.2\nM30\n");
    let lathe_t = dir.file("lathe_t.nc", "(ncsight: fanuc0t)\nG99 S500 M03\nG0 X40. Z2.\nG1 X38. F0.2\nM30\n");
    let (code, out, err) = common::ncsight(&["check", &mill, &lathe, &lathe_t, &lathe]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains(&format!("{mill}: 0 alarm(s), 0 warning(s) on fanuc0m")), "{out}");
    assert!(out.contains(&format!("{lathe}: 0 alarm(s), 0 warning(s) on gsk980tdi")), "{out}");
    assert!(out.contains(&format!("{lathe_t}: 0 alarm(s), 0 warning(s) on fanuc0t")), "{out}");
    assert_eq!(err.matches("no --machine given").count(), 1, "the default said once: {err}");
}

/// Standard input: its first line is read for the machine and given back to the run.
#[test]
fn standard_input_honours_the_first_line() {
    let exe = env!("CARGO_BIN_EXE_ncsight");
    let text = format!("%\n(ncsight: fanuc0m)\n{DRILL}");
    let piped = |args: &[&str]| {
        let mut child = std::process::Command::new(exe)
            .args(args)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let mut stdin = child.stdin.take().unwrap();
        let t = text.clone();
        let writer = std::thread::spawn(move || stdin.write_all(t.as_bytes()));
        let o = child.wait_with_output().unwrap();
        writer.join().unwrap().unwrap();
        (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
    };
    let (code, out, err) = piped(&["check", "-"]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(out.contains("<stdin>: 0 alarm(s), 0 warning(s) on fanuc0m"), "{out}");
    assert!(err.contains("using fanuc0m named by the first line of <stdin>"), "{err}");
    // The run gets the whole text, the first lines too: the drilling cycle and the end.
    let (code, out, err) = piped(&["run", "-", "--format", "jsonl"]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert_eq!(out.lines().filter(|l| l.contains(r#""kind":"feed""#)).count(), 1, "{out}");
    assert!(out.lines().last().is_some_and(|l| l.contains("M30")), "{out}");
    let (code, out, err) = piped(&["expand", "-", "--to", "linuxcnc"]);
    assert_eq!(code, Some(0), "{out}{err}");
    let (code, out, err) = piped(&["simulate", "-", "--stock", "40x20x10"]);
    assert_eq!(code, Some(0), "{out}{err}");
    let (code, _, err) = piped(&["check", "-", "-m", "gsk980tdi"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("using --machine gsk980tdi, not fanuc0m named by the first line of <stdin>"), "{err}");
}
