//! Steinberg–Guinan strength (Steinberg, Cochran & Guinan 1980, J. Appl. Phys. 51:1498,
//! eqs 1–3; the rate-independent high-strain-rate form), paper §3.2:
//!
//!   `G = G0 [1 + A P η^(−1/3) − B (T − 300 K)]`,
//!   `Y_i = Y0 (1 + β (ε_p + ε_i))^n [1 + A P η^(−1/3) − B (T − 300 K)]`,
//!   with `Y0 (1 + β (ε_p + ε_i))^n ≤ Y_max`,
//!
//! η = ρ/ρ0 the compression, ε_i the initial plastic strain, and the published
//! derivatives G'_p = G0·A, G'_T = −G0·B, Y'_p = Y0·A (SCG 1980 take Y/G constant apart
//! from work hardening, so Y and G share one bracket). Damage weakening is multiplicative,
//! eq. (12): `Y = Y_i (1 − D)`.
//!
//! **Melting:** G = Y = 0 for T ≥ T_m (SCG 1980). T_m is T_m0 by default; with a
//! [`SgMeltLaw`] it follows the SCG modified Lindemann law
//! `T_m = T_m0 exp[2a (1 − 1/η)] η^(2(γ0 − a − 1/3))` (SCG 1980 eq. 5).
//! Note that T_m0 is a fit parameter of that law, not the handbook melting point (copper:
//! T_m0 = 1790 K, Steinberg 1996, against 1358 K at 1 atm).
//!
//! The bracket is clamped at zero (documented, physical): a negative modulus is
//! meaningless, and it is reached only far outside the fit (deep tension with
//! P < −1/(A η^(−1/3)), about −35 GPa for copper, or T above 300 K + 1/B).

use crate::error::{Check, StrengthError};
use crate::model::{StrengthModel, StrengthPoint, StrengthState};
use crate::weakening::multiplicative_weakening;
use serde::{Deserialize, Serialize};

/// SCG 1980 reference temperature of the bracket (K).
pub const SG_REFERENCE_TEMPERATURE: f64 = 300.0;

/// Pressure (compression) dependence of the melt temperature, SCG 1980 eq. 5.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SgMeltLaw {
    /// γ0, the Grüneisen coefficient at the reference density.
    pub gamma0: f64,
    /// a, the first-order volume correction to γ (γ = γ0 − a (1 − 1/η)).
    pub a: f64,
}

/// Parameters of [`SteinbergGuinan`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SteinbergGuinanParams {
    /// G0, the shear modulus at P = 0, T = 300 K (Pa), > 0.
    pub shear_modulus: f64,
    /// A = G'_p/G0 = Y'_p/Y0 (1/Pa), ≥ 0.
    pub pressure_coefficient: f64,
    /// B = −G'_T/G0 (1/K), ≥ 0.
    pub temperature_coefficient: f64,
    /// Y0, the yield strength at zero plastic strain, P = 0, T = 300 K (Pa), ≥ 0.
    pub yield_strength: f64,
    /// Y_max, the cap on the work-hardened Y0 (1 + βε)^n (Pa), ≥ Y0.
    pub max_yield_strength: f64,
    /// β, the work-hardening coefficient, ≥ 0.
    pub hardening_coefficient: f64,
    /// n, the work-hardening exponent, ≥ 0.
    pub hardening_exponent: f64,
    /// ε_i, the initial equivalent plastic strain, ≥ 0.
    #[serde(default)]
    pub initial_plastic_strain: f64,
    /// ρ0, the reference density for η = ρ/ρ0 (kg/m³), > 0.
    pub reference_density: f64,
    /// T_m0, the melt temperature at ρ0 (K), > 0.
    pub melt_temperature: f64,
    /// Optional compression dependence of T_m; `None` keeps T_m = T_m0.
    #[serde(default)]
    pub melt_law: Option<SgMeltLaw>,
}

