//! G and M codes that the G-code-system-A lathes share (GSK980TDi, GSK988T, YASNAC LX3).
//! Sources: GSK980TDi help text (../shared/reference/gsk980tdi_help_text_zh.txt) sections
//! G00-G04, G17-G19, G20/21, G28, G40-42, G50, G54-G59, G96/97, G98/99, and the M-code list.

use super::{GDef, GFn, Group, MDef, MFn};

pub(super) const fn g(major: u32, group: Group, function: GFn, meaning: &'static str) -> GDef {
    GDef { major, minor: None, group, function, meaning }
}

pub(super) const fn gp(major: u32, minor: u32, group: Group, function: GFn, meaning: &'static str) -> GDef {
    GDef { major, minor: Some(minor), group, function, meaning }
}

const LATER_MRC: GFn = GFn::NotYet("multiple repetitive cycles (G70-G75) are not simulated by ncsight yet");
const LATER_BOX: GFn = GFn::NotYet("single turning/facing cycles (G90/G94) are not simulated by ncsight yet");
pub(super) const LATER_THREAD: GFn = GFn::NotYet("this thread command is not simulated by ncsight yet");
pub(super) const LATER_G76: GFn = GFn::NotYet("the G76 compound threading cycle is not simulated by ncsight yet");

/// Shared by all three lathe profiles.
pub(super) const G_CODES: &[GDef] = &[
    g(0, Group::Motion, GFn::Rapid, "rapid positioning; each axis at its own rapid rate (TDi help G00)"),
    g(1, Group::Motion, GFn::Linear, "linear interpolation at feed F"),
    g(2, Group::Motion, GFn::ArcCw, "circular interpolation clockwise (rear tool post view)"),
    g(3, Group::Motion, GFn::ArcCcw, "circular interpolation counter-clockwise (rear tool post view)"),
    g(4, Group::NonModal, GFn::Dwell, "dwell: P in ms, X or U in s"),
    g(17, Group::Plane, GFn::PlaneXY, "XY plane"),
    g(18, Group::Plane, GFn::PlaneZX, "ZX plane (power-on plane of a lathe)"),
    g(19, Group::Plane, GFn::PlaneYZ, "YZ plane"),
    g(20, Group::Units, GFn::Inch, "inch input"),
    g(21, Group::Units, GFn::Metric, "metric input"),
    g(28, Group::NonModal, GFn::ReferenceReturn, "return to the reference point via an intermediate point"),
    g(40, Group::CutterComp, GFn::RadiusComp(false), "cancel tool nose radius compensation"),
    g(41, Group::CutterComp, GFn::RadiusComp(true), "tool nose radius compensation, left"),
    g(42, Group::CutterComp, GFn::RadiusComp(true), "tool nose radius compensation, right"),
    g(50, Group::NonModal, GFn::LatheCoordinateSet, "set the coordinates of the current position; S: spindle speed clamp"),
    g(54, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 1"),
    g(55, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 2"),
    g(56, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 3"),
    g(57, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 4"),
    g(58, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 5"),
    g(59, Group::WorkOffset, GFn::WorkOffset, "work coordinate system 6"),
    g(70, Group::NonModal, LATER_MRC, "finishing cycle"),
    g(71, Group::NonModal, LATER_MRC, "stock removal in turning"),
    g(72, Group::NonModal, LATER_MRC, "stock removal in facing"),
    g(73, Group::NonModal, LATER_MRC, "pattern repeating"),
    g(74, Group::NonModal, LATER_MRC, "end face peck drilling"),
    g(75, Group::NonModal, LATER_MRC, "outer/inner diameter grooving"),
    g(76, Group::NonModal, LATER_G76, "compound thread cutting cycle"),
    g(90, Group::Motion, LATER_BOX, "outer/inner diameter cutting cycle"),
    g(94, Group::Motion, LATER_BOX, "end face cutting cycle"),
    g(96, Group::SpindleSpeedMode, GFn::ConstantSurfaceSpeed, "constant surface speed: S in m/min"),
    g(97, Group::SpindleSpeedMode, GFn::ConstantRpm, "constant spindle speed: S in rpm"),
    g(98, Group::FeedMode, GFn::FeedPerMinute, "feed per minute: F in mm/min"),
    g(99, Group::FeedMode, GFn::FeedPerRevolution, "feed per revolution: F in mm/rev"),
];

/// M codes shared by the lathes (TDi help M00-M99).
pub(super) const M_CODES: &[MDef] = &[
    MDef { code: 0, function: MFn::ProgramStop, meaning: "programme stop" },
    MDef { code: 1, function: MFn::OptionalStop, meaning: "optional stop" },
    MDef { code: 2, function: MFn::ProgramEnd, meaning: "programme end" },
    MDef { code: 3, function: MFn::SpindleCw, meaning: "spindle forward (positive direction)" },
    MDef { code: 4, function: MFn::SpindleCcw, meaning: "spindle reverse (negative direction)" },
    MDef { code: 5, function: MFn::SpindleStop, meaning: "spindle stop" },
    MDef { code: 8, function: MFn::Auxiliary, meaning: "coolant on" },
    MDef { code: 9, function: MFn::Auxiliary, meaning: "coolant off" },
    MDef { code: 10, function: MFn::Auxiliary, meaning: "tailstock forward" },
    MDef { code: 11, function: MFn::Auxiliary, meaning: "tailstock back" },
    MDef { code: 12, function: MFn::Auxiliary, meaning: "chuck clamp" },
    MDef { code: 13, function: MFn::Auxiliary, meaning: "chuck release" },
    MDef { code: 30, function: MFn::ProgramEnd, meaning: "programme end and rewind" },
    MDef { code: 98, function: MFn::SubprogramCall, meaning: "subprogramme call" },
    MDef { code: 99, function: MFn::SubprogramReturn, meaning: "subprogramme return" },
];

/// GSK lathes: the servo spindle's position and speed modes (TDi help M14/15, seed 001).
pub(super) const GSK_M_CODES: &[MDef] = &[
    MDef { code: 0, function: MFn::ProgramStop, meaning: "programme stop" },
    MDef { code: 1, function: MFn::OptionalStop, meaning: "optional stop" },
    MDef { code: 2, function: MFn::ProgramEnd, meaning: "programme end" },
    MDef { code: 3, function: MFn::SpindleCw, meaning: "spindle forward (positive direction)" },
    MDef { code: 4, function: MFn::SpindleCcw, meaning: "spindle reverse (negative direction)" },
    MDef { code: 5, function: MFn::SpindleStop, meaning: "spindle stop" },
    MDef { code: 8, function: MFn::Auxiliary, meaning: "coolant on" },
    MDef { code: 9, function: MFn::Auxiliary, meaning: "coolant off" },
    MDef { code: 10, function: MFn::Auxiliary, meaning: "tailstock forward" },
    MDef { code: 11, function: MFn::Auxiliary, meaning: "tailstock back" },
    MDef { code: 12, function: MFn::Auxiliary, meaning: "chuck clamp" },
    MDef { code: 13, function: MFn::Auxiliary, meaning: "chuck release" },
    MDef { code: 14, function: MFn::SpindlePositionMode, meaning: "spindle to position (CS) mode" },
    MDef { code: 15, function: MFn::SpindleSpeedMode, meaning: "spindle to speed mode" },
    MDef { code: 20, function: MFn::Auxiliary, meaning: "spindle clamp" },
    MDef { code: 21, function: MFn::Auxiliary, meaning: "spindle release" },
    MDef { code: 30, function: MFn::ProgramEnd, meaning: "programme end and rewind" },
    MDef { code: 32, function: MFn::Auxiliary, meaning: "lubrication on" },
    MDef { code: 33, function: MFn::Auxiliary, meaning: "lubrication off" },
    MDef { code: 41, function: MFn::Auxiliary, meaning: "spindle gear 1" },
    MDef { code: 42, function: MFn::Auxiliary, meaning: "spindle gear 2" },
    MDef { code: 43, function: MFn::Auxiliary, meaning: "spindle gear 3" },
    MDef { code: 44, function: MFn::Auxiliary, meaning: "spindle gear 4" },
    MDef { code: 98, function: MFn::SubprogramCall, meaning: "subprogramme call" },
    MDef { code: 99, function: MFn::SubprogramReturn, meaning: "subprogramme return" },
];
