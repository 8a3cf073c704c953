//! Free flight: particles that have left the scene leave the hydrodynamics.
//!
//! With [`crate::SchemeConfig::free_flight_above`] = Some(z_f), a particle whose last
//! coordinate (z in 3-D and RZ, y in plane 2-D) is above z_f, that moves up (v_z > 0)
//! and away from every wall and contact plane (v·n ≥ 0, the RZ axis included), is taken
//! out of the particle set after the step and moves on at its velocity: x(t) = x + v
//! (t − t_f). Without gravity or drag that is its motion once nothing pushes it; what is
//! dropped is its interaction with whatever it would still meet (ejecta among ejecta).
//! Its mass, momentum and energy stay constant, so the totals are unchanged, and the
//! outputs see it where it flies ([`crate::Simulation::with_free_flight`]).
//!
//! Why: in RZ a ring flying outward keeps its volume in a longer circumference, so its
//! (r, z) section and its h shrink like r^(−1/2). A cohesive aluminium fragment in the
//! ejecta plume of the 0.25 mm basalt impact, 65 mm out and 89 mm up at 140 µs, set the
//! time step at 2.1 ns, where the particles still in the target allowed 3.5 ns
//! (docs/validation.md, "Free flight").

use crate::solver::boundary::Boundary;
use crate::solver::state::{State, take_where};
use sph_core::{Dimension, Vector};

/// The particles in flight, with what the solver keeps of them besides their state.
#[derive(Clone, Debug, Default)]
pub(crate) struct FreeFlight<D: Dimension> {
    /// Their state, positions at `state.time`.
    pub state: State<D>,
    /// Held-velocity flags (empty when none is held).
    pub held: Vec<bool>,
    /// RZ: radius at set-up (empty otherwise).
    pub radius0: Vec<f64>,
}

/// Which particles of `state` leave: above `z_f` in the last coordinate, moving up, and
/// moving away from every wall (a wall's ghosts could still reach a particle that
/// approaches it). Held particles never leave (their velocity is a constraint).
pub(crate) fn leaving<D: Dimension>(
    state: &State<D>,
    z_f: f64,
    boundaries: &[Boundary<D>],
    held: &[bool],
) -> Vec<bool> {
    let up = D::DIM - 1;
    let p = &state.particles;
    (0..p.len())
        .map(|i| {
            let (x, v) = (p.position[i], p.velocity[i]);
            let away = boundaries.iter().all(|b| match b {
                Boundary::Wall { normal, .. } | Boundary::Contact { normal, .. } => {
                    v.dot(*normal) >= 0.0
                }
                Boundary::Periodic { .. } => true,
            });
            x.component(up) > z_f
                && v.component(up) > 0.0
                && away
                && !held.get(i).copied().unwrap_or(false)
        })
        .collect()
}

impl<D: Dimension> FreeFlight<D> {
    /// Number of particles in flight.
    pub fn len(&self) -> usize {
        self.state.particles.len()
    }

    /// Moves every particle in flight on by `dt` at its velocity.
    pub fn drift(&mut self, dt: f64) {
        let p = &mut self.state.particles;
        for (x, v) in p.position.iter_mut().zip(&p.velocity) {
            *x += *v * dt;
        }
        self.state.time += dt;
    }

    /// Takes the particles with `leave[i]` true out of `state` (and their entries out
    /// of `held` and `radius0`) into the flight; returns how many left.
    pub fn take(
        &mut self,
        state: &mut State<D>,
        held: &mut Vec<bool>,
        radius0: &mut Vec<f64>,
        leave: &[bool],
    ) -> usize {
        let n = leave.iter().filter(|&&l| l).count();
        if n == 0 {
            return 0;
        }
        let mut gone = state.split_off(leave);
        // Appending to the empty default works too: fields not in use stay empty.
        self.state.append(&mut gone);
        self.held.extend(take_where(held, leave));
        self.radius0.extend(take_where(radius0, leave));
        self.state.time = state.time;
        self.state.step = state.step;
        n
    }
}
