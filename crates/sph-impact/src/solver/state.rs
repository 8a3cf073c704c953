//! The evolved state and the per-stage scratch arrays.

use crate::solver::boundary::{Boundary, Ghost};
use serde::{Deserialize, Serialize};
use sph_core::{Dimension, Particles, Permutation, Tensor, Vector};

/// What the integrator evolves: the particles (x, v, m, ρ, e, h, material, id), the
/// ASPH tensors when in use, and the initial spacing (for the artificial stress).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct State<D: Dimension> {
    /// Particle fields.
    pub particles: Particles<D>,
    /// ASPH smoothing tensors H (1/m), empty in scalar-h mode.
    pub h_tensor: Vec<D::Tensor>,
    /// Initial particle spacing Δp (m), per particle.
    pub spacing0: Vec<f64>,
    /// Deviatoric stress S (Pa) as a 3×3 (the out-of-plane components of 1-D uniaxial
    /// strain and 2-D plane strain included); empty when no material has strength.
    pub stress: Vec<sph_core::glam::DMat3>,
    /// Equivalent plastic strain; empty when no material has strength.
    pub plastic_strain: Vec<f64>,
    /// Pseudo-plastic strain ε_pp = ∫ (dS/dt)_elastic / G dt as a 3×3, the strain that
    /// activates flaws for a damage model with
    /// [`sph_damage::ActivationStrain::PseudoPlastic`]; empty unless some material's
    /// damage model asks for it.
    pub pseudo_strain: Vec<sph_core::glam::DMat3>,
    /// Equivalent plastic strain rate (1/s) of the last step, for rate-dependent strength
    /// (Johnson–Cook); empty when no material has strength.
    pub plastic_strain_rate: Vec<f64>,
    /// The damage model's integrated variable s = D^(1/p) (paper §3.3; sph-damage's
    /// [`sph_damage::DamageVariable`]), per particle; empty when no material has damage.
    pub damage_state: Vec<f64>,
    /// The damage tensor **D** (3×3, the out-of-plane or hoop direction included) of the
    /// particles of tensor-damage materials (sph_damage::tensor); zero for the others,
    /// whose D is their [`Self::damage_state`]. Empty unless some material's damage is a
    /// tensor. For those particles `damage_state` holds s of **D**'s largest eigenvalue.
    pub damage_tensor: Vec<sph_core::glam::DMat3>,
    /// Each particle's index in its material's damage model (its flaws), fixed at set-up;
    /// empty when no material has damage.
    pub damage_index: Vec<u32>,
    /// Simulated time (s).
    pub time: f64,
    /// Completed steps.
    pub step: u64,
}

impl<D: Dimension> Default for State<D> {
    /// No particles, at t = 0 (what [`crate::Simulation::step`] leaves in place while it
    /// works on the state).
    fn default() -> Self {
        State {
            particles: Particles::default(),
            h_tensor: Vec::new(),
            spacing0: Vec::new(),
            stress: Vec::new(),
            plastic_strain: Vec::new(),
            pseudo_strain: Vec::new(),
            plastic_strain_rate: Vec::new(),
            damage_state: Vec::new(),
            damage_tensor: Vec::new(),
            damage_index: Vec::new(),
            time: 0.0,
            step: 0,
        }
    }
}

impl<D: Dimension> State<D> {
    /// Makes `self` a copy of `source`'s evolving fields, reusing `self`'s allocations
    /// (the derived `clone_from` would allocate anew). The fields that never change
    /// during a run (mass, material, id, Δp0, damage index) are not copied: the
    /// integrator lends them with [`Self::swap_constants`].
    pub(crate) fn copy_evolving_from(&mut self, source: &State<D>) {
        // Destructured so that a field added to either struct fails to compile here
        // until it is either copied or listed as constant.
        let State {
            particles,
            h_tensor,
            spacing0: _,
            stress,
            plastic_strain,
            pseudo_strain,
            plastic_strain_rate,
            damage_state,
            damage_tensor,
            damage_index: _,
            time,
            step,
        } = source;
        let Particles {
            position,
            velocity,
            mass: _,
            density,
            specific_energy,
            smoothing_length,
            material: _,
            id: _,
        } = particles;
        let p = &mut self.particles;
        p.position.clone_from(position);
        p.velocity.clone_from(velocity);
        p.density.clone_from(density);
        p.specific_energy.clone_from(specific_energy);
        p.smoothing_length.clone_from(smoothing_length);
        self.h_tensor.clone_from(h_tensor);
        self.stress.clone_from(stress);
        self.plastic_strain.clone_from(plastic_strain);
        self.pseudo_strain.clone_from(pseudo_strain);
        self.plastic_strain_rate.clone_from(plastic_strain_rate);
        self.damage_state.clone_from(damage_state);
        self.damage_tensor.clone_from(damage_tensor);
        self.time = *time;
        self.step = *step;
    }

