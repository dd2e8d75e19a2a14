//! The job setup (`--setup FILE.toml`, docs/reference/interface.md "The setup file"): the
//! machine, its work offsets, tool and offset tables, and the stock. Plain data read from TOML and
//! checked; the interpreter takes the machine's frame from it, the stock simulation the stock and
//! the tools' shapes.

use serde::{Deserialize, Deserializer};

/// The most spindles a setup may name (`[machine] spindle_p`).
pub const MAX_SPINDLES: usize = 4;

/// `N` numbers, exactly: a TOML array of another length is an error naming both (serde's own
/// fixed-size arrays take three numbers where two are asked for).
fn exactly<'de, D: Deserializer<'de>, const N: usize>(d: D) -> Result<[f64; N], D::Error> {
    let v = Vec::<f64>::deserialize(d)?;
    <[f64; N]>::try_from(v.as_slice()).map_err(|_| serde::de::Error::custom(format!("give exactly {N} numbers, not {}", v.len())))
}

/// [`exactly`] for a value that may be left out.
fn exactly_opt<'de, D: Deserializer<'de>, const N: usize>(d: D) -> Result<Option<[f64; N]>, D::Error> {
    exactly::<D, N>(d).map(Some)
}

/// A number as a message shows it: `inf`, `NaN`, `12.5`.
fn shown(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else {
        format!("{v}")
    }
}

/// The job setup (`--setup FILE.toml`): the machine (axes, travel limits, reference points),
/// the work offsets, the tool and offset tables, the stock. Every part is optional; without a
/// part the run assumes what docs/setup.md says (offsets 0, the profile's reference point).
#[derive(Debug, Clone, PartialEq, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Setup {
    pub machine: Option<MachineSetup>,
    /// Work offsets: where each coordinate system's zero is in machine coordinates.
    pub work: Option<WorkOffsets>,
    #[serde(default, rename = "tool")]
    pub tools: Vec<Tool>,
    /// The offset table (a lathe's T0101 selects offset 01; a mill's H and D numbers).
    #[serde(default, rename = "offset")]
    pub offsets: Vec<Offset>,
    pub stock: Option<Bar>,
    /// A block on a machining centre (drilling cycles).
    pub block: Option<Block>,
}

/// `[machine]`: what the machine is, in machine coordinates (mm; X as a diameter on a lathe).
#[derive(Debug, Clone, PartialEq, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct MachineSetup {
    /// The axes the machine has (`["X", "Z"]`, or with their kinds
    /// `[{ name = "B", kind = "linear" }]`); the profile's axes when absent.
    #[serde(default)]
    pub axes: Vec<AxisDecl>,
    /// Multi-spindle machines: the P values that select a spindle in an S/M block.
    #[serde(default)]
    pub spindle_p: Vec<u32>,
    /// Soft travel limits, `[min, max]` per axis.
    pub limits: Option<Limits>,
    /// The reference point (G28), where the tool is at power on.
    pub reference: Option<Point>,
    /// Seconds added to the cycle time at each tool change (0 when absent).
    pub tool_change_s: Option<f64>,
    /// M codes the machine builder made calls of a programme with the block's other words as
    /// arguments (FANUC parameters 6080-6089, as the machine has them): `{ 165 = "O9832" }`.
    #[serde(default)]
    pub m_macro: std::collections::BTreeMap<String, String>,
    /// The machine builder's own M codes, with what each does (`{ 150 = "sub-spindle
    /// synchronous control on" }`: a chuck transfer, a parts catcher): passed to the machine as
    /// any unlisted M code, without the warning that says it is unknown.
    #[serde(default)]
    pub m_codes: std::collections::BTreeMap<String, String>,
    /// Folders of the machine's resident programmes (O8000-O9999 libraries), searched for a
    /// called programme as `--subprogram-dir` folders are; relative to the setup file.
    #[serde(default)]
    pub library: Vec<String>,
    /// The 2nd, 3rd and 4th reference points (G30 P2-P4).
    pub reference_2: Option<Point>,
    pub reference_3: Option<Point>,
    pub reference_4: Option<Point>,
}

/// One axis of `[machine] axes`: its name alone (`"C"`), or a table with its kind and its
/// incremental address (`{ name = "B", kind = "linear" }`, `{ name = "C", kind = "rotary",
/// incremental = "H" }`).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(untagged)]
pub enum AxisDecl {
    Name(String),
    Full {
        name: String,
        /// `linear` or `rotary`; A, B and C are rotary unless declared linear (a sub-spindle's
        /// travel, say), X, Y and Z linear.
        kind: Option<String>,
        /// The incremental address: `V` for Y and `H` for C on the FANUC lathe's G-code system
        /// A (the default there); an axis without one moves incrementally in G91 only.
        incremental: Option<String>,
    },
}

