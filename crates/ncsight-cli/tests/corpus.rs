//! Every programme of the corpus of real programmes written by others (the folder named by
//! `NCSIGHT_CORPUS`, kept outside the repository; without it these tests are skipped, said in one
//! line) goes through `ncsight check` on the profile closest to its dialect, never panics, and
//! gives the diagnostics committed in tests/corpus/<file>.check (NCSIGHT_BLESS=1 rewrites them).

mod common;
mod roundtrip;

/// The tests of this file, named in the line that says they were skipped.
const TESTS: &str = "corpus_checks_give_clear_answers, corpus_programme_libraries_run_from_each_entry, corpus_programmes_expand_for_linuxcnc_and_grbl";

fn corpus() -> Option<std::path::PathBuf> {
    common::corpus(TESTS)
}

/// Milling programmes go to fanuc0m (a FANUC 0i mill's to fanuc0i-mf), FANUC 0i-T lathe
/// programmes (Doosan shop, the ICNC and CNCLearn courses) to fanuc0i-tf, the Haas lathe files
/// written FANUC-style to fanuc0t, the rest (GSK shop notes, LinuxCNC and other dialects) to the
/// GSK lathe.
fn machine_for(name: &str) -> &'static str {
    const FANUC_0I_LATHE: &[&str] = &["doosan-lynx300__", "icnc__", "cnclearn__2", "cnclearn__1002"];
    if FANUC_0I_LATHE.iter().any(|p| name.starts_with(p)) {
        return "fanuc0i-tf";
    }
    const FANUC_LATHE: &[&str] = &["enier-cnc__weld", "cadekiely-haas__Caliper"];
    if FANUC_LATHE.iter().any(|p| name.starts_with(p)) {
        return "fanuc0t";
    }
    if name == "cnclearn__O0001.txt" {
        return "fanuc0i-mf";
    }
    // A FANUC 0i thread grinder (X, Z, C) written with G90/G91 and G92 as a coordinate preset:
    // the FANUC 0-M's G-code system is the nearest (its C axis waits for issue 19).
    if name.starts_with("sk7420-fanuc__") {
        return "fanuc0m";
    }
    const MILL: &[&str] = &[
        "printhor-asyncgcode__example3_nist_cycle_test.gcode",
        "enier-cnc__1006.nc",
        "enier-cnc__slot_assembly_11.nc",
        "cadekiely-haas__4x3_block_o78244.nc",
        "z64-cncbook__stdbc.nc",
        "cnclearn__O0001.txt",
        "gcodeworkshop__SINUMERIK850.nc",
        "linuxcnc__mmount.ngc",
        "linuxcnc__tests-interp-g81__g17-g98-g81.ngc",
    ];
    if MILL.contains(&name) {
        "fanuc0m"
    } else {
        "gsk980tdi"
    }
}

/// Settings a programme's own machine evidently had: the ICNC course programmes write lengths
/// without a decimal point as millimetres (`X55`, `R3`), a FANUC with calculator-type input.
fn params_for(name: &str) -> &'static [&'static str] {
    if name.starts_with("icnc__") {
        &["--param", "3401.0=1"]
    } else {
        &[]
    }
}

#[test]
fn corpus_checks_give_clear_answers() {
    let Some(corpus) = corpus() else { return };
    let mut files: Vec<_> = std::fs::read_dir(&corpus).unwrap().map(|e| e.unwrap().path()).collect();
    files.retain(|p| {
        let n = p.file_name().unwrap().to_str().unwrap();
        n != "INDEX.md" && !n.ends_with("expected.txt")
    });
    files.sort();
    assert!(files.len() >= 25, "corpus looks incomplete: {} files", files.len());
    let out_dir = common::root().join("tests/corpus");
    for f in files {
        let name = f.file_name().unwrap().to_str().unwrap().to_string();
        let machine = machine_for(&name);
        // Run from the corpus folder so the file names in the output do not depend on paths.
        let shown = format!("corpus/{name}");
        let mut params: Vec<String> = params_for(&name).iter().map(|p| p.to_string()).collect();
        // The machine a programme is written for, where it has axes the profile's default lacks
        // (a 4th axis, a C axis): tests/corpus/<file>.toml.
        let setup = format!("tests/corpus/{name}.toml");
        if common::root().join(&setup).is_file() {
            params.extend(["--setup".to_string(), setup]);
        }
        let run_params: Vec<String> =
            params.iter().map(|p| if p.starts_with("tests/") { common::root().join(p).to_str().unwrap().to_string() } else { p.clone() }).collect();
        let params: Vec<&str> = params.iter().map(String::as_str).collect();
        let args: Vec<&str> = ["check", f.to_str().unwrap(), "--machine", machine].into_iter().chain(run_params.iter().map(String::as_str)).collect();
        let (code, out, err) = common::ncsight(&args);
        assert!(code == 0 || code == 1, "{name}: exit {code}: {err}");
        let out = out.replace(f.to_str().unwrap(), &shown);
        assert!(out.contains(&format!("{shown}: ")), "{name}: no summary line");
        common::expect_file(
            &out_dir.join(format!("{name}.check")),
            &format!("$ ncsight check {shown} --machine {machine}{}\n{out}", params.iter().map(|p| format!(" {p}")).collect::<String>()),
        );
        let args: Vec<&str> =
            ["run", f.to_str().unwrap(), "--machine", machine, "--format", "jsonl"].into_iter().chain(run_params.iter().map(String::as_str)).collect();
        let (code, _, err) = common::ncsight(&args);
        assert!(code == 0 || code == 1, "{name}: run exit {code}: {err}");
        // The stock simulation: its exit status, the stock or block it guessed and every
        // finding, in tests/corpus/<file>.simulate (why each finding is real, or what it cannot
        // know: tests/corpus/README.md).
        let args: Vec<&str> = ["simulate", f.to_str().unwrap(), "--machine", machine].into_iter().chain(run_params.iter().map(String::as_str)).collect();
        let (code, out, err) = common::ncsight(&args);
        assert!(matches!(code, 0 | 1 | 3), "{name}: simulate exit {code}: {err}");
        let kept: Vec<&str> = out
            .lines()
            .chain(err.lines())
            .filter(|l| {
                l.starts_with("finding")
                    || l.starts_with("stock guessed")
                    || l.starts_with("block guessed")
                    || l.starts_with("ncsight: the stock was not simulated")
            })
            .collect();
        common::expect_file(
            &out_dir.join(format!("{name}.simulate")),
            &format!(
                "$ ncsight simulate {shown} --machine {machine}{}
exit {code}
{}",
                params.iter().map(|p| format!(" {p}")).collect::<String>(),
                kept.iter().map(|l| format!("{l}\n")).collect::<String>()
            ),
        );
    }
}

