//! Typed errors: a bad model parameter or a bad local state, naming the field and value.

use thiserror::Error;

/// Errors of the strength crate. Each names the model (for parameters), the field as it
/// is spelled in the parameter struct (and so in a scene file), the bad value and why.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum StrengthError {
    /// A model parameter is outside its valid range.
    #[error("{model}: parameter `{field}` = {value} is invalid ({reason})")]
    Parameter {
        /// Model name, e.g. `"lundborg"`.
        model: &'static str,
        /// Field name in the parameter struct, e.g. `"limit_strength"`.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// Why it is invalid.
        reason: &'static str,
    },
    /// A field of a [`crate::StrengthState`] is outside its physical range.
    #[error("strength state: `{field}` = {value} is invalid ({reason})")]
    State {
        /// Field name in [`crate::StrengthState`].
        field: &'static str,
        /// The offending value.
        value: f64,
        /// Why it is invalid.
        reason: &'static str,
    },
}

/// Parameter checks shared by the model constructors. Each returns the typed error for
/// `model`/`field` when the check fails.
pub(crate) struct Check {
    pub(crate) model: &'static str,
}

impl Check {
    fn fail(&self, field: &'static str, value: f64, reason: &'static str) -> StrengthError {
        StrengthError::Parameter {
            model: self.model,
            field,
            value,
            reason,
        }
    }

    /// `value` finite and > 0.
    pub(crate) fn positive(&self, field: &'static str, value: f64) -> Result<(), StrengthError> {
        if value.is_finite() && value > 0.0 {
            Ok(())
        } else {
            Err(self.fail(field, value, "must be positive and finite"))
        }
    }

    /// `value` finite and ≥ 0.
    pub(crate) fn non_negative(
        &self,
        field: &'static str,
        value: f64,
    ) -> Result<(), StrengthError> {
        if value.is_finite() && value >= 0.0 {
            Ok(())
        } else {
            Err(self.fail(field, value, "must be non-negative and finite"))
        }
    }

    /// `value` finite (any sign).
    pub(crate) fn finite(&self, field: &'static str, value: f64) -> Result<(), StrengthError> {
        if value.is_finite() {
            Ok(())
        } else {
            Err(self.fail(field, value, "must be finite"))
        }
    }

    /// A custom condition with its own reason.
    pub(crate) fn require(
        &self,
        ok: bool,
        field: &'static str,
        value: f64,
        reason: &'static str,
    ) -> Result<(), StrengthError> {
        if ok {
            Ok(())
        } else {
            Err(self.fail(field, value, reason))
        }
    }
}
