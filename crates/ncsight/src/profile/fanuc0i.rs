//! FANUC 0i-F (issue 35): the 0i-TF turning centre and the 0i-MF machining centre, the
//! controllers most shop programmes today are written for. Each is the FANUC 0-T (0-M) profile's
//! data with the 0i-F's own parameters where they change an everyday programme (docs/profiles.md
//! names each row's source):
//! - 3403#5 CIR: G02/G03 with neither R nor I/J/K is a straight move (0) or alarm PS0022 (1);
//! - 3405#4 CCR (lathe): the drawing's words C, R, A without the comma, C the right-angle chamfer;
//! - the 0i's parameter numbers on the machining centre (1420 rapid, 1422 feed limit, 5114/5115
//!   peck amounts, 5101#4/#5 the G76/G87 shift).

use super::{fanuc0m, fanuc0t, CallRules, DrawingRules, FrameRules, ParamDef, ParamKey, Profile, TimeKeys};

/// 3403#5 CIR, both machines.
const CIR: ParamKey = ParamKey::Number(3403, Some(5));
/// 3405#4 CCR, the lathe.
const CCR: ParamKey = ParamKey::Number(3405, Some(4));

const ARC: &[ParamDef] = &[ParamDef {
    key: CIR,
    meaning: "CIR: G02/G03 with neither R nor I, J, K: 0 = a straight move to the end point, 1 = alarm PS0022",
    unit: "bit",
    min: 0.0,
    max: 1.0,
    default: 0.0,
    source: "FANUC 0i-F parameter manual, 3403#5 CIR (as recalled; docs/profiles.md)",
}];

const DRAWING: &[ParamDef] = &[ParamDef {
    key: CCR,
    meaning: "CCR: 0 = chamfer and corner R by I, K, R and the drawing's words ,C ,R ,A; 1 = C, R, A without the comma (C the chamfer, A and C no axes)",
    unit: "bit",
    min: 0.0,
    max: 1.0,
    default: 0.0,
    source: "FANUC 0i-TF parameter manual, 3405#4 CCR (as recalled; docs/profiles.md)",
}];

/// The machining centre's rates and cycle amounts by their 0i numbers.
const MILL: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(1420, None),
        meaning: "rapid traverse rate (each axis)",
        unit: "mm/min",
        min: 1.0,
        max: 100000.0,
        default: 15000.0,
        source: "FANUC 0i-F parameter manual numbering (No. 1420); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(1422, None),
        meaning: "upper limit of the cutting feed",
        unit: "mm/min",
        min: 6.0,
        max: 100000.0,
        default: 5000.0,
        source: "FANUC 0i parameter manual numbering (No. 1422, as recalled); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5114, None),
        meaning: "G73 retract amount d",
        unit: "0.001 mm",
        min: 0.0,
        max: 32767.0,
        default: 500.0,
        source: "FANUC 0i parameter manual numbering (No. 5114, as recalled); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5115, None),
        meaning: "G83 clearance d above the previous depth",
        unit: "0.001 mm",
        min: 0.0,
        max: 32767.0,
        default: 500.0,
        source: "FANUC 0i parameter manual numbering (No. 5115, as recalled); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5101, Some(4)),
        meaning: "RD1: G76/G87 shift direction, with bit 5 (RD2): (bit 5, bit 4) 00 = +X, 01 = -X, 10 = +Y, 11 = -Y",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i parameter manual numbering (5101#4 RD1, #5 RD2, as recalled)",
    },
    ParamDef {
        key: ParamKey::Number(5101, Some(5)),
        meaning: "RD2: G76/G87 shift direction, see 5101.4",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i parameter manual numbering (5101#5 RD2, as recalled)",
    },
];

