//! The lathe stock holds its inside (issue 33): a drilled, bored and turned part, a crash in a
//! bore, a part parted off, and cutting only ever removes material. Sizes are checked within one
//! cell of the grid (0.02 mm on a diameter at dz = 0.01 mm: the nose's and the drill's samples).

use ncsight::stock::measure::{simulate, SimOptions};
use ncsight::stock::{Bar, Setup};
use ncsight::Record;

mod common;

fn records(text: &str) -> Vec<Record> {
    let (records, diags) = common::run_plain("gsk980tdi", &[], text);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    records
}

/// A Ø40 x 50 bar, face at Z0, and the tools given where `tools` says (TOML).
fn setup(tools: &str) -> Setup {
    let mut s = Setup::from_toml(tools).unwrap();
    s.stock = Some(Bar { diameter_mm: 40.0, length_mm: 50.0, bore_mm: 0.0, front_z_mm: 0.0 });
    s
}

fn opts() -> SimOptions {
    SimOptions { dz_mm: Some(0.01), dtheta_deg: Some(5.0), ..SimOptions::default() }
}

/// Drill Ø16 to Z-30 (T01), bore to Ø18 to Z-25 (T02, retracting toward the axis), turn the
/// outside to Ø38 to Z-30 (T03).
const PART: &str = "G99 M03 S600\nT0101\nG00 X0. Z2.\nG01 Z-30. F0.1\nG00 Z2.\nT0202\nG00 X18. Z2.\nG01 Z-25. F0.1\nG00 X16.\nG00 Z2.\nT0303\nG00 X42. Z2.\nG01 X38. F0.2\nG01 Z-30.\nG00 X42.\nG00 X100. Z100.\nM30\n";

const TOOLS: &str = "[[tool]]\nnumber = 1\nkind = \"drill\"\ndiameter_mm = 16.0\n[[tool]]\nnumber = 2\nkind = \"boring\"\ntip_radius_mm = 0.4\nincluded_angle_deg = 80.0\n[[tool]]\nnumber = 3\nkind = \"turning\"\ntip_radius_mm = 0.4\nincluded_angle_deg = 80.0\n";

/// By hand: from the face, Ø38 with a Ø18 bore down to Z-25 (the boring bar's main edge stops
/// there, 5 degrees past the radial, its nose rounding the corner); below, the Ø16 drill's
/// 118-degree point (8 / tan 59 = 4.807 mm of cone above the tip at Z-30: at Z-26, 4 mm above
/// the tip, Ø 2 x 4 x tan 59 = 13.314); the outside Ø38 to Z-30, Ø40 beyond. No finding.
#[test]
fn a_drilled_bored_and_turned_part_is_measured_inside_and_out() {
    for tools in [TOOLS, ""] {
        let sim = simulate(&records(PART), &setup(tools), &SimOptions { expect_bore_mm: Some(18.0), expect_od_mm: Some(38.0), ..opts() }).unwrap();
        let m = &sim.measurement;
        assert!(m.findings.is_empty(), "tools {tools:?}: {:?}", m.findings);
        let at = |z: f64| m.profile.iter().find(|r| r.z_from_mm + 0.005 >= z && z >= r.z_to_mm - 0.005).copied().unwrap_or_else(|| panic!("no row at Z{z}"));
        let near = |a: f64, b: f64| (a - b).abs() <= 0.02;
        let r = at(-10.0);
        assert!(near(r.outer_diameter_mm, 38.0) && near(r.inner_diameter_mm, 18.0), "{r:?}");
        // The bar's 0.4 mm nose rounds the bottom of the bore: 0.1 mm below Z-25 the bore is
        // Ø 2 x (9 - (0.4 - sqrt(0.4^2 - 0.1^2))) = 17.975, above the drill's Ø16.
        let r = at(-25.1);
        assert!(near(r.outer_diameter_mm, 38.0) && near(r.inner_diameter_mm, 2.0 * (9.0 - (0.4 - (0.16f64 - 0.01).sqrt()))), "{r:?}");
        let cone = |above_tip: f64| 2.0 * above_tip * 59f64.to_radians().tan();
        let r = at(-26.0);
        assert!(near(r.inner_diameter_mm, cone(4.0)), "{r:?}");
        let r = at(-28.0);
        assert!(near(r.inner_diameter_mm, cone(2.0)), "{r:?}");
        let r = at(-40.0);
        assert!(near(r.outer_diameter_mm, 40.0) && r.inner_diameter_mm == 0.0, "{r:?}");
    }
}