impl AxisDecl {
    pub fn name(&self) -> &str {
        match self {
            AxisDecl::Name(n) | AxisDecl::Full { name: n, .. } => n,
        }
    }

    /// The axis's letter (checked: one of X Y Z A B C).
    pub fn letter(&self) -> u8 {
        self.name().as_bytes().first().copied().unwrap_or(b'?')
    }

    /// A, B or C declared as a linear axis (millimetres, as X, Y and Z).
    pub fn linear_extra(&self) -> bool {
        matches!(self, AxisDecl::Full { kind: Some(k), .. } if k == "linear") && matches!(self.letter(), b'A' | b'B' | b'C')
    }

    fn check(&self) -> Result<(), SetupError> {
        let name = self.name();
        if !matches!(name, "X" | "Y" | "Z" | "A" | "B" | "C") {
            return Err(SetupError(format!("machine.axes: {name:?} is not an axis (X, Y, Z, A, B or C)")));
        }
        if let AxisDecl::Full { kind, incremental, .. } = self {
            match kind.as_deref() {
                None | Some("linear") => {}
                Some("rotary") if matches!(name, "A" | "B" | "C") => {}
                Some(k) => return Err(SetupError(format!("machine.axes: {name}: kind {k:?}: X, Y and Z are linear; A, B and C rotary or linear"))),
            }
            match (name, incremental.as_deref()) {
                (_, None) | ("Y", Some("V")) => {}
                ("C", Some("H")) if !self.linear_extra() => {}
                (_, Some(i)) => {
                    return Err(SetupError(format!(
                        "machine.axes: {name}: incremental {i:?}: the FANUC lathe's G-code system A has V for Y and H for a rotary C (other axes move incrementally in G91)"
                    )))
                }
            }
        }
        Ok(())
    }
}

/// A point in machine coordinates; an axis left out is 0.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Point {
    pub x_mm: Option<f64>,
    pub y_mm: Option<f64>,
    pub z_mm: Option<f64>,
}

impl Point {
    /// X, Y, Z with 0 for what is left out (X as written: a diameter on a lathe).
    pub fn xyz(&self) -> [f64; 3] {
        [self.x_mm.unwrap_or(0.0), self.y_mm.unwrap_or(0.0), self.z_mm.unwrap_or(0.0)]
    }
}

/// Soft travel limits per axis, `[min, max]` in machine coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Limits {
    #[serde(default, deserialize_with = "exactly_opt")]
    pub x_mm: Option<[f64; 2]>,
    #[serde(default, deserialize_with = "exactly_opt")]
    pub y_mm: Option<[f64; 2]>,
    #[serde(default, deserialize_with = "exactly_opt")]
    pub z_mm: Option<[f64; 2]>,
}

impl Limits {
    pub fn by_axis(&self) -> [Option<[f64; 2]>; 3] {
        [self.x_mm, self.y_mm, self.z_mm]
    }
}

/// `[work]`: G54-G59 and the external (common) offset that shifts all six.
#[derive(Debug, Clone, PartialEq, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct WorkOffsets {
    #[serde(rename = "G54")]
    pub g54: Option<Point>,
    #[serde(rename = "G55")]
    pub g55: Option<Point>,
    #[serde(rename = "G56")]
    pub g56: Option<Point>,
    #[serde(rename = "G57")]
    pub g57: Option<Point>,
    #[serde(rename = "G58")]
    pub g58: Option<Point>,
    #[serde(rename = "G59")]
    pub g59: Option<Point>,
    pub external: Option<Point>,
    /// The additional work coordinate systems G54.1 P1, P2, ... in order (at most 48).
    #[serde(rename = "G54.1", default)]
    pub g54_1: Vec<Point>,
}

/// The additional work coordinate systems (G54.1 P1-P48, FANUC 0i-F).
pub const ADDITIONAL_WORK_SYSTEMS: usize = 48;

impl WorkOffsets {
    /// The external offset, then G54-G59, then G54.1 P1-P48 (each absent where not given).
    pub fn all(&self) -> impl Iterator<Item = Option<Point>> + '_ {
        [self.external, self.g54, self.g55, self.g56, self.g57, self.g58, self.g59]
            .into_iter()
            .chain((0..ADDITIONAL_WORK_SYSTEMS).map(|i| self.g54_1.get(i).copied()))
    }
}

