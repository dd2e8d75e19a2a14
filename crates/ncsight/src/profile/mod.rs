//! Controller profiles. A profile answers the interpreter's questions: which G and M codes exist
//! and what they mean, how a number without a decimal point is read, which parameters exist with
//! their manual numbers, units, ranges and defaults, and which alarm numbering is used.
//! The interpreter never tests a profile's name.
//!
//! Profiles are data (`gsk980tdi.rs`, `gsk988t.rs`, `fanuc0m.rs`, `yasnac_lx3.rs`); the G-code
//! tables that several lathes share live in `lathe_a.rs`.

mod builder;
mod common;
mod fanuc0i;
mod fanuc0m;
mod fanuc0t;
mod gsk980tdi;
mod gsk988t;
mod later;
mod lathe_a;
mod lathe_drill;
mod meaning_zh;
mod yasnac_lx3;

use crate::alarm::AlarmStyle;

pub use meaning_zh::meaning_zh;

/// Highest spindle speed any profile turns (G96 at the centre without a G50 clamp), rpm. Assumed.
pub const MAX_RPM: f64 = 10000.0;

/// Lathe (X diameter, Z spindle axis, XZ plane) or machining centre.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MachineKind {
    Lathe,
    Mill,
}

/// How a length written without a decimal point is read (docs/reference/behaviour.md,
/// "Numbers and words").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IntegerLengths {
    /// GSK: `Z-28` is 28 mm (seed 000's example O0012 only makes sense that way).
    Millimetres,
    /// FANUC and YASNAC: `X100` is 100 least input increments = 0.100 mm (0.0100 inch).
    LeastIncrement,
}

/// The modal group a G code belongs to, by meaning (the numbers differ between lathe and mill
/// manuals; the rules "last of a group counts" and "00 with 01 is an alarm" need only identity).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Group {
    /// Group 00: one-shot codes (G04, G28, G50, ...).
    NonModal,
    /// Group 01: interpolation and cycles of the lathe's group 01.
    Motion,
    Plane,
    Distance,
    Units,
    FeedMode,
    SpindleSpeedMode,
    CutterComp,
    LengthComp,
    /// FANUC 0-M group 09: drilling canned cycles and G80.
    CannedCycle,
    /// FANUC 0-M group 10: G98/G99 return level.
    ReturnLevel,
    WorkOffset,
    PathMode,
    /// Polar coordinate interpolation (G12.1/G13.1) or command (G15/G16).
    Polar,
    /// The GSK980TDi's G15/G16, beside its G12.1/G13.1.
    Polar2,
    /// Stored stroke check G22/G23.
    StrokeCheck,
    /// Scaling G50/G51 (FANUC 0-M).
    Scaling,
    /// Modal macro call G66/G67.
    MacroCall,
    /// Coordinate rotation (mill) or turret mirror image (lathe) G68/G69.
    Rotation,
    /// Spindle speed fluctuation detection G25/G26 (FANUC 0-T).
    SpindleCheck,
    /// Programmable mirror image G50.1/G51.1 (FANUC 0i-M group 22).
    MirrorImage,
}

impl Group {
    /// How many groups there are (for tables indexed by `group as usize`).
    pub const COUNT: usize = Group::MirrorImage as usize + 1;
}

/// FANUC's numbers of the modal groups, which #4001-#4022 read (#4000 + the group number; the
/// G-code lists of the FANUC 0i-MC and 0i-TC operator's manuals, inferred for the FANUC 0;
/// docs/reference/macro.md section 8).
pub const FANUC_M_GROUPS: &[(u8, Group)] = &[
    (1, Group::Motion),
    (2, Group::Plane),
    (3, Group::Distance),
    (4, Group::StrokeCheck),
    (5, Group::FeedMode),
    (6, Group::Units),
    (7, Group::CutterComp),
    (8, Group::LengthComp),
    (9, Group::CannedCycle),
    (10, Group::ReturnLevel),
    (11, Group::Scaling),
    (12, Group::MacroCall),
    (13, Group::SpindleSpeedMode),
    (14, Group::WorkOffset),
    (15, Group::PathMode),
    (16, Group::Rotation),
    (17, Group::Polar),
    (22, Group::MirrorImage),
];

/// The lathe's numbering (G-code system A; FANUC 0i-TC list, inferred for the FANUC 0-T and,
/// without a list of their own, for the GSK and YASNAC lathes).
pub const FANUC_T_GROUPS: &[(u8, Group)] = &[
    (1, Group::Motion),
    (2, Group::SpindleSpeedMode),
    (3, Group::Distance),
    (4, Group::Rotation),
    (5, Group::FeedMode),
    (6, Group::Units),
    (7, Group::CutterComp),
    (8, Group::SpindleCheck),
    (9, Group::StrokeCheck),
    (10, Group::CannedCycle),
    (11, Group::ReturnLevel),
    (12, Group::MacroCall),
    (14, Group::WorkOffset),
    (15, Group::PathMode),
    (16, Group::Plane),
    (17, Group::Polar2),
    (21, Group::Polar),
];

/// What a G code does, as far as the interpreter is concerned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GFn {
    Rapid,
    Linear,
    ArcCw,
    ArcCcw,
    Dwell,
    PlaneXY,
    PlaneZX,
    PlaneYZ,
    Inch,
    Metric,
    Absolute,
    Incremental,
    FeedPerMinute,
    FeedPerRevolution,
    /// G96: S is a surface speed in m/min.
    ConstantSurfaceSpeed,
    /// G97: S is in rpm.
    ConstantRpm,
    /// G28: via an intermediate point to the reference point.
    ReferenceReturn,
    /// G29: from the reference point through the last G28/G30's intermediate point to the point
    /// given.
    FromReference,
    /// G50 (lathe, system A): set the current position's coordinates; with S, the spindle clamp.
    LatheCoordinateSet,
    /// G92 (mill): set the current position's coordinates.
    MillCoordinateSet,
    /// G40 (0), G41 (+1: the tool left of the path), G42 (-1): tool (nose) radius compensation.
    RadiusComp(i8),
    /// G43 (+1), G44 (-1), G49 (0): tool length compensation along Z by the offset H names.
    LengthComp(i8),
    /// G10: data setting (work offsets, tool offsets) in the forms of the profile's `G10Forms`.
    DataSetting,
    /// G11: the end of G10's parameter (or tool life) lines.
    DataSettingEnd,
    /// G45 (+1), G46 (-1), G47 (+2), G48 (-2): the block's move lengthened (shortened) by the
    /// offset D once (twice).
    OffsetMove(i8),
    /// G27: rapid to the point given, then a check that it is the reference point.
    ReferenceCheck,
    /// G31: a cutting feed that the skip signal would end early; none comes in a simulation.
    Skip,
    /// G60: single direction positioning (each axis comes to its end point from one side).
    SingleDirection,
    /// G54..G59: select work coordinate system 1-6 (offsets from the setup's `[work]`).
    WorkOffset(u8),
    /// G54.1 P1-P48: an additional work coordinate system (the setup's `[work] "G54.1"`).
    AdditionalWorkOffset,
    /// G52: a local coordinate system inside the work system (FANUC; GSK980TDi help G52).
    LocalCoordinates,
    /// G53: positioning in machine coordinates, this block only.
    MachineCoordinates,
    /// G30: via an intermediate point to the 2nd (3rd, 4th: P) reference point.
    OtherReferenceReturn,
    /// Codes that change nothing ncsight models: G61/G64 path control and G09 exact stop (every
    /// move of the time model starts and ends at rest), G25/G26 spindle speed fluctuation
    /// detection (the simulated spindle does not fluctuate).
    PathControl,
    /// G98/G99 on a mill: return to the initial level / to the R point.
    ReturnInitial,
    ReturnR,
    /// G80 on a mill: cancel the canned cycle.
    CycleCancel,
    /// A drilling canned cycle (FANUC 0-M group 09).
    Drill(crate::codes::DrillKind),
    /// A thread-cutting command (group 01).
    Thread(ThreadCmd),
    /// A three-point arc, an ellipse or a parabola (group 01; cycles/curve.rs).
    Curve(Curve),
    /// G76 compound thread cutting, or the GSK980TDi G78 with its infeed modes: the two-block
    /// form (group 00).
    CompoundThread(Compound),
    /// G71 / G72 roughing on the lathes (group 00, two blocks, the contour blocks after them).
    Rough(crate::codes::RoughKind),
    /// G70 finishing along a contour roughed before (group 00).
    Finish,
    /// G74 / G75 on the lathes: peck cutting along one axis, stepping along the other, two
    /// blocks (group 00).
    PeckCycle(crate::codes::PeckKind),
    /// G90 / G94: the single turning and facing cycles of the lathes (group 01).
    BoxCycle(crate::codes::BoxKind),
    /// G68 (on) / G69 (off): coordinate system rotation in the plane.
    Rotation(bool),
    /// G51.1 (on) / G50.1 (off): programmable mirror image.
    MirrorImage(bool),
    /// G68 (on) / G69 (off) on a lathe: X mirrored about the spindle's centre line (YASNAC LX3
    /// program mirror image; FANUC 0-T mirror image for double turrets).
    TurretMirror(bool),
    /// G51 (on) / G50 (off) on a machining centre: scaling (an option).
    Scaling(bool),
    /// G16 (on) / G15 (off): polar coordinate command.
    PolarCoordinates(bool),
    /// G63: tapping mode (a tap in a floating holder fed by G01): the feed override is 100 % and
    /// FEED HOLD waits for the block's end. G61, G62 and G64 end it (group 15).
    TappingMode,
    /// G62: automatic override of the feed at inner corners in cutter compensation.
    CornerOverride,
    /// G39: the next outer corner of the compensated path is an arc about the corner.
    CornerArc,
    /// G12.1 (on) / G13.1 (off): polar coordinate interpolation with the C axis.
    PolarInterpolation(bool),
    /// G07.1 C<radius> (on; C0 off): cylindrical interpolation with the C axis.
    CylindricalInterpolation,
    /// G22 (on) / G23 (off): stored stroke check 2, a forbidden area.
    StrokeCheck(bool),
    /// G36 (X, 0) / G37 (Z, 2): automatic tool compensation or tool length measurement, a
    /// move to the measuring position that a sensor's signal would end.
    ToolMeasure(u8),
    /// Known to the controller, not yet simulated: an alarm that says so.
    NotYet(&'static str),
    /// G65: a custom macro call, run by the programme (not the interpreter) with a new level of
    /// local variables.
    MacroCall,
    /// G66: the macro is called after each later block with a move, until G67 (run by the
    /// programme, as G65).
    ModalMacroCall,
    ModalMacroCancel,
}

