//! Defects found by outside checks in the third round (issue 32), through the command line:
//! each test failed before its fix.

mod common;

use common::Scratch;

/// A Ø40 shaft roughed with G71, finished with G70 and threaded M20x2.5, simulated without
/// `--stock`: the stock is guessed from the cuts (Ø40.5, the roughing's allowance, by 65 mm:
/// Z0 to 5 mm behind the deepest cut at Z-60) and said to be guessed; no chuck finding. The old
/// guess took the thread alone (Ø20.87 x 27 mm) and found four chucks that are not there.
const SHAFT: &str = "O0040\nG99 M03 S800 T0101\nG00 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\nN10 G00 X16.\nG01 Z0.\nX19.8 Z-2.\nZ-25.\nX30.\nZ-45.\nX40.\nN20 Z-60.\nG70 P10 Q20\nG00 X100. Z100.\nT0303\nG00 X22. Z5.\nG92 X19.2 Z-22. F2.5\nX18.6\nX18.1\nX17.8\nG00 X100. Z100.\nM30\n";

#[test]
fn simulate_without_stock_guesses_it_from_the_cuts_and_says_so() {
    let dir = Scratch::new("guess");
    let f = dir.file("shaft.nc", SHAFT);
    let (code, out, err) = common::ncsight(&["simulate", &f, "-m", "gsk980tdi"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("stock guessed          40.5 x 65 mm from Z0 (guessed from the programme's cuts"), "{out}");
    assert!(!out.contains("chuck") && out.contains("findings               none"), "{out}");
    let (_, json, _) = common::ncsight(&["simulate", &f, "-m", "gsk980tdi", "--format", "json"]);
    assert!(json.contains("\"stock_guessed\":{\"diameter_mm\":40.5,\"length_mm\":65,\"front_z_mm\":0,\"bore_mm\":0}"), "{json}");
    // Given, it is not a guess; a stock too short meets the chuck, said plainly.
    let (code, out, _) = common::ncsight(&["simulate", &f, "-m", "gsk980tdi", "--stock", "42x30"]);
    assert_eq!(code, 3, "{out}");
    assert!(!out.contains("stock guessed") && out.contains("chuck") && !out.contains("against a guessed stock"), "{out}");
}

/// No output may be a file the run reads: a subprogramme file of `--subprogram-dir`, the setup
/// (`-o`, `--image`, for run, expand, simulate and report alike). Refused with exit 2 before
/// anything is written; the files stay as they were.
#[test]
fn outputs_never_overwrite_a_subprogramme_or_the_setup() {
    let dir = Scratch::new("outputs");
    let main = dir.file("main.nc", "G97 S500 M03\nG00 X40. Z2.\nM98 P1234\nM30\n");
    std::fs::create_dir_all(dir.path("sd")).unwrap();
    let sub_text = "O1234\nG01 X30. Z-10. F100\nM99\n";
    let sub = dir.file("sd/O1234.nc", sub_text);
    let setup_text = "[stock]\ndiameter_mm = 60.0\nlength_mm = 80.0\n";
    let setup = dir.file("s.toml", setup_text);
    let sd = dir.path("sd");
    let cases: Vec<Vec<&str>> = vec![
        vec!["run", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "-o", &sub],
        vec!["expand", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "--to", "linuxcnc", "-o", &sub],
        vec!["report", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "-o", &sub],
        vec!["run", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "--setup", &setup, "-o", &setup],
        vec!["simulate", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "--setup", &setup, "--image", &setup],
        vec!["report", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "--setup", &setup, "-o", &setup],
    ];
    for args in cases {
        let (code, _, err) = common::ncsight(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains("a file this run reads: refusing to overwrite it"), "{args:?}: {err}");
        assert_eq!(std::fs::read_to_string(&sub).unwrap(), sub_text, "{args:?} changed the subprogramme");
        assert_eq!(std::fs::read_to_string(&setup).unwrap(), setup_text, "{args:?} changed the setup");
    }
    // Another file in the folder is fine.
    let other = dir.path("sd/out.txt");
    let (code, _, err) = common::ncsight(&["run", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "-o", &other]);
    assert_eq!(code, 0, "{err}");
}

/// A reader that goes away at once, as `head -c 0` does.
struct CutPipe;

impl std::io::Write for CutPipe {
    fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
        Err(std::io::Error::new(std::io::ErrorKind::BrokenPipe, "the reader went away"))
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Err(std::io::Error::new(std::io::ErrorKind::BrokenPipe, "the reader went away"))
    }
}

