//! Pairs evaluated once: the blocks of rows of the pair passes.
//!
//! A pair term is the same for both particles up to the sign of ∇W and the partner's
//! mass, so evaluating it from both sides, as a plain gather does, pays for the kernel,
//! the pair's Riemann problem and the reading of both particles' data twice. The pair
//! passes instead walk the real particles' rows in fixed blocks of consecutive indices
//! (the particles are in Morton order, so a block is a compact region of space): a pair
//! whose two particles lie in one block is evaluated once, at the row of the smaller
//! index, and its share is added to both; a pair that crosses blocks, or has a ghost, is
//! evaluated from each real side as before. Each block writes only its own rows, so the
//! blocks run in parallel without atomics.
//!
//! The block size depends only on the number of particles, never on the thread count,
//! so the order in which each particle's sums are added is fixed and results stay
//! bit-identical for any number of threads.

/// Rows per block for `n` real particles: n/64 rounded up to a power of two, kept within
/// 256–4 096 (at least 64 blocks where n allows it, for the threads; at most 4 096 rows,
/// whose accumulators stay in cache). In a Morton-ordered 3-D block of 4 096 particles
/// (about 16 spacings across) with a support of 2.5 spacings, about four pairs in five
/// lie inside the block.
pub(crate) fn block_rows(n: usize) -> usize {
    (n / 64).next_power_of_two().clamp(256, 4096)
}

/// The rows of the blocks `blocks` (of `rows` rows each, over `n` real particles; the
/// last block may be shorter).
pub(crate) fn rows_of(
    blocks: &std::ops::Range<usize>,
    rows: usize,
    n: usize,
) -> std::ops::Range<usize> {
    (blocks.start * rows).min(n)..(blocks.end * rows).min(n)
}

/// How row `i` of the block `start..end` treats its neighbour `j`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Visit {
    /// j lies in the block above i: the pair is evaluated here for both particles.
    Both,
    /// j lies outside the block (or is a ghost): the pair is evaluated here for i only.
    OwnOnly,
    /// j lies in the block below i: the pair was evaluated at row j for both.
    Done,
}

/// The rule of [`Visit`] for row `i` and neighbour `j` in the block `start..end` (real
/// particles only; ghosts have indices past every block).
#[inline]
pub(crate) fn visit(i: usize, j: usize, start: usize, end: usize) -> Visit {
    if j < start || j >= end {
        Visit::OwnOnly
    } else if j > i {
        Visit::Both
    } else {
        Visit::Done
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rows_of_blocks_end_at_the_last_particle() {
        assert_eq!(rows_of(&(0..2), 256, 700), 0..512);
        assert_eq!(rows_of(&(2..3), 256, 700), 512..700);
        assert_eq!(rows_of(&(3..3), 256, 700), 700..700);
    }

    #[test]
    fn block_rows_depend_on_n_only_and_stay_in_range() {
        assert_eq!(block_rows(0), 256);
        assert_eq!(block_rows(6_418), 256);
        assert_eq!(block_rows(100_000), 2048);
        assert_eq!(block_rows(311_999), 4096);
        assert_eq!(block_rows(10_000_000), 4096);
    }

    /// Every directed pair (i, j) of a symmetric neighbour relation gets its share exactly
    /// once: from row i (OwnOnly or Both) or from row j (Both).
    #[test]
    fn every_directed_pair_is_counted_once() {
        let n = 700;
        let rows = block_rows(n);
        // A symmetric relation: |i − j| ≤ 40 or (i + j) divisible by 97, with ghosts
        // (indices ≥ n) attached to a few rows.
        let related =
            |i: usize, j: usize| i != j && (i.abs_diff(j) <= 40 || (i + j).is_multiple_of(97));
        let mut count = std::collections::HashMap::new();
        for start in (0..n).step_by(rows) {
            let end = (start + rows).min(n);
            for i in start..end {
                let ghosts = if i.is_multiple_of(50) {
                    vec![n + i]
                } else {
                    vec![]
                };
                for j in (0..n).filter(|&j| related(i, j)).chain(ghosts) {
                    match visit(i, j, start, end) {
                        Visit::OwnOnly => *count.entry((i, j)).or_insert(0) += 1,
                        Visit::Both => {
                            *count.entry((i, j)).or_insert(0) += 1;
                            *count.entry((j, i)).or_insert(0) += 1;
                        }
                        Visit::Done => {}
                    }
                }
            }
        }
        for i in 0..n {
            for j in (0..n).filter(|&j| related(i, j)) {
                assert_eq!(count.get(&(i, j)), Some(&1), "pair ({i}, {j})");
            }
            if i.is_multiple_of(50) {
                assert_eq!(count.get(&(i, n + i)), Some(&1), "ghost of {i}");
            }
        }
        let total: usize = count.values().sum();
        let expected = (0..n)
            .map(|i| (0..n).filter(|&j| related(i, j)).count() + usize::from(i.is_multiple_of(50)))
            .sum::<usize>();
        assert_eq!(total, expected);
    }
}
