//! Where the tool is on the machine (MACRO.md section 10.2; docs/setup.md): the machine's
//! tables from the setup, and the codes that move programme coordinates against machine
//! coordinates: G54-G59, G50/G92, G52, G53, and the reference returns G28/G30.
//!
//! machine = programme + external offset + work offset (G54-G59) + G50/G92 shift + G52 local
//! origin + tool offset. Positions stay in programme coordinates, as the controller's absolute
//! display shows them; every record carries the sum to add for machine coordinates.

use super::{axis_target, Step, Words};
use crate::alarm::{Diagnostic, Rule};
use crate::modal::Frame;
use crate::motion::{Op, Vec3};
use crate::profile::Profile;
use crate::setup::{Point, Setup};
use crate::source::Span;

/// The machine's tables for one run, in the interpreter's units (X as a radius on a lathe).
#[derive(Debug, Clone, PartialEq)]
pub struct Tables {
    /// A setup gave them: records carry machine positions.
    pub given: bool,
    /// The external offset (0), then G54-G59 (1-6): machine coordinates of each zero.
    pub work_mm: [Vec3; 7],
    /// Reference points 1-4 in machine coordinates (`None`: not in the setup).
    pub reference_mm: [Option<Vec3>; 4],
    /// Soft travel limits per axis, machine coordinates.
    pub limits_mm: [Option<[f64; 2]>; 3],
    /// Where the tool is at power on (machine coordinates), when the setup says.
    pub power_on_mm: Option<Vec3>,
}

