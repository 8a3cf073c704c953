//! A spinning elastic disc (2-D, plane strain): angular momentum Σ m (x × v) must be
//! conserved over 1000 steps. SPH pair forces with deviatoric stress are not central, so
//! this checks that the scheme's torques cancel pair by pair (the pair force is
//! antisymmetric and the stress symmetric). Aluminium (linear elastic EOS, K = 58.33 GPa,
//! G = 26.92 GPa, ρ = 2700, yield far above the stresses), radius 5 cm, rim speed 50 m/s.

use super::outcome::{Outcome, Profile};
use super::setup::elastic_solid;
use super::setup::simulation;
use crate::{Material, SchemeConfig, SolverError};
use sph_core::glam::DVec2;
use sph_core::{Dim2, ParticleInit, Particles};
use sph_geometry::{Sphere, cubic_lattice};

const RADIUS: f64 = 0.05;
const RIM_SPEED: f64 = 50.0;
const STEPS: u64 = 1000;

/// Angular momentum about the origin (2-D: the z component).
fn angular_momentum(p: &Particles<Dim2>) -> f64 {
    (0..p.len())
        .map(|i| {
            p.mass[i] * (p.position[i].x * p.velocity[i].y - p.position[i].y * p.velocity[i].x)
        })
        .sum()
}

/// Runs with `n` lattice spacings across the radius.
pub(crate) fn run(n: usize, scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    let bad = |e: String| SolverError::Material(e);
    let (rho, bulk, shear) = (2700.0, 58.33e9, 26.92e9);
    let (eos, strength) = elastic_solid(rho, bulk, shear, 1.0e12, None)?;
    let dx = RADIUS / n as f64;
    let disc = Sphere::new(DVec2::ZERO, RADIUS).map_err(|e| bad(e.to_string()))?;
    let body = cubic_lattice(&disc, dx, rho).map_err(|e| bad(e.to_string()))?;
    let omega = RIM_SPEED / RADIUS;
    let mut p = Particles::<Dim2>::new();
    for (x, m) in body.positions.iter().zip(&body.masses) {
        p.push(ParticleInit {
            position: *x,
            velocity: DVec2::new(-x.y, x.x) * omega,
            mass: *m,
            density: rho,
            specific_energy: 0.0,
            smoothing_length: scheme.n_target * dx,
            material: 0,
        });
    }
    let mut sim = simulation(
        p,
        vec![Material::solid("aluminium (linear elastic)", eos, strength)],
        scheme,
        Vec::new(),
        None,
    )?;
    let l0 = angular_momentum(&sim.state.particles);
    let c0 = sim.conserved();
    let wall = std::time::Instant::now();
    let mut worst: f64 = 0.0;
    for _ in 0..STEPS {
        sim.step(f64::INFINITY)?;
        worst = worst.max(((angular_momentum(&sim.state.particles) - l0) / l0).abs());
    }
    let c1 = sim.conserved();
    let mut out = Outcome {
        problem: "spin".into(),
        ..Default::default()
    };
    out.set("particles", sim.state.particles.len() as f64);
    out.set("resolution", n as f64);
    out.set("steps", STEPS as f64);
    out.set("simulated_time", sim.state.time);
    out.set("rotation_angle_rad", omega * sim.state.time);
    out.set("angular_momentum_change_max_relative", worst);
    out.set(
        "momentum_relative",
        (c1.momentum - c0.momentum).length() / (c0.mass * RIM_SPEED),
    );
    out.set(
        "energy_change_relative",
        (c1.energy() - c0.energy()) / c0.energy(),
    );
    out.set("wall_time_s", wall.elapsed().as_secs_f64());
    let pa = &sim.state.particles;
    out.profile = Profile {
        columns: ["x", "y", "vx", "vy"].map(String::from).to_vec(),
        rows: (0..pa.len())
            .map(|i| {
                vec![
                    pa.position[i].x,
                    pa.position[i].y,
                    pa.velocity[i].x,
                    pa.velocity[i].y,
                ]
            })
            .collect(),
    };
    Ok(out)
}
