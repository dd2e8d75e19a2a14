//! The interpreter: one block at a time, checked first and committed only if valid (atomic per
//! block), against a profile and its parameters. It turns a block into records of the canonical
//! stream and warnings, or into one alarm that leaves the modal state untouched.

mod call;
mod comp;
mod compound;
mod corner;
mod curve;
mod deferred;
mod drawing;
mod drill;
mod frame;
mod groove;
mod involute;
mod polar;
mod rough;
mod table_vars;
pub use call::{Flow, MAX_PROGRAM_NUMBER, MAX_PROGRAM_NUMBER_8};
pub use frame::{TableWrite, Tables};
pub use rough::{FinishRequest, RoughRequest};
mod stroke;
mod thread;
mod transform;
mod turning;
mod words;

use crate::alarm::{Diagnostic, Rule};
use crate::geom::{self, ArcError};
use crate::modal::{Modal, Motion, SpindleDir};
use crate::motion::{ArcDir, Op, Plane, Record, StopReason, Vec3};
use crate::profile::{CompInCycle, GDef, GFn, Group, IntegerLengths, MDef, MFn, ParamKey, Params, Profile, MAX_RPM};
use crate::read::{Block, Word};
use crate::source::Span;
use words::Words;

/// Largest |coordinate| accepted, mm: 99999.999 mm is the widest value an 8-digit word with
/// 0.001 mm resolution can hold; under G20, 9999.9999 inch.
pub const MAX_COORD_MM: f64 = 99_999.999;
pub const MAX_COORD_INCH: f64 = 9_999.999_9;

/// The most motion records one block may make (a canned cycle with K repeats, a G71 of tiny
/// depth): past it the block alarms (NCS-E40), so the memory a block holds stays bounded by a
/// constant (about 20 MB) whatever it expands to. Documented in docs/robustness.md.
pub const MAX_MOTIONS_PER_BLOCK: usize = 100_000;

/// Arc end-point radius tolerance, mm (assumed; FANUC's is a parameter): start and end radii
/// may differ by this much before OVER TOLERANCE OF RADIUS.
pub const ARC_TOLERANCE_MM: f64 = 0.01;

/// What a valid block produced.
#[derive(Debug, Default)]
pub struct Outcome {
    pub records: Vec<Record>,
    pub warnings: Vec<Diagnostic>,
    /// Records are not kept (a check that wants only the diagnostics): the blocks still move the
    /// tool in the modal state, so every rule is checked as in a run.
    pub discard_records: bool,
    /// Lengths without a decimal point read in least input increments so far, and how many of
    /// them came to less than 1 mm (0.1 inch): kept across blocks for the summary of NCS-W02.
    pub increment_words: u32,
    pub increment_words_small: u32,
    /// Records made by the block being executed (kept or not).
    pub(crate) emitted: usize,
    /// A second G71/G72/G73 block asks for the contour blocks that follow it to be collected.
    rough_request: Option<Box<RoughRequest>>,
    /// G70 asks for a stored contour to be run.
    finish_request: Option<FinishRequest>,
    /// M98 or M99: the jump the block asks for, after its records.
    pub flow: Option<Flow>,
    /// The first move of the block beyond a soft travel limit: (its block, axis, limit, where
    /// it went, beyond the upper end).
    overtravel: Option<(Span, usize, f64, f64, bool)>,
    /// The first move of the block into G22's forbidden area: its block and what it did.
    stroke_hit: Option<(Span, String)>,
    /// What a G10 block writes into the machine's tables, once it has run.
    table_write: Option<TableWrite>,
    /// What a parameter line between G10 L50/L52 and G11 writes, once it has run.
    param_writes: Vec<(crate::profile::ParamKey, f64)>,
    /// A macro variable a GSK parameter line reads a parameter into (`N_ R_`): the programme
    /// sets it after the block.
    pub var_write: Option<(u32, f64)>,
    /// Radius compensation found no path (the block alarms).
    comp_error: Option<Diagnostic>,
    /// The block made a move in the plane in compensation.
    comp_plane_move: bool,
    /// The blocks whose records the compensation stage made during this block.
    comp_spans: Vec<Span>,
    /// A block's records too many to hold (a drilling block's holes, a roughing's levels): made
    /// one at a time as they are handed on, after the first `.0` records of `records`.
    pub deferred: Option<Box<(usize, Deferred)>>,
    /// Whether the consumer takes records as they are made (a sink), so a block may defer its
    /// holes; a pull iterator that queues a line's events does not (its queue would hold them).
    pub may_defer: bool,
}

/// What a block lays out to be made as it is handed on: its records made one at a time, so a
/// block of any number of moves holds a constant memory.
#[derive(Debug, Clone)]
pub enum Deferred {
    Holes(drill::DeferredHoles),
    Cuts(deferred::DeferredCuts),
}

impl Deferred {
    /// Every record, in order.
    pub fn each_record(&self, sink: &mut dyn FnMut(Record)) {
        match self {
            Deferred::Holes(h) => h.each_record(sink),
            Deferred::Cuts(c) => c.each_record(sink),
        }
    }
}

impl Outcome {
    /// An outcome for a consumer that takes each record as it comes (see [`Outcome::may_defer`]).
    pub fn streaming() -> Outcome {
        Outcome { may_defer: true, ..Outcome::default() }
    }

    fn clear(&mut self) {
        self.records.clear();
        self.warnings.clear();
        self.emitted = 0;
        self.rough_request = None;
        self.finish_request = None;
        self.flow = None;
        self.overtravel = None;
        self.stroke_hit = None;
        self.table_write = None;
        self.param_writes.clear();
        self.var_write = None;
        self.comp_error = None;
        self.comp_plane_move = false;
        self.comp_spans.clear();
        self.deferred = None;
    }
}

/// Switches on the operator's panel, and what the operator recorded, that change what a
/// programme does.
#[derive(Debug, Clone, Copy, Default)]
pub struct Switches {
    /// The thread repair position recorded on the machine (GSK980TDi help, thread repair 3).
    pub repair_position: Option<crate::repair::Recorded>,
    /// Block delete: blocks that start with `/` are skipped.
    pub block_delete: bool,
    /// Optional stop: M01 stops.
    pub optional_stop: bool,
}

/// The interpreter of one programme run.
#[derive(Clone)]
pub struct Interpreter {
    profile: &'static Profile,
    params: Params,
    /// The machine's offsets, reference points and limits (the setup's, else all zero).
    tables: Tables,
    /// Radius compensation's held move and the records waiting behind it.
    comp_queue: Vec<Record>,
    /// The corner stage's held records.
    corner_queue: Vec<Record>,
    state: Modal,
    switches: Switches,
    /// A G71/G72 block is collecting its contour blocks (they follow it).
    collecting: Option<(RoughRequest, Vec<Block>)>,
    /// Contours collected so far, by (ns, nf), for G70.
    contours: Vec<rough::Contour>,
    /// G70 is running a stored contour.
    replaying: bool,
    /// How many blocks are running inside one another (G70's contour blocks run inside it).
    nested_blocks: u8,
}

/// What a message names: a code by its function (its name looked up in the profile's table only
/// when a message needs it), or a name.
#[derive(Clone, Copy)]
enum What {
    Code(GFn),
    Name(&'static str),
}

impl What {
    fn name(self, profile: &Profile) -> &'static str {
        match self {
            What::Code(f) => profile.name_of(f),
            What::Name(n) => n,
        }
    }
}

impl From<&'static str> for What {
    fn from(n: &'static str) -> What {
        What::Name(n)
    }
}

/// The working copy of one block's effects.
struct Step<'a> {
    profile: &'static Profile,
    params: &'a Params,
    tables: &'a Tables,
    /// Radius compensation's held records.
    queue: &'a mut Vec<Record>,
    /// The corner stage's held records (a move waiting for its chamfer, a line of an angle
    /// alone, what waits behind them).
    corners: &'a mut Vec<Record>,
    /// This block runs outside radius compensation (a cycle, a reference return...).
    bypass_comp: bool,
    /// A G71-G73 contour's blocks worked out for roughing: the programmed path, its corners
    /// (chamfers, corner arcs, lines of an angle alone) made by the look-ahead stage, which
    /// compensates nothing.
    contour: bool,
    /// The recorded thread repair position, if any.
    repair: Option<crate::repair::Recorded>,
    span: Span,
    /// The block's sequence number, for its records.
    n: Option<u32>,
    /// The interpreter's modal state, changed in place (each part saved when the block first
    /// changes it, put back on an alarm: `modal::Kept`).
    st: &'a mut Modal,
    /// The block runs in programmed coordinates: its records are carried through these
    /// transforms (G51.1, G51, G68) and its end position back at the block's end.
    carry: Option<crate::modal::Transforms>,
    /// What the cycle making records now says of them, set on each as it is made.
    marks: Marks,
    out: &'a mut Outcome,
}

/// What a cycle says of the records it is making, set on each record as it is made, never
/// patched afterwards: FEED HOLD's rule, the feed override, the thread cycle a record belongs
/// to, the time constant of its feeds ([`Step::marked`]).
#[derive(Debug, Clone, Copy, Default)]
struct Marks {
    /// FEED HOLD's rule, and the records it is for.
    hold: Option<(crate::motion::Hold, HoldOn)>,
    /// The feed override does not act (tapping).
    override_free: bool,
    /// The thread cycle the records belong to (a cycle's start, a compound thread's pass).
    cycle: Option<u32>,
    /// The time constant of the feed records among them.
    feed_accel_s: Option<Option<f64>>,
    /// The next record only (then the marks end): the one an op makes.
    once: bool,
}

/// Which records a cycle's FEED HOLD rule is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum HoldOn {
    Every,
    /// The thread records (not the cycle's rapids).
    Threads,
    /// The feed records (a pull-out after the thread's end point).
    Feeds,
}

impl Marks {
    /// Tapping: FEED HOLD and single block wait for the end of the tapping and its way out, and
    /// the feed override does not act (FANUC 0-M manual, G84; GSK980TDi help text, G33 note 4).
    const TAPPING: Marks =
        Marks { hold: Some((crate::motion::Hold::AfterRun, HoldOn::Every)), override_free: true, cycle: None, feed_accel_s: None, once: false };

    fn apply(&self, r: &mut Record) {
        if let Some(id) = self.cycle {
            r.cycle = Some(id);
        }
        if let Some((hold, on)) = self.hold {
            let applies = match on {
                HoldOn::Every => true,
                HoldOn::Threads => r.op.is_thread(),
                HoldOn::Feeds => matches!(r.op, Op::Feed { .. }),
            };
            if applies {
                r.hold = hold;
            }
        }
        if self.override_free {
            r.override_free = true;
        }
        if let (Some(accel_s), Op::Feed { .. }) = (self.feed_accel_s, &r.op) {
            r.accel_s = accel_s;
        }
    }
}

