//! Eigen-decomposition of symmetric 2×2 and 3×3 tensors: principal stresses for damage
//! criteria and the principal axes of the ASPH smoothing tensor.
//!
//! 2×2 is closed form. 3×3 uses cyclic Jacobi rotations, which are slower than the
//! trigonometric closed form but accurate to round-off for repeated and nearly repeated
//! eigenvalues, where the closed form loses digits.

/// Eigenvalues (ascending) and eigenvectors (the columns of `vectors`, orthonormal) of a
/// symmetric tensor `T`. For a `DIM`-dimensional tensor only the first `DIM` entries of
/// `values` are meaningful; the rest are zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SymEigen<T> {
    /// Eigenvalues in ascending order.
    pub values: [f64; 3],
    /// Eigenvectors as columns, in the order of `values`.
    pub vectors: T,
}

/// Symmetric 2×2 `[[a, b], [b, d]]`.
pub fn sym_eigen2(a: f64, b: f64, d: f64) -> SymEigen<glam::DMat2> {
    let mean = 0.5 * (a + d);
    let half_diff = 0.5 * (a - d);
    let r = half_diff.hypot(b);
    // Angle of the eigenvector of the larger eigenvalue.
    let theta = 0.5 * (2.0 * b).atan2(a - d);
    let (s, c) = theta.sin_cos();
    let v_max = glam::DVec2::new(c, s);
    let v_min = glam::DVec2::new(-s, c);
    SymEigen {
        values: [mean - r, mean + r, 0.0],
        vectors: glam::DMat2::from_cols(v_min, v_max),
    }
}

/// Symmetric 3×3 given as rows (only the upper triangle is read).
pub fn sym_eigen3(m: [[f64; 3]; 3]) -> SymEigen<glam::DMat3> {
    let (a, v) = jacobi3::<true>(m);
    let order = ascending(&a);
    let col = |k: usize| glam::DVec3::new(v[0][k], v[1][k], v[2][k]);
    SymEigen {
        values: order.map(|k| a[k][k]),
        vectors: glam::DMat3::from_cols(col(order[0]), col(order[1]), col(order[2])),
    }
}

/// The eigenvalues of [`sym_eigen3`] (ascending), without the eigenvectors: the same
/// rotations of the matrix, bit for bit, without accumulating them (a third less work).
/// What a principal-stress criterion needs.
pub fn sym_eigenvalues3(m: [[f64; 3]; 3]) -> [f64; 3] {
    let (a, _) = jacobi3::<false>(m);
    ascending(&a).map(|k| a[k][k])
}

/// The eigenvalues of [`sym_eigen2`] (ascending, the third zero), without its angle.
pub fn sym_eigenvalues2(a: f64, b: f64, d: f64) -> [f64; 3] {
    let mean = 0.5 * (a + d);
    let r = (0.5 * (a - d)).hypot(b);
    [mean - r, mean + r, 0.0]
}

/// The indices of the diagonal of `a` in ascending order.
fn ascending(a: &[[f64; 3]; 3]) -> [usize; 3] {
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| a[i][i].total_cmp(&a[j][j]));
    order
}

/// Cyclic Jacobi rotations of the symmetric `m` until its off-diagonal part is below
/// 1e-17 of its norm: the rotated matrix, whose diagonal holds the eigenvalues, and, with
/// `VECTORS`, the accumulated rotation (the eigenvectors as columns; the identity
/// otherwise). The matrix's rotations do not depend on `VECTORS`.
fn jacobi3<const VECTORS: bool>(m: [[f64; 3]; 3]) -> ([[f64; 3]; 3], [[f64; 3]; 3]) {
    let mut a = [
        [m[0][0], m[0][1], m[0][2]],
        [m[0][1], m[1][1], m[1][2]],
        [m[0][2], m[1][2], m[2][2]],
    ];
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let scale: f64 = a.iter().flatten().map(|x| x * x).sum::<f64>().sqrt();
    if scale > 0.0 && scale.is_finite() {
        for _sweep in 0..64 {
            let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
            if off.sqrt() <= 1e-17 * scale {
                break;
            }
            for (p, q) in [(0usize, 1usize), (0, 2), (1, 2)] {
                let apq = a[p][q];
                if apq == 0.0 {
                    continue;
                }
                // Rotation that annihilates a[p][q] (Golub & Van Loan, Alg. 8.4.1).
                let tau = (a[q][q] - a[p][p]) / (2.0 * apq);
                let t = tau.signum() / (tau.abs() + (1.0 + tau * tau).sqrt());
                let t = if tau == 0.0 { 1.0 } else { t };
                let c = 1.0 / (1.0 + t * t).sqrt();
                let s = t * c;
                for k in 0..3 {
                    let akp = a[k][p];
                    let akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for k in 0..3 {
                    let apk = a[p][k];
                    let aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                if VECTORS {
                    for row in v.iter_mut() {
                        let vkp = row[p];
                        let vkq = row[q];
                        row[p] = c * vkp - s * vkq;
                        row[q] = s * vkp + c * vkq;
                    }
                }
            }
        }
    }
    (a, v)
}
