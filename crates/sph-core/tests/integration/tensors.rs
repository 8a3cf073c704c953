//! Tensor helpers checked against nalgebra as an independent oracle.

use nalgebra::{Matrix2, Matrix3};
use proptest::prelude::*;
use sph_core::glam::{DMat2, DMat3, DVec2, DVec3};
use sph_core::{Tensor, Vector};

fn sym3(a: [f64; 6]) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(a[0], a[3], a[4]),
        DVec3::new(a[3], a[1], a[5]),
        DVec3::new(a[4], a[5], a[2]),
    )
}

fn to_na3(m: &DMat3) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| m.component(i, j))
}

fn check_eigen3(m: DMat3) -> Result<(), TestCaseError> {
    let e = m.sym_eigen();
    let mut na: Vec<f64> = to_na3(&m)
        .symmetric_eigen()
        .eigenvalues
        .iter()
        .cloned()
        .collect();
    na.sort_by(f64::total_cmp);
    let scale = 1.0 + m.frobenius_norm();
    for k in 0..3 {
        prop_assert!(
            (e.values[k] - na[k]).abs() <= 1e-12 * scale,
            "{:?} vs {:?}",
            e.values,
            na
        );
        // A v = λ v, |v| = 1.
        let v = e.vectors.col(k);
        prop_assert!(((m * v) - v * e.values[k]).length() <= 1e-12 * scale);
        prop_assert!((v.length() - 1.0).abs() < 1e-12);
    }
    // Orthonormal columns.
    let vtv = e.vectors.transpose() * e.vectors;
    prop_assert!(
        (vtv - DMat3::IDENTITY)
            .to_cols_array()
            .iter()
            .all(|x| x.abs() < 1e-12)
    );
    Ok(())
}

proptest! {
    #[test]
    fn eigen3_matches_nalgebra(a in proptest::array::uniform6(-1.0e3f64..1.0e3)) {
        check_eigen3(sym3(a))?;
    }

    #[test]
    fn eigen3_handles_repeated_eigenvalues(l in -10.0f64..10.0, d in -10.0f64..10.0, angle in 0.0f64..6.0) {
        // Two equal eigenvalues, arbitrary rotation.
        let r = DMat3::from_axis_angle(DVec3::new(0.3, -0.5, 0.8).normalize(), angle);
        check_eigen3(r * DMat3::from_diagonal(DVec3::new(l, l, d)) * r.transpose())?;
    }

    #[test]
    fn eigenvalues_alone_are_those_of_the_decomposition_bit_for_bit(
        a in proptest::array::uniform6(-1.0e3f64..1.0e3),
        repeated in -10.0f64..10.0,
        angle in 0.0f64..6.0,
    ) {
        let r = DMat3::from_axis_angle(DVec3::new(0.3, -0.5, 0.8).normalize(), angle);
        let twice = r * DMat3::from_diagonal(DVec3::new(repeated, repeated, a[0])) * r.transpose();
        for m in [sym3(a), twice] {
            prop_assert_eq!(m.sym_eigenvalues().map(f64::to_bits), m.sym_eigen().values.map(f64::to_bits));
        }
        let m2 = DMat2::from_cols(DVec2::new(a[0], a[1]), DVec2::new(a[1], a[2]));
        prop_assert_eq!(m2.sym_eigenvalues().map(f64::to_bits), m2.sym_eigen().values.map(f64::to_bits));
        prop_assert_eq!(Tensor::sym_eigenvalues(&a[3]), Tensor::sym_eigen(&a[3]).values);
    }

    #[test]
    fn eigen2_matches_nalgebra(a in -1.0e3f64..1.0e3, b in -1.0e3f64..1.0e3, d in -1.0e3f64..1.0e3) {
        let m = DMat2::from_cols(DVec2::new(a, b), DVec2::new(b, d));
        let e = m.sym_eigen();
        let mut na: Vec<f64> = Matrix2::new(a, b, b, d).symmetric_eigen().eigenvalues.iter().cloned().collect();
        na.sort_by(f64::total_cmp);
        let scale = 1.0 + m.frobenius_norm();
        for k in 0..2 {
            prop_assert!((e.values[k] - na[k]).abs() <= 1e-12 * scale);
            let v = e.vectors.col(k);
            prop_assert!(((m * v) - v * e.values[k]).length() <= 1e-12 * scale);
        }
    }

    #[test]
    fn invariants_match_nalgebra(a in proptest::array::uniform9(-1.0e2f64..1.0e2), b in proptest::array::uniform9(-1.0e2f64..1.0e2)) {
        let ma = DMat3::from_cols_array(&a);
        let mb = DMat3::from_cols_array(&b);
        let (na, nb) = (to_na3(&ma), to_na3(&mb));
        prop_assert!((ma.trace() - na.trace()).abs() < 1e-12);
        prop_assert!((ma.double_dot(&mb) - na.component_mul(&nb).sum()).abs() < 1e-9);
        prop_assert!((ma.determinant() - na.determinant()).abs() < 1e-7 * (1.0 + na.determinant().abs()));
        // Deviator is traceless; J2 = ½ s:s equals the nalgebra expression.
        let s = ma.deviator();
        prop_assert!(s.trace().abs() < 1e-11);
        let ns = na - Matrix3::identity() * (na.trace() / 3.0);
        prop_assert!((ma.j2() - 0.5 * ns.component_mul(&ns).sum()).abs() < 1e-9 * (1.0 + ma.j2()));
        // Symmetric + antisymmetric parts reassemble A.
        let back = ma.symmetric() + ma.antisymmetric();
        prop_assert!((back - ma).to_cols_array().iter().all(|x| x.abs() < 1e-12));
        // Outer product and matrix–vector product.
        let u = DVec3::new(a[0], a[1], a[2]);
        let v = DVec3::new(b[0], b[1], b[2]);
        let o = DMat3::outer(u, v);
        let no = nalgebra::Vector3::new(a[0], a[1], a[2]) * nalgebra::Vector3::new(b[0], b[1], b[2]).transpose();
        prop_assert!((to_na3(&o) - no).abs().max() < 1e-9);
        let mv = ma.mul_vec(v);
        let nmv = na * nalgebra::Vector3::new(b[0], b[1], b[2]);
        prop_assert!((mv - DVec3::new(nmv[0], nmv[1], nmv[2])).length() < 1e-9);
        if let Some(inv) = Tensor::inverse(&ma) {
            let id = inv.mul_tensor(&ma);
            let cond = ma.frobenius_norm() * inv.frobenius_norm();
            prop_assert!((id - DMat3::IDENTITY).to_cols_array().iter().all(|x| x.abs() < 1e-12 * cond));
        }
        prop_assert!(u.dot(v) == Vector::dot(u, v));
    }
}