/// Files of many programmes whose first one calls none of the others: each programme a shop
/// runs is checked as the main one (`--main`), so the macros and calls in them are read and
/// run as far as their content allows (tests/corpus/<file>.O<n>.check; why each stops is in
/// tests/corpus/README.md).
#[test]
fn corpus_programme_libraries_run_from_each_entry() {
    const ENTRIES: &[(&str, &str, &[&str])] = &[
        // The grinding machine's MAIN, its axis test loops (endless on the machine: the runaway
        // guard, set low to keep the test quick), tool setting and the grinding cycle.
        ("sk7420-fanuc__ALL-PROG.TXT", "0100", &[]),
        ("sk7420-fanuc__ALL-PROG.TXT", "0800", &["--max-blocks", "20000"]),
        ("sk7420-fanuc__ALL-PROG.TXT", "8100", &[]),
        ("sk7420-fanuc__ALL-PROG.TXT", "8200", &[]),
    ];
    let Some(corpus) = corpus() else { return };
    let out_dir = common::root().join("tests/corpus");
    for (name, main, extra) in ENTRIES {
        let f = corpus.join(name);
        let machine = machine_for(name);
        let shown = format!("corpus/{name}");
        let setup = format!("tests/corpus/{name}.toml");
        let setup_path = common::root().join(&setup);
        let with_setup: Vec<&str> = if setup_path.is_file() { vec!["--setup", setup_path.to_str().unwrap()] } else { vec![] };
        let args: Vec<&str> = ["check", f.to_str().unwrap(), "--machine", machine, "--main", main]
            .into_iter()
            .chain(extra.iter().copied())
            .chain(with_setup.iter().copied())
            .collect();
        let (code, out, err) = common::ncsight(&args);
        assert!(code == 0 || code == 1, "{name} O{main}: exit {code}: {err}");
        let out = out.replace(f.to_str().unwrap(), &shown);
        let mut shown_args: String = extra.iter().map(|a| format!(" {a}")).collect();
        if setup_path.is_file() {
            shown_args.push_str(&format!(" --setup {setup}"));
        }
        common::expect_file(
            &out_dir.join(format!("{name}.O{main}.check")),
            &format!("$ ncsight check {shown} --machine {machine} --main {main}{shown_args}\n{out}"),
        );
    }
}

/// The corpus programmes that run to their end expand for LinuxCNC (read back by rs274 as the
/// original moves) and for grbl (its words only; their threads alarm).
#[test]
fn corpus_programmes_expand_for_linuxcnc_and_grbl() {
    let Some(corpus) = corpus() else { return };
    let programmes: Vec<roundtrip::Programme> = ["doosan-lynx300__O0201.nc", "doosan-lynx300__O3380.nc"]
        .into_iter()
        .map(|name| (name.to_string(), corpus.join(name), vec!["--machine".into(), "fanuc0t".into()]))
        .collect();
    let (files, compared) = roundtrip::linuxcnc_round_trip(&programmes);
    if roundtrip::rs274().is_some() {
        assert!(files == 2 && compared > 100, "only {files} programmes, {compared} calls compared");
    }
    let (refused, lines) = roundtrip::grbl_check(&programmes);
    assert!(refused >= 1 && lines > 100, "{refused} threaded programmes refused, {lines} lines checked");
}
