//! `ncsight report`: one self-contained page; programme text never becomes markup.

mod common;

#[test]
fn report_is_self_contained_and_escapes_programme_text() {
    let dir = std::env::temp_dir().join(format!("ncsight-report-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("evil.nc");
    std::fs::write(&prog, "(<script>alert(1)</script>)\n(<img src=x onerror=alert(2)>)\nG0 X10 Z5\nM30\n").unwrap();
    let out = dir.join("r.html");
    let (code, _, err) = common::ncsight(&["report", prog.to_str().unwrap(), "--machine", "gsk980tdi", "-o", out.to_str().unwrap()]);
    // The second comment closes at `alert(2)`: what follows is an alarm on the controller too; the
    // page is written all the same.
    assert!(code == 0 || code == 1, "{err}");
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    // Exactly the page's own four script elements (the job, the engine, three.js, the page's
    // script), and no markup from the programme.
    assert_eq!(html.matches("<script").count(), 4, "only the page's own scripts");
    assert!(!html.contains("<img"));
    assert!(html.contains("\\u003cscript\\u003ealert(1)"));
    // Nothing fetched from anywhere (the only URL is the SVG namespace name, which is no request).
    for bad in ["src=\"http", "href=\"http", "url(http", "import(", "fetch("] {
        assert!(!html.contains(bad), "{bad}");
    }
    let _ = std::fs::remove_dir_all(dir);
}

/// The page carries the programme and the files of --subprogram-dir (its engine runs them; the
/// messages it makes, with their call chains, are tested in ncsight-io's scene module).
#[test]
fn report_carries_the_programme_and_its_library() {
    let dir = std::env::temp_dir().join(format!("ncsight-report-calls-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("calls.nc");
    std::fs::write(&prog, "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0100\nM30\nO0100\nG00 Q1.\nM99\n").unwrap();
    let out = dir.join("r.html");
    let (code, _, err) = common::ncsight(&["report", prog.to_str().unwrap(), "--machine", "fanuc0m", "-o", out.to_str().unwrap()]);
    assert_eq!(code, 1, "{err}");
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.contains(r#""text":"O0001\nG90 G00 X0. Y0. Z10.\nM98 P0100\nM30\nO0100\nG00 Q1.\nM99\n""#), "the programme is on the page");
    let lib = dir.join("lib");
    std::fs::create_dir_all(&lib).unwrap();
    std::fs::write(lib.join("o0200.nc"), "O0200\nG00 X5.\nM99\n").unwrap();
    std::fs::write(&prog, "G90 G00 X0. Y0. Z10.\nM98 P0200\nM30\n").unwrap();
    let (code, _, err) =
        common::ncsight(&["report", prog.to_str().unwrap(), "--machine", "fanuc0m", "--subprogram-dir", lib.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.contains(r#"o0200.nc","O0200\nG00 X5.\nM99\n"]]"#), "the library is on the page");
    let _ = std::fs::remove_dir_all(dir);
}

/// The report says which machine setup the run used, and what it assumed without one.
#[test]
fn report_says_what_the_setup_gives_and_what_is_assumed() {
    let dir = std::env::temp_dir().join(format!("ncsight-report-setup-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("p.nc");
    std::fs::write(&prog, "G0 X10 Z5\nM30\n").unwrap();
    let out = dir.join("r.html");
    let (code, _, err) = common::ncsight(&["report", prog.to_str().unwrap(), "--machine", "gsk980tdi", "-o", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.contains("no machine setup (--setup): work and tool offsets 0"), "the defaults are said");
    assert!(html.contains("reference point assumed at X200 Z200"));
    let setup = dir.join("s.toml");
    std::fs::write(&setup, "[work]\nG54 = { z_mm = -300.0 }\n[[offset]]\nnumber = 1\nradius_mm = 0.4\n").unwrap();
    let (code, _, err) =
        common::ncsight(&["report", prog.to_str().unwrap(), "--machine", "gsk980tdi", "--setup", setup.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.contains("work offsets G54 from the setup, the others 0"), "what the setup gives is said");
    assert!(html.contains("1 tool offset(s) from the setup"));
    assert!(html.contains("no travel limits"));
    let _ = std::fs::remove_dir_all(dir);
}
