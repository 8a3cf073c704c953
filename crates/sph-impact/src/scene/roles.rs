//! Which body is the projectile and which the target, and the numbers the impact
//! diagnostics need (surface, impact speed, bins), from `[diagnostics]` and its defaults.

use crate::scene::Scene;
use crate::scene::error::{SceneError, SceneErrorKind};
use serde::Serialize;
use sph_core::glam::DVec3;

/// The smallest accepted `diagnostics.crater_bin`, as a fraction of the finest particle
/// spacing.
pub const MIN_CRATER_BIN_FRACTION: f64 = 0.01;

/// The smallest accepted `diagnostics.ejecta_bin` (a fraction of the impact speed).
pub const MIN_EJECTA_BIN: f64 = 1e-4;

/// The resolved diagnostics settings of a scene.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DiagnosticSetup {
    /// Index of the projectile body.
    pub projectile: usize,
    /// Indices of the target bodies.
    pub targets: Vec<usize>,
    /// The target's original top surface z (m).
    pub surface_z: f64,
    /// Impact speed U (m/s); 0 when the projectile does not move relative to the target
    /// (then β is not defined and is reported as NaN).
    pub impact_speed: f64,
    /// Radial bin of the crater profile (m).
    pub crater_bin: f64,
    /// Depth a profile bin must exceed to be crater (m).
    pub crater_depth_threshold: f64,
    /// Ejecta height tolerance above the surface (m).
    pub ejecta_tolerance: f64,
    /// Bin width of the ejecta distribution in v_z/U.
    pub ejecta_bin: f64,
    /// Damage above which target material is spall for the crater diameter; `None` off.
    pub spall_damage: Option<f64>,
    /// Fraction of the target's reference density below which its material is rubble,
    /// not crater wall; `None` off.
    pub rubble_density: Option<f64>,
    /// Support radius of the axis depth's kernel (m).
    pub axis_kernel_width: f64,
    /// Radius of the disc the axis depth's volume fraction is averaged over (m; 0 the
    /// axis line).
    pub axis_disc_radius: f64,
}

impl DiagnosticSetup {
    /// Default of `[diagnostics] spall_damage`. 0.9 and 0.99 give the same diameters on
    /// the bundled basalt runs (docs/validation.md): the spall is fully fractured.
    pub const DEFAULT_SPALL_DAMAGE: f64 = 0.9;
    /// Default of `[diagnostics] rubble_density`: the density below which the solver
    /// fragments damaged rock (`fragment_density_ratio`). Loose rubble left in the crater
    /// would otherwise read as its floor: one such ring in the axis bin moved the 1 mm,
    /// 3.9 km/s depth from 14.9 to 11.3 mm (docs/validation.md).
    pub const DEFAULT_RUBBLE_DENSITY: f64 = 0.5;
}

