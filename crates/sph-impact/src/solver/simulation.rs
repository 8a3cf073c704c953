//! The simulation: state, materials, scheme and boundaries, advanced with the
//! second-order Runge–Kutta (midpoint) method and the adaptive CFL step (paper §2.5).

use crate::solver::axisymmetric::{
    Geometry, HoopInput, SmoothedRadius, add_hoop_terms, hoop_strain_rate, radius,
    reference_spacing, ring_area, ring_density_for_area,
};
use crate::solver::boundary::Boundary;
use crate::solver::config::{
    CrackLength, DensityForm, EnergyForm, NeighbourSearch, SchemeConfig, SmoothingMode,
};
use crate::solver::damage::{
    DamageEvents, DamageRate, DamageStageInput, TensorRate, activates_on_pseudo_strain,
    add_shear_damage, advance_damage, damage_at, damage_of, damage_rates, damaged_pressure,
    fragment_densities, has_tensor_damage, tensor_damage_rates,
};
use crate::solver::derivatives::{
    GradientOptions, GradientSet, PairRates, Rates, gradients, rates, summation_density,
};
use crate::solver::error::SolverError;
use crate::solver::free_flight::{FreeFlight, leaving};
use crate::solver::material::Material;
use crate::solver::pair_blocks;
use crate::solver::pair_kernel::{
    PairKernel, ScalarPairKernel, TensorPairKernel, equivalent_radius,
};
use crate::solver::pair_rules::{NoPairRule, PairRule};
use crate::solver::ranks::{self, Halo, OneRank, Ranks};
use crate::solver::state::{Extended, Ghosts, PairProbe, PlacedGhost, RealColumns, State};
use crate::solver::timestep::{TimestepVote, acceleration_vote, cfl_vote, density_vote};
use crate::solver::warm_threads::KeepAwake;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use sph_core::{
    CellList, Dimension, NeighborList, PairSelection, Pairs, Particles, Permutation, ScalarSupport,
    Tensor, TensorSupport, Vector,
};
use sph_damage::DamageForm;
use sph_kernel::Kernel;
use sph_riemann::ViscositySoundSpeed;
use std::ops::Range;
use std::time::Instant;

mod advance;
mod checkpoint;
mod local_stage;
mod particle_terms;
mod smoothing;
mod stage;
mod stress;
mod verlet;
pub use checkpoint::SolverCheckpoint;
use particle_terms::ParticleTerms;
use stage::{Stage, Topology, eos_pass};
use verlet::SkinBuild;

/// Particles per task of the per-particle passes that write several arrays at once
/// (modules `advance`, `stress`, `particle_terms`, the artificial stresses of `stage`):
/// small enough to share a few thousand rings between threads, large enough that a
/// task's bookkeeping is negligible.
const PASS_CHUNK: usize = 512;

/// `v` by chunks of [`PASS_CHUNK`] as `Some`, or `n_chunks` times `None` when `v` is
/// empty ([`crate::solver::chunks::chunks_or_none`]).
fn chunks_or_none<T: Send>(
    v: &mut [T],
    n_chunks: usize,
) -> impl IndexedParallelIterator<Item = Option<&mut [T]>> {
    crate::solver::chunks::chunks_or_none(v, PASS_CHUNK, n_chunks)
}

/// Wall-clock seconds spent per phase, and the work done.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PhaseTimes {
    /// The neighbour search (`CellList::neighbors`) and, with a Verlet list, each stage's
    /// test of whether the kept list still holds and, where pass 1 does not pick them as
    /// it reads the rows (counted in [`Self::gradients`] then), its picking of the
    /// stage's pairs.
    pub neighbours: f64,
    /// The pair arrays around it: supports, ghosts, RZ radii, summation density and
    /// artificial stresses.
    #[serde(default)]
    pub setup: f64,
    /// The per-particle terms before the pairs: the equation of state, damage, damaged
    /// pressures, shear moduli, signal speeds and adhesion flags (one pass).
    pub eos: f64,
    /// Gradient pass (pass 1), with a Verlet list in one process its picking of the
    /// stage's pairs too.
    pub gradients: f64,
    /// Pair loop (rates).
    pub pairs: f64,
    /// The time-step vote, state updates, smoothing lengths, checks.
    pub integration: f64,
    /// The ranks' gathers of the pair passes' rows (0 on one rank; solver/ranks.rs).
    #[serde(default)]
    pub exchange: f64,
    /// Particle-derivative evaluations (particles × stages).
    pub derivative_evaluations: u64,
    /// Neighbours listed for those particles, summed over the evaluations: the mean
    /// neighbour count is this over `derivative_evaluations`.
    #[serde(default)]
    pub neighbour_entries: u64,
    /// Neighbour searches made (two per step with a search at each stage, one with
    /// `neighbour_search = "each-step"`, fewer with a Verlet list).
    #[serde(default)]
    pub searches: u64,
}

