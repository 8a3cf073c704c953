//! The ranks of one run (processes under MPI: the `mpi` feature; docs/mpi.md).
//!
//! Every rank holds the whole state and does the same per-particle work; the two pair
//! passes, which are most of a step, are shared out. Their rows come in fixed blocks
//! (pair_blocks.rs); each rank takes a contiguous range of blocks, balanced by the
//! neighbour count of their rows (a pair's cost), sums its blocks as a single process
//! would, and the ranks then share what the others read: after pass 1, each rank
//! receives the gradients of the rows its own rows' pairs read (its halo,
//! solver/ranks/halo.rs) and every rank's strain-rate gradient, which the stress update
//! reads for every particle; after pass 2, every rank's rates. A block's sums do not
//! depend on which rank adds them, so a run gives the same bits on any number of ranks
//! and threads, and a checkpoint written on some number of ranks resumes on any other.
//!
//! The state is replicated, not distributed: memory per rank is that of one process,
//! and the neighbour search, the EOS and the integration run on every rank.

use sph_core::{Dimension, Tensor, Vector};
use std::ops::Range;

mod halo;
mod local;
#[cfg(test)]
pub(crate) mod test_threads;
pub(crate) use halo::{Halo, rows_read};
pub use local::{LocalState, exchange_halo};

/// The ranks of a run, as the solver sees them: who this is, how many there are, and the
/// two collectives it needs. Implemented over MPI by the program (`mpi` feature) and by
/// [`OneRank`]; a test may implement it over threads.
pub trait Ranks: Sync {
    /// This rank, `0..size()`.
    fn rank(&self) -> usize;
    /// The number of ranks.
    fn size(&self) -> usize;
    /// Every rank's `own` values, in rank order (an all-gather of varying lengths).
    fn all_gather(&self, own: Vec<f64>) -> Gathered;
    /// Rank 0's `data` on every rank (what the others pass is ignored).
    fn broadcast(&self, data: Vec<u8>) -> Vec<u8>;
    /// Sends `to[k]` to each rank k and returns what each rank sent this one, in rank
    /// order (a personalised all-to-all; `to` has [`Ranks::size`] entries, this rank's
    /// own included). The default goes through [`Ranks::all_gather`], so every rank
    /// receives every message: correct, but with the traffic of a gather. The MPI
    /// transport sends each rank only its own (MPI_Alltoallv).
    fn exchange(&self, to: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
        assert_eq!(to.len(), self.size(), "one message per rank");
        // Each rank's part: the lengths of its messages, then the messages.
        let mut own: Vec<f64> = to.iter().map(|m| m.len() as f64).collect();
        for m in &to {
            own.extend_from_slice(m);
        }
        let all = self.all_gather(own);
        let (me, size) = (self.rank(), self.size());
        (0..size)
            .map(|k| {
                let part = all.part(k);
                let before: usize = part[..me].iter().map(|&n| n as usize).sum();
                let start = size + before;
                part[start..start + part[me] as usize].to_vec()
            })
            .collect()
    }
}

/// The values of an all-gather: every rank's, one after the other in rank order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Gathered {
    /// The values.
    pub values: Vec<f64>,
    /// How many each rank sent.
    pub lengths: Vec<usize>,
}

impl Gathered {
    /// Rank k's values.
    pub fn part(&self, k: usize) -> &[f64] {
        let start: usize = self.lengths[..k].iter().sum();
        &self.values[start..start + self.lengths[k]]
    }
}

/// A single process: nothing to share.
#[derive(Clone, Copy, Debug, Default)]
pub struct OneRank;

impl Ranks for OneRank {
    fn rank(&self) -> usize {
        0
    }
    fn size(&self) -> usize {
        1
    }
    fn all_gather(&self, own: Vec<f64>) -> Gathered {
        Gathered {
            lengths: vec![own.len()],
            values: own,
        }
    }
    fn broadcast(&self, data: Vec<u8>) -> Vec<u8> {
        data
    }
}

/// The contiguous ranges of blocks of each of `size` ranks, given each block's cost:
/// rank k takes the blocks whose cost midpoint lies in [k, k + 1) × total/size. Every
/// rank computes the same ranges from the same costs.
pub fn shares(costs: &[u64], size: usize) -> Vec<Range<usize>> {
    let total: u64 = costs.iter().sum();
    let mut ranges = Vec::with_capacity(size);
    let mut start = 0;
    let mut before = 0_u64;
    let mut b = 0;
    for k in 0..size {
        // The blocks whose midpoint (before + cost/2) is below (k + 1) total/size.
        let bound = (k as u128 + 1) * total as u128;
        while b < costs.len() && (2 * before as u128 + costs[b] as u128) * size as u128 <= 2 * bound
        {
            before += costs[b];
            b += 1;
        }
        if k + 1 == size {
            b = costs.len();
        }
        ranges.push(start..b);
        start = b;
    }
    ranges
}

/// A value of the pair passes' output per particle, written as f64s for the gather.
pub(crate) trait Flat: Copy {
    /// How many f64s.
    const LEN: usize;
    /// Appends the value's f64s to `out`.
    fn put(&self, out: &mut Vec<f64>);
    /// The value from the first [`Flat::LEN`] of `v`.
    fn get(v: &[f64]) -> Self;
}

impl Flat for f64 {
    const LEN: usize = 1;
    fn put(&self, out: &mut Vec<f64>) {
        out.push(*self);
    }
    fn get(v: &[f64]) -> Self {
        v[0]
    }
}

