//! # sph-diagnostics
//!
//! What a run is judged by.
//!
//! **Status:** scaffold. This crate will own: exact solutions for verification (Riemann
//! problem, Noh, Sedov–Taylor) and error norms; conservation sums; impact diagnostics
//! (ejecta, momentum transfer β, crater diameter, depth and profile); writers (VTK
//! .vtu/.pvd, CSV, JSON) and plots.
