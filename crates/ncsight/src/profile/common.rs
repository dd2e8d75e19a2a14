//! G and M codes that every profile here shares, with the same meaning on the FANUC 0-M, the
//! GSK lathes and the YASNAC LX3 (GSK980TDi help text G00-G04, G17-G21, G28, G40-G42, G54-G59;
//! the M-code lists).

use super::{GDef, GFn, Group, MDef, MFn};

pub(super) const fn g(major: u32, group: Group, function: GFn, meaning: &'static str) -> GDef {
    GDef { major, minor: None, group, function, meaning }
}

pub(super) const fn gp(major: u32, minor: u32, group: Group, function: GFn, meaning: &'static str) -> GDef {
    GDef { major, minor: Some(minor), group, function, meaning }
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
    g(20, Group::Units, GFn::Inch, "inch input"),
    g(21, Group::Units, GFn::Metric, "metric input"),
    g(28, Group::NonModal, GFn::ReferenceReturn, "return to the reference point via an intermediate point"),
    g(40, Group::CutterComp, GFn::RadiusComp(false), "cancel radius compensation"),
    g(41, Group::CutterComp, GFn::RadiusComp(true), "radius compensation, left"),
    g(42, Group::CutterComp, GFn::RadiusComp(true), "radius compensation, right"),
    g(54, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 1"),
    g(55, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 2"),
    g(56, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 3"),
    g(57, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 4"),
    g(58, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 5"),
    g(59, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 6"),
];

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