/// The curves the GSK980TDi cuts besides the circle (help text G05/G05.1, G6.2/G6.3, G7.2/G7.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Curve {
    /// G05: the arc through a middle point I/K from the start; G05.1: I/K the middle point's
    /// absolute coordinates.
    ThreePoint { mid_absolute: bool },
    /// G6.2 (`Cw`, as G02) / G6.3: an ellipse of half axes A and B, its long axis at Q.
    Ellipse(crate::motion::ArcDir),
    /// G7.2 (`Cw`) / G7.3: the parabola Y² = 2PX, its axis at Q.
    Parabola(crate::motion::ArcDir),
}

/// The two-block compound threading cycles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Compound {
    /// G76: decreasing depths, infeed along one flank.
    G76,
    /// G78 (GSK980TDi help text): G76 with a choice of depth schedule, infeed mode, finishing
    /// passes D and starts L.
    G78,
}

/// The thread-cutting commands. What differs between them is data here and in
/// `interp/thread.rs`, not copies of the geometry.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ThreadCmd {
    /// G32 on the GSK lathes: F lead or I threads per inch, J (signed) / K pull-out, Q.
    Lead,
    /// G32.1 rigid thread cutting on the GSK988T (seed 001 section 2).
    Rigid,
    /// A four-step thread-cutting cycle, with the rules of its controller's manual.
    Cycle(&'static CycleRules),
    /// G32.2 (clockwise) and G32.3 (counter-clockwise) arc threads (seed 002).
    Arc(crate::motion::ArcDir),
    /// G33 on the GSK980TDi: tapping, in and out with the spindle reversed (help text).
    Tap,
    /// G34 on the GSK980TDi: variable lead, R more (or less) per revolution (help text).
    VariableLead,
}

/// The rules of a four-step thread-cutting cycle (G92, G92.1) as a manual gives them: which
/// words it takes, how it pulls out, what FEED HOLD does. A profile fills one in per cycle code;
/// the interpreter asks it and never which controller it is.
#[derive(Debug, PartialEq, Eq)]
pub struct CycleRules {
    /// The code as a message names it (`G92`, `G92.1`).
    pub code: &'static str,
    /// Spindle-synchronised (rigid): the spindle in position mode, its speed from S.
    pub rigid: bool,
    /// A negative F is a left-hand thread: the spindle turns the other way.
    pub negative_f_left_hand: bool,
    /// Besides F: I threads per inch, E a lead.
    pub lead_i: bool,
    pub lead_e: bool,
    /// P1 repairs the thread (thread repair enabled by the profile's parameter).
    pub repair_p: bool,
    /// L: the number of starts, 1-99, modal.
    pub starts_l: bool,
    pub jk: JkWords,
    /// K shifts this pass's start along Z with its sign (flank infeed).
    pub flank_k: bool,
    /// T and S belong in the blocks before the cycle: a warning when the cycle block has them.
    pub ts_before: bool,
    /// Q: the start angle in 0.001 degree.
    pub q_start: bool,
    /// The taper's address (`R` or `I`): radius, cut start minus cut end.
    pub taper: u8,
    /// The taper may not exceed |U/2| where it differs from U in sign.
    pub taper_limit: bool,
    pub pull_out: PullOutRule,
    pub hold: HoldRule,
}

/// The J and K words of a cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JkWords {
    None,
    /// Negative J and K count as positive.
    SignIgnored,
    /// J and K are 0 or more.
    NonNegative,
}

/// How a cycle's thread pulls out at its end.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PullOutRule {
    /// The feed axes and the spindle stop together at the end point.
    None,
    /// J and K, the parameter (in 0.1 x lead) for what is omitted.
    JkTenths(ParamKey),
    /// J and K, the chamfer parameters (amount in 0.1 x lead, angle) for what is omitted, a J
    /// without K straight out after the end point.
    JkChamfer { amount: ParamKey, angle: ParamKey },
    /// The chamfer parameters only (no J/K words).
    Chamfer { amount: ParamKey, angle: ParamKey },
}

/// What FEED HOLD does during the thread of a cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HoldRule {
    /// Pull out at once and return to the start, or (the bit = 1) finish the thread first.
    PullOutOrFinish(ParamKey),
    /// Thread up at once and return to the start, or (the bit = 1) stop where threading up ends.
    ThreadUp(ParamKey),
    /// The press is discarded.
    Ignored,
    /// The thread and its pull-out are finished, then the stop.
    AfterRun,
}

/// How a decimal point in the thread start angle Q is treated (docs/reference/behaviour.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum QPoint {
    /// GSK988T: "Q cannot have a decimal point" (seed 001).
    Alarm,
    /// GSK980TDi: the point is ignored, `Q180.0` is 0.18 degrees (TDi p150); a warning says so.
    Ignored,
}

/// The parameters the drilling canned cycles read.
#[derive(Debug, Clone, Copy)]
pub struct DrillRules {
    /// G73's retract d, in 0.001 mm (FANUC 0-M 531).
    pub g73_retract_um: Option<ParamKey>,
    /// G83's clearance d above the previous depth, in 0.001 mm (FANUC 0-M 532).
    pub g83_clearance_um: Option<ParamKey>,
    /// The G76/G87 shift direction bits (low, high): (high, low) 00 = +X, 01 = -X, 10 = +Y,
    /// 11 = -Y (FANUC 0-M parameter 2 bits 4 and 5).
    pub shift_bits: Option<(ParamKey, ParamKey)>,
    /// The lathe's G83/G87 with Q: the bit that chooses the standard peck cycle (1: back to R
    /// after each peck, then down to `g83_clearance_um` short) over the high-speed one (0: back
    /// off `g73_retract_um`) (FANUC 0i-T 5101#2 RTR, inferred).
    pub lathe_peck_full_return: Option<ParamKey>,
}

impl DrillRules {
    /// A profile without those cycles' parameters.
    pub const NONE: DrillRules = DrillRules { g73_retract_um: None, g83_clearance_um: None, shift_bits: None, lathe_peck_full_return: None };
}

/// How the controller calls subprogrammes (M98) and returns from them (M99).
#[derive(Debug, Clone, Copy)]
pub struct CallRules {
    /// The largest repeat count of `M98 P<count><number>` (the digits above the last four).
    pub max_count: u32,
    /// M98 also takes `L` as the repeat count; P is then the programme number alone.
    pub l_count: bool,
    /// Subprogramme calls may nest this many levels (the main programme's call is level 1).
    pub max_depth: u8,
    /// Calls a machine builder sets up by parameter.
    pub builder: BuilderCalls,
    /// `M98 Q<n>` (no P) calls the blocks from N`n` of the running programme to its M99
    /// (FANUC 0i-F).
    pub sequence_q: bool,
    /// G70 P(ns) Q(nf) runs the programme's blocks N`ns` to N`nf` when no G71-G73 collected
    /// that range (FANUC: G70 reads them from memory); else alarm PS0063.
    pub g70_reads_programme: bool,
    /// The setting that makes programme numbers eight digits (the FANUC 0i-F's option): M98 P
    /// and G65 P are then the number alone (O1-O99999999), the count L.
    pub eight_digit: Option<ParamKey>,
    /// The manual this comes from, and what was inferred.
    pub source: &'static str,
}

/// G and M codes that call the machine's macro programmes, by parameter: the first of ten (or
/// nine) parameters and the programme the first calls.
#[derive(Debug, Clone, Copy, Default)]
pub struct BuilderCalls {
    /// G codes called as G65 (FANUC 6050-6059 -> O9010-O9019).
    pub g_macro: Option<(u32, u32, u32)>,
    /// M codes called as M98 (FANUC 6071-6079 -> O9001-O9009).
    pub m_subprogram: Option<(u32, u32, u32)>,
    /// M codes called as G65 (FANUC 6080-6089 -> O9020-O9029).
    pub m_macro: Option<(u32, u32, u32)>,
    /// M9000-M9999 call O9000-O9999 (GSK980TDi help text, M9000-9999).
    pub m9000: bool,
}

impl BuilderCalls {
    /// No such calls known (no manual text at hand).
    pub const NONE: BuilderCalls = BuilderCalls { g_macro: None, m_subprogram: None, m_macro: None, m9000: false };
    pub const FANUC: BuilderCalls =
        BuilderCalls { g_macro: Some((6050, 9010, 10)), m_subprogram: Some((6071, 9001, 9)), m_macro: Some((6080, 9020, 10)), m9000: false };

    /// The parameters the calls read.
    pub fn keys(&self) -> impl Iterator<Item = ParamKey> + '_ {
        [self.g_macro, self.m_subprogram, self.m_macro].into_iter().flatten().flat_map(|(first, _, n)| (first..first + n).map(|k| ParamKey::Number(k, None)))
    }
}

