//! G and M codes that the G-code-system-A lathes share (GSK980TDi, GSK988T, YASNAC LX3), beyond
//! the common ones. Sources: GSK980TDi help text sections G50, G70-G76, G90/G94, G96/97, G98/99
//! and the M-code list.

use super::common::{g, m};
use super::{GDef, GFn, Group, MDef, MFn};
use crate::codes::BoxKind;
use crate::codes::PeckKind;
use crate::codes::RoughKind;

pub(super) const LATER_G76: GFn = GFn::NotYet("the G76 compound threading cycle is not simulated by ncsight yet");

/// The multiple repetitive cycles G70-G75, with the same numbers in G-code systems A and B
/// (the FANUC lathe's system B, profile/fanuc0i.rs, has them too).
pub(super) const MULTIPLE_CYCLES: &[GDef] = &[
    g(70, Group::NonModal, GFn::Finish, "finishing cycle"),
    g(71, Group::NonModal, GFn::Rough(RoughKind::Turning), "stock removal in turning"),
    g(72, Group::NonModal, GFn::Rough(RoughKind::Facing), "stock removal in facing"),
    g(73, Group::NonModal, GFn::Rough(RoughKind::Pattern), "pattern repeating"),
    g(74, Group::NonModal, GFn::PeckCycle(PeckKind::Face), "end face peck drilling"),
    g(75, Group::NonModal, GFn::PeckCycle(PeckKind::Groove), "outer/inner diameter grooving"),
];

/// Shared by all the system-A lathe profiles, with `MULTIPLE_CYCLES`.
pub(super) const G_CODES: &[GDef] = &[
    g(50, Group::NonModal, GFn::LatheCoordinateSet, "set the coordinates of the current position; S: spindle speed clamp"),
    g(90, Group::Motion, GFn::BoxCycle(BoxKind::Turning), "outer/inner diameter cutting cycle"),
    g(94, Group::Motion, GFn::BoxCycle(BoxKind::Facing), "end face cutting cycle"),
    g(96, Group::SpindleSpeedMode, GFn::ConstantSurfaceSpeed, "constant surface speed: S in m/min"),
    g(97, Group::SpindleSpeedMode, GFn::ConstantRpm, "constant spindle speed: S in rpm"),
    g(98, Group::FeedMode, GFn::FeedPerMinute, "feed per minute: F in mm/min"),
    g(99, Group::FeedMode, GFn::FeedPerRevolution, "feed per revolution: F in mm/rev"),
];

/// M codes of the lathes beyond the common ones (TDi help M10-M13).
pub(super) const M_CODES: &[MDef] = &[
    m(10, MFn::Auxiliary, "tailstock forward"),
    m(11, MFn::Auxiliary, "tailstock back"),
    m(12, MFn::Auxiliary, "chuck clamp"),
    m(13, MFn::Auxiliary, "chuck release"),
];

/// GSK lathes: the servo spindle's modes and the other M codes of the TDi help (M14-M44).
pub(super) const GSK_M_CODES: &[MDef] = &[
    m(14, MFn::SpindlePositionMode, "spindle to position (CS) mode"),
    m(15, MFn::SpindleSpeedMode, "spindle to speed mode"),
    m(20, MFn::Auxiliary, "spindle clamp"),
    m(21, MFn::Auxiliary, "spindle release"),
    m(32, MFn::Auxiliary, "lubrication on"),
    m(33, MFn::Auxiliary, "lubrication off"),
    m(41, MFn::Auxiliary, "spindle gear 1"),
    m(42, MFn::Auxiliary, "spindle gear 2"),
    m(43, MFn::Auxiliary, "spindle gear 3"),
    m(44, MFn::Auxiliary, "spindle gear 4"),
];
