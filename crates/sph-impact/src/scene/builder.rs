//! [`SceneBuilder`]: the same scene as a TOML file, built in Rust.

use crate::scene::Scene;
use crate::scene::body::{BodySpec, PlacementSpec, ShapeSpec};
use crate::scene::error::SceneError;
use crate::scene::material_ref::MaterialRef;
use crate::scene::settings::{DiagnosticsSettings, GeometryKind, OutputSettings};
use crate::scene::solver_settings::SolverSettings;

/// Builds a [`Scene`] step by step; [`SceneBuilder::build`] runs the same checks as
/// reading a file.
///
/// ```
/// use sph_impact::scene::{GeometryKind, PlacementSpec, SceneBuilder, ShapeSpec};
///
/// // A 2 mm aluminium ball at 3.9 km/s into a basalt block, on coarse lattices.
/// let scene = SceneBuilder::new(2.0e-6)
///     .body(
///         "projectile",
///         ShapeSpec::Sphere { centre: [0.0, 0.0, 1.5e-3], radius: 1.0e-3 },
///         "aluminium-2024-jc",
///         PlacementSpec::Lattice { spacing: 0.5e-3 },
///     )
///     .velocity([0.0, 0.0, -3900.0])
///     .body(
///         "target",
///         ShapeSpec::Cuboid { min: [-4e-3, -4e-3, -4e-3], max: [4e-3, 4e-3, 0.0] },
///         "basalt-study",
///         PlacementSpec::Lattice { spacing: 0.5e-3 },
///     )
///     .snapshot_interval(1.0e-6)
///     .build()?;
/// assert_eq!(scene.bodies.len(), 2);
/// assert_eq!(scene.diagnostic_setup(1.0)?.impact_speed, 3900.0);
///
/// // The same scene as TOML reads back equal.
/// let again = sph_impact::scene::Scene::from_toml_str(&scene.to_toml()?, "again.toml")?;
/// assert_eq!(again, scene);
///
/// // Building places the particles and makes the simulation.
/// let built = scene.build()?;
/// assert_eq!(built.bodies[1].name, "target");
/// let sim = built.simulation.three_d().unwrap();
/// assert_eq!(sim.state.particles.len(), built.bodies[1].range.end);
///
/// // The same impact in RZ: a cylinder on the z axis for the block, (r, z) particles.
/// let rz = SceneBuilder::new(2.0e-6)
///     .geometry(GeometryKind::Rz)
///     .body(
///         "projectile",
///         ShapeSpec::Sphere { centre: [0.0, 0.0, 1.5e-3], radius: 1.0e-3 },
///         "aluminium-2024-jc",
///         PlacementSpec::Variable { origin: [0.0, 0.0, 1.5e-3], a_res: 0.25e-3, q: 1.0 },
///     )
///     .velocity([0.0, 0.0, -3900.0])
///     .body(
///         "target",
///         ShapeSpec::Cylinder {
///             base: [0.0, 0.0, -4e-3],
///             axis: [0.0, 0.0, 1.0],
///             radius: 4e-3,
///             length: 4e-3,
///         },
///         "basalt-study",
///         PlacementSpec::Variable { origin: [0.0, 0.0, 0.0], a_res: 0.25e-3, q: 1.05 },
///     )
///     .build()?
///     .build()?;
/// let sim = rz.simulation.rz().unwrap();
/// assert!(sim.state.particles.position.iter().all(|x| x.x > 0.0));
/// // Body masses are the whole rings', 2π × Σ(mass per radian): within 1 % of ρV.
/// assert!(rz.bodies.iter().all(|b| b.mass_error().unwrap().abs() < 0.01));
///
/// // The first scene in plane strain and in 1-D: the sections y = 0 and x = y = 0 of the
/// // same bodies, masses per metre of depth and per square metre.
/// let mut plane = scene.clone();
/// plane.geometry = GeometryKind::Plane;
/// let plane = plane.build()?;
/// assert!(plane.simulation.plane().unwrap().state.particles.len() > 0);
/// let block = &plane.bodies[1]; // its section is 8 mm × 4 mm: ρ × 3.2e-5 m² exactly
/// assert!(block.mass_error().unwrap().abs() < 1e-12);
/// let mut line = scene.clone();
/// line.geometry = GeometryKind::Line;
/// assert_eq!(line.build()?.simulation.line().unwrap().state.particles.len(), 4 + 8);
/// # Ok::<(), sph_impact::scene::SceneError>(())
/// ```
#[derive(Clone, Debug)]
pub struct SceneBuilder {
    scene: Scene,
}

impl SceneBuilder {
    /// A 3-D scene ending at `end_time` (s), with no bodies yet, the study's scheme and
    /// default output and diagnostics ([`Self::geometry`] makes it RZ).
    pub fn new(end_time: f64) -> Self {
        Self {
            scene: Scene {
                description: None,
                geometry: GeometryKind::ThreeD,
                end_time,
                seed: crate::scene::DEFAULT_SEED,
                bodies: Vec::new(),
                solver: SolverSettings::default(),
                output: OutputSettings::default(),
                diagnostics: DiagnosticsSettings::default(),
                source: Default::default(),
            },
        }
    }

    /// Adds a body at rest; the following body settings apply to it.
    pub fn body(
        mut self,
        name: impl Into<String>,
        shape: ShapeSpec,
        material: impl Into<MaterialRef>,
        placement: PlacementSpec,
    ) -> Self {
        self.scene
            .bodies
            .push(BodySpec::new(name, shape, material, placement));
        self
    }

    /// The last body's initial velocity (m/s).
    pub fn velocity(mut self, velocity: [f64; 3]) -> Self {
        if let Some(b) = self.scene.bodies.last_mut() {
            b.velocity = velocity;
        }
        self
    }

    /// The last body's damage seed.
    pub fn damage_seed(mut self, seed: u64) -> Self {
        if let Some(b) = self.scene.bodies.last_mut() {
            b.damage_seed = Some(seed);
        }
        self
    }

    /// A one-line description.
    pub fn description(mut self, text: impl Into<String>) -> Self {
        self.scene.description = Some(text.into());
        self
    }

    /// The geometry: 3-D, or axisymmetric about z (every body then a sphere or a cylinder
    /// on the z axis moving along it; [`SceneBuilder::build`] checks).
    pub fn geometry(mut self, geometry: GeometryKind) -> Self {
        self.scene.geometry = geometry;
        self
    }

    /// The scene's random seed.
    pub fn seed(mut self, seed: u64) -> Self {
        self.scene.seed = seed;
        self
    }

    /// Solver settings over the study's scheme.
    pub fn solver(mut self, solver: SolverSettings) -> Self {
        self.scene.solver = solver;
        self
    }

    /// Simulated time between snapshots (s).
    pub fn snapshot_interval(mut self, dt: f64) -> Self {
        self.scene.output.snapshot_interval = Some(dt);
        self
    }

    /// Output settings.
    pub fn output(mut self, output: OutputSettings) -> Self {
        self.scene.output = output;
        self
    }

    /// Diagnostics settings.
    pub fn diagnostics(mut self, diagnostics: DiagnosticsSettings) -> Self {
        self.scene.diagnostics = diagnostics;
        self
    }

    /// The scene, [`check`](Scene::check)ed.
    pub fn build(self) -> Result<Scene, SceneError> {
        self.scene.check()?;
        Ok(self.scene)
    }
}
