//! Damage rates and bounds of the models: point values, invariants (proptest), and the
//! solver-side bounding.

use proptest::prelude::*;
use sph_core::glam::{DMat2, DMat3};
use sph_damage::{
    ActivationStrain, BenzAsphaug, BenzAsphaugParams, BoundAction, BuiltinDamage, DamageBounds,
    DamageError, DamageEval, DamageInput, DamageModel, DamageVariable, FlawSet, FlawTail,
    GrowthLaw, MaxTensileStress, NoDamage, TensileFailure, WeibullParams, apply_bounds,
    max_principal_stress, max_principal_stress_bound, youngs_modulus,
};

const E: f64 = 53.062_354_085_603_11e9; // 9·26.7·22.7/102.8 GPa
const CL: f64 = 4593.3;
const RS: f64 = 1.0e-3;
/// c_g / R_s = 0.4 · 4593.3 / 1e-3 = 1 837 320 s⁻¹.
const GROWTH: f64 = 1_837_320.0;

/// A hand-made flaw set: particle 0 has flaws at 1e-4, 2e-4, 3e-4; particle 1 one at 5e-5.
/// With k = 4e35 m⁻³, m = 9 and V = 1280 m³, kV = 2⁹·10³⁶, so ε_1 = 5e-5 and the ranks
/// 2⁹, 4⁹, 6⁹ are 2, 4 and 6 ε_1.
fn small_flaws(seed: u64) -> FlawSet {
    let f: FlawSet = serde_json::from_value(serde_json::json!({
        "params": {"k": 4e35, "m": 9.0},
        "total_volume": 1280.0,
        "seed": seed,
        "offsets": [0, 3, 4],
        "ranks": [512, 262_144, 10_077_696, 1],
    }))
    .unwrap();
    for (got, want) in f
        .thresholds(0)
        .unwrap()
        .iter()
        .chain(&f.thresholds(1).unwrap())
        .zip([1e-4, 2e-4, 3e-4, 5e-5])
    {
        assert!((got / want - 1.0).abs() < 1e-14, "{got} vs {want}");
    }
    f
}

fn small_model(growth: GrowthLaw) -> BenzAsphaug {
    let params = BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 0).with_growth(growth);
    BenzAsphaug::from_flaws(params, small_flaws(0)).unwrap()
}

fn input(strain: f64, damage: f64) -> DamageInput {
    DamageInput {
        max_principal_stress: strain * (1.0 - damage) * E,
        youngs_modulus: E,
        longitudinal_wave_speed: CL,
        particle_size: RS,
        damage,
        principal_strain: None,
    }
}

#[test]
fn hand_computed_rates_of_the_three_growth_laws() {
    assert!((youngs_modulus(26.7e9, 22.7e9) / E - 1.0).abs() < 1e-15);
    // Particle 0 at ε = 2.5e-4: two of three flaws active.
    let inp = input(2.5e-4, 0.0);
    for (law, rate) in [
        (GrowthLaw::PerActivatedFlaw, 2.0 * GROWTH),
        (GrowthLaw::ActivatedFraction, 2.0 / 3.0 * GROWTH),
        (GrowthLaw::SingleCrack, GROWTH),
    ] {
        let m = small_model(law);
        let ev = m.evaluate(0, &inp);
        assert!((ev.rate / rate - 1.0).abs() < 1e-14, "{law:?}: {}", ev.rate);
        assert_eq!(ev.active_flaws, 2);
        assert_eq!(
            ev.bounds,
            DamageBounds {
                min: 0.0,
                max: 2.0 / 3.0
            }
        );
        assert_eq!(m.rate(0, &inp), ev.rate);
        assert_eq!(m.max_damage(0, &inp), 2.0 / 3.0);
        // dD/dt at D = 0 is zero for the cube root: the reason the solver integrates s.
        assert_eq!(m.damage_rate(0, &inp), 0.0);
    }
    // Particle 1 (one flaw at 5e-5) at ε = 6e-5, D = 0.125 (s = 0.5): dD/dt = 3 s² ds/dt.
    let m = small_model(GrowthLaw::PerActivatedFlaw);
    let inp = input(6e-5, 0.125);
    let ev = m.evaluate(1, &inp);
    assert!((ev.rate / GROWTH - 1.0).abs() < 1e-14);
    assert_eq!(ev.bounds.max, 1.0);
    assert!((m.damage_rate(1, &inp) / (3.0 * 0.25 * GROWTH) - 1.0).abs() < 1e-14);
}

