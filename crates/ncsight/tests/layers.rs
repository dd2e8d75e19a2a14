//! The flow in one direction (docs/ARCHITECTURE.md): every module of the core imports only the
//! modules below it. The test reads the code of every source file (comments, strings and
//! character literals taken out), follows every `crate::` path (grouped imports and names the
//! crate root re-exports included) and every `super::` path to the module it names, and fails on
//! one that runs back up. No macro is exported across modules (a macro call writes no path).
//!
//! And no file in interp/ or cycles/ names a controller in its code or writes a parameter
//! number: profiles are data the interpreter asks; it never tests which controller it is.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// The layers, bottom first. A module may use any module of a lower layer, and its own
/// submodules; nothing of its own layer or above.
const LAYERS: &[&[&str]] = &[
    &["source"],
    &["alarm", "motion"],
    &["geom", "codes"],
    &["cycles", "event", "comp"],
    &["profile", "read", "dialect", "setup"],
    &["time", "repair", "explain"],
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

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
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

/// The code of a file with comments, string literals (kept as `""`) and character literals
/// (kept as `' '`) taken out; newlines stay so that line numbers hold.
fn code_of(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c == b'/' && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if c == b'/' && b.get(i + 1) == Some(&b'*') {
            i += 2;
            while i + 1 < b.len() && !(b[i] == b'*' && b[i + 1] == b'/') {
                if b[i] == b'\n' {
                    out.push('\n');
                }
                i += 1;
            }
            i += 2;
        } else if c == b'r'
            && (b.get(i + 1) == Some(&b'"') || (b.get(i + 1) == Some(&b'#') && !b[..i].last().is_some_and(|p| p.is_ascii_alphanumeric() || *p == b'_')))
        {
            // A raw string r"..." or r#"..."#.
            let mut j = i + 1;
            let mut hashes = 0;
            while b.get(j) == Some(&b'#') {
                hashes += 1;
                j += 1;
            }
            if b.get(j) != Some(&b'"') {
                out.push(c as char);
                i += 1;
                continue;
            }
            j += 1;
            let close: Vec<u8> = std::iter::once(b'"').chain(std::iter::repeat_n(b'#', hashes)).collect();
            while j < b.len() && !b[j..].starts_with(&close) {
                if b[j] == b'\n' {
                    out.push('\n');
                }
                j += 1;
            }
            out.push_str("\"\"");
            i = j + close.len();
        } else if c == b'"' {
            i += 1;
            while i < b.len() && b[i] != b'"' {
                if b[i] == b'\\' {
                    i += 1;
                }
                if b.get(i) == Some(&b'\n') {
                    out.push('\n');
                }
                i += 1;
            }
            out.push_str("\"\"");
            i += 1;
        } else if c == b'\'' && (b.get(i + 2) == Some(&b'\'') || (b.get(i + 1) == Some(&b'\\') && b[i..].iter().skip(2).take(10).any(|x| *x == b'\''))) {
            // A character literal ('a', '\n', '\u{..}'); a lifetime has no closing quote.
            let mut j = i + 1;
            if b[j] == b'\\' {
                j += 1;
                while j < b.len() && b[j] != b'\'' {
                    j += 1;
                }
            } else {
                j += 1;
            }
            out.push_str("' '");
            i = j + 1;
        } else {
            out.push(c as char);
            i += 1;
        }
    }
    out
}

/// The module path of a source file: `interp/mod.rs` -> [interp], `cycles/thread/arc.rs` ->
/// [cycles, thread, arc], `lib.rs` -> [].
fn module_path(path: &Path) -> Vec<String> {
    let rel = path.strip_prefix(src()).unwrap();
    let mut parts: Vec<String> = rel.components().map(|c| c.as_os_str().to_str().unwrap().trim_end_matches(".rs").to_string()).collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts
}

/// The names the crate root re-exports, each with the module it comes from (`pub use x::{A, B}`).
fn root_exports() -> HashMap<String, String> {
    let lib = code_of(&std::fs::read_to_string(src().join("lib.rs")).unwrap());
    let mut map = HashMap::new();
    for stmt in lib.split(';') {
        let Some(rest) = stmt.trim().strip_prefix("pub use ") else { continue };
        let module = rest.split("::").next().unwrap().trim().to_string();
        let names = rest.rsplit("::").next().unwrap().trim_matches(|c| c == '{' || c == '}' || c == ' ');
        for n in names.split(',') {
            map.insert(n.trim().to_string(), module.clone());
        }
    }
    map
}

fn ident(s: &str) -> &str {
    let end = s.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(s.len());
    &s[..end]
}