    /// Exchanges the constant fields (those [`Self::copy_evolving_from`] skips) with
    /// `other`: the RK2 midpoint state borrows them from the step's start state for its
    /// stage and gives them back, so they are held once (30 bytes per particle).
    pub(crate) fn swap_constants(&mut self, other: &mut State<D>) {
        let (p, q) = (&mut self.particles, &mut other.particles);
        std::mem::swap(&mut p.mass, &mut q.mass);
        std::mem::swap(&mut p.material, &mut q.material);
        std::mem::swap(&mut p.id, &mut q.id);
        std::mem::swap(&mut self.spacing0, &mut other.spacing0);
        std::mem::swap(&mut self.damage_index, &mut other.damage_index);
    }
}

/// An operation on one per-particle field of two states at a time
/// ([`State::zip_fields`]): generic over the field's element type.
trait FieldOp {
    fn apply<T: Clone>(&mut self, a: &mut Vec<T>, b: &mut Vec<T>);
}

impl<D: Dimension> State<D> {
    /// Applies `op` to each per-particle field of `a` with the same field of `b`.
    /// Destructured so that a field added to the struct fails to compile here until it
    /// is listed.
    fn zip_fields(a: &mut State<D>, b: &mut State<D>, op: &mut impl FieldOp) {
        let State {
            particles: pa,
            h_tensor: a_h,
            spacing0: a_s0,
            stress: a_s,
            plastic_strain: a_ep,
            pseudo_strain: a_pp,
            plastic_strain_rate: a_epr,
            damage_state: a_d,
            damage_tensor: a_dt,
            damage_index: a_di,
            time: _,
            step: _,
        } = a;
        let Particles {
            position: a_x,
            velocity: a_v,
            mass: a_m,
            density: a_rho,
            specific_energy: a_e,
            smoothing_length: a_sl,
            material: a_mat,
            id: a_id,
        } = pa;
        let pb = &mut b.particles;
        op.apply(a_x, &mut pb.position);
        op.apply(a_v, &mut pb.velocity);
        op.apply(a_m, &mut pb.mass);
        op.apply(a_rho, &mut pb.density);
        op.apply(a_e, &mut pb.specific_energy);
        op.apply(a_sl, &mut pb.smoothing_length);
        op.apply(a_mat, &mut pb.material);
        op.apply(a_id, &mut pb.id);
        op.apply(a_h, &mut b.h_tensor);
        op.apply(a_s0, &mut b.spacing0);
        op.apply(a_s, &mut b.stress);
        op.apply(a_ep, &mut b.plastic_strain);
        op.apply(a_pp, &mut b.pseudo_strain);
        op.apply(a_epr, &mut b.plastic_strain_rate);
        op.apply(a_d, &mut b.damage_state);
        op.apply(a_dt, &mut b.damage_tensor);
        op.apply(a_di, &mut b.damage_index);
    }

