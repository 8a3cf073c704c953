//! FSISPH's density stabilisation (Spheral `SolidFSISPHEvaluateDerivatives.cc`;
//! docs/scenes.md, `density_stabilization`): within one material the interface velocity
//! gets a push along the pair's axis that evens out the pressures,
//!
//! ```text
//! Δv* = f_D κ c̄ (1 + min(0, max(−1, v_ij·r̂/c̄))) clamp((P_j − P_i)/(K_i + K_j), ±¼) r̂,
//! ```
//!
//! with K + 4G/3 = ρ c_L², the reconstructed pressures and f_D FSISPH's damage factor.
//! Symmetric in (i, j) (r̂, v_ij and P_j − P_i all change sign), so conservation is
//! unchanged.

use super::pair_bulk_speed;
use crate::solver::state::Extended;
use sph_core::{Dimension, Vector};

/// One side of a pair as the stabilisation reads it: density, signal speed, the
/// pressure reconstructed to the midpoint, and damage.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Side {
    pub rho: f64,
    pub c: f64,
    pub p: f64,
    pub d: f64,
}

/// Δv* of the pair (i, j) with the coefficient `kappa` (> 0), or `None` where the
/// pair's bulk sound speed is zero. `vij` = v_i − v_j, `r_hat` from j to i.
#[inline(always)]
pub(crate) fn density_stabilization<D: Dimension>(
    ext: &Extended<'_, D>,
    (i, j): (usize, usize),
    (a, b): (Side, Side),
    kappa: f64,
    vij: D::Vector,
    r_hat: D::Vector,
) -> Option<D::Vector> {
    let c_bar = pair_bulk_speed(ext, i, j, a.c, b.c);
    if !(c_bar > 0.0) {
        return None;
    }
    let f_d = sph_damage::fsisph_factor(a.d, b.d);
    let c_factor = 1.0 + (vij.dot(r_hat) / c_bar).clamp(-1.0, 0.0);
    let k_sum = a.rho * a.c * a.c + b.rho * b.c * b.c;
    let dp = ((b.p - a.p) / k_sum).clamp(-0.25, 0.25);
    Some(r_hat * (f_d * kappa * c_factor * c_bar * dp))
}
