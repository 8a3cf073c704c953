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

/// Checks a geometry index `name` ∈ {1, 2, 3} (planar, cylindrical, spherical).
pub(crate) fn check_geometry(name: &'static str, value: u32) -> Result<(), ExactError> {
    if (1..=3).contains(&value) {
        Ok(())
    } else {
        Err(ExactError::BadParameter {
            name,
            value: value as f64,
            reason: "must be 1, 2 or 3",
        })
    }
}

/// Checks that each named value is positive and finite.
pub(crate) fn check_positive(values: &[(&'static str, f64)]) -> Result<(), ExactError> {
    for &(name, value) in values {
        if !(value > 0.0 && value.is_finite()) {
            return Err(ExactError::BadParameter {
                name,
                value,
                reason: "must be positive and finite",
            });
        }
    }
    Ok(())
}
