//! Where the tool is on the machine (docs/reference/macro.md section 10.2; docs/setup.md): the machine's
//! tables from the setup, and the codes that move programme coordinates against machine
//! coordinates: G54-G59, G50/G92, G52, G53, and the reference returns G28/G30.
//!
//! machine = programme + external offset + work offset (G54-G59) + G50/G92 shift + G52 local
//! origin + tool offset. Positions stay in programme coordinates, as the controller's absolute
//! display shows them; every record carries the sum to add for machine coordinates.

use super::{axis_target, Step, Words};
use crate::alarm::{Diagnostic, Rule};
use crate::modal::{DataInput, Frame};
use crate::motion::{Op, Vec3};
use crate::profile::Profile;
use crate::setup::{Offset, Point, Setup};
use crate::source::Span;

/// The machine's tables for one run, in the interpreter's units (X as a radius on a lathe).
#[derive(Debug, Clone, PartialEq)]
pub struct Tables {
    /// A setup gave them: records carry machine positions.
    pub given: bool,
    /// The setup has a `[machine]` part (a reference point it lacks is then worth a warning).
    pub machine_given: bool,
    /// The external offset (0), then G54-G59 (1-6): machine coordinates of each zero.
    pub work_mm: [Vec3; WORK_SYSTEMS],
    /// Reference points 1-4 in machine coordinates (`None`: not in the setup).
    pub reference_mm: [Option<Vec3>; 4],
    /// Soft travel limits per axis, machine coordinates.
    pub limits_mm: [Option<[f64; 2]>; 3],
    /// Some axis has a limit (checked once per record).
    pub limited: bool,
    /// Where the tool is at power on (machine coordinates), when the setup says.
    pub power_on_mm: Option<Vec3>,
    /// The offset table by number (X and its wear as radii on a lathe).
    pub offsets: Vec<Offset>,
    /// The axes A, B, C the setup declares (`[machine] axes`), rotary unless `linear_extra`.
    pub rotary: [bool; 3],
    /// Axes taken without a setup's `[machine] axes` (the profile's `assumed_axes`): their first
    /// word is worth a warning.
    pub assumed_axes: crate::profile::Letters,
    /// Those of them declared linear (`kind = "linear"`: a sub-spindle's travel B): millimetres
    /// as X, Y and Z, moved as the rotary axes are (G00, G01, G28, G53), recorded as slides.
    pub linear_extra: [bool; 3],
    /// Axis addresses the setup adds to the profile's: a lathe's Y (and V), the rotary axes
    /// (and H, the FANUC lathe's incremental C).
    pub added_addresses: crate::profile::Letters,
    /// The controlled axes in the control's order (what #5001-#5006 read): the setup's
    /// `[machine] axes` as written, else the profile's.
    pub axis_order: Vec<u8>,
    /// The P values that select a spindle (the setup's `spindle_p`; empty: one spindle).
    pub spindle_p: Vec<u32>,
    /// They are the profile's assumption, no setup's: the first selection is worth a warning.
    pub spindle_p_assumed: bool,
    /// The machine builder's own M codes the setup lists (`[machine] m_codes`): no warning.
    pub own_m_codes: Vec<u32>,
}

/// The external offset, G54-G59 and G54.1 P1-P48: the work systems a table holds.
pub const WORK_SYSTEMS: usize = 7 + crate::setup::ADDITIONAL_WORK_SYSTEMS;

/// G54.1 P1-P48: work system 6 + P (FANUC 0i-MF, additional work coordinate systems).
pub(super) fn select_additional_work(step: &mut Step, words: &mut Words, span: Span) -> Result<(), Diagnostic> {
    let max = crate::setup::ADDITIONAL_WORK_SYSTEMS;
    let p = match words.take(b'P') {
        Some(w) if w.decimal || w.value < 1.0 || w.value > max as f64 || w.value.fract() != 0.0 => {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: G54.1 P selects additional work system 1 to {max}", w.text())));
        }
        Some(w) => w.value as u8,
        None => return Err(step.alarm(Rule::MissingWord, span, format!("G54.1 needs P: the additional work system, 1 to {max}"))),
    };
    select_work(step, 6 + p);
    Ok(())
}

impl Tables {
    /// Without a setup: every offset 0, machine coordinates the programme's, the reference
    /// point the profile's assumption, the tool at programme zero at power on (docs/setup.md).
    pub fn none(profile: &Profile) -> Tables {
        let mut t = Tables {
            given: false,
            machine_given: false,
            work_mm: [Vec3::default(); WORK_SYSTEMS],
            reference_mm: [Some(profile.reference_point_mm), None, None, None],
            limits_mm: [None; 3],
            limited: false,
            power_on_mm: None,
            offsets: Vec::new(),
            rotary: [false; 3],
            linear_extra: [false; 3],
            added_addresses: crate::profile::Letters::EMPTY,
            axis_order: profile.axes.bytes().collect(),
            spindle_p: profile.frame.assumed_spindle_p.to_vec(),
            assumed_axes: crate::profile::Letters::EMPTY,
            spindle_p_assumed: !profile.frame.assumed_spindle_p.is_empty(),
            own_m_codes: Vec::new(),
        };
        // The axes a machine of this controller usually has, taken (with a warning at their first
        // word) until a setup says which it has.
        for letter in profile.frame.assumed_axes.bytes() {
            t.add_axis(profile, letter, false);
            t.assumed_axes = t.assumed_axes.with(letter);
            t.axis_order.push(letter);
        }
        t
    }

