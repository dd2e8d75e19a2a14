//! Parameters: their identity (`ParamKey`) and definition (`ParamDef`), the tables several
//! profiles share, and the values in force for one run (`Params`).

use super::*;
/// FANUC 0i-T 5002: how a lathe's tool offsets act (docs/reference/macro.md 10.1).
pub const FANUC_LATHE_OFFSETS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(5002, Some(4)),
        meaning: "LGT: 0 = the geometry offset shifts the coordinates (no motion); 1 = it moves the tool, as the wear offset does",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i-T parameter manual, 5002#4 LGT, as recalled (docs/reference/macro.md 10.1; inferred for the FANUC 0-T)",
    },
    ParamDef {
        key: ParamKey::Number(5002, Some(6)),
        meaning: "LWM: 0 = the offset's movement is made in the T block; 1 = together with the next axis move",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "FANUC 0i-T parameter manual, 5002#6 LWM, as recalled (docs/reference/macro.md 10.1; inferred for the FANUC 0-T)",
    },
];

/// One of the two on/off settings of a lathe's tool offsets (an ncsight setting where the
/// parameter's number was not found).
const fn offset_bit(key: &'static str, meaning: &'static str, default: f64, source: &'static str) -> ParamDef {
    ParamDef { key: ParamKey::Setting(key), meaning, unit: "bit", min: 0.0, max: 1.0, default, source }
}

const WEAR_WITH_NEXT_MOVE: &str = "1 = the offset's movement is made with the next axis move; 0 = in the T block";

/// [`FANUC_LATHE_OFFSETS`] as ncsight settings, for the lathes whose parameter numbers were not
/// found: `geometry_by_movement` defaults to 1 (GSK's "tool traverse" mode, inferred).
pub const GSK_LATHE_OFFSETS: &[ParamDef] = &[
    offset_bit(
        "geometry_by_movement",
        "1 = the geometry offset moves the tool (GSK 'tool traverse'); 0 = it shifts the coordinates (GSK 'coordinate offset')",
        1.0,
        "ncsight setting; GSK980TD/TDi have both modes by a state parameter whose number was not found (docs/reference/macro.md 10.1), traverse assumed",
    ),
    offset_bit("wear_with_next_move", WEAR_WITH_NEXT_MOVE, 0.0, "ncsight setting; assumed (in the T block, as FANUC's default)"),
];

/// [`GSK_LATHE_OFFSETS`] with FANUC's defaults, for the YASNAC LX3 (no text at hand).
pub const YASNAC_LATHE_OFFSETS: &[ParamDef] = &[
    offset_bit(
        "geometry_by_movement",
        "1 = the geometry offset moves the tool; 0 = it shifts the coordinates",
        0.0,
        "ncsight setting; inferred as FANUC 5002#4 LGT's default (no YASNAC LX3 text at hand)",
    ),
    offset_bit("wear_with_next_move", WEAR_WITH_NEXT_MOVE, 0.0, "ncsight setting; inferred as FANUC 5002#6 LWM's default (no YASNAC LX3 text at hand)"),
];

/// A parameter's identity: the manual's own number (with a bit for bit parameters), or, where
/// no manual number is known, an ncsight setting name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamKey {
    Number(u32, Option<u8>),
    Setting(&'static str),
}

impl std::fmt::Display for ParamKey {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParamKey::Number(n, None) => write!(f, "{n}"),
            ParamKey::Number(n, Some(b)) => write!(f, "{n}.{b}"),
            ParamKey::Setting(s) => write!(f, "{s}"),
        }
    }
}

impl ParamKey {
    /// The key as a manual's text says it: `No.19`, `No.174 bit 4`.
    pub fn spoken(&self) -> String {
        match self {
            ParamKey::Number(n, None) => format!("No.{n}"),
            ParamKey::Number(n, Some(b)) => format!("No.{n} bit {b}"),
            ParamKey::Setting(s) => s.to_string(),
        }
    }

    /// Parse `19`, `18.6`, `0018.6`, `8135.7` or a setting name.
    pub fn parse(text: &str) -> Option<ParamKey> {
        let t = text.trim();
        if t.is_empty() {
            return None;
        }
        if t.bytes().all(|c| c.is_ascii_digit() || c == b'.') {
            let mut it = t.splitn(2, '.');
            let n: u32 = it.next()?.parse().ok()?;
            let bit = match it.next() {
                Some(b) => Some(b.parse::<u8>().ok().filter(|b| *b < 8)?),
                None => None,
            };
            return Some(ParamKey::Number(n, bit));
        }
        None
    }
}

