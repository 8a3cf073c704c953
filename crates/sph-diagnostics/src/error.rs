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

/// Errors from the impact diagnostics (particle views, ejecta, β, crater, damage, melt).
///
/// Bad input is a value naming the particle and the field, never a panic
/// (docs/architecture.md, "Conventions").
#[derive(Debug, Error, Clone, PartialEq)]
pub enum ImpactError {
    /// A per-particle array does not have one entry per particle.
    #[error("{field} has {len} entries, expected {expected} (one per particle)")]
    LengthMismatch {
        /// The array's name.
        field: &'static str,
        /// Its length.
        len: usize,
        /// The number of particles (the length of `position`).
        expected: usize,
    },
    /// A per-particle value is NaN or infinite.
    #[error("particle {index}: {field} = {value} is not finite")]
    NonFinite {
        /// The array's name.
        field: &'static str,
        /// The particle's index in the view.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A particle has negative mass (kg).
    #[error("particle {index}: mass {mass} kg is negative")]
    NegativeMass {
        /// The particle's index in the view.
        index: usize,
        /// Its mass (kg).
        mass: f64,
    },
    /// A damage value outside [0, 1].
    #[error("particle {index}: damage {value} is outside [0, 1]")]
    DamageOutOfRange {
        /// The particle's index in the view.
        index: usize,
        /// Its damage.
        value: f64,
    },
    /// A density that is not positive (kg/m³).
    #[error("particle {index}: density {value} kg/m³ is not positive")]
    NonPositiveDensity {
        /// The particle's index in the view.
        index: usize,
        /// Its density (kg/m³).
        value: f64,
    },
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
    /// The diagnostic needs an optional per-particle array the view does not have.
    #[error("the particle view has no {0} array, which this diagnostic needs")]
    MissingField(&'static str),
    /// The selection a diagnostic works on is empty (no bodies, particles or mass).
    #[error("empty selection: {0}")]
    EmptySelection(&'static str),
    /// A binning would need more bins than the limit (a stray particle far out).
    #[error("{what}: {count} bins needed, more than the limit {limit}")]
    TooManyBins {
        /// What is being binned.
        what: &'static str,
        /// Bins needed (f64: may be astronomically large).
        count: f64,
        /// The limit.
        limit: usize,
    },
}

/// Checks that `value` is positive and finite.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, ImpactError> {
    if value > 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(ImpactError::BadParameter {
            name,
            value,
            reason: "must be positive and finite",
        })
    }
}

/// Checks that `value` is finite.
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64, ImpactError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ImpactError::BadParameter {
            name,
            value,
            reason: "must be finite",
        })
    }
}
