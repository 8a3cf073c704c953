//! Tillotson: the check points of docs/reference/tillotson.md, derivatives in every region,
//! continuity across E_iv and E_cv, and the sign of c² over (0.1–3 ρ0) × (0–100 E_cv).

use crate::common::{close, fd, isentropic_c2, rel};
use proptest::prelude::*;
use sph_eos::{EquationOfState, Tillotson, TillotsonParams, TillotsonRegion};

fn basalt() -> Tillotson {
    Tillotson::new(TillotsonParams::basalt_ba99()).unwrap()
}
fn aluminium() -> Tillotson {
    Tillotson::new(TillotsonParams::aluminium_melosh89()).unwrap()
}

/// One row of docs/reference/tillotson.md, "Check points": (η, e selector, printed P, 40-digit
/// P, region).
/// The 40-digit values come from tests/reference/tillotson_reference.py (mpmath).
struct Row {
    eta: f64,
    e: E,
    printed: f64,
    exact: f64,
    region: TillotsonRegion,
}
#[derive(Clone, Copy)]
enum E {
    Value(f64),
    MidIvCv,
    TwiceCv,
}

fn energy(sel: E, t: &Tillotson) -> f64 {
    let p = t.params();
    match sel {
        E::Value(v) => v,
        E::MidIvCv => 0.5 * (p.E_iv + p.E_cv),
        E::TwiceCv => 2.0 * p.E_cv,
    }
}

fn rows(basalt: bool) -> Vec<Row> {
    use E::*;
    use TillotsonRegion::*;
    // (η, e, basalt printed, basalt exact, Al printed, Al exact, region)
    let table: [(f64, E, f64, f64, f64, f64, TillotsonRegion); 13] = [
        (1.00, Value(0.0), 0.0, 0.0, 0.0, 0.0, Compressed),
        (
            1.00,
            Value(1e6),
            5.391701e9,
            5_391_700_819.672_131_1,
            5.017500e9,
            5_017_500_000.0,
            Compressed,
        ),
        (
            1.10,
            Value(0.0),
            2.937000e9,
            2_937_000_000.0,
            8.170000e9,
            8_170_000_000.0,
            Compressed,
        ),
        (
            1.20,
            Value(0.0),
            6.408000e9,
            6_408_000_000.0,
            1.764000e10,
            17_640_000_000.0,
            Compressed,
        ),
        (
            1.50,
            Value(0.0),
            2.002500e10,
            20_025_000_000.0,
            5.385000e10,
            53_850_000_000.0,
            Compressed,
        ),
        (
            1.50,
            Value(1e7),
            1.004756e11,
            100_475_599_140.854_62,
            1.090491e11,
            109_049_117_647.058_82,
            Compressed,
        ),
        (
            2.00,
            Value(1e8),
            1.093849e12,
            1_093_849_218_750.0,
            5.569000e11,
            556_900_000_000.0,
            Compressed,
        ),
        (
            0.95,
            Value(0.0),
            -1.268250e9,
            -1_268_250_000.0,
            -3.597500e9,
            -3_597_500_000.0,
            ColdExpanded,
        ),
        (
            0.90,
            Value(1e6),
            2.447783e9,
            2_447_783_118.820_643_8,
            -2.478437e9,
            -2_478_436_633.663_366_3,
            ColdExpanded,
        ),
        (
            0.80,
            MidIvCv,
            4.068882e10,
            40_688_822_609.299_247,
            8.405002e9,
            8_405_002_161.110_006,
            Intermediate,
        ),
        (
            0.50,
            TwiceCv,
            2.495174e10,
            24_951_737_467.210_768,
            1.878103e10,
            18_781_029_042.500_111,
            HotExpanded,
        ),
        (
            0.10,
            TwiceCv,
            4.914000e9,
            4_914_000_000.0,
            3.753000e9,
            3_753_000_000.0,
            HotExpanded,
        ),
        (
            0.50,
            Value(1e8),
            6.824853e10,
            68_248_525_239.215_361,
            6.751660e10,
            67_516_597_718.655_113,
            HotExpanded,
        ),
    ];
    table
        .into_iter()
        .map(|(eta, e, pb, xb, pa, xa, region)| Row {
            eta,
            e,
            printed: if basalt { pb } else { pa },
            exact: if basalt { xb } else { xa },
            region,
        })
        .collect()
}

