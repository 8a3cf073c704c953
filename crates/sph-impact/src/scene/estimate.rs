//! What `sph-impact check` reports: per body the particle count, mass and exact mass
//! ρ·V, and estimates of the first time step, the steps to the end time, the runtime and
//! the memory.
//!
//! The estimates are stated, not measured:
//!
//! - **first dt** = λ_CFL · Δx_min / (c_L,max + U): the solver's CFL vote (paper §2.5)
//!   with the smallest spacing, the largest longitudinal wave speed c_L = √((K + 4G/3)/ρ0)
//!   of the materials at rest, and the impact speed U as the approach speed;
//! - **steps** = end time / first dt (the step shrinks when shocks compress and heat the
//!   material, so this is a lower bound);
//! - **runtime** = steps × 2 derivative evaluations (RK2) × particles / (rate × cores),
//!   a lower bound like the steps it is made from,
//!   with the rate [`ASSUMED_EVALUATIONS_PER_CORE_SOLID`] for 3-D scenes with strength and
//!   [`ASSUMED_EVALUATIONS_PER_CORE_FLUID`] otherwise (docs/performance.md); for RZ and
//!   plane-strain scenes those rates × [`RZ_RATE_FACTOR`], the 3-D neighbour count over
//!   the 2-D one, for 1-D scenes × [`LINE_RATE_FACTOR`];
//! - **memory** = particles × [`ASSUMED_BYTES_PER_PARTICLE`] (the 3-D figure, an upper
//!   bound for RZ, plane and 1-D).

use crate::scene::Scene;
use crate::scene::build::BodyInfo;
use crate::scene::error::SceneError;
use crate::scene::settings::GeometryKind;
use serde::Serialize;

/// Derivative evaluations per second per core assumed for a solid scene: the scenes
/// bench's 3-D basalt impact at A_res 1 mm (the bundled `basalt_3.9kms.toml`, full solid
/// physics, its Verlet list) ran 8.96e4–9.19e4 particle-steps/s per core on two threads
/// and 9.28e4–9.48e4 on one, two evaluations each (docs/performance.md, "The pair
/// passes' blocks handed out one at a time"): 1.8e5, the two-thread figure rounded down.
pub const ASSUMED_EVALUATIONS_PER_CORE_SOLID: f64 = 1.8e5;

/// Derivative evaluations per second per core assumed for a fluid scene: the 3-D Sedov
/// bench with the default continuity density, 1.494e5 on one thread and 1.444e5 per core
/// on two (docs/performance.md, "Solver throughput (sph-impact, 3-D Sedov)"): 1.4e5.
pub const ASSUMED_EVALUATIONS_PER_CORE_FLUID: f64 = 1.4e5;

/// An RZ particle costs less than a 3-D one by the ratio of neighbour counts in the
/// support, (4π/3) n³ / (π n²) = 4n/3 for n = 2.5 spacings per support radius (65.4
/// against 19.6 neighbours): the rate assumed for RZ scenes is the 3-D one × this. An
/// assumption (the pair loop dominates the cost), checked against the RZ basalt scene in
/// docs/scenes.md.
pub const RZ_RATE_FACTOR: f64 = 4.0 * 2.5 / 3.0;

/// A 1-D particle costs less than a 3-D one by the ratio of neighbour counts,
/// (4π/3) n³ / (2n) = (2π/3) n² for n = 2.5 (65.4 against 5): the rate assumed for 1-D
/// scenes is the 3-D one × this (plane-strain scenes use [`RZ_RATE_FACTOR`], the same
/// 2-D neighbour count). An assumption, like [`RZ_RATE_FACTOR`].
pub const LINE_RATE_FACTOR: f64 = 2.0 * std::f64::consts::PI / 3.0 * 2.5 * 2.5;

/// Memory per particle assumed (bytes): the peak resident growth per particle of the
/// scenes bench's 3-D basalt impact at A_res 1 mm, 1 149 bytes rounded up (its set-up
/// included: the placement's scratch; the steps' own live-heap peak is 978 bytes: the
/// step's start and midpoint states, the Verlet list at ≈ 66 neighbours, the pair passes'
/// extended arrays; docs/performance.md, "The pair passes' blocks handed out one at a
/// time").
pub const ASSUMED_BYTES_PER_PARTICLE: f64 = 1150.0;