/// The continued tail (sph_damage::flaw_tail) past the strongest seeded flaw, ε_top =
/// 3e-4 in `small_flaws`: below it nothing changes; above it a particle's count goes on
/// as k (V/N) (ε^m − ε_top^m) and the cap is 1.
#[test]
fn the_continued_tail_adds_the_population_past_the_strongest_seeded_flaw() {
    let model = |tail| {
        let params = BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 0)
            .with_growth(GrowthLaw::CrackVolume)
            .with_tail(tail);
        BenzAsphaug::from_flaws(params, small_flaws(0)).unwrap()
    };
    let (seeded, tail) = (model(FlawTail::Seeded), model(FlawTail::Continuum));
    assert_eq!(tail.params().tail(), FlawTail::Continuum);
    assert!((tail.flaws().strongest_threshold() / 3e-4 - 1.0).abs() < 1e-14);
    // Below ε_top: identical evaluations.
    for (particle, strain) in [(0, 2.5e-4), (1, 6e-5), (0, 2.9e-4)] {
        let inp = input(strain, 0.0);
        assert_eq!(
            tail.evaluate(particle, &inp),
            seeded.evaluate(particle, &inp)
        );
    }
    // At 2 ε_top, particle 1 (one seeded flaw): kV/N = 2⁹·10³⁶/2 and ε_top^9 = 6⁹/kV, so
    // the tail adds (6⁹/2)(2⁹ − 1) flaws; crack volumes grow at n^(1/3) c_g/R_s.
    let inp = input(6e-4, 0.0);
    let count = 1.0 + 6f64.powi(9) / 2.0 * 511.0;
    let ev = tail.evaluate(1, &inp);
    assert!(
        (ev.rate / (count.cbrt() * GROWTH) - 1.0).abs() < 1e-12,
        "{}",
        ev.rate
    );
    assert_eq!(ev.bounds.max, 1.0);
    assert!(
        (f64::from(ev.active_flaws) - count).abs() <= 1.0,
        "{}",
        ev.active_flaws
    );
    let ev = seeded.evaluate(1, &inp);
    assert!((ev.rate / GROWTH - 1.0).abs() < 1e-14);
    assert_eq!(ev.active_flaws, 1);

    // Flaws dealt over more particles than keep them (an RZ ring standing for 3-D
    // particles): the tail is the mean share of one of those, k V / N_dealt.
    let (kept, dealt, volume) = (50, 5_000, 1e-6);
    let params = BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 3)
        .with_growth(GrowthLaw::CrackVolume)
        .with_tail(FlawTail::Continuum);
    let m = BenzAsphaug::seed_with_volumes_dealt(params, &vec![volume / kept as f64; kept], dealt)
        .unwrap();
    let top = m.flaws().strongest_threshold();
    let n_tot = m.flaws().n_flaws(0).unwrap() as f64;
    let kv = WeibullParams::BASALT_BA99.k() * volume;
    let strain = 1.5 * top;
    let expected = n_tot + kv / dealt as f64 * (strain.powi(9) - top.powi(9));
    let ev = m.evaluate(0, &input(strain, 0.0));
    assert!(
        (ev.rate / (expected.cbrt() * GROWTH) - 1.0).abs() < 1e-9,
        "{} vs {}",
        ev.rate,
        expected.cbrt() * GROWTH
    );
}

#[test]
fn zero_below_the_first_threshold_and_in_compression() {
    let params = BenzAsphaugParams::new(WeibullParams::BASALT_STUDY, 5);
    let m = BenzAsphaug::seed(params, 2000, 1.47e-3).unwrap();
    for i in 0..2000 {
        let eps1 = m.flaws().min_threshold(i).unwrap();
        for d in [0.0, 0.3] {
            let below = m.evaluate(i, &input(eps1 * (1.0 - 1e-9), d));
            assert_eq!(below.rate, 0.0);
            assert_eq!(below.active_flaws, 0);
            assert_eq!(below.bounds.max, d, "no flaw active: no room to grow");
            let above = m.evaluate(i, &input(eps1 * (1.0 + 1e-9), d));
            assert!(above.rate > 0.0);
            assert_eq!(above.active_flaws, 1);
        }
        let compressed = DamageInput {
            max_principal_stress: -1e9,
            ..input(0.0, 0.0)
        };
        assert_eq!(m.evaluate(i, &compressed).rate, 0.0);
    }
}

