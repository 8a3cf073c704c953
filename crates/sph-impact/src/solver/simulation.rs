//! The simulation: state, materials, scheme and boundaries, advanced with the
//! second-order Runge–Kutta (midpoint) method and the adaptive CFL step (paper §2.5).

use crate::solver::axisymmetric::{
    Geometry, HoopInput, SmoothedRadius, add_hoop_terms, hoop_strain_rate, radius,
    reference_spacing, ring_area, ring_density_for_area,
};
use crate::solver::boundary::Boundary;
use crate::solver::config::{CrackLength, DensityForm, EnergyForm, SchemeConfig, SmoothingMode};
use crate::solver::damage::{
    DamageEvents, DamageRate, DamageStageInput, TensorRate, activates_on_pseudo_strain,
    add_shear_damage, advance_damage, damage_of, damage_rates, damaged_pressure,
    fragment_densities, has_tensor_damage, tensor_damage_rates,
};
use crate::solver::derivatives::{
    GradientOptions, GradientSet, PairRates, Rates, gradients, rates, summation_density,
};
use crate::solver::error::SolverError;
use crate::solver::free_flight::{FreeFlight, leaving};
use crate::solver::material::Material;
use crate::solver::pair_blocks;
use crate::solver::pair_kernel::{ScalarPairKernel, TensorPairKernel, equivalent_radius};
use crate::solver::state::{Extended, State};
use crate::solver::timestep::{TimestepVote, acceleration_vote, cfl_vote, density_vote};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use sph_core::{
    CellList, Dimension, NeighborList, NeighborSearch, Particles, Permutation, ScalarSupport,
    Tensor, TensorSupport, Vector,
};
use sph_damage::DamageForm;
use sph_kernel::Kernel;
use sph_riemann::ViscositySoundSpeed;
use std::time::Instant;

mod checkpoint;
pub use checkpoint::SolverCheckpoint;

/// Wall-clock seconds spent per phase, and the work done.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PhaseTimes {
    /// The neighbour search itself (`CellList::neighbors`).
    pub neighbours: f64,
    /// The pair arrays around it: supports, moduli, ghosts, RZ radii, summation density
    /// and artificial stresses.
    #[serde(default)]
    pub setup: f64,
    /// Equation-of-state evaluations.
    pub eos: f64,
    /// Gradient pass.
    pub gradients: f64,
    /// Pair loop (rates).
    pub pairs: f64,
    /// State updates, smoothing lengths, checks.
    pub integration: f64,
    /// Particle-derivative evaluations (particles × stages).
    pub derivative_evaluations: u64,
}