    /// Axis `letter` added to the profile's own (a setup's `[machine] axes`, or an assumed one):
    /// its address, V for Y and H for a rotary C where the profile has incremental addresses.
    fn add_axis(&mut self, profile: &Profile, letter: u8, linear: bool) {
        if profile.takes_address(letter) {
            return;
        }
        self.added_addresses = self.added_addresses.with(letter);
        match letter {
            b'Y' if profile.incremental_addresses => self.added_addresses = self.added_addresses.with(b'V'),
            b'A' | b'B' | b'C' => {
                let i = usize::from(letter - b'A');
                self.rotary[i] = true;
                self.linear_extra[i] = linear;
                if letter == b'C' && profile.incremental_addresses && !linear {
                    self.added_addresses = self.added_addresses.with(b'H');
                }
            }
            _ => {}
        }
    }

    /// The tables a setup gives; what it leaves out is as [`Tables::none`], except that the
    /// tool starts at the reference point (the machine has been referenced).
    pub fn from_setup(setup: &Setup, profile: &Profile) -> Tables {
        let x_scale = if profile.diameter_x { 0.5 } else { 1.0 };
        let point = |p: &Point| {
            let [x, y, z] = p.xyz();
            Vec3::new(x * x_scale, y, z)
        };
        let mut t = Tables::none(profile);
        t.given = true;
        t.machine_given = setup.machine.is_some();
        if let Some(w) = &setup.work {
            for (slot, p) in t.work_mm.iter_mut().zip(w.all()) {
                if let Some(p) = p {
                    *slot = point(&p);
                }
            }
        }
        if let Some(m) = &setup.machine {
            t.own_m_codes = m.own_m_codes().collect();
            if !m.spindle_p.is_empty() {
                t.spindle_p = m.spindle_p.clone();
                t.spindle_p_assumed = false;
            }
            if !m.axes.is_empty() {
                // The machine's axes as declared: none assumed.
                t.axis_order = m.axes.iter().map(|a| a.letter()).collect();
                t.added_addresses = crate::profile::Letters::EMPTY;
                t.assumed_axes = crate::profile::Letters::EMPTY;
                t.rotary = [false; 3];
            }
            for a in &m.axes {
                t.add_axis(profile, a.letter(), a.linear_extra());
            }
            for (slot, p) in t.reference_mm.iter_mut().zip([m.reference, m.reference_2, m.reference_3, m.reference_4]) {
                if let Some(p) = p {
                    *slot = Some(point(&p));
                }
            }
            if let Some(l) = m.limits {
                t.limits_mm = l.by_axis();
                t.limited = t.limits_mm.iter().any(Option::is_some);
                if let Some([lo, hi]) = t.limits_mm[0] {
                    t.limits_mm[0] = Some([lo * x_scale, hi * x_scale]);
                }
            }
        }
        // The tool starts at the reference point the setup gives; without one, at programme
        // zero as without a setup (a setup of stock and tools only changes no position).
        t.power_on_mm = setup.machine.as_ref().and_then(|m| m.reference).map(|_| t.reference_mm[0].unwrap_or_default());
        t.offsets = setup.offsets.iter().map(|o| Offset { x_mm: o.x_mm * x_scale, wear_x_mm: o.wear_x_mm * x_scale, ..*o }).collect();
        t
    }

    /// Offset `number` of the table.
    pub fn offset(&self, number: u32) -> Option<&Offset> {
        self.offsets.iter().find(|o| o.number == number)
    }

    /// Apply a G10 write (after its block ran); returns what the origin of `frame` moved by.
    pub fn write(&mut self, w: TableWrite, frame: &Frame) -> Vec3 {
        let before = self.to_machine(frame);
        match w {
            TableWrite::Work(i, p) => self.work_mm[i] = p,
            TableWrite::Offset(o) => match self.offsets.iter_mut().find(|e| e.number == o.number) {
                Some(e) => *e = o,
                None => self.offsets.push(o),
            },
        }
        self.to_machine(frame) - before
    }

    /// What to add to programme coordinates for machine coordinates in `frame`.
    pub fn to_machine(&self, frame: &Frame) -> Vec3 {
        self.work_mm[0] + self.work_mm[usize::from(frame.work).clamp(1, WORK_SYSTEMS - 1)] + frame.shift + frame.local + frame.tool()
    }

    /// A machine position beyond a soft limit: (axis, the limit, the machine coordinate,
    /// beyond the upper end). Checked on every motion record's ends and an arc's extremes.
    pub fn beyond_limit(&self, lo: &Vec3, hi: &Vec3) -> Option<(usize, f64, f64, bool)> {
        for axis in 0..3 {
            if let Some([min, max]) = self.limits_mm[axis] {
                // A hundredth of a micrometre for rounding in the sums.
                if hi.axis(axis) > max + 1e-6 {
                    return Some((axis, max, hi.axis(axis), true));
                }
                if lo.axis(axis) < min - 1e-6 {
                    return Some((axis, min, lo.axis(axis), false));
                }
            }
        }
        None
    }
}

/// What a G10 block writes into the tables, applied when the block has run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TableWrite {
    /// Work offset 0 (external) or 1-6 (G54-G59).
    Work(usize, Vec3),
    /// A whole entry of the offset table.
    Offset(Offset),
}

/// Change the frame and keep the tool where it is on the machine: its programme coordinates
/// move by what the frame moved.
pub(super) fn reframe(step: &mut Step, change: impl FnOnce(&mut Frame)) {
    let before = step.tables.to_machine(&step.st.frame);
    change(&mut step.st.frame);
    let after = step.tables.to_machine(&step.st.frame);
    step.st.place.pos = step.st.place.pos + before - after;
    // Where the compensated tool waits moves with it.
    if let Some(a) = step.st.comp.actual {
        step.st.comp.actual = Some(a + before - after);
    }
}

