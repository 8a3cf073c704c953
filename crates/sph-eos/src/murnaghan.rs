//! Murnaghan EOS and its linear-elastic limit (both barotropic: P does not depend on e).
//!
//! - Murnaghan (1944), PNAS 30:244: P = (K0/n) [(ρ/ρ0)^n − 1], n = dK/dP (K0′), the same
//!   function as the "Tait" EOS of weakly compressible SPH (Monaghan 1994, n = 7).
//!   ∂P/∂ρ|_e = (K0/ρ0) (ρ/ρ0)^(n−1), ∂P/∂e|_ρ = 0.
//! - Linear elastic: P = K0 (ρ/ρ0 − 1) = K0 μ, the n = 1 case and the n → small-strain
//!   limit of any n (the EOS of docs/verification.md, "Solid dynamics: elastic–plastic
//!   planar impact"): ∂P/∂ρ|_e = K0/ρ0, so c = c0 = √(K0/ρ0) everywhere.
//!
//! With ∂P/∂e = 0 the sound speed is c² = ∂P/∂ρ > 0 for every ρ > 0; the floor
//! (a fraction of c0 = √(K0/ρ0)) acts only where (ρ/ρ0)^(n−1) drops below fraction², i.e.
//! in extreme expansion, and is flagged. Both are valid for ρ > 0; in tension they give
//! P < 0 down to −K0/n (Murnaghan) as ρ → 0, with no cutoff.

use crate::eos::{
    DEFAULT_SOUND_SPEED_FLOOR_FRACTION, EosPoint, EquationOfState, floor_from_fraction,
};
use crate::error::{EosError, positive};
use serde::{Deserialize, Serialize};

/// Parameters of the Murnaghan EOS.
#[allow(non_snake_case)]
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MurnaghanParams {
    /// Reference density ρ0, kg/m³ (> 0).
    pub rho0: f64,
    /// Bulk modulus at ρ0, K0, Pa (> 0).
    pub K0: f64,
    /// Exponent n = K0′ (> 0, dimensionless; typically 4–7).
    pub n: f64,
}

/// The Murnaghan EOS. Construct with [`Murnaghan::new`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Murnaghan {
    p: MurnaghanParams,
    inv_rho0: f64,
    c0: f64,
    c_floor: f64,
}

impl Murnaghan {
    /// Validates ρ0, K0, n > 0; sound-speed floor [`DEFAULT_SOUND_SPEED_FLOOR_FRACTION`]·c0.
    pub fn new(params: MurnaghanParams) -> Result<Self, EosError> {
        positive("rho0", params.rho0)?;
        positive("K0", params.K0)?;
        positive("n", params.n)?;
        let c0 = (params.K0 / params.rho0).sqrt();
        Ok(Self {
            p: params,
            inv_rho0: 1.0 / params.rho0,
            c0,
            c_floor: DEFAULT_SOUND_SPEED_FLOOR_FRACTION * c0,
        })
    }

    /// Sets the sound-speed floor to `fraction · c0`, fraction in [0, 1].
    pub fn with_sound_speed_floor_fraction(mut self, fraction: f64) -> Result<Self, EosError> {
        self.c_floor = floor_from_fraction(fraction, self.c0)?;
        Ok(self)
    }

    /// The parameters.
    pub fn params(&self) -> &MurnaghanParams {
        &self.p
    }

    /// Sound-speed floor, m/s.
    pub fn sound_speed_floor(&self) -> f64 {
        self.c_floor
    }
}

impl EquationOfState for Murnaghan {
    fn name(&self) -> &str {
        "murnaghan"
    }

    fn reference_density(&self) -> Option<f64> {
        Some(self.p.rho0)
    }

    fn reference_sound_speed(&self) -> Option<f64> {
        Some(self.c0)
    }

    #[inline]
    fn pressure(&self, rho: f64, _e: f64) -> f64 {
        // η = ρ/ρ0 by division so that η = 1 exactly at ρ0 (P(ρ0) = 0 exactly).
        // expm1 keeps (η^n − 1)/n accurate for small n and near η = 1.
        let n = self.p.n;
        self.p.K0 / n * (n * (rho / self.p.rho0).ln()).exp_m1()
    }

    #[inline]
    fn evaluate(&self, rho: f64, e: f64) -> EosPoint {
        let eta = rho / self.p.rho0;
        let dp_drho = self.p.K0 * self.inv_rho0 * eta.powf(self.p.n - 1.0);
        EosPoint::from_derivatives(rho, self.pressure(rho, e), dp_drho, 0.0, self.c_floor)
    }
}

/// Parameters of the linear-elastic EOS.
#[allow(non_snake_case)]
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinearElasticParams {
    /// Reference density ρ0, kg/m³ (> 0).
    pub rho0: f64,
    /// Bulk modulus K0, Pa (> 0).
    pub K0: f64,
}

/// The linear-elastic EOS P = K0 (ρ/ρ0 − 1). Construct with [`LinearElastic::new`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearElastic {
    p: LinearElasticParams,
    c0: f64,
    dp_drho: f64,
}

impl LinearElastic {
    /// Validates ρ0, K0 > 0.
    pub fn new(params: LinearElasticParams) -> Result<Self, EosError> {
        positive("rho0", params.rho0)?;
        positive("K0", params.K0)?;
        Ok(Self {
            p: params,
            c0: (params.K0 / params.rho0).sqrt(),
            dp_drho: params.K0 / params.rho0,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &LinearElasticParams {
        &self.p
    }
}

impl EquationOfState for LinearElastic {
    fn name(&self) -> &str {
        "linear-elastic"
    }

    fn reference_density(&self) -> Option<f64> {
        Some(self.p.rho0)
    }

    fn reference_sound_speed(&self) -> Option<f64> {
        Some(self.c0)
    }

    #[inline]
    fn pressure(&self, rho: f64, _e: f64) -> f64 {
        self.p.K0 * (rho / self.p.rho0 - 1.0)
    }

    /// c = c0 exactly (∂P/∂e = 0), so no floor is ever needed.
    #[inline]
    fn evaluate(&self, rho: f64, _e: f64) -> EosPoint {
        EosPoint {
            pressure: self.p.K0 * (rho / self.p.rho0 - 1.0),
            sound_speed: self.c0,
            dp_drho: self.dp_drho,
            dp_de: 0.0,
            raw_sound_speed_squared: self.dp_drho,
            sound_speed_floored: false,
            pressure_floored: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation() {
        assert!(matches!(
            Murnaghan::new(MurnaghanParams {
                rho0: 1000.0,
                K0: 1e9,
                n: 0.0
            }),
            Err(EosError::Parameter { field: "n", .. })
        ));
        assert!(matches!(
            LinearElastic::new(LinearElasticParams {
                rho0: 1000.0,
                K0: -1.0
            }),
            Err(EosError::Parameter { field: "K0", .. })
        ));
    }
}
