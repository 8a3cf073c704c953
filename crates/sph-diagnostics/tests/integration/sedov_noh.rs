//! Sedov and Noh exact solutions against docs/verification.md, "Noh" and "Sedov–Taylor".

use approx::assert_relative_eq;
use sph_diagnostics::exact::{Noh, Sedov};

#[test]
fn sedov_xi0_matches_the_table() {
    // (γ, ν, α, ξ0) — docs/verification.md, "Sedov–Taylor" [exact].
    let table = [
        (1.4, 1, 1.07749, 0.97543),
        (1.4, 2, 0.98407, 1.00402),
        (1.4, 3, 0.85108, 1.03278),
        (5.0 / 3.0, 1, 0.60294, 1.18370),
        (5.0 / 3.0, 2, 0.56428, 1.15379),
        (5.0 / 3.0, 3, 0.49359, 1.15167),
    ];
    for (g, nu, alpha, xi0) in table {
        let s = Sedov::new(nu, g, 1.0, 1.0).unwrap();
        println!(
            "γ={g:.4} ν={nu}: α = {:.6} (table {alpha}), ξ0 = {:.6} (table {xi0})",
            s.alpha(),
            s.xi0()
        );
        assert_relative_eq!(s.alpha(), alpha, max_relative = 2e-5);
        assert_relative_eq!(s.xi0(), xi0, max_relative = 2e-5);
        assert_relative_eq!(s.shock_radius(1.0), xi0, max_relative = 2e-5);
    }
}

#[test]
fn sedov_interior_matches_the_spot_values() {
    // ξ, then (v/v2, ρ/ρ2, P/P2) for γ=5/3 3-D, γ=5/3 2-D, γ=1.4 3-D, γ=1.4 2-D.
    let rows: [(f64, [[f64; 3]; 4]); 6] = [
        (
            0.1,
            [
                [0.0800, 0.0000, 0.3062],
                [0.0800, 0.0004, 0.3215],
                [0.0859, 0.0000, 0.3655],
                [0.0857, 0.0000, 0.3729],
            ],
        ),
        (
            0.5,
            [
                [0.4013, 0.0153, 0.3098],
                [0.4037, 0.0474, 0.3321],
                [0.4287, 0.0017, 0.3659],
                [0.4292, 0.0103, 0.3753],
            ],
        ),
        (
            0.8,
            [
                [0.6828, 0.1578, 0.3962],
                [0.7003, 0.2567, 0.4593],
                [0.7004, 0.0655, 0.4045],
                [0.7120, 0.1311, 0.4472],
            ],
        ),
        (
            0.9,
            [
                [0.8203, 0.3563, 0.5447],
                [0.8368, 0.4762, 0.6219],
                [0.8218, 0.2054, 0.5077],
                [0.8376, 0.3140, 0.5767],
            ],
        ),
        (
            0.95,
            [
                [0.9048, 0.5747, 0.7055],
                [0.9153, 0.6768, 0.7697],
                [0.9016, 0.4106, 0.6510],
                [0.9135, 0.5304, 0.7214],
            ],
        ),
        (
            0.99,
            [
                [0.9802, 0.8887, 0.9251],
                [0.9826, 0.9217, 0.9451],
                [0.9787, 0.8178, 0.8997],
                [0.9819, 0.8708, 0.9273],
            ],
        ),
    ];
    let cases = [(5.0 / 3.0, 3), (5.0 / 3.0, 2), (1.4, 3), (1.4, 2)];
    for (xi, values) in rows {
        for (k, (g, nu)) in cases.into_iter().enumerate() {
            let (f, gg, h) = Sedov::new(nu, g, 1.0, 1.0).unwrap().relative_profile(xi);
            if (g, nu, xi) == (1.4, 3, 0.1) {
                // verification.md lists v/v2 = 0.0859 here, but near the centre
                // v/v2 → (γ+1)/(2γ)·ξ = 0.085714 and v/(v2 ξ) rises monotonically to
                // 0.85735 at ξ = 0.5 (itself matching the table's 0.4287), so 0.0859 is
                // inconsistent with the rest of its own column; we check the limit.
                assert!((f - 0.857_142_857 * xi).abs() < 3e-5, "central limit: {f}");
                assert!((gg - values[k][1]).abs() <= 6e-5 && (h - values[k][2]).abs() <= 6e-5);
                continue;
            }
            for (got, want) in [f, gg, h].into_iter().zip(values[k]) {
                // The table has four decimals.
                assert!(
                    (got - want).abs() <= 6e-5,
                    "γ={g} ν={nu} ξ={xi}: {got:.5} vs {want}"
                );
            }
        }
    }
    // Central pressure plateau P(0)/P2: 0.306 (γ = 5/3) and 0.365 (γ = 1.4), 3-D.
    assert!(
        (Sedov::new(3, 5.0 / 3.0, 1.0, 1.0)
            .unwrap()
            .relative_profile(0.0)
            .2
            - 0.306)
            .abs()
            < 1e-3
    );
    assert!(
        (Sedov::new(3, 1.4, 1.0, 1.0)
            .unwrap()
            .relative_profile(0.0)
            .2
            - 0.365)
            .abs()
            < 1e-3
    );
    // Deep inside, v = 2r/((ν+2)γt): v/v2 = (γ+1)/(2γ)·ξ even where V is at round-off
    // distance from V0.
    let f = Sedov::new(3, 1.4, 1.0, 1.0)
        .unwrap()
        .relative_profile(0.02)
        .0;
    assert!((f - 0.02 * 2.4 / 2.8).abs() < 1e-8, "{f}");
}

