//! Quality checks of a particle arrangement: how close the closest pair comes relative
//! to the local spacing. Two particles much closer than their spacing over-weight each
//! other in every kernel sum, so placements aim at a ratio of at least 1 below.

use crate::error::GeometryError;
use sph_core::{CellList, NeighborSearch, ScalarSupport, Vector};

/// The closest pair relative to the local spacing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CloseApproach {
    /// |x_i − x_j| / (0.5 · min(Δx_i, Δx_j)): 1 means the pair is half a spacing apart,
    /// 2 a full spacing.
    pub ratio: f64,
    /// First particle.
    pub i: usize,
    /// Second particle.
    pub j: usize,
}

/// The pair with the smallest |x_i − x_j| / (0.5 min(Δx_i, Δx_j)), searched with the
/// sph-core cell list at support radii Δx_i (pairs within max(Δx_i, Δx_j)). `None` when
/// no pair is that close: then every ratio is at least 2.
pub fn closest_approach<V: Vector>(
    positions: &[V],
    spacing: &[f64],
) -> Result<Option<CloseApproach>, GeometryError> {
    let list = CellList::new().neighbors(positions, &ScalarSupport::new(spacing)?)?;
    let mut best: Option<CloseApproach> = None;
    for i in 0..positions.len() {
        for j in list.neighbors(i) {
            let j = j as usize;
            if j <= i {
                continue;
            }
            let ratio = (positions[i] - positions[j]).norm() / (0.5 * spacing[i].min(spacing[j]));
            if best.is_none_or(|b| ratio < b.ratio) {
                best = Some(CloseApproach { ratio, i, j });
            }
        }
    }
    Ok(best)
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::glam::DVec2;

    #[test]
    fn finds_the_closest_pair() {
        let x = vec![
            DVec2::ZERO,
            DVec2::new(1.0, 0.0),
            DVec2::new(1.3, 0.0),
            DVec2::new(5.0, 0.0),
        ];
        let dx = vec![1.0, 1.0, 0.5, 1.0];
        let c = closest_approach(&x, &dx).unwrap().unwrap();
        assert_eq!((c.i, c.j), (1, 2));
        assert!((c.ratio - 0.3 / 0.25).abs() < 1e-12);
        let far = closest_approach(&[DVec2::ZERO, DVec2::X * 3.0], &[1.0, 1.0]).unwrap();
        assert!(far.is_none());
        assert!(closest_approach(&[DVec2::ZERO], &[0.0]).is_err());
    }
}