impl PhaseTimes {
    /// Total of the phases.
    pub fn total(&self) -> f64 {
        self.neighbours
            + self.setup
            + self.eos
            + self.gradients
            + self.pairs
            + self.integration
            + self.exchange
    }
}

/// Mass, momentum and energy totals.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(bound = "")]
pub struct Conserved<D: Dimension> {
    /// Σ m.
    pub mass: f64,
    /// Σ m v.
    pub momentum: D::Vector,
    /// Σ ½ m v².
    pub kinetic: f64,
    /// Σ m e.
    pub internal: f64,
}

impl<D: Dimension> Conserved<D> {
    /// Kinetic + internal.
    pub fn energy(&self) -> f64 {
        self.kinetic + self.internal
    }
}

/// What one step did.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StepInfo {
    /// The step taken (s).
    pub dt: f64,
    /// The vote that set it (before clipping to an end time).
    pub vote: TimestepVote,
    /// Particles moved back into the domain by a boundary this step.
    pub boundary_corrections: usize,
}

/// A running simulation.
pub struct Simulation<D: Dimension, K: Kernel, R: PairRule<D> = NoPairRule> {
    /// The evolved state.
    pub state: State<D>,
    /// Materials by id.
    pub materials: Vec<Material>,
    /// The numerical scheme.
    pub scheme: SchemeConfig,
    /// Boundary conditions.
    pub boundaries: Vec<Boundary<D>>,
    /// Time per phase so far.
    pub timings: PhaseTimes,
    /// Momentum delivered by the boundaries so far (ghost forces and particles mirrored
    /// back through walls): Σ m v(t) − Σ m v(0) equals this up to round-off.
    pub boundary_impulse: D::Vector,
    /// What the damage bounds did so far (instant failures, caps at the active-flaw
    /// fraction).
    pub damage_events: DamageEvents,
    /// How many times a solid particle's density was raised to its floor at the end of
    /// a step (`SchemeConfig::solid_density_floor`).
    pub density_floor_events: u64,
    /// RZ only: how many times a ring crossed the axis within a step and was mirrored
    /// back to r > 0 by the axis wall (issue 6 asks that none does); 0 in the other
    /// geometries.
    pub axis_crossings: u64,
    /// RZ only: how many times a ring's RK2 midpoint position lay across the axis
    /// (r < 0). The midpoint is not corrected, its rates are what they are, so this
    /// counts crossings the end-of-step mirror never sees; 0 in the other geometries.
    pub axis_crossings_midpoint: u64,
    /// Particles whose velocity is held at its value (a clamp, a driven end); empty
    /// when none. See [`Self::hold_velocity`].
    held: Vec<bool>,
    /// RZ with summation density: the kernel-smoothed radius table.
    smoothed_radius: Option<SmoothedRadius>,
    /// RZ only: each particle's radius at set-up, r₀ (the artificial stress' reference
    /// spacing scales with √(r₀/r); `axisymmetric::reference_spacing`); empty otherwise.
    radius0: Vec<f64>,
    /// The first step's vote (the reference of `SchemeConfig::dt_floor_fraction`).
    first_dt: Option<f64>,
    /// Rows per block of the pair passes; None: the automatic size. See
    /// [`Self::set_pair_block_rows`].
    pair_block_rows: Option<usize>,
    /// Whether the pair passes always run their loops that read the scheme's choices
    /// (see [`Self::set_generic_pair_loop`]).
    generic_pair_loop: bool,
    kernel: K,
    /// The user's own pair force (`with_pair_rule`); `NoPairRule` by default.
    pair_rule: R,
    search: CellList,
    /// On several ranks: each block of the pair passes' rows' cost (its neighbours and
    /// rows) at the last evaluation, which shares the blocks out at the next (search
    /// included); empty on one rank, and when the particle count has changed.
    block_costs: Vec<u64>,
    /// The particles in free flight (`SchemeConfig::free_flight_above`).
    flight: FreeFlight<D>,
    /// The midpoint state's storage, kept from step to step and overwritten in place:
    /// allocating it anew between the two stages of every step left the heap
    /// fragmented, resident memory 90 bytes per particle above the live peak (solid3d
    /// bench).
    midpoint: State<D>,
    /// A Verlet list kept for the next stage (`NeighbourSearch::Verlet`).
    kept: Option<Topology<D>>,
    /// Whether the next step keeps the pool's threads awake (solver/warm_threads.rs).
    keep_awake: KeepAwake,
}

