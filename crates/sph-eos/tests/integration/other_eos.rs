//! Ideal gas, Mie–Grüneisen, Murnaghan and linear elastic: point values, derivatives against
//! central differences, thermodynamic consistency (c² = (∂P/∂ρ)_s along an isentrope).

use crate::common::{close, fd, isentropic_c2, rel};
use proptest::prelude::*;
use sph_eos::{
    EquationOfState, IdealGas, LinearElastic, LinearElasticParams, MieGruneisen,
    MieGruneisenParams, Murnaghan, MurnaghanParams,
};

fn mg() -> MieGruneisen {
    MieGruneisen::new(MieGruneisenParams::aluminium_6061()).unwrap()
}
fn water_tait() -> Murnaghan {
    // Weakly compressible water (Monaghan 1994 form): ρ0 = 1000, K0 = 2.2 GPa, n = 7.
    Murnaghan::new(MurnaghanParams {
        rho0: 1000.0,
        K0: 2.2e9,
        n: 7.0,
    })
    .unwrap()
}
fn al_linear() -> LinearElastic {
    // docs/reference/weibull_flaws.md, "Parameter sets", aluminium: E = 70 GPa, ν = 0.3
    // → K = E/(3(1 − 2ν)).
    LinearElastic::new(LinearElasticParams {
        rho0: 2700.0,
        K0: 70e9 / (3.0 * 0.4),
    })
    .unwrap()
}

#[test]
fn ideal_gas_point_values() {
    // Sod left state: ρ = 1, P = 1, γ = 1.4 → e = 2.5, c = √1.4.
    let g = IdealGas::with_gamma(1.4).unwrap();
    let p = g.evaluate(1.0, 2.5);
    assert!(rel(p.pressure, 1.0) <= 1e-15);
    assert!(rel(p.sound_speed, 1.183_215_956_619_923_2) <= 1e-15);
    assert!(rel(p.dp_drho, 1.0) <= 1e-15 && rel(p.dp_de, 0.4) <= 1e-15);
    assert!(!p.sound_speed_floored);
    assert_eq!(g.reference_density(), None);
    // e < 0 is outside the range: c² < 0 is floored at 0 m/s and flagged.
    let q = g.evaluate(1.0, -1.0);
    assert!(q.sound_speed_floored && q.sound_speed == 0.0 && q.pressure < 0.0);
    let r = g.with_min_sound_speed(1e-3).unwrap().evaluate(1.0, -1.0);
    assert_eq!(r.sound_speed, 1e-3);
}

#[test]
fn mie_gruneisen_point_values() {
    // 30-digit mpmath values of the module formula at ρ = η·2703 (rounded to f64).
    let m = mg();
    for (eta, e, exact) in [
        (1.1, 0.0, 8_290_855_709.013_29),
        (1.1, 1e6, 13_696_855_709.013_29),
        (1.5, 2e6, 66_964_284_438.960_662),
        (0.9, 0.0, -7_736_661_749.999_992),
        (0.9, 5e5, -5_033_661_749.999_992),
    ] {
        let p = m.evaluate(eta * 2703.0, e);
        assert!(
            rel(p.pressure, exact) <= 1e-13,
            "η={eta} e={e}: {} vs {exact}",
            p.pressure
        );
        assert_eq!(p.dp_de, 2.0 * 2703.0);
    }
    // At ρ0, e = 0: P = 0 and c = c0 exactly.
    let p0 = m.evaluate(2703.0, 0.0);
    assert_eq!(p0.pressure, 0.0);
    assert!(rel(p0.sound_speed, 5350.0) <= 1e-15);
    // Cold tension: c² = c0²(1 + Γ0 μ/η²) changes sign at η* = (−Γ0 + √(Γ0² + 4Γ0))/2.
    let eta_star = 0.732_050_807_568_877_3;
    assert!(
        m.evaluate(1.001 * eta_star * 2703.0, 0.0)
            .raw_sound_speed_squared
            > 0.0
    );
    assert!(
        m.evaluate(0.999 * eta_star * 2703.0, 0.0)
            .raw_sound_speed_squared
            < 0.0
    );
}

