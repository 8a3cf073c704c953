//! From a scene to a running simulation: the bodies' particles in one store (body k's
//! particles contiguous, material id k), each body's solver material with its own
//! Benz–Asphaug flaws, the scheme, the kernel; no boundaries (every surface is free).

use crate::materials::MaterialSpec;
use crate::scene::Scene;
use crate::scene::error::{SceneError, SceneErrorKind};
use crate::scene::place::PlacedBody;
use crate::solver::{Material, Simulation};
use serde::Serialize;
use sph_core::{Dim3, ParticleInit, Particles};
use sph_kernel::KernelChoice;
use std::ops::Range;

/// What a body became in the simulation.
#[derive(Clone, Debug, Serialize)]
pub struct BodyInfo {
    /// The body's name.
    pub name: String,
    /// Its particles' indices in the simulation (also its material id's particles).
    pub range: Range<usize>,
    /// Its material.
    #[serde(skip)]
    pub material: MaterialSpec,
    /// Name of its material.
    pub material_name: String,
    /// Number of particles.
    pub particles: usize,
    /// Σ m of its particles (kg).
    pub mass: f64,
    /// ρ·V of its shape (kg), when the volume is known exactly.
    pub exact_mass: Option<f64>,
    /// Finest and coarsest particle spacing (m).
    pub spacing: (f64, f64),
    /// Initial velocity (m/s).
    pub velocity: [f64; 3],
}

impl BodyInfo {
    /// The body's info from its placed particles, at particle offset `start`.
    pub fn of(body: &PlacedBody, start: usize) -> Self {
        let p = &body.particles;
        Self {
            name: body.name.clone(),
            range: start..start + p.len(),
            material: body.material.clone(),
            material_name: body.material.name.clone(),
            particles: p.len(),
            mass: p.total_mass(),
            exact_mass: body.exact_mass,
            spacing: (p.min_spacing(), p.max_spacing()),
            velocity: body.velocity.to_array(),
        }
    }

    /// Relative mass error Σm/(ρV) − 1, when ρV is known.
    pub fn mass_error(&self) -> Option<f64> {
        self.exact_mass.map(|m| self.mass / m - 1.0)
    }
}

/// A scene ready to run.
pub struct Built {
    /// The simulation at t = 0.
    pub simulation: Simulation<Dim3, KernelChoice>,
    /// The bodies, in scene order (body k has material id k).
    pub bodies: Vec<BodyInfo>,
}

impl Scene {
    /// Builds the simulation of the scene as written.
    pub fn build(&self) -> Result<Built, SceneError> {
        self.build_scaled(1.0)
    }

    /// Builds the simulation with every particle spacing divided by `resolution_scale`.
    pub fn build_scaled(&self, resolution_scale: f64) -> Result<Built, SceneError> {
        let placed = self.place(resolution_scale)?;
        if placed.len() > u16::MAX as usize {
            return Err(SceneError::at_key(
                "body",
                SceneErrorKind::Solver("more than 65535 bodies".into()),
            ));
        }
        let scheme = self.solver.scheme();
        let mut particles = Particles::<Dim3>::new();
        let mut spacing0 = Vec::new();
        let mut materials: Vec<Material> = Vec::with_capacity(placed.len());
        let mut bodies = Vec::with_capacity(placed.len());
        for (k, body) in placed.iter().enumerate() {
            bodies.push(BodyInfo::of(body, particles.len()));
            let p = &body.particles;
            let rho = body.material.density;
            for i in 0..p.len() {
                particles.push(ParticleInit {
                    position: p.positions[i],
                    velocity: body.velocity,
                    mass: p.masses[i],
                    density: rho,
                    specific_energy: 0.0,
                    smoothing_length: scheme.n_target * p.spacing[i],
                    material: k as u16,
                });
            }
            spacing0.extend_from_slice(&p.spacing);
            // Each body is its own material: Benz–Asphaug flaws belong to one body, and
            // the flaw count of a volume depends on the volumes of its particles.
            let volumes: Vec<f64> = p.masses.iter().map(|m| m / rho).collect();
            let seed = self.bodies[k]
                .damage_seed
                .unwrap_or(self.seed.wrapping_add(k as u64));
            let material = body
                .material
                .body_material(&volumes, seed, sph_damage::DamageVariable::CubeRoot)
                .map_err(|e| {
                    self.locate(SceneError::in_body(
                        k,
                        &body.name,
                        "material",
                        SceneErrorKind::Material(e.to_string()),
                    ))
                })?;
            materials.push(material);
        }
        let kernel = scheme.kernel;
        let simulation = Simulation::new(
            particles,
            materials,
            scheme,
            kernel,
            Vec::new(),
            Some(spacing0),
        )
        .map_err(|e| {
            self.locate(SceneError::at_key(
                "solver",
                SceneErrorKind::Solver(e.to_string()),
            ))
        })?;
        Ok(Built { simulation, bodies })
    }
}
