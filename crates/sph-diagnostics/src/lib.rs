//! # sph-diagnostics
//!
//! What a run is judged by: exact solutions for verification problems, error norms,
//! conservation sums, and (to come) impact diagnostics (ejecta, β, crater) and writers.
//!
//! ```
//! use sph_diagnostics::exact::{GasState, RiemannSolution};
//! // Sod's shock tube (Toro ch. 4, test 1).
//! let sod = RiemannSolution::solve(
//!     GasState { density: 1.0, velocity: 0.0, pressure: 1.0 },
//!     GasState { density: 0.125, velocity: 0.0, pressure: 0.1 },
//!     1.4,
//! ).unwrap();
//! assert!((sod.p_star - 0.30313).abs() < 1e-5);
//! assert!((sod.u_star - 0.92745).abs() < 1e-5);
//! ```
//!
//! ## Feature flags
//! None.

pub mod error;
pub mod exact;
pub mod norms;
pub mod plot;

pub use error::ExactError;
pub use norms::{ErrorNorms, convergence_order, error_norms, log_log_slope};
pub use plot::{Figure, PlotError};