#[test]
fn local_strain_divides_out_the_damage() {
    // Half damaged: σ_1 = 0.6 ε_1 E is an effective strain of 1.2 ε_1.
    let m = small_model(GrowthLaw::PerActivatedFlaw);
    let inp = DamageInput {
        max_principal_stress: 0.6 * 1e-4 * E,
        ..input(0.0, 0.5)
    };
    assert!((inp.local_strain() / 1.2e-4 - 1.0).abs() < 1e-15);
    assert_eq!(m.evaluate(0, &inp).active_flaws, 1);
}

/// A principal strain given by the solver (pseudo-plastic activation) replaces the
/// stress's: a compressive σ_1 does not matter, the strain is divided by (1 − D), and a
/// non-finite one is reported by `validate`.
#[test]
fn a_given_principal_strain_replaces_the_stress_strain() {
    let m = small_model(GrowthLaw::PerActivatedFlaw);
    let inp = DamageInput {
        max_principal_stress: -1e9,
        principal_strain: Some(0.6e-4),
        ..input(0.0, 0.5)
    };
    assert!((inp.local_strain() / 1.2e-4 - 1.0).abs() < 1e-15);
    assert_eq!(m.evaluate(0, &inp).active_flaws, 1);
    let below = DamageInput {
        principal_strain: Some(-1e-3),
        max_principal_stress: 1e9,
        ..input(0.0, 0.0)
    };
    assert_eq!(m.evaluate(0, &below).rate, 0.0);
    let nan = DamageInput {
        principal_strain: Some(f64::NAN),
        ..input(0.0, 0.0)
    };
    match nan.validate(4) {
        Err(DamageError::ParticleValue { field, index, .. }) => {
            assert_eq!((field, index), ("principal_strain", 4))
        }
        other => panic!("{other:?}"),
    }
    // The model reports the activation it was built with.
    assert_eq!(m.activation_strain(), ActivationStrain::Stress);
    let params = BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 0)
        .with_activation(ActivationStrain::PseudoPlastic);
    let pp = BenzAsphaug::from_flaws(params, small_flaws(0)).unwrap();
    assert_eq!(pp.activation_strain(), ActivationStrain::PseudoPlastic);
    // The enum of built-in models passes it on (the solver sees models through it).
    let builtin = BuiltinDamage::BenzAsphaug(pp);
    assert_eq!(builtin.activation_strain(), ActivationStrain::PseudoPlastic);
}

