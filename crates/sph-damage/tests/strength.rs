//! Static strength σ_b = E (kV)^(−1/m) and elastic helpers: the study's numbers (paper
//! §3.3) and docs/reference/weibull_flaws.md, "Parameter sets".

use sph_damage::{
    DamageError, WeibullParams, longitudinal_wave_speed, min_activation_strain, poisson_ratio,
    static_strength, youngs_modulus,
};
use std::f64::consts::PI;

fn basalt_e() -> f64 {
    youngs_modulus(26.7e9, 22.7e9)
}

/// `value` rounds to `table` at `decimals` decimals (the table's printed precision).
fn rounds_to(value: f64, table: f64, decimals: i32) -> bool {
    (value - table).abs() <= 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9)
}

#[test]
fn basalt_elastic_constants() {
    // E = 9KG/(3K + G) = 9·26.7·22.7/102.8 GPa = 53.0624 GPa (hand computed).
    let e = basalt_e();
    assert!((e - 9.0 * 26.7e9 * 22.7e9 / (3.0 * 26.7e9 + 22.7e9)).abs() <= 1e-6);
    assert!(rounds_to(e / 1e9, 53.06, 2), "{e}");
    // ν = (3K − 2G)/(2(3K + G)) = 34.7/205.6 = 0.16877 (docs/reference/weibull_flaws.md,
    // "Parameter sets": 0.1688).
    assert!(rounds_to(poisson_ratio(26.7e9, 22.7e9), 0.1688, 4));
    // c_L at 2700 kg/m³ = 4593.3 m/s (docs/reference/weibull_flaws.md, "Parameter sets").
    assert!(rounds_to(
        longitudinal_wave_speed(26.7e9, 22.7e9, 2700.0),
        4593.3,
        1
    ));
    // Consistency E = 2G(1 + ν).
    let nu = poisson_ratio(26.7e9, 22.7e9);
    assert!((e / (2.0 * 22.7e9 * (1.0 + nu)) - 1.0).abs() < 1e-14);
}

#[test]
fn study_static_strength_of_disc_and_target() {
    // Paper §3.3: 9.62 MPa for the Ø50 × 50 mm Brazilian disc, 7.34 MPa for the
    // Ø123.3 × 123.3 mm target cylinder, m = 10, k = 2.7e41 m⁻³, E = 53.06 GPa.
    let w = WeibullParams::BASALT_STUDY;
    let e = basalt_e();
    for (diameter, height, expected) in [(0.050, 0.050, 9.62e6), (0.1233, 0.1233, 7.34e6)] {
        let v = PI * (0.5 * diameter) * (0.5 * diameter) * height;
        let sigma = w.static_strength(e, v);
        let rel = sigma / expected - 1.0;
        println!(
            "Ø{diameter} × {height} m: V = {v:.5e} m³, σ_b = {:.4} MPa (study {:.2}, {:+.3} %)",
            sigma / 1e6,
            expected / 1e6,
            100.0 * rel
        );
        assert!(rel.abs() < 5e-3, "{sigma}");
        assert_eq!(sigma, static_strength(e, w.k(), w.m(), v));
    }
}

