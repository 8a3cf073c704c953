//! The deviatoric stress update of a stage: the stress rate (Hooke's law with the
//! damaged shear modulus, the Jaumann rotation), the yield cap of each material's
//! strength model, and the plastic work (paper §3.2–3.3).

use super::*;
use sph_core::glam::DMat3;

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// The strength model's view of particle i at the given pressure.
    pub(super) fn strength_state(
        &self,
        s: &State<D>,
        i: usize,
        pressure: f64,
    ) -> sph_strength::StrengthState {
        let p = &s.particles;
        self.strength_view(
            p.material[i],
            p.specific_energy[i],
            p.density[i],
            (
                s.plastic_strain.get(i).copied().unwrap_or(0.0),
                s.plastic_strain_rate.get(i).copied().unwrap_or(0.0),
            ),
            s.damage_state.get(i).copied(),
            pressure,
        )
    }

    /// The strength model's view of a particle of material `material` with specific
    /// energy `e`, density `rho`, plastic strain and its rate `plastic`, damage state
    /// `damage_state` (none without damage) at pressure `pressure`.
    fn strength_view(
        &self,
        material: u16,
        e: f64,
        rho: f64,
        plastic: (f64, f64),
        damage_state: Option<f64>,
        pressure: f64,
    ) -> sph_strength::StrengthState {
        let m = &self.materials[material as usize];
        let temperature = m.thermal.as_ref().map_or(300.0, |t| t.temperature(e));
        let mut st = sph_strength::StrengthState::new(pressure, rho, temperature);
        (st.plastic_strain, st.plastic_strain_rate) = plastic;
        st.damage = damage_state.map_or(0.0, |x| damage_at(m, x));
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
        let p = &y.particles;
        let damage_state = &y.damage_state;
        // Particle i's update, in place: S, ε_p, its rate and (where tracked) the
        // pseudo-plastic strain.
        let update =
            |i: usize, s: &mut DMat3, ep: &mut f64, rate: &mut f64, pseudo: Option<&mut DMat3>| {
                let Some(model) = &self.materials[p.material[i] as usize].strength else {
                    (*s, *rate) = (DMat3::ZERO, 0.0);
                    return;
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
                    _ => DMat3::ZERO,
                };
                let trial = *s + ds * dt;
                let st = self.strength_view(
                    p.material[i],
                    p.specific_energy[i],
                    p.density[i],
                    (*ep, *rate),
                    damage_state.get(i).copied(),
                    self.scheme.yield_pressure.of(stage.pressure[i]),
                );
                let ret = sph_strength::radial_return(trial, model.yield_strength(&st));
                let dep = ret.plastic_strain_increment(g).unwrap_or(0.0);
                (*s, *ep, *rate) = (ret.stress, *ep + dep, dep / dt);
                // ds is zero where G = 0, so the pseudo-plastic strain only grows in a solid.
                if let Some(e_pp) = pseudo
                    && g > 0.0
                {
                    *e_pp += ds * (dt / g);
                }
            };
        let n_chunks = y.stress.len().div_ceil(PASS_CHUNK);
        y.stress
            .par_chunks_mut(PASS_CHUNK)
            .zip(y.plastic_strain.par_chunks_mut(PASS_CHUNK))
            .zip(y.plastic_strain_rate.par_chunks_mut(PASS_CHUNK))
            .zip(chunks_or_none(&mut y.pseudo_strain, n_chunks))
            .enumerate()
            .for_each(|(c, (((s, ep), rate), mut pseudo))| {
                for k in 0..s.len() {
                    let e_pp = pseudo.as_deref_mut().map(|e| &mut e[k]);
                    update(
                        c * PASS_CHUNK + k,
                        &mut s[k],
                        &mut ep[k],
                        &mut rate[k],
                        e_pp,
                    );
                }
            });
    }
}