/// The top-level modules a `crate::` path names: `a::x` -> a; `{a::x, b}` -> a, b; a name the
/// root re-exports -> its module.
fn crate_targets(rest: &str, exports: &HashMap<String, String>) -> Vec<String> {
    let rest = rest.trim_start();
    if let Some(group) = rest.strip_prefix('{') {
        // Up to the matching brace; items split at depth 0.
        let mut depth = 1;
        let mut items = vec![String::new()];
        for c in group.chars() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                ',' if depth == 1 => {
                    items.push(String::new());
                    continue;
                }
                _ => {}
            }
            items.last_mut().unwrap().push(c);
        }
        return items.iter().flat_map(|i| crate_targets(i, exports)).collect();
    }
    let name = ident(rest);
    if name.is_empty() || name == "self" {
        return Vec::new();
    }
    let is_module = rest[name.len()..].trim_start().starts_with("::") && name.chars().next().unwrap().is_ascii_lowercase();
    match exports.get(name) {
        Some(m) if !is_module => vec![m.clone()],
        // A type the root does not export: the path was relative to an inline module (`mod
        // tests`), which the compiler has checked; not a top-level module.
        None if name.starts_with(|c: char| c.is_ascii_uppercase()) => Vec::new(),
        _ => vec![name.to_string()],
    }
}

