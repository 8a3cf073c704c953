//! Temperature from specific internal energy with latent heats of melting and vaporisation
//! (paper §3.1: a plateau at T_melt while the latent heat of melting is absorbed, another
//! at T_vap; the study reports the energies where melting and vaporisation start and end).
//!
//! A piecewise-linear caloric model with one constant specific heat c_v (J/kg/K), e
//! measured from the reference state (e = 0 at T = T_ref):
//!
//! | e (J/kg) | T (K) | melt fraction f_m | vapour fraction f_v |
//! |---|---|---|---|
//! | e < e_ms = c_v (T_melt − T_ref) | T_ref + e/c_v | 0 | 0 |
//! | e_ms ≤ e < e_mf = e_ms + L_melt | T_melt | (e − e_ms)/L_melt | 0 |
//! | e_mf ≤ e < e_vs = e_mf + c_v (T_vap − T_melt) | T_melt + (e − e_mf)/c_v | 1 | 0 |
//! | e_vs ≤ e < e_vf = e_vs + L_vap | T_vap | 1 | (e − e_vs)/L_vap |
//! | e ≥ e_vf | T_vap + (e − e_vf)/c_v | 1 | 1 |
//!
//! f_m counts all material that has melted (liquid and vapour), so the liquid fraction is
//! f_m − f_v. T, f_m and f_v are continuous and non-decreasing in e.
//!
//! **Below the reference state** (e < 0) the first line is extended linearly. Below
//! e_0K = −c_v T_ref it would give T < 0 K: [`ThermalModel::state`] then returns T = 0 K
//! with [`ThermalState::clamped_at_zero`] set ([`ThermalModel::temperature`] returns the
//! same clamped value; use `state` when the flag matters).
//!
//! Limits of the model: c_v is one constant for solid, liquid and vapour (real c_p of Al
//! rises from 0.90 to ~1.2 kJ/kg/K between 300 K and the melt); pressure does not shift
//! T_melt or T_vap (the plateaus are the 1-atm values), and the energy is the total specific
//! internal energy, including the cold compression energy, as in the study.

use crate::error::{EosError, check, non_negative, positive};
use serde::{Deserialize, Serialize};

/// Parameters of the caloric model (SI).
#[allow(non_snake_case)]
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalParams {
    /// Specific heat c_v, J/kg/K (> 0), used in every phase.
    pub c_v: f64,
    /// Temperature at e = 0, K (≥ 0).
    pub T_ref: f64,
    /// Melting temperature, K (> T_ref).
    pub T_melt: f64,
    /// Latent heat of melting, J/kg (> 0).
    pub L_melt: f64,
    /// Vaporisation (boiling) temperature, K (> T_melt).
    pub T_vap: f64,
    /// Latent heat of vaporisation, J/kg (> 0).
    pub L_vap: f64,
}

impl ThermalParams {
    /// Checks every field: c_v, L_melt, L_vap > 0 and 0 ≤ T_ref < T_melt < T_vap.
    pub fn validate(&self) -> Result<(), EosError> {
        positive("c_v", self.c_v)?;
        non_negative("T_ref", self.T_ref)?;
        check(
            "T_melt",
            self.T_melt,
            self.T_melt > self.T_ref,
            "must exceed T_ref",
        )?;
        positive("L_melt", self.L_melt)?;
        check(
            "T_vap",
            self.T_vap,
            self.T_vap > self.T_melt,
            "must exceed T_melt",
        )?;
        positive("L_vap", self.L_vap)
    }
}

/// Temperature and phase fractions at one specific energy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThermalState {
    /// Temperature, K.
    pub temperature: f64,
    /// Fraction that has melted (liquid + vapour), in [0, 1].
    pub melt_fraction: f64,
    /// Fraction vaporised, in [0, 1].
    pub vapour_fraction: f64,
    /// True when e < −c_v T_ref and the temperature was clamped at 0 K.
    pub clamped_at_zero: bool,
}

/// The caloric model. Construct with [`ThermalModel::new`] or a named material
/// ([`ThermalModel::aluminium`], [`ThermalModel::basalt`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThermalModel {
    p: ThermalParams,
    inv_cv: f64,
    e_ms: f64,
    e_mf: f64,
    e_vs: f64,
    e_vf: f64,
}

impl ThermalModel {
    /// Validates the parameters and precomputes the four threshold energies.
    pub fn new(params: ThermalParams) -> Result<Self, EosError> {
        params.validate()?;
        Ok(Self::from_valid(params))
    }

