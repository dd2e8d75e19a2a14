//! GSK980TDi lathe, G-code system A. Seed 000 (G92) and the on-line help text.

use super::common::{self, g, gp};
use super::lathe_a;
use super::{
    Compound, Curve, CycleRules, G76Keys, GDef, GFn, Group, HoldRule, IntegerLengths, JkWords, MachineKind, ParamDef, ParamKey, Profile, PullOutRule, QPoint,
    ThreadCmd, ThreadRules, TimeKeys, DRY_RUN, SETTINGS,
};
use crate::alarm::AlarmStyle;
use crate::codes::DrillKind;
use crate::motion::ArcDir;

/// M29 S_: rigid tapping mode (help text G84/88).
const TAPPING_M: &[super::MDef] = &[super::MDef { code: 29, function: super::MFn::RigidTapping, meaning: "rigid tapping mode: with S, before G84/G88" }];

/// The help text's second spindle and spindle positioning codes: machine functions without a
/// motion of the tool (the second spindle and the positioning time are not modelled).
const SECOND_SPINDLE_M: &[super::MDef] = &[
    common::m(24, super::MFn::Auxiliary, "second spindle to position control"),
    common::m(25, super::MFn::Auxiliary, "second spindle to speed control"),
    common::m(50, super::MFn::Auxiliary, "spindle positioning cancelled"),
    common::m(51, super::MFn::Auxiliary, "spindle positioned to point 1"),
    common::m(52, super::MFn::Auxiliary, "spindle positioned to point 2"),
    common::m(53, super::MFn::Auxiliary, "spindle positioned to point 3"),
    common::m(54, super::MFn::Auxiliary, "spindle positioned to point 4"),
    common::m(55, super::MFn::Auxiliary, "spindle positioned to point 5"),
    common::m(56, super::MFn::Auxiliary, "spindle positioned to point 6"),
    common::m(57, super::MFn::Auxiliary, "spindle positioned to point 7"),
    common::m(58, super::MFn::Auxiliary, "spindle positioned to point 8"),
    common::m(63, super::MFn::Auxiliary, "second spindle forward"),
    common::m(64, super::MFn::Auxiliary, "second spindle reverse"),
    common::m(65, super::MFn::Auxiliary, "second spindle stop"),
];

/// G92 (GSK980TDi manual, G92): R taper, F lead or I threads per inch, J/K pull-out with No.19
/// for what is omitted (note 10: negative J, K count as positive), L starts, P1 repair; FEED HOLD
/// by NO.0018 bit 6 (note 1).
static G92: CycleRules = CycleRules {
    code: "G92",
    rigid: false,
    negative_f_left_hand: false,
    lead_i: true,
    lead_e: false,
    repair_p: true,
    starts_l: true,
    jk: JkWords::SignIgnored,
    flank_k: false,
    ts_before: false,
    q_start: false,
    taper: b'R',
    taper_limit: true,
    pull_out: PullOutRule::JkTenths(ParamKey::Number(19, None)),
    hold: HoldRule::PullOutOrFinish(ParamKey::Number(18, Some(6))),
};

/// G92.1 (help text): R, F (negative: left hand) or I, L, P, S; no J, K, Q; the feed axes and
/// the spindle stop together at the end point (no pull-out); FEED HOLD waits for the thread's
/// end (note 3).
static G92_1: CycleRules = CycleRules {
    code: "G92.1",
    rigid: true,
    negative_f_left_hand: true,
    lead_i: true,
    lead_e: false,
    repair_p: true,
    starts_l: true,
    jk: JkWords::None,
    flank_k: false,
    ts_before: false,
    q_start: false,
    taper: b'R',
    taper_limit: true,
    pull_out: PullOutRule::None,
    hold: HoldRule::AfterRun,
};

