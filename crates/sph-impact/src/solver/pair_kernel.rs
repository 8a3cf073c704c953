//! The kernel as a pair sees it: symmetrised over the two particles' supports, with
//! scalar h or ASPH tensors H, chosen once per run and monomorphised.

use rayon::prelude::*;
use sph_core::{Dimension, Tensor, Vector};
use sph_kernel::Kernel;

/// Symmetrised kernel of a pair, W̄_ij = ½(W(r, h_i) + W(r, h_j)), and its gradient
/// ∇_i W̄_ij (antisymmetric in i, j, which makes pair forces conserve momentum).
pub(crate) trait PairKernel<D: Dimension>: Sync {
    /// W̄ for separation r = x_i − x_j.
    fn w(&self, i: usize, j: usize, r: D::Vector) -> f64;
    /// W̄ when |r| is already known.
    fn w_dist(&self, i: usize, j: usize, r: D::Vector, dist: f64) -> f64 {
        let _ = dist;
        self.w(i, j, r)
    }
    /// ∇_i W̄.
    fn grad(&self, i: usize, j: usize, r: D::Vector) -> D::Vector;
    /// ∇_i W̄ when |r| is already known.
    fn grad_at(&self, i: usize, j: usize, r: D::Vector, dist: f64) -> D::Vector {
        let _ = dist;
        self.grad(i, j, r)
    }
    /// A scalar support radius of particle i (for viscosity lengths and spacings).
    fn h(&self, i: usize) -> f64;
    /// ∂W(r, h_i)/∂h with particle i's own support (for the grad-h factor).
    fn dw_dh_own(&self, i: usize, r: D::Vector) -> f64;
    /// [`Self::dw_dh_own`] when |r| is already known (scalar supports need no more).
    fn dw_dh_own_at(&self, i: usize, r: D::Vector, dist: f64) -> f64 {
        let _ = dist;
        self.dw_dh_own(i, r)
    }
    /// W̄ at distance `d` along the pair axis `r_hat` (artificial-stress normaliser).
    #[inline(always)]
    fn w_at(&self, i: usize, j: usize, r_hat: D::Vector, d: f64) -> f64 {
        self.w(i, j, r_hat * d)
    }
    /// ∇_i W̄ with both particles' own ∂W/∂h, for a pair evaluated once for both
    /// (pass 1 with the grad-h factor): the same numbers as [`Self::grad_at`] and
    /// [`Self::dw_dh_own_at`] for i (at r) and for j (at −r), sharing what they have in
    /// common.
    #[inline(always)]
    fn grad_and_dw_dh(&self, i: usize, j: usize, r: D::Vector, dist: f64) -> (D::Vector, f64, f64) {
        (
            self.grad_at(i, j, r, dist),
            self.dw_dh_own_at(i, r, dist),
            self.dw_dh_own_at(j, -r, dist),
        )
    }
}

/// Scalar support radii, with the per-particle factors 1/h, σ/h^d and σ/h^(d+1)
/// computed once per stage (the pair loop then needs one square root per pair).
pub(crate) struct ScalarPairKernel<'a, K> {
    pub kernel: K,
    pub h: &'a [f64],
    /// Each particle's factors together: a pair reads all of a partner's with one
    /// bounds test and from one cache line.
    scale: Vec<Scale>,
}

/// A particle's kernel factors for a scalar support h.
#[derive(Clone, Copy, Debug)]
struct Scale {
    /// 1/h.
    inv_h: f64,
    /// σ/h^d, W's.
    w_norm: f64,
    /// σ/h^(d+1), ∇W's and ∂W/∂h's.
    g_norm: f64,
}

impl<'a, K: Kernel> ScalarPairKernel<'a, K> {
    /// Precomputes the factors for `dim` dimensions.
    pub fn new(kernel: K, h: &'a [f64], dim: usize) -> Self {
        let sigma = kernel.sigma(dim);
        // Once per stage over every particle and ghost: in parallel (the same numbers).
        let scale = h
            .par_iter()
            .map(|h| {
                let inv_h = 1.0 / h;
                Scale {
                    inv_h,
                    w_norm: sigma * inv_h.powi(dim as i32),
                    g_norm: sigma * inv_h.powi(dim as i32 + 1),
                }
            })
            .collect();
        Self { kernel, h, scale }
    }
    /// W = σ h^(−d) f(r/h), ∂W/∂h = −σ h^(−d−1) (d f + q f').
    #[inline(always)]
    fn dw_dh(s: Scale, q: f64, f: f64, df: f64, d: f64) -> f64 {
        -s.g_norm * (d * f + q * df)
    }
}

