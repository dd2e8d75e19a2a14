//! `ncsight repair`: the programme on standard output only; alarms exit 1 with no programme.

mod common;

#[test]
fn repair_prints_the_two_blocks() {
    let args = [
        "repair",
        "--machine",
        "gsk988t",
        "--param",
        "8135.7=1",
        "--start",
        "30.14,3",
        "--end",
        "51.57,-72",
        "--lead",
        "2",
        "--rpm",
        "500",
        "--measured",
        "40,-30.5,12.345",
        "--j",
        "1",
    ];
    let (code, out, err) = common::ncsight(&args);
    assert_eq!(code, 0, "{err}");
    // 33.5 mm from the start is 16.75 revolutions: Q = 12.345 - 270 = 102.345 degrees.
    assert_eq!(out, "G0 X30.14 Z3.\nG32.1 X51.57 Z-72. F2. Q102345 S500 J1.\n");
    assert!(err.is_empty());
}

#[test]
fn repair_alarms() {
    // RPTH off (seed 001 1.4): alarm, no programme.
    let base = ["repair", "--machine", "gsk988t", "--start", "30,3", "--end", "30,-72", "--lead", "2", "--rpm", "-500"];
    let (code, out, err) = common::ncsight(&[&base[..], &["--measured", "30,-10,0"]].concat());
    assert_eq!(code, 1);
    assert!(out.is_empty() && err.contains("NCS-E49"), "{err}");
    // The recorded Z outside the thread (seed 001 1.3 note 3).
    let (code, out, err) = common::ncsight(&[&base[..], &["--param", "8135.7=1", "--measured", "30,10,0"]].concat());
    assert_eq!(code, 1);
    assert!(out.is_empty() && err.contains("NCS-E48"), "{err}");
    // Usage errors exit 2.
    let (code, _, _) = common::ncsight(&[&base[..], &["--measured", "30,10"]].concat());
    assert_eq!(code, 2);
    let (code, _, err) =
        common::ncsight(&["repair", "--machine", "fanuc0m", "--start", "1,1", "--end", "1,-1", "--lead", "1", "--rpm", "1", "--measured", "1,0,0"]);
    assert_eq!(code, 2, "{err}");
}
