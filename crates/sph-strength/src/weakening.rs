//! Damage weakening of the yield strength (paper §3.2, eqs 12 and 13).
//!
//! Two forms, exactly as the paper:
//!
//! - **multiplicative** (constant/von Mises, Johnson–Cook, Steinberg–Guinan), eq. (12):
//!   `Y = Y_i (1 − D)` — fully damaged metal has no shear strength;
//! - **frictional** (Drucker–Prager, Lundborg), eq. (13):
//!   `Y = Y_d D + Y_i (1 − D)` with `Y_d = min(μ_d P, Y_i)` — fully damaged rock keeps
//!   the friction of a granular material, μ_d the friction coefficient of fully damaged
//!   material (Collins, Melosh & Ivanov 2004, MAPS 39:217, eqs 4–6).
//!
//! In tension (P < 0) the damaged strength is `Y_d = 0`: μ_d P would be negative, and a
//! fully damaged granular material has no cohesion to resist shear under tension. Then
//! `Y = Y_i (1 − D)`. (miluphcuda's implementation of the same model instead keeps
//! Y = Y0 for P ≤ 0 whatever D; we follow the paper's formula with the clamp.)
//!
//! D must lie in [0, 1] (see [`crate::StrengthState::validate`]); for such D both forms
//! lie between the damaged and the intact strength.
//!
//! Damage also weakens the **shear modulus** (the study, paper §1.2.3: "the damage D
//! weakens the material's strength and its shear modulus"): G(D) = (1 − D) G0
//! ([`damaged_shear_modulus`]), the rule of LLNL Spheral's constant and Collins
//! strength models with a zero fully-damaged modulus (src/SolidMaterial/ConstantStrength.cc,
//! CollinsStrength.cc), which the study ran. Young's modulus E = 9KG/(3K + G) follows it,
//! and with it the flaw-activation strain, the longitudinal wave speed and the stress
//! rate 2G ε̇'. It is one rule for every model ([`crate::StrengthModel::damaged_shear_modulus`]),
//! switched on by the solver (`SchemeConfig::damaged_moduli`).

/// Eq. (12): `Y = Y_i (1 − D)`.
#[inline]
pub fn multiplicative_weakening(intact_yield: f64, damage: f64) -> f64 {
    intact_yield * (1.0 - damage)
}

/// Strength of fully damaged material, `Y_d = min(μ_d P, Y_i)` for P ≥ 0 and 0 in
/// tension (see the module docs).
#[inline]
pub fn damaged_strength(damaged_friction: f64, pressure: f64, intact_yield: f64) -> f64 {
    if pressure > 0.0 {
        (damaged_friction * pressure).min(intact_yield)
    } else {
        0.0
    }
}

/// Eq. (13): `Y = Y_d D + Y_i (1 − D)`, with `Y_d` from [`damaged_strength`].
#[inline]
pub fn frictional_weakening(
    intact_yield: f64,
    damaged_friction: f64,
    pressure: f64,
    damage: f64,
) -> f64 {
    let y_d = damaged_strength(damaged_friction, pressure, intact_yield);
    y_d * damage + intact_yield * (1.0 - damage)
}

/// G(D) = (1 − D) G0: the shear modulus of material with damage D (module docs).
#[inline]
pub fn damaged_shear_modulus(intact_modulus: f64, damage: f64) -> f64 {
    (1.0 - damage) * intact_modulus
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn damaged_modulus_is_linear_in_d() {
        assert_eq!(damaged_shear_modulus(22.7e9, 0.0), 22.7e9);
        assert_eq!(damaged_shear_modulus(22.7e9, 1.0), 0.0);
        assert_eq!(damaged_shear_modulus(20.0e9, 0.25), 15.0e9);
    }

    #[test]
    fn multiplicative_end_points() {
        assert_eq!(multiplicative_weakening(2.0e8, 0.0), 2.0e8);
        assert_eq!(multiplicative_weakening(2.0e8, 1.0), 0.0);
        assert_eq!(multiplicative_weakening(2.0e8, 0.25), 1.5e8);
    }

    #[test]
    fn damaged_strength_is_friction_capped_by_intact() {
        // μ_d = 0.8: Y_d = 0.8 P below Y_i, Y_i above, 0 in tension.
        assert_eq!(damaged_strength(0.8, 50.0e6, 183.0e6), 40.0e6);
        assert_eq!(damaged_strength(0.8, 5.0e9, 1.3e9), 1.3e9);
        assert_eq!(damaged_strength(0.8, -1.0e6, 90.0e6), 0.0);
    }

    #[test]
    fn frictional_mixes_linearly_in_d() {
        // Y_i = 100, Y_d = 0.5·100 = 50 at P = 100: D = 0.4 gives 0.4·50 + 0.6·100 = 80.
        let y = frictional_weakening(100.0, 0.5, 100.0, 0.4);
        assert!((y - 80.0).abs() < 1e-12);
    }
}
