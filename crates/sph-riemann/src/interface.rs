//! The interface velocity v* of a pair (paper §2.1):
//!
//!   v* = b_ij (v_i + v_j)/2 + (1 − b_ij) v̄* + v^p_ij,
//!   b_ij = 1 − |D_i − D_j| (same material), 0 (different materials),
//!
//! with v̄* the impedance-weighted mean velocity and v^p_ij = (u*_R − ū_Z) r̂ the
//! pressure correction: the star velocity of the pair's Riemann problem minus the
//! impedance-weighted mean normal velocity. For the acoustic solver this is exactly the
//! paper's (P_j − P_i)/(Z_i + Z_j) r̂; for HLLC it is the HLLC contact speed's excess.
//!
//! The FSISPH variant (Pearl, Raskin & Owen, J. Comput. Phys. 2022) squares the
//! coupling, b = (1 − |D_i − D_j|)², and lets the pressure term act only through the
//! (1 − b) branch: v* = b v̄ + (1 − b)(v̄* + v^p).

use crate::hllc::RiemannSolver;
use crate::state::SideState;
use serde::{Deserialize, Serialize};
use sph_core::Vector;

/// How damage and material interfaces couple the pair (paper §2.1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum InterfaceCoupling {
    /// The study's form: b = 1 − |D_i − D_j|, pressure correction always applied.
    #[default]
    Study,
    /// Spheral FSISPH's form: b = (1 − |D_i − D_j|)², pressure correction only in the
    /// (1 − b) branch.
    Fsisph,
    /// Pure Riemann interface: b = 0 for every pair (ignores damage).
    Riemann,
    /// Classic SPH: v* = (v_i + v_j)/2 for every pair (no Riemann solution); with
    /// Monaghan viscosity this is standard SPH, kept as a reference.
    Mean,
}

/// Everything the interface velocity of pair (i, j) depends on.
#[derive(Clone, Copy, Debug)]
pub struct PairInterface<V> {
    /// Velocity of particle i.
    pub v_i: V,
    /// Velocity of particle j.
    pub v_j: V,
    /// Unit vector from j to i, (x_i − x_j)/|x_i − x_j|.
    pub r_hat: V,
    /// Particle i as the right state along r̂ (normal velocity possibly reconstructed).
    pub right: SideState,
    /// Particle j as the left state along r̂.
    pub left: SideState,
    /// Damage of i.
    pub damage_i: f64,
    /// Damage of j.
    pub damage_j: f64,
    /// Whether i and j are the same material.
    pub same_material: bool,
}

/// The coupling weight b_ij.
#[inline]
pub fn coupling_weight(
    coupling: InterfaceCoupling,
    damage_i: f64,
    damage_j: f64,
    same_material: bool,
) -> f64 {
    if !same_material {
        return 0.0;
    }
    let b = 1.0 - (damage_i - damage_j).abs();
    match coupling {
        InterfaceCoupling::Study => b,
        InterfaceCoupling::Fsisph => b * b,
        InterfaceCoupling::Riemann => 0.0,
        InterfaceCoupling::Mean => 1.0,
    }
}

/// The interface velocity v* of the pair (paper §2.1).
// Always inlined: the pair loop of pass 2 calls it once per pair, and left to the
// compiler it stayed a call (its lines 5.5 % of the 3-D smoke run's instructions); inlined,
// that run executes 0.8 % fewer instructions, with byte-identical outputs
// (docs/performance.md, "One neighbour search per step").
#[inline(always)]
pub fn interface_velocity<V: Vector>(
    p: &PairInterface<V>,
    solver: RiemannSolver,
    coupling: InterfaceCoupling,
) -> V {
    let mean = (p.v_i + p.v_j) * 0.5;
    if coupling == InterfaceCoupling::Mean {
        return mean;
    }
    let (zi, zj) = (p.right.impedance(), p.left.impedance());
    let z = zi + zj;
    if !(z > 0.0) {
        // No signal can cross (vacuum on both sides): the plain mean.
        return mean;
    }
    // Impedance-weighted mean velocity v̄*: its normal part from the (possibly
    // reconstructed) normal velocities, its tangential part from the full velocities.
    let u_bar = (zi * p.right.velocity + zj * p.left.velocity) / z;
    let w_i = p.v_i - p.r_hat * p.v_i.dot(p.r_hat);
    let w_j = p.v_j - p.r_hat * p.v_j.dot(p.r_hat);
    let v_bar_star = p.r_hat * u_bar + (w_i * zi + w_j * zj) / z;
    let u_star = solver.star(&p.left, &p.right).velocity;
    let v_p = p.r_hat * (u_star - u_bar);
    let b = coupling_weight(coupling, p.damage_i, p.damage_j, p.same_material);
    match coupling {
        InterfaceCoupling::Fsisph => mean * b + (v_bar_star + v_p) * (1.0 - b),
        InterfaceCoupling::Study | InterfaceCoupling::Riemann | InterfaceCoupling::Mean => {
            mean * b + v_bar_star * (1.0 - b) + v_p
        }
    }
}
