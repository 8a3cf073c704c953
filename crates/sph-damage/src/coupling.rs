//! How damage weakens the deviatoric stress a pair of particles exchanges:
//! [`StressCoupling`].
//!
//! * [`StressCoupling::Particle`] (default; paper §2): each particle brings its own
//!   damaged stress, σ_i = (1 − D_i) S_i − P_i I, into the pair force
//!   m_j (σ_i + σ_j)/(ρ_i ρ_j) ∇W. An intact particle next to a crack still pulls on the
//!   crack's particles with its full stress S_i: the crack is only half open.
//! * [`StressCoupling::PairMax`]: both deviatoric stresses of a pair are multiplied by one
//!   factor of the pair's damage, f_ij = (1 − D_max)(1 − D_min) + D_min with
//!   D_max = max(D_i, D_j), D_min = min(D_i, D_j). It is 1 for two intact particles, 0
//!   for an intact particle and a fully damaged one (a crack transmits no deviatoric
//!   stress from either side), and 1 again for two fully damaged ones (whose stress is
//!   already zero, or only the rubble's friction). This is the default pair coupling of
//!   LLNL Spheral's solid SPH (its `PairMaxDamageNodeCoupling`, with scalar damage), the
//!   code the reference study modified (paper header); the study does not say which
//!   coupling it used. The factor is symmetric in (i, j), so the pair force stays
//!   antisymmetric: momentum and (with the compatible energy equation) energy are still
//!   conserved exactly.
//! * [`StressCoupling::YieldOnly`]: damage does not scale the deviatoric stress at all;
//!   it acts only through the damaged yield strength of paper §3.2 (Y = D Y_d +
//!   (1 − D) Y_i for Drucker–Prager and Lundborg, (1 − D) Y_i for von Mises and
//!   Johnson–Cook) and through the damaged pressure. Broken rock then keeps the stress
//!   its friction allows, Y_d = μ_d P, in every pair, in the hoop force of RZ runs and in
//!   the artificial stress. This is the form of Collins, Melosh & Ivanov (2004), where
//!   damage enters the strength model alone (iSALE's rock strength).
//!
//! The coupling acts only on the deviatoric stress; the damaged pressure (tension weakened
//! by 1 − D) is each particle's own in every form.

use serde::{Deserialize, Serialize};

/// How the pair force weakens the deviatoric stress by damage (module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum StressCoupling {
    /// (1 − D_i) S_i and (1 − D_j) S_j: each particle's own damage (paper §2).
    #[default]
    Particle,
    /// f_ij S_i and f_ij S_j with f_ij = (1 − D_max)(1 − D_min) + D_min.
    PairMax,
    /// S_i and S_j: damage acts through the yield strength only (Collins et al. 2004).
    YieldOnly,
}

impl StressCoupling {
    /// The factors (a_i, a_j) that multiply the undamaged deviatoric stresses S_i and S_j
    /// of a pair of the same material with damages `d_i` and `d_j` (each in [0, 1]).
    #[inline]
    pub fn factors(self, d_i: f64, d_j: f64) -> (f64, f64) {
        match self {
            Self::Particle => (1.0 - d_i, 1.0 - d_j),
            Self::PairMax => {
                let f = pair_max_factor(d_i, d_j);
                (f, f)
            }
            Self::YieldOnly => (1.0, 1.0),
        }
    }

    /// The coupling of a pair across a material interface: pair-max falls back to each
    /// particle's own (1 − D) (a crack in one body is not a crack in the other); the
    /// other two forms are the same across an interface as within a body.
    #[inline]
    pub fn across_interface(self) -> Self {
        match self {
            Self::PairMax => Self::Particle,
            other => other,
        }
    }

    /// The factor on one particle's own deviatoric stress where no pair is involved: the
    /// RZ hoop force, the artificial stress and the stress that activates the flaws.
    /// 1 − D for the two pair forms (the paper's σ = (1 − D) S − P_D I), 1 for
    /// [`Self::YieldOnly`].
    #[inline]
    pub fn own_factor(self, d: f64) -> f64 {
        match self {
            Self::Particle | Self::PairMax => 1.0 - d,
            Self::YieldOnly => 1.0,
        }
    }
}

/// f_ij = (1 − D_max)(1 − D_min) + D_min (module docs), in [0, 1] for damages in [0, 1].
#[inline]
pub fn pair_max_factor(d_i: f64, d_j: f64) -> f64 {
    let (lo, hi) = if d_i <= d_j { (d_i, d_j) } else { (d_j, d_i) };
    (1.0 - hi) * (1.0 - lo) + lo
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn point_values() {
        assert_eq!(pair_max_factor(0.0, 0.0), 1.0);
        assert_eq!(pair_max_factor(0.0, 1.0), 0.0);
        assert_eq!(pair_max_factor(1.0, 0.0), 0.0);
        assert_eq!(pair_max_factor(1.0, 1.0), 1.0);
        // One half-damaged particle next to an intact one: half its stress.
        assert_eq!(pair_max_factor(0.5, 0.0), 0.5);
        // Two half-damaged: 0.25 + 0.5.
        assert_eq!(pair_max_factor(0.5, 0.5), 0.75);
        assert_eq!(StressCoupling::Particle.factors(0.25, 0.5), (0.75, 0.5));
        assert_eq!(StressCoupling::PairMax.factors(0.0, 1.0), (0.0, 0.0));
        assert_eq!(StressCoupling::YieldOnly.factors(0.25, 1.0), (1.0, 1.0));
        assert_eq!(StressCoupling::Particle.own_factor(0.25), 0.75);
        assert_eq!(StressCoupling::PairMax.own_factor(0.25), 0.75);
        assert_eq!(StressCoupling::YieldOnly.own_factor(1.0), 1.0);
        assert_eq!(
            StressCoupling::PairMax.across_interface(),
            StressCoupling::Particle
        );
        assert_eq!(
            StressCoupling::YieldOnly.across_interface(),
            StressCoupling::YieldOnly
        );
    }

    proptest! {
        #[test]
        fn symmetric_and_bounded(a in 0.0..=1.0f64, b in 0.0..=1.0f64) {
            let f = pair_max_factor(a, b);
            prop_assert_eq!(f, pair_max_factor(b, a));
            prop_assert!((0.0..=1.0).contains(&f));
            // Never stronger than the intact pair, never weaker than the more damaged
            // particle's own (1 − D_max), up to round-off.
            prop_assert!(f >= (1.0 - a.max(b)) - 1e-15);
        }
    }
}