/// One body in the check report.
#[derive(Clone, Debug, Serialize)]
pub struct BodyReport {
    /// The body's name.
    pub name: String,
    /// Its material's name.
    pub material: String,
    /// Number of particles.
    pub particles: usize,
    /// Σ m (kg).
    pub mass_kg: f64,
    /// ρ·V of the shape (kg), when known.
    pub exact_mass_kg: Option<f64>,
    /// Σm/(ρV) − 1.
    pub mass_error: Option<f64>,
    /// Finest particle spacing (m).
    pub min_spacing_m: f64,
    /// Coarsest particle spacing (m).
    pub max_spacing_m: f64,
    /// Longitudinal wave speed at rest c_L (m/s).
    pub wave_speed_m_s: f64,
    /// With Benz–Asphaug damage: the number of 3-D particles the flaws are dealt over
    /// (the particle count in 3-D, Σ round(2πr/Δ) over the rings in RZ); else `None`.
    pub flaws_dealt_over: Option<usize>,
}

/// The report of `sph-impact check`.
#[derive(Clone, Debug, Serialize)]
pub struct CheckReport {
    /// The scene file (or `"<builder>"`).
    pub scene: String,
    /// `"3d"` or `"rz"` (then particles are rings and masses the whole rings').
    pub geometry: GeometryKind,
    /// Per body.
    pub bodies: Vec<BodyReport>,
    /// All particles.
    pub particles: usize,
    /// Resolution scale used (spacings divided by it).
    pub resolution_scale: f64,
    /// Estimated first time step (s).
    pub first_dt_s: f64,
    /// Estimated number of steps to the end time.
    pub steps: f64,
    /// End time (s).
    pub end_time_s: f64,
    /// Threads assumed for the runtime.
    pub threads: usize,
    /// Rate assumed (derivative evaluations per second per core).
    pub assumed_rate_per_core: f64,
    /// Estimated wall time (s).
    pub runtime_s: f64,
    /// Estimated memory (bytes).
    pub memory_bytes: f64,
    /// Wall time of the placement itself (s).
    pub placement_s: f64,
}

impl Scene {
    /// Places the bodies and estimates the run; `end_time` overrides the scene's.
    pub fn check_report(
        &self,
        resolution_scale: f64,
        threads: usize,
        end_time: Option<f64>,
    ) -> Result<CheckReport, SceneError> {
        let t0 = std::time::Instant::now();
        // The run's own validation: what it rejects, `check` rejects.
        let super::Preflight {
            placed,
            end_time: end,
            first_dt,
            ..
        } = self.preflight(resolution_scale, end_time)?;
        let placement_s = t0.elapsed().as_secs_f64();
        let mut start = 0;
        let mut bodies = Vec::new();
        for b in &placed {
            let info = BodyInfo::of(b, start);
            start = info.range.end;
            bodies.push(BodyReport {
                name: info.name.clone(),
                material: info.material_name.clone(),
                particles: info.particles,
                mass_kg: info.mass,
                exact_mass_kg: info.exact_mass,
                mass_error: info.mass_error(),
                min_spacing_m: info.spacing.0,
                max_spacing_m: info.spacing.1,
                wave_speed_m_s: b.material.longitudinal_wave_speed().unwrap_or(0.0),
                flaws_dealt_over: matches!(
                    b.material.damage,
                    crate::materials::DamageSpec::BenzAsphaug { .. }
                )
                .then(|| match self.solver.flaw_dealing() {
                    crate::scene::FlawDealing::ThreeDCount => b.particles.stands_for(),
                    crate::scene::FlawDealing::BodyCount => b.particles.len(),
                }),
            });
        }
        let steps = (end / first_dt).ceil();
        let solid = placed.iter().any(|b| !b.material.is_fluid());
        let rate = if solid {
            ASSUMED_EVALUATIONS_PER_CORE_SOLID
        } else {
            ASSUMED_EVALUATIONS_PER_CORE_FLUID
        } * match self.geometry {
            GeometryKind::ThreeD | GeometryKind::ThreeDQuarter => 1.0,
            GeometryKind::Rz | GeometryKind::Plane => RZ_RATE_FACTOR,
            GeometryKind::Line => LINE_RATE_FACTOR,
        };
        let threads = threads.max(1);
        Ok(CheckReport {
            scene: self.origin().unwrap_or("<builder>").to_owned(),
            geometry: self.geometry,
            particles: start,
            bodies,
            resolution_scale,
            first_dt_s: first_dt,
            steps,
            end_time_s: end,
            threads,
            assumed_rate_per_core: rate,
            runtime_s: steps * 2.0 * start as f64 / (rate * threads as f64),
            memory_bytes: start as f64 * ASSUMED_BYTES_PER_PARTICLE,
            placement_s,
        })
    }
}

