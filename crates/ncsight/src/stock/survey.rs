//! The first look a simulation takes at a whole programme, record by record, before it cuts: the
//! tools a setup lacks (assumed from what each does), the stock a programme implies when none
//! is given, the grid a thread needs, and how much work the cut will be. Its memory grows with
//! the number of tools, never with the number of records, so a programme of any length is
//! surveyed and then cut in a second pass over the same records (the command line runs the
//! programme twice; nothing holds its records).

use super::{Bar, Setup, Tool, ToolKind};
use crate::motion::{Op, Record, Vec3};

/// How far behind the deepest cut a guessed stock ends (where the chuck is assumed): a part
/// needs some length to be held by, and a parting tool's width goes past its programmed point.
pub const GUESS_HOLD_MM: f64 = 5.0;

/// What one tool does over the whole programme.
#[derive(Debug, Clone, Copy, Default)]
struct Use {
    threads: bool,
    on_axis_feeds: bool,
    other_cuts: bool,
    /// Rapids straight after a cut, mostly along X: toward the axis, away from it.
    leaves_down: u32,
    leaves_up: u32,
    /// The drilled range along Z (a drill's feeds): deepest, highest.
    drilled: Option<(f64, f64)>,
}

impl Use {
    fn is_drill(&self) -> bool {
        self.on_axis_feeds && !self.other_cuts && !self.threads
    }

    /// A tool that works inside: it leaves its cuts toward the axis.
    fn inside(&self) -> bool {
        !self.is_drill() && self.leaves_down > self.leaves_up
    }
}

/// The cutting moves' extents, for the stock a programme implies ([`LatheSurvey::guessed_bar`]).
#[derive(Debug, Clone, Copy)]
struct BarGuess {
    /// The largest radius a cut runs along (the smaller end of each cutting move), and the
    /// largest any cut reaches.
    along: f64,
    widest: f64,
    /// Whether anything but threads cuts (then the programme makes its own bore).
    other_cuts: bool,
    zmin: f64,
    zmax: f64,
    lead: f64,
    thread_max_x: f64,
    thread_min_x: f64,
}

impl Default for BarGuess {
    fn default() -> BarGuess {
        BarGuess { along: 0.0, widest: 0.0, other_cuts: false, zmin: f64::MAX, zmax: f64::MIN, lead: 0.0, thread_max_x: f64::MIN, thread_min_x: f64::MAX }
    }
}

impl BarGuess {
    fn add(&mut self, op: &Op) {
        let (from, to) = match *op {
            Op::Feed { from, to, .. } | Op::Arc { from, to, .. } => {
                self.other_cuts = true;
                (from, to)
            }
            Op::Thread { from, to, lead_mm, .. } | Op::ThreadArc { from, to, lead_mm, .. } => {
                self.lead = self.lead.max(lead_mm);
                self.thread_max_x = self.thread_max_x.max(from.x).max(to.x);
                self.thread_min_x = self.thread_min_x.min(from.x).min(to.x);
                (from, to)
            }
            _ => return,
        };
        self.along = self.along.max(from.x.min(to.x));
        self.widest = self.widest.max(from.x).max(to.x);
        self.zmin = self.zmin.min(from.z).min(to.z);
        self.zmax = self.zmax.max(from.z).max(to.z);
    }

    /// See [`LatheSurvey::guessed_bar`].
    fn bar(&self, internal: bool) -> Option<Bar> {
        if self.zmin > self.zmax {
            return None;
        }
        let mut radius = if self.along > 0.0 { self.along } else { self.widest };
        let mut bore = 0.0;
        let height = 0.61343 * self.lead;
        if internal && self.lead > 0.0 && !self.other_cuts {
            // A programme that only threads inside: the bore it was written for, and a wall of
            // twice the thread's height and 5 mm around it.
            radius = radius.max(self.thread_max_x + 2.0 * height + 5.0);
            bore = 2.0 * (self.thread_max_x - height);
        } else if self.lead > 0.0 && !internal {
            radius = radius.max(self.thread_min_x + height);
        }
        if radius <= 0.0 {
            return None;
        }
        // Z0 where the cuts reach it; else the nearest cut when they all lie below Z0, the
        // highest when they all lie above it (the programme's zero is not at the face), less
        // two leads where it threads (a thread starts in the air, to come up to speed).
        let front = if self.zmin > 0.0 { (self.zmax - 2.0 * self.lead).max(self.zmin) } else { self.zmax.min(0.0).max(self.zmin) };
        Some(Bar { diameter_mm: 2.0 * radius, length_mm: (front - self.zmin) + GUESS_HOLD_MM, bore_mm: bore.max(0.0), front_z_mm: front })
    }
}

