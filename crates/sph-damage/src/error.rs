//! Typed errors of sph-damage. Each names the offending field (and particle, where there
//! is one) and the bad value.

use thiserror::Error;

/// Errors from constructing damage models, seeding flaws or checking solver inputs.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum DamageError {
    /// A model parameter is out of its physical range.
    #[error("damage parameter {field} = {value} is invalid ({reason})")]
    Parameter {
        /// Parameter name as written in the docs (`k`, `m`, `sigma_b`, …).
        field: &'static str,
        /// The offending value.
        value: f64,
        /// Why it is invalid.
        reason: &'static str,
    },
    /// A per-particle value handed to the crate (a volume, a stress, …) is invalid.
    #[error("particle {index}: {field} = {value} is invalid ({reason})")]
    ParticleValue {
        /// Particle index.
        index: usize,
        /// Field name.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// Why it is invalid.
        reason: &'static str,
    },
    /// Flaw seeding needs at least one particle.
    #[error("flaw seeding needs at least one particle")]
    NoParticles,
    /// More particles than the flaw seeding can address.
    #[error("{count} particles exceed the limit of {limit}")]
    TooManyParticles {
        /// Number of particles requested.
        count: usize,
        /// The limit.
        limit: usize,
    },
    /// A model holds per-particle state for a different number of particles than the
    /// solver has.
    #[error("{what}: model holds {expected} particles, the solver has {got}")]
    ParticleCount {
        /// Which model or state.
        what: &'static str,
        /// Particles the model was built for.
        expected: usize,
        /// Particles the solver has.
        got: usize,
    },
    /// A flaw set read back (from a checkpoint) breaks an invariant.
    #[error("flaw set is inconsistent: {reason}")]
    CorruptFlawSet {
        /// The broken invariant.
        reason: &'static str,
    },
    /// A user's damage model ([`crate::BodyDamage`]) could not be built or used.
    #[error("damage model {model}: {message}")]
    Custom {
        /// The model's name.
        model: String,
        /// What went wrong, in the model's words.
        message: String,
    },
}

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, DamageError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(DamageError::Parameter {
            field,
            value,
            reason: "must be positive and finite",
        })
    }
}
