//! The rows of other ranks that a rank's pair pass reads (its halo), and their exchange
//! between pass 1 and pass 2 (docs/mpi.md, "How a run is shared").
//!
//! Pass 2 of a rank's rows reads pass 1's gradients of every particle its rows list as
//! neighbours, and of the sources of the boundary ghosts they list. A rank knows these
//! exactly from its own neighbour rows, so it asks each owner for them by index (one
//! exchange of indices) instead of gathering every rank's rows; the owners then send
//! the values asked of them. The rows a rank receives are the ones a single process
//! reads, with the same bits, so the run stays bit-identical on any number of ranks.

use super::{Flat, Ranks};
use sph_core::Pairs;
use std::ops::Range;

/// The real particles (of `n`) whose pass-1 values the pairs of the rows `own` read,
/// besides `own` itself: the source of every neighbour `list` gives those rows (a real
/// particle is its own source, a boundary ghost's is the particle it images), ascending.
pub(crate) fn rows_read(list: Pairs<'_>, source: &[u32], own: Range<usize>, n: usize) -> Vec<u32> {
    let mut read = vec![false; n];
    let mut scratch = Vec::new();
    for i in own.clone() {
        for &j in list.row(i, &mut scratch) {
            read[source[j as usize] as usize] = true;
        }
    }
    read[own].fill(false);
    (0..n as u32).filter(|&j| read[j as usize]).collect()
}

/// Which rows a rank receives from each rank, and which it sends to each, for one
/// neighbour list.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Halo {
    /// The rows this rank receives from each rank, ascending (none from itself).
    pub(super) receive: Vec<Vec<u32>>,
    /// The rows each rank asked of this one, ascending.
    pub(super) send: Vec<Vec<u32>>,
}

impl Halo {
    /// The halo of the rows `needed` (ascending, none of them this rank's own), each
    /// asked of the rank whose range of `rows` holds it. Every rank calls this together
    /// (one [`Ranks::exchange`] of the indices).
    pub(crate) fn new(ranks: &dyn Ranks, needed: &[u32], rows: &[Range<usize>]) -> Self {
        let size = ranks.size();
        let mut receive = vec![Vec::new(); size];
        let mut k = 0;
        for &j in needed {
            // Both `needed` and the ranges ascend, so the owner only moves forward.
            while !rows[k].contains(&(j as usize)) {
                k += 1;
            }
            debug_assert_ne!(k, ranks.rank(), "row {j} is this rank's own");
            receive[k].push(j);
        }
        let asks = receive
            .iter()
            .map(|r| r.iter().map(|&j| f64::from(j)).collect())
            .collect();
        // An index travels as an f64, exact below 2⁵³.
        let send = ranks
            .exchange(asks)
            .into_iter()
            .map(|m| m.into_iter().map(|x| x as u32).collect())
            .collect();
        Halo { receive, send }
    }

    /// Sends the rows asked of this rank and writes the rows received into `data`
    /// (every rank calls this together).
    pub(crate) fn fill<T: Flat>(&self, ranks: &dyn Ranks, data: &mut [T]) {
        self.fill_by(ranks, data, T::LEN, T::put, T::get);
    }

    /// [`Halo::fill`] with the value's `len` f64s written by `put` and read by `get`.
    pub(crate) fn fill_by<T>(
        &self,
        ranks: &dyn Ranks,
        data: &mut [T],
        len: usize,
        put: impl Fn(&T, &mut Vec<f64>),
        get: impl Fn(&[f64]) -> T,
    ) {
        let to = self
            .send
            .iter()
            .map(|rows| {
                let mut m = Vec::with_capacity(rows.len() * len);
                for &j in rows {
                    put(&data[j as usize], &mut m);
                }
                m
            })
            .collect();
        for (k, m) in ranks.exchange(to).iter().enumerate() {
            let rows = &self.receive[k];
            assert_eq!(
                m.len(),
                rows.len() * len,
                "rank {k} sent {} values for {} rows",
                m.len(),
                rows.len()
            );
            for (&j, v) in rows.iter().zip(m.chunks_exact(len)) {
                data[j as usize] = get(v);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::OneRank;
    use super::*;
    use sph_core::NeighborList;

    #[test]
    fn the_rows_read_are_the_sources_of_the_listed_neighbours_outside_the_rows() {
        // Six real particles and two ghosts (6 copies 5, 7 copies 0); rows 2 and 3 are
        // this rank's. Row 2 lists 1, 3 and ghost 6; row 3 lists 2, 4 and ghost 7.
        let list = NeighborList::from_rows(vec![
            vec![1],
            vec![0, 2],
            vec![1, 3, 6],
            vec![2, 4, 7],
            vec![3, 5],
            vec![4],
        ]);
        let source = [0, 1, 2, 3, 4, 5, 5, 0];
        assert_eq!(rows_read(Pairs::all(&list), &source, 2..4, 6), [0, 1, 4, 5]);
        assert_eq!(
            rows_read(Pairs::all(&list), &source, 0..6, 6),
            [] as [u32; 0]
        );
    }

    #[test]
    fn one_rank_has_no_halo() {
        let rows: Vec<Range<usize>> = std::iter::once(0..10).collect();
        let halo = Halo::new(&OneRank, &[], &rows);
        assert_eq!(
            halo,
            Halo {
                receive: vec![vec![]],
                send: vec![vec![]]
            }
        );
        let mut data = vec![1.0_f64, 2.0, 3.0];
        halo.fill(&OneRank, &mut data);
        assert_eq!(data, [1.0, 2.0, 3.0]);
    }
}