/// The same part with the boring bar's retract moved into the wall (X16 -> X22: 2 mm into the
/// Ø18 bore's wall), line 9: one crash, at that line, and none for the rapid that follows from
/// there.
#[test]
fn a_retract_into_the_bore_wall_is_one_crash() {
    for tools in [TOOLS, ""] {
        let sim = simulate(&records(&PART.replace("G00 X16.\n", "G00 X22.\n")), &setup(tools), &opts()).unwrap();
        let crashes: Vec<_> = sim.measurement.findings.iter().filter(|f| f.kind == "crash").collect();
        assert_eq!(crashes.len(), 1, "tools {tools:?}: {crashes:?}");
        assert_eq!(crashes[0].line, 9);
        assert!(crashes[0].message.contains("cuts 2.000 mm into the stock"), "{}", crashes[0].message);
    }
}

/// A drill rapids into the face (no hole there yet): a crash.
#[test]
fn a_drill_rapid_into_the_face_is_a_crash() {
    let text = "G99 M03 S600\nT0101\nG00 X0. Z2.\nG00 Z-5.\nG01 Z-30. F0.1\nG00 Z2.\nM30\n";
    let sim = simulate(&records(text), &setup(TOOLS), &opts()).unwrap();
    let crashes: Vec<_> = sim.measurement.findings.iter().filter(|f| f.kind == "crash").collect();
    assert_eq!(crashes.len(), 1, "{crashes:?}");
    assert_eq!(crashes[0].line, 4);
}

/// A part drilled Ø16 to Z-45, then cut off at Z-20 by a tool fed from outside to X15, inside
/// the bore: at Z-20 no material is left (the part is parted), and the profile says so.
#[test]
fn a_parting_cut_leaves_no_material() {
    let text = "G99 M03 S600\nT0101\nG00 X0. Z2.\nG01 Z-45. F0.1\nG00 Z2.\nT0303\nG00 X42.\nG00 Z-20.\nG01 X15. F0.05\nG00 X42.\nM30\n";
    let sim = simulate(&records(text), &setup(TOOLS), &opts()).unwrap();
    assert!(sim.measurement.findings.is_empty(), "{:?}", sim.measurement.findings);
    let cut = sim.measurement.profile.iter().find(|r| r.z_from_mm >= -20.0 && -20.0 >= r.z_to_mm).unwrap();
    assert_eq!((cut.outer_diameter_mm, cut.inner_diameter_mm), (0.0, 0.0), "{cut:?}");
}

/// Cutting only removes material: after every record, no cell's outside grew and no bore
/// shrank; and a move cut twice removes what it removes once.
#[test]
fn material_only_decreases_and_a_move_cut_twice_cuts_once() {
    let recs = records(PART);
    let s = setup(TOOLS);
    let once = simulate(&recs, &s, &opts()).unwrap();
    let mut twice_recs = Vec::new();
    for r in &recs {
        twice_recs.push(r.clone());
        if matches!(r.op, ncsight::motion::Op::Feed { .. }) {
            twice_recs.push(r.clone());
        }
    }
    let twice = simulate(&twice_recs, &s, &opts()).unwrap();
    assert_eq!(once.stock.outer, twice.stock.outer);
    assert_eq!(once.stock.inner, twice.stock.inner);
    let full = (40.0f32 / 2.0, 0.0f32);
    assert!(once.stock.outer.iter().all(|r| *r <= full.0) && once.stock.inner.iter().all(|r| *r >= full.1));
}