#[test]
fn verification_table_static_strength_for_basalt() {
    // docs/reference/weibull_flaws.md, "Parameter sets", E = 53.06 GPa; MPa at
    // the table's precision.
    let e = basalt_e();
    let volumes = [
        ("1 cm³", 1.0e-6),
        ("6 cm sphere", 4.0 / 3.0 * PI * 0.03f64.powi(3)),
        ("1 m³", 1.0),
        ("1 km-radius body", 4.0 / 3.0 * PI * 1.0e9),
    ];
    let table: [(WeibullParams, [(f64, i32); 4]); 3] = [
        (
            WeibullParams::BASALT_BA99,
            [(27.3, 1), (16.1, 1), (5.88, 2), (0.50, 2)],
        ),
        (
            WeibullParams::BASALT_SCHAEFER16,
            [(13.7, 1), (7.60, 2), (2.44, 2), (0.15, 2)],
        ),
        (
            WeibullParams::BASALT_NAKAMURA07,
            [(19.4, 1), (14.4, 1), (8.17, 2), (2.05, 2)],
        ),
    ];
    for (w, row) in table {
        for ((name, v), (mpa, decimals)) in volumes.iter().zip(row) {
            let sigma = w.static_strength(e, *v) / 1e6;
            println!(
                "k = {:e}, m = {}: {name}: σ = {sigma:.4} MPa (table {mpa})",
                w.k(),
                w.m()
            );
            // The table's printed digits, or within 0.1 %: the table's 5.88 MPa for BA99
            // at 1 m³ is 5.8749 MPa exactly (ε_min = 1.10700e-4), a last-digit rounding
            // slip of the table.
            let ok = rounds_to(sigma, mpa, decimals) || (sigma / mpa - 1.0).abs() <= 1e-3;
            assert!(ok, "{name}: {sigma} vs {mpa}");
        }
    }
    // ε_min for BA99, to the table's four significant figures.
    let w = WeibullParams::BASALT_BA99;
    for ((_, v), (eps, decimals)) in
        volumes
            .iter()
            .zip([(5.139e-4, 7), (3.039e-4, 7), (1.107e-4, 7), (9.44e-6, 8)])
    {
        let got = w.min_activation_strain(*v);
        assert!(rounds_to(got, eps, decimals), "{got} vs {eps}");
        assert_eq!(got, min_activation_strain(w.k(), w.m(), *v));
    }
}

#[test]
fn size_effect_slope_is_minus_one_over_m() {
    let w = WeibullParams::BASALT_BA99;
    let e = basalt_e();
    let s1 = w.static_strength(e, 1.0e-6);
    let s2 = w.static_strength(e, 1.0e3);
    let slope = (s2 / s1).ln() / (1.0e3f64 / 1.0e-6).ln();
    assert!((slope + 1.0 / 9.0).abs() < 1e-14, "{slope}");
}

#[test]
fn named_sets_are_valid_and_found_by_name() {
    for n in WeibullParams::NAMED {
        let p = WeibullParams::new(n.params.k(), n.params.m()).unwrap();
        assert_eq!(p, n.params);
        assert_eq!(WeibullParams::named(n.name), Some(n.params));
        assert!(!n.citation.is_empty());
    }
    let expect = [
        ("basalt-study", 2.7e41, 10.0),
        ("basalt-ba99", 4.0e35, 9.0),
        ("basalt-ba94", 5.0e34, 8.5),
        ("basalt-schaefer16", 5.0e34, 8.0),
        ("ice-ba99", 1.4e38, 9.6),
    ];
    for (name, k, m) in expect {
        let p = WeibullParams::named(name).unwrap();
        assert_eq!((p.k(), p.m()), (k, m), "{name}");
    }
    assert_eq!(WeibullParams::named("granite"), None);
}

#[test]
fn weibull_parameters_are_validated_with_the_field_named() {
    for (k, m, field) in [
        (0.0, 9.0, "k"),
        (-4e35, 9.0, "k"),
        (f64::NAN, 9.0, "k"),
        (f64::INFINITY, 9.0, "k"),
        (4e35, 0.0, "m"),
        (4e35, -1.0, "m"),
        (4e35, f64::NAN, "m"),
    ] {
        match WeibullParams::new(k, m) {
            Err(DamageError::Parameter { field: f, .. }) => assert_eq!(f, field),
            other => panic!("({k}, {m}): {other:?}"),
        }
    }
    // serde applies the same checks.
    let ok: WeibullParams = serde_json::from_str(r#"{"k": 4e35, "m": 9.0}"#).unwrap();
    assert_eq!(ok, WeibullParams::BASALT_BA99);
    let bad = serde_json::from_str::<WeibullParams>(r#"{"k": 4e35, "m": -9.0}"#);
    assert!(bad.unwrap_err().to_string().contains("m = -9"));
    let json = serde_json::to_string(&WeibullParams::BASALT_STUDY).unwrap();
    assert_eq!(
        serde_json::from_str::<WeibullParams>(&json).unwrap(),
        WeibullParams::BASALT_STUDY
    );
}