impl SteinbergGuinanParams {
    /// Builds the parameters from the published derivatives G'_p = dG/dP
    /// (dimensionless), G'_T = dG/dT (Pa/K) as in SCG 1980 and Steinberg 1996 tables.
    /// Y'_p is implied (Y'_p = Y0 G'_p/G0); check a table's Y'_p against
    /// `yield_strength · pressure_coefficient`.
    pub fn from_derivatives(
        g0: f64,
        dg_dp: f64,
        dg_dt: f64,
        y0: f64,
        y_max: f64,
        beta: f64,
        n: f64,
        reference_density: f64,
        melt_temperature: f64,
    ) -> Self {
        Self {
            shear_modulus: g0,
            pressure_coefficient: dg_dp / g0,
            temperature_coefficient: -dg_dt / g0,
            yield_strength: y0,
            max_yield_strength: y_max,
            hardening_coefficient: beta,
            hardening_exponent: n,
            initial_plastic_strain: 0.0,
            reference_density,
            melt_temperature,
            melt_law: None,
        }
    }
}

/// Steinberg–Guinan pressure-, temperature- and strain-dependent G and Y.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "SteinbergGuinanParams", into = "SteinbergGuinanParams")]
pub struct SteinbergGuinan {
    params: SteinbergGuinanParams,
    inv_rho0: f64,
}

