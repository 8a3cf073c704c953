//! `[solver]`: a partial [`SchemeConfig`] merged over the study's settings. Every key is
//! optional and has the name of the `SchemeConfig` field it sets; what a scene leaves out
//! keeps the value of [`study_scheme`].

use crate::solver::{
    CrackLength, DensityForm, EnergyForm, MomentumForm, NeighbourSearch, SchemeConfig,
    SmoothingMode, YieldPressure,
};
use serde::{Deserialize, Serialize};
use sph_damage::StressCoupling;
use sph_kernel::KernelChoice;
use sph_riemann::{
    ArtificialStressForm, InterfaceCoupling, Limiter, RiemannSolver, ViscositySoundSpeed,
};

/// The study's scheme (paper §6): Wendland C2, n_target 2.5, λ_CFL 0.25, α_Π = β_Π = 1,
/// artificial stress ε = 0.2, n = 4 (scalar form), the study's interface coupling; the
/// other settings are [`SchemeConfig::default`]. The study used ASPH; the scalar h stays
/// the default here until ASPH is validated on the impact.
pub fn study_scheme() -> SchemeConfig {
    let mut s = SchemeConfig::default();
    s.artificial_stress.epsilon = 0.2;
    s.artificial_stress.exponent = 4;
    s.artificial_stress.form = ArtificialStressForm::Pressure;
    s
}

/// A named set of scheme choices, applied over [`study_scheme`] before the scene's own
/// `[solver]` keys (each of which still overrides it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Preset {
    /// The study's published scheme as written in the paper ([`study_scheme`]).
    #[default]
    Study,
    /// What the study's code, LLNL Spheral's solid FSISPH, does where the paper is silent
    /// ([`fsisph_scheme`]; docs/scenes.md, "The FSISPH preset").
    Fsisph,
}

/// The FSISPH preset over `base`: the choices of LLNL Spheral's solid FSISPH (Pearl,
/// Raskin & Owen 2022; src/FSISPH/SolidFSISPHEvaluateDerivatives.cc, FSISPHHydros.py) and
/// of the strength and damage models the study ran in it, for fractured rock:
///
/// | setting | value | Spheral |
/// |---|---|---|
/// | `damaged_moduli` | true | G(D) = (1 − D) G0 (ConstantStrength, CollinsStrength) |
/// | `decouple_damaged` | true | decoupleDamagedMaterial (default true) |
/// | `stress_coupling` | `fsisph` | f_Dij = (1 − ΔD)² on pairs in tension only |
/// | `coupling` | `fsisph` | v* = f_Dij v̄ + (1 − f_Dij)(HLLC) |
/// | `yield_pressure` | `compression` | CollinsStrength: Y at max(P, 0) |
/// | `viscosity` | `reconstruct`, `sound-speed = "bulk"` | LimitedMonaghanGingoldViscosity with the fluid sound speed |
/// | `viscosity_length_factor` | 1 | μ_ij from η = H r with Spheral's h, the support radius of its Wendland C2 (kernel extent 1) |
/// | `gradient_correction`, `momentum_correction` | true | linearCorrectGradients (default true) |
/// | `crack_length` | `support` | DamageModel::computeScalarDDDt: c_g/(extent × h) |
/// | `energy_diffusion`, `density_stabilization` | 0.1, 0.1 | specificThermalEnergyDiffusionCoefficient, densityStabilizationCoefficient (defaults 0.1) |
///
/// The viscosity coefficients, CFL number, artificial stress and smoothing stay the
/// study's (α = β = 1, 0.25, ε = 0.2, n = 4), and the neighbour search stays the
/// scene's: at each stage, or a Verlet list, which gives the same pairs (Spheral's once
/// per step is `neighbour_search = "each-step"`).
pub fn fsisph_scheme(base: SchemeConfig) -> SchemeConfig {
    let mut s = base;
    s.damaged_moduli = true;
    s.decouple_damaged = true;
    s.stress_coupling = StressCoupling::Fsisph;
    s.coupling = InterfaceCoupling::Fsisph;
    s.yield_pressure = YieldPressure::Compression;
    s.viscosity.reconstruct = true;
    s.viscosity.sound_speed = ViscositySoundSpeed::Bulk;
    s.viscosity_length_factor = 1.0;
    s.gradient_correction = true;
    s.momentum_correction = true;
    s.crack_length = CrackLength::Support;
    s.energy_diffusion = 0.1;
    s.density_stabilization = 0.1;
    s
}

