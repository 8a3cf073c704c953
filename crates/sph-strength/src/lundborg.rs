//! Lundborg strength (Lundborg 1968, Int. J. Rock Mech. Min. Sci. 5:427; in the form of
//! Collins, Melosh & Ivanov 2004, MAPS 39:217, eq. 4), paper §3.2:
//!
//!   `Y_i = Y0 + μ P / (1 + μ P / (Y_M − Y0))`,
//!
//! Y0 the cohesion (strength at P = 0), μ the internal friction (the slope at P = 0) and
//! Y_M the limit strength as P → ∞. Damage weakening is frictional, eq. (13):
//! `Y = Y_d D + Y_i (1 − D)`, `Y_d = min(μ_d P, Y_i)` ([`crate::weakening`]).
//!
//! ## Tension (P < 0)
//!
//! The formula has a pole at P = −(Y_M − Y0)/μ and falls faster than linearly before it,
//! so it is not used in tension. What codes do there:
//!
//! - Collins et al. 2004 define the curve for compression; the tensile side is handled
//!   by their separate tensile-failure model. (iSALE's source is not public, so we could
//!   not check its branch for P < 0.)
//! - miluphcuda (`COLLINS_PRESSURE_DEPENDENT_YIELD_STRENGTH`, after Collins 2004 and
//!   Jutzi 2015) keeps `Y_i = Y0` for P ≤ 0 — [`LundborgTension::ConstantCohesion`].
//!
//! The default here, [`LundborgTension::LinearToZero`], continues the curve by its
//! tangent at P = 0, `Y_i = max(0, Y0 + μ P)` (the Drucker–Prager line): Y_i and dY_i/dP
//! are continuous at P = 0, and the strength vanishes at P = −Y0/μ, so a rock under
//! enough tension carries no shear stress even before it is damaged. The damaged
//! strength is zero in tension in both cases (see [`crate::weakening`]).

use crate::error::{Check, StrengthError};
use crate::model::{StrengthModel, StrengthState};
use crate::weakening::frictional_weakening;
use serde::{Deserialize, Serialize};

/// The intact strength in tension (P < 0); see the module docs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum LundborgTension {
    /// `Y_i = max(0, Y0 + μ P)`: the tangent at P = 0, down to zero at P = −Y0/μ.
    #[default]
    LinearToZero,
    /// `Y_i = Y0` for all P ≤ 0 (miluphcuda's choice).
    ConstantCohesion,
}

/// Parameters of [`Lundborg`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LundborgParams {
    /// Cohesion Y0, the shear strength at zero pressure (Pa), ≥ 0.
    pub cohesion: f64,
    /// Internal friction coefficient μ_i of intact material (slope at P = 0), ≥ 0.
    pub friction: f64,
    /// Limit strength Y_M as P → ∞ (Pa), > Y0 (`f64::INFINITY` gives the uncapped line).
    pub limit_strength: f64,
    /// Friction coefficient μ_d of fully damaged material, ≥ 0.
    pub damaged_friction: f64,
    /// Shear modulus G (Pa), > 0.
    pub shear_modulus: f64,
    /// Intact strength in tension.
    #[serde(default)]
    pub tension: LundborgTension,
}

/// Lundborg pressure-dependent strength with frictional damage weakening.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "LundborgParams", into = "LundborgParams")]
pub struct Lundborg {
    params: LundborgParams,
    /// μ / (Y_M − Y0), precomputed (0 for an infinite Y_M).
    inv_span: f64,
}

impl Lundborg {
    /// Validates the parameters.
    pub fn new(params: LundborgParams) -> Result<Self, StrengthError> {
        let c = Check { model: "lundborg" };
        c.non_negative("cohesion", params.cohesion)?;
        c.non_negative("friction", params.friction)?;
        c.require(
            params.limit_strength > params.cohesion,
            "limit_strength",
            params.limit_strength,
            "must exceed the cohesion (the curve divides by Y_M − Y0)",
        )?;
        c.non_negative("damaged_friction", params.damaged_friction)?;
        c.positive("shear_modulus", params.shear_modulus)?;
        let inv_span = params.friction / (params.limit_strength - params.cohesion);
        Ok(Self { params, inv_span })
    }

