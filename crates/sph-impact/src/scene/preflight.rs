//! The one validation a run passes before it steps, shared by `sph-impact check`
//! ([`Scene::check_report`]) and `sph-impact run` (`run::run`), so that `check` rejects
//! exactly what `run` would reject before doing any work: the scene's own checks
//! ([`Scene::check`]), the end time, the placement (overlaps), each body's resolution,
//! mass and speed, the diagnostics' settings, and the output cadence.

use crate::scene::body::DEFAULT_MASS_TOLERANCE;
use crate::scene::error::{SceneError, SceneErrorKind, shown};
use crate::scene::settings::{DEFAULT_MAX_SNAPSHOTS, GeometryKind};
use crate::scene::{BodyInfo, DiagnosticSetup, PlacedBody, Scene};
use sph_core::glam::DVec3;

/// The fewest particles across a body ([`particles_across`]): below it the body is a
/// handful of points whose mass, shape and β mean nothing.
pub const MIN_PARTICLES_ACROSS: f64 = 3.0;

/// How many particle spacings across a body of `count` particles is: the diameter, in
/// spacings, of the ball that many particles fill (in 3-D, count = π/6 n³; a quarter
/// holds a fourth of the body), of the half-disc of rings in RZ (count = π/8 n²), of the
/// disc in plane strain (count = π/4 n²), and the count itself in 1-D.
pub fn particles_across(geometry: GeometryKind, count: usize) -> f64 {
    use std::f64::consts::PI;
    let n = count as f64;
    match geometry {
        GeometryKind::ThreeD => (6.0 * n / PI).cbrt(),
        GeometryKind::ThreeDQuarter => (24.0 * n / PI).cbrt(),
        GeometryKind::Rz => (8.0 * n / PI).sqrt(),
        GeometryKind::Plane => (4.0 * n / PI).sqrt(),
        GeometryKind::Line => n,
    }
}

/// The largest accepted body speed (m/s): 1000 km/s, far beyond any impact the
/// built-in materials' equations of state describe.
pub const MAX_SPEED: f64 = 1.0e6;

/// The most steps a run may be estimated to take (the study's case at 0.5 mm takes
/// about 3 × 10⁴): more means a CFL number, a modulus or a density far out of range.
pub const MAX_STEPS: f64 = 1.0e9;

/// The most finest-particle spacings the bodies may span along an axis.
pub const MAX_EXTENT_IN_SPACINGS: f64 = 1.0e12;

/// The bounding box of every placed particle (as 3-D points).
fn bounds(placed: &[PlacedBody]) -> (DVec3, DVec3) {
    let mut lo = DVec3::splat(f64::INFINITY);
    let mut hi = DVec3::splat(f64::NEG_INFINITY);
    for b in placed {
        for i in 0..b.particles.len() {
            let x = b.particles.point(i);
            lo = lo.min(x);
            hi = hi.max(x);
        }
    }
    (lo, hi)
}

/// What the validation found and a run starts from.
pub struct Preflight {
    /// The bodies, placed.
    pub placed: Vec<PlacedBody>,
    /// The diagnostics' roles and settings.
    pub setup: DiagnosticSetup,
    /// The simulated end time (s): the given one, else the scene's.
    pub end_time: f64,
    /// The estimated first time step (s): CFL × the smallest spacing / (the largest
    /// longitudinal wave speed + the impact speed).
    pub first_dt: f64,
}

