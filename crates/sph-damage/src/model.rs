//! The [`DamageModel`] trait: what the solver asks a damage model per particle per stage,
//! the variable it integrates, and the bounds it applies afterwards.
//!
//! # The solver's side of the contract
//!
//! Per particle i and per RK2 stage the solver
//! 1. builds a [`DamageInput`] from the stage state: σ_1, the largest eigenvalue of the
//!    (damaged) total stress, tension positive (e.g. with [`max_principal_stress`], which
//!    uses the eigen-decomposition of sph-core); Young's modulus E; the longitudinal wave
//!    speed c_L; the crack-growth radius R_s; and the stage damage D;
//! 2. calls [`DamageModel::evaluate`], which returns the rate ds/dt of the model's
//!    integrated variable s = D^(1/p) ([`DamageModel::variable`]) and the bounds on D;
//! 3. advances s (not D: see below) with its RK2 weights, and passes the result through
//!    [`apply_bounds`] with the bounds of the most recent evaluation, counting each
//!    [`BoundAction`] other than [`BoundAction::Within`] (nothing is clamped silently).
//!
//! # Why the solver integrates D^(1/3), not D
//!
//! Crack growth is linear in time for the crack *radius*, a = c_g t, while damage is a
//! volume fraction, D = (a/R_s)³ (Benz & Asphaug 1994, Icarus 107:98, eq. for dD^(1/3)/dt).
//! So d(D^(1/3))/dt = c_g/R_s is constant, whereas dD/dt = 3 D^(2/3) c_g/R_s vanishes at
//! D = 0: a solver integrating D would never leave D = 0. Integrating s = D^(1/3) starts
//! from s = 0 with a finite rate. [`DamageModel::damage_rate`] gives dD/dt by the chain
//! rule for output and diagnostics only.
//!
//! # Local strain for flaw activation
//!
//! Flaws activate on the local tensile strain
//!
//! ```text
//! ε = σ_1 / ((1 − D) E)
//! ```
//!
//! (Benz & Asphaug 1994, 1995 CPC 87:253): σ_1 is the maximum principal stress of the
//! damaged material, so dividing by (1 − D) recovers the strain carried by the intact
//! fraction, and E converts it to strain. Compression (σ_1 ≤ 0) activates nothing.

use crate::error::DamageError;
use serde::{Deserialize, Serialize};
use sph_core::{Tensor, Vector};

/// Per-particle inputs of one damage evaluation (SI units, tension positive).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DamageInput {
    /// σ_1, the largest principal value of the total (damaged) stress, Pa, tension
    /// positive. In plane strain or RZ include the out-of-plane normal stress.
    pub max_principal_stress: f64,
    /// Young's modulus E, Pa (see [`crate::youngs_modulus`]).
    pub youngs_modulus: f64,
    /// Longitudinal wave speed c_L = √((K + 4G/3)/ρ), m/s. Crack speed is a fraction of it.
    pub longitudinal_wave_speed: f64,
    /// R_s, the radius over which a crack grows to damage the whole particle, m. Benz &
    /// Asphaug use the particle size; SPH codes commonly pass the smoothing length.
    pub particle_size: f64,
    /// Current damage D ∈ [0, 1] of this stage.
    pub damage: f64,
    /// The largest principal value of the strain the model activates on, when it is not
    /// the stress's ([`crate::ActivationStrain::PseudoPlastic`]); `None` for the stress
    /// form ([`DamageModel::activation_strain`]).
    pub principal_strain: Option<f64>,
}

impl DamageInput {
    /// Checks the input's ranges: finite σ_1 (and principal strain, if given); positive
    /// finite E, c_L, R_s; D ∈ [0, 1].
    /// The models' evaluations never panic on bad input (a NaN σ_1 gives a NaN rate), so
    /// a solver calls this where it validates its state, not in the hot loop.
    pub fn validate(&self, particle: usize) -> Result<(), DamageError> {
        let bad = |field, value, reason| {
            Err(DamageError::ParticleValue {
                index: particle,
                field,
                value,
                reason,
            })
        };
        if !self.max_principal_stress.is_finite() {
            return bad(
                "max_principal_stress",
                self.max_principal_stress,
                "must be finite",
            );
        }
        if let Some(e) = self.principal_strain
            && !e.is_finite()
        {
            return bad("principal_strain", e, "must be finite");
        }
        for (field, value) in [
            ("youngs_modulus", self.youngs_modulus),
            ("longitudinal_wave_speed", self.longitudinal_wave_speed),
            ("particle_size", self.particle_size),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return bad(field, value, "must be positive and finite");
            }
        }
        if !(0.0..=1.0).contains(&self.damage) {
            return bad("damage", self.damage, "must lie in [0, 1]");
        }
        Ok(())
    }

    /// The local tensile strain that activates flaws: ε = σ_1 / ((1 − D) E) (Benz &
    /// Asphaug 1994, 1995), or ε = [`Self::principal_strain`]/(1 − D) when given
    /// ([`crate::activation`]). IEEE arithmetic: at D = 1 it is ±∞ (or NaN for a zero
    /// numerator); the models return a zero rate for D ≥ 1 before using it.
    #[inline]
    pub fn local_strain(&self) -> f64 {
        match self.principal_strain {
            Some(e) => e / (1.0 - self.damage),
            None => self.max_principal_stress / ((1.0 - self.damage) * self.youngs_modulus),
        }
    }
}