const EXTRA: &[GDef] = &[
    g(32, Group::Motion, GFn::Thread(ThreadCmd::Lead), "thread cutting: F lead or I threads per inch, J/K pull-out, Q start angle"),
    g(92, Group::Motion, GFn::Thread(ThreadCmd::Cycle(&G92)), "thread cutting cycle (GSK980TDi manual, G92)"),
    gp(
        32,
        1,
        "G32.1",
        Group::Motion,
        GFn::Thread(ThreadCmd::Rigid),
        "rigid thread cutting: C the start angle, F(I) the lead (negative: left hand), J/K pull-out, S the speed; M14 first",
    ),
    gp(32, 2, "G32.2", Group::Motion, GFn::Thread(ThreadCmd::Arc(ArcDir::Cw)), "arc thread, clockwise"),
    gp(32, 3, "G32.3", Group::Motion, GFn::Thread(ThreadCmd::Arc(ArcDir::Ccw)), "arc thread, counter-clockwise"),
    g(76, Group::NonModal, GFn::CompoundThread(Compound::G76), "compound thread cutting cycle, two blocks"),
    g(33, Group::Motion, GFn::Thread(ThreadCmd::Tap), "tapping: in, spindle reversed, out (help text)"),
    g(34, Group::Motion, GFn::Thread(ThreadCmd::VariableLead), "variable-lead thread cutting"),
    gp(92, 1, "G92.1", Group::Motion, GFn::Thread(ThreadCmd::Cycle(&G92_1)), "rigid thread cutting cycle (help text: R F L P S)"),
    g(80, Group::Motion, GFn::CycleCancel, "cancel a drilling cycle"),
    g(83, Group::Motion, GFn::Drill(DrillKind::FaceG83), "end face peck drilling cycle"),
    g(84, Group::Motion, GFn::Drill(DrillKind::TapFace), "end face rigid tapping cycle (after M29 S_)"),
    g(85, Group::Motion, GFn::Drill(DrillKind::FaceBoreStart), "end face boring cycle: feed in along Z, dwell P, feed out (inferred)"),
    g(87, Group::Motion, GFn::Drill(DrillKind::SideG87), "side peck drilling cycle"),
    g(88, Group::Motion, GFn::Drill(DrillKind::TapSide), "side rigid tapping cycle (after M29 S_)"),
    g(89, Group::Motion, GFn::Drill(DrillKind::SideBoreStart), "side boring cycle: feed in along X, dwell P, feed out (inferred)"),
    g(78, Group::NonModal, GFn::CompoundThread(Compound::G78), "compound thread cutting cycle with infeed modes, two blocks"),
];

/// G05/G05.1, G6.2/G6.3, G7.2/G7.3 (help text pages of those names; docs/commands/g05_g6_g7.md).
const CURVES: &[GDef] = &[
    g(5, Group::Motion, GFn::Curve(Curve::ThreePoint { mid_absolute: false }), "three-point arc: I/K the middle point from the start (I a radius)"),
    gp(5, 1, "G05.1", Group::Motion, GFn::Curve(Curve::ThreePoint { mid_absolute: true }), "three-point arc: I/K the middle point's coordinates"),
    gp(6, 2, "G06.2", Group::Motion, GFn::Curve(Curve::Ellipse(ArcDir::Cw)), "ellipse, turning as G02: A long and B short half axis, Q the long axis's angle"),
    gp(6, 3, "G06.3", Group::Motion, GFn::Curve(Curve::Ellipse(ArcDir::Ccw)), "ellipse, turning as G03: A long and B short half axis, Q the long axis's angle"),
    gp(7, 2, "G07.2", Group::Motion, GFn::Curve(Curve::Parabola(ArcDir::Cw)), "parabola Y² = 2PX, turning as G02: Q its axis's angle"),
    gp(7, 3, "G07.3", Group::Motion, GFn::Curve(Curve::Parabola(ArcDir::Ccw)), "parabola Y² = 2PX, turning as G03: Q its axis's angle"),
];

