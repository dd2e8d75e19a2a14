//! The modal state a controller carries from block to block, split by owner (the modes, the
//! tool's place, the notes only warnings read, the cycles' memories, the frame, compensation,
//! threading, drilling). A block changes the parts it must, each saved the first time ([`Kept`]),
//! and an alarm puts those back: no block copies the whole state.

use crate::cycles::thread::Pass;
use crate::motion::{Op, Plane, Vec3};
use crate::profile::{MachineKind, Profile, ThreadCmd};
use crate::source::Span;

/// Group 01 motion in force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Motion {
    Rapid,
    Linear,
    ArcCw,
    ArcCcw,
    /// A thread command (G32, G32.1, G92, G92.1, G32.2/G32.3) is the group 01 mode.
    Thread(ThreadCmd),
    /// G90 / G94 single turning or facing cycle is the group 01 mode.
    Box(crate::cycles::turning::BoxKind),
    /// G05/G05.1, G6.2/G6.3, G7.2/G7.3 (GSK980TDi).
    Curve(crate::profile::Curve),
}

/// The last block of a run of continuous thread blocks, held back until the next block shows
/// whether the run goes on (then no pull-out and no wait for the one-revolution signal) or
/// ends (then the pull-out in force is made). Seed 001 G32.1 note 1; TDi help G32 notes 1-2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PendingThread {
    pub span: Span,
    pub n: Option<u32>,
    pub body: PendingBody,
    /// A block that gave J/K itself ends the run (seed 001 G32.1 note 1).
    pub ends_run: bool,
    /// Rigid (G32.1) runs and encoder-following (G32, G32.2/G32.3) runs do not mix.
    pub rigid: bool,
    /// Spindle angle at the end of the block when it continues without a pull-out.
    pub end_deg: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PendingBody {
    /// A straight pass; its pull-out is made only if the run ends here.
    Straight(Pass),
    /// An arc thread (no pull-out).
    Arc(Op),
}

/// What the warnings about repeated passes compare (issue 3, "passes will not line up").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PassMemory {
    pub lead_mm: f64,
    /// Long-axis coordinate where the passes start.
    pub long_start: f64,
    pub rpm: f64,
    pub start_deg: f64,
    /// Short-axis coordinate of the last cut.
    pub depth: f64,
    /// Infeed from the pass before the last to the last.
    pub last_infeed: Option<f64>,
}

/// G76's data from its first block (or the parameters): finishing passes m, pull-out r in
/// 0.1 x lead, tool angle a, minimum cut, finishing allowance, and the GSK's J/K.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct G76Data {
    pub finishing: u32,
    pub pull_out_tenths: f64,
    pub angle_deg: f64,
    pub dmin_mm: f64,
    pub allowance_mm: f64,
    pub j: Option<f64>,
    pub k: Option<f64>,
}

/// What the first G78 block sets beyond the G76 data (GSK980TDi help text, G78).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct G78Data {
    pub base: G76Data,
    pub schedule: crate::cycles::thread::compound::Schedule,
    pub infeed: crate::cycles::thread::compound::Infeed,
    /// L: number of starts.
    pub starts: u32,
}

/// What the blocks after a G90/G94 block repeat: its end point and taper, kept while the cycle
/// is the group 01 mode (X, Z and R are modal in these cycles; ncsight follows the FANUC
/// reading, the GSK help text calls the codes modal without listing the words).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BoxMemory {
    pub end: Option<Vec3>,
    pub taper_mm: f64,
}

/// Thread words and memories that last from block to block.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThreadState {
    /// The last lead was written with a negative F (a left-hand thread, GSK980TDi G92.1 and
    /// G32.1): a later block that takes the lead from memory is left-hand too.
    pub left_hand: bool,
    /// Lead in force (F, I or E of a thread block), mm.
    pub lead_mm: Option<f64>,
    /// J and K in force, as written (mm): modal, cancelled by a non-thread group 01 code.
    pub j: Option<f64>,
    pub k: Option<f64>,
    /// Number of starts L in force (seed 000: modal, 1 when omitted).
    pub starts: u32,
    /// The cycle's end point C and taper, kept for continuation blocks that give only X (U).
    pub cycle_end: Option<Vec3>,
    pub taper_mm: f64,
    /// S of a rigid thread command, signed (seed 001: the sign selects the direction).
    pub rigid_rpm: Option<f64>,
    /// Held inline, as are the other rarely-set parts: the modal state is a plain `Copy` value,
    /// each part saved by value when a block first changes it (`Kept`), which is cheaper than
    /// cloning boxes.
    pub pending: Option<PendingThread>,
    pub memory: Option<PassMemory>,
    /// Four-step cycles started so far (each start of each block), to tell them apart.
    pub cycles: u32,
    /// G92 P1 / G92.1 P1 repair in force (P1 in the first block is enough: help note 4).
    pub repair: bool,
    /// G76 data set by its first block for the rest of the run (it rewrites the parameters).
    pub g76: Option<G76Data>,
    /// G78 data set by its first block (GSK980TDi), kept apart from G76's.
    pub g78: Option<G78Data>,
}

