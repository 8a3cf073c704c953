//! Scheme settings: everything about the numerical method that is not a material.

use serde::{Deserialize, Serialize};
use sph_damage::StressCoupling;
use sph_kernel::KernelChoice;
use sph_riemann::{ArtificialStress, InterfaceCoupling, Limiter, MonaghanViscosity, RiemannSolver};

/// The largest accepted Monaghan viscosity coefficient, α or β.
pub const MAX_VISCOSITY: f64 = 100.0;

/// The largest accepted artificial-stress ε, energy-diffusion and density-stabilisation
/// coefficient.
pub const MAX_COEFFICIENT: f64 = 10.0;

/// The largest accepted `n_target` (spacings per smoothing length).
pub const MAX_N_TARGET: f64 = 8.0;

/// The largest accepted artificial-stress exponent n (the study's is 4).
pub const MAX_ARTIFICIAL_STRESS_EXPONENT: i32 = 16;

/// How the specific internal energy is evolved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum EnergyForm {
    /// The study's equation (paper §2): de_i/dt = −2 Σ_j m_j σ_i/(ρ_iρ_j):(v_i − v*)⊗∇W,
    /// plus the viscous heating ½ Σ_j m_j Π_ij v_ij·∇W. Total energy is conserved only up
    /// to the difference between v* and the pair mean velocity.
    Study,
    /// The compatible form: each pair's work on i is its pair force times (v_i − v*),
    /// de_i/dt = −Σ_j m_j F_ij·(v_i − v*), so kinetic + internal energy is conserved to
    /// round-off for any v* (v*_ij = v*_ji and F_ji = −F_ij).
    #[default]
    Compatible,
}

/// The continuity equation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum DensityForm {
    /// The study's form (paper §2): dρ_i/dt = 2ρ_i Σ_j (m_j/ρ_j)(v_i − v*)·∇W. Its
    /// density drifts across strong shocks (planar Noh: L1(ρ) = 0.51 at nx = 100, not
    /// converging; docs/verification.md), so it is not the default.
    Volume,
    /// The mass form: dρ_i/dt = 2 Σ_j m_j (v_i − v*)·∇W, the time derivative of the
    /// summation density (with the grad-h factor when `grad_h` is on). The default.
    #[default]
    Mass,
    /// Summation density ρ_i = Σ_j m_j W̄_ij (self included), recomputed from the
    /// positions at every stage: tied to the particle volumes, so it cannot drift at
    /// strong shocks; unsuitable at free surfaces of solids (the kernel sum is truncated).
    Summation,
}

/// The pressure in the momentum equation's pair force.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MomentumForm {
    /// The study's form: (σ_i + σ_j)/(ρ_iρ_j), for a fluid −(P_i + P_j)/(ρ_iρ_j).
    #[default]
    ParticlePressure,
    /// −2P*/(ρ_iρ_j) with P* the star pressure of the pair's Riemann problem (as in
    /// Godunov SPH, Inutsuka 2002; Spheral's GSPH): the Riemann solver then also
    /// dissipates in the momentum equation. P* is symmetric in (i, j), so momentum is
    /// still conserved exactly.
    StarPressure,
}

/// How smoothing lengths follow the flow.
///
/// Read through `SmoothingModeRepr`, so that a key next to `kind = "scalar"` is an
/// error like one next to `kind = "asph"` (serde ignores extra keys beside a unit
/// variant's tag).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(
    rename_all = "kebab-case",
    tag = "kind",
    deny_unknown_fields,
    from = "SmoothingModeRepr"
)]
pub enum SmoothingMode {
    /// Scalar support radius h_i = n_target (m_i/ρ_i)^(1/d), set from the density at every
    /// stage, so the neighbour count stays near its target as the material compresses.
    #[default]
    Scalar,
    /// ASPH: a symmetric tensor H_i. Its metric G = HᵀH is advected with the velocity
    /// gradient L (dG/dt = −(LᵀG + GL), so the support ellipsoid deforms with the
    /// material), then relaxed toward the ideal H: the same shape scaled to the volume
    /// n_target^d m/ρ, with the axis ratio limited to `max_aspect`.
    Asph {
        /// Largest allowed ratio of the longest to the shortest support axis.
        max_aspect: f64,
    },
}

