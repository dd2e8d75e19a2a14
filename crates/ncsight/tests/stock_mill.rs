//! The machining centre's stock (issue 33): every move cuts, not only the drills' plunges. A
//! pocket, a slot and a helical bore with a 6 mm flat end mill, measured within one cell (0.1
//! mm); a rapid through the block is one crash at its line.

use ncsight::stock::measure::simulate_mill;
use ncsight::stock::Setup;
use ncsight::Record;

mod common;

fn records(text: &str) -> Vec<Record> {
    let (records, diags) = common::run_plain("fanuc0m", &[], text);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    records
}

fn setup() -> Setup {
    Setup::from_toml("[block]\nmin_mm = [0.0, 0.0, -20.0]\nmax_mm = [90.0, 60.0, 0.0]\n[[tool]]\nnumber = 1\nkind = \"mill\"\ndiameter_mm = 6.0\n").unwrap()
}

/// The pocket: the cutter's centre around X15-29 Y15-19, 3 deep: 20 x 10 less the four corners
/// the Ø6 cutter rounds (4 x (9 - 9 pi / 4) = 7.73): 192.27 mm². The slot: X10 to X50 at Y40, 2
/// deep: 40 x 6 + pi x 9 = 268.27 mm². The helix: around X66 Y20 at radius 4 down to Z-4, then a
/// full turn there: a bore Ø 2 x 4 + 6 = 14 with a Ø2 post left standing in its middle (4 - 3),
/// its floor pi x (49 - 1) = 150.80 mm². The volume: 192.27 x 3 + 268.27 x 2 + 150.80 x 4 =
/// 1716.5 mm³.
const PROGRAMME: &str = "G21 G17 G90 G54\nT1 M06\nS3000 M03\nG00 X0 Y0 Z10.\nG00 X15. Y15.\nG01 Z-3. F100.\nG01 X29. F300.\nY19.\nX15.\nY15.\nG00 Z10.\nG00 X10. Y40.\nG01 Z-2. F100.\nG01 X50. F300.\nG00 Z10.\nG00 X70. Y20.\nG01 Z0 F100.\nG02 X70. Y20. Z-2. I-4. J0 F200.\nG02 X70. Y20. Z-4. I-4. J0\nG02 X70. Y20. Z-4. I-4. J0\nG00 Z10.\nG00 X0 Y0\nM30\n";

#[test]
fn a_pocket_a_slot_and_a_helical_bore_are_cut_and_measured() {
    let sim = simulate_mill(&records(PROGRAMME), &setup(), Some(0.1), None).unwrap();
    assert!(sim.findings.is_empty(), "{:?}", sim.findings);
    let floors = sim.stock.floors();
    let floor = |z: f64| floors.iter().find(|(fz, _)| (fz - z).abs() < 1e-6).map(|(_, a)| *a).unwrap_or_else(|| panic!("no floor at Z{z}: {floors:?}"));
    // Within one cell along the rim: the perimeter times 0.1 mm.
    assert!((floor(-3.0) - 192.27).abs() <= 60.0 * 0.1, "{floors:?}");
    assert!((floor(-2.0) - 268.27).abs() <= 100.0 * 0.1, "{floors:?}");
    assert!((floor(-4.0) - 150.80).abs() <= 50.0 * 0.1, "{floors:?}");
    assert_eq!(sim.holes.len(), 1, "{:?}", sim.holes);
    let h = sim.holes[0];
    assert!((h.x - 66.0).abs() <= 0.1 && (h.y - 20.0).abs() <= 0.1 && (h.diameter_mm - 14.0).abs() <= 0.1 && (h.depth_mm - 4.0).abs() < 1e-6, "{h:?}");
    assert!((sim.stock.removed_mm3() - 1716.5).abs() <= 0.01 * 1716.5, "{}", sim.stock.removed_mm3());
}

