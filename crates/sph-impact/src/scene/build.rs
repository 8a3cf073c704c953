//! From a scene to a running simulation, 3-D, axisymmetric (RZ), plane strain or 1-D: the
//! bodies' particles
//! in one store (body k's particles contiguous, material id k), each body's solver
//! material with its own Benz–Asphaug flaws, the scheme, the kernel; no boundaries (every
//! surface is free; in RZ the solver adds the axis as a mirror) except the two symmetry
//! planes of a 3-D quarter model, x = 0 and y = 0, as mirror walls.

use crate::materials::MaterialSpec;
use crate::scene::Scene;
use crate::scene::dimension::{In3d, InLine, InPlane, InRz, SceneDimension, SceneSimulation};
use crate::scene::error::{SceneError, SceneErrorKind};
use crate::scene::place::PlacedBody;
use crate::scene::settings::GeometryKind;
use crate::scene::solver_settings::FlawDealing;
use crate::solver::{Boundary, Material, Simulation};
use serde::Serialize;
use sph_core::glam::DVec3;
use sph_core::{ParticleInit, Particles};
use std::ops::Range;

/// What a body became in the simulation.
#[derive(Clone, Debug, Serialize)]
pub struct BodyInfo {
    /// The body's name.
    pub name: String,
    /// Its particles' indices in the simulation (also its material id's particles; rings
    /// in RZ).
    pub range: Range<usize>,
    /// Its material.
    #[serde(skip)]
    pub material: MaterialSpec,
    /// Name of its material.
    pub material_name: String,
    /// Number of particles.
    pub particles: usize,
    /// The body's mass (kg): Σ m of its particles, 2π Σ m in RZ; per metre of depth
    /// (kg/m) in plane strain, per square metre (kg/m²) in 1-D.
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
            mass: p.body_mass(),
            exact_mass: body.exact_mass,
            spacing: p.spacing_range(),
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
    /// The simulation at t = 0, 3-D or RZ as the scene's `geometry` says.
    pub simulation: SceneSimulation,
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
        self.build_placed(&self.place(resolution_scale)?)
    }

    /// Builds the simulation of bodies placed by [`Scene::place`] (or
    /// [`Scene::preflight`]) from this scene.
    pub fn build_placed(&self, placed: &[PlacedBody]) -> Result<Built, SceneError> {
        if placed.len() > u16::MAX as usize {
            return Err(SceneError::at_key(
                "body",
                SceneErrorKind::Solver("more than 65535 bodies".into()),
            ));
        }
        let (simulation, bodies) = match self.geometry {
            GeometryKind::ThreeD => self.assemble::<In3d>(placed, Vec::new())?,
            // The quarter x > 0, y > 0: the planes x = 0 and y = 0 are mirrors.
            GeometryKind::ThreeDQuarter => self.assemble::<In3d>(
                placed,
                [DVec3::X, DVec3::Y]
                    .map(|normal| Boundary::Wall {
                        point: DVec3::ZERO,
                        normal,
                    })
                    .to_vec(),
            )?,
            GeometryKind::Rz => self.assemble::<InRz>(placed, Vec::new())?,
            GeometryKind::Plane => self.assemble::<InPlane>(placed, Vec::new())?,
            GeometryKind::Line => self.assemble::<InLine>(placed, Vec::new())?,
        };
        Ok(Built { simulation, bodies })
    }

    /// The simulation of the placed bodies in geometry `G`: in RZ the (r, z) particles
    /// with their masses per radian and the axisymmetric scheme.
    fn assemble<G: SceneDimension>(
        &self,
        placed: &[PlacedBody],
        boundaries: Vec<Boundary<G::Dim>>,
    ) -> Result<(SceneSimulation, Vec<BodyInfo>), SceneError> {
        let scheme = self.scheme();
        debug_assert_eq!(scheme.geometry, G::GEOMETRY);
        let mut particles = Particles::<G::Dim>::new();
        let mut spacing0 = Vec::new();
        let mut materials: Vec<Material> = Vec::with_capacity(placed.len());
        let mut bodies = Vec::with_capacity(placed.len());
        for (k, body) in placed.iter().enumerate() {
            bodies.push(BodyInfo::of(body, particles.len()));
            let p =
                G::placed(&body.particles).expect("the bodies are placed in the scene's geometry");
            let rho = body.material.density;
            let velocity = G::from_scene(body.velocity);
            for i in 0..p.len() {
                particles.push(ParticleInit {
                    position: p.positions[i],
                    velocity,
                    mass: p.masses[i],
                    density: rho,
                    specific_energy: 0.0,
                    smoothing_length: scheme.n_target * p.spacing[i],
                    material: k as u16,
                });
            }
            spacing0.extend_from_slice(&p.spacing);
            // Each body is its own material: Benz–Asphaug flaws belong to one body, and
            // the flaw count of a volume depends on the volumes of its particles (the
            // rings' volumes in RZ, so the body's flaws are those of its 3-D volume).
            // They are dealt over the 3-D particles the body's particles stand for, so
            // that an RZ ring has the flaws of one particle of the 3-D run.
            let volumes = body.particles.volumes(rho);
            let seed = self.bodies[k]
                .damage_seed
                .unwrap_or(self.seed.wrapping_add(k as u64));
            let material = body
                .material
                .body_material(
                    &volumes,
                    (
                        seed,
                        match self.solver.flaw_dealing() {
                            FlawDealing::ThreeDCount => G::stands_for(p),
                            FlawDealing::BodyCount => p.len(),
                        },
                    ),
                    sph_damage::DamageVariable::CubeRoot,
                )
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
        let solver_error = |message: String| {
            self.locate(SceneError::at_key(
                "solver",
                SceneErrorKind::Solver(message),
            ))
        };
        let kernel = scheme.kernel;
        let mut simulation = Simulation::new(
            particles,
            materials,
            scheme,
            kernel,
            boundaries,
            Some(spacing0),
        )
        .map_err(|e| solver_error(e.to_string()))?;
        // Along a Morton curve, a particle's neighbours sit close to it in memory, so the
        // pair loops read them from cache rather than at random (docs/performance.md,
        // "The scenes users run"). Each body is sorted within its own range, which
        // `BodyInfo::range` keeps naming.
        let positions = &simulation.state.particles.position;
        let mut order = Vec::with_capacity(positions.len());
        for info in &bodies {
            let local = sph_core::morton_order(&positions[info.range.clone()])
                .map_err(|e| solver_error(e.to_string()))?;
            order.extend(local.as_slice().iter().map(|&k| info.range.start + k));
        }
        sph_core::Permutation::new(order)
            .map_err(|e| solver_error(e.to_string()))
            .and_then(|perm| {
                simulation
                    .reorder_particles(&perm)
                    .map_err(|e| solver_error(e.to_string()))
            })?;
        Ok((G::wrap(simulation), bodies))
    }
}
