//! Monaghan's artificial stress against the tensile instability (Monaghan 2000, JCP 159;
//! Gray, Monaghan & Swift 2001, CMAME 190; paper §2.3), scalar form:
//!
//!   F_ij = f_ij^n (R_i + R_j),   f_ij = W(r_ij)/W(Δp),
//!   R_i = −ε P_i/ρ_i²  if P_i < 0 (tension), else 0,
//!
//! with Δp the initial particle spacing (ε = 0.2, n = 4 in the study). R has the units of
//! P/ρ², and F enters the momentum equation once per pair as
//! dv_i/dt ∋ −Σ_j m_j F_ij ∇_i W_ij (repulsive between particles in tension).

use serde::{Deserialize, Serialize};

/// Parameters of the artificial stress.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ArtificialStress {
    /// Strength ε (the study: 0.2; 0 disables).
    pub epsilon: f64,
    /// Exponent n (the study: 4).
    pub exponent: i32,
}

impl Default for ArtificialStress {
    fn default() -> Self {
        Self {
            epsilon: 0.2,
            exponent: 4,
        }
    }
}

impl ArtificialStress {
    /// R_i for a particle with pressure `p` (compression positive) and density `rho`.
    #[inline]
    pub fn r(&self, p: f64, rho: f64) -> f64 {
        if p < 0.0 {
            -self.epsilon * p / (rho * rho)
        } else {
            0.0
        }
    }

    /// F_ij from R_i, R_j and the kernel ratio f_ij = W(r_ij)/W(Δp).
    #[inline]
    pub fn f(&self, r_i: f64, r_j: f64, w_ratio: f64) -> f64 {
        let s = r_i + r_j;
        if s == 0.0 {
            0.0
        } else {
            w_ratio.powi(self.exponent) * s
        }
    }

    /// True when the term is switched off (ε = 0).
    pub fn is_off(&self) -> bool {
        self.epsilon == 0.0
    }
}
