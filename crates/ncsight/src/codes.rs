//! The commands the profiles name and the cycles expand, as enums that know no controller:
//! the bottom of the flow (profile, interp and cycles all use them; they use nothing).

/// The enum of the hole cycles and the list of all its kinds, from one list of variants.
macro_rules! drill_kinds {
    ($($(#[$doc:meta])* $kind:ident,)*) => {
        /// The cycle of a hole.
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub enum DrillKind {
            $($(#[$doc])* $kind,)*
        }

        impl DrillKind {
            /// Every kind, in the enum's order (for tests that go through them all).
            pub const ALL: &'static [DrillKind] = &[$(DrillKind::$kind,)*];
        }
    };
}

drill_kinds! {
    /// High-speed peck: feed Q, back d (parameter 531), again (seed 003 8.1.1).
    G73,
    /// Left-hand tapping: the spindle reverses at the bottom (8.1.2).
    G74,
    /// Fine boring: oriented stop and shift Q at the bottom, rapid out (8.1.3).
    G76,
    /// Drilling (8.1.5).
    G81,
    /// Drilling with a dwell at the bottom (8.1.6).
    G82,
    /// Peck drilling: back to R after each peck, down again to d above the last depth (8.1.7).
    G83,
    /// Right-hand tapping (8.1.8).
    G84,
    /// Boring, feed out to R (8.1.9).
    G85,
    /// Boring, spindle stop at the bottom, rapid out.
    G86,
    /// Back boring: from the R level below the hole up to Z.
    G87,
    /// Boring, dwell, spindle stop, manual retract.
    G88,
    /// Boring with a dwell, feed out to R.
    G89,
    /// GSK980TDi lathe G83: peck drilling along Z from the start point (help text G83/87).
    FaceG83,
    /// GSK980TDi lathe G87: peck drilling along X from the start point (help text G83/87).
    SideG87,
    /// FANUC 0-T lathe G83: drilling along Z from the R level (pecking with Q), dwell, rapid out
    /// to the initial level (docs/commands/g83_g87_lathe.md).
    FaceFromR,
    /// FANUC 0-T lathe G87: the same along X.
    SideFromR,
    /// FANUC 0-T lathe G84: tapping along Z from the R level, the spindle reversed at the
    /// bottom (docs/commands/g83_g87_lathe.md, inferred from the FANUC 0i-T family).
    FaceTapR,
    /// FANUC 0-T lathe G88: the same along X.
    SideTapR,
    /// FANUC 0-T lathe G85: boring along Z from the R level, feed out to R.
    FaceBoreR,
    /// FANUC 0-T lathe G89: the same along X.
    SideBoreR,
    /// GSK980TDi G85: boring along Z from the start point: feed in, dwell P, feed out (the help
    /// text names it only; inferred from its G83 and the FANUC G85).
    FaceBoreStart,
    /// GSK980TDi G89: the same along X.
    SideBoreStart,
    /// GSK980TDi G84: rigid tapping along Z from the start point (help text G84/88).
    TapFace,
    /// GSK980TDi G88: rigid tapping along X from the start point.
    TapSide,
}

impl DrillKind {
    pub fn code(self) -> &'static str {
        match self {
            DrillKind::G73 => "G73",
            DrillKind::G74 => "G74",
            DrillKind::G76 => "G76",
            DrillKind::G81 => "G81",
            DrillKind::G82 => "G82",
            DrillKind::G83 => "G83",
            DrillKind::G84 => "G84",
            DrillKind::G85 => "G85",
            DrillKind::G86 => "G86",
            DrillKind::G87 => "G87",
            DrillKind::G88 => "G88",
            DrillKind::G89 => "G89",
            DrillKind::FaceG83 | DrillKind::FaceFromR => "G83",
            DrillKind::SideG87 | DrillKind::SideFromR => "G87",
            DrillKind::TapFace | DrillKind::FaceTapR => "G84",
            DrillKind::TapSide | DrillKind::SideTapR => "G88",
            DrillKind::FaceBoreR | DrillKind::FaceBoreStart => "G85",
            DrillKind::SideBoreR | DrillKind::SideBoreStart => "G89",
        }
    }

    /// The cycle needs a peck depth Q (FANUC PS0045 otherwise).
    pub fn needs_q(self) -> bool {
        matches!(self, DrillKind::G73 | DrillKind::G83)
    }

    /// Q is the shift at the bottom.
    pub fn shifts(self) -> bool {
        matches!(self, DrillKind::G76 | DrillKind::G87)
    }

    /// A lathe cycle that drills from the start point (GSK980TDi G83/G87, G85/G89).
    pub fn from_start(self) -> bool {
        matches!(self, DrillKind::FaceG83 | DrillKind::SideG87 | DrillKind::FaceBoreStart | DrillKind::SideBoreStart)
    }

    /// A boring cycle from the start point: feed in and feed out, no pecks.
    pub fn bores_from_start(self) -> bool {
        matches!(self, DrillKind::FaceBoreStart | DrillKind::SideBoreStart)
    }

    /// A lathe cycle: it drills along Z (G83) or X (G87) of the lathe, not along a plane's normal.
    pub fn on_lathe(self) -> bool {
        matches!(
            self,
            DrillKind::FaceG83
                | DrillKind::SideG87
                | DrillKind::FaceBoreStart
                | DrillKind::SideBoreStart
                | DrillKind::FaceFromR
                | DrillKind::SideFromR
                | DrillKind::TapFace
                | DrillKind::TapSide
                | DrillKind::FaceTapR
                | DrillKind::SideTapR
                | DrillKind::FaceBoreR
                | DrillKind::SideBoreR
        )
    }

    /// The lathe cycles that drill along X.
    pub fn along_x(self) -> bool {
        matches!(self, DrillKind::SideG87 | DrillKind::SideFromR | DrillKind::TapSide | DrillKind::SideTapR | DrillKind::SideBoreR | DrillKind::SideBoreStart)
    }

    /// GSK980TDi rigid tapping G84/G88: spindle-synchronised, not laid out by the hole cycles of `cycles::drill`.
    pub fn rigid_tap(self) -> bool {
        matches!(self, DrillKind::TapFace | DrillKind::TapSide)
    }

    /// A group 01 code that starts a lathe cycle of the GSK980TDi (G83, G87, G84, G88): it ends
    /// the motion mode in force.
    pub fn ends_motion_mode(self) -> bool {
        self.from_start() || self.rigid_tap()
    }
}

/// Which cycle: which axis pecks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PeckKind {
    /// G74: pecks along Z, steps along X.
    Face,
    /// G75: pecks along X, steps along Z.
    Groove,
}

impl PeckKind {
    pub fn code(self) -> &'static str {
        match self {
            PeckKind::Face => "G74",
            PeckKind::Groove => "G75",
        }
    }

    /// (peck axis, step axis) as `Vec3` indices.
    pub fn axes(self) -> (usize, usize) {
        match self {
            PeckKind::Face => (2, 0),
            PeckKind::Groove => (0, 2),
        }
    }
}

/// Which roughing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RoughKind {
    /// G71: depth along X, cuts along Z.
    Turning,
    /// G72: depth along Z, cuts along X.
    Facing,
    /// G73: the whole contour again and again, each pass closer (pattern repeating).
    Pattern,
}

impl RoughKind {
    pub fn code(self) -> &'static str {
        match self {
            RoughKind::Turning => "G71",
            RoughKind::Facing => "G72",
            RoughKind::Pattern => "G73",
        }
    }

    /// (level axis, cut axis) as `Vec3` indices (G73 has none; it answers as G71).
    pub fn axes(self) -> (usize, usize) {
        match self {
            RoughKind::Turning | RoughKind::Pattern => (0, 2),
            RoughKind::Facing => (2, 0),
        }
    }
}

/// Which box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BoxKind {
    /// G90: cuts along Z; R is the X difference (radius) of cut start minus cut end.
    Turning,
    /// G94: cuts along X; R is the Z difference of cut start minus cut end.
    Facing,
}

impl BoxKind {
    pub fn code(self) -> &'static str {
        match self {
            BoxKind::Turning => "G90",
            BoxKind::Facing => "G94",
        }
    }

    /// Index of the axis the tool steps along (X for G90, Z for G94) in `Vec3`.
    pub fn step_axis(self) -> usize {
        match self {
            BoxKind::Turning => 0,
            BoxKind::Facing => 2,
        }
    }
}
