//! ns per `evaluate` call of each EOS (and each Tillotson region), the thermal model and
//! the Hugoniot solver. Run: `cargo bench -p sph-eos -- --noplot`.

use criterion::{Criterion, criterion_group, criterion_main};
use sph_eos::{
    EquationOfState, IdealGas, LinearElastic, LinearElasticParams, MieGruneisen,
    MieGruneisenParams, Murnaghan, MurnaghanParams, ThermalModel, Tillotson, TillotsonParams,
    TillotsonRegion, hugoniot,
};
use std::hint::black_box;
use std::time::Duration;

fn evaluate(c: &mut Criterion) {
    let t = Tillotson::new(TillotsonParams::basalt_study()).unwrap();
    let rho0 = 2876.0;
    let states = [
        ("compressed", 1.2 * rho0, 1e6),
        ("cold_expanded", 0.9 * rho0, 1e6),
        ("intermediate", 0.8 * rho0, 1.1e7),
        ("hot_expanded", 0.5 * rho0, 3.6e7),
    ];
    let mut g = c.benchmark_group("evaluate");
    for (name, rho, e) in states {
        assert_eq!(
            format!("{:?}", t.region(rho, e))
                .to_lowercase()
                .replace('_', ""),
            name.replace('_', "")
        );
        g.bench_function(format!("tillotson/{name}"), |b| {
            b.iter(|| t.evaluate(black_box(rho), black_box(e)))
        });
    }
    let dynamic: Box<dyn EquationOfState> = Box::new(t);
    g.bench_function("tillotson/intermediate_dyn", |b| {
        b.iter(|| dynamic.evaluate(black_box(0.8 * rho0), black_box(1.1e7)))
    });
    g.bench_function("tillotson/pressure_only_hot", |b| {
        b.iter(|| t.pressure(black_box(0.5 * rho0), black_box(3.6e7)))
    });
    let gas = IdealGas::with_gamma(1.4).unwrap();
    g.bench_function("ideal_gas", |b| {
        b.iter(|| gas.evaluate(black_box(1.0), black_box(2.5)))
    });
    let mg = MieGruneisen::new(MieGruneisenParams::aluminium_6061()).unwrap();
    g.bench_function("mie_gruneisen/compressed", |b| {
        b.iter(|| mg.evaluate(black_box(3000.0), black_box(1e6)))
    });
    g.bench_function("mie_gruneisen/tension", |b| {
        b.iter(|| mg.evaluate(black_box(2600.0), black_box(1e5)))
    });
    let mu = Murnaghan::new(MurnaghanParams {
        rho0: 1000.0,
        K0: 2.2e9,
        n: 7.0,
    })
    .unwrap();
    g.bench_function("murnaghan", |b| {
        b.iter(|| mu.evaluate(black_box(1010.0), black_box(0.0)))
    });
    let le = LinearElastic::new(LinearElasticParams {
        rho0: 2700.0,
        K0: 58.3e9,
    })
    .unwrap();
    g.bench_function("linear_elastic", |b| {
        b.iter(|| le.evaluate(black_box(2710.0), black_box(0.0)))
    });
    g.finish();

    let al = ThermalModel::aluminium();
    c.bench_function("thermal/state", |b| b.iter(|| al.state(black_box(7.7e5))));
    let ta = Tillotson::new(TillotsonParams::aluminium_melosh89()).unwrap();
    c.bench_function("hugoniot/tillotson_al_up_3km_s", |b| {
        b.iter(|| hugoniot(&ta, black_box(2700.0), black_box(3000.0)).unwrap())
    });
    let _ = TillotsonRegion::Compressed;
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    targets = evaluate
}
criterion_main!(benches);
