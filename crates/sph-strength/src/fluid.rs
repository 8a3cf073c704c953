//! No strength: fluids (gas, melt, water). G = 0, Y = 0 and
//! [`StrengthModel::has_strength`] is false, so the solver skips the deviatoric stress
//! and pays nothing for it (design.md, "model only what the scene needs").

use crate::model::{StrengthModel, StrengthState};
use serde::{Deserialize, Serialize};

/// A material without shear strength.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct NoStrength;

impl StrengthModel for NoStrength {
    fn name(&self) -> &str {
        "none"
    }
    #[inline]
    fn shear_modulus(&self, _s: &StrengthState) -> f64 {
        0.0
    }
    #[inline]
    fn intact_yield(&self, _s: &StrengthState) -> f64 {
        0.0
    }
    #[inline]
    fn yield_strength(&self, _s: &StrengthState) -> f64 {
        0.0
    }
    fn has_strength(&self) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fluid_has_no_strength() {
        let s = StrengthState::new(1.0e9, 1000.0, 300.0);
        assert_eq!(NoStrength.shear_modulus(&s), 0.0);
        assert_eq!(NoStrength.intact_yield(&s), 0.0);
        assert_eq!(NoStrength.yield_strength(&s), 0.0);
        assert!(!NoStrength.has_strength());
    }
}
