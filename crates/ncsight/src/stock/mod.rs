//! Material removal (issue 7): the job setup (stock and tools), the lathe stock as a cylindrical
//! height field cut by the motion stream with the exact spindle angle of every thread record,
//! and the measurement of the thread that results.

pub mod lathe;
pub mod measure;
pub mod mill;
pub mod standard;

pub use lathe::{Finding, Place};

use serde::Deserialize;

/// The stock and the tools of a job (`--setup FILE`, TOML).
#[derive(Debug, Clone, PartialEq, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Setup {
    pub stock: Option<Bar>,
    /// A block on a machining centre (drilling cycles).
    pub block: Option<mill::Block>,
    #[serde(default, rename = "tool")]
    pub tools: Vec<Tool>,
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
    /// Tip (nose) radius, mm.
    #[serde(default)]
    pub tip_radius_mm: f64,
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
            tip_flat_mm: 0.0,
            internal: false,
            diameter_mm: 0.0,
            point_angle_deg: 118.0,
        }
    }

    /// How far the cut surface lies from the tip's radius at axial distance `u` from the tip
    /// (the edge profile): flat, then the nose radius, then the flanks at half the included
    /// angle. `None` beyond the tool's reach is never returned: the flanks go on.
    pub fn profile(&self, u: f64) -> f64 {
        let u = u.abs();
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
        // silently. Lengths are at most 100 m.
        const MAX_MM: f64 = 100_000.0;
        let length = |v: f64| v.is_finite() && v.abs() <= MAX_MM;
        if let Some(b) = s.stock {
            if !(length(b.diameter_mm) && length(b.length_mm) && length(b.bore_mm) && length(b.front_z_mm)) {
                return Err(SetupError(format!("stock: every length must be a finite number of at most {MAX_MM} mm")));
            }
            if !(b.diameter_mm > 0.0 && b.length_mm > 0.0 && b.bore_mm >= 0.0 && b.bore_mm < b.diameter_mm) {
                return Err(SetupError("stock: diameter and length must be more than 0, the bore less than the diameter".into()));
            }
        }
        for t in &s.tools {
            let lengths_ok = [t.tip_radius_mm, t.tip_flat_mm, t.diameter_mm].into_iter().all(|v| length(v) && v >= 0.0);
            let angles_ok = [t.included_angle_deg, t.point_angle_deg].into_iter().all(|a| a.is_finite() && a > 0.0 && a < 180.0);
            if !(lengths_ok && angles_ok) {
                return Err(SetupError(format!(
                    "tool {}: the included and point angles must be more than 0 and less than 180 degrees, the radius, flat and diameter finite, 0 or more",
                    t.number
                )));
            }
        }
        Ok(s)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn setup_from_toml() {
        let s = Setup::from_toml(
            "[stock]\ndiameter_mm = 60\nlength_mm = 80\n\n[[tool]]\nnumber = 1\nincluded_angle_deg = 60\ntip_radius_mm = 0.2\n\n[[tool]]\nnumber = 2\ninternal = true\n",
        )
        .unwrap();
        assert_eq!(s.stock.unwrap().diameter_mm, 60.0);
        assert_eq!(s.tool(1).tip_radius_mm, 0.2);
        assert!(s.tool(2).internal);
        assert_eq!(s.tool(9), Tool::default_thread());
        assert!(Setup::from_toml("[stock]\ndiameter_mm = 60\n").is_err());
        assert!(Setup::from_toml("[stok]\n").is_err());
        assert_eq!(Setup::parse_stock("60x80").unwrap().length_mm, 80.0);
        assert!(Setup::parse_stock("60").is_err());
    }

    #[test]
    fn tool_profiles() {
        let sharp = Tool::default_thread();
        // 60 degrees: 1 mm off the tip axially is 1 / tan 30 = 1.732 mm radially.
        assert!((sharp.profile(1.0) - 3f64.sqrt()).abs() < 1e-12);
        let flat = Tool { tip_flat_mm: 0.4, ..sharp };
        assert_eq!(flat.profile(0.2), 0.0);
        assert!((flat.profile(1.2) - 3f64.sqrt()).abs() < 1e-12);
        let round = Tool { tip_radius_mm: 0.5, ..sharp };
        assert_eq!(round.profile(0.0), 0.0);
        // Past the nose, parallel to the sharp flank.
        let d = round.profile(3.0) - round.profile(2.0);
        assert!((d - 3f64.sqrt()).abs() < 1e-9);
    }
}