/// The serialized form of [`SmoothingMode`]: every variant a struct, so unknown keys are
/// rejected for each.
#[derive(Deserialize)]
#[serde(rename_all = "kebab-case", tag = "kind", deny_unknown_fields)]
enum SmoothingModeRepr {
    Scalar {},
    Asph { max_aspect: f64 },
}

impl From<SmoothingModeRepr> for SmoothingMode {
    fn from(repr: SmoothingModeRepr) -> Self {
        match repr {
            SmoothingModeRepr::Scalar {} => SmoothingMode::Scalar,
            SmoothingModeRepr::Asph { max_aspect } => SmoothingMode::Asph { max_aspect },
        }
    }
}

/// The pressure at which a strength model's yield strength is evaluated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum YieldPressure {
    /// The particle's (damaged) pressure P_D, as the model defines its tension branch
    /// (e.g. [`sph_strength::LundborgTension`]).
    #[default]
    Signed,
    /// max(P_D, 0): in tension the yield is the model's at zero pressure, e.g. the
    /// cohesion Y0 of an intact Lundborg rock and (1 − D) Y0 damaged (LLNL Spheral's
    /// CollinsStrength::yieldStrength, src/SolidMaterial/CollinsStrength.cc, the study's
    /// code).
    Compression,
}

impl YieldPressure {
    /// The pressure the yield strength is evaluated at.
    #[inline]
    pub fn of(self, pressure: f64) -> f64 {
        match self {
            Self::Signed => pressure,
            Self::Compression => pressure.max(0.0),
        }
    }
}

/// The length R_s over which a Benz–Asphaug crack grows through a particle (the growth
/// rate is c_g/R_s).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum CrackLength {
    /// The particle's spacing Δx = h/n_target (Benz & Asphaug's particle size).
    #[default]
    Spacing,
    /// The kernel's support radius h (LLNL Spheral: DamageModel::computeScalarDDDt
    /// divides c_g by the kernel extent times its h, src/Damage/DamageModel.cc), so cracks
    /// take n_target times longer to cross a particle.
    Support,
}

/// When the neighbour list is built ([`SchemeConfig::neighbour_search`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum NeighbourSearch {
    /// At each of the RK2 step's two stages, from that stage's positions and supports.
    #[default]
    EachStage,
    /// Once per step, at its start; the midpoint stage reuses that list and those
    /// boundary ghosts (placed again from their sources' midpoint positions), as LLNL
    /// Spheral does: `Integrator::step` updates the connectivity once per cycle
    /// (src/Integrator/Integrator.cc, `setGhostNodes`) and `CheapSynchronousRK2`
    /// evaluates both stages with it. A listed pair that has moved out of both supports
    /// by the midpoint has ∇W = 0 and is skipped; a pair that comes within reach during
    /// the half step is missed there, at the support's edge, where W and ∇W vanish. Saves
    /// one of the step's two searches.
    EachStep,
    /// A Verlet list: the pairs within (1 + s) times the supports, s the skin
    /// ([`SchemeConfig::neighbour_skin`]), and the ghosts of the particles within that
    /// reach of a boundary, kept over both stages and over as many steps as the list
    /// still holds every pair: until, for some particle i, h_i + max_j |Δx_i − Δx_j| over
    /// its present neighbours exceeds its reach (1 + s) h_i at the build (Δx the
    /// displacement since, h_i its present support), or a ghost a placement would make
    /// now was not placed then (solver/simulation/verlet.rs). The pair passes skip a listed pair beyond both present supports,
    /// and a ghost that a placement from the present positions would not make, by the
    /// search's own test, so every stage sees the pairs a search of its own would find,
    /// in the same order: the results are those of [`Self::EachStage`] to the bit, at
    /// fewer searches. Scalar supports only (not with ASPH).
    Verlet,
}

