//! Benz–Asphaug flaw seeding (docs/verification.md, "Damage: tensile bar with Benz–Asphaug
//! flaws"): thresholds, statistics, reproducibility, serialisation.

use sph_damage::{DamageError, FlawSet, WeibullParams, min_activation_strain};

/// The study's target cylinder, Ø123.3 × 123.3 mm.
fn cylinder_volume() -> f64 {
    std::f64::consts::PI * 0.06165_f64.powi(2) * 0.1233
}

/// All thresholds of a set, sorted ascending (the body's flaw sequence).
fn body_sequence(f: &FlawSet) -> Vec<f64> {
    let mut all: Vec<f64> = (0..f.n_particles())
        .flat_map(|i| f.thresholds(i).unwrap().to_vec())
        .collect();
    all.sort_by(f64::total_cmp);
    all
}

#[test]
fn weakest_flaw_is_kv_to_minus_one_over_m_within_4_ulp() {
    for (params, volume, n) in [
        (WeibullParams::BASALT_STUDY, cylinder_volume(), 2000),
        (WeibullParams::BASALT_BA99, 1.0e-6, 500),
        (WeibullParams::ICE_BA99, 4.18879e9, 100),
        (WeibullParams::BASALT_NAKAMURA07, 1.131e-4, 50),
    ] {
        let f = FlawSet::seed_benz_asphaug(params, n, volume, 3).unwrap();
        let weakest = (0..n)
            .map(|i| f.min_threshold(i).unwrap())
            .fold(f64::INFINITY, f64::min);
        let exact = min_activation_strain(params.k(), params.m(), volume);
        let ulps = (weakest - exact).abs() / (exact * f64::EPSILON);
        println!(
            "k = {:e}, m = {}, V = {volume:e}: eps_1 = {weakest:e}, (kV)^(-1/m) = {exact:e}, {ulps:.2} ulp",
            params.k(),
            params.m()
        );
        assert!(ulps <= 4.0, "{ulps} ulp");
        assert_eq!(f.body_threshold(1), Some(weakest));
    }
}

#[test]
fn stored_flaws_are_exactly_the_sequence_eps_j_and_log_slope_is_one_over_m() {
    let params = WeibullParams::BASALT_STUDY;
    let f = FlawSet::seed_benz_asphaug(params, 10_000, cylinder_volume(), 11).unwrap();
    let seq = body_sequence(&f);
    assert_eq!(seq.len(), f.total_flaws());
    for (j0, &eps) in seq.iter().enumerate() {
        assert_eq!(
            Some(eps),
            f.body_threshold(j0 as u64 + 1),
            "flaw j = {}",
            j0 + 1
        );
    }
    // Least-squares slope of ln ε_j against ln j, with centred sums.
    let n = seq.len() as f64;
    let xs: Vec<f64> = (1..=seq.len()).map(|j| (j as f64).ln()).collect();
    let ys: Vec<f64> = seq.iter().map(|e| e.ln()).collect();
    let mx = xs.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    let slope = sxy / sxx;
    println!("fitted slope {slope:.15}, 1/m = {}", 1.0 / params.m());
    assert!((slope * params.m() - 1.0).abs() < 1e-12, "slope {slope}");
}