impl Step<'_> {
    /// Run `f` with `marks` on the records it makes; the marks in force before come back after.
    fn marked<R>(&mut self, marks: Marks, f: impl FnOnce(&mut Self) -> R) -> R {
        let outer = std::mem::replace(&mut self.marks, marks);
        let result = f(self);
        self.marks = outer;
        result
    }

    fn alarm(&self, rule: Rule, span: Span, msg: impl Into<String>) -> Diagnostic {
        Diagnostic::new(rule, self.profile.alarm_style, span, msg)
    }

    fn warn(&mut self, rule: Rule, span: Span, msg: impl Into<String>) {
        let d = Diagnostic::new(rule, self.profile.alarm_style, span, msg);
        self.out.warnings.push(d);
    }

    /// The P of the spindle selected (the setup's `spindle_p`), 0 on a machine with one.
    fn spindle_p(&self) -> u32 {
        // Assumed spindles are named once the programme has selected one with P.
        if self.tables.spindle_p_assumed && !self.st.notes.assumed_warned.contains(b'P') {
            return 0;
        }
        self.tables.spindle_p.get(usize::from(self.st.modes.spindle_sel)).copied().unwrap_or(0)
    }

    fn emit(&mut self, op: Op) {
        self.emit_at(self.span, self.n, op);
    }

    /// Emit an operation of an earlier block (a held-back thread run end). Past
    /// [`MAX_MOTIONS_PER_BLOCK`] nothing more is kept: the block then alarms.
    fn emit_at(&mut self, span: Span, n: Option<u32>, op: Op) {
        if let Some(p) = op.end_point() {
            self.st.place.pos = p;
            // The tool offset's movement is made (FANUC 5002#6 LWM: with the next move).
            if self.st.frame.unmoved != Vec3::default() {
                self.st.frame.unmoved = Vec3::default();
            }
        }
        let op = match &self.carry {
            Some(t) => transform::carry(t, op),
            None => op,
        };
        // Radius compensation: the move goes through the look-ahead stage; a move outside it
        // starts where the tool is.
        // A chamfer or corner arc (GSK980TDi L, D; FANUC ,C ,R) holds its move in the corner
        // stage first, until the next move shows the corner.
        if corner::active(self) && (!self.bypass_comp || self.contour || corner::waits(self)) {
            return corner::take(self, span, n, op);
        }
        if self.st.comp.side != 0 && !self.bypass_comp {
            return comp::take(self, span, n, op);
        }
        let op = if self.st.comp.actual.is_some() { comp::from_actual(self, span, n, op) } else { op };
        self.push_record(span, n, op);
    }

    /// Put a record in the block's outcome: as it is, or in G12.1 as the machine makes it.
    fn push_record(&mut self, span: Span, n: Option<u32>, op: Op) {
        match self.st.modes.polar_interp {
            Some(p) => polar::push(self, span, n, op, p),
            None => self.push_machine(span, n, op, None),
        }
    }

    /// Put a record in the block's outcome as it is (positions as the controller moves), with
    /// its own time constant where it has one.
    fn push_machine(&mut self, span: Span, n: Option<u32>, op: Op, accel_s: Option<f64>) {
        self.out.emitted += 1;
        if self.out.emitted > MAX_MOTIONS_PER_BLOCK {
            return;
        }
        // Machine coordinates only where something reads them (a check without limits keeps no
        // record).
        if !self.tables.limited && self.out.discard_records && self.st.stroke2.is_none() {
            return;
        }
        let to_machine = self.tables.to_machine(&self.st.frame);
        self.travel_checks(span, &op, &to_machine);
        if !self.out.discard_records {
            let mut r = Record::of_block(span, n, op);
            r.to_machine = to_machine;
            if accel_s.is_some() {
                r.accel_s = accel_s;
            }
            // G63: a tap fed by G01 in a floating holder; the override is 100 % and FEED HOLD
            // lets the move end (FANUC group 15, "tapping mode").
            if self.st.modes.tapping_mode && matches!(r.op, Op::Feed { .. } | Op::Arc { .. }) {
                r.override_free = true;
                r.hold = crate::motion::Hold::AfterRecord;
            }
            self.marks.apply(&mut r);
            if self.marks.once {
                self.marks = Marks::default();
            }
            self.out.records.push(r);
        }
    }

    /// The drawing's words are plain C, R and A in this run (FANUC 0i-TF 3405#4 CCR = 1).
    fn plain_drawing(&self) -> bool {
        self.profile.frame.drawing.is_some_and(|r| corner::plain_letters(self, r))
    }

    /// The alarm of a move the machine refused in this block, if one was noted: beyond a soft
    /// limit first, then into G22's area.
    fn travel_alarm(&mut self) -> Result<(), Diagnostic> {
        if let Some(hit) = self.out.overtravel {
            return Err(overtravel_alarm(self.profile, hit));
        }
        match self.out.stroke_hit.take() {
            Some((span, why)) => Err(self.alarm(Rule::StrokeCheck2, span, why)),
            None => Ok(()),
        }
    }

    /// The first move of the block into G22's forbidden area or beyond a soft limit, noted (the
    /// block then alarms).
    fn travel_checks(&mut self, span: Span, op: &Op, to_machine: &Vec3) {
        if let (Some(area), None) = (*self.st.stroke2, &self.out.stroke_hit) {
            if let Some(why) = stroke::entered(&area, op, to_machine) {
                self.out.stroke_hit = Some((span, why));
            }
        }
        if self.tables.limited && self.out.overtravel.is_none() {
            if let Some((from, to)) = op.start_point().zip(op.end_point()) {
                let (lo, hi) = match geom::arc_geom_of(op) {
                    Some(g) => match *op {
                        Op::Arc { plane, dir, .. } | Op::ThreadArc { plane, dir, .. } => geom::arc_extent(&from, &to, plane, dir, &g),
                        _ => unreachable!("only arcs have an arc's geometry"),
                    },
                    None => (Vec3::new(from.x.min(to.x), from.y.min(to.y), from.z.min(to.z)), Vec3::new(from.x.max(to.x), from.y.max(to.y), from.z.max(to.z))),
                };
                if let Some((axis, limit, at, upper)) = self.tables.beyond_limit(&(lo + *to_machine), &(hi + *to_machine)) {
                    self.out.overtravel = Some((span, axis, limit, at, upper));
                }
            }
        }
    }

    /// Emit a move a cycle laid out: a feed or an arc gets the feed in force for its points (F
    /// per revolution under G99, at the speed of its points under G96); anything else as it is.
    fn emit_cut(&mut self, what: &'static str, op: Op) -> Result<(), Diagnostic> {
        let op = match op {
            Op::Feed { from, to, .. } => {
                let feed_mm_min = self.cutting_feed(what, &|u| lerp(&from, &to, u))?;
                Op::Feed { from, to, feed_mm_min }
            }
            Op::Arc { from, to, center, plane, dir, .. } => {
                let feed_mm_min = match crate::geom::arc_geom_of(&op) {
                    Some(g) => self.cutting_feed(what, &|u| geom::arc_point(&from, &to, plane, dir, &g, u))?,
                    None => self.cutting_feed(what, &|u| lerp(&from, &to, u))?,
                };
                Op::Arc { from, to, center, plane, dir, feed_mm_min }
            }
            other => other,
        };
        self.emit(op);
        Ok(())
    }

    /// The records emitted since `from` (an index into this block's records).
    fn records_since(&mut self, from: usize) -> &mut [Record] {
        &mut self.out.records[from..]
    }

    /// An angle word in degrees (a rotary axis, G68's R, a polar angle): with a decimal point as
    /// written; without, in least input increments (0.001 degree) where lengths are, else
    /// degrees.
    fn degrees(&self, w: &Word) -> f64 {
        if !w.decimal && self.params.integer_lengths() == IntegerLengths::LeastIncrement {
            w.value * 0.001
        } else {
            w.value
        }
    }

    /// An angle word in 0.001 degree, with a decimal point too (the GSK980TDi's Q: `Q180.` is
    /// 0.18 degree, the GSK980TDc manual says), with a warning when it has one.
    fn thousandths_deg(&mut self, w: &Word, what: &str) -> f64 {
        let deg = w.value * 0.001;
        if w.decimal {
            let msg = format!("{}: {what} is in 0.001 degree even with a decimal point (GSK980TDc manual): {} degree", w.text(), crate::alarm::shown(deg, 4));
            self.warn(Rule::Implausible, w.span, msg);
        }
        deg
    }

    /// A length word in mm, read by the profile's decimal-point rule and the units in force.
    #[inline]
    fn length(&mut self, w: &Word) -> Result<f64, Diagnostic> {
        let mut v = w.value;
        if !w.decimal && self.params.integer_lengths() == IntegerLengths::LeastIncrement {
            v *= if self.st.modes.inch { 0.0001 } else { 0.001 };
            if w.value != 0.0 {
                self.warn_increments(w, v);
            }
        }
        let limit = if self.st.modes.inch { MAX_COORD_INCH } else { MAX_COORD_MM };
        if v.abs() > limit + 1e-9 {
            return Err(self.out_of_range(w, v));
        }
        if self.st.modes.inch {
            v *= 25.4;
        }
        Ok(v)
    }

    #[cold]
    fn warn_increments(&mut self, w: &Word, v: f64) {
        self.out.increment_words += 1;
        if v.abs() < if self.st.modes.inch { 0.1 } else { 1.0 } {
            self.out.increment_words_small += 1;
        }
        let unit = if self.st.modes.inch { "inch" } else { "mm" };
        let shown = if self.st.modes.inch { format!("{v:.4}") } else { format!("{v:.3}") };
        self.warn(Rule::IntegerLength, w.span, format!("{} is {shown} {unit} on this control (no decimal point: least input increments)", w.text()));
    }

    #[cold]
    fn out_of_range(&self, w: &Word, v: f64) -> Diagnostic {
        self.alarm(
            Rule::ValueOutOfRange,
            w.span,
            if self.st.modes.inch {
                format!("{}: {} inch is beyond the controller's range (at most {MAX_COORD_INCH:.4} inch)", w.text(), crate::alarm::shown(v, 4))
            } else {
                format!("{}: {} mm is beyond the controller's range (at most {MAX_COORD_MM:.3} mm)", w.text(), crate::alarm::shown(v, 3))
            },
        )
    }

    /// A word for the student (issue 15): a lathe feed per minute below 10 mm/min (`F0.2` under
    /// G98: a 22 mm cut takes nearly two hours) was meant per revolution; a feed per revolution
    /// above 10 mm/rev was meant per minute. Once per programme and feed mode, with the numbers
    /// of the first F that was (issue 36: one hint, not one per F).
    #[cold]
    #[inline(never)]
    fn feed_plausible(&mut self, f: f64, point: &dyn Fn(f64) -> Vec3) {
        let unit = if self.st.modes.inch { 25.4 } else { 1.0 };
        let shown = crate::alarm::shown(f / unit, 4);
        // The caller has found F implausible in its mode.
        let msg = if !self.st.modes.per_rev {
            // Along the path (an arc's length, not its chord).
            let length: f64 = (0..16).map(|k| point(k as f64 / 16.0).dist(&point((k + 1) as f64 / 16.0))).sum();
            let minutes = length / f;
            format!(
                "F{shown} under feed per minute is {} {}/min: this {} mm cut takes {}; feed per revolution (G99) was probably meant",
                shown,
                if self.st.modes.inch { "inch" } else { "mm" },
                crate::alarm::shown(length, 3),
                hours_minutes(minutes * 60.0)
            )
        } else {
            format!(
                "F{shown} under feed per revolution is {shown} {}/rev, more than any cutting tool takes; feed per minute (G98 on these lathes) was probably meant",
                if self.st.modes.inch { "inch" } else { "mm" }
            )
        };
        self.st.notes.feed_warned = Some(self.st.modes.per_rev);
        self.warn(Rule::Implausible, self.span, msg);
    }

    /// The axis whose position is the radius G96 works from: X on a lathe, the axis the
    /// parameter names on a machining centre (a facing head's radius), none otherwise.
    fn css_axis(&self) -> Option<usize> {
        match self.profile.css_axis {
            Some(k) => Some((self.params.get(k) as usize).clamp(1, 3) - 1),
            None if self.profile.diameter_x => Some(0),
            None => None,
        }
    }

    /// Spindle speed at a point (G96 makes it depend on the diameter), signed.
    fn rpm_at(&self, p: &Vec3) -> f64 {
        // Without G96 the speed is S whatever the diameter (the parameter is not read).
        let dia = if self.st.modes.css { self.css_axis().map_or(0.0, |k| 2.0 * p.axis(k)) } else { 0.0 };
        self.st.modes.rpm_at(dia, MAX_RPM)
    }

    /// Spindle speed at the current position.
    fn rpm_here(&self) -> f64 {
        self.rpm_at(&self.st.place.pos)
    }

    /// The cutting feed of a move in mm/min, or the alarm that it has none. `point(u)` gives
    /// the tool position at fraction `u` of the path length. With feed per revolution under G96
    /// the spindle speed changes along the move; the feed returned is then the mean one
    /// (length / time), the time integrated over the path (Simpson's rule, 64 intervals).
    fn cutting_feed(&mut self, what: impl Into<What>, point: &dyn Fn(f64) -> Vec3) -> Result<f64, Diagnostic> {
        let f = self.checked_feed(what, point)?;
        // Feed per minute (the common case, every drilled hole): F, at most the limit.
        if !self.st.modes.per_rev {
            let max = self.params.feed_max_mm_min();
            if f > max {
                self.warn_clamped(f, max);
                return Ok(max);
            }
            return Ok(f);
        }
        let rule = self.cut_feed(f);
        let (feed, asked) = rule.mm_min(self.rpm_here(), point);
        if let Some(asked) = asked {
            self.warn_clamped(asked, rule.max_mm_min);
        }
        Ok(feed)
    }

    fn warn_clamped(&mut self, asked_mm_min: f64, max: f64) {
        self.warn(Rule::FeedClamped, self.span, format!("cutting feed {asked_mm_min:.1} mm/min is above the limit {max} mm/min: clamped"));
    }

    /// How the moves of this block get their feed ([`CutFeed`]), or the alarm that they have
    /// none (no F; feed per revolution with the spindle stopped); an implausible F is said
    /// once, of the move along `point`.
    fn feed_rule(&mut self, what: impl Into<What>, point: &dyn Fn(f64) -> Vec3) -> Result<CutFeed, Diagnostic> {
        let f = self.checked_feed(what, point)?;
        Ok(self.cut_feed(f))
    }

    /// F in force for a cutting move (in mm), or the alarm that there is none: no F, or feed per
    /// revolution with the spindle stopped; an implausible F is said once, of the move along
    /// `point`.
    fn checked_feed(&mut self, what: impl Into<What>, point: &dyn Fn(f64) -> Vec3) -> Result<f64, Diagnostic> {
        let what: What = what.into();
        let f = match self.st.modes.feed {
            Some(f) if f > 0.0 => f,
            _ => {
                return Err(self.alarm(Rule::FeedZero, self.span, format!("{} needs a feed: no F word greater than zero is in force", what.name(self.profile))))
            }
        };
        // A lathe F that is implausible in its mode (the check inline, the message cold).
        let implausible = if self.st.modes.per_rev { f > 10.0 } else { f < 10.0 };
        if implausible && self.profile.is_lathe() && self.st.notes.feed_warned != Some(self.st.modes.per_rev) {
            self.feed_plausible(f, point);
        }
        if self.st.modes.per_rev && self.rpm_here() == 0.0 {
            return Err(self.alarm(
                Rule::SpindleStopped,
                self.span,
                format!("{}: feed per revolution (F{} mm/rev) with the spindle stopped or at S0", what.name(self.profile), crate::alarm::shown(f, 4)),
            ));
        }
        Ok(f)
    }

    /// The feed rule of F in the modes in force.
    fn cut_feed(&self, f: f64) -> CutFeed {
        CutFeed {
            f,
            per_rev: self.st.modes.per_rev,
            max_mm_min: self.params.feed_max_mm_min(),
            spindle: self.st.modes.spindle_speed(MAX_RPM),
            css_axis: if self.st.modes.css { self.css_axis() } else { None },
        }
    }
}

impl Interpreter {
    pub fn new(params: Params, switches: Switches) -> Interpreter {
        let profile = params.profile();
        Interpreter {
            profile,
            state: Modal::power_on(profile),
            params,
            tables: Tables::none(profile),
            comp_queue: Vec::new(),
            corner_queue: Vec::new(),
            switches,
            collecting: None,
            contours: Vec::new(),
            replaying: false,
            nested_blocks: 0,
        }
    }

    /// Take the machine's tables from a setup (before the first block): the offsets, reference
    /// points and limits; the tool starts at the reference point.
    pub fn set_setup(&mut self, setup: &crate::setup::Setup) {
        self.tables = Tables::from_setup(setup, self.profile);
        if let Some(p) = self.tables.power_on_mm {
            self.state.place.pos = p - self.tables.to_machine(&self.state.frame);
        }
    }

    pub fn tables(&self) -> &Tables {
        &self.tables
    }

    /// Set system variable `number` where it names a table entry (`#2001 = 0.1`, `#5221 =
    /// -200.`): the table changes as G10 changes it, the tool staying where it is on the
    /// machine. `None` where the number names no table entry.
    pub fn write_table_variable(&mut self, number: i64, value: f64) -> Option<Result<(), String>> {
        Some(self.tables.variable_write(self.profile, number, value)?.map(|w| self.write_table(w)))
    }

    /// A table written (G10, a system variable): the tool stays where it is on the machine, so
    /// its programme coordinates move by what the write moved.
    fn write_table(&mut self, w: TableWrite) {
        let moved = self.tables.write(w, &self.state.frame);
        self.state.place.pos = self.state.place.pos - moved;
        if let Some(a) = self.state.comp.actual {
            self.state.comp.actual = Some(a - moved);
        }
    }
}

/// The overtravel alarm of a block whose move went beyond a soft limit.
fn overtravel_alarm(profile: &Profile, hit: (Span, usize, f64, f64, bool)) -> Diagnostic {
    let (span, axis, limit, at, upper) = hit;
    let scale = if axis == 0 && profile.diameter_x { 2.0 } else { 1.0 };
    let name = ["X", "Y", "Z"][axis];
    let (rule, side, bound) = if upper { (Rule::OvertravelPlus, "+", "upper") } else { (Rule::OvertravelMinus, "-", "lower") };
    let msg = format!(
        "{side}{name}: this block moves {name} to {:.3} in machine coordinates, beyond the soft limit {:.3} ({bound} end of [machine.limits] {}_mm)",
        at * scale,
        limit * scale,
        name.to_ascii_lowercase()
    );
    Diagnostic::new(rule, profile.alarm_style, span, msg)
}

