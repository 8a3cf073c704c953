//! Neighbour search: which particles interact.
//!
//! * [`PairCriterion`]: when a pair interacts. [`ScalarSupport`] accepts
//!   |r_ij| < max(h_i, h_j); [`TensorSupport`] (ASPH) accepts |H_i r_ij| < 1 or
//!   |H_j r_ij| < 1. Both are symmetric, so j is a neighbour of i exactly when i is one
//!   of j, which momentum-conserving pair forces need.
//! * [`CellList`]: a sorted-grid cell list with one grid level per octave of support
//!   radius; each particle gathers within its own radius, and the pairs only the
//!   larger side reaches are handed to the smaller one, so fine and coarse particles
//!   each search a volume sized for them.
//! * [`NeighborList`]: the result in compressed sparse rows (CSR), each row sorted by
//!   index, self excluded. Built in parallel with rayon, identical for any thread count.
//! * [`PairSelection`]: a subset of a list's pairs, one bit per listed pair (a Verlet
//!   list's pairs of one stage), read with the list through [`Pairs`].
//! * [`brute_force_neighbors`]: the O(N²) reference used by the tests.
//! * [`halo`]: which particles outside a domain of rows can pair with one inside it, from
//!   the domain's block [`Region`]s: the ghost layer of a rank in a distributed run.

mod criterion;
mod grid;
mod halo;
mod list;
mod selection;

pub use criterion::{PairCriterion, ScalarSupport, TensorSupport};
pub use grid::{CellList, DEFAULT_CELL_FRACTION, DEFAULT_MAX_LEVELS, LevelStats};
pub use halo::{Region, halo, regions_of_rows};
pub use list::{NeighborList, Neighbors};
pub use selection::{PairSelection, Pairs, PickedRows, RowPicker};

use crate::error::CoreError;
use crate::vector::Vector;

/// A neighbour-search method. Implementations must return exactly the pairs the
/// criterion accepts (tested against [`brute_force_neighbors`]).
pub trait NeighborSearch<V: Vector> {
    /// All neighbours of every particle.
    fn neighbors<C: PairCriterion<V>>(
        &mut self,
        positions: &[V],
        criterion: &C,
    ) -> Result<NeighborList, CoreError>;
}

/// The O(N²) reference search: tests every pair. For tests and tiny problems only.
pub fn brute_force_neighbors<V: Vector, C: PairCriterion<V>>(
    positions: &[V],
    criterion: &C,
) -> Result<NeighborList, CoreError> {
    criterion::check_inputs(positions, criterion)?;
    let mut rows = Vec::with_capacity(positions.len());
    for (i, &xi) in positions.iter().enumerate() {
        let row: Vec<u32> = positions
            .iter()
            .enumerate()
            .filter(|&(j, &xj)| j != i && criterion.accepts(i, j, xi - xj))
            .map(|(j, _)| j as u32)
            .collect();
        rows.push(row);
    }
    Ok(NeighborList::from_rows(rows))
}