/// Hole data that stays from block to block while a drilling cycle is in force (seed 003): the
/// values as written, with the distance mode they were written in. G80 and every group 01 code
/// clear it (F is kept elsewhere).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DrillData {
    pub kind: Option<crate::cycles::drill::DrillKind>,
    /// Drilling-axis level of the tool when the cycle mode was entered.
    pub initial: f64,
    /// The drilling-axis word (Z in G17) and R as written, mm, and whether under G91.
    pub bottom: Option<(f64, bool)>,
    pub r: Option<(f64, bool)>,
    pub q: Option<f64>,
    pub dwell_s: Option<f64>,
    /// GSK lathe G83/G87 J1: the deep-hole cycle.
    pub deep: bool,
    /// M29 given: rigid tapping mode for G84/G88 (GSK980TDi).
    pub rigid_tap: bool,
    /// M29 given and no G84/G88 block run since: no axis may move (help text G84/88).
    pub tap_waiting: bool,
    /// G84/G88 with a negative F: a left-hand thread.
    pub tap_left: bool,
}

/// The programme coordinate transforms in force (FANUC 0-M G16, G51.1, G51, G68;
/// `interp/transform.rs`). Centres are in programmed coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Transforms {
    /// G16: a block's two plane words are a radius and an angle.
    pub polar: bool,
    /// The last radius (mm) and angle (degrees) of the polar coordinates.
    pub polar_radius: f64,
    pub polar_angle_deg: f64,
    /// G51.1: the axes mirrored (bit 0 X, 1 Y, 2 Z), each about its coordinate in `mirror_at`.
    pub mirror_axes: u8,
    pub mirror_at: Vec3,
    pub scaling: Option<Scaling>,
    pub rotation: Option<Rotation>,
}

/// G22's area: a box in machine coordinates (an axis G22 did not bound is unbounded), the
/// tool forbidden inside it, or outside it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrokeArea {
    pub lo: Vec3,
    pub hi: Vec3,
    pub outside: bool,
}

/// G51: magnification per axis about a centre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scaling {
    pub centre: Vec3,
    pub factor: [f64; 3],
}

/// G68: rotation in a plane about a centre, counter-clockwise positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation {
    pub plane: crate::motion::Plane,
    pub centre: Vec3,
    pub angle_deg: f64,
}

/// Where programme coordinates lie on the machine, as far as the modal state says: the work
/// system selected, the G50/G92 shift (acting on every work system), the G52 local origin and
/// the tool offset in effect. The offsets' values are the machine's tables (`interp::Tables`):
/// machine = programme + external + work + shift + local + tool.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Frame {
    /// 1-6: G54-G59.
    pub work: u8,
    pub shift: Vec3,
    pub local: Vec3,
    /// The tool offset applied to the position: a lathe's geometry and wear (T), a mill's tool
    /// length (G43/G44 H) in `geometry`.
    pub geometry: Vec3,
    pub wear: Vec3,
    /// The part of a tool offset not moved out yet (a lathe's offset by movement with the next
    /// move, FANUC 5002#6 LWM): the display reads the position plus this until the next move.
    pub unmoved: Vec3,
    /// The offset number in force (a lathe's T0102 -> 2; a mill's H), 0: none.
    pub offset_number: u32,
    /// G43 (+1), G44 (-1), G49 (0).
    pub length_sign: i8,
}

impl Frame {
    /// The tool offset applied.
    pub fn tool(&self) -> Vec3 {
        self.geometry + self.wear
    }
}