/// Drilled Ø16, bored Ø18.376 (the minor diameter of M20x1.5 inside), an internal groove 3 mm
/// wide to Ø22 at Z-10 to Z-13 (a groove tool working inside: its 3 mm flat is centred on its
/// programmed point, Z-11.5, as ncsight models a flat tip), then an internal G92 M20x1.5
/// thread from Z5 to Z-8 in four passes out to X20: the thread's major Ø20, minor Ø18.376,
/// pitch 1.5 measured on the bore within one cell (dz 0.005 mm from the lead); the groove
/// Ø22; the bore Ø18.376 below it. No finding.
#[test]
fn an_internal_groove_and_thread_are_measured_on_the_bore() {
    let text = "G99 M03 S600\nT0101\nG00 X0. Z2.\nG01 Z-30. F0.1\nG00 Z2.\nT0202\nG00 X18.376 Z2.\nG01 Z-25. F0.1\nG00 X16.\nG00 Z2.\nT0303\nG00 X17. Z2.\nG00 Z-11.5\nG01 X22. F0.05\nG00 X17.\nG00 Z2.\nT0404\nG00 X17. Z5.\nG92 X18.8 Z-8. F1.5\nX19.3\nX19.7\nX20.\nX20.\nG00 X100. Z100.\nM30\n";
    let tools = format!("{TOOLS}[[tool]]\nnumber = 3\nkind = \"groove\"\ninternal = true\nincluded_angle_deg = 2.0\ntip_flat_mm = 3.0\n[[tool]]\nnumber = 4\nkind = \"thread\"\ninternal = true\nincluded_angle_deg = 60.0\n");
    let tools = tools.replace("number = 3\nkind = \"turning\"\ntip_radius_mm = 0.4\nincluded_angle_deg = 80.0\n", "number = 5\nkind = \"turning\"\n");
    let sim = simulate(&records(text), &setup(&tools), &SimOptions { dz_mm: None, dtheta_deg: Some(2.0), ..SimOptions::default() }).unwrap();
    let m = &sim.measurement;
    assert!(m.findings.is_empty(), "{:?}", m.findings);
    let cell = 2.0 * m.dz_mm + 0.002;
    assert!((m.major_diameter_mm.unwrap() - 20.0).abs() <= cell, "{m:?}");
    assert!((m.minor_diameter_mm.unwrap() - 18.376).abs() <= cell, "{m:?}");
    assert!((m.pitch_mm.unwrap() - 1.5).abs() <= m.dz_mm + 0.001, "{m:?}");
    let at = |z: f64| m.profile.iter().find(|r| r.z_from_mm + m.dz_mm / 2.0 >= z && z >= r.z_to_mm - m.dz_mm / 2.0).copied().unwrap();
    assert!((at(-11.5).inner_diameter_mm - 22.0).abs() <= 0.02, "{:?}", at(-11.5));
    assert!((at(-18.0).inner_diameter_mm - 18.376).abs() <= 0.02, "{:?}", at(-18.0));
    assert!((at(-18.0).outer_diameter_mm - 40.0).abs() <= 0.02);
}