impl SteinbergGuinan {
    /// Validates the parameters.
    pub fn new(params: SteinbergGuinanParams) -> Result<Self, StrengthError> {
        let c = Check {
            model: "steinberg-guinan",
        };
        c.positive("shear_modulus", params.shear_modulus)?;
        c.non_negative("pressure_coefficient", params.pressure_coefficient)?;
        c.non_negative("temperature_coefficient", params.temperature_coefficient)?;
        c.non_negative("yield_strength", params.yield_strength)?;
        c.finite("max_yield_strength", params.max_yield_strength)?;
        c.require(
            params.max_yield_strength >= params.yield_strength,
            "max_yield_strength",
            params.max_yield_strength,
            "must be at least yield_strength",
        )?;
        c.non_negative("hardening_coefficient", params.hardening_coefficient)?;
        c.non_negative("hardening_exponent", params.hardening_exponent)?;
        c.non_negative("initial_plastic_strain", params.initial_plastic_strain)?;
        c.positive("reference_density", params.reference_density)?;
        c.positive("melt_temperature", params.melt_temperature)?;
        if let Some(law) = params.melt_law {
            c.finite("melt_law.gamma0", law.gamma0)?;
            c.finite("melt_law.a", law.a)?;
        }
        Ok(Self {
            params,
            inv_rho0: 1.0 / params.reference_density,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &SteinbergGuinanParams {
        &self.params
    }

    /// Melt temperature T_m (K) at density ρ: T_m0, or the SCG law if configured.
    #[inline]
    pub fn melt_temperature(&self, density: f64) -> f64 {
        let p = &self.params;
        match p.melt_law {
            None => p.melt_temperature,
            Some(law) => {
                let eta = density * self.inv_rho0;
                p.melt_temperature
                    * (2.0 * law.a * (1.0 - 1.0 / eta)).exp()
                    * eta.powf(2.0 * (law.gamma0 - law.a - 1.0 / 3.0))
            }
        }
    }

    /// The shared bracket 1 + A P η^(−1/3) − B (T − 300), clamped at 0; `None` when
    /// melted.
    #[inline]
    fn bracket(&self, s: &StrengthState) -> Option<f64> {
        if s.temperature >= self.melt_temperature(s.density) {
            return None;
        }
        let p = &self.params;
        let eta = s.density * self.inv_rho0;
        let b = 1.0 + p.pressure_coefficient * s.pressure / eta.cbrt()
            - p.temperature_coefficient * (s.temperature - SG_REFERENCE_TEMPERATURE);
        Some(b.max(0.0))
    }

    /// Work-hardened Y0 (1 + β(ε_p + ε_i))^n capped at Y_max.
    #[inline]
    fn hardened(&self, plastic_strain: f64) -> f64 {
        let p = &self.params;
        let e = plastic_strain + p.initial_plastic_strain;
        (p.yield_strength * (1.0 + p.hardening_coefficient * e).powf(p.hardening_exponent))
            .min(p.max_yield_strength)
    }
}

crate::params_conversions!(SteinbergGuinan, SteinbergGuinanParams);

impl StrengthModel for SteinbergGuinan {
    fn name(&self) -> &str {
        "steinberg-guinan"
    }
    #[inline]
    fn shear_modulus(&self, s: &StrengthState) -> f64 {
        self.bracket(s)
            .map_or(0.0, |b| self.params.shear_modulus * b)
    }
    #[inline]
    fn intact_yield(&self, s: &StrengthState) -> f64 {
        self.bracket(s)
            .map_or(0.0, |b| self.hardened(s.plastic_strain) * b)
    }
    #[inline]
    fn yield_strength(&self, s: &StrengthState) -> f64 {
        multiplicative_weakening(self.intact_yield(s), s.damage)
    }
    #[inline]
    fn evaluate(&self, s: &StrengthState) -> StrengthPoint {
        match self.bracket(s) {
            None => StrengthPoint::default(),
            Some(b) => StrengthPoint {
                shear_modulus: self.params.shear_modulus * b,
                yield_strength: multiplicative_weakening(
                    self.hardened(s.plastic_strain) * b,
                    s.damage,
                ),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::materials::{ALUMINIUM_2024_SG, COPPER_SG};

    #[test]
    fn table_a3_derivatives_round_trip() {
        // Table A3 lists G'_p = 1.8647, G'_T = −1.762e7 Pa/K, Y'_p = 0.01695.
        let p = ALUMINIUM_2024_SG;
        let gp = p.shear_modulus * p.pressure_coefficient;
        let gt = -p.shear_modulus * p.temperature_coefficient;
        let yp = p.yield_strength * p.pressure_coefficient;
        assert!((gp - 1.8647).abs() < 1e-12);
        assert!((gt + 1.762e7).abs() < 1e-6);
        // Y'_p implied by the shared bracket: 0.016952, the table's 0.01695 to its digits.
        assert!((yp - 0.01695).abs() < 0.5e-5, "Y'_p = {yp}");
    }

    #[test]
    fn melted_has_no_strength() {
        let m = SteinbergGuinan::new(COPPER_SG).unwrap();
        let s = StrengthState::new(0.0, 8930.0, 1790.0);
        assert_eq!(m.shear_modulus(&s), 0.0);
        assert_eq!(m.yield_strength(&s), 0.0);
        assert_eq!(m.evaluate(&s), StrengthPoint::default());
        let s = StrengthState::new(0.0, 8930.0, 1789.0);
        assert!(m.yield_strength(&s) > 0.0);
    }

    #[test]
    fn melt_law_reduces_to_tm0_at_reference_density() {
        let mut p = COPPER_SG;
        p.melt_law = Some(SgMeltLaw {
            gamma0: 2.02,
            a: 1.5,
        });
        let m = SteinbergGuinan::new(p).unwrap();
        assert!((m.melt_temperature(8930.0) - 1790.0).abs() < 1e-9);
        // Compression raises T_m: η = 1.1 gives 1790·exp(3(1 − 1/1.1))·1.1^(2(2.02 − 1.5 − 1/3)).
        let eta: f64 = 1.1;
        let expect =
            1790.0 * (3.0 * (1.0 - 1.0 / eta)).exp() * eta.powf(2.0 * (2.02 - 1.5 - 1.0 / 3.0));
        assert!((m.melt_temperature(8930.0 * eta) - expect).abs() < 1e-9 * expect);
        assert!(expect > 1790.0);
    }

    #[test]
    fn hardening_capped_at_y_max() {
        let m = SteinbergGuinan::new(COPPER_SG).unwrap();
        let mut s = StrengthState::new(0.0, 8930.0, 300.0);
        // 0.12 (1 + 36·10)^0.45 = 1.69 GPa > Y_max = 0.64 GPa.
        s.plastic_strain = 10.0;
        assert!((m.yield_strength(&s) - 0.64e9).abs() < 1e-3);
    }

    #[test]
    fn evaluate_matches_separate_calls() {
        let m = SteinbergGuinan::new(COPPER_SG).unwrap();
        let mut s = StrengthState::new(5.0e9, 9200.0, 500.0);
        s.plastic_strain = 0.3;
        s.damage = 0.2;
        let e = m.evaluate(&s);
        assert_eq!(e.shear_modulus, m.shear_modulus(&s));
        assert_eq!(e.yield_strength, m.yield_strength(&s));
    }

    #[test]
    fn rejects_bad_parameters() {
        let mut p = COPPER_SG;
        p.max_yield_strength = 0.1e9;
        assert!(matches!(
            SteinbergGuinan::new(p),
            Err(StrengthError::Parameter {
                field: "max_yield_strength",
                ..
            })
        ));
        let mut p = COPPER_SG;
        p.reference_density = -1.0;
        assert!(matches!(
            SteinbergGuinan::new(p),
            Err(StrengthError::Parameter {
                field: "reference_density",
                ..
            })
        ));
    }
}