/// Tool radius compensation in force (docs/reference/macro.md 10.3; docs/compensation.md). The move held
/// back until the next one shows its corner is in the interpreter's queue; this is its scalar
/// part.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CompState {
    /// +1 G41 (the tool left of the path), -1 G42, 0 G40.
    pub side: i8,
    pub radius_mm: f64,
    /// From the nose centre to the point the controller positions (the imaginary tool nose:
    /// R times the tip's direction; 0 on a mill and for tips 0 and 9).
    pub tip: Vec3,
    /// The D in force (mills): its offset's radius.
    pub d: u32,
    /// A D given in compensation without G41/G42: it takes effect at the end of its block (the
    /// block's move starts on the old radius's vector and ends on the new one's).
    pub next_d: Option<u32>,
    /// A compensated move has been made since G41/G42: a move that starts the path again (after
    /// a block compensation does not act in) may be an arc, joined by a straight move; before
    /// that, an arc is alarm 034.
    pub started: bool,
    /// The held move starts its compensated path here (nose centre).
    pub held_start: Vec3,
    /// The held move is the start-up (its end is perpendicular to the next move: type A).
    pub held_startup: bool,
    /// Where the nose centre is when it is not on the programmed point (after a move that ended
    /// perpendicular): the next move starts there.
    pub actual: Option<Vec3>,
    /// Blocks run since the held move without a move in the plane.
    pub idle_blocks: u8,
    /// G39 came after the held move: the outer corner to the next move is an arc about the
    /// corner point.
    pub round_corner: bool,
    /// The path goes on from `actual` (after G39 with a direction): the next move is not a
    /// start-up.
    pub resume: bool,
    /// G62 (automatic corner override) is the path mode.
    pub corner_override: bool,
    /// The held move starts after an inner corner under G62: this much of it runs at the
    /// overridden feed.
    pub slow_start_mm: f64,
    /// A chamfer or corner arc this block asks for at the end of its move (GSK980TDi L, D).
    pub corner_for_next: Option<CornerRequest>,
    /// The one asked for at the end of the move held in the corner stage.
    pub held_corner: Option<CornerRequest>,
    /// Where the move held in the corner stage starts (the end of the chamfer before it, if one
    /// was made).
    pub corner_start: Vec3,
    /// A line given by its angle alone, held in the queue until the next block's line shows
    /// where it ends.
    pub angle_line: Option<AngleLine>,
}

/// A G01 (or G00) line given by its angle alone (FANUC `,A1`; GSK `Q`): it ends where it meets
/// the next block's line, which gives its end point and its angle (GSK980TDi help text, angle
/// programming note 6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleLine {
    pub angle_deg: f64,
    /// Where it starts (programme coordinates).
    pub from: Vec3,
    /// The block that gave it.
    pub span: crate::source::Span,
    /// Blocks without a move since (a G04, an M, S or T block: at most one, note 7).
    pub between: u8,
}

/// A chamfer or a corner arc between a block's move and the next (GSK980TDi help text, chamfer
/// function: L, D; FANUC 0-T: ,C ,R).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CornerRequest {
    /// The address that asked (as the reader stores it: `b'c'` for `,C`).
    pub letter: u8,
    /// The chamfer's size, or the corner arc's radius, mm.
    pub size_mm: f64,
    /// D: a corner arc; else a chamfer.
    pub round: bool,
    /// A chamfer's L is the distance from the corner to each end (type II, No.181.0 = 1);
    /// else the chamfer's length (type I).
    pub from_corner: bool,
    /// The block that asked.
    pub span: crate::source::Span,
    /// FANUC's chamfer or corner R between two moves at a right angle (I, K, R in G01): the
    /// next move's axis and way.
    pub right_angle: Option<RightAngle>,
}

/// The next move of a right-angle chamfer or corner R: along the plane's second axis (X in
/// G18: after I, or R after a move along Z) or its first, the way the word's sign gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RightAngle {
    pub next_along_second: bool,
    /// +1 or -1.
    pub sign: f64,
}

impl CornerRequest {
    /// The word that asked, as a message names it.
    pub fn word(&self) -> String {
        format!("{} ({})", crate::read::address_name(self.letter), if self.round { "corner arc" } else { "chamfer" })
    }
}

/// Spindle rotation commanded by M03/M04/M05.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpindleDir {
    Stopped,
    /// M03: the spindle's positive direction.
    Positive,
    /// M04.
    Negative,
}

