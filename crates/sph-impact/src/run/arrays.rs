//! The solver's particle arrays in the `[f64; 3]` form the diagnostics and the VTU writer
//! read, copied once per measurement.

use crate::Simulation;
use sph_core::Dim3;
use sph_diagnostics::ParticleView;
use sph_kernel::KernelChoice;

/// One instant's particle arrays.
pub(crate) struct Arrays {
    pub position: Vec<[f64; 3]>,
    pub velocity: Vec<[f64; 3]>,
    pub mass: Vec<f64>,
    pub body: Vec<u16>,
    pub damage: Vec<f64>,
    pub density: Vec<f64>,
    pub specific_energy: Vec<f64>,
}

impl Arrays {
    /// Copies the current state of `sim`.
    pub fn of(sim: &Simulation<Dim3, KernelChoice>) -> Self {
        let p = &sim.state.particles;
        Self {
            position: p.position.iter().map(|x| x.to_array()).collect(),
            velocity: p.velocity.iter().map(|v| v.to_array()).collect(),
            mass: p.mass.clone(),
            body: p.material.clone(),
            damage: sim.damage(),
            density: p.density.clone(),
            specific_energy: p.specific_energy.clone(),
        }
    }

    /// The diagnostics' view, with damage and density.
    pub fn view(&self) -> ParticleView<'_> {
        ParticleView::new(&self.position, &self.velocity, &self.mass, &self.body)
            .with_damage(&self.damage)
            .with_density(&self.density)
    }
}