impl CallRules {
    /// FANUC 0 and its compatibles: `M98 P<count 1-999><number>` or `M98 P<number> L<count>`,
    /// four levels (FANUC 0i-TB/MB operator's manual 12.3; the L form is the FANUC 0-M's own).
    pub const FANUC: CallRules = CallRules {
        max_count: 999,
        l_count: true,
        max_depth: 4,
        builder: BuilderCalls::FANUC,
        sequence_q: false,
        g70_reads_programme: true,
        eight_digit: None,
        source: "FANUC 0i-TB/MB operator's manual 12.3 (count 1-999, four levels); M98 P_ L_ as on the FANUC 0-M (inferred for the lathe)",
    };
}

/// Custom macro B as the controller has it.
#[derive(Debug, Clone, Copy)]
pub struct MacroRules {
    /// Brackets nest at most this deep, a function's included (FANUC alarm 118: five).
    pub max_brackets: u8,
    /// G65 is followed directly by P (or H) (GSK980TDi help text, G65).
    pub p_first: bool,
    /// `G65 H..` is the controller's macro A (GSK980TDi), not simulated yet; elsewhere H is an
    /// argument (#11).
    pub macro_a: bool,
    /// A G65 cancels a G66 modal call (GSK980TDi help text, G66; FANUC: not, inferred).
    pub g65_cancels_g66: bool,
    /// `IF [..] #i = ..` without THEN is taken as THEN (a FANUC 0i programme relies on it), with
    /// warning NCS-W28; elsewhere it is alarm 114 (docs/reference/macro.md section 6, inferred).
    pub if_without_then: bool,
    /// The parameter that makes single block stop after a macro statement as well (FANUC 6000#5
    /// SBM; docs/reference/macro.md section 6). Without one, or with it 0, single block stops only after NC
    /// blocks.
    pub single_block_param: Option<ParamKey>,
    /// The group numbers #4001-#4022 read (`FANUC_M_GROUPS`, `FANUC_T_GROUPS`).
    pub group_numbers: &'static [(u8, Group)],
    /// #2001.., #5201.., #10001.. name the tool and work offset tables (FANUC memory C;
    /// interp/table_vars.rs).
    pub table_variables: bool,
    pub source: &'static str,
}

impl MacroRules {
    pub const FANUC: MacroRules = MacroRules {
        max_brackets: 5,
        p_first: false,
        macro_a: false,
        g65_cancels_g66: false,
        if_without_then: true,
        single_block_param: Some(ParamKey::Number(6000, Some(5))),
        group_numbers: FANUC_T_GROUPS,
        table_variables: true,
        source: "FANUC Series 16/18 operator's manual for lathe (brackets: five levels, alarm 118); FANUC Series 16i (G65 arguments)",
    };
}

/// How the coordinate systems behave (docs/reference/macro.md section 10.2).
#[derive(Debug, Clone, Copy)]
pub struct FrameRules {
    /// G50/G92 in the same block as G54-G59 wins: the work system stays as it was (GSK980TDi
    /// help text, G54-G59 note 6). Elsewhere the system is selected first, then set.
    pub coordinate_set_wins: bool,
    /// G28 and G30 cancel the tool offset (GSK980TDi help text, G28 note 2, G30 note 3).
    pub reference_cancels_tool_offset: bool,
    /// The highest reference point G30 reaches with P (4: P2-P4; 2: the 2nd only).
    pub last_reference: u8,
    /// Lathes: the parameters that say how a T word's offset acts: (geometry by movement = 1,
    /// by shifting the coordinates = 0: FANUC 5002#4 LGT; wear with the next move = 1, in the
    /// T block = 0: FANUC 5002#6 LWM). Mills: `None` (G43/G44 move in their block).
    pub lathe_offset_keys: Option<(ParamKey, ParamKey)>,
    /// What G10 sets, where the profile simulates it.
    pub g10: G10Forms,
    /// `G10 L_` ... `G11`: the parameter-writing mode, where the profile has one.
    pub parameter_entry: Option<ParamEntry>,
    /// G12.1 under feed per revolution (G99) is an alarm (GSK980TDi help text, G12.1 note 3).
    pub polar_refuses_per_rev: bool,
    /// Corners and line angles written as the drawing gives them, where the controller has
    /// them (lathes).
    pub drawing: Option<DrawingRules>,
    /// Radius compensation looks ahead across this many blocks without a move in the plane
    /// before the held move ends perpendicular (FANUC: 1, as its manuals draw it).
    pub comp_lookahead: u8,
    /// This many consecutive blocks without a move in compensation is an alarm (GSK980TDi help
    /// text, G40-G42 note 1: seven).
    pub comp_idle_alarm: Option<u8>,
    /// G71-G73 cancel radius compensation (GSK980TDi help text, G40-G42 note 6); elsewhere they
    /// rough along the compensated shape.
    pub rough_cancels_comp: bool,
    /// G90/G94 in compensation are offset by the imaginary tool nose (FANUC, inferred); elsewhere
    /// they run as programmed (the GSK text says nothing: suspended, with a warning).
    pub box_by_tip: bool,
    /// The parameters of the coordinate transforms (G68, G51), where the profile has them.
    pub transform_keys: TransformKeys,
    /// G62's inner-corner override, where the profile has it.
    pub corner_override: Option<CornerOverrideKeys>,
    /// Axes beyond the profile's own that its machines usually have (a turning centre's C and
    /// Y): taken, with a warning, until a setup's `[machine] axes` says which the machine has.
    pub assumed_axes: &'static str,
    /// The spindle selection P values its machines usually have (FANUC multi-spindle: P11 the
    /// first spindle, P12 the second), taken with a warning until a setup gives `spindle_p`.
    pub assumed_spindle_p: &'static [u32],
    /// The bit that says what G02/G03 with neither R nor a centre word does: 0 a straight move
    /// to the end point, 1 alarm PS0022 (FANUC 0i-F 3403#5 CIR); without one, the alarm.
    pub arc_without_centre: Option<ParamKey>,
    pub source: &'static str,
}

/// G62, automatic corner override (FANUC 16i manual, inside-corner override; 0i numbering): in
/// cutter compensation the feed at an inner corner of at most `angle` degrees on the work side is
/// overridden by `percent` from `before` mm before the corner to `after` mm after it, on the
/// cutter centre path. And inside an arc in cutter compensation (with or without G62) the
/// centre path runs at F times its radius over the programmed one, `arc_min_percent` at least.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CornerOverrideKeys {
    /// The least a cutter centre path inside an arc is slowed to, per cent (FANUC 1710 MDR).
    pub arc_min_percent: ParamKey,
    pub angle: ParamKey,
    pub percent: ParamKey,
    pub after: ParamKey,
    pub before: ParamKey,
}

/// The programmable parameter mode: `G10 L<l>`, then one parameter a line (`N` the number, `P`
/// the axis, the value), then `G11`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParamEntry {
    pub l: u32,
    /// The letter of the value written: R on the FANUC (0i manual, G10 L50), W on the GSK
    /// (GSK980TDi help text, parameter reading and writing).
    pub value: u8,
    /// The letter naming a macro variable the parameter is read into (GSK: R).
    pub read_into: Option<u8>,
}

/// The parameters G68 and G51 read.
#[derive(Debug, Clone, Copy)]
pub struct TransformKeys {
    /// G68's R in G91 adds to the angle in force when this bit is 1 (FANUC 0i 5400#0 RIN).
    pub rotation_incremental: Option<ParamKey>,
    /// G68's angle when R is omitted, 0.001 degree (FANUC 0i 5410).
    pub rotation_angle: Option<ParamKey>,
    /// G51's magnification when P is omitted, 0.001 (FANUC 0i 5411).
    pub magnification: Option<ParamKey>,
    /// The machine has the scaling option (a setting).
    pub scaling_option: Option<ParamKey>,
}

impl TransformKeys {
    pub const NONE: TransformKeys = TransformKeys { rotation_incremental: None, rotation_angle: None, magnification: None, scaling_option: None };
}

/// The G10 forms a controller has (docs/reference/macro.md 10.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum G10Forms {
    /// FANUC 0-T: `G10 P_ X(U) Z(W) R(C) Q` (P1-64 wear, P10001-10064 geometry), `G10 L2 P0-6`.
    LatheOffsets,
    /// FANUC 0-M: `G10 L2 P0-6 X Y Z`, `G10 L10-L13 P R` (memory C), `G10 P R` (memory A).
    MillOffsets,
    /// GSK980TDi: only `G10 L3` (tool life) and `G10 L52` (parameters); no offsets.
    ToolLifeAndParameters,
}

/// A chamfer or corner arc between a block's move and the next, and a line given by its angle
/// with one coordinate (or with none: its end is where it meets the next line), as a drawing
/// dimensions them. Addresses as the reader stores them: `b'c'` is `,C`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DrawingRules {
    /// The chamfer's address.
    pub chamfer: u8,
    /// The corner arc's address (its radius).
    pub round: u8,
    /// The bit that says what the chamfer's value measures (0: the chamfer's length; 1: the
    /// distance from the corner to each end); `None`: always the distance from the corner.
    pub chamfer_type: Option<ParamKey>,
    /// The line's angle from the plane's first axis (Z in G18), counter-clockwise.
    pub angle: u8,
    /// The angle's word counts 0.001 degree, with a decimal point too; else degrees as an
    /// angle word reads.
    pub angle_thousandths: bool,
    /// The angle forms work in G00 blocks too (positioning only).
    pub angle_in_rapid: bool,
    /// A corner's block must be followed by a G01 move: another move is an alarm, as is no
    /// move; else a G00 next or no move makes the move whole, with a warning.
    pub corner_needs_g01: bool,
    /// G17 and G19 have the angle forms too; else only G18 (the ZX plane).
    pub any_plane: bool,
    /// FANUC's chamfering and corner R between two moves at a right angle: `G01 Z_ I_` (a 45
    /// degree chamfer to an X move), `G01 X_ K_` (to a Z move), `G01 Z_ R_` or `X_ R_` (a corner
    /// arc), the sign the next move's way.
    pub right_angle: bool,
    /// The bit that makes the drawing's words plain C, R and A, without the comma, and C the
    /// right-angle chamfer instead of I/K (FANUC 0i-TF 3405#4 CCR = 1); then A and C cannot be
    /// axes. Without one, the comma words only.
    pub plain_letters: Option<ParamKey>,
    pub source: &'static str,
}

