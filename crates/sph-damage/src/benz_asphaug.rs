//! Benz–Asphaug damage: explicit Weibull flaws per particle ([`FlawSet`]) activated by the
//! local tensile strain, with damage growing at the crack speed (paper §3.3; Benz &
//! Asphaug 1994, Icarus 107:98; 1995, CPC 87:253).
//!
//! # The growth law
//!
//! A particle whose local strain ε = σ_1/((1 − D)E) has reached n_act of its n_tot flaw
//! thresholds grows damage as
//!
//! ```text
//! d(D^(1/3))/dt = f(n_act, n_tot) · c_g / R_s,   c_g = 0.4 c_L,
//! D ≤ n_act / n_tot,
//! ```
//!
//! where R_s is the particle's crack-growth radius and c_g the crack speed (0.4 of the
//! longitudinal wave speed, B&A 1994). D^(1/3) is the natural
//! variable: a crack of radius a = c_g t damages the volume fraction (a/R_s)³. The
//! published implementations differ in f, and all three are offered ([`GrowthLaw`]):
//!
//! * [`GrowthLaw::PerActivatedFlaw`], f = n_act (default): every active flaw grows its
//!   own crack at c_g. This is the form of miluphcuda (Schäfer et al. 2016, A&A 590:A19),
//!   which computes `dddt = n_active * c_g / sml` for d = D^(1/DIM).
//! * [`GrowthLaw::ActivatedFraction`], f = n_act/n_tot: LLNL Spheral's Benz–Asphaug
//!   tensor damage (`TensorDamagePolicy`), which advances D^(1/3) by the fraction of
//!   active (and failed) flaws times c_g/R_s.
//! * [`GrowthLaw::SingleCrack`], f = 1 once any flaw is active: eq. dD^(1/3)/dt = c_g/R_s
//!   of B&A 1994 as written for one crack per particle.
//! * [`GrowthLaw::CrackVolume`], f = n_act^(1/p) for the integrated variable D^(1/p):
//!   n_act cracks of radius a each damage n_act (a/R_s)^p, so D^(1/p) = n_act^(1/p) a/R_s
//!   grows at n_act^(1/p) c_g/R_s. With n_act = k V_i ε^m and ε = ε̇t this gives
//!   D ∝ k V_i c_g³ ε̇^m t^(m+3)/R_s³ in 3-D: the continuum Grady–Kipp law (Grady & Kipp
//!   1980), hence σ_max ∝ ε̇^(3/(m+3)) while the cap n_act/n_tot is not reached. Past the
//!   strongest seeded flaw every seeded flaw is active and the count stops growing, unless
//!   the population is continued ([`FlawTail::Continuum`], [`crate::flaw_tail`]): then
//!   the law follows Grady–Kipp at any rate past the seeded flaws.
//!
//! In every form the cap D ≤ n_act/n_tot holds (the solver applies it through
//! [`crate::apply_bounds`]); the cap never falls below the current D, so damage does not
//! heal when the strain drops. Which form matches the continuum Grady–Kipp strain-rate
//! scaling σ_max ∝ ε̇^(3/(m+3)) best is measured in `tests/strain_rate.rs`.

use crate::activation::ActivationStrain;
use crate::error::DamageError;
use crate::flaw_tail::{FlawTail, Tail};
use crate::model::{DamageBounds, DamageEval, DamageInput, DamageModel, DamageVariable};
use crate::params::WeibullParams;
use crate::tensor::DamageForm;
use crate::weibull::FlawSet;
use serde::{Deserialize, Serialize};

/// How the growth rate of D^(1/3) depends on the number of activated flaws (module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum GrowthLaw {
    /// d(D^(1/3))/dt = n_act c_g/R_s (miluphcuda; Schäfer et al. 2016).
    #[default]
    PerActivatedFlaw,
    /// d(D^(1/3))/dt = (n_act/n_tot) c_g/R_s (Spheral's Benz–Asphaug tensor damage).
    ActivatedFraction,
    /// d(D^(1/3))/dt = c_g/R_s once n_act ≥ 1 (B&A 1994, one crack per particle).
    SingleCrack,
    /// d(D^(1/p))/dt = n_act^(1/p) c_g/R_s: the damaged volumes of the n_act cracks add
    /// up (the Grady–Kipp continuum limit; module docs).
    CrackVolume,
}

