//! Solver throughput on a 3-D Sedov blast with ~1e5 particles (46³ lattice): particle
//! steps per second and particle-derivative evaluations per second (an RK2 step is two),
//! at 1 and 2 threads, with the share of time per phase.
//!
//! `cargo bench -p sph-benches --bench sedov3d` (options after `--`: side, steps).

use sph_core::glam::DVec3;
use sph_core::{Dim3, ParticleInit, Particles};
use sph_eos::IdealGas;
use sph_impact::{DensityForm, Material, SchemeConfig, Simulation};
use sph_kernel::{Kernel, WendlandC2};
use std::time::Instant;

fn setup(side: usize, density: DensityForm) -> Simulation<Dim3, WendlandC2> {
    let dx = 2.0 / side as f64;
    let scheme = SchemeConfig {
        density,
        ..Default::default()
    };
    let h = scheme.n_target * dx;
    let mut xs = Vec::with_capacity(side * side * side);
    for k in 0..side * side * side {
        let (a, b, c) = (k % side, (k / side) % side, k / (side * side));
        xs.push(DVec3::new(
            -1.0 + (a as f64 + 0.5) * dx,
            -1.0 + (b as f64 + 0.5) * dx,
            -1.0 + (c as f64 + 0.5) * dx,
        ));
    }
    let weights: Vec<f64> = xs.iter().map(|x| WendlandC2.w(*x, h)).collect();
    let wsum: f64 = weights.iter().sum();
    let m = dx * dx * dx;
    let mut p = Particles::<Dim3>::new();
    for (x, w) in xs.iter().zip(&weights) {
        p.push(ParticleInit {
            position: *x,
            velocity: DVec3::ZERO,
            mass: m,
            density: 1.0,
            specific_energy: 1.5e-6 + w / wsum / m,
            smoothing_length: h,
            material: 0,
        });
    }
    let gas = vec![Material::fluid(
        "gas",
        IdealGas::with_gamma(5.0 / 3.0).unwrap(),
    )];
    Simulation::new(p, gas, scheme, WendlandC2, Vec::new(), None).unwrap()
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let side: usize = args.first().and_then(|s| s.parse().ok()).unwrap_or(46);
    let steps: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(10);
    println!(
        "3-D Sedov, {} particles, {steps} RK2 steps after 2 warm-up steps",
        side * side * side
    );
    for density in [DensityForm::Summation, DensityForm::Mass] {
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| {
                let mut sim = setup(side, density);
                for _ in 0..2 {
                    sim.step(f64::INFINITY).unwrap();
                }
                sim.timings = Default::default();
                let t0 = Instant::now();
                for _ in 0..steps {
                    sim.step(f64::INFINITY).unwrap();
                }
                let wall = t0.elapsed().as_secs_f64();
                let n = sim.state.particles.len() as f64;
                let t = sim.timings;
                let tot = t.total();
                println!(
                    "{density:?} density, {threads} thread(s): {:.3e} particle-steps/s, {:.3e} derivative evaluations/s ({:.3e} per core); phases: neighbours {:.0} %, pair set-up {:.0} %, EOS {:.0} %, gradients {:.0} %, pair loop {:.0} %, integration {:.0} %",
                    n * steps as f64 / wall,
                    t.derivative_evaluations as f64 / wall,
                    t.derivative_evaluations as f64 / wall / threads as f64,
                    100.0 * t.neighbours / tot,
                    100.0 * t.setup / tot,
                    100.0 * t.eos / tot,
                    100.0 * t.gradients / tot,
                    100.0 * t.pairs / tot,
                    100.0 * t.integration / tot,
                );
            });
        }
    }
}