/// The modes: what each modal group commands, with the words a later block reads again (F, S, T).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Modes {
    pub motion: Motion,
    pub plane: Plane,
    /// G91 on mills. Lathes use U/W instead and keep this false.
    pub incremental: bool,
    /// G20.
    pub inch: bool,
    /// G99 (lathe) / G95 (mill): feed per revolution.
    pub per_rev: bool,
    /// G96.
    pub css: bool,
    pub spindle: SpindleDir,
    /// Last S word: rpm (G97) or m/min (G96).
    pub s_word: f64,
    /// Several spindles (the setup's `spindle_p`): the one selected (an index into it), and
    /// the direction and S word each keeps while another is selected.
    pub spindle_sel: u8,
    pub spindles: [(SpindleDir, f64); crate::setup::MAX_SPINDLES],
    /// G50 S: the spindle speed clamp, rpm.
    pub rpm_clamp: Option<f64>,
    /// M14 (position / CS mode) on servo-spindle lathes.
    pub spindle_position_mode: bool,
    /// Last F word converted to mm (per minute or per revolution by `per_rev`).
    pub feed: Option<f64>,
    /// Tool in the spindle / turret.
    pub tool: u32,
    /// G98 (return to the initial level) on mills.
    pub return_initial: bool,
    /// M02/M30 reached.
    pub ended: bool,
    /// Between `G10 L3` / `G10 L50` (`L52`) and `G11`, the lines are data, not motion.
    pub data_input: Option<DataInput>,
    /// G63 tapping mode in force (group 15).
    pub tapping_mode: bool,
    /// G12.1 polar coordinate interpolation in force.
    pub polar_interp: Option<PolarInterp>,
}

/// Where the tool stands, in the programme's coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Place {
    /// Current position, programme coordinates, mm, X as a radius.
    pub pos: Vec3,
    /// Where the rotary axes A, B, C stand, degrees (those the setup declares; no offsets).
    pub rotary_deg: [f64; 3],
    /// The intermediate point of the last G28 or G30, per axis it named, in the coordinates the
    /// programme gave it (G29 goes through it; a coordinate change shifts it with the system).
    pub reference_mid: [Option<f64>; 3],
}

/// What only warnings and the macro variables #4001-#4120 read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Notes {
    /// The feed mode (per revolution or not) an implausibility warning was given in: one hint
    /// ("G99 was probably meant") per programme and mode, not one per F value.
    pub feed_warned: Option<bool>,
    /// What was assumed without a setup and warned at its first word: the axes (a turning
    /// centre's C and Y) by their letters, the spindle selection P by P.
    pub assumed_warned: crate::profile::Letters,
    /// The last code commanded in each modal group since power on, ten times its number
    /// (G41 -> 410, G32.1 -> 321; 0: none yet), indexed by `Group as usize`: what #4001-#4022
    /// read for the groups ncsight accepts without modelling (G43/G49, G54-G59, G61/G64, the
    /// side of G41/G42).
    pub group_codes: [u16; crate::profile::Group::COUNT],
    /// The last B, D, E, H and M words (#4102, #4107, #4108, #4111, #4113).
    pub last_words: LastWords,
}

/// What the lathe's cycles keep from their first blocks for the blocks that follow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleMemories {
    /// G71 / G72 depth of cut and back-off from their first blocks (index 0 G71, 1 G72).
    pub rough_data: [Option<(f64, f64)>; 2],
    /// G73 relief Δi (radius), Δk and number of passes d from its first block.
    pub pattern_data: Option<(f64, f64, u32)>,
    /// G74 / G75 back-off e set by a first block (one value for both, as the parameter).
    pub peck_back_off_mm: Option<f64>,
    /// G90/G94 end point and taper of the last cycle block, for the blocks that repeat it.
    pub box_cycle: BoxMemory,
}

/// The modal state a controller carries from block to block, split by owner. Each part is
/// [`Kept`]: a block that changes a part saves it first, so a block that alarms puts back what it
/// changed ([`Modal::roll_back`]) and no block copies the whole state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Modal {
    pub modes: Kept<Modes>,
    pub place: Kept<Place>,
    pub notes: Kept<Notes>,
    pub memory: Kept<CycleMemories>,
    /// Polar coordinates, mirror image, scaling and rotation in force.
    pub transform: Kept<Transforms>,
    /// G22: the stored stroke check 2 area in force, machine coordinates (X a radius).
    pub stroke2: Kept<Option<StrokeArea>>,
    /// Where those coordinates are on the machine.
    pub frame: Kept<Frame>,
    /// Tool radius compensation (G40/G41/G42) and its held-back move.
    pub comp: Kept<CompState>,
    pub thread: Kept<ThreadState>,
    pub drill: Kept<DrillData>,
}