/// A grooving tool 3 mm wide with 0.2 mm corners, plunged from Ø42 to Ø30 at Z-20 (line 4).
/// By hand: with `reference = "left"` (the default) the programmed point is the corner toward
/// the chuck, so the groove runs from Z-20 to Z-17; with "right" from Z-23 to Z-20; with
/// "centre" from Z-21.5 to Z-18.5. Its floor is Ø30 away from the corners, and 0.1 mm inside a
/// corner the floor is up by 0.2 - sqrt(0.2^2 - 0.1^2) = 0.0268 mm (Ø30.054).
#[test]
fn a_grooving_tool_cuts_its_width_from_its_reference_corner() {
    let text = "G99 M03 S600\nT0101\nG00 X42. Z2.\nG00 Z-20.\nG01 X30. F0.05\nG00 X42.\nG00 X100. Z100.\nM30\n";
    for (reference, from, to) in [("left", -20.0, -17.0), ("right", -23.0, -20.0), ("centre", -21.5, -18.5)] {
        let tools = format!("[[tool]]\nnumber = 1\nkind = \"groove\"\nwidth_mm = 3.0\ncorner_radius_mm = 0.2\nreference = \"{reference}\"\n");
        let sim = simulate(&records(text), &setup(&tools), &opts()).unwrap();
        let m = &sim.measurement;
        assert!(m.findings.is_empty(), "{reference}: {:?}", m.findings);
        let at = |z: f64| m.profile.iter().find(|r| r.z_from_mm + 0.005 >= z && z >= r.z_to_mm - 0.005).copied().unwrap();
        let mid = (from + to) / 2.0;
        assert!((at(mid).outer_diameter_mm - 30.0).abs() <= 0.02, "{reference}: {:?}", at(mid));
        let corner = 30.0 + 2.0 * (0.2 - (0.04f64 - 0.01).sqrt());
        assert!((at(from + 0.1).outer_diameter_mm - corner).abs() <= 0.02, "{reference}: {:?}", at(from + 0.1));
        assert!((at(to - 0.1).outer_diameter_mm - corner).abs() <= 0.02, "{reference}: {:?}", at(to - 0.1));
        // Outside the width, the bar is whole.
        assert!((at(from - 0.05).outer_diameter_mm - 40.0).abs() <= 0.02, "{reference}: {:?}", at(from - 0.05));
        assert!((at(to + 0.05).outer_diameter_mm - 40.0).abs() <= 0.02, "{reference}: {:?}", at(to + 0.05));
    }
}

/// An ISO D insert (55 degrees) in a 93-degree holder, 0.4 mm nose: turned from Z0 to Z-20 at
/// Ø30 it leaves, toward the face, its end edge at 180 - 93 - 55 = 32 degrees off the axis; and
/// a C insert (80 degrees, 95-degree holder) 5 degrees. The shoulder it leaves toward the chuck
/// is its main edge at 87 (D) and 85 (C) degrees. By hand, 1 mm toward the chuck from the
/// nose's lowest point the shoulder is at radius 15 + 0.4 (1 - cos a) + (1 - 0.4 sin a) tan a.
#[test]
fn an_iso_insert_leaves_its_edges_on_the_shoulder() {
    let text = "G99 M03 S600\nT0101\nG00 X42. Z2.\nG00 X30.\nG01 Z-20. F0.1\nG00 X42.\nG00 X100. Z100.\nM30\n";
    for (shape, main_deg) in [("D", 87.0f64), ("C", 85.0)] {
        let tools = format!("[[tool]]\nnumber = 1\nkind = \"turning\"\niso_shape = \"{shape}\"\nnose_radius_mm = 0.4\n");
        let sim = simulate(&records(text), &setup(&tools), &opts()).unwrap();
        let m = &sim.measurement;
        assert!(m.findings.is_empty(), "{shape}: {:?}", m.findings);
        let at = |z: f64| m.profile.iter().find(|r| r.z_from_mm + 0.005 >= z && z >= r.z_to_mm - 0.005).copied().unwrap();
        let a = main_deg.to_radians();
        let want = 2.0 * (15.0 + 0.4 * (1.0 - a.cos()) + (1.0 - 0.4 * a.sin()) * a.tan());
        let got = at(-21.0).outer_diameter_mm;
        assert!((got - want.min(40.0)).abs() <= 0.05, "{shape}: {got} against {want}");
        assert!((at(-10.0).outer_diameter_mm - 30.0).abs() <= 0.02);
    }
}

/// A right-hand tool cutting with M04 (line 5), a feed into the bar with the spindle stopped
/// (line 9, per minute: per revolution it would be the controller's alarm): each one `spindle`
/// finding at its line; the same tool with M03 none.
#[test]
fn the_spindle_stopped_or_turning_the_wrong_way_is_found() {
    let tools = "[[tool]]\nnumber = 1\nkind = \"turning\"\nhand = \"right\"\n";
    let text = "G99 M04 S600\nT0101\nG00 X42. Z2.\nG00 X36.\nG01 Z-10. F0.1\nG00 X42.\nG00 Z2.\nM05\nG98 G01 X34. Z-5. F100.\nG00 X42.\nM30\n";
    let sim = simulate(&records(text), &setup(tools), &opts()).unwrap();
    let found: Vec<_> = sim.measurement.findings.iter().map(|f| (f.kind, f.line)).collect();
    assert_eq!(found, [("spindle", 5), ("spindle", 9)], "{:?}", sim.measurement.findings);
    let sim = simulate(&records(&text.replace("M04", "M03").replace("M05\n", "")), &setup(tools), &opts()).unwrap();
    assert!(sim.measurement.findings.is_empty(), "{:?}", sim.measurement.findings);
}