/// One entry of the offset table: geometry and wear per axis, the nose (or cutter) radius and
/// the imaginary tool nose number (lathes), the tool length (mills, H).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Offset {
    pub number: u32,
    #[serde(default)]
    pub x_mm: f64,
    #[serde(default)]
    pub y_mm: f64,
    #[serde(default)]
    pub z_mm: f64,
    #[serde(default)]
    pub wear_x_mm: f64,
    #[serde(default)]
    pub wear_y_mm: f64,
    #[serde(default)]
    pub wear_z_mm: f64,
    #[serde(default)]
    pub radius_mm: f64,
    #[serde(default)]
    pub wear_radius_mm: f64,
    #[serde(default)]
    pub tip: u8,
    #[serde(default)]
    pub length_mm: f64,
    #[serde(default)]
    pub wear_length_mm: f64,
}

/// A block of stock on a machining centre's table, its corners in programme coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Block {
    #[serde(deserialize_with = "exactly")]
    pub min_mm: [f64; 3],
    #[serde(deserialize_with = "exactly")]
    pub max_mm: [f64; 3],
}

/// A bar on a lathe: its face at `front_z_mm`, extending `length_mm` toward -Z; `bore_mm` for
/// internal threads (0: solid).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Bar {
    pub diameter_mm: f64,
    pub length_mm: f64,
    #[serde(default)]
    pub bore_mm: f64,
    #[serde(default)]
    pub front_z_mm: f64,
}

/// What a tool is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum ToolKind {
    /// A threading insert (V profile).
    #[default]
    Thread,
    /// A turning tool (a nose radius).
    Turning,
    /// A drill (diameter, point angle).
    Drill,
    /// A grooving tool: a flat end `width_mm` wide (corners `corner_radius_mm`), positioned by
    /// its `reference` corner.
    Groove,
    /// A parting (cut-off) tool: as a grooving tool.
    Parting,
    /// A boring bar (a nose radius, inside the bore).
    Boring,
    /// A tap.
    Tap,
    /// A milling cutter (its diameter).
    Mill,
}

impl ToolKind {
    /// A tool that works along the spindle axis (drill, tap, an end mill): not cut in the
    /// lathe stock's height field.
    pub fn on_spindle_axis(self) -> bool {
        matches!(self, ToolKind::Drill | ToolKind::Tap | ToolKind::Mill)
    }
}

/// A tool by its T number.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tool {
    /// T number (the tool part of a lathe's `T0101`).
    pub number: u32,
    #[serde(default)]
    pub kind: ToolKind,
    /// Included angle of a threading insert, degrees (60 for ISO metric and UN).
    #[serde(default = "sixty")]
    pub included_angle_deg: f64,
    /// A grooving or parting tool's width, mm (0: a threading-style point, as before).
    #[serde(default)]
    pub width_mm: f64,
    /// Which corner of a grooving or parting tool the programmed point is.
    #[serde(default)]
    pub reference: GrooveReference,
    /// A turning or boring insert's shape by its ISO 1832 letter (the nose angle).
    #[serde(default)]
    pub iso_shape: Option<IsoShape>,
    /// The spindle direction the tool cuts in: a right-hand tool with M03 (the spindle's positive
    /// direction), a left-hand one with M04. Not given: not checked.
    #[serde(default)]
    pub hand: Option<Hand>,
    /// A boring bar's smallest bore, mm: entering a smaller one is a `holder` finding (0: not
    /// checked).
    #[serde(default)]
    pub min_bore_mm: f64,
    /// Tip (nose) radius, mm (`nose_radius_mm` is the same key).
    #[serde(default, alias = "nose_radius_mm")]
    pub tip_radius_mm: f64,
    /// The imaginary tool nose number 0-9 (lathes), where the offset table does not give it.
    #[serde(default)]
    pub tip: Option<u8>,
    /// Width of a flat tip, mm (instead of a radius).
    #[serde(default)]
    pub tip_flat_mm: f64,
    /// Cuts an internal thread (works on the bore, cutting outward).
    #[serde(default)]
    pub internal: bool,
    /// Drill diameter, mm.
    #[serde(default)]
    pub diameter_mm: f64,
    /// Drill point angle, degrees.
    #[serde(default = "one_eighteen")]
    pub point_angle_deg: f64,
    /// A milling cutter's end (`kind = "mill"`): flat, ball or bull (a corner radius).
    #[serde(default)]
    pub shape: MillShape,
    /// A bull-nose mill's corner radius, mm.
    #[serde(default)]
    pub corner_radius_mm: f64,
    /// Whether a mill cuts at its centre (false: a plunge straight down is a `plunge` finding).
    #[serde(default = "yes")]
    pub centre_cutting: bool,
    /// How deep the cutting edges reach up the tool, mm (0: not checked).
    #[serde(default)]
    pub flute_length_mm: f64,
    /// From the holder's face to the tool's tip, mm (0: no holder checked).
    #[serde(default)]
    pub stick_out_mm: f64,
    /// What holds the tool, which must not touch the part.
    #[serde(default)]
    pub holder: Option<Holder>,
}