/// The 0i-TF's codes beyond the 0-T's that change nothing here.
const TF_CODES: &[super::GDef] = &[
    super::common::g(
        43,
        super::Group::LengthComp,
        super::GFn::NotYet("tool length compensation on a lathe (the mill-turn option)"),
        "tool length compensation + (the mill-turn option): not simulated yet",
    ),
    super::common::g(
        44,
        super::Group::LengthComp,
        super::GFn::NotYet("tool length compensation on a lathe (the mill-turn option)"),
        "tool length compensation - (the mill-turn option): not simulated yet",
    ),
    super::common::g(
        49,
        super::Group::LengthComp,
        super::GFn::LengthComp(0),
        "tool length compensation cancel (G43/G44 are not simulated: nothing is in force to cancel)",
    ),
];

/// Eight-digit programme numbers, an option of the 0i-F (its parameter not found: a setting).
const EIGHT_DIGIT: ParamKey = ParamKey::Setting("eight_digit_programs");

const CALLS: &[ParamDef] = &[ParamDef {
    key: EIGHT_DIGIT,
    meaning:
        "the eight-digit programme number option: 1 = M98 P and G65 P are the programme number alone (O1-O99999999), L the count; 0 = M98 P<count><four digits>",
    unit: "bit",
    min: 0.0,
    max: 1.0,
    default: 0.0,
    source: "ncsight setting (an option of the FANUC 0i-F; its parameter number not at hand); off, assumed",
}];

const CALL_RULES: CallRules = CallRules {
    // Ten levels of subprogramme calls on the 0i-D/F (as recalled; four on the 0i-TB/MB).
    max_depth: 10,
    sequence_q: true,
    eight_digit: Some(EIGHT_DIGIT),
    source: "FANUC 0i-F: M98 Q (a sequence number of the same programme) as the shop programmes use it, eight-digit numbers an option (a setting), ten nesting levels (as recalled; G65 calls counted apart, ten too: inferred); M98 P as the FANUC 0i-TB/MB operator's manual 12.3",
    ..CallRules::FANUC
};

/// 3401#6 GSB and #7 GSC: the lathe's G-code system B or C (C when both).
const GSB: ParamKey = ParamKey::Number(3401, Some(6));
const GSC: ParamKey = ParamKey::Number(3401, Some(7));

const SYSTEMS: &[ParamDef] = &[
    ParamDef {
        key: GSB,
        meaning: "GSB: 1 = G-code system B (G90/G91 absolute/incremental, G92 coordinate set, G94/G95 feed modes, G98/G99 return levels, G77/G78/G79 the single cycles)",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i-TF parameter 3401#6 GSB (as recalled); the B and C tables as the FANUC lathe G-code lists give them",
    },
    ParamDef {
        key: GSC,
        meaning: "GSC: 1 = G-code system C (as B, with G70/G71 inch/metric, G72-G78 the multiple cycles, G20/G21/G24 the single cycles)",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i-TF parameter 3401#7 GSC (as recalled)",
    },
];

use super::common::g;
use super::{GDef, GFn, Group, ThreadCmd};
use crate::codes::{BoxKind, PeckKind, RoughKind};

static G78: super::CycleRules = super::CycleRules { code: "G78", ..fanuc0t::G92_RULES };
static G21_THREAD: super::CycleRules = super::CycleRules { code: "G21", ..fanuc0t::G92_RULES };

/// What systems B and C share: G90/G91, the feed modes G94/G95, the return levels G98/G99,
/// G92 for G50 (G-code system A's codes of the same functions are not in them).
const B_AND_C: &[GDef] = &[
    g(90, Group::Distance, GFn::Absolute, "absolute command"),
    g(91, Group::Distance, GFn::Incremental, "incremental command"),
    g(92, Group::NonModal, GFn::LatheCoordinateSet, "set the coordinates of the current position; S: spindle speed clamp"),
    g(94, Group::FeedMode, GFn::FeedPerMinute, "feed per minute: F in mm/min"),
    g(95, Group::FeedMode, GFn::FeedPerRevolution, "feed per revolution: F in mm/rev"),
    g(96, Group::SpindleSpeedMode, GFn::ConstantSurfaceSpeed, "constant surface speed: S in m/min"),
    g(97, Group::SpindleSpeedMode, GFn::ConstantRpm, "constant spindle speed: S in rpm"),
    g(98, Group::ReturnLevel, GFn::ReturnInitial, "drilling cycles return to the initial level"),
    g(99, Group::ReturnLevel, GFn::ReturnR, "drilling cycles return to the R level"),
    g(32, Group::Motion, GFn::Thread(ThreadCmd::Lead), "thread cutting: F lead, Q start angle"),
    g(
        34,
        Group::Motion,
        GFn::Thread(ThreadCmd::VariableLead),
        "variable-lead thread cutting: F the lead at the start, K its change per revolution, Q start angle",
    ),
];

