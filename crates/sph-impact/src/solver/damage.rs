//! Damage in the solver (paper §2, §3.3): the per-stage damage evaluation and the
//! bounded update of the integrated variable s = D^(1/p); the damaged pressure P_D is
//! sph-damage's (`sph_damage::damaged_pressure`).
//!
//! Damage weakens tension and shear only: σ = (1 − D) S − P_D I with P_D = (1 − D) P
//! for P < 0 and P otherwise (paper §2). The flaws activate on the local strain
//! σ_1/((1 − D) E) of the total stress (Benz & Asphaug 1994, 1995), and cracks grow over
//! the particle's own spacing Δx (the "particle size" of Benz & Asphaug) at a fraction of
//! c_L.

use crate::solver::material::Material;
use crate::solver::state::State;
use rayon::prelude::*;
use sph_core::Dimension;
use sph_core::glam::{DMat3, DVec3};
use sph_damage::tensor::{DirectionalGrowth, grow, largest_damage, principal_strains};
use sph_damage::{BoundAction, DamageBounds, DamageForm, DamageInput, apply_bounds};

pub(crate) use sph_damage::damaged_pressure;

/// D of every particle from its integrated variable (empty when no material has damage;
/// 0 for particles of materials without a damage model).
pub(crate) fn damage_of<D: Dimension>(state: &State<D>, materials: &[Material]) -> Vec<f64> {
    if state.damage_state.is_empty() {
        return Vec::new();
    }
    let p = &state.particles;
    state
        .damage_state
        .iter()
        .zip(&p.material)
        .map(|(&s, &m)| damage_at(&materials[m as usize], s))
        .collect()
}

/// D of a particle of `material` with damage state s (0 without a damage model).
#[inline]
pub(crate) fn damage_at(material: &Material, s: f64) -> f64 {
    match &material.damage {
        Some(model) => model.variable().to_damage(s),
        None => 0.0,
    }
}

/// One particle's damage rate ds/dt and the bounds on D after the update.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DamageRate {
    pub rate: f64,
    pub bounds: DamageBounds,
}

/// What the damage model needs of one particle in one stage.
pub(crate) struct DamageStageInput<'a> {
    /// Deviatoric stress S per real particle (3×3), undamaged: the damage D below is
    /// applied here, σ = (1 − D) S − P_D I (σ = S − P_D I where damage acts on the
    /// yield strength only, [`Self::coupling`]).
    pub stress: &'a [sph_core::glam::DMat3],
    /// Damaged pressure P_D.
    pub pressure: &'a [f64],
    /// Bulk sound speed from the EOS.
    pub sound_speed: &'a [f64],
    /// Shear modulus G.
    pub shear_modulus: &'a [f64],
    /// Damage D.
    pub damage: &'a [f64],
    /// How damage weakens the stress that activates the flaws.
    pub coupling: sph_damage::StressCoupling,
    /// Particle spacing Δx (crack-growth radius).
    pub spacing: &'a [f64],
    /// The spin Ω = ½ (L − Lᵀ) of each particle (3×3), for tensor damage only (empty
    /// otherwise).
    pub spin: &'a [DMat3],
}

/// A tensor-damage particle's growth along its principal strain directions, largest
/// first, and its spin, from one stage (sph_damage::tensor).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TensorRate {
    pub growth: [DirectionalGrowth; 3],
    pub spin: DMat3,
}

impl TensorRate {
    /// No growth, no rotation (particles of scalar materials).
    const NONE: TensorRate = TensorRate {
        growth: [
            DirectionalGrowth::none(DVec3::X),
            DirectionalGrowth::none(DVec3::Y),
            DirectionalGrowth::none(DVec3::Z),
        ],
        spin: DMat3::ZERO,
    };
}

/// True when the material's damage is a tensor (sph_damage::tensor).
pub(crate) fn has_tensor_damage(material: &Material) -> bool {
    material
        .damage
        .as_ref()
        .is_some_and(|d| d.form() == DamageForm::Tensor)
}

/// E and c_L of particle i from the EOS's bulk modulus K = ρ c² and the shear modulus G.
fn elastic_moduli<D: Dimension>(
    state: &State<D>,
    input: &DamageStageInput<'_>,
    i: usize,
) -> (f64, f64) {
    let rho = state.particles.density[i];
    let c = input.sound_speed[i];
    let g = input.shear_modulus[i];
    (
        sph_damage::youngs_modulus(rho * c * c, g),
        sph_damage::longitudinal_speed(c, g, rho),
    )
}

