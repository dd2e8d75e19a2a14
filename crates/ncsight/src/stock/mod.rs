//! Material removal (issue 7): the job setup (stock and tools), the lathe stock as a cylindrical
//! height field cut by the motion stream with the exact spindle angle of every thread record,
//! and the measurement of the thread that results.

pub mod lathe;
pub mod measure;
pub mod mesh;
pub mod mill;
pub mod section;
pub mod standard;
pub mod survey;

pub use lathe::{Finding, Place};

pub use crate::setup::{Bar, Setup, SetupError, Tool, ToolKind};

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
