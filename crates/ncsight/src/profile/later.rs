//! Codes each controller's manual has that ncsight does not simulate yet: listed so that a
//! programme using one stops with "not simulated yet" (NCS-E38), never "no such G code". The
//! lists follow each manual's G-code table; where no table of that controller was at hand the
//! nearest one is used and the meaning says "inferred" (docs/profiles.md names the sources).

use super::common::{g, gp};
use super::{GDef, GFn, Group};

/// FANUC 0-M (the 0-M list as the FANUC 0i-MC manual gives it; seed 003's table of contents
/// names G27-G30, G52, G53, G92).
pub(super) const FANUC_0M: &[GDef] = &[
    g(9, Group::NonModal, GFn::PathControl, "exact stop for one block (no effect here: every move of ncsight's time model ends at rest)"),
    g(10, Group::NonModal, GFn::DataSetting, "programmable data input (offsets, work offsets; L50 parameters)"),
    g(11, Group::NonModal, GFn::DataSettingEnd, "programmable data input cancel (the end of G10 L50's parameter lines)"),
    g(15, Group::Polar, GFn::PolarCoordinates(false), "polar coordinate command off"),
    g(16, Group::Polar, GFn::PolarCoordinates(true), "polar coordinate command on: the plane's first word a radius, the second an angle"),
    g(22, Group::StrokeCheck, GFn::StrokeCheck(true), "stored stroke check 2 on: X Y Z the upper limits, I J K the lower, machine coordinates"),
    g(23, Group::StrokeCheck, GFn::StrokeCheck(false), "stored stroke check 2 off"),
    g(27, Group::NonModal, GFn::ReferenceCheck, "reference point return check"),
    g(29, Group::NonModal, GFn::FromReference, "return from the reference point through the last G28/G30 intermediate point"),
    g(30, Group::NonModal, GFn::OtherReferenceReturn, "return to the 2nd, 3rd or 4th reference point"),
    g(31, Group::NonModal, GFn::Skip, "skip function (feed until the skip signal)"),
    g(33, Group::Motion, GFn::Thread(crate::profile::ThreadCmd::Lead), "thread cutting: F the lead along the long axis, Q the start angle"),
    g(37, Group::NonModal, GFn::ToolMeasure(2), "automatic tool length measurement: G37 Z_, the measuring position"),
    g(39, Group::NonModal, GFn::CornerArc, "corner circular interpolation in cutter compensation: the next outer corner an arc of the cutter's radius"),
    g(45, Group::NonModal, GFn::OffsetMove(1), "tool offset increase"),
    g(46, Group::NonModal, GFn::OffsetMove(-1), "tool offset decrease"),
    g(47, Group::NonModal, GFn::OffsetMove(2), "tool offset double increase"),
    g(48, Group::NonModal, GFn::OffsetMove(-2), "tool offset double decrease"),
    g(50, Group::Scaling, GFn::Scaling(false), "scaling off"),
    gp(50, 1, "G50.1", Group::MirrorImage, GFn::MirrorImage(false), "programmable mirror image off"),
    g(51, Group::Scaling, GFn::Scaling(true), "scaling on (an option: setting scaling_option)"),
    gp(51, 1, "G51.1", Group::MirrorImage, GFn::MirrorImage(true), "programmable mirror image on"),
    g(52, Group::NonModal, GFn::LocalCoordinates, "local coordinate system"),
    g(60, Group::NonModal, GFn::SingleDirection, "single direction positioning"),
    g(
        62,
        Group::PathMode,
        GFn::CornerOverride,
        "automatic corner override: the feed lowered about inner corners in cutter compensation (parameters 1711-1714)",
    ),
    g(63, Group::PathMode, GFn::TappingMode, "tapping mode: feed override 100 %, FEED HOLD at the block's end"),
    g(65, Group::NonModal, GFn::MacroCall, "custom macro call"),
    g(66, Group::MacroCall, GFn::ModalMacroCall, "custom macro modal call"),
    g(67, Group::MacroCall, GFn::ModalMacroCancel, "custom macro modal call cancel"),
    g(68, Group::Rotation, GFn::Rotation(true), "coordinate system rotation"),
    g(69, Group::Rotation, GFn::Rotation(false), "coordinate system rotation cancel"),
    g(96, Group::SpindleSpeedMode, GFn::ConstantSurfaceSpeed, "constant surface speed control: S in m/min at the radius of the axis parameter 3770 names"),
    g(97, Group::SpindleSpeedMode, GFn::ConstantRpm, "constant surface speed control cancel: S in rpm"),
];

