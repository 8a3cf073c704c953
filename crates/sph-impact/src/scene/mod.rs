//! # Impact scenes
//!
//! A scene is everything a run needs (paper §5–§6): the bodies (shape, material,
//! particle placement, initial velocity), the geometry, the scheme, the end time, the
//! output cadence and the diagnostics settings. It is read from TOML
//! ([`Scene::from_toml_str`], [`Scene::from_toml_file`]; every table rejects unknown
//! keys and every error is one line naming file, line, column, body and key) or built in
//! Rust ([`SceneBuilder`]); [`Scene::build`] turns it into a [`crate::Simulation`]: 3-D,
//! or with `geometry = "rz"` an axisymmetric one on (r, z) particles, with `"plane"` a
//! plane-strain one on (x, z) particles, with `"1d"` a uniaxial-strain one on z
//! particles ([`SceneSimulation`]).
//! The format is documented key by key in `docs/scenes.md`.
//!
//! ```
//! use sph_impact::scene::Scene;
//!
//! let text = r#"
//! end_time = 1e-6
//!
//! [[body]]
//! name = "projectile"
//! shape = { kind = "sphere", centre = [0.0, 0.0, 1.5e-3], radius = 1e-3 }
//! material = "aluminium-2024-jc"
//! placement = { kind = "lattice", spacing = 0.5e-3 }
//! velocity = [0.0, 0.0, -3900.0]
//!
//! [[body]]
//! name = "target"
//! shape = { kind = "cuboid", min = [-3e-3, -3e-3, -3e-3], max = [3e-3, 3e-3, 0.0] }
//! material = "basalt-x"
//! placement = { kind = "lattice", spacing = 0.5e-3 }
//! "#;
//! let err = Scene::from_toml_str(text, "scene.toml").unwrap_err();
//! assert!(err.to_string().starts_with(
//!     "scene.toml:14:12: body \"target\": `material`: unknown material \"basalt-x\""
//! ));
//! ```

mod axisymmetry;
mod body;
mod build;
mod builder;
mod check;
mod dimension;
mod error;
mod estimate;
mod material_ref;
mod place;
mod preflight;
mod read;
mod roles;
mod section;
mod settings;
mod solver_settings;
pub(crate) mod spans;

pub use body::{BodySpec, DEFAULT_MASS_TOLERANCE, PlacementSpec, ShapeSpec};
pub use build::{BodyInfo, Built};
pub use builder::SceneBuilder;
pub use dimension::SceneSimulation;
pub(crate) use dimension::{In3d, InLine, InPlane, InRz, SceneDimension, SimOf};
pub use error::{SceneError, SceneErrorKind, shown as shown_value};
pub(crate) use estimate::human_seconds as estimate_human_seconds;
pub use estimate::{
    ASSUMED_BYTES_PER_PARTICLE, ASSUMED_EVALUATIONS_PER_CORE_FLUID,
    ASSUMED_EVALUATIONS_PER_CORE_SOLID, BodyReport, CheckReport, LINE_RATE_FACTOR, RZ_RATE_FACTOR,
};
pub use material_ref::MaterialRef;
pub use place::{PlacedBody, PlacedParticles};
pub use preflight::{
    MAX_EXTENT_IN_SPACINGS, MAX_SPEED, MAX_STEPS, MIN_PARTICLES_ACROSS, Preflight, particles_across,
};
pub use roles::DiagnosticSetup;
pub use settings::{DEFAULT_MAX_SNAPSHOTS, DiagnosticsSettings, GeometryKind, OutputSettings};
pub use solver_settings::{
    ArtificialStressSettings, FlawDealing, Preset, SolverSettings, ViscositySettings,
    fsisph_scheme, study_scheme,
};
pub use spans::SourceMap;

use serde::{Deserialize, Serialize};

/// The seed when a scene gives none.
pub const DEFAULT_SEED: u64 = 1;

fn default_seed() -> u64 {
    DEFAULT_SEED
}

/// An impact scene (SI units). Fields mirror the TOML keys (`body` for [`Self::bodies`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Free text describing the scene.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// `"3d"` (default), `"3d-quarter"` (3-D, a quarter between symmetry planes),
    /// `"rz"` (axisymmetric about z), `"plane"` (plane strain, the section y = 0) or
    /// `"1d"` (uniaxial strain, the section on the z axis).
    #[serde(default)]
    pub geometry: GeometryKind,
    /// Simulated time to run (s), > 0.
    pub end_time: f64,
    /// Seed of the random parts (Benz–Asphaug flaws); default 1.
    #[serde(default = "default_seed")]
    pub seed: u64,
    /// The bodies, in order: body k has material id k.
    #[serde(rename = "body", default)]
    pub bodies: Vec<BodySpec>,
    /// Scheme settings over the study's ([`study_scheme`]).
    #[serde(default)]
    pub solver: SolverSettings,
    /// Output cadence and directory.
    #[serde(default)]
    pub output: OutputSettings,
    /// Diagnostics settings.
    #[serde(default)]
    pub diagnostics: DiagnosticsSettings,
    /// Where each key was in the file read (empty for scenes built in Rust).
    #[serde(skip)]
    pub(crate) source: SourceMap,
}

impl Scene {
    /// The numerical scheme: `[solver]` over [`study_scheme`], in the scene's geometry
    /// (`geometry = "rz"` sets [`crate::Geometry::Axisymmetric`]).
    pub fn scheme(&self) -> crate::SchemeConfig {
        let mut s = self.solver.scheme();
        s.geometry = match self.geometry {
            GeometryKind::ThreeD
            | GeometryKind::ThreeDQuarter
            | GeometryKind::Plane
            | GeometryKind::Line => crate::Geometry::Cartesian,
            GeometryKind::Rz => crate::Geometry::Axisymmetric,
        };
        s
    }

    /// How many copies of the modelled part make the whole bodies: 4 for
    /// `"3d-quarter"`, 1 otherwise (RZ's 2π per radian is the dimension's,
    /// `SceneDimension::BODY_FACTOR`).
    pub fn symmetry_copies(&self) -> f64 {
        match self.geometry {
            GeometryKind::ThreeDQuarter => 4.0,
            _ => 1.0,
        }
    }

    /// The scene as TOML; reading it back gives an equal scene. Fails only for a
    /// material given in Rust with a user-defined model (which has no TOML form).
    pub fn to_toml(&self) -> Result<String, SceneError> {
        toml::to_string(self)
            .map_err(|e| SceneError::general(SceneErrorKind::Syntax(e.to_string())))
    }

    /// The file the scene was read from, if any.
    pub fn origin(&self) -> Option<&str> {
        self.source.is_file().then(|| self.source.origin())
    }
}