#[test]
fn fully_damaged_nan_and_out_of_range_inputs() {
    let m = small_model(GrowthLaw::PerActivatedFlaw);
    let dead = m.evaluate(0, &input(1.0, 1.0));
    assert_eq!(dead.rate, 0.0);
    assert_eq!(dead.bounds.max, 1.0);
    assert_eq!(dead.active_flaws, 3);
    let nan = DamageInput {
        max_principal_stress: f64::NAN,
        ..input(0.0, 0.0)
    };
    assert!(m.evaluate(0, &nan).rate.is_nan());
    assert!(m.evaluate(2, &input(1e-3, 0.0)).rate.is_nan());
    assert_eq!(
        m.check_particles(3),
        Err(DamageError::ParticleCount {
            what: "benz-asphaug flaws",
            expected: 2,
            got: 3
        })
    );
    assert_eq!(m.check_particles(2), Ok(()));
    assert!(nan.validate(4).is_err());
    assert!(input(1e-4, 0.2).validate(0).is_ok());
    match (DamageInput {
        damage: 1.5,
        ..input(0.0, 0.0)
    })
    .validate(9)
    {
        Err(DamageError::ParticleValue { index, field, .. }) => {
            assert_eq!((index, field), (9, "damage"))
        }
        other => panic!("{other:?}"),
    }
    match (DamageInput {
        particle_size: 0.0,
        ..input(0.0, 0.0)
    })
    .validate(0)
    {
        Err(DamageError::ParticleValue { field, .. }) => assert_eq!(field, "particle_size"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn from_flaws_rejects_a_foreign_flaw_set() {
    let params = BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 1);
    assert!(matches!(
        BenzAsphaug::from_flaws(params, small_flaws(0)),
        Err(DamageError::CorruptFlawSet { .. })
    ));
    let params = BenzAsphaugParams::new(WeibullParams::BASALT_STUDY, 0);
    assert!(BenzAsphaug::from_flaws(params, small_flaws(0)).is_err());
}

#[test]
fn tensile_crack_growth_and_instant_failure() {
    let sb = 9.62e6;
    let grow = MaxTensileStress::new(sb).unwrap();
    assert_eq!(grow.failure(), TensileFailure::CrackGrowth);
    assert_eq!(grow.variable(), DamageVariable::CubeRoot);
    let at = |sigma: f64, d: f64| DamageInput {
        max_principal_stress: sigma,
        ..input(0.0, d)
    };
    assert_eq!(grow.evaluate(0, &at(0.999 * sb, 0.0)).rate, 0.0);
    assert_eq!(grow.evaluate(0, &at(0.999 * sb, 0.0)).bounds.max, 0.0);
    let ev = grow.evaluate(0, &at(sb, 0.0));
    assert!((ev.rate / GROWTH - 1.0).abs() < 1e-14);
    assert_eq!(ev.bounds, DamageBounds::FULL);
    // Damaged: the criterion is on σ_1/(1 − D): 0.6 σ_b at D = 0.5 keeps growing,
    // 0.4 σ_b does not, and D does not heal.
    assert!(grow.evaluate(0, &at(0.6 * sb, 0.5)).rate > 0.0);
    let paused = grow.evaluate(0, &at(0.4 * sb, 0.5));
    assert_eq!((paused.rate, paused.bounds.max), (0.0, 0.5));
    assert_eq!(grow.evaluate(0, &at(1e9, 1.0)).rate, 0.0);
    assert!(grow.evaluate(0, &at(f64::NAN, 0.0)).rate.is_nan());

    let instant = MaxTensileStress::new(2500e6)
        .unwrap()
        .with_failure(TensileFailure::Instant);
    assert_eq!(instant.variable(), DamageVariable::Damage);
    let ev = instant.evaluate(0, &at(2500e6, 0.0));
    assert_eq!(ev.bounds, DamageBounds { min: 1.0, max: 1.0 });
    let b = apply_bounds(instant.variable(), 0.0 + 1e-7 * ev.rate, ev.bounds);
    assert_eq!((b.damage, b.action), (1.0, BoundAction::RaisedToMin));
    let below = instant.evaluate(0, &at(2499e6, 0.0));
    let b = apply_bounds(instant.variable(), 0.0, below.bounds);
    assert_eq!((b.damage, b.action), (0.0, BoundAction::Within));

    for bad in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            MaxTensileStress::new(bad),
            Err(DamageError::Parameter {
                field: "sigma_b",
                ..
            })
        ));
    }
    for bad in [0.0, 1.5, f64::NAN] {
        assert!(matches!(
            grow.with_crack_speed_fraction(bad),
            Err(DamageError::Parameter {
                field: "crack_speed_fraction",
                ..
            })
        ));
    }
}

#[test]
fn apply_bounds_reports_every_change() {
    let v = DamageVariable::CubeRoot;
    let bounds = DamageBounds { min: 0.0, max: 0.5 };
    let inside = apply_bounds(v, 0.7, bounds);
    assert_eq!(inside.action, BoundAction::Within);
    assert_eq!(inside.state, 0.7); // bit for bit
    assert!((inside.damage - 0.343).abs() < 1e-15);
    let capped = apply_bounds(v, 0.9, bounds);
    assert_eq!(capped.action, BoundAction::CappedAtMax);
    assert_eq!(capped.damage, 0.5);
    assert!((capped.state - 0.5f64.cbrt()).abs() < 1e-16);
    let negative = apply_bounds(v, -0.1, bounds);
    assert_eq!(
        (negative.action, negative.damage),
        (BoundAction::RaisedToMin, 0.0)
    );
    assert_eq!(
        apply_bounds(v, f64::NAN, bounds).action,
        BoundAction::NonFinite
    );
    assert_eq!(
        apply_bounds(v, f64::INFINITY, bounds).action,
        BoundAction::NonFinite
    );
}