/// The crack speed as a fraction of the longitudinal wave speed used by Benz & Asphaug
/// 1994 (c_g = 0.4 c_L).
pub const CRACK_SPEED_FRACTION_BA94: f64 = 0.4;

/// Parameters of the Benz–Asphaug model (validated; serde with the same checks).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "BenzAsphaugParamsUnchecked")]
pub struct BenzAsphaugParams {
    weibull: WeibullParams,
    seed: u64,
    crack_speed_fraction: f64,
    growth: GrowthLaw,
    variable: DamageVariable,
    tail: FlawTail,
    activation: ActivationStrain,
    form: DamageForm,
}

#[derive(Deserialize)]
struct BenzAsphaugParamsUnchecked {
    weibull: WeibullParams,
    seed: u64,
    #[serde(default = "default_crack_speed_fraction")]
    crack_speed_fraction: f64,
    #[serde(default)]
    growth: GrowthLaw,
    #[serde(default)]
    variable: DamageVariable,
    #[serde(default)]
    tail: FlawTail,
    #[serde(default)]
    activation: ActivationStrain,
    #[serde(default)]
    form: DamageForm,
}

fn default_crack_speed_fraction() -> f64 {
    CRACK_SPEED_FRACTION_BA94
}

impl TryFrom<BenzAsphaugParamsUnchecked> for BenzAsphaugParams {
    type Error = DamageError;
    fn try_from(raw: BenzAsphaugParamsUnchecked) -> Result<Self, DamageError> {
        BenzAsphaugParams::new(raw.weibull, raw.seed)
            .with_crack_speed_fraction(raw.crack_speed_fraction)
            .map(|p| {
                p.with_growth(raw.growth)
                    .with_variable(raw.variable)
                    .with_tail(raw.tail)
                    .with_activation(raw.activation)
                    .with_form(raw.form)
            })
    }
}

impl BenzAsphaugParams {
    /// Defaults: c_g = 0.4 c_L, [`GrowthLaw::PerActivatedFlaw`], the solver integrates
    /// D^(1/3) (3-D cracks), only the seeded flaws exist ([`FlawTail::Seeded`]), flaws
    /// activate on the stress's strain ([`ActivationStrain::Stress`]), scalar damage
    /// ([`DamageForm::Scalar`]).
    pub fn new(weibull: WeibullParams, seed: u64) -> Self {
        BenzAsphaugParams {
            weibull,
            seed,
            crack_speed_fraction: CRACK_SPEED_FRACTION_BA94,
            growth: GrowthLaw::default(),
            variable: DamageVariable::CubeRoot,
            tail: FlawTail::Seeded,
            activation: ActivationStrain::Stress,
            form: DamageForm::Scalar,
        }
    }

    /// Sets c_g / c_L, in (0, 1].
    pub fn with_crack_speed_fraction(mut self, fraction: f64) -> Result<Self, DamageError> {
        if !(fraction.is_finite() && fraction > 0.0 && fraction <= 1.0) {
            return Err(DamageError::Parameter {
                field: "crack_speed_fraction",
                value: fraction,
                reason: "must lie in (0, 1]",
            });
        }
        self.crack_speed_fraction = fraction;
        Ok(self)
    }

    /// Sets the growth law.
    pub fn with_growth(mut self, growth: GrowthLaw) -> Self {
        self.growth = growth;
        self
    }

    /// Sets the integrated variable: D^(1/3) for 3-D cracks (default), D^(1/2) for 2-D
    /// (miluphcuda integrates D^(1/DIM)).
    pub fn with_variable(mut self, variable: DamageVariable) -> Self {
        self.variable = variable;
        self
    }

    /// Sets what lies beyond the strongest seeded flaw ([`crate::flaw_tail`]).
    pub fn with_tail(mut self, tail: FlawTail) -> Self {
        self.tail = tail;
        self
    }

    /// Sets the strain the flaws activate on ([`crate::activation`]).
    pub fn with_activation(mut self, activation: ActivationStrain) -> Self {
        self.activation = activation;
        self
    }

    /// Sets scalar or tensor damage ([`crate::tensor`]).
    pub fn with_form(mut self, form: DamageForm) -> Self {
        self.form = form;
        self
    }

