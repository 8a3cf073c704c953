//! Constant (von Mises) strength, paper §3.2: `Y_i = Y0`, optionally with linear
//! isotropic hardening `Y_i = Y0 + H ε_p` (the bilinear copper of the Taylor-bar
//! benchmark, docs/verification.md, "Taylor bar": Y0 = 400 MPa, H = 100 MPa). Damage weakening is
//! multiplicative, eq. (12): `Y = Y_i (1 − D)`.
//!
//! H here is the *plastic* hardening modulus dY/dε_p. FE codes that quote a "tangent
//! modulus" E_t of the bilinear σ–ε curve mean H = E E_t / (E − E_t); for the Taylor bar
//! (E = 117 GPa, E_t = 100 MPa) that is 100.09 MPa, a 0.09 % difference.

use crate::error::{Check, StrengthError};
use crate::model::{StrengthModel, StrengthState};
use crate::weakening::multiplicative_weakening;
use serde::{Deserialize, Serialize};

/// Linear isotropic hardening: Y grows by `modulus · ε_p`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LinearHardening {
    /// Plastic hardening modulus H = dY/dε_p (Pa), ≥ 0.
    pub modulus: f64,
}

/// Parameters of [`VonMises`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct VonMisesParams {
    /// Yield strength Y0 (Pa), ≥ 0.
    pub yield_strength: f64,
    /// Shear modulus G (Pa), > 0.
    pub shear_modulus: f64,
    /// Optional linear hardening; `None` is perfectly plastic.
    #[serde(default)]
    pub hardening: Option<LinearHardening>,
}

/// Constant yield strength, optionally linearly hardening.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "VonMisesParams", into = "VonMisesParams")]
pub struct VonMises {
    params: VonMisesParams,
    hardening_modulus: f64,
}

impl VonMises {
    /// Validates the parameters.
    pub fn new(params: VonMisesParams) -> Result<Self, StrengthError> {
        let c = Check { model: "von-mises" };
        c.non_negative("yield_strength", params.yield_strength)?;
        c.positive("shear_modulus", params.shear_modulus)?;
        let hardening_modulus = match params.hardening {
            Some(h) => {
                c.non_negative("hardening.modulus", h.modulus)?;
                h.modulus
            }
            None => 0.0,
        };
        Ok(Self {
            params,
            hardening_modulus,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &VonMisesParams {
        &self.params
    }
}

crate::params_conversions!(VonMises, VonMisesParams);

impl StrengthModel for VonMises {
    fn name(&self) -> &str {
        "von-mises"
    }
    #[inline]
    fn shear_modulus(&self, _s: &StrengthState) -> f64 {
        self.params.shear_modulus
    }
    #[inline]
    fn intact_yield(&self, s: &StrengthState) -> f64 {
        self.params.yield_strength + self.hardening_modulus * s.plastic_strain
    }
    #[inline]
    fn yield_strength(&self, s: &StrengthState) -> f64 {
        multiplicative_weakening(self.intact_yield(s), s.damage)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn taylor() -> VonMises {
        VonMises::new(crate::materials::TAYLOR_BAR_COPPER).unwrap()
    }

    #[test]
    fn linear_hardening_point_values() {
        let m = taylor();
        let mut s = StrengthState::new(0.0, 8930.0, 300.0);
        assert_eq!(m.yield_strength(&s), 400.0e6);
        // ε_p = 2.5 (centre of the impact face): 400 + 100·2.5 = 650 MPa.
        s.plastic_strain = 2.5;
        assert!((m.yield_strength(&s) - 650.0e6).abs() < 1e-6);
        // D = 0.5 halves it (eq. 12).
        s.damage = 0.5;
        assert!((m.yield_strength(&s) - 325.0e6).abs() < 1e-6);
    }

    #[test]
    fn perfectly_plastic_ignores_strain() {
        let m = VonMises::new(VonMisesParams {
            yield_strength: 0.29e9,
            shear_modulus: 26.92e9,
            hardening: None,
        })
        .unwrap();
        let mut s = StrengthState::new(1.0e9, 2700.0, 300.0);
        s.plastic_strain = 3.0;
        assert_eq!(m.yield_strength(&s), 0.29e9);
    }

    #[test]
    fn rejects_bad_parameters() {
        let mut p = crate::materials::TAYLOR_BAR_COPPER;
        p.shear_modulus = 0.0;
        let e = VonMises::new(p).unwrap_err();
        assert!(matches!(
            e,
            StrengthError::Parameter {
                field: "shear_modulus",
                ..
            }
        ));
        let mut p = crate::materials::TAYLOR_BAR_COPPER;
        p.hardening = Some(LinearHardening { modulus: f64::NAN });
        let e = VonMises::new(p).unwrap_err();
        assert!(matches!(
            e,
            StrengthError::Parameter {
                field: "hardening.modulus",
                ..
            }
        ));
    }
}
