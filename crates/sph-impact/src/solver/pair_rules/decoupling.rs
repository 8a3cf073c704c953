//! Decoupling of fractured material (FSISPH's `decoupleDamagedMaterial`, Spheral
//! `SolidFSISPHEvaluateDerivatives.cc`; docs/scenes.md, `decouple_damaged`): a pair of one
//! material that is separating, with one side in tension past its adhesion limit and one
//! side fully damaged, does not interact at all.

use crate::solver::state::Extended;
use sph_core::{Dimension, Vector};
use sph_damage::tensor::projected_damage;

/// Whether the pair (i, j), r = x_i − x_j, v_ij = v_i − v_j, is decoupled as fractured
/// material (`SchemeConfig::decouple_damaged`, sph_damage::decoupling): same material,
/// separating, one side in tension past its adhesion limit and one side fully damaged
/// (its damage projected on the pair's axis for tensor damage). False when the rule is
/// off (no adhesion flags). Symmetric in (i, j).
#[inline(always)]
pub(crate) fn decoupled<D: Dimension>(
    ext: &Extended<'_, D>,
    i: usize,
    j: usize,
    r: D::Vector,
    vij: D::Vector,
) -> bool {
    if ext.adhesion.is_empty() || ext.material[i] != ext.material[j] {
        return false;
    }
    let separating = r.dot(vij) > 0.0;
    let (ai, aj) = (ext.adhesion[i], ext.adhesion[j]);
    if !separating || !(ai || aj) {
        return false;
    }
    let (di, dj) = if ext.damage_tensor.is_empty() {
        (ext.damage[i], ext.damage[j])
    } else {
        let n = sph_core::glam::DVec3::from_array((r / r.norm()).to_array3());
        (
            projected_damage(&ext.damage_tensor[i], n),
            projected_damage(&ext.damage_tensor[j], n),
        )
    };
    sph_damage::decoupling::decouples(separating, ai, aj, di, dj)
}
