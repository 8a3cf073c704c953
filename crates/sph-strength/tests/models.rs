//! Damage weakening (eqs 12/13) as properties, trait objects, the enum and serde.

use proptest::prelude::*;
use sph_strength::{
    BuiltinStrength, DruckerPrager, DruckerPragerParams, JohnsonCook, Lundborg, LundborgTension,
    NoStrength, SteinbergGuinan, StrengthError, StrengthModel, StrengthState, VonMises,
    damaged_strength, materials,
};

fn granite_dp() -> DruckerPrager {
    DruckerPrager::new(DruckerPragerParams {
        cohesion: 90.0e6,
        friction: 2.0,
        limit_strength: 1.5e9,
        damaged_friction: 0.8,
        shear_modulus: 27.0e9,
    })
    .unwrap()
}

fn multiplicative_models() -> Vec<Box<dyn StrengthModel>> {
    vec![
        Box::new(VonMises::new(materials::TAYLOR_BAR_COPPER).unwrap()),
        Box::new(JohnsonCook::new(materials::ALUMINIUM_2024_JC_MEASURED).unwrap()),
        Box::new(JohnsonCook::new(materials::OFHC_COPPER_JC).unwrap()),
        Box::new(SteinbergGuinan::new(materials::COPPER_SG).unwrap()),
        Box::new(SteinbergGuinan::new(materials::ALUMINIUM_2024_SG).unwrap()),
    ]
}

/// (model, μ_d) pairs for the frictional form.
fn frictional_models() -> Vec<(Box<dyn StrengthModel>, f64)> {
    let mut cst = materials::BASALT_LUNDBORG;
    cst.tension = LundborgTension::ConstantCohesion;
    vec![
        (
            Box::new(Lundborg::new(materials::BASALT_LUNDBORG).unwrap()),
            0.6,
        ),
        (Box::new(Lundborg::new(cst).unwrap()), 0.6),
        (
            Box::new(Lundborg::new(materials::GRANITE_LUNDBORG_COLLINS2004).unwrap()),
            0.8,
        ),
        (Box::new(granite_dp()), 0.8),
    ]
}