    /// Moves the particles with `leave[i]` true out of `self` into a new state (same time
    /// and step), both keeping their order. Every per-particle field moves with its
    /// particle; fields that are empty (a model not in use) stay empty.
    pub(crate) fn split_off(&mut self, leave: &[bool]) -> State<D> {
        struct Split<'l>(&'l [bool]);
        impl FieldOp for Split<'_> {
            fn apply<T: Clone>(&mut self, a: &mut Vec<T>, b: &mut Vec<T>) {
                *b = take_where(a, self.0);
            }
        }
        let mut out = State {
            time: self.time,
            step: self.step,
            ..State::default()
        };
        Self::zip_fields(self, &mut out, &mut Split(leave));
        out
    }

    /// A copy of the particles with `keep[i]` true (same time and step), in order; `self`
    /// is left as it is (the walk over the fields takes it mutably).
    pub(crate) fn copy_rows(&mut self, keep: &[bool]) -> State<D> {
        struct CopyRows<'k>(&'k [bool]);
        impl FieldOp for CopyRows<'_> {
            fn apply<T: Clone>(&mut self, a: &mut Vec<T>, b: &mut Vec<T>) {
                *b = a
                    .iter()
                    .zip(self.0)
                    .filter(|(_, keep)| **keep)
                    .map(|(x, _)| x.clone())
                    .collect();
            }
        }
        let mut out = State {
            time: self.time,
            step: self.step,
            ..State::default()
        };
        Self::zip_fields(self, &mut out, &mut CopyRows(keep));
        out
    }

    /// Overwrites the particles `start..start + n` with the `n` of `other` (a state with
    /// the same fields in use), every field.
    pub(crate) fn overwrite_rows(&mut self, start: usize, other: &mut State<D>) {
        struct Overwrite(usize);
        impl FieldOp for Overwrite {
            fn apply<T: Clone>(&mut self, a: &mut Vec<T>, b: &mut Vec<T>) {
                if !b.is_empty() {
                    a[self.0..self.0 + b.len()].clone_from_slice(b);
                }
            }
        }
        Self::zip_fields(self, other, &mut Overwrite(start));
    }

    /// Appends the particles of `other` (a state [`Self::split_off`] made from this one,
    /// so the same fields are in use) after `self`'s.
    pub(crate) fn append(&mut self, other: &mut State<D>) {
        struct Append;
        impl FieldOp for Append {
            fn apply<T: Clone>(&mut self, a: &mut Vec<T>, b: &mut Vec<T>) {
                a.extend_from_slice(b);
            }
        }
        Self::zip_fields(self, other, &mut Append);
    }

    /// Reorders every per-particle field with `perm` (`perm[new] = old`); fields that
    /// are empty (a model not in use) stay empty.
    pub(crate) fn reorder(&mut self, perm: &Permutation) {
        struct Reorder<'p>(&'p Permutation);
        impl FieldOp for Reorder<'_> {
            fn apply<T: Clone>(&mut self, a: &mut Vec<T>, _: &mut Vec<T>) {
                if !a.is_empty() {
                    self.0
                        .apply("state field", a)
                        .expect("a field in use has one entry per particle");
                }
            }
        }
        Self::zip_fields(self, &mut State::default(), &mut Reorder(perm));
    }

    /// Keeps the first `n` particles (undoes an [`Self::append`]).
    pub(crate) fn truncate(&mut self, n: usize) {
        struct Truncate(usize);
        impl FieldOp for Truncate {
            fn apply<T: Clone>(&mut self, a: &mut Vec<T>, _: &mut Vec<T>) {
                a.truncate(self.0);
            }
        }
        Self::zip_fields(self, &mut State::default(), &mut Truncate(n));
    }
}

/// Removes the elements of `v` with `leave[i]` true and returns them, both parts in
/// order; an empty `v` (a field not in use) gives an empty result.
pub(crate) fn take_where<T>(v: &mut Vec<T>, leave: &[bool]) -> Vec<T> {
    if v.is_empty() {
        return Vec::new();
    }
    debug_assert_eq!(v.len(), leave.len());
    let (mut out, mut keep) = (Vec::new(), Vec::with_capacity(v.len()));
    for (x, &l) in std::mem::take(v).into_iter().zip(leave) {
        if l { out.push(x) } else { keep.push(x) }
    }
    *v = keep;
    out
}

/// Whether a pair of a Verlet list interacts at a stage: where a search of the present
/// supports would list it, by that search's own test (`sph_core::ScalarSupport`:
/// |x_i − x_j|² < max(h_i, h_j)²), between live particles. Each particle's position and
/// support are held together, so that a pair reads its partner's with one bounds test,
/// and a ghost that is not live stands at infinity, where the test fails (|x_i − x_j|² is
/// then infinite or NaN): the same answers as testing liveness apart.
pub(crate) struct PairProbe<D: Dimension>(Vec<(D::Vector, f64)>);

impl<D: Dimension> PairProbe<D> {
    /// Whether the pair (i, j) interacts. Without branches, for
    /// `NeighborList::select_pairs`: about a sixth of a Verlet row fails, in no order a
    /// branch predictor could learn.
    #[inline(always)]
    pub fn interacts(&self, i: usize, j: usize) -> bool {
        let ((xi, hi), (xj, hj)) = (self.0[i], self.0[j]);
        let s = hi.max(hj);
        Vector::norm_squared(xi - xj) < s * s
    }
}

/// The real particles' columns that an [`Extended`] state takes over for a stage: x, v,
/// m, ρ and h, to which the ghosts are appended, given back to the particles (the ghosts
/// cut off) when the pair passes end ([`Extended::release_pair_columns`]). So no second
/// copy of them is alive at the stage's memory peak, pass 2 (72 bytes per particle in
/// 3-D). While they are lent the particles' own columns are empty.
#[derive(Debug, Default)]
pub(crate) struct RealColumns<D: Dimension> {
    position: Vec<D::Vector>,
    velocity: Vec<D::Vector>,
    mass: Vec<f64>,
    density: Vec<f64>,
    h: Vec<f64>,
}

