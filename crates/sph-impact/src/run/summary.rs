//! `summary.json`: the final diagnostics and the run's cost, with the scene as parsed.

use crate::run::measure::BetaMeasure;
use crate::scene::{BodyInfo, GeometryKind, SceneDimension, SimOf};
use crate::{DamageEvents, PhaseTimes, SchemeConfig};
use serde::Serialize;
use sph_diagnostics::{BodyDamage, EjectaBin, PhaseFractions};

/// Mass, momentum and energy totals of the whole bodies (in RZ 2π × the solver's totals
/// per radian; per metre of depth in plane strain, per square metre in 1-D; momentum in the scene's frame, (p_r, 0, p_z) in RZ, where p_r is the sum of
/// the rings' radial momenta, not a net momentum).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Totals {
    /// Σ m (kg).
    pub mass: f64,
    /// Σ m v (kg·m/s).
    pub momentum: [f64; 3],
    /// Σ ½ m v² (J).
    pub kinetic: f64,
    /// Σ m e (J).
    pub internal: f64,
}

impl Totals {
    /// The totals of a simulation's current state, of the whole bodies: the modelled
    /// part's times `copies` (4 for a 3-D quarter model, else 1) and the dimension's
    /// factor. With copies > 1 the x and y momenta are zero by symmetry.
    pub(crate) fn of<D: SceneDimension>(sim: &SimOf<D>, copies: f64) -> Self {
        let c = sim.conserved();
        let f = D::BODY_FACTOR * copies;
        let mut momentum = D::to_scene(c.momentum).map(|p| f * p);
        if copies > 1.0 {
            momentum[0] = 0.0;
            momentum[1] = 0.0;
        }
        Self {
            mass: f * c.mass,
            momentum,
            kinetic: f * c.kinetic,
            internal: f * c.internal,
        }
    }

    /// Kinetic + internal (J).
    pub fn energy(&self) -> f64 {
        self.kinetic + self.internal
    }
}

/// Damage of one body at the end.
#[derive(Clone, Debug, Serialize)]
pub struct BodyDamageSummary {
    /// The body.
    pub body: String,
    /// Its mass (kg).
    pub mass_kg: f64,
    /// Mass-weighted mean damage.
    pub mean_damage: f64,
    /// Mass with D ≥ 0.99 (kg).
    pub fully_damaged_mass_kg: f64,
}

impl BodyDamageSummary {
    pub(crate) fn of(d: &BodyDamage, bodies: &[BodyInfo]) -> Self {
        Self {
            body: bodies
                .get(d.body as usize)
                .map_or_else(|| d.body.to_string(), |b| b.name.clone()),
            mass_kg: d.mass,
            mean_damage: d.mean_damage,
            fully_damaged_mass_kg: d.fully_damaged_mass,
        }
    }
}