/// A rapid through the block (G00 from above X5 Y5 down to Z-1 at X40): one crash, at its line.
#[test]
fn a_rapid_through_the_block_is_one_crash_at_its_line() {
    let text = PROGRAMME.replace("G00 X10. Y40.\n", "G00 X10. Y40.\nG00 Z-1.\nG00 Z10.\n");
    let sim = simulate_mill(&records(&text), &setup(), Some(0.1), None).unwrap();
    let crashes: Vec<_> = sim.findings.iter().filter(|f| f.kind == "crash").collect();
    assert_eq!(crashes.len(), 1, "{:?}", sim.findings);
    assert_eq!(crashes[0].line, 13);
}

/// A cut with the spindle stopped is a `spindle` finding.
#[test]
fn a_cut_with_the_spindle_stopped_is_found() {
    let text = PROGRAMME.replace("S3000 M03\n", "S3000 M05\n");
    let sim = simulate_mill(&records(&text), &setup(), Some(0.1), None).unwrap();
    assert!(sim.findings.iter().any(|f| f.kind == "spindle" && f.line == 6), "{:?}", sim.findings);
}

/// Cutting only removes: every cell is at or below the block's top, and cutting a move twice
/// removes what once does.
#[test]
fn material_only_decreases_and_a_move_cut_twice_cuts_once() {
    let recs = records(PROGRAMME);
    let once = simulate_mill(&recs, &setup(), Some(0.2), None).unwrap();
    let twice: Vec<Record> = recs.iter().flat_map(|r| if matches!(r.op, ncsight::motion::Op::Feed { .. } | ncsight::motion::Op::Arc { .. }) { vec![r.clone(), r.clone()] } else { vec![r.clone()] }).collect();
    let twice = simulate_mill(&twice, &setup(), Some(0.2), None).unwrap();
    assert_eq!(once.stock.top, twice.stock.top);
    assert!(once.stock.top.iter().all(|z| *z <= 0.0));
}

/// The tool's shape forbids what the same programme does with another tool: a mill that does not
/// cut at its centre plunging (line 6, 3 mm into the block), flutes 2.5 mm long cutting 3 mm deep
/// (line 6), and a Ø30 holder 3.5 mm above the tip coming down into the block when the helix
/// reaches Z-4 (line 19: its face at Z-0.5, the block's top at Z0 within 15 mm).
#[test]
fn the_tools_shape_forbids_plunges_deep_cuts_and_holder_contact() {
    let tool = |extra: &str| Setup::from_toml(&format!("[block]\nmin_mm = [0.0, 0.0, -20.0]\nmax_mm = [90.0, 60.0, 0.0]\n[[tool]]\nnumber = 1\nkind = \"mill\"\ndiameter_mm = 6.0\n{extra}")).unwrap();
    let first = |s: &Setup, kind: &str| {
        let sim = simulate_mill(&records(PROGRAMME), s, Some(0.1), None).unwrap();
        sim.findings.iter().find(|f| f.kind == kind).map(|f| (f.line, f.tool, f.message.clone()))
    };
    let (line, tool_n, msg) = first(&tool("centre_cutting = false\n"), "plunge").expect("a plunge finding");
    assert_eq!((line, tool_n), (6, Some(1)));
    assert!(msg.contains("plunges 3.000 mm"), "{msg}");
    let (line, _, msg) = first(&tool("flute_length_mm = 2.5\n"), "flute").expect("a flute finding");
    assert_eq!(line, 6);
    assert!(msg.contains("reaches 3.000 mm up the tool, beyond its 2.500 mm flutes"), "{msg}");
    let (line, _, msg) = first(&tool("stick_out_mm = 3.5\nholder = { diameter_mm = 30.0, length_mm = 50.0 }\n"), "holder").expect("a holder finding");
    assert_eq!(line, 19);
    assert!(msg.contains("comes 0.500 mm into the material"), "{msg}");
    // With the flutes long enough, a centre-cutting mill and the holder high enough: none.
    let fine = tool("flute_length_mm = 20.0\nstick_out_mm = 30.0\nholder = { diameter_mm = 30.0, length_mm = 50.0 }\n");
    assert!(simulate_mill(&records(PROGRAMME), &fine, Some(0.1), None).unwrap().findings.is_empty());
}