#[test]
fn damage_variables_round_trip() {
    for v in [
        DamageVariable::Damage,
        DamageVariable::SquareRoot,
        DamageVariable::CubeRoot,
    ] {
        for d in [0.0, 1e-9, 0.125, 0.5, 1.0] {
            let s = v.from_damage(d);
            assert!((v.to_damage(s) - d).abs() <= 2.0 * f64::EPSILON * d);
            assert_eq!(s.powi(v.exponent() as i32), v.to_damage(s));
        }
    }
    // dD/dt = p s^(p−1) ds/dt.
    assert_eq!(DamageVariable::SquareRoot.damage_rate(0.5, 2.0), 2.0);
    assert_eq!(DamageVariable::CubeRoot.damage_rate(0.5, 2.0), 1.5);
    assert_eq!(DamageVariable::CubeRoot.damage_rate(0.0, 2.0), 0.0);
}

#[test]
fn max_principal_stress_from_the_eigen_decomposition() {
    let s3 = DMat3::from_cols_array(&[-1.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 2.0]);
    assert!((max_principal_stress(&s3) - 3.0).abs() < 1e-14);
    // [[1, 2], [2, 1]] has eigenvalues −1 and 3.
    let s2 = DMat2::from_cols_array(&[1.0, 2.0, 2.0, 1.0]);
    assert!((max_principal_stress(&s2) - 3.0).abs() < 1e-14);
    assert_eq!(max_principal_stress(&-4.0f64), -4.0);
    // Pure compression stays negative (the unused eigenvalue slots are not read).
    let c = DMat3::from_diagonal(sph_core::glam::DVec3::new(-3.0, -2.0, -1.0));
    assert!((max_principal_stress(&c) + 1.0).abs() < 1e-14);
    let c2 = DMat2::from_diagonal(sph_core::glam::DVec2::new(-3.0, -2.0));
    assert!((max_principal_stress(&c2) + 2.0).abs() < 1e-14);
}

#[test]
fn no_damage_and_the_builtin_enum() {
    let inp = input(1.0, 0.25);
    let ev = NoDamage.evaluate(3, &inp);
    assert_eq!((ev.rate, ev.bounds.max), (0.0, 0.25));
    let models = [
        BuiltinDamage::None(NoDamage),
        BuiltinDamage::MaxTensileStress(MaxTensileStress::new(9.62e6).unwrap()),
        BuiltinDamage::BenzAsphaug(small_model(GrowthLaw::ActivatedFraction)),
    ];
    let concrete: [&dyn DamageModel; 3] = [
        &NoDamage,
        &MaxTensileStress::new(9.62e6).unwrap(),
        &small_model(GrowthLaw::ActivatedFraction),
    ];
    for (b, c) in models.iter().zip(concrete) {
        assert_eq!(b.name(), c.name());
        assert_eq!(b.variable(), c.variable());
        assert_eq!(
            b.evaluate(0, &input(2.5e-4, 0.0)),
            c.evaluate(0, &input(2.5e-4, 0.0))
        );
        let json = serde_json::to_string(b).unwrap();
        let back: BuiltinDamage = serde_json::from_str(&json).unwrap();
        assert_eq!(&back, b, "{json}");
    }
    assert!(models[2].check_particles(5).is_err());
    // Scene-file form with defaults.
    let ba: BuiltinDamage = serde_json::from_str(
        r#"{"model": "benz-asphaug",
            "params": {"weibull": {"k": 4e35, "m": 9.0}, "seed": 0, "growth": "activated-fraction"},
            "flaws": {"params": {"k": 4e35, "m": 9.0}, "total_volume": 1280.0, "seed": 0,
                      "offsets": [0, 3, 4], "ranks": [512, 262144, 10077696, 1]}}"#,
    )
    .unwrap();
    assert_eq!(ba, models[2]);
    let bad = serde_json::from_str::<BuiltinDamage>(
        r#"{"model": "max-tensile-stress", "threshold": -5.0}"#,
    );
    assert!(bad.is_err());
    let params_bad = serde_json::from_str::<BenzAsphaugParams>(
        r#"{"weibull": {"k": 4e35, "m": 9.0}, "seed": 0, "crack_speed_fraction": 2.0}"#,
    );
    assert!(params_bad.is_err());
}

