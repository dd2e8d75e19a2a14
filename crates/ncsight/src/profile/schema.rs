//! The vocabulary of a profile: machine kinds, modal groups, the G and M functions a code can
//! have (`GFn`, `MFn`) and what the interpreter asks of each, the code tables' entries.

use super::*;
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

/// The curves cut besides the circle: the GSK980TDi's (help text G05/G05.1, G6.2/G6.3, G7.2/G7.3)
/// and FANUC's involute (G02.2/G03.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Curve {
    /// G05: the arc through a middle point I/K from the start; G05.1: I/K the middle point's
    /// absolute coordinates.
    ThreePoint { mid_absolute: bool },
    /// G6.2 (`Cw`, as G02) / G6.3: an ellipse of half axes A and B, its long axis at Q.
    Ellipse(crate::motion::ArcDir),
    /// G7.2 (`Cw`) / G7.3: the parabola Y² = 2PX, its axis at Q.
    Parabola(crate::motion::ArcDir),
    /// FANUC G02.2 (`Cw`) / G03.2: the involute of the base circle of radius R whose centre
    /// I/J/K gives from the start point (`interp/involute.rs`).
    Involute(crate::motion::ArcDir),
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
