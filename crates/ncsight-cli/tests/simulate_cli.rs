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

/// `--stl OUT.stl`: the cut stock as a binary STL, closed (every edge shared by two triangles in
/// opposite directions), for a lathe part (a drilled bar) and a mill block (a slot).
#[test]
fn simulate_writes_a_closed_stl() {
    let dir = std::env::temp_dir().join(format!("ncsight-stl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cases = [
        ("lathe.nc", "G99 M03 S600\nG00 X0. Z2.\nG01 Z-10. F0.1\nG00 Z2.\nM30\n", vec!["-m", "gsk980tdi", "--stock", "20x20", "--resolution", "0.1,10"]),
        ("mill.nc", "G21 G17 G90 G00 X0 Y0 Z5.\nS1000 M03\nG00 X5. Y5.\nG01 Z-2. F100.\nG01 X15. F300.\nG00 Z5.\nM30\n", vec!["-m", "fanuc0m", "--resolution", "0.5"]),
    ];
    for (name, text, args) in cases {
        let f = dir.join(name);
        std::fs::write(&f, text).unwrap();
        let stl = dir.join(format!("{name}.stl"));
        let mut argv = vec!["simulate", f.to_str().unwrap(), "--stl", stl.to_str().unwrap()];
        argv.extend(args);
        let (code, out, err) = common::ncsight(&argv);
        assert_eq!(code, 0, "{name}: {out}{err}");
        let b = std::fs::read(&stl).unwrap();
        let n = u32::from_le_bytes(b[80..84].try_into().unwrap()) as usize;
        assert!(n > 100 && b.len() == 84 + 50 * n, "{name}: {n} triangles in {} bytes", b.len());
        let f32at = |at: usize| f32::from_le_bytes(b[at..at + 4].try_into().unwrap());
        let key = |at: usize| ((f32at(at) * 1e3).round() as i64, (f32at(at + 4) * 1e3).round() as i64, (f32at(at + 8) * 1e3).round() as i64);
        let mut edges = std::collections::HashMap::new();
        for t in 0..n {
            let base = 84 + 50 * t + 12;
            let v = [key(base), key(base + 12), key(base + 24)];
            for k in 0..3 {
                let (a, c) = (v[k], v[(k + 1) % 3]);
                if a != c {
                    *edges.entry((a, c)).or_insert(0i32) += 1;
                    *edges.entry((c, a)).or_insert(0i32) -= 1;
                }
            }
        }
        assert!(edges.values().all(|v| *v == 0), "{name}: the mesh is not closed");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