    /// For parameter sets known to be valid (the named materials; tested).
    pub(crate) fn from_valid(p: ThermalParams) -> Self {
        let e_ms = p.c_v * (p.T_melt - p.T_ref);
        let e_mf = e_ms + p.L_melt;
        let e_vs = e_mf + p.c_v * (p.T_vap - p.T_melt);
        Self {
            p,
            inv_cv: 1.0 / p.c_v,
            e_ms,
            e_mf,
            e_vs,
            e_vf: e_vs + p.L_vap,
        }
    }

    /// The parameters.
    pub fn params(&self) -> &ThermalParams {
        &self.p
    }

    /// e_ms = c_v (T_melt − T_ref): melting starts, J/kg.
    pub fn incipient_melting_energy(&self) -> f64 {
        self.e_ms
    }

    /// e_mf = e_ms + L_melt: melting complete, J/kg.
    pub fn complete_melting_energy(&self) -> f64 {
        self.e_mf
    }

    /// e_vs = e_mf + c_v (T_vap − T_melt): vaporisation starts, J/kg.
    pub fn incipient_vaporisation_energy(&self) -> f64 {
        self.e_vs
    }

    /// e_vf = e_vs + L_vap: vaporisation complete, J/kg.
    pub fn complete_vaporisation_energy(&self) -> f64 {
        self.e_vf
    }

    /// Energy of 0 K, −c_v T_ref (J/kg): below it the temperature is clamped.
    pub fn zero_kelvin_energy(&self) -> f64 {
        -self.p.c_v * self.p.T_ref
    }

    /// Temperature and phase fractions at specific internal energy `e` (J/kg). A NaN e
    /// gives NaN in every field.
    #[inline]
    pub fn state(&self, e: f64) -> ThermalState {
        let p = &self.p;
        let (temperature, melt_fraction, vapour_fraction) = if e.is_nan() {
            (f64::NAN, f64::NAN, f64::NAN)
        } else if e < self.e_ms {
            let t = p.T_ref + e * self.inv_cv;
            if t < 0.0 {
                return ThermalState {
                    temperature: 0.0,
                    melt_fraction: 0.0,
                    vapour_fraction: 0.0,
                    clamped_at_zero: true,
                };
            }
            (t, 0.0, 0.0)
        } else if e < self.e_mf {
            (p.T_melt, (e - self.e_ms) / p.L_melt, 0.0)
        } else if e < self.e_vs {
            (p.T_melt + (e - self.e_mf) * self.inv_cv, 1.0, 0.0)
        } else if e < self.e_vf {
            (p.T_vap, 1.0, (e - self.e_vs) / p.L_vap)
        } else {
            (p.T_vap + (e - self.e_vf) * self.inv_cv, 1.0, 1.0)
        };
        ThermalState {
            temperature,
            melt_fraction,
            vapour_fraction,
            clamped_at_zero: false,
        }
    }

    /// Temperature in K at `e` (clamped at 0 K below [`Self::zero_kelvin_energy`]; see
    /// [`Self::state`] for the flag).
    #[inline]
    pub fn temperature(&self, e: f64) -> f64 {
        self.state(e).temperature
    }

    /// Melted fraction (liquid + vapour) in [0, 1] at `e`.
    #[inline]
    pub fn melt_fraction(&self, e: f64) -> f64 {
        self.state(e).melt_fraction
    }

    /// Vaporised fraction in [0, 1] at `e`.
    #[inline]
    pub fn vapour_fraction(&self, e: f64) -> f64 {
        self.state(e).vapour_fraction
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_names_the_field() {
        let good = ThermalParams {
            c_v: 900.0,
            T_ref: 300.0,
            T_melt: 933.0,
            L_melt: 4e5,
            T_vap: 2792.0,
            L_vap: 1e7,
        };
        assert!(ThermalModel::new(good).is_ok());
        type Breaker = (&'static str, fn(&mut ThermalParams));
        let cases: [Breaker; 5] = [
            ("c_v", |p| p.c_v = 0.0),
            ("T_melt", |p| p.T_melt = p.T_ref),
            ("T_vap", |p| p.T_vap = p.T_melt - 1.0),
            ("L_melt", |p| p.L_melt = -1.0),
            ("L_vap", |p| p.L_vap = f64::NAN),
        ];
        for (field, break_it) in cases {
            let mut p = good;
            break_it(&mut p);
            match ThermalModel::new(p) {
                Err(EosError::Parameter { field: f, .. }) => assert_eq!(f, field),
                other => panic!("{field}: {other:?}"),
            }
        }
    }
}