#[test]
fn murnaghan_and_linear_point_values() {
    let w = water_tait();
    for (eta, p_exact, dp_exact) in [
        (1.01, 22_671_110.662_203_143, 2_335_344.331_322_2),
        (0.9, -163_963_831.428_571_43, 1_169_170.2),
        (2.0, 39_914_285_714.285_714, 140_800_000.0),
    ] {
        let p = w.evaluate(eta * 1000.0, 123.0);
        assert!(rel(p.pressure, p_exact) <= 1e-13, "η={eta}: {}", p.pressure);
        assert!(rel(p.dp_drho, dp_exact) <= 1e-13);
        assert_eq!(p.dp_de, 0.0);
    }
    assert_eq!(w.pressure(1000.0, 0.0), 0.0);
    // docs/reference/weibull_flaws.md, "Parameter sets": c_bulk = √(K/ρ) = 4648.1 m/s for
    // Al (K = 58.33 GPa, ρ = 2700).
    let l = al_linear();
    let p = l.evaluate(2700.0 * 1.01, 5e6);
    assert!((p.sound_speed - 4648.1).abs() < 0.05);
    assert!(rel(p.pressure, 0.01 * 70e9 / 1.2) <= 1e-12);
    assert_eq!(l.pressure(2700.0, 0.0), 0.0);
    // Murnaghan with n = 1 is the linear-elastic EOS.
    let m1 = Murnaghan::new(MurnaghanParams {
        rho0: 2700.0,
        K0: 70e9 / 1.2,
        n: 1.0,
    })
    .unwrap();
    for eta in [0.3, 0.9, 1.0, 1.2, 2.5] {
        let (a, b) = (
            m1.evaluate(eta * 2700.0, 0.0),
            l.evaluate(eta * 2700.0, 0.0),
        );
        assert!(close(a.pressure, b.pressure, 1e-14, 1e-3), "η={eta}");
        assert!(rel(a.sound_speed, b.sound_speed) <= 1e-14);
    }
}

/// A named EOS for property tests, with its valid sampling box (η range, e range).
/// An EOS with its (η range, e range) of validity.
type Case = (Box<dyn EquationOfState>, (f64, f64), (f64, f64));

fn cases() -> Vec<Case> {
    let mu_max = mg().max_compression();
    vec![
        (
            Box::new(IdealGas::with_gamma(5.0 / 3.0).unwrap()),
            (0.01, 100.0),
            (0.0, 1e7),
        ),
        (Box::new(mg()), (0.8, 1.0 + 0.8 * mu_max), (0.0, 1e7)),
        (Box::new(water_tait()), (0.3, 3.0), (-1e6, 1e6)),
        (Box::new(al_linear()), (0.3, 3.0), (-1e6, 1e6)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    #[test]
    fn derivatives_consistency_and_positive_c2(which in 0usize..4, u in 0.0..1.0f64, v in 0.0..1.0f64) {
        let (eos, (eta_lo, eta_hi), (e_lo, e_hi)) = cases().swap_remove(which);
        let rho0 = eos.reference_density().unwrap_or(1.0);
        let rho = rho0 * (eta_lo + (eta_hi - eta_lo) * u);
        let e = e_lo + (e_hi - e_lo) * v;
        if (rho / rho0 - 1.0).abs() < 1e-4 && eos.name() == "mie-gruneisen" {
            // The compressed/tension switch at μ = 0 is only C¹: skip FD across it.
            return Ok(());
        }
        let p = eos.evaluate(rho, e);
        prop_assert_eq!(p.pressure, eos.pressure(rho, e));
        let (dr, de) = fd(eos.as_ref(), rho, e, 1e-6 * rho, 1e-6 * e.abs().max(1e6));
        let c2_scale = p.dp_drho.abs().max(1.0);
        prop_assert!(close(p.dp_drho, dr, 1e-6, 1e-9 * c2_scale), "{} ρ={} e={}: {} vs {}", eos.name(), rho, e, p.dp_drho, dr);
        prop_assert!(close(p.dp_de, de, 1e-6, 1e-9 * rho), "{} ρ={} e={}: {} vs {}", eos.name(), rho, e, p.dp_de, de);
        let c2 = isentropic_c2(eos.as_ref(), rho, e, 1e-6 * rho);
        prop_assert!(close(p.raw_sound_speed_squared, c2, 1e-6, 1e-9 * c2_scale));
        // Inside the valid box c² ≥ 0 and no floor is needed.
        prop_assert!(p.raw_sound_speed_squared >= 0.0, "{} ρ={} e={}", eos.name(), rho, e);
        prop_assert!(eos.checked_evaluate(rho, e).is_ok());
    }
}

#[test]
fn solids_have_zero_pressure_at_the_reference_state() {
    for (eos, _, _) in cases().into_iter().skip(1) {
        let rho0 = eos.reference_density().unwrap();
        assert_eq!(eos.pressure(rho0, 0.0), 0.0, "{}", eos.name());
        let c0 = eos.reference_sound_speed().unwrap();
        assert!(
            rel(eos.sound_speed(rho0, 0.0), c0) <= 1e-15,
            "{}",
            eos.name()
        );
    }
}