/// One parameter with the facts the manuals give. `source` says where the fact comes from and
/// whether it was read or inferred (docs/reference/parameters.md).
#[derive(Debug, Clone, Copy)]
pub struct ParamDef {
    pub key: ParamKey,
    pub meaning: &'static str,
    /// The unit the controller's parameter screen uses.
    pub unit: &'static str,
    pub min: f64,
    pub max: f64,
    pub default: f64,
    /// Manual reference, or "assumed" with the reason.
    pub source: &'static str,
}

impl ParamDef {
    /// The parameter screen takes a whole number: bits, counts, times in ms, angles in degrees
    /// and lengths in increments (0.001 mm, 0.1 x lead); only lengths in mm and rates in mm/min
    /// take decimals (FANUC's real-type parameters).
    pub fn whole(&self) -> bool {
        !matches!(self.unit, "mm" | "mm/min")
    }
}

/// Which parameters the time model reads. Rates are in mm/min.
#[derive(Debug, Clone, Copy)]
pub struct TimeKeys {
    /// Rapid traverse rate of X, Y, Z (the same key may serve several axes).
    pub rapid: [ParamKey; 3],
    /// Upper limit of the cutting feed.
    pub feed_max: ParamKey,
    /// Dry-run rate (GSK988T 1410, seed 001 G32.1 note 13).
    pub dry_run: ParamKey,
}

/// ncsight's own settings, on every profile: what the time model needs where no manual gave a
/// parameter number (docs/reference/parameters.md: acc/dec time constants were not found).
/// The rapid rate and feed ceiling under their FANUC numbers (1420, 1422), shared by the
/// profiles that use FANUC parameter numbering (fanuc0t; the GSK988T, whose manual numbers its
/// parameters the FANUC way).
pub const FANUC_RATES: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Number(1420, None),
        meaning: "rapid traverse rate (each axis)",
        unit: "mm/min",
        min: 1.0,
        max: 60000.0,
        default: 8000.0,
        source: "FANUC 0i numbering (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Number(1422, None),
        meaning: "upper limit of the cutting feed",
        unit: "mm/min",
        min: 1.0,
        max: 60000.0,
        default: 8000.0,
        source: "FANUC 0i numbering (inferred); default assumed",
    },
];

/// FANUC input format: 3401#0 DPI (docs/reference/parameters.md, FANUC: [inferred]).
pub const FANUC_INPUT: &[ParamDef] = &[ParamDef {
    key: ParamKey::Number(3401, Some(0)),
    meaning: "DPI: 1 = a length without a decimal point is in mm (inch), calculator-type input; 0 = in least input increments",
    unit: "bit",
    min: 0.0,
    max: 1.0,
    default: 0.0,
    source: "docs/sources.md, FANUC (inferred)",
}];

/// FANUC 0-M G60: the overrun of single direction positioning per axis, signed by the side the
/// axis approaches from (FANUC 0i 5440, per axis; ncsight settings, one per axis, 0 at power
/// on as the parameter's default).
pub const FANUC_G60: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Setting("g60_overrun_x_mm"),
        meaning: "G60: X comes to its end point from this far before it (signed: + from the minus side); 0 = straight there",
        unit: "mm",
        min: -100.0,
        max: 100.0,
        default: 0.0,
        source: "ncsight setting; FANUC 0i parameter 5440 for X (a machine builder's value: set it as the machine has it)",
    },
    ParamDef {
        key: ParamKey::Setting("g60_overrun_y_mm"),
        meaning: "G60: the same for Y",
        unit: "mm",
        min: -100.0,
        max: 100.0,
        default: 0.0,
        source: "ncsight setting; FANUC 0i parameter 5440 for Y",
    },
    ParamDef {
        key: ParamKey::Setting("g60_overrun_z_mm"),
        meaning: "G60: the same for Z",
        unit: "mm",
        min: -100.0,
        max: 100.0,
        default: 0.0,
        source: "ncsight setting; FANUC 0i parameter 5440 for Z",
    },
];

/// FANUC custom macro: 6000#5 SBM (docs/reference/macro.md section 6; FANUC 0i parameter manual, inferred for
/// the FANUC 0).
pub const FANUC_MACRO: &[ParamDef] = &[ParamDef {
    key: ParamKey::Number(6000, Some(5)),
    meaning: "SBM: 1 = single block stops after each macro statement (assignment, IF, GOTO, WHILE, END) too; 0 = only after NC blocks",
    unit: "bit",
    min: 0.0,
    max: 1.0,
    default: 0.0,
    source: "FANUC 0i parameter manual, 6000#5 SBM (inferred for the FANUC 0)",
}];