/// `ncsight run big.nc | head`: the first failed write stops `run` and `expand` (exit 0, as for
/// any cut pipe), instead of computing the whole programme for nobody. The programme's alarm at
/// its end is never reached, so it is not reported; `check` (whose status is the point) still
/// runs to the end.
#[test]
fn a_cut_output_pipe_stops_run_and_expand() {
    let dir = Scratch::new("pipe");
    let mut text = String::from("G21 G17 G90 G0 X0 Y0 Z10.\n");
    for _ in 0..2000 {
        text.push_str("G91 G81 X1. Y0 Z-1. R1. F100 K10\n");
    }
    text.push_str("G90 G02 X0 Y0 R0.1\nM30\n");
    let f = dir.file("k.nc", &text);
    for args in [
        vec!["run", f.as_str(), "-m", "fanuc0m", "--format", "canon"],
        vec!["expand", f.as_str(), "-m", "fanuc0m", "--to", "grbl"],
        vec!["check", f.as_str(), "-m", "fanuc0m"],
    ] {
        let mut err = Vec::new();
        let argv = std::iter::once("ncsight").chain(args.iter().copied()).map(std::ffi::OsString::from);
        let code = ncsight_cli::main_with(argv, &mut CutPipe, &mut err);
        let err = String::from_utf8_lossy(&err);
        if args[0] == "check" {
            assert_eq!(code, 1, "check runs to its end and reports the alarm: {err}");
        } else {
            assert_eq!(code, 0, "{args:?}: {err}");
            assert!(!err.contains("alarm"), "{args:?} ran on after the pipe was cut: {err}");
        }
    }
}

/// A named pipe as the programme or the setup is read once: `check`, `run`, `expand`,
/// `simulate` and `report` return with the writer's data (they used to open the file twice and
/// wait for a second writer for ever).
#[cfg(unix)]
#[test]
fn a_named_pipe_is_read_once() {
    use std::io::Write;
    let dir = Scratch::new("fifo");
    let fifo = |name: &str| {
        let p = dir.path(name);
        assert!(std::process::Command::new("mkfifo").arg(&p).status().unwrap().success());
        p
    };
    let exe = env!("CARGO_BIN_EXE_ncsight");
    let feed = |path: String, text: &'static str| {
        std::thread::spawn(move || std::fs::File::options().write(true).open(path).unwrap().write_all(text.as_bytes()).unwrap())
    };
    let programme = "G97 S500 M03\nG0 X40. Z2.\nG1 X38. F0.2\nZ-10.\nM30\n";
    for cmd in [&["check"][..], &["run"], &["expand", "--to", "linuxcnc"], &["simulate", "--stock", "40x20"]] {
        let p = fifo(&format!("p{}", cmd[0]));
        let writer = feed(p.clone(), programme);
        let mut c = std::process::Command::new(exe);
        c.arg(cmd[0]).arg(&p).args(["-m", "gsk980tdi"]).args(&cmd[1..]);
        let mut child = c.stdout(std::process::Stdio::null()).stderr(std::process::Stdio::piped()).spawn().unwrap();
        let status = wait_at_most(&mut child, 20);
        writer.join().unwrap();
        assert_eq!(status, Some(0), "{cmd:?} did not return with 0 from a named pipe");
    }
    let s = fifo("s.toml");
    let writer = feed(s.clone(), "[stock]\ndiameter_mm = 40.0\nlength_mm = 20.0\n");
    let main = dir.file("m.nc", programme);
    let mut child =
        std::process::Command::new(exe).args(["simulate", &main, "-m", "gsk980tdi", "--setup", &s]).stdout(std::process::Stdio::null()).spawn().unwrap();
    let status = wait_at_most(&mut child, 20);
    writer.join().unwrap();
    assert_eq!(status, Some(0), "--setup from a named pipe");
}