/// FANUC 0-T, G-code system A (the FANUC 0-TC G-code table; the 0i-TC for what it lacks).
pub(super) const FANUC_0T: &[GDef] = &[
    gp(
        7,
        1,
        "G07.1",
        Group::NonModal,
        GFn::CylindricalInterpolation,
        "cylindrical interpolation: G07.1 C<radius> on, G07.1 C0 off; Z and C (degrees) on the unrolled cylinder",
    ),
    g(10, Group::NonModal, GFn::DataSetting, "programmable data input (offsets, work offsets; L50 parameters)"),
    g(11, Group::NonModal, GFn::DataSettingEnd, "programmable data input cancel (the end of G10 L50's parameter lines)"),
    gp(
        12,
        1,
        "G12.1",
        Group::Polar,
        GFn::PolarInterpolation(true),
        "polar coordinate interpolation on: X (a diameter) and the hypothetical C (a length) made by X and the C axis",
    ),
    gp(13, 1, "G13.1", Group::Polar, GFn::PolarInterpolation(false), "polar coordinate interpolation off"),
    g(22, Group::StrokeCheck, GFn::StrokeCheck(true), "stored stroke check 2 on: X Y Z the upper limits, I J K the lower, machine coordinates"),
    g(23, Group::StrokeCheck, GFn::StrokeCheck(false), "stored stroke check 2 off"),
    g(25, Group::SpindleCheck, GFn::PathControl, "spindle speed fluctuation detection off (no effect: the simulated spindle does not fluctuate)"),
    g(26, Group::SpindleCheck, GFn::PathControl, "spindle speed fluctuation detection on (no effect: the simulated spindle does not fluctuate)"),
    g(27, Group::NonModal, GFn::ReferenceCheck, "reference point return check"),
    g(30, Group::NonModal, GFn::OtherReferenceReturn, "return to the 2nd, 3rd or 4th reference point"),
    g(31, Group::NonModal, GFn::Skip, "skip function"),
    g(36, Group::NonModal, GFn::ToolMeasure(0), "automatic tool compensation, X: G36 X_, the measuring position"),
    g(37, Group::NonModal, GFn::ToolMeasure(2), "automatic tool compensation, Z: G37 Z_, the measuring position"),
    g(52, Group::NonModal, GFn::LocalCoordinates, "local coordinate system"),
    g(53, Group::NonModal, GFn::MachineCoordinates, "positioning in the machine coordinate system"),
    g(65, Group::NonModal, GFn::MacroCall, "custom macro call"),
    g(66, Group::MacroCall, GFn::ModalMacroCall, "custom macro modal call"),
    g(67, Group::MacroCall, GFn::ModalMacroCancel, "custom macro modal call cancel"),
    g(
        68,
        Group::Rotation,
        GFn::TurretMirror(true),
        "mirror image for double turrets on: X mirrored about the centre line (the turret shift, parameter 1290, not applied)",
    ),
    g(69, Group::Rotation, GFn::TurretMirror(false), "mirror image for double turrets off"),
];

/// GSK980TDi (every code of the on-line help text).
pub(super) const GSK980TDI: &[GDef] = &[
    gp(
        7,
        1,
        "G07.1",
        Group::NonModal,
        GFn::CylindricalInterpolation,
        "cylindrical interpolation, type I: G07.1 C<radius> on, G07.1 C0 off (type II, the roughing cycle, is not simulated)",
    ),
    g(9, Group::NonModal, GFn::PathControl, "exact stop for one block (no effect here: every move of ncsight's time model ends at rest)"),
    g(10, Group::NonModal, GFn::DataSetting, "data input from the programme (L3: tool life; L52: parameters)"),
    g(11, Group::NonModal, GFn::DataSettingEnd, "data input cancel (the end of G10 L3's or L52's lines)"),
    gp(
        12,
        1,
        "G12.1",
        Group::Polar,
        GFn::PolarInterpolation(true),
        "polar coordinate interpolation on: X (a diameter) and the hypothetical C (a length) made by X and the C axis",
    ),
    gp(13, 1, "G13.1", Group::Polar, GFn::PolarInterpolation(false), "polar coordinate interpolation off"),
    g(15, Group::Polar2, GFn::PolarCoordinates(false), "polar coordinate command off: Cartesian X, C in the polar interpolation plane"),
    g(16, Group::Polar2, GFn::PolarCoordinates(true), "polar coordinate command on, in the polar interpolation plane: X the radius, C the angle"),
    g(22, Group::StrokeCheck, GFn::StrokeCheck(true), "stored stroke check 2 on: X Y Z the upper limits, I J K the lower, machine coordinates"),
    g(23, Group::StrokeCheck, GFn::StrokeCheck(false), "stored stroke check 2 off"),
    g(30, Group::NonModal, GFn::OtherReferenceReturn, "return to the 2nd, 3rd or 4th reference point"),
    g(31, Group::NonModal, GFn::Skip, "skip function"),
    g(36, Group::NonModal, GFn::ToolMeasure(0), "automatic tool compensation, X: G36 X_, the measuring position"),
    g(37, Group::NonModal, GFn::ToolMeasure(2), "automatic tool compensation, Z: G37 Z_, the measuring position"),
    g(52, Group::NonModal, GFn::LocalCoordinates, "local coordinate system"),
    g(61, Group::PathMode, GFn::PathControl, "exact stop mode (no effect on the path or the time modelled)"),
    g(64, Group::PathMode, GFn::PathControl, "continuous cutting mode (no effect on the path or the time modelled)"),
    g(65, Group::NonModal, GFn::MacroCall, "macro call (macro A and B)"),
    g(66, Group::MacroCall, GFn::ModalMacroCall, "macro modal call"),
    g(67, Group::MacroCall, GFn::ModalMacroCancel, "macro modal call cancel"),
];

