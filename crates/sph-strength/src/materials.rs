//! Named parameter sets, each with its source. Pass one to its model's `new`:
//!
//! ```
//! use sph_strength::{Lundborg, materials};
//! let basalt = Lundborg::new(materials::BASALT_LUNDBORG).unwrap();
//! # let _ = basalt;
//! ```
//!
//! Every set here passes validation (tested). Values the cited source does not give
//! (mostly the shear modulus of a Johnson–Cook set) are marked with their own source.

use crate::johnson_cook::JohnsonCookParams;
use crate::lundborg::{LundborgParams, LundborgTension};
use crate::steinberg_guinan::SteinbergGuinanParams;
use crate::von_mises::{LinearHardening, VonMisesParams};

/// Basalt target of the reference study (paper §6, Table 1): Lundborg with
/// Y0 = 26.5 MPa, μ = μ_d = 0.6, Y_M = 300 MPa, G = 22.7 GPa.
pub const BASALT_LUNDBORG: LundborgParams = LundborgParams {
    cohesion: 26.5e6,
    friction: 0.6,
    limit_strength: 300.0e6,
    damaged_friction: 0.6,
    shear_modulus: 22.7e9,
    tension: LundborgTension::LinearToZero,
};

/// Granite of Collins, Melosh & Ivanov 2004 (MAPS 39:217) as in
/// docs/reference/strength_point_values.md, "Lundborg granite and radial return":
/// Y0 = 90 MPa, μ_i = 2, Y_M = 1.5 GPa, μ_d = 0.8. Neither source gives G here:
/// G = 27 GPa is the granite shear modulus of miluphcuda's Collins-model test material.
pub const GRANITE_LUNDBORG_COLLINS2004: LundborgParams = LundborgParams {
    cohesion: 90.0e6,
    friction: 2.0,
    limit_strength: 1.5e9,
    damaged_friction: 0.8,
    shear_modulus: 27.0e9,
    tension: LundborgTension::LinearToZero,
};

/// Aluminium 2024 projectile, Johnson–Cook "measured" row of Table A2 (the set the
/// study uses): A = 265 MPa, B = 426 MPa, n = 0.34, C = 0.015, m = 1.0, T_m = 935 K,
/// T_r = 300 K; G = 26.5 GPa (Table 1). The paper does not state ε̇0: 1 /s assumed.
pub const ALUMINIUM_2024_JC_MEASURED: JohnsonCookParams = JohnsonCookParams {
    a: 2.65e8,
    b: 4.26e8,
    n: 0.34,
    c: 0.015,
    m: 1.0,
    melt_temperature: 935.0,
    reference_temperature: 300.0,
    reference_strain_rate: 1.0,
    shear_modulus: 26.5e9,
};

/// Aluminium 2024, Johnson–Cook "earlier" row of Table A2 (a set from an earlier
/// simulation of the same experiment, which the study calls inconsistent): n = 0.019,
/// C = 0.34, m = 0.4, otherwise as [`ALUMINIUM_2024_JC_MEASURED`].
pub const ALUMINIUM_2024_JC_EARLIER: JohnsonCookParams = JohnsonCookParams {
    a: 2.65e8,
    b: 4.26e8,
    n: 0.019,
    c: 0.34,
    m: 0.4,
    melt_temperature: 935.0,
    reference_temperature: 300.0,
    reference_strain_rate: 1.0,
    shear_modulus: 26.5e9,
};

/// Aluminium 2024, Steinberg–Guinan Table A3: G0 = 28.6 GPa, Y0 = 260 MPa,
/// Y_max = 760 MPa, β = 310, n = 0.185, G'_p = 1.8647, G'_T = −1.762e7 Pa/K,
/// T_m0 = 1220 K (Y'_p = 0.01695 is implied by the shared bracket, see
/// [`crate::SteinbergGuinan`]). ρ0 = 2785 kg/m³ from paper Table 1.
pub const ALUMINIUM_2024_SG: SteinbergGuinanParams = SteinbergGuinanParams {
    shear_modulus: 2.86e10,
    pressure_coefficient: 1.8647 / 2.86e10,
    temperature_coefficient: 1.762e7 / 2.86e10,
    yield_strength: 2.6e8,
    max_yield_strength: 7.6e8,
    hardening_coefficient: 310.0,
    hardening_exponent: 0.185,
    initial_plastic_strain: 0.0,
    reference_density: 2785.0,
    melt_temperature: 1220.0,
    melt_law: None,
};

