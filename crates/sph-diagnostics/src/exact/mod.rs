//! Exact solutions for the verification problems (verification.md §1–3).

pub mod noh;
pub mod riemann;
pub mod sedov;

pub use noh::{Noh, RadialState};
pub use riemann::{GasState, RiemannSolution};
pub use sedov::Sedov;
