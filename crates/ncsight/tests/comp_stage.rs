//! Radius compensation's look-ahead stage with what goes on around it: held thread runs, moves
//! along the normal axis, blocks without moves, subprogramme ends, single block (the cases a
//! reviewer found, each a programme).

mod common;

use ncsight::motion::Op;
use ncsight::Record;

fn run(machine: &str, setup: &str, text: &str, single_block: bool) -> (Vec<Record>, Vec<ncsight::Diagnostic>) {
    common::run_setup(machine, setup, text, single_block)
}

const LATHE: &str = "[[offset]]\nnumber = 1\nradius_mm = 0.8\ntip = 3\n";
const MILL: &str = "[[offset]]\nnumber = 1\nradius_mm = 2.5\n";

/// Every move starts where the one before it ended (time order, no jumps), unless `except`.
fn continuous(records: &[Record]) {
    let moves: Vec<&Record> = records.iter().filter(|r| r.op.start_point().is_some()).collect();
    for w in moves.windows(2) {
        let (a, b) = (w[0].op.end_point().unwrap(), w[1].op.start_point().unwrap());
        assert!(a.dist(&b) < 1e-9, "line {} ends at {a:?}, line {} starts at {b:?}", w[0].span.line, w[1].span.line);
    }
}

#[test]
fn a_thread_in_compensation_is_cut_where_it_is_written() {
    let text = "T0101\nG97 S500 M03\nG0 X20. Z2.\nG42 G1 Z0 F100.\nG32 Z-20. F1.5\nG0 X30.\nG40 G0 X100. Z100.\nM30\n";
    let (records, diags) = run("gsk980tdi", LATHE, text, false);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    let thread = records.iter().find(|r| r.op.is_thread()).expect("the thread");
    // G32 Z-20 from X20 Z0 as written (the tool is first brought there from where the
    // compensated start-up left it).
    let (from, to) = (thread.op.start_point().unwrap(), thread.op.end_point().unwrap());
    assert!((from.x - 10.0).abs() < 1e-9 && from.z.abs() < 1e-9 && (to.z + 20.0).abs() < 1e-9, "{from:?} -> {to:?}");
    continuous(&records);
}

#[test]
fn a_move_along_the_normal_axis_waits_behind_the_held_move_and_the_next_start_follows_it() {
    // FANUC: one block without a move in the plane (M08) is looked across; the Z move is the
    // second: the held X20 ends perpendicular, the Z plunge is made there, Y20 starts from it.
    let text = "G21 G17 G90 G0 X0. Y0. Z5.\nG41 D1 G1 X0. Y0. F100.\nX20.\nM08\nG1 Z-2.\nY20.\nG40 X0.\nM30\n";
    let (records, diags) = run("fanuc0m", MILL, text, false);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    continuous(&records);
    let y20 = records.iter().find(|r| r.span.line == 6).unwrap();
    assert!((y20.op.start_point().unwrap().z + 2.0).abs() < 1e-9, "Y20 starts at Z-2: {:?}", y20.op);
}

#[test]
fn an_arc_after_the_look_ahead_ran_out_is_no_start_up() {
    let text = "G21 G17 G90 G0 X0. Y-10. Z5.\nG41 D1 G1 X0. Y0. F100.\nX20.\nM08\nM09\nG3 X30. Y10. R10.\nG1 Y20.\nG40 X40.\nM30\n";
    let (records, diags) = run("fanuc0m", MILL, text, false);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    continuous(&records);
}

#[test]
fn m99_in_the_main_programme_ends_after_the_held_move() {
    let text = "G21 G17 G90 G0 X0. Y-10. Z5.\nG41 D1 G1 X0. Y0. F100.\nX20.\nM99\n";
    let (records, _) = run("fanuc0m", MILL, text, false);
    let last = records.last().unwrap();
    assert!(matches!(last.op, Op::End { code: 99 }), "{:?}", last.op);
    assert!(records.iter().any(|r| r.span.line == 3 && r.op.end_point().is_some()), "the X20 move is made");
}

