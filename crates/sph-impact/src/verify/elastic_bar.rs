//! Elastic bars in uniaxial strain (docs/verification.md, "Solid dynamics: elastic bars"): two
//! identical aluminium bars (E = 70 GPa, ν = 0.3, ρ = 2700 kg/m³: K = 58.33 GPa, G = 26.92 GPa,
//! linear elastic EOS, von Mises with a yield strength far above the stresses reached) of length
//! L = 0.1 m collide at ±10 m/s. The symmetric pair replaces a rigid wall, which could pull on the
//! bar in tension through its ghosts.
//!
//! Exact (linear elasticity): the compressive front runs at c_L = √((K + 4G/3)/ρ) =
//! 5907.6 m/s with σ_xx = −ρ c_L v = −159.5 MPa behind it; the bars part at 2L/c_L =
//! 33.85 µs with ∓10 m/s. Checks: front speed from the half-plateau crossing at three
//! times, the plateau stress, and KE/KE0 after separation (t = 3L/c_L).

use super::outcome::{Outcome, Profile};
use super::setup::elastic_solid;
use super::setup::{last_crossing, median, simulation};
use crate::{Material, SchemeConfig, Simulation, SolverError};
use sph_core::{Dim1, ParticleInit, Particles};
use sph_kernel::KernelChoice;

const RHO: f64 = 2700.0;
const E_YOUNG: f64 = 70.0e9;
const NU: f64 = 0.3;
const LENGTH: f64 = 0.1;
const SPEED: f64 = 10.0;

/// σ_xx = S_xx − P of every particle, with positions, sorted by x.
pub(crate) fn axial_stress(sim: &Simulation<Dim1, KernelChoice>) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let (p, _) = sim.pressure_and_sound_speed();
    let s = &sim.state;
    let mut idx: Vec<usize> = (0..s.particles.len()).collect();
    idx.sort_by(|&a, &b| s.particles.position[a].total_cmp(&s.particles.position[b]));
    let x = idx.iter().map(|&i| s.particles.position[i]).collect();
    let sxx = idx.iter().map(|&i| s.stress[i].x_axis.x - p[i]).collect();
    let v = idx.iter().map(|&i| s.particles.velocity[i]).collect();
    (x, sxx, v)
}

/// Two aluminium plates of `length`, `n` particles each, closing at `2·speed` in
/// uniaxial strain, one material per plate (an unbonded interface), von Mises with
/// `yield_strength`. Returns the simulation and c_L.
pub(crate) fn two_plates(
    n: usize,
    length: f64,
    speed: f64,
    yield_strength: f64,
    scheme: SchemeConfig,
) -> Result<(Simulation<Dim1, KernelChoice>, f64), SolverError> {
    let (p, plates, c_l, _) = two_plates_set_up(n, length, speed, yield_strength, &scheme)?;
    Ok((simulation(p, plates, scheme, Vec::new(), None)?, c_l))
}

/// The particles and materials of [`two_plates`], with c_L and the spacing.
pub(crate) fn two_plates_set_up(
    n: usize,
    length: f64,
    speed: f64,
    yield_strength: f64,
    scheme: &SchemeConfig,
) -> Result<(Particles<Dim1>, Vec<Material>, f64, f64), SolverError> {
    let bulk = E_YOUNG / (3.0 * (1.0 - 2.0 * NU));
    let shear = E_YOUNG / (2.0 * (1.0 + NU));
    let c_l = ((bulk + 4.0 / 3.0 * shear) / RHO).sqrt();
    let (eos, strength) = elastic_solid(RHO, bulk, shear, yield_strength, None)?;
    let dx = length / n as f64;
    let mut p = Particles::<Dim1>::new();
    for k in 0..n {
        for (side, material) in [(-1.0, 0), (1.0, 1)] {
            let x = side * (k as f64 + 0.5) * dx;
            p.push(ParticleInit {
                position: x,
                velocity: -side * speed,
                mass: RHO * dx,
                density: RHO,
                specific_energy: 0.0,
                smoothing_length: scheme.n_target * dx,
                material,
            });
        }
    }
    // One material per plate, so their contact is an unbonded interface that can part.
    let plates = vec![
        Material::solid("plate A (aluminium)", eos, strength),
        Material::solid("plate B", eos, strength),
    ];
    Ok((p, plates, c_l, dx))
}

