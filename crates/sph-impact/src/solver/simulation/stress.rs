//! The deviatoric stress update of a stage: the stress rate (Hooke's law with the
//! damaged shear modulus, the Jaumann rotation), the yield cap of each material's
//! strength model, and the plastic work (paper §3.2–3.3).

use super::*;

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// The strength model's view of particle i at the given pressure.
    pub(super) fn strength_state(
        &self,
        s: &State<D>,
        i: usize,
        pressure: f64,
    ) -> sph_strength::StrengthState {
        let p = &s.particles;
        let m = &self.materials[p.material[i] as usize];
        let temperature = m
            .thermal
            .as_ref()
            .map_or(300.0, |t| t.temperature(p.specific_energy[i]));
        let mut st = sph_strength::StrengthState::new(pressure, p.density[i], temperature);
        st.plastic_strain = s.plastic_strain.get(i).copied().unwrap_or(0.0);
        st.plastic_strain_rate = s.plastic_strain_rate.get(i).copied().unwrap_or(0.0);
        st.damage = match (&m.damage, s.damage_state.get(i)) {
            (Some(model), Some(&x)) => model.variable().to_damage(x),
            _ => 0.0,
        };
        st
    }

    /// S ← S + dt dS/dt, then the radial return onto the yield surface at the stage's
    /// pressure; the plastic strain grows by (√(3J2_trial) − Y)/(3G) (Wilkins 1964).
    /// Where tracked, the pseudo-plastic strain grows by dt (dS/dt)/G with the elastic
    /// (trial) rate, before the return (sph_damage::activation).
    /// dS/dt = 2G ε̇' + ΩS − SΩ (Jaumann) is formed here from the stage's strain-rate
    /// velocity gradient and the stress of `rate_state`, the state the stage was evaluated
    /// at, with the particle's velocity gradient embedded in 3-D (1-D uniaxial and 2-D
    /// plane strain: the out-of-plane rates are zero; RZ: L_θθ = v_r/r).
    pub(super) fn update_stress(
        &self,
        y: &mut State<D>,
        stage: &Stage<D>,
        dt: f64,
        rate_state: &State<D>,
    ) {
        // RZ: the table of R̂ for the hoop strain rate.
        let rz_table = match self.scheme.geometry {
            Geometry::Axisymmetric => self.smoothed_radius.as_ref(),
            _ => None,
        };
        let grads = stage.grads.as_ref();
        let pseudo = !y.pseudo_strain.is_empty();
        type Updated = (sph_core::glam::DMat3, f64, f64, sph_core::glam::DMat3);
        let updated: Vec<Updated> = (0..y.particles.len())
            .into_par_iter()
            .map(|i| {
                let pseudo_0 = if pseudo {
                    y.pseudo_strain[i]
                } else {
                    sph_core::glam::DMat3::ZERO
                };
                let Some(model) = &self.materials[y.particles.material[i] as usize].strength else {
                    return (
                        sph_core::glam::DMat3::ZERO,
                        y.plastic_strain[i],
                        0.0,
                        pseudo_0,
                    );
                };
                let g = stage.shear_modulus[i];
                // The rate of the intact stress S (damage scales it only where it acts).
                let ds = match grads {
                    Some(gr) if g > 0.0 => {
                        let mut l = D::embed(&gr.each[i].strain_velocity);
                        if let Some(table) = rz_table {
                            l.z_axis.z = hoop_strain_rate(&rate_state.particles, i, table);
                        }
                        sph_strength::jaumann_rate(&rate_state.stress[i], &l, g)
                    }
                    _ => sph_core::glam::DMat3::ZERO,
                };
                let trial = y.stress[i] + ds * dt;
                let st =
                    self.strength_state(y, i, self.scheme.yield_pressure.of(stage.pressure[i]));
                let ret = sph_strength::radial_return(trial, model.yield_strength(&st));
                let dep = ret.plastic_strain_increment(g).unwrap_or(0.0);
                // ds is zero where G = 0, so the pseudo-plastic strain only grows in a
                // solid.
                let pseudo_1 = if pseudo && g > 0.0 {
                    pseudo_0 + ds * (dt / g)
                } else {
                    pseudo_0
                };
                (ret.stress, y.plastic_strain[i] + dep, dep / dt, pseudo_1)
            })
            .collect();
        y.stress
            .par_iter_mut()
            .zip(&mut y.plastic_strain)
            .zip(&mut y.plastic_strain_rate)
            .zip(&updated)
            .for_each(|(((s, ep), rate), u)| {
                (*s, *ep, *rate) = (u.0, u.1, u.2);
            });
        if pseudo {
            y.pseudo_strain
                .par_iter_mut()
                .zip(&updated)
                .for_each(|(e_pp, u)| *e_pp = u.3);
        }
    }
}