impl DrawingRules {
    /// GSK980TDi help text, chamfer function (L, D; No.181.0) and angle programming (Q).
    pub const GSK: DrawingRules = DrawingRules {
        chamfer: b'L',
        round: b'D',
        chamfer_type: Some(ParamKey::Number(181, Some(0))),
        angle: b'Q',
        angle_thousandths: true,
        angle_in_rapid: true,
        corner_needs_g01: false,
        any_plane: true,
        right_angle: false,
        plain_letters: None,
        source: "GSK980TDi help text: chamfer function; angle programming notes 1-8",
    };
    /// FANUC 0-T direct drawing dimension programming (`,A` `,C` `,R`): the forms and alarms
    /// 051-058 of the FANUC lathe manuals (docs/commands/drawing.md says which were verified).
    pub const FANUC_T: DrawingRules = DrawingRules {
        chamfer: b'c',
        round: b'r',
        chamfer_type: None,
        angle: b'a',
        angle_thousandths: false,
        angle_in_rapid: false,
        corner_needs_g01: true,
        any_plane: false,
        right_angle: true,
        plain_letters: None,
        source: "FANUC lathe manuals, direct drawing dimension programming (the forms from a secondary source; alarms 051-058, 212)",
    };

    /// The address is one of these words.
    pub fn takes(&self, letter: u8) -> bool {
        letter == self.chamfer || letter == self.round || letter == self.angle
    }
}

/// What radius compensation does in a block whose code suspends it (`GFn::suspends_compensation`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CompInCycle {
    /// The cycle's moves are the programmed ones; a canned cycle warns that they are.
    Suspended,
    /// The mode ends (G40 in effect): GSK980TDi help text, G40-G42 note 6, for G71-G73.
    Cancelled,
    /// The cycle offsets its own moves (FANUC roughing along the compensated shape, G90/G94 by
    /// the imaginary tool nose).
    OffsetByCycle,
}

impl FrameRules {
    /// What radius compensation does in a block of the code `f` (one that suspends it).
    pub fn compensation_in(&self, f: GFn) -> CompInCycle {
        match f {
            GFn::Rough(_) if self.rough_cancels_comp => CompInCycle::Cancelled,
            GFn::Rough(_) => CompInCycle::OffsetByCycle,
            GFn::BoxCycle(_) if self.box_by_tip => CompInCycle::OffsetByCycle,
            _ => CompInCycle::Suspended,
        }
    }

    pub const FANUC: FrameRules = FrameRules {
        coordinate_set_wins: false,
        reference_cancels_tool_offset: false,
        last_reference: 4,
        lathe_offset_keys: Some((ParamKey::Number(5002, Some(4)), ParamKey::Number(5002, Some(6)))),
        g10: G10Forms::LatheOffsets,
        parameter_entry: Some(ParamEntry { l: 50, value: b'R', read_into: None }),
        comp_lookahead: 1,
        comp_idle_alarm: None,
        polar_refuses_per_rev: false,
        drawing: None,
        rough_cancels_comp: false,
        box_by_tip: true,
        transform_keys: TransformKeys::NONE,
        corner_override: None,
        arc_without_centre: None,
        assumed_axes: "",
        assumed_spindle_p: &[],
        source: "FANUC 0i manuals as recalled (G30 P2-P4; G92 after G54 in one block sets the system selected; 5002#4 LGT, #6 LWM; G10 forms); docs/reference/macro.md 10",
    };
    pub const GSK: FrameRules = FrameRules {
        coordinate_set_wins: true,
        reference_cancels_tool_offset: true,
        last_reference: 4,
        lathe_offset_keys: Some((ParamKey::Setting("geometry_by_movement"), ParamKey::Setting("wear_with_next_move"))),
        g10: G10Forms::ToolLifeAndParameters,
        parameter_entry: Some(ParamEntry { l: 52, value: b'W', read_into: Some(b'R') }),
        comp_lookahead: 6,
        comp_idle_alarm: Some(7),
        polar_refuses_per_rev: true,
        drawing: Some(DrawingRules::GSK),
        rough_cancels_comp: true,
        box_by_tip: false,
        transform_keys: TransformKeys::NONE,
        corner_override: None,
        arc_without_centre: None,
        assumed_axes: "",
        assumed_spindle_p: &[],
        source: "GSK980TDi help text: G54-G59 note 6, G28 note 2, G30 (P2-P4) note 3, G10 L3 and L52 only; the offset mode's parameter number not found (an ncsight setting)",
    };
}

/// FANUC 0i-T 5002: how a lathe's tool offsets act (docs/reference/macro.md 10.1).
pub const FANUC_LATHE_OFFSETS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(5002, Some(4)),
        meaning: "LGT: 0 = the geometry offset shifts the coordinates (no motion); 1 = it moves the tool, as the wear offset does",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i-T parameter manual, 5002#4 LGT, as recalled (docs/reference/macro.md 10.1; inferred for the FANUC 0-T)",
    },
    ParamDef {
        key: ParamKey::Number(5002, Some(6)),
        meaning: "LWM: 0 = the offset's movement is made in the T block; 1 = together with the next axis move",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i-T parameter manual, 5002#6 LWM, as recalled (docs/reference/macro.md 10.1; inferred for the FANUC 0-T)",
    },
];

/// One of the two on/off settings of a lathe's tool offsets (an ncsight setting where the
/// parameter's number was not found).
const fn offset_bit(key: &'static str, meaning: &'static str, default: f64, source: &'static str) -> ParamDef {
    ParamDef { key: ParamKey::Setting(key), meaning, unit: "bit", min: 0.0, max: 1.0, default, source }
}

const WEAR_WITH_NEXT_MOVE: &str = "1 = the offset's movement is made with the next axis move; 0 = in the T block";

/// [`FANUC_LATHE_OFFSETS`] as ncsight settings, for the lathes whose parameter numbers were not
/// found: `geometry_by_movement` defaults to 1 (GSK's "tool traverse" mode, inferred).
pub const GSK_LATHE_OFFSETS: &[ParamDef] = &[
    offset_bit(
        "geometry_by_movement",
        "1 = the geometry offset moves the tool (GSK 'tool traverse'); 0 = it shifts the coordinates (GSK 'coordinate offset')",
        1.0,
        "ncsight setting; GSK980TD/TDi have both modes by a state parameter whose number was not found (docs/reference/macro.md 10.1), traverse assumed",
    ),
    offset_bit("wear_with_next_move", WEAR_WITH_NEXT_MOVE, 0.0, "ncsight setting; assumed (in the T block, as FANUC's default)"),
];

/// [`GSK_LATHE_OFFSETS`] with FANUC's defaults, for the YASNAC LX3 (no text at hand).
pub const YASNAC_LATHE_OFFSETS: &[ParamDef] = &[
    offset_bit(
        "geometry_by_movement",
        "1 = the geometry offset moves the tool; 0 = it shifts the coordinates",
        0.0,
        "ncsight setting; inferred as FANUC 5002#4 LGT's default (no YASNAC LX3 text at hand)",
    ),
    offset_bit("wear_with_next_move", WEAR_WITH_NEXT_MOVE, 0.0, "ncsight setting; inferred as FANUC 5002#6 LWM's default (no YASNAC LX3 text at hand)"),
];

/// Thread facts of a profile.
#[derive(Debug, Clone, Copy)]
pub struct ThreadRules {
    pub q_point: QPoint,
    /// Unit of Q in G32.2/G32.3, degrees per count: 1.0 on the GSK988T (seed 002's table),
    /// 0.001 on the GSK980TDi (help text).
    pub arc_q_unit_deg: f64,
    /// Parameter giving the pull-out's short-axis speed (GSK No.107), if the profile has one.
    pub pull_out_speed: Option<ParamKey>,
    /// Parameter giving the perpendicular pull-out speed after the end point (GSK988T 1466).
    pub after_end_feed: Option<ParamKey>,
    /// Parameter giving that pull-out's acceleration/deceleration time constant, ms (GSK988T
    /// 1628, seed 001 G32.1 note 5).
    pub pull_out_accel: Option<ParamKey>,
    /// Bit parameter that enables thread repair (GSK988T 8135.7 RPTH, GSK980TDi No.174 bit 4).
    pub repair_enable: Option<ParamKey>,
    /// G32 takes J and K (GSK) or not (FANUC).
    pub g32_pull_out: bool,
    /// G32 takes E as the lead, as F (YASNAC LX3, as its G92: seed 004; inferred for G32).
    pub g32_lead_e: bool,
    /// G76: the parameters its first block rewrites, with their units.
    pub g76: Option<G76Keys>,
    /// G34: the words of variable-lead thread cutting.
    pub g34: VariableLeadRules,
    /// G32.1: the words of rigid thread cutting.
    pub g32_1: RigidRules,
}

/// The words of G32.1 as a manual gives them.
#[derive(Debug, Clone, Copy)]
pub struct RigidRules {
    /// The start angle: Q in 0.001 degree (GSK988T manual, G32.1), or C, the spindle's position
    /// as a C axis in degrees (GSK980TDi help text, G32.1).
    pub start_c: bool,
    /// F < 0 is a left-hand thread, the spindle turning the other way (GSK980TDi help text).
    pub negative_f_left_hand: bool,
    /// I gives threads per inch (GSK980TDi: F(I)).
    pub lead_i: bool,
    /// K omitted or 0 with J: out along the short axis after the end point at the pull-out
    /// speed (GSK988T notes 3 and 5); otherwise K = J, as G32 (GSK980TDi, inferred).
    pub k_zero_after_end: bool,
}