impl Scene {
    /// The diagnostics settings with their defaults filled in, for particle spacings
    /// divided by `resolution_scale`.
    pub fn diagnostic_setup(&self, resolution_scale: f64) -> Result<DiagnosticSetup, SceneError> {
        let d = &self.diagnostics;
        let known = || {
            self.bodies
                .iter()
                .map(|b| b.name.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        };
        let find = |key: &str, name: &str| {
            self.bodies
                .iter()
                .position(|b| b.name == name)
                .ok_or_else(|| {
                    SceneError::at_key(
                        key,
                        SceneErrorKind::MissingBody {
                            name: name.to_owned(),
                            known: known(),
                        },
                    )
                })
        };
        let projectile = match &d.projectile {
            Some(n) => find("diagnostics.projectile", n)?,
            None => 0,
        };
        let targets: Vec<usize> = match &d.target {
            Some(n) => vec![find("diagnostics.target", n)?],
            None => (0..self.bodies.len())
                .filter(|&i| i != projectile)
                .collect(),
        };
        if targets.contains(&projectile) {
            return Err(SceneError::at_key(
                "diagnostics.target",
                SceneErrorKind::Syntax("the target must not be the projectile".into()),
            ));
        }
        let invalid = |key: &str, value: f64, reason: &str| {
            SceneError::at_key(
                key,
                SceneErrorKind::Invalid {
                    value,
                    reason: reason.to_owned(),
                },
            )
        };
        let surface_z = match d.surface_z {
            Some(z) if z.is_finite() => z,
            Some(z) => return Err(invalid("diagnostics.surface_z", z, "must be finite (m)")),
            None => targets
                .iter()
                .filter_map(|&t| self.bodies[t].shape.shape().ok()?.bounds())
                .map(|b| b.max.z)
                .fold(f64::NAN, f64::max),
        };
        let v = |i: usize| DVec3::from_array(self.bodies[i].velocity);
        let impact_speed = match d.impact_speed {
            Some(u) if u > 0.0 && u.is_finite() => u,
            Some(u) => {
                return Err(invalid(
                    "diagnostics.impact_speed",
                    u,
                    "must be positive (m/s)",
                ));
            }
            None => targets
                .first()
                .map_or(v(projectile).length(), |&t| (v(projectile) - v(t)).length()),
        };
        // Lengths in metres: positive when given, else a default from the spacings.
        let length = |key: &str, value: Option<f64>, default: f64| match value {
            None => Ok(default),
            Some(x) if x > 0.0 && x.is_finite() => Ok(x),
            Some(x) => Err(invalid(key, x, "must be positive (m)")),
        };
        let finest = |bodies: &[usize]| {
            bodies
                .iter()
                .map(|&b| self.bodies[b].placement.finest_spacing())
                .fold(f64::INFINITY, f64::min)
                / resolution_scale
        };
        // A single-body scene has no target: its lengths default to the body's own.
        let finest_target = if targets.is_empty() {
            finest(std::slice::from_ref(&projectile))
        } else {
            finest(&targets)
        };
        let finest_all = finest_target.min(finest(std::slice::from_ref(&projectile)));
        let crater_bin = length("diagnostics.crater_bin", d.crater_bin, finest_all)?;
        // A bin far finer than the particles holds none of them, and the profile's bins
        // would fill memory.
        if crater_bin < MIN_CRATER_BIN_FRACTION * finest_all {
            return Err(invalid(
                "diagnostics.crater_bin",
                crater_bin,
                &format!(
                    "must be at least {MIN_CRATER_BIN_FRACTION} × the finest particle \
                     spacing ({finest_all:.3e} m)"
                ),
            ));
        }
        // One bin by default: an untouched surface's particle-scale roughness is not
        // crater (sph_diagnostics::CraterOptions::depth_threshold).
        let crater_depth_threshold = length(
            "diagnostics.crater_depth_threshold",
            d.crater_depth_threshold,
            crater_bin,
        )?;
        // By default the finest target particles' own support radius at rest.
        let axis_kernel_width = length(
            "diagnostics.axis_kernel_width",
            d.axis_kernel_width,
            self.solver.scheme().n_target * finest_target,
        )?;
        // Lengths that may be zero: finite and ≥ 0 when given, else the default.
        let non_negative = |key: &str, value: Option<f64>, default: f64, reason: &str| match value
            .unwrap_or(default)
        {
            x if x >= 0.0 && x.is_finite() => Ok(x),
            x => Err(invalid(key, x, reason)),
        };
        // By default as wide as the kernel: a pit two spacings wide is read, one column
        // of particles is not (docs/diagnostics.md §4.4).
        let axis_disc_radius = non_negative(
            "diagnostics.axis_disc_radius",
            d.axis_disc_radius,
            axis_kernel_width,
            "must be ≥ 0 (m; 0 reads the axis line alone)",
        )?;
        let ejecta_tolerance = non_negative(
            "diagnostics.ejecta_tolerance",
            d.ejecta_tolerance,
            0.0,
            "must be ≥ 0 (m)",
        )?;
        let ejecta_bin = d.ejecta_bin.unwrap_or(0.02);
        if !(MIN_EJECTA_BIN..=1.0).contains(&ejecta_bin) {
            return Err(invalid(
                "diagnostics.ejecta_bin",
                ejecta_bin,
                &format!("must be in [{MIN_EJECTA_BIN}, 1] (a fraction of the impact speed)"),
            ));
        }
        // Both are fractions in (0, 1) with one end of the range turning them off.
        let fraction =
            |key: &str, value: Option<f64>, default: f64, off: f64, reason: &str| match value {
                None => Ok(Some(default)),
                Some(x) if x == off => Ok(None),
                Some(x) if x > 0.0 && x < 1.0 => Ok(Some(x)),
                Some(x) => Err(invalid(key, x, reason)),
            };
        let spall_damage = fraction(
            "diagnostics.spall_damage",
            d.spall_damage,
            DiagnosticSetup::DEFAULT_SPALL_DAMAGE,
            1.0,
            "must be in (0, 1] (1 turns the spall count off)",
        )?;
        let rubble_density = fraction(
            "diagnostics.rubble_density",
            d.rubble_density,
            DiagnosticSetup::DEFAULT_RUBBLE_DENSITY,
            0.0,
            "must be in [0, 1) (0 turns the rubble cut off)",
        )?;
        Ok(DiagnosticSetup {
            projectile,
            targets,
            surface_z,
            impact_speed,
            crater_bin,
            crater_depth_threshold,
            ejecta_tolerance,
            ejecta_bin,
            spall_damage,
            rubble_density,
            axis_kernel_width,
            axis_disc_radius,
        })
    }
}