#[test]
fn every_particle_has_a_flaw_and_thresholds_ascend() {
    let f = FlawSet::seed_benz_asphaug(WeibullParams::BASALT_BA99, 5000, 1.0e-3, 5).unwrap();
    assert_eq!(f.n_particles(), 5000);
    for i in 0..5000 {
        let t = f.thresholds(i).unwrap();
        assert!(!t.is_empty());
        assert!(t.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(f.n_flaws(i), Some(t.len()));
        assert_eq!(f.min_threshold(i), Some(t[0]));
    }
    assert_eq!(f.thresholds(5000), None);
    assert_eq!(f.n_flaws(5000), None);
    assert_eq!(f.activated(5000, 1.0), None);
}

#[test]
fn activated_counts_thresholds_at_or_below_the_strain() {
    let f = FlawSet::seed_benz_asphaug(WeibullParams::BASALT_BA94, 100, 1.0e-4, 9).unwrap();
    for i in 0..100 {
        let t = f.thresholds(i).unwrap();
        assert_eq!(f.activated(i, 0.0), Some(0));
        assert_eq!(f.activated(i, -1.0), Some(0));
        assert_eq!(f.activated(i, f64::NAN), Some(0));
        assert_eq!(f.activated(i, f64::INFINITY), Some(t.len()));
        for (k, &eps) in t.iter().enumerate() {
            // Inclusive at the threshold: ε ≥ ε_j activates flaw j.
            assert_eq!(f.activated(i, eps), Some(k + 1));
            assert_eq!(f.activated(i, eps * (1.0 - 1e-12)), Some(k));
        }
    }
}

/// H_N and Σ 1/i² for the coupon-collector mean and variance.
fn harmonic(n: usize) -> (f64, f64) {
    (1..=n).rev().fold((0.0, 0.0), |(h, h2), i| {
        let x = 1.0 / i as f64;
        (h + x, h2 + x * x)
    })
}

#[test]
fn mean_flaws_per_particle_is_the_coupon_collector_number() {
    // E[T/N] = H_N ≈ ln N + 0.5772; SD(T/N) = sqrt(Σ1/i² − H_N/N) ≈ π/√6 for one body,
    // so several seeds are averaged to make the check sharp.
    for (n, seeds) in [(1_000usize, 100u64), (10_000, 30), (100_000, 10)] {
        let (h, h2) = harmonic(n);
        let sd_one = (h2 - h / n as f64).sqrt();
        let se = sd_one / (seeds as f64).sqrt();
        let mean = (0..seeds)
            .map(|s| {
                FlawSet::seed_benz_asphaug(WeibullParams::BASALT_STUDY, n, 1.0, 1000 + s)
                    .unwrap()
                    .mean_flaws_per_particle()
            })
            .sum::<f64>()
            / seeds as f64;
        println!(
            "N = {n:>6}: measured mean flaws/particle {mean:.4} over {seeds} seeds; \
             expected H_N = {h:.4} (ln N + 0.5772 = {:.4}); SE {se:.3}; deviation {:+.2} SE",
            (n as f64).ln() + 0.5772,
            (mean - h) / se
        );
        assert!((mean - h).abs() < 4.0 * se, "N = {n}: {mean} vs {h}");
    }
}

#[test]
fn per_particle_counts_are_close_to_poisson() {
    // Flaws go to particles uniformly, so counts are ≈ Poisson: variance ≈ mean. The
    // sample variance's relative SE is sqrt((1/λ + 2)/N) ≈ 0.005 at N = 1e5.
    let n = 100_000;
    let f = FlawSet::seed_benz_asphaug(WeibullParams::BASALT_STUDY, n, 1.0, 77).unwrap();
    let counts: Vec<f64> = (0..n).map(|i| f.n_flaws(i).unwrap() as f64).collect();
    let mean = counts.iter().sum::<f64>() / n as f64;
    let var = counts.iter().map(|c| (c - mean).powi(2)).sum::<f64>() / (n as f64 - 1.0);
    let max = counts.iter().cloned().fold(0.0, f64::max);
    let ones = counts.iter().filter(|&&c| c == 1.0).count();
    println!(
        "N = 1e5: mean {mean:.3}, variance {var:.3} (ratio {:.4}), max {max}, particles with one flaw {ones}",
        var / mean
    );
    let rel_se = ((1.0 / mean + 2.0) / n as f64).sqrt();
    assert!((var / mean - 1.0).abs() < 5.0 * rel_se, "{}", var / mean);
}

#[test]
fn same_seed_same_flaws_different_seed_different_flaws() {
    let p = WeibullParams::BASALT_STUDY;
    let v = cylinder_volume();
    let a = FlawSet::seed_benz_asphaug(p, 3000, v, 123).unwrap();
    let b = FlawSet::seed_benz_asphaug(p, 3000, v, 123).unwrap();
    let c = FlawSet::seed_benz_asphaug(p, 3000, v, 124).unwrap();
    assert_eq!(a, b);
    assert_ne!(a, c);
    // Different seeds assign the flaws differently, but the body's sequence is the same
    // up to the shorter total.
    let differing = (0..3000)
        .filter(|&i| a.thresholds(i) != c.thresholds(i))
        .count();
    assert!(differing > 2900, "{differing}");
}

#[test]
fn seeding_does_not_depend_on_the_thread_count() {
    // Seeding is sequential (one random stream, flaws in order j = 1, 2, …). This pins
    // that: a seeding run inside 1- and 2-thread pools, and from inside a parallel loop,
    // gives the same set.
    let p = WeibullParams::BASALT_BA99;
    let seed_in = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| FlawSet::seed_benz_asphaug(p, 20_000, 1.0e-3, 99).unwrap())
    };
    let one = seed_in(1);
    let two = seed_in(2);
    assert_eq!(one, two);
    use rayon::prelude::*;
    let many: Vec<FlawSet> = (0..4)
        .into_par_iter()
        .map(|_| FlawSet::seed_benz_asphaug(p, 20_000, 1.0e-3, 99).unwrap())
        .collect();
    assert!(many.iter().all(|f| *f == one));
}

