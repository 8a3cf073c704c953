//! The [`Tensor`] trait: second-rank tensors in `DIM` dimensions (velocity gradients,
//! stresses, the ASPH smoothing tensor H), implemented for `f64` (1-D),
//! [`glam::DMat2`] and [`glam::DMat3`].
//!
//! Conventions: `component(i, j)` is row `i`, column `j`; glam stores columns, so
//! `DMat3::col(j)[i]` is the same entry. The deviator here is the `DIM`-dimensional one,
//! `A − (tr A / DIM) I`. Stress in reduced dimensions (plane strain, RZ) needs the
//! out-of-plane normal component as well; the solid-dynamics stress type carries it.

use crate::eigen::{SymEigen, sym_eigen2, sym_eigen3, sym_eigenvalues2, sym_eigenvalues3};
use crate::vector::Vector;
use glam::{DMat2, DMat3, DVec2, DVec3};
use std::fmt::Debug;
use std::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A `DIM`×`DIM` f64 tensor.
pub trait Tensor:
    Copy
    + Clone
    + Send
    + Sync
    + Debug
    + Default
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<f64, Output = Self>
    + AddAssign
    + SubAssign
    + 'static
{
    /// The vector type this tensor acts on.
    type Vector: Vector;
    /// The zero tensor.
    const ZERO: Self;
    /// The identity tensor δ.
    const IDENTITY: Self;

    /// Entry in row `i`, column `j`.
    fn component(&self, i: usize, j: usize) -> f64;
    /// Builds a tensor from a function of (row, column).
    fn from_fn(f: impl FnMut(usize, usize) -> f64) -> Self;
    /// Matrix–vector product `A·v`.
    fn mul_vec(&self, v: Self::Vector) -> Self::Vector;
    /// Matrix product `A·B`.
    fn mul_tensor(&self, other: &Self) -> Self;
    /// Transpose `Aᵀ`.
    fn transpose(&self) -> Self;
    /// Determinant.
    fn determinant(&self) -> f64;
    /// Inverse, or `None` when the determinant is zero or not finite.
    fn inverse(&self) -> Option<Self>;
    /// Eigen-decomposition of the symmetric part (the tensor is assumed symmetric;
    /// only the upper triangle is read). Eigenvalues ascending.
    fn sym_eigen(&self) -> SymEigen<Self>;
    /// The eigenvalues of [`Self::sym_eigen`], bit for bit, without the eigenvectors
    /// (less work: no accumulated rotations in 3-D, no angle in 2-D).
    fn sym_eigenvalues(&self) -> [f64; 3];
    /// Gershgorin's discs of the symmetric part: (min_i (a_ii − R_i), max_i (a_ii + R_i),
    /// max_i (|a_ii| + R_i)) with R_i = Σ_{j≠i} max(|a_ij|, |a_ji|), so every eigenvalue
    /// of [`Self::sym_eigen`] lies in [first, second] up to rounding (either triangle may
    /// be the one read); the third is a scale for such rounding margins. None when an
    /// entry is not finite. Costs no square root: a test that these bounds decide skips
    /// the eigenvalue problem.
    fn gershgorin(&self) -> Option<(f64, f64, f64)> {
        let n = Self::Vector::DIM;
        let (mut lower, mut upper, mut size) = (f64::INFINITY, f64::NEG_INFINITY, 0.0_f64);
        for i in 0..n {
            let mut radius = 0.0;
            for j in (0..n).filter(|&j| j != i) {
                let (a, b) = (self.component(i, j), self.component(j, i));
                if !(a.is_finite() && b.is_finite()) {
                    return None;
                }
                radius += a.abs().max(b.abs());
            }
            let d = self.component(i, i);
            if !d.is_finite() {
                return None;
            }
            lower = lower.min(d - radius);
            upper = upper.max(d + radius);
            size = size.max(d.abs() + radius);
        }
        Some((lower, upper, size))
    }

    /// Outer product `a ⊗ b`, entry (i, j) = a_i b_j.
    #[inline]
    fn outer(a: Self::Vector, b: Self::Vector) -> Self {
        Self::from_fn(|i, j| a.component(i) * b.component(j))
    }
    /// Trace `A_ii`.
    #[inline]
    fn trace(&self) -> f64 {
        (0..Self::Vector::DIM).map(|i| self.component(i, i)).sum()
    }
    /// Double contraction `A : B = A_ij B_ij`.
    #[inline]
    fn double_dot(&self, other: &Self) -> f64 {
        let n = Self::Vector::DIM;
        let mut s = 0.0;
        for i in 0..n {
            for j in 0..n {
                s += self.component(i, j) * other.component(i, j);
            }
        }
        s
    }
    /// Symmetric part `(A + Aᵀ)/2`.
    #[inline]
    fn symmetric(&self) -> Self {
        (*self + self.transpose()) * 0.5
    }
    /// Antisymmetric part `(A − Aᵀ)/2`.
    #[inline]
    fn antisymmetric(&self) -> Self {
        (*self - self.transpose()) * 0.5
    }
    /// Deviator `A − (tr A / DIM) I`.
    #[inline]
    fn deviator(&self) -> Self {
        *self - Self::IDENTITY * (self.trace() / Self::Vector::DIM as f64)
    }
    /// Second invariant of the deviator, `J2 = ½ s:s` with `s` the deviator of `A`.
    #[inline]
    fn j2(&self) -> f64 {
        let s = self.deviator();
        0.5 * s.double_dot(&s)
    }
    /// Frobenius norm `sqrt(A:A)`.
    #[inline]
    fn frobenius_norm(&self) -> f64 {
        self.double_dot(self).sqrt()
    }
    /// True when every entry is finite.
    #[inline]
    fn all_finite(&self) -> bool {
        let n = Self::Vector::DIM;
        (0..n).all(|i| (0..n).all(|j| self.component(i, j).is_finite()))
    }
}

