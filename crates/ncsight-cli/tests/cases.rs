//! The golden traces and the bad programmes, one test each, run by name (`cargo test -p
//! ncsight-cli --test cases -- golden::gsk980tdi_o0012`, or `-- bad::` for all bad programmes):
//!
//! - `golden::<case>`: tests/golden/<case>/ holds `input.nc`, `args` (the machine and
//!   parameters, one line), perhaps `setup.toml`, and `expected.jsonl`, the trace `ncsight run
//!   --format jsonl` must print. Each case says in its comments what the manual says and how the
//!   trace was checked by hand. A difference is told record by record: the first record whose
//!   motion differs (kind, positions, feeds, lines: everything but the times), and, apart from
//!   it, the first whose time differs and by how much, so a change of the time model is seen as
//!   one. NCSIGHT_BLESS=1 rewrites the expected files (review the diff before committing).
//! - `bad::<file>`: tests/bad/<file>.nc begins with `(expect CODE line L col C on MACHINE)` (a
//!   same-name `.toml` is its setup, a `.args` more arguments); `run` must stop with that alarm
//!   at that place, and `check` must report it and exit 1.

mod common;

use libtest_mimic::{Arguments, Failed, Trial};
use std::path::{Path, PathBuf};

fn main() {
    let args = Arguments::from_args();
    let mut trials = Vec::new();
    for case in sorted(&common::root().join("tests/golden"), |p| p.is_dir()) {
        let name = format!("golden::{}", case.file_name().unwrap().to_str().unwrap());
        trials.push(Trial::test(name, move || golden(&case)));
    }
    for file in sorted(&common::root().join("tests/bad"), |p| p.extension().is_some_and(|x| x == "nc")) {
        let name = format!("bad::{}", file.file_stem().unwrap().to_str().unwrap());
        trials.push(Trial::test(name, move || bad(&file)));
    }
    libtest_mimic::run(&args, trials).exit();
}

fn sorted(dir: &Path, keep: impl Fn(&Path) -> bool) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).filter(|p| keep(p)).collect();
    v.sort();
    v
}

/// A golden case: its trace as expected, or the first difference of motion and of time.
fn golden(case: &Path) -> Result<(), Failed> {
    let input = case.join("input.nc");
    let args = std::fs::read_to_string(case.join("args")).unwrap_or_default();
    let mut argv = vec!["run", input.to_str().unwrap(), "--format", "jsonl"];
    argv.extend(args.split_whitespace());
    // A case with a machine setup keeps it beside its programme.
    let setup = case.join("setup.toml");
    if setup.is_file() {
        argv.extend(["--setup", setup.to_str().unwrap()]);
    }
    let (code, out, err) = common::ncsight(&argv);
    let expected_code = if out.lines().last().is_some_and(|l| l.contains("\"kind\":\"alarm\"")) { 1 } else { 0 };
    if code != expected_code {
        return Err(format!("exit status {code}, {expected_code} expected: {err}").into());
    }
    let path = case.join("expected.jsonl");
    if std::env::var_os("NCSIGHT_BLESS").is_some() {
        std::fs::write(&path, &out).map_err(|e| e.to_string())?;
        return Ok(());
    }
    let expected = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e} (NCSIGHT_BLESS=1 writes it)", path.display()))?;
    match differences(&expected, &out) {
        None => Ok(()),
        Some(told) => Err(format!("{}\n(NCSIGHT_BLESS=1 rewrites {} once the change is checked)", told, path.display()).into()),
    }
}

/// A JSONL line without its times (`t`, and the fields that are durations), and its time.
fn split_time(line: &str) -> (serde_json::Value, Option<f64>) {
    let mut v: serde_json::Value = serde_json::from_str(line).unwrap_or(serde_json::Value::String(line.to_string()));
    let t = v.get("t").and_then(|t| t.as_f64());
    if let Some(o) = v.as_object_mut() {
        o.remove("t");
    }
    (v, t)
}