/// ∇_i W̄ from both sides' f'(q): r ½(σ f'(q_i)/h_i^(d+1) + σ f'(q_j)/h_j^(d+1))/|r|,
/// zero for coincident particles.
#[inline(always)]
fn pair_gradient<V: Vector>((si, sj): (Scale, Scale), r: V, dist: f64, df: (f64, f64)) -> V {
    if dist == 0.0 {
        return V::ZERO;
    }
    let (gi, gj) = (df.0 * si.g_norm, df.1 * sj.g_norm);
    r * (0.5 * (gi + gj) / dist)
}

impl<D: Dimension, K: Kernel> PairKernel<D> for ScalarPairKernel<'_, K> {
    #[inline(always)]
    fn w(&self, i: usize, j: usize, r: D::Vector) -> f64 {
        <Self as PairKernel<D>>::w_dist(self, i, j, r, r.norm())
    }
    #[inline(always)]
    fn w_dist(&self, i: usize, j: usize, _r: D::Vector, d: f64) -> f64 {
        let (si, sj) = (self.scale[i], self.scale[j]);
        0.5 * (self.kernel.f(d * si.inv_h) * si.w_norm + self.kernel.f(d * sj.inv_h) * sj.w_norm)
    }
    #[inline(always)]
    fn grad(&self, i: usize, j: usize, r: D::Vector) -> D::Vector {
        <Self as PairKernel<D>>::grad_at(self, i, j, r, r.norm())
    }
    #[inline(always)]
    fn grad_at(&self, i: usize, j: usize, r: D::Vector, dist: f64) -> D::Vector {
        if dist == 0.0 {
            return D::Vector::ZERO;
        }
        let (si, sj) = (self.scale[i], self.scale[j]);
        let df = (
            self.kernel.df(dist * si.inv_h),
            self.kernel.df(dist * sj.inv_h),
        );
        pair_gradient((si, sj), r, dist, df)
    }
    #[inline(always)]
    fn h(&self, i: usize) -> f64 {
        self.h[i]
    }
    #[inline(always)]
    fn dw_dh_own(&self, i: usize, r: D::Vector) -> f64 {
        <Self as PairKernel<D>>::dw_dh_own_at(self, i, r, r.norm())
    }
    #[inline(always)]
    fn dw_dh_own_at(&self, i: usize, _r: D::Vector, dist: f64) -> f64 {
        let si = self.scale[i];
        let q = dist * si.inv_h;
        Self::dw_dh(si, q, self.kernel.f(q), self.kernel.df(q), D::DIM as f64)
    }
    #[inline(always)]
    fn grad_and_dw_dh(&self, i: usize, j: usize, r: D::Vector, dist: f64) -> (D::Vector, f64, f64) {
        // Each side's kernel and its derivative once, through the helpers of grad_at and
        // dw_dh_own_at, so the numbers are theirs to the bit.
        let d = D::DIM as f64;
        let (si, sj) = (self.scale[i], self.scale[j]);
        let (qi, qj) = (dist * si.inv_h, dist * sj.inv_h);
        let (dfi, dfj) = (self.kernel.df(qi), self.kernel.df(qj));
        (
            pair_gradient((si, sj), r, dist, (dfi, dfj)),
            Self::dw_dh(si, qi, self.kernel.f(qi), dfi, d),
            Self::dw_dh(sj, qj, self.kernel.f(qj), dfj, d),
        )
    }
}

/// ASPH tensors, with `h` the geometric-mean support radius det(H)^(−1/d).
pub(crate) struct TensorPairKernel<'a, K, T> {
    pub kernel: K,
    pub h_tensor: &'a [T],
    pub h: &'a [f64],
}

impl<D: Dimension, K: Kernel> PairKernel<D> for TensorPairKernel<'_, K, D::Tensor> {
    #[inline]
    fn w(&self, i: usize, j: usize, r: D::Vector) -> f64 {
        0.5 * (self.kernel.w_tensor(r, &self.h_tensor[i])
            + self.kernel.w_tensor(r, &self.h_tensor[j]))
    }
    #[inline]
    fn grad(&self, i: usize, j: usize, r: D::Vector) -> D::Vector {
        (self.kernel.grad_w_tensor(r, &self.h_tensor[i])
            + self.kernel.grad_w_tensor(r, &self.h_tensor[j]))
            * 0.5
    }
    #[inline]
    fn h(&self, i: usize) -> f64 {
        self.h[i]
    }
    #[inline]
    fn dw_dh_own(&self, i: usize, r: D::Vector) -> f64 {
        // H scaled uniformly as H/s: the scalar formula with η = |H r|, h = det(H)^(−1/d).
        let eta = self.h_tensor[i].mul_vec(r).norm();
        let d = D::DIM as f64;
        let w = self.kernel.sigma(D::DIM) * self.h_tensor[i].determinant();
        -w / self.h[i] * (d * self.kernel.f(eta) + eta * self.kernel.df(eta))
    }
    /// The isotropic kernel of each particle's equivalent radius h = det(H)^(−1/d) at
    /// distance `d`, whatever the direction. The normaliser W(Δp) of the artificial
    /// stress stands for "one mean spacing", which an anisotropic H puts at the same
    /// kernel coordinate in every direction: evaluating the tensor kernel itself at Δp
    /// along a compressed axis gave W(Δp) → 0, so f = W/W(Δp) and f^n without bound
    /// (RZ Taylor bar with ASPH: NaN at 20 µs). For an isotropic H this is the tensor
    /// kernel's own value.
    #[inline]
    fn w_at(&self, i: usize, j: usize, _r_hat: D::Vector, d: f64) -> f64 {
        let sigma = self.kernel.sigma(D::DIM);
        let iso =
            |k: usize| sigma * self.h[k].powi(-(D::DIM as i32)) * self.kernel.f(d / self.h[k]);
        0.5 * (iso(i) + iso(j))
    }
}