#[test]
fn single_block_stops_after_every_block_in_compensation() {
    let text = "G21 G17 G90 G0 X0. Y-10. Z5.\nG41 D1 G1 X0. Y0. F100.\nX20.\nY20.\nX0.\nG40 Y-10.\nM30\n";
    let (records, _) = run("fanuc0m", MILL, text, true);
    let stops: Vec<u32> = records.iter().filter(|r| matches!(r.op, Op::Stop { .. })).map(|r| r.span.line).collect();
    for line in 2..=6 {
        assert!(stops.contains(&line), "no single-block stop after line {line}: {stops:?}");
    }
}

#[test]
fn a_new_t_offset_in_compensation_brings_its_radius() {
    let setup = "[[offset]]\nnumber = 1\nradius_mm = 0.8\ntip = 3\n[[offset]]\nnumber = 2\nradius_mm = 0.4\ntip = 3\n";
    let text = "T0101\nG0 X20. Z2.\nG42 G1 Z0 F100.\nZ-10.\nT0102\nG1 Z-20.\nZ-30.\nG40 G0 X100.\nM30\n";
    let (records, diags) = run("gsk980tdi", setup, text, false);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    // Z-parallel with tip 3: the tip is on the line whatever the radius; the perpendicular end
    // of the last move shows the radius: R0.4 -> Z-30.4.
    let last_cut = records.iter().rev().find(|r| r.span.line == 7).unwrap();
    assert!((last_cut.op.end_point().unwrap().z + 30.4).abs() < 1e-9, "{:?}", last_cut.op);
}

#[test]
fn single_block_does_not_stop_inside_a_thread_run_in_compensation() {
    let text = "T0101\nG97 S500 M03\nG0 X30. Z5.\nG42 G1 X20. F100.\nG32 Z-10. F1.5\nG32 X24. Z-20.\nG0 X40.\nG40 G0 X100. Z100.\nM30\n";
    let (records, diags) = run("fanuc0t", LATHE, text, true);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    let threads: Vec<usize> = records.iter().enumerate().filter(|(_, r)| r.op.is_thread()).map(|(i, _)| i).collect();
    assert!(threads.len() >= 2, "{records:?}");
    assert!(records[threads[0]..threads[threads.len() - 1]].iter().all(|r| !matches!(r.op, Op::Stop { .. })), "a stop inside the thread run");
}

#[test]
fn g92_in_compensation_moves_the_waiting_point_with_the_coordinates() {
    // The held X10 ends perpendicular at X10 Y5; G92 makes X10 Y0 the new X0 Y0: the next move
    // starts at X0 Y5 in the new coordinates.
    let text = "G21 G17 G90 G0 X0. Y0. Z0.\nG41 D1 G1 X10. F100.\nG92 X0. Y0.\nG1 X10.\nG40 X20.\nM30\n";
    let (records, diags) = run("fanuc0m", "[[offset]]\nnumber = 1\nradius_mm = 5.0\n", text, false);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
    let next = records.iter().find(|r| r.span.line == 4).unwrap();
    let from = next.op.start_point().unwrap();
    assert!(from.x.abs() < 1e-9 && (from.y - 5.0).abs() < 1e-9, "{from:?}");
}

#[test]
fn a_shallow_g90_pass_in_compensation_is_no_interference() {
    // The start 0.5 mm (radius) from the cut, the nose radius 0.8: the out move ends where it ends.
    let text = "T0101\nG99 G97 S800 M03\nG0 X50. Z2.\nG42\nG90 X49. Z-20. F0.2\nG40 G0 X100. Z100.\nM30\n";
    let (_, diags) = run("fanuc0t", LATHE, text, false);
    assert!(diags.iter().all(|d| !d.is_alarm()), "{diags:?}");
}
