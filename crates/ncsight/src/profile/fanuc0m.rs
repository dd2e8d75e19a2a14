//! FANUC 0-M machining centre: seed 003 (drilling canned cycles G73-G89).

use super::common::{self, g, m};
use super::{SETTINGS, DRY_RUN, QPoint, ThreadRules, GDef, GFn, Group, IntegerLengths, MDef, MFn, MachineKind, ParamDef, ParamKey, Profile, TimeKeys};
use crate::alarm::AlarmStyle;
use crate::codes::DrillKind;


pub(super) const G_CODES: &[GDef] = &[
    g(43, Group::LengthComp, GFn::LengthComp(1), "tool length compensation +"),
    g(44, Group::LengthComp, GFn::LengthComp(-1), "tool length compensation -"),
    g(49, Group::LengthComp, GFn::LengthComp(0), "cancel tool length compensation"),
    g(53, Group::NonModal, GFn::MachineCoordinates, "positioning in the machine coordinate system"),
    g(61, Group::PathMode, GFn::PathControl, "exact stop mode"),
    g(64, Group::PathMode, GFn::PathControl, "cutting mode"),
    g(73, Group::CannedCycle, GFn::Drill(DrillKind::G73), "high-speed peck drilling"),
    g(74, Group::CannedCycle, GFn::Drill(DrillKind::G74), "left-hand tapping"),
    g(76, Group::CannedCycle, GFn::Drill(DrillKind::G76), "fine boring"),
    g(80, Group::CannedCycle, GFn::CycleCancel, "cancel canned cycle"),
    g(81, Group::CannedCycle, GFn::Drill(DrillKind::G81), "drilling, spot drilling"),
    g(82, Group::CannedCycle, GFn::Drill(DrillKind::G82), "drilling with dwell"),
    g(83, Group::CannedCycle, GFn::Drill(DrillKind::G83), "peck drilling"),
    g(84, Group::CannedCycle, GFn::Drill(DrillKind::G84), "tapping"),
    g(85, Group::CannedCycle, GFn::Drill(DrillKind::G85), "boring, feed out"),
    g(86, Group::CannedCycle, GFn::Drill(DrillKind::G86), "boring, spindle stop, rapid out"),
    g(87, Group::CannedCycle, GFn::Drill(DrillKind::G87), "back boring"),
    g(88, Group::CannedCycle, GFn::Drill(DrillKind::G88), "boring, dwell, manual retract"),
    g(89, Group::CannedCycle, GFn::Drill(DrillKind::G89), "boring with dwell, feed out"),
    g(90, Group::Distance, GFn::Absolute, "absolute programming"),
    g(91, Group::Distance, GFn::Incremental, "incremental programming"),
    g(92, Group::NonModal, GFn::MillCoordinateSet, "set the coordinates of the current position"),
    g(94, Group::FeedMode, GFn::FeedPerMinute, "feed per minute"),
    g(95, Group::FeedMode, GFn::FeedPerRevolution, "feed per revolution"),
    g(98, Group::ReturnLevel, GFn::ReturnInitial, "canned cycle: return to the initial level"),
    g(99, Group::ReturnLevel, GFn::ReturnR, "canned cycle: return to the R point"),
];

pub(super) const M_CODES: &[MDef] = &[
    m(6, MFn::ToolChange, "tool change"),
    m(19, MFn::Auxiliary, "spindle orientation"),
];

/// Coordinate rotation and scaling (FANUC 0i numbering, inferred for the FANUC 0-M).
pub(super) const TRANSFORMS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(5400, Some(0)),
        meaning: "RIN: G68's R in G91 is 0 = always an absolute angle, 1 = added to the angle in force",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i-C connection manual, coordinate system rotation (5400#0 RIN; inferred for the FANUC 0-M)",
    },
    ParamDef {
        key: ParamKey::Number(5410, None),
        meaning: "G68's angle when R is omitted",
        unit: "0.001 deg",
        min: -360000.0,
        max: 360000.0,
        default: 0.0,
        source: "FANUC 0i-C connection manual, coordinate system rotation (5410; inferred for the FANUC 0-M)",
    },
    ParamDef {
        key: ParamKey::Number(5411, None),
        meaning: "G51's magnification when P is omitted",
        unit: "0.001",
        min: 1.0,
        max: 999999.0,
        default: 1000.0,
        source: "FANUC 0i numbering (inferred); default assumed (1.0)",
    },
    ParamDef {
        key: ParamKey::Setting("scaling_option"),
        meaning: "the machine has the scaling option (G51); 0 = G51 and G50 are IMPROPER G-CODE",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "ncsight setting (scaling is a FANUC option; off at power on, assumed)",
    },
];

