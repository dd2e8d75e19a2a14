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
    let twice: Vec<Record> = recs
        .iter()
        .flat_map(
            |r| if matches!(r.op, ncsight::motion::Op::Feed { .. } | ncsight::motion::Op::Arc { .. }) { vec![r.clone(), r.clone()] } else { vec![r.clone()] },
        )
        .collect();
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
    let tool = |extra: &str| {
        Setup::from_toml(&format!(
            "[block]\nmin_mm = [0.0, 0.0, -20.0]\nmax_mm = [90.0, 60.0, 0.0]\n[[tool]]\nnumber = 1\nkind = \"mill\"\ndiameter_mm = 6.0\n{extra}"
        ))
        .unwrap()
    };
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

/// A 30 x 20 mm boss (X15-45, Y10-30) left standing 5 mm high by a Ø10 end mill contouring round
/// it under cutter compensation (offset D1 = 5 mm): once with G41, going round clockwise (climb
/// milling with M03), once with G42 counter-clockwise (conventional). By hand, both leave the
/// boss's walls at X15, X45, Y10 and Y30 (the tool's centre 5 mm out), within one 0.1 mm cell;
/// outside the walls the floor at Z-5 as far as the tool reaches (10 mm out from the wall: to
/// X55 beyond the X45 wall, the block running on to X60).
#[test]
fn a_contour_climb_or_conventional_leaves_its_walls_where_drawn() {
    let setup = Setup::from_toml("[block]\nmin_mm = [0.0, 0.0, -10.0]\nmax_mm = [60.0, 40.0, 0.0]\n[[tool]]\nnumber = 1\nkind = \"mill\"\ndiameter_mm = 10.0\n[[offset]]\nnumber = 1\nradius_mm = 5.0\n").unwrap();
    let climb =
        "G21 G17 G90 G54\nT1 M06\nS3000 M03\nG00 X5. Y5. Z5.\nG01 Z-5. F200.\nG41 D1 G01 X15. Y10.\nY30.\nX45.\nY10.\nX15.\nG40 G01 X5. Y5.\nG00 Z5.\nM30\n";
    let conventional =
        "G21 G17 G90 G54\nT1 M06\nS3000 M03\nG00 X5. Y5. Z5.\nG01 Z-5. F200.\nG42 D1 G01 X15. Y10.\nX45.\nY30.\nX15.\nY10.\nG40 G01 X5. Y5.\nG00 Z5.\nM30\n";
    for (name, text) in [("climb", climb), ("conventional", conventional)] {
        let (recs, diags) = common::run_setup(
            "fanuc0m",
            "[block]\nmin_mm = [0.0, 0.0, -10.0]\nmax_mm = [60.0, 40.0, 0.0]\n[[offset]]\nnumber = 1\nradius_mm = 5.0\n",
            text,
            false,
        );
        assert!(diags.iter().all(|d| !d.is_alarm()), "{name}: {diags:?}");
        let sim = simulate_mill(&recs, &setup, Some(0.1), None).unwrap();
        assert!(sim.findings.is_empty(), "{name}: {:?}", sim.findings);
        let s = &sim.stock;
        let top = |x: f64, y: f64| s.top[((y / 0.1) as usize) * s.nx + (x / 0.1) as usize] as f64;
        // Across the middle row and column: the walls within a cell of where they are drawn.
        for (inside, outside) in [((15.05, 20.0), (14.95, 20.0)), ((44.95, 20.0), (45.05, 20.0)), ((30.0, 10.05), (30.0, 9.95)), ((30.0, 29.95), (30.0, 30.05))]
        {
            let (a, b) = (top(inside.0, inside.1), top(outside.0, outside.1));
            let (c, d) = (
                top(inside.0 + (inside.0 - outside.0), inside.1 + (inside.1 - outside.1)),
                top(outside.0 - (inside.0 - outside.0), outside.1 - (inside.1 - outside.1)),
            );
            assert!(a == 0.0 && c == 0.0, "{name}: the boss stands at {inside:?}: {a} {c}");
            assert!(b == -5.0 && d == -5.0, "{name}: the floor beside it at {outside:?}: {b} {d}");
        }
        // The floor reaches 10 mm out from the wall (the tool's width), not further: X45 to X55.
        assert_eq!(top(54.95, 20.0), -5.0, "{name}");
        assert_eq!(top(55.05, 20.0), 0.0, "{name}");
    }
}

mod property {
    use super::*;
    use ncsight::motion::{ArcDir, Op, Plane};
    use ncsight::source::Span;
    use ncsight::Vec3;
    use proptest::prelude::*;

    fn tool_of(kind: u8, d: f64) -> ncsight::stock::Tool {
        let mut t = ncsight::stock::Tool { number: 1, kind: ncsight::stock::ToolKind::Mill, diameter_mm: d, ..ncsight::stock::Tool::default_thread() };
        match kind {
            0 => {}
            1 => t.shape = ncsight::setup::MillShape::Ball,
            2 => {
                t.shape = ncsight::setup::MillShape::Bull;
                t.corner_radius_mm = d / 4.0;
            }
            _ => t.kind = ncsight::stock::ToolKind::Drill,
        }
        t
    }

    fn moves() -> impl Strategy<Value = Vec<Op>> {
        let p = (2.0f64..38.0, 2.0f64..28.0, -6.0f64..1.0);
        prop::collection::vec((p.clone(), p, any::<bool>()), 1..12).prop_map(|v| {
            v.into_iter()
                .map(|((ax, ay, az), (bx, by, _), arc)| {
                    let (from, to) = (Vec3::new(ax, ay, az), Vec3::new(bx, by, az));
                    if arc {
                        // A half circle from `from` to the point opposite it about the middle.
                        let center = Vec3::new((ax + bx) / 2.0, (ay + by) / 2.0, az);
                        Op::Arc {
                            from,
                            to: Vec3::new(2.0 * center.x - ax, 2.0 * center.y - ay, az),
                            center,
                            plane: Plane::XY,
                            dir: ArcDir::Ccw,
                            feed_mm_min: 300.0,
                        }
                    } else {
                        Op::Feed { from, to, feed_mm_min: 300.0 }
                    }
                })
                .collect()
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// Any moves with any of the tools: after every record no cell stands higher than before
        /// it (material only decreases), and a record cut a second time removes nothing more.
        #[test]
        fn material_only_decreases_and_a_second_cut_removes_nothing(ops in moves(), kind in 0u8..4, d in 1.0f64..12.0) {
            let tool = tool_of(kind, d);
            let block = ncsight::stock::mill::Block { min_mm: [0.0, 0.0, -10.0], max_mm: [40.0, 30.0, 0.0] };
            let mut s = ncsight::stock::mill::MillStock::new(block, 0.25);
            for op in ops {
                let r = Record::new(Span::default(), op);
                let before = s.top.clone();
                s.apply(&r, &tool, 1000.0);
                prop_assert!(s.top.iter().zip(&before).all(|(a, b)| a <= b));
                let once = s.top.clone();
                s.apply(&r, &tool, 1000.0);
                prop_assert_eq!(&s.top, &once);
            }
        }
    }
}