/// Half a unit in the 7th significant digit of a value printed as d.dddddd·10^k.
fn half_printed_unit(v: f64) -> f64 {
    if v == 0.0 {
        0.0
    } else {
        0.5 * 10f64.powi(v.abs().log10().floor() as i32 - 6)
    }
}

#[test]
fn check_points_of_verification_section_8() {
    let mut worst: f64 = 0.0;
    for (name, t, is_basalt) in [
        ("basalt", basalt(), true),
        ("aluminium", aluminium(), false),
    ] {
        for row in rows(is_basalt) {
            let rho = row.eta * 2700.0;
            let e = energy(row.e, &t);
            let p = t.evaluate(rho, e);
            assert_eq!(t.region(rho, e), row.region, "{name} η={} e={e}", row.eta);
            assert_eq!(
                t.pressure(rho, e),
                p.pressure,
                "pressure() must equal evaluate()"
            );
            // Against the printed table: within half a unit of its last printed digit.
            assert!(
                (p.pressure - row.printed).abs() <= half_printed_unit(row.printed),
                "{name} η={} e={e}: P = {:.7e}, table {:.6e}",
                row.eta,
                p.pressure,
                row.printed
            );
            // Against the 40-digit recomputation: round-off only (spec tolerance 1e-12).
            let r = rel(p.pressure, row.exact);
            worst = worst.max(r);
            assert!(
                r <= 1e-12,
                "{name} η={} e={e}: P = {:.17e}, exact {:.17e}, rel {r:.2e}",
                row.eta,
                p.pressure,
                row.exact
            );
            if row.exact == 0.0 {
                assert_eq!(p.pressure, 0.0, "P(ρ0, 0) must be exactly 0");
            }
        }
    }
    println!("Tillotson check points: worst relative error vs 40-digit reference = {worst:.2e}");
}

#[test]
fn study_sets_use_the_study_densities() {
    let b = TillotsonParams::basalt_study();
    let a = TillotsonParams::aluminium_study();
    assert_eq!((b.rho0, b.E0, b.E_cv), (2876.0, 4.87e8, 1.82e7));
    assert_eq!((a.rho0, a.E_cv, a.E_iv), (2785.0, 1.5e7, 3.0e6));
    // Same A, B, a, b, α, β as the literature sets.
    let bl = TillotsonParams::basalt_ba99();
    let al = TillotsonParams::aluminium_melosh89();
    assert_eq!(
        (b.A, b.B, b.a, b.b, b.alpha, b.beta),
        (bl.A, bl.B, bl.a, bl.b, bl.alpha, bl.beta)
    );
    assert_eq!(
        (a.A, a.B, a.a, a.b, a.alpha, a.beta, a.E0),
        (al.A, al.B, al.a, al.b, al.alpha, al.beta, al.E0)
    );
}

/// Region bounds used to sample strictly inside one region (margin ≥ 1e-3 relative, far
/// beyond the 1e-6 relative finite-difference steps).
fn sample(t: &Tillotson, region: TillotsonRegion, u: f64, v: f64) -> (f64, f64) {
    let p = t.params();
    let lerp = |a: f64, b: f64, s: f64| a + (b - a) * s;
    let (eta, e) = match region {
        TillotsonRegion::Compressed => (lerp(1.001, 3.0, u), lerp(0.0, 100.0 * p.E_cv, v)),
        TillotsonRegion::ColdExpanded => (lerp(0.1, 0.999, u), lerp(0.0, 0.999 * p.E_iv, v)),
        TillotsonRegion::Intermediate => {
            (lerp(0.1, 0.999, u), lerp(1.001 * p.E_iv, 0.999 * p.E_cv, v))
        }
        TillotsonRegion::HotExpanded => {
            (lerp(0.1, 0.999, u), lerp(1.001 * p.E_cv, 100.0 * p.E_cv, v))
        }
    };
    (eta * p.rho0, e)
}