/// System B: A's multiple cycles' numbers (`lathe_a::MULTIPLE_CYCLES` and G76), G77/G78/G79
/// the single cycles.
const SYSTEM_B: &[GDef] = &[
    g(76, Group::NonModal, GFn::CompoundThread(super::Compound::G76), "compound thread cutting cycle, two blocks"),
    g(77, Group::Motion, GFn::BoxCycle(BoxKind::Turning), "outer/inner diameter cutting cycle (system A's G90)"),
    g(78, Group::Motion, GFn::Thread(ThreadCmd::Cycle(&G78)), "thread cutting cycle (system A's G92): R taper, F lead, Q start angle"),
    g(79, Group::Motion, GFn::BoxCycle(BoxKind::Facing), "end face cutting cycle (system A's G94)"),
];

/// System C: G70/G71 inch and metric, G72-G78 the multiple cycles, G20/G21/G24 the single ones.
const SYSTEM_C: &[GDef] = &[
    g(70, Group::Units, GFn::Inch, "inch input (system A's G20)"),
    g(71, Group::Units, GFn::Metric, "metric input (system A's G21)"),
    g(72, Group::NonModal, GFn::Finish, "finishing cycle (system A's G70)"),
    g(73, Group::NonModal, GFn::Rough(RoughKind::Turning), "stock removal in turning (system A's G71)"),
    g(74, Group::NonModal, GFn::Rough(RoughKind::Facing), "stock removal in facing (system A's G72)"),
    g(75, Group::NonModal, GFn::Rough(RoughKind::Pattern), "pattern repeating (system A's G73)"),
    g(76, Group::NonModal, GFn::PeckCycle(PeckKind::Face), "end face peck drilling (system A's G74)"),
    g(77, Group::NonModal, GFn::PeckCycle(PeckKind::Groove), "outer/inner diameter grooving (system A's G75)"),
    g(78, Group::NonModal, GFn::CompoundThread(super::Compound::G76), "compound thread cutting cycle, two blocks (system A's G76)"),
    g(20, Group::Motion, GFn::BoxCycle(BoxKind::Turning), "outer/inner diameter cutting cycle (system A's G90)"),
    g(21, Group::Motion, GFn::Thread(ThreadCmd::Cycle(&G21_THREAD)), "thread cutting cycle (system A's G92): R taper, F lead, Q start angle"),
    g(24, Group::Motion, GFn::BoxCycle(BoxKind::Facing), "end face cutting cycle (system A's G94)"),
];

const SOURCE_BC: &str = "the FANUC lathe G-code list, systems B and C (as recalled; the 0i-TF's own table was not at hand)";

static SYSTEMS_OF_TF: super::GCodeSystems = super::GCodeSystems { b: GSB, c: GSC, profile_b: &TF_B, profile_c: &TF_C };

/// The 0i-TF in G-code system B.
pub static TF_B: Profile = Profile {
    title: "FANUC 0i-TF lathe (G-code system B)",
    g_codes: &[
        super::Codes { source: SOURCE_BC, codes: super::common::G_CODES },
        super::Codes { source: SOURCE_BC, codes: super::common::UNITS },
        super::Codes { source: SOURCE_BC, codes: B_AND_C },
        super::Codes { source: SOURCE_BC, codes: super::lathe_a::MULTIPLE_CYCLES },
        super::Codes { source: SOURCE_BC, codes: SYSTEM_B },
        super::Codes { source: "FANUC 0i-T documentation (docs/commands/g83_g87_lathe.md)", codes: super::lathe_drill::CODES },
        super::Codes { source: SOURCE_BC, codes: super::later::FANUC_0T },
        super::Codes { source: "FANUC 0i-TF G-code list as recalled (G49 with the tool length compensation option; inferred)", codes: TF_CODES },
    ],
    g_code_systems: None,
    ..TF
};

