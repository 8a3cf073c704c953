//! Solver throughput on a 3-D solid scene with strength and damage (~1e5 particles): the
//! scene of `verify contact`'s 3-D part (`sph_impact::verify::sphere_into_block`), an
//! aluminium sphere (Tillotson, Johnson–Cook with temperature, maximum-tensile-stress
//! damage) at 3.9 km/s into a basalt block (Tillotson, Lundborg, Benz–Asphaug flaws),
//! cubic lattices at 6 mm/15 = 0.4 mm, the study's artificial stress, scalar h. Prints
//! particle-steps per second and particle-derivative evaluations per second (an RK2 step
//! is two) at 1 and 2 threads, the share of time per phase, and the peak resident memory
//! per particle (VmHWM growth from before the set-up, Linux), and the peak of the live heap
//! per particle counted by this binary's allocator, over the whole run and over the steps
//! alone (what a long run holds at its worst, whatever the set-up needed).
//!
//! `cargo bench -p sph-benches --bench solid3d` (options after `--`: spacings across the
//! sphere, steps).

use sph_benches::{Counting, LIVE, PEAK, peak_rss};
use sph_core::Dim3;
use sph_impact::{SchemeConfig, Simulation};
use sph_kernel::KernelChoice;
use std::sync::atomic::Ordering;
use std::time::Instant;

#[global_allocator]
static ALLOCATOR: Counting = Counting;

fn setup(n: usize) -> Simulation<Dim3, KernelChoice> {
    sph_impact::verify::sphere_into_block(n, SchemeConfig::default())
        .expect("scene")
        .0
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let n: usize = args.first().and_then(|s| s.parse().ok()).unwrap_or(15);
    let steps: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(6);
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let rss0 = peak_rss();
            let heap0 = LIVE.load(Ordering::Relaxed);
            PEAK.store(heap0, Ordering::Relaxed);
            let mut sim = setup(n);
            let heap_setup = LIVE.load(Ordering::Relaxed);
            let peak_setup = PEAK.swap(heap_setup, Ordering::Relaxed);
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
            let peak_steps = PEAK.load(Ordering::Relaxed);
            // Between steps the simulation also keeps the RK2 midpoint's storage.
            let heap_steps = LIVE.load(Ordering::Relaxed);
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
                println!(
                    "live heap per particle: {:.0} bytes held after the set-up, {:.0} between steps, peak {:.0} during the steps, peak {:.0} during the set-up",
                    (heap_setup - heap0) as f64 / n,
                    (heap_steps - heap0) as f64 / n,
                    (peak_steps - heap0) as f64 / n,
                    (peak_setup - heap0) as f64 / n,
                );
            }
            println!(
                "{threads} thread(s): {:.3e} particle-steps/s, {:.3e} derivative evaluations/s ({:.3e} per core); phases: neighbours {:.0} %, pair set-up {:.0} %, EOS {:.0} %, gradients {:.0} %, pair loop {:.0} %, integration {:.0} %",
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