const REGIONS: [TillotsonRegion; 4] = [
    TillotsonRegion::Compressed,
    TillotsonRegion::ColdExpanded,
    TillotsonRegion::Intermediate,
    TillotsonRegion::HotExpanded,
];

/// Max relative FD error of (∂P/∂ρ, ∂P/∂e) at one state; the absolute floors are 1e-9 of the
/// natural scales A/ρ0 and ρ (a derivative crossing zero has no relative error).
fn derivative_errors(t: &Tillotson, rho: f64, e: f64) -> (f64, f64) {
    let p = t.evaluate(rho, e);
    // Steps ≥ 1 J/kg: at e ≈ 0 with P ~ 1e11 Pa a smaller step would lose the difference
    // in round-off (ε P / h).
    let h_e = 1e-6 * e.abs().max(1e6);
    let (dr, de) = fd(t, rho, e, 1e-6 * rho, h_e);
    let c02 = t.params().A / t.params().rho0;
    let er = (p.dp_drho - dr).abs() / (p.dp_drho.abs().max(dr.abs()) + 1e-3 * c02);
    let ee = (p.dp_de - de).abs() / (p.dp_de.abs().max(de.abs()) + 1e-3 * rho);
    (er, ee)
}

#[test]
fn derivatives_match_central_differences_in_every_region() {
    for (name, params) in TillotsonParams::named() {
        let t = Tillotson::new(params).unwrap();
        for region in REGIONS {
            let (mut wr, mut we) = (0.0f64, 0.0f64);
            for i in 0..=40 {
                for j in 0..=40 {
                    let (rho, e) = sample(&t, region, i as f64 / 40.0, j as f64 / 40.0);
                    assert_eq!(t.region(rho, e), region);
                    let (er, ee) = derivative_errors(&t, rho, e);
                    wr = wr.max(er);
                    we = we.max(ee);
                }
            }
            println!("{name:>18} {region:?}: max FD rel error dP/dρ {wr:.1e}, dP/de {we:.1e}");
            assert!(
                wr < 1e-6 && we < 1e-6,
                "{name} {region:?}: {wr:.2e} {we:.2e}"
            );
        }
    }
}

#[test]
fn pressure_is_continuous_across_e_iv_and_e_cv_and_eta_one() {
    let mut worst: f64 = 0.0;
    for (name, params) in TillotsonParams::named() {
        let t = Tillotson::new(params).unwrap();
        for k in 1..=99 {
            let rho = k as f64 / 100.0 * params.rho0;
            for (edge, below, above) in [
                ("E_iv", params.E_iv, params.E_iv.next_up()),
                ("E_cv", params.E_cv.next_down(), params.E_cv),
            ] {
                assert_ne!(t.region(rho, below), t.region(rho, above));
                let (pl, pr) = (t.pressure(rho, below), t.pressure(rho, above));
                let jump = (pl - pr).abs() / pl.abs().max(pr.abs());
                worst = worst.max(jump);
                assert!(
                    jump <= 1e-9,
                    "{name} η={} at {edge}: {pl} vs {pr}",
                    k as f64 / 100.0
                );
            }
        }
        // η = 1: P_c = P_e there, so the expanded branches meet the compressed one.
        for e in [
            0.5 * params.E_iv,
            0.5 * (params.E_iv + params.E_cv),
            3.0 * params.E_cv,
        ] {
            let (pl, pr) = (
                t.pressure(params.rho0.next_down(), e),
                t.pressure(params.rho0, e),
            );
            assert!(rel(pl, pr) <= 1e-9, "{name} η=1 e={e}: {pl} vs {pr}");
        }
    }
    println!("largest relative jump across E_iv / E_cv: {worst:.2e}");
}

