//! Monaghan's artificial stress against the tensile instability (Monaghan 2000, JCP 159;
//! Gray, Monaghan & Swift 2001, CMAME 190; paper §2.3), scalar form:
//!
//!   F_ij = f_ij^n (R_i + R_j),   f_ij = W(r_ij)/W(Δp),
//!   R_i = −ε P_i/ρ_i²  if P_i < 0 (tension), else 0,
//!
//! with Δp the initial particle spacing (ε = 0.2, n = 4 in the study). R has the units of
//! P/ρ², and F enters the momentum equation once per pair as
//! dv_i/dt ∋ −Σ_j m_j F_ij ∇_i W_ij (repulsive between particles in tension).
//!
//! The tensor form (Gray, Monaghan & Swift 2001, eqs. 4.9–4.11) works on the principal
//! values σ'_a of the total stress σ (tension positive): R'_a = −ε σ'_a/ρ² where σ'_a > 0,
//! rotated back, R = V diag(R') Vᵀ, and dv_i/dt ∋ Σ_j m_j f_ij^n (R_i + R_j)·∇_i W_ij.
//! It also acts on tension carried by the deviatoric stress (a bent plate, a stretched
//! ring), which the pressure form cannot see. With σ = −P I both forms agree:
//! R = −R_i^{scalar} I.

use serde::{Deserialize, Serialize};
use sph_core::{Tensor, Vector};

/// Which stress the artificial stress reads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ArtificialStressForm {
    /// The study's scalar form on the (damaged) pressure (paper §2.3).
    #[default]
    Pressure,
    /// The tensor form on the principal values of the total stress (Gray et al. 2001).
    Principal,
}

/// Parameters of the artificial stress.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArtificialStress {
    /// Strength ε (the study: 0.2; 0 disables).
    pub epsilon: f64,
    /// Exponent n (the study: 4).
    pub exponent: i32,
    /// Scalar (pressure) or tensor (principal-stress) form.
    #[serde(default)]
    pub form: ArtificialStressForm,
    /// Upper bound on ε fⁿ, the pair's artificial stress over the tension it answers
    /// (`None`, the study's form: unbounded). With ε fⁿ > 1 a pair in tension is pushed
    /// apart, and pushing it apart deepens its tension: a pair compressed to well under
    /// Δp that then goes into tension runs away (fⁿ ≈ 58 at 0.45 Δp with the Wendland C2
    /// kernel of support 2.2 Δp). A cap of 1 lets the term cancel a close pair's tensile pull but never
    /// reverse it (docs/verification.md, "the axis jet").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cap: Option<f64>,
}

impl Default for ArtificialStress {
    fn default() -> Self {
        Self {
            epsilon: 0.2,
            exponent: 4,
            form: ArtificialStressForm::Pressure,
            cap: None,
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
            self.kernel_factor(w_ratio) * s
        }
    }

    /// fⁿ for the kernel ratio f = W(r_ij)/W(Δp), bounded by `cap`/ε when a cap is set.
    #[inline]
    pub fn kernel_factor(&self, w_ratio: f64) -> f64 {
        let f_n = w_ratio.powi(self.exponent);
        match self.cap {
            Some(cap) if self.epsilon > 0.0 => f_n.min(cap / self.epsilon),
            _ => f_n,
        }
    }

    /// The tensor R of a particle in the sign convention of the tensor form (its pair term
    /// is Σ_j m_j f^n (R_i + R_j)·∇_i W): `total_stress` is σ (tension positive), used by
    /// the principal form; `pressure` is P (compression positive), used by the pressure
    /// form, which returns −R_i I with R_i from [`Self::r`].
    pub fn tensor<T: Tensor>(&self, total_stress: &T, pressure: f64, density: f64) -> T {
        match self.form {
            ArtificialStressForm::Pressure => T::IDENTITY * (-self.r(pressure, density)),
            ArtificialStressForm::Principal => {
                let e = total_stress.sym_eigen();
                let n = T::Vector::DIM;
                let scale = -self.epsilon / (density * density);
                let r: Vec<f64> = (0..n)
                    .map(|a| {
                        let s = e.values[a];
                        if s > 0.0 { scale * s } else { 0.0 }
                    })
                    .collect();
                if r.iter().all(|&x| x == 0.0) {
                    return T::ZERO;
                }
                let v = e.vectors;
                T::from_fn(|a, b| {
                    (0..n)
                        .map(|k| v.component(a, k) * r[k] * v.component(b, k))
                        .sum()
                })
                .symmetric()
            }
        }
    }

    /// The out-of-plane (hoop, θθ) component of R for an axisymmetric particle, in the
    /// sign convention of [`Self::tensor`]: θ is a principal direction of an axisymmetric
    /// stress, so the principal form takes −ε σ_θθ/ρ² where σ_θθ is tensile; the pressure
    /// form is isotropic, −R_i from [`Self::r`].
    #[inline]
    pub fn hoop(&self, sigma_tt: f64, pressure: f64, density: f64) -> f64 {
        match self.form {
            ArtificialStressForm::Pressure => -self.r(pressure, density),
            ArtificialStressForm::Principal => {
                if sigma_tt > 0.0 {
                    -self.epsilon * sigma_tt / (density * density)
                } else {
                    0.0
                }
            }
        }
    }

    /// True when the term is switched off (ε = 0).
    pub fn is_off(&self) -> bool {
        self.epsilon == 0.0
    }
}
