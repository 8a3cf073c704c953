//! Typed errors of sph-eos.

use thiserror::Error;

/// Errors from constructing or evaluating an equation of state, the thermal model and the
/// Hugoniot solver. Each variant names the offending field or state and its value.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum EosError {
    /// A model parameter is outside its physical range.
    #[error("parameter {field} = {value} is invalid: {reason}")]
    Parameter {
        /// Parameter name, spelled as in the documentation (e.g. `"E_iv"`).
        field: &'static str,
        /// The offending value.
        value: f64,
        /// Why it is invalid.
        reason: &'static str,
    },
    /// A thermodynamic state lies outside the range where the EOS is defined.
    #[error("{eos}: state rho = {rho} kg/m^3, e = {e} J/kg is outside the valid range: {reason}")]
    OutsideValidity {
        /// Name of the EOS ([`crate::EquationOfState::name`]).
        eos: String,
        /// Density, kg/m³.
        rho: f64,
        /// Specific internal energy, J/kg.
        e: f64,
        /// Which condition failed.
        reason: &'static str,
    },
    /// The EOS returned a NaN or infinite pressure, sound speed or derivative.
    #[error("{eos}: non-finite {quantity} = {value} at rho = {rho} kg/m^3, e = {e} J/kg")]
    NonFinite {
        /// Name of the EOS.
        eos: String,
        /// Which output (`"pressure"`, `"sound_speed"`, ...).
        quantity: &'static str,
        /// The value returned.
        value: f64,
        /// Density, kg/m³.
        rho: f64,
        /// Specific internal energy, J/kg.
        e: f64,
    },
    /// The shock-Hugoniot solver could not find a state.
    #[error("Hugoniot at u_p = {particle_velocity} m/s (rho0 = {rho0} kg/m^3): {reason}")]
    Hugoniot {
        /// Particle velocity asked for, m/s.
        particle_velocity: f64,
        /// Reference density, kg/m³.
        rho0: f64,
        /// What went wrong.
        reason: &'static str,
    },
}

/// Checks that `value` is finite and satisfies `ok`, else names it in a
/// [`EosError::Parameter`].
pub(crate) fn check(
    field: &'static str,
    value: f64,
    ok: bool,
    reason: &'static str,
) -> Result<(), EosError> {
    if value.is_finite() && ok {
        Ok(())
    } else {
        Err(EosError::Parameter {
            field,
            value,
            reason: if value.is_finite() {
                reason
            } else {
                "must be finite"
            },
        })
    }
}

/// `value` finite and > 0.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<(), EosError> {
    check(field, value, value > 0.0, "must be positive")
}

/// `value` finite and ≥ 0.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<(), EosError> {
    check(field, value, value >= 0.0, "must be non-negative")
}