/// The parameters with the FANUC 0i's numbers (the 0-M's own not found), which the 0i-MF has too.
pub(super) const PARAMS_0I: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(1710, None),
        meaning: "MDR: inside an arc in cutter compensation the centre path runs at F times its radius over the programmed radius, at least this",
        unit: "%",
        min: 1.0,
        max: 100.0,
        default: 10.0,
        source: "FANUC 0i numbering as recalled (No. 1710, minimum deceleration ratio of inner circular cutting; inferred for the FANUC 0-M); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(1711, None),
        meaning: "G62: an inner corner whose angle on the work side is at most this is overridden (2-178)",
        unit: "deg",
        min: 2.0,
        max: 178.0,
        default: 91.0,
        source: "FANUC 16i operator's manual, inside-corner override (No. 1711; 0i numbering, inferred for the FANUC 0-M); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(1712, None),
        meaning: "G62: the override at inner corners",
        unit: "%",
        min: 1.0,
        max: 100.0,
        default: 50.0,
        source: "FANUC 16i operator's manual, inside-corner override (No. 1712); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(1713, None),
        meaning: "G62: Le, how far after an inner corner the override lasts (cutter centre path)",
        unit: "mm",
        min: 0.0,
        max: 3999.0,
        default: 1.0,
        source: "FANUC 0i numbering as recalled (No. 1713, Le from the start of the next block); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(1714, None),
        meaning: "G62: Ls, how far before an inner corner the override starts (cutter centre path)",
        unit: "mm",
        min: 0.0,
        max: 3999.0,
        default: 1.0,
        source: "FANUC 0i numbering as recalled (No. 1714, Ls up to the end of the block); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(3770, None),
        meaning: "G96 on a machining centre: the axis whose coordinate is the radius of the surface speed (1 = X, 2 = Y, 3 = Z)",
        unit: "axis",
        min: 1.0,
        max: 3.0,
        default: 1.0,
        source: "FANUC 0i-MC numbering, as recalled (the 0-M's number not found); default assumed",
    },
];

/// The FANUC 0-M's own numbers: the G76/G87 shift, the rates, the peck amounts.
const PARAMS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(2, Some(4)),
        meaning: "G76/G87 shift direction, with bit 5: (bit 5, bit 4) 00 = +X, 01 = -X, 10 = +Y, 11 = -Y",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0-M manual, canned cycles (G76: machine parameter 2 bits 4 and 5); bit layout as docs/guide.md",
    },
    ParamDef {
        key: ParamKey::Number(2, Some(5)),
        meaning: "G76/G87 shift direction, see 2.4",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0-M manual, canned cycles (G76)",
    },
    ParamDef {
        key: ParamKey::Number(518, None),
        meaning: "rapid traverse rate, X",
        unit: "mm/min",
        min: 30.0,
        max: 24000.0,
        default: 15000.0,
        source: "FANUC 0-M numbering (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(519, None),
        meaning: "rapid traverse rate, Y",
        unit: "mm/min",
        min: 30.0,
        max: 24000.0,
        default: 15000.0,
        source: "FANUC 0-M numbering (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(520, None),
        meaning: "rapid traverse rate, Z",
        unit: "mm/min",
        min: 30.0,
        max: 24000.0,
        default: 12000.0,
        source: "FANUC 0-M numbering (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(527, None),
        meaning: "upper limit of the cutting feed",
        unit: "mm/min",
        min: 6.0,
        max: 15000.0,
        default: 5000.0,
        source: "FANUC 0-M numbering (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(531, None),
        meaning: "G73 retract amount d",
        unit: "0.001 mm",
        min: 0.0,
        max: 32767.0,
        default: 500.0,
        source: "FANUC 0-M manual, canned cycles (G73: parameter 531); range 0-MC (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(532, None),
        meaning: "G83 clearance d above the previous depth",
        unit: "0.001 mm",
        min: 0.0,
        max: 32767.0,
        default: 500.0,
        source: "FANUC 0-M manual, canned cycles (G83: parameter 532); range 0-MC (inferred); default assumed",
    },
];

