//! Peak stress under constant strain rate (docs/verification.md, "Damage: tensile bar with
//! Benz–Asphaug flaws"): the continuum Grady–Kipp scaling σ_max ∝ ε̇^(3/(m+3)) and what the
//! explicit-flaw Benz–Asphaug model gives.
//!
//! The loading is a homogeneous bar of N particles under uniaxial stress: every
//! particle sees the same applied strain ε = ε̇ t, carries σ_i = E ε̇ t (1 − D_i), and the
//! bar's stress is the mean of σ_i. The local strain of flaw activation,
//! σ_i/((1 − D_i)E), is then ε̇ t for every particle. The integration is an explicit
//! midpoint (RK2) loop on s = D^(1/3) with the model's bounds, as a solver would do it.

use sph_damage::{
    BenzAsphaug, BenzAsphaugParams, DamageInput, DamageModel, FlawTail, GrowthLaw, WeibullParams,
    apply_bounds, longitudinal_wave_speed, youngs_modulus,
};
use std::f64::consts::PI;

const RATES: [f64; 5] = [1e2, 1e3, 1e4, 1e5, 1e6];

fn basalt() -> (f64, f64) {
    (
        youngs_modulus(26.7e9, 22.7e9),
        longitudinal_wave_speed(26.7e9, 22.7e9, 2700.0),
    )
}

/// Least-squares slope of ln y against ln x.
fn log_slope(x: &[f64], y: &[f64]) -> f64 {
    let lx: Vec<f64> = x.iter().map(|v| v.ln()).collect();
    let ly: Vec<f64> = y.iter().map(|v| v.ln()).collect();
    let n = lx.len() as f64;
    let mx = lx.iter().sum::<f64>() / n;
    let my = ly.iter().sum::<f64>() / n;
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = lx.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

/// The slopes of log σ_max per decade of ε̇ between neighbouring rates, for printing.
fn local_slopes(peaks: &[f64]) -> String {
    let local: Vec<String> = peaks
        .windows(2)
        .map(|p| format!("{:.3}", (p[1] / p[0]).log10()))
        .collect();
    local.join(", ")
}

/// Peak of σ(t) = E ε̇ t (1 − D(t)) for the continuum Grady–Kipp damage
/// D = α ε̇^m t^(m+3), α = 8π c_g³ k / ((m+1)(m+2)(m+3)) (Grady & Kipp 1980; Melosh et
/// al. 1992), found by the same kind of time scan as the particle runs.
fn grady_kipp_peak(w: WeibullParams, e: f64, cg: f64, rate: f64) -> (f64, f64) {
    let m = w.m();
    let alpha = 8.0 * PI * cg.powi(3) * w.k() / ((m + 1.0) * (m + 2.0) * (m + 3.0));
    // Scan in time with 1e5 steps up to twice the analytic peak time scale.
    let t_scale = ((m + 4.0) * alpha * rate.powf(m)).powf(-1.0 / (m + 3.0));
    let steps = 100_000;
    let dt = 2.0 * t_scale / steps as f64;
    let (mut best, mut t_best) = (0.0, 0.0);
    for k in 1..=steps {
        let t = k as f64 * dt;
        let d = (alpha * rate.powf(m) * t.powf(m + 3.0)).min(1.0);
        let s = e * rate * t * (1.0 - d);
        if s > best {
            best = s;
            t_best = t;
        }
    }
    (best, t_best)
}

#[test]
fn grady_kipp_reference_reproduces_the_verification_table_and_exponent() {
    // docs/reference/weibull_flaws.md, "Grady–Kipp dynamic strength", BA99 basalt (k = 4e35,
    // m = 9), c_g = 0.4 c_L.
    let (e, cl) = basalt();
    let w = WeibullParams::BASALT_BA99;
    let table = [
        (1.0, 1.85e-4, 9.07e6),
        (1e2, 5.86e-6, 28.7e6),
        (1e4, 1.85e-7, 90.7e6),
        (1e6, 5.86e-9, 287e6),
    ];
    for (rate, t_star, sigma) in table {
        let (s, t) = grady_kipp_peak(w, e, 0.4 * cl, rate);
        println!(
            "GK ε̇ = {rate:e}: σ_max = {:.3} MPa at t = {t:.3e} s",
            s / 1e6
        );
        assert!((s / sigma - 1.0).abs() < 2e-3, "{s} vs {sigma}");
        assert!((t / t_star - 1.0).abs() < 3e-3, "{t} vs {t_star}");
    }
    let peaks: Vec<f64> = RATES
        .iter()
        .map(|&r| grady_kipp_peak(w, e, 0.4 * cl, r).0)
        .collect();
    let slope = log_slope(&RATES, &peaks);
    println!("GK fitted slope {slope:.5} (3/(m+3) = 0.25)");
    assert!((slope - 0.25).abs() < 1e-4);
}

/// The bar of `n` particles of volume `v_i` each; returns σ_max (Pa) and the strain at
/// the peak.
fn benz_asphaug_peak(model: &BenzAsphaug, rate: f64, e: f64, cl: f64, rs: f64) -> (f64, f64) {
    let n = model.flaws().n_particles();
    let v = model.variable();
    let eps_1 = model.flaws().body_threshold(1).unwrap();
    let mut s = vec![0.0f64; n];
    let mut stage1 = vec![(0.0f64, sph_damage::DamageBounds::FULL); n];
    let mut t = 0.0f64;
    let (mut best, mut eps_best) = (0.0f64, 0.0f64);
    let input = |strain: f64, d: f64| DamageInput {
        max_principal_stress: e * strain * (1.0 - d),
        youngs_modulus: e,
        longitudinal_wave_speed: cl,
        particle_size: rs,
        damage: d,
        principal_strain: None,
    };
    for _ in 0..10_000_000 {
        let strain0 = rate * t;
        // Stage 1 at t.
        let mut max_rate = 0.0f64;
        for i in 0..n {
            let ev = model.evaluate(i, &input(strain0, v.to_damage(s[i])));
            stage1[i] = (ev.rate, ev.bounds);
            max_rate = max_rate.max(ev.rate);
        }
        // Step: resolve the strain (1e-3 of ε_1) and the crack growth (Δs ≤ 0.01).
        let mut dt = 1e-3 * eps_1 / rate;
        if max_rate > 0.0 {
            dt = dt.min(0.01 / max_rate);
        }
        // Stage 2 at the midpoint, then the full step with the midpoint rates.
        let strain_h = rate * (t + 0.5 * dt);
        let mut sigma_sum = 0.0;
        for i in 0..n {
            let (r1, b1) = stage1[i];
            let half = apply_bounds(v, s[i] + 0.5 * dt * r1, b1);
            let e2 = model.evaluate(i, &input(strain_h, half.damage));
            let b = apply_bounds(v, s[i] + dt * e2.rate, e2.bounds);
            s[i] = b.state;
            sigma_sum += e * rate * (t + dt) * (1.0 - b.damage);
        }
        t += dt;
        let sigma = sigma_sum / n as f64;
        if sigma > best {
            best = sigma;
            eps_best = rate * t;
        } else if sigma < 0.5 * best {
            break;
        }
    }
    (best, eps_best)
}

/// Runs the five strain rates for one growth law and returns the peaks and the fitted
/// slope.
fn sweep(law: GrowthLaw, n: usize, v_i: f64, rs: f64) -> (Vec<f64>, Vec<f64>, f64) {
    sweep_rates(&RATES, (law, FlawTail::Seeded), n, v_i, rs)
}

/// As [`sweep`] at the given rates, with the given growth law and flaw tail.
fn sweep_rates(
    rates: &[f64],
    (law, tail): (GrowthLaw, FlawTail),
    n: usize,
    v_i: f64,
    rs: f64,
) -> (Vec<f64>, Vec<f64>, f64) {
    let (e, cl) = basalt();
    let params = BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 2024)
        .with_growth(law)
        .with_tail(tail);
    let model = BenzAsphaug::seed(params, n, n as f64 * v_i).unwrap();
    let mut peaks = Vec::new();
    let mut strains = Vec::new();
    for &r in rates {
        let (s, eps) = benz_asphaug_peak(&model, r, e, cl, rs);
        peaks.push(s);
        strains.push(eps);
    }
    let slope = log_slope(rates, &peaks);
    let total = model.flaws().total_flaws() as u64;
    println!(
        "{law:?}: {total} flaws, strongest ε_max = {:.3e}",
        model.flaws().body_threshold(total).unwrap()
    );
    (peaks, strains, slope)
}