/// G54-G59: select work system `n` (1-6).
pub(super) fn select_work(step: &mut Step, n: u8) {
    reframe(step, |f| f.work = n);
}

/// G50 (lathe) / G92 (mill): the current position gets the coordinates given. The shift acts on
/// every work system (GSK980TDi help text, G54-G59 note 7), and cancels the G52 local system
/// of the axes given (help text G52 note 5; FANUC the same, inferred).
pub(super) fn set_coordinates(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let (target, given) = axis_target(step, words)?;
    let st = &mut *step.st;
    // The position shown (the tool's plus an offset's movement not made yet) gets the values.
    let shown = st.place.pos + st.frame.unmoved;
    for (a, _) in given.iter().enumerate().filter(|(_, g)| g.is_some()) {
        let shift = st.frame.shift.axis(a) + st.frame.local.axis(a) + shown.axis(a) - target.axis(a);
        st.frame.shift.set_axis(a, shift);
        st.frame.local.set_axis(a, 0.0);
    }
    let moved = (target - st.frame.unmoved) - st.place.pos;
    st.place.pos = target - st.frame.unmoved;
    // Where a compensated tool waits is in the new coordinates too.
    if let Some(a) = st.comp.actual {
        st.comp.actual = Some(a + moved);
    }
    Ok(())
}

/// The axis words of a block as written, mm (X as a radius), whether absolute or incremental
/// addresses, each with whether it came by its incremental address (U, V, W): G52 and G53 read
/// them as values (GSK980TDi help text, G52: X and U have the same effect), G10 sets or adds.
fn written_axes(step: &mut Step, words: &mut Words) -> Result<[Option<(f64, bool)>; 3], Diagnostic> {
    let mut values = [None; 3];
    for (abs_l, inc_l, axis) in [(b'X', b'U', 0), (b'Y', b'V', 1), (b'Z', b'W', 2)] {
        let abs_w = words.take(abs_l);
        let inc_w = if step.profile.incremental_addresses { words.take(inc_l) } else { None };
        if let (Some(a), Some(i)) = (abs_w, inc_w) {
            return Err(step.alarm(Rule::DuplicateWord, i.span, format!("{} and {} both give the {} axis", a.text(), i.text(), abs_l as char)));
        }
        if let Some(w) = abs_w.or(inc_w) {
            let scale = if axis == 0 && step.profile.diameter_x { 0.5 } else { 1.0 };
            values[axis] = Some((step.length(w)? * scale, inc_w.is_some()));
        }
    }
    Ok(values)
}

/// G52: the local system's origin at the point given, in the work system (absolute whatever
/// the address or G90/G91: GSK980TDi help text, G52; FANUC inferred alike). `G52 X0 Z0` cancels.
pub(super) fn local(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let values = written_axes(step, words)?;
    reframe(step, |f| {
        for (a, v) in values.iter().enumerate() {
            if let Some((v, _)) = v {
                f.local.set_axis(a, *v);
            }
        }
    });
    Ok(())
}

/// G53: positioning at rapid traverse to the machine coordinates given, this block only. The
/// FANUC manuals make it absolute only: given incrementally (G91, U/W), G53 is ignored and the
/// block moves as it would without it (warning NCS-W30). Returns whether the move was made.
pub(super) fn machine_move(step: &mut Step, words: &mut Words, span: Span) -> Result<bool, Diagnostic> {
    let incremental = step.st.modes.incremental || {
        let letters: &[u8] = if step.profile.incremental_addresses { b"UVW" } else { b"" };
        letters.iter().any(|l| words.has(*l))
    };
    if incremental {
        let msg = "G53 with an incremental command is ignored (FANUC: machine coordinates are absolute only); the block moves as without it";
        step.warn(Rule::MachineIncremental, span, msg);
        return Ok(false);
    }
    let values = written_axes(step, words)?;
    // The declared A, B, C: no work offset applies to them, so machine and programme agree.
    let extra = super::rotary_target(step, words)?;
    let origin = step.tables.to_machine(&step.st.frame);
    let from = step.st.place.pos;
    let mut to = from;
    for (a, v) in values.iter().enumerate() {
        if let Some((v, _)) = v {
            to.set_axis(a, v - origin.axis(a));
        }
    }
    if to != from {
        step.emit(Op::Rapid { from, to });
    }
    if let Some(to_deg) = extra {
        super::emit_rotary(step, to_deg, true, 0.0, to != from);
    }
    Ok(true)
}