pub const SETTINGS: &[ParamDef] = &[
    ParamDef {
        key: ParamKey::Setting("measure_approach_mm"),
        meaning: "G36/G37: the tool comes at rapid to this far before the measuring position, then at the measuring feed",
        unit: "mm",
        min: 0.0,
        max: 100.0,
        default: 5.0,
        source: "ncsight setting for FANUC 0i parameter 6254 (gamma; inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Setting("measure_feed_mm_min"),
        meaning: "G36/G37: the measuring feed",
        unit: "mm/min",
        min: 1.0,
        max: 10000.0,
        default: 100.0,
        source: "ncsight setting for FANUC 0i parameter 6241 (inferred); default assumed",
    },
    ParamDef {
        key: ParamKey::Setting("stroke2_outside"),
        meaning: "G22's area: 0 = the tool may not enter it, 1 = it may not leave it",
        unit: "bit",
        min: 0.0,
        max: 1.0,
        default: 0.0,
        source: "ncsight setting for FANUC 0i parameter 1300#0 (OUT) and GSK980TDi No.172 bit 2 (help text G22 note 2); inside forbidden assumed at power on",
    },
    ParamDef {
        key: ParamKey::Setting("tool_change_s"),
        meaning: "time a tool change takes (added to the cycle time at each change of tool number)",
        unit: "s",
        min: 0.0,
        max: 3600.0,
        default: 0.0,
        source: "ncsight setting (the setup's [machine] tool_change_s sets it); 0 assumed: the machine builder's figure",
    },
    ParamDef {
        key: ParamKey::Setting("rotary_rapid_deg_min"),
        meaning: "rapid rate of a rotary axis (A, B, C) the setup declares",
        unit: "deg/min",
        min: 1.0,
        max: 1000000.0,
        default: 10800.0,
        source: "ncsight setting; assumed (30 rpm; the FANUC per-axis rapid parameter 1420 of the rotary axis is the machine builder's)",
    },
    ParamDef {
        key: ParamKey::Setting("rapid_accel_ms"),
        meaning: "time to reach the rapid rate from a stop (linear acceleration), each axis",
        unit: "ms",
        min: 0.0,
        max: 5000.0,
        default: 100.0,
        source: "ncsight setting; assumed (the manuals' time constants were not found)",
    },
    ParamDef {
        key: ParamKey::Setting("feed_accel_ms"),
        meaning: "time to reach a cutting feed or a thread's speed from a stop (linear acceleration)",
        unit: "ms",
        min: 0.0,
        max: 5000.0,
        default: 50.0,
        source: "ncsight setting; assumed (the manuals' time constants were not found)",
    },
];

/// The dry-run rate where the profile's manual gives none.
pub const DRY_RUN_SETTING: ParamDef = ParamDef {
    key: ParamKey::Setting("dry_run_mm_min"),
    meaning: "dry-run rate: feeds and threads run at it in dry run",
    unit: "mm/min",
    min: 1.0,
    max: 60000.0,
    default: 5000.0,
    source: "ncsight setting; assumed (the parameter number was not found)",
};

/// [`DRY_RUN_SETTING`] as a table.
pub const DRY_RUN: &[ParamDef] = &[DRY_RUN_SETTING];

/// Parameter values in force for one run: the profile's defaults, overridden by `--param`.
#[derive(Debug, Clone)]
pub struct Params {
    /// The profile in force: `base`, or its G-code system B or C as the parameters select.
    profile: &'static Profile,
    base: &'static Profile,
    values: Vec<f64>,
    /// The feed limit, read by every cutting block: kept up to date by `set`.
    feed_max_mm_min: f64,
    /// How lengths without a decimal point read (the profile's rule, or calculator-type input
    /// when its parameter is set): kept up to date by `set`.
    integer_lengths: IntegerLengths,
}