/// The numerical scheme.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SchemeConfig {
    /// Smoothing kernel (the study: Wendland C2).
    pub kernel: KernelChoice,
    /// Support radius in particle spacings, h = n_target Δx (the study: 2.5).
    pub n_target: f64,
    /// CFL number λ (the study: 0.25).
    pub cfl: f64,
    /// Monaghan viscosity coefficients (the study: α = β = 1).
    pub viscosity: MonaghanViscosity,
    /// The length in μ_ij is this factor times the mean support radius; 0.5 makes it
    /// Monaghan's smoothing length for a kernel reaching 2h.
    pub viscosity_length_factor: f64,
    /// Artificial stress (the study: ε = 0.2, n = 4; 0 disables).
    pub artificial_stress: ArtificialStress,
    /// Star-state solver for v*.
    pub riemann: RiemannSolver,
    /// Damage/material coupling b_ij in v*.
    pub coupling: InterfaceCoupling,
    /// How damage weakens the deviatoric stress in the pair force of two particles of the
    /// same material: each particle's own (1 − D) (the study's §2, default), one factor
    /// of the pair's damages (Spheral's pair-max coupling), or not at all, damage acting
    /// on the yield strength only (Collins et al. 2004; [`StressCoupling`]).
    pub stress_coupling: StressCoupling,
    /// Reconstruction of the normal velocity and pressure toward the pair midpoint.
    pub limiter: Limiter,
    /// Energy equation.
    pub energy: EnergyForm,
    /// Continuity equation.
    pub density: DensityForm,
    /// Pressure in the momentum equation.
    pub momentum: MomentumForm,
    /// Linear gradient correction in the continuity equation and the velocity gradient:
    /// ∇W → M_i⁻ᵀ∇W with M_i = Σ_j V_j (x_j − x_i) ⊗ ∇_i W̄_ij, exact for linear velocity
    /// fields (Bonet & Lok 1999; miluphcuda's tensorial correction). The momentum
    /// equation keeps the plain, antisymmetric gradient, so conservation is unchanged.
    pub gradient_correction: bool,
    /// Linear correction of the kernel gradient in the momentum equation's stress and
    /// pressure terms: m_j[σ_i (M_i⁻ᵀ∇W) + σ_j (M_j⁻ᵀ∇W)]/(ρ_iρ_j) with the
    /// `gradient_correction` matrices (Bonet & Lok 1999), for the particle-pressure
    /// momentum form (the star-pressure form keeps the plain gradient). The pair force
    /// stays antisymmetric (momentum exact; energy exact with the compatible form); M⁻ᵀ
    /// restores the part of the kernel a free surface truncates, where the plain form
    /// makes a bending plate too soft (docs/verification.md, oscillating plate).
    pub momentum_correction: bool,
    /// Linear correction (M_i⁻¹) of the velocity gradient that drives the deviatoric
    /// stress, independent of `gradient_correction`: exact for linear velocity fields, so a
    /// rigid rotation produces no strain rate even at a free surface (spinning disc:
    /// angular momentum drift 5.6e-8 in 1000 steps with it, 1.8e-2 without).
    pub strain_rate_correction: bool,
    /// Divide dρ/dt by the grad-h factor Ω_i = 1 + h_i/(dρ_i) Σ_j m_j ∂W_ij/∂h, so the
    /// evolved density follows the summation density as h changes (scalar h; with ASPH
    /// the equivalent radius). Needed for strong compressions (docs/verification.md).
    pub grad_h: bool,
    /// Upper bound of h as a multiple of each particle's initial support radius
    /// (n_target × initial spacing): in strong expansions (a blast centre, ejecta) the
    /// density falls without bound and h would grow with it.
    pub h_max_factor: f64,
    /// Interfaces between different materials are unbonded: such a pair exerts no
    /// attractive (tensile) force, so bodies in contact can separate (a projectile from
    /// its target, two colliding bars). The pair force is antisymmetric, so both sides
    /// drop it together and conservation is unchanged.
    pub unbonded_interfaces: bool,
    /// Smoothing-length evolution.
    pub smoothing: SmoothingMode,
    /// What a 2-D run stands for: the plane, or rings about the z axis (RZ; see
    /// [`crate::solver::axisymmetric`]).
    pub geometry: crate::solver::axisymmetric::Geometry,
    /// A step shorter than this fraction of the run's first step is a collapse: the run
    /// stops with [`crate::SolverError::TimestepCollapse`] naming the particle and the
    /// reason, instead of crawling on at ever smaller steps (0 disables).
    pub dt_floor_fraction: f64,
    /// A damaged solid whose density falls below this fraction of its EOS reference
    /// density ρ0 has come apart: its damage is set to 1 for good, so it carries no
    /// deviatoric stress and no tension (0 disables; default
    /// [`Self::DEFAULT_FRAGMENT_DENSITY_RATIO`]). Why: the flaws of Benz–Asphaug damage
    /// activate on the stress-based strain σ_1/((1 − D)E), which a particle that has lost
    /// its stress never reaches again, so its damage can stop at the cap n_act/n_tot < 1
    /// and it keeps (1 − D) of its cohesion however far it expands. With ρ → 0 the
    /// acceleration of that residual stress, ~(1 − D)S/(ρh), diverges and the time step
    /// collapses (the 0.5 mm basalt run at 96 µs, docs/validation.md). Each setting is
    /// counted in [`crate::DamageEvents::fragmented`].
    pub fragment_density_ratio: f64,
    /// A solid's density never falls below m/(h_max_factor Δp0)^d (in RZ with the ring's
    /// area mass m/r): the density at which its smoothing length reaches the cap
    /// `h_max_factor`, about ρ0/h_max_factor^d. Below it the continuity equation no longer
    /// describes anything the capped kernel can resolve; what drives it there is the mass
    /// form's neighbour-mass sum, Σ m_j v_ij·∇W, which does not scale with ρ_i: a
    /// particle torn off a dense plate, still inside the plate's kernels, is emptied at
    /// the plate's rate. At ρ ≈ 1e-5 ρ0 the next neighbour to come by then compresses
    /// it at a relative rate ~1e13 /s and the density vote stops the run (0.5 mm basalt
    /// run at 100 µs, docs/validation.md). Fluids are left free (near-vacuum Riemann
    /// problems need their low densities). Each flooring of a particle in a step is
    /// counted in [`crate::Simulation::density_floor_events`].
    pub solid_density_floor: bool,
    /// Damage weakens the shear modulus, G(D) = (1 − D) G0, for every strength model
    /// (`StrengthModel::damaged_shear_modulus`; paper §3.3 as corrected, Spheral's
    /// ConstantStrength/CollinsStrength): Young's modulus E(D) in the flaw-activation
    /// strain, the longitudinal wave speed (time step, signal speeds, crack speed) and the
    /// stress rate 2G ε̇' all follow D. Off: G stays the model's (the earlier default).
    pub damaged_moduli: bool,
    /// Fractured material decouples: a same-material pair that is separating, with one
    /// side in tension past its adhesion limit and one side fully damaged (D > 0.9), does
    /// not interact (Spheral FSISPH's decoupleDamagedMaterial; sph_damage::decoupling).
    pub decouple_damaged: bool,
    /// The pressure the yield strength is evaluated at ([`YieldPressure`]).
    pub yield_pressure: YieldPressure,
    /// The crack-growth length of Benz–Asphaug damage ([`CrackLength`]).
    pub crack_length: CrackLength,
    /// FSISPH's energy diffusion coefficient κ_e (0 off; Spheral's default 0.1): within
    /// one material a pair exchanges κ_e c_eff (ẽ_i − ẽ_j) η·∇W̄/(ρ̄ |η|²) of specific
    /// energy, ẽ reconstructed to the midpoint with the limiter, c_eff the pair's bulk
    /// sound speed reduced by its approach speed, η = r/h̄
    /// (src/FSISPH/SolidFSISPHEvaluateDerivatives.cc). Conserves energy pair by pair.
    pub energy_diffusion: f64,
    /// FSISPH's density stabilisation coefficient κ_ρ (0 off; Spheral's default 0.1):
    /// within one material v* gains f_D κ_ρ c̄ (1 + min(0, max(−1, v_ij·r̂/c̄)))
    /// clamp((P_j − P_i)/(K_i + K_j), ±¼) r̂, a pressure-driven smoothing of the continuity
    /// and energy equations, weighted by f_D = (1 − |D_i − D_j|)² (same file).
    pub density_stabilization: f64,
    /// Free flight (`None`, the default, disables): a particle above this height in the
    /// last coordinate (m; z in 3-D and RZ, y in plane 2-D), moving up and away from
    /// every wall, leaves the hydrodynamics after the step and moves on at constant
    /// velocity (no gravity or drag; its interactions with other ejecta are dropped). It
    /// stays in every output and total ([`crate::Simulation::with_free_flight`]). Why:
    /// in RZ a ring flying outward thins like r^(−1/2) and would set the time step for
    /// the rest of the run (solver/free_flight.rs).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub free_flight_above: Option<f64>,
    /// When the neighbour list is built ([`NeighbourSearch`]; default: at each stage).
    pub neighbour_search: NeighbourSearch,
    /// The skin s of a Verlet list ([`NeighbourSearch::Verlet`]): the list holds the pairs
    /// within (1 + s) times the supports. `None` gives
    /// [`Self::DEFAULT_NEIGHBOUR_SKIN`]; refused with another `neighbour_search`, which
    /// would not read it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub neighbour_skin: Option<f64>,
}