impl CheckReport {
    /// The report as text, one fact per line.
    pub fn to_text(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        // The path as given, its control characters escaped (names have none: a scene
        // with them is refused).
        let _ = writeln!(
            s,
            "scene {} (resolution scale {})",
            crate::input::printable(&self.scene),
            self.resolution_scale
        );
        let geometry = match self.geometry {
            GeometryKind::ThreeD => None,
            GeometryKind::Rz => {
                Some("RZ (axisymmetric): particles are rings, masses the whole rings'")
            }
            GeometryKind::ThreeDQuarter => Some(
                "3-D quarter (x > 0, y > 0): particles of the quarter, masses the whole bodies'",
            ),
            GeometryKind::Plane => Some(
                "plane strain (section y = 0): masses per metre of depth (the \"kg\" below are kg/m)",
            ),
            GeometryKind::Line => Some(
                "1-D (section on the z axis): masses per square metre (the \"kg\" below are kg/m²)",
            ),
        };
        if let Some(what) = geometry {
            let _ = writeln!(s, "geometry        {what}");
        }
        for b in &self.bodies {
            let _ = writeln!(s, "body \"{}\" ({})", b.name, b.material);
            let _ = writeln!(s, "  particles     {}", b.particles);
            let _ = writeln!(s, "  mass          {:.6e} kg", b.mass_kg);
            match (b.exact_mass_kg, b.mass_error) {
                (Some(m), Some(e)) => {
                    let _ = writeln!(s, "  exact mass ρV {m:.6e} kg (error {e:+.2e})");
                }
                _ => {
                    let _ = writeln!(
                        s,
                        "  exact mass ρV unknown (the shape has no closed-form volume)"
                    );
                }
            }
            let _ = writeln!(
                s,
                "  spacing       {:.4} … {:.4} mm; c_L {:.0} m/s",
                b.min_spacing_m * 1e3,
                b.max_spacing_m * 1e3,
                b.wave_speed_m_s
            );
            if let Some(n) = b.flaws_dealt_over {
                let body = if self.geometry.is_section() {
                    "a 3-D body of cubes of their spacing"
                } else {
                    "the 3-D body"
                };
                let _ = writeln!(
                    s,
                    "  flaws         Benz–Asphaug, dealt over {n} particles of {body}"
                );
            }
        }
        let _ = writeln!(s, "particles       {}", self.particles);
        let _ = writeln!(
            s,
            "first dt        {:.3e} s (CFL × smallest spacing / (c_L + impact speed))",
            self.first_dt_s
        );
        let _ = writeln!(
            s,
            "steps           ≥ {:.0} to t = {:.3e} s",
            self.steps, self.end_time_s
        );
        let _ = writeln!(
            s,
            "runtime         ≥ {} on {} thread(s) (from the steps' lower bound; assumed {:.2e} derivative evaluations/s/core, 2 per RK2 step)",
            human_seconds(self.runtime_s),
            self.threads,
            self.assumed_rate_per_core
        );
        let _ = writeln!(
            s,
            "memory          ≈ {:.2} GB (estimate: assumed {:.0} bytes/particle)",
            self.memory_bytes / 1e9,
            ASSUMED_BYTES_PER_PARTICLE
        );
        let _ = writeln!(s, "placement took  {:.2} s", self.placement_s);
        s
    }
}

/// Seconds as "12 s", "3.4 min", "5.6 h" or "2.1 d".
pub(crate) fn human_seconds(s: f64) -> String {
    if !s.is_finite() {
        "?".into()
    } else if s < 120.0 {
        format!("{s:.0} s")
    } else if s < 7200.0 {
        format!("{:.1} min", s / 60.0)
    } else if s < 172_800.0 {
        format!("{:.1} h", s / 3600.0)
    } else {
        format!("{:.1} d", s / 86_400.0)
    }
}