/// ds/dt and bounds of every particle (rate 0 and bounds [D, D] for particles without a
/// damage model); empty when no material has damage.
pub(crate) fn damage_rates<D: Dimension>(
    state: &State<D>,
    materials: &[Material],
    input: &DamageStageInput<'_>,
) -> Vec<DamageRate> {
    if state.damage_state.is_empty() {
        return Vec::new();
    }
    let p = &state.particles;
    // Per material, once per stage rather than per particle.
    let pseudo: Vec<bool> = materials.iter().map(activates_on_pseudo_strain).collect();
    (0..p.len())
        .into_par_iter()
        .map(|i| {
            let d = input.damage[i];
            let still = DamageRate {
                rate: 0.0,
                bounds: DamageBounds { min: d, max: d },
            };
            let Some(model) = &materials[p.material[i] as usize].damage else {
                return still;
            };
            if model.form() == DamageForm::Tensor {
                // Grown by tensor_damage_rates.
                return still;
            }
            // σ_1 of the total stress σ = (1 − D) S − P_D I (S − P_D I where damage acts
            // on the yield strength only), tension positive; the stored 3×3 includes the
            // out-of-plane components of 1-D and 2-D runs.
            let sigma = input.stress[i] * input.coupling.activation_factor(d)
                - sph_core::glam::DMat3::from_diagonal(sph_core::glam::DVec3::splat(
                    input.pressure[i],
                ));
            // K = ρ c² (the EOS's isentropic bulk modulus), E = 9KG/(3K + G).
            let (e, c_l) = elastic_moduli(state, input, i);
            let index = state.damage_index[i] as usize;
            let mut at = DamageInput {
                max_principal_stress: f64::NAN,
                youngs_modulus: e,
                longitudinal_wave_speed: c_l,
                particle_size: input.spacing[i],
                damage: d,
                // λ_max of the pseudo-plastic strain (3×3: in RZ with the hoop entry)
                // where the model activates on it; none is tracked in a run without
                // strength, where it stays zero.
                principal_strain: pseudo[p.material[i] as usize].then(|| {
                    state
                        .pseudo_strain
                        .get(i)
                        .map_or(0.0, sph_damage::max_principal_stress)
                }),
            };
            // σ_1 is an eigenvalue problem (Jacobi rotations). Where Gershgorin's upper
            // bound of it already leaves the model quiet (no flaw activated), the model's
            // result at the bound is its result at σ_1, to the bit
            // (`DamageModel::evaluate_if_quiet`): most of a target is compressed or at
            // rest, and there σ_1 is not needed.
            let quiet = sph_damage::max_principal_stress_bound(&sigma).and_then(|bound| {
                at.max_principal_stress = bound;
                model.evaluate_if_quiet(index, &at)
            });
            let eval = quiet.unwrap_or_else(|| {
                at.max_principal_stress = sph_damage::max_principal_stress(&sigma);
                model.evaluate(index, &at)
            });
            DamageRate {
                rate: eval.rate,
                bounds: eval.bounds,
            }
        })
        .collect()
}

/// The tensor-damage growth of every particle (sph_damage::tensor; [`TensorRate::NONE`]
/// for particles of scalar materials); empty when no material's damage is a tensor.
///
/// The activation strain tensor is the pseudo-plastic strain where the model activates
/// on it, else the stress's, (S − P_D I)/E with the intact deviatoric stress (as
/// Spheral's Benz–Asphaug strain). Along each principal direction n_j with λ_j > 0 the
/// model is evaluated at the damage across it, D_0 = |**D** n_j|, so its local strain
/// is λ_j/(1 − D_0).
pub(crate) fn tensor_damage_rates<D: Dimension>(
    state: &State<D>,
    materials: &[Material],
    input: &DamageStageInput<'_>,
) -> Vec<TensorRate> {
    if state.damage_tensor.is_empty() {
        return Vec::new();
    }
    let p = &state.particles;
    (0..p.len())
        .into_par_iter()
        .map(|i| {
            let Some(model) = &materials[p.material[i] as usize].damage else {
                return TensorRate::NONE;
            };
            if model.form() != DamageForm::Tensor {
                return TensorRate::NONE;
            }
            let (e, c_l) = elastic_moduli(state, input, i);
            let pseudo = model.activation_strain() == sph_damage::ActivationStrain::PseudoPlastic;
            let strain = if pseudo {
                state.pseudo_strain.get(i).copied().unwrap_or(DMat3::ZERO)
            } else {
                (input.stress[i] - DMat3::from_diagonal(DVec3::splat(input.pressure[i])))
                    * (1.0 / e)
            };
            let d = state.damage_tensor[i];
            let growth = principal_strains(&strain).map(|(lambda, n)| {
                if !(lambda > 0.0) {
                    return DirectionalGrowth::none(n);
                }
                let d0 = sph_damage::tensor::projected_damage(&d, n);
                let eval = model.evaluate(
                    state.damage_index[i] as usize,
                    &DamageInput {
                        max_principal_stress: lambda * e,
                        youngs_modulus: e,
                        longitudinal_wave_speed: c_l,
                        particle_size: input.spacing[i],
                        damage: d0,
                        principal_strain: Some(lambda),
                    },
                );
                DirectionalGrowth {
                    direction: n,
                    rate: eval.rate,
                    cap: eval.bounds.max,
                }
            });
            TensorRate {
                growth,
                spin: input.spin.get(i).copied().unwrap_or(DMat3::ZERO),
            }
        })
        .collect()
}

