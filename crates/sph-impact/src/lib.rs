//! # sph-impact
//!
//! The Riemann-SPH solver assembled from the workspace crates (paper §2): particle state,
//! derivative evaluation as a gather loop over CSR neighbour lists, RK2 time integration
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
//! ## Feature flags
//! None.

pub mod cli;
pub mod input;
pub mod materials;
pub mod plot;
pub mod run;
pub mod scene;
pub mod solver;
pub mod study;
pub mod verify;

pub use solver::*;