/// GSK988T: G12.1/G13.1 from its G-code table; the rest inferred from the GSK980TDi help text.
pub(super) const GSK988T: &[GDef] = &[
    g(10, Group::NonModal, GFn::DataSetting, "data input from the programme: L3 tool life, L52 parameters (inferred)"),
    g(11, Group::NonModal, GFn::DataSettingEnd, "data input cancel (inferred)"),
    gp(
        12,
        1,
        "G12.1",
        Group::Polar,
        GFn::PolarInterpolation(true),
        "polar coordinate interpolation on: X (a diameter) and the hypothetical C (a length) made by X and the C axis",
    ),
    gp(13, 1, "G13.1", Group::Polar, GFn::PolarInterpolation(false), "polar coordinate interpolation off"),
    g(22, Group::StrokeCheck, GFn::StrokeCheck(true), "stored stroke check 2 on: X Y Z the upper limits, I J K the lower, machine coordinates (inferred)"),
    g(23, Group::StrokeCheck, GFn::StrokeCheck(false), "stored stroke check 2 off (inferred)"),
    g(27, Group::NonModal, GFn::ReferenceCheck, "reference point return check (inferred)"),
    g(30, Group::NonModal, GFn::OtherReferenceReturn, "return to the 2nd, 3rd or 4th reference point (inferred)"),
    g(31, Group::NonModal, GFn::Skip, "skip function (inferred)"),
    g(36, Group::NonModal, GFn::ToolMeasure(0), "automatic tool compensation, X: G36 X_, the measuring position (inferred)"),
    g(37, Group::NonModal, GFn::ToolMeasure(2), "automatic tool compensation, Z: G37 Z_, the measuring position (inferred)"),
    g(52, Group::NonModal, GFn::LocalCoordinates, "local coordinate system (inferred)"),
    g(53, Group::NonModal, GFn::MachineCoordinates, "positioning in the machine coordinate system (inferred)"),
    g(65, Group::NonModal, GFn::MacroCall, "macro call (inferred)"),
    g(66, Group::MacroCall, GFn::ModalMacroCall, "macro modal call (inferred)"),
    g(67, Group::MacroCall, GFn::ModalMacroCancel, "macro modal call cancel (inferred)"),
];

/// YASNAC LX3: no G-code table was found; FANUC 0-T-style lathe codes (inferred).
pub(super) const YASNAC_LX3: &[GDef] = &[
    g(10, Group::NonModal, GFn::DataSetting, "data setting: offsets, work offsets, L50 parameters (inferred)"),
    g(11, Group::NonModal, GFn::DataSettingEnd, "data setting cancel (inferred)"),
    g(22, Group::StrokeCheck, GFn::StrokeCheck(true), "stored stroke check 2 on: X Y Z the upper limits, I J K the lower, machine coordinates (inferred)"),
    g(23, Group::StrokeCheck, GFn::StrokeCheck(false), "stored stroke check 2 off (inferred)"),
    g(27, Group::NonModal, GFn::ReferenceCheck, "reference point return check (inferred)"),
    g(29, Group::NonModal, GFn::FromReference, "return from the reference point through the last G28/G30 intermediate point (inferred)"),
    g(30, Group::NonModal, GFn::OtherReferenceReturn, "return to the 2nd reference point (inferred)"),
    g(31, Group::NonModal, GFn::Skip, "skip function (inferred)"),
    g(65, Group::NonModal, GFn::MacroCall, "custom macro call (inferred)"),
    g(66, Group::MacroCall, GFn::ModalMacroCall, "custom macro modal call (inferred)"),
    g(67, Group::MacroCall, GFn::ModalMacroCancel, "custom macro modal call cancel (inferred)"),
    g(68, Group::Rotation, GFn::TurretMirror(true), "program mirror image on: X mirrored about the centre line (YASNAC LX3 manual 2.8.24)"),
    g(69, Group::Rotation, GFn::TurretMirror(false), "program mirror image off (YASNAC LX3 manual 2.8.24)"),
];