impl Default for SchemeConfig {
    fn default() -> Self {
        Self {
            kernel: KernelChoice::WendlandC2,
            n_target: 2.5,
            cfl: 0.25,
            viscosity: MonaghanViscosity::default(),
            viscosity_length_factor: 0.5,
            artificial_stress: ArtificialStress {
                epsilon: 0.0,
                ..ArtificialStress::default()
            },
            riemann: RiemannSolver::Acoustic,
            coupling: InterfaceCoupling::Study,
            stress_coupling: StressCoupling::Particle,
            limiter: Limiter::VanLeer,
            energy: EnergyForm::Compatible,
            density: DensityForm::Mass,
            momentum: MomentumForm::ParticlePressure,
            gradient_correction: false,
            momentum_correction: false,
            strain_rate_correction: true,
            grad_h: true,
            h_max_factor: 4.0,
            unbonded_interfaces: true,
            smoothing: SmoothingMode::Scalar,
            geometry: crate::solver::axisymmetric::Geometry::Cartesian,
            dt_floor_fraction: 1e-6,
            fragment_density_ratio: Self::DEFAULT_FRAGMENT_DENSITY_RATIO,
            solid_density_floor: true,
            free_flight_above: None,
            damaged_moduli: false,
            decouple_damaged: false,
            yield_pressure: YieldPressure::Signed,
            crack_length: CrackLength::Spacing,
            energy_diffusion: 0.0,
            density_stabilization: 0.0,
            neighbour_search: NeighbourSearch::EachStage,
            neighbour_skin: None,
        }
    }
}

