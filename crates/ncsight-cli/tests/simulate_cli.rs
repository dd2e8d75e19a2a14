//! `ncsight simulate`: JSON fields as issue 7 asks, the image, usage errors.

mod common;

#[test]
fn simulate_o0012_json_and_image() {
    let root = common::root();
    let ex = root.join("examples/gsk980tdi_o0012.nc");
    let png = std::env::temp_dir().join(format!("ncsight-o0012-{}.png", std::process::id()));
    let (code, out, err) = common::ncsight(&[
        "simulate", ex.to_str().unwrap(), "--machine", "gsk980tdi", "--stock", "60x80", "--expect", "M60x3",
        "--format", "json", "--image", png.to_str().unwrap(),
    ]);
    // O0012's M60x3 is a deviation (its minor 56.9 mm is not M60x3's 56.32): exit status 3.
    assert_eq!(code, 3, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    for k in ["major_diameter_mm", "minor_diameter_mm", "pitch_mm", "lead_mm", "starts", "depth_mm"] {
        assert!(v[k].is_number(), "{k}: {out}");
    }
    assert!((v["minor_diameter_mm"].as_f64().unwrap() - 56.9).abs() <= 0.02);
    assert!((v["pitch_mm"].as_f64().unwrap() - 3.0).abs() <= 0.02);
    let findings = v["findings"].as_array().unwrap();
    assert!(findings.iter().any(|f| f["kind"] == "deviation"), "{out}");
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    let _ = std::fs::remove_file(png);
}

#[test]
fn simulate_usage_errors() {
    let ex = common::root().join("examples/gsk980tdi_o0012.nc");
    let ex = ex.to_str().unwrap();
    for bad in [vec!["--stock", "60"], vec!["--expect", "M7"], vec!["--resolution", "0"], vec!["--format", "xml"]] {
        let mut args = vec!["simulate", ex, "--machine", "gsk980tdi"];
        args.extend(bad.iter());
        let (code, _, err) = common::ncsight(&args);
        assert_eq!(code, 2, "{bad:?}: {err}");
    }
}

#[test]
fn simulate_drilling_on_a_mill() {
    let prog = common::root().join("tests/golden/seed003_nine_steps/input.nc");
    let (code, out, err) = common::ncsight(&["simulate", prog.to_str().unwrap(), "--machine", "fanuc0m", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let holes = v["holes"].as_array().unwrap();
    // The nine steps drill six places (the first twice); G01 X70 Y70 at Z50 cuts nothing.
    assert_eq!(holes.len(), 6, "{out}");
    assert!(holes.iter().any(|h| h["x"] == 50.0 && h["y"] == 40.0 && h["depth_mm"] == 10.0), "{out}");
    assert_eq!(v["findings"].as_array().unwrap().len(), 0, "{out}");
}