impl Tensor for f64 {
    type Vector = f64;
    const ZERO: Self = 0.0;
    const IDENTITY: Self = 1.0;
    #[inline]
    fn component(&self, i: usize, j: usize) -> f64 {
        assert!(i == 0 && j == 0, "component ({i},{j}) of a 1-D tensor");
        *self
    }
    #[inline]
    fn from_fn(mut f: impl FnMut(usize, usize) -> f64) -> Self {
        f(0, 0)
    }
    #[inline]
    fn mul_vec(&self, v: f64) -> f64 {
        self * v
    }
    #[inline]
    fn mul_tensor(&self, other: &Self) -> Self {
        self * other
    }
    #[inline]
    fn transpose(&self) -> Self {
        *self
    }
    #[inline]
    fn determinant(&self) -> f64 {
        *self
    }
    #[inline]
    fn inverse(&self) -> Option<Self> {
        let inv = 1.0 / self;
        (self.is_finite() && *self != 0.0 && inv.is_finite()).then_some(inv)
    }
    #[inline]
    fn sym_eigen(&self) -> SymEigen<Self> {
        SymEigen {
            values: [*self, 0.0, 0.0],
            vectors: 1.0,
        }
    }
    #[inline]
    fn sym_eigenvalues(&self) -> [f64; 3] {
        [*self, 0.0, 0.0]
    }
}

impl Tensor for DMat2 {
    type Vector = DVec2;
    const ZERO: Self = DMat2::ZERO;
    const IDENTITY: Self = DMat2::IDENTITY;
    #[inline]
    fn component(&self, i: usize, j: usize) -> f64 {
        self.col(j)[i]
    }
    #[inline]
    fn from_fn(mut f: impl FnMut(usize, usize) -> f64) -> Self {
        DMat2::from_cols(DVec2::new(f(0, 0), f(1, 0)), DVec2::new(f(0, 1), f(1, 1)))
    }
    #[inline]
    fn mul_vec(&self, v: DVec2) -> DVec2 {
        *self * v
    }
    #[inline]
    fn mul_tensor(&self, other: &Self) -> Self {
        *self * *other
    }
    #[inline]
    fn transpose(&self) -> Self {
        DMat2::transpose(self)
    }
    #[inline]
    fn determinant(&self) -> f64 {
        DMat2::determinant(self)
    }
    #[inline]
    fn inverse(&self) -> Option<Self> {
        let d = DMat2::determinant(self);
        (d != 0.0 && d.is_finite()).then(|| DMat2::inverse(self))
    }
    #[inline]
    fn sym_eigen(&self) -> SymEigen<Self> {
        sym_eigen2(self.x_axis.x, self.y_axis.x, self.y_axis.y)
    }
    #[inline]
    fn sym_eigenvalues(&self) -> [f64; 3] {
        sym_eigenvalues2(self.x_axis.x, self.y_axis.x, self.y_axis.y)
    }
}

