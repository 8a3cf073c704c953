//! The material table the solver reads: one entry per material id.

use sph_damage::{DamageModel, PlasticFailure};
use sph_eos::{EquationOfState, ThermalModel};
use sph_strength::StrengthModel;
use std::sync::Arc;

/// A material as the solver sees it: an EOS, and for a solid a strength model (with the
/// thermal model its temperature comes from) and optionally a damage model.
///
/// A damage model with per-particle state (Benz–Asphaug flaws) belongs to one body: its
/// particle index is the particle's rank among the particles of this material, in the
/// order they are given to [`crate::Simulation::new`]. Two bodies of the same rock with
/// their own flaws are two materials.
#[derive(Clone, Debug)]
pub struct Material {
    /// Name for messages and output.
    pub name: String,
    /// Equation of state.
    pub eos: Arc<dyn EquationOfState>,
    /// Strength model; `None` for a fluid (no deviatoric stress is carried).
    pub strength: Option<Arc<dyn StrengthModel>>,
    /// Temperature from specific energy (for temperature-dependent strength); `None`
    /// holds the temperature at 300 K.
    pub thermal: Option<ThermalModel>,
    /// Damage model (paper §3.3); `None` for none. Only solids can be damaged.
    pub damage: Option<Arc<dyn DamageModel>>,
    /// Shear failure (sph_damage::shear_failure): plastic strain adds dε_p/ε_f(P) to the
    /// damage. Needs a scalar damage model, whose D it raises; `None` for none.
    pub shear_failure: Option<PlasticFailure>,
}

impl Material {
    /// A fluid material.
    pub fn fluid(name: impl Into<String>, eos: impl EquationOfState + 'static) -> Self {
        Self {
            name: name.into(),
            eos: Arc::new(eos),
            strength: None,
            thermal: None,
            damage: None,
            shear_failure: None,
        }
    }

    /// A solid with the given strength model (a model whose `has_strength()` is false
    /// makes it a fluid).
    pub fn solid(
        name: impl Into<String>,
        eos: impl EquationOfState + 'static,
        strength: impl StrengthModel + 'static,
    ) -> Self {
        let strength: Arc<dyn StrengthModel> = Arc::new(strength);
        let strength = strength.has_strength().then_some(strength);
        Self {
            name: name.into(),
            eos: Arc::new(eos),
            strength,
            thermal: None,
            damage: None,
            shear_failure: None,
        }
    }

    /// Adds a damage model.
    pub fn with_damage(mut self, damage: impl DamageModel + 'static) -> Self {
        self.damage = Some(Arc::new(damage));
        self
    }

    /// Adds shear failure (needs a scalar damage model: [`crate::Simulation::new`]
    /// rejects it otherwise).
    pub fn with_shear_failure(mut self, law: PlasticFailure) -> Self {
        self.shear_failure = Some(law);
        self
    }

    /// Adds a thermal model.
    pub fn with_thermal(mut self, thermal: ThermalModel) -> Self {
        self.thermal = Some(thermal);
        self
    }
}