/// G28 (`n` = 1) and G30 (`n` = 2-4): rapid to the intermediate point given (absolute or
/// incremental), then to reference point `n` on the axes given. GSK: the tool offset is
/// cancelled (help text G28 note 2, G30 note 3).
pub(super) fn reference_return(step: &mut Step, words: &mut Words, n: usize, span: Span) -> Result<(), Diagnostic> {
    // A, B, C named (`G28 H0`, `G28 B0`): each goes at rapid to its intermediate point with the
    // linear axes, then to its reference point, zero (the setup gives none for them: assumed, as
    // no offset applies to them either).
    let extra = super::extra_axes_target(step, words)?;
    let (mid, given) = axis_target(step, words)?;
    let linear = given.iter().any(Option::is_some);
    if !linear && extra.is_none() {
        return Ok(());
    }
    let reference = if linear { reference_point(step, n, span) } else { Vec3::default() };
    let moved = mid != step.st.place.pos;
    if moved {
        step.emit(Op::Rapid { from: step.st.place.pos, to: mid });
    }
    if let Some((extra_mid, _)) = extra {
        super::emit_rotary(step, extra_mid, true, 0.0, moved);
    }
    // Kept for G29, per axis named (FANUC 0i manual, G29: the G28 or G30 before it).
    for (a, _) in given.iter().enumerate().filter(|(_, g)| g.is_some()) {
        step.st.place.reference_mid[a] = Some(mid.axis(a));
    }
    if step.profile.frame.reference_cancels_tool_offset && linear {
        reframe(step, |f| {
            f.geometry = Vec3::default();
            f.wear = Vec3::default();
            f.unmoved = Vec3::default();
            f.offset_number = 0;
        });
    }
    let origin = step.tables.to_machine(&step.st.frame);
    let mut home = step.st.place.pos;
    for (a, _) in given.iter().enumerate().filter(|(_, g)| g.is_some()) {
        home.set_axis(a, reference.axis(a) - origin.axis(a));
    }
    let moved = home != step.st.place.pos;
    if moved {
        step.emit(Op::Rapid { from: step.st.place.pos, to: home });
    }
    if let Some((mut extra_home, named)) = extra {
        for i in (0..3).filter(|&i| named[i]) {
            extra_home[i] = 0.0;
        }
        super::emit_rotary(step, extra_home, true, 0.0, moved);
    }
    Ok(())
}

/// Reference point `n` of the setup, machine coordinates; without it, machine zero (with a
/// warning where the setup gives a [machine] but not that point).
fn reference_point(step: &mut Step, n: usize, span: Span) -> Vec3 {
    match step.tables.reference_mm[n - 1] {
        Some(r) => r,
        None => {
            // Without a setup's [machine], every reference point but the first is at machine
            // zero silently (as every other setting then).
            if step.tables.machine_given {
                let msg = format!("reference point {n} is not in the setup ([machine.reference_{n}]): taken as machine zero");
                step.warn(Rule::ReferenceAssumed, span, msg);
            }
            Vec3::default()
        }
    }
}

/// G29 (FANUC 0i manual, "return from the reference position"): each axis named goes at rapid
/// to the intermediate point the last G28 or G30 gave it, then to the point given; an
/// incremental word counts from the intermediate point. The intermediate point is kept as the
/// programme wrote it, so it moves with a change of the coordinate system (as the manual says).
/// An axis no G28/G30 has named since power on has no intermediate point: alarm NCS-E88
/// (ncsight's rule; what the control does then was not found).
pub(super) fn from_reference(step: &mut Step, words: &mut Words, span: Span) -> Result<(), Diagnostic> {
    let shown = step.st.place.pos + step.st.frame.unmoved;
    let (written, given) = axis_target(step, words)?;
    if !given.iter().any(Option::is_some) {
        return Ok(());
    }
    let (mut mid, mut end) = (step.st.place.pos, step.st.place.pos);
    for (a, how) in given.iter().enumerate().filter_map(|(a, g)| g.map(|g| (a, g))) {
        let Some(m) = step.st.place.reference_mid[a] else {
            let letter = ['X', 'Y', 'Z'][a];
            return Err(step.alarm(
                Rule::NoIntermediatePoint,
                span,
                format!("G29 names {letter}, and no G28 or G30 has given {letter} an intermediate point since the start"),
            ));
        };
        mid.set_axis(a, m);
        end.set_axis(a, if how == super::Given::Incremental { m + (written.axis(a) - shown.axis(a)) } else { written.axis(a) });
    }
    if mid != step.st.place.pos {
        step.emit(Op::Rapid { from: step.st.place.pos, to: mid });
    }
    if end != step.st.place.pos {
        step.emit(Op::Rapid { from: step.st.place.pos, to: end });
    }
    Ok(())
}

/// A line between G10 L3/L50/L52 and G11. G11 ends the lines. A tool life line is dropped (GSK
/// help text, G10 L3 note 1: its words are ignored). A parameter line is `N<number> [P<axis>]
/// <value letter><value>`, or on the GSK `N<number> R<variable>` to read the parameter into a
/// macro variable. A bit parameter's value is its bits as binary digits (`R00000100` sets bit
/// 2), the FANUC 0i manual's example and GSK note 1. ncsight keeps one value for an axis
/// parameter: P names the axis and the value is the parameter's for every axis (docs).
pub(super) fn data_line(step: &mut Step, block: &crate::read::Block, mode: DataInput) -> Result<(), Diagnostic> {
    let ends = super::codes_of(step.profile, &block.words).any(|g| g.function == crate::profile::GFn::DataSettingEnd);
    if ends {
        step.st.modes.data_input = None;
        return Ok(());
    }
    let DataInput::Parameters(entry) = mode else {
        // A programme end among the tool life lines is data too: G11 is probably missing.
        if let Some(w) = block.words.iter().find(|w| w.letter == b'M' && !w.expr && matches!(w.value as u32, 2 | 30) && w.value.fract() == 0.0) {
            let msg = format!("{}: read as tool life data (the lines after G10 L3 are data up to G11): the programme has not ended; is G11 missing?", w.text());
            step.warn(Rule::TextIgnored, w.span, msg);
        }
        return Ok(());
    };
    let Some(number) = block.sequence else {
        return Err(step.alarm(Rule::MissingWord, block.span, "a parameter line between G10 and G11 needs N, the parameter's number"));
    };
    let (mut value, mut read, mut axis) = (None, None, None);
    for w in &block.words {
        match w.letter {
            l if l == entry.value && value.is_none() => value = Some(w),
            l if Some(l) == entry.read_into && read.is_none() => read = Some(w),
            b'P' if axis.is_none() => axis = Some(w),
            // A programme end among the lines: G11 is probably missing.
            b'M' => {
                return Err(step.alarm(
                    Rule::WordNotTaken,
                    w.span,
                    format!("{}: a parameter line between G10 L{} and G11 takes no M code: is G11 missing?", w.text(), entry.l),
                ));
            }
            // GSK: K and D name PLC parameters, which ncsight does not have.
            b'K' | b'D' if entry.read_into.is_some() => {
                let msg = format!("{}: PLC parameters (K, D) are not modelled by ncsight; the line changes nothing here", w.text());
                step.warn(Rule::NotSimulated, w.span, msg);
                return Ok(());
            }
            _ => {
                return Err(step.alarm(
                    Rule::WordNotTaken,
                    w.span,
                    format!(
                        "{}: a parameter line between G10 L{} and G11 takes N, P and {} only",
                        w.text(),
                        entry.l,
                        std::iter::once(entry.value).chain(entry.read_into).map(|c| (c as char).to_string()).collect::<Vec<_>>().join(" and ")
                    ),
                ))
            }
        }
    }
    if let Some(p) = axis {
        if p.decimal || p.value < 1.0 || p.value > 8.0 {
            return Err(step.alarm(Rule::ValueOutOfRange, p.span, format!("{}: P is the axis number, 1 to 8", p.text())));
        }
    }
    // The profile's parameters of this number: one value, or bits.
    let defs = step.profile.params_numbered(number);
    match (value, read) {
        (Some(a), Some(b)) => {
            Err(step.alarm(Rule::DuplicateWord, b.span, format!("{} and {}: a parameter line writes or reads, not both", a.text(), b.text())))
        }
        (None, None) => Err(step.alarm(Rule::MissingWord, block.span, format!("parameter line N{number}: {} gives the value to write", entry.value as char))),
        (Some(w), None) => write_parameter(step, w, number, &defs),
        (None, Some(r)) => read_parameter(step, r, number, &defs, block.span),
    }
}