/// A model seeded once for the property tests.
fn seeded() -> &'static BenzAsphaug {
    use std::sync::OnceLock;
    static M: OnceLock<BenzAsphaug> = OnceLock::new();
    M.get_or_init(|| {
        BenzAsphaug::seed(
            BenzAsphaugParams::new(WeibullParams::BASALT_STUDY, 17),
            500,
            1.47e-3,
        )
        .unwrap()
    })
}

fn law() -> impl Strategy<Value = GrowthLaw> {
    prop_oneof![
        Just(GrowthLaw::PerActivatedFlaw),
        Just(GrowthLaw::ActivatedFraction),
        Just(GrowthLaw::SingleCrack)
    ]
}

proptest! {
    #[test]
    fn rate_nonnegative_and_cap_is_the_active_fraction(
        i in 0usize..500,
        strain in -1e-3f64..1e-3,
        d in 0.0f64..1.0,
        growth in law(),
    ) {
        let base = seeded();
        let m = BenzAsphaug::from_flaws(base.params().with_growth(growth), base.flaws().clone()).unwrap();
        let ev = m.evaluate(i, &input(strain, d));
        let n_act = m.flaws().activated(i, input(strain, d).local_strain()).unwrap();
        let n_tot = m.flaws().n_flaws(i).unwrap();
        prop_assert!(ev.rate >= 0.0);
        prop_assert_eq!(ev.active_flaws as usize, n_act);
        prop_assert_eq!(ev.bounds.max, (n_act as f64 / n_tot as f64).max(d));
        prop_assert!(ev.bounds.max >= d && ev.bounds.max <= 1.0);
        prop_assert_eq!(ev.bounds.min, 0.0);
        prop_assert_eq!(ev.rate == 0.0, n_act == 0);
    }

    #[test]
    fn integrated_damage_never_exceeds_the_active_fraction_seen(
        i in 0usize..500,
        peak in 1e-4f64..6e-4,
        steps in 20usize..200,
        growth in law(),
    ) {
        // Load linearly to `peak` strain and unload, advancing s = D^(1/3) with RK2
        // (midpoint) and the bounds: D stays ≤ the largest n_act/n_tot seen so far, and
        // never decreases.
        let base = seeded();
        let m = BenzAsphaug::from_flaws(base.params().with_growth(growth), base.flaws().clone()).unwrap();
        let v = m.variable();
        let n_tot = m.flaws().n_flaws(i).unwrap() as f64;
        let dt = 2e-8;
        let mut s = 0.0f64;
        let mut max_fraction = 0.0f64;
        for k in 0..2 * steps {
            let strain = peak * if k < steps { k as f64 } else { (2 * steps - k) as f64 } / steps as f64;
            let d0 = v.to_damage(s);
            let e1 = m.evaluate(i, &input(strain, d0));
            let sh = apply_bounds(v, s + 0.5 * dt * e1.rate, e1.bounds);
            let e2 = m.evaluate(i, &input(strain, sh.damage));
            let b = apply_bounds(v, s + dt * e2.rate, e2.bounds);
            prop_assert_ne!(b.action, BoundAction::NonFinite);
            max_fraction = max_fraction.max(e1.active_flaws as f64 / n_tot);
            prop_assert!(b.damage >= d0);
            prop_assert!(b.damage <= max_fraction.max(e2.active_flaws as f64 / n_tot) + 1e-15);
            s = b.state;
        }
    }
}

/// Two evaluations equal to the bit (a NaN equal to itself).
fn same_bits(a: &DamageEval, b: &DamageEval) -> bool {
    a.rate.to_bits() == b.rate.to_bits()
        && a.bounds.min.to_bits() == b.bounds.min.to_bits()
        && a.bounds.max.to_bits() == b.bounds.max.to_bits()
        && a.active_flaws == b.active_flaws
}

