//! Helpers shared by the CLI's integration tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// The repository root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

/// The corpus of real programmes written by others, kept outside the repository (docs/reference/
/// interface.md, "Stand-alone tests"): the folder named by `NCSIGHT_CORPUS`, else the `corpus`
/// folder of the project's library beside the repository where CI keeps it. Absent, the tests
/// that read it are skipped, said once per test binary in one line naming them (written past the
/// test harness's capture, so a passing run shows it); with `NCSIGHT_REQUIRE_CORPUS=1` (CI) its
/// absence fails.
pub fn corpus(tests: &str) -> Option<PathBuf> {
    let dir = match std::env::var_os("NCSIGHT_CORPUS") {
        Some(d) => PathBuf::from(d),
        None => root().join("..").join("shared").join("corpus"),
    };
    if dir.is_dir() {
        return Some(dir);
    }
    let required = std::env::var_os("NCSIGHT_REQUIRE_CORPUS").is_some_and(|v| v == "1");
    assert!(!required, "NCSIGHT_REQUIRE_CORPUS=1 but the corpus of real programmes is not at {}: set NCSIGHT_CORPUS", dir.display());
    static SAID: std::sync::Once = std::sync::Once::new();
    SAID.call_once(|| {
        use std::io::Write;
        let place = match std::env::var_os("NCSIGHT_CORPUS") {
            Some(_) => format!("at NCSIGHT_CORPUS={}", dir.display()),
            None => "(NCSIGHT_CORPUS names its folder)".to_string(),
        };
        let line = format!("skipped: the corpus tests ({tests}): no corpus of real programmes {place}\n");
        let _ = std::io::stderr().lock().write_all(line.as_bytes());
    });
    None
}

/// Run the command line in-process: (exit status, stdout, stderr).
pub fn ncsight(args: &[&str]) -> (i32, String, String) {
    let mut out = Vec::new();
    let mut err = Vec::new();
    let mut full = vec!["ncsight".to_string()];
    full.extend(args.iter().map(|s| s.to_string()));
    let code = ncsight_cli::main_with(full.into_iter().map(Into::into), &mut out, &mut err);
    (code, String::from_utf8_lossy(&out).into_owned(), String::from_utf8_lossy(&err).into_owned())
}

/// Compare with an expected file; with NCSIGHT_BLESS=1 write it instead.
pub fn expect_file(path: &Path, actual: &str) {
    if std::env::var_os("NCSIGHT_BLESS").is_some() {
        std::fs::write(path, actual).unwrap();
        return;
    }
    let expected = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e} (run with NCSIGHT_BLESS=1 to create it)", path.display()));
    if expected != actual {
        let diff: Vec<String> = expected
            .lines()
            .zip(actual.lines())
            .enumerate()
            .filter(|(_, (a, b))| a != b)
            .take(5)
            .map(|(i, (a, b))| format!("line {}:\n  expected: {a}\n  actual:   {b}", i + 1))
            .collect();
        panic!("{} differs ({} vs {} lines):\n{}", path.display(), expected.lines().count(), actual.lines().count(), diff.join("\n"));
    }
}

/// The motion calls of a canonical-call text (ncsight's `--format canon` or `rs274 -g`):
/// STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED and DWELL with their numbers; a straight move to
/// where the last one ended (rs274 prints some, ncsight leaves them out) is dropped.
pub fn motion_calls(text: &str) -> Vec<(String, Vec<f64>)> {
    let mut last: Option<Vec<f64>> = None;
    let mut out = Vec::new();
    for (name, nums) in parse_calls(text) {
        if name.starts_with("STRAIGHT_") {
            if last.as_ref() == Some(&nums) {
                continue;
            }
            last = Some(nums.clone());
        } else if name == "ARC_FEED" {
            last = None;
        }
        out.push((name, nums));
    }
    out
}

pub fn parse_calls(text: &str) -> Vec<(String, Vec<f64>)> {
    text.lines()
        .filter(|l| ["STRAIGHT_TRAVERSE(", "STRAIGHT_FEED(", "ARC_FEED(", "DWELL("].iter().any(|p| l.starts_with(p)))
        .map(|l| {
            let (name, rest) = l.split_once('(').unwrap();
            let nums = rest.trim_end_matches(')').split(',').map(|n| n.trim().parse::<f64>().unwrap()).collect();
            (name.to_string(), nums)
        })
        .collect()
}

/// Two lists of motion calls are the same, each number within 0.0002 (the four decimals of
/// the canonical text); the number of calls compared.
pub fn same_calls(what: &str, ours: &[(String, Vec<f64>)], theirs: &[(String, Vec<f64>)]) -> usize {
    assert_eq!(ours.len(), theirs.len(), "{what}: {} calls vs rs274's {}", ours.len(), theirs.len());
    for (i, ((n1, v1), (n2, v2))) in ours.iter().zip(theirs).enumerate() {
        assert_eq!(n1, n2, "{what} call {}", i + 1);
        assert_eq!(v1.len(), v2.len(), "{what} call {}", i + 1);
        for (a, b) in v1.iter().zip(v2) {
            assert!((a - b).abs() <= 2e-4, "{what} call {}: {n1} {v1:?} vs rs274 {v2:?}", i + 1);
        }
    }
    ours.len()
}

/// A folder of its own under the system's temporary folder, removed when dropped.
pub struct Scratch(pub PathBuf);

impl Scratch {
    /// `ncsight-NAME-PID` under the temporary folder, empty.
    pub fn new(name: &str) -> Scratch {
        let p = std::env::temp_dir().join(format!("ncsight-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&p);
        std::fs::create_dir_all(&p).unwrap();
        Scratch(p)
    }

    /// Write `text` to the file `name` in it; its path.
    pub fn file(&self, name: &str, text: &str) -> String {
        let p = self.0.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    }

    /// The path of `name` in it.
    pub fn path(&self, name: &str) -> String {
        self.0.join(name).to_str().unwrap().to_string()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
