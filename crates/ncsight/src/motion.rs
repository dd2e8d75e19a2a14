//! The canonical motion stream: a small closed set of operations, each tagged with the block
//! that produced it. Positions are real geometry in millimetres with X as a radius; a lathe's
//! diameter display is applied only at the edges (formatters).

use crate::source::Span;

/// A point or a vector in programme coordinates, millimetres.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Vec3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

impl Vec3 {
    pub const fn new(x: f64, y: f64, z: f64) -> Vec3 {
        Vec3 { x, y, z }
    }

    pub fn axis(&self, i: usize) -> f64 {
        match i {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }

    pub fn set_axis(&mut self, i: usize, v: f64) {
        match i {
            0 => self.x = v,
            1 => self.y = v,
            _ => self.z = v,
        }
    }

    pub fn dist(&self, o: &Vec3) -> f64 {
        ((self.x - o.x).powi(2) + (self.y - o.y).powi(2) + (self.z - o.z).powi(2)).sqrt()
    }
}

impl std::ops::Add for Vec3 {
    type Output = Vec3;
    fn add(self, o: Vec3) -> Vec3 {
        Vec3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl std::ops::Sub for Vec3 {
    type Output = Vec3;
    fn sub(self, o: Vec3) -> Vec3 {
        Vec3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

/// The plane of circular interpolation. Its axes (first, second, normal) form a right-handed
/// set, as LinuxCNC's canonical interface orders them: XY = (X, Y, Z), ZX = (Z, X, Y),
/// YZ = (Y, Z, X).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Plane {
    XY,
    ZX,
    YZ,
}

impl Plane {
    /// Indices of (first, second, normal) axes in X=0, Y=1, Z=2.
    pub fn axes(self) -> (usize, usize, usize) {
        match self {
            Plane::XY => (0, 1, 2),
            Plane::ZX => (2, 0, 1),
            Plane::YZ => (1, 2, 0),
        }
    }

    /// The point with plane-local coordinates `[a, b, n]` (the inverse of [`Plane::axes`]),
    /// built whole rather than axis by axis.
    pub fn from_local(self, l: [f64; 3]) -> Vec3 {
        match self {
            Plane::XY => Vec3::new(l[0], l[1], l[2]),
            Plane::ZX => Vec3::new(l[1], l[2], l[0]),
            Plane::YZ => Vec3::new(l[2], l[0], l[1]),
        }
    }
}

/// Direction of an arc as G02/G03 name it (seen from the positive end of the plane's normal).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArcDir {
    Cw,
    Ccw,
}

/// The long axis of a thread: the one with the larger travel (X counted as a radius); on
/// equality Z (docs/reference/behaviour.md, "Thread pull-out"). Y only for arc threads in G17/G19.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LongAxis {
    X,
    Y,
    Z,
}

impl LongAxis {
    /// Index in X=0, Y=1, Z=2 of the long axis and of the short axis of a lathe thread
    /// (the ZX plane).
    pub fn indices(self) -> (usize, usize) {
        match self {
            LongAxis::X => (0, 2),
            LongAxis::Y => (1, 0),
            LongAxis::Z => (2, 0),
        }
    }

    pub fn index(self) -> usize {
        match self {
            LongAxis::X => 0,
            LongAxis::Y => 1,
            LongAxis::Z => 2,
        }
    }

    pub fn from_index(i: usize) -> LongAxis {
        match i {
            0 => LongAxis::X,
            1 => LongAxis::Y,
            _ => LongAxis::Z,
        }
    }

    /// The long axis of a straight thread from `from` to `to` (ZX plane).
    pub fn of(from: &Vec3, to: &Vec3) -> LongAxis {
        if (to.x - from.x).abs() > (to.z - from.z).abs() {
            LongAxis::X
        } else {
            LongAxis::Z
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            LongAxis::X => "x",
            LongAxis::Y => "y",
            LongAxis::Z => "z",
        }
    }
}

/// Why the machine stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopReason {
    /// M00.
    ProgramStop,
    /// M01 with the optional-stop switch on.
    OptionalStop,
    /// G88: the operator retracts the tool by hand, then presses cycle start.
    ManualRetract,
    /// The operator pressed FEED HOLD; CYCLE START follows once the machine has stopped.
    FeedHold,
    /// Single-block mode: the machine stops at the end of a block (or a cycle, or a hole).
    SingleBlock,
    /// The operator pressed RESET: the axes decelerate to a stop and the programme ends.
    Reset,
}

impl StopReason {
    pub fn as_str(self) -> &'static str {
        match self {
            StopReason::ProgramStop => "program_stop",
            StopReason::OptionalStop => "optional_stop",
            StopReason::ManualRetract => "manual_retract",
            StopReason::FeedHold => "feed_hold",
            StopReason::SingleBlock => "single_block",
            StopReason::Reset => "reset",
        }
    }
}

