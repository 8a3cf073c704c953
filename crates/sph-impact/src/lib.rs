//! # sph-impact
//!
//! The solver assembled from the other crates.
//!
//! **Status:** scaffold. This crate will own: materials, the scene description
//! (serde/TOML), the state and RK2 integrator with its CFL step, the smoothing-length
//! update, checkpoints, and the `sph-impact` command-line program (`run`, `check`,
//! `verify`, `materials`).