/// Runs with `n` particles per bar.
pub(crate) fn run(n: usize, scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    let (mut sim, c_l) = two_plates(n, LENGTH, SPEED, 1.0e12, scheme)?;
    let c0 = sim.conserved();
    let ke0 = c0.kinetic;
    let plateau = RHO * c_l * SPEED;
    let mut out = Outcome {
        problem: "elastic-bar".into(),
        ..Default::default()
    };
    // Front position (right bar, x > 0) at three times before it reaches the free end.
    let t_cross = LENGTH / c_l;
    let (mut times, mut fronts, mut plateaus) = (Vec::new(), Vec::new(), Vec::new());
    let wall = std::time::Instant::now();
    let mut steps = 0;
    for frac in [0.3, 0.5, 0.7] {
        let t = frac * t_cross;
        steps += sim.run_until(t, |_, _| {})?;
        let (x, sxx, _) = axial_stress(&sim);
        let right: Vec<usize> = (0..x.len()).filter(|&k| x[k] > 0.0).collect();
        let xr: Vec<f64> = right.iter().map(|&k| x[k]).collect();
        let sr: Vec<f64> = right.iter().map(|&k| -sxx[k]).collect();
        if let Some(front) = last_crossing(&xr, &sr, 0.5 * plateau) {
            times.push(t);
            fronts.push(front);
        }
        // Plateau: the middle half of the compressed zone.
        let zone: Vec<f64> = right
            .iter()
            .filter(|&&k| x[k] > 0.25 * c_l * t && x[k] < 0.75 * c_l * t)
            .map(|&k| -sxx[k])
            .collect();
        plateaus.push(median(zone));
    }
    // Front speed: least-squares line through (t, x_front) (fronts start at x = 0, t = 0).
    let speed = if times.len() >= 2 {
        let n = times.len() as f64;
        let (mt, mx) = (
            times.iter().sum::<f64>() / n,
            fronts.iter().sum::<f64>() / n,
        );
        let sxy: f64 = times
            .iter()
            .zip(&fronts)
            .map(|(t, x)| (t - mt) * (x - mx))
            .sum();
        let sxx: f64 = times.iter().map(|t| (t - mt) * (t - mt)).sum();
        sxy / sxx
    } else {
        f64::NAN
    };
    out.set("longitudinal_wave_speed_exact", c_l);
    // Relative to the material ahead of the front, which moves at −SPEED.
    let speed = speed + SPEED;
    out.set("front_speed", speed);
    out.set("front_speed_error_relative", speed / c_l - 1.0);
    out.set("plateau_stress_exact", plateau);
    for (k, ps) in plateaus.iter().enumerate() {
        out.set(&format!("plateau_stress_t{}", k + 1), *ps);
    }
    let worst = plateaus
        .iter()
        .map(|p| (p / plateau - 1.0).abs())
        .fold(0.0, f64::max);
    out.set("plateau_stress_error_max", worst);
    // Rebound: well after separation at 2L/c_L.
    steps += sim.run_until(3.0 * t_cross, |_, _| {})?;
    let c1 = sim.conserved();
    out.set("rebound_kinetic_energy_ratio", c1.kinetic / ke0);
    out.set(
        "energy_change_relative",
        (c1.energy() - c0.energy()) / c0.energy(),
    );
    out.set("internal_energy_over_ke0", c1.internal / ke0);
    let (x, sxx, v) = axial_stress(&sim);
    let right_speed = median((0..x.len()).filter(|&k| x[k] > 0.0).map(|k| v[k]).collect());
    out.set("rebound_speed_right_bar", right_speed);
    out.set("particles", sim.state.particles.len() as f64);
    out.set("resolution", n as f64);
    out.set("steps", steps as f64);
    out.set("wall_time_s", wall.elapsed().as_secs_f64());
    out.profile = Profile {
        columns: ["x", "sigma_xx", "v"].map(String::from).to_vec(),
        rows: (0..x.len()).map(|k| vec![x[k], sxx[k], v[k]]).collect(),
    };
    Ok(out)
}
