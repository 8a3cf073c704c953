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
//! * [`StressCoupling::Fsisph`]: LLNL Spheral's solid FSISPH (Pearl, Raskin & Owen, J.
//!   Comput. Phys. 2022; src/FSISPH/SolidFSISPHEvaluateDerivatives.cc), the study's code.
//!   Within one material the deviatoric stresses of both sides are multiplied by
//!   f_ij = (1 − |D_i − D_j|)² only when the pair is in tension along its axis,
//!   r̂·((S_i + S_j) − (P_D,i + P_D,j) I)·r̂ > 0 ([`pair_is_tensile`]); otherwise they
//!   are passed whole. Across materials they are not passed at all (f = 0). A uniformly
//!   damaged region therefore keeps its stress, which the damaged yield strength
//!   (Y = D Y_d + (1 − D) Y_i) limits, as in [`StressCoupling::YieldOnly`]; a crack
//!   (a jump in D) opens in tension. The factor and the tension test are symmetric in
//!   (i, j), so momentum and energy stay exact.
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
    /// Spheral FSISPH's: f_ij S_i and f_ij S_j with f_ij = (1 − |D_i − D_j|)² for a pair
    /// in tension along its axis, S_i and S_j otherwise; nothing across materials.
    Fsisph,
}

impl StressCoupling {
    /// The factors (a_i, a_j) that multiply the undamaged deviatoric stresses S_i and S_j
    /// of a pair of the same material with damages `d_i` and `d_j` (each in [0, 1]).
    /// `tensile` is the pair's tension test ([`pair_is_tensile`]), read by
    /// [`Self::Fsisph`] only.
    #[inline]
    pub fn factors(self, d_i: f64, d_j: f64, tensile: bool) -> (f64, f64) {
        match self {
            Self::Particle => (1.0 - d_i, 1.0 - d_j),
            Self::PairMax => {
                let f = pair_max_factor(d_i, d_j);
                (f, f)
            }
            Self::YieldOnly => (1.0, 1.0),
            Self::Fsisph => {
                let f = if tensile {
                    fsisph_factor(d_i, d_j)
                } else {
                    1.0
                };
                (f, f)
            }
        }
    }

    /// The factors of a pair of particles of different materials: each particle's own
    /// (1 − D) for the particle and pair-max forms (a crack in one body is not a crack in
    /// the other), the whole stresses for [`Self::YieldOnly`], none for [`Self::Fsisph`]
    /// (Spheral's f_D = 0 across materials: an interface passes pressure only).
    #[inline]
    pub fn interface_factors(self, d_i: f64, d_j: f64) -> (f64, f64) {
        match self {
            Self::Particle | Self::PairMax => (1.0 - d_i, 1.0 - d_j),
            Self::YieldOnly => (1.0, 1.0),
            Self::Fsisph => (0.0, 0.0),
        }
    }

    /// Whether [`Self::factors`] reads the pair's tension test (only [`Self::Fsisph`]), so
    /// the other forms skip computing it.
    #[inline]
    pub fn needs_tension_test(self) -> bool {
        self == Self::Fsisph
    }

    /// The factor on one particle's own deviatoric stress where no pair is involved: the
    /// RZ hoop force and the artificial stress. 1 − D for the particle and pair-max forms
    /// (the paper's σ = (1 − D) S − P_D I), 1 for [`Self::YieldOnly`] and
    /// [`Self::Fsisph`], where a particle's own damage reaches its stress through the
    /// damaged yield strength.
    #[inline]
    pub fn own_factor(self, d: f64) -> f64 {
        match self {
            Self::Particle | Self::PairMax => 1.0 - d,
            Self::YieldOnly | Self::Fsisph => 1.0,
        }
    }

    /// The factor on the deviatoric stress in the total stress σ = a S − P_D I whose
    /// largest principal value activates the flaws, σ_1/((1 − D) E): 1 − D for every form
    /// but [`Self::YieldOnly`] (1), so that in tension the activation strain is that of the
    /// intact fraction, σ_1(S − P I)/E, whatever the pairs do with the stress (Spheral
    /// evaluates its strain from the whole S and P, src/Damage/StrainPolicy.cc).
    #[inline]
    pub fn activation_factor(self, d: f64) -> f64 {
        match self {
            Self::Particle | Self::PairMax | Self::Fsisph => 1.0 - d,
            Self::YieldOnly => 1.0,
        }
    }
}

