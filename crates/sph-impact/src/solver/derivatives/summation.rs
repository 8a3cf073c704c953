//! Summation density (pass 0, with `DensityForm::Summation`): ρ_i = m_i W(0) + Σ_j m_j W̄_ij.

use super::*;

/// Summation density ρ_i = m_i W(0) + Σ_j m_j W̄_ij over real particles.
pub(crate) fn summation_density<D: Dimension, P: PairKernel<D>>(
    ext: &Extended<'_, D>,
    list: Pairs<'_>,
    pk: &P,
    rz_radius: Option<&crate::solver::axisymmetric::SmoothedRadius>,
) -> Vec<f64> {
    per_geometry!(summation_density_in(ext, list, pk, rz_radius))
}

/// [`summation_density`] for one geometry (`RZ`), fixed at compile time.
fn summation_density_in<D: Dimension, P: PairKernel<D>, const RZ: bool>(
    ext: &Extended<'_, D>,
    list: Pairs<'_>,
    pk: &P,
    rz_radius: Option<&crate::solver::axisymmetric::SmoothedRadius>,
) -> Vec<f64> {
    let rz = RZ;
    (0..ext.n_real)
        .into_par_iter()
        .map_init(Vec::new, |scratch, i| {
            let xi = ext.position[i];
            let w0 = pk.w(i, i, D::Vector::ZERO);
            let eta = list
                .row(i, scratch)
                .iter()
                .fold(ext.mass[i] * w0, |acc, &j| {
                    let j = j as usize;
                    acc + ext.mass[j] * pk.w(i, j, xi - ext.position[j])
                });
            match rz_radius {
                // RZ: Σ m W of a uniform density is ρ R̂(r, h), the kernel-smoothed |r|
                // (larger than r next to the axis, where the mirror images sit).
                Some(s) if rz => eta / s.at(ext.radius[i], pk.h(i)),
                _ => eta,
            }
        })
        .collect()
}