/// The exit status of a child, or None (and the child killed) after `secs` seconds: a hang is
/// a failure, not a stuck test.
fn wait_at_most(child: &mut std::process::Child, secs: u64) -> Option<i32> {
    let until = std::time::Instant::now() + std::time::Duration::from_secs(secs);
    while std::time::Instant::now() < until {
        if let Some(s) = child.try_wait().unwrap() {
            return s.code();
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let _ = child.kill();
    let _ = child.wait();
    None
}

/// The setup file is bounded: `--setup /dev/zero` is refused with the size, instead of growing
/// until memory runs out; a parse error quotes a long line cut short.
#[test]
fn the_setup_file_is_bounded_and_long_lines_are_cut() {
    let dir = Scratch::new("setup-size");
    let main = dir.file("m.nc", "G0 X40. Z2.\nM30\n");
    if cfg!(unix) {
        let (code, _, err) = common::ncsight(&["run", &main, "-m", "gsk980tdi", "--setup", "/dev/zero"]);
        assert_eq!(code, 2);
        assert!(err.contains("a setup file holds at most 16 MiB (16777216 bytes); this one holds 16777217 bytes or more"), "{err}");
    }
    let long = format!("[stock]\ndiameter_mm = {}\n", "9".repeat(100_000));
    let s = dir.file("long.toml", &long);
    let (code, _, err) = common::ncsight(&["run", &main, "-m", "gsk980tdi", "--setup", &s]);
    assert_eq!(code, 2);
    assert!(err.len() < 5_000, "{} bytes of message", err.len());
    assert!(err.contains("more characters)"), "{err}");
}

/// `expand` never writes F0: a feed below the target's four decimals (0.0001 mm/rev at 0.4 rpm,
/// 0.00004 mm/min) stops the expansion with NCS-E76 before its line is begun (both targets refuse
/// G1 F0). The G96 note names the speed as the S word writes it (S0.2, not S0).
#[test]
fn expand_refuses_f0_and_names_the_speed_it_writes() {
    let dir = Scratch::new("expand-f0");
    let f = dir.file("f0.nc", "G99 G97 S0.4 M03\nG00 X20. Z2.\nG01 Z-10. F0.0001\nM30\n");
    for to in ["linuxcnc", "grbl"] {
        let (code, out, err) = common::ncsight(&["expand", &f, "-m", "gsk980tdi", "--to", to]);
        assert_eq!(code, 1, "{out}{err}");
        assert!(err.contains("NCS-E76") && err.contains("is F0 at the target's 4 decimals"), "{err}");
        assert!(!out.contains(" F0") && !out.contains("G1 X10 Z-10"), "{out}");
    }
    let s = dir.file("s0.nc", "G99 G50 S0.2\nG96 S100 M03\nG00 X20. Z2.\nG01 Z-10. F0.2\nM30\n");
    let (code, out, err) = common::ncsight(&["expand", &s, "-m", "gsk980tdi", "--to", "linuxcnc"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("S0.2 M3") && err.contains("the spindle speed of this moment, S0.2:"), "{err}");
}

/// Entries of `--subprogram-dir` named after the called programme but not readable as a
/// programme file (a folder, a named pipe called `O1235.nc`) are named in the "not found" alarm,
/// with why, instead of being passed over in silence (and a named pipe is never opened).
#[cfg(unix)]
#[test]
fn unreadable_subprogramme_entries_are_named() {
    let dir = Scratch::new("sd-entries");
    std::fs::create_dir_all(dir.path("sd/O1234.nc")).unwrap();
    assert!(std::process::Command::new("mkfifo").arg(dir.path("sd/O1235.nc")).status().unwrap().success());
    let main = dir.file("m.nc", "G0 X1. Z1.\nM98 P1234\nM98 P1235\nM30\n");
    let sd = dir.path("sd");
    let (code, out, _) = common::ncsight(&["check", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains(&format!("passed over, not readable as a programme file: {sd}/O1234.nc (a folder)")), "{out}");
    assert!(out.contains(&format!("{sd}/O1235.nc (a named pipe or a device, not a regular file)")), "{out}");
}

/// The setup's `[machine] tool_change_s` (third-round setup keys): each change to another tool
/// adds it to the cycle time. T0101, T0202, T0202 again (no change), T0101: three changes, 3 x 4
/// s = 12 s more than without; `--param tool_change_s=1` overrides the setup (3 s more).
#[test]
fn a_tool_change_adds_the_setups_time() {
    let dir = Scratch::new("tool-change");
    let prog = dir.file("p.nc", "G99 M03 S600\nT0101\nG00 X40. Z2.\nT0202\nG00 X50.\nT0202\nT0101\nG00 X60.\nM30\n");
    let setup = dir.file("s.toml", "[machine]\ntool_change_s = 4.0\n");
    let seconds = |args: &[&str]| -> f64 {
        let (code, out, err) = common::ncsight(&[&["run", &prog, "--machine", "gsk980tdi"], args].concat());
        assert_eq!(code, 0, "{err}");
        let line = out.lines().find(|l| l.contains("cycle time")).unwrap_or_else(|| panic!("{out}"));
        line.rsplit('(').next().unwrap().trim_end_matches(" s)").trim().parse().unwrap_or_else(|_| panic!("{line}"))
    };
    let plain = seconds(&[]);
    assert!((seconds(&["--setup", &setup]) - plain - 12.0).abs() < 0.01, "{plain}");
    assert!((seconds(&["--setup", &setup, "--param", "tool_change_s=1"]) - plain - 3.0).abs() < 0.01);
    let bad = dir.file("bad.toml", "[machine]\ntool_change_s = -1\n");
    let (code, _, err) = common::ncsight(&["run", &prog, "--machine", "gsk980tdi", "--setup", &bad]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("tool_change_s"), "{err}");
}
