//! The user documentation stays true: docs/alarms.md is the table of every rule the code has
//! (NCSIGHT_BLESS=1 rewrites it), and README's quick-start example exists.

mod common;
use ncsight::Rule;

#[test]
fn alarm_table_lists_every_rule() {
    let mut s = String::from(
        "# Alarms and warnings\n\nEvery diagnostic has a stable code. On `fanuc0m` the FANUC alarm number is used where one is\n\
known (docs/sources.md); every other case, and every case on the GSK and YASNAC\n\
profiles (no numbered alarm list was found for them), uses the project code. This file is generated\n\
from the code by `NCSIGHT_BLESS=1 cargo test --test docs`.\n\n\
| project code | FANUC code | severity | title |\n|---|---|---|---|\n",
    );
    for r in Rule::ALL {
        let sev = if r.severity() == ncsight::Severity::Alarm { "alarm" } else { "warning" };
        s.push_str(&format!("| {} | {} | {sev} | {} |\n", r.project_code(), r.fanuc_code().unwrap_or("–"), r.title()));
    }
    // Each code explained, in English and Chinese: `ncsight explain CODE` gives the same text.
    s.push_str("\n## Each code explained\n\nAs `ncsight explain CODE` (`--lang zh` for Chinese) gives it.\n");
    for r in Rule::ALL {
        let Some((rule, e)) = ncsight::explain::explain(r.project_code()) else { continue };
        for lang in [ncsight::explain::Lang::En, ncsight::explain::Lang::Zh] {
            s.push_str(&format!("\n```text\n{}```\n", ncsight::explain::render(rule, &e, lang)));
        }
    }
    common::expect_file(&common::root().join("docs/alarms.md"), &s);
}

/// `ncsight explain`: a code or the controller's number, English or Chinese; --list; an unknown
/// code is a usage error (exit 2).
#[test]
fn explain_gives_each_code_in_both_languages() {
    let (code, out, err) = common::ncsight(&["explain", "PS0063", "--lang", "zh"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("NCS-E53 / FANUC PS0063 (报警)") && out.contains("常见原因") && out.contains("错误示例"), "{out}");
    let (code, out, _) = common::ncsight(&["explain", "ncs-w25", "--lang", "en"]);
    assert_eq!(code, 0);
    assert!(out.starts_with("NCS-W25 (warning)") && out.contains("Usual causes"), "{out}");
    let (code, out, _) = common::ncsight(&["explain", "--list"]);
    assert_eq!(code, 0);
    assert_eq!(out.lines().count(), Rule::ALL.len());
    let (code, _, err) = common::ncsight(&["explain", "NCS-E00"]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn readme_quick_start_runs() {
    let readme = std::fs::read_to_string(common::root().join("README.md")).unwrap();
    let line = readme.lines().find(|l| l.starts_with("cargo run --release -- run ")).expect("quick start command in README");
    let args: Vec<&str> = line.trim_start_matches("cargo run --release -- ").split_whitespace().collect();
    let path = common::root().join(args[1]);
    let mut argv: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    argv[1] = path.to_str().unwrap().to_string();
    let refs: Vec<&str> = argv.iter().map(|s| s.as_str()).collect();
    let (code, out, err) = common::ncsight(&refs);
    assert_eq!(code, 0, "{err}");
    assert!(out.lines().count() > 5);
    assert!(readme.contains("cargo test --workspace"));
}

/// docs/commands/operator.md states the cycle time of each seed example: it must be true.
#[test]
fn stated_cycle_times_are_true() {
    let doc = std::fs::read_to_string(common::root().join("docs/commands/operator.md")).unwrap();
    let mut checked = 0;
    // The rows of the cycle-time table: a programme in backquotes, a machine, a time in s.
    for line in doc.lines().filter(|l| l.starts_with("| ") && l.contains("`") && l.trim_end().ends_with(" s |")) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let path = cells[1].split('`').nth(1).unwrap();
        let machine = cells[2];
        let stated: f64 = cells[3].trim_end_matches(" s").parse().unwrap();
        let file = common::root().join(path);
        let (code, out, err) = common::ncsight(&["run", file.to_str().unwrap(), "--machine", machine, "--format", "jsonl"]);
        assert_eq!(code, 0, "{path}: {err}");
        let last: serde_json::Value = serde_json::from_str(out.lines().last().unwrap()).unwrap();
        let t = last["t"].as_f64().unwrap();
        assert!((t - stated).abs() < 0.0005, "{path}: the docs say {stated} s, the run gives {t} s");
        checked += 1;
    }
    assert_eq!(checked, 6);
}

/// `ncsight machines NAME` lists every code of the profile's tables, in order, with the status
/// the profile gives it; docs/codes.md is the same list for all profiles (NCSIGHT_BLESS=1
/// rewrites it).
#[test]
fn machines_lists_every_code_with_its_status_and_source() {
    use ncsight::profile::{self, CodeStatus};
    let status = |s: CodeStatus| match s {
        CodeStatus::Simulated => "simulated",
        CodeStatus::Assumed(_) => "assumed",
        CodeStatus::NotYet => "not yet",
    };
    let mut md = String::from(
        "# Codes by profile\n\nEvery G and M code of each profile's tables, as `ncsight machines NAME` prints them: \
**simulated** (run as the controller runs it), **assumed** (run; a warning or this table names what is assumed), \
**not yet** (the alarm NCS-E38, \"not simulated yet\"). A code that is not listed is not the controller's: \
IMPROPER G-CODE (G), a machine builder's M code (warning NCS-W05). The source says where the code comes from; \
\"inferred\" marks a table taken from the nearest controller whose manual was at hand. This file is generated \
by `NCSIGHT_BLESS=1 cargo test --test docs`.\n",
    );
    for p in profile::all() {
        let (code, out, err) = common::ncsight(&["machines", p.name]);
        assert_eq!(code, 0, "{err}");
        let listed: Vec<&str> = out.lines().filter(|l| l.starts_with("  G") || l.starts_with("  M")).collect();
        let mut want = Vec::new();
        md.push_str(&format!("\n## {} ({})\n\n| code | status | meaning | source |\n|---|---|---|---|\n", p.name, p.title));
        for t in p.g_codes {
            for g in t.codes {
                let s = p.code_status(g);
                let why = if let CodeStatus::Assumed(a) = s { format!(" ({a})") } else { String::new() };
                want.push((g.name.to_string(), status(s)));
                md.push_str(&format!("| {} | {} | {}{why} | {} |\n", g.name, status(s), g.meaning, t.source));
            }
        }
        for t in p.m_codes {
            for m in t.codes {
                let s = m.function.status();
                let why = if let CodeStatus::Assumed(a) = s { format!(" ({a})") } else { String::new() };
                want.push((format!("M{:02}", m.code), status(s)));
                md.push_str(&format!("| M{:02} | {} | {}{why} | {} |\n", m.code, status(s), m.meaning, t.source));
            }
        }
        assert_eq!(listed.len(), want.len(), "{}: {out}", p.name);
        for (line, (code, st)) in listed.iter().zip(&want) {
            let mut f = line.split_whitespace();
            assert_eq!(f.next(), Some(code.as_str()), "{}: {line}", p.name);
            assert!(line[2 + 8..].starts_with(st), "{}: {line} (want {st})", p.name);
            assert!(line.ends_with(']'), "{}: a source in brackets: {line}", p.name);
        }
    }
    common::expect_file(&common::root().join("docs/codes.md"), &md);
}