/// σ_1: the largest eigenvalue of a symmetric stress tensor (tension positive), from
/// sph-core's eigen-solver (values only). For 2-D tensors the out-of-plane normal stress of
/// plane strain or RZ is not included; take the max with it where it exists.
pub fn max_principal_stress<T: Tensor>(stress: &T) -> f64 {
    let dim = <T::Vector as Vector>::DIM;
    // Eigenvalues are ascending over the first DIM entries.
    stress.sym_eigenvalues()[dim - 1]
}

/// An upper bound of [`max_principal_stress`] of the symmetric `stress` from Gershgorin's
/// discs (`Tensor::gershgorin`), widened by 1e-12 of the matrix's largest row sum, far
/// beyond the rounding of the discs and of the eigen-solver's σ_1. None when an entry is
/// not finite (σ_1 must then be computed, to carry the NaN).
pub fn max_principal_stress_bound<T: Tensor>(stress: &T) -> Option<f64> {
    let (_, upper, size) = stress.gershgorin()?;
    Some(upper + 1e-12 * size)
}

/// The variable s the solver integrates; D = s^p.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum DamageVariable {
    /// s = D (p = 1).
    Damage,
    /// s = D^(1/2) (p = 2): crack growth in 2-D, where damage is an area fraction.
    SquareRoot,
    /// s = D^(1/3) (p = 3): crack growth in 3-D (Benz & Asphaug 1994).
    #[default]
    CubeRoot,
}

impl DamageVariable {
    /// The power p with D = s^p.
    pub fn exponent(self) -> u32 {
        match self {
            DamageVariable::Damage => 1,
            DamageVariable::SquareRoot => 2,
            DamageVariable::CubeRoot => 3,
        }
    }
    /// D = s^p.
    #[inline]
    pub fn to_damage(self, s: f64) -> f64 {
        match self {
            DamageVariable::Damage => s,
            DamageVariable::SquareRoot => s * s,
            DamageVariable::CubeRoot => s * s * s,
        }
    }
    /// s = D^(1/p).
    #[inline]
    pub fn from_damage(self, damage: f64) -> f64 {
        match self {
            DamageVariable::Damage => damage,
            DamageVariable::SquareRoot => damage.sqrt(),
            DamageVariable::CubeRoot => damage.cbrt(),
        }
    }
    /// dD/dt = p s^(p−1) ds/dt (chain rule). Zero at s = 0 for p > 1, which is why the
    /// solver integrates s.
    #[inline]
    pub fn damage_rate(self, s: f64, ds_dt: f64) -> f64 {
        match self {
            DamageVariable::Damage => ds_dt,
            DamageVariable::SquareRoot => 2.0 * s * ds_dt,
            DamageVariable::CubeRoot => 3.0 * s * s * ds_dt,
        }
    }
}

/// Bounds on D after an update: `0 ≤ min ≤ max ≤ 1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DamageBounds {
    /// Lower bound: 0, or 1 once an instant-failure model has failed the particle.
    pub min: f64,
    /// Upper bound: e.g. the fraction of activated flaws, never below the current D
    /// (damage does not heal).
    pub max: f64,
}

impl DamageBounds {
    /// The bounds [0, 1].
    pub const FULL: DamageBounds = DamageBounds { min: 0.0, max: 1.0 };
}

/// One evaluation of a damage model for one particle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DamageEval {
    /// ds/dt of the integrated variable s ([`DamageModel::variable`]), ≥ 0 (NaN if the
    /// input was NaN).
    pub rate: f64,
    /// Bounds on D to apply after the update.
    pub bounds: DamageBounds,
    /// Flaws active at this strain (0 or 1 for single-threshold models), for output.
    pub active_flaws: u32,
}

