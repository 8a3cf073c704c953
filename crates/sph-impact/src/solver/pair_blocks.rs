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

/// How the pair passes evaluate a list's pairs ([`pair_evaluations`]): the directed
/// entries of its rows, over the passes' blocks of `block_rows` rows, by where each
/// pair is evaluated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PairEvaluations {
    /// Rows per block (a function of the particle count alone).
    pub block_rows: usize,
    /// Entries whose pair is evaluated at that row for both particles.
    pub both: u64,
    /// Entries whose partner lies outside the row's block (or is a ghost): evaluated at
    /// that row for it alone, so such a pair is evaluated from each real side.
    pub across: u64,
    /// Entries whose pair was evaluated at the partner's row.
    pub done: u64,
    /// The real particles of later blocks that a block's rows list, counted once per
    /// block and summed over the blocks: the shares a block would owe other blocks if
    /// pairs across blocks were evaluated once (docs/performance.md, "Three levers of
    /// pass 2 measured on a quiet machine").
    pub later: u64,
}

impl PairEvaluations {
    /// Directed entries counted.
    fn entries(&self) -> u64 {
        self.both + self.across + self.done
    }

    /// Pair evaluations per pair (per two directed entries): 1 when every pair lies
    /// inside a block, 2 for a gather that evaluates each pair from both sides; 0 for
    /// no pairs.
    pub fn per_pair(&self) -> f64 {
        match self.entries() {
            0 => 0.0,
            e => (self.both + self.across) as f64 / (e as f64 / 2.0),
        }
    }

    /// The share of the entries whose partner lies outside the row's block; 0 for no
    /// pairs.
    pub fn across_share(&self) -> f64 {
        match self.entries() {
            0 => 0.0,
            e => self.across as f64 / e as f64,
        }
    }
}

/// Counts how the pair passes would evaluate the pairs of `list`, whose first `n` rows
/// are the real particles', over the blocks the passes use for `n` particles, with the
/// passes' own rule per neighbour: a measure of what evaluating each pair once costs at
/// the blocks' edges (the scenes bench prints it).
pub fn pair_evaluations(list: &sph_core::NeighborList, n: usize) -> PairEvaluations {
    let rows = block_rows(n);
    let mut e = PairEvaluations {
        block_rows: rows,
        ..PairEvaluations::default()
    };
    let mut later = Vec::new();
    for b in 0..n.div_ceil(rows) {
        let block = rows_of(&(b..b + 1), rows, n);
        later.clear();
        for i in block.start..block.end.min(list.len()) {
            for j in list.neighbors(i) {
                match visit(i, j as usize, block.start, block.end) {
                    Visit::Both => e.both += 1,
                    Visit::OwnOnly => {
                        e.across += 1;
                        if (block.end..n).contains(&(j as usize)) {
                            later.push(j);
                        }
                    }
                    Visit::Done => e.done += 1,
                }
            }
        }
        later.sort_unstable();
        later.dedup();
        e.later += later.len() as u64;
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A chain of 600 particles, each paired with those within 3 indices: blocks of
    /// 256 rows cut the chain twice, and each cut has 1 + 2 + 3 = 6 pairs across it.
    #[test]
    fn the_evaluations_of_a_chain_count_the_pairs_across_the_cuts() {
        let n = 600;
        let rows: Vec<Vec<u32>> = (0..n)
            .map(|i: usize| {
                (i.saturating_sub(3)..(i + 4).min(n))
                    .filter(|&j| j != i)
                    .map(|j| j as u32)
                    .collect()
            })
            .collect();
        let list = sph_core::NeighborList::from_rows(rows);
        let e = pair_evaluations(&list, n);
        assert_eq!(e.block_rows, 256);
        // Pairs: 3 per particle less the chain's ends (1 + 2 + 3 = 6 missing): 1 794.
        let pairs = 3 * n as u64 - 6;
        assert_eq!(e.across, 2 * 2 * 6);
        assert_eq!(e.both, pairs - 2 * 6);
        assert_eq!(e.done, e.both);
        // Blocks 0 and 1 each list the first three rows of the next block.
        assert_eq!(e.later, 2 * 3);
        let expected = (pairs + 2 * 6) as f64 / pairs as f64;
        assert!((e.per_pair() - expected).abs() < 1e-12);
        assert!((e.across_share() - 24.0 / (2 * pairs) as f64).abs() < 1e-12);
    }

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
