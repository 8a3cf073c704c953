//! # sph-impact
//!
//! The Riemann-SPH solver assembled from the workspace crates (paper §2): particle state,
//! derivative evaluation over CSR neighbour lists (each pair inside a block of rows
//! evaluated once for both particles, `solver/pair_blocks.rs`), RK2 time integration
//! with the adaptive CFL step, smoothing-length (scalar or ASPH) update, boundaries
//! (free surface, reflecting wall, contact wall that pushes but cannot pull, periodic) —
//! and the verification problems.
//!
//! **Status:** fluids and solids in 1-D, 2-D (plane strain) and 3-D: any
//! `EquationOfState`, deviatoric stress with a `StrengthModel` (Jaumann rate, radial
//! return), damage with a `DamageModel` (damaged pressure, (1 − D)S, b_ij in v*), artificial
//! stress (pressure or tensor form), held particles; and axisymmetric (RZ) 2-D runs of
//! rings about the z axis ([`Geometry::Axisymmetric`], `solver/axisymmetric.rs`).
//!
//! Impact runs: [`scene`] reads a TOML scene (or builds one in Rust) and turns it into a
//! [`Simulation`]; [`run`] steps it to the end time and writes snapshots, history, summary
//! and plots (docs/scenes.md); the `sph-impact` program's `run`, `check` and `materials`
//! commands are in [`cli`].
//!
//! A small RZ impact built from a scene and stepped in Rust (the `sph-impact run` command
//! does the same and writes the outputs):
//!
//! ```
//! use sph_impact::scene::{Scene, SceneSimulation};
//!
//! let text = r#"
//! geometry = "rz"
//! end_time = 1.0e-6
//!
//! [[body]]
//! name = "projectile"
//! material = "aluminium-2024-jc"
//! shape = { kind = "sphere", centre = [0.0, 0.0, 1.5e-3], radius = 1.0e-3 }
//! placement = { kind = "lattice", spacing = 0.25e-3 }
//! velocity = [0.0, 0.0, -3900.0]
//!
//! [[body]]
//! name = "target"
//! material = "basalt-study"
//! shape = { kind = "cylinder", base = [0.0, 0.0, -2.0e-3], axis = [0.0, 0.0, 1.0], radius = 3.0e-3, length = 2.0e-3 }
//! placement = { kind = "lattice", spacing = 0.25e-3 }
//! "#;
//! let scene = Scene::from_toml_str(text, "scene.toml").unwrap();
//! let SceneSimulation::Rz(mut sim) = scene.build().unwrap().simulation else {
//!     unreachable!("an RZ scene");
//! };
//! let p0: f64 = sim.state.particles.mass.iter()
//!     .zip(&sim.state.particles.velocity)
//!     .map(|(m, v)| m * v.y)
//!     .sum();
//! for _ in 0..10 {
//!     sim.step(f64::INFINITY).unwrap();
//! }
//! // The projectile has hit: the target moves, and the axial momentum is conserved.
//! let p: f64 = sim.state.particles.mass.iter()
//!     .zip(&sim.state.particles.velocity)
//!     .map(|(m, v)| m * v.y)
//!     .sum();
//! assert!(sim.state.time > 0.0);
//! assert!((p / p0 - 1.0).abs() < 1e-12, "{p} against {p0}");
//! ```
//!
//! ## Feature flags
//! - `mpi` (off by default): one run over several MPI ranks (`mpirun -n N sph-impact run
//!   SCENE`; docs/mpi.md). Needs an MPI implementation and libclang (.ci/install-mpi).

#![forbid(unsafe_code)]

pub mod cli;
pub mod input;
pub mod materials;
#[cfg(feature = "mpi")]
pub mod mpi_world;
pub mod plot;
pub mod run;
pub mod scene;
pub mod solver;
pub mod study;
pub mod verify;

pub use solver::*;