/// Which corner of a grooving or parting tool the programmed point is (the chuck is on the left).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum GrooveReference {
    /// The corner toward the chuck (-Z): the tool spans from the point toward the face.
    #[default]
    Left,
    /// The corner toward the face (+Z).
    Right,
    /// The middle of the cutting edge.
    #[serde(alias = "center")]
    Centre,
}

/// A lathe insert's shape, by the first letter of its ISO 1832 code.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum IsoShape {
    C,
    D,
    V,
    T,
    W,
    S,
    R,
}

impl IsoShape {
    /// The insert's nose angle, degrees (ISO 1832: C 80, D 55, V 35, T 60, W 80, S 90; R round).
    pub fn nose_angle_deg(self) -> f64 {
        match self {
            IsoShape::C | IsoShape::W => 80.0,
            IsoShape::D => 55.0,
            IsoShape::V => 35.0,
            IsoShape::T => 60.0,
            IsoShape::S => 90.0,
            IsoShape::R => 180.0,
        }
    }

    /// The holder's approach angle assumed for the shape, degrees from the feed direction (-Z)
    /// to the main edge: 95 for C and W (as SCLCR/MWLNR holders), 93 for D, V and T (SDJCR,
    /// SVJBR, MTJNR), 45 for S (SSSCR). Assumed: the setup names no holder.
    pub fn approach_deg(self) -> f64 {
        match self {
            IsoShape::C | IsoShape::W => 95.0,
            IsoShape::D | IsoShape::V | IsoShape::T => 93.0,
            IsoShape::S => 45.0,
            IsoShape::R => 90.0,
        }
    }
}

/// The spindle direction a tool cuts in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Hand {
    /// Cuts with the spindle turning in its positive direction (M03).
    Right,
    /// Cuts with M04.
    Left,
}

/// A tool holder: a cylinder above the tool.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Holder {
    pub diameter_mm: f64,
    pub length_mm: f64,
}

fn yes() -> bool {
    true
}

/// The end of a milling cutter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum MillShape {
    /// A flat end mill.
    #[default]
    Flat,
    /// A ball-nose mill (its radius the cutter's).
    Ball,
    /// A bull-nose (toroidal) mill: flat with `corner_radius_mm` corners.
    Bull,
    /// A chamfer (spot) mill: a cone of `point_angle_deg` to its `diameter_mm`.
    Chamfer,
    /// A face mill: flat, as a flat end mill.
    Face,
}

fn sixty() -> f64 {
    60.0
}

fn one_eighteen() -> f64 {
    118.0
}

impl Tool {
    /// The default without a setup: a sharp 60-degree external threading insert.
    pub fn default_thread() -> Tool {
        Tool {
            number: 0,
            kind: ToolKind::Thread,
            included_angle_deg: 60.0,
            tip_radius_mm: 0.0,
            tip: None,
            tip_flat_mm: 0.0,
            width_mm: 0.0,
            reference: GrooveReference::Left,
            iso_shape: None,
            hand: None,
            min_bore_mm: 0.0,
            internal: false,
            diameter_mm: 0.0,
            point_angle_deg: 118.0,
            shape: MillShape::Flat,
            corner_radius_mm: 0.0,
            centre_cutting: true,
            flute_length_mm: 0.0,
            stick_out_mm: 0.0,
            holder: None,
        }
    }

    /// How far above the tool's tip its end is at distance `d` from its axis (a mill or a drill
    /// cutting along Z), mm; None beyond its radius.
    pub fn end_height(&self, d: f64) -> Option<f64> {
        let r = self.diameter_mm / 2.0;
        if d > r + 1e-9 {
            return None;
        }
        Some(match (self.kind, self.shape) {
            (ToolKind::Mill, MillShape::Flat | MillShape::Face) => 0.0,
            (ToolKind::Mill, MillShape::Ball) => r - (r * r - d * d).max(0.0).sqrt(),
            (ToolKind::Mill, MillShape::Bull) => {
                let rc = self.corner_radius_mm.clamp(0.0, r);
                let flat = r - rc;
                if d <= flat {
                    0.0
                } else {
                    rc - (rc * rc - (d - flat).powi(2)).max(0.0).sqrt()
                }
            }
            // A drill or a tap: the cone of its point.
            _ => d / (self.point_angle_deg.clamp(1.0, 179.0) / 2.0).to_radians().tan(),
        })
    }