/// How two traces differ, for a person: the number of lines, the first line whose motion
/// differs (everything but its time), and the first whose time differs; None when equal.
fn differences(expected: &str, actual: &str) -> Option<String> {
    if expected == actual {
        return None;
    }
    let (e, a): (Vec<&str>, Vec<&str>) = (expected.lines().collect(), actual.lines().collect());
    let mut told = Vec::new();
    if e.len() != a.len() {
        told.push(format!("{} lines, {} expected", a.len(), e.len()));
    }
    let pairs = || e.iter().zip(&a).enumerate().map(|(k, (x, y))| (k, split_time(x), split_time(y), *x, *y));
    if let Some((k, _, _, x, y)) = pairs().find(|(_, (ex, _), (ay, _), _, _)| ex != ay) {
        told.push(format!("motion differs first at line {}:\n  expected {x}\n  got      {y}", k + 1));
    } else if e.len() != a.len() {
        let (k, extra) = if a.len() > e.len() { (e.len(), a[e.len()]) } else { (a.len(), e[a.len()]) };
        told.push(format!("line {} is {} only: {extra}", k + 1, if a.len() > e.len() { "got" } else { "expected" }));
    }
    if let Some((k, (_, te), (_, ta), _, _)) = pairs().find(|(_, (_, te), (_, ta), _, _)| te != ta) {
        let by = match (te, ta) {
            (Some(x), Some(y)) => format!("{:+.4} s", y - x),
            _ => "one has no time".to_string(),
        };
        told.push(format!(
            "time differs first at line {} ({by}; the motion there {})",
            k + 1,
            if pairs().nth(k).is_some_and(|(_, (x, _), (y, _), _, _)| x == y) { "is the same" } else { "differs too" }
        ));
    }
    if told.is_empty() {
        told.push("the text differs (spacing or number format)".into());
    }
    Some(told.join("\n"))
}

/// A bad programme: `run` stops with its alarm at its place, `check` reports it.
fn bad(f: &Path) -> Result<(), Failed> {
    let text = std::fs::read(f).map_err(|e| e.to_string())?;
    let first = String::from_utf8_lossy(text.split(|&b| b == b'\n').next().unwrap_or_default()).into_owned();
    let spec: Vec<&str> = first.trim().trim_start_matches('(').trim_end_matches(')').split_whitespace().collect();
    if !(spec.len() == 8 && spec[0] == "expect" && spec[2] == "line" && spec[4] == "col" && spec[6] == "on") {
        return Err("the first line must be (expect CODE line L col C on MACHINE)".into());
    }
    let (code, line, col, machine) = (spec[1], spec[3], spec[5], spec[7]);
    let path = f.to_str().unwrap();
    let setup_file = f.with_extension("toml");
    let mut more: Vec<&str> = if setup_file.is_file() { vec!["--setup", setup_file.to_str().unwrap()] } else { vec![] };
    // More arguments (a setting the programme's machine has) in `<name>.args`.
    let extra = std::fs::read_to_string(f.with_extension("args")).unwrap_or_default();
    more.extend(extra.split_whitespace());
    let with = |args: &[&str]| -> Vec<String> { args.iter().chain(more.iter()).map(|s| s.to_string()).collect() };
    let run_args = with(&["run", path, "--machine", machine, "--format", "jsonl"]);
    let (status, out, err) = common::ncsight(&run_args.iter().map(String::as_str).collect::<Vec<_>>());
    if status != 1 {
        return Err(format!("run must stop on an alarm (exit {status})\n{out}{err}").into());
    }
    let last = out.lines().last().unwrap_or_default();
    let v: serde_json::Value = serde_json::from_str(last).map_err(|e| format!("{e}: {last}"))?;
    let got = (v["kind"].as_str().unwrap_or(""), v["code"].as_str().unwrap_or(""), v["line"].to_string(), v["col"].to_string());
    if got != ("alarm", code, line.to_string(), col.to_string()) || v["message"].as_str().unwrap_or("").is_empty() {
        return Err(format!("expected alarm {code} at line {line} col {col}, got: {last}").into());
    }
    let check_args = with(&["check", path, "--machine", machine]);
    let (status, out, _) = common::ncsight(&check_args.iter().map(String::as_str).collect::<Vec<_>>());
    if status != 1 || !out.contains(&format!(":{line}:{col}: alarm[{code}]")) {
        return Err(format!("check must report it and exit 1 (exit {status}):\n{out}").into());
    }
    Ok(())
}