impl<D: Dimension, K: Kernel> Simulation<D, K> {
    /// Checks everything and prepares the run. `spacing0` is each particle's initial
    /// spacing (for the artificial stress); pass `None` to take h/n_target.
    pub fn new(
        particles: Particles<D>,
        materials: Vec<Material>,
        scheme: SchemeConfig,
        kernel: K,
        boundaries: Vec<Boundary<D>>,
        spacing0: Option<Vec<f64>>,
    ) -> Result<Self, SolverError> {
        scheme.validate()?;
        particles.validate()?;
        for (index, &m) in particles.material.iter().enumerate() {
            if m as usize >= materials.len() {
                return Err(SolverError::UnknownMaterial {
                    index,
                    material: m,
                    count: materials.len(),
                });
            }
        }
        for (index, b) in boundaries.iter().enumerate() {
            b.validate()
                .map_err(|reason| SolverError::BadBoundary { index, reason })?;
        }
        let mut boundaries = boundaries;
        if scheme.geometry == Geometry::Axisymmetric {
            check_axisymmetric(&particles)?;
            // The axis is a mirror: ghosts with v_r and S_rz reversed.
            let axis = Boundary::axis();
            if !boundaries.contains(&axis) {
                boundaries.push(axis);
            }
        }
        let n = particles.len();
        let spacing0 = spacing0.unwrap_or_else(|| {
            particles
                .smoothing_length
                .iter()
                .map(|h| h / scheme.n_target)
                .collect()
        });
        if spacing0.len() != n {
            return Err(SolverError::BadState(sph_core::CoreError::LengthMismatch {
                what: "spacing0",
                expected: n,
                got: spacing0.len(),
            }));
        }
        let h_tensor = match scheme.smoothing {
            SmoothingMode::Scalar => Vec::new(),
            SmoothingMode::Asph { .. } => particles
                .smoothing_length
                .iter()
                .map(|&h| D::Tensor::IDENTITY * (1.0 / h))
                .collect(),
        };
        let solid = materials.iter().any(|m| m.strength.is_some());
        let (stress, plastic_strain) = if solid {
            (vec![sph_core::glam::DMat3::ZERO; n], vec![0.0; n])
        } else {
            (Vec::new(), Vec::new())
        };
        let (damage_state, damage_index) = damage_setup(&particles, &materials)?;
        // The pseudo-plastic strain only when a damage model activates on it (it needs
        // the deviatoric stress rate, so only with strength).
        let pseudo_strain = if solid && materials.iter().any(activates_on_pseudo_strain) {
            vec![sph_core::glam::DMat3::ZERO; n]
        } else {
            Vec::new()
        };
        let damage_tensor = if materials.iter().any(has_tensor_damage) {
            vec![sph_core::glam::DMat3::ZERO; n]
        } else {
            Vec::new()
        };
        let rz = scheme.geometry == Geometry::Axisymmetric;
        let radius0 = if rz {
            particles.position.iter().map(|x| radius(*x)).collect()
        } else {
            Vec::new()
        };
        Ok(Self {
            state: State {
                particles,
                h_tensor,
                spacing0,
                stress,
                plastic_strain_rate: plastic_strain.clone(),
                plastic_strain,
                pseudo_strain,
                damage_state,
                damage_tensor,
                damage_index,
                time: 0.0,
                step: 0,
            },
            materials,
            scheme,
            boundaries,
            timings: PhaseTimes::default(),
            boundary_impulse: D::Vector::ZERO,
            damage_events: DamageEvents::default(),
            density_floor_events: 0,
            axis_crossings: 0,
            axis_crossings_midpoint: 0,
            held: Vec::new(),
            first_dt: None,
            pair_block_rows: None,
            generic_pair_loop: false,
            radius0,
            smoothed_radius: rz.then(|| {
                SmoothedRadius::new(|u, v| {
                    kernel.w(D::Vector::from_fn(|k| if k == 0 { u } else { v }), 1.0)
                })
            }),
            kernel,
            pair_rule: NoPairRule,
            search: CellList::new(),
            block_costs: Vec::new(),
            flight: FreeFlight::default(),
            midpoint: State::default(),
            kept: None,
            keep_awake: KeepAwake::default(),
        })
    }