    /// How far the cut surface lies from the tip's radius at axial distance `u` from the tip
    /// (the edge profile): flat, then the nose radius, then the flanks at half the included
    /// angle. `None` beyond the tool's reach is never returned: the flanks go on. A turning or
    /// boring tool with an imaginary tool nose (`tip`) cuts with its nose circle only: the
    /// insert's edges beyond it are clearance, not a symmetric V (docs/compensation.md).
    /// [`Tool::profile`] on one side of the tip: `chuck_side` toward -Z (where a right-hand
    /// turning tool's or boring bar's main edge faces as it feeds toward the chuck), else toward
    /// +Z.
    /// - A grooving or parting tool with a `width_mm`: a flat end that wide from its `reference`
    ///   corner, its corners rounded by `corner_radius_mm`, its sides straight up.
    /// - A turning tool or boring bar of an `iso_shape`: its main edge at the holder's approach
    ///   angle toward the chuck, its end edge at 180 - approach - nose angle toward the face
    ///   ([`IsoShape::approach_deg`]), the nose radius between; R: a round insert of the nose
    ///   radius. Without a shape, an 80-degree insert in a 95-degree holder (ISO C in PCLNR, the
    ///   commonest): the main edge 5 degrees past the radial, the end edge 5 degrees off the
    ///   axis (an assumption, said in docs/setup.md).
    /// - Other tools are symmetric ([`Tool::profile`]).
    pub fn profile_toward(&self, u: f64, chuck_side: bool) -> f64 {
        if matches!(self.kind, ToolKind::Groove | ToolKind::Parting) && self.width_mm > 0.0 {
            return self.groove_profile(if chuck_side { -u.abs() } else { u.abs() });
        }
        if !matches!(self.kind, ToolKind::Turning | ToolKind::Boring) {
            return self.profile(u);
        }
        let (u, rho) = (u.abs(), self.tip_radius_mm);
        let (chuck_deg, face_deg) = match self.iso_shape {
            Some(IsoShape::R) => return if u <= rho { rho - (rho * rho - u * u).max(0.0).sqrt() } else { 1e6 },
            // A main edge leaning back from the radial (approach over 90) is taken as leaning
            // forward as much: it cuts a little more of a shoulder than the real insert would.
            Some(shape) => {
                let kr = shape.approach_deg();
                (if kr > 90.0 { 180.0 - kr } else { kr }, (180.0 - kr - shape.nose_angle_deg()).max(1.0))
            }
            None if self.tip.is_some() && rho > 0.0 => return self.profile(u),
            None => (85.0, 5.0),
        };
        // The edge's angle from the axis.
        let angle = if chuck_side { chuck_deg } else { face_deg }.to_radians();
        let u_t = rho * angle.sin();
        if u <= u_t {
            return rho - (rho * rho - u * u).max(0.0).sqrt();
        }
        rho * (1.0 - angle.cos()) + (u - u_t) * angle.tan()
    }

    /// Whether the spindle at `rpm` (signed: negative is M04) turns the wrong way for the tool's
    /// `hand` (a right-hand tool cuts with M03); never when the setup gives no hand.
    pub fn turns_wrong_way(&self, rpm: f64) -> bool {
        match self.hand {
            Some(Hand::Right) => rpm < 0.0,
            Some(Hand::Left) => rpm > 0.0,
            None => false,
        }
    }

    /// Where along Z from the programmed point a point of the tool's cutting end lies, mm: the
    /// middle of a grooving or parting tool's width (its reference corner may be rounded
    /// away), else the point itself. The rapids' crash check follows this point.
    pub fn edge_point_dz_mm(&self) -> f64 {
        if !(matches!(self.kind, ToolKind::Groove | ToolKind::Parting) && self.width_mm > 0.0) {
            return 0.0;
        }
        match self.reference {
            GrooveReference::Left => self.width_mm / 2.0,
            GrooveReference::Right => -self.width_mm / 2.0,
            GrooveReference::Centre => 0.0,
        }
    }

    /// A grooving or parting tool's end at signed axial offset `s` from the programmed point
    /// (+ toward the face): 0 on its flat, rising in its rounded corners, a wall (far above
    /// anything) beyond its width.
    fn groove_profile(&self, s: f64) -> f64 {
        let w = self.width_mm;
        let from = match self.reference {
            GrooveReference::Left => 0.0,
            GrooveReference::Right => -w,
            GrooveReference::Centre => -w / 2.0,
        };
        let (a, b) = (from, from + w);
        // A hair of slack so the corner cell on the grid is inside the tool.
        if s < a - 1e-9 || s > b + 1e-9 {
            return 1e6;
        }
        let rc = self.corner_radius_mm.clamp(0.0, w / 2.0);
        let e = (s - a).min(b - s).max(0.0);
        if e >= rc {
            0.0
        } else {
            rc - (rc * rc - (rc - e) * (rc - e)).max(0.0).sqrt()
        }
    }