    /// The parameters.
    pub fn params(&self) -> &LundborgParams {
        &self.params
    }
}

crate::params_conversions!(Lundborg, LundborgParams);

impl StrengthModel for Lundborg {
    fn name(&self) -> &str {
        "lundborg"
    }
    #[inline]
    fn shear_modulus(&self, _s: &StrengthState) -> f64 {
        self.params.shear_modulus
    }
    #[inline]
    fn intact_yield(&self, s: &StrengthState) -> f64 {
        let p = &self.params;
        let pressure = s.pressure;
        if pressure >= 0.0 {
            // μP / (1 + μP/(Y_M − Y0)), Collins et al. 2004 eq. 4.
            p.cohesion + p.friction * pressure / (1.0 + self.inv_span * pressure)
        } else {
            match p.tension {
                LundborgTension::LinearToZero => (p.cohesion + p.friction * pressure).max(0.0),
                LundborgTension::ConstantCohesion => p.cohesion,
            }
        }
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
    use crate::materials::BASALT_LUNDBORG;

    fn at(p: f64) -> StrengthState {
        StrengthState::new(p, 2876.0, 300.0)
    }

    #[test]
    fn basalt_point_values() {
        // Y0 = 26.5 MPa, μ = 0.6, Y_M = 300 MPa: at P = 100 MPa,
        // 26.5 + 60/(1 + 60/273.5) = 26.5 + 49.2054 = 75.7054 MPa.
        let m = Lundborg::new(BASALT_LUNDBORG).unwrap();
        let expect = 26.5e6 + 60.0e6 / (1.0 + 60.0 / 273.5);
        assert!((m.intact_yield(&at(100.0e6)) - expect).abs() <= 1e-9 * expect);
        assert!((expect - 75.705_4e6).abs() < 1e2);
        // P → ∞ approaches Y_M.
        let big = m.intact_yield(&at(1.0e15));
        assert!((big - 300.0e6).abs() < 1e-3 * 300.0e6);
        assert!(big < 300.0e6);
    }

    #[test]
    fn tension_branches() {
        let lin = Lundborg::new(BASALT_LUNDBORG).unwrap();
        // 26.5 − 0.6·10 = 20.5 MPa; zero beyond −Y0/μ = −44.17 MPa.
        assert!((lin.intact_yield(&at(-10.0e6)) - 20.5e6).abs() < 1e-6);
        assert_eq!(lin.intact_yield(&at(-50.0e6)), 0.0);
        let mut p = BASALT_LUNDBORG;
        p.tension = LundborgTension::ConstantCohesion;
        let cst = Lundborg::new(p).unwrap();
        assert_eq!(cst.intact_yield(&at(-50.0e6)), 26.5e6);
        // Damaged strength is zero in tension: D = 1 gives no strength.
        let mut s = at(-10.0e6);
        s.damage = 1.0;
        assert_eq!(lin.yield_strength(&s), 0.0);
        assert_eq!(cst.yield_strength(&s), 0.0);
    }

    #[test]
    fn continuous_slope_at_zero_pressure() {
        let m = Lundborg::new(BASALT_LUNDBORG).unwrap();
        let dp = 1.0;
        let right = (m.intact_yield(&at(dp)) - m.intact_yield(&at(0.0))) / dp;
        let left = (m.intact_yield(&at(0.0)) - m.intact_yield(&at(-dp))) / dp;
        assert!((right - 0.6).abs() < 1e-6);
        assert!((left - 0.6).abs() < 1e-6);
    }

    #[test]
    fn rejects_limit_not_above_cohesion() {
        let mut p = BASALT_LUNDBORG;
        p.limit_strength = p.cohesion;
        let e = Lundborg::new(p).unwrap_err();
        assert_eq!(
            e,
            StrengthError::Parameter {
                model: "lundborg",
                field: "limit_strength",
                value: 26.5e6,
                reason: "must exceed the cohesion (the curve divides by Y_M − Y0)",
            }
        );
        let mut p = BASALT_LUNDBORG;
        p.friction = -0.1;
        assert!(matches!(
            Lundborg::new(p),
            Err(StrengthError::Parameter {
                field: "friction",
                ..
            })
        ));
    }
}