impl PhaseTimes {
    /// Total of the phases.
    pub fn total(&self) -> f64 {
        self.neighbours + self.setup + self.eos + self.gradients + self.pairs + self.integration
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

struct Stage<D: Dimension> {
    rates: Vec<Rates<D>>,
    /// (i, the ghosts' part of dv_i/dt) for the particles with ghost neighbours.
    boundary: Vec<(u32, D::Vector)>,
    grads: Option<GradientSet<D>>,
    sound_speed: Vec<f64>,
    pressure: Vec<f64>,
    /// Shear modulus per particle (0 for fluids).
    shear_modulus: Vec<f64>,
    /// Damage rates and bounds (empty without damage).
    damage_rates: Vec<DamageRate>,
    /// Tensor-damage growth (empty unless some material's damage is a tensor).
    tensor_rates: Vec<TensorRate>,
}

/// A running simulation.
pub struct Simulation<D: Dimension, K: Kernel> {
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
    kernel: K,
    search: CellList,
    /// The particles in free flight (`SchemeConfig::free_flight_above`).
    flight: FreeFlight<D>,
    /// The midpoint state's storage, kept from step to step and overwritten in place:
    /// allocating it anew between the two stages of every step left the heap
    /// fragmented, resident memory 90 bytes per particle above the live peak (solid3d
    /// bench).
    midpoint: State<D>,
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
            radius0,
            smoothed_radius: rz.then(|| {
                SmoothedRadius::new(|u, v| {
                    kernel.w(D::Vector::from_fn(|k| if k == 0 { u } else { v }), 1.0)
                })
            }),
            kernel,
            search: CellList::new(),
            flight: FreeFlight::default(),
            midpoint: State::default(),
        })
    }

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
    pub fn with_free_flight<R>(&mut self, f: impl FnOnce(&Self) -> R) -> R {
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

    /// A particle's kernel measure at density `rho` (the length, area or volume per
    /// particle that h follows): m/ρ, in RZ the ring's (r, z) area
    /// (`axisymmetric::ring_area`).
    fn kernel_measure(&self, m: f64, x: D::Vector, rho: f64) -> f64 {
        match self.scheme.geometry {
            Geometry::Cartesian => m / rho,
            Geometry::Axisymmetric => ring_area(m, radius(x), rho),
        }
    }

    /// Particle spacing Δx_i = (smallest support semi-axis)/n_target.
    fn spacing(&self, state: &State<D>, i: usize) -> f64 {
        let h_min = if state.h_tensor.is_empty() {
            state.particles.smoothing_length[i]
        } else {
            1.0 / state.h_tensor[i].sym_eigen().values[D::DIM - 1]
        };
        h_min / self.scheme.n_target
    }

    /// Derivatives of `state`, and the neighbour list used.
    fn stage(&mut self, state: &mut State<D>) -> Result<(Stage<D>, NeighborList), SolverError> {
        let t0 = Instant::now();
        let (pressure, mut sound_speed) = eos_pass(&state.particles, &self.materials);
        let damage = damage_of(state, &self.materials);
        // The pair terms see the damaged pressure P_D (paper §2).
        let pressure_d = damaged_pressures(&pressure, &damage);
        let mut t1 = Instant::now();
        let support: Vec<f64> = if state.h_tensor.is_empty() {
            state.particles.smoothing_length.clone()
        } else {
            state
                .h_tensor
                .iter()
                .map(|h| 1.0 / h.sym_eigen().values[0])
                .collect()
        };
        // A solid's signal speed in the pair's Riemann problem and viscosity is the
        // longitudinal wave speed c_L = √(c² + 4G/(3ρ)) (paper §2.1).
        let mut shear_modulus = self.shear_moduli(state, &pressure);
        let adhesion = self.adhesion_flags(state, &pressure, &sound_speed, &damage);
        // Only what the pair passes read stays alive through them (peak memory): the
        // undamaged pressure and the supports are spent, and P_D, c_L and D move into the
        // extended arrays, which are read back for the real particles below.
        drop(pressure);
        let signal = longitudinal_speeds(&sound_speed, &shear_modulus, &state.particles.density);
        let mut ext = Extended::build(
            state,
            &state.stress,
            pressure_d,
            signal,
            damage,
            &support,
            &self.boundaries,
        );
        ext.coupling = self.scheme.stress_coupling;
        if !adhesion.is_empty() {
            ext.adhesion = ext.over_ghosts(adhesion);
        }
        let bulk_viscosity = self.scheme.viscosity.sound_speed == ViscositySoundSpeed::Bulk;
        if bulk_viscosity {
            ext.bulk_sound_speed = ext.over_ghosts(sound_speed.clone());
        }
        if self.scheme.energy_diffusion > 0.0 {
            ext.specific_energy = ext.over_ghosts(state.particles.specific_energy.clone());
        }
        drop(support);
        let n_real = ext.n_real;
        // D of the real particles (empty without damage).
        let n_damage = ext.damage.len().min(n_real);
        if !state.damage_tensor.is_empty() {
            // The pairs project each particle's damage tensor on their direction; a
            // scalar material's D enters as D I.
            let tensor_form: Vec<bool> = self.materials.iter().map(has_tensor_damage).collect();
            let tensors = (0..n_real)
                .map(|i| {
                    if tensor_form[state.particles.material[i] as usize] {
                        state.damage_tensor[i]
                    } else {
                        sph_core::glam::DMat3::IDENTITY * ext.damage[i]
                    }
                })
                .collect();
            ext.set_damage_tensor(tensors);
        }
        let rz = self.scheme.geometry == Geometry::Axisymmetric;
        if rz {
            ext.radius = ext.position.iter().map(|x| radius(*x)).collect();
            let table = self.smoothed_radius.as_ref().expect("RZ has the table");
            ext.smoothed_radius = ext
                .radius
                .iter()
                .zip(&ext.h)
                .map(|(&r, &h)| table.at(r, h))
                .collect();
            // A mirror ghost stands for the same area of material as its source, so its
            // ring mass per radian scales with its own radius: ρ A r' (a wall normal to
            // r is a cylinder; the axis and walls normal to z leave r unchanged).
            for k in ext.n_real..ext.position.len() {
                let src = ext.source[k] as usize;
                ext.mass[k] *= ext.radius[k] / ext.radius[src];
            }
            // The artificial stress' Δp is the ring's (r, z) spacing at its present radius
            // (a mirror or wall ghost has its source's: it stands for the same area).
            if !self.scheme.artificial_stress.is_off() {
                for k in 0..ext.position.len() {
                    let src = ext.source[k] as usize;
                    ext.spacing0[k] = reference_spacing(
                        state.spacing0[src],
                        self.radius0[src],
                        ext.radius[src],
                        self.scheme.h_max_factor,
                    );
                }
            }
        }
        let t_search = Instant::now();
        let list = if ext.h_tensor.is_empty() {
            self.search
                .neighbors(&ext.position, &ScalarSupport::new(&ext.h)?)?
        } else {
            self.search
                .neighbors(&ext.position, &TensorSupport::new(&ext.h_tensor)?)?
        };
        let search = t_search.elapsed().as_secs_f64();
        if self.scheme.density == DensityForm::Summation {
            // Density from the positions, then the EOS again with it (real and ghosts).
            let rho = if ext.h_tensor.is_empty() {
                summation_density(
                    &ext,
                    &list,
                    &ScalarPairKernel::new(self.kernel, &ext.h, D::DIM),
                    self.smoothed_radius.as_ref(),
                )
            } else {
                summation_density(
                    &ext,
                    &list,
                    &TensorPairKernel {
                        kernel: self.kernel,
                        h_tensor: &ext.h_tensor,
                        h: &ext.h,
                    },
                    self.smoothed_radius.as_ref(),
                )
            };
            state.particles.density = rho;
            let t = Instant::now();
            let pressure;
            (pressure, sound_speed) = eos_pass(&state.particles, &self.materials);
            let pressure_d = damaged_pressures(&pressure, &ext.damage[..n_damage]);
            shear_modulus = self.shear_moduli(state, &pressure);
            let adhesion =
                self.adhesion_flags(state, &pressure, &sound_speed, &ext.damage[..n_damage]);
            if !adhesion.is_empty() {
                ext.adhesion = ext.over_ghosts(adhesion);
            }
            if bulk_viscosity {
                ext.bulk_sound_speed = ext.over_ghosts(sound_speed.clone());
            }
            let signal =
                longitudinal_speeds(&sound_speed, &shear_modulus, &state.particles.density);
            t1 += t.elapsed();
            for k in 0..ext.position.len() {
                let s = ext.source[k] as usize;
                ext.density[k] = state.particles.density[s];
                ext.pressure[k] = pressure_d[s];
                ext.sound_speed[k] = signal[s];
            }
        }
        if !self.scheme.artificial_stress.is_off() {
            ext.astress = artificial_stress_tensors(&ext, &self.scheme.artificial_stress);
        }
        let t2 = Instant::now();
        let need_grads = self.scheme.limiter != sph_riemann::Limiter::None
            || !state.h_tensor.is_empty()
            || self.scheme.gradient_correction
            || self.scheme.momentum_correction
            || self.scheme.grad_h
            || self.scheme.viscosity.switch != sph_riemann::ViscositySwitch::None
            || self.scheme.energy_diffusion > 0.0
            || !state.stress.is_empty();
        let options = GradientOptions {
            correct: self.scheme.gradient_correction,
            correct_strain: self.scheme.strain_rate_correction && !state.stress.is_empty(),
            keep_correction: self.scheme.momentum_correction,
            grad_h: self.scheme.grad_h,
        };
        let rows = self
            .pair_block_rows
            .unwrap_or_else(|| pair_blocks::block_rows(ext.n_real));
        let (grads, rates_out, t3) = if ext.h_tensor.is_empty() {
            let pk = ScalarPairKernel::new(self.kernel, &ext.h, D::DIM);
            let g = need_grads.then(|| gradients(&ext, &list, &pk, options, rows));
            let t3 = Instant::now();
            let r = rates(&ext, &list, &pk, g.as_ref(), &self.scheme, rows);
            (g, r, t3)
        } else {
            let pk = TensorPairKernel {
                kernel: self.kernel,
                h_tensor: &ext.h_tensor,
                h: &ext.h,
            };
            let g = need_grads.then(|| gradients(&ext, &list, &pk, options, rows));
            let t3 = Instant::now();
            let r = rates(&ext, &list, &pk, g.as_ref(), &self.scheme, rows);
            (g, r, t3)
        };
        let PairRates {
            each: mut rates_out,
            boundary,
            hoop_gauge,
        } = rates_out;
        if rz {
            // The hoop stress is weakened by the damage across the hoop direction: D for
            // a scalar damage, D_θθ of a tensor (θ is a principal direction in RZ).
            let hoop_damage: Vec<f64> = if ext.damage_tensor.is_empty() {
                Vec::new()
            } else {
                ext.damage_tensor[..n_real]
                    .iter()
                    .map(|d| d.z_axis.z.clamp(0.0, 1.0))
                    .collect()
            };
            add_hoop_terms(
                &HoopInput {
                    particles: &state.particles,
                    stress: &state.stress,
                    damage: if hoop_damage.is_empty() {
                        &ext.damage[..n_damage]
                    } else {
                        &hoop_damage
                    },
                    pressure: &ext.pressure[..n_real],
                    coupling: self.scheme.stress_coupling,
                    energy: self.scheme.energy,
                    smoothed_radius: self.smoothed_radius.as_ref().expect("RZ has the table"),
                },
                &mut rates_out,
                &hoop_gauge,
            );
        }
        drop(hoop_gauge);
        // The crack-growth length R_s: the spacing, or the support radius (CrackLength).
        let crack_length = match self.scheme.crack_length {
            CrackLength::Spacing => 1.0,
            CrackLength::Support => self.scheme.n_target,
        };
        let spacing: Vec<f64> = if n_damage == 0 {
            Vec::new()
        } else {
            (0..state.particles.len())
                .map(|i| self.spacing(state, i) * crack_length)
                .collect()
        };
        // Tensor damage turns with the particle's spin Ω = ½ (L − Lᵀ).
        let spin: Vec<sph_core::glam::DMat3> = match &grads {
            Some(gr) if !state.damage_tensor.is_empty() => gr
                .each
                .iter()
                .take(n_real)
                .map(|g| sph_strength::spin(&D::embed(&g.strain_velocity)))
                .collect(),
            _ => Vec::new(),
        };
        let damage_input = DamageStageInput {
            stress: &state.stress,
            pressure: &ext.pressure[..n_real],
            sound_speed: &sound_speed,
            shear_modulus: &shear_modulus,
            damage: &ext.damage[..n_damage],
            coupling: self.scheme.stress_coupling,
            spacing: &spacing,
            spin: &spin,
        };
        let damage_rates = damage_rates(state, &self.materials, &damage_input);
        let tensor_rates = tensor_damage_rates(state, &self.materials, &damage_input);
        let t4 = Instant::now();
        self.timings.eos += (t1 - t0).as_secs_f64();
        self.timings.neighbours += search;
        self.timings.setup += (t2 - t1).as_secs_f64() - search;
        self.timings.gradients += (t3 - t2).as_secs_f64();
        self.timings.pairs += (t4 - t3).as_secs_f64();
        self.timings.derivative_evaluations += n_real as u64;
        let mut pressure_d = std::mem::take(&mut ext.pressure);
        pressure_d.truncate(n_real);
        Ok((
            Stage {
                rates: rates_out,
                boundary,
                grads,
                sound_speed,
                pressure: pressure_d,
                shear_modulus,
                damage_rates,
                tensor_rates,
            },
            list,
        ))
    }

    /// The smallest time-step vote of a stage.
    fn vote(&self, state: &State<D>, stage: &Stage<D>) -> TimestepVote {
        let p = &state.particles;
        let mut best = TimestepVote {
            dt: f64::INFINITY,
            particle_id: 0,
            reason: crate::solver::timestep::REASON_NONE,
        };
        for i in 0..p.len() {
            let dx = self.spacing(state, i);
            let r = &stage.rates[i];
            best = best.min(density_vote(self.scheme.cfl, p.density[i], r.drho, p.id[i]));
            // For a solid the signal is the longitudinal wave: c_L² = c² + 4G/(3ρ) (paper §2.5).
            let c_signal = sph_damage::longitudinal_speed(
                stage.sound_speed[i],
                stage.shear_modulus[i],
                p.density[i],
            );
            best = best.min(cfl_vote(self.scheme.cfl, dx, c_signal, r.approach, p.id[i]));
            best = best.min(acceleration_vote(self.scheme.cfl, dx, r.dv.norm(), p.id[i]));
        }
        best
    }

    /// One RK2 (midpoint) step, at most `max_dt` long.
    ///
    /// On an error before the update (a stage that fails, a collapsed time step) the state
    /// is left as it was; when the updated state fails the check (a non-finite or
    /// non-positive value, [`SolverError::Unphysical`]) the state is that rejected update,
    /// for post-mortem output. The step works on the state in place rather than on a copy
    /// of it: one state fewer at the step's memory peak.
    pub fn step(&mut self, max_dt: f64) -> Result<StepInfo, SolverError> {
        let mut s0_state = std::mem::take(&mut self.state);
        let (s0, _) = match self.stage(&mut s0_state) {
            Ok(stage) => stage,
            Err(e) => return Err(self.put_back(s0_state, e)),
        };
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
        let t0 = Instant::now();
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
        let stage = self.stage(&mut half);
        half.swap_constants(&mut s0_state);
        let (s1, _) = match stage {
            Ok(stage) => stage,
            Err(e) => return Err(self.put_back(s0_state, e)),
        };
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
        Ok(StepInfo {
            dt,
            vote,
            boundary_corrections: corrections,
        })
    }

    /// Puts the step's start state back (an error before the update) and passes the
    /// error on.
    fn put_back(&mut self, start: State<D>, e: SolverError) -> SolverError {
        self.state = start;
        e
    }

    /// y ← y0 + dt·f(stage), positions with the stage state's own velocities.
    fn advance(&self, y: &mut State<D>, y0: &State<D>, stage: &Stage<D>, dt: f64) {
        self.advance_with_velocity(y, &y0.particles.velocity, stage, dt, y0);
        self.floor_density(y);
    }

    /// Raises each solid particle's density to m/(h_max_factor Δp0)^d (in RZ the density
    /// at which the ring's area is (h_max_factor Δp0)², `ring_density_for_area`) if it
    /// fell below, and returns how many were raised; a no-op with
    /// `solid_density_floor` off or summation density (never below its self-term). See
    /// [`SchemeConfig::solid_density_floor`].
    fn floor_density(&self, y: &mut State<D>) -> u64 {
        if !self.scheme.solid_density_floor || self.scheme.density == DensityForm::Summation {
            return 0;
        }
        let d = D::DIM as i32;
        let cap = self.scheme.h_max_factor;
        let materials = &self.materials;
        let p = &mut y.particles;
        let rz = self.scheme.geometry == Geometry::Axisymmetric;
        let (m, x, mat) = (&p.mass, &p.position, &p.material);
        let s0 = &y.spacing0;
        p.density
            .par_iter_mut()
            .enumerate()
            .map(|(i, rho)| {
                if materials[mat[i] as usize].strength.is_none() {
                    return 0;
                }
                let side = cap * s0[i];
                let floor = if rz {
                    ring_density_for_area(m[i], radius(x[i]), side)
                } else {
                    m[i] / side.powi(d)
                };
                if *rho < floor {
                    *rho = floor;
                    1
                } else {
                    0
                }
            })
            .sum()
    }

    fn advance_with_velocity(
        &self,
        y: &mut State<D>,
        velocity: &[D::Vector],
        stage: &Stage<D>,
        dt: f64,
        rate_state: &State<D>,
    ) {
        let p = &mut y.particles;
        let v_old = p.velocity.clone();
        p.position
            .par_iter_mut()
            .zip(velocity)
            .for_each(|(x, &v)| *x += v * dt);
        p.velocity
            .par_iter_mut()
            .zip(&stage.rates)
            .for_each(|(v, r)| *v += r.dv * dt);
        for (i, _) in self.held.iter().enumerate().filter(|(_, h)| **h) {
            p.velocity[i] = v_old[i];
        }
        // ρ ← ρ exp(dt (dρ/dt)/ρ_rate): first-order equal to the linear update, but a
        // density can never change sign, however violent the expansion.
        let rho_rate = &rate_state.particles.density;
        p.density
            .par_iter_mut()
            .zip(&stage.rates)
            .zip(rho_rate)
            .for_each(|((rho, r), &rr)| *rho *= (r.drho * dt / rr).exp());
        if self.scheme.energy == EnergyForm::Compatible {
            // de = W − v̄·a with the time-centred v̄ = (v_old + v_new)/2: then the kinetic
            // energy change m v̄·Δv and Σ m Δe cancel pair by pair (F_ji = −F_ij,
            // v*_ji = v*_ij), so the step conserves energy to round-off, not just to O(dt³).
            let v_new = &p.velocity;
            p.specific_energy
                .par_iter_mut()
                .enumerate()
                .for_each(|(i, e)| {
                    let r = &stage.rates[i];
                    let v_bar = (v_old[i] + v_new[i]) * 0.5;
                    *e += (r.work - v_bar.dot(r.dv)) * dt;
                });
        } else {
            p.specific_energy
                .par_iter_mut()
                .zip(&stage.rates)
                .for_each(|(e, r)| *e += r.de * dt);
        }
        let d = D::DIM as f64;
        let n_target = self.scheme.n_target;
        match self.scheme.smoothing {
            SmoothingMode::Scalar => {
                let (m, rho) = (&p.mass, &p.density);
                let (s0, cap) = (&y.spacing0, self.scheme.h_max_factor);
                let x = &p.position;
                p.smoothing_length
                    .par_iter_mut()
                    .enumerate()
                    .for_each(|(i, h)| {
                        // The area (or volume) per particle: m/ρ, in RZ the ring's area.
                        if rho[i] > 0.0 {
                            let measure = self.kernel_measure(m[i], x[i], rho[i]);
                            *h = (n_target * measure.powf(1.0 / d)).min(cap * n_target * s0[i]);
                        }
                    });
            }
            SmoothingMode::Asph { max_aspect } => {
                let grads = stage.grads.as_ref().expect("ASPH computes gradients");
                let h_src = &rate_state.h_tensor;
                let (m, rho) = (&p.mass, &p.density);
                let (s0, cap) = (&y.spacing0, self.scheme.h_max_factor);
                let new: Vec<(D::Tensor, f64)> = (0..p.len())
                    .into_par_iter()
                    .map(|i| {
                        // The equivalent radius follows the density as in the scalar
                        // mode, with the same cap: a particle expanding into vacuum
                        // would otherwise grow its support without bound.
                        let target = if rho[i] > 0.0 {
                            let measure = self.kernel_measure(m[i], p.position[i], rho[i]);
                            (n_target * measure.powf(1.0 / d)).min(cap * n_target * s0[i])
                        } else {
                            1.0 / h_src[i].sym_eigen().values[0]
                        };
                        asph_update(
                            &y.h_tensor[i],
                            &grads.each[i].velocity,
                            dt,
                            target,
                            max_aspect,
                        )
                    })
                    .collect();
                for (i, (h, radius)) in new.into_iter().enumerate() {
                    y.h_tensor[i] = h;
                    p.smoothing_length[i] = radius;
                }
            }
        }
        if !y.stress.is_empty() {
            self.update_stress(y, stage, dt, rate_state);
        }
    }

    /// With summation density, recomputes ρ (and h) from the current positions, so that
    /// output reflects the final state; a no-op for the evolved density forms.
    pub fn sync_density(&mut self) -> Result<(), SolverError> {
        if self.scheme.density == DensityForm::Summation {
            let mut s = self.state.clone();
            self.stage(&mut s)?;
            self.state.particles.density = s.particles.density;
        }
        Ok(())
    }

    /// The strength model's view of particle i at the given pressure.
    fn strength_state(&self, s: &State<D>, i: usize, pressure: f64) -> sph_strength::StrengthState {
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

    /// Shear modulus of every particle (0 for fluids, and for everything when no
    /// material has strength).
    fn shear_moduli(&self, s: &State<D>, pressure: &[f64]) -> Vec<f64> {
        if s.stress.is_empty() {
            return vec![0.0; s.particles.len()];
        }
        (0..s.particles.len())
            .into_par_iter()
            .map(
                |i| match &self.materials[s.particles.material[i] as usize].strength {
                    Some(model) => {
                        let st = self.strength_state(s, i, pressure[i]);
                        if self.scheme.damaged_moduli {
                            model.damaged_shear_modulus(&st)
                        } else {
                            model.shear_modulus(&st)
                        }
                    }
                    None => 0.0,
                },
            )
            .collect()
    }

    /// Whether each particle is past its adhesion limit (in tension and damaged,
    /// sph_damage::decoupling::past_adhesion), from its undamaged pressure, bulk sound
    /// speed and damage; empty unless fractured material is decoupled
    /// (`SchemeConfig::decouple_damaged`) and some material has damage.
    fn adhesion_flags(
        &self,
        s: &State<D>,
        pressure: &[f64],
        sound_speed: &[f64],
        damage: &[f64],
    ) -> Vec<bool> {
        if !self.scheme.decouple_damaged || damage.is_empty() {
            return Vec::new();
        }
        let rho = &s.particles.density;
        (0..s.particles.len())
            .map(|i| {
                let rho_c2 = rho[i] * sound_speed[i] * sound_speed[i];
                sph_damage::decoupling::past_adhesion(pressure[i], damage[i], rho_c2)
            })
            .collect()
    }

    /// S ← S + dt dS/dt, then the radial return onto the yield surface at the stage's
    /// pressure; the plastic strain grows by (√(3J2_trial) − Y)/(3G) (Wilkins 1964).
    /// Where tracked, the pseudo-plastic strain grows by dt (dS/dt)/G with the elastic
    /// (trial) rate, before the return (sph_damage::activation).
    /// dS/dt = 2G ε̇' + ΩS − SΩ (Jaumann) is formed here from the stage's strain-rate
    /// velocity gradient and the stress of `rate_state`, the state the stage was evaluated
    /// at, with the particle's velocity gradient embedded in 3-D (1-D uniaxial and 2-D
    /// plane strain: the out-of-plane rates are zero; RZ: L_θθ = v_r/r).
    fn update_stress(&self, y: &mut State<D>, stage: &Stage<D>, dt: f64, rate_state: &State<D>) {
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
        for (i, (s, ep, rate, e_pp)) in updated.into_iter().enumerate() {
            y.stress[i] = s;
            y.plastic_strain[i] = ep;
            y.plastic_strain_rate[i] = rate;
            if pseudo {
                y.pseudo_strain[i] = e_pp;
            }
        }
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

/// c_L = √(c² + 4G/(3ρ)) of every particle (c itself for fluids).
fn longitudinal_speeds(sound_speed: &[f64], shear_modulus: &[f64], density: &[f64]) -> Vec<f64> {
    sound_speed
        .iter()
        .zip(shear_modulus)
        .zip(density)
        .map(|((&c, &g), &rho)| sph_damage::longitudinal_speed(c, g, rho))
        .collect()
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

/// P_D of every particle (P itself without damage).
fn damaged_pressures(pressure: &[f64], damage: &[f64]) -> Vec<f64> {
    if damage.is_empty() {
        return pressure.to_vec();
    }
    pressure
        .iter()
        .zip(damage)
        .map(|(&p, &d)| damaged_pressure(p, d))
        .collect()
}

/// The artificial-stress tensor R of every particle, ghosts included, from its total
/// stress σ = (1 − D) S − P_D I (paper §2.3; S itself where damage acts on the yield
/// strength only).
fn artificial_stress_tensors<D: Dimension>(
    ext: &Extended<'_, D>,
    a: &sph_riemann::ArtificialStress,
) -> Vec<D::Tensor> {
    (0..ext.position.len())
        .into_par_iter()
        .map(|k| {
            let p = ext.pressure[k];
            let sigma = if !ext.has_stress() {
                D::Tensor::IDENTITY * (-p)
            } else {
                D::project(&ext.stress(k)) - D::Tensor::IDENTITY * p
            };
            a.tensor(&sigma, p, ext.density[k])
        })
        .collect()
}

/// P and c of every particle.
fn eos_pass<D: Dimension>(p: &Particles<D>, materials: &[Material]) -> (Vec<f64>, Vec<f64>) {
    let pc: Vec<(f64, f64)> = (0..p.len())
        .into_par_iter()
        .map(|i| {
            let pt = materials[p.material[i] as usize]
                .eos
                .evaluate(p.density[i], p.specific_energy[i]);
            (pt.pressure, pt.sound_speed)
        })
        .collect();
    pc.into_iter().unzip()
}

/// ASPH update of one H: advect the metric G = H² with L, take its square root, scale
/// it to the target equivalent radius and limit its aspect ratio.
fn asph_update<T: Tensor>(h: &T, l: &T, dt: f64, target_radius: f64, max_aspect: f64) -> (T, f64) {
    let g = h.mul_tensor(h);
    let dg = (l.transpose().mul_tensor(&g) + g.mul_tensor(l)) * (-dt);
    let g_new = (g + dg).symmetric();
    let eig = g_new.sym_eigen();
    let n = T::Vector::DIM;
    let mut lam: Vec<f64> = (0..n).map(|k| eig.values[k].max(0.0).sqrt()).collect();
    // Limit the aspect: no semi-axis longer than max_aspect × the shortest.
    let lmax = lam.iter().cloned().fold(0.0, f64::max);
    if !(lmax > 0.0) {
        return (T::IDENTITY * (1.0 / target_radius), target_radius);
    }
    for l in lam.iter_mut() {
        *l = l.max(lmax / max_aspect);
    }
    // Scale to the target volume: Π λ_k = target^(−n).
    let prod: f64 = lam.iter().product();
    let scale = (target_radius.powi(-(n as i32)) / prod).powf(1.0 / n as f64);
    let v = eig.vectors;
    let h_new = T::from_fn(|a, b| {
        (0..n)
            .map(|k| v.component(a, k) * lam[k] * scale * v.component(b, k))
            .sum()
    });
    // V diag(λ) Vᵀ is symmetric in exact arithmetic; make it so in floating point.
    let h_new = h_new.symmetric();
    let radius = equivalent_radius(&h_new);
    (h_new, radius)
}
