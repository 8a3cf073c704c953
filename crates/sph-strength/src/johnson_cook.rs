//! Johnson–Cook strength (Johnson & Cook 1983, Proc. 7th Int. Symp. Ballistics, 541):
//!
//!   `Y_i = [A + B ε_p^n] [1 + C ln ε̇*] [1 − T*^m]`,
//!
//! with the dimensionless plastic strain rate ε̇* = ε̇_p / ε̇0 (reference rate ε̇0,
//! commonly 1 /s) and the homologous temperature T* = (T − T_r)/(T_m − T_r). Damage
//! weakening is multiplicative, eq. (12): `Y = Y_i (1 − D)` (paper §3.2).
//!
//! Conventions (each documented because codes differ):
//!
//! - **Rate term only above the reference rate.** For ε̇* ≤ 1 the factor is 1: below
//!   ε̇0 the logarithm is negative and diverges as ε̇ → 0 (at rest), which the fit was
//!   never meant to describe (Johnson & Cook fitted ε̇ ≥ ε̇0).
//! - **T* is clamped to [0, 1] after the division**: below T_r the material is taken as
//!   at T_r (T*^m with T* < 0 and non-integer m is not a real number), and
//! - **Y = 0 when melted, T ≥ T_m** (where the clamped T* = 1 gives 1 − T*^m = 0 anyway;
//!   the explicit branch makes it exact and cheap).

use crate::error::{Check, StrengthError};
use crate::model::{StrengthModel, StrengthState};
use crate::weakening::multiplicative_weakening;
use serde::{Deserialize, Serialize};

fn one_per_second() -> f64 {
    1.0
}

/// Parameters of [`JohnsonCook`], named as in Johnson & Cook 1983.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct JohnsonCookParams {
    /// A, the yield strength at zero plastic strain, reference rate and temperature (Pa), ≥ 0.
    pub a: f64,
    /// B, the strain-hardening coefficient (Pa), ≥ 0.
    pub b: f64,
    /// n, the strain-hardening exponent, > 0.
    pub n: f64,
    /// C, the strain-rate coefficient, ≥ 0.
    pub c: f64,
    /// m, the thermal-softening exponent, > 0.
    pub m: f64,
    /// T_m, the melt temperature (K), > T_r.
    pub melt_temperature: f64,
    /// T_r, the reference (room) temperature (K), ≥ 0.
    pub reference_temperature: f64,
    /// ε̇0, the reference plastic strain rate (1/s), > 0; default 1 /s.
    #[serde(default = "one_per_second")]
    pub reference_strain_rate: f64,
    /// Shear modulus G (Pa), > 0 (constant in this model).
    pub shear_modulus: f64,
}

/// Johnson–Cook strain-, rate- and temperature-dependent strength.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "JohnsonCookParams", into = "JohnsonCookParams")]
pub struct JohnsonCook {
    params: JohnsonCookParams,
    inv_rate0: f64,
    inv_dt: f64,
}

impl JohnsonCook {
    /// Validates the parameters.
    pub fn new(params: JohnsonCookParams) -> Result<Self, StrengthError> {
        let c = Check {
            model: "johnson-cook",
        };
        c.non_negative("a", params.a)?;
        c.non_negative("b", params.b)?;
        c.positive("n", params.n)?;
        c.non_negative("c", params.c)?;
        c.positive("m", params.m)?;
        c.non_negative("reference_temperature", params.reference_temperature)?;
        c.finite("melt_temperature", params.melt_temperature)?;
        c.require(
            params.melt_temperature > params.reference_temperature,
            "melt_temperature",
            params.melt_temperature,
            "must exceed the reference temperature",
        )?;
        c.positive("reference_strain_rate", params.reference_strain_rate)?;
        c.positive("shear_modulus", params.shear_modulus)?;
        Ok(Self {
            params,
            inv_rate0: 1.0 / params.reference_strain_rate,
            inv_dt: 1.0 / (params.melt_temperature - params.reference_temperature),
        })
    }

    /// The parameters.
    pub fn params(&self) -> &JohnsonCookParams {
        &self.params
    }

