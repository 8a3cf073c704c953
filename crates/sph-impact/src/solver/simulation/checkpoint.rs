//! A checkpoint of a running simulation: everything a step carries to the next that the
//! set-up does not rebuild, so that a simulation rebuilt from the same scene and given
//! it back steps on exactly as the one that wrote it would have (the same bits).
//!
//! What is not in it is rebuilt from the set-up: the materials (their flaws are dealt
//! from the scene's seed), the scheme, the boundaries, the kernel and the RZ radius
//! table. The neighbour search and the midpoint state are scratch, filled anew every
//! step.

use super::Simulation;
use crate::solver::axisymmetric::Geometry;
use crate::solver::damage::DamageEvents;
use crate::solver::error::SolverError;
use crate::solver::free_flight::FreeFlight;
use crate::solver::pair_rules::PairRule;
use crate::solver::simulation::PhaseTimes;
use crate::solver::state::State;
use serde::{Deserialize, Serialize};
use sph_core::Dimension;
use sph_kernel::Kernel;

/// The evolving part of a [`Simulation`] ([`Simulation::checkpoint`],
/// [`Simulation::restore`]).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct SolverCheckpoint<D: Dimension> {
    /// The particles still in the hydrodynamics, in their current order.
    pub state: State<D>,
    /// Held-velocity flags of `state` (empty when none is held).
    pub held: Vec<bool>,
    /// RZ: each particle's radius at set-up, in `state`'s order (empty otherwise).
    pub radius0: Vec<f64>,
    /// The particles in free flight, with their flags and RZ radii.
    pub flight_state: State<D>,
    /// Held flags of the particles in flight.
    pub flight_held: Vec<bool>,
    /// RZ radii at set-up of the particles in flight.
    pub flight_radius0: Vec<f64>,
    /// The first step's vote (the reference of the time-step floor).
    pub first_dt: Option<f64>,
    /// Momentum the boundaries delivered so far.
    pub boundary_impulse: D::Vector,
    /// What the damage bounds did so far.
    pub damage_events: DamageEvents,
    /// Density-floor events so far.
    pub density_floor_events: u64,
    /// RZ axis crossings so far (end of step, midpoint).
    pub axis_crossings: [u64; 2],
    /// Wall time per phase so far.
    pub timings: PhaseTimes,
}

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// A copy of everything the simulation carries from step to step
    /// ([`SolverCheckpoint`]).
    pub fn checkpoint(&self) -> SolverCheckpoint<D> {
        SolverCheckpoint {
            state: self.state.clone(),
            held: self.held.clone(),
            radius0: self.radius0.clone(),
            flight_state: self.flight.state.clone(),
            flight_held: self.flight.held.clone(),
            flight_radius0: self.flight.radius0.clone(),
            first_dt: self.first_dt,
            boundary_impulse: self.boundary_impulse,
            damage_events: self.damage_events,
            density_floor_events: self.density_floor_events,
            axis_crossings: [self.axis_crossings, self.axis_crossings_midpoint],
            timings: self.timings,
        }
    }

    /// Puts a checkpoint's state in place of this simulation's. `self` must have been
    /// set up from the same scene as the simulation that wrote it: the checkpoint must
    /// hold the same particles (by id, with the same mass, material and flaw index), and
    /// its fields must be the ones this set-up evolves. Otherwise nothing changes and the
    /// error says what differs.
    pub fn restore(&mut self, c: SolverCheckpoint<D>) -> Result<(), SolverError> {
        self.check_checkpoint(&c)?;
        let SolverCheckpoint {
            state,
            held,
            radius0,
            flight_state,
            flight_held,
            flight_radius0,
            first_dt,
            boundary_impulse,
            damage_events,
            density_floor_events,
            axis_crossings,
            timings,
        } = c;
        self.state = state;
        self.held = held;
        self.radius0 = radius0;
        self.flight = FreeFlight {
            state: flight_state,
            held: flight_held,
            radius0: flight_radius0,
        };
        self.first_dt = first_dt;
        self.boundary_impulse = boundary_impulse;
        self.damage_events = damage_events;
        self.density_floor_events = density_floor_events;
        [self.axis_crossings, self.axis_crossings_midpoint] = axis_crossings;
        self.timings = timings;
        Ok(())
    }

    fn check_checkpoint(&self, c: &SolverCheckpoint<D>) -> Result<(), SolverError> {
        let bad = |reason: String| SolverError::BadCheckpoint(reason);
        // A per-particle field holds one entry per particle where this set-up evolves it
        // and none where it does not (an empty state, no particle in flight, holds none).
        let fits = |what: &str, field: &str, len: usize, n: usize, used: bool| {
            let expected = if used { n } else { 0 };
            if len == expected || (n == 0 && len == 0) {
                Ok(())
            } else {
                Err(bad(format!(
                    "{what}: `{field}` has {len} entries for {n} particles, this set-up \
                     expects {expected}"
                )))
            }
        };
        let own = &self.state;
        let rz = self.scheme.geometry == Geometry::Axisymmetric;
        for (what, s, held, radius0) in [
            ("state", &c.state, &c.held, &c.radius0),
            (
                "free flight",
                &c.flight_state,
                &c.flight_held,
                &c.flight_radius0,
            ),
        ] {
            s.particles
                .validate()
                .map_err(|e| bad(format!("{what}: {e}")))?;
            let n = s.particles.len();
            for (field, len, used) in [
                ("h_tensor", s.h_tensor.len(), !own.h_tensor.is_empty()),
                ("spacing0", s.spacing0.len(), true),
                ("stress", s.stress.len(), !own.stress.is_empty()),
                (
                    "plastic_strain",
                    s.plastic_strain.len(),
                    !own.plastic_strain.is_empty(),
                ),
                (
                    "pseudo_strain",
                    s.pseudo_strain.len(),
                    !own.pseudo_strain.is_empty(),
                ),
                (
                    "plastic_strain_rate",
                    s.plastic_strain_rate.len(),
                    !own.plastic_strain_rate.is_empty(),
                ),
                (
                    "damage_state",
                    s.damage_state.len(),
                    !own.damage_state.is_empty(),
                ),
                (
                    "damage_tensor",
                    s.damage_tensor.len(),
                    !own.damage_tensor.is_empty(),
                ),
                (
                    "damage_index",
                    s.damage_index.len(),
                    !own.damage_index.is_empty(),
                ),
                // Held flags may be empty when none is held, in flight as in the state.
                ("held", held.len(), !held.is_empty()),
                ("radius0", radius0.len(), rz),
            ] {
                fits(what, field, len, n, used)?;
            }
        }
        // The same particles: each id once, with this set-up's mass, material and flaws.
        let mut by_id: std::collections::HashMap<u64, usize> = own
            .particles
            .id
            .iter()
            .enumerate()
            .map(|(i, &id)| (id, i))
            .collect();
        let total = c.state.particles.len() + c.flight_state.particles.len();
        if total != by_id.len() || self.flight.len() != 0 {
            return Err(bad(format!(
                "it holds {total} particles, this set-up {}",
                own.particles.len() + self.flight.len()
            )));
        }
        for s in [&c.state, &c.flight_state] {
            let p = &s.particles;
            for k in 0..p.len() {
                let Some(i) = by_id.remove(&p.id[k]) else {
                    return Err(bad(format!(
                        "particle id {} is not in this set-up, or is there twice",
                        p.id[k]
                    )));
                };
                let same = p.mass[k] == own.particles.mass[i]
                    && p.material[k] == own.particles.material[i]
                    && s.damage_index.get(k) == own.damage_index.get(i);
                if !same {
                    return Err(bad(format!(
                        "particle id {} has another mass, material or flaw index than in \
                         this set-up",
                        p.id[k]
                    )));
                }
            }
        }
        Ok(())
    }
}
