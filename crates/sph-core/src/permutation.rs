//! Reordering particle arrays: a validated [`Permutation`] and the space-filling-curve
//! (Morton / Z-order) ordering that keeps neighbours close in memory.

use crate::error::CoreError;
use crate::vector::Vector;

/// A bijection of `0..n`. `order[new] = old`: applying it moves the element at `old` to
/// position `new`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Permutation {
    order: Vec<usize>,
}

impl Permutation {
    /// Checks that `order` is a bijection of `0..order.len()`.
    pub fn new(order: Vec<usize>) -> Result<Self, CoreError> {
        let mut seen = vec![false; order.len()];
        for &o in &order {
            if o >= order.len() || seen[o] {
                return Err(CoreError::BadPermutation {
                    len: order.len(),
                    index: o,
                });
            }
            seen[o] = true;
        }
        Ok(Self { order })
    }
    /// The identity of length `n`.
    pub fn identity(n: usize) -> Self {
        Self {
            order: (0..n).collect(),
        }
    }
    /// `order[new] = old`.
    pub fn as_slice(&self) -> &[usize] {
        &self.order
    }
    /// Number of elements.
    pub fn len(&self) -> usize {
        self.order.len()
    }
    /// True for the empty permutation.
    pub fn is_empty(&self) -> bool {
        self.order.is_empty()
    }
    /// The inverse: `inverse[old] = new`.
    pub fn inverse(&self) -> Permutation {
        let mut inv = vec![0; self.order.len()];
        for (new, &old) in self.order.iter().enumerate() {
            inv[old] = new;
        }
        Permutation { order: inv }
    }
    /// Reorders `values` in place; errors if its length differs.
    pub fn apply<T: Clone>(
        &self,
        what: &'static str,
        values: &mut Vec<T>,
    ) -> Result<(), CoreError> {
        if values.len() != self.order.len() {
            return Err(CoreError::LengthMismatch {
                what,
                expected: self.order.len(),
                got: values.len(),
            });
        }
        let reordered: Vec<T> = self.order.iter().map(|&o| values[o].clone()).collect();
        *values = reordered;
        Ok(())
    }
}

/// Interleaves the low `bits` bits of each coordinate (Morton / Z-order key).
fn interleave(cells: &[u64], bits: u32) -> u64 {
    let dims = cells.len() as u32;
    let mut key = 0u64;
    for b in (0..bits).rev() {
        for c in cells {
            key = (key << 1) | ((c >> b) & 1);
        }
    }
    debug_assert!(bits * dims <= 64);
    key
}

/// The order of `positions` along a Morton (Z-order) space-filling curve over their
/// bounding box; ties keep the input order, so the result is deterministic.
///
/// Non-finite positions are an error (they have no place on the curve).
pub fn morton_order<V: Vector>(positions: &[V]) -> Result<Permutation, CoreError> {
    if positions.is_empty() {
        return Ok(Permutation::identity(0));
    }
    let mut lo = V::splat(f64::INFINITY);
    let mut hi = V::splat(f64::NEG_INFINITY);
    for (i, &p) in positions.iter().enumerate() {
        if !p.all_finite() {
            return Err(CoreError::NonFinitePosition {
                index: i,
                position: p.to_array3(),
            });
        }
        lo = lo.component_min(p);
        hi = hi.component_max(p);
    }
    let bits: u32 = 63 / V::DIM as u32;
    let cells_per_axis = ((1u64 << bits) - 1) as f64;
    let mut keyed: Vec<(u64, usize)> = positions
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let mut cells = [0u64; 3];
            for k in 0..V::DIM {
                let span = hi.component(k) - lo.component(k);
                let f = if span > 0.0 {
                    (p.component(k) - lo.component(k)) / span
                } else {
                    0.0
                };
                cells[k] = (f * cells_per_axis) as u64;
            }
            (interleave(&cells[..V::DIM], bits), i)
        })
        .collect();
    keyed.sort_unstable();
    Ok(Permutation {
        order: keyed.into_iter().map(|(_, i)| i).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn rejects_non_bijection() {
        assert!(Permutation::new(vec![0, 0]).is_err());
        assert!(Permutation::new(vec![0, 2]).is_err());
        assert!(Permutation::new(vec![1, 0]).is_ok());
    }

    #[test]
    fn inverse_undoes_apply() {
        let p = Permutation::new(vec![2, 0, 3, 1]).unwrap();
        let mut v = vec!['a', 'b', 'c', 'd'];
        p.apply("v", &mut v).unwrap();
        assert_eq!(v, vec!['c', 'a', 'd', 'b']);
        p.inverse().apply("v", &mut v).unwrap();
        assert_eq!(v, vec!['a', 'b', 'c', 'd']);
    }

    #[test]
    fn morton_visits_quadrants_in_z_order() {
        // One point per quadrant of the unit square, given in scrambled order.
        let pts = vec![
            DVec2::new(0.9, 0.9),
            DVec2::new(0.1, 0.1),
            DVec2::new(0.1, 0.9),
            DVec2::new(0.9, 0.1),
        ];
        let p = morton_order(&pts).unwrap();
        // Z-order with x as the lower bit within each level: (0,0), (1,0), (0,1), (1,1)
        // but our interleave puts x first (higher bit), so: (0,0), (0,1), (1,0), (1,1).
        assert_eq!(p.as_slice(), &[1, 2, 3, 0]);
    }

    #[test]
    fn morton_rejects_nan() {
        assert!(morton_order(&[DVec2::new(f64::NAN, 0.0)]).is_err());
    }
}
