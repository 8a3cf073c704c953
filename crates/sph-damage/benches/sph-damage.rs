//! Benchmarks: ns per damage evaluation, and flaw seeding time.

use criterion::{Criterion, criterion_group, criterion_main};
use sph_damage::{
    BenzAsphaug, BenzAsphaugParams, DamageInput, DamageModel, FlawSet, MaxTensileStress,
    WeibullParams, youngs_modulus,
};
use std::hint::black_box;

fn inputs(n: usize, eps_scale: f64) -> Vec<DamageInput> {
    let e = youngs_modulus(26.7e9, 22.7e9);
    // A deterministic spread of strains around the activation range, and damages.
    (0..n)
        .map(|i| {
            let f = ((i as f64 * 0.618_033_988_749_895) % 1.0) * 2.0;
            DamageInput {
                max_principal_stress: f * eps_scale * e,
                youngs_modulus: e,
                longitudinal_wave_speed: 4593.3,
                particle_size: 1.0e-3,
                damage: ((i as f64 * 0.414_213_562_373_095) % 1.0) * 0.5,
                principal_strain: None,
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let n = 100_000;
    let volume = std::f64::consts::PI * 0.06165_f64.powi(2) * 0.1233;
    let weibull = WeibullParams::BASALT_STUDY;
    let model = BenzAsphaug::seed(BenzAsphaugParams::new(weibull, 7), n, volume).unwrap();
    let eps_max = model
        .flaws()
        .body_threshold(model.flaws().total_flaws() as u64)
        .unwrap();
    let ins = inputs(n, eps_max);

    c.bench_function("benz_asphaug_evaluate_1e5_particles", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for (i, inp) in ins.iter().enumerate() {
                acc += model.evaluate(i, black_box(inp)).rate;
            }
            black_box(acc)
        })
    });

    let tensile = MaxTensileStress::new(9.62e6).unwrap();
    let ins_t = inputs(n, 9.62e6 / youngs_modulus(26.7e9, 22.7e9));
    c.bench_function("max_tensile_evaluate_1e5_particles", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for (i, inp) in ins_t.iter().enumerate() {
                acc += tensile.evaluate(i, black_box(inp)).rate;
            }
            black_box(acc)
        })
    });

    let mut g = c.benchmark_group("seeding");
    g.sample_size(10);
    g.bench_function("seed_benz_asphaug_1e5_particles", |b| {
        b.iter(|| FlawSet::seed_benz_asphaug(weibull, black_box(n), volume, 7).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
