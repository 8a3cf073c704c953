//! What a stage computes of each real particle before its pairs, in one pass: the EOS's
//! pressure P and sound speed c, the damage D and the damaged pressure P_D (paper §3.3),
//! the shear modulus G, the longitudinal signal speed c_L = √(c² + 4G/(3ρ)) (paper §2.1)
//! and the adhesion flags of fractured rock (sph_damage::decoupling).
//!
//! Each term is particle i's own, so one pass gives what a pass per term gave, to the
//! bit, at one fork-join instead of six: a scene of a few thousand rings does little
//! work per pass, and the threads' hand-overs would otherwise cost as much as the work.

use super::*;

/// The per-particle terms of a stage (real particles only).
pub(super) struct ParticleTerms {
    /// P from the EOS, undamaged.
    pub(super) pressure: Vec<f64>,
    /// c from the EOS.
    pub(super) sound_speed: Vec<f64>,
    /// D (empty without damage, and when the caller gave it).
    pub(super) damage: Vec<f64>,
    /// P_D, what the pair terms see (P itself without damage).
    pub(super) pressure_d: Vec<f64>,
    /// G (0 for fluids, and for everything when no material has strength).
    pub(super) shear_modulus: Vec<f64>,
    /// c_L (c for fluids).
    pub(super) signal: Vec<f64>,
    /// Whether each particle is past its adhesion limit (in tension and damaged,
    /// sph_damage::decoupling::past_adhesion, from its undamaged pressure and bulk sound
    /// speed); empty unless fractured material is decoupled
    /// (`SchemeConfig::decouple_damaged`) and some material has damage.
    pub(super) adhesion: Vec<bool>,
}

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// The terms of `state`'s particles. `damage` is D where the stage has it already
    /// (summation density evaluates the terms again at its new density; the returned
    /// `damage` is then empty); `None` computes it from the damage state.
    pub(super) fn particle_terms(&self, state: &State<D>, damage: Option<&[f64]>) -> ParticleTerms {
        let p = &state.particles;
        // Counted by the materials: with a summation density this runs while the
        // positions are lent to the stage's extended state (state.rs, `RealColumns`).
        let n = p.material.len();
        let n_chunks = n.div_ceil(PASS_CHUNK);
        let has_damage = !state.damage_state.is_empty();
        let solid = !state.stress.is_empty();
        let mut terms = ParticleTerms {
            pressure: vec![0.0; n],
            sound_speed: vec![0.0; n],
            // Computed only where not given (and then not returned).
            damage: if damage.is_none() && has_damage {
                vec![0.0; n]
            } else {
                Vec::new()
            },
            pressure_d: vec![0.0; n],
            shear_modulus: vec![0.0; n],
            signal: vec![0.0; n],
            adhesion: if self.scheme.decouple_damaged && has_damage {
                vec![false; n]
            } else {
                Vec::new()
            },
        };
        // An empty D given is a run without damage.
        let given = damage.filter(|d| !d.is_empty());
        let ParticleTerms {
            pressure,
            sound_speed,
            damage,
            pressure_d,
            shear_modulus,
            signal,
            adhesion,
        } = &mut terms;
        (
            pressure.par_chunks_mut(PASS_CHUNK),
            sound_speed.par_chunks_mut(PASS_CHUNK),
            chunks_or_none(damage, n_chunks),
            pressure_d.par_chunks_mut(PASS_CHUNK),
            shear_modulus.par_chunks_mut(PASS_CHUNK),
            signal.par_chunks_mut(PASS_CHUNK),
            chunks_or_none(adhesion, n_chunks),
        )
            .into_par_iter()
            .enumerate()
            .for_each(|(c, (pr, cs, mut dm, pd, g, cl, mut adh))| {
                for k in 0..pr.len() {
                    let i = c * PASS_CHUNK + k;
                    let m = &self.materials[p.material[i] as usize];
                    let pt = m.eos.evaluate(p.density[i], p.specific_energy[i]);
                    (pr[k], cs[k]) = (pt.pressure, pt.sound_speed);
                    // D as given, or from the damage model's integrated variable.
                    let d = match (given, dm.as_deref_mut()) {
                        (Some(given), _) => Some(given[i]),
                        (None, Some(dm)) => {
                            dm[k] = damage_at(m, state.damage_state[i]);
                            Some(dm[k])
                        }
                        (None, None) => None,
                    };
                    pd[k] = match d {
                        Some(d) => damaged_pressure(pt.pressure, d),
                        None => pt.pressure,
                    };
                    g[k] = match &m.strength {
                        Some(model) if solid => {
                            let st = self.strength_state(state, i, pt.pressure);
                            if self.scheme.damaged_moduli {
                                model.damaged_shear_modulus(&st)
                            } else {
                                model.shear_modulus(&st)
                            }
                        }
                        _ => 0.0,
                    };
                    cl[k] = sph_damage::longitudinal_speed(pt.sound_speed, g[k], p.density[i]);
                    if let (Some(adh), Some(d)) = (adh.as_deref_mut(), d) {
                        let rho_c2 = p.density[i] * pt.sound_speed * pt.sound_speed;
                        adh[k] = sph_damage::decoupling::past_adhesion(pt.pressure, d, rho_c2);
                    }
                }
            });
        terms
    }
}
