//! Temperature with latent heats (paper §3.1): plateaus, thresholds, monotonicity, fractions.

use crate::common::rel;
use proptest::prelude::*;
use sph_eos::{ThermalModel, ThermalParams};

#[test]
fn aluminium_thresholds_and_plateaus() {
    let al = ThermalModel::aluminium();
    let p = *al.params();
    // Hand values: e_ms = 897·(933.47 − 300) = 568 222.59 J/kg; e_mf = e_ms + 397 000;
    // e_vs = e_mf + 897·(2792 − 933.47) = e_mf + 1 667 101.41; e_vf = e_vs + 1.09e7.
    let e_ms = 568_222.59;
    let e_mf = 965_222.59;
    let e_vs = 2_632_324.0;
    let e_vf = 13_532_324.0;
    assert!(rel(al.incipient_melting_energy(), e_ms) <= 1e-12);
    assert!(rel(al.complete_melting_energy(), e_mf) <= 1e-12);
    assert!(rel(al.incipient_vaporisation_energy(), e_vs) <= 1e-12);
    assert!(rel(al.complete_vaporisation_energy(), e_vf) <= 1e-12);
    println!(
        "Al: melting {:.4}–{:.4} MJ/kg, vaporisation {:.4}–{:.4} MJ/kg",
        e_ms / 1e6,
        e_mf / 1e6,
        e_vs / 1e6,
        e_vf / 1e6
    );

    assert_eq!(al.temperature(0.0), 300.0);
    assert!(rel(al.temperature(0.5 * e_ms), 300.0 + 0.5 * e_ms / 897.0) <= 1e-14);
    // Melting plateau at T_melt from e_ms to e_mf, melt fraction linear 0 → 1.
    for s in [0.0, 0.25, 0.5, 0.999] {
        let e = e_ms + s * p.L_melt;
        let st = al.state(e);
        assert_eq!(st.temperature, p.T_melt, "s={s}");
        assert!((st.melt_fraction - s).abs() <= 1e-9, "s={s}");
        assert_eq!(st.vapour_fraction, 0.0);
    }
    // Liquid heating, then the vaporisation plateau at T_vap.
    assert!(
        rel(
            al.temperature(0.5 * (e_mf + e_vs)),
            0.5 * (p.T_melt + p.T_vap)
        ) <= 1e-9
    );
    assert_eq!(al.melt_fraction(0.5 * (e_mf + e_vs)), 1.0);
    for s in [0.0, 0.3, 0.999] {
        let st = al.state(e_vs + s * p.L_vap);
        assert_eq!(st.temperature, p.T_vap);
        assert_eq!(st.melt_fraction, 1.0);
        assert!((st.vapour_fraction - s).abs() <= 1e-9);
    }
    // Vapour heating.
    assert!(rel(al.temperature(e_vf + 897.0 * 1000.0), p.T_vap + 1000.0) <= 1e-12);
    assert_eq!(al.vapour_fraction(2.0 * e_vf), 1.0);
}

#[test]
fn basalt_thresholds() {
    let b = ThermalModel::basalt();
    // 840·1173 = 985 320; + 4e5; + 840·1427 = 1 198 680; + 1.1e7.
    assert!(rel(b.incipient_melting_energy(), 985_320.0) <= 1e-12);
    assert!(rel(b.complete_melting_energy(), 1_385_320.0) <= 1e-12);
    assert!(rel(b.incipient_vaporisation_energy(), 2_584_000.0) <= 1e-12);
    assert!(rel(b.complete_vaporisation_energy(), 13_584_000.0) <= 1e-12);
}

#[test]
fn below_absolute_zero_is_clamped_with_a_flag() {
    let al = ThermalModel::aluminium();
    let e0k = al.zero_kelvin_energy();
    assert_eq!(e0k, -897.0 * 300.0);
    let st = al.state(0.5 * e0k);
    assert!(!st.clamped_at_zero && rel(st.temperature, 150.0) <= 1e-12);
    let st = al.state(1.01 * e0k);
    assert!(st.clamped_at_zero && st.temperature == 0.0);
    assert_eq!((st.melt_fraction, st.vapour_fraction), (0.0, 0.0));
    assert!(al.temperature(f64::NAN).is_nan());
}

fn model() -> impl Strategy<Value = ThermalModel> {
    (
        100.0..2000.0f64,
        0.0..500.0f64,
        1.0..2000.0f64,
        1e4..1e6f64,
        1.0..3000.0f64,
        1e5..2e7f64,
    )
        .prop_map(|(c_v, t_ref, dt_m, l_melt, dt_v, l_vap)| {
            ThermalModel::new(ThermalParams {
                c_v,
                T_ref: t_ref,
                T_melt: t_ref + dt_m,
                L_melt: l_melt,
                T_vap: t_ref + dt_m + dt_v,
                L_vap: l_vap,
            })
            .unwrap()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    /// T, f_m, f_v non-decreasing in e; fractions in [0, 1]; f_v ≤ f_m.
    #[test]
    fn monotone_and_bounded(m in model(), a in -1.0..1.0f64, b in -1.0..1.0f64) {
        let span = 1.2 * m.complete_vaporisation_energy();
        let (e1, e2) = if a <= b { (a * span, b * span) } else { (b * span, a * span) };
        let (s1, s2) = (m.state(e1), m.state(e2));
        prop_assert!(s1.temperature <= s2.temperature);
        prop_assert!(s1.melt_fraction <= s2.melt_fraction);
        prop_assert!(s1.vapour_fraction <= s2.vapour_fraction);
        for s in [s1, s2] {
            prop_assert!((0.0..=1.0).contains(&s.melt_fraction));
            prop_assert!((0.0..=1.0).contains(&s.vapour_fraction));
            prop_assert!(s.vapour_fraction <= s.melt_fraction);
            prop_assert!(s.temperature >= 0.0);
        }
    }

    /// T is continuous at the four thresholds.
    #[test]
    fn continuous_at_thresholds(m in model()) {
        for e in [m.incipient_melting_energy(), m.complete_melting_energy(),
                  m.incipient_vaporisation_energy(), m.complete_vaporisation_energy()] {
            let (lo, hi) = (m.state(e.next_down()), m.state(e));
            prop_assert!((hi.temperature - lo.temperature).abs() <= 1e-9 * hi.temperature);
            prop_assert!((hi.melt_fraction - lo.melt_fraction).abs() <= 1e-9);
            prop_assert!((hi.vapour_fraction - lo.vapour_fraction).abs() <= 1e-9);
        }
    }
}

/// Gives the melt fraction a Hugoniot-heated aluminium particle would have: a sanity link
/// to the study's "~50 % melting at 3.9 km/s" (an energy ≈ e_ms + L_melt/2 ≈ 0.77 MJ/kg).
#[test]
fn half_melted_energy() {
    let al = ThermalModel::aluminium();
    let e_half = al.incipient_melting_energy() + 0.5 * al.params().L_melt;
    assert!((e_half - 766_722.59).abs() < 1e-6);
    assert!((al.melt_fraction(e_half) - 0.5).abs() < 1e-12);
}