impl<D: Dimension> RealColumns<D> {
    /// Takes the columns out of `p`, leaving them empty there.
    pub fn take(p: &mut Particles<D>) -> Self {
        use std::mem::take;
        RealColumns {
            position: take(&mut p.position),
            velocity: take(&mut p.velocity),
            mass: take(&mut p.mass),
            density: take(&mut p.density),
            h: take(&mut p.smoothing_length),
        }
    }

    /// Gives the columns back to `p`, the first `n` entries of each (the real
    /// particles'; the ghosts' are cut off, their room kept for the next stage). A
    /// summation density that `p` was given meanwhile is replaced by the lent column,
    /// which the stage set to the same values.
    pub fn put_back(self, p: &mut Particles<D>, n: usize) {
        let RealColumns {
            mut position,
            mut velocity,
            mut mass,
            mut density,
            mut h,
        } = self;
        for len in [
            position.len(),
            velocity.len(),
            mass.len(),
            density.len(),
            h.len(),
        ] {
            debug_assert!(
                len >= n,
                "a column lent for a stage holds every real particle"
            );
        }
        position.truncate(n);
        velocity.truncate(n);
        mass.truncate(n);
        density.truncate(n);
        h.truncate(n);
        p.position = position;
        p.velocity = velocity;
        p.mass = mass;
        p.density = density;
        p.smoothing_length = h;
    }
}

/// Real particles followed by ghosts, with everything a pair term reads.
#[derive(Clone, Debug, Default)]
pub(crate) struct Extended<'a, D: Dimension> {
    pub n_real: usize,
    pub position: Vec<D::Vector>,
    pub velocity: Vec<D::Vector>,
    pub mass: Vec<f64>,
    pub density: Vec<f64>,
    pub pressure: Vec<f64>,
    pub sound_speed: Vec<f64>,
    pub h: Vec<f64>,
    pub h_tensor: Vec<D::Tensor>,
    pub spacing0: Vec<f64>,
    pub material: Vec<u16>,
    /// For ghosts: the real particle they copy (themselves for real particles).
    pub source: Vec<u32>,
    /// For ghosts only (index k − n_real): the map from the source's vectors to the
    /// ghost's (reflection or identity); real particles map by the identity, which is not
    /// stored (72 bytes per particle in 3-D).
    pub ghost_map: Vec<D::Tensor>,
    /// For ghosts only (index k − n_real): true for the ghosts of a contact wall
    /// ([`Boundary::Contact`]), and for the ghosts other boundaries make of them.
    ghost_unilateral: Vec<bool>,
    /// The real particles' deviatoric stress S, borrowed from the state (empty without
    /// strength): [`Self::stress`] applies the damage when it is read, so the pair passes
    /// hold no copy of it (72 bytes per particle in 3-D).
    real_stress: &'a [sph_core::glam::DMat3],
    /// Ghosts only (index k − n_real): their undamaged stress M S Mᵀ (the damage is
    /// applied when it is read, as for the real particles).
    ghost_stress: Vec<sph_core::glam::DMat3>,
    /// Damage D (empty without damage).
    pub damage: Vec<f64>,
    /// How damage weakens a particle's own deviatoric stress in [`Self::stress`]
    /// (`StressCoupling::own_factor`); the pair terms apply the pair factors themselves.
    pub coupling: sph_damage::StressCoupling,
    /// The damage tensor of every particle, real and ghost (a scalar damage D as D I),
    /// for the pairs' projected coupling; empty unless some material's damage is a
    /// tensor ([`Self::set_damage_tensor`]).
    pub damage_tensor: Vec<sph_core::glam::DMat3>,
    /// Artificial-stress tensor R, in RZ weighted as R (1/r) the way the pair term reads
    /// it (once per particle, not per pair); empty when the artificial stress is off.
    pub astress: Vec<D::Tensor>,
    /// Whether each particle's artificial-stress tensor R has a nonzero entry, ghosts
    /// included (empty when the artificial stress is off): in Cartesian runs a pair of
    /// two zero tensors skips the term.
    pub astress_on: Vec<bool>,
    /// RZ: the hoop component R_θθ of each particle's artificial stress, ghosts included,
    /// which the hoop force balances (empty in Cartesian runs and when the artificial
    /// stress is off).
    pub astress_hoop: Vec<f64>,
    /// Whether each particle is past its adhesion limit (in tension and damaged,
    /// sph_damage::decoupling::past_adhesion); empty unless fractured material is
    /// decoupled (`SchemeConfig::decouple_damaged`).
    pub adhesion: Vec<bool>,
    /// The EOS's bulk sound speed of each particle, for a viscosity that reads it
    /// (`ViscositySoundSpeed::Bulk`); empty otherwise ([`Self::sound_speed`] holds c_L).
    pub bulk_sound_speed: Vec<f64>,
    /// The specific internal energy of each particle, for FSISPH's energy diffusion;
    /// empty unless it is on (`SchemeConfig::energy_diffusion`).
    pub specific_energy: Vec<f64>,
    /// RZ only: each particle's radius r = |x| (ghosts mirrored across the axis keep their
    /// source's); empty in Cartesian runs.
    pub radius: Vec<f64>,
    /// RZ only: the kernel-smoothed radius R̂(r, h) that the denominators η = ρ R̂ use
    /// (axisymmetric.rs); empty in Cartesian runs.
    pub smoothed_radius: Vec<f64>,
    /// The ghosts as placed, in order, when [`Ghosts::Place`] asked to record them: what
    /// [`Ghosts::Replay`] places again from the sources' later positions.
    pub placed: Vec<PlacedGhost<D>>,
    /// With a Verlet list's ghosts ([`Ghosts::SkinPlace`], [`Ghosts::SkinReplay`]): whether each particle is real or a
    /// ghost that a placement from the present positions and supports would make. Empty
    /// otherwise: every particle is.
    live: Vec<bool>,
    /// Whether the ghosts are a Verlet list's (not every one live): its pairs are picked
    /// with [`Self::pair_probe`] for the pair passes.
    pub skin: bool,
}