/// One operation of the stream.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Op {
    /// Positioning. `rates_mm_min` are the per-axis rates used (each axis at its own rate).
    Rapid {
        from: Vec3,
        to: Vec3,
    },
    /// Straight cutting feed at `feed_mm_min` (per-revolution feeds already multiplied out).
    Feed {
        from: Vec3,
        to: Vec3,
        feed_mm_min: f64,
    },
    /// Circular (helical along the plane's normal) cutting feed.
    Arc {
        from: Vec3,
        to: Vec3,
        center: Vec3,
        plane: Plane,
        dir: ArcDir,
        feed_mm_min: f64,
    },
    /// Spindle-synchronised straight motion: the long axis moves `lead_mm` per spindle
    /// revolution. `spindle_deg` is the spindle angle at the start, from the one-revolution
    /// signal in the direction of turning; `rpm` is signed.
    Thread {
        from: Vec3,
        to: Vec3,
        lead_mm: f64,
        long_axis: LongAxis,
        spindle_deg: f64,
        rpm: f64,
    },
    /// Spindle-synchronised circular motion (G32.2/G32.3).
    ThreadArc {
        from: Vec3,
        to: Vec3,
        center: Vec3,
        plane: Plane,
        dir: ArcDir,
        lead_mm: f64,
        long_axis: LongAxis,
        spindle_deg: f64,
        rpm: f64,
    },
    Dwell {
        seconds: f64,
    },
    /// A rotary axis (`axis`: b'A', b'B' or b'C', as the setup declares it) turns from
    /// `from_deg` to `to_deg`: at its rapid rate, or at `rate_deg_min`. `with_move`: it turns
    /// together with the linear move recorded just before it (the block moved both), and takes
    /// only the time that move does not already take. `linear`: the axis is declared linear (a
    /// sub-spindle's travel B): a slide, its `_deg` values millimetres and its rate mm/min, its
    /// rapid the linear axes' (JSONL kind `slide`).
    Rotary {
        axis: u8,
        from_deg: f64,
        to_deg: f64,
        rate_deg_min: f64,
        rapid: bool,
        with_move: bool,
        linear: bool,
    },
    /// Spindle state changed. `rpm` is signed: negative = the spindle's negative direction;
    /// 0 = stopped. `surface_m_min` is the G96 surface speed when constant surface speed is on.
    /// `oriented`: an oriented spindle stop (G76, G87).
    /// `p`: the spindle it is, by the P that selects it on a machine with several (the setup's
    /// `spindle_p`); 0 on a machine with one.
    Spindle {
        rpm: f64,
        surface_m_min: Option<f64>,
        position_mode: bool,
        oriented: bool,
        p: u32,
    },
    /// Tool selected (lathe T word) or changed (M06). `offset` is the lathe offset number.
    Tool {
        number: u32,
        offset: Option<u32>,
    },
    Stop {
        reason: StopReason,
    },
    /// M02 / M30 (and M99 in a main programme).
    End {
        code: u32,
    },
}

impl Op {
    /// The record kind, as the JSONL interface names it.
    pub fn kind(&self) -> &'static str {
        match self {
            Op::Rapid { .. } => "rapid",
            Op::Feed { .. } => "feed",
            Op::Arc { .. } => "arc",
            Op::Thread { .. } => "thread",
            Op::ThreadArc { .. } => "thread_arc",
            Op::Dwell { .. } => "dwell",
            Op::Rotary { linear: false, .. } => "rotary",
            Op::Rotary { linear: true, .. } => "slide",
            Op::Spindle { .. } => "spindle",
            Op::Tool { .. } => "tool",
            Op::Stop { .. } => "stop",
            Op::End { .. } => "end",
        }
    }

    /// Start point of a motion.
    pub fn start_point(&self) -> Option<Vec3> {
        match self {
            Op::Rapid { from, .. } | Op::Feed { from, .. } | Op::Arc { from, .. } | Op::Thread { from, .. } | Op::ThreadArc { from, .. } => Some(*from),
            _ => None,
        }
    }

    /// A move (G00, G01, G02/G03) from `from` to `to`, of the same kind, feed and centre; any
    /// other record as it is.
    pub fn with_ends(&self, from: Vec3, to: Vec3) -> Op {
        match *self {
            Op::Rapid { .. } => Op::Rapid { from, to },
            Op::Feed { feed_mm_min, .. } => Op::Feed { from, to, feed_mm_min },
            Op::Arc { center, plane, dir, feed_mm_min, .. } => Op::Arc { from, to, center, plane, dir, feed_mm_min },
            ref other => other.clone(),
        }
    }

    /// Spindle-synchronised (thread) motion.
    pub fn is_thread(&self) -> bool {
        matches!(self, Op::Thread { .. } | Op::ThreadArc { .. })
    }

    /// End point of a motion.
    pub fn end_point(&self) -> Option<Vec3> {
        match self {
            Op::Rapid { to, .. } | Op::Feed { to, .. } | Op::Arc { to, .. } | Op::Thread { to, .. } | Op::ThreadArc { to, .. } => Some(*to),
            _ => None,
        }
    }
}

