//! The [`Kernel`] trait.
//!
//! Convention (paper §2.4): the kernel has compact support of radius `h`, q = r/h, and
//!
//!   W(r, h) = σ_d / h^d · f(q),   f(q) = 0 for q ≥ 1,
//!
//! with σ_d chosen so that ∫ W dV = 1 in d dimensions. With a symmetric positive
//! definite smoothing tensor H (ASPH, units 1/m) the same kernel is
//!
//!   W(r, H) = σ_d det(H) f(|H r|),
//!
//! which reduces to the scalar form for H = I/h and integrates to one for any H (change
//! of variables s = H r).

use sph_core::{Tensor, Vector};

/// A radially symmetric smoothing kernel with compact support of radius h.
pub trait Kernel: Copy + Send + Sync + std::fmt::Debug {
    /// Name for output and messages.
    fn name(&self) -> &'static str;
    /// The shape function f(q) on q ∈ [0, 1); zero for q ≥ 1.
    fn f(&self, q: f64) -> f64;
    /// df/dq; zero for q ≥ 1.
    fn df(&self, q: f64) -> f64;
    /// σ_d, the normalisation in `dim` = 1, 2 or 3 dimensions (support radius 1).
    /// Panics for other dimensions.
    fn sigma(&self, dim: usize) -> f64;

    /// W(r, h) for separation vector `r` and support radius `h`.
    #[inline]
    fn w<V: Vector>(&self, r: V, h: f64) -> f64 {
        self.w_radial(V::DIM, r.norm(), h)
    }

    /// W as a function of the distance |r| in `dim` dimensions.
    #[inline]
    fn w_radial(&self, dim: usize, r: f64, h: f64) -> f64 {
        self.sigma(dim) / h.powi(dim as i32) * self.f(r / h)
    }

    /// ∂W/∂r (radial derivative) in `dim` dimensions.
    #[inline]
    fn dw_radial(&self, dim: usize, r: f64, h: f64) -> f64 {
        self.sigma(dim) / h.powi(dim as i32 + 1) * self.df(r / h)
    }

    /// ∇_r W(r, h) = ∂W/∂r · r/|r| (zero at r = 0).
    #[inline]
    fn grad_w<V: Vector>(&self, r: V, h: f64) -> V {
        let d = r.norm();
        if d == 0.0 {
            return V::ZERO;
        }
        r * (self.dw_radial(V::DIM, d, h) / d)
    }

    /// ASPH value W(r, H) = σ_d det(H) f(|H r|).
    #[inline]
    fn w_tensor<T: Tensor>(&self, r: T::Vector, hten: &T) -> f64 {
        let eta = hten.mul_vec(r).norm();
        self.sigma(T::Vector::DIM) * hten.determinant() * self.f(eta)
    }

    /// ASPH gradient ∇_r W(r, H) = σ_d det(H) f'(η) Hᵀ(H r)/η with η = |H r|.
    #[inline]
    fn grad_w_tensor<T: Tensor>(&self, r: T::Vector, hten: &T) -> T::Vector {
        let hr = hten.mul_vec(r);
        let eta = hr.norm();
        if eta == 0.0 {
            return T::Vector::ZERO;
        }
        let scale = self.sigma(T::Vector::DIM) * hten.determinant() * self.df(eta) / eta;
        hten.transpose().mul_vec(hr) * scale
    }
}

/// Panics with a clear message for an unsupported dimension.
#[inline]
pub(crate) fn pick(dim: usize, s: [f64; 3]) -> f64 {
    match dim {
        1..=3 => s[dim - 1],
        _ => panic!("kernels are normalised for 1, 2 or 3 dimensions, not {dim}"),
    }
}