/// A particle's index and a vector (a boundary force of pass 2); the index as an f64,
/// exact below 2⁵³.
impl<V: Vector> Flat for (u32, V) {
    const LEN: usize = 1 + V::DIM;
    fn put(&self, out: &mut Vec<f64>) {
        out.push(f64::from(self.0));
        put_vector(self.1, out);
    }
    fn get(v: &[f64]) -> Self {
        (v[0] as u32, get_vector(&v[1..]))
    }
}

/// A vector's components.
pub(crate) fn put_vector<V: Vector>(v: V, out: &mut Vec<f64>) {
    out.extend((0..V::DIM).map(|k| v.component(k)));
}

/// A tensor's components, row by row.
pub(crate) fn put_tensor<T: Tensor>(t: &T, out: &mut Vec<f64>) {
    let n = T::Vector::DIM;
    out.extend((0..n * n).map(|k| t.component(k / n, k % n)));
}

/// The vector of the first DIM f64s of `v`.
pub(crate) fn get_vector<V: Vector>(v: &[f64]) -> V {
    V::from_fn(|k| v[k])
}

/// The tensor of the first DIM² f64s of `v`, row by row.
pub(crate) fn get_tensor<T: Tensor>(v: &[f64]) -> T {
    let n = T::Vector::DIM;
    T::from_fn(|i, j| v[i * n + j])
}

/// The f64s of a tensor of dimension `D`.
pub(crate) const fn tensor_len<D: Dimension>() -> usize {
    D::DIM * D::DIM
}

/// Gathers the rows `rows[k]` of `data` from each rank k into every rank's `data` (this
/// rank's own rows are left as they are).
pub(crate) fn gather_rows<T: Flat>(ranks: &dyn Ranks, data: &mut [T], rows: &[Range<usize>]) {
    gather_rows_by(ranks, data, rows, T::LEN, T::put, |x, v| *x = T::get(v));
}

/// [`gather_rows`] of `len` f64s of each value, written by `put` and stored back into
/// the value by `set` (which may set only some of its fields).
pub(crate) fn gather_rows_by<T>(
    ranks: &dyn Ranks,
    data: &mut [T],
    rows: &[Range<usize>],
    len: usize,
    put: impl Fn(&T, &mut Vec<f64>),
    set: impl Fn(&mut T, &[f64]),
) {
    let me = ranks.rank();
    let mut own = Vec::with_capacity(rows[me].len() * len);
    for x in &data[rows[me].clone()] {
        put(x, &mut own);
    }
    let all = ranks.all_gather(own);
    for k in (0..ranks.size()).filter(|&k| k != me) {
        let theirs = all.part(k);
        assert_eq!(
            theirs.len(),
            rows[k].len() * len,
            "rank {k} sent {} values for {} rows",
            theirs.len(),
            rows[k].len()
        );
        for (x, v) in data[rows[k].clone()]
            .iter_mut()
            .zip(theirs.chunks_exact(len))
        {
            set(x, v);
        }
    }
}

/// Every rank's `own` list, concatenated in rank order.
pub(crate) fn gather_list<T: Flat>(ranks: &dyn Ranks, own: &[T]) -> Vec<T> {
    let mut flat = Vec::with_capacity(own.len() * T::LEN);
    for x in own {
        x.put(&mut flat);
    }
    ranks
        .all_gather(flat)
        .values
        .chunks_exact(T::LEN)
        .map(T::get)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::glam::{DMat3, DVec3};

    #[test]
    fn shares_cover_the_blocks_in_order_and_balance_their_cost() {
        for size in 1..=7 {
            for costs in [
                vec![],
                vec![5],
                vec![1; 10],
                vec![100, 1, 1, 1, 1, 1, 1, 100],
                (0..64).map(|k| (k * k % 17 + 1) as u64).collect(),
            ] {
                let s = shares(&costs, size);
                assert_eq!(s.len(), size);
                assert_eq!(s[0].start, 0);
                assert_eq!(s[size - 1].end, costs.len());
                for w in s.windows(2) {
                    assert_eq!(w[0].end, w[1].start, "{costs:?} on {size}");
                }
                // Each rank's cost is within one block's cost of the even share.
                let total: u64 = costs.iter().sum();
                let largest = costs.iter().copied().max().unwrap_or(0);
                for r in &s {
                    let cost: u64 = costs[r.clone()].iter().sum();
                    let even = total as f64 / size as f64;
                    assert!(
                        (cost as f64 - even).abs() <= largest as f64,
                        "{costs:?} on {size}: {s:?}"
                    );
                }
            }
        }
        // Even costs split evenly.
        assert_eq!(shares(&[1; 8], 4), vec![0..2, 2..4, 4..6, 6..8]);
        assert_eq!(shares(&[1; 8], 1), vec![0..8]);
    }

    #[test]
    fn vectors_and_tensors_round_trip_through_their_f64s() {
        let v = DVec3::new(1.5, -2.0, 3.25);
        let t = DMat3::from_cols_array(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.5]);
        let mut out = Vec::new();
        put_vector(v, &mut out);
        put_tensor(&t, &mut out);
        assert_eq!(out.len(), 3 + tensor_len::<sph_core::Dim3>());
        assert_eq!(get_vector::<DVec3>(&out), v);
        assert_eq!(get_tensor::<DMat3>(&out[3..]), t);
        let mut one = Vec::new();
        put_vector(2.5_f64, &mut one);
        put_tensor(&-1.0_f64, &mut one);
        assert_eq!(
            (get_vector::<f64>(&one), get_tensor::<f64>(&one[1..])),
            (2.5, -1.0)
        );
    }
}