#[test]
fn imports_point_down_the_flow() {
    let mut all = Vec::new();
    files(&src(), &mut all);
    let exports = root_exports();
    let mut wrong = Vec::new();
    for f in &all {
        let path = module_path(f);
        let Some(me) = path.first().cloned() else { continue };
        let mine = layer(&me);
        let code = code_of(&std::fs::read_to_string(f).unwrap());
        let shown = f.strip_prefix(src()).unwrap().display().to_string();
        assert!(!code.contains("macro_export") && !code.contains("macro_use"), "{shown}: a macro exported across modules writes no path the test can follow");
        for (n, line) in code.lines().enumerate() {
            let mut targets = Vec::new();
            let mut at = 0;
            while let Some(k) = line[at..].find("crate::") {
                let start = at + k;
                at = start + "crate::".len();
                // `$crate::` in a macro, or a path like `ncsight_crate::`.
                if line[..start].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_' || c == '$') {
                    continue;
                }
                // A group may run over lines: take the rest of the file from here.
                let offset = code.lines().take(n).map(|l| l.len() + 1).sum::<usize>() + at;
                targets.extend(crate_targets(&code[offset..], &exports));
            }
            at = 0;
            while let Some(k) = line[at..].find("super::") {
                let start = at + k;
                if line[..start].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_') || line[..start].ends_with("super::") {
                    at = start + 1;
                    continue;
                }
                let mut rest = &line[start..];
                let mut ups = 0;
                while let Some(r) = rest.strip_prefix("super::") {
                    ups += 1;
                    rest = r;
                }
                at = line.len() - rest.len();
                // A file's own module is the last part of its path.
                let base = path.len().saturating_sub(ups);
                if base == 0 {
                    let offset = code.lines().take(n).map(|l| l.len() + 1).sum::<usize>() + at;
                    targets.extend(crate_targets(&code[offset..], &exports));
                }
            }
            for t in targets {
                if t != me && layer(&t) >= mine {
                    wrong.push(format!("{shown}:{}: {me} uses {t}", n + 1));
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
    let names = ["gsk", "fanuc", "yasnac", "tdi", "988t", "980t", "lx3"];
    let mut found = Vec::new();
    for f in &all {
        let code = code_of(&std::fs::read_to_string(f).unwrap());
        let shown = f.strip_prefix(src()).unwrap().display().to_string();
        for (n, line) in code.lines().enumerate() {
            // Messages may cite a manual by name (strings are out of `code`); identifiers may
            // not name a controller, the code may not test which one it runs, and a parameter
            // number belongs in the profile's rules.
            let lower = line.to_ascii_lowercase();
            if let Some(name) = names.iter().find(|w| lower.contains(*w)) {
                found.push(format!("{shown}:{}: {name}: {}", n + 1, line.trim()));
            }
            if line.contains("Number(") {
                found.push(format!("{shown}:{}: a parameter number in the code: {}", n + 1, line.trim()));
            }
            let compact: String = line.chars().filter(|c| !c.is_whitespace()).collect();
            if compact.contains(".name==")
                || compact.contains(".title==")
                || compact.contains("matchstep.profile.name")
                || compact.contains("matchprofile.name")
            {
                found.push(format!("{shown}:{}: a test of which controller this is: {}", n + 1, line.trim()));
            }
        }
    }
    assert!(found.is_empty(), "controller names or parameter numbers in interp/ or cycles/ (make them profile data):\n{}", found.join("\n"));
}

/// The test itself finds what it is meant to find.
#[test]
fn the_layer_reader_sees_through_groups_exports_and_super() {
    let exports = root_exports();
    assert_eq!(crate_targets("{interp::Interpreter, motion::Op}", &exports), vec!["interp", "motion"]);
    assert_eq!(crate_targets("Machine;", &exports), vec!["machine"]);
    assert_eq!(crate_targets("program::Program", &exports), vec!["program"]);
    let code = code_of("let s = \"crate::interp\"; // crate::program\nuse crate::motion::Op; let c = '\"'; use crate::geom;");
    assert!(!code.contains("interp") && !code.contains("program") && code.contains("crate::motion") && code.contains("crate::geom"), "{code}");
}

/// Functions of the core and their lengths in lines, longest first: (lines, file:line, name).
/// A function runs from its `fn` to its closing brace (comments and strings taken out first).
fn function_lengths() -> Vec<(usize, String, String)> {
    let mut paths = Vec::new();
    files(&src(), &mut paths);
    let mut out = Vec::new();
    for path in paths {
        let code = code_of(&std::fs::read_to_string(&path).unwrap());
        let b = code.as_bytes();
        let shown = path.strip_prefix(src()).unwrap().display().to_string();
        let mut i = 0;
        while let Some(at) = code[i..].find("fn ").map(|k| k + i) {
            i = at + 3;
            // A whole word `fn`, followed by a name.
            if at > 0 && (b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_') {
                continue;
            }
            let name: String = code[i..].chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            if name.is_empty() {
                continue;
            }
            // Its body's braces (a declaration without a body ends at `;` first).
            let (Some(open), semi) = (code[i..].find('{').map(|k| k + i), code[i..].find(';').map(|k| k + i)) else { continue };
            if semi.is_some_and(|s| s < open) {
                continue;
            }
            let mut depth = 0usize;
            let mut close = open;
            for (k, c) in b.iter().enumerate().skip(open) {
                match c {
                    b'{' => depth += 1,
                    b'}' => {
                        depth -= 1;
                        if depth == 0 {
                            close = k;
                            break;
                        }
                    }
                    _ => {}
                }
            }
            let line = |k: usize| code[..k].matches('\n').count() + 1;
            out.push((line(close) - line(at) + 1, format!("{shown}:{}", line(at)), name));
        }
    }
    out.sort_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
    out
}

/// The longest functions of the core, printed (`cargo test -p ncsight --test layers
/// longest_functions -- --nocapture`, or `tests/longest-functions`): none runs over 100 lines
/// (issue 34 brought them from 21 to none).
#[test]
fn longest_functions() {
    let all = function_lengths();
    for (n, at, name) in all.iter().take(30) {
        println!("{n:5} {at} {name}");
    }
    let over: Vec<_> = all.iter().filter(|f| f.0 > 100).collect();
    println!("{} functions over 100 lines", over.len());
    assert!(over.is_empty(), "functions over 100 lines: {over:?}");
}

/// Adding a cycle family touches one dispatch point in the interpreter (docs/ARCHITECTURE.md,
/// "Adding a cycle"): a one-shot code whose block function is a cycle family's (a module with a
/// file in cycles/) is named in interp/mod.rs by its dispatch arm in `one_shot` and nowhere else;
/// what the interpreter asks of every such code is asked of the code (`GFn` methods) or the
/// profile's rules, never by listing the variant again.
#[test]
fn a_cycle_family_is_named_once_in_the_interpreter() {
    let text = code_of(&std::fs::read_to_string(src().join("interp/mod.rs")).unwrap());
    let body = &text[text.find("fn one_shot(").expect("one_shot in interp/mod.rs")..];
    let body = &body[..body.find("\n}\n").unwrap()];
    let mut cycle_files = Vec::new();
    files(&src().join("cycles"), &mut cycle_files);
    let is_family = |m: &str| cycle_files.iter().any(|p| p.file_stem().is_some_and(|s| s == m));
    let mut families = Vec::new();
    for line in body.lines() {
        let (Some(g), Some(arrow)) = (line.find("GFn::"), line.find("=> ")) else { continue };
        let variant = ident(&line[g + 5..]);
        let module = ident(&line[arrow + 3..]);
        if line[arrow + 3 + module.len()..].starts_with("::") && is_family(module) {
            families.push(variant.to_string());
        }
    }
    assert!(families.len() >= 3, "the families dispatched by one_shot: {families:?}");
    for v in &families {
        let needle = format!("GFn::{v}");
        let uses: Vec<&str> =
            text.lines().filter(|l| l.split(&needle).skip(1).any(|rest| !rest.starts_with(|c: char| c.is_alphanumeric() || c == '_'))).collect();
        assert_eq!(uses.len(), 1, "{needle} is named {} times in interp/mod.rs (once, at its dispatch):\n{}", uses.len(), uses.join("\n"));
    }
}