    pub fn profile(&self, u: f64) -> f64 {
        let u = u.abs();
        if self.tip.is_some() && matches!(self.kind, ToolKind::Turning | ToolKind::Boring) && self.tip_radius_mm > 0.0 {
            let rho = self.tip_radius_mm;
            // Beyond the circle: far above anything, so it never cuts.
            return if u <= rho { rho - (rho * rho - u * u).sqrt() } else { 1e6 };
        }
        let half = (self.included_angle_deg / 2.0).to_radians();
        let slope = 1.0 / half.tan().max(1e-9); // radial per axial on a flank
        let flat = self.tip_flat_mm / 2.0;
        if u <= flat {
            return 0.0;
        }
        let u = u - flat;
        let rho = self.tip_radius_mm;
        if rho > 0.0 {
            // The nose arc meets the flanks where its tangent has the flank's slope.
            let u_t = rho * half.cos();
            if u <= u_t {
                return rho - (rho * rho - u * u).sqrt();
            }
            let r_t = rho - (rho * rho - u_t * u_t).sqrt();
            return r_t + (u - u_t) * slope;
        }
        u * slope
    }
}

/// The number of an M code as a setup key writes it (`"165"` or `"M165"`).
fn m_code_number(key: &str) -> Option<u32> {
    key.trim().trim_start_matches(['M', 'm']).parse().ok()
}

/// One `[machine] m_macro` entry: the M code and the programme number it calls.
pub fn m_macro_entry(code: &str, program: &str) -> Option<(u32, u32)> {
    let code = m_code_number(code)?;
    let digits = program.trim().trim_start_matches(['O', 'o']);
    let number: u32 = digits.parse().ok()?;
    let reserved = matches!(code, 0 | 1 | 2 | 30 | 98 | 99);
    (!reserved && (1..=9999).contains(&code) && (1..=99_999_999).contains(&number)).then_some((code, number))
}

impl MachineSetup {
    /// The machine's own M codes (`m_codes`) by number.
    pub fn own_m_codes(&self) -> impl Iterator<Item = u32> + '_ {
        self.m_codes.keys().filter_map(|c| m_code_number(c))
    }

    /// The M codes that call programmes, as (code, programme) pairs.
    pub fn m_macros(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        self.m_macro.iter().filter_map(|(c, p)| m_macro_entry(c, p))
    }
}

/// `[machine]`: its axes (each once), spindles, reference points and travel limits.
fn check_machine(m: &MachineSetup) -> Result<(), SetupError> {
    for (i, a) in m.axes.iter().enumerate() {
        a.check()?;
        // Each axis once (so at most six).
        if m.axes[..i].iter().any(|b| b.name() == a.name()) {
            return Err(SetupError(format!("machine.axes: {:?} is named twice; each axis once", a.name())));
        }
    }
    for (code, program) in &m.m_macro {
        let parsed = m_macro_entry(code, program);
        if parsed.is_none() {
            return Err(SetupError(format!(
                "machine.m_macro: {code} = {program:?}: an M code 1-9999 other than M00-M02, M30, M98, M99, calling a programme O1-O99999999 (\"O9832\")"
            )));
        }
    }
    for (code, what) in &m.m_codes {
        let n = m_code_number(code);
        if n.is_none_or(|n| n > 99_999_999) || what.len() > 200 {
            return Err(SetupError(format!("machine.m_codes: {code} = {what:?}: an M code number and what it does (at most 200 characters)")));
        }
    }
    if m.tool_change_s.is_some_and(|s| !(s.is_finite() && (0.0..=3600.0).contains(&s))) {
        return Err(SetupError("machine.tool_change_s: seconds from 0 to 3600".into()));
    }
    if m.spindle_p.len() > MAX_SPINDLES {
        return Err(SetupError(format!("machine.spindle_p: at most {} spindles", MAX_SPINDLES)));
    }
    if m.spindle_p.iter().enumerate().any(|(i, p)| m.spindle_p[..i].contains(p)) {
        return Err(SetupError("machine.spindle_p: each spindle's P once".into()));
    }
    for (name, p) in [("reference", m.reference), ("reference_2", m.reference_2), ("reference_3", m.reference_3), ("reference_4", m.reference_4)] {
        if p.is_some_and(|p| !point_ok(&p)) {
            return Err(SetupError(format!("machine.{name}: every coordinate must be a finite number of at most {MAX_MM} mm")));
        }
    }
    if let Some(l) = m.limits {
        for (axis, r) in ["x", "y", "z"].into_iter().zip(l.by_axis()) {
            if let Some([lo, hi]) = r {
                if !range_ok(lo, hi) {
                    return Err(SetupError(format!(
                        "machine.limits.{axis}_mm = [{}, {}]: give [min, max] with min less than max, finite, at most {MAX_MM} mm",
                        shown(lo),
                        shown(hi)
                    )));
                }
            }
        }
    }
    Ok(())
}

