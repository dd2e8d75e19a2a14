//! Drilling canned cycles G73, G74, G76, G81-G89 (seed 003, FANUC 0-M), written once in
//! plane-local coordinates: `a` and `b` are the plane's first and second axes (where the hole
//! is), `h` the drilling axis normal to the plane (Z in G17, Y in G18, X in G19). The tool drills
//! from the R level toward the bottom.
//!
//! Each hole: positioning in the plane at the current level, rapid to the R level, the cycle's
//! own motion, and the return to the initial level (G98) or the R level (G99).
//!
//! The GSK980TDi lathe cycles G83 (end face, along Z) and G87 (side, along X) are the same family
//! in the same local terms: `h` is their drilling axis, the R level is the start point, and R is
//! the retract after each peck (help text G83/87).

pub use crate::codes::DrillKind;

/// A point in plane-local coordinates: (a, b, h).
pub type Local = [f64; 3];

/// One hole, resolved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hole {
    pub kind: DrillKind,
    /// Where the tool stands before the hole.
    pub from: Local,
    /// The hole's position in the plane.
    pub at: [f64; 2],
    /// Initial level, R level and bottom along the drilling axis.
    pub initial: f64,
    pub r: f64,
    pub bottom: f64,
    /// G98: return to the initial level; G99: to the R level. G87 always returns to the initial
    /// level.
    pub return_initial: bool,
    /// Peck depth (G73/G83) or shift (G76/G87), positive.
    pub q: f64,
    /// Dwell at the bottom, seconds (P).
    pub dwell_s: f64,
    /// G73 retract / G83 clearance d (parameters 531/532), mm; the R word of the GSK lathe
    /// cycles.
    pub d: f64,
    /// GSK lathe cycles: J1, the deep-hole cycle (back to the start after each peck); J0 the
    /// high-speed one (back by d).
    pub deep: bool,
    /// Unit direction of the G76/G87 shift in the plane (parameter 2 bits 4 and 5).
    pub shift_dir: [f64; 2],
    /// Cutting feed, mm/min.
    pub feed: f64,
    /// Spindle speed in force, signed (positive: M03).
    pub rpm: f64,
}

/// One step of a hole, in plane-local coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step {
    Rapid(Local),
    Feed(Local, f64),
    Dwell(f64),
    /// The spindle turns at this signed speed (0: stopped).
    Spindle(f64),
    /// Oriented spindle stop (G76, G87).
    Orient,
    /// G88: the machine stops for the operator to retract by hand; cycle start goes on.
    ManualRetract,
}

/// The steps of one hole.
pub fn expand(h: &Hole) -> Vec<Step> {
    let mut s = Vec::with_capacity(12);
    expand_each(h, &mut |step| s.push(step));
    s
}

/// The steps of one hole, each passed to `s` as it is made (no allocation).
pub fn expand_each(h: &Hole, s: &mut dyn FnMut(Step)) {
    let [a, b] = h.at;
    let p = |lvl: f64| [a, b, lvl];
    // Positioning in the plane at the current level.
    if h.from[0] != a || h.from[1] != b {
        s(Step::Rapid([a, b, h.from[2]]));
    }
    let level = h.from[2];
    if h.kind == DrillKind::G87 {
        back_boring(h, &p, s);
        return;
    }
    if h.kind.from_start() {
        from_start(h, &p, s);
        return;
    }
    if level != h.r {
        s(Step::Rapid(p(h.r)));
    }
    let down = if h.bottom < h.r { -1.0 } else { 1.0 };
    // Pecking: G73 backs off d after each peck; G83 (and the FANUC 0-T lathe G83/G87 with Q
    // under the standard cycle) goes back to R and down again to d short of the last depth.
    let peck = match h.kind {
        DrillKind::G73 => Some(false),
        DrillKind::G83 => Some(true),
        DrillKind::FaceFromR | DrillKind::SideFromR if h.q > 0.0 => Some(h.deep),
        _ => None,
    };
    match peck {
        Some(full_return) => pecks_from_r(h, down, full_return, &p, s),
        None => s(Step::Feed(p(h.bottom), h.feed)),
    }
    out_of_hole(h, &p, s);
}

/// Where the hole's last move ends, if it moves: the last of `expand_each`'s moves, found
/// without making the ones before where the way out of the hole moves (every cycle from R but
/// G87), so that a check that keeps no record does not lay each hole out whole.
pub fn end_of(h: &Hole) -> Option<Local> {
    if h.kind != DrillKind::G87 && !h.kind.from_start() {
        let [a, b] = h.at;
        if let Some(l) = last_move(|s| out_of_hole(h, &|lvl| [a, b, lvl], s)) {
            return Some(l);
        }
    }
    last_move(|s| expand_each(h, s))
}

