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
}

/// Direction of an arc as G02/G03 name it (seen from the positive end of the plane's normal).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArcDir {
    Cw,
    Ccw,
}

/// The long axis of a thread: the one with the larger travel (X counted as a radius); on
/// equality Z (../shared/spec/BEHAVIOUR.md, "Thread pull-out"). Y only for arc threads in G17/G19.
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
}

impl StopReason {
    pub fn as_str(self) -> &'static str {
        match self {
            StopReason::ProgramStop => "program_stop",
            StopReason::OptionalStop => "optional_stop",
            StopReason::ManualRetract => "manual_retract",
        }
    }
}

/// One operation of the stream.
#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    /// Positioning. `rates_mm_min` are the per-axis rates used (each axis at its own rate).
    Rapid { from: Vec3, to: Vec3 },
    /// Straight cutting feed at `feed_mm_min` (per-revolution feeds already multiplied out).
    Feed { from: Vec3, to: Vec3, feed_mm_min: f64 },
    /// Circular (helical along the plane's normal) cutting feed.
    Arc { from: Vec3, to: Vec3, center: Vec3, plane: Plane, dir: ArcDir, feed_mm_min: f64 },
    /// Spindle-synchronised straight motion: the long axis moves `lead_mm` per spindle
    /// revolution. `spindle_deg` is the spindle angle at the start, from the one-revolution
    /// signal in the direction of turning; `rpm` is signed.
    Thread { from: Vec3, to: Vec3, lead_mm: f64, long_axis: LongAxis, spindle_deg: f64, rpm: f64 },
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
    Dwell { seconds: f64 },
    /// Spindle state changed. `rpm` is signed: negative = the spindle's negative direction;
    /// 0 = stopped. `surface_m_min` is the G96 surface speed when constant surface speed is on.
    /// `oriented`: an oriented spindle stop (G76, G87).
    Spindle { rpm: f64, surface_m_min: Option<f64>, position_mode: bool, oriented: bool },
    /// Tool selected (lathe T word) or changed (M06). `offset` is the lathe offset number.
    Tool { number: u32, offset: Option<u32> },
    Stop { reason: StopReason },
    /// M02 / M30 (and M99 in a main programme).
    End { code: u32 },
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
            Op::Spindle { .. } => "spindle",
            Op::Tool { .. } => "tool",
            Op::Stop { .. } => "stop",
            Op::End { .. } => "end",
        }
    }

    /// Start point of a motion.
    pub fn start_point(&self) -> Option<Vec3> {
        match self {
            Op::Rapid { from, .. }
            | Op::Feed { from, .. }
            | Op::Arc { from, .. }
            | Op::Thread { from, .. }
            | Op::ThreadArc { from, .. } => Some(*from),
            _ => None,
        }
    }

    /// Spindle-synchronised (thread) motion.
    pub fn is_thread(&self) -> bool {
        matches!(self, Op::Thread { .. } | Op::ThreadArc { .. })
    }

    /// End point of a motion.
    pub fn end_point(&self) -> Option<Vec3> {
        match self {
            Op::Rapid { to, .. }
            | Op::Feed { to, .. }
            | Op::Arc { to, .. }
            | Op::Thread { to, .. }
            | Op::ThreadArc { to, .. } => Some(*to),
            _ => None,
        }
    }
}

/// One record of the stream.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// The block that produced it.
    pub span: Span,
    /// Seconds from programme start at the end of this record (time model).
    pub t_s: f64,
    pub op: Op,
}