/// Everything `summary.json` holds (SI units; NaN is written as null).
#[derive(Clone, Debug, Serialize)]
pub struct RunSummary {
    /// False for a run stopped on request (SIGINT, SIGTERM) before its end time: its
    /// numbers are those of the state at `time_reached_s`, and it can be continued
    /// from its checkpoint with `--resume`.
    pub complete: bool,
    /// The simulated time of the state measured (s): the end time for a complete run.
    pub time_reached_s: f64,
    /// `"3d"`, `"3d-quarter"`, `"rz"`, `"plane"` or `"1d"`.
    pub geometry: GeometryKind,
    /// What every mass, momentum and energy (and the ejecta masses) is of: `"body"` (the
    /// whole bodies), `"m of depth"` (plane strain: kg/m, J/m) or `"m² of area"` (1-D:
    /// kg/m², J/m²). β, speeds and lengths are the same in every geometry.
    pub totals_per: &'static str,
    /// Crater diameter including the spall zone (m).
    pub crater_diameter_m: f64,
    /// Diameter of the removed material alone, spall still in place counting as
    /// surface (m).
    pub crater_diameter_removed_m: f64,
    /// Diameter of the central bowl (m).
    pub bowl_diameter_m: f64,
    /// Crater depth (m).
    pub crater_depth_m: f64,
    /// Crater depth on the axis from the target's volume fraction (m;
    /// docs/diagnostics.md §4.4).
    pub crater_axis_depth_m: f64,
    /// Support radius of the kernel that reads that volume fraction (m).
    pub crater_axis_kernel_width_m: f64,
    /// Radius of the disc about the axis it is averaged over (m; 0 the axis line).
    pub crater_axis_disc_radius_m: f64,
    /// Highest rim above the surface (m).
    pub rim_height_m: f64,
    /// β = 1 + P_ej/P_imp.
    pub beta: f64,
    /// β from the target's momentum change (cross-check).
    pub beta_target: f64,
    /// β as a ballistic pendulum (the experiment) sees it: escaping projectile debris
    /// (above the surface, rising) is not part of the target, so
    /// β = 1 + (P_ej + P_esc)/P_imp (docs/diagnostics.md §3).
    pub beta_pendulum: f64,
    /// β from the ejecta no longer touching the target (docs/diagnostics.md §3.1): it
    /// rises toward `beta` as the ejecta separate, and equals it once all fly free.
    pub beta_detached: f64,
    /// (β(t_end) − β(t_end/2))/β(t_end) from `history.csv`: how far β still moved over
    /// the run's second half (`run::beta_change_last_half`); near zero once it has
    /// settled.
    pub beta_change_last_half: f64,
    /// Ejecta mass (kg).
    pub ejecta_mass_kg: f64,
    /// Ejecta axial momentum (kg·m/s).
    pub ejecta_momentum_z_kg_m_s: f64,
    /// Projectile mass (kg).
    pub projectile_mass_kg: f64,
    /// Impact speed (m/s).
    pub impact_speed_m_s: f64,
    /// Particles (rings in RZ).
    pub particles: usize,
    /// Steps taken.
    pub steps: u64,
    /// Simulated end time (s).
    pub end_time_s: f64,
    /// Wall time of the run, set-up and output included (s).
    pub wall_time_s: f64,
    /// Particles × steps / wall time of the stepping.
    pub particle_steps_per_s: f64,
    /// Mean number of neighbours a particle's row listed, over every derivative
    /// evaluation of the run (ghosts of walls included).
    pub neighbours_per_particle: f64,
    /// Worker threads.
    pub threads: usize,
    /// Particle spacings were divided by this.
    pub resolution_scale: f64,
    /// The sph-impact version.
    pub version: String,
    /// The scene as parsed (the same keys as the file).
    pub scene: serde_json::Value,
    /// The scheme used (the scene's `[solver]` over the study's settings).
    pub scheme: SchemeConfig,
    /// The bodies as built.
    pub bodies: Vec<BodyInfo>,
    /// Damage per body.
    pub damage: Vec<BodyDamageSummary>,
    /// Projectile mass fractions past the melting/vaporisation energies (when its
    /// material has a thermal model).
    pub projectile_phase_fractions: Option<PhaseFractions>,
    /// Ejecta mass and momentum against v_z/U.
    pub ejecta_distribution: Vec<EjectaBin>,
    /// The crater profile: bin outer radius (m) and depth (m; null in empty bins).
    pub crater_profile: (Vec<f64>, Vec<f64>),
    /// Totals of the whole bodies at the start.
    pub initial: Totals,
    /// Totals of the whole bodies at the end.
    pub last: Totals,
    /// (E_end − E_0)/E_0.
    pub energy_error: f64,
    /// Time per solver phase (s).
    pub timings: PhaseTimes,
    /// What the damage bounds did.
    pub damage_events: DamageEvents,
    /// Times a solid particle's density was raised to its floor
    /// (`SchemeConfig::solid_density_floor`).
    pub density_floor_events: u64,
    /// RZ only: rings that crossed the axis within a step and were mirrored back
    /// (`Simulation::axis_crossings`); 0 in 3-D.
    pub axis_crossings: u64,
    /// RZ only: RK2 midpoint positions found across the axis
    /// (`Simulation::axis_crossings_midpoint`); 0 in 3-D.
    pub axis_crossings_midpoint: u64,
    /// Particles in free flight at the end (`SchemeConfig::free_flight_above`): out of
    /// the hydrodynamics, moving at constant velocity; they are in every other output.
    pub free_flight_particles: usize,
    /// The simulated times (s) of the checkpoints this run resumed from, in order; empty
    /// for a run that went through in one go (docs/scenes.md, "Checkpoints"). The wall
    /// time and the steps count the work of every part.
    pub resumed_from_s: Vec<f64>,
    /// What the run could not measure or draw (a figure left out, a quantity undefined),
    /// one line each; also printed on standard error.
    pub warnings: Vec<String>,
}

impl RunSummary {
    /// β and ejecta from a measurement.
    pub(crate) fn set_beta(&mut self, b: &BetaMeasure) {
        self.beta = b.beta;
        self.beta_target = b.beta_target;
        self.beta_pendulum = b.beta_pendulum;
        self.ejecta_mass_kg = b.ejecta_mass;
        self.ejecta_momentum_z_kg_m_s = b.ejecta_momentum_z;
    }
}