/// Scans (ρ/ρ0 ∈ [0.1, 3], e ∈ [0, 100 E_cv]) for every named set and reports where the raw
/// c² falls below the floor (default 1 % of c0), by region. Asserted findings: c > 0 and
/// finite everywhere; the floor is flagged exactly where raw c² < floor²; it is needed only
/// in expanded states (never compressed); for the basalt and aluminium sets only in cold
/// or intermediate expanded states (tension), never hot expanded. Ice (α = 10) also needs
/// it in part of its hot-expanded region (printed).
#[test]
fn sound_speed_over_the_whole_grid() {
    for (set, (name, params)) in TillotsonParams::named().into_iter().enumerate() {
        let basalt_or_al = set < 4;
        let t = Tillotson::new(params).unwrap();
        let floor2 = t.sound_speed_floor().powi(2);
        let mut n = 0usize;
        let mut by_region = [0usize; 4];
        let (mut eta_max, mut e_max) = (0.0f64, 0.0f64);
        let mut zero_crossing_at_e0 = f64::NAN;
        for i in 0..=290 {
            let eta = 0.1 + 0.01 * i as f64;
            let rho = eta * params.rho0;
            // Dense at low e (where the floor acts), coarser up to 100 E_cv.
            let energies = (0..=400)
                .map(|j| 2.0 * params.E_cv * j as f64 / 400.0)
                .chain(
                    (1..=200).map(|j| 2.0 * params.E_cv + 98.0 * params.E_cv * j as f64 / 200.0),
                );
            for e in energies {
                let p = t.evaluate(rho, e);
                n += 1;
                assert!(
                    p.sound_speed.is_finite() && p.sound_speed > 0.0,
                    "{name} η={eta} e={e}"
                );
                assert_eq!(p.sound_speed_floored, p.raw_sound_speed_squared < floor2);
                if p.sound_speed_floored {
                    let region = t.region(rho, e);
                    by_region[REGIONS.iter().position(|r| *r == region).unwrap()] += 1;
                    eta_max = eta_max.max(eta);
                    e_max = e_max.max(e);
                    assert_ne!(region, TillotsonRegion::Compressed, "{name} η={eta} e={e}");
                    if basalt_or_al {
                        assert_ne!(region, TillotsonRegion::HotExpanded, "{name} η={eta} e={e}");
                    }
                } else {
                    assert!(p.raw_sound_speed_squared > 0.0);
                }
                if e == 0.0 && p.raw_sound_speed_squared > 0.0 && zero_crossing_at_e0.is_nan() {
                    zero_crossing_at_e0 = eta;
                }
            }
        }
        let floored: usize = by_region.iter().sum();
        println!(
            "{name:>18}: floor (c ≥ {:5.1} m/s) at {floored:5}/{n} states [cold exp. {}, intermediate {}, hot exp. {}], \
             all with η ≤ {eta_max:.2}, e ≤ {:.2} MJ/kg (E_iv {:.2}, E_cv {:.2}); at e = 0 raw c² > 0 from η = {zero_crossing_at_e0:.2}",
            t.sound_speed_floor(),
            by_region[1],
            by_region[2],
            by_region[3],
            e_max / 1e6,
            params.E_iv / 1e6,
            params.E_cv / 1e6,
        );
        assert!(floored > 0, "{name}: the cold-tension floor region exists");
    }
}

/// Basalt cold branch at e = 0: c² = (A/ρ0)(1 + 4μ) (A = B, a + b = 2), so c² < 0 for η < 0.75.
#[test]
fn basalt_cold_tension_sound_speed_formula() {
    let t = basalt();
    let c02 = 26.7e9 / 2700.0;
    for eta in [0.5, 0.7, 0.74, 0.76, 0.9, 1.0, 1.3] {
        let p = t.evaluate(eta * 2700.0, 0.0);
        let expected = c02 * (1.0 + 4.0 * (eta - 1.0));
        assert!(
            close(p.raw_sound_speed_squared, expected, 1e-12, 1e-9 * c02),
            "η={eta}"
        );
        assert_eq!(p.sound_speed_floored, expected < (0.01f64).powi(2) * c02);
    }
}

