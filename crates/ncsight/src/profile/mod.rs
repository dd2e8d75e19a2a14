//! Controller profiles. A profile answers the interpreter's questions: which G and M codes exist
//! and what they mean, how a number without a decimal point is read, which parameters exist with
//! their manual numbers, units, ranges and defaults, and which alarm numbering is used.
//! The interpreter never tests a profile's name.
//!
//! Profiles are data (`gsk980tdi.rs`, `gsk988t.rs`, `fanuc0m.rs`, `yasnac_lx3.rs`); the G-code
//! tables that several lathes share live in `lathe_a.rs`. What a profile is made of: its codes'
//! vocabulary (`schema.rs`), the rules where controllers differ (`rules.rs`), the parameters
//! (`params.rs`), and here the `Profile` that holds them.

mod builder;
mod common;
mod fanuc0i;
mod fanuc0m;
mod fanuc0t;
mod gsk980tdi;
mod gsk988t;
mod later;
mod lathe_a;
mod lathe_drill;
mod meaning_zh;
mod params;
mod rules;
mod schema;
mod yasnac_lx3;

use crate::alarm::AlarmStyle;

pub use meaning_zh::meaning_zh;
pub use params::*;
pub use rules::*;
pub use schema::*;

/// A controller profile.
#[derive(Debug, Clone)]
pub struct Profile {
    pub name: &'static str,
    pub title: &'static str,
    pub kind: MachineKind,
    /// X words are diameters (lathes).
    pub diameter_x: bool,
    /// Constant surface speed on a machining centre: the parameter naming the axis whose
    /// coordinate is the radius (FANUC 3770: 1 X, 2 Y, 3 Z); lathes take the X diameter.
    pub css_axis: Option<ParamKey>,
    pub integer_lengths: IntegerLengths,
    /// The parameter that makes a length without a decimal point millimetres (inches) instead
    /// (FANUC 3401#0 DPI, "calculator-type" input), if the profile knows one.
    pub calculator_input: Option<ParamKey>,
    pub alarm_style: AlarmStyle,
    /// `U`/`W` (and `V`) are incremental X/Z (Y) words: lathes with G-code system A.
    pub incremental_addresses: bool,
    /// Feed per revolution at power on (lathes: G98 on GSK per the TDi manual p179).
    pub power_on_per_rev: bool,
    /// Two G codes from group 00 and group 01 in one block is an alarm (GSK, TAC p65).
    pub group00_with_01_alarm: bool,
    /// A reference-point code (G27-G30) while a drilling canned cycle is in force is an alarm
    /// (FANUC alarm 0044, G27-G30 NOT ALLOWED IN FIXED CYC).
    pub reference_in_canned_cycle_alarm: bool,
    /// Axes the machine has, of "XYZ" (formatters omit the others).
    pub axes: &'static str,
    /// The reference point G28 returns to, in machine coordinates (mm, X as a radius), where the
    /// setup gives none: a documented assumption per profile (docs/setup.md).
    pub reference_point_mm: crate::motion::Vec3,
    /// Addresses the controller reads at all (anything else is IMPROPER NC-ADDRESS).
    pub addresses: Letters,
    /// The parameter with the power-on back-off e of the lathe peck cycles G74/G75 (one value
    /// for both; their first block rewrites it), if the profile knows it.
    pub peck_back_off: Option<ParamKey>,
    /// The address of G90/G94's taper (the cut start's offset from the end point): R on the
    /// FANUC 0-T and the GSKs; I on the YASNAC LX3 (its manual, G68 mirror image: "I command
    /// for canned cycle taper", and its G92).
    pub box_taper: u8,
    /// The G codes, table by table, each table with the manual it comes from.
    pub g_codes: &'static [Codes<GDef>],
    pub m_codes: &'static [Codes<MDef>],
    /// The manual's parameters, then ncsight's own settings ([`SETTINGS`]).
    pub params: &'static [&'static [ParamDef]],
    pub time: TimeKeys,
    pub thread: ThreadRules,
    pub drill: DrillRules,
    pub calls: CallRules,
    pub macros: MacroRules,
    pub frame: FrameRules,
    /// The G-code systems B and C a parameter selects (FANUC lathes: 3401#6 GSB, #7 GSC):
    /// the same profile with the codes renamed.
    pub g_code_systems: Option<&'static GCodeSystems>,
    /// One paragraph for `ncsight machines`.
    pub summary: &'static str,
}

