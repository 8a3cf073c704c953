//! The per-particle factor of the viscosity switch (Balsara), from pass 1's velocity
//! gradient.

use super::*;

/// The per-particle factor of the scheme's viscosity switch, for the real particles;
/// empty when there is no switch. Balsara: |∇·v| and |∇×v| from pass 1's velocity
/// gradient L (∂v_a/∂x_b) that drives the deviatoric stress (the linearly corrected
/// L M⁻¹ where `strain_rate_correction` acts, exact for a linear flow also at a free
/// surface, where the raw sums read a spurious divergence; the raw L in a run without
/// strength), with the hoop rate v_r/r added to the divergence in RZ;
/// |∇×v| = √2 ‖(L − Lᵀ)/2‖_F. The length in the noise floor ε c/h is the viscosity's
/// own (`viscosity_length_factor` × the support radius), the h of Monaghan's μ_ij.
pub(super) fn viscosity_switch_factors<D: Dimension, P: PairKernel<D>>(
    ext: &Extended<'_, D>,
    pk: &P,
    grads: Option<&GradientSet<D>>,
    scheme: &SchemeConfig,
) -> Vec<f64> {
    match scheme.viscosity.switch {
        sph_riemann::ViscositySwitch::None => Vec::new(),
        sph_riemann::ViscositySwitch::Balsara => {
            let gr = grads.expect("the Balsara switch runs pass 1 (need_grads)");
            let rz = is_rz(ext);
            (0..ext.n_real)
                .into_par_iter()
                .map(|i| {
                    let l = &gr.each[i].strain_velocity;
                    let hoop = if rz {
                        ext.velocity[i].component(0) / ext.radius[i]
                    } else {
                        0.0
                    };
                    let div = l.trace() + hoop;
                    let curl = std::f64::consts::SQRT_2 * l.antisymmetric().frobenius_norm();
                    let h = scheme.viscosity_length_factor * pk.h(i);
                    sph_riemann::balsara_factor(div, curl, ext.sound_speed[i], h)
                })
                .collect()
        }
    }
}