const PARAMS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(181, Some(0)),
        meaning: "what a chamfer's L measures: 0 = the chamfer's length (type I), 1 = the distance from the corner to each end of the chamfer (type II)",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "GSK980TDi help text, chamfer function (the bit named; which value is which type inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(18, Some(6)),
        meaning: "feed hold during a G92 thread: 0 = pull out at once and return to the start, 1 = finish the thread with its pull-out, then stop",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "GSK980TDi manual, G92 note 1",
    },
    ParamDef {
        key: ParamKey::Number(19, None),
        meaning: "thread pull-out (run-out) width used by G92 and G76 when J and K are omitted",
        unit: "0.1 x lead",
        min: 0.0,
        max: 99.0,
        default: 10.0,
        source: "GSK980TDi manual, G92 notes 2-3; range TAC p135; default assumed (not found): 1 lead",
    },
    ParamDef {
        key: ParamKey::Number(22, None),
        meaning: "rapid traverse rate (each axis)",
        unit: "mm/min",
        min: 1.0,
        max: 60000.0,
        default: 8000.0,
        source: "TDi help G00 names No.022; default assumed (not found)",
    },
    ParamDef {
        key: ParamKey::Number(27, None),
        meaning: "upper limit of the cutting feed",
        unit: "mm/min",
        min: 1.0,
        max: 60000.0,
        default: 8000.0,
        source: "TDi help G01 names No.027; default assumed (not found)",
    },
    ParamDef {
        key: ParamKey::Number(174, Some(4)),
        meaning: "thread repair: 1 = G92 P1 / G92.1 P1 repair the thread at the recorded position",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "TDi help, thread repair, operation 1",
    },
    ParamDef {
        key: ParamKey::Number(174, Some(5)),
        meaning: "thread repair mode: 0 = follow type (G92 P1), 1 = interpolation type (G92.1 P1) (meaning of the values assumed)",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "TDi help, thread repair, operation 2",
    },
    ParamDef {
        key: ParamKey::Number(57, None),
        meaning: "G76 number of finishing passes m; G76 P rewrites it",
        unit: "passes",
        min: 0.0,
        max: 99.0,
        default: 1.0,
        source: "TAC p135 (GSK980TDb/TDc numbering); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(58, None),
        meaning: "G76 tool angle a; G76 P rewrites it",
        unit: "deg",
        min: 0.0,
        max: 99.0,
        default: 60.0,
        source: "TAC p135; default assumed",
    },
    ParamDef {
        key: ParamKey::Number(59, None),
        meaning: "G76 minimum cut dmin, the power-on value of Q",
        unit: "0.001 mm",
        min: 0.0,
        max: 999999.0,
        default: 100.0,
        source: "TAC p135 (the ordering, inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(56, None),
        meaning: "G74/G75 back-off e at power on; their first block R rewrites it",
        unit: "mm",
        min: 0.0,
        max: 99.0,
        default: 0.0,
        source: "TDi p70; default assumed",
    },
    ParamDef {
        key: ParamKey::Number(60, None),
        meaning: "G76 finishing allowance d, the power-on value of R",
        unit: "mm",
        min: 0.0,
        max: 99.0,
        default: 0.05,
        source: "TDi p70, Table 3-2; default assumed",
    },
    ParamDef {
        key: ParamKey::Number(107, None),
        meaning: "short-axis speed of the thread pull-out; 0 = the pull-out angle follows J:K",
        unit: "mm/min",
        min: 0.0,
        max: 60000.0,
        default: 0.0,
        source: "GSK980TDi manual, G92 note 8; TDi p151",
    },
];

