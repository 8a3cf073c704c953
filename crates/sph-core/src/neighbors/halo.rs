//! The halo of a domain: the particles outside it that can pair with one inside.
//!
//! A run whose particles are shared among ranks as contiguous ranges of rows (the
//! Morton order makes each range a region of space) needs, on each rank, the particles
//! of the others that pair with its own: its ghost layer. A rank cannot search the
//! others' particles, so the rule works from what is cheap to exchange: each domain is
//! described by a few [`Region`]s, the bounding boxes of runs of its consecutive rows
//! with the largest reach among their particles ([`regions_of_rows`]), and the owner of
//! a particle j sends it
//! to a domain when j is within max(reach_j, region reach) of one of the domain's
//! boxes ([`halo`]).
//!
//! The rule misses no pair: for i in a region B and j outside the domain, a criterion
//! that accepts the pair has |x_i − x_j| < max(radius(i), radius(j)) ([`PairCriterion`]),
//! the distance from x_j to B is at most |x_i − x_j|, and radius(i) ≤ B's reach. It may
//! send more than the pairs need (a box is larger than its particles); the test suite
//! holds both the completeness, against the brute-force search, and the excess on a
//! lattice.

use std::ops::Range;

use super::PairCriterion;
use crate::error::CoreError;
use crate::vector::Vector;

/// An axis-aligned box around some particles, with the largest reach (support radius)
/// among them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region<V: Vector> {
    /// The smallest coordinates of the particles.
    pub lo: V,
    /// The largest coordinates of the particles.
    pub hi: V,
    /// The largest `radius(i)` of the particles.
    pub reach: f64,
}

impl<V: Vector> Region<V> {
    /// The box around the particles `rows` and their largest reach; `None` for no rows.
    pub fn around<C: PairCriterion<V>>(
        positions: &[V],
        criterion: &C,
        rows: Range<usize>,
    ) -> Option<Self> {
        if rows.is_empty() {
            return None;
        }
        let first = *positions.get(rows.start)?;
        let mut region = Region {
            lo: first,
            hi: first,
            reach: 0.0,
        };
        for i in rows {
            region.lo = region.lo.component_min(positions[i]);
            region.hi = region.hi.component_max(positions[i]);
            region.reach = region.reach.max(criterion.radius(i));
        }
        Some(region)
    }

    /// The box around both regions, with the larger reach.
    pub fn union(&self, other: &Self) -> Self {
        Region {
            lo: self.lo.component_min(other.lo),
            hi: self.hi.component_max(other.hi),
            reach: self.reach.max(other.reach),
        }
    }

    /// The squared Euclidean distance from `x` to the box (0 inside it), summed over
    /// the axes in the order a vector's squared norm is: never above the squared
    /// distance to a point inside the box, to the last bit.
    pub fn distance_squared(&self, x: V) -> f64 {
        let outside = V::from_fn(|k| {
            let (c, lo, hi) = (x.component(k), self.lo.component(k), self.hi.component(k));
            (lo - c).max(c - hi).max(0.0)
        });
        outside.norm_squared()
    }

    /// The Euclidean distance from `x` to the box (0 inside it).
    pub fn distance(&self, x: V) -> f64 {
        self.distance_squared(x).sqrt()
    }

    /// Whether a particle at `x` with reach `radius` can pair with one of the region's
    /// particles: closer to the box than the larger of the two reaches (compared squared,
    /// as the pair criterion compares |r_ij|², so no pair is lost to rounding).
    pub fn may_pair(&self, x: V, radius: f64) -> bool {
        let reach = radius.max(self.reach);
        self.distance_squared(x) < reach * reach
    }
}

/// The regions of the rows `rows`, each a run of consecutive rows whose box stays
/// within `size` times its largest reach on every side: a domain's description for
/// [`halo`]. Where the rows jump (a space-filling curve does at its cell boundaries) a
/// new region starts, so each box stays near its particles. A smaller `size` gives
/// tighter boxes and more of them.
pub fn regions_of_rows<V: Vector, C: PairCriterion<V>>(
    positions: &[V],
    criterion: &C,
    rows: Range<usize>,
    size: f64,
) -> Result<Vec<Region<V>>, CoreError> {
    super::criterion::check_inputs(positions, criterion)?;
    check_rows(&rows, positions.len())?;
    if !(size > 0.0 && size.is_finite()) {
        return Err(CoreError::BadField {
            index: rows.start,
            field: "region size",
            value: size,
            reason: "a region's size (in reaches) must be positive and finite",
        });
    }
    Ok(regions_of(positions, criterion, rows, size))
}

