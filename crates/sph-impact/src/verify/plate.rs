//! Elastic oscillating plate (docs/verification.md, "Oscillating plate"; Gray, Monaghan & Swift
//! 2001): a cantilever in 2-D plane strain, L = 0.2 m beyond the clamp, H = 0.02 m thick,
//! ρ = 1000 kg/m³, E = 2 MPa, ν = 0.3975 (K = 3.25203 MPa, G = 0.715564 MPa; linear
//! elastic EOS, no yield). The clamp is the plate's own continuation over 0.06 m behind
//! x = 0 with its particles held at rest (SPHinXsys's constrained section).
//!
//! Initial velocity v_y(x) = V_f c0 [M(cos kx − cosh kx) − N(sin kx − sinh kx)]/Q with
//! kL = 1.8751041, c0 = √(K/ρ); the thin-plate period is T = 2π/ω,
//! ω² = E H² k⁴/(12ρ(1 − ν²)): T = 0.25403 s.
//!
//! Three runs: V_f = 0.01 with the tensor artificial stress (ε = 0.3, n = 4) over two
//! periods for the period (from the zero crossings of the tip's mean deflection), and
//! V_f = 0.05 with and without artificial stress over one period for the tensile
//! instability (smallest pair distance over the run, in initial spacings; pictures), the
//! latter two at min(n, 10) particles across.

use super::outcome::{Outcome, Panel, Picture, Profile};
use super::setup::elastic_solid;
use super::setup::{closest_pair, pieces, simulation};
use crate::{Material, SchemeConfig, Simulation, SolverError};
use sph_core::glam::DVec2;
use sph_core::{Dim2, ParticleInit, Particles};
use sph_kernel::KernelChoice;
use sph_riemann::{ArtificialStress, ArtificialStressForm};

const RHO: f64 = 1000.0;
const E_YOUNG: f64 = 2.0e6;
const NU: f64 = 0.3975;
const LENGTH: f64 = 0.2;
const THICKNESS: f64 = 0.02;
const CLAMP: f64 = 0.06;
const KL: f64 = 1.875_104_1;

fn moduli() -> (f64, f64) {
    (
        E_YOUNG / (3.0 * (1.0 - 2.0 * NU)),
        E_YOUNG / (2.0 * (1.0 + NU)),
    )
}

/// The thin-plate period (s).
pub(crate) fn exact_period() -> f64 {
    let k = KL / LENGTH;
    let omega = (E_YOUNG * THICKNESS.powi(2) * k.powi(4) / (12.0 * RHO * (1.0 - NU * NU))).sqrt();
    2.0 * std::f64::consts::PI / omega
}

/// The mode-shape velocity profile, 1 at x = L.
fn mode(x: f64) -> f64 {
    let k = KL / LENGTH;
    let (s, c, sh, ch) = (KL.sin(), KL.cos(), KL.sinh(), KL.cosh());
    let (m, n, q) = (s + sh, c + ch, 2.0 * (c * sh - s * ch));
    let kx = k * x;
    (m * (kx.cos() - kx.cosh()) - n * (kx.sin() - kx.sinh())) / q
}

/// A plate with `n` particles across the thickness and tip speed factor `vf`; returns
/// the simulation and the indices of the tip column.
fn plate(
    n: usize,
    vf: f64,
    scheme: SchemeConfig,
) -> Result<(Simulation<Dim2, KernelChoice>, Vec<usize>), SolverError> {
    let (bulk, shear) = moduli();
    let (eos, strength) = elastic_solid(RHO, bulk, shear, 1.0e12, None)?;
    let c0 = (bulk / RHO).sqrt();
    let dx = THICKNESS / n as f64;
    let nx_clamp = (CLAMP / dx).round() as usize;
    let nx = (LENGTH / dx).round() as usize;
    let mut p = Particles::<Dim2>::new();
    let (mut held, mut tip) = (Vec::new(), Vec::new());
    for ix in 0..nx_clamp + nx {
        let x = (ix as f64 + 0.5) * dx - CLAMP;
        for iy in 0..n {
            let y = (iy as f64 + 0.5) * dx - 0.5 * THICKNESS;
            let k = p.len();
            if x < 0.0 {
                held.push(k);
            }
            if ix == nx_clamp + nx - 1 {
                tip.push(k);
            }
            let vy = if x > 0.0 { vf * c0 * mode(x) } else { 0.0 };
            p.push(ParticleInit {
                position: DVec2::new(x, y),
                velocity: DVec2::new(0.0, vy),
                mass: RHO * dx * dx,
                density: RHO,
                specific_energy: 0.0,
                smoothing_length: scheme.n_target * dx,
                material: 0,
            });
        }
    }
    let mut sim = simulation(
        p,
        vec![Material::solid("rubber-like plate", eos, strength)],
        scheme,
        Vec::new(),
        Some(vec![dx; (nx_clamp + nx) * n]),
    )?;
    sim.hold_velocity(held)?;
    Ok((sim, tip))
}