impl SchemeConfig {
    /// Whether pass 2 runs its loop compiled with the paper's choices of the scheme as
    /// constants (the limiter, the Riemann solver and its damage coupling, the energy,
    /// density and momentum forms, the stress coupling, the plain viscosity, unbonded
    /// interfaces, no corrections, no density stabilisation or energy diffusion: those
    /// of [`SchemeConfig::default`]), which executes fewer instructions per pair than
    /// the loop that reads them. The results are the same to the bit either way
    /// (docs/performance.md, "The scheme's choices as constants of the pair loop").
    pub fn takes_study_pair_loop(&self) -> bool {
        crate::solver::derivatives::PairScheme::is_study(self)
    }

    /// Default of [`Self::fragment_density_ratio`]: a solid expanded to half its
    /// reference density has certainly come apart, and no intact or merely cracked
    /// material of an impact (spall plates, crater walls, compressed rock) gets there.
    pub const DEFAULT_FRAGMENT_DENSITY_RATIO: f64 = 0.5;

    /// Default of [`Self::neighbour_skin`] (docs/performance.md, "A Verlet list").
    pub const DEFAULT_NEIGHBOUR_SKIN: f64 = 0.15;

    /// The skin of the neighbour list: `Some(s)` with [`NeighbourSearch::Verlet`],
    /// `None` for a list of the exact pairs.
    pub fn skin(&self) -> Option<f64> {
        (self.neighbour_search == NeighbourSearch::Verlet)
            .then(|| self.neighbour_skin.unwrap_or(Self::DEFAULT_NEIGHBOUR_SKIN))
    }

