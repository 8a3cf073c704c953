//! The built-in models as one enum, for scene files and checkpoints. A solver `match`es
//! on it once per material and runs the concrete model in its loop; the enum also
//! implements [`DamageModel`] itself (a branch per call) for convenience.

use crate::benz_asphaug::BenzAsphaug;
use crate::error::DamageError;
use crate::model::{DamageEval, DamageInput, DamageModel, DamageVariable};
use crate::none::NoDamage;
use crate::tensile::MaxTensileStress;
use serde::{Deserialize, Serialize};

/// One of the built-in damage models.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "model")]
pub enum BuiltinDamage {
    /// [`NoDamage`].
    None(NoDamage),
    /// [`MaxTensileStress`].
    MaxTensileStress(MaxTensileStress),
    /// [`BenzAsphaug`] with its flaws.
    BenzAsphaug(BenzAsphaug),
}

macro_rules! dispatch {
    ($self:ident, $m:ident => $e:expr) => {
        match $self {
            BuiltinDamage::None($m) => $e,
            BuiltinDamage::MaxTensileStress($m) => $e,
            BuiltinDamage::BenzAsphaug($m) => $e,
        }
    };
}

impl DamageModel for BuiltinDamage {
    fn name(&self) -> &str {
        dispatch!(self, m => m.name())
    }
    fn variable(&self) -> DamageVariable {
        dispatch!(self, m => m.variable())
    }
    fn activation_strain(&self) -> crate::ActivationStrain {
        dispatch!(self, m => m.activation_strain())
    }
    fn form(&self) -> crate::DamageForm {
        dispatch!(self, m => m.form())
    }
    #[inline]
    fn evaluate(&self, particle: usize, input: &DamageInput) -> DamageEval {
        dispatch!(self, m => m.evaluate(particle, input))
    }
    fn evaluate_if_quiet(&self, particle: usize, input: &DamageInput) -> Option<DamageEval> {
        dispatch!(self, m => m.evaluate_if_quiet(particle, input))
    }
    fn check_particles(&self, n_particles: usize) -> Result<(), DamageError> {
        dispatch!(self, m => m.check_particles(n_particles))
    }
}