/// The first look at a lathe programme (see the module).
#[derive(Debug, Clone, Default)]
pub struct LatheSurvey {
    uses: Vec<(u32, Use)>,
    current: u32,
    after_cut: bool,
    /// (a tool that has drilled, a tool used after it, the narrowest diameter the later tool's
    /// positions reached within the hole as drilled by then).
    within_holes: Vec<(u32, u32, f64)>,
    guess: BarGuess,
    /// The largest lead of a thread record (the grid's spacing follows it).
    pub max_lead_mm: f64,
    /// The first rapid's index: motion up to and including it is not cut.
    pub first_rapid: Option<usize>,
    /// Records seen.
    pub records: usize,
    /// The z spans of the moves, each clipped to the stock's length as then known, and how
    /// many moves (for [`LatheSurvey::work_estimate`]).
    spans_mm: f64,
    moves: f64,
    /// The setup's bar length, which clips the spans (0: none given).
    bar_length_mm: f64,
}

impl LatheSurvey {
    pub fn new(setup: &Setup) -> LatheSurvey {
        LatheSurvey { bar_length_mm: setup.stock.map_or(0.0, |b| b.length_mm), ..LatheSurvey::default() }
    }

    /// The stock became known during the survey (a simulator's `[BILLET` line): its length
    /// from there on, the records surveyed kept.
    pub fn stock_given(&mut self, setup: &Setup) {
        self.bar_length_mm = setup.stock.map_or(0.0, |b| b.length_mm);
    }

    fn use_of(&mut self, n: u32) -> usize {
        match self.uses.iter().position(|(m, _)| *m == n) {
            Some(i) => i,
            None => {
                self.uses.push((n, Use::default()));
                self.uses.len() - 1
            }
        }
    }

    /// Take one record in.
    pub fn add(&mut self, r: &Record) {
        if self.first_rapid.is_none() && matches!(r.op, Op::Rapid { .. }) {
            self.first_rapid = Some(self.records);
        }
        self.records += 1;
        let i = self.use_of(self.current);
        let u = &mut self.uses[i].1;
        match r.op {
            Op::Tool { number, .. } => {
                self.current = number;
                self.use_of(number);
            }
            Op::Thread { .. } | Op::ThreadArc { .. } => u.threads = true,
            Op::Feed { from, to, .. } if from.x.abs() < 1e-3 && to.x.abs() < 1e-3 && from.z != to.z => {
                u.on_axis_feeds = true;
                let (lo, hi) = u.drilled.unwrap_or((f64::MAX, f64::MIN));
                u.drilled = Some((lo.min(from.z).min(to.z), hi.max(from.z).max(to.z)));
            }
            Op::Feed { .. } | Op::Arc { .. } => u.other_cuts = true,
            Op::Rapid { from, to } if self.after_cut && (to.x - from.x).abs() > (to.z - from.z).abs() => {
                if to.x < from.x {
                    u.leaves_down += 1
                } else {
                    u.leaves_up += 1
                }
            }
            _ => {}
        }
        self.after_cut = matches!(r.op, Op::Feed { .. } | Op::Arc { .. } | Op::Thread { .. } | Op::ThreadArc { .. });
        if let Some(p) = r.op.end_point() {
            self.within_holes(p);
        }
        self.guess.add(&r.op);
        if let Op::Thread { lead_mm, .. } | Op::ThreadArc { lead_mm, .. } = r.op {
            self.max_lead_mm = self.max_lead_mm.max(lead_mm);
        }
        self.add_span(&r.op);
    }

    /// Where the tool in use is, within the holes other tools have drilled: the narrowest place
    /// it reaches in each (a drill is as wide as what a later inside tool works in).
    fn within_holes(&mut self, p: Vec3) {
        if p.x <= 1e-3 {
            return;
        }
        let current = self.current;
        for (n, u) in &self.uses {
            let Some((lo, hi)) = u.drilled.filter(|_| *n != current) else { continue };
            if p.z < hi && p.z > lo {
                match self.within_holes.iter_mut().find(|(d, t, _)| *d == *n && *t == current) {
                    Some(w) => w.2 = w.2.min(2.0 * p.x),
                    None => self.within_holes.push((*n, current, 2.0 * p.x)),
                }
            }
        }
    }

