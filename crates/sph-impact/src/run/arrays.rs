//! The solver's particle arrays in the `[f64; 3]` form the diagnostics and the VTU writer
//! read, copied once per measurement: in RZ the rings as points (r, 0, z) with velocity
//! (v_r, 0, v_z) and their whole mass, 2π × mass per radian (docs/diagnostics.md §1).

use crate::scene::{SceneDimension, SimOf};
use sph_diagnostics::ParticleView;

/// One instant's particle arrays.
pub(crate) struct Arrays {
    pub position: Vec<[f64; 3]>,
    pub velocity: Vec<[f64; 3]>,
    pub mass: Vec<f64>,
    pub body: Vec<u16>,
    pub damage: Vec<f64>,
    pub density: Vec<f64>,
    pub specific_energy: Vec<f64>,
    /// Support radius h (m; in RZ in the (r, z) plane).
    pub support: Vec<f64>,
}

impl Arrays {
    /// Copies the current state of `sim`; each particle's mass is that of all the
    /// `copies` it stands for (4 in a 3-D quarter model, else 1; in RZ also × 2π).
    pub fn of<D: SceneDimension>(sim: &SimOf<D>, copies: f64) -> Self {
        let p = &sim.state.particles;
        Self {
            position: p.position.iter().map(|&x| D::to_scene(x)).collect(),
            velocity: p.velocity.iter().map(|&v| D::to_scene(v)).collect(),
            mass: p.mass.iter().map(|m| D::BODY_FACTOR * copies * m).collect(),
            body: p.material.clone(),
            damage: sim.damage(),
            density: p.density.clone(),
            specific_energy: p.specific_energy.clone(),
            support: p.smoothing_length.clone(),
        }
    }

    /// The diagnostics' view, with damage and density.
    pub fn view(&self) -> ParticleView<'_> {
        ParticleView::new(&self.position, &self.velocity, &self.mass, &self.body)
            .with_damage(&self.damage)
            .with_density(&self.density)
    }
}