/// G12.1 or G07.1 in force: the plane and the machine's Y before it (the plane's Y is the
/// hypothetical C meanwhile; interp/polar.rs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PolarInterp {
    pub kind: Hypothetical,
    pub plane_before: Plane,
    pub y_before: f64,
}

/// What the hypothetical C of the plane is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Hypothetical {
    /// G12.1: Cartesian with X on the face; the machine's C is the angle of (x, c).
    Polar,
    /// G07.1: the cylinder of `radius_mm` unrolled; the plane's Y is `sign` times the arc length
    /// of C (the sign keeps the programme's plane turning the way it turned).
    Cylinder { radius_mm: f64, sign: f64 },
}

/// What the lines between G10 and G11 are.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DataInput {
    /// GSK980TDi `G10 L3`: tool life management data (read, not kept).
    ToolLife,
    /// `G10 L50` (FANUC) or `G10 L52` (GSK): one parameter a line.
    Parameters(crate::profile::ParamEntry),
}

/// Words a macro reads back as modal information (FANUC #4102-#4113).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LastWords {
    pub b: Option<f64>,
    pub d: Option<f64>,
    pub e: Option<f64>,
    pub h: Option<f64>,
    pub m: Option<f64>,
}

impl Modal {
    /// Power-on state of a profile.
    pub fn power_on(profile: &Profile) -> Modal {
        let modes = Modes {
            motion: Motion::Rapid,
            plane: if profile.kind == MachineKind::Lathe { Plane::ZX } else { Plane::XY },
            incremental: false,
            inch: false,
            per_rev: profile.power_on_per_rev,
            css: false,
            spindle: SpindleDir::Stopped,
            s_word: 0.0,
            spindle_sel: 0,
            spindles: [(SpindleDir::Stopped, 0.0); crate::setup::MAX_SPINDLES],
            rpm_clamp: None,
            spindle_position_mode: false,
            feed: None,
            tool: 0,
            return_initial: true,
            ended: false,
            data_input: None,
            tapping_mode: false,
            polar_interp: None,
        };
        let thread = ThreadState {
            lead_mm: None,
            j: None,
            k: None,
            starts: 1,
            cycle_end: None,
            taper_mm: 0.0,
            rigid_rpm: None,
            pending: None,
            memory: None,
            cycles: 0,
            repair: false,
            g76: None,
            g78: None,
            left_hand: false,
        };
        Modal {
            modes: Kept::new(modes),
            place: Kept::new(Place { pos: Vec3::default(), rotary_deg: [0.0; 3], reference_mid: [None; 3] }),
            notes: Kept::new(Notes {
                feed_warned: None,
                assumed_warned: crate::profile::Letters::EMPTY,
                group_codes: [0; crate::profile::Group::COUNT],
                last_words: LastWords::default(),
            }),
            memory: Kept::new(CycleMemories { rough_data: [None; 2], pattern_data: None, peck_back_off_mm: None, box_cycle: BoxMemory::default() }),
            transform: Kept::new(Transforms::default()),
            stroke2: Kept::new(None),
            frame: Kept::new(Frame { work: 1, ..Frame::default() }),
            comp: Kept::new(CompState::default()),
            thread: Kept::new(thread),
            drill: Kept::new(DrillData::default()),
        }
    }

    /// A block begins: what each part is now is what an alarm in the block goes back to.
    pub fn begin_block(&mut self) {
        // Every part, named so that a part added to `Modal` and not here does not compile.
        let Modal { modes, place, notes, memory, transform, stroke2, frame, comp, thread, drill } = self;
        modes.begin();
        place.begin();
        notes.begin();
        memory.begin();
        transform.begin();
        stroke2.begin();
        frame.begin();
        comp.begin();
        thread.begin();
        drill.begin();
    }

    /// The block alarmed: every part it changed goes back to what it was at [`Modal::begin_block`].
    pub fn roll_back(&mut self) {
        let Modal { modes, place, notes, memory, transform, stroke2, frame, comp, thread, drill } = self;
        modes.roll_back();
        place.roll_back();
        notes.roll_back();
        memory.roll_back();
        transform.roll_back();
        stroke2.roll_back();
        frame.roll_back();
        comp.roll_back();
        thread.roll_back();
        drill.roll_back();
    }
}

impl Modes {
    /// The G96 surface speed in m/min: S is feet per minute under G20.
    pub fn surface_m_min(&self) -> f64 {
        if self.inch {
            self.s_word * 0.3048
        } else {
            self.s_word
        }
    }