/// The end of the last move among the steps `expand` makes.
fn last_move(expand: impl FnOnce(&mut dyn FnMut(Step))) -> Option<Local> {
    let mut last = None;
    expand(&mut |s| {
        if let Step::Rapid(l) | Step::Feed(l, _) = s {
            last = Some(l);
        }
    });
    last
}

/// The point of the hole shifted by Q along the shift direction (G76, G87), at level `lvl`.
#[inline(always)]
fn shifted(h: &Hole, lvl: f64) -> Local {
    let [a, b] = h.at;
    [a + h.q * h.shift_dir[0], b + h.q * h.shift_dir[1], lvl]
}

/// G87 from the level the tool stands on, positioned over the hole.
#[inline(always)]
fn back_boring(h: &Hole, p: &impl Fn(f64) -> Local, s: &mut dyn FnMut(Step)) {
    let level = h.from[2];
    // Back boring: orient and shift, rapid down to R (below the hole), shift back, start the
    // spindle, feed up to Z, orient, shift, rapid up to the initial level, shift back, start.
    s(Step::Orient);
    s(Step::Rapid(shifted(h, level)));
    s(Step::Rapid(shifted(h, h.r)));
    s(Step::Rapid(p(h.r)));
    s(Step::Spindle(h.rpm));
    s(Step::Feed(p(h.bottom), h.feed));
    if h.dwell_s > 0.0 {
        s(Step::Dwell(h.dwell_s));
    }
    s(Step::Orient);
    s(Step::Rapid(shifted(h, h.bottom)));
    s(Step::Rapid(shifted(h, h.initial)));
    s(Step::Rapid(p(h.initial)));
    s(Step::Spindle(h.rpm));
}

/// The pecks from the R level to the bottom (`down`: the sign of the drilling direction), each
/// followed by a rapid back d (`full_return` false) or to R and down again to d short of the
/// depth reached (true).
#[inline(always)]
fn pecks_from_r(h: &Hole, down: f64, full_return: bool, p: &impl Fn(f64) -> Local, s: &mut dyn FnMut(Step)) {
    // Peck k ends at R + k Q, computed afresh, and within a nanometre of the bottom is the
    // bottom: the control counts in whole increments, so rounding leaves no sliver of a
    // last peck (LinuxCNC's rs274, adding Q again and again, sometimes makes one).
    let mut k = 0.0;
    loop {
        k += 1.0;
        let depth = h.r + down * h.q * k;
        let next = if (h.bottom - depth) * down <= 1e-6 { h.bottom } else { depth };
        s(Step::Feed(p(next), h.feed));
        if next == h.bottom {
            break;
        }
        if !full_return {
            s(Step::Rapid(p(next - down * h.d)));
        } else {
            s(Step::Rapid(p(h.r)));
            s(Step::Rapid(p(next - down * h.d)));
        }
    }
}

/// The cycle's motion at the bottom of the hole and out of it, back to the initial level (G98)
/// or the R level (G99).
#[inline(always)]
fn out_of_hole(h: &Hole, p: &impl Fn(f64) -> Local, s: &mut dyn FnMut(Step)) {
    let ret = if h.return_initial || h.kind == DrillKind::G87 { h.initial } else { h.r };
    let dwell = |s: &mut dyn FnMut(Step)| {
        if h.dwell_s > 0.0 {
            s(Step::Dwell(h.dwell_s));
        }
    };
    match h.kind {
        DrillKind::G73 | DrillKind::G81 | DrillKind::G83 => s(Step::Rapid(p(ret))),
        DrillKind::G82 | DrillKind::FaceFromR | DrillKind::SideFromR => {
            dwell(s);
            s(Step::Rapid(p(ret)));
        }
        DrillKind::G85 | DrillKind::G89 | DrillKind::FaceBoreR | DrillKind::SideBoreR => {
            if h.kind != DrillKind::G85 {
                dwell(s);
            }
            s(Step::Feed(p(h.r), h.feed));
            if ret != h.r {
                s(Step::Rapid(p(ret)));
            }
        }
        DrillKind::G74 | DrillKind::G84 | DrillKind::FaceTapR | DrillKind::SideTapR => {
            // Tapping: reverse at the bottom, feed out to R, turn forward again.
            dwell(s);
            s(Step::Spindle(-h.rpm));
            s(Step::Feed(p(h.r), h.feed));
            s(Step::Spindle(h.rpm));
            if ret != h.r {
                s(Step::Rapid(p(ret)));
            }
        }
        DrillKind::G86 => {
            s(Step::Spindle(0.0));
            s(Step::Rapid(p(ret)));
            s(Step::Spindle(h.rpm));
        }
        DrillKind::G76 => {
            dwell(s);
            s(Step::Orient);
            s(Step::Rapid(shifted(h, h.bottom)));
            s(Step::Rapid(shifted(h, ret)));
            s(Step::Rapid(p(ret)));
            s(Step::Spindle(h.rpm));
        }
        DrillKind::G88 => {
            dwell(s);
            s(Step::Spindle(0.0));
            s(Step::ManualRetract);
            s(Step::Rapid(p(ret)));
            s(Step::Spindle(h.rpm));
        }
        DrillKind::G87 | DrillKind::FaceG83 | DrillKind::SideG87 | DrillKind::FaceBoreStart | DrillKind::SideBoreStart => unreachable!("handled above"),
        DrillKind::TapFace | DrillKind::TapSide => unreachable!("rigid tapping is laid out by the interpreter"),
    }
}

