//! Multi-material contact in 3-D: the study's aluminium 2024 sphere (Tillotson,
//! Johnson–Cook with its thermal model, maximum-tensile-stress damage) at 3.9 km/s into a
//! basalt block (Tillotson, Lundborg, Benz–Asphaug flaws), with the study's artificial
//! stress (ε = 0.2, n = 4), for the first microseconds. Checks that it runs without NaN,
//! negative density or a collapsing time step, and reports the peak pressure at the
//! contact against the planar Tillotson impedance match (a sphere's first contact is
//! locally planar).

use super::setup::simulation;
use crate::materials::MaterialSpec;
use crate::{SchemeConfig, Simulation, SolverError};
use sph_core::glam::DVec3;
use sph_core::{Dim3, ParticleInit, Particles};
use sph_damage::DamageVariable;
use sph_kernel::KernelChoice;
use sph_riemann::ArtificialStress;

/// What the 3-D run measured.
pub(crate) struct SphereContact {
    pub particles: usize,
    pub steps: u64,
    pub t_end: f64,
    pub min_density_ratio: f64,
    pub dt_first: f64,
    pub dt_min: f64,
    pub dt_last: f64,
    pub peak_pressure: f64,
    pub damaged_fraction: f64,
    pub wall_time_s: f64,
}

/// The study's 6 mm aluminium sphere at 3.9 km/s just above a basalt block 24 × 24 × 12 mm
/// (all the study's material models, flaws seeded per body), cubic lattices at spacing
/// 6 mm / `n`, with the study's artificial stress (ε = 0.2, n = 4). Returns the simulation
/// and the number of block particles (the first ones). Also the `solid3d` bench's scene.
pub fn sphere_into_block(
    n: usize,
    mut scheme: SchemeConfig,
) -> Result<(Simulation<Dim3, KernelChoice>, usize), SolverError> {
    scheme.artificial_stress = ArtificialStress::default();
    let bad = |e: String| SolverError::Material(e);
    let (basalt, al) = (
        MaterialSpec::basalt_study(),
        MaterialSpec::aluminium_2024_jc(),
    );
    let radius = 3.0e-3;
    let dx = 2.0 * radius / n as f64;
    let h = scheme.n_target * dx;
    let half_width = 4.0 * radius;
    let depth = 4.0 * radius;
    let mut p = Particles::<Dim3>::new();
    let (nw, nd) = (
        (2.0 * half_width / dx).round() as usize,
        (depth / dx).round() as usize,
    );
    for c in 0..nd {
        for b in 0..nw {
            for a in 0..nw {
                p.push(ParticleInit {
                    position: DVec3::new(
                        (a as f64 + 0.5) * dx - half_width,
                        (b as f64 + 0.5) * dx - half_width,
                        -(c as f64 + 0.5) * dx,
                    ),
                    velocity: DVec3::ZERO,
                    mass: basalt.density * dx * dx * dx,
                    density: basalt.density,
                    specific_energy: 0.0,
                    smoothing_length: h,
                    material: 0,
                });
            }
        }
    }
    let n_block = p.len();
    let m = (radius / dx).ceil() as i64;
    for a in -m..=m {
        for b in -m..=m {
            for c in -m..=m {
                // Lattice offset by half a spacing so the sphere is symmetric about the axis.
                let x = DVec3::new(a as f64 + 0.5, b as f64 + 0.5, c as f64 + 0.5) * dx;
                if x.length() <= radius {
                    p.push(ParticleInit {
                        position: x + DVec3::new(0.0, 0.0, radius),
                        velocity: DVec3::new(0.0, 0.0, -3900.0),
                        mass: al.density * dx * dx * dx,
                        density: al.density,
                        specific_energy: 0.0,
                        smoothing_length: h,
                        material: 1,
                    });
                }
            }
        }
    }
    let n_proj = p.len() - n_block;
    let v = dx * dx * dx;
    let target = basalt
        .body_material(&vec![v; n_block], (7, n_block), DamageVariable::CubeRoot)
        .map_err(|e| bad(e.to_string()))?;
    let sphere = al
        .body_material(&vec![v; n_proj], (8, n_proj), DamageVariable::CubeRoot)
        .map_err(|e| bad(e.to_string()))?;
    let count = p.len();
    let sim = simulation(
        p,
        vec![target, sphere],
        scheme,
        Vec::new(),
        Some(vec![dx; count]),
    )?;
    Ok((sim, n_block))
}

/// [`sphere_into_block`] with `n` spacings across the sphere, run to 2 µs.
pub(crate) fn run(n: usize, scheme: SchemeConfig) -> Result<SphereContact, SolverError> {
    let (mut sim, n_block) = sphere_into_block(n, scheme)?;
    let dx = 6.0e-3 / n as f64;
    let count = sim.state.particles.len();
    let t_end = 2.0e-6;
    let wall = std::time::Instant::now();
    let rho0: Vec<f64> = sim.state.particles.density.clone();
    let mut out = SphereContact {
        particles: count,
        steps: 0,
        t_end,
        min_density_ratio: f64::INFINITY,
        dt_first: f64::NAN,
        dt_min: f64::INFINITY,
        dt_last: f64::NAN,
        peak_pressure: 0.0,
        damaged_fraction: 0.0,
        wall_time_s: 0.0,
    };
    while sim.state.time < t_end * (1.0 - 1e-12) {
        let info = sim.step(t_end - sim.state.time)?;
        out.steps += 1;
        if out.steps == 1 {
            out.dt_first = info.dt;
        }
        // The last step is shortened to land on t_end: not a vote.
        if sim.state.time < t_end * (1.0 - 1e-12) {
            out.dt_min = out.dt_min.min(info.dt);
            out.dt_last = info.dt;
        }
        let (pressure, _) = sim.pressure_and_sound_speed();
        let pa = &sim.state.particles;
        for i in 0..pa.len() {
            out.min_density_ratio = out.min_density_ratio.min(pa.density[i] / rho0[i]);
            // Near the axis and the contact (within two spacings of the original surface).
            let x = pa.position[i];
            if x.x.hypot(x.y) < 2.0 * dx && x.z.abs() < 2.0 * dx {
                out.peak_pressure = out.peak_pressure.max(pressure[i]);
            }
        }
    }
    let d = sim.damage();
    out.damaged_fraction =
        d[..n_block].iter().filter(|&&x| x >= 0.99).count() as f64 / n_block as f64;
    out.wall_time_s = wall.elapsed().as_secs_f64();
    Ok(out)
}
