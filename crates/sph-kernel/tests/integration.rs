//! sph-kernel integration tests: normalisation, gradients, ASPH form.

use approx::assert_relative_eq;
use proptest::prelude::*;
use sph_core::Vector;
use sph_core::glam::{DMat2, DMat3, DVec2, DVec3};
use sph_kernel::{CubicSpline, Kernel, KernelChoice, WendlandC2, WendlandC4, WendlandC6};
use std::f64::consts::PI;

/// 20-point Gauss–Legendre nodes/weights on [0, 1], composite over `panels` panels:
/// exact for the piecewise polynomials here up to round-off.
fn gauss_radial(k: &impl Kernel, dim: usize, panels: usize) -> f64 {
    // Nodes and weights of 5-point Gauss–Legendre on [-1, 1].
    let x = [
        0.0,
        -0.538_469_310_105_683_1,
        0.538_469_310_105_683_1,
        -0.906_179_845_938_664,
        0.906_179_845_938_664,
    ];
    let w = [
        0.568_888_888_888_888_9,
        0.478_628_670_499_366_5,
        0.478_628_670_499_366_5,
        0.236_926_885_056_189_1,
        0.236_926_885_056_189_1,
    ];
    let surface = [2.0, 2.0 * PI, 4.0 * PI][dim - 1];
    let mut s = 0.0;
    for p in 0..panels {
        let (a, b) = (p as f64 / panels as f64, (p + 1) as f64 / panels as f64);
        for (xi, wi) in x.iter().zip(&w) {
            let q = 0.5 * (a + b) + 0.5 * (b - a) * xi;
            s += 0.5 * (b - a) * wi * surface * q.powi(dim as i32 - 1) * k.w_radial(dim, q, 1.0);
        }
    }
    s
}

#[test]
fn radial_normalisation_is_one_in_every_dimension() {
    for k in KernelChoice::ALL {
        for dim in 1..=3 {
            // 20 panels put a panel edge at q = 1/2, the cubic spline's knot.
            let i = gauss_radial(&k, dim, 20);
            println!("{:>13} {dim}-D: ∫W dV − 1 = {:+.2e}", k.name(), i - 1.0);
            assert!((i - 1.0).abs() < 1e-12, "{} {dim}-D: {i}", k.name());
        }
    }
}

/// Midpoint rule on a Cartesian grid over [−h, h]^d, through the vector API.
fn cartesian<V: Vector>(k: &impl Kernel, h: f64, n: usize, hten: Option<&dyn Fn(V) -> f64>) -> f64 {
    let dx = 2.0 * h / n as f64;
    let mut s = 0.0;
    let total = n.pow(V::DIM as u32);
    for idx in 0..total {
        let mut rem = idx;
        let r = V::from_fn(|_| {
            let c = rem % n;
            rem /= n;
            -h + (c as f64 + 0.5) * dx
        });
        s += match hten {
            Some(f) => f(r),
            None => k.w(r, h),
        };
    }
    s * dx.powi(V::DIM as i32)
}

#[test]
fn cartesian_normalisation_is_one_to_1e6() {
    for k in KernelChoice::ALL {
        let e1 = cartesian::<f64>(&k, 0.7, 20_000, None) - 1.0;
        let e2 = cartesian::<DVec2>(&k, 0.7, 1_000, None) - 1.0;
        let e3 = cartesian::<DVec3>(&k, 0.7, 160, None) - 1.0;
        println!(
            "{:>13}: ∫W dV − 1 = {e1:+.2e} (1-D), {e2:+.2e} (2-D), {e3:+.2e} (3-D)",
            k.name()
        );
        for (d, e) in [(1, e1), (2, e2), (3, e3)] {
            assert!(e.abs() < 1e-6, "{} {d}-D: {e:e}", k.name());
        }
    }
}

#[test]
fn asph_tensor_kernel_integrates_to_one() {
    // An anisotropic, rotated H: the ellipse/ellipsoid support still carries unit mass.
    let k = WendlandC2;
    let rot2 = DMat2::from_angle(0.3);
    let h2 = rot2 * DMat2::from_diagonal(DVec2::new(1.0 / 0.5, 1.0 / 0.2)) * rot2.transpose();
    let f2 = |r: DVec2| k.w_tensor(r, &h2);
    let i2 = cartesian::<DVec2>(&k, 0.5, 1_000, Some(&f2));
    let rot3 = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7);
    let h3 =
        rot3 * DMat3::from_diagonal(DVec3::new(1.0 / 0.5, 1.0 / 0.3, 1.0 / 0.2)) * rot3.transpose();
    let f3 = |r: DVec3| k.w_tensor(r, &h3);
    let i3 = cartesian::<DVec3>(&k, 0.5, 200, Some(&f3));
    println!(
        "ASPH Wendland C2: ∫W dV − 1 = {:+.2e} (2-D), {:+.2e} (3-D)",
        i2 - 1.0,
        i3 - 1.0
    );
    assert!((i2 - 1.0).abs() < 1e-6);
    assert!((i3 - 1.0).abs() < 1e-5);
}

