//! The modal state a controller carries from block to block. It is a plain value: the
//! interpreter works on a copy and commits it only when the whole block is valid.

use crate::motion::{Plane, Vec3};
use crate::profile::{MachineKind, Profile};

/// Group 01 motion in force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Motion {
    Rapid,
    Linear,
    ArcCw,
    ArcCcw,
}

/// Spindle rotation commanded by M03/M04/M05.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpindleDir {
    Stopped,
    /// M03: the spindle's positive direction.
    Positive,
    /// M04.
    Negative,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Modal {
    /// Current position, programme coordinates, mm, X as a radius.
    pub pos: Vec3,
    pub motion: Motion,
    pub plane: Plane,
    /// G91 on mills. Lathes use U/W instead and keep this false.
    pub incremental: bool,
    /// G20.
    pub inch: bool,
    /// G99 (lathe) / G95 (mill): feed per revolution.
    pub per_rev: bool,
    /// G96.
    pub css: bool,
    pub spindle: SpindleDir,
    /// Last S word: rpm (G97) or m/min (G96).
    pub s_word: f64,
    /// G50 S: the spindle speed clamp, rpm.
    pub rpm_clamp: Option<f64>,
    /// M14 (position / CS mode) on servo-spindle lathes.
    pub spindle_position_mode: bool,
    /// Last F word converted to mm (per minute or per revolution by `per_rev`).
    pub feed: Option<f64>,
    /// Tool in the spindle / turret.
    pub tool: u32,
    /// G98 (return to the initial level) on mills.
    pub return_initial: bool,
    /// Tool radius compensation requested (not simulated: the programmed path is shown).
    pub radius_comp: bool,
    /// M02/M30 reached.
    pub ended: bool,
}

impl Modal {
    /// Power-on state of a profile.
    pub fn power_on(profile: &Profile) -> Modal {
        Modal {
            pos: Vec3::default(),
            motion: Motion::Rapid,
            plane: if profile.kind == MachineKind::Lathe { Plane::ZX } else { Plane::XY },
            incremental: false,
            inch: false,
            per_rev: profile.power_on_per_rev,
            css: false,
            spindle: SpindleDir::Stopped,
            s_word: 0.0,
            rpm_clamp: None,
            spindle_position_mode: false,
            feed: None,
            tool: 0,
            return_initial: true,
            radius_comp: false,
            ended: false,
        }
    }

    /// Spindle speed in rpm at a given diameter (G96 needs it), signed by direction; 0 if
    /// stopped.
    pub fn rpm_at(&self, diameter_mm: f64, max_rpm: f64) -> f64 {
        let sign = match self.spindle {
            SpindleDir::Stopped => return 0.0,
            SpindleDir::Positive => 1.0,
            SpindleDir::Negative => -1.0,
        };
        // G50 S clamps the speed that G96 computes (TDi help G96/97).
        let rpm = if self.css {
            let clamp = self.rpm_clamp.unwrap_or(max_rpm).min(max_rpm);
            let d = diameter_mm.abs();
            if d < 1e-9 { clamp } else { (self.s_word * 1000.0 / (std::f64::consts::PI * d)).min(clamp) }
        } else {
            self.s_word.min(max_rpm)
        };
        sign * rpm
    }
}
