//! Planar problems run either in 1-D or, in axisymmetric RZ, as a column of rings along
//! z (issue: the RZ solver must give the planar plateau states on the axis).
//!
//! The RZ column extrudes the 1-D set-up: each 1-D particle at x becomes `columns` rings
//! at r = (a + ½)Δx, z = x, with the same density, energy, velocity (along z) and
//! material, and ring mass per radian ρ Δx² r. A reflecting wall at r = columns·Δx keeps
//! the state one of uniaxial strain, as in 1-D. Profiles are taken on the axis: the
//! innermost ring of each row (r < Δx), sorted by z.

use super::setup::simulation;
use crate::{Boundary, Material, SchemeConfig, Simulation, SolverError};
use sph_core::glam::DVec2;
use sph_core::{Dim1, Dim2, ParticleInit, Particles};
use sph_kernel::KernelChoice;

/// The geometry a planar problem runs in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Planar {
    /// 1-D.
    OneD,
    /// A column of rings `columns` spacings wide, the axis along the 1-D x.
    Rz { columns: usize },
}

/// A planar run in either geometry.
pub(crate) enum PlanarRun {
    OneD(Simulation<Dim1, KernelChoice>),
    Rz {
        sim: Simulation<Dim2, KernelChoice>,
        dx: f64,
    },
}

/// Profile along the planar axis: positions, σ_xx (σ_zz in RZ), velocity, pressure and
/// density, sorted by position.
pub(crate) struct AxisProfile {
    pub x: Vec<f64>,
    pub sigma: Vec<f64>,
    pub v: Vec<f64>,
    pub p: Vec<f64>,
    pub rho: Vec<f64>,
}

impl PlanarRun {
    /// Builds the run from the 1-D particles (uniform spacing `dx`, no boundaries).
    pub fn new(
        particles: Particles<Dim1>,
        materials: Vec<Material>,
        scheme: SchemeConfig,
        dx: f64,
        geometry: Planar,
    ) -> Result<Self, SolverError> {
        let n = particles.len();
        match geometry {
            Planar::OneD => Ok(Self::OneD(simulation(
                particles,
                materials,
                scheme,
                Vec::new(),
                Some(vec![dx; n]),
            )?)),
            Planar::Rz { columns } => {
                let mut scheme = scheme;
                scheme.geometry = crate::Geometry::Axisymmetric;
                let mut p = Particles::<Dim2>::new();
                for k in 0..n {
                    for a in 0..columns {
                        let r = (a as f64 + 0.5) * dx;
                        let rho = particles.density[k];
                        p.push(ParticleInit {
                            position: DVec2::new(r, particles.position[k]),
                            velocity: DVec2::new(0.0, particles.velocity[k]),
                            mass: rho * dx * dx * r,
                            density: rho,
                            specific_energy: particles.specific_energy[k],
                            smoothing_length: particles.smoothing_length[k],
                            material: particles.material[k],
                        });
                    }
                }
                let wall = Boundary::Wall {
                    point: DVec2::new(columns as f64 * dx, 0.0),
                    normal: -DVec2::X,
                };
                let count = p.len();
                Ok(Self::Rz {
                    sim: simulation(p, materials, scheme, vec![wall], Some(vec![dx; count]))?,
                    dx,
                })
            }
        }
    }

    /// Runs to `t`, calling `on_step` with the densities after every step.
    pub fn run_until(
        &mut self,
        t: f64,
        mut on_step: impl FnMut(&[f64]),
    ) -> Result<u64, SolverError> {
        match self {
            Self::OneD(sim) => sim.run_until(t, |s, _| on_step(&s.state.particles.density)),
            Self::Rz { sim, .. } => sim.run_until(t, |s, _| on_step(&s.state.particles.density)),
        }
    }

    /// RZ: the axis crossings so far (`Simulation::axis_crossing_counts`; `None` in 1-D).
    pub fn axis_crossings(&self) -> Option<(u64, u64)> {
        match self {
            Self::OneD(_) => None,
            Self::Rz { sim, .. } => sim.axis_crossing_counts(),
        }
    }

    /// Number of particles.
    pub fn particles(&self) -> usize {
        match self {
            Self::OneD(sim) => sim.state.particles.len(),
            Self::Rz { sim, .. } => sim.state.particles.len(),
        }
    }

    /// The profile along the planar axis (on the axis in RZ).
    pub fn profile(&self) -> AxisProfile {
        match self {
            Self::OneD(sim) => {
                let (p, _) = sim.pressure_and_sound_speed();
                let s = &sim.state;
                let idx: Vec<usize> = (0..s.particles.len()).collect();
                collect(
                    idx,
                    |i| s.particles.position[i],
                    |i| s.stress.get(i).map_or(0.0, |t| t.x_axis.x) - p[i],
                    |i| s.particles.velocity[i],
                    &p,
                    &s.particles.density,
                )
            }
            Self::Rz { sim, dx } => {
                let (p, _) = sim.pressure_and_sound_speed();
                let s = &sim.state;
                let idx: Vec<usize> = (0..s.particles.len())
                    .filter(|&i| s.particles.position[i].x < *dx)
                    .collect();
                collect(
                    idx,
                    |i| s.particles.position[i].y,
                    |i| s.stress.get(i).map_or(0.0, |t| t.y_axis.y) - p[i],
                    |i| s.particles.velocity[i].y,
                    &p,
                    &s.particles.density,
                )
            }
        }
    }
}

/// The profile of the particles `idx`, sorted by position.
fn collect(
    mut idx: Vec<usize>,
    x: impl Fn(usize) -> f64,
    sigma: impl Fn(usize) -> f64,
    v: impl Fn(usize) -> f64,
    p: &[f64],
    rho: &[f64],
) -> AxisProfile {
    idx.sort_by(|&a, &b| x(a).total_cmp(&x(b)));
    AxisProfile {
        x: idx.iter().map(|&i| x(i)).collect(),
        sigma: idx.iter().map(|&i| sigma(i)).collect(),
        v: idx.iter().map(|&i| v(i)).collect(),
        p: idx.iter().map(|&i| p[i]).collect(),
        rho: idx.iter().map(|&i| rho[i]).collect(),
    }
}
