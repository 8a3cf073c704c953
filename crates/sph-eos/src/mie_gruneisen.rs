//! Mie–Grüneisen EOS on a linear U_s–u_p shock Hugoniot (c0, s, Γ0, ρ0).
//!
//! Form used (LS-DYNA Keyword User's Manual, `*EOS_GRUNEISEN`, with S2 = S3 = 0 and no
//! volume correction of Γ, a = 0), μ = ρ/ρ0 − 1:
//!
//! - compression, μ > 0: P = ρ0 c0² μ [1 + (1 − Γ0/2) μ] / [1 − (s − 1) μ]² + Γ0 ρ0 e
//! - tension, μ ≤ 0:     P = ρ0 c0² μ + Γ0 ρ0 e
//!
//! Why this form: with Γρ = Γ0ρ0 constant, P = P_H + Γ0ρ0 (e − e_H) referenced to the
//! Hugoniot of U_s = c0 + s u_p from (ρ0, e = 0, P = 0), where
//! P_H = ρ0 c0² μ (1 + μ)/[1 − (s − 1)μ]² and e_H = P_H μ/(2ρ0(1 + μ)) (Rankine–Hugoniot);
//! expanding gives the compressed line above exactly (e.g. Meyers 1994, *Dynamic Behavior
//! of Materials*, Wiley, the Mie–Grüneisen equation of state chapter). So along the
//! principal Hugoniot this EOS reproduces U_s = c0 + s u_p exactly (tested). In tension
//! the Hugoniot reference is replaced by the linear term ρ0c0²μ (LS-DYNA's expanded form),
//! which joins the compressed form with equal value and slope (c0²) at μ = 0.
//!
//! Derivatives: ∂P/∂e|_ρ = Γ0 ρ0; ∂P/∂ρ|_e = c0² f'(μ) with f = μ(1 + kμ)/D², k = 1 − Γ0/2,
//! D = 1 − (s − 1)μ, f' = [(1 + 2kμ) D + 2(s − 1) μ (1 + kμ)]/D³ (compression), c0² (tension).
//!
//! Sound speed: c² = ∂P/∂ρ + Γ0ρ0 P/ρ². In cold tension (e = 0, μ < 0) this is
//! c0² (1 + Γ0 μ/η²), negative below η* = (−Γ0 + √(Γ0² + 4Γ0))/2 (0.732 for Γ0 = 2): there
//! the floor (a fraction of c0) is returned and flagged.
//!
//! Validity: ρ > 0, and for s > 1 the compression μ < 1/(s − 1) (the linear Hugoniot's
//! limiting compression η = s/(s − 1), where D = 0 and P → ∞). Beyond it the formula is
//! meaningless (the pole is crossed); [`EquationOfState::check_state`] rejects it and the
//! hot path returns the formula's value (±∞/NaN at the pole).

use crate::eos::{
    DEFAULT_SOUND_SPEED_FLOOR_FRACTION, EosPoint, EquationOfState, basic_state_check,
    floor_from_fraction,
};
use crate::error::{EosError, non_negative, positive};
use serde::{Deserialize, Serialize};

/// Parameters of the Mie–Grüneisen EOS.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MieGruneisenParams {
    /// Reference density ρ0, kg/m³ (> 0).
    pub rho0: f64,
    /// Bulk sound speed c0, m/s (> 0): the intercept of U_s = c0 + s u_p.
    pub c0: f64,
    /// Hugoniot slope s (≥ 0, dimensionless).
    pub s: f64,
    /// Grüneisen parameter Γ0 at ρ0 (≥ 0, dimensionless); Γρ = Γ0ρ0 is held constant.
    pub gamma0: f64,
}

impl MieGruneisenParams {
    /// Aluminium 6061-T6, an example set: ρ0 = 2703 kg/m³ and the experimental Hugoniot
    /// U_s ≈ 5.35 + 1.34 u_p km/s quoted in docs/reference/tillotson.md, "Shock Hugoniot and planar impact"
    /// (LASL shock data, Marsh 1980), with Γ0 = 2.0 (Al's usual value; Steinberg 1996,
    /// UCRL-MA-106439, lists 1.97 with a slightly different fit, c0 = 5.24 km/s, s = 1.4). Not a
    /// study parameter.
    pub fn aluminium_6061() -> Self {
        Self {
            rho0: 2703.0,
            c0: 5350.0,
            s: 1.34,
            gamma0: 2.0,
        }
    }

    /// Checks every field.
    pub fn validate(&self) -> Result<(), EosError> {
        positive("rho0", self.rho0)?;
        positive("c0", self.c0)?;
        non_negative("s", self.s)?;
        non_negative("gamma0", self.gamma0)
    }
}