#[test]
fn point_values_of_wendland_c2() {
    // Paper §2.4: W = 21/(2π h³) (1−R)⁴(4R+1). At R = 1/2, h = 1: 21/(2π)·(1/16)·3.
    let w = WendlandC2.w_radial(3, 0.5, 1.0);
    assert_relative_eq!(w, 21.0 / (2.0 * PI) * 3.0 / 16.0, max_relative = 1e-15);
    assert_relative_eq!(
        WendlandC2.w_radial(2, 0.0, 2.0),
        7.0 / (PI * 4.0),
        max_relative = 1e-15
    );
    assert_eq!(WendlandC2.w_radial(3, 1.0, 1.0), 0.0);
    assert_eq!(WendlandC2.w_radial(3, 1.5, 1.0), 0.0);
    // Cubic spline continuity at the knot q = 1/2: 1 − 6/4 + 6/8 = 2·(1/8).
    assert_relative_eq!(
        CubicSpline.f(0.5 - 1e-14),
        CubicSpline.f(0.5),
        max_relative = 1e-12
    );
}

#[test]
#[should_panic(expected = "1, 2 or 3 dimensions")]
fn four_dimensions_panic_with_a_message() {
    let _ = WendlandC2.sigma(4);
}

fn fd_df(k: &impl Kernel, q: f64) -> f64 {
    let e = 1e-6;
    (k.f(q + e) - k.f(q - e)) / (2.0 * e)
}

proptest! {
    #[test]
    fn df_matches_finite_difference(q in 0.001f64..0.999) {
        for k in KernelChoice::ALL {
            let err = (k.df(q) - fd_df(&k, q)).abs();
            prop_assert!(err < 1e-7, "{} q={q}: {} vs {}", k.name(), k.df(q), fd_df(&k, q));
        }
    }

    #[test]
    fn gradient_3d_matches_finite_difference(
        x in -1.0f64..1.0, y in -1.0f64..1.0, z in -1.0f64..1.0, h in 0.5f64..2.0
    ) {
        let r = DVec3::new(x, y, z);
        for k in KernelChoice::ALL {
            let g = k.grad_w(r, h);
            let e = 1e-6;
            for a in 0..3 {
                let d = DVec3::unit(a) * e;
                let fd = (k.w(r + d, h) - k.w(r - d, h)) / (2.0 * e);
                prop_assert!((g[a] - fd).abs() < 1e-6 * (1.0 + fd.abs()), "{} axis {a}", k.name());
            }
        }
    }

    #[test]
    fn gradient_2d_and_1d_match_finite_difference(x in -1.0f64..1.0, y in -1.0f64..1.0) {
        let k = WendlandC2;
        let e = 1e-6;
        let r = DVec2::new(x, y);
        let g = k.grad_w(r, 1.1);
        for a in 0..2 {
            let d = DVec2::unit(a) * e;
            let fd = (k.w(r + d, 1.1) - k.w(r - d, 1.1)) / (2.0 * e);
            prop_assert!((g[a] - fd).abs() < 1e-6);
        }
        let g1 = k.grad_w(x, 1.1);
        let fd1 = (k.w(x + e, 1.1) - k.w(x - e, 1.1)) / (2.0 * e);
        prop_assert!((g1 - fd1).abs() < 1e-6);
    }

    #[test]
    fn asph_with_isotropic_h_equals_scalar_kernel(
        x in -1.0f64..1.0, y in -1.0f64..1.0, z in -1.0f64..1.0, h in 0.5f64..2.0
    ) {
        let r = DVec3::new(x, y, z);
        let hten = DMat3::IDENTITY * (1.0 / h);
        for k in KernelChoice::ALL {
            let (a, b) = (k.w(r, h), k.w_tensor(r, &hten));
            prop_assert!((a - b).abs() <= 1e-12 * (1.0 + a.abs()));
            let (ga, gb) = (k.grad_w(r, h), k.grad_w_tensor(r, &hten));
            prop_assert!((ga - gb).length() <= 1e-12 * (1.0 + ga.length()));
        }
    }

    #[test]
    fn asph_gradient_matches_finite_difference(
        x in -0.5f64..0.5, y in -0.5f64..0.5, z in -0.5f64..0.5,
        a in 1.0f64..4.0, b in 1.0f64..4.0, c in 1.0f64..4.0, angle in 0.0f64..3.0
    ) {
        let rot = DMat3::from_axis_angle(DVec3::new(1.0, -1.0, 2.0).normalize(), angle);
        let hten = rot * DMat3::from_diagonal(DVec3::new(a, b, c)) * rot.transpose();
        let r = DVec3::new(x, y, z);
        let k = WendlandC4;
        let g = k.grad_w_tensor(r, &hten);
        let e = 1e-7;
        for ax in 0..3 {
            let d = DVec3::unit(ax) * e;
            let fd = (k.w_tensor(r + d, &hten) - k.w_tensor(r - d, &hten)) / (2.0 * e);
            prop_assert!((g[ax] - fd).abs() < 1e-5 * (1.0 + fd.abs()), "axis {ax}: {} vs {fd}", g[ax]);
        }
    }

    #[test]
    fn kernels_are_non_negative_and_decreasing(q1 in 0.0f64..1.0, q2 in 0.0f64..1.0) {
        let (lo, hi) = if q1 < q2 { (q1, q2) } else { (q2, q1) };
        for k in [KernelChoice::WendlandC2, KernelChoice::WendlandC4, KernelChoice::WendlandC6, KernelChoice::CubicSpline] {
            prop_assert!(k.f(hi) >= 0.0);
            prop_assert!(k.f(lo) >= k.f(hi));
        }
        let _ = WendlandC6.f(q1);
    }
}

#[test]
fn tensor_determinant_scales_like_h_to_minus_d() {
    let h = 0.37;
    assert_relative_eq!(
        (DMat3::IDENTITY * (1.0 / h)).determinant(),
        h.powi(-3),
        max_relative = 1e-14
    );
}