/// The 0i-TF in G-code system C.
pub static TF_C: Profile = Profile {
    title: "FANUC 0i-TF lathe (G-code system C)",
    g_codes: &[
        super::Codes { source: SOURCE_BC, codes: super::common::G_CODES },
        super::Codes { source: SOURCE_BC, codes: B_AND_C },
        super::Codes { source: SOURCE_BC, codes: SYSTEM_C },
        super::Codes { source: "FANUC 0i-T documentation (docs/commands/g83_g87_lathe.md)", codes: super::lathe_drill::CODES },
        super::Codes { source: SOURCE_BC, codes: super::later::FANUC_0T },
        super::Codes { source: "FANUC 0i-TF G-code list as recalled (G49 with the tool length compensation option; inferred)", codes: TF_CODES },
    ],
    ..TF_B
};

const TF_PARAMS: &[&[ParamDef]] = &[
    super::FANUC_RATES,
    fanuc0t::PARAMS,
    super::lathe_drill::PARAMS,
    super::FANUC_G76,
    super::FANUC_INPUT,
    super::DRY_RUN,
    super::builder::FANUC,
    super::FANUC_MACRO,
    super::FANUC_LATHE_OFFSETS,
    ARC,
    DRAWING,
    CALLS,
    SYSTEMS,
    super::SETTINGS,
];

pub static TF: Profile = Profile {
    name: "fanuc0i-tf",
    title: "FANUC 0i-TF lathe (G-code system A)",
    params: TF_PARAMS,
    g_codes: &[
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: super::common::G_CODES },
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: super::common::UNITS },
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: super::lathe_a::G_CODES },
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: super::lathe_a::MULTIPLE_CYCLES },
        super::Codes { source: "FANUC 0i-T documentation (docs/profiles.md)", codes: fanuc0t::EXTRA },
        super::Codes { source: "FANUC 0i-T documentation (docs/commands/g83_g87_lathe.md)", codes: super::lathe_drill::CODES },
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: super::later::FANUC_0T },
        super::Codes { source: "FANUC 0i-TF G-code list as recalled (G49 with the tool length compensation option; inferred)", codes: TF_CODES },
    ],
    frame: FrameRules {
        drawing: Some(DrawingRules { plain_letters: Some(CCR), ..DrawingRules::FANUC_T }),
        arc_without_centre: Some(CIR),
        // The 0i-TF's machines are turning centres with a C axis and often a Y (assumed).
        assumed_axes: "CY",
        // A main and a sub spindle, selected by P11 and P12 (parameter 3781's usual values; assumed).
        assumed_spindle_p: &[11, 12],
        ..fanuc0t::BASE.frame
    },
    calls: CALL_RULES,
    g_code_systems: Some(&SYSTEMS_OF_TF),
    summary: "FANUC 0i-TF turning centre, G-code system A: the FANUC 0-T's words, with the 0i-F's \
parameters 3403#5 (G02/G03 without R or I/K: a straight move) and 3405#4 (C, R, A without the \
comma). X is a diameter, U/W incremental; Y (V), C (H) and a sub-spindle's B come from the \
setup's [machine] axes. Lengths without a decimal point are least input increments (X100 = 0.1 mm).",
    ..fanuc0t::BASE
};

const MF_PARAMS: &[&[ParamDef]] = &[
    fanuc0m::PARAMS_0I,
    MILL,
    fanuc0m::TRANSFORMS,
    super::FANUC_INPUT,
    super::DRY_RUN,
    super::builder::FANUC,
    super::FANUC_MACRO,
    super::FANUC_G60,
    ARC,
    CALLS,
    super::SETTINGS,
];

