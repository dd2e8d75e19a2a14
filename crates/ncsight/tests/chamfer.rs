//! The GSK980TDi's chamfer function (L, D): what comes after the block that asks for one.

mod common;
use ncsight::motion::Op;

fn kinds(text: &str) -> (Vec<String>, Vec<&'static str>) {
    let (r, d) = common::run_plain("gsk980tdi", &[], text);
    (r.iter().map(|r| format!("{}:{}", r.span.line, r.op.kind())).collect(), d.iter().map(|d| d.code).collect())
}

#[test]
fn a_rapid_next_gets_no_corner() {
    let (k, d) = kinds("G98 G00 X0 Z2\nG01 Z0 F100\nX20 L2\nG00 Z-10\nM30\n");
    assert_eq!(k, ["1:rapid", "2:feed", "3:feed", "4:rapid", "5:end"]);
    assert_eq!(d, ["NCS-W04"]);
}

#[test]
fn what_waits_behind_the_move_comes_after_its_chamfer() {
    let (k, d) = kinds("G98 G00 X0 Z2\nG01 Z0 F100\nX20 L2\nS500 M03 Z-10\nM30\n");
    assert_eq!(k, ["1:rapid", "2:feed", "3:feed", "3:feed", "4:spindle", "4:feed", "5:end"]);
    assert!(d.is_empty(), "{d:?}");
}

#[test]
fn a_second_chamfer_counts_the_first() {
    // 2 mm of Z, 1.0607 taken by each chamfer: the second one does not fit.
    let (_, d) = kinds("G98 G00 X0 Z2\nG01 Z0 F100\nX20 L1.5\nZ-2 L1.5\nX30\nM30\n");
    assert_eq!(d, ["NCS-E89"]);
}

#[test]
fn an_l_without_a_move_makes_no_corner() {
    let (r, d) = common::run_plain("gsk980tdi", &[], "G98 G00 X0 Z2\nG01 Z0 F100\nX0 L2\nZ-5\nM30\n");
    assert_eq!(d.iter().map(|d| d.code).collect::<Vec<_>>(), ["NCS-W04"]);
    assert!(matches!(r[2].op, Op::Feed { .. }) && r[2].span.line == 4);
}

#[test]
fn compensation_or_polar_interpolation_next_makes_the_move_first() {
    let (k, _) = kinds("G98 G00 X0 Z2\nG01 Z0 F100\nX20 L2\nG42 Z-10\nG40 X30\nM30\n");
    assert_eq!(&k[..3], ["1:rapid", "2:feed", "3:feed"]);
    let (k, _) = kinds("G98 G00 X0 Z2\nG01 Z0 F100\nX20 L2\nG19\nG18 Z-5\nM30\n");
    assert_eq!(&k[..3], ["1:rapid", "2:feed", "3:feed"]);
}
