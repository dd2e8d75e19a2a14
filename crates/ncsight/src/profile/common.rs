//! G and M codes that every profile here shares, with the same meaning on the FANUC 0-M, the
//! GSK lathes and the YASNAC LX3 (GSK980TDi help text G00-G04, G17-G21, G28, G40-G42, G54-G59;
//! the M-code lists).

use super::{GDef, GFn, Group, MDef, MFn};

/// The names of the plain codes G00-G99, as the controllers' manuals write them.
const NAMES: [&str; 100] = {
    // One string of all the names, three bytes each (a const fn cannot format numbers).
    const ALL: &str = "G00G01G02G03G04G05G06G07G08G09G10G11G12G13G14G15G16G17G18G19G20G21G22G23G24G25G26G27G28G29G30G31G32G33G34G35G36G37G38G39G40G41G42G43G44G45G46G47G48G49G50G51G52G53G54G55G56G57G58G59G60G61G62G63G64G65G66G67G68G69G70G71G72G73G74G75G76G77G78G79G80G81G82G83G84G85G86G87G88G89G90G91G92G93G94G95G96G97G98G99";
    let mut names = [""; 100];
    let mut i = 0;
    while i < 100 {
        names[i] = ALL.split_at(i * 3).1.split_at(3).0;
        i += 1;
    }
    names
};

pub(super) const fn g(major: u32, group: Group, function: GFn, meaning: &'static str) -> GDef {
    assert!(major < 100, "plain G codes are G00-G99");
    GDef { major, minor: None, name: NAMES[major as usize], group, function, meaning }
}

pub(super) const fn gp(major: u32, minor: u32, name: &'static str, group: Group, function: GFn, meaning: &'static str) -> GDef {
    GDef { major, minor: Some(minor), name, group, function, meaning }
}

pub(super) const fn m(code: u32, function: MFn, meaning: &'static str) -> MDef {
    MDef { code, function, meaning }
}

pub(super) const G_CODES: &[GDef] = &[
    g(0, Group::Motion, GFn::Rapid, "rapid positioning; each axis at its own rapid rate (TDi help G00)"),
    g(1, Group::Motion, GFn::Linear, "linear interpolation at feed F"),
    g(2, Group::Motion, GFn::ArcCw, "circular interpolation clockwise"),
    g(3, Group::Motion, GFn::ArcCcw, "circular interpolation counter-clockwise"),
    g(4, Group::NonModal, GFn::Dwell, "dwell: P in ms, X (U) in s"),
    g(17, Group::Plane, GFn::PlaneXY, "XY plane"),
    g(18, Group::Plane, GFn::PlaneZX, "ZX plane"),
    g(19, Group::Plane, GFn::PlaneYZ, "YZ plane"),
    g(28, Group::NonModal, GFn::ReferenceReturn, "return to the reference point via an intermediate point"),
    g(40, Group::CutterComp, GFn::RadiusComp(0), "cancel radius compensation"),
    g(41, Group::CutterComp, GFn::RadiusComp(1), "radius compensation, left"),
    g(42, Group::CutterComp, GFn::RadiusComp(-1), "radius compensation, right"),
    g(54, Group::WorkOffset, GFn::WorkOffset(1), "work coordinate system 1"),
    g(55, Group::WorkOffset, GFn::WorkOffset(2), "work coordinate system 2"),
    g(56, Group::WorkOffset, GFn::WorkOffset(3), "work coordinate system 3"),
    g(57, Group::WorkOffset, GFn::WorkOffset(4), "work coordinate system 4"),
    g(58, Group::WorkOffset, GFn::WorkOffset(5), "work coordinate system 5"),
    g(59, Group::WorkOffset, GFn::WorkOffset(6), "work coordinate system 6"),
];

/// G20/G21, apart: the FANUC lathe's G-code system C names them G70/G71.
pub(super) const UNITS: &[GDef] = &[g(20, Group::Units, GFn::Inch, "inch input"), g(21, Group::Units, GFn::Metric, "metric input")];

pub(super) const M_CODES: &[MDef] = &[
    m(0, MFn::ProgramStop, "programme stop"),
    m(1, MFn::OptionalStop, "optional stop"),
    m(2, MFn::ProgramEnd, "programme end"),
    m(3, MFn::SpindleCw, "spindle forward (positive direction)"),
    m(4, MFn::SpindleCcw, "spindle reverse (negative direction)"),
    m(5, MFn::SpindleStop, "spindle stop"),
    m(8, MFn::Auxiliary, "coolant on"),
    m(9, MFn::Auxiliary, "coolant off"),
    m(30, MFn::ProgramEnd, "programme end and rewind"),
    m(98, MFn::SubprogramCall, "subprogramme call"),
    m(99, MFn::SubprogramReturn, "subprogramme return"),
];