/// The Mie–Grüneisen EOS. Construct with [`MieGruneisen::new`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MieGruneisen {
    p: MieGruneisenParams,
    k0: f64, // ρ0 c0²
    c02: f64,
    k: f64, // 1 − Γ0/2
    sm1: f64,
    g0rho0: f64,
    floor_fraction: f64,
    c_floor: f64,
}

impl MieGruneisen {
    /// Validates the parameters; sound-speed floor [`DEFAULT_SOUND_SPEED_FLOOR_FRACTION`]·c0.
    pub fn new(params: MieGruneisenParams) -> Result<Self, EosError> {
        params.validate()?;
        Ok(Self {
            p: params,
            k0: params.rho0 * params.c0 * params.c0,
            c02: params.c0 * params.c0,
            k: 1.0 - 0.5 * params.gamma0,
            sm1: params.s - 1.0,
            g0rho0: params.gamma0 * params.rho0,
            floor_fraction: DEFAULT_SOUND_SPEED_FLOOR_FRACTION,
            c_floor: DEFAULT_SOUND_SPEED_FLOOR_FRACTION * params.c0,
        })
    }

    /// Sets the sound-speed floor to `fraction · c0`, fraction in [0, 1].
    pub fn with_sound_speed_floor_fraction(mut self, fraction: f64) -> Result<Self, EosError> {
        self.c_floor = floor_from_fraction(fraction, self.p.c0)?;
        self.floor_fraction = fraction;
        Ok(self)
    }

    /// The parameters.
    pub fn params(&self) -> &MieGruneisenParams {
        &self.p
    }

    /// Sound-speed floor, m/s.
    pub fn sound_speed_floor(&self) -> f64 {
        self.c_floor
    }

    /// Limiting compression μ_max = 1/(s − 1) of the linear Hugoniot (∞ for s ≤ 1).
    pub fn max_compression(&self) -> f64 {
        if self.sm1 > 0.0 {
            1.0 / self.sm1
        } else {
            f64::INFINITY
        }
    }

    /// Cold (e = 0) pressure and its density derivative.
    #[inline(always)]
    fn reference_curve(&self, rho: f64) -> (f64, f64) {
        let mu = rho / self.p.rho0 - 1.0;
        if mu > 0.0 {
            let d = 1.0 - self.sm1 * mu;
            let n = 1.0 + self.k * mu;
            let inv_d = 1.0 / d;
            let f = mu * n * inv_d * inv_d;
            let df =
                ((1.0 + 2.0 * self.k * mu) * d + 2.0 * self.sm1 * mu * n) * inv_d * inv_d * inv_d;
            (self.k0 * f, self.c02 * df)
        } else {
            (self.k0 * mu, self.c02)
        }
    }
}

impl EquationOfState for MieGruneisen {
    fn name(&self) -> &str {
        "mie-gruneisen"
    }

    fn reference_density(&self) -> Option<f64> {
        Some(self.p.rho0)
    }

    fn reference_sound_speed(&self) -> Option<f64> {
        Some(self.p.c0)
    }

    #[inline]
    fn pressure(&self, rho: f64, e: f64) -> f64 {
        self.reference_curve(rho).0 + self.g0rho0 * e
    }

    #[inline]
    fn evaluate(&self, rho: f64, e: f64) -> EosPoint {
        let (pr, dpr) = self.reference_curve(rho);
        EosPoint::from_derivatives(rho, pr + self.g0rho0 * e, dpr, self.g0rho0, self.c_floor)
    }

    /// ρ > 0, e finite, and μ < 1/(s − 1) for s > 1.
    fn check_state(&self, rho: f64, e: f64) -> Result<(), EosError> {
        basic_state_check(self.name(), rho, e)?;
        if rho / self.p.rho0 - 1.0 < self.max_compression() {
            Ok(())
        } else {
            Err(EosError::OutsideValidity {
                eos: self.name().to_owned(),
                rho,
                e,
                reason: "compression mu reaches the linear-Hugoniot limit 1/(s - 1)",
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_and_limit() {
        let mut p = MieGruneisenParams::aluminium_6061();
        p.c0 = 0.0;
        assert!(matches!(
            MieGruneisen::new(p),
            Err(EosError::Parameter { field: "c0", .. })
        ));
        let mg = MieGruneisen::new(MieGruneisenParams::aluminium_6061()).unwrap();
        let mu_max = 1.0 / 0.34;
        assert!((mg.max_compression() - mu_max).abs() < 1e-12);
        assert!(mg.check_state(2703.0 * (1.0 + 0.99 * mu_max), 0.0).is_ok());
        assert!(mg.check_state(2703.0 * (1.0 + 1.01 * mu_max), 0.0).is_err());
    }
}
