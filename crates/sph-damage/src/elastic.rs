//! Isotropic elastic relations needed by the damage models (Landau & Lifshitz,
//! *Theory of Elasticity*, §4–5). Plain formulas: inputs are not validated.

/// Young's modulus E = 9KG / (3K + G) from the bulk modulus K and shear modulus G, Pa.
/// Basalt (paper §3.3): K = 26.7 GPa, G = 22.7 GPa give E = 53.06 GPa.
#[inline]
pub fn youngs_modulus(bulk_modulus: f64, shear_modulus: f64) -> f64 {
    9.0 * bulk_modulus * shear_modulus / (3.0 * bulk_modulus + shear_modulus)
}

/// Poisson's ratio ν = (3K − 2G) / (2(3K + G)). Basalt: ν = 0.1688.
#[inline]
pub fn poisson_ratio(bulk_modulus: f64, shear_modulus: f64) -> f64 {
    (3.0 * bulk_modulus - 2.0 * shear_modulus) / (2.0 * (3.0 * bulk_modulus + shear_modulus))
}

/// Longitudinal (P-wave) speed c_L = √((K + 4G/3)/ρ), m/s (paper §2.5). Basalt at
/// ρ = 2700 kg/m³: 4593.3 m/s (verification.md §10).
#[inline]
pub fn longitudinal_wave_speed(bulk_modulus: f64, shear_modulus: f64, density: f64) -> f64 {
    ((bulk_modulus + 4.0 / 3.0 * shear_modulus) / density).sqrt()
}
