//! The material table the solver reads: one entry per material id.

use sph_eos::EquationOfState;
use std::sync::Arc;

/// A material as the hydrodynamic solver sees it. Strength, damage and thermal models
/// join in the solid-dynamics work; a fluid needs only its EOS.
#[derive(Clone, Debug)]
pub struct Material {
    /// Name for messages and output.
    pub name: String,
    /// Equation of state.
    pub eos: Arc<dyn EquationOfState>,
}

impl Material {
    /// A fluid material.
    pub fn fluid(name: impl Into<String>, eos: impl EquationOfState + 'static) -> Self {
        Self {
            name: name.into(),
            eos: Arc::new(eos),
        }
    }
}