/// A lathe's G-code systems B and C (FANUC): the bits that select them and the profiles with
/// their code tables (the same parameters, so the values carry over).
#[derive(Debug)]
pub struct GCodeSystems {
    pub b: ParamKey,
    pub c: ParamKey,
    pub profile_b: &'static Profile,
    pub profile_c: &'static Profile,
}

/// All profiles, in the order `ncsight machines` lists them.
pub fn all() -> [&'static Profile; 7] {
    [&gsk980tdi::PROFILE, &gsk988t::PROFILE, &fanuc0m::PROFILE, &yasnac_lx3::PROFILE, &fanuc0t::PROFILE, &fanuc0i::TF, &fanuc0i::MF]
}

/// The profile of that name.
pub fn by_name(name: &str) -> Option<&'static Profile> {
    all().into_iter().find(|p| p.name.eq_ignore_ascii_case(name))
}

impl Profile {
    /// Whether the profile's data hold together, so that a run never fails on a mistake in it:
    /// parameter defaults in range, no code twice, each code's name its numbers, every
    /// parameter a rule names defined, the drilling cycles' parameters where they are listed,
    /// the codes the interpreter names by function present. Every built-in profile passes (a
    /// test); a profile defined as data elsewhere should be checked with it first.
    pub fn validate(&'static self) -> Result<(), String> {
        let p = self;
        let fail = |msg: String| Err(format!("profile {}: {msg}", p.name));
        for d in p.all_params() {
            if !(d.min <= d.default && d.default <= d.max) || d.source.is_empty() || d.meaning.is_empty() {
                return fail(format!("parameter {}: default out of range, or no source or meaning", d.key));
            }
        }
        let all: Vec<&GDef> = p.g_defs().collect();
        for (i, g) in all.iter().enumerate() {
            if all[i + 1..].iter().any(|h| h.major == g.major && h.minor == g.minor) {
                return fail(format!("{} twice", g.name));
            }
            let want = match g.minor {
                Some(m) => format!("G{:02}.{m}", g.major),
                None => format!("G{:02}", g.major),
            };
            if g.name != want {
                return fail(format!("the code {want} is named {}", g.name));
            }
        }
        let mut keys: Vec<ParamKey> = Vec::new();
        for g in &all {
            if let GFn::Thread(ThreadCmd::Cycle(rules)) = g.function {
                match rules.pull_out {
                    PullOutRule::JkTenths(k) => keys.push(k),
                    PullOutRule::JkChamfer { amount, angle } | PullOutRule::Chamfer { amount, angle } => keys.extend([amount, angle]),
                    PullOutRule::None => {}
                }
                if let HoldRule::PullOutOrFinish(k) | HoldRule::ThreadUp(k) = rules.hold {
                    keys.push(k);
                }
                if rules.repair_p && p.thread.repair_enable.is_none() {
                    return fail(format!("{} repairs with P1 but the profile has no repair switch", g.name));
                }
            }
            if let GFn::CompoundThread(_) = g.function {
                match p.thread.g76 {
                    Some(k) => keys.extend([k.finishing, k.pull_out, k.angle, k.dmin_um, k.allowance].into_iter().chain(k.pull_out_angle)),
                    None => return fail(format!("{} without its parameters (ThreadRules.g76)", g.name)),
                }
            }
            if let GFn::Drill(kind) = g.function {
                use crate::codes::DrillKind;
                let d = p.drill;
                let missing = match kind {
                    DrillKind::G73 => d.g73_retract_um.map(|k| keys.push(k)).is_none(),
                    DrillKind::G83 => d.g83_clearance_um.map(|k| keys.push(k)).is_none(),
                    DrillKind::G76 | DrillKind::G87 => d.shift_bits.map(|(a, b)| keys.extend([a, b])).is_none(),
                    DrillKind::FaceFromR | DrillKind::SideFromR => match (d.lathe_peck_full_return, d.g73_retract_um, d.g83_clearance_um) {
                        (Some(a), Some(b), Some(c)) => {
                            keys.extend([a, b, c]);
                            false
                        }
                        _ => true,
                    },
                    _ => false,
                };
                if missing {
                    return fail(format!("{} without its parameters (DrillRules)", g.name));
                }
            }
        }
        let t = p.thread;
        keys.extend([t.pull_out_speed, t.after_end_feed, t.pull_out_accel, t.repair_enable].into_iter().flatten());
        keys.extend(p.time.rapid);
        keys.extend([p.time.feed_max, p.time.dry_run]);
        keys.extend(p.calculator_input);
        keys.extend(p.peck_back_off);
        keys.extend(p.calls.builder.keys());
        keys.extend(SETTINGS.iter().map(|d| d.key));
        if let Some(k) = keys.into_iter().find(|k| p.param(*k).is_none()) {
            return fail(format!("a rule names parameter {k}, which the profile does not define"));
        }
        for f in [GFn::Rapid, GFn::Linear, GFn::ArcCw, GFn::ArcCcw, GFn::PlaneXY, GFn::PlaneZX, GFn::PlaneYZ, GFn::Dwell, GFn::ReferenceReturn] {
            if !p.has(f) {
                return fail(format!("no code for {f:?}"));
            }
        }
        let ms: Vec<&MDef> = p.m_defs().collect();
        for (i, m) in ms.iter().enumerate() {
            if ms[i + 1..].iter().any(|n| n.code == m.code) {
                return fail(format!("M{} twice", m.code));
            }
        }
        let params = Params::defaults(p);
        if !((0..3).all(|a| params.rapid_mm_min(a) > 0.0) && params.feed_max_mm_min() > 0.0) {
            return fail("the rapid rates and the feed limit must be more than 0".into());
        }
        Ok(())
    }

