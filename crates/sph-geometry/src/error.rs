//! Typed errors of sph-geometry.
//!
//! Every variant names what is wrong: the parameter (as `Type.field`) and its value, or
//! the body (its [`Shape::describe`](crate::Shape::describe) text) that could not be
//! filled.

use sph_core::{CoreError, Vector};
use thiserror::Error;

/// Errors from shape construction, lattices and particle placement.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum GeometryError {
    /// A scalar parameter is outside its valid range.
    #[error("{field} = {value} is invalid: {requirement}")]
    InvalidParameter {
        /// The parameter, as `Type.field`.
        field: &'static str,
        /// The value given.
        value: f64,
        /// What it must satisfy.
        requirement: &'static str,
    },
    /// A vector parameter is outside its valid range.
    #[error("{field} = {value:?} is invalid: {requirement}")]
    InvalidVector {
        /// The parameter, as `Type.field`.
        field: &'static str,
        /// Its components (missing ones zero).
        value: [f64; 3],
        /// What it must satisfy.
        requirement: &'static str,
    },
    /// An integer parameter is outside its valid range.
    #[error("{field} = {value} is invalid: {requirement}")]
    InvalidCount {
        /// The parameter, as `Type.field` or `function(argument)`.
        field: &'static str,
        /// The value given.
        value: usize,
        /// What it must satisfy.
        requirement: &'static str,
    },
    /// The operation needs a bounded shape (a lattice or a placement must know where
    /// to stop), but the body has no bounds (a half-space, or a union with one).
    #[error("{body} is unbounded; {operation} needs a bounded shape")]
    Unbounded {
        /// The body.
        body: String,
        /// What was attempted.
        operation: &'static str,
    },
    /// The placement produced no particle: the body is smaller than the spacing, or
    /// the placement origin is far from it.
    #[error("no particle of {body} was placed: {reason}")]
    EmptyPlacement {
        /// The body.
        body: String,
        /// Why, with the numbers.
        reason: String,
    },
    /// The placement would need an absurd number of candidate points (spacing far too
    /// small for the body).
    #[error(
        "{body}: {operation} would test about {estimate:.3e} candidate points, over the limit {limit:.3e}"
    )]
    TooManyPoints {
        /// The body.
        body: String,
        /// What was attempted.
        operation: &'static str,
        /// The estimated number of candidate points.
        estimate: f64,
        /// The limit.
        limit: f64,
    },
    /// An error from sph-core (neighbour search in the quality checks).
    #[error(transparent)]
    Core(#[from] CoreError),
}

/// Upper bound on the candidate points any one lattice or placement may test; it keeps
/// a mistyped spacing (millimetres given as metres) from exhausting memory.
pub const MAX_CANDIDATE_POINTS: f64 = 4.0e9;

/// The shape's bounds, or [`GeometryError::Unbounded`] for `operation` (a lattice or
/// placement must know where to stop).
pub(crate) fn bounds_of<V: Vector, S: crate::Shape<V> + ?Sized>(
    shape: &S,
    operation: &'static str,
) -> Result<crate::Aabb<V>, GeometryError> {
    shape.bounds().ok_or_else(|| GeometryError::Unbounded {
        body: shape.describe(),
        operation,
    })
}

/// [`GeometryError::TooManyPoints`] when `operation` would test more than
/// [`MAX_CANDIDATE_POINTS`] candidates for `shape`.
pub(crate) fn check_candidates<V: Vector, S: crate::Shape<V> + ?Sized>(
    shape: &S,
    operation: &'static str,
    candidates: f64,
) -> Result<(), GeometryError> {
    if candidates > MAX_CANDIDATE_POINTS {
        return Err(GeometryError::TooManyPoints {
            body: shape.describe(),
            operation,
            estimate: candidates,
            limit: MAX_CANDIDATE_POINTS,
        });
    }
    Ok(())
}

/// `value` if it is positive and finite, else [`GeometryError::InvalidParameter`].
pub(crate) fn positive_finite(field: &'static str, value: f64) -> Result<f64, GeometryError> {
    if value > 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(GeometryError::InvalidParameter {
            field,
            value,
            requirement: "must be positive and finite",
        })
    }
}

/// `value` if every component is finite, else [`GeometryError::InvalidVector`].
pub(crate) fn finite_vector<V: Vector>(field: &'static str, value: V) -> Result<V, GeometryError> {
    if value.all_finite() {
        Ok(value)
    } else {
        Err(GeometryError::InvalidVector {
            field,
            value: value.to_array3(),
            requirement: "every component must be finite",
        })
    }
}

/// `value / |value|` if it is finite and non-zero, else [`GeometryError::InvalidVector`].
pub(crate) fn unit_vector<V: Vector>(field: &'static str, value: V) -> Result<V, GeometryError> {
    let norm = value.norm();
    if value.all_finite() && norm > 0.0 && norm.is_finite() {
        Ok(value / norm)
    } else {
        Err(GeometryError::InvalidVector {
            field,
            value: value.to_array3(),
            requirement: "must be finite and non-zero (it is normalised to unit length)",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::glam::DVec3;

    #[test]
    fn messages_name_field_and_value() {
        let e = positive_finite("Sphere.radius", -2.0).unwrap_err();
        assert_eq!(
            e.to_string(),
            "Sphere.radius = -2 is invalid: must be positive and finite"
        );
        let e = unit_vector("Cylinder.axis", DVec3::ZERO).unwrap_err();
        assert!(e.to_string().starts_with("Cylinder.axis = [0.0, 0.0, 0.0]"));
        assert!(positive_finite("x", f64::NAN).is_err());
        assert!(positive_finite("x", f64::INFINITY).is_err());
        assert!(finite_vector("p", DVec3::new(0.0, f64::NAN, 0.0)).is_err());
        assert_eq!(
            unit_vector("a", DVec3::new(0.0, 0.0, 2.0)).unwrap(),
            DVec3::Z
        );
    }
}