/// G32.1 of the GSK988T manual (seed 001 section 2).
pub const G32_1_GSK988T: RigidRules = RigidRules { start_c: false, negative_f_left_hand: false, lead_i: false, k_zero_after_end: true };
/// G32.1 of the GSK980TDi help text: C the start angle, F(I) signed by the hand, J/K as G32.
pub const G32_1_GSK980TDI: RigidRules = RigidRules { start_c: true, negative_f_left_hand: true, lead_i: true, k_zero_after_end: false };

/// The words of G34 as a manual gives them.
#[derive(Debug, Clone, Copy)]
pub struct VariableLeadRules {
    /// The lead's change per revolution: R on the GSK lathes (GSK980TDi help text G34), K on the
    /// FANUC 0-T (its G34 X(U) Z(W) F(E) K).
    pub change: u8,
    /// J and K give a pull-out (GSK; ncsight ends the thread at its end point, with a warning).
    pub pull_out_words: bool,
    /// The largest change per revolution, mm (FANUC: ±500 mm/rev); None: no limit of its own.
    pub change_max_mm: Option<f64>,
    /// The alarm when the lead leaves its range (FANUC 014; a project code on the GSK).
    pub lead_rule: crate::alarm::Rule,
}

/// G34 on the GSK lathes: R, J/K (GSK980TDi help text G34; GSK988T manual 2.16.2).
pub const G34_GSK: VariableLeadRules = VariableLeadRules { change: b'R', pull_out_words: true, change_max_mm: None, lead_rule: crate::alarm::Rule::ThreadData };
/// G34 on the FANUC 0-T: K, ±0.0001 to ±500 mm/rev, alarm 014 (FANUC 0-TD programming notes;
/// docs/commands/g76.md).
pub const G34_FANUC: VariableLeadRules =
    VariableLeadRules { change: b'K', pull_out_words: false, change_max_mm: Some(500.0), lead_rule: crate::alarm::Rule::IllegalLead };

/// The parameters of G76 (GSK No.57/19/58/59/60; FANUC 5142/5130/5143/5140/5141).
#[derive(Debug, Clone, Copy)]
pub struct G76Keys {
    /// Number of finishing passes m.
    pub finishing: ParamKey,
    /// Pull-out r, 0.1 x lead.
    pub pull_out: ParamKey,
    /// Tool angle a, degrees.
    pub angle: ParamKey,
    /// Minimum cut, 0.001 mm.
    pub dmin_um: ParamKey,
    /// Finishing allowance, and the factor from its unit to mm.
    pub allowance: ParamKey,
    pub allowance_to_mm: f64,
    /// The pull-out angle (FANUC 5131; 0 = 45 degrees), if the profile has one.
    pub pull_out_angle: Option<ParamKey>,
}

/// G76's keys in FANUC 0i-T numbering (see [`FANUC_G76`]; 5130/5131 the pull-out and its angle).
pub(crate) const FANUC_G76_KEYS: G76Keys = G76Keys {
    finishing: ParamKey::Number(5142, None),
    pull_out: ParamKey::Number(5130, None),
    angle: ParamKey::Number(5143, None),
    dmin_um: ParamKey::Number(5140, None),
    allowance: ParamKey::Number(5141, None),
    allowance_to_mm: 0.001,
    pull_out_angle: Some(ParamKey::Number(5131, None)),
};

/// The G76 parameters in FANUC 0i-T numbering (minimum cut, finishing allowance, finishing
/// passes, tool angle), for the profiles that number their parameters as FANUC does.
pub(crate) const FANUC_G76: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(5140, None),
        meaning: "G76 minimum cut dmin",
        unit: "0.001 mm",
        min: 0.0,
        max: 999999.0,
        default: 100.0,
        source: "FANUC 0i-T numbering (docs/sources.md section 3; inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5141, None),
        meaning: "G76 finishing allowance d",
        unit: "0.001 mm",
        min: 0.0,
        max: 999999.0,
        default: 50.0,
        source: "FANUC 0i-T numbering (docs/sources.md section 3; inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5142, None),
        meaning: "G76 number of finishing passes m",
        unit: "passes",
        min: 1.0,
        max: 99.0,
        default: 1.0,
        source: "FANUC 0i-T numbering (docs/sources.md section 3; inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(5143, None),
        meaning: "G76 tool angle a",
        unit: "deg",
        min: 0.0,
        max: 99.0,
        default: 60.0,
        source: "FANUC 0i-T numbering (docs/sources.md section 3; inferred); default assumed",
    },
];

/// One G code of a profile.
#[derive(Debug, Clone, Copy)]
pub struct GDef {
    pub major: u32,
    /// The digit after the point for codes that have one (G32.1); `None` for plain codes.
    pub minor: Option<u32>,
    /// The code as the manual writes it: `G04`, `G32.1`.
    pub name: &'static str,
    pub group: Group,
    pub function: GFn,
    pub meaning: &'static str,
}

/// What an M code does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MFn {
    ProgramStop,
    OptionalStop,
    ProgramEnd,
    /// M99 in a main programme.
    SubprogramReturn,
    SubprogramCall,
    SpindleCw,
    SpindleCcw,
    SpindleStop,
    /// M06 on a machining centre.
    ToolChange,
    /// M14: servo spindle in position (CS) mode; M15: back to speed mode (seed 001).
    SpindlePositionMode,
    SpindleSpeedMode,
    /// Coolant, chuck, tailstock...: no motion, accepted.
    Auxiliary,
    /// M29 S_ on the GSK980TDi: rigid tapping mode for the G84/G88 that follows (help text
    /// G84/88).
    RigidTapping,
}

/// One table of a profile's codes and the manual (or the inference) it comes from.
#[derive(Debug, Clone, Copy)]
pub struct Codes<T: 'static> {
    pub source: &'static str,
    pub codes: &'static [T],
}

/// How far ncsight simulates a code (what `ncsight machines NAME` prints).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CodeStatus {
    /// Run as the controller runs it.
    Simulated,
    /// Run, with an assumption a warning names where the controller depends on something a
    /// simulation does not have (a skip signal).
    Assumed(&'static str),
    /// Known to the controller, not simulated: the alarm NCS-E38 "not simulated yet".
    NotYet,
}

/// What each function is, asked of the code (never of the controller) wherever the interpreter
/// treats a kind of command alike: a new cycle family answers here, beside its variant, and
/// the interpreter names it in one place only, its dispatch (`interp::one_shot` or
/// `modal_motion`; `crates/ncsight/tests/layers.rs` holds it).
impl GFn {
    /// Radius compensation acts on plain moves only: a block with a cycle, a thread, a reference
    /// return or a coordinate change runs uncompensated, and the compensated path ends before it
    /// (GSK980TDi help text, G40-G42 notes 5-6; FANUC threading likewise, inferred).
    pub fn suspends_compensation(self) -> bool {
        self.is_canned_cycle()
            || matches!(
                self,
                GFn::WorkOffset(_)
                    | GFn::AdditionalWorkOffset
                    | GFn::LocalCoordinates
                    | GFn::MachineCoordinates
                    | GFn::ReferenceReturn
                    | GFn::OtherReferenceReturn
                    | GFn::FromReference
                    | GFn::LatheCoordinateSet
                    | GFn::MillCoordinateSet
                    | GFn::DataSetting
                    | GFn::OffsetMove(_)
                    | GFn::ReferenceCheck
                    | GFn::Skip
                    | GFn::SingleDirection
                    | GFn::Thread(_)
                    | GFn::CompoundThread(_)
                    | GFn::Finish
                    | GFn::LengthComp(_)
            )
    }

    /// A canned cycle whose moves are the programmed ones when radius compensation is in force
    /// (the compensation is suspended in it, and a warning says so): the box, roughing, drilling
    /// and peck cycles.
    pub fn is_canned_cycle(self) -> bool {
        matches!(self, GFn::BoxCycle(_) | GFn::Rough(_) | GFn::Drill(_) | GFn::PeckCycle(_))
    }

    /// What a one-shot command is called in a message ("G74 (peck cutting cycle)").
    pub fn one_shot_title(self) -> Option<&'static str> {
        Some(match self {
            GFn::Dwell => "dwell",
            GFn::ReferenceReturn | GFn::OtherReferenceReturn => "reference return",
            GFn::FromReference => "return from the reference point",
            GFn::LocalCoordinates => "local coordinate system",
            GFn::DataSetting => "data setting",
            GFn::DataSettingEnd => "data setting end",
            GFn::CornerArc => "corner circular interpolation",
            GFn::OffsetMove(_) => "tool offset increase/decrease",
            GFn::ReferenceCheck => "reference point return check",
            GFn::Skip => "skip function",
            GFn::SingleDirection => "single direction positioning",
            GFn::MachineCoordinates => "positioning in machine coordinates",
            GFn::LatheCoordinateSet | GFn::MillCoordinateSet => "coordinate setting",
            GFn::CompoundThread(Compound::G76) => "compound threading",
            GFn::CompoundThread(Compound::G78) => "compound threading with infeed modes",
            GFn::PeckCycle(_) => "peck cutting cycle",
            GFn::Rough(_) => "roughing cycle",
            GFn::Finish => "finishing cycle",
            _ => return None,
        })
    }

    pub fn status(self) -> CodeStatus {
        match self {
            GFn::NotYet(_) => CodeStatus::NotYet,
            GFn::Skip => CodeStatus::Assumed("no skip signal comes: the move runs to its end (NCS-W34)"),
            GFn::ToolMeasure(_) => CodeStatus::Assumed("no measuring signal comes: the tool reaches the measuring position, the offset stays (NCS-W35)"),
            _ => CodeStatus::Simulated,
        }
    }
}

