//! Typed errors of sph-core.

use thiserror::Error;

/// Errors from particle storage and neighbour search. Each names the offending
/// particle (its index in the arrays passed in) and the bad value.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum CoreError {
    /// A position has a NaN or infinite component.
    #[error("particle {index}: position {position:?} is not finite")]
    NonFinitePosition {
        /// Particle index.
        index: usize,
        /// The position, as up to three components.
        position: [f64; 3],
    },
    /// A support radius (or the largest semi-axis of an ASPH ellipsoid) is not positive
    /// and finite.
    #[error("particle {index}: support radius {radius} must be positive and finite")]
    BadSupportRadius {
        /// Particle index.
        index: usize,
        /// The offending radius.
        radius: f64,
    },
    /// An ASPH tensor is not symmetric positive definite.
    #[error(
        "particle {index}: ASPH tensor H is not symmetric positive definite (eigenvalues {eigenvalues:?})"
    )]
    BadSupportTensor {
        /// Particle index.
        index: usize,
        /// Its eigenvalues.
        eigenvalues: [f64; 3],
    },
    /// Arrays that must have one entry per particle differ in length.
    #[error("{what}: expected {expected} entries (one per particle), got {got}")]
    LengthMismatch {
        /// Which array.
        what: &'static str,
        /// Expected length.
        expected: usize,
        /// Actual length.
        got: usize,
    },
    /// More particles than the 32-bit neighbour indices can address.
    #[error("{count} particles exceed the neighbour-list limit of {limit}")]
    TooManyParticles {
        /// Number of particles requested.
        count: usize,
        /// The limit.
        limit: usize,
    },
    /// A particle field holds a value outside its physical range.
    #[error("particle {index}: {field} = {value} is invalid ({reason})")]
    BadField {
        /// Particle index.
        index: usize,
        /// Field name.
        field: &'static str,
        /// The value.
        value: f64,
        /// Why it is invalid.
        reason: &'static str,
    },
    /// A permutation is not a bijection of 0..n.
    #[error(
        "permutation of length {len} is not a bijection (index {index} repeated or out of range)"
    )]
    BadPermutation {
        /// Length of the permutation.
        len: usize,
        /// The first offending entry.
        index: usize,
    },
    /// The particles span too many cells of the smallest support radius.
    #[error("domain extent {extent} m is more than 1e15 cells of size {cell} m")]
    DomainTooLarge {
        /// Extent of the bounding box along one axis.
        extent: f64,
        /// Cell size.
        cell: f64,
    },
}
