//! The Monaghan–Gingold viscous pressure Π_ij of a pair (paper §2.2; Spheral's limited
//! form, `LimitedMonaghanGingoldViscosity.cc`, when `viscosity.reconstruct` is on), with
//! the RZ weight r̄/(r_i r_j) and the viscosity switch. Symmetric in (i, j).

use super::pair_bulk_speed;
use crate::solver::state::Extended;
use sph_core::Dimension;
use sph_riemann::MonaghanViscosity;

/// What Π_ij reads of the pair (i, j), r = x_i − x_j.
pub(crate) struct ViscosityPair<D: Dimension> {
    /// v_i, v_j.
    pub v: (D::Vector, D::Vector),
    /// v_i − v_j.
    pub vij: D::Vector,
    /// Both sides' velocity gradients, when pass 1 computed them.
    pub gradients: Option<(D::Tensor, D::Tensor)>,
    pub r: D::Vector,
    pub dist: f64,
    pub rho: (f64, f64),
    /// Signal speeds (c_L for solids), for the pair's mean sound speed.
    pub c: (f64, f64),
    /// Support radii h_i, h_j.
    pub h: (f64, f64),
    /// RZ weights r_i, r_j (1 in Cartesian runs).
    pub weights: (f64, f64),
    /// The switch's factors of i and j, when a switch is on.
    pub switch: Option<(f64, f64)>,
}

/// Π_ij: the relative velocity v_i − v_j, or each side reconstructed to the midpoint with
/// its limited gradient (Spheral's limited viscosity); the length
/// `length_factor` × the mean support radius; the pair's mean sound speed
/// (`pair_bulk_speed`); × r̄/(r_i r_j) in RZ, like the pressure; × the mean switch
/// factor.
#[inline(always)]
pub(crate) fn viscous_pressure<D: Dimension>(
    ext: &Extended<'_, D>,
    (i, j): (usize, usize),
    visc: &MonaghanViscosity,
    (length_factor, n_target): (f64, f64),
    p: &ViscosityPair<D>,
) -> f64 {
    let (ri, rj) = p.weights;
    let r_bar = 0.5 * (ri + rj);
    let h_bar = length_factor * 0.5 * (p.h.0 + p.h.1);
    let v_visc = match p.gradients {
        Some((li, lj)) if visc.reconstruct => {
            let dx_pair = p.h.0.max(p.h.1) / n_target;
            sph_riemann::limited_relative_velocity(p.v.0, p.v.1, &li, &lj, p.r, p.dist / dx_pair)
        }
        _ => p.vij,
    };
    let c_visc = pair_bulk_speed(ext, i, j, p.c.0, p.c.1);
    let mut pi_ij =
        visc.pi(v_visc, p.r, 0.5 * (p.rho.0 + p.rho.1), c_visc, h_bar) * (r_bar / (ri * rj));
    if let Some((si, sj)) = p.switch
        && pi_ij != 0.0
    {
        pi_ij *= 0.5 * (si + sj);
    }
    pi_ij
}