impl MFn {
    pub fn status(self) -> CodeStatus {
        match self {
            MFn::Auxiliary => CodeStatus::Assumed("a machine function with no motion of the tool: accepted, nothing moves and no record is made"),
            _ => CodeStatus::Simulated,
        }
    }
}

#[derive(Debug, Clone, Copy)]
pub struct MDef {
    pub code: u32,
    pub function: MFn,
    pub meaning: &'static str,
}

/// A parameter's identity: the manual's own number (with a bit for bit parameters), or, where
/// no manual number is known, an ncsight setting name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamKey {
    Number(u32, Option<u8>),
    Setting(&'static str),
}

impl std::fmt::Display for ParamKey {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParamKey::Number(n, None) => write!(f, "{n}"),
            ParamKey::Number(n, Some(b)) => write!(f, "{n}.{b}"),
            ParamKey::Setting(s) => write!(f, "{s}"),
        }
    }
}

impl ParamKey {
    /// The key as a manual's text says it: `No.19`, `No.174 bit 4`.
    pub fn spoken(&self) -> String {
        match self {
            ParamKey::Number(n, None) => format!("No.{n}"),
            ParamKey::Number(n, Some(b)) => format!("No.{n} bit {b}"),
            ParamKey::Setting(s) => s.to_string(),
        }
    }

    /// Parse `19`, `18.6`, `0018.6`, `8135.7` or a setting name.
    pub fn parse(text: &str) -> Option<ParamKey> {
        let t = text.trim();
        if t.is_empty() {
            return None;
        }
        if t.bytes().all(|c| c.is_ascii_digit() || c == b'.') {
            let mut it = t.splitn(2, '.');
            let n: u32 = it.next()?.parse().ok()?;
            let bit = match it.next() {
                Some(b) => Some(b.parse::<u8>().ok().filter(|b| *b < 8)?),
                None => None,
            };
            return Some(ParamKey::Number(n, bit));
        }
        None
    }
}

/// One parameter with the facts the manuals give. `source` says where the fact comes from and
/// whether it was read or inferred (docs/reference/parameters.md).
#[derive(Debug, Clone, Copy)]
pub struct ParamDef {
    pub key: ParamKey,
    pub meaning: &'static str,
    /// The unit the controller's parameter screen uses.
    pub unit: &'static str,
    pub min: f64,
    pub max: f64,
    pub default: f64,
    /// Manual reference, or "assumed" with the reason.
    pub source: &'static str,
}

impl ParamDef {
    /// The parameter screen takes a whole number: bits, counts, times in ms, angles in degrees
    /// and lengths in increments (0.001 mm, 0.1 x lead); only lengths in mm and rates in mm/min
    /// take decimals (FANUC's real-type parameters).
    pub fn whole(&self) -> bool {
        !matches!(self.unit, "mm" | "mm/min")
    }
}

/// Which parameters the time model reads. Rates are in mm/min.
#[derive(Debug, Clone, Copy)]
pub struct TimeKeys {
    /// Rapid traverse rate of X, Y, Z (the same key may serve several axes).
    pub rapid: [ParamKey; 3],
    /// Upper limit of the cutting feed.
    pub feed_max: ParamKey,
    /// Dry-run rate (GSK988T 1410, seed 001 G32.1 note 13).
    pub dry_run: ParamKey,
}

/// ncsight's own settings, on every profile: what the time model needs where no manual gave a
/// parameter number (docs/reference/parameters.md: acc/dec time constants were not found).
/// The rapid rate and feed ceiling under their FANUC numbers (1420, 1422), shared by the
/// profiles that use FANUC parameter numbering (fanuc0t; the GSK988T, whose manual numbers its
/// parameters the FANUC way).
pub const FANUC_RATES: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(1420, None),
        meaning: "rapid traverse rate (each axis)",
        unit: "mm/min",
        min: 1.0,
        max: 60000.0,
        default: 8000.0,
        source: "FANUC 0i numbering (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(1422, None),
        meaning: "upper limit of the cutting feed",
        unit: "mm/min",
        min: 1.0,
        max: 60000.0,
        default: 8000.0,
        source: "FANUC 0i numbering (inferred); default assumed",
    },
];

/// FANUC input format: 3401#0 DPI (docs/reference/parameters.md, FANUC: [inferred]).
pub const FANUC_INPUT: &[ParamDef] = &[ParamDef {
    key: ParamKey::Number(3401, Some(0)),
    meaning: "DPI: 1 = a length without a decimal point is in mm (inch), calculator-type input; 0 = in least input increments",
    unit: "bit",
    min: 0.0,
    max: 1.0,
    default: 0.0,
    source: "docs/sources.md, FANUC (inferred)",
}];

/// FANUC 0-M G60: the overrun of single direction positioning per axis, signed by the side the
/// axis approaches from (FANUC 0i 5440, per axis; ncsight settings, one per axis, 0 at power
/// on as the parameter's default).
pub const FANUC_G60: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Setting("g60_overrun_x_mm"),
        meaning: "G60: X comes to its end point from this far before it (signed: + from the minus side); 0 = straight there",
        unit: "mm",
        min: -100.0,
        max: 100.0,
        default: 0.0,
        source: "ncsight setting; FANUC 0i parameter 5440 for X (a machine builder's value: set it as the machine has it)",
    },
    ParamDef {
        key: ParamKey::Setting("g60_overrun_y_mm"),
        meaning: "G60: the same for Y",
        unit: "mm",
        min: -100.0,
        max: 100.0,
        default: 0.0,
        source: "ncsight setting; FANUC 0i parameter 5440 for Y",
    },
    ParamDef {
        key: ParamKey::Setting("g60_overrun_z_mm"),
        meaning: "G60: the same for Z",
        unit: "mm",
        min: -100.0,
        max: 100.0,
        default: 0.0,
        source: "ncsight setting; FANUC 0i parameter 5440 for Z",
    },
];

/// FANUC custom macro: 6000#5 SBM (docs/reference/macro.md section 6; FANUC 0i parameter manual, inferred for
/// the FANUC 0).
pub const FANUC_MACRO: &[ParamDef] = &[ParamDef {
    key: ParamKey::Number(6000, Some(5)),
    meaning: "SBM: 1 = single block stops after each macro statement (assignment, IF, GOTO, WHILE, END) too; 0 = only after NC blocks",
    unit: "bit",
    min: 0.0,
    max: 1.0,
    default: 0.0,
    source: "FANUC 0i parameter manual, 6000#5 SBM (inferred for the FANUC 0)",
}];

pub const SETTINGS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Setting("measure_approach_mm"),
        meaning: "G36/G37: the tool comes at rapid to this far before the measuring position, then at the measuring feed",
        unit: "mm",
        min: 0.0,
        max: 100.0,
        default: 5.0,
        source: "ncsight setting for FANUC 0i parameter 6254 (gamma; inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Setting("measure_feed_mm_min"),
        meaning: "G36/G37: the measuring feed",
        unit: "mm/min",
        min: 1.0,
        max: 10000.0,
        default: 100.0,
        source: "ncsight setting for FANUC 0i parameter 6241 (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Setting("stroke2_outside"),
        meaning: "G22's area: 0 = the tool may not enter it, 1 = it may not leave it",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "ncsight setting for FANUC 0i parameter 1300#0 (OUT) and GSK980TDi No.172 bit 2 (help text G22 note 2); inside forbidden assumed at power on",
    },
    ParamDef {
        key: ParamKey::Setting("tool_change_s"),
        meaning: "time a tool change takes (added to the cycle time at each change of tool number)",
        unit: "s",
        min: 0.0,
        max: 3600.0,
        default: 0.0,
        source: "ncsight setting (the setup's [machine] tool_change_s sets it); 0 assumed: the machine builder's figure",
    },
    ParamDef {
        key: ParamKey::Setting("rotary_rapid_deg_min"),
        meaning: "rapid rate of a rotary axis (A, B, C) the setup declares",
        unit: "deg/min",
        min: 1.0,
        max: 1000000.0,
        default: 10800.0,
        source: "ncsight setting; assumed (30 rpm; the FANUC per-axis rapid parameter 1420 of the rotary axis is the machine builder's)",
    },
    ParamDef {
        key: ParamKey::Setting("rapid_accel_ms"),
        meaning: "time to reach the rapid rate from a stop (linear acceleration), each axis",
        unit: "ms",
        min: 0.0,
        max: 5000.0,
        default: 100.0,
        source: "ncsight setting; assumed (the manuals' time constants were not found)",
    },
    ParamDef {
        key: ParamKey::Setting("feed_accel_ms"),
        meaning: "time to reach a cutting feed or a thread's speed from a stop (linear acceleration)",
        unit: "ms",
        min: 0.0,
        max: 5000.0,
        default: 50.0,
        source: "ncsight setting; assumed (the manuals' time constants were not found)",
    },
];

/// The dry-run rate where the profile's manual gives none.
pub const DRY_RUN_SETTING: ParamDef = ParamDef {
    key: ParamKey::Setting("dry_run_mm_min"),
    meaning: "dry-run rate: feeds and threads run at it in dry run",
    unit: "mm/min",
    min: 1.0,
    max: 60000.0,
    default: 5000.0,
    source: "ncsight setting; assumed (the parameter number was not found)",
};

/// [`DRY_RUN_SETTING`] as a table.
pub const DRY_RUN: &[ParamDef] = &[DRY_RUN_SETTING];

