//! `ncsight simulate`: JSON fields as issue 7 asks, the image, usage errors.

mod common;

#[test]
fn simulate_o0012_json_and_image() {
    let root = common::root();
    let ex = root.join("examples/gsk980tdi_o0012.nc");
    let png = std::env::temp_dir().join(format!("ncsight-o0012-{}.png", std::process::id()));
    let (code, out, err) = common::ncsight(&[
        "simulate",
        ex.to_str().unwrap(),
        "--machine",
        "gsk980tdi",
        "--stock",
        "60x80",
        "--expect",
        "M60x3",
        "--format",
        "json",
        "--image",
        png.to_str().unwrap(),
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
        (
            "mill.nc",
            "G21 G17 G90 G00 X0 Y0 Z5.\nS1000 M03\nG00 X5. Y5.\nG01 Z-2. F100.\nG01 X15. F300.\nG00 Z5.\nM30\n",
            vec!["-m", "fanuc0m", "--resolution", "0.5"],
        ),
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

/// `--section OUT.svg|OUT.dxf`: the axial section of a part drilled Ø16 to Z-30, bored Ø18 to
/// Z-25 and turned Ø38 to Z-30 on a Ø40 x 50 bar. By hand, the upper half's outline runs along
/// the bore at radius 9 from the face (Z0, half a 0.01 mm cell beyond: 0.005) to the boring
/// bar's corner at Z-25, down the drill's cone to the axis at Z-30, and back along the outside
/// at 19 (Ø38) from the face to Z-30 and 20 (Ø40) to the chuck's end at Z-50; the lower half is
/// its mirror. SVG draws a point above the axis at -y. The DXF has the same corners as LINEs.
#[test]
fn simulate_draws_the_section_as_svg_and_dxf() {
    let dir = std::env::temp_dir().join(format!("ncsight-section-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("part.nc");
    std::fs::write(&prog, "G99 M03 S600\nT0101\nG00 X0. Z2.\nG01 Z-30. F0.1\nG00 Z2.\nT0202\nG00 X18. Z2.\nG01 Z-25. F0.1\nG00 X16.\nG00 Z2.\nT0303\nG00 X42. Z2.\nG01 X38. F0.2\nG01 Z-30.\nG00 X42.\nG00 X100. Z100.\nM30\n").unwrap();
    let tools = dir.join("tools.toml");
    std::fs::write(
        &tools,
        "[[tool]]\nnumber = 1\nkind = \"drill\"\ndiameter_mm = 16.0\n[[tool]]\nnumber = 2\nkind = \"boring\"\n[[tool]]\nnumber = 3\nkind = \"turning\"\n",
    )
    .unwrap();
    let (svg, dxf) = (dir.join("part.svg"), dir.join("part.dxf"));
    for out in [&svg, &dxf] {
        let (code, _, err) = common::ncsight(&[
            "simulate",
            prog.to_str().unwrap(),
            "--machine",
            "gsk980tdi",
            "--stock",
            "40x50",
            "--setup",
            tools.to_str().unwrap(),
            "--section",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{err}");
    }
    let svg = std::fs::read_to_string(&svg).unwrap();
    let polygons: Vec<Vec<(f64, f64)>> = svg
        .lines()
        .filter_map(|l| l.strip_prefix("<polygon points=\""))
        .map(|l| {
            l.split('"')
                .next()
                .unwrap()
                .split(' ')
                .map(|p| {
                    let (z, y) = p.split_once(',').unwrap();
                    (z.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect();
    assert_eq!(polygons.len(), 2, "{svg}");
    let near = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).abs() <= 0.011 && (p.1 - q.1).abs() <= 0.011;
    for (poly, s) in polygons.iter().zip([-1.0, 1.0]) {
        for corner in [(0.005, 9.0), (0.005, 19.0), (-30.0, 0.0), (-50.005, 20.0), (-50.005, 0.0)] {
            assert!(poly.iter().any(|p| near(*p, (corner.0, s * corner.1))), "no corner {corner:?} in {poly:?}");
        }
        // The tools have sharp corners (no nose radius given): the bore is one straight edge from
        // the face to Z-25, the outside one from the face to Z-30; the drill's 118-degree cone
        // meets its Ø16 body 8 / tan 59 = 4.807 mm above its tip, at Z-25.193.
        for corner in [(-25.0, 9.0), (-30.0, 19.0), (-25.193, 8.0)] {
            assert!(poly.iter().any(|p| near(*p, (corner.0, s * corner.1))), "no corner {corner:?} in {poly:?}");
        }
    }
    let dxf = std::fs::read_to_string(&dxf).unwrap();
    assert!(dxf.starts_with("0\nSECTION\n2\nHEADER\n") && dxf.ends_with("0\nENDSEC\n0\nEOF\n"));
    let lines = dxf.matches("0\nLINE\n").count();
    assert_eq!(lines, polygons.iter().map(Vec::len).sum::<usize>() + 1, "every edge and the axis");
    assert!(dxf.contains("8\nSECTION\n10\n0.005\n20\n9\n") || dxf.contains("11\n0.005\n21\n9\n"), "the bore's corner at the face");
    // A machining centre has no turned section; a drawing is named .svg or .dxf.
    let (code, _, err) = common::ncsight(&["simulate", prog.to_str().unwrap(), "--machine", "fanuc0m", "--section", dir.join("m.svg").to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    let (code, _, err) = common::ncsight(&["simulate", prog.to_str().unwrap(), "--machine", "gsk980tdi", "--section", dir.join("m.png").to_str().unwrap()]);
    assert!(code == 2 && err.contains(".svg or"), "{err}");
    let _ = std::fs::remove_dir_all(dir);
}

/// Every example programme simulates on its controller with no finding (the stock guessed from
/// its cuts where it gives none), exit status 0.
#[test]
fn every_example_simulates_without_a_finding() {
    let dir = common::root().join("examples");
    let mut seen = 0;
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_str().unwrap().to_string();
        if !name.ends_with(".nc") {
            continue;
        }
        let machine = match name.split('_').next().unwrap() {
            "yasnac" => "yasnac-lx3",
            m => m,
        };
        let (code, out, err) = common::ncsight(&["simulate", p.to_str().unwrap(), "--machine", machine]);
        assert_eq!(code, 0, "{name}: {out}{err}");
        assert!(!out.lines().any(|l| l.starts_with("finding ")), "{name}: {out}");
        seen += 1;
    }
    assert!(seen >= 8, "{seen} examples");
}

/// A school simulator's stock line (`[BILLET X42 Z60`, Denford's form) is skipped with warning
/// NCS-W37 and gives the stock when neither --stock nor a setup does; --stock wins over it.
#[test]
fn simulate_takes_the_stock_from_a_billet_line() {
    let dir = std::env::temp_dir().join(format!("ncsight-billet-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("billet.nc");
    std::fs::write(
        &prog,
        "O0001\n[BILLET X42 Z60\nG21 G99 T0101\nG00 X45. Z2. S800 M03\nG01 Z0. F0.2\nX0.\nG00 X40. Z1.\nG01 Z-20.\nX45.\nG00 X100. Z100.\nM30\n",
    )
    .unwrap();
    let p = prog.to_str().unwrap();
    let (code, out, err) = common::ncsight(&["simulate", p, "--machine", "fanuc0t", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("stock 42x60 mm from its [BILLET line"), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["stock_diameter_mm"], 42.0, "{out}");
    // The turned step: diameter 40 over the first 20 mm, the bar's 42 beyond.
    let rows = v["profile"].as_array().unwrap();
    assert!(rows.iter().any(|r| r["outer_diameter_mm"] == 40.0), "{out}");
    assert!(rows.iter().any(|r| r["outer_diameter_mm"] == 42.0 && r["z_to_mm"] == -60.0), "{out}");
    let (code, out, _) = common::ncsight(&["simulate", p, "--machine", "fanuc0t", "--format", "json", "--stock", "50x70"]);
    assert_eq!(code, 0);
    assert_eq!(serde_json::from_str::<serde_json::Value>(&out).unwrap()["stock_diameter_mm"], 50.0);
    // check: the warning, and the programme runs to its end.
    let (code, out, _) = common::ncsight(&["check", p, "--machine", "fanuc0t"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("NCS-W37"), "{out}");
    let _ = std::fs::remove_dir_all(dir);
}
