//! Optional columns cut into the chunks of a parallel pass.

use rayon::prelude::*;

/// `v` by chunks of `chunk` as `Some`, or `n_chunks` times `None` when `v` is empty (a
/// column the run does not have), to be zipped with the chunks of the arrays a pass
/// always writes.
pub(crate) fn chunks_or_none<T: Send>(
    v: &mut [T],
    chunk: usize,
    n_chunks: usize,
) -> impl IndexedParallelIterator<Item = Option<&mut [T]>> {
    if v.is_empty() {
        rayon::iter::Either::Left((0..n_chunks).into_par_iter().map(|_| None))
    } else {
        rayon::iter::Either::Right(v.par_chunks_mut(chunk).map(Some))
    }
}

/// An optional column's rows `own`, or the empty column itself where the run does not
/// keep it (for [`chunks_or_none`]).
pub(crate) fn rows_or_empty<'a, T>(v: &'a mut [T], own: &std::ops::Range<usize>) -> &'a mut [T] {
    if v.is_empty() { v } else { &mut v[own.clone()] }
}