    /// How far ncsight simulates `g` on this profile: the function's status, and for G10 the
    /// forms the profile has (the GSK980TDi's L3 tool life data are read and not kept).
    pub fn code_status(&self, g: &GDef) -> CodeStatus {
        match g.function {
            GFn::DataSetting if self.frame.g10 == G10Forms::ToolLifeAndParameters => {
                CodeStatus::Assumed("G10 L3's tool life data are read and not kept: ncsight does not count tool life")
            }
            f => f.status(),
        }
    }

    /// Every G code of the profile, in table order.
    pub fn g_defs(&self) -> impl Iterator<Item = &'static GDef> + '_ {
        self.g_codes.iter().flat_map(|t| t.codes.iter())
    }

    /// Every M code of the profile, in table order.
    pub fn m_defs(&self) -> impl Iterator<Item = &'static MDef> + '_ {
        self.m_codes.iter().flat_map(|t| t.codes.iter())
    }

    /// Whether a G code of the profile does `f`.
    pub fn has(&self, f: GFn) -> bool {
        self.g_defs().any(|g| g.function == f)
    }

    pub fn g_code(&self, major: u32, minor: Option<u32>) -> Option<&'static GDef> {
        self.g_defs().find(|g| g.major == major && g.minor == minor)
    }

    /// The name of the code that does `f` (`G01` for linear interpolation), from the profile's
    /// table; `?` if the profile has none (a mistake in a table, caught by the profile tests).
    pub fn name_of(&self, f: GFn) -> &'static str {
        self.g_defs().find(|g| g.function == f).map_or("?", |g| g.name)
    }

    pub fn m_code(&self, code: u32) -> Option<&'static MDef> {
        self.m_defs().find(|m| m.code == code)
    }

    /// The parameters a manual's number names: one value, or its bits (key, bit).
    pub fn params_numbered(&self, number: u32) -> Vec<(ParamKey, Option<u8>)> {
        self.params
            .iter()
            .flat_map(|t| t.iter())
            .filter_map(|d| match d.key {
                ParamKey::Number(n, bit) if n == number => Some((d.key, bit)),
                _ => None,
            })
            .collect()
    }

    pub fn param(&self, key: ParamKey) -> Option<(usize, &'static ParamDef)> {
        // Plain loops: this runs for every parameter read of every block.
        let mut i = 0;
        for table in self.params {
            for p in table.iter() {
                if p.key == key {
                    return Some((i, p));
                }
                i += 1;
            }
        }
        None
    }

    /// Every parameter and setting, in order.
    pub fn all_params(&self) -> impl Iterator<Item = &'static ParamDef> + '_ {
        self.params.iter().flat_map(|t| t.iter())
    }

    pub fn takes_address(&self, letter: u8) -> bool {
        if letter.is_ascii_lowercase() {
            // A comma word (`,A`): the drawing's words only.
            return self.frame.drawing.is_some_and(|d| d.takes(letter));
        }
        self.addresses.contains(letter)
    }

    pub fn is_lathe(&self) -> bool {
        self.kind == MachineKind::Lathe
    }
}

