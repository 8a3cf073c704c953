//! Estimates of the fastest left- and right-going signal speeds S_L ≤ S_R of the 1-D
//! Riemann problem, for the HLLC solver (Toro, *Riemann Solvers and Numerical Methods for
//! Fluid Dynamics*, 3rd ed., §10.5–10.6).

use crate::state::SideState;
use serde::{Deserialize, Serialize};

/// Which wave-speed estimate the HLLC solver uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum WaveSpeedEstimate {
    /// Davis (1988): S_L = min(u_L − c_L, u_R − c_R), S_R = max(u_L + c_L, u_R + c_R)
    /// (Toro eq. 10.48).
    #[default]
    Davis,
    /// Einfeldt (1988) HLLE speeds with Roe averages (Toro eqs. 10.52–10.54), using the
    /// ideal-gas-free form: Roe-averaged velocity and the d̄ mixed sound speed.
    Einfeldt,
    /// Pressure-based (Toro §10.6, eq. 10.59–10.60): S_K = u_K ∓ c_K q_K with q_K from a
    /// primitive-variable estimate of P* and the shock relation for adiabatic index
    /// `gamma`. Most accurate for gas dynamics.
    PressureBased {
        /// The adiabatic index used in q_K.
        gamma: f64,
    },
}

/// S_L and S_R for the given states.
pub fn wave_speeds(left: &SideState, right: &SideState, estimate: WaveSpeedEstimate) -> (f64, f64) {
    let (ul, ur) = (left.velocity, right.velocity);
    let (cl, cr) = (left.sound_speed, right.sound_speed);
    match estimate {
        WaveSpeedEstimate::Davis => ((ul - cl).min(ur - cr), (ul + cl).max(ur + cr)),
        WaveSpeedEstimate::Einfeldt => {
            let (sl, sr) = (left.density.sqrt(), right.density.sqrt());
            let u_roe = (sl * ul + sr * ur) / (sl + sr);
            let eta2 = 0.5 * sl * sr / ((sl + sr) * (sl + sr));
            let d2 = (sl * cl * cl + sr * cr * cr) / (sl + sr) + eta2 * (ur - ul) * (ur - ul);
            let d = d2.sqrt();
            ((ul - cl).min(u_roe - d), (ur + cr).max(u_roe + d))
        }
        WaveSpeedEstimate::PressureBased { gamma } => {
            // Primitive-variable (PVRS) estimate of P*, Toro eq. 9.20, floored at zero.
            let rho_bar = 0.5 * (left.density + right.density);
            let c_bar = 0.5 * (cl + cr);
            let p_pv = 0.5 * (left.pressure + right.pressure) - 0.5 * (ur - ul) * rho_bar * c_bar;
            let p_star = p_pv.max(0.0);
            let q = |p_k: f64| -> f64 {
                if p_star <= p_k || p_k <= 0.0 {
                    1.0
                } else {
                    (1.0 + (gamma + 1.0) / (2.0 * gamma) * (p_star / p_k - 1.0)).sqrt()
                }
            };
            (ul - cl * q(left.pressure), ur + cr * q(right.pressure))
        }
    }
}
