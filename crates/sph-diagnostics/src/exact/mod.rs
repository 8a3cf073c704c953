//! Exact solutions for the verification problems (docs/verification.md, "1-D Riemann problems",
//! "Noh" and "Sedov–Taylor").

pub mod noh;
pub mod riemann;
pub mod sedov;

pub use noh::{Noh, RadialState};
pub use riemann::{GasState, RiemannSolution};
pub use sedov::Sedov;