impl Tensor for DMat3 {
    type Vector = DVec3;
    const ZERO: Self = DMat3::ZERO;
    const IDENTITY: Self = DMat3::IDENTITY;
    #[inline]
    fn component(&self, i: usize, j: usize) -> f64 {
        self.col(j)[i]
    }
    #[inline]
    fn from_fn(mut f: impl FnMut(usize, usize) -> f64) -> Self {
        DMat3::from_cols(
            DVec3::new(f(0, 0), f(1, 0), f(2, 0)),
            DVec3::new(f(0, 1), f(1, 1), f(2, 1)),
            DVec3::new(f(0, 2), f(1, 2), f(2, 2)),
        )
    }
    #[inline]
    fn mul_vec(&self, v: DVec3) -> DVec3 {
        *self * v
    }
    #[inline]
    fn mul_tensor(&self, other: &Self) -> Self {
        *self * *other
    }
    #[inline]
    fn transpose(&self) -> Self {
        DMat3::transpose(self)
    }
    #[inline]
    fn determinant(&self) -> f64 {
        DMat3::determinant(self)
    }
    #[inline]
    fn inverse(&self) -> Option<Self> {
        let d = DMat3::determinant(self);
        (d != 0.0 && d.is_finite()).then(|| DMat3::inverse(self))
    }
    #[inline]
    fn sym_eigen(&self) -> SymEigen<Self> {
        sym_eigen3([
            [self.x_axis.x, self.y_axis.x, self.z_axis.x],
            [self.y_axis.x, self.y_axis.y, self.z_axis.y],
            [self.z_axis.x, self.z_axis.y, self.z_axis.z],
        ])
    }
    #[inline]
    fn sym_eigenvalues(&self) -> [f64; 3] {
        sym_eigenvalues3([
            [self.x_axis.x, self.y_axis.x, self.z_axis.x],
            [self.y_axis.x, self.y_axis.y, self.z_axis.y],
            [self.z_axis.x, self.z_axis.y, self.z_axis.z],
        ])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn gershgorin_discs_bound_the_eigenvalues() {
        // [[2, 1], [1, 3]]: discs [1, 3] and [2, 4]; eigenvalues (5 ∓ √5)/2 = 1.38, 3.62.
        let m = DMat2::from_cols_array(&[2.0, 1.0, 1.0, 3.0]);
        assert_eq!(m.gershgorin(), Some((1.0, 4.0, 4.0)));
        let e = m.sym_eigenvalues();
        assert!(e[0] >= 1.0 && e[1] <= 4.0);
        // Triangles that differ: the larger entry counts.
        let skew = DMat3::from_cols_array(&[-5.0, 0.5, 0.0, -2.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
        assert_eq!(skew.gershgorin(), Some((-7.0, 3.0, 7.0)));
        // A non-finite entry: no bounds.
        let mut bad = DMat3::IDENTITY;
        bad.z_axis.x = f64::NAN;
        assert_eq!(bad.gershgorin(), None);
        assert_eq!(2.5f64.gershgorin(), Some((2.5, 2.5, 2.5)));
    }

    #[test]
    fn hand_computed_invariants_3d() {
        // A = [[1,2,3],[2,5,6],[3,6,9]]: tr = 15, deviator diag (-4, 0, 4).
        let a = DMat3::from_fn(|i, j| [[1.0, 2.0, 3.0], [2.0, 5.0, 6.0], [3.0, 6.0, 9.0]][i][j]);
        assert_eq!(a.trace(), 15.0);
        let s = a.deviator();
        assert_eq!(s.component(0, 0), -4.0);
        assert_eq!(s.component(1, 1), 0.0);
        assert_eq!(s.component(2, 2), 4.0);
        // J2 = ½ (16 + 0 + 16 + 2(4 + 9 + 36)) = ½ (32 + 98) = 65
        assert_relative_eq!(a.j2(), 65.0, max_relative = 1e-15);
        assert_eq!(a.double_dot(&DMat3::IDENTITY), 15.0);
    }

    #[test]
    fn outer_product_is_row_times_column() {
        let t = DMat2::outer(DVec2::new(1.0, 2.0), DVec2::new(3.0, 5.0));
        assert_eq!(t.component(0, 1), 5.0);
        assert_eq!(t.component(1, 0), 6.0);
        assert_eq!(t.mul_vec(DVec2::new(1.0, 0.0)), DVec2::new(3.0, 6.0));
    }

    #[test]
    fn inverse_rejects_singular() {
        assert!(Tensor::inverse(&DMat2::ZERO).is_none());
        assert!(Tensor::inverse(&0.0_f64).is_none());
        assert_eq!(Tensor::inverse(&4.0_f64), Some(0.25));
    }
}
