//! FSISPH's energy diffusion between same-material pairs (Spheral
//! `SolidFSISPHEvaluateDerivatives.cc`; docs/scenes.md, `energy_diffusion`):
//!
//! ```text
//! de_i/dt += m_j κ c_eff (ẽ_i − ẽ_j) η·∇W̄/(ρ̄ |η|²),
//! ```
//!
//! with ẽ the energies reconstructed to the midpoint (Spheral's limiter), c_eff =
//! max(0, min(c̄, c̄ + v_ij·r̂)) and η = r/h̄. Antisymmetric in (i, j), so Σ m e is
//! unchanged.

use super::pair_bulk_speed;
use crate::solver::state::Extended;
use sph_core::{Dimension, Vector};

/// What the diffusion reads of the pair (i, j), r = x_i − x_j.
pub(crate) struct DiffusionPair<D: Dimension> {
    /// ∇e of i and of j (a ghost's mapped).
    pub energy_gradients: (D::Vector, D::Vector),
    pub r: D::Vector,
    pub r_hat: D::Vector,
    /// v_i − v_j.
    pub vij: D::Vector,
    /// ∇W̄ from i's side.
    pub g: D::Vector,
    /// Support radii h_i, h_j.
    pub h: (f64, f64),
    /// The densities η_i, η_j (ρ, or ρ R̂ in RZ).
    pub eta: (f64, f64),
    /// Signal speeds, for the pair's mean sound speed.
    pub c: (f64, f64),
}

/// κ c_eff (ẽ_i − ẽ_j) η·∇W̄/(ρ̄ |η|²) with κ = `kappa`: de_i/dt gets m_j times it and
/// de_j/dt −m_i times it.
#[inline(always)]
pub(crate) fn energy_diffusion<D: Dimension>(
    ext: &Extended<'_, D>,
    (i, j): (usize, usize),
    kappa: f64,
    p: &DiffusionPair<D>,
) -> f64 {
    let (ei, ej) = (ext.specific_energy[i], ext.specific_energy[j]);
    let half = p.r * 0.5;
    let (ei_t, ej_t) = sph_riemann::spheral_reconstruct(
        ei,
        ej,
        p.energy_gradients.0.dot(half),
        p.energy_gradients.1.dot(half),
    );
    let c_bar = pair_bulk_speed(ext, i, j, p.c.0, p.c.1);
    let c_eff = (c_bar + p.vij.dot(p.r_hat)).min(c_bar).max(0.0);
    let h_pair = 0.5 * (p.h.0 + p.h.1);
    let eta = p.r / h_pair;
    let eta_bar = 0.5 * (p.eta.0 + p.eta.1);
    kappa * c_eff * (ei_t - ej_t) * eta.dot(p.g) / (eta_bar * eta.norm_squared())
}
