//! The artificial stress of a pair (paper §2.3; Monaghan 2000, Gray et al. 2001):
//! m_j f_ij^n (R_i + R_j)·∇_i W, with R from the total stress (repulsive in tension) and
//! f_ij = W(r_ij)/W(Δp), here per unit mass of the partner. In RZ each R is weighted by
//! 1/r like the stress, and f_ij is also returned for the hoop part (`rates`' finish).
//! Symmetric in (i, j) through ∇W.

use crate::solver::pair_kernel::PairKernel;
use crate::solver::state::Extended;
use sph_core::{Dimension, Tensor, Vector};
use sph_riemann::ArtificialStress;

/// (the artificial-stress force per unit partner mass, f_ij) of the pair (i, j) with
/// r = x_i − x_j, |r|, r̂ and the kernel gradient `g` (in RZ each R is read already
/// weighted by 1/r, `Extended::astress`); f_ij is 0 where R_i + R_j vanishes unless
/// `hoop` (RZ: a side has a hoop component R_θθ, whose force needs f_ij; `rates`'
/// finish).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn artificial_stress<D: Dimension, P: PairKernel<D>, const RZ: bool>(
    ext: &Extended<'_, D>,
    pk: &P,
    astress: &ArtificialStress,
    (i, j): (usize, usize),
    (r, dist): (D::Vector, f64),
    r_hat: D::Vector,
    g: D::Vector,
    hoop: bool,
) -> (D::Vector, f64) {
    // Two zero tensors: R_i + R_j is zero and a Cartesian pair gets no term (RZ goes on,
    // for the hoop test and the signs of its zero force below).
    if !RZ && !ext.astress_on[i] && !ext.astress_on[j] {
        return (D::Vector::ZERO, 0.0);
    }
    // In RZ the extended state holds R/r (stage.rs), computed once per particle.
    let r_sum = ext.astress[i] + ext.astress[j];
    if r_sum.double_dot(&r_sum) > 0.0 || (RZ && hoop) {
        let dp = 0.5 * (ext.spacing0[i] + ext.spacing0[j]);
        let f = astress.kernel_factor(pk.w_dist(i, j, r, dist) / pk.w_at(i, j, r_hat, dp));
        (r_sum.mul_vec(g) * f, f)
    } else if RZ {
        // The zero force with the signs of zero that the product with f ≥ 0 gives, so
        // that skipping the kernel ratio changes no bit of the pair's force.
        (r_sum.mul_vec(g) * 0.0, 0.0)
    } else {
        (D::Vector::ZERO, 0.0)
    }
}
