//! FANUC 0-T lathe, G-code system A (issue 11): G32, G92 with a start angle Q, the two-block G76,
//! thread chamfering by parameters 5130/5131 (FANUC 0i-T numbering, docs/reference/parameters.md section 3:
//! inferred). It is here so that the FANUC lathe programmes of the corpus (Doosan, ICNC) run on
//! the profile they were written for.

use super::common::{self, g};
use super::lathe_a;
use super::{
    Compound, CycleRules, GDef, GFn, Group, HoldRule, IntegerLengths, JkWords, MachineKind, ParamDef, ParamKey, Profile, PullOutRule, QPoint, ThreadCmd,
    ThreadRules, TimeKeys, DRY_RUN, FANUC_RATES, SETTINGS,
};
use crate::alarm::AlarmStyle;

/// G92 (FANUC 0i-T, inferred): R taper, F lead, Q start angle; the thread chamfer of parameters
/// 5130/5131 (no J/K words); without the thread-cutting retract option FEED HOLD waits for the
/// thread's end (docs/commands/operator.md).
pub(super) const G92_RULES: CycleRules = CycleRules {
    code: "G92",
    rigid: false,
    negative_f_left_hand: false,
    lead_i: false,
    lead_e: false,
    repair_p: false,
    starts_l: false,
    jk: JkWords::None,
    flank_k: false,
    ts_before: false,
    q_start: true,
    taper: b'R',
    taper_limit: true,
    pull_out: PullOutRule::Chamfer { amount: ParamKey::Number(5130, None), angle: ParamKey::Number(5131, None) },
    hold: HoldRule::AfterRun,
};
static G92: CycleRules = G92_RULES;

pub(super) const EXTRA: &[GDef] = &[
    g(32, Group::Motion, GFn::Thread(ThreadCmd::Lead), "thread cutting: F lead, Q start angle"),
    g(92, Group::Motion, GFn::Thread(ThreadCmd::Cycle(&G92)), "thread cutting cycle: R taper, F lead, Q start angle"),
    g(76, Group::NonModal, GFn::CompoundThread(Compound::G76), "compound thread cutting cycle, two blocks"),
    g(
        34,
        Group::Motion,
        GFn::Thread(ThreadCmd::VariableLead),
        "variable-lead thread cutting: F the lead at the start, K its change per revolution, Q start angle",
    ),
];

pub(super) const PARAMS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(5139, None),
        meaning: "G74/G75 return amount e at power on; their first block R rewrites it",
        unit: "mm",
        min: 0.0,
        max: 99.0,
        default: 0.0,
        source: "FANUC 0i numbering (inferred; not in docs/sources.md); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5130, None),
        meaning: "thread chamfering (pull-out) amount of G92 and G76",
        unit: "0.1 x lead",
        min: 0.0,
        max: 127.0,
        default: 10.0,
        source: "docs/sources.md section 3 (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5131, None),
        meaning: "thread chamfering angle; 0 = 45 degrees",
        unit: "deg",
        min: 0.0,
        max: 89.0,
        default: 0.0,
        source: "docs/sources.md section 3 (inferred)",
    },
];

/// The profile's data, for the profiles built on it (the FANUC 0i-F).
pub(super) const BASE: Profile = Profile {
    name: "fanuc0t",
    title: "FANUC 0-T lathe (G-code system A)",
    kind: MachineKind::Lathe,
    diameter_x: true,
    css_axis: None,
    integer_lengths: IntegerLengths::LeastIncrement,
    calculator_input: Some(ParamKey::Number(3401, Some(0))),
    alarm_style: AlarmStyle::Fanuc,
    incremental_addresses: true,
    power_on_per_rev: true,
    reference_in_canned_cycle_alarm: true,
    group00_with_01_alarm: false,
    axes: "XZ",
    reference_point_mm: crate::motion::Vec3::new(100.0, 0.0, 200.0),
    addresses: super::Letters::new("GMSTFXZUWRIKPQLN"),
    peck_back_off: Some(ParamKey::Number(5139, None)),
    box_taper: b'R',
    g_codes: &[
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: common::G_CODES },
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: common::UNITS },
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: lathe_a::G_CODES },
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: lathe_a::MULTIPLE_CYCLES },
        super::Codes { source: "FANUC 0i-T documentation (inferred for the 0-T; docs/profiles.md)", codes: EXTRA },
        super::Codes { source: "FANUC 0i-T documentation (inferred for the 0-T; docs/commands/g83_g87_lathe.md)", codes: super::lathe_drill::CODES },
        super::Codes { source: "the FANUC 0-TC G-code table, system A (the 0i-TC where it lacks)", codes: super::later::FANUC_0T },
    ],
    m_codes: &[
        super::Codes { source: "FANUC 0i-TC M codes (inferred for the 0-T)", codes: common::M_CODES },
        super::Codes { source: "FANUC 0i-TC M codes (inferred for the 0-T)", codes: lathe_a::M_CODES },
    ],
    params: &[
        FANUC_RATES,
        PARAMS,
        super::lathe_drill::PARAMS,
        super::FANUC_G76,
        super::FANUC_INPUT,
        DRY_RUN,
        super::builder::FANUC,
        super::FANUC_MACRO,
        super::FANUC_LATHE_OFFSETS,
        SETTINGS,
    ],
    time: TimeKeys {
        rapid: [ParamKey::Number(1420, None), ParamKey::Number(1420, None), ParamKey::Number(1420, None)],
        dry_run: ParamKey::Setting("dry_run_mm_min"),
        feed_max: ParamKey::Number(1422, None),
    },
    thread: ThreadRules {
        q_point: QPoint::Alarm,
        arc_q_unit_deg: 0.001,
        pull_out_speed: None,
        after_end_feed: None,
        pull_out_accel: None,
        repair_enable: None,
        g32_pull_out: false,
        g32_lead_e: false,
        g76: Some(super::FANUC_G76_KEYS),
        g34: super::G34_FANUC,
        g32_1: super::G32_1_GSK988T,
    },
    drill: super::lathe_drill::RULES,
    calls: super::CallRules::FANUC,
    macros: super::MacroRules::FANUC,
    frame: super::FrameRules { drawing: Some(super::DrawingRules::FANUC_T), ..super::FrameRules::FANUC },
    g_code_systems: None,
    summary: "FANUC 0-T turning centre, G-code system A. X is a diameter, U/W incremental; lengths without \
a decimal point are least input increments (X100 = 0.1 mm, X1 = 0.0001 inch under G20). Feed per \
revolution (G99) at power on.",
};

pub static PROFILE: Profile = BASE;