/// True when the material's damage model activates its flaws on the pseudo-plastic
/// strain, which the solver then tracks (sph_damage::activation).
pub(crate) fn activates_on_pseudo_strain(material: &Material) -> bool {
    material
        .damage
        .as_ref()
        .is_some_and(|d| d.activation_strain() == sph_damage::ActivationStrain::PseudoPlastic)
}

/// Counts of what the damage bounds did over a run (nothing is clamped silently).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct DamageEvents {
    /// Updates that raised D to the model's minimum (instant failures).
    pub raised_to_min: u64,
    /// Updates capped at the model's maximum (e.g. the active-flaw fraction n_act/n_tot).
    pub capped_at_max: u64,
    /// Particles set to D = 1 because their density fell below
    /// `SchemeConfig::fragment_density_ratio` × ρ0 (each particle once: D = 1 stays).
    pub fragmented: u64,
    /// Tensor-damage updates whose eigenvalues had to be brought back into [0, 1]
    /// (growth along a direction oblique to earlier damage, or the rotation's round-off).
    pub tensor_rebounded: u64,
    /// Updates in which shear failure raised D (particle-steps; sph_damage::shear_failure).
    #[serde(default)]
    pub shear_raised: u64,
    /// Particles that shear failure brought to D = 1 (each once: D = 1 stays).
    #[serde(default)]
    pub shear_failed: u64,
}

impl DamageEvents {
    /// Adds the counts of `other`.
    pub(crate) fn add(&mut self, other: DamageEvents) {
        self.raised_to_min += other.raised_to_min;
        self.capped_at_max += other.capped_at_max;
        self.fragmented += other.fragmented;
        self.tensor_rebounded += other.tensor_rebounded;
        self.shear_raised += other.shear_raised;
        self.shear_failed += other.shear_failed;
    }
}

/// Shear failure (sph_damage::shear_failure; Collins et al. 2004): D ← min(1, D +
/// Δε_p/ε_f(P)) for the particles of materials with a [`sph_damage::PlasticFailure`] law, where Δε_p
/// is the plastic strain `y` gained since `plastic_strain_0` (the start of the update)
/// and P the pressure of the stage whose rates made it. Called after
/// [`advance_damage`], which integrates the tensile part from the same start, so the
/// two add. Returns the counts of raised and newly whole-damaged particles.
pub(crate) fn add_shear_damage<D: Dimension>(
    y: &mut State<D>,
    plastic_strain_0: &[f64],
    pressure: &[f64],
    materials: &[Material],
) -> DamageEvents {
    let mut events = DamageEvents::default();
    if y.damage_state.is_empty() || materials.iter().all(|m| m.shear_failure.is_none()) {
        return events;
    }
    let p = &y.particles;
    let raised: Vec<Option<(f64, bool)>> = (0..p.len())
        .into_par_iter()
        .map(|i| {
            let mat = &materials[p.material[i] as usize];
            let (Some(law), Some(model)) = (&mat.shear_failure, &mat.damage) else {
                return None;
            };
            let dep = y.plastic_strain[i] - plastic_strain_0[i];
            if dep <= 0.0 {
                return None;
            }
            let variable = model.variable();
            let d0 = variable.to_damage(y.damage_state[i]);
            if d0 >= 1.0 {
                return None;
            }
            let d1 = (d0 + law.damage_increment(dep, pressure[i])).min(1.0);
            Some((variable.from_damage(d1), d1 >= 1.0))
        })
        .collect();
    for (i, r) in raised.into_iter().enumerate() {
        if let Some((s, whole)) = r {
            y.damage_state[i] = s;
            events.shear_raised += 1;
            events.shear_failed += u64::from(whole);
        }
    }
    events
}

