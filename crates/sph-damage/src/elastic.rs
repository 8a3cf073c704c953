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
/// ρ = 2700 kg/m³: 4593.3 m/s (docs/reference/weibull_flaws.md, "Parameter sets").
#[inline]
pub fn longitudinal_wave_speed(bulk_modulus: f64, shear_modulus: f64, density: f64) -> f64 {
    ((bulk_modulus + 4.0 / 3.0 * shear_modulus) / density).sqrt()
}

/// The same c_L from the bulk sound speed c = √(K/ρ) an equation of state gives:
/// c_L = √(c² + 4G/(3ρ)) (c itself for a fluid, G = 0). The one formula the solver uses
/// for the time step, the pair's signal speed and the crack speed.
#[inline]
pub fn longitudinal_speed(sound_speed: f64, shear_modulus: f64, density: f64) -> f64 {
    if shear_modulus > 0.0 {
        (sound_speed * sound_speed + 4.0 * shear_modulus / (3.0 * density)).sqrt()
    } else {
        sound_speed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// c_L from the sound speed equals c_L from K (basalt at 2700 kg/m³: 4593.3 m/s) to
    /// round-off; a fluid's is its sound speed, bit for bit.
    #[test]
    fn longitudinal_speed_from_the_sound_speed() {
        let (k, g, rho): (f64, f64, f64) = (26.7e9, 22.7e9, 2700.0);
        let c = (k / rho).sqrt();
        let from_c = longitudinal_speed(c, g, rho);
        assert!((from_c / longitudinal_wave_speed(k, g, rho) - 1.0).abs() < 1e-15);
        assert!((from_c - 4593.3).abs() < 0.05, "{from_c}");
        assert_eq!(longitudinal_speed(1500.0, 0.0, 1000.0), 1500.0);
    }
}