fn any_region() -> impl Strategy<Value = TillotsonRegion> {
    prop_oneof![
        Just(TillotsonRegion::Compressed),
        Just(TillotsonRegion::ColdExpanded),
        Just(TillotsonRegion::Intermediate),
        Just(TillotsonRegion::HotExpanded),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    /// Random states in a random region of a random named set: analytic derivatives
    /// against central differences, and c² against the isentropic difference.
    #[test]
    fn derivatives_and_isentropic_c2(set in 0usize..7, region in any_region(), u in 0.0..1.0f64, v in 0.0..1.0f64) {
        let (_, params) = TillotsonParams::named()[set];
        let t = Tillotson::new(params).unwrap();
        let (rho, e) = sample(&t, region, u, v);
        let (er, ee) = derivative_errors(&t, rho, e);
        prop_assert!(er < 1e-6 && ee < 1e-6, "{:?} ρ={} e={}: {:.2e} {:.2e}", region, rho, e, er, ee);
        let p = t.evaluate(rho, e);
        let c2 = isentropic_c2(&t, rho, e, 1e-6 * rho);
        let c02 = params.A / params.rho0;
        prop_assert!(close(p.raw_sound_speed_squared, c2, 1e-6, 1e-6 * c02),
            "{:?} ρ={} e={}: c² {} vs isentropic {}", region, rho, e, p.raw_sound_speed_squared, c2);
    }

    /// c > 0 on (0.1–3 ρ0) × (0–100 E_cv); the floor only where the raw c² is below it,
    /// never in compression, and for the basalt/aluminium sets (0..4) never hot expanded.
    #[test]
    fn sound_speed_positive(set in 0usize..7, eta in 0.1..3.0f64, s in 0.0..100.0f64) {
        let (_, params) = TillotsonParams::named()[set];
        let t = Tillotson::new(params).unwrap();
        let (rho, e) = (eta * params.rho0, s * params.E_cv);
        let p = t.evaluate(rho, e);
        prop_assert!(p.sound_speed > 0.0 && p.sound_speed.is_finite());
        prop_assert_eq!(p.sound_speed_floored, p.raw_sound_speed_squared < t.sound_speed_floor().powi(2));
        if p.sound_speed_floored {
            let region = t.region(rho, e);
            prop_assert!(region != TillotsonRegion::Compressed);
            if set < 4 {
                prop_assert!(region != TillotsonRegion::HotExpanded, "{:?}", region);
            }
        }
    }
}

#[test]
fn object_safe_use_matches_the_concrete_type() {
    let t = basalt();
    let boxed: Box<dyn EquationOfState> = Box::new(t);
    for (rho, e) in [(2970.0, 0.0), (2160.0, 1.146e7), (1350.0, 3.64e7)] {
        assert_eq!(boxed.evaluate(rho, e), t.evaluate(rho, e));
    }
    assert_eq!(boxed.reference_density(), Some(2700.0));
    assert_eq!(boxed.name(), "tillotson");
    // Generic code accepts the box, a reference and an Arc.
    fn p_at<E: EquationOfState + ?Sized>(eos: &E) -> f64 {
        eos.pressure(2970.0, 0.0)
    }
    assert_eq!(p_at(&boxed), p_at(&t));
    assert_eq!(p_at(&std::sync::Arc::new(t)), p_at(&&t));
}

#[test]
fn checked_evaluate_rejects_bad_states() {
    let t = basalt();
    assert!(t.checked_evaluate(2700.0, 0.0).is_ok());
    assert!(t.checked_evaluate(0.0, 0.0).is_err());
    assert!(t.checked_evaluate(2700.0, f64::NAN).is_err());
    assert!(t.checked_evaluate(2700.0, -1e9).is_err()); // ω0 < 0
}

#[test]
fn params_deserialize_by_literature_names_and_reject_typos() {
    use serde::Deserialize;
    use serde::de::value::{Error, MapDeserializer};
    let fields = [
        ("rho0", 2700.0),
        ("A", 26.7e9),
        ("B", 26.7e9),
        ("a", 0.5),
        ("b", 1.5),
        ("alpha", 5.0),
        ("beta", 5.0),
        ("E0", 487e6),
        ("E_iv", 4.72e6),
        ("E_cv", 18.2e6),
    ];
    let p =
        TillotsonParams::deserialize(MapDeserializer::<_, Error>::new(fields.into_iter())).unwrap();
    assert_eq!(p, TillotsonParams::basalt_ba99());
    let mut typo = fields.to_vec();
    typo[8] = ("E_IV", 4.72e6);
    assert!(
        TillotsonParams::deserialize(MapDeserializer::<_, Error>::new(typo.into_iter())).is_err()
    );
}
