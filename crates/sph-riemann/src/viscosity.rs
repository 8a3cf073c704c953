//! Monaghan artificial viscosity (Monaghan & Gingold 1983; paper §2.2).
//!
//!   Π_ij = (−α_Π c̄ μ_ij + β_Π μ_ij²)/ρ̄   if v_ij·x_ij < 0, else 0,
//!   μ_ij = h̄ v_ij·x_ij / (|x_ij|² + 0.01 h̄²),
//!
//! with pair means ρ̄, c̄, h̄ and v_ij = v_i − v_j, x_ij = x_i − x_j. This returns Π in
//! the standard units of P/ρ² that enter the momentum equation once per pair,
//! dv_i/dt ∋ −Σ_j m_j Π_ij ∇_i W_ij; the paper's pressure-like Π (its eq. for σ) is
//! ρ_i ρ_j Π_ij. The length h̄ is the *smoothing* length of Monaghan's formula; the
//! caller decides how it relates to the kernel support radius.

use serde::{Deserialize, Serialize};
use sph_core::Vector;

/// Coefficients of the Monaghan viscosity.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MonaghanViscosity {
    /// Linear coefficient α_Π (the study: 1).
    pub alpha: f64,
    /// Quadratic coefficient β_Π (the study: 1).
    pub beta: f64,
    /// The limiter that multiplies Π per pair (the study: none). Scenes:
    /// `viscosity = { …, switch = "balsara" }`.
    #[serde(default)]
    pub switch: crate::ViscositySwitch,
    /// Reconstruct each side's velocity to the pair midpoint with its limited velocity
    /// gradient before Π is formed (Spheral's LimitedMonaghanGingoldViscosity,
    /// [`crate::limited_relative_velocity`]); off: Π from v_i − v_j (the paper's §2.2).
    #[serde(default)]
    pub reconstruct: bool,
    /// The sound speed c̄ in Π: each solid's longitudinal wave speed (default) or the
    /// EOS's bulk sound speed (Spheral's, whose viscosity reads the fluid sound speed).
    #[serde(default)]
    pub sound_speed: ViscositySoundSpeed,
}

/// The sound speed of the viscosity's linear term (see [`MonaghanViscosity::sound_speed`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ViscositySoundSpeed {
    /// c_L = √(c² + 4G/(3ρ)) for a solid, c for a fluid (paper §2.5's signal speed).
    #[default]
    Longitudinal,
    /// The EOS's bulk sound speed c (Spheral).
    Bulk,
}

impl Default for MonaghanViscosity {
    fn default() -> Self {
        Self {
            alpha: 1.0,
            beta: 1.0,
            switch: crate::ViscositySwitch::None,
            reconstruct: false,
            sound_speed: ViscositySoundSpeed::Longitudinal,
        }
    }
}

impl MonaghanViscosity {
    /// Π_ij (units P/ρ², i.e. m²/s² per kg/m³... J·m³/kg²) for the pair.
    #[inline]
    pub fn pi<V: Vector>(&self, v_ij: V, x_ij: V, rho_bar: f64, c_bar: f64, h_bar: f64) -> f64 {
        let vx = v_ij.dot(x_ij);
        if vx >= 0.0 {
            return 0.0;
        }
        let mu = h_bar * vx / (x_ij.norm_squared() + 0.01 * h_bar * h_bar);
        (-self.alpha * c_bar * mu + self.beta * mu * mu) / rho_bar
    }

    /// The signal speed the viscosity adds to the time-step estimate,
    /// c + 1.2(α c + β max |μ|) (Monaghan 1992), for a particle with sound speed `c` and
    /// largest approaching |μ| among its pairs.
    #[inline]
    pub fn signal_speed(&self, c: f64, mu_max: f64) -> f64 {
        c + 1.2 * (self.alpha * c + self.beta * mu_max)
    }
}
