//! Mass-weighted histogram with given edges: mass per bin, and the mass below the first
//! and above the last edge kept apart rather than dropped, so the bins plus the two
//! outsides always add up to the total.

use crate::error::{ImpactError, finite};
use serde::{Deserialize, Serialize};

/// Mass (kg) per bin e_k ≤ x < e_(k+1); the last bin also holds x = e_last.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MassHistogram {
    /// Bin edges, strictly increasing (units of the binned quantity).
    pub edges: Vec<f64>,
    /// Mass in each bin (kg); one fewer than edges.
    pub mass: Vec<f64>,
    /// Mass with x < e_0 (kg).
    pub below: f64,
    /// Mass with x > e_last, or x NaN (kg): mass is never dropped.
    pub above: f64,
}

impl MassHistogram {
    /// An empty histogram on `edges` (at least two, finite, strictly increasing).
    pub fn new(edges: Vec<f64>) -> Result<Self, ImpactError> {
        if edges.len() < 2 {
            return Err(ImpactError::BadParameter {
                name: "edges",
                value: edges.len() as f64,
                reason: "a histogram needs at least two edges",
            });
        }
        for w in edges.windows(2) {
            finite("edge", w[0])?;
            finite("edge", w[1])?;
            if !(w[1] > w[0]) {
                return Err(ImpactError::BadParameter {
                    name: "edge",
                    value: w[1],
                    reason: "edges must increase strictly",
                });
            }
        }
        let n = edges.len() - 1;
        Ok(Self {
            edges,
            mass: vec![0.0; n],
            below: 0.0,
            above: 0.0,
        })
    }

    /// Adds mass `m` (kg) at value `x` (binary search: O(log bins)). Never panics, even
    /// on a hand-built histogram with inconsistent fields (then the mass goes `above`).
    pub fn add(&mut self, x: f64, m: f64) {
        let (Some(&first), Some(&last)) = (self.edges.first(), self.edges.last()) else {
            self.above += m;
            return;
        };
        if x < first {
            self.below += m;
            return;
        }
        if !(x <= last) {
            self.above += m;
            return;
        }
        // Edges ≤ x, minus one, is the bin (≥ 0 since e_0 ≤ x); x = e_last goes last.
        let k = self.edges.partition_point(|&e| e <= x).saturating_sub(1);
        let k = k.min(self.mass.len().saturating_sub(1));
        match self.mass.get_mut(k) {
            Some(b) => *b += m,
            None => self.above += m,
        }
    }

    /// Total mass, bins and outsides (kg).
    pub fn total(&self) -> f64 {
        self.below + self.mass.iter().sum::<f64>() + self.above
    }
}

/// `bins` + 1 equal-width edges from `lo` to `hi` (finite, lo < hi, bins ≥ 1).
pub fn uniform_edges(lo: f64, hi: f64, bins: usize) -> Result<Vec<f64>, ImpactError> {
    if bins == 0 {
        return Err(ImpactError::BadParameter {
            name: "bins",
            value: 0.0,
            reason: "at least one bin",
        });
    }
    let (lo, hi) = (finite("lo", lo)?, finite("hi", hi)?);
    // Each edge from its index (not by repeated addition), with the last exactly `hi`.
    let mut e: Vec<f64> = (0..=bins)
        .map(|k| lo + (hi - lo) * k as f64 / bins as f64)
        .collect();
    e[bins] = hi;
    Ok(e)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn hand_made_histogram() {
        let mut h = MassHistogram::new(uniform_edges(0.0, 1.0, 4).unwrap()).unwrap();
        assert_eq!(h.edges, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
        for (x, m) in [
            (-0.1, 1.0),
            (0.0, 2.0),
            (0.25, 3.0),
            (0.6, 4.0),
            (1.0, 5.0),
            (1.1, 6.0),
        ] {
            h.add(x, m);
        }
        assert_eq!(h.mass, vec![2.0, 3.0, 4.0, 5.0]);
        assert_eq!((h.below, h.above, h.total()), (1.0, 6.0, 21.0));
        h.add(f64::NAN, 1.0);
        assert_eq!(h.above, 7.0);
        assert!(MassHistogram::new(vec![0.0]).is_err());
        assert!(MassHistogram::new(vec![0.0, 0.0]).is_err());
        assert!(MassHistogram::new(vec![0.0, f64::NAN]).is_err());
        assert!(uniform_edges(0.0, 1.0, 0).is_err());
        assert!(uniform_edges(0.0, f64::INFINITY, 3).is_err());
    }

    proptest! {
        #[test]
        fn nothing_is_lost(
            xs in prop::collection::vec((-2.0f64..3.0, 0.0f64..1.0), 0..100),
            bins in 1usize..20,
        ) {
            let mut h = MassHistogram::new(uniform_edges(0.0, 1.0, bins).unwrap()).unwrap();
            let mut sum = 0.0;
            for &(x, m) in &xs {
                h.add(x, m);
                sum += m;
            }
            prop_assert!((h.total() - sum).abs() <= 1e-12 * (1.0 + sum));
        }
    }
}