impl Interpreter {
    pub fn profile(&self) -> &'static Profile {
        self.profile
    }

    pub fn params(&self) -> &Params {
        &self.params
    }

    pub fn switches(&self) -> Switches {
        self.switches
    }

    pub fn state(&self) -> &Modal {
        &self.state
    }

    /// A held-back thread run end is made now, with its pull-out: the input ended, or the next
    /// block alarmed (the controller finishes the thread it is cutting).
    pub fn flush_pending(&mut self) -> Outcome {
        let mut out = Outcome::default();
        self.flush_pending_into(&mut out);
        out
    }

    /// [`Interpreter::flush_pending`] into `out` (emptied first), reusing its allocations.
    pub fn flush_pending_into(&mut self, out: &mut Outcome) {
        self.flush_into(out, true);
    }

    /// [`Interpreter::flush_pending_into`] for the held thread run only: the machine stops (a
    /// single-block stop after a macro statement) but radius compensation keeps its look-ahead.
    pub fn flush_thread_into(&mut self, out: &mut Outcome) {
        self.flush_into(out, false);
    }

    /// A step over this interpreter's state and stages for the block at `span` (numbered `n`),
    /// its records into `out`. `cycle`: a cycle's moves made for the block (G70-G73), which
    /// bypass radius compensation and the thread repair position.
    fn step<'a>(&'a mut self, span: Span, n: Option<u32>, cycle: bool, out: &'a mut Outcome) -> Step<'a> {
        Step {
            profile: self.profile,
            params: &self.params,
            tables: &self.tables,
            queue: &mut self.comp_queue,
            corners: &mut self.corner_queue,
            bypass_comp: cycle,
            contour: false,
            repair: if cycle { None } else { self.switches.repair_position },
            span,
            n,
            st: &mut self.state,
            carry: None,
            marks: Marks::default(),
            out,
        }
    }

    fn flush_into(&mut self, out: &mut Outcome, with_comp: bool) {
        out.clear();
        if self.state.thread.pending.is_none() && (!with_comp || (self.comp_queue.is_empty() && self.corner_queue.is_empty())) {
            return;
        }
        let mut step = self.step(Span::default(), None, false, out);
        if let Some(p) = step.st.thread.take_some(|t| &mut t.pending) {
            step.bypass_comp = true;
            thread::flush(&mut step, p, true);
            step.bypass_comp = false;
        }
        // A line of an angle alone has no end: the next block alarmed (and said so), or the
        // input ended without M30 (W13). It is not made; what waited behind it still happens.
        let behind_line: Vec<Record> = match (with_comp, step.st.comp.angle_line.take()) {
            (true, Some(_)) => step.corners.drain(..).skip(1).collect(),
            _ => Vec::new(),
        };
        // The input ended (or the next block alarmed) in compensation: the held move ends
        // perpendicular.
        if with_comp {
            corner::break_off(&mut step);
            step.corners.clear();
            comp::break_off(&mut step);
            // A held move that cannot be made was the next block's alarm already (or, at the
            // end of the input, ends where the path stops): not told twice.
            step.out.comp_error = None;
            step.queue.clear();
        }
        for rec in behind_line {
            step.push_record(rec.span, rec.n, rec.op);
        }
        // The run has ended: a pull-out beyond a limit is told, with nothing left to stop.
        if let Some(hit) = out.overtravel.take() {
            let d = overtravel_alarm(self.profile, hit);
            out.warnings.push(d);
        }
    }

    /// The records both look-ahead stages hold (the corner stage's, compensation's), kept before
    /// a block so that a block that alarms changes nothing: none when both are empty (outside
    /// compensation, nearly always), else a copy of both behind one pointer. (One word on the
    /// stack: two `Option<Vec>` written field by field and read back whole stalled each block.)
    fn held(&self) -> Option<Box<[Vec<Record>; 2]>> {
        if self.comp_queue.is_empty() && self.corner_queue.is_empty() {
            return None;
        }
        Some(Box::new([self.comp_queue.clone(), self.corner_queue.clone()]))
    }

    /// Put back the modal state and the held records as they were before a block that alarmed.
    fn roll_back(&mut self, held: Option<Box<[Vec<Record>; 2]>>) {
        self.state.roll_back();
        let [comp, corners] = held.map_or_else(Default::default, |h| *h);
        self.comp_queue = comp;
        self.corner_queue = corners;
    }

    /// Execute one block. On an alarm nothing changes.
    pub fn execute(&mut self, block: &Block) -> Result<Outcome, Diagnostic> {
        let mut out = Outcome::default();
        self.execute_into(block, &mut out)?;
        Ok(out)
    }

    /// [`Interpreter::execute`] into `out` (emptied first), reusing its allocations; on an
    /// alarm `out` is left empty.
    pub fn execute_into(&mut self, block: &Block, out: &mut Outcome) -> Result<(), Diagnostic> {
        out.clear();
        if block.block_delete && self.switches.block_delete {
            return Ok(());
        }
        if self.collecting.is_some() {
            return self.collect_contour(block, out);
        }
        // A block inside a block (G70 runs its contour's blocks within its own) is part of the
        // outer block's transaction: only the outermost begins it and rolls it back, so an alarm
        // in a finishing pass puts back everything G70 changed.
        let outermost = self.nested_blocks == 0;
        let held_before = if outermost {
            self.state.begin_block();
            self.held()
        } else {
            None
        };
        self.nested_blocks += 1;
        let result = self.run_through_stages(block, out).and_then(|()| self.apply_effects(block, out));
        self.nested_blocks -= 1;
        if result.is_err() {
            out.clear();
            if outermost {
                self.roll_back(held_before);
            }
        }
        result
    }

    /// The block run, through the look-ahead stages (corners, compensation), with the alarms
    /// found only by moving (the motion cap, a soft limit, G22, a compensated path with no
    /// solution); its records marked where single block stops.
    fn run_through_stages(&mut self, block: &Block, out: &mut Outcome) -> Result<(), Diagnostic> {
        let (switches, replaying) = (self.switches, self.replaying);
        let mut step = self.step(block.span, block.sequence, false, out);
        let result = run_block(&mut step, block, switches).and_then(|()| {
            if step.out.emitted > MAX_MOTIONS_PER_BLOCK {
                return Err(step.alarm(
                    Rule::MotionLimit,
                    block.span,
                    format!("this block makes more than {MAX_MOTIONS_PER_BLOCK} motions (K repeats, pecks or passes too many): ncsight stops here"),
                ));
            }
            Ok(())
        });
        let result = result.and_then(|()| match step.out.flow {
            // GSK980TDi help text, G71 note 4 (G72, G73 likewise): no subprogramme call or
            // return in the contour blocks ns to nf.
            Some(Flow::Call { span, .. } | Flow::Return { span, .. }) if replaying => Err(Diagnostic::new(
                Rule::ContourCommand,
                step.profile.alarm_style,
                span,
                "M98 and M99 may not be used in the contour blocks ns to nf (GSK980TDi manual, G71 note 4)",
            )),
            _ => Ok(()),
        });
        // Compensation's block end and the stage's or the limits' alarm (rare: tested before
        // anything is moved).
        let mut result = result;
        if result.is_ok() && (!step.corners.is_empty() || step.st.modes.ended) {
            result = corner::end_of_block(&mut step);
        }
        if result.is_ok() && (!step.queue.is_empty() || step.st.modes.ended) {
            result = comp::end_of_block(&mut step);
        }
        if result.is_ok() {
            result = match step.out.comp_error.take() {
                Some(d) => Err(d),
                None => step.travel_alarm(),
            };
        }
        result?;
        // Single block stops after the block's last record (a held-back thread run end carries
        // its own mark). In radius compensation a block's move is made during a later block: each
        // block's last record made here is its end, unless a move of it is still held.
        if !step.out.comp_spans.is_empty() || !step.queue.is_empty() || !step.corners.is_empty() {
            // Marked: this block's last record and the last of each block whose moves the
            // compensation stage made here, unless a move of it is still held (a thread run left
            // open keeps its own mark). Backwards, once per span.
            let held: Vec<Span> = step.queue.iter().chain(step.corners.iter()).map(|r| r.span).collect();
            let mut wanted: Vec<Span> = step.out.comp_spans.clone();
            wanted.push(block.span);
            wanted.retain(|s| !held.contains(s));
            for r in step.out.records.iter_mut().rev() {
                if wanted.is_empty() {
                    break;
                }
                if let Some(k) = wanted.iter().position(|s| *s == r.span) {
                    r.block_end = true;
                    wanted.swap_remove(k);
                }
            }
        } else if let Some(deferred) = step.out.deferred.as_deref_mut() {
            // The deferred records end the block with their last, unless the block made records
            // after them (a trailing M code's): then the last of those, as on the ordinary path.
            let at = deferred.0.min(step.out.records.len());
            if let Some(last) = step.out.records[at..].iter_mut().rev().find(|r| r.span == block.span) {
                last.block_end = true;
                if let Deferred::Cuts(c) = &mut deferred.1 {
                    c.followed();
                }
            }
        } else if let Some(last) = step.out.records.iter_mut().rev().find(|r| r.span == block.span) {
            last.block_end = true;
        }
        Ok(())
    }

    /// What the block asks of the machine's tables and of the programme once it has run: a
    /// parameter line's values, G10's table write, a roughing's contour to collect, G70's
    /// contour to run (the caller rolls the block back if one of those alarms).
    fn apply_effects(&mut self, block: &Block, out: &mut Outcome) -> Result<(), Diagnostic> {
        // A parameter line: checked when it was read (frame::data_line).
        for (key, value) in out.param_writes.drain(..) {
            self.params.set(key, value).expect("checked by the parameter line");
        }
        // G10: the tables change; the tool stays where it is on the machine.
        if let Some(w) = out.table_write.take() {
            self.write_table(w);
        }
        if let Some(req) = out.rough_request.take() {
            if self.replaying {
                return Err(self.contour_alarm(
                    Rule::ContourCommand,
                    block.span,
                    format!("{} cannot run inside the contour that G70 is finishing", req.kind.code()),
                ));
            }
            self.collecting = Some((*req, Vec::new()));
        }
        if let Some(req) = out.finish_request.take() {
            self.finish_contour(req, out)?;
        }
        Ok(())
    }
}

/// How the cutting moves of one block get their feed: F in its mode and the spindle's speed,
/// fixed when the block is worked out (a cycle whose moves are made after it keeps this).
#[derive(Debug, Clone, Copy)]
pub(crate) struct CutFeed {
    f: f64,
    per_rev: bool,
    max_mm_min: f64,
    spindle: crate::modal::SpindleSpeed,
    /// The axis G96 takes the radius from ([`Step::css_axis`]).
    css_axis: Option<usize>,
}

impl CutFeed {
    fn rpm_at(&self, p: &Vec3) -> f64 {
        self.spindle.rpm_at(self.css_axis.map_or(0.0, |k| 2.0 * p.axis(k)))
    }

    /// The feed of a move along `point` (fraction of the path to position) starting where the
    /// spindle turns at `rpm_start`, and the feed asked for when the limit clamped it. Under
    /// G96 with feed per revolution the mean feed (length / time, the time integrated over the
    /// path by Simpson's rule, 64 intervals), each point's feed at most the limit.
    fn mm_min(&self, rpm_start: f64, point: &dyn Fn(f64) -> Vec3) -> (f64, Option<f64>) {
        let max = self.max_mm_min;
        let mut feed = self.f;
        if self.per_rev {
            feed = self.f * rpm_start.abs();
            if self.spindle.css() {
                const N: usize = 64;
                let feed_at = |rpm: f64| (self.f * rpm.abs()).min(max);
                let mut sum = 0.0;
                for i in 0..=N {
                    let w = if i == 0 || i == N {
                        1.0
                    } else if i % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    };
                    sum += w / feed_at(self.rpm_at(&point(i as f64 / N as f64)));
                }
                let mean_inverse = sum / (3.0 * N as f64);
                return (1.0 / mean_inverse, None);
            }
        }
        if feed > max {
            return (max, Some(feed));
        }
        (feed, None)
    }

    /// The feed asked for and the limit, when the limit clamps every move (not under G96 with
    /// feed per revolution, whose feed follows the diameter).
    fn clamped(&self) -> Option<(f64, f64)> {
        if self.per_rev && self.spindle.css() {
            return None;
        }
        let asked = if self.per_rev { self.f * self.spindle.rpm_at(0.0).abs() } else { self.f };
        (asked > self.max_mm_min).then_some((asked, self.max_mm_min))
    }

    /// A cycle's move with its feed (a feed's or an arc's; anything else as it is), and the
    /// feed asked for when the limit clamped it.
    fn apply(&self, op: Op) -> (Op, Option<f64>) {
        match op {
            Op::Feed { from, to, .. } => {
                let (feed_mm_min, asked) = self.mm_min(self.rpm_at(&from), &|u| lerp(&from, &to, u));
                (Op::Feed { from, to, feed_mm_min }, asked)
            }
            Op::Arc { from, to, center, plane, dir, .. } => {
                let (feed_mm_min, asked) = match crate::geom::arc_geom_of(&op) {
                    Some(g) => self.mm_min(self.rpm_at(&from), &|u| geom::arc_point(&from, &to, plane, dir, &g, u)),
                    None => self.mm_min(self.rpm_at(&from), &|u| lerp(&from, &to, u)),
                };
                (Op::Arc { from, to, center, plane, dir, feed_mm_min }, asked)
            }
            other => (other, None),
        }
    }
}

/// The G and M codes of a block, and its other words into `words` (filled in place: the table
/// is not moved once written), checking addresses and duplicates.
#[allow(clippy::type_complexity)]
fn collect<'w>(
    step: &mut Step,
    all: &'w [Word],
    words: &mut Words<'w>,
) -> Result<(Vec<(&'w Word, &'static GDef)>, Vec<(&'w Word, Option<&'static MDef>)>), Diagnostic> {
    let profile = step.profile;
    let mut gs = Vec::new();
    let mut ms = Vec::new();
    // A code not simulated yet answers for its block: its own words (G65's H, G10's L) are not
    // judged by the rules of the codes that are. Looked at only when a letter is not read.
    let not_yet = || {
        all.iter().any(|w| {
            w.letter == b'G'
                && !w.expr
                && w.value >= 0.0
                && w.is_code()
                && matches!(profile.g_code(w.code().0, w.code().1).map(|g| g.function), Some(GFn::NotYet(_)))
        })
    };
    // G32.1 in the block, or in force.
    let rigid_block = || {
        let rigid = GFn::Thread(crate::profile::ThreadCmd::Rigid);
        let motion_code = codes_of(profile, all).filter(|g| g.group == Group::Motion).last();
        match motion_code {
            Some(g) => g.function == rigid,
            None => step.st.modes.motion == Motion::Thread(crate::profile::ThreadCmd::Rigid),
        }
    };
    for (i, w) in all.iter().enumerate() {
        let letter = w.letter;
        // In G12.1 the hypothetical C is read as the plane's Y (V incremental; interp/polar.rs).
        let hypothetical = step.st.modes.polar_interp.is_some() && matches!(letter, b'Y' | b'V');
        // The GSK980TDi's G32.1 gives its start angle with C (help text G32.1), C axis or not.
        let rigid_start = letter == b'C' && profile.thread.g32_1.start_c && rigid_block();
        // FANUC 0i-TF 3405#4 CCR = 1: A and C are the drawing's words, without the comma.
        let plain_drawing = matches!(letter, b'A' | b'C') && step.plain_drawing();
        if !profile.takes_address(letter) && !step.tables.added_addresses.contains(letter) && !hypothetical && !rigid_start && !plain_drawing && !not_yet() {
            return Err(improper_address(step, w));
        }
        match letter {
            b'G' => {
                if w.value < 0.0 || w.expr {
                    return Err(step.alarm(Rule::ImproperGCode, w.span, format!("{}: not a G code", w.text())));
                }
                if !w.is_code() {
                    return Err(step.alarm(Rule::ImproperGCode, w.span, format!("{}: a G code has at most one digit after the point", w.text())));
                }
                let (major, minor) = w.code();
                match profile.g_code(major, minor) {
                    Some(g) => gs.push((w, g)),
                    None => {
                        // GSK: a G code written with a point is an alarm unless the code has one
                        // (988T p43); FANUC likewise.
                        let msg = if minor.is_some() && profile.g_code(major, None).is_some() {
                            format!("G{major:02}.{}: a G code may not be written with a decimal point", minor.unwrap())
                        } else {
                            format!("{}: no such G code on {}", w.text(), profile.name)
                        };
                        let d = step.alarm(Rule::ImproperGCode, w.span, msg);
                        let simulated = |p: &Profile| p.g_code(major, minor).is_some_and(|g| !matches!(g.function, GFn::NotYet(_)));
                        // A code of another G-code system of a profile (a FANUC lathe's B or C).
                        if let Some(hint) = other_system(profile, &simulated) {
                            return Err(d.with_hint(format!("{} is a code of {hint}", w.text())));
                        }
                        // A machining centre's code on a lathe (or the reverse): the other kind's profiles.
                        return Err(match other_kind(profile, simulated) {
                            Some((kind, names)) => {
                                d.with_hint(format!("{} is a code of the {kind} profiles ({names}): a {kind} programme? choose one with --machine", w.text()))
                            }
                            None => d,
                        });
                    }
                }
            }
            b'M' => {
                if w.decimal || w.value < 0.0 {
                    return Err(step.alarm(Rule::IllegalDecimalPoint, w.span, format!("{}: an M code is a whole number", w.text())));
                }
                ms.push((w, profile.m_code(w.value as u32)));
            }
            _ => {
                if let Some(old) = words.insert(i) {
                    return Err(step.alarm(
                        Rule::DuplicateWord,
                        w.span,
                        format!("address {} appears twice in the block ({} and {})", crate::read::address_name(letter), old.text(), w.text()),
                    ));
                }
            }
        }
    }
    if !step.tables.assumed_axes.is_empty() {
        for w in all {
            assumed_axis_word(step, w);
        }
    }
    Ok((gs, ms))
}