#[test]
fn sedov_state_carries_the_blast_energy() {
    // ∫ (ρ v²/2 + P/(γ−1)) dV over the sphere must return E (here 2.5 at t = 0.7).
    let s = Sedov::new(3, 5.0 / 3.0, 2.5, 1.3).unwrap();
    let t = 0.7;
    let r_s = s.shock_radius(t);
    let n = 20_000;
    let mut e = 0.0;
    for k in 0..n {
        let r = (k as f64 + 0.5) / n as f64 * r_s;
        let st = s.state(r, t);
        e += (0.5 * st.density * st.velocity * st.velocity + st.pressure / (2.0 / 3.0))
            * 4.0
            * std::f64::consts::PI
            * r
            * r
            * r_s
            / n as f64;
    }
    assert_relative_eq!(e, 2.5, max_relative = 1e-4);
}

#[test]
fn noh_reference_values() {
    // γ = 5/3, t = 0.6: shock at 0.2; ρ2 = 4, 16, 64; P2 = 4/3, 16/3, 64/3.
    for (d, rho2) in [(1, 4.0), (2, 16.0), (3, 64.0)] {
        let noh = Noh::new(d, 5.0 / 3.0, 1.0, 1.0).unwrap();
        assert_relative_eq!(noh.shock_radius(0.6), 0.2, max_relative = 1e-14);
        let inside = noh.state(0.1, 0.6);
        assert_relative_eq!(inside.density, rho2, max_relative = 1e-14);
        assert_relative_eq!(inside.pressure, rho2 / 3.0, max_relative = 1e-14);
        // Just outside the shock the pre-shock compression is 4^(d−1), so the jump is 4.
        let outside = noh.state(0.2 + 1e-12, 0.6);
        assert_relative_eq!(
            outside.density,
            4f64.powi(d as i32 - 1),
            max_relative = 1e-9
        );
    }
    // γ = 1.4: r_s = 0.12 at t = 0.6, ρ2 = 6, 36, 216.
    let noh = Noh::new(3, 1.4, 1.0, 1.0).unwrap();
    assert_relative_eq!(noh.shock_radius(0.6), 0.12, max_relative = 1e-14);
    assert_relative_eq!(noh.post_shock_density(), 216.0, max_relative = 1e-12);
    assert!(Noh::new(4, 1.4, 1.0, 1.0).is_err());
    assert!(Sedov::new(3, 2.5, 1.0, 1.0).is_err());
}