    /// Homologous temperature T* = (T − T_r)/(T_m − T_r), clamped to [0, 1] after the
    /// division.
    #[inline]
    pub fn homologous_temperature(&self, temperature: f64) -> f64 {
        ((temperature - self.params.reference_temperature) * self.inv_dt).clamp(0.0, 1.0)
    }
}

crate::params_conversions!(JohnsonCook, JohnsonCookParams);

impl StrengthModel for JohnsonCook {
    fn name(&self) -> &str {
        "johnson-cook"
    }
    #[inline]
    fn shear_modulus(&self, _s: &StrengthState) -> f64 {
        self.params.shear_modulus
    }
    #[inline]
    fn intact_yield(&self, s: &StrengthState) -> f64 {
        let p = &self.params;
        if s.temperature >= p.melt_temperature {
            return 0.0;
        }
        let hardening = p.a + p.b * s.plastic_strain.powf(p.n);
        let rate = s.plastic_strain_rate * self.inv_rate0;
        let rate_factor = if rate > 1.0 {
            1.0 + p.c * rate.ln()
        } else {
            1.0
        };
        let t_star = self.homologous_temperature(s.temperature);
        let thermal = if t_star > 0.0 {
            1.0 - t_star.powf(p.m)
        } else {
            1.0
        };
        hardening * rate_factor * thermal
    }
    #[inline]
    fn yield_strength(&self, s: &StrengthState) -> f64 {
        multiplicative_weakening(self.intact_yield(s), s.damage)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::materials::ALUMINIUM_2024_JC_MEASURED;

    #[test]
    fn reference_state_gives_a() {
        let m = JohnsonCook::new(ALUMINIUM_2024_JC_MEASURED).unwrap();
        let s = StrengthState::new(0.0, 2785.0, 300.0);
        assert_eq!(m.yield_strength(&s), 2.65e8);
    }

    #[test]
    fn rate_term_only_above_reference_rate() {
        let m = JohnsonCook::new(ALUMINIUM_2024_JC_MEASURED).unwrap();
        let mut s = StrengthState::new(0.0, 2785.0, 300.0);
        s.plastic_strain_rate = 0.5;
        assert_eq!(m.yield_strength(&s), 2.65e8);
        // ε̇ = e² /s: factor 1 + 0.015·2 = 1.03.
        s.plastic_strain_rate = std::f64::consts::E * std::f64::consts::E;
        assert!((m.yield_strength(&s) - 2.65e8 * 1.03).abs() < 1e-3);
    }

    #[test]
    fn temperature_clamped_and_melt_zero() {
        let m = JohnsonCook::new(ALUMINIUM_2024_JC_MEASURED).unwrap();
        // Below T_r: T* = 0 (not NaN).
        assert_eq!(m.homologous_temperature(100.0), 0.0);
        let cold = StrengthState::new(0.0, 2785.0, 100.0);
        assert_eq!(m.yield_strength(&cold), 2.65e8);
        // Halfway (m = 1): Y = A/2.
        let half = StrengthState::new(0.0, 2785.0, 617.5);
        assert!((m.yield_strength(&half) - 1.325e8).abs() < 1e-3);
        // At and above T_m: zero.
        assert_eq!(
            m.yield_strength(&StrengthState::new(0.0, 2785.0, 935.0)),
            0.0
        );
        assert_eq!(
            m.yield_strength(&StrengthState::new(0.0, 2785.0, 5000.0)),
            0.0
        );
    }

    #[test]
    fn rejects_bad_parameters() {
        let mut p = ALUMINIUM_2024_JC_MEASURED;
        p.melt_temperature = 250.0;
        assert!(matches!(
            JohnsonCook::new(p),
            Err(StrengthError::Parameter {
                field: "melt_temperature",
                ..
            })
        ));
        let mut p = ALUMINIUM_2024_JC_MEASURED;
        p.reference_strain_rate = 0.0;
        assert!(matches!(
            JohnsonCook::new(p),
            Err(StrengthError::Parameter {
                field: "reference_strain_rate",
                ..
            })
        ));
        let mut p = ALUMINIUM_2024_JC_MEASURED;
        p.n = 0.0;
        assert!(matches!(
            JohnsonCook::new(p),
            Err(StrengthError::Parameter { field: "n", .. })
        ));
    }
}
