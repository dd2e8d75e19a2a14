//! The rules a profile gives where controllers differ: the thread cycles (`CycleRules`,
//! `ThreadRules`), drilling, calls and macros, the frame and compensation (`FrameRules`), the
//! drawing dimensions. The interpreter asks them; it never asks which controller it is.

use super::*;
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