/// A boring bar that needs a Ø20 bore (`min_bore_mm`) entering the Ø16 drilled hole (line 7):
/// one `holder` finding there; with a Ø14 minimum none.
#[test]
fn a_boring_bar_in_a_bore_too_small_for_it_is_found() {
    let text = "G99 M03 S600\nT0101\nG00 X0. Z2.\nG01 Z-30. F0.1\nG00 Z2.\nT0202\nG00 X16. Z-10.\nG00 Z2.\nG00 X100. Z100.\nM30\n";
    for (min_bore, want) in [(20.0, vec![("holder", 7)]), (14.0, vec![])] {
        let tools = format!("[[tool]]\nnumber = 1\nkind = \"drill\"\ndiameter_mm = 16.0\n[[tool]]\nnumber = 2\nkind = \"boring\"\nmin_bore_mm = {min_bore}\n");
        let sim = simulate(&records(text), &setup(&tools), &opts()).unwrap();
        let found: Vec<_> = sim.measurement.findings.iter().map(|f| (f.kind, f.line)).collect();
        assert_eq!(found, want, "{:?}", sim.measurement.findings);
    }
}

mod property {
    use ncsight::motion::Op;
    use ncsight::source::Span;
    use ncsight::stock::lathe::LatheStock;
    use ncsight::stock::{Bar, Tool, ToolKind};
    use ncsight::{Record, Vec3};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// Any feeds of a turning tool, a boring bar, a grooving tool or a drill on a Ø40 bar:
        /// after every record no cell's outside grew and no bore shrank (material only
        /// decreases), and a record cut a second time removes nothing more.
        #[test]
        fn material_only_decreases_and_a_second_cut_removes_nothing(
            moves in prop::collection::vec(((0.0f64..22.0, -45.0f64..3.0), (0.0f64..22.0, -45.0f64..3.0)), 1..10),
            kind in 0u8..4,
        ) {
            let tool = match kind {
                0 => Tool { number: 1, kind: ToolKind::Turning, tip_radius_mm: 0.4, ..Tool::default_thread() },
                1 => Tool { number: 1, kind: ToolKind::Boring, tip_radius_mm: 0.4, ..Tool::default_thread() },
                2 => Tool { number: 1, kind: ToolKind::Groove, width_mm: 3.0, corner_radius_mm: 0.2, ..Tool::default_thread() },
                _ => Tool { number: 1, kind: ToolKind::Drill, diameter_mm: 12.0, ..Tool::default_thread() },
            };
            let mut s = LatheStock::new(Bar { diameter_mm: 40.0, length_mm: 50.0, bore_mm: 0.0, front_z_mm: 0.0 }, false, 0.05, 24);
            for ((ax, az), (bx, bz)) in moves {
                let (from, to) = if kind == 3 { (Vec3::new(0.0, 0.0, az), Vec3::new(0.0, 0.0, bz)) } else { (Vec3::new(ax, 0.0, az), Vec3::new(bx, 0.0, bz)) };
                let r = Record::new(Span::default(), Op::Feed { from, to, feed_mm_min: 100.0 });
                let (outer, inner) = (s.outer.clone(), s.inner.clone());
                s.apply(&r, &tool, 600.0);
                prop_assert!(s.outer.iter().zip(&outer).all(|(a, b)| a <= b));
                prop_assert!(s.inner.iter().zip(&inner).all(|(a, b)| a >= b));
                let (outer, inner) = (s.outer.clone(), s.inner.clone());
                s.apply(&r, &tool, 600.0);
                prop_assert_eq!(&s.outer, &outer);
                prop_assert_eq!(&s.inner, &inner);
            }
        }
    }
}
