//! No damage: for fluids and for materials whose failure is not modelled. D stays where
//! it is (normally 0).

use crate::model::{DamageBounds, DamageEval, DamageInput, DamageModel, DamageVariable};
use serde::{Deserialize, Serialize};

/// The model with zero damage rate.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct NoDamage;

impl DamageModel for NoDamage {
    fn name(&self) -> &str {
        "none"
    }
    fn variable(&self) -> DamageVariable {
        DamageVariable::Damage
    }
    #[inline]
    fn evaluate(&self, _particle: usize, input: &DamageInput) -> DamageEval {
        DamageEval {
            rate: 0.0,
            bounds: DamageBounds {
                min: 0.0,
                max: input.damage.max(0.0),
            },
            active_flaws: 0,
        }
    }

    /// σ_1 is never read.
    fn evaluate_if_quiet(&self, particle: usize, input: &DamageInput) -> Option<DamageEval> {
        Some(self.evaluate(particle, input))
    }
}