/// Lengths in a setup are at most 100 m.
const MAX_MM: f64 = 100_000.0;

/// A finite length of at most [`MAX_MM`].
fn length(v: f64) -> bool {
    v.is_finite() && v.abs() <= MAX_MM
}

/// A `[min, max]` of lengths, min below max.
fn range_ok(lo: f64, hi: f64) -> bool {
    length(lo) && length(hi) && lo < hi
}

/// A point whose given coordinates are lengths.
fn point_ok(p: &Point) -> bool {
    [p.x_mm, p.y_mm, p.z_mm].into_iter().flatten().all(length)
}

/// Why a setup cannot be used.
#[derive(Debug, Clone, PartialEq)]
pub struct SetupError(pub String);

impl std::fmt::Display for SetupError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl Setup {
    /// Read a setup from its TOML text.
    pub fn from_toml(text: &str) -> Result<Setup, SetupError> {
        let s: Setup = toml::from_str(text).map_err(|e| SetupError(e.to_string()))?;
        // Every value is checked: NaN or infinity would make the simulation answer wrongly and
        // silently.
        s.check_stock_and_tools()?;
        if let Some(m) = &s.machine {
            check_machine(m)?;
        }
        s.check_work_and_block()?;
        s.check_offsets()?;
        Ok(s)
    }

    /// The stock's and the tools' sizes.
    fn check_stock_and_tools(&self) -> Result<(), SetupError> {
        if let Some(b) = self.stock {
            if !(length(b.diameter_mm) && length(b.length_mm) && length(b.bore_mm) && length(b.front_z_mm)) {
                return Err(SetupError(format!("stock: every length must be a finite number of at most {MAX_MM} mm")));
            }
            if !(b.diameter_mm > 0.0 && b.length_mm > 0.0 && b.bore_mm >= 0.0 && b.bore_mm < b.diameter_mm) {
                return Err(SetupError("stock: diameter and length must be more than 0, the bore less than the diameter".into()));
            }
        }
        for t in &self.tools {
            let holder = t.holder.map_or([0.0, 0.0], |h| [h.diameter_mm, h.length_mm]);
            let lengths_ok = [
                t.tip_radius_mm,
                t.tip_flat_mm,
                t.width_mm,
                t.min_bore_mm,
                t.diameter_mm,
                t.corner_radius_mm,
                t.flute_length_mm,
                t.stick_out_mm,
                holder[0],
                holder[1],
            ]
            .into_iter()
            .all(|v| length(v) && v >= 0.0);
            let angles_ok = [t.included_angle_deg, t.point_angle_deg].into_iter().all(|a| a.is_finite() && a > 0.0 && a < 180.0);
            if !(lengths_ok && angles_ok) {
                return Err(SetupError(format!(
                    "tool {}: the included and point angles must be more than 0 and less than 180 degrees, every length (radius, flat, width, minimum bore, diameter, corner radius, flute length, stick-out, holder) finite, 0 or more",
                    t.number
                )));
            }
        }
        for t in &self.tools {
            if t.tip.is_some_and(|n| n > 9) {
                return Err(SetupError(format!("tool {}: tip is the imaginary tool nose number, 0 to 9", t.number)));
            }
        }
        Ok(())
    }

    /// The work offsets' points and the mill block's corners.
    fn check_work_and_block(&self) -> Result<(), SetupError> {
        if let Some(w) = &self.work {
            if w.g54_1.len() > ADDITIONAL_WORK_SYSTEMS {
                return Err(SetupError(format!("work.\"G54.1\": at most {ADDITIONAL_WORK_SYSTEMS} systems (P1-P{ADDITIONAL_WORK_SYSTEMS})")));
            }
            let names = ["external", "G54", "G55", "G56", "G57", "G58", "G59"];
            for (k, p) in w.all().enumerate() {
                if p.is_some_and(|p| !point_ok(&p)) {
                    let name = names.get(k).map_or_else(|| format!("\"G54.1\" P{}", k - 6), |n| n.to_string());
                    return Err(SetupError(format!("work.{name}: every coordinate must be a finite number of at most {MAX_MM} mm")));
                }
            }
        }
        if let Some(b) = self.block {
            for (k, axis) in ["x", "y", "z"].into_iter().enumerate() {
                let (lo, hi) = (b.min_mm[k], b.max_mm[k]);
                if !range_ok(lo, hi) {
                    return Err(SetupError(format!(
                        "block: {axis} from {} to {} mm: each corner's coordinate must be a finite number of at most {MAX_MM} mm, min_mm less than max_mm",
                        shown(lo),
                        shown(hi)
                    )));
                }
            }
        }
        Ok(())
    }