/// A parameter line's value written: each parameter (or bit) of the number checked against its
/// range, the G-code system refused; the writes applied after the block.
fn write_parameter(step: &mut Step, w: &crate::read::Word, number: u32, defs: &[(crate::profile::ParamKey, Option<u8>)]) -> Result<(), Diagnostic> {
    if defs.is_empty() {
        let msg = format!("parameter {number} is not one ncsight models: writing it changes nothing here");
        step.warn(Rule::NotSimulated, w.span, msg);
        return Ok(());
    }
    for &(key, bit) in defs {
        let v = match bit {
            // The bits as binary digits: bit b is the digit b places from the right.
            Some(b) => {
                let digits = w.value.round() as u64;
                if w.decimal || w.value < 0.0 || digits.to_string().bytes().any(|c| c > b'1') || digits > 11_111_111 {
                    return Err(step.alarm(
                        Rule::ValueOutOfRange,
                        w.span,
                        format!("{}: parameter {number} is a bit parameter: its value is eight binary digits (as 00000100)", w.text()),
                    ));
                }
                ((digits / 10u64.pow(u32::from(b))) % 10) as f64
            }
            None => w.value,
        };
        if let Err(e) = step.params.check(key, v) {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: {e}", w.text())));
        }
        // The G-code system is the run's (its codes are read by the table chosen at the
        // start): a programme that changes it is not simulated.
        let system_bit = step.profile.g_code_systems.or(step.params.base().g_code_systems).is_some_and(|s| key == s.b || key == s.c);
        if system_bit && v != step.params.get(key) {
            return Err(step.alarm(
                Rule::NotSupported,
                w.span,
                format!("{}: changing the G-code system inside a programme is not simulated by ncsight: give it with --param {key}={v}", w.text()),
            ));
        }
        step.out.param_writes.push((key, v));
    }
    Ok(())
}

/// GSK `N<number> R<variable>`: the parameter read into a macro variable after the block.
fn read_parameter(step: &mut Step, r: &crate::read::Word, number: u32, defs: &[(crate::profile::ParamKey, Option<u8>)], span: Span) -> Result<(), Diagnostic> {
    if r.decimal || r.value < 1.0 || r.value > 9999.0 {
        return Err(step.alarm(
            Rule::ValueOutOfRange,
            r.span,
            format!("{}: R names the macro variable the parameter is read into (R100 reads into #100; inferred)", r.text()),
        ));
    }
    if defs.is_empty() {
        return Err(step.alarm(Rule::NotSupported, span, format!("parameter {number} is not one ncsight models: its value cannot be read")));
    }
    // A bit parameter reads as its binary digits; the bits ncsight does not model read 0.
    let v = defs.iter().map(|(key, bit)| match bit {
        Some(b) => step.params.get(*key) * 10f64.powi(i32::from(*b)),
        None => step.params.get(*key),
    });
    step.out.var_write = Some((r.value as u32, v.sum()));
    Ok(())
}

/// G30's P: the reference point 2-4 (2 when omitted), as far as the profile has them.
pub(super) fn other_reference(step: &mut Step, words: &mut Words) -> Result<usize, Diagnostic> {
    let last = step.profile.frame.last_reference;
    match words.take(b'P') {
        None => Ok(2),
        Some(w) if !w.decimal && w.value >= 2.0 && w.value <= last as f64 => Ok(w.value as usize),
        Some(w) => {
            let range = if last == 2 { "the 2nd reference point only (P2)".to_string() } else { format!("reference point P2 to P{last}") };
            Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: G30 returns to {range} on {}", w.text(), step.profile.name)))
        }
    }
}