/// A controller profile.
#[derive(Debug, Clone)]
pub struct Profile {
    pub name: &'static str,
    pub title: &'static str,
    pub kind: MachineKind,
    /// X words are diameters (lathes).
    pub diameter_x: bool,
    /// Constant surface speed on a machining centre: the parameter naming the axis whose
    /// coordinate is the radius (FANUC 3770: 1 X, 2 Y, 3 Z); lathes take the X diameter.
    pub css_axis: Option<ParamKey>,
    pub integer_lengths: IntegerLengths,
    /// The parameter that makes a length without a decimal point millimetres (inches) instead
    /// (FANUC 3401#0 DPI, "calculator-type" input), if the profile knows one.
    pub calculator_input: Option<ParamKey>,
    pub alarm_style: AlarmStyle,
    /// `U`/`W` (and `V`) are incremental X/Z (Y) words: lathes with G-code system A.
    pub incremental_addresses: bool,
    /// Feed per revolution at power on (lathes: G98 on GSK per the TDi manual p179).
    pub power_on_per_rev: bool,
    /// Two G codes from group 00 and group 01 in one block is an alarm (GSK, TAC p65).
    pub group00_with_01_alarm: bool,
    /// A reference-point code (G27-G30) while a drilling canned cycle is in force is an alarm
    /// (FANUC alarm 0044, G27-G30 NOT ALLOWED IN FIXED CYC).
    pub reference_in_canned_cycle_alarm: bool,
    /// Axes the machine has, of "XYZ" (formatters omit the others).
    pub axes: &'static str,
    /// The reference point G28 returns to, in machine coordinates (mm, X as a radius), where the
    /// setup gives none: a documented assumption per profile (docs/setup.md).
    pub reference_point_mm: crate::motion::Vec3,
    /// Addresses the controller reads at all (anything else is IMPROPER NC-ADDRESS).
    pub addresses: Letters,
    /// The parameter with the power-on back-off e of the lathe peck cycles G74/G75 (one value
    /// for both; their first block rewrites it), if the profile knows it.
    pub peck_back_off: Option<ParamKey>,
    /// The address of G90/G94's taper (the cut start's offset from the end point): R on the
    /// FANUC 0-T and the GSKs; I on the YASNAC LX3 (its manual, G68 mirror image: "I command
    /// for canned cycle taper", and its G92).
    pub box_taper: u8,
    /// The G codes, table by table, each table with the manual it comes from.
    pub g_codes: &'static [Codes<GDef>],
    pub m_codes: &'static [Codes<MDef>],
    /// The manual's parameters, then ncsight's own settings ([`SETTINGS`]).
    pub params: &'static [&'static [ParamDef]],
    pub time: TimeKeys,
    pub thread: ThreadRules,
    pub drill: DrillRules,
    pub calls: CallRules,
    pub macros: MacroRules,
    pub frame: FrameRules,
    /// The G-code systems B and C a parameter selects (FANUC lathes: 3401#6 GSB, #7 GSC):
    /// the same profile with the codes renamed.
    pub g_code_systems: Option<&'static GCodeSystems>,
    /// One paragraph for `ncsight machines`.
    pub summary: &'static str,
}

/// A lathe's G-code systems B and C (FANUC): the bits that select them and the profiles with
/// their code tables (the same parameters, so the values carry over).
#[derive(Debug)]
pub struct GCodeSystems {
    pub b: ParamKey,
    pub c: ParamKey,
    pub profile_b: &'static Profile,
    pub profile_c: &'static Profile,
}

/// All profiles, in the order `ncsight machines` lists them.
pub fn all() -> [&'static Profile; 7] {
    [&gsk980tdi::PROFILE, &gsk988t::PROFILE, &fanuc0m::PROFILE, &yasnac_lx3::PROFILE, &fanuc0t::PROFILE, &fanuc0i::TF, &fanuc0i::MF]
}

/// The profile of that name.
pub fn by_name(name: &str) -> Option<&'static Profile> {
    all().into_iter().find(|p| p.name.eq_ignore_ascii_case(name))
}

impl Profile {
    /// Whether the profile's data hold together, so that a run never fails on a mistake in it:
    /// parameter defaults in range, no code twice, each code's name its numbers, every
    /// parameter a rule names defined, the drilling cycles' parameters where they are listed,
    /// the codes the interpreter names by function present. Every built-in profile passes (a
    /// test); a profile defined as data elsewhere should be checked with it first.
    pub fn validate(&'static self) -> Result<(), String> {
        let p = self;
        let fail = |msg: String| Err(format!("profile {}: {msg}", p.name));
        for d in p.all_params() {
            if !(d.min <= d.default && d.default <= d.max) || d.source.is_empty() || d.meaning.is_empty() {
                return fail(format!("parameter {}: default out of range, or no source or meaning", d.key));
            }
        }
        let all: Vec<&GDef> = p.g_defs().collect();
        for (i, g) in all.iter().enumerate() {
            if all[i + 1..].iter().any(|h| h.major == g.major && h.minor == g.minor) {
                return fail(format!("{} twice", g.name));
            }
            let want = match g.minor {
                Some(m) => format!("G{:02}.{m}", g.major),
                None => format!("G{:02}", g.major),
            };
            if g.name != want {
                return fail(format!("the code {want} is named {}", g.name));
            }
        }
        let mut keys: Vec<ParamKey> = Vec::new();
        for g in &all {
            if let GFn::Thread(ThreadCmd::Cycle(rules)) = g.function {
                match rules.pull_out {
                    PullOutRule::JkTenths(k) => keys.push(k),
                    PullOutRule::JkChamfer { amount, angle } | PullOutRule::Chamfer { amount, angle } => keys.extend([amount, angle]),
                    PullOutRule::None => {}
                }
                if let HoldRule::PullOutOrFinish(k) | HoldRule::ThreadUp(k) = rules.hold {
                    keys.push(k);
                }
                if rules.repair_p && p.thread.repair_enable.is_none() {
                    return fail(format!("{} repairs with P1 but the profile has no repair switch", g.name));
                }
            }
            if let GFn::CompoundThread(_) = g.function {
                match p.thread.g76 {
                    Some(k) => keys.extend([k.finishing, k.pull_out, k.angle, k.dmin_um, k.allowance].into_iter().chain(k.pull_out_angle)),
                    None => return fail(format!("{} without its parameters (ThreadRules.g76)", g.name)),
                }
            }
            if let GFn::Drill(kind) = g.function {
                use crate::codes::DrillKind;
                let d = p.drill;
                let missing = match kind {
                    DrillKind::G73 => d.g73_retract_um.map(|k| keys.push(k)).is_none(),
                    DrillKind::G83 => d.g83_clearance_um.map(|k| keys.push(k)).is_none(),
                    DrillKind::G76 | DrillKind::G87 => d.shift_bits.map(|(a, b)| keys.extend([a, b])).is_none(),
                    DrillKind::FaceFromR | DrillKind::SideFromR => match (d.lathe_peck_full_return, d.g73_retract_um, d.g83_clearance_um) {
                        (Some(a), Some(b), Some(c)) => {
                            keys.extend([a, b, c]);
                            false
                        }
                        _ => true,
                    },
                    _ => false,
                };
                if missing {
                    return fail(format!("{} without its parameters (DrillRules)", g.name));
                }
            }
        }
        let t = p.thread;
        keys.extend([t.pull_out_speed, t.after_end_feed, t.pull_out_accel, t.repair_enable].into_iter().flatten());
        keys.extend(p.time.rapid);
        keys.extend([p.time.feed_max, p.time.dry_run]);
        keys.extend(p.calculator_input);
        keys.extend(p.peck_back_off);
        keys.extend(p.calls.builder.keys());
        keys.extend(SETTINGS.iter().map(|d| d.key));
        if let Some(k) = keys.into_iter().find(|k| p.param(*k).is_none()) {
            return fail(format!("a rule names parameter {k}, which the profile does not define"));
        }
        for f in [GFn::Rapid, GFn::Linear, GFn::ArcCw, GFn::ArcCcw, GFn::PlaneXY, GFn::PlaneZX, GFn::PlaneYZ, GFn::Dwell, GFn::ReferenceReturn] {
            if !p.has(f) {
                return fail(format!("no code for {f:?}"));
            }
        }
        let ms: Vec<&MDef> = p.m_defs().collect();
        for (i, m) in ms.iter().enumerate() {
            if ms[i + 1..].iter().any(|n| n.code == m.code) {
                return fail(format!("M{} twice", m.code));
            }
        }
        let params = Params::defaults(p);
        if !((0..3).all(|a| params.rapid_mm_min(a) > 0.0) && params.feed_max_mm_min() > 0.0) {
            return fail("the rapid rates and the feed limit must be more than 0".into());
        }
        Ok(())
    }

    /// How far ncsight simulates `g` on this profile: the function's status, and for G10 the
    /// forms the profile has (the GSK980TDi's L3 tool life data are read and not kept).
    pub fn code_status(&self, g: &GDef) -> CodeStatus {
        match g.function {
            GFn::DataSetting if self.frame.g10 == G10Forms::ToolLifeAndParameters => {
                CodeStatus::Assumed("G10 L3's tool life data are read and not kept: ncsight does not count tool life")
            }
            f => f.status(),
        }
    }

    /// Every G code of the profile, in table order.
    pub fn g_defs(&self) -> impl Iterator<Item = &'static GDef> + '_ {
        self.g_codes.iter().flat_map(|t| t.codes.iter())
    }

    /// Every M code of the profile, in table order.
    pub fn m_defs(&self) -> impl Iterator<Item = &'static MDef> + '_ {
        self.m_codes.iter().flat_map(|t| t.codes.iter())
    }

    /// Whether a G code of the profile does `f`.
    pub fn has(&self, f: GFn) -> bool {
        self.g_defs().any(|g| g.function == f)
    }

