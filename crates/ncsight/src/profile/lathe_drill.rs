//! The FANUC 0-T lathe's drilling cycles (G80, G83-G89 from the R level; docs/commands/g83_g87_lathe.md,
//! inferred from the FANUC 0i-T family), as data for the profiles that have them: the FANUC 0-T,
//! and the GSK988T (its manual follows FANUC's numbering; its drilling page was not at hand).

use super::common::g;
use super::{DrillRules, GDef, GFn, Group, ParamDef, ParamKey};
use crate::codes::DrillKind;

pub(super) const CODES: &[GDef] = &[
    g(80, Group::CannedCycle, GFn::CycleCancel, "cancel a drilling cycle (group 10 on the FANUC)"),
    g(83, Group::CannedCycle, GFn::Drill(DrillKind::FaceFromR), "face drilling cycle; with Q, peck drilling (5101#2)"),
    g(84, Group::CannedCycle, GFn::Drill(DrillKind::FaceTapR), "face tapping cycle: the spindle reversed at the bottom"),
    g(85, Group::CannedCycle, GFn::Drill(DrillKind::FaceBoreR), "face boring cycle: feed out to R"),
    g(87, Group::CannedCycle, GFn::Drill(DrillKind::SideFromR), "side drilling cycle; with Q, peck drilling (5101#2)"),
    g(88, Group::CannedCycle, GFn::Drill(DrillKind::SideTapR), "side tapping cycle: the spindle reversed at the bottom"),
    g(89, Group::CannedCycle, GFn::Drill(DrillKind::SideBoreR), "side boring cycle: feed out to R"),
];

pub(super) const PARAMS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(5101, Some(2)),
        meaning: "RTR: G83/G87 with Q: 0 = high-speed peck (back off 5114 after each peck), 1 = peck drilling (back to R, down again to 5115 short of the last depth)",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i-T numbering (inferred: the bit's meaning from FANUC lathe documentation not read in a page)",
    },
    ParamDef {
        key: ParamKey::Number(5114, None),
        meaning: "G83/G87 high-speed peck: back-off d after each peck",
        unit: "0.001 mm",
        min: 0.0,
        max: 32767.0,
        default: 500.0,
        source: "FANUC 0i numbering (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5115, None),
        meaning: "G83/G87 peck drilling: clearance d above the last depth when the drill comes back down",
        unit: "0.001 mm",
        min: 0.0,
        max: 32767.0,
        default: 500.0,
        source: "FANUC 0i numbering (inferred, as the 0i-M G83's d); default assumed",
    },
];

pub(super) const RULES: DrillRules = DrillRules {
    g73_retract_um: Some(ParamKey::Number(5114, None)),
    g83_clearance_um: Some(ParamKey::Number(5115, None)),
    shift_bits: None,
    lathe_peck_full_return: Some(ParamKey::Number(5101, Some(2))),
};
