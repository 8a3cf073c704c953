//! Solver throughput on a 3-D solid scene with strength and damage (~1e5 particles): an
//! aluminium sphere (Tillotson, Johnson–Cook with temperature, maximum-tensile-stress
//! damage) at 3.9 km/s into a basalt block (Tillotson, Lundborg, Benz–Asphaug flaws),
//! both on cubic lattices, the study's solver settings (ASPH off: scalar h). Prints
//! particle-steps per second and particle-derivative evaluations per second (an RK2 step
//! is two) at 1 and 2 threads, the share of time per phase, and the peak resident memory
//! per particle (VmHWM growth from before the set-up, Linux).
//!
//! `cargo bench -p sph-benches --bench solid3d` (options after `--`: block side in
//! spacings, steps).

use sph_core::glam::DVec3;
use sph_core::{Dim3, ParticleInit, Particles};
use sph_impact::materials::MaterialSpec;
use sph_impact::{SchemeConfig, Simulation};
use sph_kernel::WendlandC2;
use sph_riemann::ArtificialStress;
use std::time::Instant;

/// Peak resident set size (bytes) of this process so far, from /proc (Linux); 0 elsewhere.
fn peak_rss() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(0.0, |kb| kb * 1024.0)
}

fn setup(side: usize) -> Simulation<Dim3, WendlandC2> {
    let dx = 0.5e-3;
    let scheme = SchemeConfig {
        artificial_stress: ArtificialStress::default(),
        ..Default::default()
    };
    let h = scheme.n_target * dx;
    let basalt = MaterialSpec::basalt_study();
    let al = MaterialSpec::aluminium_2024_jc();
    let mut p = Particles::<Dim3>::new();
    // Block: side × side × side/2 spacings below z = 0.
    let half = side / 2;
    for k in 0..side * side * half {
        let (a, b, c) = (k % side, (k / side) % side, k / (side * side));
        let x = DVec3::new(
            (a as f64 + 0.5 - side as f64 / 2.0) * dx,
            (b as f64 + 0.5 - side as f64 / 2.0) * dx,
            -(c as f64 + 0.5) * dx,
        );
        p.push(ParticleInit {
            position: x,
            velocity: DVec3::ZERO,
            mass: basalt.density * dx * dx * dx,
            density: basalt.density,
            specific_energy: 0.0,
            smoothing_length: h,
            material: 0,
        });
    }
    let n_block = p.len();
    // Projectile: a 6 mm sphere just above the surface.
    let r = 3.0e-3;
    let m = (r / dx).ceil() as i64;
    for a in -m..=m {
        for b in -m..=m {
            for c in -m..=m {
                let x = DVec3::new(a as f64, b as f64, c as f64) * dx;
                if x.length() <= r {
                    p.push(ParticleInit {
                        position: x + DVec3::new(0.0, 0.0, r + dx),
                        velocity: DVec3::new(0.0, 0.0, -3900.0),
                        mass: al.density * dx * dx * dx,
                        density: al.density,
                        specific_energy: 0.0,
                        smoothing_length: h,
                        material: 1,
                    });
                }
            }
        }
    }
    let n_proj = p.len() - n_block;
    let block = basalt
        .body_material(
            &vec![dx * dx * dx; n_block],
            1,
            sph_damage::DamageVariable::CubeRoot,
        )
        .expect("basalt flaws");
    let sphere = al
        .body_material(
            &vec![dx * dx * dx; n_proj],
            2,
            sph_damage::DamageVariable::CubeRoot,
        )
        .expect("aluminium damage");
    Simulation::new(p, vec![block, sphere], scheme, WendlandC2, Vec::new(), None).unwrap()
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let side: usize = args.first().and_then(|s| s.parse().ok()).unwrap_or(58);
    let steps: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(6);
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let rss0 = peak_rss();
            let mut sim = setup(side);
            let n = sim.state.particles.len() as f64;
            for _ in 0..2 {
                sim.step(f64::INFINITY).unwrap();
            }
            sim.timings = Default::default();
            let t0 = Instant::now();
            for _ in 0..steps {
                sim.step(f64::INFINITY).unwrap();
            }
            let wall = t0.elapsed().as_secs_f64();
            let t = sim.timings;
            let tot = t.total();
            if threads == 1 {
                println!(
                    "3-D solid scene (Al sphere into basalt, strength + damage): {n} particles, {steps} RK2 steps after 2 warm-up steps"
                );
                println!(
                    "peak memory growth: {:.0} bytes per particle (VmHWM)",
                    (peak_rss() - rss0) / n
                );
            }
            println!(
                "{threads} thread(s): {:.3e} particle-steps/s, {:.3e} derivative evaluations/s ({:.3e} per core); phases: neighbours {:.0} %, EOS {:.0} %, gradients {:.0} %, pair loop {:.0} %, integration {:.0} %",
                n * steps as f64 / wall,
                t.derivative_evaluations as f64 / wall,
                t.derivative_evaluations as f64 / wall / threads as f64,
                100.0 * t.neighbours / tot,
                100.0 * t.eos / tot,
                100.0 * t.gradients / tot,
                100.0 * t.pairs / tot,
                100.0 * t.integration / tot,
            );
        });
    }
}