    /// This simulation with `rule`'s force added to every pair's (solver/pair_rules/user.rs):
    /// the rule is compiled into the pair loop, so the default, `NoPairRule`, costs
    /// nothing. The rule is not part of a checkpoint: give it again after `restore`.
    pub fn with_pair_rule<R: PairRule<D>>(self, rule: R) -> Simulation<D, K, R> {
        Simulation {
            state: self.state,
            materials: self.materials,
            scheme: self.scheme,
            boundaries: self.boundaries,
            timings: self.timings,
            boundary_impulse: self.boundary_impulse,
            damage_events: self.damage_events,
            density_floor_events: self.density_floor_events,
            axis_crossings: self.axis_crossings,
            axis_crossings_midpoint: self.axis_crossings_midpoint,
            held: self.held,
            smoothed_radius: self.smoothed_radius,
            radius0: self.radius0,
            first_dt: self.first_dt,
            pair_block_rows: self.pair_block_rows,
            generic_pair_loop: self.generic_pair_loop,
            kernel: self.kernel,
            pair_rule: rule,
            search: self.search,
            block_costs: self.block_costs,
            flight: self.flight,
            midpoint: self.midpoint,
            kept: self.kept,
            keep_awake: self.keep_awake,
        }
    }
}

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// Sets the rows per block of the pair passes (None: the automatic size, which
    /// depends on the particle count only). A pair of two particles in one block is
    /// evaluated once for both, any other from each side, so `Some(1)` evaluates every
    /// pair from both of its particles, as a plain gather does: the results then differ
    /// from the automatic blocks only at round-off, which is how the pair-once
    /// evaluation is tested (tests/pair_once.rs). Results never depend on the thread
    /// count. Panics if `rows` is `Some(0)`.
    pub fn set_pair_block_rows(&mut self, rows: Option<usize>) {
        assert!(
            rows != Some(0),
            "a block of the pair passes needs at least one row"
        );
        self.pair_block_rows = rows;
    }

    /// Whether the pair passes run, for every scheme, their loops that read the scheme's
    /// choices per pair. By default (`false`) a scheme that makes the paper's choices
    /// runs loops compiled with them as constants, which execute fewer instructions
    /// (solver/derivatives/pair_scheme.rs, and `GradientOptions::STUDY` for pass 1); both
    /// do the same arithmetic in the same order, so results are the same to the bit
    /// either way, which is what this setting is for: tests/pair_scheme.rs compares the
    /// two.
    pub fn set_generic_pair_loop(&mut self, generic: bool) {
        self.generic_pair_loop = generic;
    }

    /// Holds the velocity of the particles at `indices` at their current value for the
    /// rest of the run (a clamp at zero velocity, or an end driven at constant speed):
    /// they move with it and take part in every pair sum, but their own acceleration is
    /// discarded. The force the constraint exerts is added to
    /// [`Self::boundary_impulse`], so momentum still balances.
    pub fn hold_velocity(
        &mut self,
        indices: impl IntoIterator<Item = usize>,
    ) -> Result<(), SolverError> {
        let n = self.state.particles.len();
        if self.held.is_empty() {
            self.held = vec![false; n];
        }
        for i in indices {
            if i >= n {
                return Err(SolverError::BadConfig {
                    field: "hold_velocity",
                    value: i as f64,
                    reason: "particle index out of range",
                });
            }
            self.held[i] = true;
        }
        Ok(())
    }

    /// Reorders the particles (`perm[new] = old`), every per-particle field with them
    /// (state, flaws' indices, held flags, RZ set-up radii). Sorting them along a
    /// space-filling curve ([`sph_core::morton_order`]) puts neighbours close in memory,
    /// which the pair loops read at random otherwise. The order changes which pair
    /// sums come first, so results differ from another order's at round-off; for a
    /// given order they are identical for any thread count.
    ///
    /// Errors if `perm` does not have one entry per particle or particles are in free
    /// flight (they have left the arrays).
    pub fn reorder_particles(&mut self, perm: &Permutation) -> Result<(), SolverError> {
        let n = self.state.particles.len();
        if perm.len() != n || self.flight.len() > 0 {
            return Err(SolverError::BadConfig {
                field: "reorder_particles",
                value: perm.len() as f64,
                reason: "the permutation must cover every particle, none in free flight",
            });
        }
        self.state.reorder(perm);
        if !self.radius0.is_empty() {
            perm.apply("radius0", &mut self.radius0)?;
        }
        if !self.held.is_empty() {
            perm.apply("held", &mut self.held)?;
        }
        // The midpoint's storage is refilled from the state at each step.
        self.midpoint = State::default();
        Ok(())
    }

    /// Damage D of every particle (0 for particles without a damage model).
    pub fn damage(&self) -> Vec<f64> {
        let d = damage_of(&self.state, &self.materials);
        if d.is_empty() {
            vec![0.0; self.state.particles.len()]
        } else {
            d
        }
    }

    /// Pressure and sound speed of every particle from its material's EOS.
    pub fn pressure_and_sound_speed(&self) -> (Vec<f64>, Vec<f64>) {
        eos_pass(&self.state.particles, &self.materials)
    }

    /// RZ only: the axis crossings so far, (mirrored back at the end of a step, found in
    /// a midpoint state); `None` in the other geometries.
    pub fn axis_crossing_counts(&self) -> Option<(u64, u64)> {
        (self.scheme.geometry == Geometry::Axisymmetric)
            .then_some((self.axis_crossings, self.axis_crossings_midpoint))
    }

    /// RZ: how many of `positions` lie across the axis (r < 0); 0 in other geometries.
    fn across_axis(&self, positions: &[D::Vector]) -> u64 {
        if self.scheme.geometry != Geometry::Axisymmetric {
            return 0;
        }
        positions.iter().filter(|x| x.component(0) < 0.0).count() as u64
    }

    /// Mass, momentum and energy totals of the current state, the particles in free
    /// flight included.
    pub fn conserved(&self) -> Conserved<D> {
        let mut c = Conserved {
            mass: 0.0,
            momentum: D::Vector::ZERO,
            kinetic: 0.0,
            internal: 0.0,
        };
        for p in [&self.state.particles, &self.flight.state.particles] {
            for i in 0..p.len() {
                let m = p.mass[i];
                c.mass += m;
                c.momentum += p.velocity[i] * m;
                c.kinetic += 0.5 * m * p.velocity[i].norm_squared();
                c.internal += m * p.specific_energy[i];
            }
        }
        c
    }

    /// How many particles are in free flight (`SchemeConfig::free_flight_above`): out
    /// of [`Self::state`], moving at constant velocity.
    pub fn in_free_flight(&self) -> usize {
        self.flight.len()
    }

    /// Calls `f` with the particles in free flight appended to [`Self::state`] at their
    /// present positions (after the particles still in the hydrodynamics, in the order
    /// they left), then takes them out again: how the outputs see every particle.
    pub fn with_free_flight<T>(&mut self, f: impl FnOnce(&Self) -> T) -> T {
        if self.flight.len() == 0 {
            return f(self);
        }
        let n = self.state.particles.len();
        self.join_flight();
        let r = f(self);
        self.state.truncate(n);
        self.held.truncate(n);
        self.radius0.truncate(n);
        r
    }

    /// Puts the particles in free flight back into [`Self::state`] for good (at the end
    /// of a run, so the final state holds every particle). Steps taken after this let
    /// them leave again.
    pub fn end_free_flight(&mut self) {
        self.join_flight();
        self.flight = FreeFlight::default();
    }

    /// Appends the particles in flight to the state (and their held flags and RZ radii).
    fn join_flight(&mut self) {
        self.state.append(&mut self.flight.state);
        if !self.held.is_empty() {
            // Flags set after the particles left (hold_velocity) do not cover them.
            if self.flight.held.is_empty() {
                self.held.resize(self.state.particles.len(), false);
            } else {
                self.held.extend_from_slice(&self.flight.held);
            }
        }
        self.radius0.extend_from_slice(&self.flight.radius0);
    }

    /// One RK2 (midpoint) step, at most `max_dt` long.
    ///
    /// On an error before the update (a stage that fails, a collapsed time step) the state
    /// is left as it was; when the updated state fails the check (a non-finite or
    /// non-positive value, [`SolverError::Unphysical`]) the state is that rejected update,
    /// for post-mortem output. The step works on the state in place rather than on a copy
    /// of it: one state fewer at the step's memory peak.
    pub fn step(&mut self, max_dt: f64) -> Result<StepInfo, SolverError> {
        self.step_over(max_dt, &OneRank)
    }

    /// [`Self::step`] with its pair passes shared out among `ranks` (solver/ranks.rs):
    /// every rank calls it with the same state and `max_dt`, and every rank ends the
    /// step with the same state, the same bits as [`Self::step`] gives.
    pub fn step_over(&mut self, max_dt: f64, ranks: &dyn Ranks) -> Result<StepInfo, SolverError> {
        // The pool's other threads stay awake between a short step's passes
        // (warm_threads.rs).
        let started = Instant::now();
        let _warm = self.keep_awake.for_step();
        let mut s0_state = std::mem::take(&mut self.state);
        // One search per step (NeighbourSearch::EachStep): the first stage keeps its list
        // and ghosts for the second. A Verlet list is kept while it holds.
        let search = self.scheme.neighbour_search;
        let kept = self.verlet_list_for(&s0_state);
        let keep = search != NeighbourSearch::EachStage;
        let (s0, topology) = match self.stage(&mut s0_state, kept, keep, ranks, None) {
            Ok(stage) => stage,
            Err(e) => return Err(self.put_back(s0_state, e)),
        };
        // The vote counts with the update that follows it (PhaseTimes::integration).
        let t0 = Instant::now();
        let vote = self.vote(&s0_state, &s0);
        let dt = vote.dt.min(max_dt);
        // The floor applies to the vote, not to a step shortened to land on an end time.
        let floor = self.first_dt.get_or_insert(vote.dt).to_owned() * self.scheme.dt_floor_fraction;
        if !(dt > 0.0 && dt.is_finite()) || vote.dt < floor {
            let step = s0_state.step;
            // Where the collapse is, for the post-mortem (the particle that bound it).
            let p = &s0_state.particles;
            let (position, density, specific_energy, speed, smoothing_length) =
                match p.id.iter().position(|&id| id == vote.particle_id) {
                    Some(i) => (
                        p.position[i].to_array3(),
                        p.density[i],
                        p.specific_energy[i],
                        p.velocity[i].norm(),
                        p.smoothing_length[i],
                    ),
                    None => ([f64::NAN; 3], f64::NAN, f64::NAN, f64::NAN, f64::NAN),
                };
            let error = SolverError::TimestepCollapse {
                step,
                dt: vote.dt,
                min: floor,
                id: vote.particle_id,
                reason: vote.reason,
                position,
                density,
                specific_energy,
                speed,
                smoothing_length,
            };
            return Err(self.put_back(s0_state, error));
        }
        let mut half = std::mem::take(&mut self.midpoint);
        half.copy_evolving_from(&s0_state);
        // The midpoint holds the constant fields until the step's end; the start state
        // does not read them meanwhile.
        half.swap_constants(&mut s0_state);
        self.advance(&mut half, &s0_state, &s0, 0.5 * dt);
        self.axis_crossings_midpoint += self.across_axis(&half.particles.position);
        let fragment_below =
            fragment_densities(&self.materials, self.scheme.fragment_density_ratio);
        if !half.damage_state.is_empty() {
            advance_damage(
                &mut half,
                &s0_state.damage_state,
                &s0_state.damage_tensor,
                &self.materials,
                &fragment_below,
                &s0.damage_rates,
                &s0.tensor_rates,
                0.5 * dt,
            );
            add_shear_damage(
                &mut half,
                &s0_state.plastic_strain,
                &s0.pressure,
                &self.materials,
            );
        }
        // The first stage's rates are spent: free them before the second stage allocates
        // its own (peak memory per particle).
        drop(s0);
        self.timings.integration += t0.elapsed().as_secs_f64();
        let verlet = search == NeighbourSearch::Verlet;
        let reuse = if verlet {
            self.kept = topology;
            self.verlet_list_for(&half)
        } else {
            topology
        };
        let stage = self.stage(&mut half, reuse, verlet, ranks, None);
        half.swap_constants(&mut s0_state);
        let (s1, kept) = match stage {
            Ok(stage) => stage,
            Err(e) => return Err(self.put_back(s0_state, e)),
        };
        self.kept = kept;
        let t1 = Instant::now();
        let mut next = s0_state;
        // The step's start plastic strain, for shear failure's Δε_p (only when in use).
        let shear = self.materials.iter().any(|m| m.shear_failure.is_some());
        let plastic_strain_0 = if shear {
            next.plastic_strain.clone()
        } else {
            Vec::new()
        };
        // x_{n+1} = x_n + dt v_{1/2}; the other fields with the midpoint rates.
        self.advance_with_velocity(&mut next, &half.particles.velocity, &s1, dt, &half);
        self.midpoint = half;
        self.density_floor_events += self.floor_density(&mut next);
        if !next.damage_state.is_empty() {
            let s_start = next.damage_state.clone();
            let t_start = next.damage_tensor.clone();
            let ev = advance_damage(
                &mut next,
                &s_start,
                &t_start,
                &self.materials,
                &fragment_below,
                &s1.damage_rates,
                &s1.tensor_rates,
                dt,
            );
            self.damage_events.add(ev);
            if shear {
                let ev =
                    add_shear_damage(&mut next, &plastic_strain_0, &s1.pressure, &self.materials);
                self.damage_events.add(ev);
            }
        }
        // The midpoint stage's ghost forces act over the whole step (v_{n+1} = v_n + dt a_½).
        let m = &next.particles.mass;
        let impulse = s1
            .boundary
            .iter()
            .fold(D::Vector::ZERO, |acc, &(i, dv)| acc + dv * m[i as usize]);
        self.boundary_impulse += impulse * dt;
        // A held particle's discarded acceleration is the constraint's force on it:
        // −m_i a_i, applied over the step (the sum above counted the ghost part of a_i,
        // which the held particle does not feel either).
        for (i, _) in self.held.iter().enumerate().filter(|(_, h)| **h) {
            self.boundary_impulse -= s1.rates[i].dv * (m[i] * dt);
        }
        // The axis mirror below brings these back.
        self.axis_crossings += self.across_axis(&next.particles.position);
        let mut corrections = 0;
        for i in 0..next.particles.len() {
            for b in &self.boundaries {
                let before = next.particles.velocity[i];
                let (x, v) = (
                    &mut next.particles.position[i],
                    &mut next.particles.velocity[i],
                );
                if b.enforce(x, v) {
                    corrections += 1;
                    self.boundary_impulse +=
                        (next.particles.velocity[i] - before) * next.particles.mass[i];
                }
            }
        }
        next.time += dt;
        next.step += 1;
        let checked = self.check(&next);
        self.state = next;
        checked?;
        self.flight.drift(dt);
        if let Some(z) = self.scheme.free_flight_above {
            let leave = leaving(&self.state, z, &self.boundaries, &self.held);
            self.flight
                .take(&mut self.state, &mut self.held, &mut self.radius0, &leave);
        }
        self.timings.integration += t1.elapsed().as_secs_f64();
        self.keep_awake.step_took(started.elapsed());
        Ok(StepInfo {
            dt,
            vote,
            boundary_corrections: corrections,
        })
    }

    /// The kept Verlet list, taken, if it holds for `state` (simulation/verlet.rs);
    /// `None` otherwise and without a Verlet list. The test's time counts as neighbour
    /// time (`PhaseTimes::neighbours`).
    fn verlet_list_for(&mut self, state: &State<D>) -> Option<Topology<D>> {
        let skin = self.scheme.skin()?;
        let kept = self.kept.take()?;
        let build = kept.skin.as_ref()?;
        let t = Instant::now();
        let holds = build.holds(skin, state, &self.boundaries, kept.ghosts());
        self.timings.neighbours += t.elapsed().as_secs_f64();
        holds.then_some(kept)
    }

    /// Puts the step's start state back (an error before the update) and passes the
    /// error on.
    fn put_back(&mut self, start: State<D>, e: SolverError) -> SolverError {
        self.state = start;
        e
    }

    /// With summation density, recomputes ρ (and h) from the current positions, so that
    /// output reflects the final state; a no-op for the evolved density forms.
    pub fn sync_density(&mut self) -> Result<(), SolverError> {
        if self.scheme.density == DensityForm::Summation {
            let mut s = self.state.clone();
            // On one rank: the state is every rank's (solver/ranks.rs).
            self.stage(&mut s, None, false, &OneRank, None)?;
            self.state.particles.density = s.particles.density;
        }
        Ok(())
    }

    /// Rejects non-finite or non-physical states, naming the particle.
    fn check(&self, s: &State<D>) -> Result<(), SolverError> {
        let p = &s.particles;
        for i in 0..p.len() {
            let bad = |what, value| SolverError::Unphysical {
                step: s.step,
                time: s.time,
                id: p.id[i],
                position: p.position[i].to_array3(),
                what,
                value,
            };
            if !p.position[i].all_finite() {
                return Err(bad("position", f64::NAN));
            }
            if !p.velocity[i].all_finite() {
                return Err(bad("velocity", f64::NAN));
            }
            if !(p.density[i] > 0.0 && p.density[i].is_finite()) {
                return Err(bad("density", p.density[i]));
            }
            if !p.specific_energy[i].is_finite() {
                return Err(bad("specific energy", p.specific_energy[i]));
            }
        }
        Ok(())
    }

    /// Runs until `t_end` (the last step is shortened to land on it), calling
    /// `on_step` after every step. Returns the number of steps taken.
    pub fn run_until(
        &mut self,
        t_end: f64,
        mut on_step: impl FnMut(&Self, &StepInfo),
    ) -> Result<u64, SolverError> {
        let mut steps = 0;
        while self.state.time < t_end * (1.0 - 1e-14) {
            let info = self.step(t_end - self.state.time)?;
            steps += 1;
            on_step(self, &info);
        }
        self.sync_density()?;
        Ok(steps)
    }

    /// The kernel in use.
    pub fn kernel(&self) -> &K {
        &self.kernel
    }
}