/// The first word of an axis the profile assumes without a setup (C, H, Y, V on a turning
/// centre): a warning that it was taken as the machine's axis.
fn assumed_axis_word(step: &mut Step, w: &Word) {
    let axis = match w.letter {
        b'H' => b'C',
        b'V' => b'Y',
        l => l,
    };
    // Under 3405#4 CCR = 1 a plain C is the drawing's chamfer, not an axis.
    let chamfer_c = axis == b'C' && step.plain_drawing();
    if step.tables.assumed_axes.contains(axis) && step.tables.added_addresses.contains(w.letter) && !step.st.notes.assumed_warned.contains(axis) && !chamfer_c {
        step.st.notes.assumed_warned = step.st.notes.assumed_warned.with(axis);
        let kind = if axis == b'C' { "a rotary C axis in degrees, H its incremental address" } else { "a linear Y axis, V its incremental address" };
        let msg = format!("{}: no setup says which axes the machine has: taken as {kind}; declare them with [machine] axes (docs/setup.md)", w.text());
        step.warn(Rule::AxisAssumed, w.span, msg);
    }
}

/// A word whose address this controller does not read: the alarm, with how this controller
/// writes a drawing dimension when the word is FANUC's comma one.
fn improper_address(step: &Step, w: &Word) -> Diagnostic {
    let (profile, letter) = (step.profile, w.letter);
    let d = step.alarm(
        Rule::ImproperAddress,
        w.span,
        if matches!(letter, b'A' | b'B' | b'C' | b'Y') {
            format!(
                "address {} is not used on {} ({}): a machine with this axis declares it in the setup ([machine] axes)",
                letter as char,
                profile.name,
                w.text()
            )
        } else {
            format!("address {} is not used on {} ({})", crate::read::address_name(letter), profile.name, w.text())
        },
    );
    // Y on a lathe: a turning centre's Y axis, or a machining centre's programme.
    if letter == b'Y' {
        if let Some((kind, names)) = other_kind(profile, |p| p.axes.contains('Y')) {
            return d.with_hint(format!("a {kind} programme? choose one of {names} with --machine"));
        }
    }
    // A comma word is FANUC's drawing dimensions: say how this controller writes them.
    if letter.is_ascii_lowercase() {
        d.with_hint(match profile.frame.drawing {
            Some(r) => format!(
                "{} writes a chamfer as {}, a corner arc as {} and a line's angle as {} (docs/commands/drawing.md)",
                profile.name,
                crate::read::address_name(r.chamfer),
                crate::read::address_name(r.round),
                crate::read::address_name(r.angle)
            ),
            None => "',A', ',C' and ',R' are FANUC's drawing dimensions; this controller has none: program the corner's moves".to_string(),
        })
    } else {
        d
    }
}

/// The profiles of the other kind (machining centres for a lathe, lathes for a machining
/// centre) that `has` something this profile lacks: the kind's name and theirs, for a hint that
/// the programme may be for the other kind of machine.
fn other_kind(profile: &Profile, has: impl Fn(&Profile) -> bool) -> Option<(&'static str, String)> {
    let names: Vec<&str> = crate::profile::all().into_iter().filter(|p| p.kind != profile.kind && has(p)).map(|p| p.name).collect();
    let kind = if profile.is_lathe() { "machining centre" } else { "lathe" };
    (!names.is_empty()).then(|| (kind, names.join(", ")))
}

/// The G-code systems (B, C) of the profiles of this kind that `has` something: where and how
/// to choose it, for a hint (a lathe programme written in G-code system B, say).
fn other_system(profile: &Profile, has: &dyn Fn(&Profile) -> bool) -> Option<String> {
    let found: Vec<String> = crate::profile::all()
        .into_iter()
        .filter(|p| p.kind == profile.kind)
        .filter_map(|p| {
            let s = p.g_code_systems?;
            let systems: Vec<String> = [("B", s.profile_b, s.b), ("C", s.profile_c, s.c)]
                .into_iter()
                .filter(|(_, v, _)| has(v))
                .map(|(n, _, key)| format!("{n} (--param {key}=1)"))
                .collect();
            (!systems.is_empty()).then(|| format!("{} in G-code system {}", p.name, systems.join(" or ")))
        })
        .collect();
    (!found.is_empty()).then(|| format!("{}: a programme written for that system? choose it with --machine and --param", found.join(", ")))
}

/// What one block asks for after its G codes are sorted.
#[derive(Default)]
struct Codes {
    non_modal: Option<(Span, GFn)>,
    motion: Option<(Span, Motion)>,
    /// A drilling cycle code in this block.
    drill: Option<crate::cycles::drill::DrillKind>,
    /// G40 (0), G41 (+1), G42 (-1) in this block.
    comp: Option<(Span, i8)>,
    /// G54-G59 in this block (1-6).
    work: Option<u8>,
    /// G54.1 in this block (its P read when the work system is selected).
    work_additional: Option<Span>,
    /// G68/G69, G51.1/G50.1, G51/G50 and G22/G23 in this block, in order.
    transforms: Vec<(Span, GFn)>,
    /// G12.1, G13.1 or G07.1 in this block.
    polar_interp: Option<(Span, GFn)>,
}

/// One block, in the order the controller executes it (the steps as grbl's `gc_execute_line`
/// numbers them, for these controllers). Every step may alarm; the caller restores the modal
/// state then, so a block that alarms changes nothing.
///
///  1. Collect the words: addresses the profile reads, each once; G and M codes from its tables.
///  2. G codes: the last of a modal group counts; one-shot codes not mixed; a code not simulated
///     yet, or G27-G30 in a drilling cycle, alarms.
///  3. Modal codes take effect (plane, units, distance, feed mode, surface speed, compensation,
///     return level, cycle cancel); the motion code and the drilling code are noted.
///  4. What a new motion mode cancels: the rigid thread's J/K, the cycles' memories, a drilling
///     cycle (as G80).
///  5. A held-back thread run: this block continues it or it ends (with its pull-out).
///  6. H and D words of the compensation codes.
///  7. F, S (G50 S: the clamp), T (a tool record on a lathe).
///  8. M codes that act before the motion: the spindle, its mode, rigid tapping, subprogrammes.
///  9. A spindle record when the spindle's state changes.
/// 10. The one-shot code (G04, G28, G50/G92, G70-G76, G74/G75), or else the motion of the
///     mode in force: drilling cycle, thread, box cycle, G00-G03.
/// 11. M codes that act after the motion (stops, ends), then every word must have been used.
fn run_block(step: &mut Step, block: &Block, switches: Switches) -> Result<(), Diagnostic> {
    // Between G10 L3/L50/L52 and G11 a block is a line of data.
    if let Some(mode) = step.st.modes.data_input {
        return frame::data_line(step, block, mode);
    }
    let mut read_as = ReadAs::default();
    let all = block_words(step, block, &mut read_as)?;
    // 1. Collect the words.
    let mut words = Words::new(all);
    let (gs, ms) = collect(step, all, &mut words)?;
    // 2. G codes.
    let last_of = sort_g_codes(step, &gs)?;
    suspend_compensation(step, &last_of, &words);
    // 3. Modal codes.
    // Filled in place: returned by value, its fields written one by one were read back whole.
    let mut codes = Codes::default();
    modal_codes(step, block, &last_of, &mut codes)?;
    rigid_tap_waits(step, &codes, &words)?;
    // 4. What a new motion mode cancels.
    cancel_by_motion(step, &codes);
    let motion_now = codes.motion.map(|(_, m)| m).unwrap_or(step.st.modes.motion);
    let axis_letters: &[u8] = if step.profile.incremental_addresses { b"XYZUVW" } else { b"XYZ" };
    let has_axis = axis_letters.iter().any(|l| words.has(*l));
    // 5. A held-back thread run.
    let run_deg = held_thread_run(step, &codes, ms.is_empty(), &words, motion_now, has_axis);
    if let Some(n) = codes.work {
        frame::select_work(step, n);
    }
    if let Some(span) = codes.work_additional {
        frame::select_additional_work(step, &mut words, span)?;
    }
    // 6. H and D.
    offset_words(step, &last_of, &codes, &mut words, motion_now, has_axis)?;
    // 7. F, S, T.
    let thread_block = matches!(motion_now, Motion::Thread(_)) && has_axis && codes.non_modal.is_none();
    feed_word(step, &codes, &mut words, thread_block)?;
    select_spindle(step, &codes, &ms, &mut words, thread_block)?;
    let spindle_before = speed_word(step, &codes, &last_of, &mut words, motion_now)?;
    tool_word(step, &mut words, has_axis)?;
    // 8, 9. M codes before the motion, a spindle record.
    let after = m_codes_before(step, &ms, &mut words, spindle_before)?;
    // 10, 11.
    motion_of_block(step, &mut words, &codes, after, switches, has_axis, run_deg)
}

/// Where a block's words are kept when they are read otherwise than written (step 0 of
/// [`run_block`]).
#[derive(Default)]
struct ReadAs {
    /// In G12.1: the hypothetical C axis's words as the plane's Y.
    plane: Vec<Word>,
    /// Under G16: the radius and angle as the X, Y, Z words they stand for.
    polar: Vec<Word>,
}

/// Step 0 of [`run_block`]: the words the block is read with.
#[inline(always)]
fn block_words<'a>(step: &mut Step, block: &'a Block, read_as: &'a mut ReadAs) -> Result<&'a [Word], Diagnostic> {
    // 0. Under G16 the plane's two words are a radius and an angle: the block is read with the
    // X, Y, Z words they stand for (not in a block that sets or ends a transform, or G15's own).
    // The block's own G16/G15, G90/G91 and plane count: its words are read in its modes.
    let (mut incremental, mut plane, mut polar_on) = (step.st.modes.incremental, step.st.modes.plane, step.st.transform.polar);
    for g in codes_of(step.profile, &block.words) {
        match g.function {
            GFn::Absolute => incremental = false,
            GFn::Incremental => incremental = true,
            GFn::PlaneXY => plane = Plane::XY,
            GFn::PlaneZX => plane = Plane::ZX,
            GFn::PlaneYZ => plane = Plane::YZ,
            GFn::PolarCoordinates(on) => polar_on = on,
            _ => {}
        }
    }
    if polar_on && !step.st.transform.polar {
        // G16 in this block: its words are polar already, from a radius and angle of 0.
        step.st.transform.polar = true;
        step.st.transform.polar_radius = 0.0;
        step.st.transform.polar_angle_deg = 0.0;
    }
    // In G12.1 the hypothetical C is the plane's Y (interp/polar.rs).
    let ReadAs { plane: plane_store, polar: polar_store } = read_as;
    let block_words: &'a [Word] = if step.st.modes.polar_interp.is_some() {
        *plane_store = polar::plane_words(step, &block.words)?;
        plane_store
    } else {
        &block.words
    };
    if polar_on && polar_reads(step, block) {
        if let Some(w) = transform::polar_words(step, block_words, incremental, plane)? {
            *polar_store = w;
            return Ok(polar_store);
        }
    }
    Ok(block_words)
}

/// Step 2 of [`run_block`]: the G codes sorted, the last of a modal group counting; the codes
/// that may not share a block, or not run here, alarm.
#[allow(clippy::type_complexity)]
#[inline(always)]
fn sort_g_codes<'w>(step: &mut Step, gs: &[(&'w Word, &'static GDef)]) -> Result<Vec<(Group, &'w Word, &'static GDef)>, Diagnostic> {
    let profile = step.profile;
    // 2. G codes: the last of a group counts (GSK: TAC p65; FANUC the same); a warning says so.
    let mut last_of: Vec<(Group, &'w Word, &'static GDef)> = Vec::new();
    for &(w, g) in gs {
        if let Some(slot) = last_of.iter_mut().find(|(grp, _, _)| *grp == g.group && g.group != Group::NonModal) {
            let msg = format!("{} and {} are in one modal group: {} counts", slot.1.text(), w.text(), w.text());
            step.warn(Rule::SameGroupTwice, w.span, msg);
            *slot = (g.group, w, g);
        } else {
            last_of.push((g.group, w, g));
        }
        if matches!(g.function, GFn::ReferenceReturn | GFn::OtherReferenceReturn | GFn::FromReference | GFn::ReferenceCheck)
            && profile.reference_in_canned_cycle_alarm
            && step.st.drill.kind.is_some()
            // G80, or a group 01 code, in the same block cancels the cycle first (inferred: a
            // group 01 code cancels a drilling cycle as G80 does, FANUC 0-M manual, 8.1.4).
            && !gs.iter().any(|(_, g)| g.function == GFn::CycleCancel || g.group == Group::Motion)
        {
            // FANUC alarm 0044: cancel the drilling cycle (G80) before G27-G30.
            return Err(step.alarm(
                Rule::ReferenceInCannedCycle,
                w.span,
                format!("{}: a reference-point return while a drilling canned cycle is in force; cancel it with G80 first", w.text()),
            ));
        }
        // FANUC 0i-T manual: the codes a block may use in polar coordinate interpolation.
        if step.st.modes.polar_interp.is_some() && !polar::allowed(g.function) {
            return Err(step.alarm(
                Rule::ImproperGCode,
                w.span,
                format!(
                    "{}: in polar coordinate interpolation (G12.1) a block may use G01, G02, G03, G04, G40-G42, G65-G67, G98, G99 and G13.1 only",
                    w.text()
                ),
            ));
        }
        if let GFn::NotYet(why) = g.function {
            return Err(step.alarm(Rule::NotSupported, w.span, format!("{} ({}): {why}", w.text(), g.meaning)));
        }
        // The programme runs G65 before a block reaches the interpreter: one that comes here is
        // inside a G70-G73 contour (GSK980TDi help text, G71 note 4: no calls there).
        if matches!(g.function, GFn::MacroCall | GFn::ModalMacroCall | GFn::ModalMacroCancel) {
            return Err(step.alarm(Rule::ContourCommand, w.span, format!("{}: a macro call may not be used in the contour blocks ns to nf", w.text())));
        }
    }
    let non_modal: Vec<_> = last_of.iter().filter(|(g, _, _)| *g == Group::NonModal).collect();
    if non_modal.len() > 1 {
        let (_, w, _) = non_modal[1];
        return Err(step.alarm(
            Rule::GroupConflict,
            w.span,
            format!("{} and {}: two one-shot (group 00) G codes in one block", non_modal[0].1.text(), w.text()),
        ));
    }
    if profile.group00_with_01_alarm {
        if let (Some((_, w0, _)), Some((_, w1, _))) = (non_modal.first(), last_of.iter().find(|(g, _, _)| *g == Group::Motion)) {
            // GSK: group 00 and group 01 may not share a block (TAC p65).
            return Err(step.alarm(
                Rule::GroupConflict,
                w1.span,
                format!("{} and {}: a group 00 and a group 01 G code may not share a block on {}", w0.text(), w1.text(), profile.name),
            ));
        }
    }
    Ok(last_of)
}