    fn add_span(&mut self, op: &Op) {
        let span = match *op {
            // An arc may bulge beyond its end points: its whole circle's extent.
            Op::Arc { center, from, .. } | Op::ThreadArc { center, from, .. } => 2.0 * center.dist(&from),
            Op::Thread { from, to, .. } | Op::Feed { from, to, .. } | Op::Rapid { from, to } => (to.z - from.z).abs(),
            _ => return,
        };
        // The stock's length: the setup's, or what the cuts so far span (a guess grows with them).
        let g = &self.guess;
        let length = if self.bar_length_mm > 0.0 {
            self.bar_length_mm
        } else if g.zmin <= g.zmax {
            g.zmax.min(0.0).max(g.zmin) - g.zmin + GUESS_HOLD_MM
        } else {
            GUESS_HOLD_MM
        };
        self.spans_mm += span.min(length);
        self.moves += 1.0;
    }

    /// An upper bound of the cell updates the cut makes on a grid of `ntheta` angles `dz` apart:
    /// every move touches each row over its z extent (clipped to the stock as known when it
    /// came).
    pub fn work_estimate(&self, dz: f64, ntheta: usize) -> f64 {
        (self.spans_mm / dz + 2.0 * self.moves) * ntheta as f64
    }

    /// The tools the setup lacks, from what each does (docs/commands/simulate.md):
    /// - one that cuts a thread is a sharp 60-degree threading insert (internal when it leaves
    ///   its passes toward the axis);
    /// - one that only feeds along Z on the spindle axis is a drill with a 118-degree point, as
    ///   wide as the narrowest place a later tool that works inside reaches within its hole
    ///   (10 mm when none does);
    /// - any other turns, an 80-degree insert with a 0.4 mm nose radius: a boring bar when it
    ///   leaves its cuts toward the axis (its rapids straight after a cut go mostly along X,
    ///   down): it works inside; else a turning tool, each of whose moves cuts the nearer side
    ///   of the material.
    pub fn assumed_tools(&self, setup: &Setup) -> Vec<(u32, Tool)> {
        let use_of = |n: u32| self.uses.iter().find(|(m, _)| *m == n).map(|(_, u)| *u).unwrap_or_default();
        let drill_diameter = |drill: u32| -> f64 {
            let narrowest = self
                .within_holes
                .iter()
                .filter(|(d, t, _)| {
                    *d == drill && {
                        let u = use_of(*t);
                        u.inside() || u.threads
                    }
                })
                .map(|w| w.2)
                .fold(f64::MAX, f64::min);
            if narrowest < f64::MAX {
                narrowest
            } else {
                10.0
            }
        };
        self.uses
            .iter()
            .filter(|(n, u)| !setup.tools.iter().any(|t| t.number == *n) && (u.threads || u.on_axis_feeds || u.other_cuts))
            .map(|&(n, u)| {
                let tool = if u.threads {
                    Tool { number: n, internal: u.leaves_down > u.leaves_up, ..Tool::default_thread() }
                } else if u.is_drill() {
                    Tool { number: n, kind: ToolKind::Drill, diameter_mm: drill_diameter(n), ..Tool::default_thread() }
                } else {
                    let kind = if u.inside() { ToolKind::Boring } else { ToolKind::Turning };
                    Tool { number: n, kind, included_angle_deg: 80.0, tip_radius_mm: 0.4, ..Tool::default_thread() }
                };
                (n, tool)
            })
            .collect()
    }

    /// Whether a tool (as the setup gives it, or assumed) cuts a thread inside a bore.
    pub fn threads_inside(&self, setup: &Setup, assumed: &[(u32, Tool)]) -> bool {
        self.uses
            .iter()
            .filter(|(_, u)| u.threads)
            .any(|(n, _)| assumed.iter().find(|(m, _)| m == n).map(|(_, t)| *t).unwrap_or_else(|| setup.tool(*n)).internal)
    }