impl Scene {
    /// Validates the scene for a run at `resolution_scale` to `end_time` (the scene's
    /// when `None`), placing its bodies; the error names the key (and the body).
    pub fn preflight(
        &self,
        resolution_scale: f64,
        end_time: Option<f64>,
    ) -> Result<Preflight, SceneError> {
        let end = end_time.unwrap_or(self.end_time);
        if !(end > 0.0 && end.is_finite()) {
            return Err(SceneError::general(SceneErrorKind::Invalid {
                value: end,
                reason: "the end time (--end-time) must be positive and finite (s)".into(),
            }));
        }
        // Body ids are 16-bit in the particles and the snapshots.
        if self.bodies.len() > usize::from(u16::MAX) {
            return Err(SceneError::at_key(
                "body",
                SceneErrorKind::Solver(format!(
                    "{} bodies: at most {} are supported",
                    self.bodies.len(),
                    u16::MAX
                )),
            ));
        }
        let placed = self.place(resolution_scale)?;
        let mut start = 0;
        for (i, b) in placed.iter().enumerate() {
            let spec = &self.bodies[i];
            let err = |key: &str, value: f64, reason: String| {
                self.locate(SceneError::in_body(
                    i,
                    &b.name,
                    key,
                    SceneErrorKind::Invalid { value, reason },
                ))
            };
            let info = BodyInfo::of(b, start);
            start = info.range.end;
            let across = particles_across(self.geometry, info.particles);
            if across < MIN_PARTICLES_ACROSS {
                return Err(err(
                    "placement",
                    info.particles as f64,
                    format!(
                        "{} particles resolve the body by {across:.1} across; at least \
                         {MIN_PARTICLES_ACROSS} are needed (refine its placement or raise \
                         --resolution-scale)",
                        info.particles
                    ),
                ));
            }
            let tolerance = spec.mass_tolerance.unwrap_or(DEFAULT_MASS_TOLERANCE);
            if !(tolerance >= 0.0 && tolerance.is_finite()) {
                return Err(err(
                    "mass_tolerance",
                    tolerance,
                    "must be finite and ≥ 0 (a fraction)".into(),
                ));
            }
            if let (Some(e), Some(exact)) = (info.mass_error(), info.exact_mass)
                && !(e.abs() <= tolerance)
            {
                return Err(err(
                    "mass_tolerance",
                    e,
                    format!(
                        "the placed particles weigh {:.4e} kg, {:+.1} % off ρV = {exact:.4e} kg, \
                         beyond the body's mass_tolerance {tolerance} (refine its placement, or \
                         raise mass_tolerance to accept it)",
                        info.mass,
                        100.0 * e
                    ),
                ));
            }
            // Component by component: the length of (0, 0, 1e300) overflows.
            let fastest = spec.velocity.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let speed = DVec3::from_array(spec.velocity).length();
            if !(fastest <= MAX_SPEED && speed <= MAX_SPEED) {
                return Err(err(
                    "velocity",
                    fastest.max(speed),
                    format!("the speed must be at most {MAX_SPEED:e} m/s"),
                ));
            }
        }
        let setup = self
            .diagnostic_setup(resolution_scale)
            .map_err(|e| self.locate(e))?;
        let dx = placed
            .iter()
            .map(|b| b.particles.spacing_range().0)
            .fold(f64::INFINITY, f64::min);
        let (lo, hi) = bounds(&placed);
        self.check_extent(lo, hi, dx)?;
        self.check_diagnostics(&setup, &placed, lo, hi)?;
        let c = placed
            .iter()
            .map(|b| b.material.longitudinal_wave_speed().unwrap_or(0.0))
            .fold(0.0, f64::max);
        let first_dt = self.scheme().cfl * dx / (c + setup.impact_speed);
        self.check_cadence(end, first_dt)?;
        let steps = end / first_dt;
        if !(steps <= MAX_STEPS) {
            return Err(self.locate(SceneError::at_key(
                "end_time",
                SceneErrorKind::Invalid {
                    value: end,
                    reason: format!(
                        "the run would take about {} steps of {first_dt:.3e} s (CFL × the \
                         finest spacing / (c_L {c:.4e} m/s + the impact speed)), more than \
                         {MAX_STEPS:e}; check the end time, the cfl, the materials' moduli \
                         and densities, and the spacing",
                        shown(steps.round())
                    ),
                },
            )));
        }
        Ok(Preflight {
            placed,
            setup,
            end_time: end,
            first_dt,
        })
    }

    /// The bodies may not span more than [`MAX_EXTENT_IN_SPACINGS`] finest spacings (the
    /// neighbour grid's cells would overflow).
    fn check_extent(&self, lo: DVec3, hi: DVec3, dx: f64) -> Result<(), SceneError> {
        let extent = (hi - lo).max_element();
        if !(extent <= MAX_EXTENT_IN_SPACINGS * dx) {
            return Err(self.locate(SceneError::at_key(
                "body",
                SceneErrorKind::Invalid {
                    value: extent,
                    reason: format!(
                        "the bodies span {} m, more than {MAX_EXTENT_IN_SPACINGS:e} times \
                         the finest particle spacing ({dx:.3e} m): too far apart for the \
                         neighbour search",
                        shown(extent)
                    ),
                },
            )));
        }
        Ok(())
    }

