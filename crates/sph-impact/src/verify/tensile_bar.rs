//! Tensile bar with Benz–Asphaug damage (verification.md §7): the peak stress of a bar
//! pulled at constant strain rate, against the static strength E ε_1 and the Grady–Kipp
//! rate scaling σ_max ∝ ε̇^(3/(m+3)).
//!
//! Set-up: a basalt bar (linear elastic, K = 26.7 GPa, G = 22.7 GPa, ρ = 2700 kg/m³,
//! elastic strength; BA99 Weibull flaws k = 4e35 m⁻³, m = 9) of length 50 mm and
//! cross-section (0.5 mm)², in 1-D uniaxial strain, `n` particles. The whole bar starts
//! in homogeneous stretching, v = ε̇ x, and the n_target + 1 particles beyond each end are
//! held at their velocity (undamageable, bonded to the bar): the strain then grows
//! uniformly, ε = ε̇ t, with no wave to ramp. Flaws are seeded over the bar's volume
//! V = 50 mm × (0.5 mm)², so ε_1 = (kV)^(−1/m) (first flaw).
//!
//! Measured at ε̇ = 1e2…1e6 s⁻¹: the peak over time of the mean axial stress over the
//! middle half of the bar. Checks: the peak at the slowest rate against E ε_1 (flaw
//! activation reads σ_1/E), and the fitted exponent of σ_max against ε̇ against
//! 3/(m+3) = 0.25.

use super::outcome::{Outcome, Profile};
use super::setup::elastic_solid;
use super::setup::simulation;
use crate::{Material, SchemeConfig, SolverError};
use sph_core::{Dim1, ParticleInit, Particles};
use sph_damage::{BenzAsphaug, BenzAsphaugParams, DamageVariable, WeibullParams};

const RHO: f64 = 2700.0;
const BULK: f64 = 26.7e9;
const SHEAR: f64 = 22.7e9;
const LENGTH: f64 = 0.05;
const SIDE: f64 = 0.5e-3;
const RATES: [f64; 5] = [1e2, 1e3, 1e4, 1e5, 1e6];
const SEED: u64 = 2024;

/// The peak of one run: (σ_max, ε at the peak, largest D at the end, steps).
fn peak(n: usize, rate: f64, scheme: &SchemeConfig) -> Result<(f64, f64, f64, u64), SolverError> {
    let bad = |e: String| SolverError::Material(e);
    let (eos, strength) = elastic_solid(RHO, BULK, SHEAR, 1.0e12, None)?;
    let dx = LENGTH / n as f64;
    let volume = dx * SIDE * SIDE;
    let params = BenzAsphaugParams::new(WeibullParams::BASALT_BA99, SEED)
        .with_variable(DamageVariable::CubeRoot);
    let flaws =
        BenzAsphaug::seed_with_volumes(params, &vec![volume; n]).map_err(|e| bad(e.to_string()))?;
    let hold = scheme.n_target.ceil() as usize + 1;
    let mut p = Particles::<Dim1>::new();
    let mut held = Vec::new();
    for k in 0..n + 2 * hold {
        let x = (k as f64 + 0.5 - hold as f64) * dx - 0.5 * LENGTH;
        let inside = k >= hold && k < n + hold;
        if !inside {
            held.push(k);
        }
        p.push(ParticleInit {
            position: x,
            velocity: rate * x,
            mass: RHO * dx,
            density: RHO,
            specific_energy: 0.0,
            smoothing_length: scheme.n_target * dx,
            material: if inside { 0 } else { 1 },
        });
    }
    let materials = vec![
        Material::solid("basalt bar (BA99 flaws)", eos, strength).with_damage(flaws),
        Material::solid("held ends (no flaws)", eos, strength),
    ];
    let mut sim = simulation(p, materials, scheme.clone(), Vec::new(), None)?;
    sim.hold_velocity(held)?;
    let eps_1 = WeibullParams::BASALT_BA99.min_activation_strain(LENGTH * SIDE * SIDE);
    // At most a strain increment of ε_1/300 per step, so the activation of the first
    // flaws and the peak are resolved at every rate.
    let max_dt = eps_1 / (300.0 * rate);
    let (mut best, mut eps_best, mut steps) = (0.0f64, 0.0, 0u64);
    loop {
        sim.step(max_dt)?;
        steps += 1;
        let (pressure, _) = sim.pressure_and_sound_speed();
        let damage = sim.damage();
        let s = &sim.state;
        let (mut sum, mut count) = (0.0, 0);
        for i in 0..s.particles.len() {
            if s.particles.position[i].abs() < 0.25 * LENGTH * (1.0 + rate * s.time) {
                let d = damage[i];
                let p_d = if pressure[i] < 0.0 {
                    (1.0 - d) * pressure[i]
                } else {
                    pressure[i]
                };
                sum += (1.0 - d) * s.stress[i].x_axis.x - p_d;
                count += 1;
            }
        }
        let sigma = sum / count.max(1) as f64;
        if sigma > best {
            best = sigma;
            eps_best = rate * s.time;
        }
        // Past the peak and well down from it, or far beyond any plausible peak.
        if (best > 0.0 && sigma < 0.5 * best) || rate * s.time > 200.0 * eps_1 {
            break;
        }
    }
    let d_max = sim.damage().into_iter().fold(0.0, f64::max);
    Ok((best, eps_best, d_max, steps))
}

/// Runs the five strain rates with `n` particles along the bar.
pub(crate) fn run(n: usize, scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    let wall = std::time::Instant::now();
    let e_young = sph_damage::youngs_modulus(BULK, SHEAR);
    let eps_1 = WeibullParams::BASALT_BA99.min_activation_strain(LENGTH * SIDE * SIDE);
    let mut out = Outcome {
        problem: "tensile-bar".into(),
        ..Default::default()
    };
    let (mut peaks, mut rows, mut steps) = (Vec::new(), Vec::new(), 0);
    for &rate in &RATES {
        let (sigma, eps, d_max, k) = peak(n, rate, &scheme)?;
        peaks.push(sigma);
        steps += k;
        rows.push(vec![rate, sigma, eps, d_max]);
        out.set(
            &format!("peak_stress_rate_1e{}", rate.log10().round()),
            sigma,
        );
    }
    let m = WeibullParams::BASALT_BA99.m();
    let exponent = sph_diagnostics::log_log_slope(&RATES, &peaks);
    let expected = 3.0 / (m + 3.0);
    out.set("youngs_modulus", e_young);
    out.set("first_flaw_strain", eps_1);
    out.set("static_strength_e_eps1", e_young * eps_1);
    out.set("failure_stress_slowest_rate", peaks[0]);
    out.set(
        "failure_stress_slowest_over_e_eps1",
        peaks[0] / (e_young * eps_1),
    );
    out.set("rate_exponent", exponent);
    out.set("rate_exponent_expected", expected);
    out.set("rate_exponent_error_relative", exponent / expected - 1.0);
    out.set("particles", n as f64);
    out.set("resolution", n as f64);
    out.set("steps", steps as f64);
    out.set("wall_time_s", wall.elapsed().as_secs_f64());
    out.profile = Profile {
        columns: ["strain_rate", "peak_stress", "strain_at_peak", "max_damage"]
            .map(String::from)
            .to_vec(),
        rows,
    };
    Ok(out)
}
