//! ns per call of the yield strength of each model (concrete type, enum and
//! `Box<dyn>`), of `evaluate`, of the Jaumann rate and of the radial return.
//! Each iteration evaluates a batch of 1024 varied states; the per-call time is the
//! reported time divided by 1024.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rand::{RngExt, SeedableRng};
use sph_core::glam::{DMat3, DVec3};
use sph_strength::{
    BuiltinStrength, DruckerPrager, DruckerPragerParams, JohnsonCook, Lundborg, NoStrength,
    SteinbergGuinan, StrengthModel, StrengthState, VonMises, jaumann_rate, materials,
    radial_return,
};
use std::hint::black_box;

const BATCH: usize = 1024;

fn states() -> Vec<StrengthState> {
    let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(7);
    (0..BATCH)
        .map(|_| StrengthState {
            pressure: rng.random_range(-1.0e8..5.0e9),
            density: rng.random_range(2500.0..9500.0),
            temperature: rng.random_range(250.0..1500.0),
            plastic_strain: rng.random_range(0.0..2.0),
            plastic_strain_rate: rng.random_range(0.0..1.0e5),
            damage: rng.random::<f64>(),
            melt_fraction: 0.0,
        })
        .collect()
}

fn sym(rng: &mut rand_pcg::Pcg64Mcg, scale: f64) -> DMat3 {
    let mut r = || rng.random_range(-scale..scale);
    let (a, b, c, d, e, f) = (r(), r(), r(), r(), r(), r());
    DMat3::from_cols(
        DVec3::new(a, d, e),
        DVec3::new(d, b, f),
        DVec3::new(e, f, c),
    )
}

fn bench_model<M: StrengthModel>(c: &mut Criterion, label: &str, m: &M, st: &[StrengthState]) {
    let mut g = c.benchmark_group("yield_strength");
    g.throughput(Throughput::Elements(BATCH as u64));
    g.bench_function(label, |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for s in st {
                acc += m.yield_strength(black_box(s));
            }
            black_box(acc)
        })
    });
    g.finish();
}

fn benches(c: &mut Criterion) {
    let st = states();
    let vm = VonMises::new(materials::TAYLOR_BAR_COPPER).unwrap();
    let dp = DruckerPrager::new(DruckerPragerParams {
        cohesion: 90.0e6,
        friction: 2.0,
        limit_strength: 1.5e9,
        damaged_friction: 0.8,
        shear_modulus: 27.0e9,
    })
    .unwrap();
    let lb = Lundborg::new(materials::BASALT_LUNDBORG).unwrap();
    let jc = JohnsonCook::new(materials::ALUMINIUM_2024_JC_MEASURED).unwrap();
    let sg = SteinbergGuinan::new(materials::COPPER_SG).unwrap();

    bench_model(c, "none", &NoStrength, &st);
    bench_model(c, "von-mises", &vm, &st);
    bench_model(c, "drucker-prager", &dp, &st);
    bench_model(c, "lundborg", &lb, &st);
    bench_model(c, "johnson-cook", &jc, &st);
    bench_model(c, "steinberg-guinan", &sg, &st);
    bench_model(c, "lundborg-enum", &BuiltinStrength::from(lb), &st);
    let boxed: Box<dyn StrengthModel> = Box::new(lb);
    bench_model(c, "lundborg-box-dyn", &boxed, &st);

    {
        let mut g = c.benchmark_group("evaluate");
        g.throughput(Throughput::Elements(BATCH as u64));
        g.bench_function("steinberg-guinan", |b| {
            b.iter(|| {
                let mut acc = 0.0;
                for s in &st {
                    let e = sg.evaluate(black_box(s));
                    acc += e.shear_modulus + e.yield_strength;
                }
                black_box(acc)
            })
        });
        g.finish();
    }

    let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(11);
    let stresses: Vec<DMat3> = (0..BATCH)
        .map(|_| {
            let s = sym(&mut rng, 5.0e8);
            sph_strength::deviator(&s)
        })
        .collect();
    let grads: Vec<DMat3> = (0..BATCH)
        .map(|_| {
            let mut r = || rng.random_range(-1.0e4..1.0e4);
            DMat3::from_cols(
                DVec3::new(r(), r(), r()),
                DVec3::new(r(), r(), r()),
                DVec3::new(r(), r(), r()),
            )
        })
        .collect();
    let mut g = c.benchmark_group("tensor");
    g.throughput(Throughput::Elements(BATCH as u64));
    g.bench_function("radial_return", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for s in &stresses {
                let r = radial_return(black_box(*s), black_box(3.0e8));
                acc += r.stress.x_axis.x + r.scale;
            }
            black_box(acc)
        })
    });
    g.bench_function("jaumann_rate", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for (s, l) in stresses.iter().zip(&grads) {
                acc += jaumann_rate(black_box(s), black_box(l), 26.0e9).x_axis.y;
            }
            black_box(acc)
        })
    });
    g.finish();
}

criterion_group!(group, benches);
criterion_main!(group);
