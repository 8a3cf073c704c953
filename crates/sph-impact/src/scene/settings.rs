//! The scene's `geometry`, `[output]` and `[diagnostics]` settings.

use serde::{Deserialize, Serialize};

/// The run's geometry (serialised as `"3d"`, `"3d-quarter"`, `"rz"`, `"plane"` or
/// `"1d"`). The bodies are always written in 3-D; the lower-dimensional geometries run a
/// section of them, and the outputs keep the 3-D convention (docs/scenes.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum GeometryKind {
    /// Full 3-D.
    #[default]
    #[serde(rename = "3d")]
    ThreeD,
    /// 3-D, the quarter x > 0, y > 0 between the reflecting planes x = 0 and y = 0: every
    /// body symmetric about the z axis, moving along it and placed as `rings` (each ring's
    /// points a multiple of 4, so the quarter is exact). A quarter of the particles and
    /// of the cost; every total in the outputs is the whole bodies' (4 × the quarter's;
    /// the x and y momenta are zero by symmetry).
    #[serde(rename = "3d-quarter")]
    ThreeDQuarter,
    /// Axisymmetric about z: every body a sphere or cylinder on the z axis, moving along
    /// it; the run has 2-D particles in the (r, z) half-plane, each a ring.
    #[serde(rename = "rz")]
    Rz,
    /// Plane strain: the bodies' section y = 0 extruded without end along y; the run has
    /// 2-D particles in (x, z), masses and totals per metre of depth (kg/m). Velocities
    /// have v_y = 0.
    #[serde(rename = "plane")]
    Plane,
    /// Uniaxial strain (1-D): the bodies' section on the z axis (x = y = 0) extruded
    /// without end in x and y, plates moving along z; the run has 1-D particles in z,
    /// masses and totals per square metre (kg/m²). Velocities have v_x = v_y = 0.
    #[serde(rename = "1d")]
    Line,
}

impl GeometryKind {
    /// The name the scene file uses.
    pub fn name(self) -> &'static str {
        match self {
            Self::ThreeD => "3d",
            Self::ThreeDQuarter => "3d-quarter",
            Self::Rz => "rz",
            Self::Plane => "plane",
            Self::Line => "1d",
        }
    }

    /// The bodies' measure each output total is per: "body" (3-D, quarter, RZ — the
    /// whole bodies), "m of depth" (plane) or "m² of area" (1-D).
    pub fn per(self) -> &'static str {
        match self {
            Self::ThreeD | Self::ThreeDQuarter | Self::Rz => "body",
            Self::Plane => "m of depth",
            Self::Line => "m² of area",
        }
    }

    /// The unit of the outputs' masses: kg, kg/m (plane strain) or kg/m² (1-D).
    pub fn mass_unit(self) -> &'static str {
        match self {
            Self::ThreeD | Self::ThreeDQuarter | Self::Rz => "kg",
            Self::Plane => "kg/m",
            Self::Line => "kg/m²",
        }
    }

    /// True for the sections (plane and 1-D), whose bodies are infinite and whose masses
    /// and totals are per unit depth or area.
    pub fn is_section(self) -> bool {
        matches!(self, Self::Plane | Self::Line)
    }
}

/// `[output]`: what a run writes and how often.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSettings {
    /// Simulated time between snapshots (s); default a tenth of the end time. A snapshot
    /// is also written at t = 0 and at the end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub snapshot_interval: Option<f64>,
    /// Run directory when the command line gives none; default `out/<scene file stem>`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub directory: Option<String>,
    /// Steps between rows of `history.csv` (default 1: every step).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub history_every: Option<u64>,
    /// The most snapshots a run may write (default [`DEFAULT_MAX_SNAPSHOTS`]): a
    /// snapshot interval that would write more is refused before the run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_snapshots: Option<u64>,
}

/// The default [`OutputSettings::max_snapshots`].
pub const DEFAULT_MAX_SNAPSHOTS: u64 = 10_000;

impl OutputSettings {
    /// The snapshot interval for end time `end_time` (s).
    pub fn interval(&self, end_time: f64) -> f64 {
        self.snapshot_interval.unwrap_or(end_time / 10.0)
    }
}

/// `[diagnostics]`: how ejecta, β and the crater are measured (docs/diagnostics.md).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiagnosticsSettings {
    /// The projectile body; default the first body.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub projectile: Option<String>,
    /// The target body; default every body but the projectile.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub target: Option<String>,
    /// The target's original top surface z (m); default the top of the target's shape.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub surface_z: Option<f64>,
    /// Impact speed U (m/s) for β and v_z/U; default the projectile's speed relative to
    /// the target.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub impact_speed: Option<f64>,
    /// Radial bin of the crater profile (m); default the target's finest spacing.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crater_bin: Option<f64>,
    /// Depth (m) a bin of the crater profile must exceed to count as crater (diameter,
    /// removed diameter); default one `crater_bin`. The default follows the grid; a fixed
    /// length reads every resolution of a convergence study by the same rule
    /// (docs/diagnostics.md §4).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crater_depth_threshold: Option<f64>,
    /// Height above the surface an ejecta particle must pass (m); default 0 (the study).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ejecta_tolerance: Option<f64>,
    /// Bin width of the ejecta distribution in v_z/U; default 0.02.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ejecta_bin: Option<f64>,
    /// Target material damaged above this is spall, counted as removed by the crater
    /// diameter (not the depth or bowl), in (0, 1]; default 0.9, 1 turns it off
    /// (docs/diagnostics.md §4.3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spall_damage: Option<f64>,
    /// Target material expanded below this fraction of its reference density is loose
    /// rubble, not crater wall (depth, bowl and removed diameter), in [0, 1); default 0.5
    /// (the solver's fragmentation threshold), 0 turns it off (docs/diagnostics.md §4.1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rubble_density: Option<f64>,
    /// Support radius H (m) of the kernel that reads the target's volume fraction on the
    /// impact axis for the axis depth; default n_target × the target's finest spacing
    /// (docs/diagnostics.md §4.4).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis_kernel_width: Option<f64>,
    /// Radius R (m) of the disc about the impact axis over which that volume fraction is
    /// averaged; default the kernel's H, 0 reads the axis line alone
    /// (docs/diagnostics.md §4.4).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis_disc_radius: Option<f64>,
}
