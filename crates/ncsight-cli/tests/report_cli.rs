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
    // Exactly the page's own two script elements, and no markup from the programme.
    assert_eq!(html.matches("<script").count(), 2, "only the page's own scripts");
    assert!(!html.contains("<img"));
    assert!(html.contains("\\u003cscript\\u003ealert(1)"));
    // Nothing fetched from anywhere (the only URL is the SVG namespace name, which is no request).
    for bad in ["src=\"http", "href=\"http", "url(http", "import(", "fetch("] {
        assert!(!html.contains(bad), "{bad}");
    }
    let _ = std::fs::remove_dir_all(dir);
}

/// An alarm inside a subprogramme: the page's message names the call that led there.
#[test]
fn report_shows_the_call_chain() {
    let dir = std::env::temp_dir().join(format!("ncsight-report-calls-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("calls.nc");
    std::fs::write(&prog, "O0001\nG90 G00 X0. Y0. Z10.\nM98 P0100\nM30\nO0100\nG00 Q1.\nM99\n").unwrap();
    let out = dir.join("r.html");
    let (code, _, err) = common::ncsight(&["report", prog.to_str().unwrap(), "--machine", "fanuc0m", "-o", out.to_str().unwrap()]);
    assert_eq!(code, 1, "{err}");
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.contains("in a subprogramme called at line 3"), "the call chain is on the page");
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
    let (code, _, err) = common::ncsight(&["report", prog.to_str().unwrap(), "--machine", "gsk980tdi", "--setup", setup.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.contains("work offsets G54 from the setup, the others 0"), "what the setup gives is said");
    assert!(html.contains("1 tool offset(s) from the setup"));
    assert!(html.contains("no travel limits"));
    let _ = std::fs::remove_dir_all(dir);
}

/// A rotary axis's turn is in the report's data with the time it adds (45 degrees at the rotary
/// rapid rate, 10800 deg/min: 0.25 s plus 0.1 s to accelerate), for the time chart and table.
#[test]
fn report_counts_the_time_of_rotary_turns() {
    let dir = std::env::temp_dir().join(format!("ncsight-report-rotary-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("p.nc");
    std::fs::write(&prog, "G91 G00 A45.\nM30\n").unwrap();
    let setup = dir.join("s.toml");
    std::fs::write(&setup, "[machine]\naxes = [\"X\", \"Y\", \"Z\", \"A\"]\n").unwrap();
    let out = dir.join("r.html");
    let (code, _, err) = common::ncsight(&["report", prog.to_str().unwrap(), "--machine", "fanuc0m", "--setup", setup.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.contains(r#"{"k":"rotary","axis":"A","deg":45,"s":0.35,"l":1"#), "{}", &html[html.find("\"events\"").unwrap_or(0)..][..300.min(html.len())]);
    let _ = std::fs::remove_dir_all(dir);
}