/// Checks damage models (solids only, flaw counts) and numbers each particle within its
/// material for the model's per-particle state. Empty vectors when no material has
/// damage.
fn damage_setup<D: Dimension>(
    particles: &Particles<D>,
    materials: &[Material],
) -> Result<(Vec<f64>, Vec<u32>), SolverError> {
    for (m, mat) in materials.iter().enumerate() {
        // Shear failure raises the scalar D of a damage model; without one (or with a
        // tensor) there is no D for it to raise.
        let scalar = mat
            .damage
            .as_ref()
            .is_some_and(|d| d.form() == DamageForm::Scalar);
        if mat.shear_failure.is_some() && !scalar {
            return Err(SolverError::Material(format!(
                "material {m} ({}): shear failure needs a scalar damage model \
                 (max-tensile-stress or benz-asphaug with form = \"scalar\")",
                mat.name
            )));
        }
    }
    if materials.iter().all(|m| m.damage.is_none()) {
        return Ok((Vec::new(), Vec::new()));
    }
    let mut count = vec![0u32; materials.len()];
    let index: Vec<u32> = particles
        .material
        .iter()
        .map(|&m| {
            let k = count[m as usize];
            count[m as usize] += 1;
            k
        })
        .collect();
    for (m, mat) in materials.iter().enumerate() {
        if let Some(model) = &mat.damage {
            if mat.strength.is_none() {
                return Err(SolverError::Material(format!(
                    "material {m} ({}): a damage model needs a strength model (only solids \
                     can be damaged)",
                    mat.name
                )));
            }
            model.check_particles(count[m] as usize).map_err(|e| {
                SolverError::Material(format!(
                    "material {m} ({}): damage model does not fit its {} particles: {e}",
                    mat.name, count[m]
                ))
            })?;
        }
    }
    Ok((vec![0.0; particles.len()], index))
}

/// RZ needs 2-D particles strictly off the axis (x = r > 0).
fn check_axisymmetric<D: Dimension>(p: &Particles<D>) -> Result<(), SolverError> {
    if D::DIM != 2 {
        return Err(SolverError::BadConfig {
            field: "geometry",
            value: D::DIM as f64,
            reason: "axisymmetric (RZ) runs are 2-D: (r, z) particles",
        });
    }
    for (i, x) in p.position.iter().enumerate() {
        if !(x.component(0) > 0.0) {
            return Err(SolverError::BadConfig {
                field: "geometry",
                value: x.component(0),
                reason: if i == 0 {
                    "RZ particle 0 has r ≤ 0: every particle needs r = x > 0"
                } else {
                    "an RZ particle has r ≤ 0: every particle needs r = x > 0"
                },
            });
        }
    }
    Ok(())
}
