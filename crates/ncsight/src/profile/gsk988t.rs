//! GSK lathe with a servo spindle (CS axis), A set of G codes: seed 001 (G32.1, G92.1, thread
//! repair) and seed 002 (G32.2/G32.3). Parameter numbers follow FANUC's numbering, as the 988T
//! manual does (docs/reference/parameters.md section 3).

use super::common::{self, g, gp};
use super::lathe_a;
use super::{
    Compound, CycleRules, GDef, GFn, Group, HoldRule, IntegerLengths, JkWords, MachineKind, ParamDef, ParamKey, Profile, PullOutRule, QPoint, ThreadCmd,
    ThreadRules, TimeKeys, FANUC_RATES, SETTINGS,
};
use crate::alarm::AlarmStyle;
use crate::motion::ArcDir;

/// G92.1 (GSK988T manual, G92.1): S, Q, L; J not below zero, K 0 or more; the pull-out of
/// parameters 5130/5131 for what J/K omit (notes 1-6); FEED HOLD discarded during the thread
/// (note 7).
const G92_1_RULES: CycleRules = CycleRules {
    code: "G92.1",
    rigid: true,
    negative_f_left_hand: false,
    lead_i: false,
    lead_e: false,
    repair_p: false,
    starts_l: true,
    jk: JkWords::NonNegative,
    flank_k: false,
    ts_before: false,
    q_start: true,
    taper: b'R',
    taper_limit: true,
    pull_out: PullOutRule::JkChamfer { amount: ParamKey::Number(5130, None), angle: ParamKey::Number(5131, None) },
    hold: HoldRule::Ignored,
};
static G92_1: CycleRules = G92_1_RULES;

/// G92 (GSK988TA/TB manual, G92 (printed p104), the same family as the 988T): R taper, F lead,
/// J (not below zero) and K pull-out, modal, without direction; L starts 1-99; Q start angle as
/// G32. No I (inch) word in its format. Inferred where its page was cut off: the pull-out for
/// what J/K omit is that of G92.1 on the same control (parameters 5130/5131, seed 001 G92.1
/// notes 1-3), and FEED HOLD waits for the thread's end, as in the G32 notes.
static G92: CycleRules = CycleRules { code: "G92", rigid: false, hold: HoldRule::AfterRun, ..G92_1_RULES };

const EXTRA: &[GDef] = &[
    g(
        34,
        Group::Motion,
        GFn::Thread(ThreadCmd::VariableLead),
        "variable-lead thread cutting: F, R per revolution, J/K (GSK988T manual 2.16.2, its example G34 W-78 F4 J5 K2 R0.2)",
    ),
    g(32, Group::Motion, GFn::Thread(ThreadCmd::Lead), "thread cutting: F lead or I threads per inch, J/K pull-out, Q start angle"),
    g(
        92,
        Group::Motion,
        GFn::Thread(ThreadCmd::Cycle(&G92)),
        "thread cutting cycle: R taper, F lead, J/K pull-out, L starts, Q start angle (GSK988TA/TB manual, G92)",
    ),
    gp(32, 1, "G32.1", Group::Motion, GFn::Thread(ThreadCmd::Rigid), "rigid thread cutting (GSK988T manual)"),
    gp(32, 2, "G32.2", Group::Motion, GFn::Thread(ThreadCmd::Arc(ArcDir::Cw)), "arc thread, clockwise (GSK988T manual, G32.2/G32.3)"),
    gp(32, 3, "G32.3", Group::Motion, GFn::Thread(ThreadCmd::Arc(ArcDir::Ccw)), "arc thread, counter-clockwise (GSK988T manual, G32.2/G32.3)"),
    gp(92, 1, "G92.1", Group::Motion, GFn::Thread(ThreadCmd::Cycle(&G92_1)), "rigid thread cutting cycle (GSK988T manual)"),
];

/// Codes whose GSK988T page was not at hand, run as the GSK980TDi's.
const AS_GSK980TDI: &[GDef] = &[
    g(
        76,
        Group::NonModal,
        GFn::CompoundThread(Compound::G76),
        "compound thread cutting cycle, two blocks (the GSK988T manual's definitions page agrees: sqrt(n) depths, flank infeed)",
    ),
    g(33, Group::Motion, GFn::Thread(ThreadCmd::Tap), "tapping: in, spindle reversed, out"),
];

const PARAMS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(1410, None),
        meaning: "dry-run rate; threads run at this rate in dry run whatever the override",
        unit: "mm/min",
        min: 0.0,
        max: 60000.0,
        default: 5000.0,
        source: "GSK988T manual, G32.1 note 13; default assumed (not found)",
    },
    ParamDef {
        key: ParamKey::Number(1466, None),
        meaning: "pull-out speed of the short axis when G32.1 has J without K (perpendicular pull-out after the end point)",
        unit: "mm/min",
        min: 0.0,
        max: 60000.0,
        default: 3000.0,
        source: "GSK988T manual, G32.1 note 5; default assumed (not found)",
    },
    ParamDef {
        key: ParamKey::Number(1628, None),
        meaning: "acceleration/deceleration time constant of the pull-out",
        unit: "ms",
        min: 0.0,
        max: 4000.0,
        default: 50.0,
        source: "GSK988T manual, G32.1 note 5; default assumed (not found)",
    },
    ParamDef {
        key: ParamKey::Number(5130, None),
        meaning: "G92 and G92.1 pull-out (chamfer) length along the long axis when J and K are omitted; G76 pull-out r (its first block's P rewrites it)",
        unit: "0.1 x lead",
        min: 0.0,
        max: 127.0,
        default: 10.0,
        source: "GSK988T manual, G92.1 note 1; range FANUC 0i-T (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5131, None),
        meaning: "G92, G92.1 and G76 pull-out angle; 0 = 45 degrees",
        unit: "deg",
        min: 0.0,
        max: 89.0,
        default: 0.0,
        source: "GSK988T manual, G92.1 note 1",
    },
    ParamDef {
        key: ParamKey::Number(8135, Some(7)),
        meaning: "RPTH: thread repair function enabled",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "GSK988T manual, thread repair 1.4",
    },
];