#[test]
fn particle_volumes_give_the_same_set_as_their_sum() {
    let p = WeibullParams::BASALT_STUDY;
    let volumes: Vec<f64> = (0..1000).map(|i| 1.0e-9 * (1.0 + (i % 7) as f64)).collect();
    let total: f64 = volumes.iter().sum();
    let a = FlawSet::seed_benz_asphaug_volumes(p, &volumes, 8).unwrap();
    let b = FlawSet::seed_benz_asphaug(p, 1000, total, 8).unwrap();
    assert_eq!(a, b);
    assert_eq!(a.total_volume(), total);
}

#[test]
fn bad_seeding_inputs_are_typed_errors() {
    let p = WeibullParams::BASALT_STUDY;
    assert_eq!(
        FlawSet::seed_benz_asphaug(p, 0, 1.0, 0),
        Err(DamageError::NoParticles)
    );
    for v in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        match FlawSet::seed_benz_asphaug(p, 10, v, 0) {
            Err(DamageError::Parameter { field, .. }) => assert_eq!(field, "total_volume"),
            other => panic!("{other:?}"),
        }
    }
    // kV overflows f64.
    let huge = WeibullParams::new(1e300, 9.0).unwrap();
    match FlawSet::seed_benz_asphaug(huge, 10, 1e10, 0) {
        Err(DamageError::Parameter { field, .. }) => assert_eq!(field, "k*V"),
        other => panic!("{other:?}"),
    }
    match FlawSet::seed_benz_asphaug_volumes(p, &[1e-9, f64::NAN, 1e-9], 0) {
        Err(DamageError::ParticleValue { index, field, .. }) => {
            assert_eq!((index, field), (1, "volume"))
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(
        FlawSet::seed_benz_asphaug_volumes(p, &[], 0),
        Err(DamageError::NoParticles)
    );
}

#[test]
fn flaw_set_round_trips_through_serde_and_rejects_corruption() {
    let f = FlawSet::seed_benz_asphaug(WeibullParams::BASALT_STUDY, 50, 1e-6, 4).unwrap();
    let json = serde_json::to_string(&f).unwrap();
    let back: FlawSet = serde_json::from_str(&json).unwrap();
    assert_eq!(back, f);

    let set = |offsets: serde_json::Value, ranks: serde_json::Value| {
        serde_json::json!({
            "params": {"k": 4e35, "m": 9.0},
            "total_volume": 1e-6,
            "seed": 0,
            "offsets": offsets,
            "ranks": ranks,
        })
    };
    let ok = set(serde_json::json!([0, 2, 3]), serde_json::json!([1, 3, 2]));
    let small: FlawSet = serde_json::from_value(ok).unwrap();
    assert_eq!(small.ranks(0), Some(&[1, 3][..]));
    assert_eq!(
        small.thresholds(0),
        Some(vec![
            small.body_threshold(1).unwrap(),
            small.body_threshold(3).unwrap()
        ])
    );
    for (offsets, ranks) in [
        // Unsorted within particle 0.
        (serde_json::json!([0, 2, 3]), serde_json::json!([3, 1, 2])),
        // A repeated rank within particle 0.
        (serde_json::json!([0, 2, 3]), serde_json::json!([1, 1, 2])),
        // Particle 1 without flaws.
        (serde_json::json!([0, 3, 3]), serde_json::json!([1, 2, 3])),
        // Last offset ≠ number of flaws.
        (serde_json::json!([0, 1, 2]), serde_json::json!([1, 2, 3])),
        // Not starting at zero.
        (serde_json::json!([1, 2, 3]), serde_json::json!([1, 2, 3])),
        // Rank 0 (ranks count from 1).
        (serde_json::json!([0, 1, 2]), serde_json::json!([0, 2])),
        // No particles.
        (serde_json::json!([0]), serde_json::json!([])),
    ] {
        let r = serde_json::from_value::<FlawSet>(set(offsets.clone(), ranks));
        assert!(
            matches!(r, Err(ref e) if e.to_string().contains("flaw set is inconsistent")),
            "{offsets}: {r:?}"
        );
    }
    // Invalid Weibull parameters are rejected on the way in.
    let mut badk: serde_json::Value = serde_json::from_str(&json).unwrap();
    badk["params"]["k"] = serde_json::json!(-1.0);
    assert!(serde_json::from_value::<FlawSet>(badk).is_err());
}

#[test]
fn memory_is_reported() {
    let f = FlawSet::seed_benz_asphaug(WeibullParams::BASALT_STUDY, 10_000, 1.0, 1).unwrap();
    let floor = 4 * (f.total_flaws() + f.n_particles() + 1);
    println!(
        "N = 1e4: {} flaws, {} bytes ({:.1} bytes/particle)",
        f.total_flaws(),
        f.memory_bytes(),
        f.memory_bytes() as f64 / 1e4
    );
    assert!(f.memory_bytes() >= floor && f.memory_bytes() < floor + 1024);
}

/// Flaws dealt over more particles than keep them (`FlawSet::seed_dealt`; an RZ ring
/// stands for ≈ 2πr/Δ particles of a 3-D run): dealt over the kept count it is the plain
/// seeding bit for bit; dealt over N, each kept particle has a particle of N's flaws
/// (about H_N of them, the weakest of rank ≈ N, i.e. ε ≈ (kV/N)^(−1/m)).
#[test]
fn flaws_dealt_over_more_particles_are_those_of_one_of_them() {
    let w = WeibullParams::BASALT_STUDY;
    let v = cylinder_volume();
    // Dealt over the kept particles it is the seeding before dealing existed: this
    // set's fingerprint as commit 975edce seeded it (3 130 flaws, rank sum 4 900 015).
    let f = FlawSet::seed_dealt(w, 500, 500, v, 7).unwrap();
    assert_eq!(f, FlawSet::seed_benz_asphaug(w, 500, v, 7).unwrap());
    let sum: u64 = (0..500)
        .flat_map(|i| f.ranks(i).unwrap().to_vec())
        .map(u64::from)
        .sum();
    assert_eq!((f.total_flaws(), sum), (3130, 4_900_015));
    assert_eq!(
        f.ranks(0).unwrap(),
        [65, 503, 868, 1195, 1276, 2053, 2067, 2527]
    );
    assert_eq!(f.ranks(499).unwrap(), [57, 310, 1544, 1785, 2560, 2856]);
    let volumes = vec![v / 500.0; 500];
    assert_eq!(
        FlawSet::seed_volumes_dealt(w, &volumes, 500, 7).unwrap(),
        FlawSet::seed_benz_asphaug_volumes(w, &volumes, 7).unwrap()
    );
    assert!(matches!(
        FlawSet::seed_dealt(w, 500, 499, v, 7).unwrap_err(),
        DamageError::Parameter {
            field: "dealt_over",
            ..
        }
    ));

    // The flaw count: the body's total T/N has SD ≈ π/√6 = 1.28 per seed (coupon
    // collector), so 50 seeds of 200 kept out of 20 000: standard error ≈ 0.19.
    let (h, _) = harmonic(20_000);
    let mean_count = (0..50)
        .map(|s| {
            FlawSet::seed_dealt(w, 200, 20_000, v, 100 + s)
                .unwrap()
                .mean_flaws_per_particle()
        })
        .sum::<f64>()
        / 50.0;
    println!("dealt over 20000: {mean_count:.3} flaws per kept particle (H_N {h:.3})");
    assert!((mean_count - h).abs() < 0.75, "{mean_count} vs H_N = {h}");

    let (kept, dealt) = (2_000usize, 200_000usize);
    let f = FlawSet::seed_dealt(w, kept, dealt, v, 11).unwrap();
    assert_eq!(f.n_particles(), kept);
    assert_eq!(f.dealt_over(), dealt as u64);
    // Checkpoints keep the count; a set stored without it is dealt over its particles.
    let json = serde_json::to_value(&f).unwrap();
    assert_eq!(serde_json::from_value::<FlawSet>(json.clone()).unwrap(), f);
    let mut old = json;
    old.as_object_mut().unwrap().remove("dealt_over");
    assert_eq!(
        serde_json::from_value::<FlawSet>(old).unwrap().dealt_over(),
        kept as u64
    );
    // The weakest rank of a particle is geometric with mean ≈ N: standard error of the
    // mean over 2000 particles ≈ 2.2 %.
    let mean_weakest = (0..kept)
        .map(|i| f.ranks(i).unwrap()[0] as f64)
        .sum::<f64>()
        / kept as f64;
    println!("dealt over {dealt}: mean weakest rank {mean_weakest:.0}");
    assert!(
        (mean_weakest / dealt as f64 - 1.0).abs() < 0.1,
        "{mean_weakest}"
    );
    // Against dealing over the kept particles alone, the weakest flaws are stronger by
    // ≈ (N/n)^(1/m) = 100^(1/10) = 1.58.
    let alone = FlawSet::seed_dealt(w, kept, kept, v, 11).unwrap();
    let median = |f: &FlawSet| {
        let mut e: Vec<f64> = (0..kept).map(|i| f.min_threshold(i).unwrap()).collect();
        e.sort_by(f64::total_cmp);
        e[kept / 2]
    };
    let ratio = median(&f) / median(&alone);
    println!("median weakest threshold, dealt over {dealt} / over {kept}: {ratio:.3}");
    assert!((ratio / 100f64.powf(0.1) - 1.0).abs() < 0.05, "{ratio}");
}