/// Radius compensation and the corner stage before a block that suspends them (step 2 of
/// [`run_block`]).
#[inline(always)]
fn suspend_compensation(step: &mut Step, last_of: &[(Group, &Word, &'static GDef)], words: &Words) {
    let profile = step.profile;
    // Radius compensation acts on plain moves only: a block with a cycle, a thread, a reference
    // return, a coordinate change or a T word runs uncompensated; the compensated path ends
    // before it (GSK980TDi help text, G40-G42 notes 5-6; FANUC threading likewise, inferred).
    // A chamfer's held move is made before the plane or the C-axis interpolation changes.
    if !step.corners.is_empty()
        && last_of
            .iter()
            .any(|(_, _, g)| matches!(g.function, GFn::PolarInterpolation(_) | GFn::CylindricalInterpolation | GFn::PlaneXY | GFn::PlaneZX | GFn::PlaneYZ))
    {
        corner::break_off(step);
    }
    if step.st.comp.side != 0 || !step.queue.is_empty() || !step.corners.is_empty() {
        let suspends = |f: GFn| f.suspends_compensation();
        let plain_motion = last_of.iter().any(|(_, _, g)| matches!(g.function, GFn::Rapid | GFn::Linear | GFn::ArcCw | GFn::ArcCcw));
        let mode_suspends = !plain_motion && (matches!(step.st.modes.motion, Motion::Thread(_) | Motion::Box(_)) || step.st.drill.kind.is_some());
        if let Some((_, w, g)) = last_of.iter().find(|(_, _, g)| suspends(g.function)) {
            corner::break_off(step);
            comp::break_off(step);
            step.bypass_comp = true;
            // G71-G73 cancel the mode on the GSK (the finishing shape's first block starts it
            // again); G70 runs its contour's blocks in compensation (they are moves of their own).
            let in_cycle = profile.frame.compensation_in(g.function);
            if in_cycle == CompInCycle::Cancelled {
                step.st.comp.side = 0;
                step.st.comp.started = false;
            }
            if g.function.is_canned_cycle() && step.st.comp.side != 0 && in_cycle == CompInCycle::Suspended {
                let msg = format!("{}: radius compensation is suspended in this cycle: its moves are the programmed ones (docs/compensation.md)", w.text());
                step.warn(Rule::NotSimulated, w.span, msg);
            }
        } else if mode_suspends || words.has(b'T') {
            // Outside compensation a T block without a move waits behind the corner stage's held
            // move, as an M code does, its records too (a line of an angle alone allows one such
            // block: docs/commands/drawing.md). In compensation it ends the compensated path:
            // the held move is made first.
            if mode_suspends || step.st.comp.side != 0 || b"XYZUVW".iter().any(|l| words.has(*l)) {
                corner::break_off(step);
            }
            comp::break_off(step);
            step.bypass_comp = true;
        }
    }
}

/// Step 3 of [`run_block`]: the modal codes take effect; the motion and drilling codes and
/// the others acted on later are noted.
#[inline(always)]
fn modal_codes(step: &mut Step, block: &Block, last_of: &[(Group, &Word, &'static GDef)], codes: &mut Codes) -> Result<(), Diagnostic> {
    let profile = step.profile;
    // 3. Modal codes take effect; the motion and drilling codes are noted.
    note_last_words(step.st, block);
    // GSK980TDi help text, G54-G59 note 6: with G50 in the block, G54-G59 are void.
    let set_wins = profile.frame.coordinate_set_wins && last_of.iter().any(|(_, _, g)| matches!(g.function, GFn::LatheCoordinateSet | GFn::MillCoordinateSet));
    for &(_, w, g) in last_of {
        if set_wins && matches!(g.function, GFn::WorkOffset(_) | GFn::AdditionalWorkOffset) {
            continue;
        }
        let st = &mut step.st;
        if g.group != Group::NonModal {
            st.notes.group_codes[g.group as usize] = (w.value * 10.0).round() as u16;
        }
        // G63 holds until another code of its group (G61, G62, G64). A tap in cutter
        // compensation is not simulated: the held moves would take the wrong block's rules.
        if g.function == GFn::TappingMode && st.comp.side != 0 {
            return Err(step.alarm(
                Rule::NotSupported,
                w.span,
                format!("{}: tapping mode in cutter compensation (G41/G42) is not simulated: G40 first", w.text()),
            ));
        }
        if g.group == Group::PathMode {
            st.modes.tapping_mode = g.function == GFn::TappingMode;
            st.comp.corner_override = g.function == GFn::CornerOverride;
        }
        match g.function {
            GFn::Rapid => codes.motion = Some((w.span, Motion::Rapid)),
            GFn::Linear => codes.motion = Some((w.span, Motion::Linear)),
            GFn::ArcCw => codes.motion = Some((w.span, Motion::ArcCw)),
            GFn::ArcCcw => codes.motion = Some((w.span, Motion::ArcCcw)),
            GFn::Thread(cmd) => codes.motion = Some((w.span, Motion::Thread(cmd))),
            GFn::BoxCycle(kind) => codes.motion = Some((w.span, Motion::Box(kind))),
            GFn::Curve(kind) => codes.motion = Some((w.span, Motion::Curve(kind))),
            GFn::PlaneXY | GFn::PlaneZX | GFn::PlaneYZ => set_plane(step, w, g.function)?,
            GFn::Inch => st.modes.inch = true,
            GFn::Metric => st.modes.inch = false,
            GFn::Absolute => st.modes.incremental = false,
            GFn::Incremental => st.modes.incremental = true,
            GFn::FeedPerMinute => st.modes.per_rev = false,
            GFn::FeedPerRevolution => st.modes.per_rev = true,
            GFn::ConstantSurfaceSpeed => st.modes.css = true,
            GFn::ConstantRpm => st.modes.css = false,
            // Step 6 puts it in force, with the block's D.
            GFn::RadiusComp(side) => codes.comp = Some((w.span, side)),
            // After step 5: a thread run held back from the block before is made in its frame.
            GFn::WorkOffset(n) => codes.work = Some(n),
            GFn::AdditionalWorkOffset => codes.work_additional = Some(w.span),
            // Step 6 puts the length offset in force, with the H of the block.
            // G62 slows inner corners in cutter compensation (interp/comp.rs).
            GFn::LengthComp(_) | GFn::PathControl | GFn::TappingMode | GFn::CornerOverride => {}
            GFn::Rotation(_) | GFn::MirrorImage(_) | GFn::TurretMirror(_) | GFn::Scaling(_) | GFn::StrokeCheck(_) => {
                codes.transforms.push((w.span, g.function))
            }
            // Step 0 turned it on (from a radius and angle of 0) before reading the block.
            GFn::PolarCoordinates(on) => {
                // On a lathe G16 is the polar interpolation plane's (GSK980TDi help text,
                // G12.1/13.1: G15/G16 in that plane).
                if on && profile.is_lathe() && st.modes.polar_interp.is_none() {
                    return Err(step.alarm(
                        Rule::PlaneMismatch,
                        w.span,
                        format!("{}: polar coordinate command on a lathe is for the polar interpolation plane: G12.1 first", w.text()),
                    ));
                }
                st.transform.polar = on;
            }
            GFn::PolarInterpolation(_) | GFn::CylindricalInterpolation => codes.polar_interp = Some((w.span, g.function)),
            GFn::ReturnInitial => st.modes.return_initial = true,
            GFn::ReturnR => st.modes.return_initial = false,
            // G80: the cycle and its hole data end; F stays (seed 003 8.1.4).
            GFn::CycleCancel => *step.st.drill = Default::default(),
            GFn::Drill(kind) => {
                codes.drill = Some(kind);
                // The GSK lathe's G83/G87 (and G84/G88) are group 01 codes: they end the motion
                // mode in force (its thread and box-cycle memories with it); G80 then leaves G00
                // (docs).
                if kind.ends_motion_mode() {
                    codes.motion = Some((w.span, Motion::Rapid));
                }
            }
            GFn::NotYet(_) | GFn::MacroCall | GFn::ModalMacroCall | GFn::ModalMacroCancel => unreachable!("rejected above"),
            // What is left is the block's one-shot command, run by `one_shot` in step 10 (a new
            // modal function needs its own arm above, else it is taken for a one-shot one and
            // `one_shot` answers that ncsight has no block function for it).
            f => codes.non_modal = Some((w.span, f)),
        }
    }
    Ok(())
}

/// The words a macro reads back (#4102-#4113) of this block.
#[inline(always)]
fn note_last_words(st: &mut crate::modal::Modal, block: &Block) {
    // Only a block with one of these words changes (and saves) the notes.
    for w in block.words.iter().filter(|w| matches!(w.letter, b'B' | b'D' | b'E' | b'H' | b'M')) {
        let last = &mut st.notes.last_words;
        match w.letter {
            b'B' => last.b = Some(w.value),
            b'D' => last.d = Some(w.value),
            b'E' => last.e = Some(w.value),
            b'H' => last.h = Some(w.value),
            _ => last.m = Some(w.value),
        }
    }
}

/// G17, G18, G19: the plane, unless compensation or a rotation holds it (step 3 of
/// [`run_block`]).
fn set_plane(step: &mut Step, w: &Word, function: GFn) -> Result<(), Diagnostic> {
    let st = &mut *step.st;
    let plane = match function {
        GFn::PlaneXY => Plane::XY,
        GFn::PlaneZX => Plane::ZX,
        _ => Plane::YZ,
    };
    // FANUC 037; GSK980TDi help text, G17-G19 (no plane change in compensation).
    if st.comp.side != 0 && plane != st.modes.plane {
        return Err(step.alarm(
            Rule::CompPlaneChange,
            w.span,
            format!("{}: the plane cannot change while radius compensation is in force (G40 first)", w.text()),
        ));
    }
    // FANUC: no plane change in coordinate rotation (G69 first).
    if st.transform.rotation.is_some_and(|r| r.plane != plane) {
        return Err(step.alarm(
            Rule::NotSupported,
            w.span,
            format!("{}: a plane change under coordinate rotation (G68) is not simulated: G69 first", w.text()),
        ));
    }
    st.modes.plane = plane;
    Ok(())
}

/// Help text G84/88: no axis move between M29 and the G84/G88 block (a dwell's X is a time).
#[inline(always)]
fn rigid_tap_waits(step: &mut Step, codes: &Codes, words: &Words) -> Result<(), Diagnostic> {
    let profile = step.profile;
    let dwell_block = matches!(codes.non_modal, Some((_, GFn::Dwell)));
    if step.st.drill.tap_waiting && !dwell_block && !codes.drill.is_some_and(|k| k.rigid_tap()) {
        let axes: &[u8] = if profile.incremental_addresses { b"XYZUVW" } else { b"XYZ" };
        if axes.iter().any(|l| words.has(*l)) {
            return Err(step.alarm(Rule::RigidTapOrder, step.span, "an axis move between M29 and G84/G88 (help text G84/88: none may come between them)"));
        }
    }
    Ok(())
}

/// Step 4 of [`run_block`]: what a new motion mode cancels.
#[inline(always)]
fn cancel_by_motion(step: &mut Step, codes: &Codes) {
    // 4. What a new motion mode cancels. A non-thread group 01 code cancels the thread J/K and
    // the cycle memory (seed 001 G32.1 note 1).
    if let Some((_, m)) = codes.motion {
        if !matches!(m, Motion::Thread(_)) {
            // Seed 001 G32.1 note 1: a non-thread code cancels the rigid commands' J/K. Seed 000
            // and the G32 help only call J/K modal: they stay for G32 and G92 (docs).
            if matches!(step.st.modes.motion, Motion::Thread(cmd) if thread::is_rigid(cmd)) {
                step.st.thread.j = None;
                step.st.thread.k = None;
            }
            step.st.thread.cycle_end = None;
            step.st.thread.repair = false;
        }
        // Another group 01 code, or the other box cycle, ends the remembered X, Z and R.
        if m != step.st.modes.motion {
            step.st.memory.box_cycle = Default::default();
        }
        // A group 01 code cancels a drilling cycle as G80 does (seed 003 8.1.4); a GSK lathe
        // cycle restated keeps its data, another one starts afresh (its bottom is on another
        // axis).
        if !codes.drill.is_some_and(|k| k.ends_motion_mode() && step.st.drill.kind == Some(k)) {
            let before = step.st.drill;
            *step.st.drill = Default::default();
            if codes.drill.is_some_and(|k| k.rigid_tap()) {
                // M29's rigid tapping mode is for the G84/G88 that follows; between G84 and G88
                // only the bottom is to be given again (note 1): the hand and P stay.
                step.st.drill.rigid_tap = before.rigid_tap;
                step.st.drill.tap_waiting = before.tap_waiting;
                if before.kind.is_some_and(|k| k.rigid_tap()) {
                    step.st.drill.tap_left = before.tap_left;
                    step.st.drill.dwell_s = before.dwell_s;
                }
            }
        }
    }
}

/// Step 5 of [`run_block`]: a held-back thread run end is made, or this block continues the
/// run (the angle it continues from, then).
#[inline(always)]
fn held_thread_run(step: &mut Step, codes: &Codes, no_m_codes: bool, words: &Words, motion_now: Motion, has_axis: bool) -> Option<f64> {
    // 5. A held-back thread run end: does this block continue the run?
    let mut run_deg = None;
    if let Some(p) = step.st.thread.take_some(|t| &mut t.pending) {
        let goes_on = match motion_now {
            Motion::Thread(cmd) => has_axis && codes.non_modal.is_none() && no_m_codes && !words.has(b'T') && thread::continues(cmd, &p),
            _ => false,
        };
        if goes_on {
            run_deg = Some(p.end_deg);
        }
        // A thread is never compensated, whatever this block does.
        let bypass = std::mem::replace(&mut step.bypass_comp, true);
        thread::flush(step, p, !goes_on);
        step.bypass_comp = bypass;
    }
    run_deg
}

/// Step 6 of [`run_block`]: H of tool length compensation, D of cutter compensation.
#[inline(always)]
fn offset_words(
    step: &mut Step,
    last_of: &[(Group, &Word, &'static GDef)],
    codes: &Codes,
    words: &mut Words,
    motion_now: Motion,
    has_axis: bool,
) -> Result<(), Diagnostic> {
    // 6. Tool length compensation takes H (the offset number); D belongs to cutter compensation.
    let length_code = last_of.iter().find_map(|(_, w, g)| if let GFn::LengthComp(s) = g.function { Some((w.span, s)) } else { None });
    let h_word = if length_code.is_some() || step.st.frame.length_sign != 0 { words.take(b'H') } else { None };
    if length_code.is_some() || h_word.is_some() {
        let h = h_word.map(|w| offset_number(step, w)).transpose()?;
        let (span, sign) = length_code.unwrap_or((h_word.map(|w| w.span).unwrap_or(step.span), step.st.frame.length_sign));
        frame::length_offset(step, sign, h, span, has_axis);
    }
    if let Some((span, side)) = codes.comp {
        let d = words.take(b'D').map(|w| offset_number(step, w)).transpose()?;
        let arc_move = has_axis && matches!(motion_now, Motion::ArcCw | Motion::ArcCcw);
        comp::command(step, side, d, span, arc_move)?;
    } else if !step.profile.is_lathe() && !last_of.iter().any(|(_, _, g)| matches!(g.function, GFn::OffsetMove(_))) {
        // D without G40-G42 (`G43 H1 D1 Z50.`): the cutter compensation offset number, modal
        // data (FANUC #4107 reads it): kept for the next G41/G42. In compensation the vector at
        // the end of its block is the new radius's, the one at its start the old one's (FANUC
        // 0i manuals, change of the compensation value in offset mode, as recalled).
        if let Some(w) = words.take(b'D') {
            let d = offset_number(step, w)?;
            if step.st.comp.side == 0 {
                step.st.comp.d = d;
            } else {
                let e = frame::entry(step, d, w.span);
                if e.radius_mm + e.wear_radius_mm < 0.0 {
                    return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("offset {d}: the radius with its wear is negative")));
                }
                step.st.comp.next_d = Some(d);
            }
        }
    }
    Ok(())
}

/// An H or D word's offset number: a whole number, 0 to the highest a setup may give.
fn offset_number(step: &Step, w: &Word) -> Result<u32, Diagnostic> {
    if w.decimal || w.value < 0.0 || w.value > crate::setup::MAX_OFFSET_NUMBER as f64 {
        let letter = w.text().chars().next().unwrap_or('D');
        return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: {letter} is an offset number, 0 to {}", w.text(), crate::setup::MAX_OFFSET_NUMBER)));
    }
    Ok(w.value as u32)
}

/// Step 7 of [`run_block`]: F (not in a thread block or a rigid tap's, whose F is the lead).
#[inline(always)]
fn feed_word(step: &mut Step, codes: &Codes, words: &mut Words, thread_block: bool) -> Result<(), Diagnostic> {
    // G84/G88's F is the tap's lead, signed by its hand (help text G84/88): the cycle reads it.
    let tap_block = codes.drill.or(step.st.drill.kind).is_some_and(|k| k.rigid_tap());
    let f_word = if thread_block || tap_block { None } else { words.take(b'F') };
    if let Some(w) = f_word {
        if w.value < 0.0 {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: a feed cannot be negative", w.text())));
        }
        if w.value > 0.0 && w.value < 0.0001 {
            // Below the finest feed increment (0.0001 mm/rev or inch/rev): the control reads 0.
            return Err(step.alarm(Rule::FeedZero, w.span, format!("{}: below the least feed increment 0.0001, the control reads it as F0", w.text())));
        }
        let unit = if step.st.modes.inch { 25.4 } else { 1.0 };
        step.st.modes.feed = Some(w.value * unit);
    }
    Ok(())
}

/// Step 7 of [`run_block`]: P selecting the spindle S and the spindle M codes are for.
#[allow(clippy::type_complexity)]
#[inline(always)]
fn select_spindle(step: &mut Step, codes: &Codes, ms: &[(&Word, Option<&'static MDef>)], words: &mut Words, thread_block: bool) -> Result<(), Diagnostic> {
    // On a machine with several spindles (the setup's `spindle_p`), P in a block with S or a
    // spindle M code selects the spindle they are for (FANUC multi-spindle control: the P codes
    // of parameter 3781; inferred). Each spindle keeps its own speed and direction; the one
    // selected last is the one feeds per revolution and threads follow (assumed).
    let spindle_m = ms.iter().any(|(_, m)| m.is_some_and(|m| matches!(m.function, MFn::SpindleCw | MFn::SpindleCcw | MFn::SpindleStop)));
    let calls = ms.iter().any(|(_, m)| m.is_some_and(|m| matches!(m.function, MFn::SubprogramCall | MFn::SubprogramReturn)));
    // `P11` in a block of its own selects the spindle the next S and M codes are for.
    let p_alone = || words.all().iter().all(|w| w.letter == b'P') && codes.motion.is_none();
    if !step.tables.spindle_p.is_empty()
        && (words.has(b'S') || spindle_m || p_alone())
        && codes.non_modal.is_none()
        && !calls
        && codes.drill.or(step.st.drill.kind).is_none()
        && !thread_block
    {
        if let Some(w) = words.take(b'P') {
            let list = || step.tables.spindle_p.iter().map(|p| format!("P{p}")).collect::<Vec<_>>().join(", ");
            let Some(i) = step.tables.spindle_p.iter().position(|p| f64::from(*p) == w.value) else {
                return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: no such spindle: the setup's spindles are {}", w.text(), list())));
            };
            if step.tables.spindle_p_assumed && !step.st.notes.assumed_warned.contains(b'P') {
                let msg = format!("{}: no setup gives the spindles' P (spindle_p): taken as the spindle selection of a multi-spindle lathe, {} (the first spindle, the second); declare them with [machine] spindle_p", w.text(), list());
                step.st.notes.assumed_warned = step.st.notes.assumed_warned.with(b'P');
                step.warn(Rule::AxisAssumed, w.span, msg);
            }
            let i = i as u8;
            if i != step.st.modes.spindle_sel {
                let modes = &mut *step.st.modes;
                modes.spindles[usize::from(modes.spindle_sel)] = (modes.spindle, modes.s_word);
                (modes.spindle, modes.s_word) = modes.spindles[usize::from(i)];
                modes.spindle_sel = i;
            }
        }
    }
    Ok(())
}

/// The spindle's direction, speed, mode and positioning before a block's S and M codes.
type SpindleNow = (SpindleDir, f64, bool, bool);

/// Step 7 of [`run_block`]: S (the speed, or G50's clamp); the spindle as it was before.
#[inline(always)]
fn speed_word(
    step: &mut Step,
    codes: &Codes,
    last_of: &[(Group, &Word, &'static GDef)],
    words: &mut Words,
    motion_now: Motion,
) -> Result<SpindleNow, Diagnostic> {
    let profile = step.profile;
    let rigid_thread = matches!(motion_now, Motion::Thread(cmd) if thread::is_rigid(cmd));
    // G50 S on the lathes, G92 S on a machining centre with constant surface speed (FANUC 0i-M,
    // inferred for the 0-M): the maximum spindle speed.
    let g50_clamp = matches!(codes.non_modal, Some((_, GFn::LatheCoordinateSet)))
        || (matches!(codes.non_modal, Some((_, GFn::MillCoordinateSet))) && profile.css_axis.is_some());
    let spindle_before = (step.st.modes.spindle, step.st.modes.s_word, step.st.modes.css, step.st.modes.spindle_position_mode);
    let s_word = if rigid_thread { None } else { words.take(b'S') };
    if let Some(w) = s_word {
        if w.value < 0.0 {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: a spindle speed cannot be negative here", w.text())));
        }
        if g50_clamp {
            step.st.modes.rpm_clamp = Some(w.value); // G50 S: maximum spindle speed (TDi help G96/97)
        } else {
            step.st.modes.s_word = w.value;
            let css = codes_css(last_of).unwrap_or(step.st.modes.css);
            if !css && w.value > MAX_RPM {
                let msg = format!("{}: above the spindle's maximum of {MAX_RPM} rpm (assumed for every profile): the spindle turns at {MAX_RPM} rpm", w.text());
                step.warn(Rule::SpeedClamped, w.span, msg);
            }
        }
    }
    Ok(spindle_before)
}

/// Step 7 of [`run_block`]: T (on a lathe the tool and its offset, a tool record).
#[inline(always)]
fn tool_word(step: &mut Step, words: &mut Words, has_axis: bool) -> Result<(), Diagnostic> {
    let profile = step.profile;
    let tool = match words.take(b'T') {
        Some(w) => {
            if w.decimal || w.value < 0.0 {
                return Err(step.alarm(Rule::IllegalDecimalPoint, w.span, format!("{}: a tool number is a whole number", w.text())));
            }
            let v = w.value as u32;
            Some((if profile.is_lathe() && v >= 100 { (v / 100, Some(v % 100)) } else { (v, None) }, w.span))
        }
        None => None,
    };
    if let Some(((number, offset), span)) = tool {
        step.st.modes.tool = number;
        if profile.is_lathe() {
            step.emit(Op::Tool { number, offset });
            if let Some(o) = offset {
                frame::lathe_offset(step, o, span, has_axis);
                // In compensation the new offset's radius and tip take over.
                let side = step.st.comp.side;
                if side != 0 {
                    comp::command(step, side, None, span, false)?;
                }
            }
        }
    }
    Ok(())
}

/// Steps 8 and 9 of [`run_block`]: the M codes that act before the motion (the spindle and its
/// mode, rigid tapping, the words of a call or return), a spindle record when the spindle
/// changes; the M codes that act after the motion, returned.
#[allow(clippy::type_complexity)]
#[inline(always)]
fn m_codes_before<'w>(
    step: &mut Step,
    ms: &[(&'w Word, Option<&'static MDef>)],
    words: &mut Words<'w>,
    spindle_before: SpindleNow,
) -> Result<Vec<(&'w Word, MFn)>, Diagnostic> {
    let profile = step.profile;
    // 8. M codes that act before motion: spindle and its mode.
    let mut after: Vec<(&'w Word, MFn)> = Vec::new();
    let mut flow = None;
    for &(w, m) in ms {
        match m {
            // The machine's own codes the setup lists pass silently (no effect simulated).
            None if w.value.fract() == 0.0 && step.tables.own_m_codes.contains(&(w.value as u32)) => {}
            None => step.warn(
                Rule::MachineSpecificM,
                w.span,
                format!(
                    "{} is not a standard M code of {}: passed to the machine, no effect simulated (a machine's own codes go in the setup's [machine] m_codes)",
                    w.text(),
                    profile.name
                ),
            ),
            Some(m) => match m.function {
                MFn::SpindleCw => {
                    step.st.modes.spindle = SpindleDir::Positive;
                }
                MFn::SpindleCcw => {
                    step.st.modes.spindle = SpindleDir::Negative;
                }
                MFn::SpindlePositionMode => {
                    step.st.modes.spindle_position_mode = true;
                }
                MFn::SpindleSpeedMode => {
                    step.st.modes.spindle_position_mode = false;
                }
                MFn::RigidTapping => {
                    // Help text G84/88: M29 may not be given again while the mode is on.
                    if step.st.drill.rigid_tap {
                        return Err(step.alarm(
                            Rule::RigidTapOrder,
                            w.span,
                            "M29: rigid tapping mode is on already (help text G84/88: M29 may not be repeated)",
                        ));
                    }
                    step.st.drill.rigid_tap = true;
                    step.st.drill.tap_waiting = true;
                }
                MFn::Auxiliary => {}
                // The words of a call or a return are read now; the jump comes after the motion.
                MFn::SubprogramCall => {
                    flow = Some(call::call(step, words, w)?);
                    after.push((w, m.function));
                }
                MFn::SubprogramReturn => {
                    flow = Some(call::ret(step, words, w)?);
                    after.push((w, m.function));
                }
                f => after.push((w, f)),
            },
        }
    }
    step.out.flow = flow;
    // 9. A spindle record when the spindle's state changes in a way the machine shows: a new
    // direction or mode, or a new speed while it turns.
    let spindle_after = (step.st.modes.spindle, step.st.modes.s_word, step.st.modes.css, step.st.modes.spindle_position_mode);
    let turning = step.st.modes.spindle != SpindleDir::Stopped;
    if spindle_before != spindle_after && (turning || spindle_before.0 != spindle_after.0 || spindle_before.3 != spindle_after.3) {
        emit_spindle(step);
    }
    Ok(after)
}

/// Step 10 of [`run_block`]: the one-shot code, or the motion of the mode in force; then
/// step 11 ([`finish_block`]).
#[inline(always)]
fn motion_of_block<'w>(
    step: &mut Step,
    words: &mut Words<'w>,
    codes: &Codes,
    after: Vec<(&'w Word, MFn)>,
    switches: Switches,
    has_axis: bool,
    run_deg: Option<f64>,
) -> Result<(), Diagnostic> {
    // 10. The one-shot code, or the motion of the mode in force.
    // A one-shot code other than G04 ends the box cycles' remembered X, Z and R (FANUC 0-T).
    if matches!(codes.non_modal, Some((_, f)) if f != GFn::Dwell) {
        step.st.memory.box_cycle = Default::default();
    }
    // A group 01 code beside a one-shot code is in force for the blocks after (`G53 G0 Z0`).
    if codes.non_modal.is_some() {
        if let Some((_, m)) = codes.motion {
            if matches!(m, Motion::Rapid | Motion::Linear | Motion::ArcCw | Motion::ArcCcw) {
                step.st.modes.motion = m;
            }
        }
    }
    // G68/G69, G51.1/G50.1, G51/G50: set or end a transform. A block that sets one (or names
    // the axes of a mirror image to end) makes no move: its axis words are the transform's.
    if !codes.transforms.is_empty() && set_transforms(step, words, codes)? {
        // The block's group 01 code is in force for the blocks after it.
        if let Some((_, m)) = codes.motion {
            step.st.modes.motion = m;
        }
        return finish_block(step, words, codes, after, switches);
    }
    programmed_coordinates(step, words, codes, has_axis)?;
    let mut non_modal = codes.non_modal;
    if let Some((span, GFn::MachineCoordinates)) = non_modal {
        if frame::machine_move(step, words, span)? {
            return finish_block(step, words, codes, after, switches);
        }
        // Ignored in incremental: the block runs as without it.
        non_modal = None;
    }
    match non_modal {
        Some(code) => one_shot(step, words, code)?,
        None => modal_motion(step, words, codes, has_axis, run_deg)?,
    }
    finish_block(step, words, codes, after, switches)
}

/// Step 10 of [`run_block`]: G68/G69, G51.1/G50.1, G51/G50 and G22/G23 set or end a transform
/// (the cancels first); whether one was set (the block then makes no move: its axis words are
/// the transform's).
fn set_transforms(step: &mut Step, words: &mut Words, codes: &Codes) -> Result<bool, Diagnostic> {
    let t = step.st.transform;
    // The codes that set an area or a transform take the block's axis words: one of them
    // per block; the cancels run first.
    let sets = |f: &GFn| matches!(f, GFn::Rotation(true) | GFn::MirrorImage(_) | GFn::TurretMirror(_) | GFn::Scaling(true) | GFn::StrokeCheck(true));
    if let Some(&(span, _)) = codes.transforms.iter().filter(|(_, f)| sets(f)).nth(1) {
        return Err(step.alarm(Rule::NotSupported, span, "two of G68, G51, G51.1/G50.1 and G22 in one block are not simulated: give each its own block"));
    }
    if codes.transforms.iter().any(|(_, f)| !matches!(f, GFn::StrokeCheck(_))) && (step.st.drill.kind.is_some() || codes.drill.is_some()) {
        let (span, _) = codes.transforms[0];
        return Err(step.alarm(
            Rule::NotSupported,
            span,
            "a coordinate rotation, scaling or mirror image set or ended in a drilling cycle is not simulated: cancel the cycle (G80) first",
        ));
    }
    // The centres default to where the tool is, in programmed coordinates.
    let here = step.st.place.pos;
    if transform::moves_records(&t) {
        step.st.place.pos = transform::programmed(&t, here);
    }
    let mut set = Ok(false);
    let mut order: Vec<(Span, GFn)> = codes.transforms.iter().filter(|(_, f)| !sets(f)).copied().collect();
    order.extend(codes.transforms.iter().filter(|(_, f)| sets(f)).copied());
    for (span, f) in order {
        set = match f {
            GFn::Rotation(on) => transform::rotation(step, words, on, span).map(|_| on),
            GFn::MirrorImage(on) => transform::mirror_image(step, words, on, span).map(|_| true),
            GFn::TurretMirror(on) => transform::turret_mirror(step, on, span).map(|_| true),
            GFn::Scaling(on) => transform::scaling(step, words, on, span).map(|_| on),
            GFn::StrokeCheck(on) => stroke::set(step, words, on, span).map(|_| on),
            _ => unreachable!("only transform codes are noted here"),
        };
        if set.is_err() {
            break;
        }
    }
    step.st.place.pos = here;
    set
}

/// Step 10 of [`run_block`]: under a transform the block is worked out in programmed
/// coordinates (what is not simulated there alarms).
#[inline(always)]
fn programmed_coordinates(step: &mut Step, words: &Words, codes: &Codes, has_axis: bool) -> Result<(), Diagnostic> {
    // Under a transform the block is worked out in programmed coordinates.
    if transform::moves_records(&step.st.transform) {
        let t = step.st.transform;
        let what = match codes.non_modal {
            Some((_, GFn::Dwell)) | None => None,
            Some((span, f)) => Some((span, step.profile.name_of(f))),
        };
        if let Some((span, code)) = what {
            return Err(step.alarm(
                Rule::NotSupported,
                span,
                format!("{code} under coordinate rotation, scaling or mirror image (G68, G51, G51.1) is not simulated"),
            ));
        }
        if step.st.comp.side != 0 {
            return Err(step.alarm(
                Rule::NotSupported,
                step.span,
                "radius compensation under coordinate rotation, scaling or mirror image (G68, G51, G51.1) is not simulated",
            ));
        }
        // An arc this block makes (its motion mode an arc, and axis or centre words in it).
        let arc = matches!(codes.motion.map_or(step.st.modes.motion, |(_, m)| m), Motion::ArcCw | Motion::ArcCcw | Motion::Curve(_))
            && (has_axis || b"RIJK".iter().any(|l| words.has(*l)));
        if let Some(why) = transform::arc_refused(&t, step.st.modes.plane).filter(|_| arc && codes.drill.or(step.st.drill.kind).is_none()) {
            return Err(step.alarm(Rule::NotSupported, step.span, format!("an arc under this transform is not simulated: {why}")));
        }
        // FANUC: Q and d of the peck cycles and the G76/G87 shift are not scaled (and the shift is
        // a direction of the machine): those cycles are not simulated under a transform.
        if let Some(kind) = codes
            .drill
            .or(step.st.drill.kind)
            .filter(|k| matches!(k, crate::codes::DrillKind::G73 | crate::codes::DrillKind::G83 | crate::codes::DrillKind::G76 | crate::codes::DrillKind::G87))
        {
            return Err(step.alarm(
                Rule::NotSupported,
                step.span,
                format!(
                    "{} under coordinate rotation, scaling or mirror image is not simulated (its Q and shift are not transformed on the controller)",
                    kind.code()
                ),
            ));
        }
        step.st.place.pos = transform::programmed(&t, step.st.place.pos);
        step.carry = Some(*t);
    }
    Ok(())
}

/// Step 10 of [`run_block`]: the one-shot (group 00) code.
#[inline(always)]
fn one_shot(step: &mut Step, words: &mut Words, code: (Span, GFn)) -> Result<(), Diagnostic> {
    match code {
        (_, GFn::Dwell) => dwell(step, words)?,
        (_, GFn::CompoundThread(kind)) => compound::compound(step, words, kind)?,
        (_, GFn::PeckCycle(kind)) => groove::block(step, words, kind)?,
        (_, GFn::Rough(kind)) => rough::block(step, words, kind)?,
        (_, GFn::Finish) => rough::finishing(step, words)?,
        (span, GFn::ReferenceReturn) => frame::reference_return(step, words, 1, span)?,
        (span, GFn::FromReference) => frame::from_reference(step, words, span)?,
        (span, GFn::OtherReferenceReturn) => {
            let n = frame::other_reference(step, words)?;
            frame::reference_return(step, words, n, span)?;
        }
        (_, GFn::LatheCoordinateSet | GFn::MillCoordinateSet) => frame::set_coordinates(step, words)?,
        (_, GFn::LocalCoordinates) => frame::local(step, words)?,
        (span, GFn::DataSetting) => step.out.table_write = frame::data_setting(step, words, span)?,
        // G11 outside the data lines: nothing to end (FANUC and GSK texts say nothing; inferred).
        (_, GFn::DataSettingEnd) => {}
        (span, GFn::CornerArc) => comp::corner_arc(step, words, span)?,
        (span, GFn::OffsetMove(factor)) => frame::offset_move(step, words, factor, span)?,
        (span, GFn::ReferenceCheck) => frame::reference_check(step, words, span)?,
        (span, GFn::Skip) => skip(step, words, span)?,
        (span, GFn::ToolMeasure(axis)) => tool_measure(step, words, axis, span)?,
        (_, GFn::SingleDirection) => single_direction(step, words)?,
        (span, f) => {
            return Err(step.alarm(Rule::NotSupported, span, format!("{}: a one-shot command ncsight has no block function for", step.profile.name_of(f))))
        }
    }
    Ok(())
}

/// Step 10 of [`run_block`]: the motion of the mode in force (a polar interpolation switch, a
/// drilling cycle, a thread, a box cycle, a curve, G00-G03).
#[inline(always)]
fn modal_motion(step: &mut Step, words: &mut Words, codes: &Codes, has_axis: bool, run_deg: Option<f64>) -> Result<(), Diagnostic> {
    if let Some((span, f)) = codes.polar_interp {
        polar::switch(step, words, f, span)?;
        return Ok(());
    }
    if let Some((_, m)) = codes.motion {
        step.st.modes.motion = m;
    }
    if step.st.modes.polar_interp.is_some() && has_axis && !matches!(step.st.modes.motion, Motion::Linear | Motion::ArcCw | Motion::ArcCcw) {
        return Err(step.alarm(Rule::ImproperGCode, step.span, "a move in polar coordinate interpolation (G12.1) is G01, G02 or G03 (FANUC 0i-T manual)"));
    }
    let drill_kind = codes.drill.or(step.st.drill.kind);
    if let Some(kind) = drill_kind {
        drill::block(step, words, kind, codes.drill.is_some())?;
        return Ok(());
    }
    if let Motion::Thread(cmd) = step.st.modes.motion {
        if has_axis {
            thread::block(step, words, cmd, codes.motion.is_some(), run_deg)?;
        }
        return Ok(());
    }
    if let Motion::Box(kind) = step.st.modes.motion {
        if has_axis || words.has(step.profile.box_taper) {
            turning::block(step, words, kind)?;
        }
        return Ok(());
    }
    if let Motion::Curve(kind) = step.st.modes.motion {
        // Without an end point the curve's own words still count (help text G6.2 note 6);
        // P is left out: M98/M99 and the spindle selection take it too.
        if has_axis || b"IJKABQ".iter().any(|l| words.has_unused(*l)) {
            curve::block(step, words, kind)?;
        }
        return Ok(());
    }
    let arc_words = matches!(step.st.modes.motion, Motion::ArcCw | Motion::ArcCcw) && b"RIJK".iter().any(|l| words.has(*l));
    // A rotary axis the setup declares moves in G00/G01 alone too (FANUC 0-M G91 A45.).
    let rotary_words = step.tables.rotary.iter().any(|r| *r) && b"ABCH".iter().any(|l| step.tables.added_addresses.contains(*l) && words.has(*l));
    // A line given by its angle alone (docs/commands/drawing.md) moves too.
    let angle_word = step.profile.frame.drawing.is_some_and(|d| words.has(d.angle)) && matches!(step.st.modes.motion, Motion::Rapid | Motion::Linear);
    let motion_words = has_axis || arc_words || angle_word || (rotary_words && matches!(step.st.modes.motion, Motion::Rapid | Motion::Linear));
    if motion_words {
        motion(step, words)?;
    }
    Ok(())
}

/// The G codes of the profile a block's words name, in the order written (words that are not a
/// code of the table are left for the block's reading to judge).
pub(super) fn codes_of<'a>(profile: &'a Profile, words: &'a [Word]) -> impl Iterator<Item = &'static GDef> + 'a {
    words.iter().filter(|w| w.letter == b'G' && !w.expr && w.is_code()).filter_map(move |w| profile.g_code(w.code().0, w.code().1))
}

/// Whether a block's plane words are polar coordinates under G16: not when the block ends
/// G16, sets or ends another transform, or has a one-shot code (G04's X is a time; the others'
/// words are not a point of the path).
fn polar_reads(step: &Step, block: &Block) -> bool {
    codes_of(step.profile, &block.words).all(|g| {
        !matches!(
            (g.group, g.function),
            (_, GFn::PolarCoordinates(false) | GFn::Rotation(_) | GFn::MirrorImage(_) | GFn::Scaling(_) | GFn::StrokeCheck(_)) | (Group::NonModal, _)
        )
    })
}

/// Whether the block's own G codes switch constant surface speed on or off.
fn codes_css(last_of: &[(Group, &Word, &GDef)]) -> Option<bool> {
    last_of.iter().rev().find_map(|(_, _, g)| match g.function {
        GFn::ConstantSurfaceSpeed => Some(true),
        GFn::ConstantRpm => Some(false),
        _ => None,
    })
}

/// 11. M codes that act after the motion, then the check that every word was used.
fn finish_block(step: &mut Step, words: &Words, codes: &Codes, after: Vec<(&Word, MFn)>, switches: Switches) -> Result<(), Diagnostic> {
    // A D changed in compensation: the new radius from the end of this block's move on.
    if let Some(d) = step.st.comp.take_some(|c| &mut c.next_d) {
        let e = frame::entry(step, d, step.span);
        step.st.comp.d = d;
        step.st.comp.radius_mm = e.radius_mm + e.wear_radius_mm;
    }
    // An L or D whose block made no move in the plane has no corner to make.
    if let Some(c) = step.st.comp.take_some(|c| &mut c.corner_for_next) {
        step.warn(Rule::TextIgnored, c.span, format!("{}: the block makes no move in the plane: no corner is made", c.word()));
    }
    // A block worked out in programmed coordinates ends where its records took the tool.
    if let Some(t) = step.carry.take() {
        step.st.place.pos = transform::apply(&t, step.st.place.pos);
    }
    // A stop or an end after a held-back thread run end: the run ends first.
    if !after.is_empty() {
        if let Some(p) = step.st.thread.take_some(|t| &mut t.pending) {
            thread::flush(step, p, true);
        }
    }
    for (w, f) in after {
        match f {
            MFn::SpindleStop => {
                step.st.modes.spindle = SpindleDir::Stopped;
                emit_spindle(step);
            }
            MFn::ProgramStop => step.emit(Op::Stop { reason: StopReason::ProgramStop }),
            MFn::OptionalStop => {
                if switches.optional_stop {
                    step.emit(Op::Stop { reason: StopReason::OptionalStop });
                }
            }
            MFn::ToolChange => {
                let number = step.st.modes.tool;
                step.emit(Op::Tool { number, offset: None });
            }
            MFn::ProgramEnd => {
                step.st.modes.ended = true;
                step.emit(Op::End { code: w.value as u32 });
            }
            // The jump itself is the programme driver's (`Outcome::flow`).
            MFn::SubprogramCall | MFn::SubprogramReturn => {}
            _ => unreachable!("handled before motion"),
        }
    }

    if let Some(w) = words.first_unused() {
        let cmd = describe_command(step, codes);
        let d = step.alarm(Rule::WordNotTaken, w.span, format!("{}: {cmd} does not take address {}", w.text(), crate::read::address_name(w.letter)));
        // `M165 P9832`: an M code of the machine builder's that calls a macro with the block's
        // words as its arguments (FANUC parameters 6080-6089), which the setup can declare.
        let builder_m = words.all().iter().find(|m| m.letter == b'M' && m.value.fract() == 0.0 && step.profile.m_code(m.value as u32).is_none());
        return Err(match builder_m {
            Some(m) => {
                let code = m.value as u32;
                d.with_hint(format!("M{code} is not in {}'s list: if the machine builder made it a macro call (FANUC parameters 6080-6089), the block's words are its arguments; declare it in the setup: [machine] m_macro = {{ {code} = \"O9xxx\" }}", step.profile.name))
            }
            None => d,
        });
    }
    Ok(())
}

fn describe_command(step: &Step, codes: &Codes) -> String {
    let name = |f: GFn| step.profile.name_of(f);
    if let Some((f, title)) = codes.non_modal.and_then(|(_, f)| Some((f, f.one_shot_title()?))) {
        return format!("{} ({title})", name(f));
    }
    let m = step.st.modes.motion;
    if let Some(kind) = step.st.drill.kind {
        return format!("{} (drilling cycle; the repeat count is K)", kind.code());
    }
    let plane = name(match step.st.modes.plane {
        Plane::XY => GFn::PlaneXY,
        Plane::ZX => GFn::PlaneZX,
        Plane::YZ => GFn::PlaneYZ,
    });
    match m {
        Motion::Rapid => format!("{} (rapid positioning)", name(GFn::Rapid)),
        Motion::Linear => format!("{} (linear interpolation)", name(GFn::Linear)),
        Motion::ArcCw => format!("{} in the {plane} plane", name(GFn::ArcCw)),
        Motion::ArcCcw => format!("{} in the {plane} plane", name(GFn::ArcCcw)),
        Motion::Thread(cmd) => format!("{} (thread cutting)", thread::name(step.profile, cmd)),
        Motion::Box(kind) => format!("{} (single turning/facing cycle)", kind.code()),
        Motion::Curve(kind) => format!("{} in the {plane} plane", name(GFn::Curve(kind))),
    }
}

fn emit_spindle(step: &mut Step) {
    let rpm = step.rpm_here();
    let surface = if step.st.modes.css { Some(step.st.modes.surface_m_min()) } else { None };
    let position_mode = step.st.modes.spindle_position_mode;
    step.emit(Op::Spindle { rpm, surface_m_min: surface, position_mode, oriented: false, p: step.spindle_p() });
}

/// G04: P in ms (whole number), X or U in seconds; P wins over X, X over U; negative = 0
/// (TDi help G04, notes 2 and 3).
fn dwell(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let p = words.take(b'P');
    let x = words.take(b'X');
    let u = if step.profile.incremental_addresses { words.take(b'U') } else { None };
    let seconds = if let Some(w) = p {
        if w.decimal {
            return Err(step.alarm(Rule::IllegalDecimalPoint, w.span, format!("{}: P of G04 is a whole number of ms", w.text())));
        }
        w.value / 1000.0
    } else if let Some(w) = x.or(u) {
        if w.decimal || step.params.integer_lengths() == IntegerLengths::Millimetres {
            w.value
        } else {
            w.value / 1000.0
        }
    } else {
        0.0 // exact stop between blocks
    };
    let seconds = seconds.max(0.0);
    if seconds > 0.0 {
        step.emit(Op::Dwell { seconds });
    }
    Ok(())
}

/// How a block's word gave an axis: as a coordinate, or as a distance from where the tool is
/// (U/V/W, or X/Y/Z in G91).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Given {
    Absolute,
    Incremental,
}

/// The end point a block's axis words name, and how each axis was given.
fn axis_target(step: &mut Step, words: &mut Words) -> Result<(Vec3, [Option<Given>; 3]), Diagnostic> {
    let profile = step.profile;
    // From the position the controller shows: an axis not written goes there too (a tool
    // offset's movement not made yet is made with this move, on every axis).
    let mut target = step.st.place.pos + step.st.frame.unmoved;
    let mut given = [None; 3];
    let pairs: [(u8, u8, usize); 3] = [(b'X', b'U', 0), (b'Y', b'V', 1), (b'Z', b'W', 2)];
    for (abs_l, inc_l, axis) in pairs {
        let abs_w = words.take(abs_l);
        let inc_w = if profile.incremental_addresses { words.take(inc_l) } else { None };
        let scale = if axis == 0 && profile.diameter_x { 0.5 } else { 1.0 };
        if let (Some(a), Some(i)) = (abs_w, inc_w) {
            return Err(step.alarm(Rule::DuplicateWord, i.span, format!("{} and {} both give the {} axis", a.text(), i.text(), abs_l as char)));
        }
        // Incremental words count from the position the controller shows: the tool's, plus a
        // tool offset's movement not made yet (FANUC 5002#6 LWM).
        let shown = step.st.place.pos.axis(axis) + step.st.frame.unmoved.axis(axis);
        if let Some(w) = abs_w {
            let v = step.length(w)? * scale;
            target.set_axis(axis, if step.st.modes.incremental { shown + v } else { v });
            given[axis] = Some(if step.st.modes.incremental { Given::Incremental } else { Given::Absolute });
        } else if let Some(w) = inc_w {
            let v = step.length(w)? * scale;
            target.set_axis(axis, shown + v);
            given[axis] = Some(Given::Incremental);
        }
    }
    Ok((target, given))
}

/// G31: a cutting feed to the point given that the skip signal would end where it came (FANUC,
/// GSK980TDi help text G31: the position is then stored). A simulation has no signal: the move
/// runs to its end, with warning NCS-W34. P (which signal, 1-4: GSK980TDi help text) is read.
fn skip(step: &mut Step, words: &mut Words, span: Span) -> Result<(), Diagnostic> {
    if let Some(w) = words.take(b'P') {
        if w.decimal || !(1.0..=4.0).contains(&w.value) {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: G31's P names the skip signal, P1 to P4 (GSK980TDi help text, G31)", w.text())));
        }
    }
    let (target, _) = axis_target(step, words)?;
    let from = step.st.place.pos;
    let feed = step.cutting_feed(What::Name("G31"), &|u| lerp(&from, &target, u))?;
    step.warn(
        Rule::NoSkipSignal,
        span,
        "G31: no skip signal comes in a simulation: the move runs to its end (the position a signal would store is its end point)",
    );
    if target != from {
        step.emit(Op::Feed { from, to: target, feed_mm_min: feed });
    }
    Ok(())
}

/// G36 (X) / G37 (Z): automatic tool compensation (lathes) or tool length measurement (G37 on
/// a mill): at rapid to the setting's approach distance before the measuring position, then at
/// the measuring feed to it; the sensor's signal would stop the tool there and the offset would
/// be corrected by the difference (FANUC 0i, GSK980TDi G-code list; inferred). A simulation has
/// no sensor: the tool reaches the position, the offset stays, with warning NCS-W35.
fn tool_measure(step: &mut Step, words: &mut Words, axis: u8, span: Span) -> Result<(), Diagnostic> {
    let axis = usize::from(axis);
    let (abs_l, inc_l) = if axis == 0 { (b'X', b'U') } else { (b'Z', b'W') };
    let name = if axis == 0 { "G36" } else { "G37" };
    let inc = if step.profile.incremental_addresses { words.take(inc_l) } else { None };
    let scale = if axis == 0 && step.profile.diameter_x { 0.5 } else { 1.0 };
    let from = step.st.place.pos;
    let at = match (words.take(abs_l), inc) {
        (Some(w), None) => {
            let v = step.length(w)? * scale;
            if step.st.modes.incremental {
                from.axis(axis) + v
            } else {
                v
            }
        }
        (None, Some(w)) => from.axis(axis) + step.length(w)? * scale,
        (Some(a), Some(i)) => return Err(step.alarm(Rule::DuplicateWord, i.span, format!("{} and {} both give the measuring position", a.text(), i.text()))),
        (None, None) => return Err(step.alarm(Rule::MissingWord, span, format!("{name} needs the measuring position {}", abs_l as char))),
    };
    let setting = |step: &Step, k: &'static str| if step.profile.param(ParamKey::Setting(k)).is_some() { step.params.get(ParamKey::Setting(k)) } else { 0.0 };
    let approach = setting(step, "measure_approach_mm");
    let feed = setting(step, "measure_feed_mm_min").max(1.0);
    let travel = at - from.axis(axis);
    let mut via = from;
    if travel.abs() > approach {
        via.set_axis(axis, at - approach * travel.signum());
        step.emit(Op::Rapid { from, to: via });
    }
    let mut target = via;
    target.set_axis(axis, at);
    if target != via {
        step.emit(Op::Feed { from: via, to: target, feed_mm_min: feed });
    }
    step.warn(
        Rule::NoMeasuringSignal,
        span,
        format!("{name}: no measuring signal comes in a simulation: the tool reaches the measuring position and the offset stays as it is"),
    );
    Ok(())
}

/// G60 (FANUC 0-M): at rapid to a point each moving axis's overrun before the end point (the
/// profile's per-axis setting, FANUC 0i 5440), then to the end point: every axis arrives from the
/// same side whatever the direction it came from. With every overrun 0 it is a rapid there.
fn single_direction(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let (target, given) = axis_target(step, words)?;
    let from = step.st.place.pos;
    let keys = [ParamKey::Setting("g60_overrun_x_mm"), ParamKey::Setting("g60_overrun_y_mm"), ParamKey::Setting("g60_overrun_z_mm")];
    let mut via = target;
    for (a, _) in given.iter().enumerate().filter(|(_, g)| g.is_some()) {
        let overrun = if step.profile.param(keys[a]).is_some() { step.params.get(keys[a]) } else { 0.0 };
        if target.axis(a) != from.axis(a) {
            via.set_axis(a, target.axis(a) - overrun);
        }
    }
    if via != from {
        step.emit(Op::Rapid { from, to: via });
    }
    if target != via {
        step.emit(Op::Rapid { from: via, to: target });
    }
    Ok(())
}

/// The rotary axes' words of a move (A, B, C as the setup declares them; H, the FANUC lathe's
/// incremental C): where each axis turns to, degrees, or `None` without such a word. Degrees
/// without a decimal point are least input increments (0.001 degree) where lengths are, as on
/// the FANUC (IS-B); no work offset or rollover applies (FANUC 1008#0 ROA off, assumed).
fn rotary_target(step: &mut Step, words: &mut Words) -> Result<Option<[f64; 3]>, Diagnostic> {
    Ok(extra_axes_target(step, words)?.map(|(target, _)| target))
}

/// [`rotary_target`], with which of A, B, C the block named.
fn extra_axes_target(step: &mut Step, words: &mut Words) -> Result<Option<([f64; 3], [bool; 3])>, Diagnostic> {
    if !step.tables.rotary.iter().any(|r| *r) {
        return Ok(None);
    }
    let mut target = step.st.place.rotary_deg;
    let mut named = [false; 3];
    let mut any = false;
    // An assumed C is no axis while 3405#4 CCR = 1 makes a plain C the drawing's chamfer.
    let chamfer_c = step.tables.assumed_axes.contains(b'C') && step.plain_drawing();
    for (i, letter) in [b'A', b'B', b'C'].into_iter().enumerate() {
        if !step.tables.rotary[i] || (letter == b'C' && chamfer_c) {
            continue;
        }
        let abs_w = words.take(letter);
        let inc_w = if letter == b'C' && step.tables.added_addresses.contains(b'H') { words.take(b'H') } else { None };
        if let (Some(a), Some(h)) = (abs_w, inc_w) {
            return Err(step.alarm(Rule::DuplicateWord, h.span, format!("{} and {} both give the C axis", a.text(), h.text())));
        }
        let Some(w) = abs_w.or(inc_w) else { continue };
        // A linear extra axis (a sub-spindle's B) reads its word as a length, in mm.
        let v = if step.tables.linear_extra[i] { step.length(w)? } else { step.degrees(w) };
        if !v.is_finite() || v.abs() > MAX_COORD_MM {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: an axis moves at most {MAX_COORD_MM} (mm or degrees) from its zero", w.text())));
        }
        let incremental = inc_w.is_some() || step.st.modes.incremental;
        target[i] = if incremental { step.st.place.rotary_deg[i] + v } else { v };
        named[i] = true;
        any = true;
    }
    if any && step.st.comp.side != 0 {
        return Err(step.alarm(Rule::NotSupported, step.span, "a rotary axis turn in radius compensation (G41/G42) is not simulated"));
    }
    Ok(any.then_some((target, named)))
}

/// The rotary turns of a G00/G01 block, after its linear move (if any, recorded just before):
/// one record per axis that turns, each made together with the records of the block before it
/// (`with_move`). In G01 the feed F is the rate of the whole move, X, Y, Z and the degrees
/// together (FANUC: a rotary axis's degrees count as the input unit, mm or inch), so each axis
/// turns at its share of F (`rate_per_unit`: the rate in degrees per minute for each degree of
/// the axis's turn).
fn emit_rotary(step: &mut Step, to_deg: [f64; 3], rapid: bool, rate_per_unit: f64, with_move: bool) {
    let mut with_move = with_move;
    for i in 0..3 {
        let from_deg = step.st.place.rotary_deg[i];
        if to_deg[i] != from_deg {
            let rate_deg_min = rate_per_unit * (to_deg[i] - from_deg).abs();
            let linear = step.tables.linear_extra[i];
            step.emit(Op::Rotary { axis: b'A' + i as u8, from_deg, to_deg: to_deg[i], rate_deg_min, rapid, with_move, linear });
            with_move = true;
        }
    }
    step.st.place.rotary_deg = to_deg;
}

fn motion(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    if let Some(rules) = step.profile.frame.drawing {
        // FANUC's corners follow G01 lines only (alarm 052): in an arc their words are not taken.
        if step.st.modes.motion == Motion::Linear || (matches!(step.st.modes.motion, Motion::ArcCw | Motion::ArcCcw) && !rules.corner_needs_g01) {
            corner::words(step, words, rules)?;
        }
    }
    let rotary = if matches!(step.st.modes.motion, Motion::Rapid | Motion::Linear) { rotary_target(step, words)? } else { None };
    // A line given by its angle (docs/commands/drawing.md): the end it gives, or none yet.
    let drawing = step.profile.frame.drawing;
    let angle = match drawing {
        Some(rules) => drawing::angle(step, words, rules),
        None => None,
    };
    let (target, given) = axis_target(step, words)?;
    let target = match drawing {
        Some(rules) if angle.is_some() || step.st.comp.angle_line.is_some() => {
            let Some(t) = drawing::line(step, rules, angle, target, given)? else {
                if rotary.is_some() {
                    return Err(step.alarm(
                        Rule::NotSupported,
                        step.span,
                        "a rotary axis turned with a line of an angle alone is not simulated by ncsight yet",
                    ));
                }
                return Ok(());
            };
            t
        }
        _ => target,
    };
    let from = step.st.place.pos;
    match step.st.modes.motion {
        Motion::Rapid => {
            if target != from {
                step.emit(Op::Rapid { from, to: target });
            }
            if let Some(to_deg) = rotary {
                emit_rotary(step, to_deg, true, 0.0, target != from);
            }
        }
        Motion::Linear => {
            let feed = step.cutting_feed(What::Code(GFn::Linear), &|u| lerp(&from, &target, u))?;
            // The move's length in the input unit, the degrees counted as that unit (a linear
            // extra axis's millimetres converted to it); F in it.
            let unit = if step.st.modes.inch { 25.4 } else { 1.0 };
            let per_unit = |i: usize| if step.tables.linear_extra[i] { unit } else { 1.0 };
            let turn = rotary.map_or(0.0, |to| (0..3).map(|i| ((to[i] - step.st.place.rotary_deg[i]) / per_unit(i)).powi(2)).sum::<f64>().sqrt());
            let length = from.dist(&target) / unit;
            let whole = (length * length + turn * turn).sqrt();
            if target != from {
                // With a turn, the move's share of F: every axis ends at the same time.
                step.emit(Op::Feed { from, to: target, feed_mm_min: feed * length / whole });
            }
            if let Some(to_deg) = rotary {
                emit_rotary(step, to_deg, false, feed / unit / whole, target != from);
            }
        }
        Motion::ArcCw | Motion::ArcCcw => {
            let dir = if step.st.modes.motion == Motion::ArcCw { ArcDir::Cw } else { ArcDir::Ccw };
            arc(step, words, from, target, dir)?;
        }
        Motion::Thread(_) => unreachable!("thread blocks go to thread::block"),
        Motion::Box(_) => unreachable!("cycle blocks go to turning::block"),
        Motion::Curve(_) => unreachable!("curve blocks go to curve::block"),
    }
    Ok(())
}

/// A duration as a person reads it: `1 h 50 min`, `3 min 20 s`, `12.5 s`.
pub(crate) fn hours_minutes(seconds: f64) -> String {
    let s = seconds.max(0.0);
    if s >= 3600.0 {
        let m = (s / 60.0).round() as u64;
        format!("{} h {} min", m / 60, m % 60)
    } else if s >= 60.0 {
        let t = s.round() as u64;
        format!("{} min {} s", t / 60, t % 60)
    } else {
        format!("{} s", crate::alarm::shown(s, 1))
    }
}

fn lerp(a: &Vec3, b: &Vec3, u: f64) -> Vec3 {
    Vec3::new(a.x + (b.x - a.x) * u, a.y + (b.y - a.y) * u, a.z + (b.z - a.z) * u)
}

/// What the arc words of a block describe.
enum ArcOutcome {
    Arc(geom::ArcGeom),
    /// R with start = end in the plane: a 0-degree arc (TDi help G02/03 note 3).
    Zero,
    /// Neither R nor a centre word, where the parameter makes that a straight move.
    Straight,
}

/// The arc a block's R or centre words describe, from `from` to `to` in the plane in force.
/// R wins over I/J/K (TDi help G02/03 note 1; seed 002 note 4).
fn resolve_arc(step: &mut Step, words: &mut Words, from: Vec3, to: Vec3, dir: ArcDir, gname: impl Into<What>) -> Result<ArcOutcome, Diagnostic> {
    // The name is looked up only when a message needs it.
    let gname = gname.into();
    let plane = step.st.modes.plane;
    let (a, b, _) = plane.axes();
    let letter_of = |axis: usize| [b'I', b'J', b'K'][axis];
    let r_word = words.take(b'R');
    let (la, lb) = (letter_of(a), letter_of(b));
    let ca = words.take(la);
    let cb = words.take(lb);
    if let Some(rw) = r_word {
        for w in [ca, cb].into_iter().flatten() {
            let msg = format!("{}: ignored, R takes precedence over the centre words", w.text());
            step.warn(Rule::TextIgnored, w.span, msg);
        }
        let r = step.length(rw)?;
        return match geom::arc_from_radius(from, to, plane, dir, r, ARC_TOLERANCE_MM) {
            Ok(g) => Ok(ArcOutcome::Arc(g)),
            Err(ArcError::ZeroArcWithR) => {
                step.warn(
                    Rule::ZeroArc,
                    rw.span,
                    format!("{} with {}: start and end coincide, a 0-degree arc (no motion)", gname.name(step.profile), rw.text()),
                );
                Ok(ArcOutcome::Zero)
            }
            Err(ArcError::RadiusTooSmall(r, half)) => Err(step.alarm(
                Rule::RadiusTolerance,
                rw.span,
                format!("{} {}: radius {r:.4} mm is less than half the distance to the end point ({half:.4} mm)", gname.name(step.profile), rw.text()),
            )),
            Err(e) => unreachable!("{e:?}"),
        };
    }
    if ca.is_none() && cb.is_none() {
        // FANUC 0i-F parameter 3403#5 CIR = 0: G02/G03 with neither R nor I/J/K moves to the end
        // point in a straight line (PS0022 when 1).
        let cir = step.profile.frame.arc_without_centre.filter(|_| matches!(gname, What::Code(GFn::ArcCw | GFn::ArcCcw)));
        if let Some(key) = cir.filter(|k| step.params.get(*k) == 0.0) {
            let msg =
                format!("{} without R or {} {}: a straight move to the end point (parameter {key} CIR = 0)", gname.name(step.profile), la as char, lb as char);
            step.warn(Rule::ArcAsLine, step.span, msg);
            return Ok(ArcOutcome::Straight);
        }
        return Err(step.alarm(
            Rule::ArcDataMissing,
            step.span,
            format!("{} needs R or the centre words {} and {} in this plane", gname.name(step.profile), la as char, lb as char),
        ));
    }
    let mut center = from;
    for (w, axis) in [(ca, a), (cb, b)] {
        if let Some(w) = w {
            // I, J, K: from the start point to the centre, radius values (TDi help G02/03).
            let v = step.length(w)?;
            center.set_axis(axis, from.axis(axis) + v);
        }
    }
    match geom::arc_from_center(from, to, plane, dir, center, ARC_TOLERANCE_MM) {
        Ok(g) => Ok(ArcOutcome::Arc(g)),
        Err(ArcError::RadiusMismatch(rs, re)) => Err(step.alarm(
            Rule::RadiusTolerance,
            step.span,
            format!("{}: the end point is {re:.4} mm from the centre, the start point {rs:.4} mm (tolerance {ARC_TOLERANCE_MM} mm)", gname.name(step.profile)),
        )),
        Err(e) => unreachable!("{e:?}"),
    }
}

fn arc(step: &mut Step, words: &mut Words, from: Vec3, to: Vec3, dir: ArcDir) -> Result<(), Diagnostic> {
    let plane = step.st.modes.plane;
    let gname = What::Code(if dir == ArcDir::Cw { GFn::ArcCw } else { GFn::ArcCcw });
    match resolve_arc(step, words, from, to, dir, gname)? {
        ArcOutcome::Arc(g) => {
            let feed = step.cutting_feed(gname, &|u| geom::arc_point(&from, &to, plane, dir, &g, u))?;
            step.emit(Op::Arc { from, to, center: g.center, plane, dir, feed_mm_min: feed });
        }
        ArcOutcome::Zero | ArcOutcome::Straight => {
            if to != from {
                // Only the axis normal to the plane moves (a 0-degree arc), or a straight move.
                let feed = step.cutting_feed(gname, &|u| lerp(&from, &to, u))?;
                step.emit(Op::Feed { from, to, feed_mm_min: feed });
            }
        }
    }
    Ok(())
}