    pub fn g_code(&self, major: u32, minor: Option<u32>) -> Option<&'static GDef> {
        self.g_defs().find(|g| g.major == major && g.minor == minor)
    }

    /// The name of the code that does `f` (`G01` for linear interpolation), from the profile's
    /// table; `?` if the profile has none (a mistake in a table, caught by the profile tests).
    pub fn name_of(&self, f: GFn) -> &'static str {
        self.g_defs().find(|g| g.function == f).map_or("?", |g| g.name)
    }

    pub fn m_code(&self, code: u32) -> Option<&'static MDef> {
        self.m_defs().find(|m| m.code == code)
    }

    /// The parameters a manual's number names: one value, or its bits (key, bit).
    pub fn params_numbered(&self, number: u32) -> Vec<(ParamKey, Option<u8>)> {
        self.params
            .iter()
            .flat_map(|t| t.iter())
            .filter_map(|d| match d.key {
                ParamKey::Number(n, bit) if n == number => Some((d.key, bit)),
                _ => None,
            })
            .collect()
    }

    pub fn param(&self, key: ParamKey) -> Option<(usize, &'static ParamDef)> {
        // Plain loops: this runs for every parameter read of every block.
        let mut i = 0;
        for table in self.params {
            for p in table.iter() {
                if p.key == key {
                    return Some((i, p));
                }
                i += 1;
            }
        }
        None
    }

    /// Every parameter and setting, in order.
    pub fn all_params(&self) -> impl Iterator<Item = &'static ParamDef> + '_ {
        self.params.iter().flat_map(|t| t.iter())
    }

    pub fn takes_address(&self, letter: u8) -> bool {
        if letter.is_ascii_lowercase() {
            // A comma word (`,A`): the drawing's words only.
            return self.frame.drawing.is_some_and(|d| d.takes(letter));
        }
        self.addresses.contains(letter)
    }

    pub fn is_lathe(&self) -> bool {
        self.kind == MachineKind::Lathe
    }
}

/// A set of address letters A-Z, looked up once per word of every block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Letters(u32);

impl Letters {
    /// The letters of `s` (upper-case A-Z; anything else is a mistake in a profile table).
    pub const fn new(s: &str) -> Letters {
        let b = s.as_bytes();
        let mut mask = 0u32;
        let mut i = 0;
        while i < b.len() {
            assert!(b[i].is_ascii_uppercase(), "address letters are A-Z");
            mask |= 1 << (b[i] - b'A');
            i += 1;
        }
        Letters(mask)
    }

    /// These letters and `letter` (upper-case A-Z).
    pub const fn with(self, letter: u8) -> Letters {
        assert!(letter.is_ascii_uppercase(), "address letters are A-Z");
        Letters(self.0 | 1 << (letter - b'A'))
    }

    /// No letter.
    pub const EMPTY: Letters = Letters(0);

    pub fn contains(self, letter: u8) -> bool {
        letter.is_ascii_uppercase() && self.0 & (1 << (letter - b'A')) != 0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The letters in alphabetical order.
    pub fn iter(self) -> impl Iterator<Item = char> {
        (b'A'..=b'Z').filter(move |&c| self.contains(c)).map(char::from)
    }
}

/// Parameter values in force for one run: the profile's defaults, overridden by `--param`.
#[derive(Debug, Clone)]
pub struct Params {
    /// The profile in force: `base`, or its G-code system B or C as the parameters select.
    profile: &'static Profile,
    base: &'static Profile,
    values: Vec<f64>,
    /// The feed limit, read by every cutting block: kept up to date by `set`.
    feed_max_mm_min: f64,
    /// How lengths without a decimal point read (the profile's rule, or calculator-type input
    /// when its parameter is set): kept up to date by `set`.
    integer_lengths: IntegerLengths,
}

/// Why a `--param` could not be taken.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamError {
    Syntax(String),
    NotFinite(String),
    NotWhole { key: String, value: f64, unit: &'static str },
    Unknown(String),
    OutOfRange { key: String, value: f64, min: f64, max: f64, unit: &'static str },
}

impl std::fmt::Display for ParamError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParamError::Syntax(s) => write!(f, "--param {s}: expected N=V, N.B=V or NAME=V"),
            ParamError::NotFinite(s) => write!(f, "--param {s}: the value is not a finite number"),
            ParamError::NotWhole { key, value, unit } => write!(f, "parameter {key} = {value}: the parameter takes a whole number ({unit})"),
            ParamError::Unknown(s) => write!(f, "parameter {s} does not exist on this profile (see `ncsight machines`)"),
            ParamError::OutOfRange { key, value, min, max, unit } => {
                write!(f, "parameter {key} = {value} is out of range {min}..{max} {unit}")
            }
        }
    }
}

impl std::error::Error for ParamError {}

impl Params {
    pub fn defaults(profile: &'static Profile) -> Params {
        let mut params = Params {
            profile,
            base: profile,
            values: profile.all_params().map(|p| p.default).collect(),
            feed_max_mm_min: 0.0,
            integer_lengths: profile.integer_lengths,
        };
        params.cache();
        params
    }

    pub fn profile(&self) -> &'static Profile {
        self.profile
    }

    /// The profile the parameters were made for (its G-code system A where it has B and C).
    pub fn base(&self) -> &'static Profile {
        self.base
    }

    /// Apply `N=V` (`19=10`, `18.6=1`, `rapid_mm_min=12000`).
    pub fn set_text(&mut self, assignment: &str) -> Result<(), ParamError> {
        let (k, v) = assignment.split_once('=').ok_or_else(|| ParamError::Syntax(assignment.into()))?;
        let value: f64 = v.trim().parse().map_err(|_| ParamError::Syntax(assignment.into()))?;
        if !value.is_finite() {
            return Err(ParamError::NotFinite(assignment.into()));
        }
        let key = match ParamKey::parse(k) {
            Some(key) => key,
            None => match self.profile.all_params().find(|p| matches!(p.key, ParamKey::Setting(s) if s == k.trim())) {
                Some(p) => p.key,
                None => return Err(ParamError::Unknown(k.trim().into())),
            },
        };
        self.set(key, value)
    }

    pub fn set(&mut self, key: ParamKey, value: f64) -> Result<(), ParamError> {
        let i = self.check(key, value)?;
        self.values[i] = value;
        self.cache();
        Ok(())
    }

    /// Whether `value` may be set for `key`: its index when it may.
    pub fn check(&self, key: ParamKey, value: f64) -> Result<usize, ParamError> {
        let (i, def) = self.profile.param(key).ok_or_else(|| ParamError::Unknown(key.to_string()))?;
        if value < def.min || value > def.max {
            return Err(ParamError::OutOfRange { key: key.to_string(), value, min: def.min, max: def.max, unit: def.unit });
        }
        if def.whole() && value.fract() != 0.0 {
            return Err(ParamError::NotWhole { key: key.to_string(), value, unit: def.unit });
        }
        Ok(i)
    }

    /// Refresh the values kept for the blocks that read them all the time.
    fn cache(&mut self) {
        // G-code system B or C (FANUC 3401#6 GSB, #7 GSC; C when both): the same parameters.
        if let Some(sys) = self.base.g_code_systems {
            self.profile = self.base;
            self.profile = if self.get(sys.c) != 0.0 {
                sys.profile_c
            } else if self.get(sys.b) != 0.0 {
                sys.profile_b
            } else {
                self.base
            };
        }
        self.feed_max_mm_min = self.get(self.profile.time.feed_max);
        self.integer_lengths = match self.profile.calculator_input {
            Some(k) if self.get(k) != 0.0 => IntegerLengths::Millimetres,
            _ => self.profile.integer_lengths,
        };
    }

    /// How a length without a decimal point reads under these parameters.
    pub fn integer_lengths(&self) -> IntegerLengths {
        self.integer_lengths
    }

    /// The value of a parameter the profile defines. Asking for one it lacks is a programming
    /// error in a profile table, caught by the profile tests.
    pub fn get(&self, key: ParamKey) -> f64 {
        match self.profile.param(key) {
            Some((i, _)) => self.values[i],
            None => panic!("profile {} has no parameter {key}", self.profile.name),
        }
    }

    /// Rapid traverse rate of axis 0..3 (X, Y, Z), mm/min.
    pub fn rapid_mm_min(&self, axis: usize) -> f64 {
        self.get(self.profile.time.rapid[axis])
    }

    pub fn feed_max_mm_min(&self) -> f64 {
        self.feed_max_mm_min
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_profile_is_consistent() {
        for p in all() {
            if let Err(e) = p.validate() {
                panic!("{e}");
            }
            assert!(by_name(p.name).is_some());
        }
    }

    #[test]
    fn settings_by_name() {
        let mut ps = Params::defaults(by_name("fanuc0m").unwrap());
        ps.set_text("rapid_accel_ms=250").unwrap();
        assert_eq!(ps.get(ParamKey::Setting("rapid_accel_ms")), 250.0);
        ps.set_text("dry_run_mm_min=1000").unwrap();
        let mut ps = Params::defaults(by_name("gsk988t").unwrap());
        assert!(ps.set_text("dry_run_mm_min=1000").is_err()); // the GSK988T has No.1410
    }

    #[test]
    fn param_syntax() {
        let mut ps = Params::defaults(by_name("gsk980tdi").unwrap());
        ps.set_text("19=10").unwrap();
        assert_eq!(ps.get(ParamKey::Number(19, None)), 10.0);
        ps.set_text("18.6=1").unwrap();
        assert!(matches!(ps.set_text("18.6=2"), Err(ParamError::OutOfRange { .. })));
        assert!(matches!(ps.set_text("9999=1"), Err(ParamError::Unknown(_))));
        assert!(matches!(ps.set_text("19"), Err(ParamError::Syntax(_))));
        // Issue 15: an overflowing number is "not finite", a fraction of a whole-number parameter
        // is refused.
        assert!(matches!(ps.set_text("19=1e309"), Err(ParamError::NotFinite(_))));
        assert!(matches!(ps.set_text("19=0.5"), Err(ParamError::NotWhole { .. })));
        ps.set_text("19=5").unwrap();
    }
}