/// How a body's Benz–Asphaug flaws are dealt: over how many particles the N ln N flaws
/// of its volume are spread (sph_damage::FlawSet::seed_dealt).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FlawDealing {
    /// Over the 3-D particles the body's particles stand for (in RZ ≈ 2πr/Δ per ring, so
    /// a ring has the flaws of one particle of the equivalent 3-D run; elsewhere the
    /// body's own count).
    #[default]
    #[serde(rename = "3d-count")]
    ThreeDCount,
    /// Over the body's own particle count (Spheral's weibullFlawDistributionBenzAsphaug
    /// over its nodes): in RZ each ring then has the flaws of its whole ring volume.
    BodyCount,
}

/// `[solver] viscosity = { alpha = …, beta = …, switch = "none" | "balsara" }`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ViscositySettings {
    /// Linear coefficient α_Π.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    /// Quadratic coefficient β_Π.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub beta: Option<f64>,
    /// The limiter on Π: `none` (the study) or `balsara`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub switch: Option<sph_riemann::ViscositySwitch>,
    /// Reconstruct the velocities to the pair midpoint with a limiter (Spheral's limited
    /// Monaghan–Gingold viscosity).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reconstruct: Option<bool>,
    /// The sound speed of the linear term: `longitudinal` or `bulk`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sound_speed: Option<ViscositySoundSpeed>,
}

/// `[solver] artificial_stress = { epsilon = …, n = …, form = "pressure" | "principal", cap = … }`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArtificialStressSettings {
    /// Strength ε (0 disables).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub epsilon: Option<f64>,
    /// Exponent n.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub n: Option<i32>,
    /// Scalar (pressure) or tensor (principal-stress) form.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub form: Option<ArtificialStressForm>,
    /// Upper bound on ε fⁿ (none by default, the study's form).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cap: Option<f64>,
}

/// The `[solver]` table: each key overrides one [`SchemeConfig`] field of
/// [`study_scheme`] (see that type for the meaning of each).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolverSettings {
    /// The scheme the other keys override: `study` (default) or `fsisph` ([`Preset`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preset: Option<Preset>,
    /// Kernel: `wendland-c2`, `wendland-c4`, `wendland-c6`, `cubic-spline`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kernel: Option<KernelChoice>,
    /// Support radius in particle spacings.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub n_target: Option<f64>,
    /// CFL number λ.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cfl: Option<f64>,
    /// Monaghan viscosity α_Π, β_Π.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscosity: Option<ViscositySettings>,
    /// Viscosity length as a fraction of the mean support radius.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscosity_length_factor: Option<f64>,
    /// Artificial stress ε, n, form.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub artificial_stress: Option<ArtificialStressSettings>,
    /// Star-state solver: `{ kind = "acoustic" }` or `{ kind = "hllc", waves = … }`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub riemann: Option<RiemannSolver>,
    /// Interface coupling b_ij: `study`, `fsisph`, `riemann`, `mean`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coupling: Option<InterfaceCoupling>,
    /// Damage weakening of the deviatoric stress: `particle`, `pair-max`, `yield-only`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stress_coupling: Option<StressCoupling>,
    /// Reconstruction limiter: `van-leer`, `minmod`, `none`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limiter: Option<Limiter>,
    /// Energy equation: `compatible`, `study`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy: Option<EnergyForm>,
    /// Continuity equation: `mass`, `volume`, `summation`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density: Option<DensityForm>,
    /// Pressure in the momentum equation: `particle-pressure`, `star-pressure`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub momentum: Option<MomentumForm>,
    /// Linear gradient correction in the continuity equation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gradient_correction: Option<bool>,
    /// Linear correction of the kernel gradient in the momentum equation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub momentum_correction: Option<bool>,
    /// Linear correction of the strain rate.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub strain_rate_correction: Option<bool>,
    /// Grad-h factor in the continuity equation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grad_h: Option<bool>,
    /// Upper bound of h as a multiple of the initial support radius.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub h_max_factor: Option<f64>,
    /// No tension across interfaces between different materials.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unbonded_interfaces: Option<bool>,
    /// `{ kind = "scalar" }` or `{ kind = "asph", max_aspect = … }`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smoothing: Option<SmoothingMode>,
    /// Density fraction of ρ0 below which a damaged solid is fragmented (0 disables).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fragment_density_ratio: Option<f64>,
    /// Keep a solid's density above the value at which h reaches its cap.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub solid_density_floor: Option<bool>,
    /// Height (m, scene z) above which particles moving up and away leave the
    /// hydrodynamics and fly on at constant velocity (`SchemeConfig::free_flight_above`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub free_flight_above: Option<f64>,
    /// Damage weakens the shear modulus, G(D) = (1 − D) G0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damaged_moduli: Option<bool>,
    /// Fractured material separating in tension does not interact.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub decouple_damaged: Option<bool>,
    /// The pressure of the yield strength: `signed` or `compression` (max(P, 0)).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_pressure: Option<YieldPressure>,
    /// Benz–Asphaug crack-growth length: `spacing` or `support`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crack_length: Option<CrackLength>,
    /// FSISPH's energy diffusion coefficient (0 off).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_diffusion: Option<f64>,
    /// FSISPH's density stabilisation coefficient (0 off).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density_stabilization: Option<f64>,
    /// When the neighbour list is built: `each-stage` (default), `each-step` (once per
    /// RK2 step, as Spheral does) or `verlet` (a list with a skin, kept while it holds).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub neighbour_search: Option<NeighbourSearch>,
    /// The Verlet list's skin s, a fraction of each support (`neighbour_search =
    /// "verlet"` only; default `SchemeConfig::DEFAULT_NEIGHBOUR_SKIN`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub neighbour_skin: Option<f64>,
    /// How Benz–Asphaug flaws are dealt: `3d-count` (default) or `body-count`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flaw_dealing: Option<FlawDealing>,
}