    /// The diagnostics' speeds and lengths must fit the scene: the impact speed at most
    /// [`MAX_SPEED`]; the crater bin, the axis kernel and disc and the ejecta tolerance at
    /// most the bodies' extent; the surface within one extent of them; and the crater
    /// profile of the target as placed at most `MAX_PROFILE_BINS` bins.
    fn check_diagnostics(
        &self,
        d: &DiagnosticSetup,
        placed: &[PlacedBody],
        lo: DVec3,
        hi: DVec3,
    ) -> Result<(), SceneError> {
        let invalid = |key: &str, value: f64, reason: String| {
            self.locate(SceneError::at_key(
                key,
                SceneErrorKind::Invalid { value, reason },
            ))
        };
        if !(d.impact_speed <= MAX_SPEED) {
            return Err(invalid(
                "diagnostics.impact_speed",
                d.impact_speed,
                format!("must be at most {MAX_SPEED:e} m/s"),
            ));
        }
        let extent = (hi - lo).max_element();
        for (key, value) in [
            ("diagnostics.crater_bin", d.crater_bin),
            ("diagnostics.axis_kernel_width", d.axis_kernel_width),
            ("diagnostics.axis_disc_radius", d.axis_disc_radius),
            ("diagnostics.ejecta_tolerance", d.ejecta_tolerance),
        ] {
            if !(value <= extent) {
                return Err(invalid(
                    key,
                    value,
                    format!("must be at most the bodies' extent, {} m", shown(extent)),
                ));
            }
        }
        // A single-body scene has no target, no surface and no crater.
        if d.targets.is_empty() {
            return Ok(());
        }
        if !(d.surface_z >= lo.z - extent && d.surface_z <= hi.z + extent) {
            return Err(invalid(
                "diagnostics.surface_z",
                d.surface_z,
                format!(
                    "must lie within one extent ({} m) of the bodies, z in [{}, {}] m",
                    shown(extent),
                    shown(lo.z),
                    shown(hi.z)
                ),
            ));
        }
        let radius = d
            .targets
            .iter()
            .flat_map(|&t| {
                let p = &placed[t].particles;
                (0..p.len()).map(|i| p.point(i).truncate().length())
            })
            .fold(0.0f64, f64::max);
        let bins = radius / d.crater_bin + 1.0;
        if !(bins <= sph_diagnostics::crater_profile::MAX_PROFILE_BINS as f64) {
            return Err(invalid(
                "diagnostics.crater_bin",
                d.crater_bin,
                format!(
                    "the target's radius {} m would take {} bins of the crater profile, more \
                     than {}; set a coarser crater_bin",
                    shown(radius),
                    shown(bins.floor()),
                    sph_diagnostics::crater_profile::MAX_PROFILE_BINS
                ),
            ));
        }
        Ok(())
    }

    /// The snapshot interval must not lie below the first time step, nor write more than
    /// `output.max_snapshots` snapshots to `end`.
    fn check_cadence(&self, end: f64, first_dt: f64) -> Result<(), SceneError> {
        let interval = self.output.interval(end);
        let max = self.output.max_snapshots.unwrap_or(DEFAULT_MAX_SNAPSHOTS);
        let key = if self.output.snapshot_interval.is_some() {
            "output.snapshot_interval"
        } else {
            "end_time"
        };
        let invalid = |key: &str, value: f64, reason: String| {
            self.locate(SceneError::at_key(
                key,
                SceneErrorKind::Invalid { value, reason },
            ))
        };
        if max == 0 {
            return Err(invalid(
                "output.max_snapshots",
                0.0,
                "must be at least 1".into(),
            ));
        }
        if first_dt.is_finite() && interval < first_dt {
            return Err(invalid(
                key,
                interval,
                format!(
                    "the snapshot interval lies below the estimated first time step \
                     {first_dt:.3e} s: every step would write a snapshot"
                ),
            ));
        }
        let count = (end / interval).ceil() + 1.0;
        if !(count <= max as f64) {
            return Err(invalid(
                key,
                interval,
                format!(
                    "a snapshot every {interval:e} s to {end:e} s writes {} snapshots, \
                     more than output.max_snapshots = {max}",
                    crate::scene::error::shown(count)
                ),
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ball of n spacings across holds π/6 n³ particles in 3-D (a fourth of that in a
    /// quarter), its half-disc of rings π/8 n², its disc π/4 n² in plane strain.
    #[test]
    fn particles_across_inverts_the_filled_ball() {
        use std::f64::consts::PI;
        let n: f64 = 12.0;
        let close = |g, count: f64| (particles_across(g, count.round() as usize) - n).abs() < 0.05;
        assert!(close(GeometryKind::ThreeD, PI / 6.0 * n.powi(3)));
        assert!(close(GeometryKind::ThreeDQuarter, PI / 24.0 * n.powi(3)));
        assert!(close(GeometryKind::Rz, PI / 8.0 * n * n));
        assert!(close(GeometryKind::Plane, PI / 4.0 * n * n));
        assert_eq!(particles_across(GeometryKind::Line, 12), 12.0);
        // Two particles are too few anywhere; a 2 mm RZ lattice of the study's 6 mm ball
        // (6 rings) is enough.
        for g in [
            GeometryKind::ThreeD,
            GeometryKind::ThreeDQuarter,
            GeometryKind::Rz,
            GeometryKind::Plane,
            GeometryKind::Line,
        ] {
            assert!(particles_across(g, 2) < MIN_PARTICLES_ACROSS, "{g:?}");
        }
        assert!(particles_across(GeometryKind::Rz, 6) >= MIN_PARTICLES_ACROSS);
    }
}