/// What [`apply_bounds`] did to an updated state.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BoundAction {
    /// The state was inside the bounds and is returned unchanged.
    Within,
    /// D was below `min` and was raised to it (instant failure, or a negative state).
    RaisedToMin,
    /// D exceeded `max` and was lowered to it (e.g. the activated-flaw cap n_act/n_tot).
    CappedAtMax,
    /// The state was NaN or infinite; it is returned unchanged for the solver to report.
    NonFinite,
}

/// The bounded state after an update.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounded {
    /// The integrated variable s after bounding.
    pub state: f64,
    /// D = s^p after bounding.
    pub damage: f64,
    /// What was done.
    pub action: BoundAction,
}

/// Applies `bounds` (on D) to an updated state `s` of `variable`. A state inside the
/// bounds is returned bit for bit; otherwise D is set to the violated bound and the
/// action says which, so the solver can count it.
#[inline]
pub fn apply_bounds(variable: DamageVariable, s: f64, bounds: DamageBounds) -> Bounded {
    if !s.is_finite() {
        return Bounded {
            state: s,
            damage: f64::NAN,
            action: BoundAction::NonFinite,
        };
    }
    let d = variable.to_damage(s);
    let (damage, action) = if d < bounds.min {
        (bounds.min, BoundAction::RaisedToMin)
    } else if d > bounds.max {
        (bounds.max, BoundAction::CappedAtMax)
    } else {
        return Bounded {
            state: s,
            damage: d,
            action: BoundAction::Within,
        };
    };
    Bounded {
        state: variable.from_damage(damage),
        damage,
        action,
    }
}

/// A scalar damage model D ∈ [0, 1], evaluated by the solver per particle per stage.
///
/// Implementations must be pure functions of `(particle, input)` and of state fixed at
/// construction (e.g. the flaw set), so a parallel particle loop is deterministic for any
/// thread count. Rates are ≥ 0 (damage never heals) and `bounds.max` is never below the
/// input damage.
pub trait DamageModel: Send + Sync + std::fmt::Debug {
    /// Short name for logs and output.
    fn name(&self) -> &str;

    /// The variable s = D^(1/p) the solver integrates.
    fn variable(&self) -> DamageVariable;

    /// The strain the flaws activate on; with [`crate::ActivationStrain::PseudoPlastic`]
    /// the solver tracks the pseudo-plastic strain and passes it in
    /// [`DamageInput::principal_strain`]. Default: the stress's.
    fn activation_strain(&self) -> crate::ActivationStrain {
        crate::ActivationStrain::Stress
    }

    /// Whether D is one number per particle or a tensor grown along the principal strain
    /// directions ([`crate::tensor`]); with [`crate::DamageForm::Tensor`] the solver
    /// evaluates the model once per principal direction. Default: scalar.
    fn form(&self) -> crate::DamageForm {
        crate::DamageForm::Scalar
    }

    /// Rate of s and the bounds on D for particle `particle` in state `input`.
    fn evaluate(&self, particle: usize, input: &DamageInput) -> DamageEval;

    /// [`Self::evaluate`]'s result, when it is also the result for every σ_1 below
    /// `input.max_principal_stress` (the rest of `input` unchanged); else None. Some for
    /// a flaw model whose weakest flaw `input` does not activate, or a model that does not
    /// read σ_1. A solver then evaluates at an upper bound of σ_1
    /// ([`max_principal_stress_bound`]) and skips the eigenvalue problem of σ_1 itself
    /// wherever it can, with the same results to the bit. Default: None (σ_1 always
    /// computed), right for any model; answering Some where the result would differ
    /// below changes results.
    fn evaluate_if_quiet(&self, particle: usize, input: &DamageInput) -> Option<DamageEval> {
        let _ = (particle, input);
        None
    }

    /// Checks that per-particle state held by the model (e.g. flaws) matches the
    /// solver's particle count. Models without per-particle state accept any count.
    fn check_particles(&self, n_particles: usize) -> Result<(), DamageError> {
        let _ = n_particles;
        Ok(())
    }

    /// ds/dt alone.
    fn rate(&self, particle: usize, input: &DamageInput) -> f64 {
        self.evaluate(particle, input).rate
    }

    /// Upper bound of D for this particle in this state (e.g. the fraction of activated
    /// flaws).
    fn max_damage(&self, particle: usize, input: &DamageInput) -> f64 {
        self.evaluate(particle, input).bounds.max
    }

    /// dD/dt by the chain rule, for output: zero at D = 0 for the root variables, so a
    /// solver must integrate [`DamageModel::variable`], not D.
    fn damage_rate(&self, particle: usize, input: &DamageInput) -> f64 {
        let v = self.variable();
        v.damage_rate(v.from_damage(input.damage), self.rate(particle, input))
    }
}