    /// Weibull parameters.
    pub fn weibull(&self) -> WeibullParams {
        self.weibull
    }
    /// Flaw-seeding seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }
    /// c_g / c_L.
    pub fn crack_speed_fraction(&self) -> f64 {
        self.crack_speed_fraction
    }
    /// Growth law.
    pub fn growth(&self) -> GrowthLaw {
        self.growth
    }
    /// Integrated variable.
    pub fn variable(&self) -> DamageVariable {
        self.variable
    }
    /// Flaws beyond the strongest seeded one.
    pub fn tail(&self) -> FlawTail {
        self.tail
    }
    /// The strain the flaws activate on.
    pub fn activation(&self) -> ActivationStrain {
        self.activation
    }
    /// Scalar or tensor damage.
    pub fn form(&self) -> DamageForm {
        self.form
    }
}

/// The Benz–Asphaug model: parameters plus the seeded flaws of one body.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "BenzAsphaugUnchecked")]
pub struct BenzAsphaug {
    params: BenzAsphaugParams,
    flaws: FlawSet,
    /// The continued population past the strongest seeded flaw (derived from the flaws;
    /// `None` with [`FlawTail::Seeded`]).
    #[serde(skip)]
    tail: Option<Tail>,
}

#[derive(Deserialize)]
struct BenzAsphaugUnchecked {
    params: BenzAsphaugParams,
    flaws: FlawSet,
}

impl TryFrom<BenzAsphaugUnchecked> for BenzAsphaug {
    type Error = DamageError;
    fn try_from(raw: BenzAsphaugUnchecked) -> Result<Self, DamageError> {
        BenzAsphaug::from_flaws(raw.params, raw.flaws)
    }
}

impl BenzAsphaug {
    /// [`DamageModel::evaluate`], and whether its result holds for every smaller σ_1
    /// ([`DamageModel::evaluate_if_quiet`]): where it reads no σ_1 (an unknown particle,
    /// D ≥ 1, the pseudo-plastic strain as the activation strain), or where the strain
    /// σ_1/((1 − D) E) activates none of the particle's flaws. A smaller σ_1 then gives a
    /// strain no larger (a division by the same positive number keeps the order, and a
    /// flaw activates at ε ≥ ε_j), so again no flaw, rate 0 and bounds [0, D].
    fn evaluate_noting_quiet(&self, particle: usize, input: &DamageInput) -> (DamageEval, bool) {
        let d = input.damage;
        let Some(n_tot) = self.flaws.n_flaws(particle) else {
            // Out-of-range particle: NaN, for the solver's state check to report.
            let eval = DamageEval {
                rate: f64::NAN,
                bounds: DamageBounds {
                    min: 0.0,
                    max: f64::NAN,
                },
                active_flaws: 0,
            };
            return (eval, true);
        };
        if d >= 1.0 {
            // Fully damaged: nothing left to grow; all flaws count as active.
            let eval = DamageEval {
                rate: 0.0,
                bounds: DamageBounds { min: 0.0, max: d },
                active_flaws: n_tot as u32,
            };
            return (eval, true);
        }
        let strain = input.local_strain();
        if strain.is_nan() {
            let eval = DamageEval {
                rate: f64::NAN,
                bounds: DamageBounds { min: 0.0, max: d },
                active_flaws: 0,
            };
            return (eval, input.principal_strain.is_some());
        }
        // Flaw j is active when ε ≥ ε_j; past the strongest seeded flaw the continued
        // tail, if any, adds the population's mean share (crate::flaw_tail).
        let n_act = match self.tail {
            Some(tail) if strain > tail.top_strain => tail.count(n_tot, strain),
            _ => self.flaws.activated(particle, strain).unwrap_or(0) as f64,
        };
        let rate = if n_act > 0.0 {
            let growth = self.params.crack_speed_fraction * input.longitudinal_wave_speed
                / input.particle_size;
            let factor = match self.params.growth {
                GrowthLaw::PerActivatedFlaw => n_act,
                GrowthLaw::ActivatedFraction => (n_act / n_tot as f64).min(1.0),
                GrowthLaw::SingleCrack => 1.0,
                GrowthLaw::CrackVolume => match self.params.variable {
                    DamageVariable::Damage => n_act,
                    DamageVariable::SquareRoot => n_act.sqrt(),
                    DamageVariable::CubeRoot => n_act.cbrt(),
                },
            };
            factor * growth
        } else {
            0.0
        };
        // Cap D ≤ n_act/n_tot (at most 1: the tail activates past n_tot), never below the
        // current D (no healing).
        let cap = (n_act / n_tot as f64).min(1.0).max(d);
        let eval = DamageEval {
            rate,
            bounds: DamageBounds { min: 0.0, max: cap },
            // Whole flaws, saturating for an enormous tail count.
            active_flaws: n_act as u32,
        };
        let scale = (1.0 - d) * input.youngs_modulus;
        let quiet =
            input.principal_strain.is_some() || (n_act == 0.0 && scale > 0.0 && scale.is_finite());
        (eval, quiet)
    }

