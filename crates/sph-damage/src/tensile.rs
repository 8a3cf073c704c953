//! Maximum tensile stress failure (paper §3.3): every particle of the material fails at
//! one threshold σ_b, when the maximum principal stress reaches it.
//!
//! The criterion is written on the effective (undamaged) stress, σ_1/(1 − D) ≥ σ_b,
//! which at D = 0 is σ_1 ≥ σ_b. Equivalently the local strain ε = σ_1/((1 − D)E) reaches
//! σ_b/E: the model is the Benz–Asphaug model with a single flaw of threshold σ_b/E in
//! every particle, and needs no E.
//!
//! Two ways to fail ([`TensileFailure`]):
//! * [`TensileFailure::CrackGrowth`] (default, consistent with the Benz–Asphaug model):
//!   while the criterion holds, d(D^(1/3))/dt = c_g/R_s with c_g = 0.4 c_L, up to D = 1;
//!   growth pauses when the stress falls below the threshold (damage does not heal).
//! * [`TensileFailure::Instant`]: D jumps to 1 as soon as the criterion holds (the
//!   bounds' minimum becomes 1, so the solver's [`crate::apply_bounds`] raises D and
//!   reports [`crate::BoundAction::RaisedToMin`], a countable failure event).

use crate::benz_asphaug::CRACK_SPEED_FRACTION_BA94;
use crate::error::{DamageError, positive};
use crate::model::{DamageBounds, DamageEval, DamageInput, DamageModel, DamageVariable};
use serde::{Deserialize, Serialize};

/// How a particle fails once σ_1/(1 − D) ≥ σ_b.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TensileFailure {
    /// Damage grows at the crack speed: d(D^(1/3))/dt = c_g/R_s.
    #[default]
    CrackGrowth,
    /// D = 1 at once.
    Instant,
}

/// The maximum-tensile-stress model (validated; serde with the same checks).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "MaxTensileStressUnchecked")]
pub struct MaxTensileStress {
    threshold: f64,
    failure: TensileFailure,
    crack_speed_fraction: f64,
}

#[derive(Deserialize)]
struct MaxTensileStressUnchecked {
    threshold: f64,
    #[serde(default)]
    failure: TensileFailure,
    #[serde(default = "default_fraction")]
    crack_speed_fraction: f64,
}

fn default_fraction() -> f64 {
    CRACK_SPEED_FRACTION_BA94
}

impl TryFrom<MaxTensileStressUnchecked> for MaxTensileStress {
    type Error = DamageError;
    fn try_from(raw: MaxTensileStressUnchecked) -> Result<Self, DamageError> {
        MaxTensileStress::new(raw.threshold)?
            .with_failure(raw.failure)
            .with_crack_speed_fraction(raw.crack_speed_fraction)
    }
}

impl MaxTensileStress {
    /// Threshold σ_b in Pa (positive, finite); crack growth at 0.4 c_L. The study's
    /// aluminium projectile uses σ_b = 2500 MPa (paper §6, Table 1).
    pub fn new(threshold: f64) -> Result<Self, DamageError> {
        Ok(MaxTensileStress {
            threshold: positive("sigma_b", threshold)?,
            failure: TensileFailure::default(),
            crack_speed_fraction: CRACK_SPEED_FRACTION_BA94,
        })
    }

    /// Sets the failure mode.
    pub fn with_failure(mut self, failure: TensileFailure) -> Self {
        self.failure = failure;
        self
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

    /// σ_b, Pa.
    pub fn threshold(&self) -> f64 {
        self.threshold
    }
    /// Failure mode.
    pub fn failure(&self) -> TensileFailure {
        self.failure
    }
    /// c_g / c_L.
    pub fn crack_speed_fraction(&self) -> f64 {
        self.crack_speed_fraction
    }
}

impl DamageModel for MaxTensileStress {
    fn name(&self) -> &str {
        "max-tensile-stress"
    }

    fn variable(&self) -> DamageVariable {
        match self.failure {
            TensileFailure::CrackGrowth => DamageVariable::CubeRoot,
            TensileFailure::Instant => DamageVariable::Damage,
        }
    }

    #[inline]
    fn evaluate(&self, _particle: usize, input: &DamageInput) -> DamageEval {
        let d = input.damage;
        if d >= 1.0 {
            return DamageEval {
                rate: 0.0,
                bounds: DamageBounds { min: 0.0, max: d },
                active_flaws: 1,
            };
        }
        let sigma = input.max_principal_stress;
        if sigma.is_nan() {
            return DamageEval {
                rate: f64::NAN,
                bounds: DamageBounds { min: 0.0, max: d },
                active_flaws: 0,
            };
        }
        // σ_1/(1 − D) ≥ σ_b, multiplied out (1 − D > 0 here).
        if sigma < (1.0 - d) * self.threshold {
            return DamageEval {
                rate: 0.0,
                bounds: DamageBounds {
                    min: 0.0,
                    max: d.max(0.0),
                },
                active_flaws: 0,
            };
        }
        match self.failure {
            TensileFailure::Instant => DamageEval {
                rate: 0.0,
                bounds: DamageBounds { min: 1.0, max: 1.0 },
                active_flaws: 1,
            },
            TensileFailure::CrackGrowth => DamageEval {
                rate: self.crack_speed_fraction * input.longitudinal_wave_speed
                    / input.particle_size,
                bounds: DamageBounds::FULL,
                active_flaws: 1,
            },
        }
    }

    /// Some at D ≥ 1 (σ_1 unread) and below the threshold, σ_1 < (1 − D) σ_b, where the
    /// rate is 0 and the bounds [0, D] for any smaller σ_1 as well.
    fn evaluate_if_quiet(&self, particle: usize, input: &DamageInput) -> Option<DamageEval> {
        let d = input.damage;
        (d >= 1.0 || input.max_principal_stress < (1.0 - d) * self.threshold)
            .then(|| self.evaluate(particle, input))
    }
}
