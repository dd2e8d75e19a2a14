//! The flow in one direction (docs/ARCHITECTURE.md): every module of the core imports only the
//! modules below it. The test reads every `crate::` path in the source (imports and inline
//! paths alike) and fails on one that runs back up; and no file in interp/ or cycles/ names a
//! controller in its code (profiles are data the interpreter asks; it never tests which
//! controller it is).

use std::path::{Path, PathBuf};

/// The layers, bottom first. A module may use any module of a lower layer, and its own
/// submodules; nothing of its own layer or above.
const LAYERS: &[&[&str]] = &[
    &["source"],
    &["alarm", "motion"],
    &["geom", "codes"],
    &["cycles", "event"],
    &["profile", "read", "dialect"],
    &["time", "repair"],
    &["modal"],
    &["interp"],
    &["machine"],
    &["program"],
    &["stock"],
    &["lib"],
];

fn layer(module: &str) -> usize {
    LAYERS.iter().position(|l| l.contains(&module)).unwrap_or_else(|| panic!("module {module} is in no layer: add it to LAYERS"))
}

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The code of a file without its comments (line comments and doc comments).
fn code_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines().enumerate().map(|(i, l)| {
        let l = match l.find("//") {
            Some(k) if !l[..k].contains('"') => &l[..k],
            _ => l,
        };
        (i + 1, l)
    })
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The top-level module a source file belongs to.
fn module_of(path: &Path) -> String {
    let rel = path.strip_prefix(src()).unwrap();
    let first = rel.components().next().unwrap().as_os_str().to_str().unwrap();
    first.trim_end_matches(".rs").to_string()
}

#[test]
fn imports_point_down_the_flow() {
    let mut all = Vec::new();
    files(&src(), &mut all);
    let mut wrong = Vec::new();
    for f in &all {
        let me = module_of(f);
        let mine = layer(&me);
        let text = std::fs::read_to_string(f).unwrap();
        for (n, line) in code_lines(&text) {
            let mut rest = line;
            while let Some(k) = rest.find("crate::") {
                rest = &rest[k + "crate::".len()..];
                let target: String = rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
                // `crate::{a, b}` and re-exports at the root are names, not modules.
                if target.is_empty() || target.chars().next().unwrap().is_ascii_uppercase() {
                    continue;
                }
                if target != me && layer(&target) >= mine {
                    wrong.push(format!("{}:{n}: {me} uses crate::{target}", f.strip_prefix(src()).unwrap().display()));
                }
            }
        }
    }
    assert!(wrong.is_empty(), "imports that run back up the flow:\n{}", wrong.join("\n"));
}
#[test]
fn interp_and_cycles_name_no_controller() {
    let mut all = Vec::new();
    files(&src().join("interp"), &mut all);
    files(&src().join("cycles"), &mut all);
    let names = ["gsk", "fanuc", "yasnac", "tdi", "988t", "980t", "lx3", "0-m", "0-t"];
    let mut found = Vec::new();
    for f in &all {
        let text = std::fs::read_to_string(f).unwrap();
        for (n, line) in code_lines(&text) {
            // Messages may cite a manual by name (a string); identifiers and parameter numbers
            // may not name a controller.
            let code: String = line.split('"').step_by(2).collect::<Vec<_>>().join(" ");
            let lower = code.to_ascii_lowercase();
            if let Some(name) = names.iter().find(|w| lower.contains(*w)) {
                found.push(format!("{}:{n}: {name}: {}", f.strip_prefix(src()).unwrap().display(), line.trim()));
            }
            if code.contains("ParamKey::Number(") {
                found.push(format!("{}:{n}: a parameter number in the code: {}", f.strip_prefix(src()).unwrap().display(), line.trim()));
            }
        }
    }
    assert!(found.is_empty(), "controller names or parameter numbers in interp/ or cycles/ (make them profile data):\n{}", found.join("\n"));
}
