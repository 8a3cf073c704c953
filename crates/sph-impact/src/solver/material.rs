//! The material table the solver reads: one entry per material id.

use sph_eos::{EquationOfState, ThermalModel};
use sph_strength::StrengthModel;
use std::sync::Arc;

/// A material as the solver sees it: an EOS, and for a solid a strength model (with the
/// thermal model its temperature comes from). Damage joins in the solid-dynamics work.
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
}

impl Material {
    /// A fluid material.
    pub fn fluid(name: impl Into<String>, eos: impl EquationOfState + 'static) -> Self {
        Self {
            name: name.into(),
            eos: Arc::new(eos),
            strength: None,
            thermal: None,
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
        }
    }

    /// Adds a thermal model.
    pub fn with_thermal(mut self, thermal: ThermalModel) -> Self {
        self.thermal = Some(thermal);
        self
    }
}