    /// Spindle speed in rpm at a given diameter (G96 needs it), signed by direction; 0 if
    /// stopped.
    pub fn rpm_at(&self, diameter_mm: f64, max_rpm: f64) -> f64 {
        self.spindle_speed(max_rpm).rpm_at(diameter_mm)
    }

    /// What the spindle's speed is made of as the modes stand (see [`SpindleSpeed`]).
    pub fn spindle_speed(&self, max_rpm: f64) -> SpindleSpeed {
        let sign = match self.spindle {
            SpindleDir::Stopped => 0.0,
            SpindleDir::Positive => 1.0,
            SpindleDir::Negative => -1.0,
        };
        // G50 S clamps the speed that G96 computes (TDi help G96/97).
        let clamp_rpm = if self.css { self.rpm_clamp.unwrap_or(max_rpm).min(max_rpm) } else { max_rpm };
        SpindleSpeed { sign, css: self.css, clamp_rpm, surface_m_min: self.surface_m_min(), s_rpm: self.s_word.min(max_rpm) }
    }
}

/// One part of the modal state, and what it was before the block in progress first changed it.
///
/// Reading goes through `Deref`; every change goes through `DerefMut`, which saves the part
/// first. So no code can change a part without saving it (a `Kept` is made only here, so a
/// whole part cannot be replaced by a new one), and a block costs a copy of the parts it changes
/// (a hole block: the tool's place, under 100 bytes), not of the whole state (1,720 bytes,
/// copied before every block until 2026-11). The roll-back is complete when the block is begun
/// once, by the outermost block (`Interpreter::execute_into` counts the blocks G70 runs inside
/// its own).
#[derive(Debug, Clone, Copy)]
pub struct Kept<T: Copy> {
    now: T,
    before: Option<T>,
}

impl<T: Copy> Kept<T> {
    const fn new(value: T) -> Self {
        Kept { now: value, before: None }
    }

    fn begin(&mut self) {
        self.before = None;
    }

    /// Take the value out of an optional field of the part, saving the part only when the field
    /// holds one (`Option::take` through `DerefMut` would save the part at every block).
    #[inline]
    pub fn take_some<V>(&mut self, field: impl Fn(&mut T) -> &mut Option<V>) -> Option<V> {
        // Only looked at: the part is unchanged when the field is empty.
        if field(&mut self.now).is_none() {
            return None;
        }
        field(&mut **self).take()
    }

    fn roll_back(&mut self) {
        if let Some(before) = self.before.take() {
            self.now = before;
        }
    }
}

impl<T: Copy> std::ops::Deref for Kept<T> {
    type Target = T;
    #[inline]
    fn deref(&self) -> &T {
        &self.now
    }
}

impl<T: Copy> std::ops::DerefMut for Kept<T> {
    #[inline]
    fn deref_mut(&mut self) -> &mut T {
        if self.before.is_none() {
            self.before = Some(self.now);
        }
        &mut self.now
    }
}

/// Two states are equal when their parts are (what a part was before a block is not compared).
impl<T: Copy + PartialEq> PartialEq for Kept<T> {
    fn eq(&self, other: &Self) -> bool {
        self.now == other.now
    }
}

/// The spindle's speed as the modes of one block make it: a few values, kept by a cycle whose
/// moves are made after the block (their feed per revolution needs it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpindleSpeed {
    /// +1 (M03), -1 (M04), 0 (stopped).
    sign: f64,
    /// G96: the speed follows the diameter.
    css: bool,
    /// The most rpm: G50 S under G96, else the spindle's maximum.
    clamp_rpm: f64,
    surface_m_min: f64,
    /// S under G97, at most the spindle's maximum.
    s_rpm: f64,
}

impl SpindleSpeed {
    /// G96: the speed follows the diameter.
    pub fn css(&self) -> bool {
        self.css
    }

    /// Spindle speed in rpm at a given diameter, signed by direction; 0 if stopped.
    pub fn rpm_at(&self, diameter_mm: f64) -> f64 {
        if self.sign == 0.0 {
            return 0.0;
        }
        let rpm = if self.css {
            let d = diameter_mm.abs();
            // S is m/min, or ft/min under G20 (FANUC and GSK lathe manuals, G96): mm per unit.
            if d < 1e-9 {
                self.clamp_rpm
            } else {
                (self.surface_m_min * 1000.0 / (std::f64::consts::PI * d)).min(self.clamp_rpm)
            }
        } else {
            self.s_rpm
        };
        self.sign * rpm
    }
}
