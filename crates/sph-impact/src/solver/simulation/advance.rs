//! Advancing a state by one stage's rates: positions, velocities, density, energy, then
//! the smoothing length (module `smoothing`), the stress (module `stress`) and the solid
//! density floor.

use super::*;

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// y ← y0 + dt·f(stage), positions with the stage state's own velocities.
    pub(super) fn advance(&self, y: &mut State<D>, y0: &State<D>, stage: &Stage<D>, dt: f64) {
        self.advance_with_velocity(y, &y0.particles.velocity, stage, dt, y0);
        self.floor_density(y);
    }

    /// Raises each solid particle's density to m/(h_max_factor Δp0)^d (in RZ the density
    /// at which the ring's area is (h_max_factor Δp0)², `ring_density_for_area`) if it
    /// fell below, and returns how many were raised; a no-op with
    /// `solid_density_floor` off or summation density (never below its self-term). See
    /// [`SchemeConfig::solid_density_floor`].
    pub(super) fn floor_density(&self, y: &mut State<D>) -> u64 {
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

    pub(super) fn advance_with_velocity(
        &self,
        y: &mut State<D>,
        velocity: &[D::Vector],
        stage: &Stage<D>,
        dt: f64,
        rate_state: &State<D>,
    ) {
        // One pass over the particles for x, v, ρ, e and a scalar h: each is particle i's
        // own, so the pass gives what five passes gave, at one fork-join instead of five
        // (a scene of a few thousand rings does little work per pass).
        let held = &self.held;
        let rho_rate = &rate_state.particles.density;
        let compatible = self.scheme.energy == EnergyForm::Compatible;
        let scalar_h = matches!(self.scheme.smoothing, SmoothingMode::Scalar);
        let s0 = &y.spacing0;
        let p = &mut y.particles;
        let m = &p.mass;
        p.position
            .par_chunks_mut(PASS_CHUNK)
            .zip(p.velocity.par_chunks_mut(PASS_CHUNK))
            .zip(p.density.par_chunks_mut(PASS_CHUNK))
            .zip(p.specific_energy.par_chunks_mut(PASS_CHUNK))
            .zip(p.smoothing_length.par_chunks_mut(PASS_CHUNK))
            .enumerate()
            .for_each(|(c, ((((x, v), rho), e), h))| {
                let first = c * PASS_CHUNK;
                for k in 0..x.len() {
                    let i = first + k;
                    let r = &stage.rates[i];
                    x[k] += velocity[i] * dt;
                    // A held particle keeps its velocity.
                    let v_old = v[k];
                    if !held.get(i).copied().unwrap_or(false) {
                        v[k] += r.dv * dt;
                    }
                    // ρ ← ρ exp(dt (dρ/dt)/ρ_rate): first-order equal to the linear
                    // update, but a density can never change sign, however violent the
                    // expansion.
                    rho[k] *= (r.drho * dt / rho_rate[i]).exp();
                    e[k] += if compatible {
                        // de = W − v̄·a with the time-centred v̄ = (v_old + v_new)/2: then
                        // the kinetic energy change m v̄·Δv and Σ m Δe cancel pair by pair
                        // (F_ji = −F_ij, v*_ji = v*_ij), so the step conserves energy to
                        // round-off, not just to O(dt³).
                        let v_bar = (v_old + v[k]) * 0.5;
                        (r.work - v_bar.dot(r.dv)) * dt
                    } else {
                        r.de * dt
                    };
                    // The scalar h follows the new density (module `smoothing`).
                    if scalar_h && rho[k] > 0.0 {
                        h[k] = self.scalar_support(m[i], x[k], rho[k], s0[i]);
                    }
                }
            });
        self.update_asph(y, stage, dt, rate_state);
        if !y.stress.is_empty() {
            self.update_stress(y, stage, dt, rate_state);
        }
    }
}
