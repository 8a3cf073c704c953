//! Drucker–Prager (pressure-linear) strength, paper §3.2:
//!
//!   `Y_i = Y0 + μ P`, capped at the limit strength `Y_M`,
//!
//! the μP-linear limit of the Lundborg curve (docs/reference/strength_point_values.md,
//! "Lundborg granite and radial return"). Damage weakening is frictional, eq. (13):
//! `Y = Y_d D + Y_i (1 − D)`, `Y_d = min(μ_d P, Y_i)` ([`crate::weakening`]).
//!
//! In tension the line is followed down to zero strength at P = −Y0/μ and Y_i = 0
//! below that (a cohesive material cannot have negative shear strength; miluphcuda's
//! Drucker–Prager does the same: "the yield strength simply decreases (linearly) to zero
//! for p < 0").

use crate::error::{Check, StrengthError};
use crate::model::{StrengthModel, StrengthState};
use crate::weakening::frictional_weakening;
use serde::{Deserialize, Serialize};

/// Parameters of [`DruckerPrager`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct DruckerPragerParams {
    /// Cohesion Y0, the shear strength at zero pressure (Pa), ≥ 0.
    pub cohesion: f64,
    /// Internal friction coefficient μ of intact material, ≥ 0.
    pub friction: f64,
    /// Limit strength Y_M (Pa), ≥ Y0; `f64::INFINITY` for no cap.
    pub limit_strength: f64,
    /// Friction coefficient μ_d of fully damaged material, ≥ 0.
    pub damaged_friction: f64,
    /// Shear modulus G (Pa), > 0.
    pub shear_modulus: f64,
}

/// Pressure-linear strength capped at Y_M.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "DruckerPragerParams", into = "DruckerPragerParams")]
pub struct DruckerPrager {
    params: DruckerPragerParams,
}

impl DruckerPrager {
    /// Validates the parameters.
    pub fn new(params: DruckerPragerParams) -> Result<Self, StrengthError> {
        let c = Check {
            model: "drucker-prager",
        };
        c.non_negative("cohesion", params.cohesion)?;
        c.non_negative("friction", params.friction)?;
        c.require(
            params.limit_strength >= params.cohesion,
            "limit_strength",
            params.limit_strength,
            "must be at least the cohesion (or +inf for no cap)",
        )?;
        c.non_negative("damaged_friction", params.damaged_friction)?;
        c.positive("shear_modulus", params.shear_modulus)?;
        Ok(Self { params })
    }

    /// The parameters.
    pub fn params(&self) -> &DruckerPragerParams {
        &self.params
    }
}

crate::params_conversions!(DruckerPrager, DruckerPragerParams);

impl StrengthModel for DruckerPrager {
    fn name(&self) -> &str {
        "drucker-prager"
    }
    #[inline]
    fn shear_modulus(&self, _s: &StrengthState) -> f64 {
        self.params.shear_modulus
    }
    #[inline]
    fn intact_yield(&self, s: &StrengthState) -> f64 {
        let p = &self.params;
        (p.cohesion + p.friction * s.pressure)
            .max(0.0)
            .min(p.limit_strength)
    }
    #[inline]
    fn yield_strength(&self, s: &StrengthState) -> f64 {
        frictional_weakening(
            self.intact_yield(s),
            self.params.damaged_friction,
            s.pressure,
            s.damage,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn granite_dp() -> DruckerPrager {
        DruckerPrager::new(DruckerPragerParams {
            cohesion: 90.0e6,
            friction: 2.0,
            limit_strength: 1.5e9,
            damaged_friction: 0.8,
            shear_modulus: 27.0e9,
        })
        .unwrap()
    }

    fn at(p: f64) -> StrengthState {
        StrengthState::new(p, 2630.0, 300.0)
    }

    #[test]
    fn linear_then_capped() {
        let m = granite_dp();
        // 90 + 2·50 = 190 MPa; 90 + 2·500 = 1090 MPa; 90 + 2·5000 → capped at 1500 MPa.
        assert!((m.intact_yield(&at(50.0e6)) - 190.0e6).abs() < 1e-6);
        assert!((m.intact_yield(&at(500.0e6)) - 1090.0e6).abs() < 1e-6);
        assert_eq!(m.intact_yield(&at(5.0e9)), 1.5e9);
        // Tension: zero at P = −Y0/μ = −45 MPa and below.
        assert!((m.intact_yield(&at(-20.0e6)) - 50.0e6).abs() < 1e-6);
        assert_eq!(m.intact_yield(&at(-45.0e6)), 0.0);
        assert_eq!(m.intact_yield(&at(-1.0e9)), 0.0);
    }

    #[test]
    fn fully_damaged_is_damaged_friction() {
        let m = granite_dp();
        let mut s = at(500.0e6);
        s.damage = 1.0;
        assert!((m.yield_strength(&s) - 400.0e6).abs() < 1e-6);
    }

    #[test]
    fn rejects_limit_below_cohesion() {
        let mut p = *granite_dp().params();
        p.limit_strength = 1.0e6;
        assert!(matches!(
            DruckerPrager::new(p),
            Err(StrengthError::Parameter {
                field: "limit_strength",
                ..
            })
        ));
        p.limit_strength = f64::NAN;
        assert!(DruckerPrager::new(p).is_err());
    }
}
