//! Typed errors of sph-diagnostics.

use thiserror::Error;

/// Errors from the exact solutions.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum ExactError {
    /// A Riemann-problem state is not physical.
    #[error("{side} state: density {density} and pressure {pressure} must be positive")]
    BadState {
        /// "left" or "right".
        side: &'static str,
        /// Its density.
        density: f64,
        /// Its pressure.
        pressure: f64,
    },
    /// The adiabatic index must exceed 1.
    #[error("adiabatic index γ = {0} must be > 1")]
    BadGamma(f64),
    /// The initial data generate vacuum (Toro eq. 4.40); not handled.
    #[error("the initial states generate a vacuum (pressure positivity condition fails)")]
    Vacuum,
    /// A parameter outside its range.
    #[error("{name} = {value}: {reason}")]
    BadParameter {
        /// Parameter name.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Why it is invalid.
        reason: &'static str,
    },
}
