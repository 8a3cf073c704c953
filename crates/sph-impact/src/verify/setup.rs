//! Shared set-up and measurement helpers of the verification problems.

use crate::solver::{Boundary, Material, SchemeConfig, Simulation, SolverError};
use sph_core::{Dimension, ParticleInit, Particles, Vector};
use sph_eos::IdealGas;
use sph_kernel::KernelChoice;

/// The smallest distance between two particles (all pairs: the 2-D problems that use it
/// have a few thousand particles).
pub(crate) fn closest_pair<D: Dimension>(p: &Particles<D>) -> f64 {
    let x = &p.position;
    let mut best = f64::INFINITY;
    for i in 0..x.len() {
        for j in i + 1..x.len() {
            let d = x[i] - x[j];
            best = best.min(d.dot(d));
        }
    }
    best.sqrt()
}

/// How many pieces the particles form: friends-of-friends clusters with link length
/// `link`.
pub(crate) fn pieces<D: Dimension>(p: &Particles<D>, link: f64) -> usize {
    let pts: Vec<[f64; 3]> = p.position.iter().map(|x| x.to_array3()).collect();
    sph_diagnostics::friends_of_friends(&pts, link).count()
}

/// An ideal gas of adiabatic index `gamma`, as the only material.
pub(crate) fn gas(gamma: f64) -> Result<Vec<Material>, SolverError> {
    let eos = IdealGas::with_gamma(gamma).map_err(|e| SolverError::Material(e.to_string()))?;
    Ok(vec![Material::fluid(
        format!("ideal gas γ={gamma:.4}"),
        eos,
    )])
}

/// A particle of the gas at rest-frame values.
pub(crate) fn particle<V: Vector>(
    x: V,
    v: V,
    mass: f64,
    rho: f64,
    pressure: f64,
    gamma: f64,
    h: f64,
) -> ParticleInit<V> {
    ParticleInit {
        position: x,
        velocity: v,
        mass,
        density: rho,
        specific_energy: pressure / ((gamma - 1.0) * rho),
        smoothing_length: h,
        material: 0,
    }
}

/// A simulation with the scheme's kernel.
pub(crate) fn simulation<D: Dimension>(
    particles: Particles<D>,
    materials: Vec<Material>,
    scheme: SchemeConfig,
    boundaries: Vec<Boundary<D>>,
    spacing0: Option<Vec<f64>>,
) -> Result<Simulation<D, KernelChoice>, SolverError> {
    let k = scheme.kernel;
    Simulation::new(particles, materials, scheme, k, boundaries, spacing0)
}

/// Where `values` (sorted by `coords`, ascending) cross `level` for the last time going
/// outward, by linear interpolation; None if they never do.
pub(crate) fn last_crossing(coords: &[f64], values: &[f64], level: f64) -> Option<f64> {
    (1..coords.len()).rev().find_map(|k| {
        let (a, b) = (values[k - 1] - level, values[k] - level);
        if a * b <= 0.0 && a != b {
            Some(coords[k - 1] + (coords[k] - coords[k - 1]) * a / (a - b))
        } else {
            None
        }
    })
}

/// Median of a slice (NaN for none).
pub(crate) fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// A linear elastic solid: EOS P = K(ρ/ρ0 − 1) and von Mises at `yield_strength` (Pa)
/// with shear modulus G and optional linear hardening H (Pa); a yield far above the
/// stresses reached makes it purely elastic.
pub(crate) fn elastic_solid(
    rho0: f64,
    bulk: f64,
    shear: f64,
    yield_strength: f64,
    hardening: Option<f64>,
) -> Result<(sph_eos::LinearElastic, sph_strength::VonMises), SolverError> {
    let bad = |e: String| SolverError::Material(e);
    let eos = sph_eos::LinearElastic::new(sph_eos::LinearElasticParams { rho0, K0: bulk })
        .map_err(|e| bad(e.to_string()))?;
    let strength = sph_strength::VonMises::new(sph_strength::VonMisesParams {
        yield_strength,
        shear_modulus: shear,
        hardening: hardening.map(|modulus| sph_strength::von_mises::LinearHardening { modulus }),
    })
    .map_err(|e| bad(e.to_string()))?;
    Ok((eos, strength))
}