#[test]
fn benz_asphaug_peak_stress_against_strain_rate() {
    // The study's resolution: 1000 particles of (0.5 mm)³, R_s the radius of the sphere
    // of the same volume, BA99 basalt (m = 9), seed 2024.
    //
    // Finding (see the crate README): no growth law gives one power law over 1e2…1e6 s⁻¹.
    // At low rates cracks outgrow the loading and D sits at the cap n_act/n_tot (a
    // rate-independent peak); at high rates the peak strain passes the strongest seeded
    // flaw, ε_max ≈ (N H_N / (kV))^(1/m), and with every flaw active the peak grows ∝ ε̇.
    // The fitted slopes are therefore pinned as regression values, not checked against
    // 3/(m+3); the local slopes are printed.
    let n = 1000;
    let v_i = 0.5e-3f64.powi(3);
    let rs = (3.0 * v_i / (4.0 * PI)).cbrt();
    let (e, _) = basalt();
    let w = WeibullParams::BASALT_BA99;
    let eps_1 = w.min_activation_strain(n as f64 * v_i);
    println!(
        "BA99 basalt, N = {n}, V_i = {v_i:.3e} m³, R_s = {rs:.3e} m; E ε_1 = {:.2} MPa",
        e * eps_1 / 1e6
    );
    for (law, pinned) in [
        (GrowthLaw::PerActivatedFlaw, 0.2223),
        (GrowthLaw::ActivatedFraction, 0.4450),
        (GrowthLaw::SingleCrack, 0.4507),
        (GrowthLaw::CrackVolume, 0.3727),
    ] {
        let (peaks, strains, slope) = sweep(law, n, v_i, rs);
        let row: Vec<String> = peaks
            .iter()
            .zip(&strains)
            .map(|(p, s)| format!("{:.1} MPa (ε {:.2e})", p / 1e6, s))
            .collect();
        println!("{law:?}: σ_max at ε̇ = 1e2…1e6: {}", row.join(", "));
        println!(
            "{law:?}: fitted slope {slope:.4} vs 3/(m+3) = 0.25 ({:+.1} %); local slopes per decade [{}]",
            100.0 * (slope / 0.25 - 1.0),
            local_slopes(&peaks)
        );
        // Rate hardening: every faster loading has a higher peak.
        assert!(peaks.windows(2).all(|p| p[1] > p[0]), "{law:?}: {peaks:?}");
        // Regression pin of this configuration (deterministic: fixed seed, no threads).
        assert!(
            (slope - pinned).abs() < 2e-3,
            "{law:?}: slope {slope}, pinned {pinned}"
        );
    }
}