/// The entry an offset number names, in the interpreter's units; a number the table lacks is all
/// zero (warning NCS-W32 when the setup has an offset table: without one every offset is 0 by
/// design).
pub(super) fn entry(step: &mut Step, number: u32, span: Span) -> Offset {
    if number == 0 {
        return Offset::default();
    }
    match step.tables.offset(number) {
        Some(o) => *o,
        None => {
            if !step.tables.offsets.is_empty() {
                let msg = format!("offset {number} is not in the setup's [[offset]] table: taken as 0");
                step.warn(Rule::OffsetAssumed, span, msg);
            }
            Offset { number, ..Offset::default() }
        }
    }
}

/// Put a tool offset in force (docs/reference/macro.md 10.1). What shifts the coordinates changes the position
/// the programme reads, with no motion; what moves the tool does so in this block (a rapid of
/// the difference, when the block has no axis words of its own) or with the next move. Either
/// way an absolute move then puts the new tool's tip at the point written, and an incremental
/// one counts from the position the controller shows.
fn put_offset(step: &mut Step, geometry: Vec3, wear: Vec3, number: u32, geometry_by_shift: bool, with_next_move: bool, has_axis: bool) {
    let old = step.st.frame;
    let moved = (wear - old.wear) + if geometry_by_shift { Vec3::default() } else { geometry - old.geometry };
    reframe(step, |f| {
        f.geometry = geometry;
        f.wear = wear;
        f.offset_number = number;
    });
    let unmoved = old.unmoved + moved;
    if unmoved == Vec3::default() {
        return;
    }
    if with_next_move || has_axis {
        step.st.frame.unmoved = unmoved;
    } else {
        let from = step.st.place.pos;
        step.emit(Op::Rapid { from, to: from + unmoved });
    }
}

/// A lathe's T word with an offset part (`T0102` -> 2; `T0100` cancels): that entry's geometry
/// and wear act as the profile's parameters say (FANUC 5002#4 LGT, #6 LWM; GSK settings).
pub(super) fn lathe_offset(step: &mut Step, number: u32, span: Span, has_axis: bool) {
    let Some((geometry_key, wear_key)) = step.profile.frame.lathe_offset_keys else {
        return;
    };
    let e = entry(step, number, span);
    let by_shift = step.params.get(geometry_key) == 0.0;
    let next_move = step.params.get(wear_key) == 1.0;
    put_offset(step, Vec3::new(e.x_mm, e.y_mm, e.z_mm), Vec3::new(e.wear_x_mm, e.wear_y_mm, e.wear_z_mm), number, by_shift, next_move, has_axis);
}

/// G43 (+1) / G44 (-1) with H, G49 (0): the tool length of offset H along Z (FANUC tool length
/// offset A), moved in the block: with its Z move, else as a rapid of the difference. An H in a
/// block while G43/G44 is in force changes the offset (FANUC 0i-MB manual, 14.1.2).
pub(super) fn length_offset(step: &mut Step, sign: i8, h: Option<u32>, span: Span, has_axis: bool) {
    let number = if sign == 0 { 0 } else { h.unwrap_or(step.st.frame.offset_number) };
    let e = entry(step, number, span);
    let length = sign as f64 * (e.length_mm + e.wear_length_mm);
    step.st.frame.length_sign = sign;
    put_offset(step, Vec3::new(0.0, 0.0, length), Vec3::default(), number, false, false, has_axis);
}

/// G10: data setting, in the forms the profile has (docs/reference/macro.md 10.2). The values are written
/// when the block has run; later blocks see them.
pub(super) fn data_setting(step: &mut Step, words: &mut Words, span: Span) -> Result<Option<TableWrite>, Diagnostic> {
    use crate::profile::G10Forms;
    let forms = step.profile.frame.g10;
    let l = match words.take(b'L') {
        Some(w) if w.decimal || w.value < 0.0 => return Err(step.alarm(Rule::IllegalDecimalPoint, w.span, format!("{}: L is a whole number", w.text()))),
        Some(w) => Some(w.value as u32),
        None => None,
    };
    if starts_data_lines(step, l, span)? {
        return Ok(None);
    }
    let p = match words.take(b'P') {
        Some(w) if w.decimal || w.value < 0.0 => return Err(step.alarm(Rule::IllegalDecimalPoint, w.span, format!("{}: P is a whole number", w.text()))),
        Some(w) => (w.value as u32, w),
        None => return Err(step.alarm(Rule::MissingWord, span, "G10 needs P: the work system (L2 P0-P6) or the offset number")),
    };
    let (n, pw) = p;
    // Set (absolute) or add (incremental: G91 on a mill, U/V/W on a lathe) per axis.
    let incremental = step.st.modes.incremental;
    let values = written_axes(step, words)?.map(|v| v.map(|(v, by_address)| (v, by_address || incremental)));
    // Work system `i` with the values written merged into it.
    let work = |i: usize| {
        let old = step.tables.work_mm[i];
        Some(TableWrite::Work(i, Vec3::new(merge(old.x, values[0]), merge(old.y, values[1]), merge(old.z, values[2]))))
    };
    // G10 L20 P1-P48: the additional work systems, where the profile has G54.1 (FANUC 0i-MF).
    if l == Some(20) && step.profile.has(crate::profile::GFn::AdditionalWorkOffset) {
        let max = crate::setup::ADDITIONAL_WORK_SYSTEMS as u32;
        if !(1..=max).contains(&n) {
            return Err(p_out_of_range(step, pw, "G10 L20 sets additional work system P1 to P48 (G54.1)"));
        }
        return Ok(work(6 + n as usize));
    }
    if l == Some(2) {
        if n > 6 {
            return Err(p_out_of_range(step, pw, "G10 L2 sets work offset P0 (external) to P6 (G59)"));
        }
        return Ok(work(n as usize));
    }
    match (forms, l) {
        (G10Forms::LatheOffsets, None) => lathe_offset_setting(step, words, n, pw, values),
        (G10Forms::MillOffsets, None | Some(1) | Some(10..=13)) => mill_offset_setting(step, words, n, pw, l, span),
        (_, Some(l)) => {
            Err(step.alarm(Rule::ValueOutOfRange, span, format!("G10 L{l}: {} sets L2 (work offsets) and the tool offsets only here", step.profile.name)))
        }
        (_, None) => Err(step.alarm(Rule::NotSupported, span, "G10: not simulated by ncsight on this profile yet")),
    }
}

