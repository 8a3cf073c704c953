//! The scene's `geometry`, `[output]` and `[diagnostics]` settings.

use serde::{Deserialize, Serialize};

/// The run's geometry (serialised as `"3d"`, `"3d-quarter"` or `"rz"`).
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
}

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
