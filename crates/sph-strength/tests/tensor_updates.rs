//! Jaumann rate and radial return: rigid rotation, simple shear (Dienes 1979), frame
//! indifference, return onto the yield surface.

use proptest::prelude::*;
use sph_core::glam::{DMat3, DVec3};
use sph_strength::{deviator, equivalent_stress, j2, jaumann_rate, radial_return};

/// Skew matrix K with K v = a × v.
fn skew(a: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, a.z, -a.y),
        DVec3::new(-a.z, 0.0, a.x),
        DVec3::new(a.y, -a.x, 0.0),
    )
}

/// Rodrigues: rotation by `angle` about the unit vector `axis`.
fn rotation(axis: DVec3, angle: f64) -> DMat3 {
    let k = skew(axis.normalize());
    DMat3::IDENTITY + k * angle.sin() + k * k * (1.0 - angle.cos())
}

fn sym(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(a, d, e),
        DVec3::new(d, b, f),
        DVec3::new(e, f, c),
    )
}

fn max_abs(m: &DMat3) -> f64 {
    m.to_cols_array().iter().fold(0.0, |a, x| a.max(x.abs()))
}

/// Classical RK4 for dS/dt = jaumann_rate(S, L, G) with constant L.
fn integrate(s0: DMat3, l: &DMat3, g: f64, t_end: f64, steps: usize) -> DMat3 {
    let dt = t_end / steps as f64;
    let f = |s: &DMat3| jaumann_rate(s, l, g);
    let mut s = s0;
    for _ in 0..steps {
        let k1 = f(&s);
        let k2 = f(&(s + k1 * (0.5 * dt)));
        let k3 = f(&(s + k2 * (0.5 * dt)));
        let k4 = f(&(s + k3 * dt));
        s += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (dt / 6.0);
    }
    s
}

/// A rigid rotation v = ω a × x (L = Ω = ω K): the stress must turn with the body,
/// S(t) = R S0 Rᵀ with R = exp(ω t K); its invariants stay fixed.
#[test]
fn rigid_rotation_rotates_stress_with_body() {
    let axis = DVec3::new(0.3, -0.5, 0.8).normalize();
    let omega = 2.0e4; // rad/s
    let t_end = 1.5e-4; // 3 rad
    let l = skew(axis) * omega;
    let s0 = deviator(&sym(3.0e8, -1.0e8, 0.5e8, 1.2e8, -0.7e8, 0.4e8));
    let s = integrate(s0, &l, 26.0e9, t_end, 2000);
    let r = rotation(axis, omega * t_end);
    let expect = r * s0 * r.transpose();
    let err = max_abs(&(s - expect)) / max_abs(&s0);
    assert!(err < 1e-10, "|S − R S0 Rᵀ|/|S0| = {err}");
    // The opposite sign convention would give Rᵀ S0 R, far from the result.
    let wrong = r.transpose() * s0 * r;
    assert!(max_abs(&(s - wrong)) / max_abs(&s0) > 0.1);
    // Invariants: trace, J2 and det.
    let tr = s.x_axis.x + s.y_axis.y + s.z_axis.z;
    assert!(tr.abs() < 1e-10 * max_abs(&s0));
    assert!((j2(&s) - j2(&s0)).abs() < 1e-10 * j2(&s0));
    assert!((s.determinant() - s0.determinant()).abs() < 1e-9 * s0.determinant().abs());
}

/// Simple shear v_x = γ̇ y from rest with the Jaumann rate has the closed form
/// (Dienes 1979, Acta Mech. 32:217): S_xy = G sin γ, S_xx = −S_yy = G (1 − cos γ),
/// γ = γ̇ t — the well-known oscillation of hypoelasticity with the Jaumann rate.
#[test]
fn simple_shear_matches_dienes() {
    let g = 26.0e9;
    let gamma_dot = 1.0e3;
    let l = DMat3::from_cols(DVec3::ZERO, DVec3::new(gamma_dot, 0.0, 0.0), DVec3::ZERO);
    for gamma in [0.1, 1.0, std::f64::consts::PI, 2.0 * std::f64::consts::PI] {
        let s = integrate(DMat3::ZERO, &l, g, gamma / gamma_dot, 4000);
        let xy = s.col(1)[0];
        let xx = s.x_axis.x;
        let yy = s.y_axis.y;
        assert!(
            (xy - g * gamma.sin()).abs() < 1e-10 * g,
            "γ = {gamma}: S_xy {xy}"
        );
        assert!(
            (xx - g * (1.0 - gamma.cos())).abs() < 1e-10 * g,
            "S_xx {xx}"
        );
        assert!(
            (yy + g * (1.0 - gamma.cos())).abs() < 1e-10 * g,
            "S_yy {yy}"
        );
        assert!(s.z_axis.z.abs() < 1e-10 * g);
        assert_eq!(s.col(1)[0], s.col(0)[1]);
    }
}

