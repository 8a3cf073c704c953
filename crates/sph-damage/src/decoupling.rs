//! Decoupling of fractured material: broken rock pushes but does not pull (LLNL Spheral's
//! solid FSISPH, `decoupleDamagedMaterial`, src/FSISPH/SolidFSISPHEvaluateDerivatives.cc;
//! Pearl, Raskin & Owen, J. Comput. Phys. 2022), the code the reference study ran.
//!
//! A pair of particles of the same material does not interact at all (no pressure,
//! stress, viscosity, interface velocity or velocity gradient) when all three hold:
//!
//! 1. it is **separating**: (x_i − x_j)·(v_i − v_j) > 0;
//! 2. one side is **past its adhesion limit**: its pressure lies below its damaged
//!    pressure, P < P_D − 10⁻⁹ ρ c², i.e. it is in tension and damaged (P_D = (1 − D) P
//!    for P < 0, paper §2) — [`past_adhesion`];
//! 3. one side is **fully damaged**: (1 − D)² < 0.01, D > 0.9 — [`fully_damaged`].
//!
//! Fractured material then behaves like gravel: compressed fragments still push on each
//! other (the pair is approaching, or in compression), but a crack that opens in tension
//! stops transmitting anything, so the rock falls apart into pieces instead of being held
//! together by the residual tension of its damaged neighbours. The test reads each side's
//! state symmetrically, so (i, j) and (j, i) decide alike and the dropped pair force
//! cancels as a whole: momentum and energy stay exact.
//!
//! Across different materials Spheral decouples on the same separation test with its
//! interface pressure floor; this project's unbonded interfaces do that job (the solver's
//! `unbonded_interfaces`).

/// Spheral's threshold on (1 − D)² below which a particle counts as fully damaged
/// (`tinyScalarDamage`): D > 0.9.
pub const FULLY_DAMAGED_F: f64 = 1.0e-2;

/// Spheral's dimensionless margin on the adhesion test (`tinyNonDimensional`), in units
/// of the particle's ρ c².
pub const ADHESION_MARGIN: f64 = 1.0e-9;

/// Whether a particle with damage `damage` ∈ [0, 1] is fully damaged for decoupling:
/// (1 − D)² < [`FULLY_DAMAGED_F`].
#[inline]
pub fn fully_damaged(damage: f64) -> bool {
    let f = 1.0 - damage;
    f * f < FULLY_DAMAGED_F
}

/// Whether a particle is past its adhesion limit: its undamaged pressure `pressure`
/// (compression positive) lies below its damaged pressure (1 − D) P by more than
/// [`ADHESION_MARGIN`] ρ c² (`rho_c2`), i.e. −D P > 10⁻⁹ ρ c² in tension. A particle in
/// compression, or intact, never is.
#[inline]
pub fn past_adhesion(pressure: f64, damage: f64, rho_c2: f64) -> bool {
    pressure < 0.0 && -damage * pressure > ADHESION_MARGIN * rho_c2
}

/// The decoupling decision for a same-material pair (module docs): `separating` is
/// (x_i − x_j)·(v_i − v_j) > 0, `adhesion_*` each side's [`past_adhesion`], `damage_*`
/// each side's D (projected on the pair's axis for tensor damage). Symmetric in (i, j).
#[inline]
pub fn decouples(
    separating: bool,
    adhesion_i: bool,
    adhesion_j: bool,
    damage_i: f64,
    damage_j: f64,
) -> bool {
    separating && (adhesion_i || adhesion_j) && (fully_damaged(damage_i) || fully_damaged(damage_j))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn thresholds() {
        // (1 − D)² < 0.01 ⇔ D > 0.9.
        assert!(!fully_damaged(0.89));
        assert!(!fully_damaged(0.8999));
        assert!(fully_damaged(0.91));
        assert!(fully_damaged(1.0));
        // Basalt ρc² ≈ 26.7 GPa: the margin is 26.7 Pa of damaged tension.
        let rc2 = 26.7e9;
        assert!(past_adhesion(-1.0e6, 0.5, rc2));
        assert!(!past_adhesion(-1.0e6, 0.0, rc2));
        assert!(!past_adhesion(1.0e6, 1.0, rc2));
        assert!(!past_adhesion(-20.0, 1.0, rc2));
        assert!(past_adhesion(-30.0, 1.0, rc2));
    }

    #[test]
    fn all_three_conditions_are_needed() {
        assert!(decouples(true, true, false, 0.95, 0.0));
        assert!(decouples(true, false, true, 0.0, 1.0));
        // Approaching fragments still push.
        assert!(!decouples(false, true, true, 1.0, 1.0));
        // No tension in a damaged particle: still coupled.
        assert!(!decouples(true, false, false, 1.0, 1.0));
        // Damaged in tension but not fully: still coupled.
        assert!(!decouples(true, true, true, 0.8, 0.5));
    }

    proptest! {
        #[test]
        fn symmetric(s: bool, ai: bool, aj: bool, di in 0.0..=1.0f64, dj in 0.0..=1.0f64) {
            prop_assert_eq!(decouples(s, ai, aj, di, dj), decouples(s, aj, ai, dj, di));
        }
    }
}