/// GSK980TDi G83/G87 from the start level `h.r` (help text G83/87, steps 2-6 of both cycles):
/// J0 feeds Q, rapids back d but never past the start, and feeds Q plus what it went back; J1
/// feeds Q, rapids to the start, rapids to d short of the depth reached and feeds Q + d. Q 0
/// (note 5), or d 0 under J0 (note 6), drills in one feed. Dwell P at the bottom, rapid back to
/// the start.
fn from_start(h: &Hole, p: &impl Fn(f64) -> Local, s: &mut dyn FnMut(Step)) {
    let start = h.r;
    if h.kind.bores_from_start() {
        // G85/G89 (inferred): feed to the bottom, dwell, feed back to the start.
        s(Step::Feed(p(h.bottom), h.feed));
        if h.dwell_s > 0.0 {
            s(Step::Dwell(h.dwell_s));
        }
        s(Step::Feed(p(h.initial), h.feed));
        return;
    }
    let down = if h.bottom < start { -1.0 } else { 1.0 };
    // d short of `depth`, clamped at the start (J0 step 3).
    let back = |depth: f64| {
        let t = depth - down * h.d;
        if (t - start) * down < 0.0 {
            start
        } else {
            t
        }
    };
    if h.q <= 0.0 || (!h.deep && h.d <= 0.0) {
        s(Step::Feed(p(h.bottom), h.feed));
    } else {
        // Peck k ends at start + k Q, computed afresh (no drift from adding Q again and again,
        // which would leave a sliver of a last peck); within a nanometre of the bottom is the
        // bottom, as the control's whole increments make it.
        let mut k = 0.0;
        loop {
            k += 1.0;
            let depth = start + down * h.q * k;
            let next = if (h.bottom - depth) * down <= 1e-6 { h.bottom } else { depth };
            s(Step::Feed(p(next), h.feed));
            if next == h.bottom {
                break;
            }
            if h.deep {
                s(Step::Rapid(p(start)));
                let t = back(next);
                if t != start {
                    s(Step::Rapid(p(t)));
                }
            } else {
                s(Step::Rapid(p(back(next))));
            }
        }
    }
    if h.dwell_s > 0.0 {
        s(Step::Dwell(h.dwell_s));
    }
    s(Step::Rapid(p(h.initial)));
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hole(kind: DrillKind) -> Hole {
        Hole {
            kind,
            from: [0.0, 0.0, 10.0],
            at: [1.0, 1.0],
            initial: 10.0,
            r: 2.0,
            bottom: -3.0,
            return_initial: true,
            q: 1.0,
            dwell_s: 0.5,
            d: 0.254,
            deep: false,
            shift_dir: [1.0, 0.0],
            feed: 100.0,
            rpm: 1000.0,
        }
    }

    fn levels(s: &[Step]) -> Vec<f64> {
        s.iter()
            .filter_map(|x| match x {
                Step::Rapid(p) | Step::Feed(p, _) => Some((p[2] * 1000.0).round() / 1000.0),
                _ => None,
            })
            .collect()
    }

    /// `end_of` finds the last move `expand_each` makes, for every kind, G98 and G99, with and
    /// without a dwell, from above R and from R itself, over the hole or beside it.
    #[test]
    fn the_end_of_a_hole_is_where_its_last_move_ends() {
        // Rigid tapping (TapFace, TapSide) is laid out by the interpreter, never here.
        for &kind in DrillKind::ALL.iter().filter(|k| !k.rigid_tap()) {
            for (return_initial, dwell_s, from) in [(true, 0.5, [0.0, 0.0, 10.0]), (false, 0.0, [1.0, 1.0, 2.0]), (false, 0.5, [0.0, 0.0, 10.0])] {
                let h = Hole { return_initial, dwell_s, from, ..hole(kind) };
                let last = expand(&h).into_iter().rev().find_map(|s| match s {
                    Step::Rapid(l) | Step::Feed(l, _) => Some(l),
                    _ => None,
                });
                assert_eq!(end_of(&h), last, "{kind:?} G9{} dwell {dwell_s} from {from:?}", if return_initial { 8 } else { 9 });
            }
        }
    }

    #[test]
    fn g73_pecks_back_by_d() {
        // Same steps as LinuxCNC's rs274 prints for G73 with Q1 from R2 to Z-3.
        let s = expand(&hole(DrillKind::G73));
        assert_eq!(levels(&s), vec![10.0, 2.0, 1.0, 1.254, 0.0, 0.254, -1.0, -0.746, -2.0, -1.746, -3.0, 10.0]);
    }

    #[test]
    fn g83_returns_to_r_after_each_peck() {
        let s = expand(&hole(DrillKind::G83));
        assert_eq!(levels(&s), vec![10.0, 2.0, 1.0, 2.0, 1.254, 0.0, 2.0, 0.254, -1.0, 2.0, -0.746, -2.0, 2.0, -1.746, -3.0, 10.0]);
    }

    #[test]
    fn g99_returns_to_r_and_g87_to_the_initial_level() {
        let mut h = hole(DrillKind::G81);
        h.return_initial = false;
        assert_eq!(levels(&expand(&h)).last(), Some(&2.0));
        let mut h = hole(DrillKind::G87);
        h.return_initial = false;
        h.r = -3.0;
        h.bottom = 2.0;
        let s = expand(&h);
        assert_eq!(levels(&s).last(), Some(&10.0));
        assert_eq!(s.iter().filter(|x| matches!(x, Step::Orient)).count(), 2);
    }

    #[test]
    fn tapping_reverses_at_the_bottom() {
        let s = expand(&hole(DrillKind::G84));
        let spindle: Vec<f64> = s.iter().filter_map(|x| if let Step::Spindle(r) = x { Some(*r) } else { None }).collect();
        assert_eq!(spindle, vec![-1000.0, 1000.0]);
        let s = expand(&hole(DrillKind::G74));
        assert!(s.iter().any(|x| matches!(x, Step::Feed(p, _) if p[2] == 2.0)));
    }

    /// GSK G83 from Z2 to Z-3, Q1: J0 backs off R 0.3 (clamped at the start), J1 goes back to
    /// the start and down to 0.3 short of the depth; dwell, then back to the start.
    #[test]
    fn lathe_pecks_from_the_start() {
        let mut h = hole(DrillKind::FaceG83);
        h.from = [1.0, 0.0, 2.0];
        h.at = [1.0, 0.0];
        h.initial = 2.0;
        h.r = 2.0;
        h.d = 0.3;
        let s = expand(&h);
        assert_eq!(levels(&s), vec![1.0, 1.3, 0.0, 0.3, -1.0, -0.7, -2.0, -1.7, -3.0, 2.0]);
        assert!(matches!(s[s.len() - 2], Step::Dwell(_)));
        h.deep = true;
        assert_eq!(levels(&expand(&h)), vec![1.0, 2.0, 1.3, 0.0, 2.0, 0.3, -1.0, 2.0, -0.7, -2.0, 2.0, -1.7, -3.0, 2.0]);
        // A retract longer than the depth reached stops at the start (J0 step 3).
        h.deep = false;
        h.d = 1.5;
        assert_eq!(levels(&expand(&h))[..2], [1.0, 2.0]);
        // Q 0, or R 0 under J0: one feed to the bottom (notes 5 and 6).
        h.d = 0.0;
        assert_eq!(levels(&expand(&h)), vec![-3.0, 2.0]);
        h.deep = true;
        h.q = 0.0;
        assert_eq!(levels(&expand(&h)), vec![-3.0, 2.0]);
    }

    #[test]
    fn g76_shifts_away_from_the_wall() {
        let s = expand(&hole(DrillKind::G76));
        assert!(s.contains(&Step::Rapid([2.0, 1.0, -3.0])));
        assert!(s.contains(&Step::Rapid([2.0, 1.0, 10.0])));
        assert!(s.contains(&Step::Rapid([1.0, 1.0, 10.0])));
    }
}
