//! The exact Riemann solver against the [exact] table of docs/verification.md, "1-D Riemann
//! problems".

use approx::assert_relative_eq;
use sph_diagnostics::exact::{GasState, RiemannSolution};

fn st(a: [f64; 3]) -> GasState {
    GasState {
        density: a[0],
        velocity: a[1],
        pressure: a[2],
    }
}

/// (name, left, right, γ, p*, u*, ρ*_L, ρ*_R) from docs/verification.md, "1-D Riemann problems"
/// (5–6 digits).
type Row = (&'static str, [f64; 3], [f64; 3], f64, f64, f64, f64, f64);
const TABLE: [Row; 8] = [
    (
        "Sod",
        [1.0, 0.0, 1.0],
        [0.125, 0.0, 0.1],
        1.4,
        0.30313,
        0.92745,
        0.42632,
        0.26557,
    ),
    (
        "modified Sod",
        [1.0, 0.75, 1.0],
        [0.125, 0.0, 0.1],
        1.4,
        0.46629,
        1.36091,
        0.57987,
        0.33970,
    ),
    (
        "123",
        [1.0, -2.0, 0.4],
        [1.0, 2.0, 0.4],
        1.4,
        0.00189387,
        0.0,
        0.021852,
        0.021852,
    ),
    (
        "Toro 3",
        [1.0, 0.0, 1000.0],
        [1.0, 0.0, 0.01],
        1.4,
        460.894,
        19.5975,
        0.57506,
        5.99924,
    ),
    (
        "Toro 4",
        [1.0, 0.0, 0.01],
        [1.0, 0.0, 100.0],
        1.4,
        46.0950,
        -6.19633,
        5.99242,
        0.57511,
    ),
    (
        "Toro 5",
        [5.99924, 19.5975, 460.894],
        [5.99242, -6.19633, 46.0950],
        1.4,
        1691.65,
        8.68977,
        14.2823,
        31.0426,
    ),
    (
        "Sod γ=5/3",
        [1.0, 0.0, 1.0],
        [0.125, 0.0, 0.1],
        5.0 / 3.0,
        0.293945,
        0.841195,
        0.479689,
        0.229806,
    ),
    (
        "Spheral Sod",
        [1.0, 0.0, 1.0],
        [0.25, 0.0, 0.1795],
        5.0 / 3.0,
        0.421735,
        0.614215,
        0.595695,
        0.409402,
    ),
];

#[test]
fn star_states_match_the_table() {
    for (name, l, r, g, p, u, rl, rr) in TABLE {
        let s = RiemannSolution::solve(st(l), st(r), g).unwrap();
        let tol = 6e-5;
        assert!(
            (s.p_star - p).abs() <= tol * p,
            "{name}: p* {} vs {p}",
            s.p_star
        );
        assert!(
            (s.u_star - u).abs() <= tol * u.abs().max(1.0),
            "{name}: u* {} vs {u}",
            s.u_star
        );
        assert!(
            (s.rho_star_left - rl).abs() <= tol * rl,
            "{name}: ρ*L {} vs {rl}",
            s.rho_star_left
        );
        assert!(
            (s.rho_star_right - rr).abs() <= tol * rr,
            "{name}: ρ*R {} vs {rr}",
            s.rho_star_right
        );
    }
}

#[test]
fn wave_positions_match_the_table() {
    // Sod at t = 0.2, x0 = 0.5: rarefaction head 0.26336, tail 0.48595, contact 0.68549,
    // shock 0.85043; Toro 3 at t = 0.012: shock 0.78221.
    let sod = RiemannSolution::solve(st([1.0, 0.0, 1.0]), st([0.125, 0.0, 0.1]), 1.4).unwrap();
    assert_relative_eq!(
        0.5 + 0.2 * sod.right_shock_speed().unwrap(),
        0.85043,
        max_relative = 1e-5
    );
    assert_relative_eq!(0.5 + 0.2 * sod.u_star, 0.68549, max_relative = 1e-5);
    // Just inside the head: still the left state; just inside the tail: star state.
    let c_l = 1.4f64.sqrt();
    assert_eq!(sod.sample(-c_l - 1e-9).density, 1.0);
    let star = sod.sample((0.48595 - 0.5) / 0.2 + 1e-6);
    assert_relative_eq!(star.density, 0.42632, max_relative = 1e-4);
    let t3 = RiemannSolution::solve(st([1.0, 0.0, 1000.0]), st([1.0, 0.0, 0.01]), 1.4).unwrap();
    assert_relative_eq!(
        0.5 + 0.012 * t3.right_shock_speed().unwrap(),
        0.78221,
        max_relative = 1e-5
    );
    // The fan is continuous at both ends.
    let head = sod.sample(-c_l + 1e-12);
    assert_relative_eq!(head.pressure, 1.0, max_relative = 1e-9);
    let tail_xi = sod.u_star - 1.4f64.sqrt() * (sod.p_star).powf(0.4 / 2.8);
    assert_relative_eq!(
        sod.sample(tail_xi - 1e-12).pressure,
        sod.p_star,
        max_relative = 1e-9
    );
}

#[test]
fn bad_states_are_errors() {
    assert!(RiemannSolution::solve(st([0.0, 0.0, 1.0]), st([1.0, 0.0, 1.0]), 1.4).is_err());
    assert!(RiemannSolution::solve(st([1.0, 0.0, 1.0]), st([1.0, 0.0, 1.0]), 1.0).is_err());
    // Strong expansion: vacuum.
    assert!(RiemannSolution::solve(st([1.0, -20.0, 0.4]), st([1.0, 20.0, 0.4]), 1.4).is_err());
}
