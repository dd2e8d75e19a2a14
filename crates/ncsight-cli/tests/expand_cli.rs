//! `ncsight expand` (docs/commands/expand.md): the programme as plain moves for LinuxCNC or
//! grbl. For LinuxCNC the expansion is read back by LinuxCNC's own interpreter (`rs274 -g`)
//! and must move as `ncsight run --format canon` says the original moves; for grbl every line
//! must hold only what grbl 1.1 accepts, and a thread must alarm.

mod common;
mod roundtrip;

/// The golden programmes with their arguments (the corpus programmes' round trip is in corpus.rs).
fn programmes() -> Vec<roundtrip::Programme> {
    let mut out = Vec::new();
    let dir = common::root().join("tests/golden");
    let mut cases: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    cases.sort();
    for case in cases {
        let args = std::fs::read_to_string(case.join("args")).unwrap_or_default();
        out.push((case.file_name().unwrap().to_string_lossy().into_owned(), case.join("input.nc"), args.split_whitespace().map(String::from).collect()));
    }
    assert!(out.len() >= 25);
    out
}

#[test]
fn linuxcnc_reads_the_expansion_back_as_the_original_moves() {
    let (files, compared) = roundtrip::linuxcnc_round_trip(&programmes());
    if roundtrip::rs274().is_some() {
        assert!(files >= 20 && compared > 500, "only {files} programmes, {compared} calls compared");
    }
}

#[test]
fn grbl_gets_only_what_grbl_accepts_and_threads_alarm() {
    let (refused, lines) = roundtrip::grbl_check(&programmes());
    assert!(refused >= 10, "only {refused} threaded programmes refused");
    assert!(lines > 1000, "only {lines} lines checked");
}

#[test]
fn expand_says_what_it_cannot_do() {
    let (code, _, err) = common::ncsight(&["expand", "nowhere.nc", "--machine", "fanuc0m", "--to", "haas"]);
    assert_eq!(code, 2);
    assert!(err.contains("--to haas: choose linuxcnc or grbl"), "{err}");
    // A mill programme: rapids, a feed, an arc in G17 and a drilling cycle, written out.
    let dir = std::env::temp_dir().join(format!("ncsight-expand-small-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("o1.nc");
    std::fs::write(
        &f,
        "O1\nG21 G17 G90 G00 X0. Y0. Z10.\nS1000 M03\nN20 G01 Z-1. F200.\nG02 X10. Y0. I5. J0.\nG00 Z10.\nG98 G81 X20. Y5. Z-3. R2. F100.\nG80\nM30\n",
    )
    .unwrap();
    let (code, text, err) = common::ncsight(&["expand", f.to_str().unwrap(), "--machine", "fanuc0m", "--to", "grbl"]);
    assert_eq!(code, 0, "{err}");
    let body: Vec<&str> = text.lines().skip(2).collect();
    // By hand: the header, then each block's line and moves; the G81 hole as its rapid to the
    // hole, to R, the feed to the bottom, the rapid back to the initial level (G98: Z10).
    assert_eq!(
        body,
        [
            "G21 G90 G94 G17 G40 G49 G80",
            "(line 2)",
            "G0 X0 Y0 Z10",
            "(line 3)",
            "S1000 M3",
            "(line 4 N20)",
            "G1 X0 Y0 Z-1 F200",
            "(line 5)",
            "G2 X10 Y0 Z-1 I5 J0",
            "(line 6)",
            "G0 X10 Y0 Z10",
            "(line 7)",
            "G0 X20 Y5 Z10",
            "G0 X20 Y5 Z2",
            "G1 X20 Y5 Z-3 F100",
            "G0 X20 Y5 Z10",
            "(line 9)",
            "M30",
        ]
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A coordinate shift (G50 on the FANUC 0-T) in mid-programme: the moves after it are in the
/// shifted coordinates, so the expansion shifts the target the same way (`G92 X0 Z0` where the
/// tool stands), and LinuxCNC then moves as ncsight says. A programme without M30 gets one,
/// with a comment, so the target does not stop on a missing end.
#[test]
fn a_coordinate_shift_is_carried_over() {
    let dir = std::env::temp_dir().join(format!("ncsight-expand-shift-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("g50.nc");
    std::fs::write(&f, "G00 X40. Z10. S500 M03\nG50 X0 Z0\nG01 X10. Z-5. F0.2\nG00 X20.\n").unwrap();
    let (code, text, err) = common::ncsight(&["expand", f.to_str().unwrap(), "--machine", "fanuc0t", "--to", "linuxcnc"]);
    assert_eq!(code, 0, "{err}");
    let body: Vec<&str> = text.lines().skip(3).collect();
    assert_eq!(
        body,
        [
            "(line 1)",
            "S500 M3",
            "G0 X20 Z10",
            "(line 3)",
            "G92 X0 Z0 (the programme's coordinates were shifted here)",
            "G1 X5 Z-5 F100",
            "(line 4)",
            "G0 X10 Z-5",
            "(the programme has no M02 or M30: its controller stops after its last block)",
            "M30",
        ]
    );
    if let Some(rs274) = roundtrip::rs274() {
        let ngc = dir.join("g50.ngc");
        std::fs::write(&ngc, &text).unwrap();
        let (theirs, _) = roundtrip::read_back(rs274, None, &ngc);
        let (_, canon, _) = common::ncsight(&["run", f.to_str().unwrap(), "--machine", "fanuc0t", "--format", "canon"]);
        common::same_calls("g50", &common::motion_calls(&canon), &common::motion_calls(&theirs));
    }
    let _ = std::fs::remove_dir_all(&dir);
}
