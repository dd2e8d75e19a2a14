//! Streaming: `check` and `run -o` on a ~50 MB programme must keep their peak memory far below
//! the programme's size, so a regression to whole-file buffering (or to keeping every record)
//! fails here. The peak (VmHWM) is read from /proc while the built binary runs.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Duration;

/// Bytes of programme text generated.
const PROGRAMME_BYTES: usize = 50 << 20;
/// Peak resident memory allowed, KiB: a few MiB of binary and buffers, nothing per line.
const PEAK_LIMIT_KB: u64 = 32 << 10;

/// A G01 programme of about `bytes` bytes with varied coordinates.
fn write_programme(path: &Path, bytes: usize) {
    let mut chunk = String::new();
    for i in 0..1000u32 {
        let (x, y, z) = (f64::from(i % 97) * 0.25, f64::from(i % 101) * 0.125, -f64::from(i % 7) * 0.5);
        chunk.push_str(&format!("X{x:.3} Y{y:.3} Z{z:.3}\n"));
    }
    let mut f = std::io::BufWriter::new(std::fs::File::create(path).unwrap());
    f.write_all(b"G21 G17 G90 G00 X0. Y0. Z10.\nG01 F500.\n").unwrap();
    for _ in 0..bytes.div_ceil(chunk.len()) {
        f.write_all(chunk.as_bytes()).unwrap();
    }
    f.write_all(b"M30\n").unwrap();
}

