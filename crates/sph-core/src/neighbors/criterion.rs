//! Pair criteria: when two particles interact.

use crate::error::CoreError;
use crate::tensor::Tensor;
use crate::vector::Vector;

/// When particles i and j interact. Must be symmetric in (i, j) and must only accept
/// pairs with |r_ij| < max(radius(i), radius(j)), so a grid sized by the radii finds
/// every accepted pair.
pub trait PairCriterion<V: Vector>: Sync {
    /// Number of particles the criterion describes.
    fn len(&self) -> usize;
    /// True when it describes no particles.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The largest distance at which particle i can reach a neighbour on its own.
    fn radius(&self, i: usize) -> f64;
    /// True when [`Self::accepts`] is exactly |r| < max(radius(i), radius(j)) (as
    /// `r.norm_squared() < max²`): a search that has already found |r| < radius(i) may
    /// then skip the call (and its load of j's data).
    const RADIUS_IS_EXACT: bool = false;
    /// Whether i and j interact, given r = x_i − x_j.
    fn accepts(&self, i: usize, j: usize, r: V) -> bool;
}

/// Spherical support of radius h_i: |r_ij| < max(h_i, h_j).
#[derive(Clone, Copy, Debug)]
pub struct ScalarSupport<'a> {
    h: &'a [f64],
}

impl<'a> ScalarSupport<'a> {
    /// Checks that every radius is positive and finite.
    pub fn new(h: &'a [f64]) -> Result<Self, CoreError> {
        for (index, &radius) in h.iter().enumerate() {
            if !(radius > 0.0 && radius.is_finite()) {
                return Err(CoreError::BadSupportRadius { index, radius });
            }
        }
        Ok(Self { h })
    }
}

impl<V: Vector> PairCriterion<V> for ScalarSupport<'_> {
    #[inline]
    fn len(&self) -> usize {
        self.h.len()
    }
    #[inline]
    fn radius(&self, i: usize) -> f64 {
        self.h[i]
    }
    const RADIUS_IS_EXACT: bool = true;
    #[inline]
    fn accepts(&self, i: usize, j: usize, r: V) -> bool {
        let s = self.h[i].max(self.h[j]);
        r.norm_squared() < s * s
    }
}

/// Ellipsoidal (ASPH) support: the symmetric positive-definite tensor H_i (units 1/m)
/// maps the support ellipsoid of particle i onto the unit ball. The pair interacts when
/// |H_i r_ij| < 1 or |H_j r_ij| < 1.
#[derive(Clone, Debug)]
pub struct TensorSupport<'a, T: Tensor> {
    h: &'a [T],
    radius: Vec<f64>,
}

impl<'a, T: Tensor> TensorSupport<'a, T> {
    /// Checks that every H is symmetric positive definite and records the largest
    /// semi-axis 1/λ_min(H) of each ellipsoid as its search radius.
    pub fn new(h: &'a [T]) -> Result<Self, CoreError> {
        let n = T::Vector::DIM;
        let mut radius = Vec::with_capacity(h.len());
        for (index, t) in h.iter().enumerate() {
            let values = t.sym_eigenvalues();
            // Symmetric up to round-off relative to the tensor's size (entry-relative
            // tolerances reject near-zero off-diagonals that differ by 1e-17).
            let scale = t.frobenius_norm();
            let symmetric = (0..n).all(|i| {
                (0..n).all(|j| (t.component(i, j) - t.component(j, i)).abs() <= 1e-12 * scale)
            });
            let lmin = values[0];
            if !symmetric || !t.all_finite() || !(lmin > 0.0) {
                return Err(CoreError::BadSupportTensor {
                    index,
                    eigenvalues: values,
                });
            }
            // Slight enlargement keeps the grid conservative against the round-off of the
            // eigenvalue; the exact test happens in `accepts`.
            radius.push((1.0 + 1e-12) / lmin);
        }
        Ok(Self { h, radius })
    }
}

impl<T: Tensor> PairCriterion<T::Vector> for TensorSupport<'_, T> {
    #[inline]
    fn len(&self) -> usize {
        self.h.len()
    }
    #[inline]
    fn radius(&self, i: usize) -> f64 {
        self.radius[i]
    }
    #[inline]
    fn accepts(&self, i: usize, j: usize, r: T::Vector) -> bool {
        self.h[i].mul_vec(r).norm_squared() < 1.0 || self.h[j].mul_vec(r).norm_squared() < 1.0
    }
}

/// Common input checks: lengths agree, positions finite, at most u32::MAX particles.
pub(crate) fn check_inputs<V: Vector, C: PairCriterion<V>>(
    positions: &[V],
    criterion: &C,
) -> Result<(), CoreError> {
    if criterion.len() != positions.len() {
        return Err(CoreError::LengthMismatch {
            what: "support (one per particle)",
            expected: positions.len(),
            got: criterion.len(),
        });
    }
    if positions.len() > u32::MAX as usize {
        return Err(CoreError::TooManyParticles {
            count: positions.len(),
            limit: u32::MAX as usize,
        });
    }
    for (index, p) in positions.iter().enumerate() {
        if !p.all_finite() {
            return Err(CoreError::NonFinitePosition {
                index,
                position: p.to_array3(),
            });
        }
    }
    Ok(())
}