    /// Checks ranges; the error names the field.
    pub fn validate(&self) -> Result<(), crate::SolverError> {
        let bad = |field: &'static str, value: f64, reason: &'static str| {
            Err(crate::SolverError::BadConfig {
                field,
                value,
                reason,
            })
        };
        if !(self.n_target > 0.5 && self.n_target <= MAX_N_TARGET) {
            // The neighbour count grows as n_target³ in 3-D: 8 spacings is already
            // ~ 2 × 10⁴ neighbours per particle.
            return bad(
                "n_target",
                self.n_target,
                "must be a number of spacings in (0.5, 8]",
            );
        }
        if !(self.dt_floor_fraction >= 0.0 && self.dt_floor_fraction < 1.0) {
            return bad(
                "dt_floor_fraction",
                self.dt_floor_fraction,
                "must be in [0, 1)",
            );
        }
        if !(self.fragment_density_ratio >= 0.0 && self.fragment_density_ratio < 1.0) {
            return bad(
                "fragment_density_ratio",
                self.fragment_density_ratio,
                "must be in [0, 1)",
            );
        }
        if let Some(z) = self.free_flight_above
            && !z.is_finite()
        {
            return bad("free_flight_above", z, "must be a finite height (m)");
        }
        if !(self.cfl > 0.0 && self.cfl <= 1.0) {
            return bad("cfl", self.cfl, "must be in (0, 1]");
        }
        // Each field on its own, so that the value reported is the one given. The upper
        // bounds lie far above any published use (α ≈ 1, β ≈ 2, ε ≈ 0.2, the FSISPH
        // coefficients ≈ 0.1) and far below where the first step collapses or
        // overflows.
        for (field, value, max, reason) in [
            (
                "viscosity.alpha",
                self.viscosity.alpha,
                MAX_VISCOSITY,
                "must be in [0, 100]",
            ),
            (
                "viscosity.beta",
                self.viscosity.beta,
                MAX_VISCOSITY,
                "must be in [0, 100]",
            ),
            (
                "artificial_stress.epsilon",
                self.artificial_stress.epsilon,
                MAX_COEFFICIENT,
                "must be in [0, 10]",
            ),
            (
                "energy_diffusion",
                self.energy_diffusion,
                MAX_COEFFICIENT,
                "must be in [0, 10]",
            ),
            (
                "density_stabilization",
                self.density_stabilization,
                MAX_COEFFICIENT,
                "must be in [0, 10]",
            ),
        ] {
            if !(value >= 0.0 && value <= max) {
                return bad(field, value, reason);
            }
        }
        if !(self.h_max_factor >= 1.0 && self.h_max_factor.is_finite()) {
            return bad("h_max_factor", self.h_max_factor, "must be finite and ≥ 1");
        }
        if !(self.viscosity_length_factor > 0.0 && self.viscosity_length_factor.is_finite()) {
            return bad(
                "viscosity_length_factor",
                self.viscosity_length_factor,
                "must be finite and > 0",
            );
        }
        if !(1..=MAX_ARTIFICIAL_STRESS_EXPONENT).contains(&self.artificial_stress.exponent) {
            return bad(
                "artificial_stress.n",
                f64::from(self.artificial_stress.exponent),
                "must be an integer exponent in [1, 16]",
            );
        }
        // HLLC's pressure-based wave speeds need an adiabatic index > 1: with another
        // the estimate is NaN and every pair would fall back to the acoustic solver.
        if let RiemannSolver::Hllc {
            waves: sph_riemann::WaveSpeedEstimate::PressureBased { gamma },
        } = self.riemann
            && !(gamma > 1.0 && gamma.is_finite())
        {
            return bad("riemann.waves.gamma", gamma, "must be finite and > 1");
        }
        if let Some(cap) = self.artificial_stress.cap
            && !(cap > 0.0 && cap.is_finite())
        {
            return bad("artificial_stress.cap", cap, "must be finite and > 0");
        }

        if let SmoothingMode::Asph { max_aspect } = self.smoothing
            && !(max_aspect >= 1.0)
        {
            return bad("smoothing.max_aspect", max_aspect, "must be ≥ 1");
        }
        if let Some(skin) = self.neighbour_skin {
            if self.neighbour_search != NeighbourSearch::Verlet {
                return bad(
                    "neighbour_skin",
                    skin,
                    "is read only with neighbour_search = \"verlet\"",
                );
            }
            if !(skin > 0.0 && skin <= 2.0) {
                return bad("neighbour_skin", skin, "must be in (0, 2]");
            }
        }
        if let (Some(skin), SmoothingMode::Asph { .. }) = (self.skin(), self.smoothing) {
            return bad(
                "neighbour_skin",
                skin,
                "a Verlet list needs scalar supports: not with smoothing kind = \"asph\"",
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_riemann::WaveSpeedEstimate;

    /// The field and value a bad scheme is refused with.
    fn refused(edit: impl FnOnce(&mut SchemeConfig)) -> (&'static str, f64) {
        let mut s = SchemeConfig::default();
        edit(&mut s);
        match s.validate() {
            Err(crate::SolverError::BadConfig { field, value, .. }) => (field, value),
            other => panic!("accepted or another error: {other:?}"),
        }
    }

    /// Every number finite and in range, each reported with the value given (a NaN α
    /// as NaN, not as the β beside it).
    #[test]
    fn out_of_range_settings_are_refused_with_their_own_value() {
        let (f, v) = refused(|s| s.viscosity.alpha = f64::NAN);
        assert_eq!(f, "viscosity.alpha");
        assert!(v.is_nan());
        assert_eq!(
            refused(|s| s.viscosity.beta = f64::INFINITY).0,
            "viscosity.beta"
        );
        assert_eq!(
            refused(|s| s.artificial_stress.epsilon = f64::INFINITY).0,
            "artificial_stress.epsilon"
        );
        assert_eq!(
            refused(|s| s.artificial_stress.exponent = -4),
            ("artificial_stress.n", -4.0)
        );
        assert_eq!(refused(|s| s.artificial_stress.exponent = 0).1, 0.0);
        assert_eq!(
            refused(|s| s.h_max_factor = f64::INFINITY).0,
            "h_max_factor"
        );
        assert_eq!(refused(|s| s.n_target = 1e6), ("n_target", 1e6));
        assert_eq!(
            refused(|s| s.viscosity_length_factor = f64::INFINITY).0,
            "viscosity_length_factor"
        );
        for gamma in [1.0, 0.5, f64::NAN, f64::INFINITY] {
            let (f, _) = refused(|s| {
                s.riemann = RiemannSolver::Hllc {
                    waves: WaveSpeedEstimate::PressureBased { gamma },
                }
            });
            assert_eq!(f, "riemann.waves.gamma");
        }
        let mut s = SchemeConfig {
            riemann: RiemannSolver::Hllc {
                waves: WaveSpeedEstimate::PressureBased { gamma: 1.4 },
            },
            ..SchemeConfig::default()
        };
        s.n_target = MAX_N_TARGET;
        s.artificial_stress.exponent = MAX_ARTIFICIAL_STRESS_EXPONENT;
        s.validate().unwrap();
    }

    /// A skin is read by the Verlet list only, in (0, 2], and with scalar supports; the
    /// Verlet list without one takes the default.
    #[test]
    fn a_skin_is_refused_where_no_verlet_list_reads_it() {
        assert_eq!(
            refused(|s| s.neighbour_skin = Some(0.2)),
            ("neighbour_skin", 0.2)
        );
        let verlet = |s: &mut SchemeConfig| s.neighbour_search = NeighbourSearch::Verlet;
        for bad in [0.0, -0.1, 2.5, f64::NAN, f64::INFINITY] {
            let (f, v) = refused(|s| {
                verlet(s);
                s.neighbour_skin = Some(bad);
            });
            assert_eq!(f, "neighbour_skin");
            assert!(v == bad || (v.is_nan() && bad.is_nan()));
        }
        let (f, v) = refused(|s| {
            verlet(s);
            s.smoothing = SmoothingMode::Asph { max_aspect: 4.0 };
        });
        assert_eq!(
            (f, v),
            ("neighbour_skin", SchemeConfig::DEFAULT_NEIGHBOUR_SKIN)
        );
        let mut s = SchemeConfig::default();
        assert_eq!(s.skin(), None);
        verlet(&mut s);
        assert_eq!(s.skin(), Some(SchemeConfig::DEFAULT_NEIGHBOUR_SKIN));
        s.neighbour_skin = Some(2.0);
        s.validate().unwrap();
        assert_eq!(s.skin(), Some(2.0));
    }
}