/// What FEED HOLD does while a record runs, decided by the interpreter from the manuals and
/// carried out by the operator machine (`machine.rs`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Hold {
    /// The axes decelerate to a stop where they are.
    Stop,
    /// The record runs to its end first (G04: TDi help G04 note 5).
    AfterRecord,
    /// Ignored until the synchronised run or the tapping cycle this record belongs to is done
    /// (seed 001 G32.1 note 6, G92.1 note 7; seed 003 8.1.2; TDi help G32 note 3).
    AfterRun,
    /// A press during this record is discarded: the controller keeps showing RUN and does not
    /// remember it; the operator must press FEED HOLD again once no thread is being cut (GSK988T
    /// manual, G32.1 note 6 and G92.1 note 7; GSK980TDi help text, G32.1 note 4).
    Ignored,
    /// A thread of a G92 cycle: the controller's own thread hold.
    ThreadCycle(ThreadHold),
}

/// The G92 thread hold of a profile (seed 000 note 1, seed 004 "thread cutting hold").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThreadHold {
    pub style: ThreadHoldStyle,
    /// The cycle's start point A.
    pub start: Vec3,
    /// Pull-out used when the hold pulls out at once: along the long axis (mm), along the short
    /// axis (mm, toward A).
    pub pull_long_mm: f64,
    pub pull_short_mm: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ThreadHoldStyle {
    /// GSK980TDi NO.0018 bit 6 = 0: pull out at once, short axis back to A, then the long axis.
    PullOutAndReturn,
    /// GSK980TDi NO.0018 bit 6 = 1: finish the thread with its pull-out, then stop.
    FinishThenStop,
    /// YASNAC #6019 D7 = 0: thread up at once, return to A.
    ThreadUpAndReturn,
    /// YASNAC #6019 D7 = 1: thread up at once and stop there (B).
    ThreadUpAndStop,
}

/// One record of the stream.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// The block that produced it.
    pub span: Span,
    /// Its sequence number, where it has one (`N50` -> 50).
    pub n: Option<u32>,
    /// How many subprogramme calls deep the block ran (0 in the main programme).
    pub call_depth: u8,
    /// Seconds from programme start at the end of this record (the operator machine's time
    /// model; 0 until it has run).
    pub t_s: f64,
    pub op: Op,
    /// Single block may stop after this record (end of a block, of a whole cycle, of a hole).
    pub block_end: bool,
    pub hold: Hold,
    /// The four-step thread cycle instance the record belongs to (for the thread hold's restart).
    pub cycle: Option<u32>,
    /// The feed override does not apply (threads always; tapping: seed 003 8.1.2).
    pub override_free: bool,
    /// The acceleration time constant of this move where the controller has its own for it
    /// (the GSK988T's perpendicular pull-out after a G32.1 end: parameter 1628), seconds.
    pub accel_s: Option<f64>,
    /// Added to the record's points gives machine coordinates (the work offsets, G50/G92
    /// shift, G52 and the tool offset in force; 0 without a setup).
    pub to_machine: Vec3,
}

impl Record {
    /// A record with the default operator rules of its kind.
    pub fn new(span: Span, op: Op) -> Record {
        Record::of_block(span, None, op)
    }

    /// [`Record::new`] of a block with sequence number `n`.
    #[inline]
    pub fn of_block(span: Span, n: Option<u32>, op: Op) -> Record {
        let hold = match op {
            // A rotary turn, as a dwell: FEED HOLD stops after it (its position is one angle).
            Op::Dwell { .. } | Op::Rotary { .. } => Hold::AfterRecord,
            Op::Thread { .. } | Op::ThreadArc { .. } => Hold::AfterRun,
            _ => Hold::Stop,
        };
        let override_free = op.is_thread();
        Record { span, n, call_depth: 0, t_s: 0.0, op, block_end: false, hold, cycle: None, override_free, accel_s: None, to_machine: Vec3::new(0.0, 0.0, 0.0) }
    }
}
