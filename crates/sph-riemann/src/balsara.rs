//! The Balsara switch (Balsara 1995, J. Comput. Phys. 121, 357, eq. 4.1): a per-particle
//! factor that keeps the artificial viscosity in compressions and turns it off in shear,
//!
//!   f_i = |∇·v|_i / (|∇·v|_i + |∇×v|_i + ε c_i/h_i),   ε = 1e-4,
//!
//! applied to a pair as the mean (f_i + f_j)/2 times Π_ij. Why it matters for impacts:
//! Monaghan's Π acts on every approaching pair, so in a shearing flow it is a shear
//! viscosity ν ~ α c h/8. Behind the shock the excavation flow of a crater is nearly
//! divergence-free and rotational, and with the solid's longitudinal sound speed in c it
//! is viscous at the grid scale (docs/validation.md, "The viscosity and β").
//! ε c/h keeps f finite where the flow is at rest; f lies in [0, 1].

use serde::{Deserialize, Serialize};

/// Which limiter multiplies the Monaghan viscosity.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ViscositySwitch {
    /// No limiter: Π as written (the study, paper §2.2).
    #[default]
    None,
    /// The Balsara factor, the pair mean of [`balsara_factor`].
    Balsara,
}

/// The noise floor ε of the Balsara factor's denominator (Balsara 1995).
pub const BALSARA_EPSILON: f64 = 1e-4;

/// f = |div| / (|div| + |curl| + ε c/h) for a particle with velocity divergence `div`,
/// vorticity magnitude `curl`, sound speed `c` and smoothing length `h`. 0 for a particle at
/// rest (and 1 for pure compression or expansion of a flow without vorticity).
#[inline]
pub fn balsara_factor(div: f64, curl: f64, c: f64, h: f64) -> f64 {
    let d = div.abs();
    let floor = BALSARA_EPSILON * c / h;
    let den = d + curl.abs() + floor;
    if den > 0.0 { d / den } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compression_without_vorticity_keeps_the_viscosity() {
        // ∇·v = −1e5 1/s, c = 5 km/s, h = 1 mm: ε c/h = 500 1/s, f = 1e5/(1e5 + 500).
        let f = balsara_factor(-1e5, 0.0, 5000.0, 1e-3);
        assert!((f - 1e5 / 100_500.0).abs() < 1e-15);
    }

    #[test]
    fn pure_shear_turns_it_off() {
        // A simple shear v_x = γ y has div 0 and |curl| = γ.
        assert_eq!(balsara_factor(0.0, 1e4, 5000.0, 1e-3), 0.0);
    }

    #[test]
    fn equal_divergence_and_vorticity_halve_it() {
        let f = balsara_factor(1e6, 1e6, 0.0, 1e-3);
        assert!((f - 0.5).abs() < 1e-15);
    }

    #[test]
    fn at_rest_it_is_zero_not_nan() {
        assert_eq!(balsara_factor(0.0, 0.0, 0.0, 1e-3), 0.0);
        assert_eq!(balsara_factor(0.0, 0.0, 5000.0, 1e-3), 0.0);
    }
}