/// A ghost as [`Extended::build`] placed it, whether its boundary only pushes, and which
/// boundary (its index in the simulation's) made it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PlacedGhost<D: Dimension> {
    pub ghost: Ghost<D>,
    pub unilateral: bool,
    pub boundary: usize,
}

/// How [`Extended::build`] makes the ghosts.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Ghosts<'p, D: Dimension> {
    /// Every boundary's ghosts of the particles now within their support of it;
    /// `record` keeps them in [`Extended::placed`].
    Place { record: bool },
    /// The same ghosts as an earlier build, in the same order, placed from their
    /// sources' present positions: the ghost indices of a neighbour list built then stay
    /// valid (`SchemeConfig::neighbour_search`).
    Replay(&'p [PlacedGhost<D>]),
    /// A Verlet list's ghosts, placed (`NeighbourSearch::Verlet`): every boundary's ghosts
    /// of the particles within `reach` of it, in the order of [`Self::Place`], recorded
    /// in [`Extended::placed`]; each is live as with [`Self::SkinReplay`].
    SkinPlace { reach: &'p [f64] },
    /// A Verlet list's ghosts again, in their order. Each ghost is live where its source
    /// is (a real particle always) and the boundary would make it of the source's present
    /// position with the present support; a live ghost stands where that placement puts
    /// it, to the bit.
    SkinReplay(&'p [PlacedGhost<D>]),
}

impl<'a, D: Dimension> Extended<'a, D> {
    /// True when the particles carry a deviatoric stress (some material has strength).
    #[inline]
    pub fn has_stress(&self) -> bool {
        !self.real_stress.is_empty()
    }

    /// The damaged deviatoric stress of particle k (real or ghost): (1 − D) S, or S where
    /// damage acts on the yield strength only ([`Self::coupling`]); only when
    /// [`Self::has_stress`].
    #[inline]
    pub fn stress(&self, k: usize) -> sph_core::glam::DMat3 {
        match self.damage.get(k) {
            Some(&d) => self.undamaged_stress(k) * self.coupling.own_factor(d),
            None => self.undamaged_stress(k),
        }
    }

    /// The deviatoric stress S of particle k (real or ghost) before damage weakens it;
    /// only when [`Self::has_stress`].
    #[inline]
    pub fn undamaged_stress(&self, k: usize) -> sph_core::glam::DMat3 {
        if k < self.n_real {
            self.real_stress[k]
        } else {
            self.ghost_stress[k - self.n_real]
        }
    }

    /// True when particle k is a ghost of a contact wall, which pushes but cannot pull
    /// (false for real particles).
    #[inline]
    pub fn is_unilateral(&self, k: usize) -> bool {
        k >= self.n_real && self.ghost_unilateral[k - self.n_real]
    }

    /// Frees the columns only the pair passes read, keeping those the stage reads after
    /// them (the pressures, the damage and its tensor, the placed ghosts): the damage
    /// rates that follow the passes then allocate theirs without the passes' columns
    /// alive (the stage's memory peak). Returns the real particles' columns it took
    /// over ([`RealColumns`]), to be given back to them.
    #[must_use = "the real particles' columns go back to them"]
    pub fn release_pair_columns(&mut self) -> RealColumns<D> {
        let Extended {
            n_real: _,
            position,
            velocity,
            mass,
            density,
            pressure: _,
            sound_speed,
            h,
            h_tensor,
            spacing0,
            material,
            source,
            ghost_map,
            ghost_unilateral,
            real_stress: _,
            ghost_stress,
            damage: _,
            coupling: _,
            damage_tensor: _,
            astress,
            astress_on,
            astress_hoop,
            adhesion,
            bulk_sound_speed,
            specific_energy,
            radius,
            smoothed_radius,
            placed: _,
            live,
            skin: _,
        } = self;
        let columns = RealColumns {
            position: std::mem::take(position),
            velocity: std::mem::take(velocity),
            mass: std::mem::take(mass),
            density: std::mem::take(density),
            h: std::mem::take(h),
        };
        *sound_speed = Vec::new();
        *h_tensor = Vec::new();
        *spacing0 = Vec::new();
        *material = Vec::new();
        *source = Vec::new();
        *ghost_map = Vec::new();
        *ghost_unilateral = Vec::new();
        *ghost_stress = Vec::new();
        *astress = Vec::new();
        *astress_on = Vec::new();
        *astress_hoop = Vec::new();
        *adhesion = Vec::new();
        *bulk_sound_speed = Vec::new();
        *specific_energy = Vec::new();
        *radius = Vec::new();
        *smoothed_radius = Vec::new();
        *live = Vec::new();
        columns
    }

    /// The test of a Verlet list's pairs at this stage ([`Self::skin`]; [`PairProbe`]).
    pub fn pair_probe(&self) -> PairProbe<D> {
        use rayon::prelude::*;
        let far = D::Vector::splat(f64::INFINITY);
        PairProbe(
            (0..self.position.len())
                .into_par_iter()
                .with_min_len(1024)
                .map(|k| {
                    let x = if self.is_live(k) {
                        self.position[k]
                    } else {
                        far
                    };
                    (x, self.h[k])
                })
                .collect(),
        )
    }

    /// Whether particle k is real or a live ghost (every particle without a Verlet
    /// list's ghosts).
    #[inline]
    fn is_live(&self, k: usize) -> bool {
        self.live.get(k).is_none_or(|&l| l)
    }

    /// The map of particle k's vectors from its source's (identity for real particles).
    #[inline]
    pub fn map(&self, k: usize) -> D::Tensor {
        if k < self.n_real {
            D::Tensor::IDENTITY
        } else {
            self.ghost_map[k - self.n_real]
        }
    }

    /// The real particles of `state` with `columns` (their x, v, m, ρ and h, taken
    /// from them: [`RealColumns`]), and the ghosts of every boundary appended, each
    /// boundary seeing the real particles and the ghosts made before it (so corners
    /// of two periodic axes are filled).
    /// `pressure` is the damaged pressure P_D and `damage` the damage D of each real
    /// particle (empty without damage); the stress is stored as (1 − D) S. The
    /// per-particle arrays given are taken over (the ghosts are appended to them), not
    /// copied.
    pub fn build(
        state: &State<D>,
        columns: RealColumns<D>,
        stress: &'a [sph_core::glam::DMat3],
        pressure: Vec<f64>,
        sound_speed: Vec<f64>,
        damage: Vec<f64>,
        support: &[f64],
        boundaries: &[Boundary<D>],
        ghosts: Ghosts<'_, D>,
    ) -> Self {
        let p = &state.particles;
        let RealColumns {
            position,
            velocity,
            mass,
            density,
            h,
        } = columns;
        let n = position.len();
        let mut ext = Extended {
            n_real: n,
            position,
            velocity,
            mass,
            density,
            pressure,
            sound_speed,
            h,
            h_tensor: state.h_tensor.clone(),
            spacing0: state.spacing0.clone(),
            material: p.material.clone(),
            source: (0..n as u32).collect(),
            ghost_map: Vec::new(),
            ghost_unilateral: Vec::new(),
            real_stress: stress,
            ghost_stress: Vec::new(),
            damage,
            coupling: sph_damage::StressCoupling::default(),
            damage_tensor: Vec::new(),
            astress: Vec::new(),
            astress_on: Vec::new(),
            astress_hoop: Vec::new(),
            adhesion: Vec::new(),
            bulk_sound_speed: Vec::new(),
            specific_energy: Vec::new(),
            radius: Vec::new(),
            smoothed_radius: Vec::new(),
            placed: Vec::new(),
            live: Vec::new(),
            skin: false,
        };
        let mut radius = support.to_vec();
        match ghosts {
            Ghosts::Place { record } => {
                let mut made: Vec<Ghost<D>> = Vec::new();
                for (index, b) in boundaries.iter().enumerate() {
                    made.clear();
                    b.ghosts(&ext.position, &radius, &mut made);
                    ext.reserve_ghosts(made.len(), &mut radius);
                    for g in &made {
                        let placed = PlacedGhost {
                            ghost: *g,
                            unilateral: b.is_unilateral(),
                            boundary: index,
                        };
                        ext.push_ghost(&placed, &mut radius);
                        if record {
                            ext.placed.push(placed);
                        }
                    }
                }
            }
            Ghosts::Replay(plan) => {
                ext.reserve_ghosts(plan.len(), &mut radius);
                for p in plan {
                    let placed = PlacedGhost {
                        ghost: p.ghost.moved_to(ext.position[p.ghost.source]),
                        ..*p
                    };
                    ext.push_ghost(&placed, &mut radius);
                }
            }
            Ghosts::SkinPlace { reach } => {
                let plan = skin_plan(&ext.position, reach, boundaries);
                ext.place_live(&plan, boundaries, &mut radius);
            }
            Ghosts::SkinReplay(plan) => ext.place_live(plan, boundaries, &mut radius),
        }
        ext
    }

    /// Appends a Verlet list's ghosts `plan`, in order, each placed from its source's
    /// present position and marked live where the boundary would make it now with the
    /// present support `radius` (and its source is live): [`Ghosts::SkinReplay`].
    fn place_live(
        &mut self,
        plan: &[PlacedGhost<D>],
        boundaries: &[Boundary<D>],
        radius: &mut Vec<f64>,
    ) {
        self.skin = true;
        self.live = vec![true; self.n_real];
        self.reserve_ghosts(plan.len(), radius);
        self.live.reserve_exact(plan.len());
        for p in plan {
            let s = p.ghost.source;
            let x = self.position[s];
            // Live where its source is and the boundary would place it now; the others
            // follow their source and take no part in any pair.
            let fresh = boundaries[p.boundary]
                .ghost_of(s, x, radius[s])
                .filter(|g| g.offset == p.ghost.offset && self.is_live(s));
            self.live.push(fresh.is_some());
            let placed = PlacedGhost {
                ghost: fresh.unwrap_or_else(|| p.ghost.moved_to(x)),
                ..*p
            };
            self.push_ghost(&placed, radius);
            self.placed.push(placed);
        }
    }

    /// Room for `extra` more ghosts in the columns [`Self::push_ghost`] appends to,
    /// exactly: the real particles' columns go back to them with this room
    /// ([`RealColumns`]), and a column that grew by doubling would keep twice their size.
    fn reserve_ghosts(&mut self, extra: usize, radius: &mut Vec<f64>) {
        self.position.reserve_exact(extra);
        self.velocity.reserve_exact(extra);
        self.mass.reserve_exact(extra);
        self.density.reserve_exact(extra);
        self.pressure.reserve_exact(extra);
        self.sound_speed.reserve_exact(extra);
        self.h.reserve_exact(extra);
        if !self.h_tensor.is_empty() {
            self.h_tensor.reserve_exact(extra);
        }
        self.spacing0.reserve_exact(extra);
        self.material.reserve_exact(extra);
        self.source.reserve_exact(extra);
        self.ghost_map.reserve_exact(extra);
        self.ghost_unilateral.reserve_exact(extra);
        if self.has_stress() {
            self.ghost_stress.reserve_exact(extra);
        }
        if !self.damage.is_empty() {
            self.damage.reserve_exact(extra);
        }
        radius.reserve_exact(extra);
    }

    /// Appends one ghost, its fields copied from its source (`radius` is the support of
    /// every particle so far, which a later boundary's ghosts read).
    fn push_ghost(&mut self, placed: &PlacedGhost<D>, radius: &mut Vec<f64>) {
        let g = &placed.ghost;
        let s = g.source;
        self.position.push(g.position);
        self.velocity.push(g.map.mul_vec(self.velocity[s]));
        self.mass.push(self.mass[s]);
        self.density.push(self.density[s]);
        self.pressure.push(self.pressure[s]);
        self.sound_speed.push(self.sound_speed[s]);
        self.h.push(self.h[s]);
        if !self.h_tensor.is_empty() {
            // H maps as a quadratic form: H' = M H Mᵀ for an orthogonal map M.
            let hm = g
                .map
                .mul_tensor(&self.h_tensor[s])
                .mul_tensor(&g.map.transpose());
            self.h_tensor.push(hm);
        }
        self.spacing0.push(self.spacing0[s]);
        self.material.push(self.material[s]);
        self.source.push(self.source[s]);
        let composed = g.map.mul_tensor(&self.map(s));
        self.ghost_map.push(composed);
        let unilateral = placed.unilateral || self.is_unilateral(s);
        self.ghost_unilateral.push(unilateral);
        if self.has_stress() {
            // A stress maps as a tensor: S' = M S Mᵀ with M the reflection in 3-D.
            let m = embed_map::<D>(&g.map);
            let sm = m * self.undamaged_stress(s) * m.transpose();
            self.ghost_stress.push(sm);
        }
        if !self.damage.is_empty() {
            self.damage.push(self.damage[s]);
        }
        radius.push(radius[s]);
    }
}

impl<D: Dimension> Extended<'_, D> {
    /// A per-particle field of the real particles extended over the ghosts (each ghost
    /// takes its source's value): for scalar fields that a mirror does not change.
    pub fn over_ghosts<T: Copy>(&self, mut real: Vec<T>) -> Vec<T> {
        debug_assert_eq!(real.len(), self.n_real);
        let ghosts: Vec<T> = self.source[self.n_real..]
            .iter()
            .map(|&s| real[s as usize])
            .collect();
        real.extend(ghosts);
        real
    }

    /// Sets the damage tensors of the real particles and maps them onto the ghosts like
    /// the stress (**D**' = M **D** Mᵀ).
    pub fn set_damage_tensor(&mut self, mut real: Vec<sph_core::glam::DMat3>) {
        debug_assert_eq!(real.len(), self.n_real);
        real.reserve(self.position.len() - self.n_real);
        for k in self.n_real..self.position.len() {
            let m = embed_map::<D>(&self.ghost_map[k - self.n_real]);
            let src = self.source[k] as usize;
            real.push(m * real[src] * m.transpose());
        }
        self.damage_tensor = real;
    }
}

/// A Verlet list's ghosts of the real particles at `position` with reach `reach`: each
/// boundary over the particles and the ghosts made before it, in the order of
/// [`Ghosts::Place`], with every ghost some support up to the reach can make
/// (`Boundary::ghosts_within`).
pub(crate) fn skin_plan<D: Dimension>(
    position: &[D::Vector],
    reach: &[f64],
    boundaries: &[Boundary<D>],
) -> Vec<PlacedGhost<D>> {
    let n = position.len();
    let mut reach = reach.to_vec();
    let mut plan: Vec<PlacedGhost<D>> = Vec::new();
    let mut made = Vec::new();
    for (index, b) in boundaries.iter().enumerate() {
        let placed = plan.len();
        for k in 0..n + placed {
            let x = match k.checked_sub(n) {
                None => position[k],
                Some(g) => plan[g].ghost.position,
            };
            made.clear();
            b.ghosts_within(k, x, reach[k], &mut made);
            for &ghost in &made {
                reach.push(reach[k]);
                plan.push(PlacedGhost {
                    ghost,
                    unilateral: b.is_unilateral(),
                    boundary: index,
                });
            }
        }
    }
    plan
}

/// An orthogonal map of D dimensions as a 3×3 that leaves the components beyond D alone
/// (the out-of-plane or hoop direction of 1-D and 2-D runs).
fn embed_map<D: Dimension>(map: &D::Tensor) -> sph_core::glam::DMat3 {
    D::embed(map)
        + sph_core::glam::DMat3::from_diagonal(sph_core::glam::DVec3::new(
            if D::DIM > 0 { 0.0 } else { 1.0 },
            if D::DIM > 1 { 0.0 } else { 1.0 },
            if D::DIM > 2 { 0.0 } else { 1.0 },
        ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::{Dim2, glam::DVec2};

    /// The probe's test is the search's |x_i − x_j|² < max(h_i, h_j)², and a ghost that is
    /// not live (at infinity) pairs with nothing, itself included.
    #[test]
    fn the_pair_probe_is_the_search_test_between_live_particles() {
        let far = DVec2::splat(f64::INFINITY);
        let probe = PairProbe::<Dim2>(vec![
            (DVec2::new(0.0, 0.0), 1.0),
            (DVec2::new(0.9, 0.0), 0.5),
            (DVec2::new(0.0, 1.5), 2.0),
            (DVec2::new(3.0, 0.0), 1.0),
            (far, 1.0),
        ]);
        // Within the larger support only: the test is symmetric.
        for (i, j, expected) in [(0, 1, true), (0, 2, true), (1, 2, true), (0, 3, false)] {
            assert_eq!(probe.interacts(i, j), expected, "({i}, {j})");
            assert_eq!(probe.interacts(j, i), expected, "({j}, {i})");
        }
        // Exactly at the support: not a pair (strict test).
        let edge = PairProbe::<Dim2>(vec![(DVec2::ZERO, 1.0), (DVec2::new(1.0, 0.0), 1.0)]);
        assert!(!edge.interacts(0, 1));
        for k in 0..5 {
            assert!(!probe.interacts(k, 4), "({k}, dead ghost)");
            assert!(!probe.interacts(4, k), "(dead ghost, {k})");
        }
    }
}