/// det(H)^(−1/d): the radius of the sphere with the ellipsoid's volume.
pub(crate) fn equivalent_radius<T: Tensor>(h: &T) -> f64 {
    h.determinant().powf(-1.0 / T::Vector::DIM as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::Dim2;
    use sph_core::glam::{DMat2, DVec2};
    use sph_kernel::WendlandC2;

    /// The artificial stress' normaliser W(Δp) of an anisotropic H is the isotropic
    /// kernel of its equivalent radius in every direction: finite along a compressed axis
    /// where the tensor kernel itself has already vanished.
    #[test]
    fn asph_stress_normaliser_is_the_isotropic_kernel_of_the_equivalent_radius() {
        let h = 1.0e-3;
        // Support 2h along x, h/2 along y: det H = 1/h², equivalent radius h.
        let tensor = [DMat2::from_diagonal(DVec2::new(0.5 / h, 2.0 / h)); 2];
        let radii = [h; 2];
        let tk = TensorPairKernel {
            kernel: WendlandC2,
            h_tensor: &tensor,
            h: &radii,
        };
        let sk = ScalarPairKernel::new(WendlandC2, &radii, 2);
        let d = 0.6 * h;
        // The tensor kernel along y is zero at 0.6 h (|H r| = 1.2) ...
        assert_eq!(PairKernel::<Dim2>::w(&tk, 0, 1, DVec2::new(0.0, d)), 0.0);
        // ... the normaliser is the scalar kernel's value, the same along x and y.
        let iso = PairKernel::<Dim2>::w(&sk, 0, 1, DVec2::new(d, 0.0));
        assert!(iso > 0.0);
        for dir in [DVec2::X, DVec2::Y] {
            let w = PairKernel::<Dim2>::w_at(&tk, 0, 1, dir, d);
            assert!((w / iso - 1.0).abs() < 1e-14, "{w} {iso}");
        }
    }

    /// The shared evaluation of a pair's gradient and both sides' ∂W/∂h gives the
    /// separate methods' numbers to the bit, for the scalar kernel (its own expression)
    /// and the tensor kernel (the default), coincident particles included.
    #[test]
    fn grad_and_dw_dh_equal_the_separate_evaluations() {
        let radii = [1.0e-3, 1.7e-3];
        let sk = ScalarPairKernel::new(WendlandC2, &radii, 2);
        let tensor = [
            DMat2::from_diagonal(DVec2::new(1.0 / radii[0], 1.0 / radii[0])),
            DMat2::from_diagonal(DVec2::new(0.8 / radii[1], 1.3 / radii[1])),
        ];
        let tk = TensorPairKernel {
            kernel: WendlandC2,
            h_tensor: &tensor,
            h: &radii,
        };
        for r in [
            DVec2::new(0.0, 0.0),
            DVec2::new(3.1e-4, -2.2e-4),
            DVec2::new(-9.0e-4, 4.0e-4),
            DVec2::new(1.5e-3, 0.2e-3),
        ] {
            let dist = r.length();
            for (i, j) in [(0, 1), (1, 0)] {
                let (g, wi, wj) = PairKernel::<Dim2>::grad_and_dw_dh(&sk, i, j, r, dist);
                assert_eq!(g, PairKernel::<Dim2>::grad_at(&sk, i, j, r, dist));
                assert_eq!(wi, PairKernel::<Dim2>::dw_dh_own_at(&sk, i, r, dist));
                assert_eq!(wj, PairKernel::<Dim2>::dw_dh_own_at(&sk, j, -r, dist));
                let (g, wi, wj) = PairKernel::<Dim2>::grad_and_dw_dh(&tk, i, j, r, dist);
                assert_eq!(g, PairKernel::<Dim2>::grad_at(&tk, i, j, r, dist));
                assert_eq!(wi, PairKernel::<Dim2>::dw_dh_own_at(&tk, i, r, dist));
                assert_eq!(wj, PairKernel::<Dim2>::dw_dh_own_at(&tk, j, -r, dist));
            }
        }
    }
}