/// Mean y of the given particles.
fn mean_y(sim: &Simulation<Dim2, KernelChoice>, ids: &[usize]) -> f64 {
    ids.iter()
        .map(|&i| sim.state.particles.position[i].y)
        .sum::<f64>()
        / ids.len() as f64
}

/// One run to `t_end`: tip history, the zero crossings of the tip deflection, the
/// smallest pair distance (in spacings) and the most pieces (friends-of-friends, link
/// 1.5 Δp) seen at the sampled times, and snapshots at the `snapshot_times`.
struct PlateRun {
    times: Vec<f64>,
    tip: Vec<f64>,
    crossings: Vec<f64>,
    min_distance: f64,
    max_pieces: usize,
    snapshots: Vec<(f64, Vec<f64>, Vec<f64>)>,
    steps: u64,
    energy_change: f64,
    particles: usize,
}

fn run_case(
    n: usize,
    vf: f64,
    scheme: SchemeConfig,
    t_end: f64,
    snapshot_times: &[f64],
) -> Result<PlateRun, SolverError> {
    let (mut sim, tip_ids) = plate(n, vf, scheme)?;
    let dx = THICKNESS / n as f64;
    let e0 = sim.conserved().energy();
    let mut out = PlateRun {
        times: vec![0.0],
        tip: vec![0.0],
        crossings: Vec::new(),
        min_distance: closest_pair(&sim.state.particles) / dx,
        max_pieces: pieces(&sim.state.particles, 1.5 * dx),
        snapshots: Vec::new(),
        steps: 0,
        energy_change: 0.0,
        particles: sim.state.particles.len(),
    };
    let sample = t_end / 400.0;
    let mut next_sample = sample;
    let mut shots = snapshot_times.iter().copied().peekable();
    while sim.state.time < t_end * (1.0 - 1e-12) {
        // Land exactly on the next snapshot time.
        let limit = shots.peek().map_or(t_end, |&t| t.min(t_end)) - sim.state.time;
        sim.step(limit.max(1e-12))?;
        out.steps += 1;
        let t = sim.state.time;
        let y = mean_y(&sim, &tip_ids);
        let y_prev = *out.tip.last().unwrap_or(&0.0);
        if t >= next_sample || shots.peek().is_some_and(|&s| t >= s * (1.0 - 1e-12)) {
            next_sample += sample;
            out.min_distance = out
                .min_distance
                .min(closest_pair(&sim.state.particles) / dx);
            out.max_pieces = out.max_pieces.max(pieces(&sim.state.particles, 1.5 * dx));
        }
        if y_prev != 0.0 && y_prev.signum() != y.signum() && y != 0.0 {
            let t_prev = *out.times.last().unwrap_or(&0.0);
            out.crossings
                .push(t_prev + (t - t_prev) * y_prev / (y_prev - y));
        }
        out.times.push(t);
        out.tip.push(y);
        if let Some(&s) = shots.peek()
            && t >= s * (1.0 - 1e-12)
        {
            shots.next();
            let p = &sim.state.particles;
            out.snapshots.push((
                s,
                p.position.iter().map(|x| x.x).collect(),
                p.position.iter().map(|x| x.y).collect(),
            ));
        }
    }
    out.energy_change = (sim.conserved().energy() - e0) / e0;
    Ok(out)
}