/// The 0i-MF's codes beyond the 0-M's.
const MF_CODES: &[GDef] = &[super::common::gp(
    54,
    1,
    "G54.1",
    Group::WorkOffset,
    GFn::AdditionalWorkOffset,
    "additional work coordinate system P1-P48 (the setup's [work] \"G54.1\" list)",
)];

/// G02.2/G03.2 involute interpolation, an option of the 0i-MF (taken as fitted).
const MF_INVOLUTE: &[GDef] = &[
    super::common::gp(
        2,
        2,
        "G02.2",
        Group::Motion,
        GFn::Curve(super::Curve::Involute(crate::motion::ArcDir::Cw)),
        "involute interpolation clockwise: I/J/K the base circle's centre from the start, R its radius",
    ),
    super::common::gp(
        3,
        2,
        "G03.2",
        Group::Motion,
        GFn::Curve(super::Curve::Involute(crate::motion::ArcDir::Ccw)),
        "involute interpolation counter-clockwise: I/J/K the base circle's centre from the start, R its radius",
    ),
];

pub static MF: Profile = Profile {
    name: "fanuc0i-mf",
    title: "FANUC 0i-MF machining centre",
    params: MF_PARAMS,
    g_codes: &[
        super::Codes { source: "FANUC 0-M manual, canned cycles (seed 003) and the FANUC 0i-MC G-code table", codes: super::common::G_CODES },
        super::Codes { source: "FANUC 0-M manual, canned cycles (seed 003) and the FANUC 0i-MC G-code table", codes: super::common::UNITS },
        super::Codes { source: "FANUC 0-M manual, canned cycles (seed 003) and the FANUC 0i-MC G-code table", codes: fanuc0m::G_CODES },
        super::Codes { source: "the FANUC 0i-MC G-code table", codes: super::later::FANUC_0M },
        super::Codes { source: "FANUC 0i-MF: G54.1 P1-P48 (standard; P1-P300 an option, not simulated), as recalled", codes: MF_CODES },
        super::Codes { source: "FANUC Series 16/18-MC and 30i-MA operator's manuals, involute interpolation (an option)", codes: MF_INVOLUTE },
    ],
    time: TimeKeys {
        rapid: [ParamKey::Number(1420, None), ParamKey::Number(1420, None), ParamKey::Number(1420, None)],
        dry_run: ParamKey::Setting("dry_run_mm_min"),
        feed_max: ParamKey::Number(1422, None),
    },
    drill: super::DrillRules {
        g73_retract_um: Some(ParamKey::Number(5114, None)),
        g83_clearance_um: Some(ParamKey::Number(5115, None)),
        shift_bits: Some((ParamKey::Number(5101, Some(4)), ParamKey::Number(5101, Some(5)))),
        lathe_peck_full_return: None,
    },
    frame: FrameRules { arc_without_centre: Some(CIR), ..fanuc0m::BASE.frame },
    calls: CALL_RULES,
    summary: "FANUC 0i-MF machining centre: the FANUC 0-M's words and cycles with the 0i-F's parameter \
numbers (1420 rapid, 1422 feed limit, 5114/5115 peck amounts) and 3403#5 (G02/G03 without R or \
I/J/K: a straight move). G90/G91, G17 at power on; lengths without a decimal point are least \
input increments (X100 = 0.1 mm).",
    ..fanuc0m::BASE
};

#[cfg(test)]
mod tests {
    use super::*;

    /// The variants hold together as the listed profiles do, with the same parameters.
    #[test]
    fn the_g_code_systems_are_valid_profiles() {
        for p in [&TF_B, &TF_C] {
            p.validate().unwrap();
            assert_eq!(p.all_params().count(), TF.all_params().count());
        }
        let mut params = crate::profile::Params::defaults(&TF);
        params.set(GSB, 1.0).unwrap();
        assert_eq!(params.profile().title, TF_B.title);
        params.set(GSC, 1.0).unwrap();
        assert_eq!(params.profile().title, TF_C.title);
        params.set(GSB, 0.0).unwrap();
        params.set(GSC, 0.0).unwrap();
        assert_eq!(params.profile().title, TF.title);
    }
}