impl SolverSettings {
    /// These settings over [`study_scheme`].
    pub fn scheme(&self) -> SchemeConfig {
        self.apply(study_scheme())
    }

    /// How the bodies' Benz–Asphaug flaws are dealt (`flaw_dealing`, default
    /// [`FlawDealing::ThreeDCount`]).
    pub fn flaw_dealing(&self) -> FlawDealing {
        self.flaw_dealing.unwrap_or_default()
    }

    /// These settings over `base`, the preset (if any) first.
    pub fn apply(&self, base: SchemeConfig) -> SchemeConfig {
        let mut s = match self.preset.unwrap_or_default() {
            Preset::Study => base,
            Preset::Fsisph => fsisph_scheme(base),
        };
        macro_rules! set {
            ($($f:ident),*) => {$( if let Some(v) = self.$f { s.$f = v; } )*};
        }
        set!(
            kernel,
            n_target,
            cfl,
            viscosity_length_factor,
            riemann,
            coupling,
            stress_coupling,
            limiter,
            energy,
            density,
            momentum,
            gradient_correction,
            momentum_correction,
            strain_rate_correction,
            grad_h,
            h_max_factor,
            unbonded_interfaces,
            smoothing,
            fragment_density_ratio,
            solid_density_floor,
            damaged_moduli,
            decouple_damaged,
            yield_pressure,
            crack_length,
            energy_diffusion,
            density_stabilization,
            neighbour_search
        );
        if let Some(z) = self.free_flight_above {
            s.free_flight_above = Some(z);
        }
        if let Some(skin) = self.neighbour_skin {
            s.neighbour_skin = Some(skin);
        }
        if let Some(v) = self.viscosity {
            s.viscosity.alpha = v.alpha.unwrap_or(s.viscosity.alpha);
            s.viscosity.beta = v.beta.unwrap_or(s.viscosity.beta);
            s.viscosity.switch = v.switch.unwrap_or(s.viscosity.switch);
            s.viscosity.reconstruct = v.reconstruct.unwrap_or(s.viscosity.reconstruct);
            s.viscosity.sound_speed = v.sound_speed.unwrap_or(s.viscosity.sound_speed);
        }
        if let Some(a) = self.artificial_stress {
            s.artificial_stress.epsilon = a.epsilon.unwrap_or(s.artificial_stress.epsilon);
            s.artificial_stress.exponent = a.n.unwrap_or(s.artificial_stress.exponent);
            s.artificial_stress.form = a.form.unwrap_or(s.artificial_stress.form);
            s.artificial_stress.cap = a.cap.or(s.artificial_stress.cap);
        }
        s
    }
}
