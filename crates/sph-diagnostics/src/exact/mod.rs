//! Exact solutions for the verification problems (verification.md §1–3).

pub mod riemann;

pub use riemann::{GasState, RiemannSolution};