pub static PROFILE: Profile = Profile {
    name: "gsk988t",
    title: "GSK988T lathe with servo spindle (A set of G codes)",
    kind: MachineKind::Lathe,
    diameter_x: true,
    css_axis: None,
    integer_lengths: IntegerLengths::Millimetres,
    calculator_input: None,
    alarm_style: AlarmStyle::Project,
    incremental_addresses: true,
    power_on_per_rev: false,
    reference_in_canned_cycle_alarm: false,
    group00_with_01_alarm: true,
    // A lathe: X and Z. The arc threads in G17/G19 (seed 002) need a Y axis on the machines
    // that have one; the formats show Y once a programme moves it.
    axes: "XZ",
    reference_point_mm: crate::motion::Vec3::new(100.0, 0.0, 200.0),
    addresses: super::Letters::new("GMSTFXYZUVWRIJKPQLN"),
    peck_back_off: None,
    box_taper: b'R',
    g_codes: &[
        super::Codes { source: "inferred from the GSK980TDi help text (the GSK988T G-code table was not at hand)", codes: common::G_CODES },
        super::Codes { source: "inferred from the GSK980TDi help text (the GSK988T G-code table was not at hand)", codes: common::UNITS },
        super::Codes { source: "inferred from the GSK980TDi help text (the GSK988T G-code table was not at hand)", codes: lathe_a::G_CODES },
        super::Codes { source: "inferred from the GSK980TDi help text (the GSK988T G-code table was not at hand)", codes: lathe_a::MULTIPLE_CYCLES },
        super::Codes {
            source: "GSK988T manual: G32.1, G92.1, G32.2/G32.3, thread repair (seeds 001, 002); G92 of the GSK988TA/TB manual; G34 of the GSK988T manual",
            codes: EXTRA,
        },
        super::Codes { source: "inferred from the GSK980TDi help text (the GSK988T page was not at hand)", codes: AS_GSK980TDI },
        super::Codes { source: "GSK988T manual G-code table (G12.1/G13.1); the rest inferred from the GSK980TDi help text", codes: super::later::GSK988T },
        super::Codes {
            source: "inferred: the FANUC 0-T's drilling cycles (the GSK988T follows FANUC's numbering; its drilling page was not at hand)",
            codes: super::lathe_drill::CODES,
        },
    ],
    m_codes: &[
        super::Codes { source: "inferred from the GSK980TDi help text (M-code list)", codes: common::M_CODES },
        super::Codes { source: "inferred from the GSK980TDi help text (M-code list)", codes: lathe_a::M_CODES },
        super::Codes { source: "GSK988T manual, G32.1 (M14/M15); the rest inferred from the GSK980TDi help text", codes: lathe_a::GSK_M_CODES },
    ],
    params: &[FANUC_RATES, PARAMS, super::lathe_drill::PARAMS, super::FANUC_G76, super::GSK_LATHE_OFFSETS, SETTINGS],
    time: TimeKeys {
        rapid: [ParamKey::Number(1420, None), ParamKey::Number(1420, None), ParamKey::Number(1420, None)],
        dry_run: ParamKey::Number(1410, None),
        feed_max: ParamKey::Number(1422, None),
    },
    thread: ThreadRules {
        q_point: QPoint::Alarm,
        arc_q_unit_deg: 1.0,
        pull_out_speed: None,
        after_end_feed: Some(ParamKey::Number(1466, None)),
        pull_out_accel: Some(ParamKey::Number(1628, None)),
        repair_enable: Some(ParamKey::Number(8135, Some(7))),
        g32_pull_out: true,
        g32_lead_e: false,
        // The GSK988T numbers its parameters as FANUC does (1022, 1422 on its G01/G02 page;
        // 5130/5131 in G92.1): the FANUC 0i-T G76 numbers are assumed.
        g76: Some(super::FANUC_G76_KEYS),
        g34: super::G34_GSK,
        g32_1: super::G32_1_GSK988T,
    },
    drill: super::lathe_drill::RULES,
    calls: super::CallRules {
        max_count: 9999,
        l_count: false,
        max_depth: 4,
        builder: super::BuilderCalls::NONE,
        sequence_q: false,
        g70_reads_programme: false,
        eight_digit: None,
        source: "inferred from the GSK980TDi help text, M98 (count 1-9999, no L; four levels)",
    },
    macros: super::MacroRules {
        p_first: true,
        g65_cancels_g66: true,
        if_without_then: false,
        single_block_param: None,
        source: "inferred from the GSK980TDi help text, G65 (P right after G65); five bracket levels as FANUC (inferred)",
        table_variables: false,
        ..super::MacroRules::FANUC
    },
    frame: super::FrameRules {
        source: "inferred: as the GSK980TDi help text (G54-G59 note 6, G28 note 2, G30 note 3)",
        drawing: None,
        ..super::FrameRules::GSK
    },
    g_code_systems: None,
    summary: "GSK988T turning centre with a servo (CS) spindle: M14 position mode, M15 speed mode. \
X is a diameter, U/W incremental; lengths without a decimal point are millimetres.",
};