/// With the Weibull population continued past the strongest seeded flaw
/// (`FlawTail::Continuum`) and crack volumes that add up (`GrowthLaw::CrackVolume`), the
/// peak stress follows the Grady–Kipp ε̇^(3/(m+3)) wherever the strain at the peak is past
/// the seeded flaws; below, the seeded flaws set it as before.
#[test]
fn continued_flaw_tail_gives_the_grady_kipp_exponent() {
    let n = 1000;
    let v_i = 0.5e-3f64.powi(3);
    let rs = (3.0 * v_i / (4.0 * PI)).cbrt();
    let rates = [1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8];
    let (e, cl) = basalt();
    let w = WeibullParams::BASALT_BA99;
    let top = BenzAsphaug::seed(BenzAsphaugParams::new(w, 2024), n, n as f64 * v_i)
        .unwrap()
        .flaws()
        .strongest_threshold();
    for law in [GrowthLaw::CrackVolume, GrowthLaw::PerActivatedFlaw] {
        let (peaks, strains, slope) = sweep_rates(&rates, (law, FlawTail::Continuum), n, v_i, rs);
        let gk: Vec<f64> = rates
            .iter()
            .map(|&r| grady_kipp_peak(w, e, 0.4 * cl, r).0)
            .collect();
        let row: Vec<String> = peaks
            .iter()
            .zip(&strains)
            .zip(&gk)
            .map(|((p, s), g)| format!("{:.1} MPa (ε {:.2e}; GK {:.1})", p / 1e6, s, g / 1e6))
            .collect();
        println!("{law:?} + tail: σ_max at ε̇ = 1e2…1e8: {}", row.join(", "));
        println!(
            "{law:?} + tail: fitted slope 1e2…1e8 {slope:.4}; local slopes per decade [{}]",
            local_slopes(&peaks)
        );
        // Past the seeded flaws (ε at the peak ≥ 1.5 ε_top: from 1e5 s⁻¹ with crack
        // volumes, 1e7 s⁻¹ with crack radii) the continued population is k ε^m per unit
        // volume, as in the continuum law.
        let tail_rates: Vec<usize> = (0..rates.len())
            .filter(|&i| strains[i] > 1.5 * top)
            .collect();
        let needed = if law == GrowthLaw::CrackVolume { 4 } else { 2 };
        assert!(tail_rates.len() >= needed, "{law:?}: {tail_rates:?}");
        for &i in &tail_rates {
            let ratio = peaks[i] / gk[i];
            match law {
                // d(D^(1/3))/dt = n^(1/3) c_g/R_s with n = k V_i ε^m, ε = ε̇t, integrates to
                // D = (4π/3) c_g³ k ε̇^m t^(m+3) · 27/(m+3)³: Grady–Kipp's t^(m+3) with the
                // prefactor 27(m+1)(m+2)/(6(m+3)²) = 3.4375 times larger for m = 9, so the
                // peak is 3.4375^(−1/(m+3)) = 0.9022 of Grady–Kipp's at every rate.
                GrowthLaw::CrackVolume => {
                    assert!((ratio / 0.9022 - 1.0).abs() < 0.01, "{}: {ratio}", rates[i])
                }
                // Crack radii that add up: D^(1/3) ∝ ε̇^m t^(m+1), σ_max ∝ ε̇^(1/(m+1)).
                _ => assert!(ratio < 0.75, "{}: {ratio}", rates[i]),
            }
        }
        let local_last = (peaks[rates.len() - 1] / peaks[rates.len() - 2]).log10();
        let expected = match law {
            GrowthLaw::CrackVolume => 0.25,
            _ => 0.1,
        };
        assert!(
            (local_last - expected).abs() < 2e-3,
            "{law:?}: {local_last}"
        );
    }
}