/// A G10 value on an old one: added (incremental), set (absolute), or the old one kept.
#[inline]
fn merge(old: f64, v: Option<(f64, bool)>) -> f64 {
    match v {
        Some((v, true)) => old + v,
        Some((v, false)) => v,
        None => old,
    }
}

/// The alarm for G10's P word `pw` out of the form's range.
fn p_out_of_range(step: &Step, pw: &crate::read::Word, what: &str) -> Diagnostic {
    step.alarm(Rule::ValueOutOfRange, pw.span, format!("{}: {what}", pw.text()))
}

/// Whether G10 `L` starts the lines of data up to G11 (parameters; tool life on the GSK),
/// which set the data input mode; a GSK G10 of another form is an alarm.
fn starts_data_lines(step: &mut Step, l: Option<u32>, span: Span) -> Result<bool, Diagnostic> {
    use crate::profile::G10Forms;
    // The parameter lines follow, up to G11 (FANUC 0i manual, G10 L50; GSK980TDi help text,
    // parameter reading and writing, G10 L52).
    if let Some(entry) = step.profile.frame.parameter_entry.filter(|e| l == Some(e.l)) {
        step.st.modes.data_input = Some(DataInput::Parameters(entry));
        return Ok(true);
    }
    if step.profile.frame.g10 == G10Forms::ToolLifeAndParameters {
        // GSK980TDi help text, G10 L3: the tool life data up to G11; every other word there is
        // ignored (note 1). ncsight does not count tool life: the lines are read and dropped.
        if l == Some(3) {
            step.warn(Rule::NotSimulated, span, "G10 L3: the tool life management data up to G11 are read and not kept (ncsight does not count tool life)");
            step.st.modes.data_input = Some(DataInput::ToolLife);
            return Ok(true);
        }
        return Err(step.alarm(
            Rule::ImproperGCode,
            span,
            format!("G10 on {}: its help text has G10 L3 (tool life) and G10 L52 (parameters) only, no work or tool offset setting", step.profile.name),
        ));
    }
    Ok(false)
}

/// G10 P_ on a lathe (`n` the value of P, the word `pw`): the wear (P1-64) or geometry
/// (P10001-10064) offset with the axis `values`, the nose radius R (C adds) and the imaginary
/// tip Q.
fn lathe_offset_setting(
    step: &mut Step,
    words: &mut Words,
    n: u32,
    pw: &crate::read::Word,
    values: [Option<(f64, bool)>; 3],
) -> Result<Option<TableWrite>, Diagnostic> {
    // P1-64 wear, P10001-10064 geometry (docs/reference/macro.md 10.2, inferred); R (C adds) the nose
    // radius, Q the imaginary tip.
    let (number, geometry) = match n {
        1..=64 => (n, false),
        10_001..=10_064 => (n - 10_000, true),
        _ => return Err(p_out_of_range(step, pw, "G10 P sets wear offsets P1-P64 or geometry offsets P10001-P10064")),
    };
    let mut e = step.tables.offset(number).copied().unwrap_or(Offset { number, ..Offset::default() });
    if geometry {
        (e.x_mm, e.y_mm, e.z_mm) = (merge(e.x_mm, values[0]), merge(e.y_mm, values[1]), merge(e.z_mm, values[2]));
    } else {
        (e.wear_x_mm, e.wear_y_mm, e.wear_z_mm) = (merge(e.wear_x_mm, values[0]), merge(e.wear_y_mm, values[1]), merge(e.wear_z_mm, values[2]));
    }
    let r = match (words.take(b'R'), words.take(b'C')) {
        (Some(a), Some(i)) => return Err(step.alarm(Rule::DuplicateWord, i.span, format!("{} and {} both give the nose radius", a.text(), i.text()))),
        (Some(w), None) => Some((step.length(w)?, false)),
        (None, Some(w)) => Some((step.length(w)?, true)),
        (None, None) => None,
    };
    if geometry {
        e.radius_mm = merge(e.radius_mm, r)
    } else {
        e.wear_radius_mm = merge(e.wear_radius_mm, r)
    }
    if let Some(w) = words.take(b'Q') {
        if w.decimal || !(0.0..=9.0).contains(&w.value) {
            return Err(step.alarm(Rule::ValueOutOfRange, w.span, format!("{}: the imaginary tool nose is Q0 to Q9", w.text())));
        }
        e.tip = w.value as u8;
    }
    Ok(Some(TableWrite::Offset(e)))
}