/// f_ij = (1 − |D_i − D_j|)² (Spheral FSISPH's fDij), in [0, 1], symmetric.
#[inline]
pub fn fsisph_factor(d_i: f64, d_j: f64) -> f64 {
    let b = 1.0 - (d_i - d_j).abs();
    b * b
}

/// FSISPH's tension test of a pair: r̂·((S_i + S_j) − (P_i + P_j) I)·r̂ > 0 with S the
/// undamaged deviatoric stresses and P the damaged pressures (compression positive),
/// `s_rr` = r̂·(S_i + S_j)·r̂ and `p_sum` = P_i + P_j. Symmetric in (i, j) (r̂ → −r̂
/// leaves r̂·S·r̂ unchanged).
#[inline]
pub fn pair_is_tensile(s_rr: f64, p_sum: f64) -> bool {
    s_rr - p_sum > 0.0
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
        assert_eq!(
            StressCoupling::Particle.factors(0.25, 0.5, true),
            (0.75, 0.5)
        );
        assert_eq!(StressCoupling::PairMax.factors(0.0, 1.0, false), (0.0, 0.0));
        assert_eq!(
            StressCoupling::YieldOnly.factors(0.25, 1.0, true),
            (1.0, 1.0)
        );
        assert_eq!(StressCoupling::Particle.own_factor(0.25), 0.75);
        assert_eq!(StressCoupling::PairMax.own_factor(0.25), 0.75);
        assert_eq!(StressCoupling::YieldOnly.own_factor(1.0), 1.0);
        assert_eq!(StressCoupling::Fsisph.own_factor(0.75), 1.0);
        assert_eq!(StressCoupling::Fsisph.activation_factor(0.75), 0.25);
        assert_eq!(StressCoupling::YieldOnly.activation_factor(0.75), 1.0);
        assert_eq!(
            StressCoupling::PairMax.interface_factors(0.5, 0.25),
            (0.5, 0.75)
        );
        assert_eq!(
            StressCoupling::YieldOnly.interface_factors(0.5, 1.0),
            (1.0, 1.0)
        );
        assert_eq!(
            StressCoupling::Fsisph.interface_factors(0.0, 0.0),
            (0.0, 0.0)
        );
    }

    #[test]
    fn fsisph_factor_point_values() {
        // (1 − |D_i − D_j|)²: 1 for equal damage, whatever it is; 0 across a full crack.
        assert_eq!(fsisph_factor(0.0, 0.0), 1.0);
        assert_eq!(fsisph_factor(0.7, 0.7), 1.0);
        assert_eq!(fsisph_factor(1.0, 0.0), 0.0);
        assert_eq!(fsisph_factor(0.5, 0.0), 0.25);
        // Only pairs in tension along their axis are weakened.
        assert_eq!(StressCoupling::Fsisph.factors(0.5, 0.0, true), (0.25, 0.25));
        assert_eq!(StressCoupling::Fsisph.factors(0.5, 0.0, false), (1.0, 1.0));
        assert!(StressCoupling::Fsisph.needs_tension_test());
        assert!(!StressCoupling::PairMax.needs_tension_test());
        // Tension test: S_rr sum 3 MPa against a pressure sum of 2 MPa is tensile, of
        // 4 MPa is not.
        assert!(pair_is_tensile(3.0e6, 2.0e6));
        assert!(!pair_is_tensile(3.0e6, 4.0e6));
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

        #[test]
        fn fsisph_symmetric_and_bounded(a in 0.0..=1.0f64, b in 0.0..=1.0f64, t: bool) {
            let (fa, fb) = StressCoupling::Fsisph.factors(a, b, t);
            prop_assert_eq!(fa, fb);
            prop_assert_eq!((fa, fb), StressCoupling::Fsisph.factors(b, a, t));
            prop_assert!((0.0..=1.0).contains(&fa));
        }
    }
}