/// The density below which each material's particles are fragmented: `ratio` × the
/// EOS's reference density for a material with a damage model, none otherwise (and none
/// for `ratio` = 0).
pub(crate) fn fragment_densities(materials: &[Material], ratio: f64) -> Vec<Option<f64>> {
    materials
        .iter()
        .map(|m| {
            let rho0 = m.eos.reference_density()?;
            (ratio > 0.0 && m.damage.is_some()).then_some(ratio * rho0)
        })
        .collect()
}

/// s ← s0 + dt ds/dt, then the bounds; a particle whose density is below its material's
/// entry of `fragment_below` (from [`fragment_densities`]) is set to D = 1 instead.
/// Tensor-damage particles start from their tensor of `t0` instead: it turns with the
/// stage's spin, **D** += dt (Ω **D** − **D** Ω), grows along the stage's directions
/// (sph_damage::tensor::grow) and its largest eigenvalue sets s; fragmentation makes it
/// I. Returns the counts of bound actions and of new fragmentations. A non-finite state
/// is left for the solver's state check to report.
#[allow(clippy::too_many_arguments)]
pub(crate) fn advance_damage<D: Dimension>(
    y: &mut State<D>,
    s0: &[f64],
    t0: &[DMat3],
    materials: &[Material],
    fragment_below: &[Option<f64>],
    rates: &[DamageRate],
    tensor_rates: &[TensorRate],
    dt: f64,
) -> DamageEvents {
    let p = &y.particles;
    let tensor_form: Vec<bool> = materials.iter().map(has_tensor_damage).collect();
    type Advanced = (f64, BoundAction, bool, Option<(DMat3, bool)>);
    let out: Vec<Advanced> = (0..p.len())
        .into_par_iter()
        .map(|i| {
            let m = p.material[i] as usize;
            let Some(model) = &materials[m].damage else {
                return (s0[i], BoundAction::Within, false, None);
            };
            let variable = model.variable();
            let fragment = fragment_below[m].is_some_and(|rho_f| p.density[i] < rho_f);
            if tensor_form[m] {
                if fragment {
                    let whole = variable.from_damage(1.0);
                    return (
                        whole,
                        BoundAction::Within,
                        t0[i] != DMat3::IDENTITY,
                        Some((DMat3::IDENTITY, false)),
                    );
                }
                let tr = &tensor_rates[i];
                let turned = t0[i] + sph_strength::rotation_terms(&t0[i], &tr.spin) * dt;
                let (d, outcome) = grow(turned, &tr.growth, variable, dt);
                let action = if outcome.capped > 0 {
                    BoundAction::CappedAtMax
                } else {
                    BoundAction::Within
                };
                let s = variable.from_damage(largest_damage(&d));
                return (s, action, false, Some((d, outcome.rebounded)));
            }
            if fragment {
                let whole = variable.from_damage(1.0);
                return (whole, BoundAction::Within, s0[i] != whole, None);
            }
            let s = s0[i] + dt * rates[i].rate;
            let b = apply_bounds(variable, s, rates[i].bounds);
            (b.state, b.action, false, None)
        })
        .collect();
    let mut events = DamageEvents::default();
    for (i, (s, action, fragmented, tensor)) in out.into_iter().enumerate() {
        y.damage_state[i] = s;
        if let Some((d, rebounded)) = tensor {
            y.damage_tensor[i] = d;
            events.tensor_rebounded += u64::from(rebounded);
        }
        match action {
            BoundAction::RaisedToMin => events.raised_to_min += 1,
            BoundAction::CappedAtMax => events.capped_at_max += 1,
            BoundAction::Within | BoundAction::NonFinite => {}
        }
        events.fragmented += u64::from(fragmented);
    }
    events
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two rock particles, one at ρ0 and one expanded to 0.4 ρ0, plus an undamageable
    /// particle at 0.1 ρ0, advanced with zero damage rates.
    fn expanded_rock() -> (State<sph_core::Dim1>, Vec<Material>) {
        use sph_core::{ParticleInit, Particles};
        let rho0 = 2700.0;
        let eos =
            sph_eos::LinearElastic::new(sph_eos::LinearElasticParams { rho0, K0: 26.7e9 }).unwrap();
        let strength = sph_strength::VonMises::new(sph_strength::VonMisesParams {
            yield_strength: 1.0e8,
            shear_modulus: 22.7e9,
            hardening: None,
        })
        .unwrap();
        let rock = Material::solid("rock", eos, strength)
            .with_damage(sph_damage::MaxTensileStress::new(1.0e7).unwrap());
        let metal = Material::solid("metal", eos, strength);
        let mut p = Particles::new();
        for (k, (rho, material)) in [(rho0, 0), (0.4 * rho0, 0), (0.1 * rho0, 1)]
            .into_iter()
            .enumerate()
        {
            p.push(ParticleInit {
                position: k as f64,
                velocity: 0.0,
                mass: 1.0,
                density: rho,
                specific_energy: 0.0,
                smoothing_length: 1.0,
                material,
            });
        }
        let state = State {
            particles: p,
            h_tensor: Vec::new(),
            spacing0: vec![1.0; 3],
            stress: Vec::new(),
            plastic_strain: Vec::new(),
            pseudo_strain: Vec::new(),
            plastic_strain_rate: Vec::new(),
            damage_state: vec![0.3, 0.3, 0.0],
            damage_tensor: Vec::new(),
            damage_index: vec![0, 1, 0],
            time: 0.0,
            step: 0,
        };
        (state, vec![rock, metal])
    }

    #[test]
    fn rock_expanded_below_the_fragment_density_is_whole_damage_counted_once() {
        let (mut y, materials) = expanded_rock();
        let still = DamageRate {
            rate: 0.0,
            bounds: DamageBounds { min: 0.0, max: 1.0 },
        };
        let rates = vec![still; 3];
        let below = fragment_densities(&materials, 0.5);
        assert_eq!(below, vec![Some(1350.0), None]);
        let s0 = y.damage_state.clone();
        let ev = advance_damage(&mut y, &s0, &[], &materials, &below, &rates, &[], 1e-9);
        // ρ0: untouched; 0.4 ρ0: D = 1; the undamageable 0.1 ρ0 particle: untouched.
        assert_eq!(y.damage_state, vec![0.3, 1.0, 0.0]);
        assert_eq!(ev.fragmented, 1);
        let s1 = y.damage_state.clone();
        let again = advance_damage(&mut y, &s1, &[], &materials, &below, &rates, &[], 1e-9);
        assert_eq!((again.fragmented, y.damage_state[1]), (0, 1.0));
        // Ratio 0 disables the rule.
        let (mut y, materials) = expanded_rock();
        let off = fragment_densities(&materials, 0.0);
        let s0 = y.damage_state.clone();
        let ev = advance_damage(&mut y, &s0, &[], &materials, &off, &rates, &[], 1e-9);
        assert_eq!((ev.fragmented, y.damage_state[1]), (0, 0.3));
    }

    #[test]
    fn shear_failure_adds_plastic_strain_over_failure_strain_up_to_whole_damage() {
        let (mut y, mut materials) = expanded_rock();
        let law = sph_damage::PlasticFailure::ROCK_COLLINS2004;
        let variable = materials[0].damage.as_ref().unwrap().variable();
        let d0 = variable.to_damage(0.3);
        let start = vec![1.0e-3, 0.0, 0.0];
        y.plastic_strain = vec![1.0e-3 + 5.0e-5, 2.0e-4, 1.0e-3];
        // Without a law nothing changes.
        let before = y.damage_state.clone();
        let ev = add_shear_damage(&mut y, &start, &[0.0; 3], &materials);
        assert_eq!(
            (y.damage_state.clone(), ev),
            (before, DamageEvents::default())
        );
        materials[0] = materials[0].clone().with_shear_failure(law);
        // At 1.3 GPa ε_f = 0.01: Δε_p = 5e-5 adds 0.005; at 0 Pa ε_f = 1e-4, so 2e-4 breaks
        // the second particle; the third is of a material without damage.
        let ev = add_shear_damage(&mut y, &start, &[1.3e9, 0.0, 0.0], &materials);
        let d = |s: f64| variable.to_damage(s);
        assert!((d(y.damage_state[0]) - (d0 + 0.005)).abs() < 1e-12);
        assert_eq!(d(y.damage_state[1]), 1.0);
        assert_eq!(y.damage_state[2], 0.0);
        assert_eq!((ev.shear_raised, ev.shear_failed), (2, 1));
        // No new plastic strain, no change; a whole particle is not counted again.
        let start = y.plastic_strain.clone();
        let again = add_shear_damage(&mut y, &start, &[0.0; 3], &materials);
        assert_eq!(again, DamageEvents::default());
    }
}