/// G10 P_ R_ on a mill (`n` the value of P, the word `pw`): offset n's value R, in tool offset
/// memory A (no L, L1) or C (L10-L13).
fn mill_offset_setting(
    step: &mut Step,
    words: &mut Words,
    n: u32,
    pw: &crate::read::Word,
    l: Option<u32>,
    span: Span,
) -> Result<Option<TableWrite>, Diagnostic> {
    if !(1..=crate::setup::MAX_OFFSET_NUMBER).contains(&n) {
        return Err(p_out_of_range(step, pw, "G10 P is an offset number, 1 or more"));
    }
    let Some(rw) = words.take(b'R') else {
        return Err(step.alarm(Rule::MissingWord, span, "G10 P_ R_: R gives the offset value"));
    };
    let r = Some((step.length(rw)?, step.st.modes.incremental));
    let mut e = step.tables.offset(n).copied().unwrap_or(Offset { number: n, ..Offset::default() });
    match l {
        // Memory A: one value per number, read by H and by D (inferred).
        None | Some(1) => {
            e.length_mm = merge(e.length_mm + e.wear_length_mm, r);
            e.radius_mm = merge(e.radius_mm + e.wear_radius_mm, r);
            e.wear_length_mm = 0.0;
            e.wear_radius_mm = 0.0;
        }
        // Memory C: L10 H geometry, L11 H wear, L12 D geometry, L13 D wear.
        Some(10) => e.length_mm = merge(e.length_mm, r),
        Some(11) => e.wear_length_mm = merge(e.wear_length_mm, r),
        Some(12) => e.radius_mm = merge(e.radius_mm, r),
        _ => e.wear_radius_mm = merge(e.wear_radius_mm, r),
    }
    Ok(Some(TableWrite::Offset(e)))
}

/// G45 (+1) / G46 (-1) / G47 (+2) / G48 (-2) with D: each axis's move of the block is made
/// longer (shorter) by the offset's value once (twice), in the move's direction (a negative
/// value the other way; a move shortened past zero reverses). An incremental zero moves by the
/// value, signed by the zero's sign (`G45 X0` +, `G45 X-0` -); an absolute zero move does not
/// move (FANUC 0-M tool position offset; the details from the FANUC-compatible Mitsubishi
/// M700V manual, 12.6 [secondary]). In G00 or G01 only: with an arc it is not simulated.
pub(super) fn offset_move(step: &mut Step, words: &mut Words, factor: i8, span: Span) -> Result<(), Diagnostic> {
    use crate::modal::Motion;
    let d = match words.take(b'D') {
        Some(w) => super::offset_number(step, w)?,
        None => step.st.comp.d,
    };
    if matches!(step.st.modes.motion, Motion::ArcCw | Motion::ArcCcw) {
        return Err(step.alarm(Rule::NotSupported, span, "G45-G48 with a circular move: not simulated by ncsight yet (G00 or G01)"));
    }
    let e = entry(step, d, span);
    let value = factor as f64 * (e.radius_mm + e.wear_radius_mm);
    // The sign of an incremental zero (X0 or X-0 under G91, U0 or U-0), per axis.
    let mut zero_sign = [None::<f64>; 3];
    for (abs_l, inc_l, axis) in [(b'X', b'U', 0), (b'Y', b'V', 1), (b'Z', b'W', 2)] {
        let w = match (words.peek(abs_l), words.peek(inc_l).filter(|_| step.profile.incremental_addresses)) {
            (Some(w), _) if step.st.modes.incremental => Some(w),
            (None, Some(w)) => Some(w),
            _ => None,
        };
        if let Some(w) = w.filter(|w| w.value == 0.0) {
            zero_sign[axis] = Some(if w.value.is_sign_negative() { -1.0 } else { 1.0 });
        }
    }
    let (target, given) = axis_target(step, words)?;
    let shown = step.st.place.pos + step.st.frame.unmoved;
    let mut to = target;
    for (a, _) in given.iter().enumerate().filter(|(_, g)| g.is_some()) {
        let delta = target.axis(a) - shown.axis(a);
        let scale = if a == 0 && step.profile.diameter_x { 0.5 } else { 1.0 };
        if delta != 0.0 {
            to.set_axis(a, target.axis(a) + delta.signum() * value * scale);
        } else if let Some(sign) = zero_sign[a] {
            to.set_axis(a, target.axis(a) + sign * value * scale);
        }
    }
    let from = step.st.place.pos;
    if to == from {
        return Ok(());
    }
    match step.st.modes.motion {
        Motion::Linear => {
            let feed = step.cutting_feed(super::What::Code(crate::profile::GFn::Linear), &|u| super::lerp(&from, &to, u))?;
            step.emit(Op::Feed { from, to, feed_mm_min: feed });
        }
        _ => step.emit(Op::Rapid { from, to }),
    }
    Ok(())
}

/// G27: rapid to the point given (absolute or incremental) on the axes given, then the check
/// that it is the reference point in machine coordinates (within 0.001 mm, inferred): FANUC
/// alarm 092 when it is not (the setup's reference point, else the profile's assumed one).
pub(super) fn reference_check(step: &mut Step, words: &mut Words, span: Span) -> Result<(), Diagnostic> {
    let (target, given) = axis_target(step, words)?;
    let from = step.st.place.pos;
    if target != from {
        step.emit(Op::Rapid { from, to: target });
    }
    let reference = step.tables.reference_mm[0].unwrap_or_default();
    let machine = target + step.tables.to_machine(&step.st.frame);
    let x_scale = if step.profile.diameter_x { 2.0 } else { 1.0 };
    for (a, _) in given.iter().enumerate().filter(|(_, g)| g.is_some()) {
        if (machine.axis(a) - reference.axis(a)).abs() > 0.001 {
            let scale = if a == 0 { x_scale } else { 1.0 };
            let name = ["X", "Y", "Z"][a];
            return Err(step.alarm(
                Rule::ReferenceCheck,
                span,
                format!(
                    "G27: {name} ends at {:.3} in machine coordinates, not at the reference point {name}{:.3}",
                    machine.axis(a) * scale,
                    reference.axis(a) * scale
                ),
            ));
        }
    }
    Ok(())
}