/// Runs the three cases with `n` particles across the thickness. The scheme's artificial
/// stress is replaced per case: on (the tensor form, ε = 0.3, n = 4, unless the scheme
/// sets a positive ε, then the scheme's) or off.
pub(crate) fn run(n: usize, scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    let wall = std::time::Instant::now();
    let period = exact_period();
    let with = if scheme.artificial_stress.is_off() {
        ArtificialStress {
            epsilon: 0.3,
            exponent: 4,
            form: ArtificialStressForm::Principal,
            cap: None,
        }
    } else {
        scheme.artificial_stress
    };
    let without = ArtificialStress {
        epsilon: 0.0,
        ..with
    };
    let mut s_with = scheme.clone();
    s_with.artificial_stress = with;
    let mut s_without = scheme;
    s_without.artificial_stress = without;

    let small = run_case(n, 0.01, s_with.clone(), 2.1 * period, &[])?;
    let shots = [0.25 * period, 0.75 * period, period];
    // The instability pair is judged by eye: 10 particles across are enough, and finer
    // runs spend their time on the period.
    let n_big = n.min(10);
    let big_with = run_case(n_big, 0.05, s_with, period, &shots)?;
    let big_without = run_case(n_big, 0.05, s_without, period, &shots)?;

    let mut out = Outcome::for_run(
        "plate",
        small.particles,
        n,
        Some(2.1 * period),
        small.steps + big_with.steps + big_without.steps,
        0.0,
    );
    // Period: crossings at T/2, T, 3T/2, ... → least-squares slope of crossing time
    // against its index, times 2.
    let c = &small.crossings;
    let measured = if c.len() >= 2 {
        let k: Vec<f64> = (0..c.len()).map(|i| i as f64).collect();
        let (mk, mc) = (
            k.iter().sum::<f64>() / k.len() as f64,
            c.iter().sum::<f64>() / c.len() as f64,
        );
        let sxy: f64 = k.iter().zip(c).map(|(a, b)| (a - mk) * (b - mc)).sum();
        let sxx: f64 = k.iter().map(|a| (a - mk) * (a - mk)).sum();
        2.0 * sxy / sxx
    } else {
        f64::NAN
    };
    let (bulk, _) = moduli();
    let c0 = (bulk / RHO).sqrt();
    let omega = 2.0 * std::f64::consts::PI / period;
    let amp = small.tip.iter().fold(0.0f64, |a, y| a.max(y.abs()));
    out.set("artificial_stress_epsilon", with.epsilon);
    out.set("period_exact", period);
    out.set("period", measured);
    out.set("period_error_relative", measured / period - 1.0);
    out.set("zero_crossings", c.len() as f64);
    out.set("tip_amplitude_vf001", amp);
    out.set("tip_amplitude_linear_vf001", 0.01 * c0 / omega);
    out.set("energy_change_relative_vf001", small.energy_change);
    out.set("min_pair_distance_vf005_with_stress", big_with.min_distance);
    out.set(
        "min_pair_distance_vf005_without_stress",
        big_without.min_distance,
    );
    out.set("max_pieces_vf005_with_stress", big_with.max_pieces as f64);
    out.set(
        "max_pieces_vf005_without_stress",
        big_without.max_pieces as f64,
    );
    out.set(
        "tip_amplitude_vf005_with_stress",
        big_with.tip.iter().fold(0.0f64, |a, y| a.max(y.abs())),
    );
    out.set("wall_time_s", wall.elapsed().as_secs_f64());
    out.profile = Profile {
        columns: ["t", "tip_y"].map(String::from).to_vec(),
        rows: small
            .times
            .iter()
            .zip(&small.tip)
            .map(|(t, y)| vec![*t, *y])
            .collect(),
    };
    let mut panels = vec![Panel {
        title: "tip deflection, V_f = 0.01 (ε = 0.3)".into(),
        labels: ("t (s)".into(), "y_tip (m)".into()),
        lines: vec![("SPH".into(), small.times.clone(), small.tip.clone())],
        ..Default::default()
    }];
    for (label, run) in [
        ("with artificial stress", &big_with),
        ("without artificial stress", &big_without),
    ] {
        for (t, x, y) in &run.snapshots {
            panels.push(Panel {
                title: format!("V_f = 0.05 {label}, t = {:.3} T", t / period),
                labels: ("x (m)".into(), "y (m)".into()),
                points: vec![("particles".into(), x.clone(), y.clone())],
                equal_aspect: true,
                ..Default::default()
            });
        }
    }
    out.pictures.push(Picture {
        name: "plate".into(),
        title: "Oscillating plate: tip history and V_f = 0.05 snapshots".into(),
        panels,
        columns: 3,
    });
    Ok(out)
}