/// [`regions_of_rows`] on inputs already checked (the partial search's).
pub(super) fn regions_of<V: Vector, C: PairCriterion<V>>(
    positions: &[V],
    criterion: &C,
    rows: Range<usize>,
    size: f64,
) -> Vec<Region<V>> {
    let mut regions = Vec::new();
    let mut current: Option<Region<V>> = None;
    for i in rows {
        let (x, r) = (positions[i], criterion.radius(i));
        let grown = current.map(|b| Region {
            lo: b.lo.component_min(x),
            hi: b.hi.component_max(x),
            reach: b.reach.max(r),
        });
        current = match grown {
            Some(g)
                if (0..V::DIM).all(|k| g.hi.component(k) - g.lo.component(k) <= size * g.reach) =>
            {
                Some(g)
            }
            _ => {
                regions.extend(current);
                Some(Region {
                    lo: x,
                    hi: x,
                    reach: r,
                })
            }
        };
    }
    regions.extend(current);
    regions
}

/// The particles `candidates` (ascending) that can pair with a particle of a domain
/// described by `regions`: the ones its owner sends to that domain as its halo. The
/// candidates should be outside the domain (its own particles are not its halo).
pub fn halo<V: Vector, C: PairCriterion<V>>(
    regions: &[Region<V>],
    positions: &[V],
    criterion: &C,
    candidates: Range<usize>,
) -> Result<Vec<u32>, CoreError> {
    super::criterion::check_inputs(positions, criterion)?;
    check_rows(&candidates, positions.len())?;
    Ok(candidates
        .filter(|&j| {
            let (x, radius) = (positions[j], criterion.radius(j));
            regions.iter().any(|b| b.may_pair(x, radius))
        })
        .map(|j| j as u32)
        .collect())
}

/// `rows` must lie within the `n` particles.
fn check_rows(rows: &Range<usize>, n: usize) -> Result<(), CoreError> {
    if rows.start > rows.end || rows.end > n {
        return Err(CoreError::LengthMismatch {
            what: "rows (a range of the particles)",
            expected: n,
            got: rows.end,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::neighbors::ScalarSupport;
    use glam::DVec2;

    #[test]
    fn distance_to_a_box() {
        let b = Region {
            lo: DVec2::new(0.0, 0.0),
            hi: DVec2::new(1.0, 2.0),
            reach: 0.5,
        };
        assert_eq!(b.distance(DVec2::new(0.5, 1.0)), 0.0);
        assert_eq!(b.distance(DVec2::new(-3.0, 1.0)), 3.0);
        assert_eq!(b.distance(DVec2::new(4.0, 6.0)), 5.0);
        // The larger reach decides: 0.5 from the box pairs only with a reach above 0.5.
        assert!(!b.may_pair(DVec2::new(1.5, 0.0), 0.2));
        assert!(b.may_pair(DVec2::new(1.5, 0.0), 0.6));
        assert!(b.may_pair(DVec2::new(1.4, 0.0), 0.2));
    }

    #[test]
    fn a_chain_sends_what_reaches_across_the_cut() {
        // Ten particles on a line, spacing 1, reach 1.5: each pairs with its nearest
        // neighbour on each side. Domain 0..5: its
        // halo is particle 5 alone, and the rows 5..10 need particle 4 alone.
        let x: Vec<f64> = (0..10).map(f64::from).collect();
        let h = vec![1.5; 10];
        let s = ScalarSupport::new(&h).unwrap();
        // Boxes of at most 1.5 across: [0, 1], [2, 3], [4].
        let left = regions_of_rows(&x, &s, 0..5, 1.0).unwrap();
        assert_eq!(left.len(), 3);
        assert_eq!(halo(&left, &x, &s, 5..10).unwrap(), vec![5]);
        let right = regions_of_rows(&x, &s, 5..10, 10.0).unwrap();
        assert_eq!(right.len(), 1);
        assert_eq!(halo(&right, &x, &s, 0..5).unwrap(), vec![4]);
        // A wider particle far off reaches in by its own radius.
        let mut h = h;
        h[9] = 5.5;
        let s = ScalarSupport::new(&h).unwrap();
        let left = regions_of_rows(&x, &s, 0..5, 1.0).unwrap();
        assert_eq!(halo(&left, &x, &s, 5..10).unwrap(), vec![5, 9]);
    }

    #[test]
    fn bad_input_is_an_error() {
        let x = vec![0.0, 1.0];
        let h = vec![1.0, 1.0];
        let s = ScalarSupport::new(&h).unwrap();
        assert!(regions_of_rows(&x, &s, 0..3, 1.0).is_err());
        assert!(regions_of_rows(&x, &s, 0..2, 0.0).is_err());
        assert!(regions_of_rows(&x, &s, 0..2, f64::NAN).is_err());
        assert!(halo(&[], &x, &s, 1..3).is_err());
        assert!(halo::<f64, _>(&[], &[0.0], &s, 0..1).is_err());
        assert_eq!(regions_of_rows(&x, &s, 1..1, 4.0).unwrap(), vec![]);
    }
}