impl Tables {
    /// Without a setup: every offset 0, machine coordinates the programme's, the reference
    /// point the profile's assumption, the tool at programme zero at power on (docs/setup.md).
    pub fn none(profile: &Profile) -> Tables {
        Tables {
            given: false,
            work_mm: [Vec3::default(); 7],
            reference_mm: [Some(profile.reference_point_mm), None, None, None],
            limits_mm: [None; 3],
            power_on_mm: None,
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
        if let Some(w) = &setup.work {
            for (slot, p) in t.work_mm.iter_mut().zip(w.all()) {
                if let Some(p) = p {
                    *slot = point(&p);
                }
            }
        }
        if let Some(m) = &setup.machine {
            for (slot, p) in t.reference_mm.iter_mut().zip([m.reference, m.reference_2, m.reference_3, m.reference_4]) {
                if let Some(p) = p {
                    *slot = Some(point(&p));
                }
            }
            if let Some(l) = m.limits {
                t.limits_mm = l.by_axis();
                if let Some([lo, hi]) = t.limits_mm[0] {
                    t.limits_mm[0] = Some([lo * x_scale, hi * x_scale]);
                }
            }
        }
        t.power_on_mm = t.reference_mm[0];
        t
    }

    /// What to add to programme coordinates for machine coordinates in `frame`.
    pub fn to_machine(&self, frame: &Frame) -> Vec3 {
        self.work_mm[0] + self.work_mm[frame.work.clamp(1, 6) as usize] + frame.shift + frame.local + frame.tool
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

/// Change the frame and keep the tool where it is on the machine: its programme coordinates
/// move by what the frame moved.
pub(super) fn reframe(step: &mut Step, change: impl FnOnce(&mut Frame)) {
    let before = step.tables.to_machine(&step.st.frame);
    change(&mut step.st.frame);
    let after = step.tables.to_machine(&step.st.frame);
    step.st.pos = step.st.pos + before - after;
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
    for (a, _) in given.iter().enumerate().filter(|(_, g)| **g) {
        {
            let shift = st.frame.shift.axis(a) + st.frame.local.axis(a) + st.pos.axis(a) - target.axis(a);
            st.frame.shift.set_axis(a, shift);
            st.frame.local.set_axis(a, 0.0);
        }
    }
    st.pos = target;
    Ok(())
}

/// The axis words of a block as written, mm (X as a radius), whether absolute or incremental
/// addresses: G52 and G53 read them so (GSK980TDi help text, G52: X and U have the same effect).
fn written_axes(step: &mut Step, words: &mut Words) -> Result<([Option<f64>; 3], bool), Diagnostic> {
    let mut values = [None; 3];
    let mut incremental_address = false;
    for (abs_l, inc_l, axis) in [(b'X', b'U', 0), (b'Y', b'V', 1), (b'Z', b'W', 2)] {
        let abs_w = words.take(abs_l);
        let inc_w = if step.profile.incremental_addresses { words.take(inc_l) } else { None };
        if let (Some(a), Some(i)) = (abs_w, inc_w) {
            return Err(step.alarm(Rule::DuplicateWord, i.span, format!("{} and {} both give the {} axis", a.text(), i.text(), abs_l as char)));
        }
        incremental_address |= inc_w.is_some();
        if let Some(w) = abs_w.or(inc_w) {
            let scale = if axis == 0 && step.profile.diameter_x { 0.5 } else { 1.0 };
            values[axis] = Some(step.length(w)? * scale);
        }
    }
    Ok((values, incremental_address))
}

/// G52: the local system's origin at the point given, in the work system (absolute whatever
/// the address or G90/G91: GSK980TDi help text, G52; FANUC inferred alike). `G52 X0 Z0` cancels.
pub(super) fn local(step: &mut Step, words: &mut Words) -> Result<(), Diagnostic> {
    let (values, _) = written_axes(step, words)?;
    reframe(step, |f| {
        for (a, v) in values.iter().enumerate() {
            if let Some(v) = v {
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
    let incremental = step.st.incremental || {
        let letters: &[u8] = if step.profile.incremental_addresses { b"UVW" } else { b"" };
        letters.iter().any(|l| words.has(*l))
    };
    if incremental {
        let msg = "G53 with an incremental command is ignored (FANUC: machine coordinates are absolute only); the block moves as without it";
        step.warn(Rule::MachineIncremental, span, msg);
        return Ok(false);
    }
    let (values, _) = written_axes(step, words)?;
    let origin = step.tables.to_machine(&step.st.frame);
    let from = step.st.pos;
    let mut to = from;
    for (a, v) in values.iter().enumerate() {
        if let Some(v) = v {
            to.set_axis(a, v - origin.axis(a));
        }
    }
    if to != from {
        step.emit(Op::Rapid { from, to });
    }
    Ok(true)
}

/// G28 (`n` = 1) and G30 (`n` = 2-4): rapid to the intermediate point given (absolute or
/// incremental), then to reference point `n` on the axes given. GSK: the tool offset is
/// cancelled (help text G28 note 2, G30 note 3).
pub(super) fn reference_return(step: &mut Step, words: &mut Words, n: usize, span: Span) -> Result<(), Diagnostic> {
    let (mid, given) = axis_target(step, words)?;
    if !given.iter().any(|g| *g) {
        return Ok(());
    }
    let reference = match step.tables.reference_mm[n - 1] {
        Some(r) => r,
        None => {
            let msg = format!("reference point {n} is not in the setup ([machine.reference_{n}]): taken as machine zero");
            step.warn(Rule::ReferenceAssumed, span, msg);
            Vec3::default()
        }
    };
    if mid != step.st.pos {
        step.emit(Op::Rapid { from: step.st.pos, to: mid });
    }
    if step.profile.frame.reference_cancels_tool_offset {
        reframe(step, |f| f.tool = Vec3::default());
    }
    let origin = step.tables.to_machine(&step.st.frame);
    let mut home = step.st.pos;
    for (a, _) in given.iter().enumerate().filter(|(_, g)| **g) {
        {
            home.set_axis(a, reference.axis(a) - origin.axis(a));
        }
    }
    if home != step.st.pos {
        step.emit(Op::Rapid { from: step.st.pos, to: home });
    }
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