    /// The offset table: finite values, tips 0-9, numbers in range and each once.
    fn check_offsets(&self) -> Result<(), SetupError> {
        let mut seen = std::collections::BTreeSet::new();
        for o in &self.offsets {
            let values = [o.x_mm, o.y_mm, o.z_mm, o.wear_x_mm, o.wear_y_mm, o.wear_z_mm, o.radius_mm, o.wear_radius_mm, o.length_mm, o.wear_length_mm];
            if !values.into_iter().all(length) {
                return Err(SetupError(format!("offset {}: every value must be a finite number of at most {MAX_MM} mm", o.number)));
            }
            if o.tip > 9 {
                return Err(SetupError(format!("offset {}: tip is the imaginary tool nose number, 0 to 9", o.number)));
            }
            if o.number == 0 || o.number > MAX_OFFSET_NUMBER {
                return Err(SetupError(format!("offset {}: numbers run from 1 to {MAX_OFFSET_NUMBER} (0 is no offset)", o.number)));
            }
            if !seen.insert(o.number) {
                return Err(SetupError(format!("offset {} is given twice", o.number)));
            }
        }
        Ok(())
    }

    /// The offset table's entry `number`, if the setup gives it.
    pub fn offset(&self, number: u32) -> Option<&Offset> {
        self.offsets.iter().find(|o| o.number == number)
    }

    /// `--stock 60x80`: a 60 mm bar, 80 mm long, its face at Z0.
    pub fn parse_stock(text: &str) -> Result<Bar, SetupError> {
        let (d, l) = text.split_once(['x', 'X']).ok_or_else(|| SetupError(format!("--stock {text}: write DIAxLEN, e.g. 60x80")))?;
        let d: f64 = d.trim().parse().map_err(|_| SetupError(format!("--stock {text}: the diameter is not a number")))?;
        let l: f64 = l.trim().parse().map_err(|_| SetupError(format!("--stock {text}: the length is not a number")))?;
        if !(d > 0.0 && l > 0.0 && d.is_finite() && l.is_finite()) {
            return Err(SetupError(format!("--stock {text}: diameter and length must be more than 0")));
        }
        Ok(Bar { diameter_mm: d, length_mm: l, bore_mm: 0.0, front_z_mm: 0.0 })
    }

    /// A machining centre's `--stock XxYxZ`: a block X by Y by Z mm, its top at Z0 and its
    /// corner at the work zero, extending along +X, +Y and -Z.
    pub fn parse_block(text: &str) -> Result<Block, SetupError> {
        let sizes: Vec<&str> = text.split(['x', 'X']).collect();
        let bad = || SetupError(format!("--stock {text}: on a machining centre write XxYxZ, the block's sizes in mm, e.g. 100x80x30"));
        let [x, y, z] = sizes.as_slice() else { return Err(bad()) };
        let n = |s: &str| s.trim().parse::<f64>().ok().filter(|v| *v > 0.0 && length(*v));
        let (Some(x), Some(y), Some(z)) = (n(x), n(y), n(z)) else { return Err(bad()) };
        Ok(Block { min_mm: [0.0, 0.0, -z], max_mm: [x, y, 0.0] })
    }

    /// `--stock` for a machine of that kind: a bar (DIAxLEN) on a lathe, a block (XxYxZ) on a
    /// machining centre; it replaces the setup's.
    pub fn set_stock_text(&mut self, text: &str, lathe: bool) -> Result<(), SetupError> {
        if lathe {
            self.stock = Some(Setup::parse_stock(text)?);
        } else {
            self.block = Some(Setup::parse_block(text)?);
        }
        Ok(())
    }

    /// The tool of a T number, or the default threading insert.
    pub fn tool(&self, number: u32) -> Tool {
        self.tools.iter().find(|t| t.number == number).copied().unwrap_or_else(Tool::default_thread)
    }

    /// The tool of a T number on a machining centre, or the default drill (5 mm, 118 degrees).
    pub fn mill_tool(&self, number: u32) -> Tool {
        self.tools.iter().find(|t| t.number == number).copied().unwrap_or(Tool {
            kind: ToolKind::Drill,
            diameter_mm: 5.0,
            point_angle_deg: 118.0,
            ..Tool::default_thread()
        })
    }
}

/// The highest offset number a setup may give (FANUC 0i-T G10 P: up to 64 wear offsets;
/// kept wide for machines with more).
pub const MAX_OFFSET_NUMBER: u32 = 999;
