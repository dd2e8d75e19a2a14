//! YASKAWA YASNAC LX3 lathe: seed 004 (G92 with I, K, E). No LX3 parameter manual was found
//! (docs/reference/parameters.md section 5): the time-model rates are ncsight settings, named, not numbered.

use super::common::{self, g};
use super::lathe_a::{self, LATER_G76};
use super::{
    CycleRules, GDef, GFn, Group, HoldRule, IntegerLengths, JkWords, MachineKind, ParamDef, ParamKey, Profile, PullOutRule, QPoint, ThreadCmd, ThreadRules,
    TimeKeys, DRY_RUN, SETTINGS,
};
use crate::alarm::AlarmStyle;

/// G92 (YASNAC LX3 manual, G92): I taper, F or E lead, K with its sign shifts the pass's start
/// (flank infeed), T/S/M in the blocks before; no thread chamfer described; the thread-cutting
/// hold threads up at once, returning to A or (#6019 D7 = 1) stopping at B.
static G92: CycleRules = CycleRules {
    code: "G92",
    rigid: false,
    negative_f_left_hand: false,
    lead_i: false,
    lead_e: true,
    repair_p: false,
    starts_l: false,
    jk: JkWords::None,
    flank_k: true,
    ts_before: true,
    q_start: false,
    taper: b'I',
    taper_limit: false,
    pull_out: PullOutRule::None,
    hold: HoldRule::ThreadUp(ParamKey::Number(6019, Some(7))),
};

const EXTRA: &[GDef] = &[
    g(
        32,
        Group::Motion,
        GFn::Thread(ThreadCmd::Lead),
        "thread cutting: X(U) Z(W), F or E the lead, Q start angle (inferred: the FANUC 0-T's G32 with the E of the LX3's G92)",
    ),
    g(76, Group::NonModal, LATER_G76, "compound thread cutting cycle"),
    g(
        34,
        Group::Motion,
        GFn::Thread(ThreadCmd::VariableLead),
        "variable-lead thread cutting: F or E the lead at the start, K its change per revolution (inferred: the FANUC 0-T's G34)",
    ),
    g(92, Group::Motion, GFn::Thread(ThreadCmd::Cycle(&G92)), "threading cycle: I taper, K flank infeed, F or E lead (YASNAC LX3 manual, G92)"),
];

const PARAMS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(6019, Some(7)),
        meaning: "thread cutting hold: 0 = thread up and return to the start point A, 1 = stop where the threading-up ended (B)",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "YASNAC LX3 manual, G92, thread cutting hold",
    },
    ParamDef {
        key: ParamKey::Setting("rapid_mm_min"),
        meaning: "rapid traverse rate (each axis); the LX3 parameter number was not found",
        unit: "mm/min",
        min: 1.0,
        max: 60000.0,
        default: 8000.0,
        source: "ncsight setting; assumed",
    },
    ParamDef {
        key: ParamKey::Setting("feed_max_mm_min"),
        meaning: "upper limit of the cutting feed; the LX3 parameter number was not found",
        unit: "mm/min",
        min: 1.0,
        max: 60000.0,
        default: 8000.0,
        source: "ncsight setting; assumed",
    },
];

pub static PROFILE: Profile = Profile {
    name: "yasnac-lx3",
    title: "YASKAWA YASNAC LX3 lathe",
    kind: MachineKind::Lathe,
    diameter_x: true,
    css_axis: None,
    integer_lengths: IntegerLengths::LeastIncrement,
    calculator_input: None,
    alarm_style: AlarmStyle::Project,
    incremental_addresses: true,
    power_on_per_rev: true,
    reference_in_canned_cycle_alarm: false,
    group00_with_01_alarm: false,
    axes: "XZ",
    reference_point_mm: crate::motion::Vec3::new(100.0, 0.0, 200.0),
    addresses: super::Letters::new("GMSTFEXZUWRIKPQLN"),
    peck_back_off: None,
    box_taper: b'I',
    g_codes: &[
        super::Codes { source: "inferred: FANUC 0-T system A (no YASNAC LX3 G-code table was found)", codes: common::G_CODES },
        super::Codes { source: "inferred: FANUC 0-T system A (no YASNAC LX3 G-code table was found)", codes: common::UNITS },
        super::Codes { source: "inferred: FANUC 0-T system A (no YASNAC LX3 G-code table was found)", codes: lathe_a::G_CODES },
        super::Codes { source: "inferred: FANUC 0-T system A (no YASNAC LX3 G-code table was found)", codes: lathe_a::MULTIPLE_CYCLES },
        super::Codes { source: "YASNAC LX3 manual, G92 (seed 004)", codes: EXTRA },
        super::Codes { source: "inferred: FANUC 0-T system A (no YASNAC LX3 G-code table was found)", codes: super::later::YASNAC_LX3 },
    ],
    m_codes: &[
        super::Codes { source: "inferred: FANUC 0-T (no YASNAC LX3 M-code list was found)", codes: common::M_CODES },
        super::Codes { source: "inferred: FANUC 0-T (no YASNAC LX3 M-code list was found)", codes: lathe_a::M_CODES },
    ],
    params: &[PARAMS, DRY_RUN, super::YASNAC_LATHE_OFFSETS, SETTINGS],
    time: TimeKeys {
        rapid: [ParamKey::Setting("rapid_mm_min"), ParamKey::Setting("rapid_mm_min"), ParamKey::Setting("rapid_mm_min")],
        dry_run: ParamKey::Setting("dry_run_mm_min"),
        feed_max: ParamKey::Setting("feed_max_mm_min"),
    },
    thread: ThreadRules {
        q_point: QPoint::Ignored,
        arc_q_unit_deg: 0.001,
        pull_out_speed: None,
        after_end_feed: None,
        pull_out_accel: None,
        repair_enable: None,
        g32_pull_out: false,
        g32_lead_e: true,
        g76: None,
        g34: super::G34_FANUC,
        g32_1: super::G32_1_GSK988T,
    },
    drill: super::DrillRules::NONE,
    calls: super::CallRules {
        l_count: true,
        builder: super::BuilderCalls::NONE,
        g70_reads_programme: false,
        source: "inferred: as FANUC (no YASNAC LX3 text on M98 was at hand)",
        ..super::CallRules::FANUC
    },
    macros: super::MacroRules {
        if_without_then: false,
        table_variables: false,
        single_block_param: None,
        source: "inferred: as FANUC (YASNAC LX3 manual 2.8.23 gives the variables only)",
        ..super::MacroRules::FANUC
    },
    frame: super::FrameRules {
        last_reference: 2,
        lathe_offset_keys: Some((super::ParamKey::Setting("geometry_by_movement"), super::ParamKey::Setting("wear_with_next_move"))),
        source: "inferred: as FANUC 0-T, G30 to the 2nd reference point only (no YASNAC LX3 text at hand)",
        ..super::FrameRules::FANUC
    },
    g_code_systems: None,
    summary: "YASNAC LX3 turning centre. X is a diameter, U/W incremental. Lengths without a decimal \
point are least input increments (X100 = 0.1 mm); seed 004 writes every length with a point. \
Feed per revolution at power on (assumed).",
};