/// A set of address letters A-Z, looked up once per word of every block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Letters(u32);

impl Letters {
    /// The letters of `s` (upper-case A-Z; anything else is a mistake in a profile table).
    pub const fn new(s: &str) -> Letters {
        let b = s.as_bytes();
        let mut mask = 0u32;
        let mut i = 0;
        while i < b.len() {
            assert!(b[i].is_ascii_uppercase(), "address letters are A-Z");
            mask |= 1 << (b[i] - b'A');
            i += 1;
        }
        Letters(mask)
    }

    /// These letters and `letter` (upper-case A-Z).
    pub const fn with(self, letter: u8) -> Letters {
        assert!(letter.is_ascii_uppercase(), "address letters are A-Z");
        Letters(self.0 | 1 << (letter - b'A'))
    }

    /// No letter.
    pub const EMPTY: Letters = Letters(0);

    pub fn contains(self, letter: u8) -> bool {
        letter.is_ascii_uppercase() && self.0 & (1 << (letter - b'A')) != 0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The letters in alphabetical order.
    pub fn iter(self) -> impl Iterator<Item = char> {
        (b'A'..=b'Z').filter(move |&c| self.contains(c)).map(char::from)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_profile_is_consistent() {
        for p in all() {
            if let Err(e) = p.validate() {
                panic!("{e}");
            }
            assert!(by_name(p.name).is_some());
        }
    }

    #[test]
    fn settings_by_name() {
        let mut ps = Params::defaults(by_name("fanuc0m").unwrap());
        ps.set_text("rapid_accel_ms=250").unwrap();
        assert_eq!(ps.get(ParamKey::Setting("rapid_accel_ms")), 250.0);
        ps.set_text("dry_run_mm_min=1000").unwrap();
        let mut ps = Params::defaults(by_name("gsk988t").unwrap());
        assert!(ps.set_text("dry_run_mm_min=1000").is_err()); // the GSK988T has No.1410
    }

    #[test]
    fn param_syntax() {
        let mut ps = Params::defaults(by_name("gsk980tdi").unwrap());
        ps.set_text("19=10").unwrap();
        assert_eq!(ps.get(ParamKey::Number(19, None)), 10.0);
        ps.set_text("18.6=1").unwrap();
        assert!(matches!(ps.set_text("18.6=2"), Err(ParamError::OutOfRange { .. })));
        assert!(matches!(ps.set_text("9999=1"), Err(ParamError::Unknown(_))));
        assert!(matches!(ps.set_text("19"), Err(ParamError::Syntax(_))));
        // Issue 15: an overflowing number is "not finite", a fraction of a whole-number parameter
        // is refused.
        assert!(matches!(ps.set_text("19=1e309"), Err(ParamError::NotFinite(_))));
        assert!(matches!(ps.set_text("19=0.5"), Err(ParamError::NotWhole { .. })));
        ps.set_text("19=5").unwrap();
    }
}