/// OFHC copper, Johnson–Cook (Johnson & Cook 1983; docs/reference/strength_point_values.md,
/// "Johnson–Cook copper and aluminium"): A = 90 MPa, B = 292 MPa, n = 0.31, C = 0.025,
/// m = 1.09, T_m = 1356 K, T_r = 298 K, ε̇0 = 1 /s. G = 47.7 GPa is copper's ambient shear
/// modulus G0 from Steinberg 1996 (same page, "Steinberg–Guinan copper").
pub const OFHC_COPPER_JC: JohnsonCookParams = JohnsonCookParams {
    a: 90.0e6,
    b: 292.0e6,
    n: 0.31,
    c: 0.025,
    m: 1.09,
    melt_temperature: 1356.0,
    reference_temperature: 298.0,
    reference_strain_rate: 1.0,
    shear_modulus: 47.7e9,
};

/// Al 6061-T6, Johnson–Cook (the set of the LS-DYNA material libraries;
/// docs/reference/strength_point_values.md, "Johnson–Cook copper and aluminium"):
/// A = 324 MPa, B = 114 MPa, n = 0.42, C = 0.002, m = 1.34, T_m = 925 K (some sources use
/// 855 K), T_r = 298 K, ε̇0 = 1 /s. G = 26 GPa (handbook value for 6061-T6,
/// E = 68.9 GPa, ν = 0.33).
pub const AL_6061_T6_JC: JohnsonCookParams = JohnsonCookParams {
    a: 324.0e6,
    b: 114.0e6,
    n: 0.42,
    c: 0.002,
    m: 1.34,
    melt_temperature: 925.0,
    reference_temperature: 298.0,
    reference_strain_rate: 1.0,
    shear_modulus: 26.0e9,
};

/// Copper, Steinberg–Guinan "starting" set of the Spheral Taylor-impact test
/// (docs/reference/strength_point_values.md, "Steinberg–Guinan copper"; Steinberg 1996):
/// G0 = 0.477 Mbar, A = 2.83 /Mbar, B = 3.77e-4 /K, Y0 = 1.2 kbar, Y_max = 6.4 kbar, β = 36,
/// n = 0.45, ε_i = 0. ρ0 = 8930 kg/m³ and T_m0 = 1790 K from Steinberg 1996 (no melt law by
/// default; that table gives γ0 = 2.02, a = 1.5 for [`crate::SgMeltLaw`]).
pub const COPPER_SG: SteinbergGuinanParams = SteinbergGuinanParams {
    shear_modulus: 47.7e9,
    // 1 Mbar = 1e11 Pa.
    pressure_coefficient: 2.83e-11,
    temperature_coefficient: 3.77e-4,
    yield_strength: 0.12e9,
    max_yield_strength: 0.64e9,
    hardening_coefficient: 36.0,
    hardening_exponent: 0.45,
    initial_plastic_strain: 0.0,
    reference_density: 8930.0,
    melt_temperature: 1790.0,
    melt_law: None,
};

/// Copper, Steinberg–Guinan "fitted" set of the Spheral Taylor-impact test
/// (docs/reference/strength_point_values.md, "Steinberg–Guinan copper"): as [`COPPER_SG`]
/// but Y0 = 3.2 kbar, β = 5, n = 0.30.
pub const COPPER_SG_TAYLOR_FIT: SteinbergGuinanParams = SteinbergGuinanParams {
    yield_strength: 0.32e9,
    hardening_coefficient: 5.0,
    hardening_exponent: 0.30,
    ..COPPER_SG
};

/// Copper of the Taylor-bar code benchmark (docs/verification.md, "Taylor bar"; Wilkins & Guinan
/// 1973 geometry): von Mises σ_y = 400 MPa with linear hardening H = 100 MPa,
/// G = E/(2(1 + ν)) = 117 GPa / 2.7 = 43.33 GPa.
pub const TAYLOR_BAR_COPPER: VonMisesParams = VonMisesParams {
    yield_strength: 400.0e6,
    shear_modulus: 117.0e9 / 2.7,
    hardening: Some(LinearHardening { modulus: 100.0e6 }),
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{JohnsonCook, Lundborg, SteinbergGuinan, VonMises};

    #[test]
    fn every_preset_validates() {
        for p in [BASALT_LUNDBORG, GRANITE_LUNDBORG_COLLINS2004] {
            Lundborg::new(p).unwrap();
        }
        for p in [
            ALUMINIUM_2024_JC_MEASURED,
            ALUMINIUM_2024_JC_EARLIER,
            OFHC_COPPER_JC,
            AL_6061_T6_JC,
        ] {
            JohnsonCook::new(p).unwrap();
        }
        for p in [ALUMINIUM_2024_SG, COPPER_SG, COPPER_SG_TAYLOR_FIT] {
            SteinbergGuinan::new(p).unwrap();
        }
        VonMises::new(TAYLOR_BAR_COPPER).unwrap();
    }
}