pub static PROFILE: Profile = Profile {
    name: "gsk980tdi",
    title: "GSK980TDi lathe (G-code system A)",
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
    axes: "XZ",
    reference_point_mm: crate::motion::Vec3::new(100.0, 0.0, 200.0),
    addresses: super::Letters::new("GMSTFXZUWRIJKPQLNDEAB"),
    peck_back_off: Some(ParamKey::Number(56, None)),
    box_taper: b'R',
    g_codes: &[
        super::Codes { source: "GSK980TDi help text (G-code list)", codes: common::G_CODES },
        super::Codes { source: "GSK980TDi help text (G-code list)", codes: common::UNITS },
        super::Codes { source: "GSK980TDi help text (G-code list)", codes: lathe_a::G_CODES },
        super::Codes { source: "GSK980TDi help text (G-code list)", codes: lathe_a::MULTIPLE_CYCLES },
        super::Codes { source: "GSK980TDi manual, G92 (seed 000) and help text", codes: EXTRA },
        super::Codes { source: "GSK980TDi help text, G05/05.1, G6.2/6.3, G7.2/7.3; Q's sense from the GSK980TDc manual", codes: CURVES },
        super::Codes { source: "GSK980TDi help text (G-code list)", codes: super::later::GSK980TDI },
    ],
    m_codes: &[
        super::Codes { source: "GSK980TDi help text (M-code list)", codes: common::M_CODES },
        super::Codes { source: "GSK980TDi help text (M-code list)", codes: lathe_a::M_CODES },
        super::Codes { source: "GSK980TDi help text (M-code list)", codes: lathe_a::GSK_M_CODES },
        super::Codes { source: "GSK980TDi help text, G84/G88", codes: TAPPING_M },
        super::Codes { source: "GSK980TDi help text, M24/25, M50-58, M63/64/65", codes: SECOND_SPINDLE_M },
    ],
    params: &[PARAMS, DRY_RUN, super::builder::GSK980TDI, super::GSK_LATHE_OFFSETS, SETTINGS],
    time: TimeKeys {
        rapid: [ParamKey::Number(22, None), ParamKey::Number(22, None), ParamKey::Number(22, None)],
        dry_run: ParamKey::Setting("dry_run_mm_min"),
        feed_max: ParamKey::Number(27, None),
    },
    thread: ThreadRules {
        q_point: QPoint::Ignored,
        arc_q_unit_deg: 0.001,
        pull_out_speed: Some(ParamKey::Number(107, None)),
        after_end_feed: None,
        pull_out_accel: None,
        repair_enable: Some(ParamKey::Number(174, Some(4))),
        g32_pull_out: true,
        g32_lead_e: false,
        g76: Some(G76Keys {
            finishing: ParamKey::Number(57, None),
            pull_out: ParamKey::Number(19, None),
            angle: ParamKey::Number(58, None),
            dmin_um: ParamKey::Number(59, None),
            allowance: ParamKey::Number(60, None),
            allowance_to_mm: 1.0,
            pull_out_angle: None,
        }),
        g34: super::G34_GSK,
        g32_1: super::G32_1_GSK980TDI,
    },
    drill: super::DrillRules::NONE,
    calls: super::CallRules {
        max_count: 9999,
        l_count: false,
        max_depth: 4,
        builder: super::BuilderCalls { g_macro: Some((86, 9010, 10)), m9000: true, ..super::BuilderCalls::NONE },
        sequence_q: false,
        g70_reads_programme: false,
        eight_digit: None,
        source: "GSK980TDi help text, M98 (count 1-9999, number 0000-9999; no L); nesting depth not stated, four as for G65 (inferred)",
    },
    macros: super::MacroRules {
        p_first: true,
        g65_cancels_g66: true,
        if_without_then: false,
        macro_a: true,
        // Not found in the help text: single block stops only after NC blocks (docs/reference/macro.md section 6).
        single_block_param: None,
        source: "GSK980TDi help text, G65 (P right after G65; macro A with H); five bracket levels as FANUC (inferred)",
        table_variables: false,
        ..super::MacroRules::FANUC
    },
    frame: super::FrameRules::GSK,
    g_code_systems: None,
    summary: "GSK980TDi turning centre. X is a diameter, U/W incremental. Lengths without a decimal \
point are millimetres (seed 000's O0012: Z-28, F3, J3 K1). Feed per minute (G98) at power on.",
};
