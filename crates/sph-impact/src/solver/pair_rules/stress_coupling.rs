//! The pair's deviatoric stresses, weakened by damage (paper §3.3; Spheral
//! `SolidFSISPHEvaluateDerivatives.cc` for the FSISPH coupling; docs/scenes.md,
//! `stress_coupling`): across a material interface each particle's own (1 − D), within a
//! body the scheme's coupling, FSISPH's only for pairs in tension along their axis.
//! Tensor damage is read across the pair's direction. The factors are symmetric in
//! (i, j), so the pair force stays antisymmetric.

use crate::solver::state::Extended;
use sph_core::{Dimension, Tensor, Vector};
use sph_damage::StressCoupling;
use sph_damage::tensor::projected_damage;

/// (S_i, S_j) as the pair (i, j) sees them: `s_i` is i's undamaged deviatoric stress in
/// D dimensions, `d` the scalar damages, `p` the pressures (for the tension test), r̂
/// from j to i.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn coupled_stresses<D: Dimension>(
    ext: &Extended<'_, D>,
    coupling: &StressCoupling,
    (i, j): (usize, usize),
    s_i: D::Tensor,
    (di, dj): (f64, f64),
    (pi, pj): (f64, f64),
    same_material: bool,
    r_hat: D::Vector,
) -> (D::Tensor, D::Tensor) {
    let (ci, cj) = if ext.damage_tensor.is_empty() {
        (di, dj)
    } else {
        let n = sph_core::glam::DVec3::from_array(r_hat.to_array3());
        (
            projected_damage(&ext.damage_tensor[i], n),
            projected_damage(&ext.damage_tensor[j], n),
        )
    };
    let sj_undamaged = D::project(&ext.undamaged_stress(j));
    let (ai, aj) = if !same_material {
        coupling.interface_factors(ci, cj)
    } else if coupling.needs_tension_test() {
        // FSISPH: is the pair in tension along its axis?
        let s_rr = r_hat.dot((s_i + sj_undamaged).mul_vec(r_hat));
        coupling.factors(ci, cj, sph_damage::pair_is_tensile(s_rr, pi + pj))
    } else {
        coupling.factors(ci, cj, false)
    };
    (s_i * ai, sj_undamaged * aj)
}