/// The profile's data, for the profiles built on it (the FANUC 0i-F).
pub(super) const BASE: Profile = Profile {
    name: "fanuc0m",
    title: "FANUC 0-M machining centre",
    kind: MachineKind::Mill,
    diameter_x: false,
    css_axis: Some(ParamKey::Number(3770, None)),
    integer_lengths: IntegerLengths::LeastIncrement,
    calculator_input: Some(ParamKey::Number(3401, Some(0))),
    alarm_style: AlarmStyle::Fanuc,
    incremental_addresses: false,
    power_on_per_rev: false,
    reference_in_canned_cycle_alarm: true,
    group00_with_01_alarm: false,
    axes: "XYZ",
    reference_point_mm: crate::motion::Vec3::new(0.0, 0.0, 0.0),
    addresses: super::Letters::new("GMSTFXYZIJKRPQLHDN"),
    peck_back_off: None,
    box_taper: b'R',
    g_codes: &[super::Codes { source: "FANUC 0-M manual, canned cycles (seed 003) and the FANUC 0i-MC G-code table", codes: common::G_CODES }, super::Codes { source: "FANUC 0-M manual, canned cycles (seed 003) and the FANUC 0i-MC G-code table", codes: common::UNITS }, super::Codes { source: "FANUC 0-M manual, canned cycles (seed 003) and the FANUC 0i-MC G-code table", codes: G_CODES }, super::Codes { source: "the FANUC 0i-MC G-code table (the 0-M's own table was not at hand)", codes: super::later::FANUC_0M }],
    m_codes: &[super::Codes { source: "FANUC 0-M manual (seed 003: M03-M05 in the tapping cycles); FANUC 0i-MC M codes", codes: common::M_CODES }, super::Codes { source: "FANUC 0-M manual (seed 003) and FANUC 0i-MC M codes", codes: M_CODES }],
    params: &[PARAMS_0I, PARAMS, TRANSFORMS, super::FANUC_INPUT, DRY_RUN, super::builder::FANUC, super::FANUC_MACRO, super::FANUC_G60, SETTINGS],
    time: TimeKeys {
        rapid: [ParamKey::Number(518, None), ParamKey::Number(519, None), ParamKey::Number(520, None)],
        dry_run: ParamKey::Setting("dry_run_mm_min"),
        feed_max: ParamKey::Number(527, None),
    },
    thread: ThreadRules { q_point: QPoint::Alarm, arc_q_unit_deg: 0.001, pull_out_speed: None, after_end_feed: None, pull_out_accel: None, repair_enable: None, g32_pull_out: false, g32_lead_e: false, g76: None, g34: super::G34_FANUC, g32_1: super::G32_1_GSK988T },
    drill: super::DrillRules {
        g73_retract_um: Some(ParamKey::Number(531, None)),
        g83_clearance_um: Some(ParamKey::Number(532, None)),
        shift_bits: Some((ParamKey::Number(2, Some(4)), ParamKey::Number(2, Some(5)))),
        lathe_peck_full_return: None,
    },
    calls: super::CallRules::FANUC,
    macros: super::MacroRules { group_numbers: super::FANUC_M_GROUPS, ..super::MacroRules::FANUC },
    frame: super::FrameRules {
        lathe_offset_keys: None,
        g10: super::G10Forms::MillOffsets,
        transform_keys: super::TransformKeys {
            rotation_incremental: Some(ParamKey::Number(5400, Some(0))),
            rotation_angle: Some(ParamKey::Number(5410, None)),
            magnification: Some(ParamKey::Number(5411, None)),
            scaling_option: Some(ParamKey::Setting("scaling_option")),
        },
        corner_override: Some(super::CornerOverrideKeys {
            arc_min_percent: ParamKey::Number(1710, None),
            angle: ParamKey::Number(1711, None),
            percent: ParamKey::Number(1712, None),
            after: ParamKey::Number(1713, None),
            before: ParamKey::Number(1714, None),
        }),
        ..super::FrameRules::FANUC
    },
    g_code_systems: None,
    summary: "FANUC 0-M machining centre. G90/G91, G17 at power on. Lengths without a decimal point \
are least input increments (X100 = 0.1 mm), F without a point is mm/min.",
};

pub static PROFILE: Profile = BASE;
