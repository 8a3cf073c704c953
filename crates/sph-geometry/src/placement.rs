//! [`BodyParticles`]: the particles of one body, as returned by every lattice and by
//! the variable-resolution placement.

use crate::error::{GeometryError, positive_finite};
use sph_core::Vector;

/// The particles that fill one body, with the numbers that say how well they fill it.
///
/// Masses make the mass density uniform (= `density`); `spacing[i]` is the local
/// particle spacing Δx_i (the lattice spacing, or the layer spacing r_k of the
/// variable-resolution placement), from which smoothing lengths follow.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyParticles<V: Vector> {
    /// The body, as its shape describes itself.
    pub body: String,
    /// Positions (m).
    pub positions: Vec<V>,
    /// Masses (kg in 3-D; kg/m in 2-D, kg/m² in 1-D).
    pub masses: Vec<f64>,
    /// Local spacing Δx_i of each particle (m).
    pub spacing: Vec<f64>,
    /// The mass density the masses represent (kg/m³ in 3-D).
    pub density: f64,
    /// The body's exact volume when the shape knows it.
    pub exact_volume: Option<f64>,
    /// The volume used for the totals: the exact volume, else the placement's own
    /// estimate (documented per placement).
    pub volume: f64,
    /// Total-mass error Σm/(ρV) − 1 of the masses as first assigned, before any
    /// normalisation; `None` when the exact volume is unknown.
    pub raw_mass_error: Option<f64>,
    /// `volume / Δx_min^DIM`: the particle count of a uniform cubic lattice at the finest
    /// spacing, the yardstick for the savings of variable resolution.
    pub lattice_equivalent_count: f64,
}

impl<V: Vector> BodyParticles<V> {
    /// Number of particles.
    pub fn len(&self) -> usize {
        self.positions.len()
    }
    /// True when there is no particle (placements never return this; see
    /// [`GeometryError::EmptyPlacement`]).
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }
    /// Σ m_i.
    pub fn total_mass(&self) -> f64 {
        self.masses.iter().sum()
    }
    /// Smallest local spacing.
    pub fn min_spacing(&self) -> f64 {
        self.spacing.iter().cloned().fold(f64::INFINITY, f64::min)
    }
    /// Largest local spacing.
    pub fn max_spacing(&self) -> f64 {
        self.spacing.iter().cloned().fold(0.0, f64::max)
    }
    /// Particle count as a fraction of [`lattice_equivalent_count`](Self::lattice_equivalent_count).
    pub fn lattice_share(&self) -> f64 {
        self.len() as f64 / self.lattice_equivalent_count
    }
    /// Support radii h_i = n_target · Δx_i (paper §2.4: the kernel vanishes beyond h, and
    /// the support holds n_target particle spacings; the study uses n_target = 2.5).
    pub fn smoothing_lengths(&self, n_target: f64) -> Result<Vec<f64>, GeometryError> {
        let n = positive_finite("smoothing_lengths(n_target)", n_target)?;
        Ok(self.spacing.iter().map(|dx| n * dx).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::glam::DVec2;

    fn two() -> BodyParticles<DVec2> {
        BodyParticles {
            body: "test".into(),
            positions: vec![DVec2::ZERO, DVec2::X],
            masses: vec![1.0, 2.5],
            spacing: vec![1.0, 2.0],
            density: 1.0,
            exact_volume: None,
            volume: 3.5,
            raw_mass_error: None,
            lattice_equivalent_count: 3.5,
        }
    }

    #[test]
    fn totals_and_smoothing_lengths() {
        let b = two();
        assert_eq!(b.len(), 2);
        assert_eq!(b.total_mass(), 3.5);
        assert_eq!((b.min_spacing(), b.max_spacing()), (1.0, 2.0));
        assert_eq!(b.smoothing_lengths(2.5).unwrap(), vec![2.5, 5.0]);
        assert!((b.lattice_share() - 2.0 / 3.5).abs() < 1e-15);
        for bad in [0.0, -1.0, f64::NAN] {
            assert!(matches!(
                b.smoothing_lengths(bad),
                Err(GeometryError::InvalidParameter { .. })
            ));
        }
    }
}