fn arb_sym(scale: f64) -> impl Strategy<Value = DMat3> {
    prop::array::uniform6(-scale..scale).prop_map(|a| sym(a[0], a[1], a[2], a[3], a[4], a[5]))
}

fn arb_mat(scale: f64) -> impl Strategy<Value = DMat3> {
    prop::array::uniform9(-scale..scale).prop_map(|a| DMat3::from_cols_array(&a))
}

fn arb_rotation() -> impl Strategy<Value = DMat3> {
    (
        prop::array::uniform3(-1.0..1.0f64),
        0.0..std::f64::consts::TAU,
    )
        .prop_filter_map("axis too short", |(a, th)| {
            let v = DVec3::from_array(a);
            (v.length() > 0.1).then(|| rotation(v, th))
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// Objectivity: in a frame x' = Q(t) x turning with spin W (Q̇ = W Q), S' = Q S Qᵀ and
    /// L' = Q L Qᵀ + W. The Jaumann rate must give the time derivative of S' seen in
    /// that frame: dS'/dt = Q (dS/dt) Qᵀ + W S' − S' W.
    #[test]
    fn frame_indifference(
        s in arb_sym(1.0e9), l in arb_mat(1.0e4), q in arb_rotation(),
        w in prop::array::uniform3(-1.0e4..1.0e4f64), g in 1.0e9..1.0e11f64,
    ) {
        let s = deviator(&s);
        let w = skew(DVec3::from_array(w));
        let sp = q * s * q.transpose();
        let lp = q * l * q.transpose() + w;
        let lhs = jaumann_rate(&sp, &lp, g);
        let rhs = q * jaumann_rate(&s, &l, g) * q.transpose() + w * sp - sp * w;
        let scale = 2.0 * g * 1.0e4 + 4.0 * 1.0e9 * 2.0e4;
        prop_assert!(max_abs(&(lhs - rhs)) < 1e-12 * scale);
        // Constant frame (W = 0): plain tensor transformation.
        let lhs0 = jaumann_rate(&sp, &(q * l * q.transpose()), g);
        let rhs0 = q * jaumann_rate(&s, &l, g) * q.transpose();
        prop_assert!(max_abs(&(lhs0 - rhs0)) < 1e-12 * scale);
    }

    /// The rate is symmetric and traceless for a symmetric deviatoric S.
    #[test]
    fn rate_is_symmetric_deviatoric(s in arb_sym(1.0e9), l in arb_mat(1.0e4)) {
        let s = deviator(&s);
        let r = jaumann_rate(&s, &l, 3.0e10);
        let scale = 1.0e15;
        prop_assert!(max_abs(&(r - r.transpose())) < 1e-14 * scale);
        prop_assert!((r.x_axis.x + r.y_axis.y + r.z_axis.z).abs() < 1e-14 * scale);
    }

    /// Radial return: on the surface to 1e-12 when yielding, untouched when elastic,
    /// direction kept, Δε_p = (σ_eq − Y)/(3G).
    #[test]
    fn radial_return_lands_on_surface(
        a in prop::array::uniform6(-1.0..1.0f64), exp in -3.0..10.0f64,
        y_frac in 0.0..2.0f64, g in 1.0e9..1.0e11f64,
    ) {
        let mag = 10f64.powf(exp);
        let s = deviator(&sym(a[0], a[1], a[2], a[3], a[4], a[5])) * mag;
        let sigma = equivalent_stress(&s);
        prop_assume!(sigma > 0.0);
        let y = y_frac * sigma;
        let r = radial_return(s, y);
        if sigma > y {
            prop_assert!(r.yielded());
            if y > 0.0 {
                let back = equivalent_stress(&r.stress);
                prop_assert!((back - y).abs() <= 1e-12 * y, "√3J2 = {back}, Y = {y}");
            } else {
                prop_assert_eq!(r.stress, DMat3::ZERO);
            }
            // Same direction: the result is exactly the positive multiple `scale` of S.
            prop_assert!(r.scale >= 0.0 && r.scale < 1.0);
            prop_assert_eq!(r.stress, s * r.scale);
            let dep = r.plastic_strain_increment(g).unwrap();
            prop_assert!((dep - (sigma - y) / (3.0 * g)).abs() <= 1e-15 * sigma / g);
        } else {
            prop_assert!(!r.yielded());
            prop_assert_eq!(r.stress, s);
            prop_assert_eq!(r.scale, 1.0);
            prop_assert_eq!(r.plastic_strain_increment(g), Some(0.0));
        }
    }
}