/// Why a `--param` could not be taken.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamError {
    Syntax(String),
    NotFinite(String),
    NotWhole { key: String, value: f64, unit: &'static str },
    Unknown(String),
    OutOfRange { key: String, value: f64, min: f64, max: f64, unit: &'static str },
}

impl std::fmt::Display for ParamError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParamError::Syntax(s) => write!(f, "--param {s}: expected N=V, N.B=V or NAME=V"),
            ParamError::NotFinite(s) => write!(f, "--param {s}: the value is not a finite number"),
            ParamError::NotWhole { key, value, unit } => write!(f, "parameter {key} = {value}: the parameter takes a whole number ({unit})"),
            ParamError::Unknown(s) => write!(f, "parameter {s} does not exist on this profile (see `ncsight machines`)"),
            ParamError::OutOfRange { key, value, min, max, unit } => {
                write!(f, "parameter {key} = {value} is out of range {min}..{max} {unit}")
            }
        }
    }
}

impl std::error::Error for ParamError {}

impl Params {
    pub fn defaults(profile: &'static Profile) -> Params {
        let mut params = Params {
            profile,
            base: profile,
            values: profile.all_params().map(|p| p.default).collect(),
            feed_max_mm_min: 0.0,
            integer_lengths: profile.integer_lengths,
        };
        params.cache();
        params
    }

    pub fn profile(&self) -> &'static Profile {
        self.profile
    }

    /// The profile the parameters were made for (its G-code system A where it has B and C).
    pub fn base(&self) -> &'static Profile {
        self.base
    }

    /// Apply `N=V` (`19=10`, `18.6=1`, `rapid_mm_min=12000`).
    pub fn set_text(&mut self, assignment: &str) -> Result<(), ParamError> {
        let (k, v) = assignment.split_once('=').ok_or_else(|| ParamError::Syntax(assignment.into()))?;
        let value: f64 = v.trim().parse().map_err(|_| ParamError::Syntax(assignment.into()))?;
        if !value.is_finite() {
            return Err(ParamError::NotFinite(assignment.into()));
        }
        let key = match ParamKey::parse(k) {
            Some(key) => key,
            None => match self.profile.all_params().find(|p| matches!(p.key, ParamKey::Setting(s) if s == k.trim())) {
                Some(p) => p.key,
                None => return Err(ParamError::Unknown(k.trim().into())),
            },
        };
        self.set(key, value)
    }

    pub fn set(&mut self, key: ParamKey, value: f64) -> Result<(), ParamError> {
        let i = self.check(key, value)?;
        self.values[i] = value;
        self.cache();
        Ok(())
    }

    /// Whether `value` may be set for `key`: its index when it may.
    pub fn check(&self, key: ParamKey, value: f64) -> Result<usize, ParamError> {
        let (i, def) = self.profile.param(key).ok_or_else(|| ParamError::Unknown(key.to_string()))?;
        if value < def.min || value > def.max {
            return Err(ParamError::OutOfRange { key: key.to_string(), value, min: def.min, max: def.max, unit: def.unit });
        }
        if def.whole() && value.fract() != 0.0 {
            return Err(ParamError::NotWhole { key: key.to_string(), value, unit: def.unit });
        }
        Ok(i)
    }

    /// Refresh the values kept for the blocks that read them all the time.
    fn cache(&mut self) {
        // G-code system B or C (FANUC 3401#6 GSB, #7 GSC; C when both): the same parameters.
        if let Some(sys) = self.base.g_code_systems {
            self.profile = self.base;
            self.profile = if self.get(sys.c) != 0.0 {
                sys.profile_c
            } else if self.get(sys.b) != 0.0 {
                sys.profile_b
            } else {
                self.base
            };
        }
        self.feed_max_mm_min = self.get(self.profile.time.feed_max);
        self.integer_lengths = match self.profile.calculator_input {
            Some(k) if self.get(k) != 0.0 => IntegerLengths::Millimetres,
            _ => self.profile.integer_lengths,
        };
    }

    /// How a length without a decimal point reads under these parameters.
    pub fn integer_lengths(&self) -> IntegerLengths {
        self.integer_lengths
    }

    /// The value of a parameter the profile defines. Asking for one it lacks is a programming
    /// error in a profile table, caught by the profile tests.
    pub fn get(&self, key: ParamKey) -> f64 {
        match self.profile.param(key) {
            Some((i, _)) => self.values[i],
            None => panic!("profile {} has no parameter {key}", self.profile.name),
        }
    }

    /// Rapid traverse rate of axis 0..3 (X, Y, Z), mm/min.
    pub fn rapid_mm_min(&self, axis: usize) -> f64 {
        self.get(self.profile.time.rapid[axis])
    }

    pub fn feed_max_mm_min(&self) -> f64 {
        self.feed_max_mm_min
    }
}