fn state(p: f64, rho: f64, t: f64, eps: f64, rate: f64, d: f64) -> StrengthState {
    StrengthState {
        pressure: p,
        density: rho,
        temperature: t,
        plastic_strain: eps,
        plastic_strain_rate: rate,
        damage: d,
        melt_fraction: 0.0,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// Eq. (12): Y = Y_i (1 − D): equals Y_i at D = 0, 0 at D = 1, non-increasing in D.
    #[test]
    fn multiplicative_weakening_eq12(
        p in -1.0e9..5.0e10f64, eta in 0.8..1.5f64, t in 200.0..2000.0f64,
        eps in 0.0..3.0f64, rate in 0.0..1.0e6f64, d1 in 0.0..=1.0f64, d2 in 0.0..=1.0f64,
    ) {
        for m in multiplicative_models() {
            let rho0 = 8930.0;
            let base = state(p, rho0 * eta, t, eps, rate, 0.0);
            let yi = m.intact_yield(&base);
            prop_assert!(yi >= 0.0);
            prop_assert_eq!(m.yield_strength(&base), yi);
            prop_assert_eq!(m.yield_strength(&StrengthState { damage: 1.0, ..base }), 0.0);
            let (lo, hi) = if d1 <= d2 { (d1, d2) } else { (d2, d1) };
            let y_lo = m.yield_strength(&StrengthState { damage: lo, ..base });
            let y_hi = m.yield_strength(&StrengthState { damage: hi, ..base });
            prop_assert!(y_hi <= y_lo, "{}: Y({hi}) = {y_hi} > Y({lo}) = {y_lo}", m.name());
            prop_assert!((y_lo - yi * (1.0 - lo)).abs() <= 1e-15 * yi);
        }
    }

    /// Eq. (13): Y = Y_d D + Y_i (1 − D), Y_d = min(μ_d P, Y_i) (0 in tension): between
    /// Y_d and Y_i, Y_i at D = 0, Y_d at D = 1, non-increasing in D.
    #[test]
    fn frictional_weakening_eq13(
        p in -2.0e8..2.0e10f64, d1 in 0.0..=1.0f64, d2 in 0.0..=1.0f64,
    ) {
        for (m, mu_d) in frictional_models() {
            let base = state(p, 2876.0, 300.0, 0.0, 0.0, 0.0);
            let yi = m.intact_yield(&base);
            let yd = damaged_strength(mu_d, p, yi);
            prop_assert!(yi >= 0.0 && yd >= 0.0 && yd <= yi);
            if p <= 0.0 {
                prop_assert_eq!(yd, 0.0);
            } else {
                prop_assert_eq!(yd, (mu_d * p).min(yi));
            }
            prop_assert_eq!(m.yield_strength(&base), yi);
            prop_assert_eq!(m.yield_strength(&StrengthState { damage: 1.0, ..base }), yd);
            let (lo, hi) = if d1 <= d2 { (d1, d2) } else { (d2, d1) };
            let y_lo = m.yield_strength(&StrengthState { damage: lo, ..base });
            let y_hi = m.yield_strength(&StrengthState { damage: hi, ..base });
            let tol = 1e-15 * yi;
            prop_assert!(y_lo >= yd - tol && y_lo <= yi + tol);
            prop_assert!(y_hi <= y_lo + tol, "{}: Y({hi}) = {y_hi} > Y({lo}) = {y_lo}", m.name());
            prop_assert!((y_lo - (yd * lo + yi * (1.0 - lo))).abs() <= tol);
        }
    }

    /// Lundborg: continuous, monotone in P, and below Y_M.
    #[test]
    fn lundborg_monotone_and_bounded(p1 in -1.0e8..1.0e11f64, p2 in -1.0e8..1.0e11f64) {
        let m = Lundborg::new(materials::GRANITE_LUNDBORG_COLLINS2004).unwrap();
        let (lo, hi) = if p1 <= p2 { (p1, p2) } else { (p2, p1) };
        let y_lo = m.intact_yield(&state(lo, 2630.0, 300.0, 0.0, 0.0, 0.0));
        let y_hi = m.intact_yield(&state(hi, 2630.0, 300.0, 0.0, 0.0, 0.0));
        prop_assert!(y_lo <= y_hi);
        prop_assert!(y_hi < 1.5e9);
    }
}

#[test]
fn trait_objects_enum_and_concrete_agree() {
    let concrete = Lundborg::new(materials::BASALT_LUNDBORG).unwrap();
    let boxed: Box<dyn StrengthModel> = Box::new(concrete);
    let shared: std::sync::Arc<dyn StrengthModel> = std::sync::Arc::new(concrete);
    let e = BuiltinStrength::from(concrete);
    let s = state(3.0e8, 2900.0, 400.0, 0.1, 10.0, 0.3);
    let y = concrete.yield_strength(&s);
    assert_eq!(boxed.yield_strength(&s), y);
    assert_eq!(shared.yield_strength(&s), y);
    assert_eq!(e.yield_strength(&s), y);
    assert_eq!(e.name(), "lundborg");
    assert_eq!(boxed.evaluate(&s).shear_modulus, 22.7e9);
    assert!(e.has_strength());
    let fluid = BuiltinStrength::from(NoStrength);
    assert!(!fluid.has_strength());
    assert_eq!(fluid.yield_strength(&s), 0.0);
    // A heterogeneous list of models behind the trait.
    let all: Vec<Box<dyn StrengthModel>> = vec![Box::new(NoStrength), boxed, Box::new(e)];
    assert_eq!(all.iter().filter(|m| m.has_strength()).count(), 2);
}

#[test]
fn serde_round_trip_and_validation() {
    let e = BuiltinStrength::from(Lundborg::new(materials::BASALT_LUNDBORG).unwrap());
    let json = serde_json::to_string(&e).unwrap();
    assert!(json.contains("\"model\":\"lundborg\""), "{json}");
    assert!(json.contains("\"tension\":\"linear-to-zero\""), "{json}");
    let back: BuiltinStrength = serde_json::from_str(&json).unwrap();
    assert_eq!(back, e);

    for m in [
        BuiltinStrength::None,
        VonMises::new(materials::TAYLOR_BAR_COPPER).unwrap().into(),
        granite_dp().into(),
        JohnsonCook::new(materials::ALUMINIUM_2024_JC_EARLIER)
            .unwrap()
            .into(),
        SteinbergGuinan::new(materials::ALUMINIUM_2024_SG)
            .unwrap()
            .into(),
    ] {
        let json = serde_json::to_string(&m).unwrap();
        let back: BuiltinStrength = serde_json::from_str(&json).unwrap();
        assert_eq!(back, m, "{json}");
    }

    // The reference strain rate defaults to 1 /s; a bad field is named in the error.
    let jc = r#"{"model":"johnson-cook","a":2.65e8,"b":4.26e8,"n":0.34,"c":0.015,"m":1.0,
        "melt_temperature":935.0,"reference_temperature":300.0,"shear_modulus":26.5e9}"#;
    let m: BuiltinStrength = serde_json::from_str(jc).unwrap();
    match m {
        BuiltinStrength::JohnsonCook(j) => assert_eq!(j.params().reference_strain_rate, 1.0),
        other => panic!("wrong variant {other:?}"),
    }
    let bad = r#"{"model":"lundborg","cohesion":9e7,"friction":2.0,"limit_strength":5e7,
        "damaged_friction":0.8,"shear_modulus":2.7e10}"#;
    let err = serde_json::from_str::<BuiltinStrength>(bad).unwrap_err();
    assert!(err.to_string().contains("limit_strength"), "{err}");
}

#[test]
fn state_validation_names_the_field() {
    let ok = state(1.0e8, 2700.0, 300.0, 0.0, 0.0, 0.5);
    assert_eq!(ok.validate(), Ok(()));
    let cases = [
        (StrengthState { damage: 1.5, ..ok }, "damage"),
        (StrengthState { density: 0.0, ..ok }, "density"),
        (
            StrengthState {
                pressure: f64::NAN,
                ..ok
            },
            "pressure",
        ),
        (
            StrengthState {
                temperature: -1.0,
                ..ok
            },
            "temperature",
        ),
        (
            StrengthState {
                plastic_strain: -0.1,
                ..ok
            },
            "plastic_strain",
        ),
        (
            StrengthState {
                plastic_strain_rate: f64::INFINITY,
                ..ok
            },
            "plastic_strain_rate",
        ),
        (
            StrengthState {
                melt_fraction: f64::NAN,
                ..ok
            },
            "melt_fraction",
        ),
    ];
    for (s, field) in cases {
        match s.validate() {
            Err(StrengthError::State { field: f, .. }) => assert_eq!(f, field),
            other => panic!("{field}: {other:?}"),
        }
    }
    let msg = StrengthState { damage: 1.5, ..ok }
        .validate()
        .unwrap_err()
        .to_string();
    assert_eq!(
        msg,
        "strength state: `damage` = 1.5 is invalid (must lie in [0, 1])"
    );
}