    /// The stock a programme implies when none is given (docs/commands/simulate.md, an
    /// assumption: give `--stock` to be sure), from the extents of its cutting moves (feeds,
    /// arcs, threads):
    /// - the diameter is the largest one the tool cuts along (for each cutting move the smaller
    ///   of its two diameters, so a move coming in from outside, a facing cut or a retract, does
    ///   not count beyond where it cuts), or the largest diameter of any cut when none runs
    ///   along one;
    /// - the face is at Z0 where the cuts reach it (otherwise at the nearest cut below Z0, or at
    ///   the highest, less two leads of a thread's approach, when every cut lies above Z0), and
    ///   the bar runs to the deepest cut plus
    ///   [`GUESS_HOLD_MM`], where the chuck is assumed;
    /// - with an external thread, at least the thread's deepest pass plus twice the ISO external
    ///   thread height 0.61343 x lead (a programme that only threads: the blank's diameter);
    /// - a programme that only cuts an internal thread: the bore is its deepest pass less twice
    ///   that height, the outside twice that height and 5 mm beyond it (a programme that also
    ///   turns or bores makes its own bore: solid stock).
    pub fn guessed_bar(&self, internal: bool) -> Option<Bar> {
        self.guess.bar(internal)
    }
}

/// The first look at a machining centre's programme: the cutting moves' extent (the block a
/// setup lacks), which tools feed across below the top, and where the first rapid is.
#[derive(Debug, Clone)]
pub struct MillSurvey {
    /// The cutting moves' end points' extent, min and max per axis.
    pub cut_min: [f64; 3],
    pub cut_max: [f64; 3],
    /// Per tool: its feeds (their lowest point and whether any goes sideways).
    tools: Vec<(u32, f64, bool)>,
    current: u32,
    pub first_rapid: Option<usize>,
    pub records: usize,
}

impl Default for MillSurvey {
    fn default() -> MillSurvey {
        MillSurvey { cut_min: [f64::MAX; 3], cut_max: [f64::MIN; 3], tools: Vec::new(), current: 0, first_rapid: None, records: 0 }
    }
}

impl MillSurvey {
    pub fn add(&mut self, r: &Record) {
        if self.first_rapid.is_none() && matches!(r.op, Op::Rapid { .. }) {
            self.first_rapid = Some(self.records);
        }
        self.records += 1;
        let (from, to) = match r.op {
            Op::Tool { number, .. } => {
                self.current = number;
                return;
            }
            Op::Feed { from, to, .. } | Op::Arc { from, to, .. } => (from, to),
            _ => return,
        };
        for k in 0..3 {
            self.cut_min[k] = self.cut_min[k].min(to.axis(k));
            self.cut_max[k] = self.cut_max[k].max(to.axis(k));
        }
        let sideways = matches!(r.op, Op::Arc { .. }) || (from.x - to.x).abs() > 1e-9 || (from.y - to.y).abs() > 1e-9;
        let low = from.z.min(to.z);
        match self.tools.iter_mut().find(|(n, _, _)| *n == self.current) {
            // Sideways below the top is decided once the top is known: keep the lowest sideways feed.
            Some(t) => {
                if sideways {
                    t.1 = t.1.min(low);
                    t.2 = true;
                }
            }
            None => self.tools.push((self.current, if sideways { low } else { f64::MAX }, sideways)),
        }
    }

    /// The tools (T numbers) that make cutting moves.
    pub fn cutting_tools(&self) -> impl Iterator<Item = u32> + '_ {
        self.tools.iter().map(|t| t.0)
    }

    /// Whether any move cuts (feeds or arcs).
    pub fn cuts(&self) -> bool {
        self.cut_min[0] <= self.cut_max[0]
    }

    /// The tools of a machining centre the setup lacks, from what each does: one that only
    /// feeds along Z is a 5 mm drill with a 118-degree point (as before); one that feeds across
    /// below the block's top (`top_z`) is a 10 mm flat end mill (docs/commands/simulate.md).
    pub fn assumed_tools(&self, setup: &Setup, top_z: f64) -> Vec<(u32, Tool)> {
        self.tools
            .iter()
            .filter(|(n, _, _)| !setup.tools.iter().any(|t| t.number == *n))
            .map(|&(n, low, sideways)| {
                let tool = if sideways && low < top_z {
                    Tool { number: n, kind: ToolKind::Mill, diameter_mm: 10.0, ..Tool::default_thread() }
                } else {
                    Tool { number: n, ..setup.mill_tool(n) }
                };
                (n, tool)
            })
            .collect()
    }
}