/// Run the binary and return its exit status and its peak resident memory in KiB, polled from
/// /proc/<pid>/status (the last value read before it exits).
fn peak_kb(args: &[&str]) -> (i32, u64) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ncsight")).args(args).stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap();
    let status_path = format!("/proc/{}/status", child.id());
    let mut peak = 0;
    loop {
        if let Ok(text) = std::fs::read_to_string(&status_path) {
            let hwm = text.lines().find_map(|l| l.strip_prefix("VmHWM:")).and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok());
            peak = peak.max(hwm.unwrap_or(0));
        }
        if let Some(status) = child.try_wait().unwrap() {
            return (status.code().unwrap_or(-1), peak);
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn check_and_run_stream_a_50_mb_programme() {
    let dir = std::env::temp_dir().join(format!("ncsight-memory-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let programme = dir.join("big.nc");
    write_programme(&programme, PROGRAMME_BYTES);
    let out = dir.join("big.canon");
    let p = programme.to_str().unwrap();
    let runs: [&[&str]; 2] = [&["check", p, "--machine", "fanuc0m"], &["run", p, "--machine", "fanuc0m", "--format", "canon", "-o", out.to_str().unwrap()]];
    let mut results = Vec::new();
    for args in runs {
        let (code, kb) = peak_kb(args);
        results.push((args[0], code, kb));
    }
    let output_bytes = std::fs::metadata(&out).map(|m| m.len()).unwrap_or(0);
    std::fs::remove_dir_all(&dir).unwrap();
    for (command, code, kb) in results {
        eprintln!("{command}: peak {kb} KiB");
        assert_eq!(code, 0, "{command} failed");
        assert!(kb > 0, "{command}: no VmHWM read from /proc");
        assert!(kb < PEAK_LIMIT_KB, "{command} peaked at {kb} KiB on a {} MiB programme (limit {PEAK_LIMIT_KB} KiB)", PROGRAMME_BYTES >> 20);
    }
    assert!(output_bytes > PROGRAMME_BYTES as u64, "run wrote {output_bytes} bytes");
}

/// `simulate` holds none of the programme's records (it runs the programme twice: a survey,
/// then the cut): about 600,000 moves, past the 500,000 records it used to refuse, in a peak
/// far below what holding them would take (about 120 MB at some 200 bytes a record).
#[test]
fn simulate_streams_a_programme_of_600000_moves() {
    let dir = std::env::temp_dir().join(format!("ncsight-memory-sim-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let programme = dir.join("big.nc");
    // About 21 bytes a line: 600 chunks of 1,000 moves.
    write_programme(&programme, 600 * 21_000);
    let lines = std::fs::read_to_string(&programme).unwrap().lines().count();
    let p = programme.to_str().unwrap();
    let (code, kb) = peak_kb(&["simulate", p, "--machine", "fanuc0m", "--stock", "40x30x10", "--resolution", "1"]);
    std::fs::remove_dir_all(&dir).unwrap();
    eprintln!("simulate: {lines} lines, peak {kb} KiB");
    assert!(lines > 500_000, "{lines}");
    // 0: nothing found; 3: a finding (the assumed mill's cuts); never the old refusal (2).
    assert!(code == 0 || code == 3, "simulate exited {code}");
    assert!(kb > 0 && kb < PEAK_LIMIT_KB, "simulate peaked at {kb} KiB (limit {PEAK_LIMIT_KB} KiB)");
}

/// `text` run on `machine` with its canonical calls written to a file: the exit status, the peak
/// resident memory in KiB and the calls.
fn run_canon(machine: &str, text: &str) -> (i32, u64, String) {
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("ncsight-memory-canon-{}-{k}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (programme, out) = (dir.join("programme.nc"), dir.join("programme.canon"));
    std::fs::write(&programme, text).unwrap();
    let (code, kb) = peak_kb(&["run", programme.to_str().unwrap(), "--machine", machine, "--format", "canon", "-o", out.to_str().unwrap()]);
    let calls = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    (code, kb, calls)
}

/// A drilling block of any number of pecks runs (issue 34): G83 with Q0.001 over 1,000 mm is a
/// million pecks, three million records, which a FANUC runs and ncsight used to refuse
/// (NCS-E40). Its holes are made as they are handed on, so the peak stays far below what holding
/// them would take (some 700 MB): under 16 MiB.
#[test]
fn a_million_pecks_run_in_constant_memory() {
    let (code, kb, text) = run_canon("fanuc0m", "G21 G17 G90 G00 X0 Y0 Z10.\nS1000 M03\nF500.\nG98 G83 X10. Y10. Z-1000. R2. Q0.001\nG80\nG00 Z10.\nM30\n");
    let lines = text.lines().count();
    eprintln!("a million pecks: peak {kb} KiB, {lines} canonical calls");
    assert_eq!(code, 0);
    // Each peck: the feed down, the rapid back to R, the rapid down to the clearance above the
    // last depth (the first peck has none); then the approach, the return, the programme's moves.
    assert!(lines > 3_000_000, "{lines} lines");
    assert!(text.contains("STRAIGHT_FEED(10.0000, 10.0000, -1000.0000"), "the bottom is reached");
    assert!(kb > 0 && kb < 16 << 10, "peak {kb} KiB");
}

/// A roughing of any number of levels runs (issue 34): G71 with Δd 0.001 mm over 101 mm is
/// 101,000 levels, some 400,000 records, which a GSK980TDi runs and ncsight used to refuse
/// (NCS-E40). Its moves are made as they are handed on, so the peak stays that of a small
/// programme: under 16 MiB.
#[test]
fn a_roughing_of_a_hundred_thousand_levels_runs_in_constant_memory() {
    let levels = |depth: &str| {
        format!(
            "G97 S500 M03 T0101\nG99 G00 X202. Z2.\nG71 U{depth} R0.0005\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X0.\nG01 Z-10.\nN20 X202.\nG00 X250. Z50.\nM30\n"
        )
    };
    // A fifth of the levels (Δd 0.005: 20,200 levels, past the point where they are deferred):
    // the peak does not grow with the block's moves.
    let (_, kb_fifth, _) = run_canon("gsk980tdi", &levels("0.005"));
    let (code, kb, text) = run_canon("gsk980tdi", &levels("0.001"));
    eprintln!("a fifth of the levels: peak {kb_fifth} KiB");
    assert!(kb < kb_fifth + 2048, "peak {kb} KiB for five times the levels of one at {kb_fifth} KiB");
    let lines = text.lines().count();
    eprintln!("a hundred thousand levels: peak {kb} KiB, {lines} canonical calls");
    assert_eq!(code, 0);
    // Each level: to the level, the cut, the back-off, the rapid back.
    assert!(lines > 400_000, "{lines} lines");
    // The last level (X0.2015 as a radius, 0.0005 above B') and the finishing pass along the contour.
    assert!(text.contains("STRAIGHT_FEED(0.2000, 0.0000, -9.9000"), "the contour's face is cut");
    assert!(kb > 0 && kb < 16 << 10, "peak {kb} KiB");
}

/// An involute of 90 turns (G03.2 on the 0i-MF: 316,955 chords, past the 100,000 records a held
/// block keeps): its chords are made as they are handed on, so the peak stays that of a small
/// programme, under 16 MiB.
#[test]
fn an_involute_of_ninety_turns_runs_in_constant_memory() {
    let roll = 90.0 * std::f64::consts::TAU;
    let (s, c) = roll.sin_cos();
    let end = format!("X{:.4} Y{:.4}", 10.0 * (c + roll * s), 10.0 * (s - roll * c));
    let (code, kb, text) = run_canon("fanuc0i-mf", &format!("G21 G90 G17 G00 X10. Y0. Z5.\nG01 F800.\nG03.2 {end} I-10. J0. R10.\nM30\n"));
    let lines = text.lines().count();
    eprintln!("an involute of 90 turns: peak {kb} KiB, {lines} canonical calls");
    assert_eq!(code, 0);
    assert!(lines > 316_955, "{lines} lines");
    assert!(kb > 0 && kb < 16 << 10, "peak {kb} KiB");
}