#[test]
fn a_flaw_model_is_quiet_below_its_weakest_flaw_only() {
    // Particle 0's flaws are at 1e-4, 2e-4 and 3e-4 (`small_flaws`).
    let m = small_model(GrowthLaw::SingleCrack);
    assert!(m.evaluate_if_quiet(0, &input(0.99e-4, 0.0)).is_some());
    assert!(m.evaluate_if_quiet(0, &input(1.01e-4, 0.0)).is_none());
    assert!(m.evaluate_if_quiet(0, &input(-1.0, 0.0)).is_some());
    // A NaN stress is never quiet: σ_1 must carry it.
    let mut nan = input(0.0, 0.0);
    nan.max_principal_stress = f64::NAN;
    assert!(m.evaluate_if_quiet(0, &nan).is_none());
    // The maximum tensile stress: quiet below (1 − D) σ_b.
    let mts = MaxTensileStress::new(1e7).unwrap();
    let at = |sigma: f64| DamageInput {
        max_principal_stress: sigma,
        ..input(0.0, 0.5)
    };
    assert!(mts.evaluate_if_quiet(0, &at(0.49e7)).is_some());
    assert!(mts.evaluate_if_quiet(0, &at(0.51e7)).is_none());
    // A model that does not say is never quiet.
    #[derive(Debug)]
    struct Silent;
    impl DamageModel for Silent {
        fn name(&self) -> &str {
            "silent"
        }
        fn variable(&self) -> DamageVariable {
            DamageVariable::Damage
        }
        fn evaluate(&self, _: usize, input: &DamageInput) -> DamageEval {
            NoDamage.evaluate(0, input)
        }
    }
    assert!(Silent.evaluate_if_quiet(0, &at(-1e9)).is_none());
}

proptest! {
    /// Where a model answers that its result is quiet at σ_1, every smaller σ_1 gives that
    /// result to the bit: what lets the solver evaluate at Gershgorin's bound of σ_1 and
    /// skip its eigenvalues (sph-impact solver/damage.rs).
    #[test]
    fn a_quiet_result_holds_for_every_smaller_stress(
        i in 0usize..500,
        strain in -1e-3f64..1e-3,
        d in prop_oneof![Just(0.0), 0.0f64..1.0, Just(1.0)],
        fraction in 0.0f64..1.0,
        below in 0.0f64..1e8,
        growth in law(),
        continued in any::<bool>(),
        pseudo in any::<bool>(),
    ) {
        let base = seeded();
        let tail = if continued { FlawTail::Continuum } else { FlawTail::Seeded };
        let ba = BenzAsphaug::from_flaws(
            base.params().with_growth(growth).with_tail(tail),
            base.flaws().clone(),
        )
        .unwrap();
        let mts = MaxTensileStress::new(9.8e6).unwrap();
        let builtin = BuiltinDamage::BenzAsphaug(ba.clone());
        let mut at = input(strain, d);
        if pseudo {
            at.principal_strain = Some(strain.abs());
        }
        let models: [&dyn DamageModel; 4] = [&ba, &mts, &NoDamage, &builtin];
        for model in models {
            let Some(quiet) = model.evaluate_if_quiet(i, &at) else {
                continue;
            };
            prop_assert!(same_bits(&quiet, &model.evaluate(i, &at)));
            let sigma = at.max_principal_stress;
            for smaller in [sigma * fraction, sigma - below, -1e9, sigma.min(0.0)] {
                if smaller <= sigma {
                    let lower = DamageInput { max_principal_stress: smaller, ..at };
                    prop_assert!(
                        same_bits(&quiet, &model.evaluate(i, &lower)),
                        "{}: quiet at {sigma}, not at {smaller}", model.name()
                    );
                }
            }
        }
    }

    /// Gershgorin's bound is never below the σ_1 the eigen-solver computes, for
    /// symmetric stresses and for ones whose triangles differ by rounding.
    #[test]
    fn the_bound_of_sigma_1_is_not_below_it(
        e in proptest::array::uniform9(-1e9f64..1e9),
        skew in -1e-6f64..1e-6,
    ) {
        let s = DMat3::from_cols_array(&e);
        let sym = (s + s.transpose()) * 0.5;
        for m in [sym, sym + DMat3::from_cols_array(&[0.0, skew * e[1], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])] {
            let bound = max_principal_stress_bound(&m).unwrap();
            prop_assert!(bound >= max_principal_stress(&m), "{bound} < {}", max_principal_stress(&m));
        }
        let mut bad = sym;
        bad.y_axis.z = f64::NAN;
        prop_assert!(max_principal_stress_bound(&bad).is_none());
        let mut inf = sym;
        inf.x_axis.x = f64::INFINITY;
        prop_assert!(max_principal_stress_bound(&inf).is_none());
        let plane = DMat2::from_cols_array(&[e[0], e[1], e[1], e[4]]);
        prop_assert!(max_principal_stress_bound(&plane).unwrap() >= max_principal_stress(&plane));
    }
}
