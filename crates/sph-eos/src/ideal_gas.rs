//! Ideal (γ-law) gas: P = (γ − 1) ρ e.
//!
//! Derivatives: ∂P/∂ρ|_e = (γ − 1) e, ∂P/∂e|_ρ = (γ − 1) ρ, so c² = γ (γ − 1) e = γP/ρ.
//!
//! Valid for ρ > 0 and e ≥ 0. For e < 0 the formula still gives P < 0 and c² < 0; the sound
//! speed is then the floor (default 0 m/s) with [`crate::EosPoint::sound_speed_floored`] set.

use crate::eos::{EosPoint, EquationOfState};
use crate::error::{EosError, check, non_negative};
use serde::{Deserialize, Serialize};

/// Parameters of the ideal gas.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IdealGasParams {
    /// Ratio of specific heats γ (> 1), e.g. 5/3 for a monatomic gas, 1.4 for air.
    pub gamma: f64,
}

/// The ideal-gas EOS. Construct with [`IdealGas::new`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IdealGas {
    gamma: f64,
    gm1: f64,
    c_floor: f64,
}

impl IdealGas {
    /// Validates γ > 1 (finite). The sound-speed floor is 0 m/s.
    pub fn new(params: IdealGasParams) -> Result<Self, EosError> {
        check("gamma", params.gamma, params.gamma > 1.0, "must exceed 1")?;
        Ok(Self {
            gamma: params.gamma,
            gm1: params.gamma - 1.0,
            c_floor: 0.0,
        })
    }

    /// Shorthand for `IdealGas::new(IdealGasParams { gamma })`.
    pub fn with_gamma(gamma: f64) -> Result<Self, EosError> {
        Self::new(IdealGasParams { gamma })
    }

    /// Sets an absolute sound-speed floor in m/s (≥ 0). The ideal gas has no reference
    /// sound speed, so the floor is absolute; it acts only where γ(γ−1)e < c_floor².
    pub fn with_min_sound_speed(mut self, c_floor: f64) -> Result<Self, EosError> {
        non_negative("min_sound_speed", c_floor)?;
        self.c_floor = c_floor;
        Ok(self)
    }

    /// γ.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// The parameters.
    pub fn params(&self) -> IdealGasParams {
        IdealGasParams { gamma: self.gamma }
    }

    /// The sound-speed floor, m/s.
    pub fn sound_speed_floor(&self) -> f64 {
        self.c_floor
    }
}

impl EquationOfState for IdealGas {
    fn name(&self) -> &str {
        "ideal-gas"
    }

    fn reference_density(&self) -> Option<f64> {
        None
    }

    #[inline]
    fn pressure(&self, rho: f64, e: f64) -> f64 {
        self.gm1 * rho * e
    }

    #[inline]
    fn evaluate(&self, rho: f64, e: f64) -> EosPoint {
        EosPoint::from_derivatives(
            rho,
            self.gm1 * rho * e,
            self.gm1 * e,
            self.gm1 * rho,
            self.c_floor,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_must_exceed_one() {
        for g in [1.0, 0.5, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                IdealGas::with_gamma(g),
                Err(EosError::Parameter { field: "gamma", .. })
            ));
        }
        assert!(
            IdealGas::with_gamma(1.4)
                .unwrap()
                .with_min_sound_speed(-1.0)
                .is_err()
        );
    }
}