    /// Seeds the flaws of a body of `n_particles` particles and total volume V (m³).
    pub fn seed(
        params: BenzAsphaugParams,
        n_particles: usize,
        total_volume: f64,
    ) -> Result<Self, DamageError> {
        let flaws =
            FlawSet::seed_benz_asphaug(params.weibull, n_particles, total_volume, params.seed)?;
        Ok(BenzAsphaug::assemble(params, flaws))
    }

    /// Seeds the flaws of a body with V = Σ V_i from the particle volumes (m³).
    pub fn seed_with_volumes(
        params: BenzAsphaugParams,
        volumes: &[f64],
    ) -> Result<Self, DamageError> {
        let flaws = FlawSet::seed_benz_asphaug_volumes(params.weibull, volumes, params.seed)?;
        Ok(BenzAsphaug::assemble(params, flaws))
    }

    /// As [`Self::seed_with_volumes`], with the flaws dealt over `dealt_over` particles
    /// of which these are the first ([`FlawSet::seed_dealt`]): e.g. an axisymmetric
    /// body's rings, each standing for the 3-D particles around the axis.
    pub fn seed_with_volumes_dealt(
        params: BenzAsphaugParams,
        volumes: &[f64],
        dealt_over: usize,
    ) -> Result<Self, DamageError> {
        let flaws = FlawSet::seed_volumes_dealt(params.weibull, volumes, dealt_over, params.seed)?;
        Ok(BenzAsphaug::assemble(params, flaws))
    }

    /// Re-assembles a model from a stored flaw set (checkpoint restart); the flaws must
    /// have been seeded with these Weibull parameters and seed.
    pub fn from_flaws(params: BenzAsphaugParams, flaws: FlawSet) -> Result<Self, DamageError> {
        if flaws.params() != params.weibull || flaws.seed() != params.seed {
            return Err(DamageError::CorruptFlawSet {
                reason: "flaws were seeded with other Weibull parameters or another seed",
            });
        }
        Ok(BenzAsphaug::assemble(params, flaws))
    }

    /// The model of checked parameters and flaws, with the tail derived from the flaws.
    fn assemble(params: BenzAsphaugParams, flaws: FlawSet) -> BenzAsphaug {
        let tail = (params.tail == FlawTail::Continuum).then(|| {
            // A particle's mean share is that of one of the particles the flaws were
            // dealt over (in RZ one 3-D particle, not one ring).
            Tail::new(
                flaws.strongest_threshold(),
                params.weibull.k() * flaws.total_volume(),
                flaws.dealt_over() as usize,
                params.weibull.m(),
            )
        });
        BenzAsphaug {
            params,
            flaws,
            tail,
        }
    }

    /// The parameters.
    pub fn params(&self) -> &BenzAsphaugParams {
        &self.params
    }

    /// The flaws.
    pub fn flaws(&self) -> &FlawSet {
        &self.flaws
    }
}

impl DamageModel for BenzAsphaug {
    fn name(&self) -> &str {
        "benz-asphaug"
    }

    fn variable(&self) -> DamageVariable {
        self.params.variable
    }

    fn activation_strain(&self) -> ActivationStrain {
        self.params.activation
    }

    fn form(&self) -> DamageForm {
        self.params.form
    }

    #[inline]
    fn evaluate(&self, particle: usize, input: &DamageInput) -> DamageEval {
        self.evaluate_noting_quiet(particle, input).0
    }

    #[inline]
    fn evaluate_if_quiet(&self, particle: usize, input: &DamageInput) -> Option<DamageEval> {
        let (eval, quiet) = self.evaluate_noting_quiet(particle, input);
        quiet.then_some(eval)
    }

    fn check_particles(&self, n_particles: usize) -> Result<(), DamageError> {
        if self.flaws.n_particles() == n_particles {
            Ok(())
        } else {
            Err(DamageError::ParticleCount {
                what: "benz-asphaug flaws",
                expected: self.flaws.n_particles(),
                got: n_particles,
            })
        }
    }
}
